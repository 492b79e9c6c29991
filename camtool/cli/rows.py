"""What a command hands to the writers: its rows, and the ``--field`` selection of them."""

from __future__ import annotations

import sys
from collections.abc import Sequence
from typing import Any, NamedTuple

import click

from camtool.render.columns import Column
from camtool.render.output import RowWriter
from camtool.render.serial import field_line
from camtool.render.views.rows import DYNAMIC_KEYS

__all__ = ["CELLS", "DYNAMIC_KEYS", "ZIP", "Output", "check_fields", "field_line", "open_writer"]

ZIP = "camtool.zip"
CELLS = "camtool.batch_cells"  # ctx.meta: the options a --batch row gave in cells (typed, as options are)
"""The ``ctx.meta`` key that says the list options come zipped, row by row, from a batch file."""


class Output(NamedTuple):
    """What a command computed: rows of raw values, table columns, JSON/CSV keys, table footer."""

    rows: Sequence[dict[str, Any]]
    columns: Sequence[Column]
    keys: Sequence[str]
    footer: str = ""
    plan: Any = None
    """The plan's result the output was drawn from, for :attr:`redraw`."""
    redraw: Any = None
    """``redraw(merged, plans)``: the output of several combinations' plans at once (a short grid's table,
    computed a combination at a time), drawn from the plan ``merged`` of them, or None when they cannot be
    merged; None here: the table is computed vectorised."""



def check_fields(fields: Sequence[str], keys: Sequence[str]) -> None:
    """A usage error unless every ``--field`` names a key of this command's output."""
    unknown = [f for f in fields if f not in keys]
    if unknown:
        raise click.BadParameter(f"{unknown[0]!r} is not a key of this output; valid: {', '.join(keys)}",
                                 param_hint="'--field'")


def open_writer(fmt: str, units: str, fields: Sequence[str] = ()) -> RowWriter:
    """The one writer for a command's output (single run or batch); ``--field`` is checked against its keys."""

    def check(keys: Sequence[str]) -> None:
        if fields:
            check_fields(fields, keys)

    return RowWriter(fmt, units, fields, stream=sys.stdout, errors=sys.stderr, on_keys=check)
