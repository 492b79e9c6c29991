"""Angle of view and field size: 2·atan(h/2f) on worked examples, breathing, and the inverse."""

from __future__ import annotations

import math

import pytest

from camtool.core.errors import DomainError
from camtool.geometry.fov import (
    angle_of_view_deg,
    field_of_view,
    field_size_mm,
    focal_length_for_angle_mm,
)
from camtool.geometry.thinlens import magnification


@pytest.mark.parametrize(
    ("f", "horizontal", "vertical", "diagonal"),
    [
        # 36 × 24 mm frame; FOV = 2·atan(h/2f) (thin-lens lecture); the one-decimal values are
        # the table of Wikipedia, "Angle of view" (35 mm format, lenses focused at infinity)
        (24.0, 73.7, 53.1, 84.1),
        (28.0, 65.5, 46.4, 75.4),
        (35.0, 54.4, 37.8, 63.4),
        (50.0, 39.6, 27.0, 46.8),
        (85.0, 23.9, 16.1, 28.6),
        (100.0, 20.4, 13.7, 24.4),
        (135.0, 15.2, 10.2, 18.2),
        (200.0, 10.3, 6.9, 12.3),
        (300.0, 6.9, 4.6, 8.2),
    ],
)
def test_field_of_view_full_frame(f: float, horizontal: float, vertical: float, diagonal: float) -> None:
    got = field_of_view(36.0, 24.0, f)
    assert [round(a, 1) for a in got] == [horizontal, vertical, diagonal]


@pytest.mark.parametrize(
    ("size", "f", "angle"),
    [
        (36.0, 18.0, 90.0),  # h/2f = 1: 2·atan(1) = 90°
        (24.0, 12.0 / math.sqrt(3.0), 120.0),  # h/2f = √3: 2·60°
        (24.0, 12.0 * math.sqrt(3.0), 60.0),  # h/2f = 1/√3: 2·30°
    ],
)
def test_angle_of_view_exact_angles(size: float, f: float, angle: float) -> None:
    assert angle_of_view_deg(size, f) == pytest.approx(angle, rel=1e-14)
    assert focal_length_for_angle_mm(size, angle) == pytest.approx(f, rel=1e-14)


def test_focus_breathing_replaces_f_by_the_image_distance() -> None:
    # at 1:1 the image lies 2f behind the lens: 36 mm across 100 mm
    assert angle_of_view_deg(36.0, 50.0, magnification=1.0) == pytest.approx(angle_of_view_deg(36.0, 100.0))
    assert angle_of_view_deg(36.0, 50.0, magnification=0.5) < angle_of_view_deg(36.0, 50.0)


def test_field_size() -> None:
    # 50 mm focused at 5050 mm from the lens: m = 50/5000 = 0.01, so 36 mm covers 3.6 m
    assert field_size_mm(36.0, magnification(50.0, 5050.0)) == pytest.approx(3600.0, rel=1e-14)


@pytest.mark.parametrize("angle", [0.0, -5.0, 180.0, 200.0, math.nan])
def test_focal_length_for_angle_domain(angle: float) -> None:
    with pytest.raises(DomainError) as raised:
        focal_length_for_angle_mm(24.0, angle)
    assert raised.value.param == "angle_deg"


@pytest.mark.parametrize(
    ("call", "param"),
    [
        (lambda: angle_of_view_deg(36.0, 0.0), "focal_length_mm"),
        (lambda: angle_of_view_deg(36.0, -50.0), "focal_length_mm"),
        (lambda: angle_of_view_deg(36.0, math.nan), "focal_length_mm"),
        (lambda: angle_of_view_deg(0.0, 50.0), "sensor_mm"),
        (lambda: angle_of_view_deg(36.0, 50.0, magnification=-0.1), "magnification"),
        (lambda: field_size_mm(36.0, -1.0), "magnification"),
        (lambda: focal_length_for_angle_mm(-24.0, 27.0), "sensor_mm"),
    ],
)
def test_fov_domain_errors(call, param: str) -> None:  # type: ignore[no-untyped-def]
    with pytest.raises(DomainError) as raised:
        call()
    assert raised.value.param == param
