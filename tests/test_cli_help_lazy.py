"""``camtool --help`` lists the commands from their modules' source (camtool.cli.summary), without importing them:
the same text as click's."""

from __future__ import annotations

import subprocess
import sys

import click
import pytest
from cli_helpers import time_bound  # noqa: F401 - an autouse fixture

from camtool.cli import COMMANDS, CamtoolGroup, cli, summary


def test_each_summary_is_the_first_paragraph_of_its_commands_help() -> None:
    ctx = click.Context(cli)
    for name in COMMANDS:
        command = cli.get_command(ctx, name)
        assert command is not None and command.help is not None
        assert summary(name) == " ".join(command.help.split("\n\n")[0].split()), name
        assert not command.short_help and not command.hidden and not command.deprecated


@pytest.mark.parametrize("width", [40, 80, 100])
def test_the_command_list_is_what_click_writes_from_the_commands(width: int) -> None:
    ctx = click.Context(cli)
    mine, clicks = click.HelpFormatter(width=width), click.HelpFormatter(width=width)
    cli.format_commands(ctx, mine)
    super(CamtoolGroup, cli).format_commands(ctx, clicks)
    assert mine.getvalue() == clicks.getvalue() != ""


def test_help_imports_no_command_module() -> None:
    code = ("import sys; sys.argv = ['camtool', '--help']\nfrom camtool.cli import main\ntry:\n    main()\n"
            "except SystemExit:\n    pass\nprint(sorted(m for m in sys.modules if m.startswith('camtool.cli.')), "
            "'difflib' in sys.modules, file=sys.stderr)")
    result = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True)
    assert "Commands:" in result.stdout
    assert result.stderr.strip() == "[] False"
