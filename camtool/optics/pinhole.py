"""The pinhole camera: published rules for the pinhole's diameter, its blur, and its contrast by wave optics.

A pinhole of diameter d at L from the film images a point at distance s as
a patch: geometrically the shadow of the hole, d·(1 + L/s); by diffraction
an Airy pattern, 2.44·λ·L/d across its first dark ring. The published rules
balance the two as d = k·√(λ·F), with F = L·s/(L + s) the distance that
plays the focal length (F = L for a distant subject; Young, below):

- ``petzval``, k = √2 = 1.414: the first, J. Petzval (1857, 1859): the patch
  is taken as the hole plus its diffraction, D = d + 2·λ·L/d, least for
  d² = 2·λ·L (K. Sayanagi, "Pinhole imagery", J. Opt. Soc. Am. 57, 1091 (1967),
  quoting Petzval's k = 2; the worked examples of Wikipedia's "Pinhole camera":
  0.17 mm at 25 mm, 0.23 mm at 5 cm, at 550 nm);
- ``airy``, k = √2.44 = 1.562: the Airy disc as wide as the hole, d² = 2.44·λ·F
  (the pinhole forums' rule, e.g. the sundial mailing list and the
  alt-photo-process list, 1997: "the pinhole should be the same size as the
  diffraction disk");
- ``rayleigh``, k = 1.9: Lord Rayleigh's constant, the one most quoted
  (Lord Rayleigh, "On pin-hole photography", Phil. Mag. 31, 87–99 (1891), paper 178 of his
  Scientific Papers, vol. 3; quoted as
  d = 1.9√(fλ));
- ``young``, k = 2: the hole is one Fresnel zone, r² = λ·F, where the image is
  best focused (M. Young, "Pinhole optics", Applied Optics 10, 2763 (1971)).

The rules disagree by about a third (1.414 to 2). The wave optics behind them is
exact and short: the wave from the point, cut by the hole, reaches the film
with the defocus W₂₀ = (d/2)²·(1/L + 1/s)/(2λ) waves (the pinhole is a lens
of infinite focal length), so d = k·√(λ·F) means **W₂₀ = k²/8** whatever
the distances: a quarter wave for k = √2, half a wave (one Fresnel zone)
for k = 2. The contrast the pinhole transfers at ν lp/mm on the film is the
defocused MTF of a circular pupil (:mod:`camtool.optics.transfer`) at
s = ν·λ·N with N = L/d, and :func:`optimum_diameter_mm` finds the d that
maximises it; each rule is shown with the contrast it gives.
"""

from __future__ import annotations

import functools
import math
from typing import Any

from camtool.core.errors import require, require_positive
from camtool.core.record import NamedTuple
from camtool.optics.roots import golden_section

__all__ = [
    "RULES",
    "PinholeRule",
    "airy_mm",
    "best_constant",
    "defocus_waves",
    "effective_distance_mm",
    "geometric_blur_mm",
    "optimum_diameter_mm",
    "pinhole_mtf",
    "resolution_lpmm",
    "rule_diameter_mm",
    "rule_level",
]

_MM_PER_NM = 1e-6


class PinholeRule(NamedTuple):
    """A published rule d = k·√(λ·F): its name, constant k and what it balances."""

    name: str
    constant: float
    reasoning: str


RULES: tuple[PinholeRule, ...] = (
    PinholeRule("petzval", math.sqrt(2.0), "hole plus its diffraction least (Petzval 1857)"),
    PinholeRule("airy", math.sqrt(2.44), "Airy disc as wide as the hole"),
    PinholeRule("rayleigh", 1.9, "Lord Rayleigh (1891)"),
    PinholeRule("young", 2.0, "one Fresnel zone (Young 1971)"),
)
"""The published rules, smallest constant first (module docstring for their sources)."""


def effective_distance_mm(film_distance_mm: float, subject_distance_mm: float = math.inf) -> float:
    """F = L·s/(L + s): the distance in the rules for a subject at s (L for a distant one; Young 1971).

    >>> effective_distance_mm(100.0), effective_distance_mm(100.0, 100.0)
    (100.0, 50.0)
    """
    require_positive("film_distance_mm", film_distance_mm)
    require_positive("subject_distance_mm", subject_distance_mm, allow_inf=True)
    if math.isinf(subject_distance_mm):
        return float(film_distance_mm)
    return film_distance_mm / (1.0 + film_distance_mm / subject_distance_mm)


def rule_diameter_mm(constant: float, film_distance_mm: float, subject_distance_mm: float = math.inf,
                     wavelength_nm: float = 550.0) -> float:
    """d = k·√(λ·F) in mm.

    Examples
    --------
    The worked example of the Airy rule: 100 mm at 550 nm, d = √(2.44 × 0.00055 × 100) = 0.366 mm:

    >>> round(rule_diameter_mm(math.sqrt(2.44), 100.0), 3)
    0.366
    """
    require_positive("wavelength_nm", wavelength_nm, unit="nm")
    return constant * math.sqrt(wavelength_nm * _MM_PER_NM * effective_distance_mm(film_distance_mm,
                                                                                      subject_distance_mm))


def geometric_blur_mm(diameter_mm: float, film_distance_mm: float, subject_distance_mm: float = math.inf) -> float:
    """The hole's shadow of a point at s on film at L: d·(1 + L/s) (d for a distant point).

    >>> geometric_blur_mm(0.3, 50.0, 50.0)
    0.6
    """
    return diameter_mm * (1.0 + film_distance_mm / subject_distance_mm)


def airy_mm(diameter_mm: float, film_distance_mm: float, wavelength_nm: float = 550.0) -> float:
    """The Airy disc on the film, to its first dark ring: 2.44·λ·L/d (Born and Wolf §8.5.2).

    >>> round(airy_mm(0.366, 100.0), 3)
    0.367
    """
    return 2.44 * wavelength_nm * _MM_PER_NM * film_distance_mm / diameter_mm


def defocus_waves(diameter_mm: float, film_distance_mm: float, subject_distance_mm: float = math.inf,
                  wavelength_nm: float = 550.0) -> float:
    """W₂₀ = (d/2)²·(1/L + 1/s)/(2λ) in waves: the path difference from the hole's edge to its centre.

    With d = k·√(λ·F) it is k²/8 (one Fresnel zone, half a wave, at k = 2):

    >>> round(defocus_waves(rule_diameter_mm(2.0, 80.0, 2000.0), 80.0, 2000.0), 12)
    0.5
    """
    lam = wavelength_nm * _MM_PER_NM
    return (0.5 * diameter_mm) ** 2 * (1.0 / film_distance_mm + 1.0 / subject_distance_mm) / (2.0 * lam)


def pinhole_mtf(diameter_mm: Any, film_distance_mm: float, frequency_lpmm: float, subject_distance_mm: float = math.inf,
                wavelength_nm: float = 550.0) -> Any:
    """The MTF at ν lp/mm on the film of a pinhole of diameter d (a defocused circular pupil at N = L/d).

    Examples
    --------
    Rayleigh's hole for 100 mm at 550 nm, at 1 lp/mm:

    >>> round(pinhole_mtf(rule_diameter_mm(1.9, 100.0), 100.0, 1.0), 4)
    0.6963
    """
    import numpy as np

    from camtool.optics.transfer import defocus_mtf

    d = np.asarray(diameter_mm, dtype=float)
    lam = wavelength_nm * _MM_PER_NM
    s = frequency_lpmm * lam * film_distance_mm / d
    w = (0.5 * d) ** 2 * (1.0 / film_distance_mm + 1.0 / subject_distance_mm) / (2.0 * lam)
    out = np.abs(defocus_mtf(s, w))
    return float(out) if np.ndim(out) == 0 else out


@functools.lru_cache(maxsize=1)
def _table() -> tuple[Any, Any, Any]:
    """The MTF of d = k·√(λ·F) against s = ν·λ·N: k from 0.8 to 3.5 in steps of 0.02, s from 0 to 1 in 0.00125."""
    import numpy as np

    from camtool.optics.transfer import defocus_mtf

    ks = np.linspace(0.8, 3.5, 136)
    ss = np.linspace(0.0, 1.0, 801)
    mtf = np.stack([defocus_mtf(ss, np.full(ss.shape, k * k / 8.0)) for k in ks])
    for array in (ks, ss, mtf):
        array.setflags(write=False)
    return ks, ss, mtf


def _reach(level: float) -> Any:
    """For each k of the table, q = k·s at the first s where the MTF falls to ``level`` (linear between nodes)."""
    import numpy as np

    ks, ss, mtf = _table()
    below = mtf <= level
    first = np.argmax(below, axis=1)
    first = np.where(below.any(axis=1), first, ss.size - 1)
    prev = np.maximum(first - 1, 0)
    rows = np.arange(ks.size)
    m0, m1 = mtf[rows, prev], mtf[rows, first]
    with np.errstate(all="ignore"):
        t = np.where(m0 != m1, (m0 - level) / (m0 - m1), 0.0)
    s = ss[prev] + t * (ss[first] - ss[prev])
    return ks * s


def best_constant(level: float) -> float:
    """The k of d = k·√(λ·F) that resolves the finest detail at contrast ``level`` (whatever λ, L and s).

    With d = k·√(λ·F) the MTF depends only on k and q = ν·L·√(λ/F) (s = q/k,
    W₂₀ = k²/8), so the frequency at which it falls to the level is largest
    at one k for every pinhole: found on a table of the defocused OTF
    (k in steps of 0.02, s of 0.00125) and refined by a parabola through the
    best three.

    >>> round(best_constant(0.5), 2)
    1.38
    """
    import numpy as np

    require("level", level, 0.0 < level < 1.0, "between 0 and 1")
    ks = _table()[0]
    q = _reach(level)
    i = int(np.clip(np.argmax(q), 1, ks.size - 2))
    y0, y1, y2 = q[i - 1], q[i], q[i + 1]
    curvature = y0 - 2.0 * y1 + y2
    shift = 0.5 * (y0 - y2) / curvature if curvature < 0.0 else 0.0
    return float(ks[i] + shift * (ks[1] - ks[0]))


def rule_level(constant: float) -> float | None:
    """The contrast level (0.05 to 0.5) at which a rule's k is the one that resolves the finest detail, or None.

    :func:`best_constant` falls from about 2.1 at 5 % to 1.38 at 50 %, so
    each k in that span is the best for one level there (at higher levels the
    best k rises again; those levels are not considered).

    >>> round(rule_level(1.9), 3)  # Rayleigh's 1.9 is the best for detail at 7.7 % contrast
    0.077
    """
    low, high = 0.05, 0.5
    if not best_constant(high) <= constant <= best_constant(low):
        return None
    for _ in range(40):
        mid = 0.5 * (low + high)
        if best_constant(mid) > constant:
            low = mid
        else:
            high = mid
    return 0.5 * (low + high)


def resolution_lpmm(diameter_mm: float, film_distance_mm: float, level: float, subject_distance_mm: float = math.inf,
                    wavelength_nm: float = 550.0) -> float:
    """The frequency on the film (lp/mm) at which a pinhole's MTF falls to ``level``.

    >>> round(resolution_lpmm(rule_diameter_mm(1.9, 100.0), 100.0, 0.5), 2)
    1.57
    """
    import numpy as np

    base = rule_diameter_mm(1.0, film_distance_mm, subject_distance_mm, wavelength_nm)
    k = diameter_mm / base
    ks = _table()[0]
    require("diameter_mm", diameter_mm, ks[0] <= k <= ks[-1],
            f"{ks[0]:g} to {ks[-1]:g} times √(λ·F) ({ks[0] * base:.3g} to {ks[-1] * base:.3g} mm)")
    q = float(np.interp(k, ks, _reach(level)))
    lam = wavelength_nm * _MM_PER_NM
    return q / (k * lam * film_distance_mm / diameter_mm)


def optimum_diameter_mm(film_distance_mm: float, frequency_lpmm: float, subject_distance_mm: float = math.inf,
                        wavelength_nm: float = 550.0) -> float:
    """The diameter whose MTF at ν on the film is highest: d = k·√(λ·F), k found by a scan and golden section.

    k runs from 0.5 to 4 (beyond both ends the contrast only falls: diffraction
    below, the hole's shadow above); 241 points, then 60 golden-section steps.

    Examples
    --------
    >>> d = optimum_diameter_mm(100.0, 5.0)
    >>> pinhole_mtf(d, 100.0, 5.0) >= max(pinhole_mtf(rule_diameter_mm(r.constant, 100.0), 100.0, 5.0) for r in RULES)
    True
    """
    import numpy as np

    require_positive("frequency_lpmm", frequency_lpmm, unit="lp/mm")
    base = rule_diameter_mm(1.0, film_distance_mm, subject_distance_mm, wavelength_nm)

    def contrast(k: Any) -> Any:
        return pinhole_mtf(np.asarray(k) * base, film_distance_mm, frequency_lpmm, subject_distance_mm,
                           wavelength_nm)

    grid = np.linspace(0.5, 4.0, 241)
    i = int(np.argmax(contrast(grid)))
    a, b = golden_section(lambda k: float(contrast(k)), grid[max(i - 1, 0)], grid[min(i + 1, grid.size - 1)])
    require("frequency_lpmm", frequency_lpmm, float(contrast(0.5 * (a + b))) > 0.0,
            "a frequency this pinhole transfers")
    return float(0.5 * (a + b) * base)
