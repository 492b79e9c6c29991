"""docs/tables.md shows tables as a terminal draws them: SVGs made by rich's recording console, kept current.

``CAMTOOL_UPDATE_SNAPSHOTS=1`` rewrites the SVGs after a deliberate change to the tables.
"""

from __future__ import annotations

import io
import os
import re
from pathlib import Path

import pytest
from cli_helpers import run

DOCS = Path(__file__).parents[1] / "docs"
TABLES = {
    "dof-list": (100, ["dof", "-f", "50", "-N", "2.8,8,22", "-s", "3m,inf", "--model", "thin"]),
    "dof-diffraction": (80, ["dof", "-f", "50", "-N", "8,22,32", "-s", "3m", "--diffraction", "--model", "thin"]),
    "exposure-nd-film": (90, ["exposure", "--ev", "12", "-N", "8", "--nd", "10stops", "--nd", "6stops",
                              "--film", "fp4"]),
    "stack-narrow": (60, ["stack", "-f", "100", "-N", "8", "--near", "1m", "--far", "1.4m", "--units", "imperial"]),
}


def svg(name: str) -> str:
    from rich.console import Console
    from rich.text import Text

    width, args = TABLES[name]
    result = run(*args, env={"COLUMNS": str(width), "FORCE_COLOR": "1", "NO_COLOR": ""})
    assert result.exit_code == 0, result.output
    console = Console(record=True, width=width, force_terminal=True, color_system="truecolor", file=io.StringIO())
    console.print(Text.from_ansi(result.stdout), end="")
    return console.export_svg(title="camtool " + " ".join(args))


@pytest.mark.parametrize("name", sorted(TABLES))
def test_the_documented_tables_are_what_camtool_draws(name: str) -> None:
    path = DOCS / "tables" / f"{name}.svg"
    drawn = svg(name)
    if os.environ.get("CAMTOOL_UPDATE_SNAPSHOTS"):
        path.write_text(drawn, encoding="utf-8")
    assert drawn == path.read_text(encoding="utf-8"), f"{path} is out of date (CAMTOOL_UPDATE_SNAPSHOTS=1)"
    page = (DOCS / "tables.md").read_text(encoding="utf-8")
    assert f"tables/{name}.svg" in page
    assert re.search(re.escape(" ".join(TABLES[name][1][:2])), page)
