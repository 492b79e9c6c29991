"""Shell completion completes every value a user types from a list, and file paths for file arguments."""

from __future__ import annotations

import os
import subprocess
import sys

import click
import pytest

from camtool.cli import cli


def _complete(*words: str) -> list[tuple[str, str]]:
    """(type, value) pairs from click's bash protocol for the command line ``camtool WORDS``."""
    env = {**os.environ, "_CAMTOOL_COMPLETE": "bash_complete", "COMP_WORDS": " ".join(("camtool", *words)),
           "COMP_CWORD": str(len(words))}
    result = subprocess.run([sys.executable, "-c", "from camtool.cli import main; main()"], env=env,
                            capture_output=True, text=True)
    assert result.returncode == 0, result.stderr
    return [tuple(line.split(",", 1)) for line in result.stdout.splitlines()]  # type: ignore[misc]


def _params() -> list[tuple[str, click.Parameter]]:
    found = []

    def walk(command: click.Command, path: str) -> None:
        for param in command.params:
            found.append((f"{path} {param.name}", param))
        if isinstance(command, click.Group):
            for name, sub in command.commands.items():
                walk(sub, f"{path} {name}")

    walk(cli, "camtool")
    return found


@pytest.mark.parametrize(("path", "param"), _params(), ids=lambda value: value if isinstance(value, str) else "")
def test_every_named_or_file_value_completes(path: str, param: click.Parameter) -> None:
    metavar = param.metavar or ""
    listed = any(word in metavar for word in ("NAME", "FILE", "RULE")) or param.name in ("paths", "file")
    if listed:
        custom = getattr(param, "_custom_shell_complete", None)
        assert custom is not None or isinstance(param.type, (click.Path, click.Choice)), path


def test_films_lights_coc_rules_and_presets_complete() -> None:
    assert ("plain", "hp5") in _complete("exposure", "--film", "hp")
    assert ("plain", "ilford-hp5-plus") in _complete("exposure", "--film", "ilford-h")
    lights = {value for _, value in _complete("exposure", "--light", "")}
    from camtool.exposure.light import LIGHT_LEVELS

    assert lights == set(LIGHT_LEVELS)
    from camtool.geometry.coc import RULES_TO_COMPLETE

    assert [value for _, value in _complete("dof", "--coc-rule", "")] == list(RULES_TO_COMPLETE)
    assert ("plain", "nikon-z-8") in _complete("dof", "--camera", "nikon-z-")
    assert ("plain", "full-frame") in _complete("dof", "--sensor", "full")
    # presets show: every kind, not lenses only
    shown = {value for _, value in _complete("presets", "show", "")}
    assert {"nikon-z-8", "full-frame"} <= shown
    assert ("plain", "thin") in _complete("dof", "--model", "th")


@pytest.mark.parametrize("words", [("exif", "IMG"), ("dof", "--batch", "scen"), ("dof", "--presets", "my"),
                                   ("presets", "import-lensfun", "--dir", "db"), ("presets", "validate", "my")])
def test_file_arguments_complete_paths(words: tuple[str, ...]) -> None:
    completions = _complete(*words)
    assert completions and all(kind in ("file", "dir") for kind, _ in completions), completions
