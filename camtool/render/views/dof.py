"""What ``camtool dof`` shows: table columns and output keys."""

from __future__ import annotations

from camtool.render.columns import FNUMBER, SMALL, TEXT, Column

KEYS = ["focal_length_mm", "f_number", "distance_mm", "near_mm", "far_mm", "total_mm", "front_mm", "rear_mm",
        "hyperfocal_mm", "coc_mm", "magnification", "model", "error_estimate", "distance_from"]

FAR_KEYS = [*KEYS, "difference_pct", "time_per_evaluation_s"]
"""``--model all`` away from close-up: what every rung computes (no close-up or diffraction columns to leave null)."""

COLUMNS = [
    Column("focal_length_mm", "f", SMALL),
    Column("f_number", "N", FNUMBER),
    Column("distance_mm", "focus"),
    Column("near_mm", "near"),
    Column("far_mm", "far"),
    Column("total_mm", "depth"),
    Column("front_mm", "front"),
    Column("rear_mm", "rear"),
    Column("hyperfocal_mm", "H"),
    Column("sharp_zone", "sharp zone", TEXT, legend="┃ focus, H hyperfocal, ▶ ∞"),
]

ALL_COLUMNS = [
    Column("model", "model", TEXT),
    Column("focal_length_mm", "f", SMALL),
    Column("f_number", "N", FNUMBER),
    Column("distance_mm", "focus"),
    Column("near_mm", "near"),
    Column("far_mm", "far"),
    Column("total_mm", "depth"),
    Column("difference_shown", "difference", TEXT),
    Column("estimate_shown", "est. error", TEXT),
    Column("time_shown", "time/eval", TEXT),
]

ANAMORPHIC_COLUMNS = [Column("near_horizontal_mm", "near horiz."), Column("far_horizontal_mm", "far horiz.")]
