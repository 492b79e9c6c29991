"""Write the man pages of ``camtool``: ``python -m camtool.cli.manpage man/man1``.

Run it after changing a command; a test regenerates the pages and fails on
any drift from the committed ones. The pages are rendered by
:mod:`camtool.render.manpage` from the click definitions.
"""

from __future__ import annotations

import sys
from pathlib import Path

from camtool.render import manpage
from camtool.render.manpage import key_unit, output_keys

__all__ = ["key_unit", "output_keys", "pages", "write"]


def pages() -> dict[str, str]:
    """File name -> roff source for camtool.1 and every subcommand's page."""
    from camtool.cli import cli

    return manpage.pages(cli)


def write(directory: Path) -> list[Path]:
    """Write every page into ``directory`` (created if missing) and return the paths."""
    from camtool.cli import cli

    return manpage.write(cli, directory)


if __name__ == "__main__":
    for path in write(Path(sys.argv[1] if len(sys.argv) > 1 else "man/man1")):
        print(path)
