"""The inverse problem: focus distance and f-number for a wanted near and far limit, in both planes."""

from __future__ import annotations

import math

import pytest
from hypothesis import assume, given, settings
from hypothesis import strategies as st

from camtool.dof.closed import hyperfocal_mm, thin_dof
from camtool.dof.inverse import focus_for_limits

EPS = 2.0**-52
INF = math.inf
SETTINGS = settings(max_examples=150, deadline=None)


def log_uniform(lo: float, hi: float) -> st.SearchStrategy[float]:
    return st.floats(math.log(lo), math.log(hi)).map(lambda x: min(max(math.exp(x), lo), hi))


@pytest.mark.parametrize(
    ("f", "c", "near", "far", "distance", "n"),
    [
        # from the lens: u = 2nF/(n + F) and N = f²(F − n)/(2c·n·F·(1 − f/u)), by hand:
        (50.0, 0.03, 2000.0, 4000.0, 8000 / 3, 2500 * 2000 / (2 * 0.03 * 8e6 * (1 - 50 * 3 / 8000))),
        # far at infinity: focus at 2·near, which is then the hyperfocal distance H = f²/(Nc) + f
        (24.0, 0.03, 1000.0, INF, 2000.0, 576 / (0.03 * 1976)),
        (50.0, 0.03, 5000.0, INF, 10_000.0, 2500 / (0.03 * 9950)),
    ],
)
def test_inverse_from_the_lens_known(f: float, c: float, near: float, far: float, distance: float, n: float) -> None:
    s = focus_for_limits(f, c, near, far, distance_from="lens")
    assert s.distance_mm == pytest.approx(distance, rel=1e-14)
    assert s.f_number == pytest.approx(n, rel=1e-13)


def test_far_at_infinity_means_focus_at_the_hyperfocal_distance() -> None:
    s = focus_for_limits(24.0, 0.03, 1000.0, INF, distance_from="lens")
    assert hyperfocal_mm(24.0, s.f_number, 0.03) == pytest.approx(s.distance_mm, rel=1e-14)
    r = thin_dof(24.0, s.f_number, 0.03, s.distance_mm, distance_from="lens")
    assert r.near_mm == pytest.approx(1000.0, rel=1e-14)
    assert r.far_mm > 1e12 or r.far_mm == INF  # H itself: the far limit is at or within rounding of ∞


@st.composite
def forward_scenes(draw: st.DrawFn) -> tuple[float, float, float, float, str]:
    """(f, N, c, focus, plane) with a finite far limit, not within rounding of the hyperfocal distance."""
    plane = draw(st.sampled_from(["lens", "sensor"]))
    f, n, c = draw(log_uniform(1.0, 5000.0)), draw(log_uniform(0.7, 1024.0)), draw(log_uniform(0.0005, 1.0))
    h = hyperfocal_mm(f, n, c)
    closest = 2 * f if plane == "lens" else 4 * f
    assume(n * c < f)  # otherwise every focus is beyond H: no finite far limit to invert
    hyper = h if plane == "lens" else thin_dof(f, n, c, INF).hyperfocal_mm
    fraction = draw(log_uniform(1e-6, 0.999))  # how far from the closest focus toward H
    focus = closest + fraction * (hyper - closest)
    assume(closest < focus < hyper)
    return f, n, c, focus, plane


@given(forward_scenes())
@SETTINGS
def test_inverse_round_trips_through_thin_dof(scene: tuple[float, float, float, float, str]) -> None:
    f, n, c, focus, plane = scene
    r = thin_dof(f, n, c, focus, distance_from=plane)
    assume(math.isfinite(r.far_mm) and r.far_mm < 1e300)
    # the inverse takes near limits from the closest focus on (its documented domain), though a
    # near limit can lie closer than the closest focus when the focus does not
    assume(r.near_mm >= (2 if plane == "lens" else 4) * f)
    s = focus_for_limits(f, c, r.near_mm, r.far_mm, distance_from=plane)
    # N comes from 1/near − 1/far, which cancels for a shallow zone (κ ≈ far/(far − near)); the
    # far limit itself carries κ_far ≈ 5H/(H − u) near the hyperfocal distance, and from the
    # sensor the conversion D → u is flat at 1:1 (κ ≈ D/(u·|1 − f²/(u − f)²|))
    u = focus if plane == "lens" else focus / 2 * (1 + math.sqrt(max(1 - 4 * f / focus, 0.0)))
    kappa = (r.far_mm / (r.far_mm - r.near_mm)) * (1 + 5 * hyperfocal_mm(f, n, c) / abs(hyperfocal_mm(f, n, c) - u))
    if plane == "sensor":
        kappa *= 1 + focus / (u * max(abs(1 - (f / (u - f)) ** 2), 1e-300))
    assert s.distance_mm == pytest.approx(focus, rel=64 * EPS * kappa)
    assert s.f_number == pytest.approx(n, rel=64 * EPS * kappa)


@given(forward_scenes())
@SETTINGS
def test_thin_dof_round_trips_through_the_inverse(scene: tuple[float, float, float, float, str]) -> None:
    # choose the limits, solve, and check the forward model gives them back
    f, _, c, focus, plane = scene
    near = focus * 0.9 if plane == "lens" else max(focus * 0.9, 4 * f)
    far = focus * 1.2
    assume(near > (2 if plane == "lens" else 4) * f)
    s = focus_for_limits(f, c, near, far, distance_from=plane)
    r = thin_dof(f, s.f_number, c, s.distance_mm, distance_from=plane)
    assert r.near_mm == pytest.approx(near, rel=1e-9)
    assert r.far_mm == pytest.approx(far, rel=1e-9)


@pytest.mark.parametrize("plane", ["lens", "sensor"])
@pytest.mark.parametrize(
    ("f", "c", "near", "far"),
    [
        (50.0, 0.03, 2000.0, 4000.0),
        (24.0, 0.03, 1000.0, INF),
        (200.0, 0.02, 9000.0, 11_000.0),
        (100.0, 0.03, 450.0, 460.0),  # macro: a centimetre of depth
        (14.0, 0.02, 700.0, 1e9),
    ],
)
def test_round_trip_everyday(plane: str, f: float, c: float, near: float, far: float) -> None:
    s = focus_for_limits(f, c, near, far, distance_from=plane)
    assert near < s.distance_mm < far
    r = thin_dof(f, s.f_number, c, s.distance_mm, distance_from=plane)
    assert r.near_mm == pytest.approx(near, rel=1e-10)
    if math.isinf(far):
        assert r.far_mm > 1e12 or r.far_mm == INF
    else:
        assert r.far_mm == pytest.approx(far, rel=1e-10)


def test_sensor_plane_differs_from_lens_plane_by_the_image_distance() -> None:
    # the same objects seen from the sensor are v farther away; the f-number is the same
    f, c, n = 100.0, 0.03, 11.0
    lens = thin_dof(f, n, c, 1000.0, distance_from="lens")
    v = 1000.0 * f / (1000.0 - f)
    from_lens = focus_for_limits(f, c, lens.near_mm, lens.far_mm, distance_from="lens")
    from_sensor = focus_for_limits(f, c, lens.near_mm + v, lens.far_mm + v, distance_from="sensor")
    assert from_sensor.f_number == pytest.approx(from_lens.f_number, rel=1e-11)
    assert from_sensor.distance_mm == pytest.approx(from_lens.distance_mm + v, rel=1e-12)
