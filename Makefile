# One check: lint, types, tests (what .ci/run runs through the README's test command).
.PHONY: check lint types test

check: lint types test

lint:
	ruff check camtool tests benchmarks

types:
	mypy

test:
	python -m pytest
