"""Parsing of lengths, f-numbers and times as people type them.

Units live only at the edge: everything parsed here comes back in millimetres
or seconds, and the formula modules never see a unit string. Each parser
raises :class:`UnitError` (a ``ValueError``) with a message that says what was
expected, so the CLI can name the option and the value in one line.
"""

from __future__ import annotations

import itertools
import math
import re

from camtool.core.errors import CamtoolError

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
_FEET_INCHES = rf"^\s*({_NUMBER})\s*(?:ft|')\s*({_NUMBER})\s*(?:in|\")?\s*$"  # compiled on first use
_INFINITY = {"inf", "infinity", "∞", "+inf"}


class UnitError(CamtoolError, ValueError):
    """A value could not be read as the quantity it should be."""


def plain_number(text: str) -> float:
    """``float(text)`` without Python's digit separator (``1_000``), which no camtool input takes (ValueError).

    >>> plain_number(" 2.5e3 ")
    2500.0
    """
    if "_" in text:
        raise ValueError(f"{text!r}: a digit separator")
    return float(text)


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
    match = re.match(_FEET_INCHES, raw) if "ft" in raw or "'" in raw else None
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


_F_NUMBER = rf"^\s*(?:[fF]\s*/?\s*)?({_NUMBER})\s*$"  # compiled on first use (re's cache)


def parse_f_number(text: str | float) -> float:
    """Parse an f-number written ``8``, ``f/8``, ``f8`` or ``F/2.8``.

    >>> parse_f_number("f/2.8")
    2.8
    >>> parse_f_number("f8")
    8.0
    """
    if isinstance(text, (int, float)):
        return float(text)
    if text.isascii() and text.replace(".", "", 1).isdigit():  # 8, 5.6, .5: what the pattern reads, without it
        return float(text)
    match = re.match(_F_NUMBER, text)
    if not match:
        raise UnitError(f"{text!r} is not an f-number (examples: 8, f/8, f8)")
    return float(match.group(1))


class TStop(float):
    """A T-stop read from ``-N T2``: a float that remembers it was a T-stop (exposure uses it as is)."""


_T_STOP = rf"^\s*[tT]\s*/?\s*({_NUMBER})\s*$"


def parse_t_stop(text: str | float) -> float | None:
    """Read a T-stop written ``T2``, ``T/2.8`` or ``t2.8``; ``None`` when ``text`` is not a T-stop.

    A T-stop is the f-number of an ideal lens passing the same light
    (N/√transmittance): exposure uses it as is.

    >>> parse_t_stop("T2.8"), parse_t_stop("f/2.8")
    (2.8, None)
    """
    if isinstance(text, (int, float)):
        return None
    if text.lstrip()[:1] not in ("t", "T"):  # the pattern's first character: not compiled for an f-number
        return None
    match = re.match(_T_STOP, text)  # compiled on first use (re caches it): no start-up cost
    return float(match.group(1)) if match else None


_TIME_UNITS = {"h": 3600.0, "min": 60.0, "m": 60.0, "'": 60.0, "s": 1.0, '"': 1.0}
_TIME_RANK = {"h": 0, "min": 1, "m": 1, "'": 1, "s": 2, '"': 2}
# Patterns of the time parser, compiled on first use (re caches them): commands without times pay nothing.
_TIME_PART = rf"\s*({_NUMBER})\s*(h|min|m|s|'|\"|)\s*"  # matched on lower case
_FRACTION = rf"^\s*({_NUMBER})\s*/\s*({_NUMBER})\s*s?\s*$"  # compiled on first use (re's cache)
_CLOCK = r"^\s*(\d+):(\d\d(?:\.\d*)?)(?::(\d\d(?:\.\d*)?))?\s*$"
_TIME_EXAMPLES = "examples: 1/250, 0.5, 2s, 90s, 1m30s, 1:30, 2h5m, 1:02:03"


def parse_time(text: str | float) -> float:
    """Parse a time ``1/250``, ``0.004``, ``2s``, ``30``, ``90s``, ``1m30s``, ``1:30``, ``2h5m`` into seconds.

    The rules, so that no time is read in a unit the writer did not mean:

    - a bare number is seconds (``30``, ``0.5``); a fraction ``1/250`` is seconds;
    - otherwise every number carries its unit, ``h``, ``m`` (or ``min``) and
      ``s``, largest first, each once: ``1h30m``, ``2m 5s``, ``36m 25s``;
      ``2h30`` is refused (30 minutes or 30 seconds?) with the spellings that
      say it;
    - a clock ``m:ss`` or ``h:mm:ss`` (``1:30`` is 90 s, ``1:02:03`` is
      3723 s), the minutes and seconds after a colon in two digits below 60;
    - ``1'30"`` (minutes and seconds in primes) is still read.

    >>> parse_time("1/250")
    0.004
    >>> parse_time("1m30s"), parse_time("90s"), parse_time("1:30")
    (90.0, 90.0, 90.0)
    >>> parse_time("36m 25s")
    2185.0
    >>> parse_time("2h30")
    Traceback (most recent call last):
    ...
    camtool.core.units.UnitError: '2h30' is ambiguous: give every number its unit (2h30m or 2h30s) or a clock (2:30:00 is h:mm:ss)
    """
    if isinstance(text, (int, float)):
        return float(text)
    match = re.match(_FRACTION, text)
    if match:
        denominator = float(match.group(2))
        if denominator == 0:
            raise UnitError(f"{text!r} divides by zero")
        return float(match.group(1)) / denominator
    match = re.match(_CLOCK, text)
    if match:
        return _clock_seconds(text, match)
    raw = text.strip().lower()
    parts: list[tuple[float, str]] = []
    position = 0
    while position < len(raw):
        part = re.compile(_TIME_PART).match(raw, position)
        if part is None or part.end() == position:
            raise UnitError(f"{text!r} is not a time ({_TIME_EXAMPLES})")
        parts.append((float(part.group(1)), part.group(2).lower()))
        position = part.end()
    if not parts:
        raise UnitError(f"{text!r} is not a time ({_TIME_EXAMPLES})")
    if len(parts) == 1 and parts[0][1] == "":
        return parts[0][0]
    if any(unit == "" for _, unit in parts):
        raise UnitError(_ambiguous_time(text, parts))
    ranks = [_TIME_RANK[unit] for _, unit in parts]
    if any(a >= b for a, b in itertools.pairwise(ranks)):
        raise UnitError(f"{text!r} is not a time: units go largest first, each once ({_TIME_EXAMPLES})")
    return sum(value * _TIME_UNITS[unit] for value, unit in parts)


def _ambiguous_time(text: str, parts: list[tuple[float, str]]) -> str:
    """The message for a number without its unit after one with a unit (``2h30``), with the spellings meant."""
    index = next(i for i, (_, unit) in enumerate(parts) if unit == "")
    before = parts[index - 1][1] if index else "h"
    prefix = "".join(f"{v:g}{u}" for v, u in parts[:index])
    number = f"{parts[index][0]:g}"
    nearer = {"h": "m", "min": "s", "m": "s", "'": "s"}.get(before, "s")
    choices = sorted({f"{prefix}{number}{nearer}", f"{prefix}{number}s"}, key=lambda c: c[-1] != "m")
    clock = ""
    if len(parts) == 2 and before == "h":
        clock = f" or a clock ({parts[0][0]:g}:{parts[1][0]:02g}:00 is h:mm:ss)"
    elif len(parts) == 2 and before in ("m", "min", "'"):
        clock = f" or a clock ({parts[0][0]:g}:{parts[1][0]:02g} is m:ss)"
    return f"{text!r} is ambiguous: give every number its unit ({' or '.join(choices)}){clock}"


def _clock_seconds(text: str, match: re.Match[str]) -> float:
    """Seconds of a clock time ``m:ss`` or ``h:mm:ss``."""
    fields = [float(g) for g in match.groups() if g is not None]
    if any(field >= 60 for field in fields[1:]):
        raise UnitError(f"{text!r} is not a clock time: minutes and seconds after a colon are 00 to 59")
    if len(fields) == 2:
        return fields[0] * 60.0 + fields[1]
    return fields[0] * 3600.0 + fields[1] * 60.0 + fields[2]


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


def parse_guide_number(text: str | float) -> float:
    """A flash guide number in metres: a bare number or ``40m`` is metres, ``131ft`` feet (× 0.3048).

    >>> parse_guide_number("40"), parse_guide_number("40m"), round(parse_guide_number("131ft"), 4)
    (40.0, 40.0, 39.9288)
    """
    raw = str(text).strip().lower()
    scale = 1.0
    if raw.endswith("ft"):
        raw, scale = raw[:-2].strip(), 0.3048
    elif raw.endswith("m"):
        raw = raw[:-1].strip()
    try:
        return plain_number(raw) * scale
    except ValueError:
        raise UnitError(f"{text!r} is not a guide number (examples: 40, 40m, 131ft)") from None


def parse_criterion(text: str) -> tuple[float, float | None]:
    """Parse a contrast criterion ``mtf:LEVEL@FREQ`` into (level, lp/mm or None for ``@coc``).

    LEVEL is a fraction or a percentage, FREQ line pairs per mm on the sensor
    (``lp/mm`` may follow) or ``coc`` (one line pair per circle of confusion,
    1/c). Bounds: :data:`camtool.core.ranges.MTF_LEVEL` and
    :data:`camtool.core.ranges.FREQUENCY_LPMM`.

    >>> parse_criterion("mtf:0.3@40"), parse_criterion("MTF:50%@coc"), parse_criterion("mtf:0.2@25lp/mm")
    ((0.3, 40.0), (0.5, None), (0.2, 25.0))
    >>> parse_criterion("mtf:1.5@40")
    Traceback (most recent call last):
    ...
    camtool.core.units.UnitError: 'mtf:1.5@40': the level 1.5 is outside the valid range: 0.05 to 0.95
    """
    from camtool.core.ranges import FREQUENCY_LPMM, MTF_LEVEL, describe, in_range

    match = re.match(_CRITERION, str(text), re.IGNORECASE)
    if not match:
        raise UnitError(f"{text!r} is not a contrast criterion (examples: mtf:0.3@40, mtf:50%@coc)")
    level = float(match.group(1)) / (100.0 if match.group(2) else 1.0)
    if not in_range(level, MTF_LEVEL):
        raise UnitError(f"{text!r}: the level {level:g} is outside the valid range: {describe(MTF_LEVEL)}")
    if match.group(3).lower() == "coc":
        return level, None
    frequency = float(match.group(3))
    if not in_range(frequency, FREQUENCY_LPMM):
        raise UnitError(f"{text!r}: the frequency {frequency:g} lp/mm is outside the valid range: "
                        f"{describe(FREQUENCY_LPMM, 'lp/mm')}")
    return level, frequency


_CRITERION = rf"^\s*mtf\s*:\s*({_NUMBER})\s*(%?)\s*@\s*(coc|{_NUMBER})\s*(?:lp/mm)?\s*$"  # compiled on first use (re's cache)


def _bounded(text: str, number: float, bounds: tuple[float, float], unit: str, what: str = "") -> float:
    """``number`` if it is within ``bounds`` (NaN never), else the one-line range error naming ``text``."""
    from camtool.core.ranges import describe, in_range

    if not in_range(number, bounds):
        raise UnitError(f"{text} is outside the valid range: {describe(bounds, unit)}{what}")
    return number


def parse_angle(text: str | float) -> float:
    """An angle in degrees, ``3``, ``3deg``, ``3°`` or ``-2.5``, within :data:`camtool.core.ranges.TILT_DEG`.

    >>> parse_angle("3°"), parse_angle("-2.5deg")
    (3.0, -2.5)
    """
    from camtool.core.ranges import TILT_DEG

    shown = str(text).strip()
    bare = shown.lower().replace("°", "").replace("degrees", "").replace("deg", "").strip()
    try:
        number = plain_number(bare)
    except ValueError:
        raise UnitError(f"{shown!r} is not an angle (examples: 3, 3deg, 3°, -2.5)") from None
    if not TILT_DEG[0] <= number <= TILT_DEG[1]:
        raise UnitError(f"{shown} is outside the valid range: {TILT_DEG[0]:g}° to {TILT_DEG[1]:g}°")
    return number


def parse_tolerance(text: str | float) -> float:
    """A relative tolerance written ``1%`` or ``0.01``, within :data:`camtool.core.ranges.TOLERANCE`.

    >>> parse_tolerance("1%"), parse_tolerance("0.005")
    (0.01, 0.005)
    """
    from camtool.core.ranges import TOLERANCE

    shown = str(text).strip()
    try:
        number = plain_number(shown[:-1]) / 100.0 if shown.endswith("%") else plain_number(shown)
    except ValueError:
        raise UnitError(f"{text!r} is not a tolerance (examples: 1%, 0.5%, 0.01)") from None
    if not TOLERANCE[0] < number <= TOLERANCE[1]:
        raise UnitError(f"{shown} is outside the valid range: above 0 and below 100 % (1 % = 0.01)")
    return number


def parse_wavelength(text: str | float) -> float:
    """A wavelength in nm, ``550``, ``550nm`` or ``0.55um``, within :data:`camtool.core.ranges.WAVELENGTH_NM`.

    >>> parse_wavelength("550"), parse_wavelength("0.55um")
    (550.0, 550.0)
    """
    from camtool.core.ranges import WAVELENGTH_NM

    shown = str(text).strip().lower()
    try:
        nm = plain_number(shown[:-2]) if shown.endswith("nm") else parse_length(shown, "mm") * 1e6 \
            if any(shown.endswith(u) for u in ("um", "µm", "mm")) else plain_number(shown)
    except (ValueError, UnitError):
        raise UnitError(f"{text!r} is not a wavelength (examples: 550, 550nm, 0.55um)") from None
    return _bounded(str(text), nm, WAVELENGTH_NM, "nm")


def parse_signed_length(text: str | float) -> float:
    """A length of either sign in mm (``-12``, ``3.5mm``, ``-1cm``), e.g. a lens's hiatus.

    >>> parse_signed_length("-1cm"), parse_signed_length("3.5")
    (-10.0, 3.5)
    """
    shown = str(text).strip()
    mm = (-1.0 if shown.startswith("-") else 1.0) * parse_length(shown.lstrip("+-"), "mm")
    if not math.isfinite(mm):
        raise UnitError(f"{shown} is outside the valid range: a finite length in mm, either sign")
    return mm


def parse_pupil_magnification(text: str | float) -> float:
    """A pupil magnification (exit over entrance pupil diameter) within ``ranges.PUPIL_MAGNIFICATION``.

    >>> parse_pupil_magnification("0.6")
    0.6
    """
    from camtool.core.ranges import PUPIL_MAGNIFICATION

    try:
        number = plain_number(str(text).strip())
    except ValueError:
        raise UnitError(f"{text!r} is not a number (examples: 0.6, 1, 2.5)") from None
    return _bounded(str(text), number, PUPIL_MAGNIFICATION, "", " (exit over entrance pupil diameter)")


def parse_point(text: str) -> tuple[float, float]:
    """A point of a scene, ``DIST@HEIGHT`` in metres by default: (distance along the sight line, height) in mm.

    >>> parse_point("3m@-1.6m")
    (3000.0, -1600.0)
    """
    shown = str(text).strip()
    if shown.count("@") != 1:
        raise UnitError(f"{shown!r} is not a point: write DIST@HEIGHT, e.g. 3m@-1.6m (1.6 m below the lens)")
    left, right = (part.strip() for part in shown.split("@"))
    try:
        distance = parse_length(left, "m")
        height = (-1.0 if right.startswith("-") else 1.0) * parse_length(right.lstrip("+-") or "x", "m")
    except UnitError as error:
        raise UnitError(f"{shown}: {error}") from None
    if not (distance > 0 and math.isfinite(distance) and math.isfinite(height)):
        raise UnitError(f"{shown} is outside the valid range: a finite distance > 0 and a finite height")
    return distance, height


_DIGITS = r"^[0-9]+$"  # compiled on first use (re's cache)
_DIGITS_UNIT = r"^([0-9]+)\s*([a-zA-Zµ\"']+)$"  # compiled on first use (re's cache)

F_NUMBER_THIRD_STOPS = (0.7, 0.8, 0.9, 1.0, 1.1, 1.2, 1.4, 1.6, 1.8, 2.0, 2.2, 2.5, 2.8, 3.2, 3.5, 4.0,
                        4.5, 5.0, 5.6, 6.3, 7.1, 8.0, 9.0, 10.0, 11.0, 13.0, 14.0, 16.0, 18.0, 20.0,
                        22.0, 25.0, 29.0, 32.0, 36.0, 40.0, 45.0, 51.0, 57.0, 64.0)
"""Nominal f-numbers in third stops, 6·log2(N) from -3 (f/0.7) to 36 (f/64): the marks of lens barrels and camera
displays (Wikipedia, "F-number", table "Standard full-stop, half-stop and one-third-stop f-number scales")."""


def decimal_comma_length(value: str, first: str, second: str, unit: str) -> str | None:
    """The error for ``3,5ft``: a bare whole number, then digits with a unit, reads as 3.5 ft with a decimal comma.

    A list of two bare numbers (``-s 3,5``) stays a list: it gives a row each, in plain sight.
    """
    with_unit = re.match(_DIGITS_UNIT, second)
    if not (re.match(_DIGITS, first) and with_unit):
        return None
    shown = "µm" if unit == "um" else unit
    return (f"{value!r} is ambiguous: {first}.{with_unit.group(1)} {with_unit.group(2)} is written {first}.{second} "
            f"(a decimal point); for the two values {first} {shown} and {second} write {first}{shown},{second}")


def decimal_comma_f_number(value: str, first: str, second: str) -> str | None:
    """The error for ``2,8`` or ``5,6``: two bare digit strings that read as a third-stop f-number.

    ``8,11`` and ``4,8`` (no third stop) stay lists of two f-numbers.
    """
    if not (re.match(_DIGITS, first) and re.match(_DIGITS, second)) or len(first) + len(second) > 4:
        return None  # a third-stop f-number is at most two digits either side of the comma
    decimal = float(f"{first}.{second}")
    if decimal != int(decimal) and decimal in F_NUMBER_THIRD_STOPS:
        return (f"{value!r} is ambiguous: f/{decimal:g} is written {decimal:g} (a decimal point); for the two "
                f"f-numbers f/{first} and f/{second} write f{first},f{second}")
    return None


_FIGURE_SIZE = r"^\s*(\d+(?:\.\d*)?)\s*[x×X]\s*(\d+(?:\.\d*)?)\s*(in|cm|mm)?\s*$"  # compiled on first use (re's cache)


def parse_figure_size(text: str) -> tuple[float, float]:
    """A figure size ``WxH`` in inches (``8x5``) or with a unit (``20x12cm``, ``160x100mm``), in inches.

    Each side within :data:`camtool.core.ranges.CHART_SIDE_IN`.

    >>> parse_figure_size("8x5"), parse_figure_size("25.4x12.7cm")
    ((8.0, 5.0), (10.0, 5.0))
    """
    from camtool.core.ranges import CHART_SIDE_IN

    match = re.match(_FIGURE_SIZE, str(text))
    if not match:
        raise UnitError(f"{text!r} is not a size (examples: 8x5, 8x5in, 20x12cm)")
    per_inch = {"in": 1.0, None: 1.0, "cm": 2.54, "mm": 25.4}[match.group(3)]
    width, height = float(match.group(1)) / per_inch, float(match.group(2)) / per_inch
    low, high = CHART_SIDE_IN
    if not (low <= width <= high and low <= height <= high):
        raise UnitError(f"{text} is outside the valid range: {low:g} to {high:g} inches a side")
    return width, height


LUX_PER_FOOT_CANDLE = 1.0 / 0.09290304
"""Lux in one foot-candle (one lumen per square foot; the foot is 0.3048 m exactly): 10.7639."""


def parse_illuminance(text: str | float) -> float:
    """An illuminance in lux: a bare number, ``400lx`` or ``400lux``, or foot-candles ``37fc``.

    >>> parse_illuminance("400lx"), round(parse_illuminance("37fc"), 2)
    (400.0, 398.26)
    """
    raw = str(text).strip().lower()
    scale = 1.0
    for unit, factor in (("lux", 1.0), ("lx", 1.0), ("fc", LUX_PER_FOOT_CANDLE)):
        if raw.endswith(unit):
            raw, scale = raw[: -len(unit)].strip(), factor
            break
    try:
        return plain_number(raw) * scale
    except ValueError:
        raise UnitError(f"{text!r} is not an illuminance (examples: 400, 400lx, 37fc)") from None
