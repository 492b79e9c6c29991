"""Depth of field of a thick lens with pupil magnification: the ``thick`` model.

A real lens differs from a thin one, to first order, in two ways that matter
for depth of field: its principal planes H and H′ are separated by the hiatus
δ = z_H′ − z_H, and its exit pupil differs in size from its entrance pupil,
P = exit/entrance pupil diameter. With f the focal length and a unit-focusing
lens (the lens moves, the stop stays the same):

- the entrance pupil E lies e = f(1 − 1/P) in front of H, the exit pupil
  f(1 − P) behind H′;
- a subject at u in front of H is imaged at v = f·u/(u − f) behind H′ and
  lies D = u + δ + v from the sensor;
- with x = u − e = (u − f) + f/P the focus distance from E, the limits
  measured from E are near = x·f²/(f² + N·c·(u − f)) and
  far = x·f²/(f² − N·c·(u − f)).

With P = 1 and δ = 0 this is the exact thin lens. Everything is written as sums
of positive terms except f² − N·c·(u − f), whose cancellation near the
hyperfocal distance is the problem's own (the far limit really is that
sensitive there).

Works on plain floats (``math``, no numpy import) and on numpy arrays alike.
"""

from __future__ import annotations

from typing import Any

from camtool.core.arrays import broadcast, ops, quiet
from camtool.core.errors import require, require_positive
from camtool.core.planes import PLANES, check_plane
from camtool.dof.limits import DofLimits
from camtool.geometry.thinlens import LensPlaneDistances, lens_distances

__all__ = ["DISTANCE_PLANES", "entrance_pupil_offset_mm", "thick_dof", "thick_hyperfocal_mm", "working_f_number"]

DISTANCE_PLANES = PLANES
"""Planes a distance may be measured from: the sensor (image) plane, the front
principal plane H (``"lens"``), or the entrance pupil."""

# Largest finite far limit reported: reachable only a few ulps below the
# hyperfocal distance, where rounding can make f² − N·c·(u − f) vanish; the
# comparison in the input plane says the far limit is finite there.
_FAR_CAP_MM = 1e300


def entrance_pupil_offset_mm(focal_length_mm: Any, pupil_magnification: Any) -> Any:
    """Distance in mm of the entrance pupil in front of the front principal plane H: e = f(1 − 1/P).

    Negative when the entrance pupil lies behind the front principal plane
    (P < 1, telephoto designs).

    Parameters
    ----------
    focal_length_mm : float or array, f > 0
    pupil_magnification : float or array, P > 0

    References
    ----------
    Pupil imaging through the principal planes: E and the exit pupil are
    conjugate with lateral magnification P, so E sits where 1 − 1/P = u/f.
    Wikipedia, "Depth of field", §"Close-up" (pupil magnification).

    Examples
    --------
    >>> entrance_pupil_offset_mm(100.0, 2.0)
    50.0
    >>> entrance_pupil_offset_mm(100.0, 0.5)
    -100.0
    """
    return focal_length_mm - focal_length_mm / pupil_magnification


def working_f_number(f_number: Any, magnification: Any, pupil_magnification: Any = 1.0) -> Any:
    """Working (effective) f-number at magnification m: N_w = N·(1 + m/P).

    Parameters
    ----------
    f_number : float or array
        Nominal N > 0 (infinity focus).
    magnification : float or array
        Lateral magnification m ≥ 0 (0 at infinity, 1 at 1:1).
    pupil_magnification : float or array
        P > 0, exit over entrance pupil diameter.

    References
    ----------
    Wikipedia, "f-number", §"Working f-number"; Conrad, "Depth of Field in
    Depth" (2006).

    Examples
    --------
    >>> working_f_number(8.0, 1.0)
    16.0
    >>> working_f_number(8.0, 1.0, 0.5)
    24.0
    """
    require_positive("f_number", f_number, unit="")
    require_positive("pupil_magnification", pupil_magnification, unit="")
    return f_number * (1.0 + magnification / pupil_magnification)


def _check(f: Any, n: Any, c: Any, p: Any, hiatus: Any, distance: Any, distance_from: str) -> None:
    """Raise DomainError / ValueError for inputs outside the model's domain."""
    check_plane(distance_from, DISTANCE_PLANES)
    require_positive("focal_length_mm", f)
    require_positive("f_number", n, unit="")
    require_positive("coc_mm", c)
    require_positive("pupil_magnification", p, unit="")
    xp = ops(hiatus)
    require("hiatus_mm", hiatus, xp.isfinite(hiatus), "a finite length in mm")
    require_positive("distance_mm", distance, allow_inf=True)


def _focus(f: Any, distance: Any, hiatus: Any, e: Any, distance_from: str,
           focus: LensPlaneDistances | None = None) -> tuple[Any, Any, Any]:
    """Object distance u from H, image distance v from H′, and the plane's offset to E (mm)."""
    if distance_from == "sensor":
        u, v = lens_distances(f, distance, hiatus) if focus is None else focus
        to_pupil = v + hiatus + e
        require("hiatus_mm", hiatus, to_pupil > 0, "large enough that the entrance pupil lies in front of the sensor",
                detail="hiatus + image distance + f(1 − 1/P) must be > 0")
        return u, v, to_pupil
    u = distance + e if distance_from == "entrance_pupil" else distance
    require("distance_mm", distance, u > f,
            "more than f from the front principal plane (closer, the lens forms no real image)")
    return u, f / (1.0 - f / u), (0.0 if distance_from == "entrance_pupil" else e)


def thick_hyperfocal_mm(focal_length_mm: Any, f_number: Any, coc_mm: Any, pupil_magnification: Any,
                        hiatus_mm: Any, distance_from: str = "sensor") -> Any:
    """The hyperfocal distance of :func:`thick_dof` in the plane ``distance_from`` (mm), without the limits.

    u_H = max(f²/(N·c) + f, 2f) from H; from the sensor u_H + f·u_H/(u_H − f) + δ;
    from the entrance pupil u_H − e. A focus at or beyond it has a far limit of ∞.

    Examples
    --------
    100 mm f/4, c = 0.03 mm, δ = 20 mm: u_H = 83433.33, v_H = 100.12:

    >>> round(thick_hyperfocal_mm(100.0, 4.0, 0.03, 0.7, 20.0), 1)
    83553.5
    """
    f, nc = focal_length_mm, f_number * coc_mm
    if distance_from == "sensor" and type(nc) is float and type(f) is float and type(hiatus_mm) is float:
        u_hyp = max(f * f / nc + f, 2.0 * f)  # one scene: no array machinery (auto asks for it on every call)
        return u_hyp + f / (1.0 - f / u_hyp) + hiatus_mm
    xp = ops(f, f_number, coc_mm, pupil_magnification, hiatus_mm)
    with quiet(xp):
        u_hyp = xp.maximum(f * f / nc + f, 2.0 * f)
        if distance_from == "sensor":
            return u_hyp + f / (1.0 - f / u_hyp) + hiatus_mm
        e = entrance_pupil_offset_mm(f, pupil_magnification)
        return u_hyp - (e if distance_from == "entrance_pupil" else 0.0)


def thick_dof(
    focal_length_mm: Any,
    f_number: Any,
    coc_mm: Any,
    distance_mm: Any,
    pupil_magnification: Any = 1.0,
    hiatus_mm: Any = 0.0,
    distance_from: str = "sensor",
    focus: LensPlaneDistances | None = None,
    hyperfocal: Any = None,
) -> DofLimits:
    """Depth of field of a thick lens with pupil magnification, in mm (the ``thick`` model).

    With w = u − f, k = N·c·w and x = w + f/P (focus from the entrance pupil):

        front = x·k/(f² + k)      near = o + x·f²/(f² + k)
        rear  = x·k/(f² − k)      far  = focus + rear   (∞ for focus ≥ hyperfocal)

    with o the distance of the entrance pupil from the reference plane
    (sensor: v + δ + e; H: e; E: 0), so every distance is in whichever plane
    the focus distance was; the lens-to-sensor spacing stays at its focus
    setting. The hyperfocal distance from H is
    u_H = f²/(N·c) + f (from the sensor: u_H + f + N·c + δ; from E: u_H − e),
    or the closest focus when that is nearer. Magnification m = f/(u − f).

    Parameters
    ----------
    focal_length_mm : float or array
        f > 0.
    f_number : float or array
        Nominal N > 0 (for an object at infinity; the stop is fixed).
    coc_mm : float or array
        Circle of confusion c > 0, a blur diameter on the sensor.
    distance_mm : float or array
        Focus distance > 0 (``inf`` allowed) from ``distance_from``: the
        sensor (≥ 4f + δ, 1:1), the front principal plane H (``"lens"``,
        ≥ 2f), or the entrance pupil (≥ 2f − e).
    pupil_magnification : float or array
        P > 0, exit over entrance pupil diameter (1 for a symmetric lens;
        below 1 for telephotos, above 1 for retrofocus designs).
    hiatus_mm : float or array
        δ = z_H′ − z_H, finite, either sign (0 for a thin lens). From the
        sensor, the entrance pupil must lie in front of the sensor.
    distance_from : ``"sensor"``, ``"lens"`` or ``"entrance_pupil"``
    focus : LensPlaneDistances or None
        From the sensor: (u, v) of ``distance_mm`` already converted by
        :func:`camtool.geometry.thinlens.lens_distances` with this hiatus and
        checked, for a caller that has them; None converts here.
    hyperfocal : float, array or None
        :func:`thick_hyperfocal_mm` of these f, N, c, P, δ and plane, for a
        caller that has it; None computes it here.

    Returns
    -------
    DofLimits
        Scalars for scalar input, broadcast arrays otherwise.

    Raises
    ------
    DomainError
        f, N, c or P ≤ 0 or NaN, a focus closer than 1:1, a hiatus that puts
        the entrance pupil behind the sensor, or (from H, with P < 1) a near
        limit behind the front principal plane.

    References
    ----------
    J. Conrad, "Depth of Field in Depth" (2006), §"Pupil magnification";
    Wikipedia, "Depth of field", §"Close-up" with pupil magnification;
    docs/design.md §4.

    Examples
    --------
    With P = 1 and δ = 0 it is the exact thin lens (50 mm f/8, c = 0.03 mm,
    3 m from the lens):

    >>> r = thick_dof(50.0, 8.0, 0.03, 3000.0, distance_from="lens")
    >>> round(r.near_mm, 1), round(r.far_mm, 1)
    (2337.9, 4185.3)

    A telephoto-like P = 0.7 and δ = 20 mm, 3 m from the sensor:

    >>> r = thick_dof(100.0, 4.0, 0.03, 3000.0, pupil_magnification=0.7, hiatus_mm=20.0)
    >>> round(r.near_mm, 1), round(r.far_mm, 1), round(r.magnification, 4)
    (2905.9, 3100.6, 0.036)
    """
    _check(focal_length_mm, f_number, coc_mm, pupil_magnification, hiatus_mm, distance_mm, distance_from)
    f, nc, p = focal_length_mm, f_number * coc_mm, pupil_magnification
    xp = ops(f, f_number, coc_mm, p, hiatus_mm, distance_mm)
    e = entrance_pupil_offset_mm(f, p)
    u, v, to_pupil = _focus(f, distance_mm, hiatus_mm, e, distance_from, focus)
    with quiet(xp):
        w = u * f / v  # u − f without cancellation
        x = w + f / p
        f2 = f * f
        k = nc * w
        finite = xp.isfinite(distance_mm)
        front = xp.where(finite, x * k / (f2 + k), xp.inf)
        # near from E: x·f²/(f² + k), with numerator and denominator divided by w (finite at u = ∞)
        near_pupil = f2 * (1.0 + f / (p * w)) / (f2 / w + nc)
        near = to_pupil + near_pupil  # not focus − front: that cancels badly far away
        if hyperfocal is None:
            hyperfocal = thick_hyperfocal_mm(f, f_number, coc_mm, p, hiatus_mm, distance_from)
        beyond = distance_mm >= hyperfocal
        gap = f2 - k
        usable = gap > 0
        safe_gap = xp.where(usable, gap, 1.0)
        rear = xp.where(beyond, xp.inf, xp.where(usable, xp.minimum(x * k / safe_gap, _FAR_CAP_MM), _FAR_CAP_MM))
        far = xp.where(beyond, xp.inf, xp.minimum(distance_mm + rear, _FAR_CAP_MM))
        m = f / w
    if distance_from == "lens":
        require("pupil_magnification", p, near > 0,
                "≥ 1 here, or measure from the sensor or the entrance pupil",
                detail="the near limit would lie behind the front principal plane")
    return DofLimits(near, far, front, rear, front + rear, broadcast(hyperfocal, near), m)

