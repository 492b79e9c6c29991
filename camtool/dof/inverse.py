"""The inverse depth-of-field problem: where to focus, and at which f-number, for a wanted near and far limit.

For a thin lens the exact limits satisfy 1/near + 1/far = 2/u and
1/near − 1/far = 2·(N·c/f²)·(1 − f/u), with distances u from the lens: the
focus is the harmonic mean of the limits and the f-number follows. From the
sensor plane the lens-to-sensor spacing v depends on the focus itself, so the
focus distance is found by bisection on the one equation that remains.
Lengths in millimetres.
"""

from __future__ import annotations

from typing import Any

from camtool.core.arrays import ops, quiet
from camtool.core.errors import DomainError, first_bad, require, require_positive
from camtool.core.planes import FOCUS_PLANES, check_plane
from camtool.core.record import NamedTuple

_BISECTIONS = 120


class FocusSolution(NamedTuple):
    """Focus distance (same plane as the limits given) in mm and the f-number that make near..far sharp."""

    distance_mm: Any
    f_number: Any


def focus_for_limits(
    focal_length_mm: Any, coc_mm: Any, near_mm: Any, far_mm: Any, distance_from: str = "sensor"
) -> FocusSolution:
    """Focus distance in mm and f-number whose thin-lens depth of field runs exactly from near to far.

    From the lens: u = 2·n·F/(n + F) (F = ∞ gives u = 2n) and
    N = f²·(F − n) / (2·c·n·F·(1 − f/u)).

    Parameters
    ----------
    focal_length_mm : float or array, f > 0
    coc_mm : float or array, c > 0
    near_mm : float or array
        Wanted near limit; at least the closest focus (4f from the sensor, 2f from the lens).
    far_mm : float or array
        Wanted far limit, > near (``inf`` allowed).
    distance_from : ``"sensor"`` or ``"lens"``

    References
    ----------
    Inverts the exact thin-lens limits of :func:`camtool.dof.closed.thin_dof`; the
    harmonic-mean focus is the classic result (Merklinger, *The INs and OUTs
    of FOCUS*, 1992).

    Examples
    --------
    >>> s = focus_for_limits(50.0, 0.03, 2000.0, 4000.0, distance_from="lens")
    >>> round(s.distance_mm, 1), round(s.f_number, 3)
    (2666.7, 10.616)
    """
    require_positive("focal_length_mm", focal_length_mm)
    require_positive("coc_mm", coc_mm)
    require_positive("far_mm", far_mm, allow_inf=True)
    require("far_mm", far_mm, far_mm > near_mm, "greater than the near limit {limit}", limit=near_mm)
    f = focal_length_mm
    xp = ops(f, coc_mm, near_mm, far_mm)
    if check_plane(distance_from, FOCUS_PLANES) == "lens":
        require("near_mm", near_mm, near_mm >= 2.0 * f,
                "at least {limit} from the lens (the closest focus, 2 × focal length)", limit=2.0 * f)
        u = _harmonic(xp, near_mm, far_mm)
        return FocusSolution(u, _f_number(xp, f, coc_mm, near_mm, far_mm, u))
    require("near_mm", near_mm, near_mm >= 4.0 * f,
            "at least {limit} from the sensor (the closest focus, 4 × focal length)", limit=4.0 * f)
    lo = near_mm + 0.0 * f
    hi = xp.minimum(far_mm, 4.0 * near_mm)
    with quiet(xp):
        for _ in range(_BISECTIONS):
            mid = 0.5 * (lo + hi)
            above = _residual(xp, f, mid, near_mm, far_mm) > 0
            hi = xp.where(above, mid, hi)
            lo = xp.where(above, lo, mid)
        focus = 0.5 * (lo + hi)
        u, v = _split(xp, f, focus)
        n_u, f_u = near_mm - v, far_mm - v
        f_number = _f_number(xp, f, coc_mm, n_u, f_u, u)
    if not bool(xp.all(f_number > 0)):
        raise DomainError("near_mm", near_mm, "a near limit the lens can reach at this focal length")
    return FocusSolution(focus, f_number)


def _harmonic(xp: Any, near: Any, far: Any) -> Any:
    # 2nF/(n + F), written 2n/(1 + n/F) so that F = inf gives 2n
    return 2.0 * near / (1.0 + near / far)


def _f_number(xp: Any, f: Any, coc: Any, near: Any, far: Any, u: Any) -> Any:
    spread = (1.0 - near / far) / near  # 1/n - 1/F without cancelling for distant F
    return f * f * spread / (2.0 * coc * (1.0 - f / u))


def _split(xp: Any, f: Any, distance: Any) -> tuple[Any, Any]:
    root = xp.sqrt(xp.maximum(1.0 - 4.0 * f / distance, 0.0))
    v = 2.0 * f / (1.0 + root)
    return distance - v, v


def _residual(xp: Any, f: Any, distance: Any, near: Any, far: Any) -> Any:
    u, v = _split(xp, f, distance)
    return u - _harmonic(xp, near - v, far - v)


class FixedApertureFocus(NamedTuple):
    """Where to focus at a given f-number for a wanted range, and the limits that focus gives (mm).

    ``near_mm`` ≤ the wanted near limit and ``far_mm`` ≥ the wanted far limit;
    ``needed_f_number`` is the f-number that would make the range exact.
    """

    distance_mm: Any
    near_mm: Any
    far_mm: Any
    needed_f_number: Any


def focus_for_limits_at(
    focal_length_mm: Any, f_number: Any, coc_mm: Any, near_mm: Any, far_mm: Any, distance_from: str = "sensor"
) -> FixedApertureFocus:
    """Focus distance in mm that best uses a fixed f-number to cover near..far, and the limits it gives.

    The focus is the one of :func:`focus_for_limits`: it centres the wanted
    range in the reciprocal distances that the thin-lens blur is linear in
    (1/near + 1/far = 2/u from the lens), so the blur at the wanted near and
    far limits is the same and at most c. Stopped down beyond the f-number
    that range needs, the depth of field is then wider than asked on both
    sides by the same blur margin. An f-number wider than needed cannot
    cover the range at any focus (the reciprocal span 2·N·c·(1 − f/u)/f²
    grows with N); that is a :class:`DomainError` on ``f_number`` naming the
    f-number needed and the limits the given one reaches at that focus.

    Parameters
    ----------
    focal_length_mm, f_number, coc_mm : float or array, all > 0
    near_mm, far_mm : float or array
        Wanted near (at least the closest focus) and far limit (> near, ``inf`` allowed).
    distance_from : ``"sensor"`` or ``"lens"``

    References
    ----------
    Merklinger, *The INs and OUTs of FOCUS* (1992): the focus at the harmonic
    mean of the limits; the limits themselves from :func:`camtool.dof.closed.thin_dof`.

    Examples
    --------
    >>> s = focus_for_limits_at(50.0, 16.0, 0.03, 2000.0, 4000.0, distance_from="lens")
    >>> round(s.distance_mm, 1), round(s.near_mm, 1), round(s.far_mm, 1), round(s.needed_f_number, 3)
    (2666.7, 1774.9, 5359.1, 10.616)
    """
    from camtool.dof.closed import thin_dof

    require_positive("f_number", f_number, unit="")
    solution = focus_for_limits(focal_length_mm, coc_mm, near_mm, far_mm, distance_from)
    needed = solution.f_number
    xp = ops(focal_length_mm, f_number, coc_mm, near_mm, far_mm)
    ok = f_number >= needed * (1.0 - 1e-9)
    if not bool(xp.all(ok)):
        bad = first_bad(f_number, ok) if not isinstance(ok, bool) else f_number
        reached = thin_dof(focal_length_mm, f_number, coc_mm, solution.distance_mm, distance_from)
        near_reached = first_bad(reached.near_mm, ok) if not isinstance(ok, bool) else reached.near_mm
        far_reached = first_bad(reached.far_mm, ok) if not isinstance(ok, bool) else reached.far_mm
        need = first_bad(needed, ok) if not isinstance(ok, bool) else needed
        raise DomainError("f_number", bad, f"f/{float(need):.3g} or more to cover the wanted near and far limits",
                          detail=f"at f/{float(bad):g} the best focus gives {_mm(near_reached)} to {_mm(far_reached)}")
    limits = thin_dof(focal_length_mm, f_number, coc_mm, solution.distance_mm, distance_from)
    return FixedApertureFocus(solution.distance_mm, limits.near_mm, limits.far_mm, needed)


def _mm(value: Any) -> str:
    value = float(value)
    if value == float("inf"):
        return "infinity"
    return f"{value / 1000:.4g} m" if value >= 1000 else f"{value:.4g} mm"
