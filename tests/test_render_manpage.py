"""camtool.render.manpage renders any click group's pages, without the command line's package."""

from __future__ import annotations

import ast
from pathlib import Path

import click

from camtool.render import manpage


@click.group()
def tool() -> None:
    """A tool.

    \b
    Examples:
      tool go --far-away 3
    """


@tool.command("go")
@click.option("--far-away", type=float, help="How far - in metres.")
def go(far_away: float) -> None:
    """Go somewhere.

    First paragraph.

    Second paragraph.
    """


def test_pages_of_a_group_passed_in() -> None:
    pages = manpage.pages(tool, "tool")
    assert sorted(pages) == ["tool-go.1", "tool.1"]
    sub = pages["tool-go.1"]
    assert sub.startswith(f'.TH TOOL-GO 1 "{manpage.MAN_DATE}"')
    assert ".SH NAME\ntool\\-go \\- Go somewhere." in sub
    # roff's hyphen escape on the option and its help, each paragraph its own .PP
    assert ".TP\n\\fB\\-\\-far\\-away FLOAT\\fR\nHow far \\- in metres." in sub
    assert ".SH DESCRIPTION\nFirst paragraph.\n.PP\nSecond paragraph." in sub
    top = pages["tool.1"]
    assert ".SH EXAMPLES\n.nf\ntool go \\-\\-far\\-away 3\n.fi" in top
    assert ".SH COMMANDS\n.TP\n\\fBtool go\\fR\nGo somewhere." in top


def test_escape_and_key_units() -> None:
    assert manpage.escape(".x\n'y\nµ") == "\\&.x\n\\&'y\n\\[u00B5]"  # U+00B5 MICRO SIGN
    assert manpage.key_unit("near_mm") == "millimetres" and manpage.key_unit("tilt_deg") == "degrees"
    assert manpage.key_unit("unheard_of") == "number"


def test_render_does_not_import_the_command_line() -> None:
    tree = ast.parse(Path(manpage.__file__).read_text(encoding="utf-8"))
    names = [n.module for n in ast.walk(tree) if isinstance(n, ast.ImportFrom)]
    names += [a.name for n in ast.walk(tree) if isinstance(n, ast.Import) for a in n.names]
    assert not [n for n in names if n and n.startswith("camtool.cli")]
