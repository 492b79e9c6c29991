"""What ``camtool dof`` shows: table columns and output keys."""

from __future__ import annotations

from typing import Any

from camtool.render.columns import FNUMBER, SMALL, TEXT, Column
from camtool.render.views.closeup import branch_note

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
    *COLUMNS[:6],  # f, N, focus, near, far, depth
    Column("difference_shown", "difference", TEXT),
    Column("estimate_shown", "est. error", TEXT),
    Column("time_shown", "time/eval", TEXT),
]

ANAMORPHIC_COLUMNS = [Column("near_horizontal_mm", "near horiz."), Column("far_horizontal_mm", "far horiz.")]


def dof_view(table: Any, rows: Any, *, model: str, anamorphic_keys: list[str], diffraction: bool, where: str,
             table_shown: bool, close_up: float) -> tuple[list[Column], list[str], str]:
    """(columns, keys, footer) of a depth-of-field table (a :class:`camtool.plans.dof.DofTable` answer).

    ``anamorphic_keys`` are those an anamorphic lens's rows carry (none for a spherical lens).
    """
    from camtool.render.views.closeup import CLOSEUP_COLUMNS, CLOSEUP_KEYS, DIFFRACTION_COLUMNS, DIFFRACTION_KEYS, FOCUS_COLUMN

    closeup = table.path == "closeup"
    if model == "all":
        columns = list(ALL_COLUMNS)
        if closeup:
            columns[4:4] = CLOSEUP_COLUMNS  # after the focus: m and the working f-number
            if table.focus_column:
                columns[2:2] = [FOCUS_COLUMN]
        note = comparison_note(rows, table.reference_model, ", focus planning included" if closeup else "", where)
        return columns, [*FAR_KEYS, *CLOSEUP_KEYS, *DIFFRACTION_KEYS] if closeup else FAR_KEYS, \
            note if table_shown else ""
    keys = [*KEYS, *CLOSEUP_KEYS, *(DIFFRACTION_KEYS if closeup and diffraction else []),
            *anamorphic_keys]
    columns = list(COLUMNS) + (ANAMORPHIC_COLUMNS if anamorphic_keys else [])
    if table.close:
        columns[3:3] = CLOSEUP_COLUMNS
    if table.focus_column:
        columns[1:1] = [FOCUS_COLUMN]
    if closeup and diffraction:
        columns[-1:-1] = DIFFRACTION_COLUMNS
    return columns, keys, dof_footer(table, rows, where, close_up) if table_shown else ""


def dof_footer(table: Any, rows: Any, where: str, close_up: float) -> str:
    """The sharp-zone bars and the footer: the models used, their worst estimate, the facts of the rows."""
    from camtool.render.bar import axis_range, sharp_zone_bar

    answered = [r for r in rows if r["near_mm"] is not None]
    low, high = axis_range([v for r in answered for v in (r["near_mm"], r["far_mm"], r["hyperfocal_mm"])])
    for row in rows:
        row["sharp_zone"] = (sharp_zone_bar(row["near_mm"], row["distance_mm"], row["far_mm"], row["hyperfocal_mm"],
                                            low, high, width=24) if row["near_mm"] is not None else row["reason"])
    # The estimate is of what the model leaves out of the lens data given; 0 (nothing left out) is not shown.
    worst = max(row["error_estimate"] for row in answered)
    used = " / ".join(dict.fromkeys(row["model"] for row in answered))
    label = (f"{used} model" + (f" (est. error ≤ {_percent(worst)})" if worst > 0 else "")
             + (f"; H by the {table.hyperfocal_model} model" if table.hyperfocal_model else ""))
    closeup = table.path == "closeup"
    extra = " · ".join(part for part in (
        branch_note(rows, close_up) if (table.close and not closeup) or (closeup and not table.by_magnification) else "",
        "-s is the lens's own focus setting; focus is where the subject then is" if table.lens_focus_setting else "",
        _dominance(table.dominated_by) if table.dominated_by else "") if part)
    return label + " · " + where + (" · " + extra if extra else "")


def _dominance(kinds: frozenset[str]) -> str:
    if kinds == {"wave"}:
        return "wave-optics depth λ/NA² exceeds the geometric depth"
    if kinds == {"geometric"}:
        return "geometric depth exceeds the wave-optics depth λ/NA²"
    return "depth dominated by the wave-optics or geometric term, row by row"


def _percent(fraction: float | None) -> str:
    if fraction is None:  # a row with no depth of field (diffraction fills the CoC): no estimate either
        return "—"
    return f"{fraction:.2%}".replace("%", " %") if fraction >= 1e-4 else "0.01 %" if fraction > 0 else "0 %"


def comparison_note(rows: list[dict[str, Any]], most: str, timed: str, where: str) -> str:
    """Fill the shown columns of ``--model all`` rows and return the table's footer."""
    for row in rows:
        row["difference_shown"] = "—" if row["difference_pct"] is None else f"{row['difference_pct']:.3g} %"
        row["estimate_shown"] = _percent(row["error_estimate"])
        row["time_shown"] = _duration(row["time_per_evaluation_s"])
    return f"difference from {most}, the most complete model; time per evaluation{timed} · " + where


def _duration(seconds: float) -> str:
    if seconds >= 1e-3:
        return f"{seconds * 1e3:.3g} ms"
    return f"{seconds * 1e6:.3g} µs"
