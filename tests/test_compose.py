"""Perspective composition: constant-magnification distance, dolly zoom, background scale and blur."""

from __future__ import annotations

import math

import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st

from camtool.core.errors import DomainError
from camtool.geometry import thinlens
from camtool.geometry.compose import (
    composition,
    defocus_blur_mm,
    lens_distance_mm,
    magnification_for_fill,
    plane_magnification,
    plane_view,
    sensor_distance_mm,
)

FOCAL_LENGTHS = [24.0, 35.0, 50.0, 85.0, 135.0, 200.0]  # the command's default list (issue 4)
FULL_FRAME = (36.0, 24.0)  # 135 format, mm (ISO 1007 / the shared sensors reference)


@pytest.mark.parametrize(
    ("f", "m", "s", "d"),
    [
        (50.0, 1.0, 100.0, 200.0),  # 1:1: s = v = 2f, D = 4f (Hecht, Optics §5.2)
        (50.0, 0.01, 5050.0, 5100.5),  # s = 50·101, v = 50.5
        (100.0, 0.5, 300.0, 450.0),  # s = 3f, v = 1.5f
    ],
)
def test_constant_magnification_distance(f: float, m: float, s: float, d: float) -> None:
    # s = f(1 + 1/m) from the lens, D = f(1 + 1/m) + f(1 + m) from the sensor.
    assert lens_distance_mm(f, m) == pytest.approx(s, rel=1e-15)
    assert sensor_distance_mm(f, m) == pytest.approx(d, rel=1e-15)


@given(f=st.floats(1.0, 5000.0), m=st.floats(1e-6, 10.0))
def test_distance_agrees_with_the_thin_lens(f: float, m: float) -> None:
    # Cross-check against the thin-lens module: at s the lens gives back m, and the
    # sensor-plane form is u + v of the thin-lens equation.
    s = lens_distance_mm(f, m)
    assert thinlens.magnification(f, s) == pytest.approx(m, rel=1e-9)
    assert sensor_distance_mm(f, m) == pytest.approx(thinlens.sensor_distance_mm(f, s), rel=1e-12)


def test_fill_gives_magnification() -> None:
    # A 1.8 m person filling 80 % of a 24 mm frame height: m = 0.8·24/1800.
    assert magnification_for_fill(1800.0, 0.8, 24.0) == pytest.approx(0.0106667, rel=1e-5)


def test_dolly_zoom_keeps_the_field_at_the_subject() -> None:
    m = magnification_for_fill(1800.0, 0.8, FULL_FRAME[1])
    rows = composition(np.array(FOCAL_LENGTHS), m, *FULL_FRAME)
    np.testing.assert_allclose(rows.field_height_mm, 1800.0 / 0.8, rtol=1e-12)
    np.testing.assert_allclose(rows.field_width_mm, 1800.0 / 0.8 * 1.5, rtol=1e-12)
    # ... while the distance grows with f and the angle of view shrinks.
    assert np.all(np.diff(rows.distance_mm) > 0)
    assert np.all(np.diff(rows.horizontal_deg) < 0)


def test_composition_angles_match_the_field_of_view() -> None:
    c = composition(50.0, 1.0, 36.0, 24.0)
    # At 1:1 the image distance is 2f, so the angle is that of a 100 mm lens at infinity.
    assert c.horizontal_deg == pytest.approx(2 * math.degrees(math.atan(18.0 / 100.0)))
    assert c.image_distance_mm == 100.0


def test_scalar_and_array_agree() -> None:
    f = np.array(FOCAL_LENGTHS)
    table = composition(f, 0.02, *FULL_FRAME)
    for i, fi in enumerate(FOCAL_LENGTHS):
        row = composition(fi, 0.02, *FULL_FRAME)
        assert row.distance_mm == pytest.approx(table.distance_mm[i], rel=1e-15)
        assert row.vertical_deg == pytest.approx(table.vertical_deg[i], rel=1e-15)
    grid = composition(f.reshape(2, 3), 0.02, *FULL_FRAME)
    np.testing.assert_array_equal(grid.distance_mm, table.distance_mm.reshape(2, 3))


# --- background and foreground ----------------------------------------------


@pytest.mark.parametrize(
    ("f", "n", "m", "x", "b"),
    [
        (50.0, 2.0, 0.01, math.inf, 0.25),  # b → f·m/N for a background at infinity
        (100.0, 2.0, 0.02, 5100.0, 0.5),  # x = s = 5100: b = (f·m/N)·1/2 = 1·1/2
        (100.0, 2.0, 0.02, 0.0, 0.0),  # the subject plane itself is sharp
        (100.0, 2.0, 0.02, -2550.0, 1.0),  # foreground at s/2 in front: x/(s − x) = 1
    ],
)
def test_blur_disc(f: float, n: float, m: float, x: float, b: float) -> None:
    # b = (f·m/N)·x_d/(s ± x_d) (Wikipedia, "Depth of field", foreground and background blur).
    assert defocus_blur_mm(f, n, m, x) == pytest.approx(b, rel=1e-12, abs=1e-15)


@given(f=st.floats(10.0, 600.0), n=st.floats(1.0, 32.0), m=st.floats(1e-3, 1.0), x=st.floats(-0.9, 100.0))
def test_blur_agrees_with_the_thin_lens_blur_circle(f: float, n: float, m: float, x: float) -> None:
    # The same blur from the image side, C = (f/N)·|v_s − v_o|/v_o (thin-lens module);
    # x is given as a fraction of the distance f(1 + 1/m) − f that keeps the plane beyond f.
    s = lens_distance_mm(f, m)
    offset = x * (s - f)
    expected = thinlens.blur_diameter_mm(f, n, s, s + offset)
    assert defocus_blur_mm(f, n, m, offset) == pytest.approx(expected, rel=1e-9, abs=1e-12)


@given(f=st.floats(10.0, 400.0), k=st.floats(0.1, 10.0), m=st.floats(1e-3, 0.5), n=st.floats(1.0, 22.0))
def test_background_blur_scales_with_k(f: float, k: float, m: float, n: float) -> None:
    # The lecture's point: scale focal length and distance by k (same subject size in the
    # frame, so the same m) and a distant background's blur disc scales by k.
    far = 1e12  # mm; s/far < 1e-6 for every case drawn here
    assert defocus_blur_mm(k * f, n, m, far) == pytest.approx(k * defocus_blur_mm(f, n, m, far), rel=1e-5)
    assert defocus_blur_mm(k * f, n, m, math.inf) == pytest.approx(k * defocus_blur_mm(f, n, m, math.inf), rel=1e-12)


def test_background_scale_and_visible_width() -> None:
    m = 0.02
    views = plane_view(np.array(FOCAL_LENGTHS), 2.8, m, 36.0, 10000.0, reference_focal_length_mm=24.0)
    assert views.scale[0] == 1.0
    assert np.all(np.diff(views.scale) > 0)  # longer lens, larger background ("compression")
    assert np.all(np.diff(views.visible_width_mm) < 0)  # ... and less of it
    # scale = v(s_ref + x)/(v_ref(s + x)) with s = f(1 + 1/m), v = f(1 + m)
    s, s_ref = 200.0 * 51.0, 24.0 * 51.0
    assert views.scale[-1] == pytest.approx(200.0 * (s_ref + 10000.0) / (24.0 * (s + 10000.0)), rel=1e-12)
    # The background at infinity: scale f/f_ref, the whole plane visible (infinitely wide).
    far = plane_view(200.0, 2.8, m, 36.0, math.inf, reference_focal_length_mm=24.0)
    assert far.scale == pytest.approx(200.0 / 24.0)
    assert far.visible_width_mm == math.inf
    assert far.blur_pct == pytest.approx(100.0 * 200.0 * m / 2.8 / 36.0)


def test_subject_plane_scale_is_the_magnification() -> None:
    assert plane_magnification(85.0, 0.05, 0.0) == pytest.approx(0.05, rel=1e-15)


def test_foreground_in_front_of_the_focal_point_is_an_error() -> None:
    s = lens_distance_mm(50.0, 0.1)  # 550 mm
    with pytest.raises(DomainError) as info:
        defocus_blur_mm(50.0, 2.0, 0.1, -(s - 50.0))
    assert info.value.param == "offset_mm"


@pytest.mark.parametrize(
    ("call", "param"),
    [
        (lambda: lens_distance_mm(0.0, 0.1), "focal_length_mm"),
        (lambda: lens_distance_mm(50.0, 0.0), "magnification"),
        (lambda: sensor_distance_mm(50.0, float("nan")), "magnification"),
        (lambda: magnification_for_fill(1800.0, 0.0, 24.0), "fill"),
        (lambda: magnification_for_fill(-1.0, 0.5, 24.0), "subject_size_mm"),
        (lambda: defocus_blur_mm(50.0, 0.5, 0.1, 100.0), "f_number"),
        (lambda: composition(np.array([24.0, -1.0]), 0.1, 36.0, 24.0), "focal_length_mm"),
    ],
)
def test_domain_errors(call, param: str) -> None:
    with pytest.raises(DomainError) as info:
        call()
    assert info.value.param == param
