"""Lengths, f-numbers and times as people type them (docs/design.md §2), and the exact f-number series."""

from __future__ import annotations

import math
import re

import pytest
from hypothesis import given
from hypothesis import strategies as st

from camtool.core import units
from camtool.core.units import (
    UnitError,
    exact_f_number,
    parse_f_number,
    parse_length,
    parse_t_stop,
    parse_time,
)


@pytest.mark.parametrize(
    ("text", "default_unit", "expected_mm"),
    [
        ("50", "mm", 50.0),  # bare number: mm for focal lengths, CoC, sensor sizes
        ("50", "m", 50_000.0),  # bare number: metres for subject distances
        ("50mm", "m", 50.0),  # an explicit unit beats the default
        ("3m", "mm", 3000.0),
        ("3.5cm", "mm", 35.0),
        ("10ft", "mm", 3048.0),  # 1 ft = 304.8 mm exactly (international foot, 1959)
        ("6in", "mm", 152.4),  # 1 in = 25.4 mm exactly
        ("5ft6in", "mm", 1676.4),
        ("5'6\"", "mm", 1676.4),
        (" 2 m ", "mm", 2000.0),
        ("1e3mm", "m", 1000.0),
        ("0.5km", "mm", 500_000.0),
        ("inf", "m", math.inf),
        ("Infinity", "mm", math.inf),
        ("∞", "m", math.inf),
        (2, "m", 2000.0),  # numbers pass through with the default unit
        (35.0, "mm", 35.0),
    ],
)
def test_parse_length(text: str | float, default_unit: str, expected_mm: float) -> None:
    assert parse_length(text, default_unit=default_unit) == pytest.approx(expected_mm, rel=1e-15)
    assert type(parse_length(text, default_unit=default_unit)) is float


@pytest.mark.parametrize(
    "text", ["", "abc", "m", "3xm", "3 m m", "--3", "3..5m", "5,6m", "nan", "1e999m", "3 parsecs"]
)
def test_parse_length_malformed(text: str) -> None:
    with pytest.raises(UnitError):
        parse_length(text)


@pytest.mark.parametrize(
    ("text", "expected"),
    [("8", 8.0), ("f/8", 8.0), ("f8", 8.0), ("F/2.8", 2.8), ("f/ 1.4", 1.4), ("22", 22.0), (5.6, 5.6)],
)
def test_parse_f_number(text: str | float, expected: float) -> None:
    assert parse_f_number(text) == expected


@pytest.mark.parametrize("text", ["", "f", "f/", "f/8/2", "8mm", "t/2", "nan", "f/eight", "1:2.8"])
def test_parse_f_number_malformed(text: str) -> None:
    with pytest.raises(UnitError):
        parse_f_number(text)


def _by_pattern(pattern: str, text: str) -> float | None:
    match = re.match(pattern, text)
    return float(match.group(1)) if match else None


# what people type for an f-number or a T-stop, and what they mistype: digits of other scripts, other spaces
_STOP_TEXT = st.text(st.sampled_from("0123456789.+-eEfFtT/ \t\u00a0\u0663x"), max_size=8)


@given(_STOP_TEXT)
def test_f_number_and_t_stop_read_what_their_patterns_read(text: str) -> None:
    """The shortcuts before the patterns (a plain decimal; a first character that cannot start a T-stop) change
    no answer: each reads exactly what its pattern alone reads (an independent reading of the same grammar)."""
    assert parse_t_stop(text) == _by_pattern(units._T_STOP, text)
    expected = _by_pattern(units._F_NUMBER, text)
    if expected is None:
        with pytest.raises(UnitError):
            parse_f_number(text)
    else:
        assert parse_f_number(text) == expected


@given(st.text(st.sampled_from("0123456789.ftin'\" m"), max_size=9))
def test_feet_and_inches_are_read_only_where_they_are_written(text: str) -> None:
    """The feet-and-inches pattern is tried only on a text holding ft or a prime; the answer is the one the two
    patterns give in order."""
    raw = text.strip()
    if raw.lower() in ("inf", "infinity", "∞", "+inf"):
        return
    match = re.match(units._FEET_INCHES, raw)
    if match:
        assert parse_length(text) == float(match.group(1)) * 304.8 + float(match.group(2)) * 25.4
        return
    try:
        value: float | None = parse_length(text)
    except UnitError:
        value = None
    if units._LENGTH.match(raw) is None:
        assert value is None


@pytest.mark.parametrize(
    ("text", "expected_s"),
    [
        ("1/250", 0.004),
        ("0.004", 0.004),
        ("2s", 2.0),
        ("30", 30.0),
        ("1m30s", 90.0),
        ("1'30\"", 90.0),
        ("2h", 7200.0),
        ("1/3", 1 / 3),
        (0.5, 0.5),
    ],
)
def test_parse_time(text: str | float, expected_s: float) -> None:
    assert parse_time(text) == pytest.approx(expected_s, rel=1e-15)


@pytest.mark.parametrize("text", ["", "s", "abc", "1/0", "1/", "1m30x", "fast", "1/250/2", "2 s s"])
def test_parse_time_malformed(text: str) -> None:
    with pytest.raises(UnitError):
        parse_time(text)


def test_unit_error_is_a_value_error_and_says_what_was_expected() -> None:
    with pytest.raises(ValueError, match="not a length"):
        parse_length("abc")
    with pytest.raises(UnitError, match="unknown unit"):
        parse_length("3 parsecs")


@pytest.mark.parametrize(
    ("nominal", "expected"),
    [
        # third stops 2^(k/6): the nominal labels of the ISO/camera third-stop scale
        (1.4, 2 ** (3 / 6)),  # 1.414
        (2.8, 2 ** (9 / 6)),  # 2.828
        (3.2, 2 ** (10 / 6)),  # 3.175
        (3.5, 2 ** (11 / 6)),  # 3.564
        (5, 2 ** (14 / 6)),  # 5.040
        (5.6, 2 ** (15 / 6)),  # 5.657
        (6.3, 2 ** (16 / 6)),  # 6.350
        (7.1, 2 ** (17 / 6)),  # 7.127
        (11, 2 ** (21 / 6)),  # 11.314
        (13, 2 ** (22 / 6)),  # 12.699: 13 is also a half-stop label; third stops win
        (22, 2 ** (27 / 6)),  # 22.627
        (1.2, 2 ** (2 / 6)),  # 1.260: also a half-stop label; third stops win
        (4, 4.0),  # whole stops are exact already
        (8, 8.0),
        (16, 16.0),
        # half stops 2^(k/4)
        (1.7, 2 ** (3 / 4)),  # 1.682
        (2.4, 2 ** (5 / 4)),  # 2.378
        (3.3, 2 ** (7 / 4)),  # 3.364
        (4.8, 2 ** (9 / 4)),  # 4.757
        (6.7, 2 ** (11 / 4)),  # 6.727
        (9.5, 2 ** (13 / 4)),  # 9.514
        (19, 2 ** (17 / 4)),  # 19.027
        # neither series: unchanged
        (7.5, 7.5),
    ],
)
def test_exact_f_number(nominal: float, expected: float) -> None:
    assert exact_f_number(nominal) == pytest.approx(expected, rel=1e-15)


@pytest.mark.parametrize(
    ("nominal", "rounded"),
    [(5.6, 5.657), (22, 22.627), (1.4, 1.414), (3.2, 3.175), (5, 5.040)],  # docs/design.md §2 and the peer vectors
)
def test_exact_f_number_published_values(nominal: float, rounded: float) -> None:
    assert round(exact_f_number(nominal), 3) == rounded


@pytest.mark.parametrize("value", [0.0, -2.8, math.inf, math.nan])
def test_exact_f_number_passes_non_physical_values_through(value: float) -> None:
    result = exact_f_number(value)
    assert result == value or (math.isnan(result) and math.isnan(value))
