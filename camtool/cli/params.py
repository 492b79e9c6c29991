"""click parameter types for camtool's units: lengths, distances, f-numbers, times, sensors.

Each type accepts a comma-separated list (``-N 2.8,4,5.6``) and returns a
list of floats in millimetres or seconds; options that are also repeatable
are flattened by :func:`flatten`. Bad values fail with click's one-line
``Invalid value for '-N' / '--f-number': ...`` and exit status 2.
"""

from __future__ import annotations

import math
from collections.abc import Callable, Iterable
from typing import Any

import click

from camtool.core import ranges, units
from camtool.core.ranges import F_NUMBER
from camtool.core.units import UnitError


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
        scale = units.MM_PER_UNIT[default_unit]
        shown = "µm" if default_unit == "um" else default_unit
        low, high = bounds[0] / scale, bounds[1] / scale
        low_text = f"> {low:g}" if low == 0 else f"{low:g}"
        self.valid = (f"{low_text} {shown}" if high == math.inf else f"{low_text} to {high:g} {shown}") + (
            ", or inf" if allow_inf else "")

    def parse(self, text: str) -> float:
        return units.parse_length(text, self.default_unit)

    def decimal_comma(self, value: str, first: str, second: str) -> str | None:
        return units.decimal_comma_length(value, first, second, self.default_unit)

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
        t_stop = units.parse_t_stop(text) if self.t_stops else None
        return units.parse_f_number(text) if t_stop is None else units.TStop(t_stop)

    def check(self, value: float) -> bool:
        return F_NUMBER[0] <= value <= F_NUMBER[1]

    def decimal_comma(self, value: str, first: str, second: str) -> str | None:
        return units.decimal_comma_f_number(value, first, second)


class TimeType(_ListType):
    """Times written 1/250, 0.004, 2s, 30, 1m30s."""

    name = "time"
    valid = "> 0 s (written 1/250, 0.5, 2s, 1m30s)"

    def parse(self, text: str) -> float:
        return units.parse_time(text)


class NumberType(_ListType):
    """Plain numbers within [low, high]."""

    name = "number"

    def __init__(self, low: float, high: float) -> None:
        self.low, self.high = low, high
        self.valid = f"{low:g} to {high:g}"

    def parse(self, text: str) -> float:
        try:
            return units.plain_number(str(text))
        except ValueError:
            raise UnitError(f"{text!r} is not a number") from None

    def check(self, value: float) -> bool:
        return self.low <= value <= self.high


class AngleType(_ListType):
    """Angles in degrees: ``3``, ``3deg``, ``3°``, ``-2.5``; comma-separated lists (:func:`units.parse_angle`)."""

    name = "angle"
    parse = staticmethod(units.parse_angle)
    bounds = ranges.TILT_DEG

    def check(self, value: float) -> bool:
        return True  # parse_angle checks the range


class Parsed(click.ParamType):
    """One value read by a parser of :mod:`camtool.core.units`, which also checks its range."""

    def __init__(self, name: str, parse: Callable[[str], Any], done: type = float,
                 bounds: tuple[float, float] | None = None) -> None:
        self.name, self.parse, self.done, self.bounds = name, parse, done, bounds  # bounds: those parse checks

    def convert(self, value: Any, param: click.Parameter | None, ctx: click.Context | None) -> Any:
        if isinstance(value, self.done):  # a default or a value already converted
            return value
        try:
            return self.parse(str(value))
        except UnitError as error:
            self.fail(str(error), param, ctx)


def PointType() -> Parsed:
    """A point of the scene, ``DIST@HEIGHT``: distance along the line of sight, height above the lens (metres)."""
    return Parsed("DIST@HEIGHT", units.parse_point, tuple)


def ToleranceType() -> Parsed:
    """A relative tolerance written ``1%`` or ``0.01``: above 0 and below 1 (100 %)."""
    return Parsed("tolerance", units.parse_tolerance, bounds=ranges.TOLERANCE)


def WavelengthType() -> Parsed:
    """A wavelength in nm: ``550``, ``550nm`` or ``0.55um``; valid 200 to 2000 nm."""
    return Parsed("wavelength", units.parse_wavelength, bounds=ranges.WAVELENGTH_NM)


def SignedLengthType() -> Parsed:
    """A length of either sign in mm (``-12``, ``3.5mm``, ``-1cm``), e.g. a hiatus."""
    return Parsed("length", units.parse_signed_length)


def PupilMagnificationType() -> Parsed:
    """Pupil magnification P = exit/entrance pupil diameter, within ``ranges.PUPIL_MAGNIFICATION``."""
    return Parsed("ratio", units.parse_pupil_magnification, bounds=ranges.PUPIL_MAGNIFICATION)


class CriterionType(click.ParamType):
    """A contrast criterion ``mtf:LEVEL@FREQ`` (:func:`camtool.core.units.parse_criterion`), or one of ``words``."""

    name = "criterion"

    def __init__(self, words: tuple[str, ...] = ()) -> None:
        self.words = words

    def convert(self, value: Any, param: click.Parameter | None, ctx: click.Context | None) -> Any:
        from camtool.dof.wave import Criterion

        if isinstance(value, Criterion) or (isinstance(value, str) and value.strip().lower() in self.words):
            return value if isinstance(value, Criterion) else value.strip().lower()
        try:
            return Criterion(*units.parse_criterion(str(value)))
        except UnitError as error:
            words = f" (or {' or '.join(self.words)})" if self.words else ""
            self.fail(f"{error}{words}", param, ctx)


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
