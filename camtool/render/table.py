"""Tables for people, drawn by rich: units in the headers, every number whole, the answer always shown.

A table's cells are text made here (right-aligned numbers with units in the
headers, ``–`` for no value); rich lays them out and colours them (the meaning
of each colour is :mod:`camtool.render.theme`'s). A number is never cropped:
each column is exactly as wide as its widest cell. On a terminal, or with
``COLUMNS`` set, a table wider than the screen leaves out columns — pictures
first, then, from the right, the columns that neither identify a row nor hold
its answer (:data:`~camtool.render.columns.IDENTIFYING`,
:data:`~camtool.render.columns.ANSWERS`) — and names them on standard error;
when even those do not fit, the table turns into one block per row
(``key: value`` lines), so the answer is never left out. Into a pipe with no
``COLUMNS`` the table takes the width it needs. ``COLUMNS`` that is not a
positive number is ignored.

A row with no answer keeps its place (dashes) and its reason joins the footer;
many such rows are summarised (the first few, a count, and where to find all).

rich draws tables of up to :data:`RICH_ROWS` rows; longer ones (up to
:data:`WRAP_ROWS` when text must wrap, else any number) are drawn a line at a
time, long text cells broken where rich breaks them, with the same widths, gaps, rule and
escape codes (byte for byte what rich draws, which a test holds), because rich
takes about a millisecond a row to lay out (``presets list``, 400 rows, spent
most of its time there).
"""

from __future__ import annotations

import itertools
import os
from collections.abc import Sequence
from typing import IO, Any

from camtool.core import collector
from camtool.core.record import NamedTuple
from camtool.render.columns import ANGLE, ANSWERS, DISTANCE, FNUMBER, IDENTIFYING, SMALL, TEXT, Column
from camtool.render.numfmt import distance_unit, feet_inches, significant
from camtool.render.serial import ERROR, printable
from camtool.render.theme import colour_system, rich_style, styled

GAP = "   "
RULE = "─"
RICH_ROWS = 60
"""Tables longer than this are drawn line by line (the same bytes rich would draw) unless text must wrap."""
WRAP_ROWS = 500
"""Tables longer than this whose text would have to wrap are drawn as blocks (``key: value``) instead."""
ROW_NOTES = 5
"""Notes on rows with no answer shown in a footer before the rest are counted."""


class _Drawn(NamedTuple):
    column: Column
    header: list[str]
    cells: list[str]
    styles: list[str | None]
    size: int


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


def _no_answer(row: dict[str, Any]) -> bool:
    return bool(row.get(ERROR) or row.get("reason"))


def _style(column: Column, cell: str, failed: bool) -> str | None:
    if failed:
        return "no_answer"
    if cell == "∞":
        return "infinity"
    if column.legend:
        return "sharp"
    if column.key == "model":
        return "model"
    return "answer" if column.key in ANSWERS else None


def _draw(column: Column, rows: Sequence[dict[str, Any]], units: str, failed: list[bool], colour: str | None) -> _Drawn:
    header, cells = _cells(column, rows, units)
    lines = header.split("\n")
    # without colour no style is drawn: none is worked out
    styles: list[str | None] = ([_style(column, cell, bad) for cell, bad in zip(cells, failed)] if colour
                                else [None] * len(cells))
    size = max(max((len(cell) for cell in cells), default=0), max(len(line) for line in lines))
    return _Drawn(column, lines, cells, styles, size)


class Rendered(NamedTuple):
    """A drawn table: its text, the columns left out to fit the width, and whether it became blocks."""

    text: str
    left_out: list[Column]
    vertical: bool = False


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


def _keeps(drawn: _Drawn, index: int) -> bool:
    """A column that identifies the row or holds its answer (the first column always does)."""
    return index == 0 or drawn.column.key in IDENTIFYING or drawn.column.key in ANSWERS


WRAP_MIN = 16
"""The narrowest a text column (a file name, a preset's value) is wrapped to before a table becomes blocks."""


def _fit(drawn: list[_Drawn], width: int | None) -> tuple[list[int], dict[int, int] | None]:
    """The columns shown at ``width``, and the narrower widths of text columns wrapped to fit them.

    None for the widths: even wrapped, the answers do not fit side by side (the table becomes blocks).
    """
    shown = list(range(len(drawn)))
    if width is None:
        return shown, {}
    pictures = [i for i in reversed(shown) if drawn[i].column.legend]
    others = [i for i in reversed(shown) if not drawn[i].column.legend and not _keeps(drawn[i], i)]
    for index in pictures + others:
        if _width([drawn[i].size for i in shown]) <= width:
            return shown, {}
        shown.remove(index)
    excess = _width([drawn[i].size for i in shown]) - width
    if excess <= 0 or (len(shown) == 1 and drawn[shown[0]].column.kind != TEXT):
        return shown, {}
    # text (never a number) may wrap: the widest text columns give up their width first
    wrapped: dict[int, int] = {}
    for index in sorted((i for i in shown if drawn[i].column.kind == TEXT), key=lambda i: -drawn[i].size):
        floor = max(WRAP_MIN, *(len(line) for line in drawn[index].header))
        give = min(excess, drawn[index].size - floor)
        if give > 0:
            wrapped[index] = drawn[index].size - give
            excess -= give
    return shown, (wrapped if excess <= 0 else None)


def render_table(
    rows: Sequence[dict[str, Any]],
    columns: Sequence[Column],
    units: str = "metric",
    footer: str = "",
    width: int | None = None,
    colour: str | None = None,
    row_notes: Sequence[str] = (),
) -> Rendered:
    """Draw ``rows`` as a table of ``columns`` no wider than ``width`` (None: as wide as needed).

    ``colour`` is rich's colour system (None: plain text); ``row_notes`` are
    notes on single rows (summarised when many).

    >>> from camtool.render.columns import Column, SMALL
    >>> print(render_table([{"f": 50.0, "s": 3000.0}], [Column("f", "f", SMALL), Column("s", "focus")]).text, end="")
       f   focus
    (mm)     (m)
    ────────────
      50   3.000
    """
    failed = [_no_answer(row) for row in rows]
    drawn = [_draw(column, rows, units, failed, colour) for column in columns]
    shown, wrapped = _fit(drawn, width)
    vertical = wrapped is None or (bool(wrapped) and len(rows) > WRAP_ROWS)
    notes = _reasons(rows, drawn, failed, shown, vertical) + list(row_notes)
    if vertical:
        kept = [d for d in drawn if not d.column.legend]
        body = _blocks(kept, len(rows), colour)
        left_out = [d.column for d in drawn if d.column.legend]
    else:
        kept = [drawn[i]._replace(size=(wrapped or {}).get(i, drawn[i].size)) for i in shown]
        folded = {kept[shown.index(i)].column.key for i in wrapped or {}}
        body = (_rich(kept, len(rows), colour, folded) if len(rows) <= RICH_ROWS or not _plain_cells(kept, folded)
                else _lines(kept, len(rows), colour, folded))
        left_out = [drawn[i].column for i in range(len(drawn)) if i not in shown]
    legends = [d.column.legend for d in kept if d.column.legend]
    text = body + _footer(footer, legends, _summary(notes), width, colour)
    return Rendered(text, left_out, vertical)


def _reasons(rows: Sequence[dict[str, Any]], drawn: list[_Drawn], failed: list[bool], shown: list[int],
             vertical: bool) -> list[str]:
    """Footer notes for rows with no answer whose reason no shown column carries."""
    shows_reason = any(drawn[i].column.key in ("reason", ERROR) for i in ([] if vertical else shown))
    if shows_reason or not any(failed):
        return []
    # a row is named by the identifying cells that differ from row to row, else by its number
    naming = [d for i, d in enumerate(drawn) if _keeps(d, i) and d.column.key not in ANSWERS
              and len(set(d.cells)) > 1]
    notes = []
    for index, row in enumerate(rows):
        reason = row.get("reason") or row.get(ERROR)
        if failed[index] and reason:
            name = " ".join(cell for cell in (d.cells[index] for d in naming) if cell not in ("", "–"))
            notes.append(f"row {index + 1}{f' ({name})' if name else ''}: {printable(str(reason))}")
    return notes


def _summary(notes: list[str]) -> list[str]:
    if len(notes) <= ROW_NOTES + 1:
        return notes
    return [*notes[:ROW_NOTES], f"… and {len(notes) - ROW_NOTES:,} more rows with no answer "
                                 "(--format json or csv gives every row's error)"]


def _header_cell(lines: list[str]) -> Any:
    from rich.text import Text

    text = Text()
    for number, line in enumerate(lines):
        if number:
            text.append("\n")
        unit = number == len(lines) - 1 and number > 0 and line.startswith("(") and bool(lines[number - 1])
        text.append(line, rich_style("unit" if unit else "header"))
    return text


def _rich(kept: list[_Drawn], count: int, colour: str | None, wrapped: set[str] = frozenset()) -> str:  # type: ignore[assignment]
    """The header, rule and rows as rich draws them (the ``wrapped`` text columns folded to their width)."""
    import io

    with collector.importing():  # rich's classes live as long as the process
        from rich import box
        from rich.console import Console
        from rich.table import Table
        from rich.text import Text

    rule = box.Box(f"    \n    \n{RULE * 4}\n    \n    \n    \n    \n    \n")
    table = Table(box=rule, show_edge=False, pad_edge=False, padding=(0, 1), header_style="",
                  show_header=True)
    height = max(len(d.header) for d in kept)
    for d in kept:  # headers stand on the rule (units on the last line); cells hang from the top of their row
        table.add_column(_header_cell([""] * (height - len(d.header)) + d.header),
                         justify="left" if d.column.kind == TEXT else "right", vertical="top",
                         no_wrap=d.column.key not in wrapped, overflow="fold", min_width=d.size, max_width=d.size)
    for index in range(count):
        table.add_row(*(Text(d.cells[index], rich_style(d.styles[index])) for d in kept))
    out = io.StringIO()
    console = Console(file=out, width=max(1, _width([d.size for d in kept])), color_system=colour,  # type: ignore[arg-type]
                      force_terminal=bool(colour), no_color=not colour, highlight=False, markup=False,
                      emoji=False, legacy_windows=False, soft_wrap=False)
    console.print(table)
    return out.getvalue()


def _plain_cells(kept: list[_Drawn], wrapped: set[str]) -> bool:
    """Whether :func:`_lines` draws these cells as rich would: no line breaks or tabs in a column that wraps."""
    return all(not ("\n" in cell or "\t" in cell) for d in kept if d.column.key in wrapped for cell in d.cells)


def _folded(text: str, width: int) -> list[str]:
    """``text`` broken into lines of at most ``width`` as rich breaks a cell: at spaces, folding longer words.

    Each word (with the spaces around it) goes on the line if its letters
    fit, else starts the next line; a word longer than a line is cut into
    line-long pieces. A test holds the lines to rich's own.
    """
    if len(text) <= width:
        return [text]
    import re

    starts: list[int] = []
    used = 0
    for word in re.finditer(r"\s*\S+\s*", text):
        start, end = word.span()
        letters = len(word.group().rstrip())
        if used + letters <= width:
            used += end - start
            continue
        if letters > width:  # too long for any line: folded, its last piece carries on
            if used:
                starts.append(start)
            piece = start
            while end - piece > width:
                piece += width
                starts.append(piece)
            used = end - piece
            continue
        starts.append(start)
        used = end - start
    offsets = [0, *starts, len(text)]
    return [text[a:b][:width] for a, b in itertools.pairwise(offsets)]


def _lines(kept: list[_Drawn], count: int, colour: str | None, wrapped: set[str] = frozenset()) -> str:  # type: ignore[assignment]
    """The same bytes as :func:`_rich`, a line at a time: fixed widths, the same escape codes.

    A text cell of a ``wrapped`` column longer than its width takes as many
    lines as rich gives it (its row's other cells blank below their text).
    """
    height = max(len(d.header) for d in kept)
    out = []
    for line in range(height):
        parts = []
        for d in kept:
            offset = line - (height - len(d.header))
            text = d.header[offset] if offset >= 0 else ""
            unit = offset == len(d.header) - 1 and offset > 0 and text.startswith("(")
            pad = d.size - len(text)
            cell = styled(text, "unit" if unit else "header", colour)
            parts.append(cell + " " * pad if d.column.kind == TEXT else " " * pad + cell)
        out.append(GAP.join(parts))
    out.append(RULE * _width([d.size for d in kept]))
    if not wrapped and not colour:  # plain cells, padded: the same bytes as below, a column at a time
        padded = [[cell.ljust(d.size) for cell in d.cells] if d.column.kind == TEXT else
                  [cell.rjust(d.size) for cell in d.cells] for d in kept]
        out.extend(map(GAP.join, zip(*padded)))
        return "\n".join(out) + "\n"
    for index in range(count):
        if not wrapped:
            out.append(GAP.join(styled(d.cells[index].ljust(d.size) if d.column.kind == TEXT
                                       else d.cells[index].rjust(d.size), d.styles[index], colour) for d in kept))
            continue
        cells = [_folded(d.cells[index], d.size) if d.column.key in wrapped else [d.cells[index]] for d in kept]
        for line in range(max(len(lines) for lines in cells)):
            out.append(GAP.join(
                (styled(lines[line].ljust(d.size) if d.column.kind == TEXT else lines[line].rjust(d.size),
                        d.styles[index], colour) if line < len(lines) else " " * d.size)
                for d, lines in zip(kept, cells)))
    return "\n".join(out) + "\n"


def _blocks(kept: list[_Drawn], count: int, colour: str | None) -> str:
    """One block per row, ``header (unit): value`` — for a screen too narrow for the answer columns side by side."""
    labels = [" ".join(d.header) for d in kept]
    size = max(len(label) for label in labels)
    blocks = []
    for index in range(count):
        blocks.append("\n".join(styled(f"{label}:".ljust(size + 1), "header", colour) + " " +
                                styled(d.cells[index], d.styles[index], colour) for label, d in zip(labels, kept)))
    return "\n\n".join(blocks) + "\n"


def _footer(footer: str, legends: list[str], notes: list[str], width: int | None, colour: str | None) -> str:
    lines = footer.split("\n") if footer else []
    if legends:
        lines = [*lines[:-1], " · ".join(part for part in (*lines[-1:], *legends) if part)]
    out: list[str] = []
    for line in lines:
        style = "warning" if line.lower().startswith("warning") else "footer"
        out.extend(styled(part, style, colour) for part in _wrap(line, width))
    for note in notes:
        out.extend(styled(part, "no_answer", colour) for part in _wrap(note, width))
    return "".join(line + "\n" for line in out)


def _width(sizes: list[int]) -> int:
    return sum(sizes) + len(GAP) * max(0, len(sizes) - 1)


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
    row_notes: Sequence[str] = (),
) -> None:
    """Draw ``rows`` on ``stream``; columns left out to fit the terminal are named on ``errors``."""
    width = table_width(stream)
    rendered = render_table(rows, columns, units, footer, width, colour_system(stream), row_notes)
    stream.write(rendered.text)
    # a picture (a column with a legend, the sharp-zone bar) gives way quietly: it holds no value
    left_out = [column for column in rendered.left_out if not column.legend]
    # blocks leave out nothing but pictures: no note
    if errors is not None and left_out and not rendered.vertical:
        names = ", ".join(column.header for column in left_out)
        errors.write(f"camtool: left out to fit {width} columns: {names} (a wider terminal or COLUMNS shows them; "
                     "--format csv or json gives every value)\n")
