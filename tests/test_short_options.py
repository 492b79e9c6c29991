"""cli/command.Command reads a known short option as short at once; its parse is click's own, token for token."""

from __future__ import annotations

import subprocess
import sys

import click
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from camtool.cli import cli
from camtool.cli.command import Command

NAMES = ["dof", "fov", "hyperfocal", "focus", "exposure", "stack", "tilt", "compose", "flash", "equiv", "stars"]


def _command(name: str) -> click.Command:
    command = cli.get_command(click.Context(cli), name)
    assert isinstance(command, Command), name
    return command


def _parse(command: click.Command, parser: object, args: list[str]) -> object:
    try:
        opts, largs, order = parser.parse_args(list(args))  # type: ignore[attr-defined]
    except click.UsageError as error:
        return type(error).__name__, error.format_message()
    return opts, largs, [p.name for p in order]


def _both(name: str, args: list[str]) -> tuple[object, object]:
    command = _command(name)
    ctx = click.Context(command, info_name=name)
    fast = command.make_parser(ctx)
    plain = click.Command.make_parser(command, ctx)
    return _parse(command, fast, args), _parse(command, plain, args)


def _tokens(name: str) -> list[str]:
    command = _command(name)
    opts = [opt for param in command.params for opt in getattr(param, "opts", []) + getattr(param, "secondary_opts", [])]
    return [*opts, *(opt + "8" for opt in opts if len(opt) == 2), *(opt + "=3" for opt in opts),
            "-", "--", "-x", "-fx", "--no-such", "-N=8", "3m", "50", "f/8", "-1", "-0.5", "--format=json", "-Nf"]


@pytest.mark.parametrize("name", NAMES)
@settings(max_examples=150, deadline=None)
@given(data=st.data())
def test_the_parse_is_clicks(name: str, data: st.DataObject) -> None:
    args = data.draw(st.lists(st.sampled_from(_tokens(name)) | st.text(min_size=0, max_size=4), max_size=8))
    fast, plain = _both(name, args)
    assert fast == plain


def test_the_documented_spellings_parse_alike() -> None:
    for args in (["-f", "50", "-N", "8", "-s", "3m"], ["-f50", "-N8", "-s3m"], ["--focal-length=50", "-N", "8"],
                 ["-f", "-N"], ["-x"], ["--", "-f"], ["-s", "-3m"]):
        fast, plain = _both("dof", args)
        assert fast == plain, args


def test_a_short_option_imports_no_difflib() -> None:
    code = ("import atexit, sys; from camtool.cli import main; "
            "atexit.register(lambda: print('difflib' in sys.modules, file=sys.stderr)); "
            "sys.argv = ['camtool', 'dof', '-f', '50', '-N', '8', '-s', '3m', '--format', 'json']; main()")
    done = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True)
    assert done.stderr.strip() == "False"
