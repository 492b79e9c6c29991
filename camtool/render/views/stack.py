"""What ``camtool stack`` shows: table columns and output keys."""

from __future__ import annotations

from camtool.render.columns import NUMBER, TEXT, Column

KEYS = ["frame", "distance_mm", "near_mm", "far_mm", "magnification", "step_mm", "extension_step_mm",
        "criterion", "mode", "distance_from"]

COLUMNS = [
    Column("frame", "frame", TEXT),
    Column("distance_mm", "focus"),
    Column("near_mm", "near"),
    Column("far_mm", "far"),
    Column("magnification", "m", NUMBER),
    Column("step_mm", "step"),
]
