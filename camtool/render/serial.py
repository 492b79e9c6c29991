"""JSON and CSV output for scripts: raw numbers, snake_case keys with units, infinity as null.

One layout, however the rows come (options or ``--batch``), written row by
row so a long batch streams: JSON is an array with one row object per line::

    [
    {"focal_length_mm": 50.0, "f_number": 8.0, ...},
    {"focal_length_mm": 50.0, "f_number": 11.0, ...}
    ]

(``[]`` when there are no rows); CSV is a header of the keys and one line per
row, an infinite value an empty cell. A skipped ``--batch`` row keeps its
place: in JSON every computed key ``null`` plus an ``error`` key, in CSV a row
of empty cells, with ``--field`` empty values (passed-through input columns
keep their cells).
"""

from __future__ import annotations

import json
import math
from collections.abc import Iterable, Sequence
from typing import Any

from camtool.core.text import printable

Row = dict[str, Any]

ERROR = "error"
"""The key of a skipped row's message."""

_ENCODER = json.JSONEncoder(allow_nan=False, ensure_ascii=False)

def unanswered(row: Row, keys: Sequence[str]) -> list[str]:
    """The keys of ``row`` whose value is a NaN: a quantity with no answer, which must never be printed as one."""
    return [key for key in keys if isinstance(row.get(key), float) and row[key] != row[key]]


def any_unanswered(rows: Sequence[Row], keys: Sequence[str]) -> bool:
    """Whether any of ``rows`` has a key of ``keys`` :func:`unanswered` (one pass; the values are tested in C)."""
    from itertools import chain

    values: Iterable[Any] = chain.from_iterable(map(row.get, keys) for row in rows)
    return any(map(math.isnan, filter(float.__instancecheck__, values)))


def withheld(row: Row, keys: Sequence[str]) -> Row:
    """``row`` with every NaN replaced by null and the row's ``error`` naming them (the row keeps its place).

    The last line of defence behind every command: a value no formula could
    give is shown as missing, with the reason, never as a number or a crash.

    >>> withheld({"near_mm": float("nan"), "far_mm": 2.0}, ["near_mm", "far_mm"])
    {'near_mm': None, 'far_mm': 2.0, 'error': 'no answer for near_mm with these inputs'}
    """
    bad = unanswered(row, keys)
    if not bad:
        return row
    fixed = {**row, **dict.fromkeys(bad)}
    note = f"no answer for {', '.join(bad)} with these inputs"
    fixed[ERROR] = f"{row[ERROR]}; {note}" if row.get(ERROR) else note
    return fixed


def plain(value: Any) -> Any:
    """A JSON/CSV-ready value: floats stay raw, infinity becomes ``None``; NaN is a bug, not output."""
    if type(value) is float:
        if value - value == 0.0:  # finite: the common case, one comparison
            return value
        if math.isnan(value):
            raise ValueError("internal error: a NaN reached the output")
        return None if math.isinf(value) else value
    if isinstance(value, str):
        return printable(value)
    if isinstance(value, float):  # a numpy scalar
        return plain(float(value))
    return value


def json_row(row: Row, keys: Sequence[str]) -> str:
    """One row object on one line; a skipped row has every key null and its ``error``.

    >>> json_row({"a": 1.5, "b": float("inf")}, ["a", "b"])
    '{"a": 1.5, "b": null}'
    >>> json_row({ERROR: "row 2: bad"}, ["a"])
    '{"a": null, "error": "row 2: bad"}'
    """
    data = {key: plain(row.get(key)) for key in keys}
    if ERROR in row:
        data[ERROR] = printable(str(row[ERROR]))
    return _ENCODER.encode(data)


def csv_cells(row: Row, keys: Sequence[str]) -> list[Any]:
    """One CSV row's cells: raw values, empty for infinity, a missing key and a skipped row."""
    cells = []
    for key in keys:
        value = plain(row.get(key))
        cells.append("" if value is None else value)
    return cells


def field_line(row: Row, fields: Sequence[str]) -> str:
    """One line of ``--field`` output: the values, tab-separated, infinity as ``inf``.

    >>> field_line({"near_mm": 1234.5, "far_mm": float("inf")}, ["near_mm", "far_mm"])
    '1234.5\\tinf'
    """
    values = []
    for key in fields:
        value = row.get(key)
        values.append("" if value is None else repr(float(value)) if isinstance(value, float) else printable(str(value)))
    return "\t".join(values)
