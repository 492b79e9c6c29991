"""Tables for people: right-aligned numbers, units in the headers, a footer.

Drawn as plain text (three spaces between columns, a rule under the
headers), so every cell is printed whole: a number is never cropped. On a
terminal, or with ``COLUMNS`` set, a table wider than the screen leaves out
columns, pictures first and then from the right, and says on standard error
which ones (but for pictures, which hold no value) and how to get them; into a pipe with no ``COLUMNS`` the table
takes the width it needs. ``COLUMNS`` that is not a positive number is
ignored.
"""

from __future__ import annotations

import os
from collections.abc import Sequence
from typing import IO, Any, NamedTuple

from camtool.render.columns import ANGLE, DISTANCE, FNUMBER, SMALL, TEXT, Column
from camtool.render.numfmt import distance_unit, feet_inches, significant
from camtool.render.serial import printable

GAP = "   "
RULE = "─"


def _cells(column: Column, rows: Sequence[dict[str, Any]], units: str) -> tuple[str, list[str]]:
    values = [row.get(column.key) for row in rows]
    if column.kind == DISTANCE and units == "imperial":
        # one notation for every distance of the table: feet and inches, ∞ for infinity
        return f"{column.header}\n(ft in)", [feet_inches(v) for v in values]
    if column.kind == DISTANCE:
        unit, size = distance_unit(values, units)
    elif column.kind == SMALL:
        unit, size = "mm", 1.0
    elif column.kind == ANGLE:
        unit, size = "°", 1.0
    else:
        unit, size = "", 1.0
    header = f"{column.header}\n({unit})" if unit else column.header
    if column.kind == TEXT:
        return header, ["" if v is None else printable(str(v)) for v in values]
    if column.kind == FNUMBER:
        return header, [f"f/{v:.3g}" if isinstance(v, float) else "–" for v in values]
    if column.kind == SMALL:
        return header, [f"{v:.4g}" if isinstance(v, float) else "–" for v in values]
    return header, [significant(v / size) if isinstance(v, float) else significant(v) for v in values]


class Rendered(NamedTuple):
    """A drawn table: its text, and the columns left out to fit the width."""

    text: str
    left_out: list[Column]


def table_width(stream: IO[str]) -> int | None:
    """The width to fit: ``COLUMNS`` if a positive number, else the terminal's, else None (a pipe)."""
    text = os.environ.get("COLUMNS", "").strip()
    if text.isdigit() and int(text) > 0:
        return int(text)
    try:
        if stream.isatty():
            return os.get_terminal_size(stream.fileno()).columns or None
    except (AttributeError, OSError, ValueError):
        pass
    return None


def render_table(
    rows: Sequence[dict[str, Any]],
    columns: Sequence[Column],
    units: str = "metric",
    footer: str = "",
    width: int | None = None,
    bold: bool = False,
) -> Rendered:
    """Draw ``rows`` as a table of ``columns`` no wider than ``width`` (None: as wide as needed).

    >>> from camtool.render.columns import Column, SMALL
    >>> print(render_table([{"f": 50.0, "s": 3000.0}], [Column("f", "f", SMALL), Column("s", "focus")]).text, end="")
       f   focus
    (mm)     (m)
    ────────────
      50   3.000
    """
    drawn = []
    for column in columns:
        header, cells = _cells(column, rows, units)
        lines = header.split("\n")
        size = max(max((len(cell) for cell in cells), default=0), max(len(line) for line in lines))
        drawn.append((column, lines, cells, size))
    shown = list(range(len(drawn)))
    if width is not None:
        # pictures go first, then columns from the right; the first column always stays
        order = [i for i in reversed(shown) if drawn[i][0].kind == TEXT] + \
                [i for i in reversed(shown) if drawn[i][0].kind != TEXT]
        for index in order:
            if _width([drawn[i][3] for i in shown]) <= width or len(shown) == 1:
                break
            shown.remove(index)
    kept = [drawn[i] for i in shown]
    total = _width([size for *_, size in kept])
    height = max((len(lines) for _, lines, _, _ in kept), default=1)
    out = []
    for line in range(height):
        parts = []
        for column, lines, _, size in kept:
            text = lines[line - (height - len(lines))] if line >= height - len(lines) else ""
            parts.append(_justify(text, size, column))
        header = GAP.join(parts)
        out.append(f"\x1b[1m{header}\x1b[0m" if bold else header)
    out.append(RULE * total)
    for index in range(len(rows)):
        out.append(GAP.join(_justify(cells[index], size, column) for column, _, cells, size in kept))
    left_out = [drawn[i][0] for i in range(len(drawn)) if i not in shown]
    legends = [column.legend for column, *_ in kept if column.legend]
    notes = footer.split("\n") if footer else []
    if legends:
        notes = [*notes[:-1], " · ".join(part for part in (*notes[-1:], *legends) if part)]
    for note in notes:
        out.extend(_wrap(note, width))
    return Rendered("\n".join(out) + "\n", left_out)


def _width(sizes: list[int]) -> int:
    return sum(sizes) + len(GAP) * max(0, len(sizes) - 1)


def _justify(text: str, size: int, column: Column) -> str:
    return text.ljust(size) if column.kind == TEXT else text.rjust(size)


def _wrap(text: str, width: int | None) -> list[str]:
    """The footer, broken at its `` · `` separators (or spaces) to fit ``width``."""
    if width is None or len(text) <= width:
        return [text]
    import textwrap

    return textwrap.wrap(text, width, break_long_words=False, break_on_hyphens=False) or [text]


def write_table(
    rows: Sequence[dict[str, Any]],
    columns: Sequence[Column],
    stream: IO[str],
    units: str = "metric",
    footer: str = "",
    errors: IO[str] | None = None,
) -> None:
    """Draw ``rows`` on ``stream``; columns left out to fit the terminal are named on ``errors``."""
    width = table_width(stream)
    bold = width is not None and _is_terminal(stream) and not os.environ.get("NO_COLOR") \
        and os.environ.get("TERM") != "dumb"
    rendered = render_table(rows, columns, units, footer, width, bold)
    stream.write(rendered.text)
    # a picture (a column with a legend, the sharp-zone bar) gives way quietly: it holds no value
    left_out = [column for column in rendered.left_out if not column.legend]
    if left_out and errors is not None:
        names = ", ".join(column.header for column in left_out)
        errors.write(f"camtool: left out to fit {width} columns: {names} (a wider terminal or COLUMNS shows them; "
                     "--format csv or json gives every value)\n")


def _is_terminal(stream: IO[str]) -> bool:
    try:
        return stream.isatty()
    except (AttributeError, ValueError):
        return False
