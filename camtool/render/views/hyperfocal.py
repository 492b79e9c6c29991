"""What ``camtool hyperfocal`` shows: table columns and output keys."""

from __future__ import annotations

from camtool.render.columns import FNUMBER, SMALL, Column

KEYS = ["focal_length_mm", "f_number", "hyperfocal_mm", "near_mm", "coc_mm", "model", "distance_from"]

COLUMNS = [
    Column("focal_length_mm", "f", SMALL),
    Column("f_number", "N", FNUMBER),
    Column("hyperfocal_mm", "hyperfocal"),
    Column("near_mm", "sharp from"),
    Column("coc_mm", "CoC", SMALL),
]
