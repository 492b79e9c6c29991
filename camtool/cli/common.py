"""Small helpers the command modules share: option values to numbers, results to rows."""

from __future__ import annotations

from collections.abc import Sequence
from typing import Any

import click

from camtool.cli.params import flatten
from camtool.cli.params import one_value as one_value  # the option callback, where the commands import it
from camtool.core.units import TStop, exact_f_number
from camtool.render.columnar import ColumnRows


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
T_STOP_COLUMN = "camtool.t_stop_column"  # ctx.meta: a --batch -N column holds T-stops (every row gets the keys)


def f_numbers(values: Sequence[list[float]], exact: bool) -> list[float]:
    """f-numbers as typed (or mapped to exact stops with ``--exact-stops``); a T-stop becomes its f-number.

    A T-stop (``-N T2``) gives N = T·√τ with the transmittance of the --lens
    preset when it has both its widest f-number and T-stop, else the T-stop
    stands in for the f-number (:func:`camtool.exposure.ev.resolve_f_number`).
    The choices are kept in ``ctx.meta`` for the output's keys and footer.
    """
    flat = flatten(values)
    if exact:
        flat = [TStop(exact_f_number(n)) if isinstance(n, TStop) else exact_f_number(n) for n in flat]
    ctx = click.get_current_context()
    if not any(isinstance(n, TStop) for n in flat) and not ctx.meta.get(T_STOP_COLUMN):
        return flat
    from camtool.cli.equipment import LENS
    from camtool.exposure.ev import resolve_f_number

    lens = ctx.meta.get(LENS)
    transmittance = lens.transmittance if lens is not None else None
    choices = [resolve_f_number(n, isinstance(n, TStop), transmittance) for n in flat]
    ctx.meta[CHOICES] = (choices, lens)
    return [c.f_number for c in choices]


def t_stop_output(ctx: click.Context, out: Any) -> Any:
    """``out`` with the keys ``t_stop`` and ``f_number_from`` and a footer note, when a T-stop was typed."""
    found = ctx.meta.pop(CHOICES, None)
    if found is None:
        return out
    choices, lens = found
    by_n = {round(c.f_number, 9): c for c in choices}
    shown = list(dict.fromkeys(round(float(row.get("f_number") or 0.0), 9) for row in out.rows))
    if not set(shown) <= set(by_n) and len(shown) == len(choices):
        by_n = dict(zip(shown, choices))  # f-numbers scaled by the command (a teleconverter's k·N), in order
    for row in out.rows:
        n = row.get("f_number")
        choice = by_n.get(round(float(n), 9)) if isinstance(n, (int, float)) else None
        if choice is None and len(by_n) == 1:
            choice = choices[0]
        row["t_stop"] = choice.t_stop if choice is not None else None
        row["f_number_from"] = choice.source if choice is not None else None
    keys = [*out.keys, *(k for k in ("t_stop", "f_number_from") if k not in out.keys)]
    return type(out)(out.rows, out.columns, keys, _t_stop_note(out.footer, choices, lens))


def _t_stop_note(text: str, choices: Sequence[Any], lens: Any) -> str:
    """The table footer with how the f-number was found for the T-stops typed."""
    if not text:
        return text
    from camtool.exposure.ev import T_STOP_ERROR_HIGH, T_STOP_ERROR_LOW

    sources = {c.source for c in choices}
    if "transmittance" in sources:
        tau = next(c.transmittance for c in choices if c.transmittance is not None)
        note = (f"T-stops: f-number N = T·√τ, τ = {tau:.3g} from --lens {lens.id} (f/{lens.f_number_min:g}, "
                f"T{lens.t_number_min:g}; taken as constant when stopped down)")
    else:
        over_low, over_high = 1 / (1 - T_STOP_ERROR_LOW) - 1, 1 / (1 - T_STOP_ERROR_HIGH) - 1
        note = (f"T-stops stand in for the f-number (lens transmittance τ unknown): for τ 0.9–0.7 the f-number "
                f"is {T_STOP_ERROR_LOW:.0%}–{T_STOP_ERROR_HIGH:.0%} below T, so N and the depth of field may be "
                f"overstated by up to {over_low:.0%}–{over_high:.0%}")
    return f"{text} · {note}"


def rows_from(count: int, columns: dict[str, Any]) -> ColumnRows:
    """Rows from named result columns, each a float, a string or an array (dicts made only when read)."""
    return ColumnRows(count, columns)


def plane_note(distance_from: str) -> str:
    """Footer text naming the distance plane."""
    return "from the sensor plane" if distance_from == "sensor" else "from the lens"


def footer(model: str | None, cocs: Sequence[float] | None, coc_origin: str, sensor_label: str,
           distance_from: str | None, extra: str = "") -> str:
    """The one-line table footer: model, CoC and its origin, sensor, distance plane."""
    parts = [f"{model} model"] if model else []
    if cocs:
        parts.append(f"CoC {', '.join(f'{v:.3g}' for v in cocs)} mm ({coc_origin})")
    parts.append(sensor_label)
    if distance_from:
        parts.append(plane_note(distance_from))
    if extra:
        parts.append(extra)
    return " · ".join(parts)
