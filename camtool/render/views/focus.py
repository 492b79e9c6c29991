"""What ``camtool focus`` shows: table columns and output keys."""

from __future__ import annotations

from collections.abc import Sequence
from typing import Any

from camtool.render.columns import FNUMBER, NUMBER, SMALL, Column

FORWARD_KEYS = ["focal_length_mm", "distance_mm", "image_distance_mm", "extension_mm", "magnification",
                "f_number", "working_f_number", "closest_focus_mm", "distance_from", "other_magnification",
                "focal_length_at_focus_mm"]

FORWARD_COLUMNS = [
    Column("focal_length_mm", "f", SMALL),
    Column("distance_mm", "focus"),
    Column("image_distance_mm", "image dist.", SMALL),
    Column("extension_mm", "extension", SMALL),
    Column("magnification", "m", NUMBER),
    Column("working_f_number", "working N", FNUMBER),
]

INVERSE_KEYS = ["focal_length_mm", "near_mm", "far_mm", "distance_mm", "f_number", "coc_mm", "distance_from"]

FIXED_KEYS = ["wanted_near_mm", "wanted_far_mm", "needed_f_number"]

OPTIMUM_KEYS = ["focal_length_mm", "near_mm", "far_mm", "distance_mm", "magnification", "focus_spread_mm",
                "f_number", "working_f_number", "blur_mm", "blur_sum_mm", "distance_from"]

OPTIMUM_COLUMNS = [
    Column("focal_length_mm", "f", SMALL),
    Column("near_mm", "near"),
    Column("far_mm", "far"),
    Column("distance_mm", "focus at"),
    Column("magnification", "m", NUMBER),
    Column("focus_spread_mm", "spread", SMALL),
    Column("f_number", "optimum N", FNUMBER),
    Column("working_f_number", "working N", FNUMBER),
    Column("blur_mm", "blur", SMALL),
]

DEPTH_KEYS = ["magnification", "depth_mm", "f_number", "coc_mm", "working_f_number"]

DEPTH_COLUMNS = [
    Column("magnification", "m", NUMBER),
    Column("depth_mm", "depth"),
    Column("f_number", "N", FNUMBER),
    Column("coc_mm", "CoC", SMALL),
    Column("working_f_number", "working N", FNUMBER),
]

INVERSE_COLUMNS = [
    Column("focal_length_mm", "f", SMALL),
    Column("near_mm", "near"),
    Column("far_mm", "far"),
    Column("distance_mm", "focus at"),
    Column("f_number", "N", FNUMBER),
]

CONTRAST_KEYS = ["focal_length_mm", "near_mm", "far_mm", "distance_mm", "magnification", "f_number",
                 "working_f_number", "mtf", "frequency_lpmm", "defocus_waves", "mtf_level", "distance_from", "model",
                 "wavelength_nm"]

CONTRAST_COLUMNS = [*OPTIMUM_COLUMNS[:5], OPTIMUM_COLUMNS[6], OPTIMUM_COLUMNS[7], Column("mtf", "MTF", NUMBER),
                    Column("frequency_lpmm", "at lp/mm", NUMBER)]


def hansma_note(wavelength_nm: float) -> str:
    """The footer's words for the optimum aperture by Hansma's rule."""
    return f"optimum aperture (Hansma): defocus = diffraction at {wavelength_nm:g} nm; blur: root-sum-square"


def forward_view(found: Any, rows: Sequence[dict[str, Any]], *, f_number_given: bool, table: bool, close_up: float,
                 extension: float, teleconverter: float, lens_note: str,
                 distance_from: str) -> tuple[list[Column], list[str], str]:
    """(columns, keys, footer) of forward focusing, from a :class:`camtool.plans.focus.Forward` answer."""
    from camtool.render.views.closeup import FOCUS_COLUMN, branch_note
    from camtool.render.views.common import footer

    keys, columns = list(FORWARD_KEYS), list(FORWARD_COLUMNS)
    if found.focus_column:
        columns.insert(1, FOCUS_COLUMN)
    if not f_number_given:
        keys = [k for k in keys if k not in ("f_number", "working_f_number")]
        columns = [c for c in columns if c.key != "working_f_number"]
    if not table:
        return columns, keys, ""
    branch = branch_note(rows, close_up)
    how = "unit focusing, m = v/u" if not found.planned else " · ".join(x for x in (
        "internal focus (docs/closeup.md)" if found.internal_focus else "unit focusing",
        f"extension {extension:g} mm" if extension else "", f"teleconverter ×{teleconverter:g}" if teleconverter else "",
        "-s is the lens's own focus setting; focus is where the subject then is" if found.lens_focus_setting else "",
        branch) if x)
    note = footer("thick" if lens_note else "thin", None, "", how, distance_from, lens_note)
    return columns, keys, note if found.planned else " · ".join(part for part in (note, branch) if part)
