"""Focus-stacking plans (camtool.dof.stack): identities, an mpmath derivation and published stacking figures."""

from __future__ import annotations

import itertools
import math

import mpmath
import pytest

from camtool.dof.closed import approx_dof, thin_dof
from camtool.dof.closeup import closeup_dof, wave_depth_mm
from camtool.dof.ladder import depth_of_field
from camtool.dof.stack import bracket_plan, frame_depth_mm, rail_plan, wave_coc_mm

INF = math.inf

# ---- bracketing: the thin-lens formulas, derived in mpmath -----------------------------------------------


def _mp_limits(f, n, c, u):
    """Exact thin-lens limits from the blur of a point: a subject at u' images at v' = f·u'/(u' − f); with
    the sensor at v (focus u) its blur is D·|v' − v|/v', D = f/N. The limits are where that equals c."""
    f, n, c, u = (mpmath.mpf(x) for x in (f, n, c, u))
    d = f / n
    v = f * u / (u - f)

    def blur(x):
        vx = f * x / (x - f)
        return d * abs(vx - v) / vx

    near = mpmath.findroot(lambda x: blur(x) - c, (f * 1.0001, u), solver="anderson")
    k = f * f / (n * c)
    far = mpmath.inf if u - f >= k else mpmath.findroot(lambda x: blur(x) - c, (u, mpmath.mpf(10) ** 12),
                                                        solver="anderson")
    return near, far


@pytest.mark.parametrize(("f", "n", "c", "u"), [(24.0, 11.0, 0.03, 700.0), (50.0, 8.0, 0.0288, 1500.0),
                                                 (100.0, 4.0, 0.02, 350.0), (200.0, 16.0, 0.03, 20_000.0)])
def test_stated_thin_formulas_against_mpmath(f, n, c, u):
    # near = u·K/(K + (u − f)), far = u·K/(K − (u − f)), K = f²/(N·c), as docs/stack.md states them
    mpmath.mp.dps = 40
    near, far = _mp_limits(f, n, c, u)
    plan = bracket_plan(f, n, c, float(near), INF)
    first = plan.frames[0]
    assert first.distance_mm == pytest.approx(u, rel=1e-12)  # the inverse u = near·(K − f)/(K − near)
    assert first.near_mm == pytest.approx(float(near), rel=1e-13)
    if far != mpmath.inf:
        assert first.far_mm == pytest.approx(float(far), rel=1e-12)
    # and the ladder's exact thin rung agrees
    thin = thin_dof(f, n, c, u, "lens")
    assert first.far_mm == pytest.approx(float(thin.far_mm), rel=1e-12)


def test_hyperfocal_from_the_lens_is_k_plus_f():
    plan = bracket_plan(24.0, 11.0, 0.03, 500.0, INF)
    assert plan.hyperfocal_mm == pytest.approx(24.0 ** 2 / (11 * 0.03) + 24.0, rel=1e-15)
    assert plan.frames[-1].distance_mm == pytest.approx(plan.hyperfocal_mm, rel=1e-15)
    assert plan.frames[-1].far_mm == INF


@pytest.mark.parametrize(("f", "n", "c", "near"), [(24.0, 11.0, 0.03, 300.0), (50.0, 8.0, 0.03, 400.0),
                                                    (100.0, 2.8, 0.02, 1000.0)])
def test_thin_zero_overlap_image_distances_are_geometric(f, n, c, near):
    # with overlap 0 consecutive image distances are in the ratio (1 − a)/(1 + a), a = N·c/f: 1/u is evenly
    # spaced to first order in a (the thin lens is exact where the H₀ rule is not)
    plan = bracket_plan(f, n, c, near, INF)
    a = n * c / f
    u = [fr.distance_mm for fr in plan.frames[:-1]]  # the last frame is the one clamped at H
    v = [f * x / (x - f) for x in u]
    assert len(v) >= 3
    for v0, v1 in itertools.pairwise(v):
        assert v1 / v0 == pytest.approx((1 - a) / (1 + a), rel=1e-12)
    steps = [1 / x0 - 1 / x1 for x0, x1 in itertools.pairwise(u)]
    assert max(steps) / min(steps) - 1 < 4 * a * len(steps)


@pytest.mark.parametrize(("f", "n", "c", "near"), [(24.0, 11.0, 0.03, 300.0), (100.0, 2.8, 0.02, 1000.0)])
def test_approx_zero_overlap_frames_are_evenly_spaced_in_vergence(f, n, c, near):
    h0 = f * f / (n * c)
    plan = bracket_plan(f, n, c, near, INF, model="approx")
    u = [fr.distance_mm for fr in plan.frames[:-1]]
    for x0, x1 in itertools.pairwise(u):
        assert 1 / x0 - 1 / x1 == pytest.approx(2 / h0, rel=1e-9)
    # and its limits are the ladder's approx rung
    for fr in plan.frames[:-1]:
        r = approx_dof(f, n, c, fr.distance_mm)
        assert fr.near_mm == pytest.approx(float(r.near_mm), rel=1e-12)


@pytest.mark.parametrize("overlap", [0.0, 0.25, 0.5])
@pytest.mark.parametrize("plane", ["lens", "sensor"])
def test_consecutive_limits_meet_or_overlap_by_the_fraction(overlap, plane):
    plan = bracket_plan(50.0, 8.0, 0.03, 1000.0, 20_000.0, overlap, distance_from=plane)
    for a, b in itertools.pairwise(plan.frames):
        shared = a.far_mm - b.near_mm
        if b.far_mm == INF:  # a frame that would focus beyond H is focused at H: it overlaps more, never less
            assert shared >= overlap * (a.far_mm - a.near_mm)
            continue
        assert shared == pytest.approx(overlap * (a.far_mm - a.near_mm), rel=1e-9, abs=1e-9)
    assert plan.frames[0].near_mm == pytest.approx(1000.0, rel=1e-12)
    assert plan.frames[-1].far_mm >= 20_000.0 > plan.frames[-2].far_mm


def test_sensor_plane_limits_are_lens_plane_limits_plus_image_distance():
    # the sensor stays put and the lens moves: each frame's limits shift by its own v + δ
    f, delta = 50.0, 3.0
    plan = bracket_plan(f, 8.0, 0.03, 1000.0, INF, distance_from="sensor", hiatus_mm=delta)
    for fr in plan.frames[:-1]:
        u = f + f / fr.magnification
        shift = f * u / (u - f) + delta
        assert fr.distance_mm == pytest.approx(u + shift, rel=1e-12)
        r = thin_dof(f, 8.0, 0.03, u, "lens")
        assert fr.near_mm == pytest.approx(float(r.near_mm) + shift, rel=1e-12)


def test_last_frame_reaches_infinity_when_asked():
    for near in (300.0, 800.0, 1700.0, 5000.0):
        plan = bracket_plan(24.0, 11.0, 0.03, near, INF)
        assert plan.frames[-1].far_mm == INF
        assert all(fr.far_mm < INF for fr in plan.frames[:-1])


def test_numeric_path_matches_the_closed_form():
    # the bisection used for the other rungs, fed the thin rung of the ladder, reproduces the closed form
    def limits(u):
        r = depth_of_field("thin", 50.0, 8.0, 0.03, u, "lens").limits
        return float(r.near_mm), float(r.far_mm)

    closed = bracket_plan(50.0, 8.0, 0.03, 1000.0, INF, 0.2)
    numeric = bracket_plan(50.0, 8.0, 0.03, 1000.0, INF, 0.2, limits=limits, hyperfocal_mm=closed.hyperfocal_mm)
    assert len(numeric.frames) == len(closed.frames)
    for a, b in zip(closed.frames, numeric.frames):
        assert b.distance_mm == pytest.approx(a.distance_mm, rel=1e-9)


def test_too_many_frames_is_an_error_on_near():
    from camtool.core.errors import DomainError

    with pytest.raises(DomainError) as caught:
        bracket_plan(100.0, 2.0, 0.001, 110.0, INF, max_frames=100)
    assert caught.value.param == "near_mm" and "100 frames" in str(caught.value.valid)


# Hyperfocal bracketing, G. George, "Hyperfocal Informed Bracketing strategy", photography.grayheron.net
# (2020-06) and "A Rule of Thumb approach for perfect landscape focus bracketing" (2023-01): in the
# H = f²/(N·c) model, focus brackets from a near point x to infinity number H/(2x), rounded up, and the
# focus positions are the odd fractions H/(2k − 1) ("the odds rule"): H/1, H/3, H/5, ...
@pytest.mark.parametrize("j", [1, 2, 3, 5, 8])
def test_grayheron_odds_rule_and_bracket_count(j):
    f, n, c = 24.0, 11.0, 0.03
    h0 = f * f / (n * c)
    plan = bracket_plan(f, n, c, h0 / (2 * j), INF, model="approx")
    assert len(plan.frames) == j == math.ceil(h0 / (2 * (h0 / (2 * j))) - 1e-9)
    focus = sorted(fr.distance_mm for fr in plan.frames)
    assert focus == pytest.approx([h0 / (2 * k - 1) for k in range(j, 0, -1)], rel=1e-12)


def test_grayheron_telephoto_example_over_160_brackets():
    # G. George, "In-camera focus bracketing demystified" part 3 (photography.grayheron.net, 2024-06):
    # 150 mm at f/8, CoC 19 µm, near point 0.45 m: "the number of required brackets is over 160",
    # estimated as (H/x + 3)/2 (which counts an extra infinity shot).
    f, n, c, x = 150.0, 8.0, 0.019, 450.0
    plan = bracket_plan(f, n, c, x, INF, model="approx")
    estimate = (f * f / (n * c) / x + 3) / 2
    assert len(plan.frames) > 160
    assert abs(len(plan.frames) - estimate) <= 2


# ---- rail mode ---------------------------------------------------------------------------------------------

@pytest.mark.parametrize("overlap", [0.0, 0.2, 0.5])
@pytest.mark.parametrize(("depth", "n", "m"), [(10.0, 8.0, 1.0), (3.0, 5.6, 2.0), (0.5, 4.0, 5.0), (1.0, 16.0, 0.5)])
def test_rail_frames_times_step_covers_the_depth(overlap, depth, n, m):
    for criterion in ("wave", "classic"):
        p = rail_plan(depth, n, m, criterion, 0.03, overlap)
        assert p.frames * p.step_mm >= depth * (1 - 1e-12)
        assert (p.frames - 1) * p.step_mm < depth  # one frame fewer would not
        assert p.step_mm == pytest.approx((p.front_mm + p.rear_mm) * (1 - overlap), rel=1e-15)
        assert p.extension_step_mm == pytest.approx(m * m * p.step_mm, rel=1e-15)
        assert p.covered_mm >= depth


def test_rail_issue_question_10mm_at_1_to_1_f8():
    # "how many frames for a 10 mm deep subject at 1:1 and f/8?": wave depth 4λN_w²/m² = 0.5632 mm,
    # ⌈10/0.5632⌉ = 18 frames at overlap 0
    p = rail_plan(10.0, 8.0, 1.0, "wave", overlap=0.0)
    assert p.step_mm == pytest.approx(4 * 550e-6 * 16 ** 2, rel=1e-12)
    assert p.frames == 18


# Zerene Stacker, "DOF Estimates For Macro/Micro" (zerenesystems.com/cms/stacker/docs/tables/macromicrodof),
# the step-size table (two significant figures, nominal f/2 ... f/22), whose criterion is the wave-optics
# depth λ/NA² at 550 nm (tests/test_closeup.py reproduces it): the rail step at overlap 0 under --criterion wave.
ZERENE_STEP = {
    2.0: [0.020, 0.039, 0.079, 0.16, 0.32, 0.60, 1.3, 2.4],
    5.0: [0.013, 0.025, 0.051, 0.099],
    20.0: [0.0097, 0.019, 0.039, 0.076, 0.16, 0.29, 0.62, 1.2],
}
NOMINAL = [2.0, 2.8, 4.0, 5.6, 8.0, 11.0, 16.0, 22.0]


@pytest.mark.parametrize("m", sorted(ZERENE_STEP))
def test_rail_step_reproduces_zerene_table(m):
    for n, published in zip(NOMINAL, ZERENE_STEP[m]):
        step = rail_plan(1.0, n, m, "wave", overlap=0.0).step_mm
        assert float(f"{step:.2g}") == published, (m, n)


def test_rail_zerene_worked_example_classic_and_wave():
    # Zerene Stacker, "DOF Calculator" (zerenesystems.com/cms/stacker/docs/dofcalculator): m = 1, f/16,
    # wave-optics DOF 2.253 mm; with CoC 0.030 mm the classic DOF 1.92 mm: the steps at overlap 0
    assert round(rail_plan(10.0, 16.0, 1.0, "wave", overlap=0.0).step_mm, 3) == 2.253
    assert round(rail_plan(10.0, 16.0, 1.0, "classic", 0.03, overlap=0.0).step_mm, 2) == 1.92


def test_classic_frame_depth_with_focal_length_is_the_exact_closeup_depth():
    front, rear = frame_depth_mm(8.0, 0.5, "classic", 0.03, 1.0, 550.0, 100.0)
    r = closeup_dof(100.0, 8.0, 0.03, 0.5, 1.0, "lens")
    assert (front, rear) == (pytest.approx(r.front_mm, rel=1e-15), pytest.approx(r.rear_mm, rel=1e-15))
    assert rear > front  # the exact depth is not symmetric


@pytest.mark.parametrize(("n", "m", "p"), [(8.0, 1.0, 1.0), (2.8, 5.0, 0.5), (16.0, 0.2, 1.3)])
def test_wave_coc_gives_the_wave_depth_by_the_classic_rule(n, m, p):
    c = wave_coc_mm(n, m, p)
    classic = 2 * n * c * (1 + m / p) / m ** 2
    assert classic == pytest.approx(wave_depth_mm(n, m, p), rel=1e-14)


def test_bad_overlap_and_criterion():
    from camtool.core.errors import DomainError

    with pytest.raises(DomainError):
        rail_plan(1.0, 8.0, 1.0, overlap=1.0)
    with pytest.raises(DomainError):
        rail_plan(1.0, 8.0, 1.0, criterion="sharpish")
    with pytest.raises(DomainError):
        bracket_plan(50.0, 8.0, 0.03, 40.0, INF)


def test_a_lens_past_life_size_is_bracketed_to_its_nearest_near_limit():
    # A unit-focusing 100 mm lens reaching 2x: the subject-to-sensor distance f(1 + m)^2/m is least at
    # m = 1 and grows again beyond, so the nearest near limit lies just below 1:1. Its place is found
    # here independently by a dense scan of the thin-lens near limit from the sensor,
    # u·K/(K + u − f) + f(1 + m) with u = f(1 + 1/m), K = f²/(N·c).
    from camtool.core.errors import DomainError
    from camtool.dof.stack import internal_bracket_plan
    from camtool.geometry.closeup import InternalFocus

    f, n, c = 100.0, 8.0, 0.03
    k = f * f / (n * c)

    def near(m: float) -> float:
        u = f * (1 + 1 / m)
        return u * k / (k + u - f) + f * (1 + m)

    scan = min((near(0.5 + i * 1e-6), 0.5 + i * 1e-6) for i in range(1_000_000))
    assert 0.9 < scan[1] < 1.0
    lens = InternalFocus(f, 0.0, 0.0, 2.0, 0.0, 400.0)
    with pytest.raises(DomainError) as caught:
        internal_bracket_plan(lens, n, c, scan[0] - 0.01, 500.0)
    assert caught.value.limit == pytest.approx(scan[0], rel=1e-9)
    assert f"at {scan[1]:.3g}×: a closer setting moves the subject away again" in caught.value.valid
    # just beyond it, frame 1 is on the near side of the turn (m below the scan's), its near limit the one asked
    first = internal_bracket_plan(lens, n, c, scan[0] + 1e-3, 500.0).frames[0]
    assert first.near_mm == pytest.approx(scan[0] + 1e-3, rel=1e-12) and first.magnification < scan[1]
    assert first.near_mm == pytest.approx(near(first.magnification), rel=1e-12)
