"""Every ``camtool exposure`` example in the README and docs/exposure.md runs (exit 0, output on stdout)."""

from __future__ import annotations

import re
import shlex
from pathlib import Path

import pytest
from cli_helpers import run

ROOT = Path(__file__).resolve().parents[1]
EXAMPLES = [
    line.split("#")[0].strip()
    for doc in ("README.md", "docs/exposure.md")
    for line in (ROOT / doc).read_text(encoding="utf-8").splitlines()
    if re.match(r"^camtool (exposure|stars|flash|equiv) ", line.strip())
]


@pytest.mark.parametrize("line", EXAMPLES)
def test_documented_example_runs(line: str) -> None:
    args = shlex.split(line)[1:]
    result = run(*args)
    assert result.exit_code == 0, result.stderr
    assert result.stdout


def _help_examples() -> list[str]:
    from camtool.cli import cli

    lines = []
    for name in ("exposure", "stars", "flash", "equiv"):
        command = cli.get_command(None, name)  # type: ignore[arg-type]
        assert command is not None and command.help
        lines += [line.strip() for line in command.help.split("Examples:")[1].splitlines()
                  if line.strip().startswith("camtool ")]
    return lines


@pytest.mark.parametrize("line", _help_examples())
def test_help_example_runs(line: str) -> None:
    result = run(*shlex.split(line)[1:])
    assert result.exit_code == 0, result.stderr
    assert result.stdout
