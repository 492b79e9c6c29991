"""The one line a listing shows for a preset: its size, focal lengths, surfaces or model.

It is part of the preset model, not of a command, because the shipped
presets' lines are written once, by the package's build, beside their records
(:mod:`camtool.presets.shipped`), and a listing of the shipped presets alone
reads them from there instead of building every preset.
"""

from __future__ import annotations

from typing import Any

__all__ = ["summary"]


def summary(preset: Any) -> str:
    """One line describing a preset, e.g. '36 × 24 mm' or '24–70 mm f/4–22'.

    >>> from camtool.presets import Sensor
    >>> summary(Sensor("full-frame", "Full frame", 36.0, 24.0))
    '36 × 24 mm'
    """
    kind = type(preset).__name__.lower()
    if kind == "sensor":
        return f"{preset.width_mm:g} × {preset.height_mm:g} mm" + (" (approximate)" if preset.approximate else "")
    if kind == "camera":
        pixels = f", {preset.pixels_w} × {preset.pixels_h} px" if preset.pixels_w else ""
        return f"{preset.sensor.id} {preset.sensor.width_mm:g} × {preset.sensor.height_mm:g} mm{pixels}"
    if kind == "lens":
        focal = (f"{preset.focal_min_mm:g}–{preset.focal_max_mm:g} mm" if preset.is_zoom
                 else f"{preset.focal_min_mm:g} mm")
        if preset.members:
            return "set: " + ", ".join(f"{m.focal_min_mm:g}" for m in preset.members) + " mm"
        stops = f" f/{preset.f_number_min:g}" if preset.f_number_min else ""
        return focal + stops + (" (prescription)" if preset.prescription is not None else "")
    if kind == "prescription":
        return f"{len(preset.surfaces)} surfaces, f = {preset.focal_length_mm or 0:g} mm"
    if kind == "film":
        film = preset.reciprocity() if hasattr(preset, "reciprocity") else preset
        model = (f"p = {film.p:g} beyond {film.threshold_s:g} s" if film.p is not None
                 else f"published table to {film.points[-1][0]:g} s")
        return f"{film.name}, reciprocity {model}"
    return str(preset.name)
