"""The physical domain of the exposure inputs, checked in one place.

Times 1/64000 s to 10⁶ s, f-numbers 0.7 to 1024, ISO 1 to 10⁷, EV −10 to +25
(for a given EV or EV100). :func:`check` raises
:class:`camtool.core.errors.DomainError` outside them.
"""

from __future__ import annotations

from typing import Any

from camtool.core.errors import require

SHUTTER_RANGE_S = (1.0 / 64000.0, 1.0e6)
F_NUMBER_RANGE = (0.7, 1024.0)
ISO_RANGE = (1.0, 1.0e7)
EV_RANGE = (-10.0, 25.0)

_VALID = {
    "shutter_s": "1/64000 s to 1000000 s",
    "f_number": "f/0.7 to f/1024",
    "iso": "ISO 1 to 10000000",
    "ev": "EV -10 to +25",
    "ev100": "EV -10 to +25",
}
_RANGES = {
    "shutter_s": SHUTTER_RANGE_S,
    "f_number": F_NUMBER_RANGE,
    "iso": ISO_RANGE,
    "ev": EV_RANGE,
    "ev100": EV_RANGE,
}


def check(param: str, value: Any, detail: str = "") -> None:
    """Raise :class:`DomainError` unless ``value`` of ``param`` lies in its domain.

    ``param`` is one of ``shutter_s``, ``f_number``, ``iso``, ``ev``, ``ev100``.
    NaN fails (every comparison with it is false).

    >>> check("f_number", 2048.0)
    Traceback (most recent call last):
    ...
    camtool.core.errors.DomainError: f_number=2048 is outside the valid range: f/0.7 to f/1024
    """
    low, high = _RANGES[param]
    # A relative slack of 1e-12 lets round-trips land on the ends of the range.
    low, high = low - abs(low) * 1e-12, high + abs(high) * 1e-12
    require(param, value, (value >= low) & (value <= high), _VALID[param], detail)
