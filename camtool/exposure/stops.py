"""Standard full, half and third stops of aperture, shutter time and ISO, and snapping to them.

A *stop* is a factor of two in exposure. On the exact scale a stop index k
(counted in steps of 1/n stop, n = 1, 2 or 3) stands for

- the f-number 2^(k/2n) (light goes as 1/N², so N doubles every two stops),
- the shutter time 2^(−k/n) s (k = 0 is 1 s; positive k are faster),
- the ISO speed 100·2^(k/n).

Cameras mark rounded *nominal* values instead (f/5.6 for 5.657, 1/125 s for
1/128 s, ISO 320 for 317). Snapping returns both: the exact stop (for
arithmetic) and its nominal label (for people), plus the input's distance
from the stop in stops. Away from the tables below the labels continue the
rule the tables follow: each label is twice the one a full-stop period
earlier (two stops for f-numbers, one for times and ISO).

Everything works on plain floats (no numpy import) and on numpy arrays.
"""

from __future__ import annotations

from typing import Any

from camtool.core.arrays import is_scalar, ops
from camtool.core.errors import DomainError
from camtool.core.record import NamedTuple
from camtool.core.units import F_NUMBER_THIRD_STOPS

STEPS_PER_STOP = {"full": 1, "half": 2, "third": 3}
"""Divisions of a stop for each named step."""


class Snapped(NamedTuple):
    """A value snapped to a standard stop: the input, the exact stop, its marked label.

    ``error_stops`` is how far the input lies from the exact stop, in stops of
    exposure (positive: the input gives more exposure than the stop would for
    times and ISO, less for f-numbers — it is simply the input's stop index
    minus the snapped one, on the quantity's own stop axis).
    """

    value: Any
    exact: Any
    nominal: Any
    error_stops: Any


_F_THIRD = F_NUMBER_THIRD_STOPS
# Half stops, j = 4·log2(N) from j = -2 (f/0.7) to 24 (f/64); the source of F_NUMBER_THIRD_STOPS.
_F_HALF = (0.7, 0.84, 1.0, 1.2, 1.4, 1.7, 2.0, 2.4, 2.8, 3.3, 4.0, 4.8, 5.6, 6.7, 8.0, 9.5,
           11.0, 13.0, 16.0, 19.0, 22.0, 27.0, 32.0, 38.0, 45.0, 54.0, 64.0)

# Shutter times in seconds, third stops, index j = 3·log2(1/t) from j = -15 (30 s) to
# 39 (1/8000 s): the series on current camera dials and displays (full stops as in
# ISO 516 "Camera shutters": 1, 1/2, 1/4, 1/8, 1/15, 1/30, 1/60, 1/125, ...).
_T_THIRD = (30.0, 25.0, 20.0, 15.0, 13.0, 10.0, 8.0, 6.0, 5.0, 4.0, 3.2, 2.5, 2.0, 1.6, 1.3,
            1.0, 0.8, 0.6, 0.5, 0.4, 1 / 3, 1 / 4, 1 / 5, 1 / 6, 1 / 8, 1 / 10, 1 / 13, 1 / 15,
            1 / 20, 1 / 25, 1 / 30, 1 / 40, 1 / 50, 1 / 60, 1 / 80, 1 / 100, 1 / 125, 1 / 160,
            1 / 200, 1 / 250, 1 / 320, 1 / 400, 1 / 500, 1 / 640, 1 / 800, 1 / 1000, 1 / 1250,
            1 / 1600, 1 / 2000, 1 / 2500, 1 / 3200, 1 / 4000, 1 / 5000, 1 / 6400, 1 / 8000)
# Half stops, j = 2·log2(1/t) from j = -10 (30 s) to 26 (1/8000 s).
_T_HALF = (30.0, 20.0, 15.0, 10.0, 8.0, 6.0, 4.0, 3.0, 2.0, 1.5, 1.0, 0.7, 0.5, 0.3, 1 / 4,
           1 / 6, 1 / 8, 1 / 10, 1 / 15, 1 / 20, 1 / 30, 1 / 45, 1 / 60, 1 / 90, 1 / 125,
           1 / 180, 1 / 250, 1 / 350, 1 / 500, 1 / 750, 1 / 1000, 1 / 1500, 1 / 2000,
           1 / 3000, 1 / 4000, 1 / 6000, 1 / 8000)

# ISO arithmetic speeds, third stops, j = 3·log2(S/100) from j = -12 (ISO 6) to 18 (6400):
# the ISO 12232 / ISO 6 series as marked on cameras and film boxes.
_ISO_THIRD = (6.0, 8.0, 10.0, 12.0, 16.0, 20.0, 25.0, 32.0, 40.0, 50.0, 64.0, 80.0, 100.0,
              125.0, 160.0, 200.0, 250.0, 320.0, 400.0, 500.0, 640.0, 800.0, 1000.0, 1250.0,
              1600.0, 2000.0, 2500.0, 3200.0, 4000.0, 5000.0, 6400.0)
_ISO_HALF = (100.0, 140.0)


class _Series(NamedTuple):
    """Nominal labels for one quantity and step: a table starting at index ``first``."""

    table: tuple[float, ...]
    first: int
    period: int  # steps after which the label doubles (or halves, for times)
    factor: float  # label ratio per period: 2 (f-number, ISO) or 1/2 (time)


def _full(third: tuple[float, ...], first: int) -> tuple[tuple[float, ...], int]:
    """The full-stop subset of a third-stop table whose index ``first`` may not be a multiple of 3."""
    offset = (-first) % 3
    return third[offset::3], (first + offset) // 3


_F_FULL, _F_FULL_FIRST = _full(_F_THIRD, -3)
_T_FULL, _T_FULL_FIRST = _full(_T_THIRD, -15)
_ISO_FULL, _ISO_FULL_FIRST = _full(_ISO_THIRD, -12)

_SERIES = {
    ("f_number", 3): _Series(_F_THIRD, -3, 6, 2.0),
    ("f_number", 2): _Series(_F_HALF, -2, 4, 2.0),
    ("f_number", 1): _Series(_F_FULL, _F_FULL_FIRST, 2, 2.0),
    ("shutter_s", 3): _Series(_T_THIRD, -15, 3, 0.5),
    ("shutter_s", 2): _Series(_T_HALF, -10, 2, 0.5),
    ("shutter_s", 1): _Series(_T_FULL, _T_FULL_FIRST, 1, 0.5),
    ("iso", 3): _Series(_ISO_THIRD, -12, 3, 2.0),
    ("iso", 2): _Series(_ISO_HALF, 0, 2, 2.0),
    ("iso", 1): _Series(_ISO_FULL, _ISO_FULL_FIRST, 1, 2.0),
}


def steps_per_stop(step: str) -> int:
    """Number of divisions per stop for ``"full"``, ``"half"`` or ``"third"``.

    >>> steps_per_stop("third")
    3
    """
    try:
        return STEPS_PER_STOP[step]
    except KeyError:
        raise DomainError("step", step, "one of " + ", ".join(STEPS_PER_STOP)) from None


def round_half_up(x: Any) -> Any:
    """Round to the nearest integer, halves upwards: floor(x + 1/2) (scalars and arrays).

    Written with ``//`` so that the same expression runs on floats and arrays.

    >>> round_half_up(2.5), round_half_up(-2.5), round_half_up(0.49)
    (3.0, -2.0, 0.0)
    """
    return (x + 0.5) // 1.0


def snap_stops(stops: Any, step: str = "third") -> Any:
    """Round a number of stops to the nearest full, half or third stop: round(n·x)/n.

    >>> snap_stops(1.7)
    1.6666666666666667
    >>> snap_stops(1.7, "half")
    1.5
    """
    n = steps_per_stop(step)
    return round_half_up(stops * n) / n


def _label(kind: str, n: int, index: Any) -> Any:
    """Nominal label of stop ``index`` (in 1/n stops) of ``kind`` (float or array)."""
    series = _SERIES[(kind, n)]
    if is_scalar(index):
        return _label_scalar(series, int(index))
    import numpy as np

    flat = [_label_scalar(series, int(j)) for j in np.asarray(index).ravel()]
    return np.asarray(flat, dtype=float).reshape(np.shape(index))


def _label_scalar(series: _Series, j: int) -> float:
    last = series.first + len(series.table) - 1
    scale = 1.0
    if j < series.first:
        periods = -((j - series.first) // series.period)  # ceil((first - j)/period)
        j += periods * series.period
        scale = series.factor**-periods
    elif j > last:
        periods = -((last - j) // series.period)
        j -= periods * series.period
        scale = series.factor**periods
    return series.table[j - series.first] * scale


def _snap(kind: str, value: Any, index_per_stop: Any, exact_of: Any, step: str) -> Snapped:
    n = steps_per_stop(step)
    xp = ops(value)
    position = index_per_stop(xp, value) * n
    j = round_half_up(position)
    return Snapped(value, exact_of(j / n), _label(kind, n, j), (position - j) / n)


def snap_f_number(f_number: Any, step: str = "third") -> Snapped:
    """Snap an f-number to the nearest standard stop: N_exact = 2^(k/2n) and its marked label.

    The stop index is k = round(2n·log2 N); ``error_stops`` = 2·log2(N/N_exact).

    Parameters
    ----------
    f_number : float or array, > 0
    step : "full", "half" or "third"

    References
    ----------
    Wikipedia, "F-number" (standard full, half and third-stop scales).

    Examples
    --------
    >>> s = snap_f_number(5.7)
    >>> round(s.exact, 4), s.nominal
    (5.6569, 5.6)
    >>> snap_f_number(2.92, "full").nominal
    2.8
    >>> snap_f_number(100.0, "full").nominal
    90.0
    """
    return _snap("f_number", f_number, lambda xp, v: 2.0 * xp.log2(v), lambda k: 2.0 ** (k / 2.0), step)


def snap_shutter_s(shutter_s: Any, step: str = "third") -> Snapped:
    """Snap a shutter time in seconds to the nearest standard stop: t_exact = 2^(−k/n) s and its label.

    The stop index is k = round(n·log2(1/t)); ``error_stops`` = log2(t_exact/t).

    Parameters
    ----------
    shutter_s : float or array, > 0 s
    step : "full", "half" or "third"

    References
    ----------
    ISO 516, "Camera shutters" (the marked full-stop series); the third and
    half-stop series as on current camera displays.

    Examples
    --------
    >>> s = snap_shutter_s(1 / 128)
    >>> s.exact, s.nominal
    (0.0078125, 0.008)
    >>> snap_shutter_s(0.236, "full").nominal
    0.25
    >>> snap_shutter_s(60.0, "full").nominal
    60.0
    """
    return _snap("shutter_s", shutter_s, lambda xp, v: -xp.log2(v), lambda k: 2.0 ** -k, step)


def snap_iso(iso: Any, step: str = "third") -> Snapped:
    """Snap an ISO speed to the nearest standard stop: S_exact = 100·2^(k/n) and its marked label.

    Parameters
    ----------
    iso : float or array, > 0
    step : "full", "half" or "third"

    References
    ----------
    ISO 12232 (digital) and ISO 6 (film): the arithmetic speed series
    100, 125, 160, 200, 250, 320, 400, ...

    Examples
    --------
    >>> s = snap_iso(300.0)
    >>> round(s.exact, 1), s.nominal
    (317.5, 320.0)
    >>> snap_iso(12800.0).nominal
    12800.0
    """
    return _snap("iso", iso, lambda xp, v: xp.log2(v / 100.0), lambda k: 100.0 * 2.0**k, step)


def f_number_series(f_min: float, f_max: float, step: str = "full") -> list[float]:
    """Exact f-numbers 2^(k/2n) of the standard stops from ``f_min`` to ``f_max`` (inclusive; 3 % slack so nominal labels count).

    >>> [round(n, 2) for n in f_number_series(1.4, 8.0)]
    [1.41, 2.0, 2.83, 4.0, 5.66, 8.0]
    >>> len(f_number_series(2.8, 5.6, "third"))
    7
    """
    n = steps_per_stop(step)
    xp = ops(f_min, f_max)
    first = int(-((-2 * n * xp.log2(f_min / 1.03)) // 1))
    last = int(2 * n * xp.log2(f_max * 1.03) // 1)
    return [2.0 ** (k / (2 * n)) for k in range(first, last + 1)]
