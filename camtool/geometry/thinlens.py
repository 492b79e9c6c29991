"""Thin-lens image formation: image distance, magnification, extension, focus planes.

A thin lens of focal length f images an object at distance u (from the lens)
at v behind it, with 1/u + 1/v = 1/f and magnification m = v/u. A camera
focuses by moving the lens: the lens-to-sensor spacing is v, and the distance
the focus scale shows is measured from the sensor plane, D = u + v (+ the
hiatus δ between the principal planes of a thick lens).

All lengths in millimetres; scalars in, floats out; arrays in, arrays out.
"""

from __future__ import annotations

from typing import Any

from camtool.core.arrays import broadcast, ops, quiet
from camtool.core.errors import require, require_positive
from camtool.core.planes import FOCUS_PLANES, check_plane
from camtool.core.record import NamedTuple


class LensPlaneDistances(NamedTuple):
    """Object and image distances from the principal planes, in mm."""

    object_mm: Any
    image_mm: Any


def image_distance_mm(focal_length_mm: Any, object_distance_mm: Any) -> Any:
    """Image distance v in mm for an object at u from the lens: v = u·f/(u − f).

    Written v = f/(1 − f/u) so that u = ∞ gives v = f exactly.

    Parameters
    ----------
    focal_length_mm : float or array, f > 0
    object_distance_mm : float or array, u > f (``inf`` allowed)

    References
    ----------
    Thin-lens (Gaussian) equation 1/f = 1/u + 1/v; Hecht, *Optics*, §5.2.

    Examples
    --------
    >>> image_distance_mm(50.0, 5050.0)
    50.5
    >>> image_distance_mm(50.0, float("inf"))
    50.0
    """
    require_positive("focal_length_mm", focal_length_mm)
    require("object_distance_mm", object_distance_mm, object_distance_mm > focal_length_mm,
            "greater than the focal length")
    return focal_length_mm / (1.0 - focal_length_mm / object_distance_mm)


def magnification(focal_length_mm: Any, object_distance_mm: Any) -> Any:
    """Lateral magnification m = v/u = f/(u − f) of an object at u from the lens (0 at infinity).

    Examples
    --------
    >>> magnification(50.0, 100.0)
    1.0
    >>> magnification(100.0, 1100.0)
    0.1
    """
    require_positive("focal_length_mm", focal_length_mm)
    require("object_distance_mm", object_distance_mm, object_distance_mm > focal_length_mm,
            "greater than the focal length")
    return focal_length_mm / (object_distance_mm - focal_length_mm)


def extension_mm(focal_length_mm: Any, object_distance_mm: Any) -> Any:
    """Lens extension beyond infinity focus in mm: v − f = f²/(u − f) = f·m.

    Examples
    --------
    >>> extension_mm(50.0, 100.0)
    50.0
    """
    return focal_length_mm * magnification(focal_length_mm, object_distance_mm)


def closest_focus_mm(focal_length_mm: Any, hiatus_mm: Any = 0.0, distance_from: str = "sensor") -> Any:
    """Closest focus distance of a unit-focusing lens in mm: 4f + δ from the sensor, 2f from the lens (1:1).

    u + v is smallest, 4f, at u = v = 2f; any closer object has no real image
    on a sensor behind the lens.

    Examples
    --------
    >>> closest_focus_mm(50.0)
    200.0
    >>> closest_focus_mm(50.0, distance_from="lens")
    100.0
    """
    require_positive("focal_length_mm", focal_length_mm)
    if distance_from == "lens":
        return 2.0 * focal_length_mm
    return 4.0 * focal_length_mm + hiatus_mm


def working_f_number(f_number: Any, magnification: Any, pupil_magnification: Any = 1.0) -> Any:
    """Working (effective) f-number N·(1 + m/P) of a lens focused at magnification m.

    P is the pupil magnification (exit/entrance pupil diameter), 1 for a
    thin lens.

    References
    ----------
    Wikipedia, "f-number", working f-number; docs/design.md §4.

    Examples
    --------
    >>> working_f_number(8.0, 1.0)
    16.0
    """
    return f_number * (1.0 + magnification / pupil_magnification)


def span_root(focal_length_mm: Any, sensor_distance_mm: Any, hiatus_mm: Any = 0.0) -> tuple[Any, Any, Any]:
    """(array module, L = D − δ, r = √(1 − 4f/L)) of a unit-focusing lens whose subject is D from the sensor.

    The two conjugates are u, v = L·(1 ± r)/2; D < 4f + δ (closer than 1:1) is a
    :class:`DomainError` on ``distance_mm``. Shared by :func:`lens_distances` and
    :func:`camtool.geometry.closeup.magnification_branches`.
    """
    require_positive("focal_length_mm", focal_length_mm)
    xp = ops(focal_length_mm, sensor_distance_mm, hiatus_mm)
    span = sensor_distance_mm - hiatus_mm
    require("distance_mm", sensor_distance_mm, span >= 4.0 * focal_length_mm,
            "at least {limit} from the sensor (the closest focus, 1:1: 4 × focal length)",
            limit=4.0 * focal_length_mm + hiatus_mm)
    with quiet(xp):
        root = xp.sqrt(xp.maximum(1.0 - 4.0 * focal_length_mm / span, 0.0))
    return xp, span, root


def lens_distances(focal_length_mm: Any, sensor_distance_mm: Any, hiatus_mm: Any = 0.0) -> LensPlaneDistances:
    """Convert a distance from the sensor plane into object and image distances (u, v) in mm.

    With L = D − δ: u + v = L and 1/u + 1/v = 1/f give
    u = L/2·(1 + √(1 − 4f/L)) and v = 2f/(1 + √(1 − 4f/L)); v is written
    without the subtraction L − u so that it stays exact for distant objects.

    Parameters
    ----------
    focal_length_mm : float or array, f > 0
    sensor_distance_mm : float or array, D ≥ 4f + δ (``inf`` allowed)
    hiatus_mm : float or array, separation of the principal planes δ (0 for a thin lens)

    References
    ----------
    docs/design.md §4 (geometry); follows from the thin-lens equation.

    Examples
    --------
    >>> lens_distances(50.0, 200.0)
    LensPlaneDistances(object_mm=100.0, image_mm=100.0)
    >>> lens_distances(50.0, float("inf"))
    LensPlaneDistances(object_mm=inf, image_mm=50.0)
    """
    xp, span, root = span_root(focal_length_mm, sensor_distance_mm, hiatus_mm)
    image = 2.0 * focal_length_mm / (1.0 + root)
    with quiet(xp):
        obj = span * 0.5 * (1.0 + root)
    return LensPlaneDistances(obj, image)


def sensor_distance_mm(focal_length_mm: Any, object_distance_mm: Any, hiatus_mm: Any = 0.0) -> Any:
    """Distance from the sensor plane in mm of an object at u from the lens: D = u + v + δ.

    The inverse of :func:`lens_distances`.

    Examples
    --------
    >>> sensor_distance_mm(50.0, 100.0)
    200.0
    """
    return object_distance_mm + image_distance_mm(focal_length_mm, object_distance_mm) + hiatus_mm


def blur_diameter_mm(focal_length_mm: Any, f_number: Any, focus_distance_mm: Any, object_distance_mm: Any) -> Any:
    """Blur-disc diameter in mm on the sensor of an object at u when the lens is focused at s.

    With the sensor at the image v_s of the focus distance and the object
    imaged at v_o, similar triangles through the aperture A = f/N give
    C/A = |v_s − v_o|/v_o, i.e. C = (f/N)·|v_s − v_o|/v_o. Distances from the
    lens; either may be ``inf``.

    References
    ----------
    The blur-circle relation C/A = |z_s − z_i|/z_i of the thin-lens lecture
    notes; Wikipedia, "Circle of confusion".

    Examples
    --------
    >>> blur_diameter_mm(50.0, 2.0, 5050.0, float("inf"))
    0.25
    """
    v_focus = image_distance_mm(focal_length_mm, focus_distance_mm)
    v_object = image_distance_mm(focal_length_mm, object_distance_mm)
    xp = ops(v_focus, v_object)
    return focal_length_mm / f_number * xp.fabs(v_focus - v_object) / v_object



class FocusGeometry(NamedTuple):
    """Where everything sits when a thin lens focuses on a distance; lengths in mm."""

    object_mm: Any  # u, object to the lens (front principal plane)
    image_mm: Any  # v, lens (rear principal plane) to the sensor
    sensor_distance_mm: Any  # u + v + δ, object to the sensor plane
    magnification: Any  # m = v/u
    extension_mm: Any  # v − f


def focus_geometry(
    focal_length_mm: Any, distance_mm: Any, distance_from: str = "sensor", hiatus_mm: Any = 0.0
) -> FocusGeometry:
    """Object and image distances, magnification and extension for a focus distance in either plane.

    Examples
    --------
    >>> focus_geometry(50.0, 200.0)
    FocusGeometry(object_mm=100.0, image_mm=100.0, sensor_distance_mm=200.0, magnification=1.0, extension_mm=50.0)
    >>> focus_geometry(50.0, 100.0, distance_from="lens").sensor_distance_mm
    200.0
    """
    if check_plane(distance_from, FOCUS_PLANES) == "sensor":
        u, v = lens_distances(focal_length_mm, distance_mm, hiatus_mm)
        sensor = distance_mm
    else:
        require_positive("focal_length_mm", focal_length_mm)
        require("distance_mm", distance_mm, distance_mm > focal_length_mm,
                "more than {limit} from the lens (the focal length; between f and 2f the magnification is above 1)",
                limit=focal_length_mm)
        u = distance_mm
        v = image_distance_mm(focal_length_mm, u)
        sensor = u + v + hiatus_mm
    m = v / u
    return FocusGeometry(u, v, sensor, m, v - focal_length_mm)


def focus_for_magnification(focal_length_mm: Any, magnification: Any, hiatus_mm: Any = 0.0) -> FocusGeometry:
    """Focus geometry for a wanted magnification m: u = f(1 + 1/m), v = f(1 + m).

    Examples
    --------
    >>> focus_for_magnification(100.0, 0.5).sensor_distance_mm
    450.0
    """
    require_positive("focal_length_mm", focal_length_mm)
    require_positive("magnification", magnification, unit="")
    u = focal_length_mm * (1.0 + 1.0 / magnification)
    v = focal_length_mm * (1.0 + magnification)
    return FocusGeometry(u, v, u + v + hiatus_mm, broadcast(magnification, u), v - focal_length_mm)


class FocusSetting(NamedTuple):
    """A lens focused on a distance or for a magnification; lengths in mm.

    ``distance_mm`` is the focus distance in the plane asked for (from the
    sensor or from the lens); ``working_f_number`` is None without an f-number.
    """

    distance_mm: Any
    image_distance_mm: Any  # v, rear principal plane to the sensor
    extension_mm: Any  # v − f
    magnification: Any  # m = v/u
    closest_focus_mm: Any  # 1:1, in the same plane
    working_f_number: Any


def focus_setting(
    focal_length_mm: Any,
    distance_mm: Any = None,
    magnification: Any = None,
    distance_from: str = "sensor",
    hiatus_mm: Any = 0.0,
    f_number: Any = None,
    pupil_magnification: Any = 1.0,
) -> FocusSetting:
    """Focus a unit-focusing lens on ``distance_mm`` (or for ``magnification``): where everything sits.

    u, v from :func:`focus_geometry` (a distance) or :func:`focus_for_magnification`
    (u = f(1 + 1/m), v = f(1 + m)); the working f-number N(1 + m/P) when N is
    given; the closest focus (1:1) in the same plane.

    Parameters
    ----------
    focal_length_mm : float or array, f > 0
    distance_mm : float or array, or None
        Focus distance from ``distance_from`` (``inf`` allowed); give this or ``magnification``.
    magnification : float or array, or None
        Wanted m > 0.
    distance_from : ``"sensor"`` or ``"lens"``
    hiatus_mm : float or array
        δ between the principal planes (0 for a thin lens).
    f_number : float, array or None
        Nominal N for the working f-number.
    pupil_magnification : float or array
        P (1 for a thin lens).

    References
    ----------
    Thin-lens equation (Hecht, *Optics*, §5.2); working f-number: Wikipedia,
    "f-number"; docs/design.md §4.

    Examples
    --------
    >>> s = focus_setting(100.0, 500.0, distance_from="lens", f_number=8.0)
    >>> s.distance_mm, s.image_distance_mm, s.magnification, s.working_f_number
    (500.0, 125.0, 0.25, 10.0)
    >>> focus_setting(100.0, magnification=1.0).distance_mm
    400.0
    """
    if (distance_mm is None) == (magnification is None):
        raise ValueError("give either distance_mm or magnification")
    if distance_mm is not None:
        geometry = focus_geometry(focal_length_mm, distance_mm, distance_from, hiatus_mm)
    else:
        geometry = focus_for_magnification(focal_length_mm, magnification, hiatus_mm)
    nearest = closest_focus_mm(focal_length_mm, hiatus_mm, distance_from=distance_from)
    plane_distance = geometry.sensor_distance_mm if distance_from == "sensor" else geometry.object_mm
    working = None if f_number is None else working_f_number(f_number, geometry.magnification, pupil_magnification)
    return FocusSetting(plane_distance, geometry.image_mm, geometry.extension_mm, geometry.magnification, nearest,
                        working)
