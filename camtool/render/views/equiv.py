"""What ``camtool equiv`` shows: table columns and output keys."""

from __future__ import annotations

from camtool.render.columns import NUMBER, SMALL, TEXT, Column

KEYS = ["focal_length_mm", "f_number", "iso", "equivalent_focal_length_mm", "equivalent_f_number",
        "equivalent_iso", "ratio", "aperture_diameter_mm", "light_stops", "converter"]

COLUMNS = [
    Column("given", "given", TEXT),
    Column("equivalent_focal_length_mm", "f", SMALL),
    Column("aperture", "N", TEXT),
    Column("equivalent_iso", "ISO", NUMBER),
    Column("aperture_diameter_mm", "aperture", SMALL),
    Column("light_stops", "light", NUMBER),
]
