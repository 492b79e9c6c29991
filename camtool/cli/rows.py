"""What a command hands to the writers: its rows, and the ``--field`` selection of them."""

from __future__ import annotations

from collections.abc import Sequence
from typing import Any, NamedTuple

import click

from camtool.render.columns import Column

ZIP = "camtool.zip"
"""The ``ctx.meta`` key that says the list options come zipped, row by row, from a batch file."""


class Output(NamedTuple):
    """What a command computed: rows of raw values, table columns, JSON/CSV keys, table footer."""

    rows: list[dict[str, Any]]
    columns: Sequence[Column]
    keys: Sequence[str]
    footer: str = ""


def check_fields(fields: Sequence[str], keys: Sequence[str]) -> None:
    """A usage error unless every ``--field`` names a key of this command's output."""
    unknown = [f for f in fields if f not in keys]
    if unknown:
        raise click.BadParameter(f"{unknown[0]!r} is not a key of this output; valid: {', '.join(keys)}",
                                 param_hint="'--field'")


def field_line(row: dict[str, Any], fields: Sequence[str]) -> str:
    """One line of ``--field`` output: the values, tab-separated, infinity as ``inf``."""
    values = []
    for key in fields:
        value = row.get(key)
        values.append("" if value is None else repr(value) if isinstance(value, float) else str(value))
    return "\t".join(values)
