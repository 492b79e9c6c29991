"""What colour and emphasis mean in camtool's tables, defined once, and when there is colour at all.

Colour has a meaning, the same in every command: the header is bold and its
unit dim; the answer columns (near and far, the time to set, the step, …)
are bold; ∞ is cyan; the sharp-zone bar is green; a row with no answer is
red, and its reason joins the footer; the model that answered is magenta;
the footer is dim and a warning in it yellow.

There is colour only on a terminal: not when standard output is a pipe or a
file, not with ``NO_COLOR`` set to anything (https://no-color.org), not with
``TERM=dumb``. ``FORCE_COLOR`` (any value) colours a pipe too, for ``less
-R``. The escape codes are rich's, for the colour system rich detects.
"""

from __future__ import annotations

import os
from functools import lru_cache
from typing import IO, Any

THEME = {
    "header": "bold",
    "unit": "dim",
    "answer": "bold",
    "infinity": "cyan",
    "sharp": "green",
    "no_answer": "red",
    "model": "magenta",
    "footer": "dim",
    "warning": "yellow",
}
"""Style names (rich style definitions) used by the table renderer."""


def colour_system(stream: IO[str]) -> str | None:
    """rich's colour system for ``stream``, or None for plain text (no escape codes at all)."""
    if os.environ.get("NO_COLOR") or os.environ.get("TERM") == "dumb":
        return None
    forced = bool(os.environ.get("FORCE_COLOR"))
    if not forced:
        try:
            if not stream.isatty():
                return None
        except (AttributeError, ValueError, OSError):
            return None
    from rich.console import Console

    return Console(file=stream, force_terminal=True, legacy_windows=False).color_system


@lru_cache(maxsize=64)
def codes(name: str, system: str) -> tuple[str, str]:
    """The escape sequences that open and close the theme's ``name`` for colour system ``system``."""
    from rich.color import ColorSystem
    from rich.style import Style

    systems = {"standard": ColorSystem.STANDARD, "256": ColorSystem.EIGHT_BIT, "truecolor": ColorSystem.TRUECOLOR,
               "windows": ColorSystem.WINDOWS}
    opened = Style.parse(THEME[name])._make_ansi_codes(systems[system])
    return (f"\x1b[{opened}m", "\x1b[0m") if opened else ("", "")


def styled(text: str, name: str | None, system: str | None) -> str:
    """``text`` in the theme's style ``name`` (plain when there is no colour or no style)."""
    if not system or not name or not text:
        return text
    start, end = codes(name, system)
    return f"{start}{text}{end}"


def rich_style(name: str | None) -> Any:
    """The rich ``Style`` of ``name`` (the null style for None)."""
    from rich.style import Style

    return Style.parse(THEME[name]) if name else Style.null()
