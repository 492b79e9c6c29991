"""Small helpers the command modules share: option values to numbers, results to rows."""

from __future__ import annotations

from collections.abc import Sequence
from typing import Any

import click

from camtool.cli.params import flatten
from camtool.core.units import exact_f_number
from camtool.render.columnar import ColumnRows


def required(ctx: click.Context, values: Sequence[Any], option: str) -> list[Any]:
    """The flattened values of a repeatable list option, or a usage error naming it."""
    flat = flatten(values)
    if not flat:
        raise click.UsageError(f"Missing option '{option}'.", ctx)
    return flat


def f_numbers(values: Sequence[list[float]], exact: bool) -> list[float]:
    """f-numbers as typed, or mapped to exact stops with ``--exact-stops``."""
    flat = flatten(values)
    return [exact_f_number(n) for n in flat] if exact else flat


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
