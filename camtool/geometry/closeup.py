"""Close-up geometry: both magnifications of a sensor distance, extension tubes, teleconverters, internal focusing.

A unit-focusing thin lens at magnification m sits u = f(1 + 1/m) from the
subject and v = f(1 + m) from the sensor, so the subject is
D = f·(1 + m)²/m + δ from the sensor plane. Every D > 4f + δ is reached at two
magnifications, m and 1/m (the lens and the subject swap places); 4f + δ is
1:1. Lens-plane distances u > f have one magnification, m = f/(u − f).

A lens that focuses internally (docs/closeup.md §2) changes its focal
length as it focuses. camtool's model: its power grows in proportion to the
magnification,

    1/f(m) = (1 + κ·m)/f₀,

with f₀ the focal length at infinity and κ fixed by the published closest
focus D_c at the published maximum magnification m_c:
f(m_c) = (D_c − δ)·m_c/(1 + m_c)². A sensor distance D then gives m from the
quadratic (f₀ − κL)·m² + (2f₀ − L)·m + f₀ = 0, L = D − δ.

All lengths in millimetres.
"""

from __future__ import annotations

from typing import Any

from camtool.core.arrays import ops, quiet
from camtool.core.errors import DomainError, require, require_positive
from camtool.core.record import NamedTuple
from camtool.geometry.thinlens import span_root

__all__ = [
    "InternalFocus",
    "MagnificationBranches",
    "internal_focus",
    "internal_focus_at_distance",
    "internal_focus_at_magnification",
    "internal_focus_between",
    "magnification_branches",
    "with_extension",
    "with_teleconverter",
]


class MagnificationBranches(NamedTuple):
    """The two magnifications of one sensor-plane distance: ``low`` ≤ 1 ≤ ``high`` = 1/low."""

    low: Any
    high: Any


def magnification_branches(focal_length_mm: Any, sensor_distance_mm: Any, hiatus_mm: Any = 0.0) -> MagnificationBranches:
    """Both magnifications at which a unit-focusing lens focuses on a subject D from the sensor.

    With L = D − δ and r = √(1 − 4f/L): m_low = (1 − r)/(1 + r) written
    4f/(L·(1 + r)²) so that it stays exact for distant subjects, and
    m_high = 1/m_low.

    Parameters
    ----------
    focal_length_mm : float or array, f > 0
    sensor_distance_mm : float or array, D ≥ 4f + δ
    hiatus_mm : float or array, δ

    References
    ----------
    Thin-lens equation with u + v = L: u and v are the two roots of
    x² − L·x + f·L = 0 (docs/closeup.md §1).

    Examples
    --------
    >>> b = magnification_branches(65.0, 346.6666666666667)
    >>> round(b.low, 6), round(b.high, 6)
    (0.333333, 3.0)
    """
    xp, span, root = span_root(focal_length_mm, sensor_distance_mm, hiatus_mm)
    with quiet(xp):
        low = 4.0 * focal_length_mm / (span * (1.0 + root) ** 2)
        high = xp.where(low > 0.0, 1.0 / xp.where(low > 0.0, low, 1.0), xp.inf)
    return MagnificationBranches(low, high)


def with_extension(focal_length_mm: Any, magnification: Any, extension_mm: Any) -> Any:
    """Magnification with an extension tube e behind a lens set to m: m + e/f.

    The lens-to-sensor spacing grows from f(1 + m) to f(1 + m) + e, and the
    magnification of a thin lens is (v − f)/f.

    Examples
    --------
    >>> with_extension(100.0, 0.0, 25.0)
    0.25
    """
    require_positive("focal_length_mm", focal_length_mm)
    return magnification + extension_mm / focal_length_mm


def with_teleconverter(focal_length_mm: Any, f_number: Any, factor: Any) -> tuple[Any, Any]:
    """(k·f, k·N): a teleconverter of factor k treated as part of the lens.

    The combination is a lens of k times the focal length with the same
    entrance pupil; at a given lens setting it multiplies the magnification
    by k too (docs/closeup.md §4).

    Examples
    --------
    >>> [round(x, 6) for x in with_teleconverter(100.0, 2.8, 1.4)]
    [140.0, 3.92]
    """
    require_positive("teleconverter", factor, unit="")
    return focal_length_mm * factor, f_number * factor


class InternalFocus(NamedTuple):
    """An internally focusing lens: f₀ at infinity, power growing as 1 + κ·m, usable from ``min_m`` to ``max_m``."""

    focal_length_mm: float
    kappa: float
    min_magnification: float
    max_magnification: float
    hiatus_mm: float
    min_focus_mm: float


def internal_focus(focal_length_mm: float, min_focus_mm: float, max_magnification: float,
                   hiatus_mm: float = 0.0, min_magnification: float = 0.0) -> InternalFocus:
    """The internal-focus model of a lens with a published closest focus D_c (sensor plane) and magnification m_c.

    κ = (f₀/f_c − 1)/m_c with f_c = (D_c − δ)·m_c/(1 + m_c)². κ = 0 is a
    unit-focusing lens. Where κ would be negative with m_c ≤ 1 (the lens
    reaches more at its closest focus than a unit-focusing f₀ would there, yet
    with a longer focal length: wide-angle designs), the distance would turn
    back before the closest focus; the model is then unit focusing (κ = 0)
    with the principal planes further apart by D_c − δ − f₀(1 + m_c)²/m_c,
    which keeps the distance falling all the way to the closest focus.

    Examples
    --------
    Canon EF 100 mm f/2.8L Macro: 1:1 at 300 mm from the sensor.

    >>> lens = internal_focus(100.0, 300.0, 1.0)
    >>> round(lens.kappa, 6), round(100.0 / (1 + lens.kappa), 3)
    (0.333333, 75.0)
    """
    f_close = (min_focus_mm - hiatus_mm) * max_magnification / (1.0 + max_magnification) ** 2
    if not f_close > 0.0:
        raise DomainError("min_focus_mm", min_focus_mm, "more than the hiatus")
    kappa = (focal_length_mm / f_close - 1.0) / max_magnification
    if kappa < 0.0 and max_magnification <= 1.0:
        # The power would have to fall as the lens focuses, and the distance would turn back before the
        # closest focus. Instead: unit focusing with the principal planes that much further apart.
        extra = min_focus_mm - hiatus_mm - focal_length_mm * (1.0 + max_magnification) ** 2 / max_magnification
        return InternalFocus(focal_length_mm, 0.0, min_magnification, max_magnification, hiatus_mm + extra,
                             min_focus_mm)
    return InternalFocus(focal_length_mm, kappa, min_magnification, max_magnification, hiatus_mm, min_focus_mm)


def internal_focus_between(focal_length_mm: float, min_magnification: float, min_focus_mm: float,
                           max_magnification: float, far_focus_mm: float) -> InternalFocus:
    """The internal-focus model of a lens without infinity focus through both published ends of its range.

    A lens such as the Canon MP-E 65 publishes the distance (from the sensor) at
    its least magnification m₁ (D₁) and at its largest m₂ (D₂). With
    g(m) = f₀(1 + m)²/m, D(m) = g(m)/(1 + κm) + δ through both points gives, with
    Δ = D₁ − D₂, A = g(m₁), B = g(m₂),

        Δ·m₁m₂·κ² + (Δ(m₁ + m₂) − A·m₂ + B·m₁)·κ + (Δ − A + B) = 0,

    of whose roots the one keeping 1 + κm > 0 and δ the smaller in size is
    taken; δ = D₁ − A/(1 + κm₁). D(m) is least at m = 1/(1 − 2κ) (dD/dm = 0),
    which may lie inside the range: the model's closest focus is then that
    minimum, a little short of D₁.

    Examples
    --------
    The MP-E 65: 0.24 m at 1x, 0.313 m at 5x.

    >>> lens = internal_focus_between(65.0, 1.0, 240.0, 5.0, 313.0)
    >>> [round(internal_focus_at_magnification(lens, m)[1], 6) for m in (1.0, 5.0)]
    [240.0, 313.0]
    """
    import math

    f0, m1, d1, m2, d2 = focal_length_mm, min_magnification, min_focus_mm, max_magnification, far_focus_mm
    if not 0.0 < m1 < m2:
        raise DomainError("min_magnification", m1, f"more than 0 and less than {m2:g}")
    a_, b_ = f0 * (1.0 + m1) ** 2 / m1, f0 * (1.0 + m2) ** 2 / m2
    delta_d = d1 - d2
    qa, qb, qc = delta_d * m1 * m2, delta_d * (m1 + m2) - a_ * m2 + b_ * m1, delta_d - a_ + b_
    if qa == 0.0:
        roots = [-qc / qb] if qb != 0.0 else []
    else:
        disc = qb * qb - 4.0 * qa * qc
        roots = [] if disc < 0.0 else [(-qb + s * math.sqrt(disc)) / (2.0 * qa) for s in (1.0, -1.0)]
    fits = [(abs(d1 - a_ / (1.0 + k * m1)), k) for k in roots if 1.0 + k * m1 > 0.0 and 1.0 + k * m2 > 0.0]
    if not fits:
        raise DomainError("min_focus_mm", d1, f"distances a lens of {f0:g} mm can reach at {m1:g}× and {m2:g}×")
    _size, kappa = min(fits)
    hiatus = d1 - a_ / (1.0 + kappa * m1)
    turn = 1.0 / (1.0 - 2.0 * kappa) if kappa < 0.5 else math.inf
    closest = min(d1, d2)
    if m1 < turn < m2:
        closest = min(closest, f0 * (1.0 + turn) ** 2 / (turn * (1.0 + kappa * turn)) + hiatus)
    return InternalFocus(f0, kappa, m1, m2, hiatus, closest)


def internal_focus_at_magnification(lens: InternalFocus, magnification: Any) -> tuple[Any, Any]:
    """(focal length f(m), sensor distance D) of an internally focusing lens at m, in mm.

    f(m) = f₀/(1 + κ·m), D = f(m)·(1 + m)²/m + δ. Outside the lens's range
    (m above its maximum, or below its minimum) a :class:`DomainError` names
    the range.

    Examples
    --------
    >>> lens = internal_focus(100.0, 300.0, 1.0)
    >>> [round(x, 6) for x in internal_focus_at_magnification(lens, 1.0)]
    [75.0, 300.0]
    """
    _in_range(lens, magnification)
    f = lens.focal_length_mm / (1.0 + lens.kappa * magnification)
    return f, f * (1.0 + magnification) ** 2 / magnification + lens.hiatus_mm


def _in_range(lens: InternalFocus, m: Any) -> None:
    low, high = lens.min_magnification, lens.max_magnification
    span = f"{low:g}× to {high:g}×" if low > 0 else f"up to {high:g}×"
    # 0.1 % slack: published magnifications are rounded
    require("magnification", m, (m <= high * 1.001) & (m >= low * 0.999), f"{span} for this lens")


def internal_focus_at_distance(lens: InternalFocus, sensor_distance_mm: Any) -> tuple[Any, Any]:
    """(magnification, focal length) of an internally focusing lens focused on a subject D from the sensor.

    Solves (f₀ − κL)·m² + (2f₀ − L)·m + f₀ = 0 (L = D − δ) for the root in
    the lens's range, the smaller one where both are (the branch reached by
    focusing in from infinity). A distance closer than the closest focus, or
    one whose magnification falls outside the range, is a
    :class:`DomainError` naming the range.

    Examples
    --------
    >>> lens = internal_focus(100.0, 300.0, 1.0)
    >>> [round(x, 6) for x in internal_focus_at_distance(lens, 300.0)]
    [1.0, 75.0]
    """
    f0, kappa, delta = lens.focal_length_mm, lens.kappa, lens.hiatus_mm
    xp = ops(sensor_distance_mm)
    where = _range_text(lens)
    high, low = lens.max_magnification * 1.001, lens.min_magnification * 0.999
    require("distance_mm", sensor_distance_mm, sensor_distance_mm >= lens.min_focus_mm * 0.999,
            "at least {limit} from the sensor (this lens's closest focus; " + where + ")",
            limit=lens.min_focus_mm)
    at_infinity = xp.isinf(sensor_distance_mm)
    # infinity focus is m = 0 at the lens's own focal length; a large finite span keeps the algebra finite there
    span = xp.where(at_infinity, 1e100, sensor_distance_mm - delta) if not isinstance(at_infinity, bool) else (
        1e100 if at_infinity else sensor_distance_mm - delta)
    a = f0 - kappa * span
    b = 2.0 * f0 - span
    disc = b * b - 4.0 * a * f0
    disc = xp.where(at_infinity, b * b, disc) if not isinstance(at_infinity, bool) else (b * b if at_infinity else disc)
    require("distance_mm", sensor_distance_mm, disc >= 0.0,
            f"a distance this lens can focus on ({where})")
    with quiet(xp):
        root = xp.sqrt(xp.maximum(disc, 0.0))
        small = 2.0 * f0 / (-b + root)  # the smaller positive root, 2c/(−b + √disc), exact for distant subjects
        upper = xp.where(a > 0.0, (-b + root) / (2.0 * xp.where(a > 0.0, a, 1.0)), xp.inf)
    small_ok = (small >= low) & (small <= high)
    pick = xp.where(small_ok, small, upper)
    require("distance_mm", sensor_distance_mm, (pick >= low) & (pick <= high),
            f"a distance this lens can focus on ({where})")
    m = xp.maximum(xp.minimum(pick, lens.max_magnification), lens.min_magnification)
    if isinstance(at_infinity, bool):
        m = 0.0 if at_infinity and lens.min_magnification <= 0.0 else m
    else:
        m = xp.where(at_infinity & (lens.min_magnification <= 0.0), 0.0, m)
    return m, f0 / (1.0 + kappa * m)


def _range_text(lens: InternalFocus) -> str:
    low, high = lens.min_magnification, lens.max_magnification
    if low > 0:
        return f"{low:g}× to {high:g}×"
    return f"{high:.3g}× there"
