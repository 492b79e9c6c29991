"""JSON and CSV output for scripts: raw numbers, snake_case keys with units, infinity as null."""

from __future__ import annotations

import csv
import json
import math
from collections.abc import Sequence
from typing import IO, Any

Row = dict[str, Any]


def plain(value: Any) -> Any:
    """A JSON/CSV-ready value: floats stay raw, infinity becomes ``None``; NaN is a bug, not output."""
    if type(value) is float:
        if value - value == 0.0:  # finite: the common case, one comparison
            return value
        if math.isnan(value):
            raise ValueError("internal error: a NaN reached the output")
        return None if math.isinf(value) else value
    return value


def write_json(rows: Sequence[Row], keys: Sequence[str], stream: IO[str]) -> None:
    """Write ``rows`` as a JSON array of objects holding ``keys`` (an infinite value is null)."""
    data = [{key: plain(row.get(key)) for key in keys} for row in rows]
    stream.write(json.dumps(data, allow_nan=False, ensure_ascii=False, indent=2))
    stream.write("\n")


def write_csv(rows: Sequence[Row], keys: Sequence[str], stream: IO[str]) -> None:
    """Write ``rows`` as CSV with a header of ``keys`` (an infinite value is an empty cell)."""
    writer = csv.writer(stream, lineterminator="\n")
    writer.writerow(keys)
    for row in rows:
        writer.writerow(["" if plain(row.get(k)) is None else plain(row.get(k)) for k in keys])
