"""Equivalent exposures: the settings that give one exposure value, and time shifts in stops."""

from __future__ import annotations

from typing import Any

from camtool.core.arrays import ops
from camtool.core.domain import SHUTTER_RANGE_S, check
from camtool.core.record import NamedTuple
from camtool.exposure.ev import (
    exposure_value,
)
from camtool.exposure.stops import (
    Snapped,
    f_number_series,
    snap_f_number,
    snap_shutter_s,
    steps_per_stop,
)


class Equivalents(NamedTuple):
    """Equivalent settings for one EV: one entry per f-number, lists of floats.

    ``f_number`` and ``shutter_s`` are exact standard stops (f-numbers 2^(k/2n),
    times 2^(−k/n) s); ``*_nominal`` are their marked labels; ``shutter_exact_s``
    is the unsnapped time N²/2^EV and ``ev`` the EV of each snapped pair
    (equal to the target within half a snapping step).
    """

    f_number: list[float]
    f_number_nominal: list[float]
    shutter_s: list[float]
    shutter_nominal_s: list[float]
    shutter_exact_s: list[float]
    ev: list[float]


def equivalent_exposures(ev: float, f_min: float = 1.0, f_max: float = 32.0, step: str = "full") -> Equivalents:
    """Equivalent f-number and time pairs for settings of EV ``ev``, over standard stops.

    For each standard f-number N from ``f_min`` to ``f_max`` (full, half or
    third stops) the time t = N²/2^EV is snapped to the same kind of stop.
    Rows whose time (exact or snapped) falls outside 1/64000 s to 10⁶ s are left out.

    Parameters
    ----------
    ev : float, −10 to +25 (the settings' EV at the ISO in use, not EV100)
    f_min, f_max : float, f-number range, within 0.7 to 1024
    step : "full", "half" or "third"

    Examples
    --------
    >>> from camtool.exposure.timefmt import format_time
    >>> eq = equivalent_exposures(15.0, 8.0, 22.0)
    >>> eq.f_number_nominal, [format_time(t) for t in eq.shutter_nominal_s]
    ([8.0, 11.0, 16.0, 22.0], ['1/500', '1/250', '1/125', '1/60'])
    """
    check("ev", ev)
    check("f_number", f_min)
    check("f_number", f_max)
    steps_per_stop(step)
    rows: list[tuple[float, ...]] = []
    for n in f_number_series(f_min, f_max, step):
        exact = n * n * 2.0**-ev
        if not (SHUTTER_RANGE_S[0] <= exact <= SHUTTER_RANGE_S[1]):
            continue
        f_snap: Snapped = snap_f_number(n, step)
        t_snap: Snapped = snap_shutter_s(exact, step)
        if not (SHUTTER_RANGE_S[0] <= t_snap.exact <= SHUTTER_RANGE_S[1]):
            continue  # 1/65536 s snaps out of the domain, although 1/64000 s is in it
        rows.append((f_snap.exact, f_snap.nominal, t_snap.exact, t_snap.nominal, exact,
                     exposure_value(f_snap.exact, t_snap.exact)))
    columns = list(zip(*rows)) if rows else [()] * 6
    return Equivalents(*(list(c) for c in columns))


def shift_time_s(shutter_s: Any, stops: Any) -> Any:
    """Time in seconds after adding ``stops`` of exposure: t·2^stops (negative stops shorten it).

    >>> shift_time_s(1 / 125, 10.0)
    8.192
    """
    return shutter_s * ops(shutter_s, stops).exp2(stops)
