"""What ``camtool stack`` shows: table columns and output keys."""

from __future__ import annotations

from typing import Any

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


def bracket_note(plan: Any, near: float, far: float, overlap: float, units: str, where: str) -> str:
    """A focus bracket's footer: frames, range (in ``units``), criterion, model, overlap, then ``where``."""
    from camtool.render.numfmt import length

    what = f"{plan.criterion} depth" + (" (λ/NA², as a CoC of 2λN)" if plan.criterion == "wave" else "")
    if plan.focal_range_mm is not None:
        what += f" · the lens focuses internally: f {plan.focal_range_mm[0]:.4g} to {plan.focal_range_mm[1]:.4g} mm"
    return (f"{len(plan.frames)} frames · {length(near, units)} to {length(far, units)} · {what} · "
            f"{plan.model} model · overlap {overlap:g} · {where}")


def rail_note(rail: Any, coc_origin: str, units: str) -> str:
    """A rail plan's footer: frames, step (in ``units``), total and frame depth, criterion, overlap."""
    import math

    from camtool.render.numfmt import length

    plan, depth = rail.plan, rail.depth_mm
    frame_depth = plan.front_mm + plan.rear_mm
    what = (f"{rail.criterion} depth " + ("λ/NA²" if rail.criterion == "wave"
                                             else f"(CoC {rail.coc_mm:.3g} mm, {coc_origin})"))
    if math.isinf(plan.rear_mm):
        return (f"1 frame · sharp from {length(plan.front_mm, units, False)} in front of its focus to infinity "
                f"behind it (the subject at {rail.magnification:g}× is at or beyond the hyperfocal distance): it "
                f"covers any depth · total depth {length(depth, units, False)} · {what} · positions along the "
                "subject from its nearest point")
    return (f"{plan.frames} frames · step {length(plan.step_mm, units, False)} at the subject "
            f"({length(plan.extension_step_mm, units, False)} of lens extension) · total depth "
            f"{length(depth, units, False)} · {what} · frame depth {length(frame_depth, units, False)}, "
            f"overlap {rail.overlap:g} · positions along the subject from its nearest point")
