"""camtool's public Python API: the main calculations, with units in every parameter name.

Every function takes plain floats or numpy arrays (broadcast together) and
returns a named result. Lengths are millimetres, angles degrees, times
seconds. Distances are measured from the sensor (focal) plane unless
``distance_from="lens"`` says otherwise, as on the command line (see
``docs/design.md`` §2). A value outside a formula's physical domain raises
:class:`camtool.core.errors.DomainError`, a :class:`ValueError` naming the
parameter, the value and the valid range.

Examples
--------
>>> import camtool
>>> r = camtool.depth_of_field(focal_length_mm=50, f_number=8, coc_mm=0.03, distance_mm=3000, model="thin")
>>> round(r.near_mm), round(r.far_mm), r.model
(2358, 4137, 'thin')
>>> round(camtool.hyperfocal_distance(focal_length_mm=50, f_number=8, coc_mm=0.03, model="thin").hyperfocal_mm)
10517
"""

from __future__ import annotations

from typing import Any, NamedTuple

from camtool.dof.ladder import LensData
from camtool.dof.limits import DofLimits
from camtool.exposure.plan import ExposurePlan
from camtool.geometry.compose import Composition
from camtool.geometry.fov import FieldOfView
from camtool.geometry.thinlens import FocusGeometry

__all__ = [
    "Composition",
    "DepthOfField",
    "DofLimits",
    "ExposurePlan",
    "FieldOfView",
    "FocusGeometry",
    "FocusPlan",
    "LensData",
    "circle_of_confusion",
    "composition",
    "depth_of_field",
    "field_of_view",
    "focus_for_limits",
    "focus_for_magnification",
    "hyperfocal_distance",
    "plan_exposure",
]

class DepthOfField(NamedTuple):
    """The result of :func:`depth_of_field`, distances in mm from the plane the focus was given in.

    ``far_mm``, ``rear_mm`` and ``total_mm`` are ``inf`` when everything beyond the focus is sharp;
    ``model`` names the rung that ran (``+diffraction`` when the Airy disc was added) and
    ``error_estimate`` its estimated relative error.
    """

    near_mm: Any
    far_mm: Any
    front_mm: Any
    rear_mm: Any
    total_mm: Any
    hyperfocal_mm: Any
    magnification: Any
    model: Any
    error_estimate: Any


def _lens(pupil_magnification: Any, hiatus_mm: Any, prescription: Any) -> LensData | None:
    if pupil_magnification is None and hiatus_mm is None and prescription is None:
        return None
    return LensData(pupil_magnification=pupil_magnification, hiatus_mm=hiatus_mm, prescription=prescription)


def depth_of_field(
    focal_length_mm: Any,
    f_number: Any,
    coc_mm: Any,
    distance_mm: Any,
    *,
    distance_from: str = "sensor",
    model: str = "auto",
    pupil_magnification: Any = None,
    hiatus_mm: Any = None,
    prescription: Any = None,
    diffraction: bool = False,
    wavelength_nm: float = 550.0,
    tolerance: float = 0.01,
) -> DepthOfField:
    """Near and far limits of acceptable sharpness in mm, by a rung of the model ladder.

    Parameters
    ----------
    focal_length_mm : float or array, 1 to 5000 mm (ignored with a ``prescription``: pass None)
    f_number : float or array, the nominal (marked) f-number, 0.7 to 1024
    coc_mm : float or array, the circle of confusion on the sensor, mm
    distance_mm : float or array, focus distance from the plane ``distance_from``; ``inf`` allowed
    distance_from : ``"sensor"`` (default) or ``"lens"``
    model : ``"approx"``, ``"thin"``, ``"thick"``, ``"paraxial"``, ``"raytrace"`` or ``"auto"``
        (the cheapest rung whose estimated error stays within ``tolerance``)
    pupil_magnification, hiatus_mm : lens data for the ``thick`` rung (P = exit/entrance pupil diameter)
    prescription : a :class:`camtool.optics.prescription.Prescription` for ``paraxial`` and ``raytrace``
    diffraction : bool, add the Airy disc to the blur (λ = ``wavelength_nm``)

    Returns
    -------
    DepthOfField
        near, far, front, rear, total and hyperfocal distances in mm, the magnification, the ``model``
        that ran and its ``error_estimate`` (relative).

    Examples
    --------
    >>> r = depth_of_field(50, 8, 0.03, 3000, model="thin")
    >>> round(r.total_mm)
    1779
    """
    from camtool.dof.ladder import depth_of_field as run

    lens = _lens(pupil_magnification, hiatus_mm, prescription)
    result = run(model, focal_length_mm, f_number, coc_mm, distance_mm, distance_from, lens, diffraction,
                 wavelength_nm, tolerance)
    return DepthOfField(*result.limits, result.model, result.error_estimate)


def hyperfocal_distance(
    focal_length_mm: Any,
    f_number: Any,
    coc_mm: Any,
    *,
    distance_from: str = "sensor",
    model: str = "auto",
    pupil_magnification: Any = None,
    hiatus_mm: Any = None,
    prescription: Any = None,
) -> DofLimits:
    """The hyperfocal distance in mm and the near limit when focused there.

    The result's ``hyperfocal_mm`` is the closest focus at which the far limit
    reaches infinity; ``near_mm`` is the near limit with that focus (half the
    hyperfocal distance for the ``approx`` rung).

    Examples
    --------
    >>> h = hyperfocal_distance(24, 11, 0.03, model="approx")
    >>> round(h.hyperfocal_mm)
    1745
    """
    from camtool.dof.ladder import depth_of_field as run

    lens = _lens(pupil_magnification, hiatus_mm, prescription)
    first = run(model, focal_length_mm, f_number, coc_mm, float("inf"), distance_from, lens).limits
    return run(model, focal_length_mm, f_number, coc_mm, first.hyperfocal_mm, distance_from, lens).limits


def field_of_view(
    focal_length_mm: Any,
    sensor_width_mm: Any,
    sensor_height_mm: Any,
    *,
    magnification: Any = 0.0,
    pupil_magnification: Any = 1.0,
) -> FieldOfView:
    """Horizontal, vertical and diagonal angles of view in degrees (with focus breathing at ``magnification``).

    Examples
    --------
    >>> round(field_of_view(50, 36, 24).horizontal_deg, 2)  # 2·atan(18/50)
    39.6
    """
    from camtool.geometry.fov import field_of_view as run

    return run(sensor_width_mm, sensor_height_mm, focal_length_mm, magnification, pupil_magnification)


class FocusPlan(NamedTuple):
    """Where to focus and which f-number makes the depth of field run from ``near_mm`` to ``far_mm``."""

    distance_mm: Any
    f_number: Any


def focus_for_limits(
    focal_length_mm: Any, coc_mm: Any, near_mm: Any, far_mm: Any, *, distance_from: str = "sensor"
) -> FocusPlan:
    """The focus distance in mm and the f-number whose thin-lens depth of field is exactly [near, far].

    Examples
    --------
    >>> p = focus_for_limits(24, 0.03, 1000, float("inf"))
    >>> round(p.distance_mm, 1), round(p.f_number, 2)
    (1975.7, 9.96)
    """
    from camtool.dof.inverse import focus_for_limits as run

    solution = run(focal_length_mm, coc_mm, near_mm, far_mm, distance_from)
    return FocusPlan(solution.distance_mm, solution.f_number)


def focus_for_magnification(focal_length_mm: Any, magnification: Any, *, hiatus_mm: Any = 0.0) -> FocusGeometry:
    """Object and image distances in mm (and the sensor-plane focus distance) for a magnification m > 0.

    Examples
    --------
    >>> round(focus_for_magnification(100, 1.0).sensor_distance_mm)
    400
    """
    from camtool.geometry.thinlens import focus_for_magnification as run

    return run(focal_length_mm, magnification, hiatus_mm)


def circle_of_confusion(sensor_width_mm: float, sensor_height_mm: float, rule: str = "d/1500",
                        *, pixel_pitch_mm: float | None = None) -> float:
    """The circle of confusion in mm from a rule (``d/1500``, ``d/1730``, ``px:2``, ``print:8x10in@25cm``).

    Examples
    --------
    >>> round(circle_of_confusion(36, 24), 4)
    0.0288
    """
    from camtool.geometry.coc import coc_from_rule

    return coc_from_rule(rule, sensor_width_mm, sensor_height_mm, pixel_pitch_mm).coc_mm


def composition(focal_length_mm: Any, magnification: Any, sensor_width_mm: Any, sensor_height_mm: Any) -> Composition:
    """Where to stand for a framing: the distance, field and angles at a magnification (see ``camtool compose``).

    Examples
    --------
    >>> c = composition(100, 0.02, 36, 24)  # u = f(1 + 1/m), v = f(1 + m), field = 36/m
    >>> c.lens_distance_mm, c.distance_mm, c.field_width_mm
    (5100.0, 5202.0, 1800.0)
    """
    from camtool.geometry.compose import composition as run

    return run(focal_length_mm, magnification, sensor_width_mm, sensor_height_mm)


def plan_exposure(
    *,
    ev100: Any = None,
    f_number: Any = None,
    shutter_s: Any = None,
    iso: Any = None,
    nd_stops: Any = 0.0,
    magnification: Any = 0.0,
    pupil_magnification: Any = 1.0,
) -> ExposurePlan:
    """A whole exposure: from a light level (EV100) and two settings, the third; or the EV100 of settings.

    Examples
    --------
    >>> p = plan_exposure(ev100=15, f_number=16, iso=100)  # t = N²/2^EV = 256/32768
    >>> round(1 / p.shutter_s)
    128
    """
    from camtool.exposure.plan import plan_exposure as run

    return run(ev100, f_number, shutter_s, iso, nd_stops, magnification, pupil_magnification)
