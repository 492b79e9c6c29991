"""Shutter times written as photographers write them: 1/250, 1/8, 0.5", 2", 1'30", 4h.

The notation follows camera displays and exposure tables:

- shorter than about 1/3 s: a fraction ``1/N`` (N a whole number from 10 up,
  one decimal below: ``1/6.3``);
- up to a minute: seconds with a double prime, two significant digits
  below 10 s (``0.5"``, ``1.3"``, ``2"``), whole seconds above (``15"``);
- up to an hour: minutes and seconds (``1'30"``, ``2'``);
- from an hour: hours and minutes (``4h``, ``1h30'``).

The ASCII ``"`` and ``'`` are used so that :func:`camtool.core.units.parse_time`
reads every string back. Formatting is for display only: the numbers stay exact.
"""

from __future__ import annotations

import math

from camtool.core.errors import DomainError

_FRACTION_BELOW_S = 0.34  # 1/3 s is still written 1/3; 0.4 s is written 0.4"


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
    ['1/250', '1/8', '0.5"', '2"', '1\\'30"', '4h']
    >>> [format_time(t) for t in (2 ** -8, 2 ** (-8 / 3), 1 / 3, 0.4, 1.26, 15.0, 5400.0)]
    ['1/256', '1/6.3', '1/3', '0.4"', '1.3"', '15"', "1h30'"]
    """
    if not (shutter_s > 0 and math.isfinite(shutter_s)):
        raise DomainError("shutter_s", shutter_s, "> 0 s and finite")
    if shutter_s < _FRACTION_BELOW_S:
        denominator = 1.0 / shutter_s
        return "1/" + (_trim(denominator, 1) if denominator < 9.95 else str(round(denominator)))
    if shutter_s < 9.95:
        return _trim(float(f"{shutter_s:.2g}"), 2) + '"'
    seconds = round(shutter_s)
    if seconds < 60:
        return f'{seconds}"'
    if seconds < 3600:
        minutes, rest = divmod(seconds, 60)
        return f"{minutes}'" + (f'{rest}"' if rest else "")
    minutes = round(shutter_s / 60.0)
    hours, rest = divmod(minutes, 60)
    return f"{hours}h" + (f"{rest}'" if rest else "")
