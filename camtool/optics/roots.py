"""Bracketed root finding: Brent's method.

Brent's method is written as a generator (:func:`brent_steps`): it yields the
next abscissa and receives the function value there, so a caller can drive it
however the function is best evaluated; :func:`brent` drives it for a plain
scalar function. The ``raytrace`` rung finds its roots on interpolants, where
one scalar evaluation costs a few microseconds and the driving loop itself is
part of the cost. :func:`golden_section` narrows a bracket about a maximum.
"""

from __future__ import annotations

import math
from collections.abc import Callable, Generator

__all__ = ["brent", "brent_steps", "golden_section"]

_EPS = 2.0**-52


def brent_steps(a: float, fa: float, b: float, fb: float, xtol: float) -> Generator[float, float, float]:
    """Brent's root finder as a generator: yields x, is sent f(x), returns the root.

    Inverse quadratic interpolation or the secant step when they stay well
    inside the bracket [a, b], bisection otherwise; the bracket always keeps a
    sign change, so convergence is guaranteed (superlinear for smooth f).

    Parameters
    ----------
    a, b : float
        Bracket ends; f(a) and f(b) must not have the same sign.
    fa, fb : float
        f(a), f(b).
    xtol : float
        Absolute tolerance on the root (≥ 0); 4·eps·|x| is added.

    References
    ----------
    R. P. Brent, *Algorithms for Minimization without Derivatives*
    (Prentice-Hall, 1973), ch. 4.

    Examples
    --------
    >>> steps = brent_steps(1.0, -1.0, 2.0, 2.0, 1e-15)
    >>> x = next(steps)
    >>> try:
    ...     while True:
    ...         x = steps.send(x * x - 2.0)
    ... except StopIteration as done:
    ...     root = done.value
    >>> abs(root - 2.0**0.5) < 1e-15
    True
    """
    if fa == 0.0:
        return a
    if fb == 0.0:
        return b
    if (fa > 0.0) == (fb > 0.0):
        raise ValueError(f"no sign change in the bracket [{a!r}, {b!r}]")
    c, fc = a, fa
    d = e = b - a
    while True:
        if (fb > 0.0) == (fc > 0.0):
            c, fc = a, fa
            d = e = b - a
        if abs(fc) < abs(fb):
            a, b, c = b, c, b
            fa, fb, fc = fb, fc, fb
        tol = 2.0 * _EPS * abs(b) + 0.5 * xtol
        half = 0.5 * (c - b)
        if abs(half) <= tol or fb == 0.0:
            return b
        if abs(e) >= tol and abs(fa) > abs(fb):
            s = fb / fa
            if a == c:  # secant
                p, q = 2.0 * half * s, 1.0 - s
            else:  # inverse quadratic interpolation
                q, r = fa / fc, fb / fc
                p = s * (2.0 * half * q * (q - r) - (b - a) * (r - 1.0))
                q = (q - 1.0) * (r - 1.0) * (s - 1.0)
            if p > 0.0:
                q = -q
            p = abs(p)
            if 2.0 * p < min(3.0 * half * q - abs(tol * q), abs(e * q)):
                e, d = d, p / q
            else:
                d = e = half
        else:
            d = e = half
        a, fa = b, fb
        b = b + (d if abs(d) > tol else math.copysign(tol, half))
        fb = yield b


def brent(
    f: Callable[[float], float], a: float, b: float, xtol: float = 0.0, fa: float | None = None, fb: float | None = None
) -> float:
    """Root of f in the bracket [a, b] by Brent's method (scalar convenience wrapper).

    Parameters
    ----------
    f : callable
        Continuous on [a, b] with f(a)·f(b) ≤ 0.
    a, b : float
        Bracket.
    xtol : float
        Absolute tolerance (a relative 4·eps is always added).
    fa, fb : float, optional
        f(a) and f(b) when the caller has them already.

    References
    ----------
    R. P. Brent, *Algorithms for Minimization without Derivatives* (1973), ch. 4.

    Examples
    --------
    >>> round(brent(lambda x: x**3 - 2.0 * x - 5.0, 2.0, 3.0), 12)
    2.094551481542
    >>> abs(brent(lambda x: x * x - 2.0, 1.0, 2.0, fa=-1.0, fb=2.0) - 2.0**0.5) < 1e-15  # ends' values given
    True
    """
    steps = brent_steps(a, f(a) if fa is None else fa, b, f(b) if fb is None else fb, xtol)
    try:
        x = next(steps)
        for _ in range(200):
            x = steps.send(float(f(x)))
    except StopIteration as done:
        return float(done.value)
    raise RuntimeError("root search did not converge")


def golden_section(value: Callable[[float], float], a: float, b: float, *, steps: int = 60, tolerance: float = 0.0,
                   relative: float = 0.0) -> tuple[float, float]:
    """The bracket [a, b] narrowed about a maximum of ``value`` by golden-section search.

    Each step compares ``value`` at the two points b − r·(b − a) and
    a + r·(b − a), r = (√5 − 1)/2, and keeps the side of the larger (the left
    on a tie; a NaN keeps the right); at most ``steps`` steps, fewer once
    b − a ≤ ``tolerance`` + ``relative``·b. A minimum is the maximum of −value.

    Examples
    --------
    >>> a, b = golden_section(lambda x: -(x - 2.0) ** 2, 0.0, 5.0)
    >>> round(0.5 * (a + b), 9)
    2.0
    """
    ratio = (math.sqrt(5.0) - 1.0) / 2.0
    for _ in range(steps):
        c1, c2 = b - ratio * (b - a), a + ratio * (b - a)
        if value(c1) >= value(c2):
            b = c2
        else:
            a = c1
        if b - a <= tolerance + relative * b:
            break
    return a, b
