"""Circle of confusion from a rule on the sensor."""

from __future__ import annotations

import math

import pytest

from camtool.core.units import UnitError
from camtool.geometry.coc import DEFAULT_RULE, coc_from_rule

FULL_FRAME_DIAGONAL = math.hypot(36.0, 24.0)  # 43.27 mm


@pytest.mark.parametrize(
    ("rule", "width", "height", "coc"),
    [
        # Wikipedia, "Circle of confusion": d/1500 on 36 × 24 mm is 0.029 mm, d/1730 (Zeiss) 0.025 mm,
        # and d/1442 the classic 0.030 mm
        ("d/1500", 36.0, 24.0, 0.0288),
        ("d/1730", 36.0, 24.0, 0.0250),
        ("d/1442", 36.0, 24.0, 0.0300),
        ("d/1500", 23.6, 15.7, 0.0189),  # APS-C 1.5× crop: 28.3 mm diagonal
        ("D / 1500", 36.0, 24.0, 0.0288),
        # 0.25 mm acuity at 25 cm on an 8 × 10 in (203.2 × 254 mm) print filled from 36 × 24 mm:
        # enlargement max(254/36, 203.2/24) = 8.47, so 0.25/8.47 = 0.0295 mm (worked by hand)
        ("print:8x10in@25cm", 36.0, 24.0, 0.0295),
    ],
)
def test_coc_rules(rule: str, width: float, height: float, coc: float) -> None:
    assert round(coc_from_rule(rule, width, height).coc_mm, 4) == coc


def test_diagonal_rule_is_exact() -> None:
    assert coc_from_rule("d/1500", 36.0, 24.0).coc_mm == pytest.approx(FULL_FRAME_DIAGONAL / 1500, rel=1e-15)
    assert DEFAULT_RULE == "d/1500"


def test_pixel_rule() -> None:
    assert coc_from_rule("px:2", 36.0, 24.0, pixel_pitch_mm=0.0045).coc_mm == pytest.approx(0.009)
    with pytest.raises(UnitError, match="pixel pitch"):
        coc_from_rule("px:2", 36.0, 24.0)


def test_origin_names_the_rule() -> None:
    assert coc_from_rule("d/1500", 36.0, 24.0).origin.startswith("d/1500")


@pytest.mark.parametrize("rule", ["", "d/", "d/0", "x/1500", "1500", "px:", "print:8x10in", "print:0x10in@25cm"])
def test_bad_rules(rule: str) -> None:
    with pytest.raises(UnitError):
        coc_from_rule(rule, 36.0, 24.0)
