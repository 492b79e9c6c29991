"""The close-up and diffraction columns and keys that ``dof``, ``focus`` and ``fov`` add."""

from __future__ import annotations

from camtool.render.columns import FNUMBER, NUMBER, SMALL, Column

CLOSEUP_KEYS = ["working_f_number", "other_magnification", "focal_length_at_focus_mm"]

DIFFRACTION_KEYS = ["airy_mm", "diffraction_limit_f_number", "wave_dof_mm", "depth_dominated_by", "reason"]

CLOSEUP_COLUMNS = [Column("magnification", "m", NUMBER), Column("working_f_number", "working N", FNUMBER)]

FOCUS_COLUMN = Column("focal_length_at_focus_mm", "f at focus", SMALL)

DIFFRACTION_COLUMNS = [
    Column("airy_mm", "Airy", SMALL),
    Column("diffraction_limit_f_number", "diffr. limit", FNUMBER),
    Column("wave_dof_mm", "wave depth"),
]
