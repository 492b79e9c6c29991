"""The close-up and diffraction columns and keys that ``dof``, ``focus`` and ``fov`` add."""

from __future__ import annotations

from collections.abc import Sequence
from typing import Any

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


def branch_note(rows: Sequence[dict[str, Any]], close_up: float) -> str:
    """Footer text naming the other magnification of a sensor-plane distance (rows at ``close_up`` or more)."""
    others = [(r["distance_mm"], r["other_magnification"]) for r in rows
              if r.get("other_magnification") is not None and r["magnification"] >= close_up
              and r["other_magnification"] > r["magnification"] * 1.0001]
    if not others:
        return ""
    shown = ", ".join(list(dict.fromkeys(f"{m:.3g}" for _, m in others))[:3])
    return f"the same distance is also reached at m = {shown} (give -m for that branch)"
