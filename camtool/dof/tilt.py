"""Depth of field of a tilted lens: the wedge between two planes through the hinge line.

The ``thin`` model is the thick one with P = 1 and δ = 0. The ``thick`` model
puts the principal planes and the pupils where they are (docs/tilt.md §3):

- object space is imaged by the thin-lens collineation about the front
  principal point H, image space is that image moved by the hiatus δ along
  the lens axis; so the hinge rule holds about H (J = f/sin θ from H,
  parallel to the film), and the film counts from the rear principal point H′
  (its perpendicular distance v from H′);
- the cone of light that blurs a point comes from the exit pupil E′, of
  diameter P·f/N, a distance f(1 − P) behind H′ along the tilted axis, so
  f(1 − P)·cos θ nearer the film than H′;
- a point imaged w from E′ (measured perpendicular to the film) makes a blur
  P·(f/N)·|w − w₀|/w wide on the film w₀ from E′, across the tilt: exactly,
  since the aperture's extent parallel to the hinge line is not foreshortened
  by the tilt. The blur reaches c on the two image planes parallel to the
  film w₀·d/(d ∓ c) from E′ (d = P·f/N);
- planes parallel to the film in image space are the images of planes
  through the hinge line: the near and far limits of sharpness are planes
  through the hinge line (Merklinger's wedge), crossing the line of sight
  at 1/k = 1/(cos θ/f − 1/v) for their v.

Distances from H along the line of sight are written by their reciprocal k
so that a plane parallel to the line of sight (k = 0) and one crossing
behind the lens (k < 0) need no special case. Lengths in mm, angles in
degrees.
"""

from __future__ import annotations

from typing import Any

from camtool.core.arrays import broadcast, ops, quiet
from camtool.core.errors import DomainError, require
from camtool.core.record import NamedTuple
from camtool.geometry.tilt import axis_reciprocal, hinge_distance_mm, plane_angle_deg, sight_reciprocal

__all__ = [
    "ALONG",
    "TiltLens",
    "TiltWedge",
    "film_for_focus",
    "hyperfocal_film",
    "optimum_f_number",
    "required_f_number",
    "tilt_wedge",
]

ALONG = ("sight", "axis")
"""Lines focus, near and far are measured along: the camera's line of sight (normal to the film through
the lens) or the tilted lens axis."""


class TiltLens(NamedTuple):
    """The lens: focal length f (mm), pupil magnification P and hiatus δ (mm); thin with P = 1, δ = 0."""

    focal_length_mm: float
    pupil_magnification: float = 1.0
    hiatus_mm: float = 0.0

    @property
    def exit_pupil_mm(self) -> float:
        """Distance of the exit pupil behind H′ along the axis: f(1 − P)."""
        return self.focal_length_mm * (1.0 - self.pupil_magnification)

    @property
    def entrance_pupil_mm(self) -> float:
        """Distance of the entrance pupil in front of H along the axis: e = f(1 − 1/P)."""
        return self.focal_length_mm * (1.0 - 1.0 / self.pupil_magnification)


class TiltWedge(NamedTuple):
    """A tilted lens's plane of focus and depth-of-field wedge (lengths mm, angles degrees from the film plane).

    ``film_mm`` is v, the film's perpendicular distance from H′;
    ``k_focus``, ``k_near``, ``k_far`` the reciprocals of where the plane of
    sharp focus and the near and far limit planes cross the line of sight
    through H (1/mm); the ``*_deg`` their angles from the film plane.
    """

    tilt_deg: float
    hinge_mm: float
    film_mm: float
    k_focus: float
    k_near: float
    k_far: float
    focus_deg: float
    near_deg: float
    far_deg: float


def _check(lens: TiltLens, tilt_deg: Any) -> Any:
    """Raise DomainError for a lens or tilt outside the model's domain; return the ops namespace."""
    f, p, delta = lens
    xp = ops(f, p, delta, tilt_deg)
    require("focal_length_mm", f, xp.isfinite(f) & (f > 0), "> 0 mm")
    require("pupil_magnification", p, xp.isfinite(p) & (p > 0), "> 0")
    require("hiatus_mm", delta, xp.isfinite(delta), "a finite length in mm")
    require("tilt_deg", tilt_deg, xp.fabs(tilt_deg) < 90.0, "between −90° and 90°")
    return xp


def film_for_focus(lens: TiltLens, tilt_deg: Any, distance_mm: Any, along: str = "sight",
                   distance_from: str = "lens") -> Any:
    """Film distance v in mm (perpendicular to the film, from H′) that puts the plane of sharp focus through a point.

    The point is where the plane crosses the line of sight (``along="sight"``:
    1/u + 1/v = cos θ/f) or the lens axis (``"axis"``: 1/s + 1/s′ = 1/f,
    v = s′·cos θ), ``distance_mm`` from H (``"lens"``) or from the film
    (``"sensor"``: along the sight line u + v + δ·cos θ, along the axis
    s + s′ + δ). Scalars or arrays (broadcast).

    Parameters
    ----------
    lens : TiltLens
    tilt_deg : float or array, |θ| < 90
    distance_mm : float or array, > the focal length along that line (from the sensor ≥ 4 times it,
        plus the hiatus); ``inf`` allowed
    along : ``"sight"`` or ``"axis"``
    distance_from : ``"lens"`` or ``"sensor"``

    References
    ----------
    Merklinger, *Focusing the View Camera* (1993), ch. 4; docs/tilt.md §2–3.

    Examples
    --------
    >>> round(film_for_focus(TiltLens(50.0), 0.0, 3000.0), 6)
    50.847458
    >>> film_for_focus(TiltLens(90.0), [0.0, 60.0], float("inf")).round(6).tolist()  # f/cos θ
    [90.0, 180.0]
    """
    _check(lens, tilt_deg)
    if along not in ALONG or distance_from not in ("lens", "sensor"):
        raise ValueError(f"along must be one of {ALONG} and distance_from 'lens' or 'sensor'")
    f = lens.focal_length_mm
    xp = ops(f, lens.hiatus_mm, tilt_deg, distance_mm)
    cos = xp.cos(xp.radians(tilt_deg))
    g = f if along == "axis" else f / cos  # the lens equation's focal length along this line
    with quiet(xp):
        if distance_from == "sensor":
            offset = lens.hiatus_mm * (1.0 if along == "axis" else cos)
            span = distance_mm - offset
            require("distance_mm", distance_mm, span >= 4.0 * g,
                    "at least {limit} from the sensor (1:1 along this line)", limit=4.0 * g + offset)
            image = 2.0 * g / (1.0 + xp.sqrt(xp.maximum(1.0 - 4.0 * g / span, 0.0)))
        else:
            require("distance_mm", distance_mm, distance_mm > g,
                    "beyond the focal length along this line, {limit}", limit=g)
            image = g / (1.0 - g / distance_mm)
    return image * cos if along == "axis" else image


def tilt_wedge(lens: TiltLens, f_number: Any, coc_mm: Any, tilt_deg: Any, film_mm: Any) -> TiltWedge:
    """The plane of sharp focus and the two limiting planes of the depth-of-field wedge (mm, 1/mm, degrees).

    With v the film's distance from H′ and p = f(1 − P)·cos θ, the film is
    w₀ = v − p from the exit pupil, d = P·f/N, and

        v_near = p + w₀·d/(d − c),   v_far = p + w₀·d/(d + c),
        k = cos θ/f − 1/v   for v, v_near, v_far,

    each plane through the hinge line at J = f/sin θ (angle from the film
    atan2(sin θ, f·k)). With θ = 0 they are the ordinary near and far limits.
    Scalars or arrays (broadcast).

    Parameters
    ----------
    lens : TiltLens
    f_number : float or array, N > 0
    coc_mm : float or array, c > 0, with c < P·f/N
    tilt_deg : float or array, |θ| < 90
    film_mm : float or array, v > f(1 − P)·cos θ (the film behind the exit pupil)

    References
    ----------
    H. M. Merklinger, "View Camera Focus and Depth of Field, Part II",
    *View Camera*, September/October 1996, pp. 56–58 (the wedge about the
    hinge line); L. Evens, "View Camera Geometry" (2008); docs/tilt.md §3.

    Examples
    --------
    >>> w = tilt_wedge(TiltLens(150.0), 11.0, 0.1, 7.0, 152.0)
    >>> round(w.hinge_mm, 1), round(1 / w.k_focus), round(1 / w.k_near), round(w.focus_deg, 2)
    (1230.8, 26297, 11591, 87.32)
    >>> w.k_far < 0  # the far limit plane dips below the line of sight: sharp to infinity
    True
    """
    _check(lens, tilt_deg)
    f = lens.focal_length_mm
    xp = ops(f, lens.pupil_magnification, lens.hiatus_mm, f_number, coc_mm, tilt_deg, film_mm)
    require("f_number", f_number, xp.isfinite(f_number) & (f_number > 0), "> 0")
    require("coc_mm", coc_mm, xp.isfinite(coc_mm) & (coc_mm > 0), "> 0 mm")
    cos = xp.cos(xp.radians(tilt_deg))
    p = lens.exit_pupil_mm * cos
    w0 = film_mm - p
    require("film_mm", film_mm, xp.isfinite(film_mm) & (w0 > 0), "behind the exit pupil")
    d = lens.pupil_magnification * f / f_number
    require("coc_mm", coc_mm, coc_mm < d, "smaller than the exit pupil, {limit}", limit=d,
            detail="a blur that large would make everything sharp")
    v_near = p + w0 * d / (d - coc_mm)
    v_far = p + w0 * d / (d + coc_mm)
    k_focus, k_near, k_far = (cos / f - 1.0 / v for v in (film_mm, v_near, v_far))
    return TiltWedge(broadcast(tilt_deg, k_near), broadcast(hinge_distance_mm(f, tilt_deg), k_near),
                     broadcast(film_mm, k_near), broadcast(k_focus, k_near), k_near, k_far,
                     broadcast(plane_angle_deg(f, tilt_deg, k_focus), k_near), plane_angle_deg(f, tilt_deg, k_near),
                     plane_angle_deg(f, tilt_deg, k_far))


def hyperfocal_film(lens: TiltLens, f_number: Any, coc_mm: Any, tilt_deg: Any, along: str = "sight") -> Any:
    """Film distance v (from H′, mm) that puts the far limit plane parallel to the line of sight (or the lens axis).

    Merklinger's hyperfocal setting of the wedge (``along="sight"``): the far
    limit is the plane through the hinge parallel to the line of sight, so
    v_far = f/cos θ; then w₀ = (v_far − p)·(d + c)/d. Along the axis the far
    plane is parallel to the lens axis instead: v_far = f·cos θ. With a thin
    lens the focus is H/cos θ along the line of sight, H = f²/(N·c) + f.

    Parameters
    ----------
    lens : TiltLens
    f_number, coc_mm, tilt_deg : float or array (as :func:`tilt_wedge`)
    along : ``"sight"`` or ``"axis"``

    References
    ----------
    Merklinger, "View Camera Focus and Depth of Field, Part II" (1996): at the
    hyperfocal distance the wedge extends J either side of the plane of focus.

    Examples
    --------
    >>> lens = TiltLens(150.0)
    >>> w = tilt_wedge(lens, 11.0, 0.1, 5.0, hyperfocal_film(lens, 11.0, 0.1, 5.0))
    >>> round(w.k_far, 12), round(1 / w.k_focus, 3), round(1 / w.k_near, 3)
    (0.0, 20683.251, 10341.626)
    """
    _check(lens, tilt_deg)
    f = lens.focal_length_mm
    xp = ops(f, f_number, coc_mm, tilt_deg)
    cos = xp.cos(xp.radians(tilt_deg))
    p = lens.exit_pupil_mm * cos
    d = lens.pupil_magnification * f / f_number
    v_far = f / cos if along == "sight" else f * cos
    return p + (v_far - p) * (d + coc_mm) / d


def required_f_number(lens: TiltLens, coc_mm: Any, tilt_deg: Any, film_mm: Any, at_mm: Any,
                      half_depth_mm: Any) -> Any:
    """f-number whose wedge spans ±h about the plane of focus at x = D along the line of sight (parallel to the film).

    At D the limit planes lie J·D·|k − k_focus| from the plane of focus,
    parallel to the film; each side gives N in closed form (with
    p = f(1 − P)·cos θ and w the exit-pupil distances):
    near side 1/v_n = 1/v − h/(J·D), N = P·f·(1 − w₀/w_n)/c; far side
    1/v_f = 1/v + h/(J·D), N = P·f·(w₀/w_f − 1)/c. The larger is returned.
    For the thin lens both sides give N = h·f·v/(J·D·c).

    Parameters
    ----------
    lens : TiltLens
    coc_mm, tilt_deg, film_mm : float or array (as :func:`tilt_wedge`; θ ≠ 0)
    at_mm : float or array, D > 0 from H along the line of sight
    half_depth_mm : float or array, h > 0

    Raises
    ------
    DomainError
        (param ``half_depth_mm``) no f-number reaches it (the near side would
        need the image beyond infinity).

    Examples
    --------
    >>> lens = TiltLens(150.0)
    >>> v = 151.0
    >>> n = required_f_number(lens, 0.1, 7.0, v, 10000.0, 500.0)
    >>> w = tilt_wedge(lens, n, 0.1, 7.0, v)
    >>> round(w.hinge_mm * 10000.0 * (w.k_near - w.k_focus), 6)
    500.0
    """
    _check(lens, tilt_deg)
    f = lens.focal_length_mm
    xp = ops(f, coc_mm, tilt_deg, film_mm, at_mm, half_depth_mm)
    j = xp.fabs(hinge_distance_mm(f, tilt_deg))
    cos = xp.cos(xp.radians(tilt_deg))
    p = lens.exit_pupil_mm * cos
    w0 = film_mm - p
    shift = half_depth_mm / (j * at_mm)
    near_recip = 1.0 / film_mm - shift
    require("half_depth_mm", half_depth_mm, near_recip > 0, "small enough for a real near limit")
    w_near = 1.0 / near_recip - p
    w_far = 1.0 / (1.0 / film_mm + shift) - p
    pf = lens.pupil_magnification * f
    return xp.maximum(pf * (1.0 - w0 / w_near), pf * (w0 / w_far - 1.0)) / coc_mm


def optimum_f_number(needed_f_number: Any, coc_mm: Any, wavelength_nm: Any = 550.0,
                     magnification: Any = 0.0, pupil_magnification: Any = 1.0) -> tuple[Any, Any]:
    """The f-number balancing the wedge's defocus blur against diffraction, and the total blur there (mm).

    At the wedge's edge the defocus blur is c·N₀/N (it scales with the
    aperture: the image points are fixed), the Airy disc 2.44·λ·N·(1 + m/P);
    their quadrature sum is least where the two are equal:
    N = √(c·N₀/(2.44·λ·(1 + m/P))), total blur √2 times either.

    Parameters
    ----------
    needed_f_number : float or array, N₀ > 0 (the f-number whose wedge is just right, blur c at its edge)
    coc_mm : float or array, c > 0
    wavelength_nm : float or array, λ
    magnification, pupil_magnification : float or array, m ≥ 0 and P > 0 (working f-number N·(1 + m/P))

    References
    ----------
    J. Conrad, "Depth of Field in Depth" (2006), §"Diffraction"; B. Hansma,
    "View Camera Focusing in Practice", *Photo Techniques*, March/April 1996.

    Examples
    --------
    >>> n, blur = optimum_f_number(11.0, 0.1)
    >>> round(n, 2), round(blur * 1000, 1)
    (28.63, 54.3)
    """
    xp = ops(needed_f_number, coc_mm, wavelength_nm, magnification, pupil_magnification)
    require("f_number", needed_f_number, needed_f_number > 0, "> 0")
    airy_per_n = 2.44 * wavelength_nm * 1e-6 * (1.0 + magnification / pupil_magnification)
    n = xp.sqrt(coc_mm * needed_f_number / airy_per_n)
    return n, xp.sqrt(2.0) * airy_per_n * n


def sight_to_axis(lens: TiltLens, tilt_deg: float, k: float) -> float:
    """Reciprocal crossing of the lens axis (from H) of the plane crossing the line of sight at 1/k."""
    return axis_reciprocal(lens.focal_length_mm, tilt_deg, k)


def axis_to_sight(lens: TiltLens, tilt_deg: float, k_axis: float) -> float:
    """Inverse of :func:`sight_to_axis`."""
    return sight_reciprocal(lens.focal_length_mm, tilt_deg, k_axis)


def degenerate(error: DomainError) -> bool:
    """True for the errors that mean the wedge does not exist (for callers that skip such rows)."""
    return error.param in ("coc_mm", "film_mm")
