"""Identities the thin-lens depth of field must satisfy, in both distance planes."""

from __future__ import annotations

import math

import pytest
from hypothesis import assume, given, settings
from hypothesis import strategies as st

from camtool.dof.closed import hyperfocal_mm, thin_dof
from camtool.geometry.thinlens import (
    blur_diameter_mm,
    image_distance_mm,
    lens_distances,
    sensor_distance_mm,
)

EPS = 2.0**-52
INF = math.inf
SETTINGS = settings(max_examples=150, deadline=None)


def log_uniform(lo: float, hi: float) -> st.SearchStrategy[float]:
    """Floats spread evenly in log scale over [lo, hi] (the domain spans many decades)."""
    return st.floats(math.log(lo), math.log(hi)).map(lambda x: min(max(math.exp(x), lo), hi))


FOCAL = log_uniform(1.0, 5000.0)
F_NUMBER = log_uniform(0.7, 1024.0)
COC = log_uniform(0.0005, 1.0)

# a few everyday rows, besides the hypothesis draws
EVERYDAY = [(50.0, 8.0, 0.03), (24.0, 16.0, 0.03), (200.0, 2.8, 0.02), (4.0, 1.8, 0.005), (600.0, 5.6, 0.03)]


@pytest.mark.parametrize(("f", "n", "c"), EVERYDAY)
def test_focus_at_hyperfocal_from_the_lens(f: float, n: float, c: float) -> None:
    h = hyperfocal_mm(f, n, c)
    r = thin_dof(f, n, c, h, distance_from="lens")
    assert r.far_mm == INF
    assert r.near_mm == pytest.approx(h / 2, rel=4 * EPS)
    assert r.hyperfocal_mm == h


@given(FOCAL, F_NUMBER, COC)
@SETTINGS
def test_focus_at_hyperfocal_from_the_lens_everywhere(f: float, n: float, c: float) -> None:
    h = hyperfocal_mm(f, n, c)
    assume(h >= 2 * f)  # otherwise H is closer than the closest focus
    r = thin_dof(f, n, c, h, distance_from="lens")
    assert r.far_mm == INF
    assert r.near_mm == pytest.approx(h / 2, rel=4 * EPS)


@given(FOCAL, F_NUMBER, COC)
@SETTINGS
def test_focus_at_the_sensor_plane_hyperfocal(f: float, n: float, c: float) -> None:
    # from the sensor, the reported hyperfocal distance is H + v_H; focused there the far limit
    # is infinite and the near limit is H/2 from the lens, H/2 + v_H from the sensor
    h = hyperfocal_mm(f, n, c)
    assume(h >= 2.5 * f)  # H/2 + v_H is well-conditioned away from the 1:1 fold at u = 2f
    d = thin_dof(f, n, c, 1e6, distance_from="sensor").hyperfocal_mm
    assert d == pytest.approx(h + image_distance_mm(f, h), rel=4 * EPS)
    r = thin_dof(f, n, c, d, distance_from="sensor")
    assert r.far_mm == INF
    # κ(u ← D) = D/(u·|1 − f²/(u − f)²|) from D = u + fu/(u − f)
    kappa = d / (h * abs(1 - (f / (h - f)) ** 2))
    assert r.near_mm == pytest.approx(h / 2 + image_distance_mm(f, h), rel=64 * EPS * (1 + kappa))


def test_pinhole_hyperfocal_closer_than_the_closest_focus() -> None:
    # N·c > f puts H inside 2f: every focus is beyond H, from either plane
    f, n, c = 1.0, 1024.0, 1.0
    assert hyperfocal_mm(f, n, c) < 2 * f
    for d, plane in [(4.0, "sensor"), (4.5, "sensor"), (1e3, "sensor"), (2.0, "lens"), (4.5, "lens")]:
        r = thin_dof(f, n, c, d, distance_from=plane)
        assert r.far_mm == INF, (d, plane)
        assert d >= r.hyperfocal_mm


@pytest.mark.parametrize(("f", "n", "c"), EVERYDAY)
def test_focus_at_infinity(f: float, n: float, c: float) -> None:
    h = hyperfocal_mm(f, n, c)
    lens = thin_dof(f, n, c, INF, distance_from="lens")
    assert lens.near_mm == pytest.approx(h - f, rel=2 * EPS)
    assert lens.far_mm == INF
    assert lens.magnification == 0.0
    sensor = thin_dof(f, n, c, INF, distance_from="sensor")
    assert sensor.near_mm == pytest.approx(h, rel=2 * EPS)  # H − f from the lens, plus v = f
    assert sensor.far_mm == INF


@given(FOCAL, F_NUMBER, COC)
@SETTINGS
def test_focus_at_infinity_everywhere(f: float, n: float, c: float) -> None:
    assert thin_dof(f, n, c, INF, distance_from="lens").near_mm == pytest.approx(
        hyperfocal_mm(f, n, c) - f, rel=4 * EPS
    )


@given(FOCAL, st.floats(1e-9, 1e15))
@SETTINGS
def test_sensor_lens_round_trip_from_the_sensor(f: float, beyond: float) -> None:
    d = 4 * f * (1 + beyond)
    u, v = lens_distances(f, d)
    assert u + v == pytest.approx(d, rel=2 * EPS)
    assert u >= 2 * f >= v * (1 - 2 * EPS)
    assert sensor_distance_mm(f, u) == pytest.approx(d, rel=4 * EPS)


@given(FOCAL, st.floats(1e-6, 1e15))
@SETTINGS
def test_sensor_lens_round_trip_from_the_lens(f: float, beyond: float) -> None:
    u = 2 * f * (1 + beyond)
    d = sensor_distance_mm(f, u)
    back_u, back_v = lens_distances(f, d)
    # D(u) is flat at 1:1 (dD/du = 1 − f²/(u − f)² → 0), so u ← D has κ = D/(u·|dD/du|)
    kappa = d / (u * abs(1 - (f / (u - f)) ** 2))
    assert back_u == pytest.approx(u, rel=16 * EPS * (1 + kappa))
    assert back_v == pytest.approx(image_distance_mm(f, u), rel=16 * EPS * (1 + kappa))


def test_round_trip_at_the_ends() -> None:
    assert lens_distances(50.0, 200.0) == (100.0, 100.0)
    assert lens_distances(50.0, INF) == (INF, 50.0)
    assert sensor_distance_mm(50.0, INF) == INF


@st.composite
def scenes(draw: st.DrawFn) -> tuple[float, float, float, float]:
    """(f, N, c, u): a focus distance from the lens, from 1:1 out to 1e12 mm."""
    f, n, c = draw(FOCAL), draw(F_NUMBER), draw(COC)
    u = 2 * f * (1 + draw(log_uniform(1e-9, 1e12)))
    return f, n, c, u


@given(scenes())
@SETTINGS
def test_blur_at_the_limits_equals_the_coc(scene: tuple[float, float, float, float]) -> None:
    f, n, c, u = scene
    # with N·c ≥ f the blur of any object beyond f stays below the aperture f/N ≤ c; the near
    # limit then lies inside f (a virtual image), where blur_diameter_mm does not apply
    assume(n * c < 0.5 * f)
    r = thin_dof(f, n, c, u, distance_from="lens")
    # blur = (f/N)·|v_s − v_o|/v_o: the difference cancels when the depth is thin, (v_s − v_o)/v_o
    # being about N·c/f; κ ≈ 1 + f/(N·c) for near and far alike, times the far limit's own κ
    kappa = (1 + f / (n * c)) * (1 + u / abs(hyperfocal_mm(f, n, c) - u))
    assert blur_diameter_mm(f, n, u, r.near_mm) == pytest.approx(c, rel=64 * EPS * kappa)
    if math.isfinite(r.far_mm) and r.far_mm < 1e300:
        assert blur_diameter_mm(f, n, u, r.far_mm) == pytest.approx(c, rel=64 * EPS * kappa)


@pytest.mark.parametrize(("f", "n", "c"), EVERYDAY)
@pytest.mark.parametrize("focus_in_f", [2.0, 3.0, 20.0, 60.0, 200.0, 1000.0])
def test_blur_at_the_limits_everyday(f: float, n: float, c: float, focus_in_f: float) -> None:
    u = focus_in_f * f
    r = thin_dof(f, n, c, u, distance_from="lens")
    assert blur_diameter_mm(f, n, u, r.near_mm) == pytest.approx(c, rel=1e-12)
    if math.isfinite(r.far_mm):
        assert blur_diameter_mm(f, n, u, r.far_mm) == pytest.approx(c, rel=1e-12)
    else:
        assert blur_diameter_mm(f, n, u, INF) <= c


@pytest.mark.parametrize(("f", "n", "c"), EVERYDAY)
def test_limits_are_the_same_objects_from_either_plane(f: float, n: float, c: float) -> None:
    u = 30 * f
    v = image_distance_mm(f, u)
    lens = thin_dof(f, n, c, u, distance_from="lens")
    sensor = thin_dof(f, n, c, u + v, distance_from="sensor")
    assert sensor.near_mm == pytest.approx(lens.near_mm + v, rel=1e-13)
    assert sensor.far_mm == pytest.approx(lens.far_mm + v, rel=1e-12)
    assert sensor.total_mm == pytest.approx(lens.total_mm, rel=1e-12)
    assert sensor.magnification == pytest.approx(lens.magnification, rel=1e-13)
