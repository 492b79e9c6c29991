"""What ``camtool stars`` shows: table columns and output keys."""

from __future__ import annotations

from camtool.render.columns import NUMBER, SMALL, TEXT, Column

KEYS = ["focal_length_mm", "f_number", "crop_factor", "pixel_pitch_um", "declination_deg", "rule500_s",
        "npf_simple_s", "npf_s"]

COLUMNS = [
    Column("focal_length_mm", "f", SMALL),
    Column("aperture", "N", TEXT),
    Column("declination_deg", "δ (°)", NUMBER),
    Column("rule500", "500 rule", TEXT),
    Column("npf_simple", "NPF simple", TEXT),
    Column("npf", "NPF", TEXT),
]
