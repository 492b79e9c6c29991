"""What ``camtool fov`` shows: table columns and output keys."""

from __future__ import annotations

from typing import Any

from camtool.render.columns import ANGLE, NUMBER, SMALL, Column

KEYS = ["focal_length_mm", "horizontal_deg", "vertical_deg", "diagonal_deg", "equivalent_focal_length_mm",
        "crop_factor", "sensor_width_mm", "sensor_height_mm", "projection"]

DISTANCE_KEYS = ["distance_mm", "magnification", "field_width_mm", "field_height_mm", "distance_from"]

COLUMNS = [
    Column("focal_length_mm", "f", SMALL),
    Column("equivalent_focal_length_mm", "35mm eq.", SMALL),
    Column("horizontal_deg", "horizontal", ANGLE),
    Column("vertical_deg", "vertical", ANGLE),
    Column("diagonal_deg", "diagonal", ANGLE),
]

DISTANCE_COLUMNS = [
    Column("distance_mm", "distance"),
    Column("field_width_mm", "field width"),
    Column("field_height_mm", "field height"),
    Column("magnification", "m", NUMBER),
]


def fov_view(seen: Any, *, table: bool, squeeze: float | None, sensor: Any, lens_note: str,
             distance_from: str) -> tuple[list[Column], list[str], str]:
    """(columns, keys, footer) of an angle of view (:class:`camtool.plans.fov` answer ``seen``) on ``sensor``."""
    from camtool.render.views.common import footer

    keys, columns = list(KEYS) + ["squeeze"] * (squeeze is not None), list(COLUMNS)
    if seen.at_distance:
        keys += DISTANCE_KEYS
        columns += DISTANCE_COLUMNS
    if not table:
        return columns, keys, ""
    mapping = seen.values["projection"]
    extra = " · ".join(x for x in (lens_note, "" if mapping == "rectilinear" else f"{mapping} projection") if x)
    anamorphic = f" · {squeeze:g}× anamorphic: angles of the de-squeezed frame" if squeeze else ""
    return columns, keys, footer(None, None, "", f"{sensor.label} (crop {sensor.crop_factor:.3g}){anamorphic}",
                                 distance_from if seen.at_distance else None, extra)
