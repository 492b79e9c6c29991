"""What ``camtool flash`` shows: table columns and output keys."""

from __future__ import annotations

from camtool.render.columns import TEXT, Column

KEYS = ["guide_number_m", "guide_number_at_iso_m", "distance_mm", "f_number", "iso", "solved"]

COLUMNS = [
    Column("gn", "GN (ISO 100)", TEXT),
    Column("gn_iso", "GN at ISO", TEXT),
    Column("distance", "distance", TEXT),
    Column("aperture", "N", TEXT),
    Column("iso_text", "ISO", TEXT),
]
