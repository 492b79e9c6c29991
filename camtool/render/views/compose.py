"""What ``camtool compose`` shows: table columns and output keys."""

from __future__ import annotations

from collections.abc import Sequence

from camtool.render.columns import ANGLE, FNUMBER, NUMBER, SMALL, Column

KEYS = ["focal_length_mm", "f_number", "distance_mm", "magnification", "horizontal_deg", "vertical_deg",
        "field_width_mm", "field_height_mm", "near_mm", "far_mm", "coc_mm", "background_mm", "background_scale",
        "background_width_mm", "background_blur_mm", "background_blur_pct", "foreground_mm", "foreground_scale",
        "foreground_width_mm", "foreground_blur_mm", "foreground_blur_pct", "distance_from"]

COLUMNS = [
    Column("focal_length_mm", "f", SMALL),
    Column("distance_mm", "distance"),
    Column("magnification", "m", NUMBER),
    Column("horizontal_deg", "horizontal", ANGLE),
    Column("vertical_deg", "vertical", ANGLE),
    Column("field_width_mm", "field width"),
    Column("field_height_mm", "field height"),
]

APERTURE_COLUMNS = [Column("f_number", "N", FNUMBER), Column("near_mm", "near"), Column("far_mm", "far")]


def _plane_columns(name: str, short: str) -> list[Column]:
    return [
        Column(f"{name}_scale", f"{short} scale", NUMBER),
        Column(f"{name}_width_mm", f"{short} width"),
        Column(f"{name}_blur_mm", f"{short} blur", SMALL),
        Column(f"{name}_blur_pct", f"{short} blur %", NUMBER),
    ]


def compose_view(*, apertures: bool, background: bool, foreground: bool, table: bool, magnifications: Sequence[float],
                 subject_size_mm: float | None, fill: float | None, fill_axis: str, reference_mm: float,
                 cocs: Sequence[float] | None, coc_origin: str, sensor_label: str, distance_from: str,
                 squeeze: float | None, projection: str = "rectilinear") -> tuple[list[Column], str]:
    """(columns, footer) of a composition: the planes asked for, the subject, the scale's reference, the CoC."""
    from camtool.render.views.common import footer

    shown = list(COLUMNS) + (APERTURE_COLUMNS if apertures else [])
    shown += _plane_columns("background", "bg") if background else []
    shown += _plane_columns("foreground", "fg") if foreground else []
    if not table:
        return shown, ""
    subject = (f"m = {', '.join(f'{v:.4g}' for v in magnifications)}" if magnifications
               else f"subject {(subject_size_mm or 0.0) / 1000:g} m fills {fill:g} of the {fill_axis}")
    scale = f"scale vs {reference_mm:g} mm" if background or foreground else ""
    anamorphic = f"{squeeze:g}× anamorphic: widths de-squeezed, blur discs vertical" if squeeze else ""
    mapping = f"{projection} projection: m and blur at the centre" if projection != "rectilinear" else ""
    return shown, footer("thin" if apertures else None, cocs, coc_origin, sensor_label, distance_from,
                         " · ".join(part for part in (subject, scale, anamorphic, mapping) if part))
