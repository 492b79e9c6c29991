"""What several commands show alike: the footer (model, CoC, sensor, distance plane) and the T-stop column."""

from __future__ import annotations

from collections.abc import Sequence
from typing import Any

from camtool.render.columnar import ColumnRows

T_STOP_COLUMN = "camtool.t_stop_column"  # ctx.meta: a --batch -N column holds T-stops (every row gets the keys)


def t_stop_columns(rows: Any, columns: Sequence[Any]) -> list[Any]:
    """The table's columns with a ``T`` column (``T2.8``, the T-stop typed) before the f-number's, which is then
    headed ``N used``: a typed T-stop is shown as a T-stop (the JSON keys are ``t_stop`` and ``f_number``)."""
    from camtool.render.columns import TEXT, Column

    if isinstance(rows, ColumnRows) and not rows.materialised:  # columns: the labels as one more column
        from camtool.render.columnar import values_of

        rows.columns["t_stop_label"] = [f"T{t:.3g}" if isinstance(t, float) else ""
                                        for t in values_of(rows.columns.get("t_stop"), rows.size)]
    else:
        for row in rows:
            t = row.get("t_stop")
            row["t_stop_label"] = f"T{t:.3g}" if isinstance(t, float) else ""
    found = [i for i, c in enumerate(columns) if c.key == "f_number"]
    if not found:
        return list(columns)
    at = found[0]
    return [*columns[:at], Column("t_stop_label", "T", TEXT), columns[at]._replace(header="N used"), *columns[at + 1:]]


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
