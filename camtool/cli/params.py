"""click parameter types for camtool's units: lengths, distances, f-numbers, times, sensors.

Each type accepts a comma-separated list (``-N 2.8,4,5.6``) and returns a
list of floats in millimetres or seconds; options that are also repeatable
are flattened by :func:`flatten`. Bad values fail with click's one-line
``Invalid value for '-N' / '--f-number': ...`` and exit status 2.
"""

from __future__ import annotations

import math
import re
from collections.abc import Callable, Iterable
from typing import Any

import click

from camtool.core import ranges
from camtool.core.ranges import F_NUMBER
from camtool.core.units import MM_PER_UNIT, TStop, UnitError, parse_f_number, parse_length, parse_t_stop, parse_time


class _ListType(click.ParamType):
    """A comma-separated list of values, each parsed and range-checked."""

    parse: Callable[[str], float]
    valid = "> 0"

    def check(self, value: float) -> bool:
        return value > 0 and math.isfinite(value)

    def convert(self, value: Any, param: click.Parameter | None, ctx: click.Context | None) -> list[float]:
        if isinstance(value, list):
            return value
        items = [item for item in str(value).split(",") if item.strip()] if isinstance(value, str) else [value]
        if isinstance(value, str) and len(items) == 2:
            message = self.decimal_comma(value.strip(), items[0].strip(), items[1].strip())
            if message:
                self.fail(message, param, ctx)
        if not items:
            self.fail(f"{value!r} is empty; expected {self.name}", param, ctx)
        out = []
        for item in items:
            try:
                number = self.parse(item)
            except UnitError as error:
                self.fail(str(error), param, ctx)
            if not self.check(number):
                shown = item.strip() if isinstance(item, str) else item
                self.fail(f"{shown} is outside the valid range: {self.valid}", param, ctx)
            out.append(number)
        return out


    def decimal_comma(self, value: str, first: str, second: str) -> str | None:
        """A message when ``first,second`` may be one number written with a decimal comma (see the subclasses)."""
        return None


_DIGITS = re.compile(r"^[0-9]+$")
_DIGITS_UNIT = re.compile(r"^([0-9]+)\s*([a-zA-Zµ\"']+)$")


class LengthType(_ListType):
    """Lengths; a bare number is in ``default_unit`` (mm for focal lengths and sizes).

    ``bounds`` is the valid range in millimetres (a lower bound of 0 is
    exclusive); the error message shows it in ``default_unit``.
    """

    name = "length"

    def __init__(self, default_unit: str = "mm", allow_inf: bool = False,
                 bounds: tuple[float, float] = (0.0, math.inf)) -> None:
        self.default_unit = default_unit
        self.allow_inf = allow_inf
        self.bounds = bounds
        scale = MM_PER_UNIT[default_unit]
        shown = "µm" if default_unit == "um" else default_unit
        low, high = bounds[0] / scale, bounds[1] / scale
        low_text = f"> {low:g}" if low == 0 else f"{low:g}"
        self.valid = (f"{low_text} {shown}" if high == math.inf else f"{low_text} to {high:g} {shown}") + (
            ", or inf" if allow_inf else "")

    def parse(self, text: str) -> float:
        return parse_length(text, self.default_unit)

    def decimal_comma(self, value: str, first: str, second: str) -> str | None:
        """``3,5ft``: a bare whole number, then digits with a unit, reads as 3.5 ft written with a decimal comma.

        A list of two bare numbers (``-s 3,5``) stays a list: it gives a row each, in plain sight.
        """
        unit = _DIGITS_UNIT.match(second)
        if not (_DIGITS.match(first) and unit):
            return None
        shown = "µm" if self.default_unit == "um" else self.default_unit
        return (f"{value!r} is ambiguous: {first}.{unit.group(1)} {unit.group(2)} is written {first}.{second} "
                f"(a decimal point); for the two values {first} {shown} and {second} write {first}{shown},{second}")

    def check(self, value: float) -> bool:
        if value == math.inf:
            return self.allow_inf
        low, high = self.bounds
        return (value > 0 if low == 0 else value >= low * (1 - 1e-12)) and value <= high * (1 + 1e-12)


class FNumberType(_ListType):
    """f-numbers written 8, f/8 or f8; valid 0.7 to 1024 (pinholes)."""

    name = "f-number"
    valid = f"{F_NUMBER[0]:g} to {F_NUMBER[1]:g} (written 8, f/8 or f8)"

    def __init__(self, t_stops: bool = False) -> None:
        self.t_stops = t_stops  # also T-stops (T2), returned as TStop

    def parse(self, text: str) -> float:
        t_stop = parse_t_stop(text) if self.t_stops else None
        return parse_f_number(text) if t_stop is None else TStop(t_stop)

    def check(self, value: float) -> bool:
        return F_NUMBER[0] <= value <= F_NUMBER[1]

    def decimal_comma(self, value: str, first: str, second: str) -> str | None:
        """``2,8`` or ``5,6``: two bare digit strings that read as a third-stop f-number with a decimal comma.

        ``8,11`` and ``4,8`` (no third stop) stay lists of two f-numbers.
        """
        if not (_DIGITS.match(first) and _DIGITS.match(second)) or len(first) + len(second) > 4:
            return None  # a third-stop f-number is at most two digits either side of the comma
        from camtool.exposure.stops import THIRD_STOP_F_NUMBERS

        decimal = float(f"{first}.{second}")
        if decimal != int(decimal) and decimal in THIRD_STOP_F_NUMBERS:
            return (f"{value!r} is ambiguous: f/{decimal:g} is written {decimal:g} (a decimal point); for the two "
                    f"f-numbers f/{first} and f/{second} write f{first},f{second}")
        return None


class TimeType(_ListType):
    """Times written 1/250, 0.004, 2s, 30, 1m30s."""

    name = "time"
    valid = "> 0 s (written 1/250, 0.5, 2s, 1m30s)"

    def parse(self, text: str) -> float:
        return parse_time(text)


class NumberType(_ListType):
    """Plain numbers within [low, high]."""

    name = "number"

    def __init__(self, low: float, high: float) -> None:
        self.low, self.high = low, high
        self.valid = f"{low:g} to {high:g}"

    def parse(self, text: str) -> float:
        try:
            return float(text)
        except ValueError:
            raise UnitError(f"{text!r} is not a number") from None

    def check(self, value: float) -> bool:
        return self.low <= value <= self.high


TILT_MAX = 89.0


class AngleType(click.ParamType):
    """Angles in degrees: ``3``, ``3deg``, ``3°``, ``-2.5``; comma-separated lists; |θ| < 89°."""

    name = "angle"

    def convert(self, value: Any, param: click.Parameter | None, ctx: click.Context | None) -> list[float]:
        if isinstance(value, list):
            return value
        out = []
        for item in str(value).split(","):
            text = item.strip().lower().replace("°", "").replace("degrees", "").replace("deg", "").strip()
            try:
                number = float(text)
            except ValueError:
                self.fail(f"{item.strip()!r} is not an angle (examples: 3, 3deg, 3°, -2.5)", param, ctx)
            if not (abs(number) <= TILT_MAX and math.isfinite(number)):
                self.fail(f"{item.strip()} is outside the valid range: -{TILT_MAX:g}° to {TILT_MAX:g}°", param, ctx)
            out.append(number)
        return out


class PointType(click.ParamType):
    """A point of the scene, ``DIST@HEIGHT``: distance along the line of sight, height above the lens (metres)."""

    name = "DIST@HEIGHT"

    def convert(self, value: Any, param: click.Parameter | None, ctx: click.Context | None) -> tuple[float, float]:
        if isinstance(value, tuple):
            return value
        text = str(value).strip()
        if text.count("@") != 1:
            self.fail(f"{text!r} is not a point: write DIST@HEIGHT, e.g. 3m@-1.6m (1.6 m below the lens)", param, ctx)
        left, right = (part.strip() for part in text.split("@"))
        try:
            distance = parse_length(left, "m")
            height = (-1.0 if right.startswith("-") else 1.0) * parse_length(right.lstrip("+-") or "x", "m")
        except UnitError as error:
            self.fail(f"{text}: {error}", param, ctx)
        if not (distance > 0 and math.isfinite(distance) and math.isfinite(height)):
            self.fail(f"{text} is outside the valid range: a finite distance > 0 and a finite height", param, ctx)
        return distance, height


class CriterionType(click.ParamType):
    """A contrast criterion ``mtf:LEVEL@FREQ`` (:func:`camtool.core.units.parse_criterion`), or one of ``words``."""

    name = "criterion"

    def __init__(self, words: tuple[str, ...] = ()) -> None:
        self.words = words

    def convert(self, value: Any, param: click.Parameter | None, ctx: click.Context | None) -> Any:
        from camtool.core.units import parse_criterion
        from camtool.dof.wave import Criterion

        if isinstance(value, Criterion) or (isinstance(value, str) and value.strip().lower() in self.words):
            return value if isinstance(value, Criterion) else value.strip().lower()
        try:
            return Criterion(*parse_criterion(str(value)))
        except UnitError as error:
            words = f" (or {' or '.join(self.words)})" if self.words else ""
            self.fail(f"{error}{words}", param, ctx)


class ToleranceType(click.ParamType):
    """A relative tolerance written ``1%`` or ``0.01``; valid above 0 and below 1 (100 %)."""

    name = "tolerance"

    def convert(self, value: Any, param: click.Parameter | None, ctx: click.Context | None) -> float:
        if isinstance(value, float):
            return value
        text = str(value).strip()
        try:
            number = float(text[:-1]) / 100.0 if text.endswith("%") else float(text)
        except ValueError:
            self.fail(f"{value!r} is not a tolerance (examples: 1%, 0.5%, 0.01)", param, ctx)
        if not 0.0 < number < 1.0:
            self.fail(f"{text} is outside the valid range: above 0 and below 100 % (1 % = 0.01)", param, ctx)
        return number


class WavelengthType(click.ParamType):
    """A wavelength in nm: ``550``, ``550nm`` or ``0.55um``; valid 200 to 2000 nm."""

    name = "wavelength"

    def convert(self, value: Any, param: click.Parameter | None, ctx: click.Context | None) -> float:
        if isinstance(value, float):
            return value
        text = str(value).strip().lower()
        try:
            nm = float(text[:-2]) if text.endswith("nm") else parse_length(text, "mm") * 1e6 \
                if any(text.endswith(u) for u in ("um", "µm", "mm")) else float(text)
        except (ValueError, UnitError):
            self.fail(f"{value!r} is not a wavelength (examples: 550, 550nm, 0.55um)", param, ctx)
        if not (200.0 <= nm <= 2000.0 and math.isfinite(nm)):
            self.fail(f"{value} is outside the valid range: 200 to 2000 nm", param, ctx)
        return nm


class SignedLengthType(click.ParamType):
    """A length of either sign in mm (``-12``, ``3.5mm``, ``-1cm``), e.g. a hiatus."""

    name = "length"

    def convert(self, value: Any, param: click.Parameter | None, ctx: click.Context | None) -> float:
        if isinstance(value, float):
            return value
        text = str(value).strip()
        sign = -1.0 if text.startswith("-") else 1.0
        try:
            mm = sign * parse_length(text.lstrip("+-"), "mm")
        except UnitError as error:
            self.fail(str(error), param, ctx)
        if not math.isfinite(mm):
            self.fail(f"{text} is outside the valid range: a finite length in mm, either sign", param, ctx)
        return mm


class PupilMagnificationType(click.ParamType):
    """Pupil magnification P = exit/entrance pupil diameter, within ``ranges.PUPIL_MAGNIFICATION``."""

    name = "ratio"

    def convert(self, value: Any, param: click.Parameter | None, ctx: click.Context | None) -> float:
        if isinstance(value, float):
            return value
        try:
            number = float(str(value).strip())
        except ValueError:
            self.fail(f"{value!r} is not a number (examples: 0.6, 1, 2.5)", param, ctx)
        low, high = ranges.PUPIL_MAGNIFICATION
        if not low <= number <= high:
            self.fail(f"{value} is outside the valid range: {low:g} to {high:g} (exit over entrance pupil diameter)",
                      param, ctx)
        return number


def flatten(values: Iterable[list[float] | float] | None) -> list[float]:
    """Join the lists of a repeatable list option (``-N 2.8,4 -N 8``) into one list (one value: a list of one)."""
    if isinstance(values, (int, float)):  # an option that takes one value (pinhole's -s), as the equipment checks see it
        return [float(values)]
    if isinstance(values, (list, tuple)):  # a --batch column (one list, or its values already flat): copied whole
        if len(values) == 1 and type(values[0]) is list:
            return list(values[0])
        if list not in set(map(type, values)):
            return list(values)
    return [v for group in values or () for v in (group if isinstance(group, list) else [group])]


def one_value(ctx: click.Context, param: click.Parameter, value: Any) -> float | None:
    """Option callback: the single value of a list-typed option (``25mm``), or a usage error for a list."""
    if value is None:
        return None
    values = value if isinstance(value, list) else [value]
    if len(values) != 1:
        raise click.BadParameter("takes one value", ctx=ctx, param=param)
    return float(values[0])
