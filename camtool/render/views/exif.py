"""What ``camtool exif`` shows: table columns and output keys."""

from __future__ import annotations

from camtool.render.columns import ANGLE, FNUMBER, NUMBER, SMALL, TEXT, Column

COLUMNS = [Column("file", "file", TEXT), Column("focal_length_mm", "f", SMALL), Column("f_number", "N", FNUMBER),
           Column("focus_distance_mm", "focus"), Column("near_mm", "near"), Column("far_mm", "far"),
           Column("total_mm", "depth"), Column("hyperfocal_mm", "H"), Column("horizontal_deg", "h. angle", ANGLE),
           Column("ev100", "EV100", NUMBER)]
