"""Parsing of lengths, f-numbers and times as people type them.

Units live only at the edge: everything parsed here comes back in millimetres
or seconds, and the formula modules never see a unit string. Each parser
raises :class:`UnitError` (a ``ValueError``) with a message that says what was
expected, so the CLI can name the option and the value in one line.
"""

from __future__ import annotations

import math
import re

MM_PER_UNIT = {
    "um": 0.001,
    "µm": 0.001,
    "mm": 1.0,
    "cm": 10.0,
    "m": 1000.0,
    "km": 1_000_000.0,
    "in": 25.4,
    "inch": 25.4,
    "inches": 25.4,
    '"': 25.4,
    "ft": 304.8,
    "foot": 304.8,
    "feet": 304.8,
    "'": 304.8,
}
"""Millimetres per unit; the inch is exactly 25.4 mm (international yard, 1959)."""

_NUMBER = r"[+-]?(?:\d+(?:\.\d*)?|\.\d+)(?:[eE][+-]?\d+)?"
_LENGTH = re.compile(rf"^\s*({_NUMBER})\s*([a-zA-Zµ\"']*)\s*$")
_FEET_INCHES = re.compile(rf"^\s*({_NUMBER})\s*(?:ft|')\s*({_NUMBER})\s*(?:in|\")?\s*$")
_INFINITY = {"inf", "infinity", "∞", "+inf"}


class UnitError(ValueError):
    """A value could not be read as the quantity it should be."""


def parse_length(text: str | float, default_unit: str = "mm") -> float:
    """Parse a length such as ``50``, ``50mm``, ``3m``, ``10ft``, ``5'6"`` or ``inf`` into mm.

    A bare number takes ``default_unit`` (``"mm"`` for focal lengths and
    sizes, ``"m"`` for subject distances).

    >>> parse_length("3.5cm")
    35.0
    >>> parse_length("2", default_unit="m")
    2000.0
    >>> parse_length("5ft6in")
    1676.4
    >>> parse_length("inf")
    inf
    """
    if isinstance(text, (int, float)):
        return float(text) * MM_PER_UNIT[default_unit]
    raw = text.strip()
    if raw.lower() in _INFINITY:
        return math.inf
    match = _FEET_INCHES.match(raw)
    if match:
        return float(match.group(1)) * 304.8 + float(match.group(2)) * 25.4
    match = _LENGTH.match(raw)
    if not match:
        raise UnitError(f"{text!r} is not a length (examples: 50mm, 3.5cm, 3m, 10ft, 6in, inf)")
    number, unit = match.groups()
    unit = unit or default_unit
    scale = MM_PER_UNIT.get(unit) or MM_PER_UNIT.get(unit.lower())
    if scale is None:
        raise UnitError(f"{text!r} has an unknown unit {unit!r} (use mm, cm, m, km, in or ft)")
    value = float(number) * scale
    if not math.isfinite(value):
        raise UnitError(f"{text!r} is not a finite length (write inf for infinity)")
    return value


_F_NUMBER = re.compile(rf"^\s*(?:[fF]\s*/?\s*)?({_NUMBER})\s*$")


def parse_f_number(text: str | float) -> float:
    """Parse an f-number written ``8``, ``f/8``, ``f8`` or ``F/2.8``.

    >>> parse_f_number("f/2.8")
    2.8
    >>> parse_f_number("f8")
    8.0
    """
    if isinstance(text, (int, float)):
        return float(text)
    match = _F_NUMBER.match(text)
    if not match:
        raise UnitError(f"{text!r} is not an f-number (examples: 8, f/8, f8)")
    return float(match.group(1))


_TIME_PART = re.compile(rf"({_NUMBER})\s*(h|min|m|s|'|\"|)", re.IGNORECASE)
_SECONDS_PER = {"h": 3600.0, "min": 60.0, "m": 60.0, "'": 60.0, "s": 1.0, '"': 1.0, "": 1.0}
_FRACTION = re.compile(rf"^\s*({_NUMBER})\s*/\s*({_NUMBER})\s*s?\s*$")


def parse_time(text: str | float) -> float:
    """Parse a shutter time ``1/250``, ``0.004``, ``2s``, ``30``, ``1m30s``, ``1'30"`` or ``2h`` into seconds.

    >>> parse_time("1/250")
    0.004
    >>> parse_time("1m30s")
    90.0
    >>> parse_time("1'30\\"")
    90.0
    """
    if isinstance(text, (int, float)):
        return float(text)
    match = _FRACTION.match(text)
    if match:
        denominator = float(match.group(2))
        if denominator == 0:
            raise UnitError(f"{text!r} divides by zero")
        return float(match.group(1)) / denominator
    raw = text.strip()
    total, position = 0.0, 0
    for part in _TIME_PART.finditer(raw):
        if raw[position : part.start()].strip():
            break
        total += float(part.group(1)) * _SECONDS_PER[part.group(2).lower()]
        position = part.end()
    if position == 0 or raw[position:].strip():
        raise UnitError(f"{text!r} is not a time (examples: 1/250, 0.5, 2s, 1m30s, 2h)")
    return total


def exact_f_number(nominal: float) -> float:
    """Map a nominal f-number label to the exact value it stands for.

    Third-stop labels (1.4, 2.8, 3.5, 5.6, 6.3, 7.1, 11, 22, ...) are
    rounded values of 2^(k/6); half-stop labels (1.7, 2.4, 3.3, 4.8, 6.7, 9.5,
    13.5, 19, ...) of 2^(k/4). The nearest series value within 3.5 % wins,
    third stops first (so the ambiguous 1.2 and 13 read as third stops). A
    value near neither series is returned unchanged.

    The label 1.2 is 4.8 % from the third stop 2^(1/3) = 1.26 it stands for;
    a wider tolerance would pull the half stops 1.7 and 2.4 onto third stops,
    so 1.2 is looked up by name.

    >>> round(exact_f_number(5.6), 4)
    5.6569
    >>> round(exact_f_number(22), 3)
    22.627
    >>> round(exact_f_number(1.2), 3)
    1.26
    >>> exact_f_number(7.5)
    7.5
    """
    if not (nominal > 0 and math.isfinite(nominal)):
        return nominal
    if nominal == 1.2:
        return 2.0 ** (2 / 6)
    for steps in (6, 4):
        k = round(steps * math.log2(nominal))
        exact = 2.0 ** (k / steps)
        if abs(nominal / exact - 1.0) <= 0.035:
            return exact
    return nominal
