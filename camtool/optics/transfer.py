"""The optical transfer function of a perfect lens with a circular pupil, in focus and defocused.

Frequencies are normalised to the incoherent cut-off ν_c = 1/(λ·N_w):
s = ν/ν_c in [0, 1], N_w the image-side (working) f-number. Defocus is the
wavefront coefficient W₂₀ in waves, W(ρ) = W₂₀·ρ² over the unit pupil; a
shift Δz of the image plane from focus gives W₂₀ = Δz/(8·λ·N_w²).

**In focus** (the diffraction-limited MTF, Goodman, *Introduction to Fourier
Optics*, 3rd ed., eq. 6-31):

    MTF₀(s) = (2/π)·(arccos s − s·√(1 − s²)).

**Defocused**: the OTF is the overlap integral of two copies of the pupil,
shifted by ±s, with the phase difference W(x + s, y) − W(x − s, y) = 4·W₂₀·s·x
(H. H. Hopkins, "The frequency response of a defocused optical system",
Proc. R. Soc. A 231, 91–103, 1955). Integrating over y first and setting
x + s = cos θ leaves a smooth one-dimensional integral,

    OTF(s, W₂₀) = (4/π) ∫₀^{arccos s} sin²θ · cos(8π·W₂₀·s·(cos θ − s)) dθ,

which is real and even in W₂₀ (so MTF = |OTF| and the depth is symmetric in
defocus). camtool evaluates it by Gauss–Legendre quadrature on fixed nodes,
vectorised over any number of (s, W₂₀) pairs; with W₂₀ = 0 it is MTF₀
exactly (the integral of sin²θ). This is the numerical pupil
autocorrelation, not Hopkins' Bessel series; the tests check it against an
mpmath quadrature of the same autocorrelation at 30 digits.

**Geometric limit**: for a blur disc of diameter b (b = 8·λ·N_w·W₂₀) the
geometric MTF is 2·J₁(π·b·ν)/(π·b·ν) (Goodman §6.4), the limit of the OTF
above as s → 0 at fixed π·b·ν = 8π·W₂₀·s.

numpy is imported here: these functions serve the ``wave`` rung and the
pinhole, never the closed forms' scalar path.
"""

from __future__ import annotations

import functools
import math
from typing import Any

__all__ = [
    "DISC_CONTRAST",
    "defocus_at_level",
    "defocus_mtf",
    "diffraction_mtf",
    "disc_mtf",
    "frequency_at_level",
    "jinc",
]

_NODES = 48
"""Gauss–Legendre nodes: the phase of the integrand spans at most about 20 radians where it is used."""

_FIRST_ZERO_J1 = 3.8317059702075125
"""First positive zero of J₁ (Abramowitz and Stegun, Table 9.5)."""

_SCAN = 12
_REFINE = 8


def _j1(x: Any) -> Any:
    """Bessel J₁ for 0 ≤ x ≤ 12 by its power series (40 terms; error below 1e-12 there, from cancellation near 12)."""
    import numpy as np

    x = np.asarray(x, dtype=float)
    half = 0.5 * x
    term = half.copy()
    total = term.copy()
    sq = -half * half
    for k in range(1, 40):
        term = term * sq / (k * (k + 1))
        total = total + term
    return total


def jinc(x: Any) -> Any:
    """2·J₁(x)/x, 1 at x = 0 (the MTF of a uniform blur disc at argument x = π·b·ν), for 0 ≤ x ≤ 12.

    Examples
    --------
    >>> round(float(jinc(math.pi)), 6)
    0.181192
    """
    import numpy as np

    x = np.asarray(x, dtype=float)
    safe = np.where(x > 0.0, x, 1.0)
    out = np.where(x > 0.0, 2.0 * _j1(safe) / safe, 1.0)
    return float(out) if out.ndim == 0 else out


DISC_CONTRAST = 0.18119175498741530
"""2·J₁(π)/π: the contrast a geometric blur disc of diameter c leaves at ν = 1/c (the default level)."""


def disc_mtf(blur_mm: Any, frequency_lpmm: Any) -> Any:
    """Geometric MTF of a uniform blur disc of diameter b at ν: 2·J₁(π·b·ν)/(π·b·ν) (Goodman §6.4)."""
    return jinc(math.pi * blur_mm * frequency_lpmm)


def diffraction_mtf(s: Any) -> Any:
    """The diffraction-limited MTF of a circular pupil at normalised frequency s = ν·λ·N_w (0 beyond 1).

    References
    ----------
    Goodman, *Introduction to Fourier Optics*, 3rd ed., eq. 6-31.

    Examples
    --------
    >>> round(diffraction_mtf(0.5), 4)
    0.391
    >>> diffraction_mtf(1.2)
    0.0
    """
    if isinstance(s, (int, float)):
        t = min(max(float(s), 0.0), 1.0)
        return 2.0 / math.pi * (math.acos(t) - t * math.sqrt(1.0 - t * t))
    import numpy as np

    t = np.clip(np.asarray(s, dtype=float), 0.0, 1.0)
    return 2.0 / np.pi * (np.arccos(t) - t * np.sqrt(1.0 - t * t))


@functools.lru_cache(maxsize=8)
def _gauss(n: int) -> tuple[Any, Any]:
    """The n Gauss–Legendre nodes and weights on [0, 1].

    Newton's method on Pₙ from Tricomi's estimate of each root,
    (1 − (n − 1)/(8n³))·cos(π(4i − 1)/(4n + 2)), with Pₙ and P′ₙ from the
    three-term recurrence; wᵢ = 2/((1 − xᵢ²)·P′ₙ(xᵢ)²). numpy's ``leggauss``
    solves a dense n × n eigenproblem instead: about 3 s at n = 3072 against
    0.1 s here, and its weights are less exact there (2e-7 against 1e-10 at
    the worst node, against mpmath: ``tests/test_wave.py``).
    """
    import numpy as np

    half = (n + 1) // 2
    x = (1.0 - (n - 1) / (8.0 * n**3)) * np.cos(np.pi * (4 * np.arange(1, half + 1) - 1) / (4 * n + 2))

    def legendre(x: Any) -> tuple[Any, Any]:
        """Pₙ(x) and P′ₙ(x)."""
        before, p = np.ones_like(x), x.copy()
        for k in range(2, n + 1):
            before, p = p, ((2 * k - 1) * x * p - (k - 1) * before) / k
        return p, n * (x * p - before) / (x * x - 1.0)

    for _ in range(8):
        p, dp = legendre(x)
        step = p / dp
        x = x - step
        if np.max(np.abs(step)) <= 4e-16:
            break
    _, dp = legendre(x)
    w = 2.0 / ((1.0 - x * x) * dp * dp)
    middle = n % 2  # an odd n has the node 0 once
    nodes = np.concatenate([-x, x[::-1][middle:]])
    weights = np.concatenate([w, w[::-1][middle:]])
    return (nodes + 1.0) / 2.0, weights / 2.0  # on [0, 1]


def defocus_mtf(s: Any, defocus_waves: Any) -> Any:
    """The OTF of a perfect circular pupil at normalised frequency s with defocus W₂₀ (waves).

    Real and even in W₂₀; it falls below zero beyond its first zero (the
    contrast reversal of a strongly defocused image). 0 for s ≥ 1.

    Parameters
    ----------
    s : float or array, 0 ≤ s
        ν·λ·N_w.
    defocus_waves : float or array
        W₂₀ in waves (W = W₂₀·ρ²); ±λ/(2·NA²) of image-side defocus is a quarter wave.

    Examples
    --------
    >>> round(defocus_mtf(0.5, 0.0), 4) == round(diffraction_mtf(0.5), 4)
    True
    >>> round(defocus_mtf(0.5, 0.25), 4)  # a quarter wave: 26 % of the in-focus 0.391 lost
    0.2875
    """
    import numpy as np

    scalar = isinstance(s, (int, float)) and isinstance(defocus_waves, (int, float))
    s_arr, w_arr = np.broadcast_arrays(np.clip(np.asarray(s, dtype=float), 0.0, 1.0),
                                       np.asarray(defocus_waves, dtype=float))
    out = _otf(s_arr.ravel(), w_arr.ravel()).reshape(s_arr.shape)
    return float(out) if scalar else out


def _otf(s: Any, w: Any) -> Any:
    """The quadrature over flat arrays s, w (same length), with more nodes where the phase spans more.

    The phase 8π·W₂₀·s·(cos θ − s) spans Φ = 8π·|W₂₀|·s·(1 − s) radians; 48
    nodes hold it to 1e-13 up to Φ ≈ 25, and each doubling of the nodes
    doubles that reach (up to 3072 nodes, Φ ≈ 1600: beyond, |OTF| is below
    1e-3 and taken as computed).
    """
    import numpy as np

    span = 8.0 * np.pi * np.abs(w) * s * (1.0 - s)
    nodes = np.full(s.shape, _NODES)
    while True:
        more = (span > 25.0 * nodes / _NODES) & (nodes < 64 * _NODES)
        if not np.any(more):
            break
        nodes = np.where(more, 2 * nodes, nodes)
    out = np.empty(s.shape)
    for count in np.unique(nodes):
        rows = nodes == count
        out[rows] = _Quadrature(s[rows], int(count))(w[rows])
    return out


class _Quadrature:
    """The nodes of the integral for fixed frequencies s: each defocus then costs one cosine per node."""

    def __init__(self, s: Any, nodes: int = _NODES) -> None:
        import numpy as np

        t, weights = _gauss(nodes)
        top = np.arccos(s)[:, None]
        theta = top * t[None, :]
        sin = np.sin(theta)
        self.weights = (4.0 / np.pi) * top * sin * sin * weights[None, :]
        self.lever = 8.0 * np.pi * s[:, None] * (np.cos(theta) - s[:, None])

    def __call__(self, w: Any) -> Any:
        import numpy as np

        return np.einsum("ij,ij->i", np.cos(self.lever * w[:, None]), self.weights)

    def newton(self, w: Any, level: Any) -> Any:
        """One Newton step of OTF = level in W₂₀² (the OTF is even in W₂₀, quadratic near 0).

        The slope comes from differentiating under the integral.
        """
        import numpy as np

        phase = self.lever * w[:, None]
        value = np.einsum("ij,ij->i", np.cos(phase), self.weights) - level
        slope = -np.einsum("ij,ij->i", np.sin(phase) * self.lever, self.weights)
        with np.errstate(all="ignore"):
            squared = w * w - value * 2.0 * w / slope
            new = np.sqrt(squared)
        return np.where(np.isfinite(new) & (np.abs(new - w) < 0.5 * w), new, w)


def defocus_at_level(s: Any, level: Any) -> Any:
    """The smallest defocus W₂₀ ≥ 0 (waves) at which the MTF at s falls to ``level``; NaN where it never starts above.

    Where the in-focus MTF₀(s) is already at or below the level there is no
    such defocus (nothing at that frequency is sharp enough): NaN, for the
    caller to report. Otherwise the first crossing is bracketed on a scan of
    W₂₀ from 0 to past the geometric first zero 3.83/(8π·s), narrowed by the
    Illinois variant of regula falsi in W₂₀² and polished by Newton's method in W₂₀²
    (the MTF is even in W₂₀). From 4096 scenes at one level, the first guess
    comes from a table of (s·W*)² over s instead (cached per level).

    Examples
    --------
    >>> round(float(defocus_at_level(0.5, 0.2875)), 3)
    0.25
    """
    import numpy as np

    scalar = isinstance(s, (int, float)) and isinstance(level, (int, float))
    s_arr, l_arr = np.broadcast_arrays(np.asarray(s, dtype=float), np.asarray(level, dtype=float))
    s_flat = np.clip(s_arr.ravel(), 1e-12, 1.0)
    l_flat = l_arr.ravel()
    out = np.full(s_flat.shape, np.nan)
    ok = diffraction_mtf(s_flat) > l_flat
    if np.any(ok):
        if np.size(level) == 1 and np.count_nonzero(ok) > _TABLE_FROM:
            out[ok] = _from_table(s_flat[ok], float(np.ravel(level)[0]))
        else:
            out[ok] = _solve(s_flat[ok], l_flat[ok])
    out = out.reshape(s_arr.shape)
    return float(out) if scalar else out


def _solve(s: Any, level: Any) -> Any:
    """Bracket and refine the first crossing for each (s, level) with MTF₀(s) > level."""
    import numpy as np

    otf = _Quadrature(s)
    top = 1.05 * _FIRST_ZERO_J1 / (8.0 * np.pi * s) + 0.75
    low = np.zeros_like(s)
    g_low = diffraction_mtf(s) - level
    high = top.copy()
    g_high = np.full_like(s, -1e-300)  # not bracketed (cannot happen past the first zero): the scan's end
    found = np.zeros(s.shape, dtype=bool)
    for step in np.linspace(0.0, 1.0, _SCAN + 1)[1:]:
        w = top * step
        g = otf(w) - level
        new = ~found & (g <= 0.0)
        high = np.where(new, w, high)
        g_high = np.where(new, g, g_high)
        keep = ~found & ~new
        low = np.where(keep, w, low)
        g_low = np.where(keep, g, g_low)
        found |= new
    side = np.zeros(s.shape, dtype=int)  # which end the last step replaced: +1 low, -1 high
    for _ in range(_REFINE):
        # the secant in W₂₀², in which the MTF is nearly linear close to focus
        w = np.sqrt(np.abs((low * low * g_high - high * high * g_low) / (g_high - g_low)))
        w = np.where(np.isfinite(w) & (w > low) & (w < high), w, 0.5 * (low + high))
        g = otf(w) - level
        above = g > 0.0
        # Illinois: when the same end is replaced twice running, halve the value kept at the other end
        g_high = np.where(above & (side == 1), 0.5 * g_high, g_high)
        g_low = np.where(~above & (side == -1), 0.5 * g_low, g_low)
        low, g_low = np.where(above, w, low), np.where(above, g, g_low)
        high, g_high = np.where(above, high, w), np.where(above, g_high, g)
        side = np.where(above, 1, -1)
    w = np.where(np.abs(g_low) < np.abs(g_high), low, high)
    for _ in range(2):
        w = otf.newton(w, level)
    return w


_TABLE_FROM = 4096
"""From this many scenes at one level, the defocus comes from a table and two Newton steps."""

_TABLE_POINTS = 4097


@functools.lru_cache(maxsize=8)
def _table(level: float) -> tuple[Any, Any]:
    """(s grid, (s·W*)²) on [0, s*] for one level: smooth, and 0 at s* where W* vanishes."""
    import numpy as np

    top = frequency_at_level(level)
    grid = np.linspace(0.0, top, _TABLE_POINTS)
    inner = np.clip(grid[:-1], 1e-9, None)
    w = _solve(inner, np.full_like(inner, level))
    q = np.append((inner * w) ** 2, 0.0)
    q.setflags(write=False)
    grid.setflags(write=False)
    return grid, q


def _from_table(s: Any, level: float) -> Any:
    """W* for many s at one level: interpolated in the table, then polished by Newton's method."""
    import numpy as np

    grid, q = _table(level)
    w = np.sqrt(np.interp(s, grid, q)) / s
    quad = _Quadrature(s)
    for _ in range(2):
        w = quad.newton(w, level)
    return w


def frequency_at_level(level: Any) -> Any:
    """The normalised frequency s at which the in-focus MTF₀(s) equals ``level`` (0 < level < 1), by bisection.

    Examples
    --------
    >>> round(frequency_at_level(0.391), 3)
    0.5
    """
    import numpy as np

    scalar = isinstance(level, (int, float))
    lv = np.asarray(level, dtype=float)
    low, high = np.zeros_like(lv), np.ones_like(lv)
    for _ in range(60):
        mid = 0.5 * (low + high)
        above = diffraction_mtf(mid) > lv
        low = np.where(above, mid, low)
        high = np.where(above, high, mid)
    out = 0.5 * (low + high)
    return float(out) if scalar else out
