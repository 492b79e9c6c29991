"""Small helpers the command modules share: option values to numbers, results to rows."""

from __future__ import annotations

from collections.abc import Sequence
from typing import Any

import click

from camtool.cli.params import flatten
from camtool.cli.params import one_value as one_value  # the option callback, where the commands import it
from camtool.render.columnar import ColumnRows
from camtool.render.views.common import T_STOP_COLUMN, t_stop_columns


def single(ctx: click.Context, values: Any, option: str) -> Any:
    """The one value given to ``option`` (None when none), or a usage error naming it for several."""
    flat = [v for v in flatten(values) if v is not None] if isinstance(values, (list, tuple)) else [values]
    flat = [v for v in flat if v is not None]
    if len(flat) > 1:
        raise click.UsageError(f"Option '{option}' takes one value here.", ctx)
    return flat[0] if flat else None


def required(ctx: click.Context, values: Sequence[Any], option: str) -> list[Any]:
    """The flattened values of a repeatable list option, or a usage error naming it."""
    flat = flatten(values)
    if not flat:
        raise click.UsageError(f"Missing option '{option}'.", ctx)
    return flat


CHOICES = "camtool.f_number_choices"  # ctx.meta: the FNumberChoice of each typed aperture, for keys and footer


def f_numbers(values: Sequence[list[float]], exact: bool) -> list[float]:
    """f-numbers by :func:`camtool.plans.equipment.apertures` (a T-stop with the --lens preset's transmittance);
    the choices are kept in ``ctx.meta`` for :func:`t_stop_output`."""
    from camtool.cli.equipment import LENS
    from camtool.plans.equipment import apertures

    ctx = click.get_current_context()
    found = apertures(flatten(values), exact_stops=exact, lens=ctx.meta.get(LENS), t_stops=bool(ctx.meta.get(T_STOP_COLUMN)))
    if found.choices is not None:
        ctx.meta[CHOICES] = (found.choices, ctx.meta.get(LENS))
    return found.f_numbers


def t_stop_output(ctx: click.Context, out: Any) -> Any:
    """``out`` with the keys ``t_stop`` and ``f_number_from`` and a footer note, when a T-stop was typed."""
    from camtool.plans.equipment import t_stop_note, t_stop_rows

    found = ctx.meta.pop(CHOICES, None)
    if found is None:
        return out
    choices, lens = found
    rows = out.rows
    if isinstance(rows, ColumnRows) and not rows.materialised:  # a batch chunk or a grid: columns, no row dicts
        from camtool.render.columnar import values_of

        f_numbers = values_of(rows.columns.get("f_number"), rows.size)
        chosen = t_stop_rows(choices, row_f_numbers=[None if v is None else float(v) for v in f_numbers])
        if len(chosen) == rows.size:  # (no choice per row: a T-stop the plan solved stays as it is)
            rows.columns["t_stop"] = [choice.t_stop if choice is not None else None for choice in chosen]
            rows.columns["f_number_from"] = [choice.source if choice is not None else None for choice in chosen]
    else:
        for row, choice in zip(rows, t_stop_rows(choices, row_f_numbers=[row.get("f_number") for row in rows])):
            row["t_stop"] = choice.t_stop if choice is not None else None
            row["f_number_from"] = choice.source if choice is not None else None
    keys = [*out.keys, *(k for k in ("t_stop", "f_number_from") if k not in out.keys)]
    columns = t_stop_columns(rows, out.columns)
    if not out.footer:
        return type(out)(out.rows, columns, keys, out.footer)
    note = t_stop_note(choices, lens=lens)
    if note.transmittance is not None:
        text = (f"T-stops: f-number N = T·√τ, τ = {note.transmittance:.3g} from --lens {note.lens_id} "
                f"(f/{note.lens_f_number_min:g}, T{note.lens_t_number_min:g}; taken as constant when stopped down)")
    else:
        text = (f"T-stops stand in for the f-number (lens transmittance τ unknown): for τ 0.9–0.7 the f-number is "
                f"{note.below_low:.0%}–{note.below_high:.0%} below T, so N and the depth of field may be overstated "
                f"by up to {note.overstated_low:.0%}–{note.overstated_high:.0%}")
    return type(out)(out.rows, columns, keys, f"{out.footer} · {text}")


def rows_from(count: int, columns: dict[str, Any]) -> ColumnRows:
    """Rows from named result columns, each a float, a string or an array (dicts made only when read)."""
    return ColumnRows(count, columns)
