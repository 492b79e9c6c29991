"""Close-up and macro depth of field, written in the magnification m instead of a distance.

At a magnification m a lens of focal length f (front principal plane to
subject u = f(1 + 1/m), rear principal plane to sensor v = f(1 + m)) with
pupil magnification P and f-number N has the working f-number
N_w = N·(1 + m/P), and a circle of confusion c gives (docs/closeup.md §1)

    front = N·c·(1 + m/P) / (m² + m·N·c/f)
    rear  = N·c·(1 + m/P) / (m² − m·N·c/f)        (∞ when m·f ≤ N·c)
    total = 2·N·c·(1 + m/P) / m² · 1/(1 − (N·c/(f·m))²)

which is the thick-lens model of :mod:`camtool.dof.thick` rewritten exactly
(P = 1: the exact thin lens). Dropping N·c/(f·m), negligible in macro work,
leaves the photomacrography rule 2·N·c·(1 + m/P)/m².

Diffraction, wave-optics depth, the optimum aperture and the inverse
close-up problem (the CoC or f-number for a wanted depth) are here too, all
per row: an unsharp row is a result with a reason, not an exception.

All lengths in millimetres; scalars in, floats out; arrays in, arrays out.
"""

from __future__ import annotations

from typing import Any

from camtool.core.arrays import broadcast, ops, quiet
from camtool.core.errors import require, require_positive
from camtool.core.record import NamedTuple
from camtool.dof.diffraction import AIRY_FACTOR
from camtool.dof.limits import DofLimits

__all__ = [
    "DiffractionRow",
    "Optimum",
    "OptimumFocus",
    "closeup_dof",
    "coc_for_depth",
    "diffraction_row",
    "f_number_for_depth",
    "focus_spread_mm",
    "macro_depth_mm",
    "optimum_aperture",
    "optimum_for_limits",
    "wave_depth_mm",
]

_MM_PER_NM = 1e-6


def _check(f_number: Any, coc_mm: Any, magnification: Any, pupil_magnification: Any) -> None:
    require_positive("f_number", f_number, unit="")
    require_positive("coc_mm", coc_mm)
    require_positive("magnification", magnification, unit="")
    require_positive("pupil_magnification", pupil_magnification, unit="")


def closeup_dof(
    focal_length_mm: Any,
    f_number: Any,
    coc_mm: Any,
    magnification: Any,
    pupil_magnification: Any = 1.0,
    distance_from: str = "sensor",
    hiatus_mm: Any = 0.0,
) -> DofLimits:
    """Exact thin- (P = 1) or thick-lens depth of field in mm at a magnification m.

    front = N·c·(1 + m/P)/(m² + m·N·c/f), rear = N·c·(1 + m/P)/(m² − m·N·c/f)
    (∞ for m·f ≤ N·c: the focus is beyond the hyperfocal distance). The
    limits are u ∓ depth from the front principal plane (``"lens"``), with
    u = f(1 + 1/m), or from the sensor plane, u + v + δ with v = f(1 + m).
    The hyperfocal distance is the thin lens's, f²/(N·c) + f from the lens
    (+ f + N·c + δ from the sensor).

    Parameters
    ----------
    focal_length_mm : float or array, f > 0
    f_number : float or array, nominal N > 0
    coc_mm : float or array, c > 0
    magnification : float or array, m > 0 (any: 1:1 is 1, 5:1 is 5)
    pupil_magnification : float or array, P > 0 (1: thin lens)
    distance_from : ``"sensor"`` or ``"lens"``
    hiatus_mm : float or array, separation of the principal planes δ (sensor plane only)

    References
    ----------
    Wikipedia, "Depth of field", §"Close-up" (DOF ≈ 2Nc(1 + m/P)/m²);
    Cambridge in Colour, "Macro photography: depth of field"; docs/closeup.md §1.

    Examples
    --------
    1:1 at f/8 with c = 0.03 mm: the rule gives 2·8·0.03·2 = 0.96 mm.

    >>> r = closeup_dof(100.0, 8.0, 0.03, 1.0)
    >>> round(r.total_mm, 5), r.near_mm < 400.0 < r.far_mm
    (0.96001, True)
    """
    require_positive("focal_length_mm", focal_length_mm)
    _check(f_number, coc_mm, magnification, pupil_magnification)
    f, n, c, m, p = focal_length_mm, f_number, coc_mm, magnification, pupil_magnification
    xp = ops(f, n, c, m, p, hiatus_mm)
    nc = n * c
    k = nc / f  # m ≤ k: focused at or beyond the hyperfocal distance
    spread = nc * (1.0 + m / p)
    u = f + f / m
    with quiet(xp):
        front = spread / (m * (m + k))
        beyond = m <= k
        rear = xp.where(beyond, xp.inf, spread / (m * (m - k)))
        h = f * f / nc + f
        if distance_from == "sensor":
            offset = u + f + f * m  # u + v (+ δ)
            hyper = h + f + nc
            if not (isinstance(hiatus_mm, (int, float)) and hiatus_mm == 0.0):
                offset = offset + hiatus_mm
                hyper = hyper + hiatus_mm
        elif distance_from == "lens":
            offset = u
            hyper = h
        else:
            raise ValueError(f"distance_from must be 'sensor' or 'lens', not {distance_from!r}")
        near = offset - front
        far = offset + rear
    shape = getattr(near, "shape", None)
    same = (lambda x: x) if shape is None else (lambda x: x if getattr(x, "shape", None) == shape else broadcast(x, near))
    return DofLimits(near, far, front, rear, front + rear, same(hyper), same(m))


def macro_depth_mm(f_number: Any, coc_mm: Any, magnification: Any, pupil_magnification: Any = 1.0) -> Any:
    """The photomacrography rule for the total depth of field in mm: 2·N·c·(1 + m/P)/m².

    The exact result (:func:`closeup_dof`) divided by 1/(1 − (N·c/(f·m))²),
    which is within 10⁻⁶ of 1 at m ≥ 0.1 for ordinary f, N and c.

    References
    ----------
    Cambridge in Colour, "Macro photography: depth of field" (DOF = 2Nc(m+1)/m²);
    Zerene Stacker, "DOF Calculator" (classic DOF, pupil ratio P).

    Examples
    --------
    >>> round(macro_depth_mm(16.0, 0.03, 1.0), 4)  # Zerene Stacker's worked example: 1.92 mm
    1.92
    """
    _check(f_number, coc_mm, magnification, pupil_magnification)
    return 2.0 * f_number * coc_mm * (1.0 + magnification / pupil_magnification) / (magnification * magnification)


def wave_depth_mm(f_number: Any, magnification: Any, pupil_magnification: Any = 1.0, wavelength_nm: Any = 550.0) -> Any:
    """Wave-optics (quarter-wave) depth of field in mm: λ/NA² = 4·λ·N_w²/m².

    NA = m/(2·N_w) is the numerical aperture on the subject side and
    N_w = N·(1 + m/P) the working f-number. λ/NA² is the range over which the
    wavefront error of defocus stays within a quarter wave (Rayleigh's
    criterion, ±λ/(2·NA²) about the focus).

    References
    ----------
    Zerene Stacker, "DOF Calculator" and "DOF Estimates For Macro/Micro"
    (DOF (wave optics) = λ/NA²); Born and Wolf, *Principles of Optics*, §8.8.

    Examples
    --------
    >>> round(wave_depth_mm(16.0, 1.0), 3)  # Zerene Stacker: m = 1, f/16 (effective f/32): 2.253 mm
    2.253
    """
    require_positive("f_number", f_number, unit="")
    require_positive("magnification", magnification, unit="")
    working = f_number * (1.0 + magnification / pupil_magnification)
    return 4.0 * wavelength_nm * _MM_PER_NM * working * working / (magnification * magnification)


class DiffractionRow(NamedTuple):
    """Diffraction of one row (scalars) or many (arrays).

    ``airy_mm`` is the Airy diameter 2.44·λ·N_w; ``limit_f_number`` the
    nominal f-number at which it equals the CoC; ``sharp`` whether it is
    smaller (anything can be acceptably sharp); ``usable_coc_mm`` the CoC
    left for defocus, √(c² − airy²) (0 where nothing is sharp).
    """

    airy_mm: Any
    limit_f_number: Any
    sharp: Any
    usable_coc_mm: Any
    working_f_number: Any


def diffraction_row(f_number: Any, coc_mm: Any, magnification: Any = 0.0, pupil_magnification: Any = 1.0,
                    wavelength_nm: Any = 550.0) -> DiffractionRow:
    """Airy disc, diffraction-limit f-number and usable CoC of each row, without raising.

    Parameters
    ----------
    f_number : float or array, nominal N > 0
    coc_mm : float or array, c > 0
    magnification : float or array, m ≥ 0 at the focus
    pupil_magnification : float or array, P > 0
    wavelength_nm : float or array, λ > 0

    References
    ----------
    Born and Wolf, *Principles of Optics*, §8.5.2 (Airy disc 2.44·λ·N);
    docs/closeup.md §3 (how it is combined with defocus).

    Examples
    --------
    >>> r = diffraction_row(16.0, 0.03, 1.0)
    >>> round(r.airy_mm, 5), round(r.limit_f_number, 2), r.sharp
    (0.04294, 11.18, False)
    """
    require_positive("wavelength_nm", wavelength_nm, unit="nm")
    xp = ops(f_number, coc_mm, magnification, pupil_magnification, wavelength_nm)
    bellows = 1.0 + magnification / pupil_magnification
    working = f_number * bellows
    per_n = AIRY_FACTOR * wavelength_nm * _MM_PER_NM
    airy = per_n * working
    sharp = airy < coc_mm
    usable = xp.sqrt(xp.maximum((coc_mm - airy) * (coc_mm + airy), 0.0))
    return DiffractionRow(airy, coc_mm / (per_n * bellows), sharp, usable, working)


class Optimum(NamedTuple):
    """The f-number that makes the worst point sharpest, and the blur it leaves (mm)."""

    f_number: Any
    working_f_number: Any
    blur_mm: Any  # root-sum-square of defocus and diffraction (the convention of docs/closeup.md §3)
    blur_sum_mm: Any  # their plain sum: the conservative bound


def focus_spread_mm(focal_length_mm: Any, near_mm: Any, far_mm: Any) -> Any:
    """Image-side focus spread in mm between a near and a far subject at u₁ < u₂ from the lens: v₁ − v₂.

    v = f²/(u − f) + f; written f²·(u₂ − u₁)/((u₁ − f)(u₂ − f)) so that a far
    subject at infinity gives f²/(u₁ − f).

    Examples
    --------
    >>> round(focus_spread_mm(100.0, 200.0, 300.0), 6)
    50.0
    >>> round(focus_spread_mm(50.0, 5050.0, float("inf")), 6)
    0.5
    """
    require_positive("focal_length_mm", focal_length_mm)
    require("near_mm", near_mm, near_mm > focal_length_mm, "more than the focal length from the lens")
    require("far_mm", far_mm, far_mm >= near_mm, "at least the near limit")
    xp = ops(focal_length_mm, near_mm, far_mm)
    f2 = focal_length_mm * focal_length_mm
    with quiet(xp):
        to_far = xp.where(xp.isinf(far_mm), 0.0, 1.0 / (far_mm - focal_length_mm))
    return f2 * (1.0 / (near_mm - focal_length_mm) - to_far)


def optimum_aperture(spread_mm: Any, magnification: Any = 0.0, pupil_magnification: Any = 1.0,
                     wavelength_nm: Any = 550.0) -> Optimum:
    """The f-number balancing defocus against diffraction for an image-side focus spread Δ (mm).

    Focused half-way (on the image side) between the near and far points,
    each is blurred by defocus Δ/(2·N_w) and by diffraction 2.44·λ·N_w. Both
    the root-sum-square and the plain sum of the two are smallest where they
    are equal:

        N_w = √(Δ / (2·2.44·λ)),   N = N_w / (1 + m/P),

    leaving √2·2.44·λ·N_w (root-sum-square, Hansma) or 2·2.44·λ·N_w (sum).
    At m = 0 this is Hansma's view-camera rule; the close-up form works in
    the working f-number because both blurs are set by the image-side cone.

    Parameters
    ----------
    spread_mm : float or array
        Focus spread Δ > 0: the rail travel between focusing on the near and
        on the far point (mm).
    magnification : float or array
        m ≥ 0 at the focus (0: distant subjects).
    pupil_magnification : float or array, P > 0
    wavelength_nm : float or array, λ > 0

    References
    ----------
    P. K. Hansma, "View camera focusing in practice", *Photo Techniques*,
    March/April 1996; S. Peterson, "Image sharpness and focusing the view
    camera", ibid.; Q.-T. Luong, "How to select the f-stop", Large Format
    Page (Hansma's table); P. Service, "Optimal aperture in photography. 1.
    Theory" (2013).

    Examples
    --------
    >>> round(optimum_aperture(1.0).f_number, 2)
    19.3
    """
    require_positive("focus_spread_mm", spread_mm)
    require_positive("wavelength_nm", wavelength_nm, unit="nm")
    xp = ops(spread_mm, magnification, pupil_magnification, wavelength_nm)
    per_n = AIRY_FACTOR * wavelength_nm * _MM_PER_NM
    working = xp.sqrt(spread_mm / (2.0 * per_n))
    airy = per_n * working
    return Optimum(working / (1.0 + magnification / pupil_magnification), working, airy * xp.sqrt(2.0), 2.0 * airy)


def coc_for_depth(f_number: Any, magnification: Any, depth_mm: Any, pupil_magnification: Any = 1.0) -> Any:
    """The circle of confusion in mm that gives a total depth d at m and N: c = d·m²/(2·N·(1 + m/P)).

    The inverse of :func:`macro_depth_mm` (the close-up rule, within
    (N·c/(f·m))² of the exact depth).

    Examples
    --------
    >>> round(coc_for_depth(4.0, 2.5, 0.2), 6)
    0.044643
    """
    require_positive("depth_mm", depth_mm)
    require_positive("f_number", f_number, unit="")
    require_positive("magnification", magnification, unit="")
    return depth_mm * magnification * magnification / (2.0 * f_number * (1.0 + magnification / pupil_magnification))


def f_number_for_depth(coc_mm: Any, magnification: Any, depth_mm: Any, pupil_magnification: Any = 1.0) -> Any:
    """The nominal f-number giving a total depth d at m with CoC c: N = d·m²/(2·c·(1 + m/P)).

    Examples
    --------
    >>> round(f_number_for_depth(0.03, 2.5, 0.2), 4)
    5.9524
    """
    require_positive("depth_mm", depth_mm)
    require_positive("coc_mm", coc_mm)
    require_positive("magnification", magnification, unit="")
    return depth_mm * magnification * magnification / (2.0 * coc_mm * (1.0 + magnification / pupil_magnification))


class OptimumFocus(NamedTuple):
    """Where to focus between a near and a far subject, and the optimum aperture there (mm)."""

    distance_mm: Any  # focus distance, in the plane of the limits given
    magnification: Any  # at that focus
    focus_spread_mm: Any  # image-side spread Δ between the near and far images
    optimum: Optimum


def optimum_for_limits(focal_length_mm: Any, near_mm: Any, far_mm: Any, distance_from: str = "sensor",
                       hiatus_mm: Any = 0.0, pupil_magnification: Any = 1.0,
                       wavelength_nm: Any = 550.0) -> OptimumFocus:
    """Focus half-way between the images of a near and a far subject, and the optimum f-number there.

    The near and far subjects (from the sensor: the m ≤ 1 branch) are imaged
    at v₁ > v₂; the sensor goes to v = (v₁ + v₂)/2, which focuses on
    u = f·v/(v − f) at m = v/f − 1, and :func:`optimum_aperture` of the
    spread Δ = v₁ − v₂ at that m gives the f-number.

    Examples
    --------
    >>> r = optimum_for_limits(150.0, 2000.0, float("inf"), distance_from="lens")
    >>> round(r.focus_spread_mm, 4), round(r.distance_mm, 1), round(r.optimum.f_number, 1)
    (12.1622, 3850.0, 64.7)
    """
    from camtool.geometry.thinlens import focus_geometry, image_distance_mm

    require_positive("focal_length_mm", focal_length_mm)
    require_positive("near_mm", near_mm)
    require_positive("far_mm", far_mm, allow_inf=True)
    require("far_mm", far_mm, far_mm > near_mm, "beyond the near limit")
    f = focal_length_mm
    u_near = focus_geometry(f, near_mm, distance_from, hiatus_mm).object_mm
    u_far = focus_geometry(f, far_mm, distance_from, hiatus_mm).object_mm
    spread = focus_spread_mm(f, u_near, u_far)
    v = 0.5 * (image_distance_mm(f, u_near) + image_distance_mm(f, u_far))
    m = (v - f) / f
    u = f + f / m
    distance = u + v + hiatus_mm if distance_from == "sensor" else u
    return OptimumFocus(distance, m, spread, optimum_aperture(spread, m, pupil_magnification, wavelength_nm))
