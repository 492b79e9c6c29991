"""The pinhole camera: its best diameter by contrast, the published rules beside it, and what each gives.

:func:`pinhole_plan` makes every decision of ``camtool pinhole``: the rows
(the diameter that resolves the finest detail at the contrast asked for,
then each published rule of :data:`camtool.optics.pinhole.RULES`), and for
each its f-number, its geometric and diffraction blur, its defocus in
waves, the frequency on the film at which its MTF falls to the level, the
level at which that rule is itself the best, and the exposure time at its
f-number; the angle of view 2·arctan(h/2L) of the film.
"""

from __future__ import annotations

import math
from typing import Any

from camtool.core.record import NamedTuple

__all__ = ["DEFAULT_LEVEL", "PinholePlan", "pinhole_plan"]

DEFAULT_LEVEL = 0.5
"""MTF50: the frequency at which the contrast falls to half, "arguably the best single indicator of sharpness"
(Imatest, as R. Littlefield quotes it on photomacrography.net, 2014)."""


class PinholePlan(NamedTuple):
    """The rows of ``camtool pinhole`` (dicts by output key, the optimum first) and the shared facts."""

    rows: list[dict[str, Any]]
    effective_distance_mm: float
    level: float


def pinhole_plan(*, film_distance_mm: float, subject_distance_mm: float = math.inf, wavelength_nm: float = 550.0,
                 level: float = DEFAULT_LEVEL, sensor_width_mm: float = 36.0, sensor_height_mm: float = 24.0,
                 ev100: float = 15.0, iso: float = 100.0) -> PinholePlan:
    """Every row of ``camtool pinhole``.

    The optimum is :func:`camtool.optics.pinhole.best_constant` at ``level``;
    the angle of view is that of a lens of focal length L
    (:func:`camtool.geometry.fov.angle_of_view_deg`; the film sits L behind
    the hole, whatever the subject distance); the exposure time is
    N²·2^−EV at the scene's EV100 and ISO
    (:func:`camtool.exposure.ev.shutter_for_ev100`), null where it falls
    outside 1/64000 s to 10⁶ s or the f-number beyond f/1024.

    Examples
    --------
    Rayleigh's rule at 100 mm and 550 nm: d = 1.9·√(0.00055 × 100) = 0.4456 mm, f/224.4:

    >>> p = pinhole_plan(film_distance_mm=100.0)
    >>> r = next(row for row in p.rows if row["method"] == "rayleigh")
    >>> round(r["pinhole_mm"], 4), round(r["f_number"], 1)
    (0.4456, 224.4)
    """
    from camtool.core.errors import CamtoolError, require, require_positive
    from camtool.exposure.ev import shutter_for_ev100
    from camtool.geometry.fov import angle_of_view_deg
    from camtool.optics import pinhole as ph

    require_positive("film_distance_mm", film_distance_mm)
    require("level", level, 0.05 <= level <= 0.95, "0.05 to 0.95")
    length, far = float(film_distance_mm), float(subject_distance_mm)
    effective = ph.effective_distance_mm(length, far)
    angles = {f"{name}_deg": float(angle_of_view_deg(size, length)) for name, size in (
        ("horizontal", sensor_width_mm), ("vertical", sensor_height_mm),
        ("diagonal", math.hypot(sensor_width_mm, sensor_height_mm)))}
    methods: list[tuple[str, float, float | None]] = [("optimum", ph.best_constant(level), level)]
    methods += [(rule.name, rule.constant, ph.rule_level(rule.constant)) for rule in ph.RULES]
    rows = []
    for name, k, best_level in methods:
        d = ph.rule_diameter_mm(k, length, far, wavelength_nm)
        n = length / d
        try:
            shutter: float | None = float(shutter_for_ev100(ev100, n, iso))
        except CamtoolError:
            shutter = None
        rows.append({
            "method": name, "constant": k, "pinhole_mm": d, "f_number": n,
            "geometric_blur_mm": ph.geometric_blur_mm(d, length, far), "airy_mm": ph.airy_mm(d, length, wavelength_nm),
            "defocus_waves": ph.defocus_waves(d, length, far, wavelength_nm),
            "resolution_lpmm": ph.resolution_lpmm(d, length, level, far, wavelength_nm), "mtf_level": level,
            "best_at_level": best_level, "shutter_s": shutter, "film_distance_mm": length,
            "subject_distance_mm": far, "wavelength_nm": float(wavelength_nm), **angles,
        })
    return PinholePlan(rows, effective, float(level))
