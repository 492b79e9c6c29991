"""The one writer every command hands its rows to, for single runs and ``--batch`` alike.

:class:`RowWriter` takes rows chunk by chunk and writes them as they come:
JSON (one array, a row per line), CSV (one header), ``--field`` lines; the
same rows give the same bytes whether they came in one piece or in many. A
table needs every row to choose its units and widths, so it is drawn once,
at :meth:`RowWriter.close`, from rows kept until then.
"""

from __future__ import annotations

import itertools
import json
import sys
from collections.abc import Callable, Sequence
from typing import IO, Any

from camtool.render.columnar import ColumnRows, texts
from camtool.render.columns import Column
from camtool.render.serial import ERROR, any_unanswered, csv_cells, field_line, json_row, printable, withheld

FORMATS = ("table", "json", "csv")
_ENCODER = json.JSONEncoder(allow_nan=False, ensure_ascii=False)
SLICE = 20_000
"""Rows turned to text at a time by the column writer."""
LATER_NOTES = 4
"""New footer notes of later chunks shown in a table's footer before the rest are counted."""


class RowWriter:
    """Write rows as a table, JSON, CSV or ``--field`` lines, streaming what can be streamed.

    ``on_keys`` is called with the output keys before anything is written
    (to check ``--field`` against them). A skipped row (:meth:`skip`) keeps
    its place: ``null`` values and an ``error`` key in JSON, empty cells in
    CSV, an empty line with ``--field``, dashes in a table.

    >>> import io
    >>> out = io.StringIO()
    >>> writer = RowWriter("json", stream=out)
    >>> writer.write([{"a": 1.0}], [], ["a"])
    >>> writer.skip("row 2: bad")
    >>> writer.write([{"a": float("inf")}], [], ["a"])
    >>> writer.close()
    >>> print(out.getvalue(), end="")
    [
    {"a": 1.0},
    {"a": null, "error": "row 2: bad"},
    {"a": null}
    ]
    """

    def __init__(self, fmt: str, units: str = "metric", fields: Sequence[str] = (), stream: IO[str] | None = None,
                 errors: IO[str] | None = None, on_keys: Callable[[Sequence[str]], None] | None = None) -> None:
        self.fmt, self.units, self.fields = fmt, units, tuple(fields)
        self.stream = stream or sys.stdout
        self.errors = errors
        self.on_keys = on_keys
        self.keys: list[str] | None = None
        self.columns: list[Column] = []
        self.footers: list[str] = []
        self.later: list[str] = []
        self.pending: list[dict[str, Any]] = []
        self.table_rows: list[dict[str, Any]] = []
        self.started = False
        self.closed = False

    def write(self, rows: Sequence[dict[str, Any]], columns: Sequence[Column], keys: Sequence[str],
              footer: str = "") -> None:
        """Write (or, for a table, keep) one chunk of rows; the first chunk fixes the keys and columns."""
        if self.keys is None:
            self._start(keys, columns)
        if footer:
            self._footer(printable(footer))
        self._emit(rows)

    def _footer(self, footer: str) -> None:
        """Keep a chunk's footer: the first whole, a later one's parts only where they say something new."""
        if not self.footers:
            self.footers.append(footer)
            return
        said = {part for line in self.footers for part in line.split(" · ")} | set(self.later)
        self.later.extend(part for part in dict.fromkeys(footer.split(" · ")) if part not in said)

    def _footer_text(self) -> str:
        """The footers of every chunk: the first, then at most :data:`LATER_NOTES` new notes of later chunks."""
        lines = list(self.footers)
        if self.later:
            shown = " · ".join(self.later[:LATER_NOTES])
            more = len(self.later) - LATER_NOTES
            lines.append(f"later rows: {shown}" + (f" · … and {more} more notes" if more > 0 else ""))
        return "\n".join(lines)

    def skip(self, message: str, cells: dict[str, Any] | None = None) -> None:
        """A row that could not be computed, in its place (``cells``: what it keeps, e.g. passed-through input)."""
        row = {**(cells or {}), ERROR: message}
        if self.keys is None:
            self.pending.append(row)
        else:
            self._emit([row])

    def close(self, keys: Sequence[str] = (), columns: Sequence[Column] = ()) -> None:
        """End the output (close the JSON array, draw the table); ``keys`` serve if no row gave any."""
        if self.closed:
            return
        self.closed = True
        if self.keys is None:
            self._start(keys, columns)
        if self.fields:
            return
        if self.fmt == "json":
            self.stream.write("\n]\n" if self.started else "[]\n")
        elif self.fmt not in ("csv", "json") and self.columns:
            from camtool.render.table import write_table

            write_table(self.table_rows, self.columns, self.stream, self.units, self._footer_text(),
                        errors=self.errors)

    def _start(self, keys: Sequence[str], columns: Sequence[Column]) -> None:
        if self.on_keys is not None:
            self.on_keys(keys)
        self.keys, self.columns = list(keys), list(columns)
        if self.fmt == "csv" and not self.fields and self.keys:
            import csv

            csv.writer(self.stream, lineterminator="\n").writerow(self.keys)
        pending, self.pending = self.pending, []
        self._emit(pending)

    def _emit(self, rows: Sequence[dict[str, Any]]) -> None:
        if not rows:
            return
        keys = self.keys or []
        if isinstance(rows, ColumnRows) and not rows.materialised and (self.fields or self.fmt in ("csv", "json")):
            for start in range(0, rows.size, SLICE):  # a slice at a time: the text of one slice in memory
                self._emit_columns(rows.slice(start, start + SLICE) if rows.size > SLICE else rows, keys)
            return
        rows = self._withheld(rows)
        if self.fields:
            self.stream.write("".join(field_line(row, self.fields) + "\n" for row in rows))
        elif self.fmt == "json":
            text = ",\n".join(json_row(row, keys) for row in rows)
            self.stream.write(("[\n" if not self.started else ",\n") + text)
            self.started = True
        elif self.fmt == "csv":
            import csv

            csv.writer(self.stream, lineterminator="\n").writerows(csv_cells(row, keys) for row in rows)
        else:
            self.table_rows.extend(rows)

    def _withheld(self, rows: Sequence[dict[str, Any]]) -> Sequence[dict[str, Any]]:
        """The rows with every NaN withheld (see :func:`withheld`)."""
        keys = list(self.fields) or self.keys or []
        if not any_unanswered(rows, keys):
            return rows
        # a table names these rows in its footer (render.table: a row with an error has no answer)
        return [withheld(row, keys) for row in rows]

    def _emit_columns(self, rows: ColumnRows, keys: list[str]) -> None:
        """Write rows held as columns: each column turned to text at once, then joined line by line."""
        count = rows.size
        errors = _withheld_columns(rows, list(self.fields) or keys)
        skipped = [i for i, message in enumerate(errors) if message is not None]

        def cells(key: str, style: str) -> list[str]:
            return texts(rows.columns.get(key), count, style, () if key in rows.kept else skipped)

        if self.fields:
            columns = [cells(key, "field") for key in self.fields]
            self.stream.write("\n".join(map("\t".join, zip(*columns))) + "\n")
        elif self.fmt == "csv":
            columns = [cells(key, "csv") for key in keys]
            self.stream.write("\n".join(map(",".join, zip(*columns))) + "\n")
        else:
            parts: list[Any] = []
            for index, key in enumerate(keys):
                parts.append(itertools.repeat(("{" if index == 0 else ", ") + _ENCODER.encode(key) + ": "))
                parts.append(cells(key, "json"))
            if not keys:
                parts.append(itertools.repeat("{"))
            if skipped:
                tail = ["}"] * count
                for index in skipped:
                    tail[index] = (", " if keys else "") + f"{_ENCODER.encode(ERROR)}: {_ENCODER.encode(errors[index])}}}"
                parts.append(tail)
            else:
                parts.append(itertools.repeat("}", count))
            text = ",\n".join(map("".join, zip(*parts)))
            self.stream.write(("[\n" if not self.started else ",\n") + text)
            self.started = True


def _withheld_columns(rows: ColumnRows, keys: Sequence[str]) -> list[str | None]:
    """Each row's error: its own, or one naming the computed keys that hold a NaN (the whole row is then withheld)."""
    errors: list[str | None] = list(rows.errors or [])
    bad: dict[int, list[str]] = {}
    for key in keys:
        values: Any = rows.columns.get(key)
        if key in rows.kept or getattr(values, "dtype", None) is None or values.dtype.kind != "f":
            continue
        import numpy as np

        for index in np.flatnonzero(np.isnan(np.broadcast_to(values, (rows.size,)))).tolist():
            bad.setdefault(index, []).append(key)
    if bad:
        errors = errors or [None] * rows.size
        for index, names in bad.items():
            note = f"no answer for {', '.join(names)} with these inputs"
            errors[index] = f"{errors[index]}; {note}" if errors[index] else note
    return errors


def write_rows(
    rows: Sequence[dict[str, Any]],
    columns: Sequence[Column],
    fmt: str = "table",
    units: str = "metric",
    footer: str = "",
    keys: Sequence[str] | None = None,
    stream: IO[str] | None = None,
) -> None:
    """Write ``rows`` as a table (``columns`` shown, ``footer`` below) or as JSON/CSV (``keys``, default the column keys).

    JSON and CSV carry every key in ``keys`` with raw values in the units the
    key names.
    """
    writer = RowWriter(fmt, units, stream=stream, errors=sys.stderr)
    keys = list(keys) if keys is not None else [c.key for c in columns]
    writer.write(rows, columns, keys, footer)
    writer.close()
