"""The README's table of output keys is the commands' own: every key a command declares, and no other.

Each command declares every key its rows can carry (``camtool_command(keys=...)``,
what ``--field`` checks against); the README lists them per command. A key
written ``prefix_*`` (or ``*_suffix``) stands for every declared key with that prefix (suffix); ``null`` is a value.
"""

from __future__ import annotations

import re
from pathlib import Path

import click
import pytest

from camtool.cli import cli

README = (Path(__file__).resolve().parent.parent / "README.md").read_text(encoding="utf-8")
SECTION = README[README.index("## Output for scripts"):README.index("## In shell scripts")]
ROWS = {match.group(1): match.group(2) for match in re.finditer(r"^\| `([a-z ]+)` \| (.+) \|$", SECTION, re.M)}


def _declared(name: str) -> list[str]:
    command = cli.get_command(click.Context(cli), name)
    assert command is not None
    return list(getattr(command, "output_key_list", []))


@pytest.mark.parametrize("name", [n for n in ROWS if " " not in n])
def test_every_declared_key_is_in_the_readme_and_no_other(name: str) -> None:
    written = [key for key in re.findall(r"`([a-z0-9_*]+)`", ROWS[name]) if key != "null"]
    declared = _declared(name)
    assert declared, f"{name} declares no output keys"
    prefixes = [key[:-1] for key in written if key.endswith("*")]
    suffixes = [key[1:] for key in written if key.startswith("*")]
    plain = {key for key in written if "*" not in key}
    missing = [key for key in declared if key not in plain and not any(key.startswith(p) for p in prefixes)
               and not any(key.endswith(x) for x in suffixes)]
    extra = sorted(plain - set(declared))
    assert not missing and not extra, f"README's {name} row: missing {missing}, not declared {extra}"


def test_every_command_with_output_keys_has_a_row() -> None:
    for name in cli.list_commands(click.Context(cli)):
        if _declared(name):
            assert name in ROWS, f"README's key table has no row for {name}"
