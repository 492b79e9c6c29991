"""Times written as photographers write them: 1/250, 1/8, 0.5s, 2s, 15s, and bulb times 1m 30s, 36m 25s, 4h.

The notation follows camera displays and exposure tables, with units
spelled out (never ``'`` and ``"``, which read as feet and inches):

- shorter than about 1/3 s: a fraction ``1/N`` (N a whole number from 10 up,
  one decimal below: ``1/6.3``);
- up to 10 s: seconds with two significant digits (``0.5s``, ``1.3s``, ``2s``);
- up to a minute: seconds to a tenth (``15s``, ``16.7s``, ``45s``);
- longer: hours, minutes and seconds, exactly to the second (``1m 30s``,
  ``36m 25s``, ``1h 5m 3s``). Times longer than the slowest shutter-dial
  speed (30 s) are bulb times and are never rounded to a stop.

:func:`camtool.core.units.parse_time` reads every string back. Formatting is
for display only: the numbers stay exact.
"""

from __future__ import annotations

import math

from camtool.core.errors import DomainError

_FRACTION_BELOW_S = 0.34  # 1/3 s is still written 1/3; 0.4 s is written 0.4s


def _trim(number: float, decimals: int) -> str:
    text = f"{number:.{decimals}f}"
    return text.rstrip("0").rstrip(".") if "." in text else text


def format_time(shutter_s: float) -> str:
    """Write a time in seconds the way a photographer would.

    Parameters
    ----------
    shutter_s : float, > 0 s (a plain number; format arrays element by element)

    Examples
    --------
    >>> [format_time(t) for t in (1 / 250, 1 / 8, 0.5, 2.0, 90.0, 4 * 3600.0)]
    ['1/250', '1/8', '0.5s', '2s', '1m 30s', '4h']
    >>> [format_time(t) for t in (2 ** -8, 2 ** (-8 / 3), 1 / 3, 0.4, 1.26, 15.0, 2185.0, 5400.0)]
    ['1/256', '1/6.3', '1/3', '0.4s', '1.3s', '15s', '36m 25s', '1h 30m']
    """
    if not (shutter_s > 0 and math.isfinite(shutter_s)):
        raise DomainError("shutter_s", shutter_s, "> 0 s and finite")
    if shutter_s < _FRACTION_BELOW_S:
        denominator = 1.0 / shutter_s
        return "1/" + (_trim(denominator, 1) if denominator < 9.95 else str(round(denominator)))
    if shutter_s < 9.95:
        return _trim(float(f"{shutter_s:.2g}"), 2) + "s"
    if shutter_s < 59.95:
        return _trim(shutter_s, 1) + "s"
    seconds = round(shutter_s)
    hours, rest = divmod(seconds, 3600)
    minutes, seconds = divmod(rest, 60)
    parts = [f"{value}{unit}" for value, unit in ((hours, "h"), (minutes, "m"), (seconds, "s")) if value]
    return " ".join(parts)
