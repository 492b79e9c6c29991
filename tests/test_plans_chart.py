"""camtool.plans.chart called directly: keyword arguments, ChartData results, numbers checked independently."""

from __future__ import annotations

import math

import pytest

from camtool.core.errors import DomainError, InputError
from camtool.plans.chart import (
    CARD_F_NUMBERS,
    POINTS,
    aperture_chart,
    blur_chart,
    card_chart,
    check_pixels,
    dof_chart,
    figure_size,
    image_format,
)


def test_the_format_comes_from_the_extension_or_the_option() -> None:
    assert image_format(output="a/b.PDF", given=None) == "pdf"
    assert image_format(output="-", given="svg") == "svg"
    with pytest.raises(InputError) as usage:
        image_format(output="-", given=None)
    assert usage.value.usage
    with pytest.raises(InputError) as clash:
        image_format(output="{x}.png", given="svg")  # braces in a file name stay as typed
    assert str(clash.value) == "{x}.png has the extension .png but image_format is svg"


def test_the_size_and_the_pixel_bound() -> None:
    # ISO 216 A6 is 148 × 105 mm, landscape
    assert figure_size(size_in=None, paper="a6") == pytest.approx((148 / 25.4, 105 / 25.4), rel=1e-12)
    assert figure_size(size_in=(3.0, 2.0), paper="a6") == (3.0, 2.0)
    check_pixels(size_in=(40.0, 40.0), dpi=300.0)  # 12000 × 12000: the bound itself
    with pytest.raises(InputError):
        check_pixels(size_in=(40.0, 40.0), dpi=301.0)


def test_the_dof_chart_range_ends_at_twice_the_hyperfocal_distance() -> None:
    # Wikipedia, "Hyperfocal distance": H = f²/(N·c) + f from the lens; 85 mm f/2, c = 0.03 mm
    h = 85.0**2 / (2.0 * 0.03) + 85.0
    data = dof_chart(focal_lengths_mm=[85.0], f_numbers=[2.0], coc_mm=0.03, model="thin", distance_from="lens")
    x = data.curves[0].x
    assert len(x) == POINTS and x[0] == 850.0 and x[-1] == pytest.approx(2.0 * h, rel=1e-12)
    assert data.scene == "85 mm" and data.extra["models"] == ["thin"]
    with pytest.raises(DomainError):
        dof_chart(focal_lengths_mm=[85.0], f_numbers=[2.0], coc_mm=0.03, to_mm=math.inf)
    with pytest.raises(InputError):
        dof_chart(focal_lengths_mm=[35.0, 50.0], f_numbers=[2.0, 4.0], coc_mm=0.03)
    with pytest.raises(InputError):
        dof_chart(focal_lengths_mm=[50.0], f_numbers=[2.0], coc_mm=0.03, from_mm=5000.0, to_mm=4000.0)


def test_the_blur_chart_at_infinity_is_f_m_over_n() -> None:
    # a subject 1.8 m tall filling 0.8 of a 24 mm frame: m = 0.8 × 24 / 1800; blur at ∞ = f·m/N
    data = blur_chart(f_numbers=[2.8], focal_lengths_mm=[85.0], subject_size_mm=1800.0, fill=0.8,
                      sensor_width_mm=36.0, sensor_height_mm=24.0, sensor_label="full frame")
    assert data.marks[0].y == pytest.approx(85.0 * (0.8 * 24.0 / 1800.0) / 2.8, rel=1e-12)
    with pytest.raises(InputError):
        blur_chart(f_numbers=[2.8], sensor_width_mm=36.0, sensor_height_mm=24.0, sensor_label="full frame")


def test_the_aperture_chart_needs_the_scene() -> None:
    with pytest.raises(InputError):
        aperture_chart(focal_length_mm=50.0, coc_mm=0.03, near_mm=1000.0, far_mm=None)


def test_the_card_defaults_and_exact_stops() -> None:
    card = card_chart(focal_length_mm=50.0, coc_mm=0.03, model="thin", distance_from="lens")
    assert card.extra["f_numbers"] == CARD_F_NUMBERS and card.extra["distances_mm"][-1] == math.inf
    imperial = card_chart(focal_length_mm=50.0, coc_mm=0.03, units="imperial", model="thin")
    assert imperial.extra["distances_mm"][0] == pytest.approx(2 * 304.8, rel=1e-15)  # 2 ft
    exact = card_chart(focal_length_mm=50.0, coc_mm=0.03, f_numbers=[5.6], exact_stops=True, distances_mm=[3000.0])
    assert exact.extra["f_numbers"] == [pytest.approx(2 ** (5 / 2), rel=1e-12)]  # f/5.6 is 2^(5/2)
