"""Angle of view and the field covered by a lens on a sensor.

A lens focused so that its image lies v behind it maps a sensor dimension h
to an angle 2·atan(h/2v). At infinity focus v = f; focused closer, v = f(1 + m)
grows and the angle shrinks (focus breathing of a unit-focusing lens).
Lengths in millimetres, angles in degrees.
"""

from __future__ import annotations

import math
from typing import Any

from camtool.core.arrays import is_scalar, ops
from camtool.core.errors import require, require_positive
from camtool.core.record import NamedTuple


class FieldOfView(NamedTuple):
    """Horizontal, vertical and diagonal angles of view in degrees."""

    horizontal_deg: Any
    vertical_deg: Any
    diagonal_deg: Any


def angle_of_view_deg(
    size_mm: Any, focal_length_mm: Any, magnification: Any = 0.0, pupil_magnification: Any = 1.0
) -> Any:
    """Angle of view in degrees across a sensor dimension: 2·atan(h / (2·f·(1 + m/P))).

    Parameters
    ----------
    size_mm : float or array
        Sensor dimension h (width, height or diagonal), > 0.
    focal_length_mm : float or array, f > 0
    magnification : float or array, m ≥ 0
        0 at infinity focus; otherwise the image distance f(1 + m) replaces f.
    pupil_magnification : float or array, P > 0
        Exit over entrance pupil diameter (1 for a thin lens). The chief ray
        leaves the exit pupil, f(m + P) in front of the sensor, at an angle
        whose tangent is 1/P times that at the entrance pupil, so the angle of
        view is set by f(1 + m/P): a lens with P < 1 (telephoto) breathes more.

    References
    ----------
    Wikipedia, "Angle of view" (α = 2 arctan(d/2f), and the macro correction
    with the image distance f(1 + m)).

    Examples
    --------
    >>> round(angle_of_view_deg(36.0, 50.0), 2)
    39.6
    >>> round(angle_of_view_deg(36.0, 50.0, magnification=1.0), 2)
    20.41
    >>> round(angle_of_view_deg(36.0, 100.0, magnification=0.5, pupil_magnification=0.5), 2)
    10.29
    """
    require_positive("sensor_mm", size_mm)
    require_positive("focal_length_mm", focal_length_mm)
    require("magnification", magnification, magnification >= 0, ">= 0")
    require_positive("pupil_magnification", pupil_magnification, unit="")
    xp = ops(size_mm, focal_length_mm, magnification, pupil_magnification)
    effective = focal_length_mm * (1.0 + magnification / pupil_magnification)
    return 2.0 * xp.degrees(xp.atan(size_mm / (2.0 * effective)))


def field_of_view(
    width_mm: Any, height_mm: Any, focal_length_mm: Any, magnification: Any = 0.0, pupil_magnification: Any = 1.0
) -> FieldOfView:
    """Horizontal, vertical and diagonal angles of view in degrees of a sensor ``width_mm`` × ``height_mm``.

    Examples
    --------
    >>> [round(a, 1) for a in field_of_view(36.0, 24.0, 50.0)]
    [39.6, 27.0, 46.8]
    """
    xp = ops(width_mm, height_mm)
    diagonal = xp.hypot(width_mm, height_mm)
    return FieldOfView(
        angle_of_view_deg(width_mm, focal_length_mm, magnification, pupil_magnification),
        angle_of_view_deg(height_mm, focal_length_mm, magnification, pupil_magnification),
        angle_of_view_deg(diagonal, focal_length_mm, magnification, pupil_magnification),
    )


def field_size_mm(size_mm: Any, magnification: Any) -> Any:
    """Size in mm of the field an object plane shows across a sensor dimension: h / m.

    With m = f/(u − f) for a thin lens this is h·(u − f)/f; the common
    shortcut h·u/f neglects the f.

    Examples
    --------
    >>> field_size_mm(36.0, 0.01)
    3600.0
    >>> field_size_mm(36.0, 0.0)  # focused at infinity: the field is unbounded
    inf
    """
    require_positive("sensor_mm", size_mm)
    require("magnification", magnification, (magnification >= 0) & (magnification < math.inf),
            ">= 0 and finite (0 for a focus at infinity)")
    if is_scalar(size_mm) and is_scalar(magnification):
        return math.inf if magnification == 0 else size_mm / magnification
    import numpy as np

    with np.errstate(divide="ignore"):
        return np.asarray(size_mm, dtype=float) / np.asarray(magnification, dtype=float)


def focal_length_for_angle_mm(size_mm: Any, angle_deg: Any) -> Any:
    """Focal length in mm whose angle of view across a sensor dimension is ``angle_deg``: f = (h/2)/tan(α/2).

    The inverse of :func:`angle_of_view_deg` at infinity focus.

    Parameters
    ----------
    size_mm : float or array
        Sensor dimension h (width, height or diagonal), > 0.
    angle_deg : float or array
        Angle of view α in degrees, 0 < α < 180.

    References
    ----------
    Wikipedia, "Angle of view" (α = 2 arctan(d/2f), solved for f).

    Examples
    --------
    >>> round(focal_length_for_angle_mm(24.0, 27.0), 2)
    49.98
    """
    require_positive("sensor_mm", size_mm)
    require("angle_deg", angle_deg, (angle_deg > 0) & (angle_deg < 180), "between 0 and 180 degrees (exclusive)")
    xp = ops(size_mm, angle_deg)
    return 0.5 * size_mm / xp.tan(xp.radians(0.5 * angle_deg))


class View(NamedTuple):
    """What a lens focused at a distance shows: angles (degrees), magnification and field (mm).

    ``field_width_mm`` and ``field_height_mm`` are None for infinity focus
    without a distance.
    """

    angles: FieldOfView
    magnification: Any
    field_width_mm: Any
    field_height_mm: Any
    equivalent_focal_length_mm: Any


def view(
    width_mm: Any,
    height_mm: Any,
    focal_length_mm: Any,
    distance_mm: Any = None,
    distance_from: str = "sensor",
    pupil_magnification: Any = 1.0,
    hiatus_mm: Any = 0.0,
    crop_factor: Any = 1.0,
) -> View:
    """Angles of view with focus breathing, and the field covered at the focus distance.

    Focused at a distance the lens breathes: f(1 + m/P) replaces f
    (:func:`angle_of_view_deg`), and the field at the subject is the sensor
    size over m (:func:`field_size_mm`); m from the thin-lens focus geometry
    with the hiatus δ. Without a distance the focus is at infinity (m = 0) and
    there is no field. The 35 mm equivalent focal length is f times the crop
    factor.

    Parameters
    ----------
    width_mm, height_mm : float or array
        Sensor size, > 0.
    focal_length_mm : float or array, f > 0
    distance_mm : float, array or None
        Focus distance from ``distance_from``; None: infinity, no field.
    distance_from : ``"sensor"`` or ``"lens"``
    pupil_magnification, hiatus_mm : float or array
        P (1 for a thin lens) and δ (0).
    crop_factor : float
        Of the sensor, for the equivalent focal length.

    References
    ----------
    Wikipedia, "Angle of view" (2·atan(d/2f), with the focused image distance);
    docs/design.md §4.

    Examples
    --------
    >>> v = view(36.0, 24.0, 50.0, 200.0)
    >>> v.magnification, v.field_width_mm, v.field_height_mm
    (1.0, 36.0, 24.0)
    >>> round(view(36.0, 24.0, 50.0).angles.horizontal_deg, 1)
    39.6
    """
    from camtool.geometry.thinlens import focus_geometry

    s = float("inf") if distance_mm is None else distance_mm
    m = focus_geometry(focal_length_mm, s, distance_from, hiatus_mm).magnification
    angles = field_of_view(width_mm, height_mm, focal_length_mm, m, pupil_magnification)
    if distance_mm is None:
        width = height = None
    else:
        width, height = field_size_mm(width_mm, m), field_size_mm(height_mm, m)
    return View(angles, m, width, height, focal_length_mm * crop_factor)
