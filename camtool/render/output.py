"""The one renderer every command hands its rows to."""

from __future__ import annotations

import sys
from collections.abc import Sequence
from typing import IO, Any

from camtool.render.columns import Column

FORMATS = ("table", "json", "csv")


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
    key names; rich is imported only for tables.
    """
    stream = stream or sys.stdout
    keys = list(keys) if keys is not None else [c.key for c in columns]
    if fmt == "json":
        from camtool.render.serial import write_json

        write_json(rows, keys, stream)
    elif fmt == "csv":
        from camtool.render.serial import write_csv

        write_csv(rows, keys, stream)
    else:
        from camtool.render.table import write_table

        write_table(rows, columns, stream, units=units, footer=footer)
