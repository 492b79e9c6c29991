"""What a command hands to the writers: its rows, and the ``--field`` selection of them."""

from __future__ import annotations

import sys
from collections.abc import Sequence
from typing import Any

import click

from camtool.core.record import NamedTuple
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
    """``redraw(outputs)``: one output of the outputs of a short grid's combinations, each computed on its own
    (a table is drawn from every row at once), or None when they cannot make one; None here: a table of a grid
    is computed vectorised. :func:`joined` for a command whose columns and footer depend on its options alone."""


def joined(outputs: Sequence[Output]) -> Output | None:
    """The rows of ``outputs`` under their columns, keys and footer, when every output has the same ones."""
    first = outputs[0]
    if any((out.columns, out.keys, out.footer) != (first.columns, first.keys, first.footer) for out in outputs):
        return None
    return first._replace(rows=[row for out in outputs for row in out.rows])



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
