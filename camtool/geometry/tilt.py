"""Thin-lens geometry of a tilted lens: the hinge rule, the Scheimpflug rule, planes through the hinge line.

Coordinates (docs/tilt.md): the meridional plane of the tilt, the lens
centre at the origin, x along the camera's line of sight (the normal to the
film through the lens, towards the subject) and y parallel to the film,
positive on the side the lens is tilted towards (below the lens for the
usual forward tilt, so that the hinge line lies at y = J > 0). The lens axis
is a = (cos θ, sin θ) for a tilt θ. Every plane of interest contains the
hinge line, so in this section it is a line through (0, J), described by the
reciprocal k = 1/x of the distance at which it crosses the line of sight
(k = 0: parallel to the line of sight, k < 0: it crosses behind the lens).

- Hinge rule (Scheimpflug's, as Merklinger named it): the plane of sharp
  focus, the front focal plane and the plane through the lens parallel to
  the film meet in the hinge line, at J = f/sin θ from the lens.
- Scheimpflug rule: the film plane, the lens plane and the plane of sharp
  focus meet in one line, at (−v, v·cot θ) for a film v behind the lens.
- Along the line of sight the lens equation reads 1/u + 1/v = cos θ/f
  (u, v perpendicular to the film); along the lens axis it is the ordinary
  1/s + 1/s′ = 1/f, with v = s′·cos θ.

Lengths in mm, angles in degrees at the boundary.
"""

from __future__ import annotations

from typing import Any

from camtool.core.arrays import ops, quiet
from camtool.core.errors import require, require_positive
from camtool.core.record import NamedTuple

__all__ = [
    "PlaneThroughPoints",
    "axis_reciprocal",
    "hinge_distance_mm",
    "plane_angle_deg",
    "plane_through_points",
    "scheimpflug_line_mm",
    "sight_reciprocal",
    "tilt_for_hinge_deg",
]


def _reciprocal(xp: Any, x: Any) -> Any:
    """1/x with 1/0 = +inf (no ZeroDivisionError on the scalar path)."""
    zero = x == 0
    return xp.where(zero, xp.inf, 1.0 / xp.where(zero, 1.0, x))


def hinge_distance_mm(focal_length_mm: Any, tilt_deg: Any) -> Any:
    """Hinge distance J in mm: J = f/sin θ, from the lens, parallel to the film (signed like the tilt).

    The hinge line lies in the plane through the lens parallel to the film,
    so J is also the shortest distance from the lens centre to it. A tilt of
    0 puts the hinge at infinity (``inf``), not a division by zero.

    Parameters
    ----------
    focal_length_mm : float or array, f > 0
    tilt_deg : float or array, −90 < θ < 90 (degrees; negative tilts the other way)

    References
    ----------
    H. M. Merklinger, *Focusing the View Camera* (1993), ch. 4, the Hinge
    Rule; "View Camera Focus and Depth of Field, Part I", *View Camera*,
    July/August 1996, pp. 55–57.

    Examples
    --------
    >>> round(hinge_distance_mm(150.0, 14.0), 1)  # Merklinger's "just over 2 feet"
    620.0
    >>> hinge_distance_mm(50.0, 0.0)
    inf
    """
    require_positive("focal_length_mm", focal_length_mm)
    xp = ops(focal_length_mm, tilt_deg)
    require("tilt_deg", tilt_deg, xp.fabs(tilt_deg) < 90.0, "between −90° and 90°")
    s = xp.sin(xp.radians(tilt_deg))
    with quiet(xp):
        j = focal_length_mm * _reciprocal(xp, s)
        return xp.where(s < 0, -xp.fabs(j), j)


def tilt_for_hinge_deg(focal_length_mm: Any, hinge_mm: Any) -> Any:
    """Tilt in degrees that puts the hinge line J from the lens: θ = asin(f/J).

    Parameters
    ----------
    focal_length_mm : float or array, f > 0
    hinge_mm : float or array, |J| ≥ f (``inf``: no tilt); the sign gives the direction

    Raises
    ------
    DomainError
        |J| < f: no tilt brings the hinge line closer than one focal length.

    References
    ----------
    Merklinger, *Focusing the View Camera* (1993), hinge-rule tables.

    Examples
    --------
    >>> round(tilt_for_hinge_deg(150.0, 4.2 * 304.8), 2)  # Merklinger: "near enough, 7°"
    6.73
    >>> tilt_for_hinge_deg(90.0, float("inf"))
    0.0
    """
    require_positive("focal_length_mm", focal_length_mm)
    xp = ops(focal_length_mm, hinge_mm)
    require("hinge_mm", hinge_mm, xp.fabs(hinge_mm) >= focal_length_mm,
            "at least the focal length, {limit}, from the lens", limit=focal_length_mm)
    ratio = focal_length_mm / hinge_mm
    return xp.degrees(xp.atan2(ratio, xp.sqrt(xp.maximum(1.0 - ratio * ratio, 0.0))))


def plane_angle_deg(focal_length_mm: Any, tilt_deg: Any, reciprocal_mm: Any) -> Any:
    """Angle in degrees from the film plane of the plane through the hinge line crossing the line of sight at 1/k.

    φ = atan2(sin θ, f·k): 0 for a plane parallel to the film, 90° for one
    parallel to the line of sight (k = 0), above 90° for one that crosses
    behind the lens. With θ = 0 every such plane is parallel to the film.

    Examples
    --------
    >>> round(plane_angle_deg(50.0, 5.0, 0.0), 6)
    90.0
    >>> plane_angle_deg(50.0, 0.0, 1 / 3000)
    0.0
    """
    xp = ops(focal_length_mm, tilt_deg, reciprocal_mm)
    return xp.degrees(xp.atan2(xp.sin(xp.radians(tilt_deg)), focal_length_mm * reciprocal_mm))


def axis_reciprocal(focal_length_mm: Any, tilt_deg: Any, reciprocal_mm: Any) -> Any:
    """1/(distance along the lens axis) at which a plane through the hinge crosses the axis: sin²θ/f + k·cos θ.

    Examples
    --------
    >>> round(1 / axis_reciprocal(50.0, 0.0, 1 / 3000), 6)
    3000.0
    """
    xp = ops(focal_length_mm, tilt_deg, reciprocal_mm)
    t = xp.radians(tilt_deg)
    return xp.sin(t) ** 2 / focal_length_mm + reciprocal_mm * xp.cos(t)


def sight_reciprocal(focal_length_mm: Any, tilt_deg: Any, axis_reciprocal_mm: Any) -> Any:
    """Inverse of :func:`axis_reciprocal`: k = (1/s − sin²θ/f)/cos θ.

    Examples
    --------
    >>> k = axis_reciprocal(90.0, 4.0, 1 / 2000)
    >>> round(1 / sight_reciprocal(90.0, 4.0, k), 9)
    2000.0
    """
    xp = ops(focal_length_mm, tilt_deg, axis_reciprocal_mm)
    t = xp.radians(tilt_deg)
    return (axis_reciprocal_mm - xp.sin(t) ** 2 / focal_length_mm) / xp.cos(t)


def scheimpflug_line_mm(tilt_deg: Any, film_mm: Any) -> Any:
    """Where the film plane (v behind the lens) meets the lens plane: y = v·cot θ (``inf`` at θ = 0), mm.

    Examples
    --------
    >>> round(scheimpflug_line_mm(45.0, 100.0), 9)
    100.0
    """
    xp = ops(tilt_deg, film_mm)
    t = xp.radians(tilt_deg)
    with quiet(xp):
        return film_mm * xp.cos(t) * _reciprocal(xp, xp.sin(t))


class PlaneThroughPoints(NamedTuple):
    """The tilt, hinge distance (mm, signed) and reciprocal focus 1/u along the line of sight (1/mm)."""

    tilt_deg: float
    hinge_mm: float
    reciprocal_mm: float


def plane_through_points(focal_length_mm: float, x1: float, y1: float, x2: float, y2: float) -> PlaneThroughPoints:
    """The thin-lens tilt and focus that lay the plane of sharp focus through two points (x, y) in mm.

    The plane is the line through the two points; where it crosses the
    plane through the lens parallel to the film is the hinge line, so the
    tilt follows from the hinge rule and the focus from where the line
    crosses the line of sight. Points at the same distance x give a plane
    parallel to the film: no tilt, focus at x.

    Raises
    ------
    DomainError
        (param ``point``) the points coincide, lie behind the front focal
        plane of the lens that would be needed, or define a line through the
        lens or closer than f to it (no tilt can do that).

    Examples
    --------
    The ground 1.6 m below a 90 mm lens, seen at 3 m and 10 m:

    >>> r = plane_through_points(90.0, 3000.0, 1600.0, 10000.0, 1600.0)
    >>> round(r.tilt_deg, 3), r.hinge_mm, r.reciprocal_mm
    (3.225, 1600.0, 0.0)
    """
    import math

    f = focal_length_mm
    if (x1, y1) == (x2, y2):
        raise _point_error((x1, y1), "two different points")
    if min(x1, x2) <= 0:
        raise _point_error((x1, y1) if x1 <= 0 else (x2, y2), "in front of the lens (distance > 0)")
    if x1 == x2:
        tilt, hinge, k = 0.0, math.inf, 1.0 / x1
    else:
        slope = (y2 - y1) / (x2 - x1)
        hinge = y1 - slope * x1
        if abs(hinge) < f:
            raise _point_error((x1, y1), f"points on a plane whose hinge line lies at least f = {f:g} mm "
                                         f"from the lens (this one: {abs(hinge):.4g} mm)")
        tilt = math.degrees(math.asin(f / hinge))
        k = -slope / hinge + 0.0  # no -0.0
    t = math.radians(tilt)
    for x, y in ((x1, y1), (x2, y2)):
        if x * math.cos(t) + y * math.sin(t) <= f:
            raise _point_error((x, y), "beyond the front focal plane of the tilted lens (no real image)")
    if k >= math.cos(t) / f:
        raise _point_error((x1, y1), "points on a plane the lens can focus (it would cross the line of "
                                     "sight inside the focal length)")
    return PlaneThroughPoints(tilt, hinge, k)


def _point_error(point: tuple[float, float], valid: str) -> Exception:
    from camtool.core.errors import DomainError

    return DomainError("point", f"{point[0] / 1000:g} m @ {-point[1] / 1000:g} m", valid)
