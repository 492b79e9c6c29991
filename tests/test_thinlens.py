"""Thin-lens image formation: the lecture's equations on worked examples, and the plane conversion."""

from __future__ import annotations

import math

import pytest

from camtool.geometry.thinlens import (
    blur_diameter_mm,
    closest_focus_mm,
    extension_mm,
    focus_for_magnification,
    focus_geometry,
    image_distance_mm,
    lens_distances,
    magnification,
    sensor_distance_mm,
    working_f_number,
)

INF = math.inf


@pytest.mark.parametrize(
    ("f", "z_o", "z_i"),
    [
        # thin-lens lecture: 1/f = 1/z_i + 1/z_o, worked by hand
        (50.0, 5050.0, 50.5),  # 1/50 − 1/5050 = 100/5050
        (50.0, 150.0, 75.0),  # 1/50 − 1/150 = 2/150
        (50.0, 100.0, 100.0),  # 1:1, z_o = z_i = 2f
        (100.0, 1100.0, 110.0),  # 1/100 − 1/1100 = 10/1100
        (35.0, 1435.0, 35.875),  # 1/35 − 1/1435 = 40/1435
        (50.0, INF, 50.0),  # infinity focus: the image lies in the focal plane
    ],
)
def test_image_distance_lecture_equation(f: float, z_o: float, z_i: float) -> None:
    assert image_distance_mm(f, z_o) == pytest.approx(z_i, rel=1e-15)
    if math.isfinite(z_o):
        assert 1 / image_distance_mm(f, z_o) + 1 / z_o == pytest.approx(1 / f, rel=1e-15)


@pytest.mark.parametrize(
    ("f", "z_o", "m"),
    [
        # thin-lens lecture: m = z_i/z_o, with z_i from the rows above
        (50.0, 5050.0, 0.01),  # 50.5/5050
        (50.0, 150.0, 0.5),  # 75/150
        (50.0, 100.0, 1.0),  # 100/100
        (100.0, 1100.0, 0.1),  # 110/1100
        (50.0, INF, 0.0),
    ],
)
def test_magnification_is_image_over_object_distance(f: float, z_o: float, m: float) -> None:
    assert magnification(f, z_o) == pytest.approx(m, rel=1e-15)
    if math.isfinite(z_o):
        assert magnification(f, z_o) == pytest.approx(image_distance_mm(f, z_o) / z_o, rel=1e-15)


@pytest.mark.parametrize(
    ("f", "z_o", "extension"),
    [(50.0, 5050.0, 0.5), (50.0, 100.0, 50.0), (100.0, 1100.0, 10.0), (50.0, INF, 0.0)],  # v − f = f·m
)
def test_extension(f: float, z_o: float, extension: float) -> None:
    assert extension_mm(f, z_o) == pytest.approx(extension, rel=1e-14, abs=0.0)


def test_closest_focus_is_one_to_one() -> None:
    # u = v = 2f minimises u + v = 4f (docs/design.md §4)
    assert closest_focus_mm(50.0) == 200.0
    assert closest_focus_mm(50.0, distance_from="lens") == 100.0
    assert closest_focus_mm(50.0, hiatus_mm=7.5) == 207.5


@pytest.mark.parametrize(
    ("f", "n", "z_focus", "z_object", "blur"),
    [
        # thin-lens lecture: C/A = |z_s − z_i|/z_i with the aperture A = f/N
        (50.0, 2.0, 5050.0, INF, 0.25),  # A = 25, z_s = 50.5, z_i = 50: 25·0.5/50
        (50.0, 2.0, INF, 5050.0, 25 * 0.5 / 50.5),  # sensor at 50, image at 50.5
        (50.0, 2.0, 5050.0, 150.0, 25 * 24.5 / 75),  # z_s = 50.5, z_i = 75
        (100.0, 4.0, 1100.0, INF, 25 * 10 / 100),  # A = 25, z_s = 110, z_i = 100
        (50.0, 8.0, 3000.0, 3000.0, 0.0),  # in focus: no blur
    ],
)
def test_blur_diameter_lecture_equation(f: float, n: float, z_focus: float, z_object: float, blur: float) -> None:
    assert blur_diameter_mm(f, n, z_focus, z_object) == pytest.approx(blur, rel=1e-14, abs=0.0)


def test_working_f_number() -> None:
    assert working_f_number(8.0, 1.0) == 16.0  # 1:1 costs two stops
    assert working_f_number(8.0, 0.0) == 8.0


@pytest.mark.parametrize(
    ("f", "d", "u", "v"),
    [
        (50.0, 200.0, 100.0, 100.0),  # 1:1 from the sensor: 4f
        (50.0, 5100.5, 5050.0, 50.5),  # the 1/f row above seen from the sensor: 5050 + 50.5
        (100.0, 450.0, 300.0, 150.0),  # u + v = 450, 1/300 + 1/150 = 1/100
        (50.0, INF, INF, 50.0),
    ],
)
def test_lens_distances_known(f: float, d: float, u: float, v: float) -> None:
    got_u, got_v = lens_distances(f, d)
    assert got_u == pytest.approx(u, rel=1e-15)
    assert got_v == pytest.approx(v, rel=1e-15)
    if math.isfinite(d):
        assert got_u + got_v == pytest.approx(d, rel=1e-15)
        assert 1 / got_u + 1 / got_v == pytest.approx(1 / f, rel=1e-14)


def test_lens_distances_with_hiatus() -> None:
    u, v = lens_distances(100.0, 460.0, hiatus_mm=10.0)
    assert (u, v) == (pytest.approx(300.0), pytest.approx(150.0))
    assert sensor_distance_mm(100.0, 300.0, hiatus_mm=10.0) == pytest.approx(460.0)


def test_focus_geometry_in_both_planes() -> None:
    from_sensor = focus_geometry(100.0, 450.0)
    from_lens = focus_geometry(100.0, 300.0, distance_from="lens")
    for a, b in zip(from_sensor, from_lens):
        assert a == pytest.approx(b, rel=1e-14)
    assert from_lens.magnification == pytest.approx(0.5)
    assert from_lens.extension_mm == pytest.approx(50.0)
    with pytest.raises(ValueError, match="distance_from"):
        focus_geometry(100.0, 300.0, distance_from="film")


@pytest.mark.parametrize("m", [0.01, 0.5, 1.0, 2.0])
def test_focus_for_magnification_inverts_magnification(m: float) -> None:
    g = focus_for_magnification(100.0, m)
    assert magnification(100.0, g.object_mm) == pytest.approx(m, rel=1e-14)
    assert g.image_mm == pytest.approx(image_distance_mm(100.0, g.object_mm), rel=1e-14)
    assert g.sensor_distance_mm == pytest.approx(g.object_mm + g.image_mm, rel=1e-15)
