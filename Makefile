# One check: lint, types, tests (what .ci/run runs through the README's test command).
.PHONY: check lint types test fuzz-deep lock

# pytest-xdist workers for the test run: `auto` is one per core; PYTEST_WORKERS=0 runs in one process
PYTEST_WORKERS ?= auto
# uv, in an environment of its own (python3 -m venv /tmp/venv-lock && /tmp/venv-lock/bin/pip install uv)
UV ?= uv

check: lint types test

lint:
	ruff check camtool tests benchmarks

types:
	mypy

test:
	@if python -c 'import xdist' 2>/dev/null; then set -x; python -m pytest -n $(PYTEST_WORKERS); \
	else echo "make test: pytest-xdist is not installed (pip install -c requirements/test.lock -e '.[test]'); one process" >&2; \
	set -x; python -m pytest; fi

# The deep command-line fuzz (tests marked slow): 5,000 command lines for each of two seeds, about ten minutes
fuzz-deep:
	CAMTOOL_FUZZ_EXAMPLES=5000 CAMTOOL_FUZZ_SEED=1 python -m pytest -m slow tests/test_cli_fuzz.py
	CAMTOOL_FUZZ_EXAMPLES=5000 CAMTOOL_FUZZ_SEED=2 python -m pytest -m slow tests/test_cli_fuzz.py

# Refresh requirements/test.lock: the newest releases that satisfy pyproject.toml's test extra, one set of pins
# for every Python from 3.10 on and every platform (markers where they differ), resolved against PyPI alone
# (--no-config: no uv.toml or [tool.uv] of this machine's points it elsewhere).
lock:
	$(UV) pip compile pyproject.toml --extra test --universal --python-version 3.10 --upgrade --no-config \
		--no-header -q -o requirements/test.lock.new
	{ sed -n '1,/^$$/p' requirements/test.lock; cat requirements/test.lock.new; } > requirements/test.lock.tmp
	rm requirements/test.lock.new && mv requirements/test.lock.tmp requirements/test.lock
