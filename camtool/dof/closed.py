"""Depth of field of a thin lens: hyperfocal distance and the ``approx`` and ``thin`` models.

Both models answer the same question -- the nearest and farthest object
distances whose blur disc on the sensor stays within the circle of
confusion c -- and return :class:`camtool.dof.limits.DofLimits`. The formulas are
arranged so that every term is a sum of positive quantities, except the
unavoidable H − s of the far limit, whose cancellation is the problem's own
condition (the far limit really is that sensitive near the hyperfocal
distance).

All lengths in millimetres. ``distance_from`` is ``"sensor"`` (the focal-plane
mark, camtool's default) or ``"lens"`` (the front principal plane).
"""

from __future__ import annotations

from typing import Any

from camtool.core.arrays import broadcast, ops, quiet
from camtool.core.errors import require, require_positive
from camtool.core.planes import FOCUS_PLANES, check_plane
from camtool.dof.limits import DofLimits
from camtool.geometry.thinlens import LensPlaneDistances, lens_distances

DISTANCE_PLANES = FOCUS_PLANES

_ULP = 1.1102230246251565e-16  # 2⁻⁵³: half the spacing of floats relative to their value


def check_inputs(focal_length_mm: Any, f_number: Any, coc_mm: Any) -> None:
    """Raise :class:`DomainError` unless f, N and c are positive and finite."""
    require_positive("focal_length_mm", focal_length_mm)
    require_positive("f_number", f_number, unit="")
    require_positive("coc_mm", coc_mm)


def hyperfocal_mm(focal_length_mm: Any, f_number: Any, coc_mm: Any, plus_f: bool = True) -> Any:
    """Hyperfocal distance from the lens in mm: H = f²/(N·c) + f, or f²/(N·c) without the +f.

    Focused at H, a thin lens renders everything from H/2 to infinity within
    the circle of confusion. The common approximation drops the +f term.

    Parameters
    ----------
    focal_length_mm : float or array, f > 0
    f_number : float or array, N > 0
    coc_mm : float or array, circle of confusion c > 0
    plus_f : bool
        True for the exact thin-lens definition, False for f²/(N·c).

    References
    ----------
    Wikipedia, "Hyperfocal distance"; H. M. Merklinger, *The INs and OUTs of
    FOCUS* (1992).

    Examples
    --------
    50 mm at f/8 with c = 0.03 mm (a classic worked example):

    >>> round(hyperfocal_mm(50.0, 8.0, 0.03))
    10467
    >>> round(hyperfocal_mm(50.0, 8.0, 0.03, plus_f=False))
    10417
    """
    check_inputs(focal_length_mm, f_number, coc_mm)
    h0 = focal_length_mm * focal_length_mm / (f_number * coc_mm)
    return h0 + focal_length_mm if plus_f else h0


def approx_dof(focal_length_mm: Any, f_number: Any, coc_mm: Any, distance_mm: Any) -> DofLimits:
    """Depth of field by the common approximation, in mm, with H₀ = f²/(N·c).

    near = H₀·s/(H₀ + s), far = H₀·s/(H₀ − s) (∞ for s ≥ H₀). It treats the
    distance s as typed, whatever plane it is measured from, and neglects f
    against s; its relative error is of order f/s.

    Parameters
    ----------
    focal_length_mm, f_number, coc_mm : float or array, all > 0
    distance_mm : float or array, focus distance s > 0 (``inf`` allowed)

    References
    ----------
    Wikipedia, "Depth of field", the hyperfocal-distance form of the DOF
    limits for moderate-to-large distances.

    Examples
    --------
    >>> r = approx_dof(50.0, 8.0, 0.03, 3000.0)
    >>> round(r.near_mm, 1), round(r.far_mm, 1)
    (2329.2, 4213.5)
    """
    check_inputs(focal_length_mm, f_number, coc_mm)
    require_positive("distance_mm", distance_mm, allow_inf=True)
    xp = ops(focal_length_mm, f_number, coc_mm, distance_mm)
    h0 = focal_length_mm * focal_length_mm / (f_number * coc_mm)
    s = distance_mm
    with quiet(xp):
        ratio = h0 / s  # 0 at infinity
        denominator = 1.0 + ratio
        near = h0 / denominator
        front = s / denominator
        beyond = s >= h0
        gap = xp.where(beyond, 1.0, ratio - 1.0)  # > 0 where used: s < h0
        far = xp.where(beyond, xp.inf, h0 / gap)
        rear = xp.where(beyond, xp.inf, s / gap)
        past_f = s > focal_length_mm
        m = xp.where(past_f, focal_length_mm / xp.where(past_f, s - focal_length_mm, 1.0), 0.0)
    return DofLimits(near, far, front, rear, front + rear, broadcast(h0, s, focal_length_mm), m)


def thin_hyperfocal_mm(focal_length_mm: Any, f_number: Any, coc_mm: Any, distance_from: str = "sensor") -> Any:
    """The hyperfocal distance of :func:`thin_dof` in the plane ``distance_from`` (mm), without the limits.

    From the lens H = f²/(N·c) + f; from the sensor H + v_H = H + f + N·c
    while H ≥ 2f. Below 2f (N·c > f, pinholes) every reachable focus lies
    beyond H, but D = u + v grows again as u drops under 2f, so the
    hyperfocal distance is the closest focus, 4f. A focus at or beyond it
    has a far limit of ∞.

    Examples
    --------
    >>> round(thin_hyperfocal_mm(50.0, 8.0, 0.03, "lens"), 1), round(thin_hyperfocal_mm(50.0, 8.0, 0.03), 2)
    (10466.7, 10516.91)
    """
    f = focal_length_mm
    h = f * f / (f_number * coc_mm) + f
    if distance_from != "sensor":
        return h
    if type(h) is float:  # one scene: no array machinery (auto asks for it on every call)
        return h + f + f_number * coc_mm if h >= 2.0 * f else 4.0 * f
    return ops(f, f_number, coc_mm).where(h >= 2.0 * f, h + f + f_number * coc_mm, 4.0 * f)


def thin_dof(
    focal_length_mm: Any, f_number: Any, coc_mm: Any, distance_mm: Any, distance_from: str = "sensor",
    focus: LensPlaneDistances | None = None, hyperfocal: Any = None,
) -> DofLimits:
    """Exact thin-lens depth of field in mm.

    With H₀ = f²/(N·c), H = H₀ + f and u the focus distance from the lens:

        near = u·H₀/(H₀ + u − f)        front = u − near = u(u − f)/(H₀ + u − f)
        far  = u·H₀/(H − u)             rear  = far − u  = u(u − f)/(H − u)

    and far = ∞ for u ≥ H. These equal D_N = u f²/(f² + Nc(u − f)) and
    D_F = u f²/(f² − Nc(u − f)). From the sensor plane the focus distance D is
    converted exactly to (u, v) (:func:`camtool.geometry.thinlens.lens_distances`) and
    the limits back with the lens-to-sensor spacing v fixed at its focus
    setting; the reported hyperfocal distance is then H + v_H = H + f + N·c
    (the closest focus 4f when H < 2f: every focus is then beyond H).

    Parameters
    ----------
    focal_length_mm, f_number, coc_mm : float or array, all > 0
    distance_mm : float or array
        Focus distance: from the sensor, ≥ 4f (1:1; the m ≤ 1 branch); from the lens, > f
        (between f and 2f the magnification m = f/(u − f) is above 1). ``inf`` allowed.
    distance_from : ``"sensor"`` or ``"lens"``
    focus : LensPlaneDistances or None
        From the sensor: (u, v) of ``distance_mm`` already converted by
        :func:`camtool.geometry.thinlens.lens_distances` (hiatus 0) and
        checked, for a caller that has them; None converts here.
    hyperfocal : float, array or None
        :func:`thin_hyperfocal_mm` of these f, N, c and plane, for a caller
        that has it; None computes it here.

    References
    ----------
    Wikipedia, "Depth of field" (derivation of the DOF limits); Greenleaf,
    *Photographic Optics* (1950), as implemented by DOFMaster.

    Examples
    --------
    >>> r = thin_dof(50.0, 8.0, 0.03, 3000.0, distance_from="lens")
    >>> round(r.near_mm, 1), round(r.far_mm, 1), round(r.hyperfocal_mm, 1)
    (2337.9, 4185.3, 10466.7)
    >>> thin_dof(50.0, 8.0, 0.03, float("inf")).far_mm
    inf
    """
    check_inputs(focal_length_mm, f_number, coc_mm)
    f = focal_length_mm
    xp = ops(f, f_number, coc_mm, distance_mm)
    h0 = f * f / (f_number * coc_mm)
    h = h0 + f
    if check_plane(distance_from, DISTANCE_PLANES) == "sensor":
        u, v = lens_distances(f, distance_mm) if focus is None else focus
        offset = v
        if hyperfocal is None:
            hyperfocal = thin_hyperfocal_mm(f, f_number, coc_mm, "sensor")
    else:
        require_positive("distance_mm", distance_mm, allow_inf=True)
        require("distance_mm", distance_mm, distance_mm > f,
                "more than {limit} from the lens (the focal length; between f and 2f the magnification is above 1)",
                limit=f)
        u, offset = distance_mm, 0.0
        if hyperfocal is None:
            hyperfocal = h
    with quiet(xp):
        u_minus_f = u - f
        denominator = 1.0 + (h0 - f) / u  # > 0 because u > f; 1 at infinity
        near = h0 / denominator
        front = u_minus_f / denominator
        # H − u is a whole number of ulps of H when positive; flooring it at about one ulp only
        # matters within rounding of the hyperfocal distance, where the comparison in the input
        # plane (beyond) decides, and keeps such a far limit finite (≤ u/ε) instead of inf or < 0.
        gap = xp.maximum(h - u, h * _ULP)
        beyond = distance_mm >= hyperfocal
        far = xp.where(beyond, xp.inf, u * h0 / gap)
        rear = xp.where(beyond, xp.inf, u * u_minus_f / gap)
        m = f / u_minus_f
        if distance_from == "sensor":
            near = near + offset
            far = far + offset
    return DofLimits(near, far, front, rear, front + rear, broadcast(hyperfocal, u), m)
