"""What ``camtool compose`` shows: table columns and output keys."""

from __future__ import annotations

from camtool.render.columns import ANGLE, FNUMBER, NUMBER, SMALL, Column

KEYS = ["focal_length_mm", "f_number", "distance_mm", "magnification", "horizontal_deg", "vertical_deg",
        "field_width_mm", "field_height_mm", "near_mm", "far_mm", "coc_mm", "background_mm", "background_scale",
        "background_width_mm", "background_blur_mm", "background_blur_pct", "foreground_mm", "foreground_scale",
        "foreground_width_mm", "foreground_blur_mm", "foreground_blur_pct", "distance_from"]

COLUMNS = [
    Column("focal_length_mm", "f", SMALL),
    Column("distance_mm", "distance"),
    Column("magnification", "m", NUMBER),
    Column("horizontal_deg", "horizontal", ANGLE),
    Column("vertical_deg", "vertical", ANGLE),
    Column("field_width_mm", "field width"),
    Column("field_height_mm", "field height"),
]

APERTURE_COLUMNS = [Column("f_number", "N", FNUMBER), Column("near_mm", "near"), Column("far_mm", "far")]
