"""Tables for people, drawn with rich: right-aligned numbers, units in the headers, a footer.

The console is made per call, so ``COLUMNS``, ``NO_COLOR`` and whether
standard output is a terminal are read each time (pipes get plain text).
"""

from __future__ import annotations

import os
from collections.abc import Sequence
from typing import IO, Any

from rich import box
from rich.console import Console
from rich.measure import Measurement
from rich.table import Table

from camtool.render.columns import ANGLE, DISTANCE, FNUMBER, SMALL, TEXT, Column
from camtool.render.numfmt import distance_unit, feet_inches, significant


def _cells(column: Column, rows: Sequence[dict[str, Any]], units: str) -> tuple[str, list[str]]:
    values = [row.get(column.key) for row in rows]
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
        return header, ["" if v is None else str(v) for v in values]
    if column.kind == FNUMBER:
        return header, [f"f/{v:.3g}" if v is not None else "–" for v in values]
    if column.kind == SMALL:
        return header, [f"{v:.4g}" if v is not None else "–" for v in values]
    if column.kind == DISTANCE and unit == "ft":
        return f"{column.header}\n(ft in)", [feet_inches(v) for v in values]
    return header, [significant(v / size) if isinstance(v, float) else significant(v) for v in values]


def write_table(
    rows: Sequence[dict[str, Any]],
    columns: Sequence[Column],
    stream: IO[str],
    units: str = "metric",
    footer: str = "",
    title: str | None = None,
) -> None:
    """Draw ``rows`` as a table of ``columns`` with an optional one-line ``footer``.

    Into a pipe (and with no ``COLUMNS`` set) the table takes the width it
    needs; on a terminal too narrow for it, text columns (the pictures) go
    first, then rich folds the headers.
    """
    console = Console(file=stream, highlight=False, soft_wrap=False)
    table = _build(rows, columns, units, title)
    needed = Measurement.get(console, console.options.update_width(10_000), table).maximum
    if not console.is_terminal and not os.environ.get("COLUMNS"):
        console = Console(file=stream, highlight=False, soft_wrap=False, width=max(needed, len(footer), 40))
    elif needed > console.width:
        table = _build(rows, [c for c in columns if c.kind != TEXT], units, title)
    console.print(table)
    if footer:
        console.print(footer, highlight=False, overflow="fold")


def _build(rows: Sequence[dict[str, Any]], columns: Sequence[Column], units: str, title: str | None) -> Table:
    table = Table(box=box.SIMPLE_HEAD, title=title, pad_edge=False, show_edge=False)
    rendered = [_cells(column, rows, units) for column in columns]
    for column, (header, cells) in zip(columns, rendered):
        widest = max((len(cell) for cell in cells), default=1)
        table.add_column(header, justify="left" if column.kind == TEXT else "right", min_width=widest)
    for index in range(len(rows)):
        table.add_row(*(cells[index] for _, cells in rendered))
    return table
