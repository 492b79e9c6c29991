"""The ``wave`` rung: depth of field of a perfect thin lens defined by contrast, diffraction and defocus together.

A scene is sharp enough at an object distance x when the modulation transfer
function of the lens at a chosen spatial frequency ν (on the sensor) is at
least a chosen level L. The MTF is that of a perfect circular pupil with
defocus (:mod:`camtool.optics.transfer`: the pupil autocorrelation of
Hopkins 1955, by quadrature), so diffraction and defocus enter together,
with no root-sum-square of blur diameters.

**Defocus of an object at x.** With the lens focused at u (image at v, the
sensor held there), the wave converging to the image of x, measured on the
reference sphere centred on the sensor, has the defocus coefficient

    W₂₀ = (A²/8)·(1/x − 1/u),   A = f/N the aperture diameter,

(the sag difference of two spheres of radii v and v_x over the pupil radius
A/2, with 1/v − 1/v_x = 1/x − 1/u). It is linear in object vergence. The
frequency in units of the cut-off is s = ν·λ·N_w with N_w = v/A = N·(1 + m)
the working f-number, fixed by the sensor position. So with W* the defocus at
which the MTF at s falls to L (:func:`camtool.optics.transfer.defocus_at_level`),

    1/near = 1/u + k,   1/far = 1/u − k,   k = 8·λ·W*/A²,

and the far limit is infinite from the hyperfocal distance H = 1/k (k taken
at the sensor position of a focus at H) onwards.

**Limits.** In the geometric limit (large aperture, so s → 0) the MTF of the
defocused pupil tends to 2·J₁(π·b·ν)/(π·b·ν) of a blur disc of diameter b
(the blur the ``thin`` rung measures), so the default criterion — the level
2·J₁(π)/π ≈ 0.181 at ν = 1/c — gives back the ``thin`` limits there. With
the lens stopped down, the in-focus MTF itself falls; when it is below L
nothing is sharp enough (:class:`ContrastUnreachable`, with the largest
f-number that still reaches L).

**Criterion.** ``mtf:LEVEL@FREQ``: LEVEL a contrast (0.3 or 30%), FREQ in line
pairs per mm on the sensor, or ``coc`` for ν = 1/c — one line pair per
circle of confusion, the convention that pairs a CoC of 0.2 mm on a print
with 5 lp/mm (Wikipedia, "Circle of confusion", after S. F. Ray, *Applied
Photographic Optics*, 3rd ed., 2002, p. 52). The default is
``mtf:0.181@coc``, i.e. :data:`DEFAULT_CRITERION`.

The rung is a thin perfect lens: pupil magnification, hiatus and aberrations
are left out, as in ``thin``.
"""

from __future__ import annotations

import math
from typing import Any

from camtool.core.errors import DomainError, first_bad
from camtool.core.record import NamedTuple
from camtool.dof.limits import DofLimits
from camtool.optics.roots import golden_section

__all__ = [
    "DEFAULT_CRITERION",
    "ContrastOptimum",
    "ContrastUnreachable",
    "Criterion",
    "contrast_at",
    "contrast_depth_mm",
    "contrast_optimum",
    "criterion_frequency",
    "largest_contrast_f_number",
    "wave_dof",
]

_MM_PER_NM = 1e-6


class Criterion(NamedTuple):
    """A contrast criterion: the MTF ``level`` at ``frequency_lpmm`` on the sensor (None: 1/c, one line pair per CoC)."""

    level: float
    frequency_lpmm: float | None = None

    def label(self) -> str:
        """``mtf:0.181@coc`` or ``mtf:0.3@40``: how the criterion is typed.

        >>> Criterion(0.3, 40.0).label(), DEFAULT_CRITERION.label()
        ('mtf:0.3@40', 'mtf:0.181@coc')
        """
        at = "coc" if self.frequency_lpmm is None else f"{self.frequency_lpmm:g}"
        return f"mtf:{self.level:.3g}@{at}"


DEFAULT_CRITERION = Criterion(0.18119175498741530, None)
"""2·J₁(π)/π at ν = 1/c: the contrast a geometric blur disc of one CoC leaves at one line pair per CoC."""


class ContrastUnreachable(DomainError):
    """The in-focus MTF at the criterion's frequency is already below its level: nothing is sharp enough.

    ``largest_f_number`` is the nominal f-number at which the in-focus MTF
    just reaches the level at this focus.
    """

    def __init__(self, f_number: float, largest_f_number: float, criterion: Criterion, frequency_lpmm: float,
                 wavelength_nm: float) -> None:
        self.largest_f_number = largest_f_number
        self.criterion = criterion
        super().__init__(
            "f_number", f_number,
            f"below f/{largest_f_number:.3g} for any depth of field by {criterion.label()} at {wavelength_nm:g} nm",
            detail=f"nothing is sharp enough: even in focus the MTF at {frequency_lpmm:.3g} lp/mm is below "
                   f"{criterion.level:.3g}",
        )


def criterion_frequency(criterion: Criterion, coc_mm: Any) -> Any:
    """The criterion's frequency in lp/mm on the sensor: its own, or 1/c for ``@coc``.

    >>> criterion_frequency(DEFAULT_CRITERION, 0.025)
    40.0
    """
    return 1.0 / coc_mm if criterion.frequency_lpmm is None else criterion.frequency_lpmm


def largest_contrast_f_number(criterion: Criterion, coc_mm: Any, magnification: Any = 0.0,
                              wavelength_nm: Any = 550.0) -> Any:
    """The largest nominal f-number whose in-focus MTF still reaches the criterion's level: s*/(ν·λ·(1 + m)).

    s* solves MTF₀(s*) = L (the diffraction-limited MTF); beyond this f-number
    nothing is sharp by the criterion, however it is focused.

    Examples
    --------
    Full frame, c = 0.03 mm: the default criterion holds to about f/39 —
    1.7 times the f-number at which the Airy disc fills the CoC (f/22.4):

    >>> round(largest_contrast_f_number(DEFAULT_CRITERION, 0.03), 1)
    38.6
    """
    from camtool.optics.transfer import frequency_at_level

    s_star = frequency_at_level(criterion.level)
    nu = criterion_frequency(criterion, coc_mm)
    return s_star / (nu * wavelength_nm * _MM_PER_NM * (1.0 + magnification))


def contrast_at(focal_length_mm: Any, f_number: Any, focus_mm: Any, object_mm: Any, frequency_lpmm: Any,
                wavelength_nm: Any = 550.0) -> Any:
    """MTF at ν on the sensor of an object at x (from the lens) with a perfect lens focused at u (from the lens).

    The through-focus MTF in object space: s = ν·λ·N·v/f, W₂₀ = (A²/8λ)(1/x − 1/u).

    Examples
    --------
    >>> round(contrast_at(50.0, 8.0, 3000.0, 3000.0, 40.0), 4)  # in focus: the diffraction-limited MTF
    0.7733
    """
    from camtool.optics.transfer import defocus_mtf

    v = focal_length_mm / (1.0 - focal_length_mm / focus_mm)
    lam = wavelength_nm * _MM_PER_NM
    aperture = focal_length_mm / f_number
    s = frequency_lpmm * lam * v / aperture
    w = aperture * aperture / (8.0 * lam) * (1.0 / object_mm - 1.0 / focus_mm)
    return defocus_mtf(s, w)


def contrast_depth_mm(f_number: float, magnification: float, criterion: Criterion, coc_mm: float = 0.03,
                      pupil_magnification: float = 1.0, wavelength_nm: float = 550.0) -> float:
    """Total depth of field in mm at magnification m by a contrast criterion, close up: 16·λ·N_w²·W*/m².

    The image-side defocus Δz gives W₂₀ = Δz/(8·λ·N_w²), N_w = N·(1 + m/P), and
    the object-side depth is the image-side one over m² (the close-up closed
    form, as λ/NA² is); W* is the defocus at which the MTF at s = ν·λ·N_w falls
    to the level. With W* = 1/4 (a quarter wave) it is λ/NA² = 4·λ·N_w²/m².

    Examples
    --------
    1:1 at f/8 (f/16 working), 50 lp/mm at 30 %:

    >>> round(contrast_depth_mm(8.0, 1.0, Criterion(0.3, 50.0)), 4)
    0.6626
    """
    from camtool.core.errors import require_positive
    from camtool.optics.transfer import defocus_at_level

    require_positive("magnification", magnification, unit="")
    lam = wavelength_nm * _MM_PER_NM
    n_w = f_number * (1.0 + magnification / pupil_magnification)
    nu = float(criterion_frequency(criterion, coc_mm))
    w = defocus_at_level(nu * lam * n_w, criterion.level)
    if not math.isfinite(w):
        largest = largest_contrast_f_number(criterion, coc_mm, magnification / pupil_magnification, wavelength_nm)
        raise ContrastUnreachable(f_number, float(largest), criterion, nu, wavelength_nm)
    return 16.0 * lam * n_w * n_w * w / (magnification * magnification)


def wave_dof(focal_length_mm: Any, f_number: Any, coc_mm: Any, distance_mm: Any, distance_from: str = "sensor",
             criterion: Criterion | None = None, wavelength_nm: float = 550.0, focus: Any = None) -> DofLimits:
    """Near and far limits where the perfect lens's MTF at the criterion's frequency falls to its level.

    Parameters
    ----------
    focal_length_mm, f_number, coc_mm : float or array, > 0
        c sets the frequency of an ``@coc`` criterion (ν = 1/c).
    distance_mm : float or array
        Focus distance from ``distance_from`` (``inf`` allowed).
    distance_from : ``"sensor"`` or ``"lens"``
    criterion : Criterion or None
        None: :data:`DEFAULT_CRITERION`.
    wavelength_nm : float
    focus : LensPlaneDistances or None
        (u, v) of the focus when the caller has converted it.

    Raises
    ------
    ContrastUnreachable
        The in-focus MTF is below the level (a :class:`DomainError` on
        ``f_number`` naming the largest f-number that reaches it).

    Examples
    --------
    50 mm f/8 at 3 m from the lens, c = 0.03 mm: wider than the thin lens's
    2337.9 to 4185.3 mm (a defocus of under a wave costs less contrast than
    the geometric blur disc suggests), where the root-sum-square of the Airy
    disc would make it narrower (docs/wave.md):

    >>> r = wave_dof(50.0, 8.0, 0.03, 3000.0, "lens")
    >>> round(r.near_mm, 1), round(r.far_mm, 1), round(r.hyperfocal_mm)
    (2268.4, 4428.3, 9210)
    """
    import numpy as np

    from camtool.core.planes import FOCUS_PLANES, check_plane
    from camtool.dof.closed import check_inputs
    from camtool.geometry.thinlens import focus_geometry
    from camtool.optics.transfer import defocus_at_level

    check_inputs(focal_length_mm, f_number, coc_mm)
    plane = check_plane(distance_from, FOCUS_PLANES)
    criterion = criterion or DEFAULT_CRITERION
    scalar = all(isinstance(v, (int, float)) for v in (focal_length_mm, f_number, coc_mm, distance_mm))
    if focus is None:
        g = focus_geometry(focal_length_mm, distance_mm, plane)
        u, v = g.object_mm, g.image_mm
    else:
        u, v = focus
    f, n, c, d, u, v = (np.asarray(x, dtype=float) for x in (focal_length_mm, f_number, coc_mm, distance_mm, u, v))
    f, n, c, d, u, v = np.broadcast_arrays(f, n, c, d, u, v)
    lam = wavelength_nm * _MM_PER_NM
    nu = np.broadcast_to(np.asarray(criterion_frequency(criterion, c), dtype=float), f.shape)
    aperture = f / n
    s_focus = nu * lam * v / aperture
    w_focus = defocus_at_level(s_focus, criterion.level)
    bad = ~np.isfinite(w_focus)
    if np.any(bad):
        m = v / u
        largest = largest_contrast_f_number(criterion, c, m, wavelength_nm)
        pick = [float(first_bad(x, ~bad)) for x in (n, largest, nu)]
        raise ContrastUnreachable(pick[0], pick[1], criterion, pick[2], float(wavelength_nm))
    scale = 8.0 * lam / (aperture * aperture)
    k = scale * w_focus
    hyper = _hyperfocal(f, aperture, nu, lam, scale, criterion.level)
    with np.errstate(all="ignore"):
        near = u / (1.0 + k * u)
        near = np.where(np.isinf(u), 1.0 / k, near)
        gap = np.maximum(1.0 - k * u, 2.0 ** -52)
        far = u / gap
        v_h = f / (1.0 - f / hyper)
        if plane == "sensor":
            reachable = hyper >= 2.0 * f
            hyper_plane = np.where(reachable, hyper + v_h, 4.0 * f)
            near_out, far_out = near + v, far + v
        else:
            hyper_plane = hyper
            near_out, far_out = near, far
        infinite = d >= hyper_plane
        far_out = np.where(infinite, np.inf, np.minimum(far_out, 1e300))
        front = d - near_out
        front = np.where(np.isinf(d), np.inf, front)
        rear = np.where(infinite, np.inf, far_out - d)
    m_out = v / u
    limits = DofLimits(near_out, far_out, front, rear, front + rear, hyper_plane, m_out)
    if scalar:
        return DofLimits(*(float(x) for x in limits))
    return limits


def _hyperfocal(f: Any, aperture: Any, nu: Any, lam: float, scale: Any, level: float) -> Any:
    """H from the lens: 1/k at the sensor position of a focus at H.

    A fixed point, started from the sensor at f (a focus at infinity) and
    taken two steps (each moves v by about f²/H, so the third is below
    rounding): a function of the lens and the criterion alone, the same
    whatever the focus of the scene.
    """
    import numpy as np

    from camtool.optics.transfer import defocus_at_level

    w = defocus_at_level(nu * lam * f / aperture, level)
    h = np.where(np.isfinite(w), 1.0 / (scale * w), 4.0 * f)
    for _ in range(2):
        with np.errstate(all="ignore"):
            v_h = np.where(h > 1.5 * f, f / (1.0 - f / h), 3.0 * f)
        w = defocus_at_level(nu * lam * v_h / aperture, level)
        h = np.where(np.isfinite(w), 1.0 / (scale * w), h)
    return h



class ContrastOptimum(NamedTuple):
    """The focus and f-number that give the most contrast at ν at both ends of a range (mm, plane as asked).

    ``mtf`` is that contrast, the same at the near and the far limit;
    ``defocus_waves`` the defocus W₂₀ there.
    """

    distance_mm: float
    magnification: float
    f_number: float
    working_f_number: float
    mtf: float
    defocus_waves: float


def contrast_optimum(focal_length_mm: float, near_mm: float, far_mm: float, frequency_lpmm: float,
                     distance_from: str = "sensor", wavelength_nm: float = 550.0) -> ContrastOptimum:
    """The f-number that makes the worse end of a range sharpest by contrast (the wave-optics optimum aperture).

    Focused at the mean object vergence, 1/u = (1/x_near + 1/x_far)/2, both
    ends have the same defocus W₂₀ = (f²/(8λN²))·(1/x_near − 1/x_far)/2 (from
    the lens) and so the same MTF at ν; stopping down lowers W₂₀ and raises
    s = ν·λ·N·v/f. The MTF at ν is maximised over N (a scan over f/0.7 to
    f/1024 on a logarithmic grid, refined by golden-section search) — the
    contrast counterpart of Hansma's rule, with no root-sum-square.

    Examples
    --------
    150 mm, 2 m to infinity from the lens, at 20 lp/mm:

    >>> r = contrast_optimum(150.0, 2000.0, float("inf"), 20.0, "lens")
    >>> round(r.distance_mm), round(r.f_number, 1), round(r.mtf, 3)
    (4000, 60.2, 0.126)
    """
    import numpy as np

    from camtool.core.errors import require, require_positive
    from camtool.geometry.thinlens import lens_distances
    from camtool.optics.transfer import defocus_mtf

    f = float(focal_length_mm)
    require_positive("focal_length_mm", f)
    require_positive("near_mm", near_mm)
    require_positive("far_mm", far_mm, allow_inf=True)
    require("far_mm", far_mm, far_mm > near_mm, "beyond the near limit")
    lam = wavelength_nm * _MM_PER_NM
    if distance_from == "sensor":
        u_near = float(lens_distances(f, near_mm).object_mm)
        u_far = math.inf if far_mm == math.inf else float(lens_distances(f, far_mm).object_mm)
    else:
        require("near_mm", near_mm, near_mm > f, "more than the focal length from the lens")
        u_near, u_far = float(near_mm), float(far_mm)
    vergence = 0.5 * (1.0 / u_near + 1.0 / u_far)
    u = 1.0 / vergence
    require("near_mm", near_mm, u > f, "a range whose mid-focus lies beyond the focal length")
    v = f / (1.0 - f / u)
    half = 0.5 * (1.0 / u_near - 1.0 / u_far)

    def contrast(n: Any) -> Any:
        n = np.asarray(n, dtype=float)
        w = f * f / (8.0 * lam * n * n) * half
        return np.clip(defocus_mtf(frequency_lpmm * lam * n * v / f, w), 0.0, None)

    grid = np.exp(np.linspace(math.log(0.7), math.log(1024.0), 481))
    values = contrast(grid)
    i = int(np.argmax(values))
    low, high = grid[max(i - 1, 0)], grid[min(i + 1, grid.size - 1)]
    a, b = golden_section(lambda x: float(contrast(math.exp(x))), math.log(low), math.log(high))
    n_best = math.exp(0.5 * (a + b))
    w_best = f * f / (8.0 * lam * n_best * n_best) * half
    distance = u + v if distance_from == "sensor" else u
    return ContrastOptimum(distance, v / u, n_best, n_best * v / f, float(contrast(n_best)), w_best)
