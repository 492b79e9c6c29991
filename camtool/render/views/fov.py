"""What ``camtool fov`` shows: table columns and output keys."""

from __future__ import annotations

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
