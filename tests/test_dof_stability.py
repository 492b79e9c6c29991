"""Numerical stability of ``approx`` and ``thin`` over the whole domain (docs/design.md §6).

The domain is what a phone, a microscope, a pinhole or a telescope reaches: f 1–5000 mm,
N 0.7–1024, c 0.0005–1 mm, focus from just beyond the closest focus to 1e15 mm and inf, from
either plane. Hypothesis draws scenes from all of it (log-uniform, since it spans decades, with
extra weight on the two hard spots: the closest focus and the hyperfocal distance); a named
table pins the edges.

Accuracy is judged against the same formula evaluated with mpmath at 50 digits. A float64
result cannot be better than the problem allows: rounding the inputs alone moves the answer by
κ·ε, where κ = Σᵢ |∂ ln y/∂ ln xᵢ| is the relative condition number of the output y with respect
to the inputs xᵢ (f, N, c, focus). The far limit u·H₀/(H − u) (H₀ = f²/(Nc), H = H₀ + f) has

    κ_far = H/(H − u) + 2·|1 − H₀/(H − u)| + |2 − (2H₀ + f)/(H − u)|    (from u; N and c; f)

about 5H/(H − u) close to H: it grows without bound as the focus approaches the hyperfocal
distance, because the far limit itself does. The near limit's κ stays below about 3. From the sensor, u comes from D = u + fu/(u − f), which is flat at 1:1, so near the
closest focus κ grows like 1/√(D − 4f) for both limits. κ is estimated by central differences
of the 50-digit formula; a backward-stable float64 evaluation keeps the relative error within
a small multiple of κ·ε, and the tests allow 64·κ·ε.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from typing import Any

import mpmath
import pytest
from hypothesis import assume, given, settings
from hypothesis import strategies as st

from camtool.dof.closed import approx_dof, hyperfocal_mm, thin_dof
from camtool.dof.limits import DofLimits

EPS = 2.0**-52
INF = math.inf
TOLERANCE_FACTOR = 64
MODELS = ("approx", "thin-lens", "thin-sensor")  # approx takes the distance as typed, in any plane
SETTINGS = settings(max_examples=250, deadline=None)


# -- the formulas under test, and the same formulas at 50 digits ------------------------------------


def evaluate(model: str, f: float, n: float, c: float, focus: float) -> DofLimits:
    if model == "approx":
        return approx_dof(f, n, c, focus)
    return thin_dof(f, n, c, focus, distance_from=model.removeprefix("thin-"))


def closest_focus(model: str, f: float) -> float:
    return 4 * f if model == "thin-sensor" else 2 * f


def mp_limits(model: str, f: Any, n: Any, c: Any, focus: Any) -> tuple[Any, Any] | None:
    """(near, far) by the textbook formulas in mpmath; far is mpmath.inf beyond H; None outside the domain."""
    f, n, c = mpmath.mpf(f), mpmath.mpf(n), mpmath.mpf(c)
    h0 = f * f / (n * c)
    if model == "approx":
        s = mpmath.mpf(focus)
        if mpmath.isinf(s):
            return h0, mpmath.inf
        return h0 * s / (h0 + s), (h0 * s / (h0 - s) if s < h0 else mpmath.inf)
    if model == "thin-sensor":
        d = mpmath.mpf(focus)
        if d < 4 * f:
            return None
        if mpmath.isinf(d):
            u, v = mpmath.inf, f
        else:
            root = mpmath.sqrt(1 - 4 * f / d)
            u, v = d / 2 * (1 + root), 2 * f / (1 + root)
    else:
        u, v = mpmath.mpf(focus), mpmath.mpf(0)
        if u < 2 * f:
            return None
    if mpmath.isinf(u):
        return h0 + v, mpmath.inf
    # D_N = u f²/(f² + Nc(u − f)), D_F = u f²/(f² − Nc(u − f)) (the thin-lens lecture)
    near = u * f * f / (f * f + n * c * (u - f))
    below = f * f - n * c * (u - f)
    return near + v, (u * f * f / below + v if below > 0 else mpmath.inf)


def condition(model: str, inputs: tuple[float, float, float, float], which: int) -> float:
    """κ = Σᵢ |∂ ln y/∂ ln xᵢ| of near (which=0) or far (which=1), by central differences at 50 digits.

    An infinite input is not perturbed. A one-sided difference is used where the other side
    leaves the domain (focus at the closest focus); inf where a perturbation crosses the
    hyperfocal distance (the far limit is not even finite nearby).
    """
    with mpmath.workdps(50):
        base = mp_limits(model, *inputs)
        assert base is not None
        y = base[which]
        if mpmath.isinf(y):
            return INF
        delta = mpmath.mpf("1e-20")
        total = mpmath.mpf(0)
        for i, x in enumerate(inputs):
            if math.isinf(x):
                continue
            slopes = []
            for sign in (1, -1):
                moved = list(map(mpmath.mpf, inputs))
                moved[i] = mpmath.mpf(x) * (1 + sign * delta)
                other = mp_limits(model, *moved)
                if other is None:
                    continue
                if mpmath.isinf(other[which]):
                    return INF
                slopes.append(abs(other[which] / y - 1) / delta)
            total += max(slopes)
        return float(total)


def assert_close_to_mpmath(model: str, f: float, n: float, c: float, focus: float) -> None:
    got = evaluate(model, f, n, c, focus)
    with mpmath.workdps(50):
        reference = mp_limits(model, f, n, c, focus)
        assert reference is not None
        for which, (value, exact) in enumerate(zip((got.near_mm, got.far_mm), reference)):
            if mpmath.isinf(exact) and math.isinf(value):
                continue
            if mpmath.isinf(exact) or value >= 1e300:
                # the far limit's finiteness may only differ from the exact one when the focus
                # lies within rounding of the hyperfocal distance
                assert which == 1
                assert abs(_gap_to_hyperfocal(model, f, n, c, focus)) <= TOLERANCE_FACTOR * EPS * (
                    1 + _kappa_fold(model, f, focus)
                ), (value, exact)
                continue
            kappa = max(condition(model, (f, n, c, focus), which), 1.0)
            error = float(abs(mpmath.mpf(value) / exact - 1))
            assert error <= TOLERANCE_FACTOR * kappa * EPS, (("near", "far")[which], value, float(exact), kappa)


def _gap_to_hyperfocal(model: str, f: float, n: float, c: float, focus: float) -> float:
    """(u − H)/H at 50 digits (s − H₀)/H₀ for approx)."""
    with mpmath.workdps(50):
        mf, mn, mc = mpmath.mpf(f), mpmath.mpf(n), mpmath.mpf(c)
        h0 = mf * mf / (mn * mc)
        if model == "approx":
            return float((focus - h0) / h0)
        u = mpmath.mpf(focus)
        if model == "thin-sensor":
            u = u / 2 * (1 + mpmath.sqrt(1 - 4 * mf / u))
        return float((u - h0 - mf) / (h0 + mf))


def _kappa_fold(model: str, f: float, focus: float) -> float:
    """Condition of u with respect to the sensor-plane distance D: D/(u·|dD/du|), 1 elsewhere."""
    if model != "thin-sensor" or math.isinf(focus):
        return 1.0
    root = math.sqrt(max(1 - 4 * f / focus, 0.0))
    u = focus / 2 * (1 + root)
    slope = abs(1 - (f / (u - f)) ** 2)
    return INF if slope == 0 else focus / (u * slope)


# -- properties every result must have ------------------------------------------------------------


def plane_hyperfocal(model: str, f: float, n: float, c: float) -> float:
    """The hyperfocal distance the model reports, in the plane of its focus distance."""
    return evaluate(model, f, n, c, INF).hyperfocal_mm


def assert_sound(model: str, f: float, n: float, c: float, focus: float) -> DofLimits:
    r = evaluate(model, f, n, c, focus)
    for name, value in r._asdict().items():
        assert type(value) is float, name
        assert not math.isnan(value), name
        assert value >= 0, name
        assert value != -INF, name
    assert math.isfinite(r.near_mm)
    assert 0 < r.hyperfocal_mm < INF
    assert r.near_mm <= focus <= r.far_mm
    assert r.far_mm < INF or r.rear_mm == INF
    # far = ∞ exactly when the focus is at or beyond the reported hyperfocal distance
    assert (r.far_mm == INF) == (focus >= r.hyperfocal_mm)
    assert r.hyperfocal_mm == plane_hyperfocal(model, f, n, c)
    return r


# -- strategies ---------------------------------------------------------------------------------------


def log_uniform(lo: float, hi: float) -> st.SearchStrategy[float]:
    return st.floats(math.log(lo), math.log(hi)).map(lambda x: min(max(math.exp(x), lo), hi))


def with_ends(lo: float, hi: float) -> st.SearchStrategy[float]:
    return st.one_of(log_uniform(lo, hi), st.sampled_from([lo, hi]), st.floats(lo, hi))


FOCAL = with_ends(1.0, 5000.0)
F_NUMBER = with_ends(0.7, 1024.0)
COC = with_ends(0.0005, 1.0)


@st.composite
def scenes(draw: st.DrawFn, models: tuple[str, ...] = MODELS) -> tuple[str, float, float, float, float]:
    """(model, f, N, c, focus) anywhere in the domain."""
    model, f, n, c = draw(st.sampled_from(models)), draw(FOCAL), draw(F_NUMBER), draw(COC)
    closest = closest_focus(model, f)
    kind = draw(st.sampled_from(["anywhere", "anywhere", "closest", "hyperfocal", "inf"]))
    if kind == "anywhere":
        focus = min(closest * (1 + draw(log_uniform(1e-3, 1e15 / closest))), 1e15)
    elif kind == "closest":
        focus = closest * (1 + draw(st.one_of(st.just(0.0), log_uniform(1e-16, 1e-3))))
    elif kind == "hyperfocal":
        offset = draw(st.one_of(st.just(0.0), log_uniform(1e-16, 1e-2)))
        focus = plane_hyperfocal(model, f, n, c) * (1 + draw(st.sampled_from([-1, 1])) * offset)
        assume(closest <= focus <= 1e15)
    else:
        focus = INF
    return model, f, n, c, focus


# -- hypothesis properties ----------------------------------------------------------------------------


@given(scenes())
@SETTINGS
def test_limits_are_sound_everywhere(scene: tuple[str, float, float, float, float]) -> None:
    assert_sound(*scene)


@given(scenes())
@SETTINGS
def test_float64_against_50_digit_mpmath(scene: tuple[str, float, float, float, float]) -> None:
    assert_close_to_mpmath(*scene)


@given(scenes(), log_uniform(1.001, 100.0), st.sampled_from(["f_number", "coc"]))
@SETTINGS
def test_monotone_in_f_number_and_coc(scene: tuple[str, float, float, float, float], factor: float, which: str) -> None:
    # stopping down or accepting more blur never shrinks the zone: near not larger, far not smaller
    model, f, n, c, focus = scene
    n2, c2 = (n * factor, c) if which == "f_number" else (n, c * factor)
    assume(n2 <= 1024 and c2 <= 1)
    before, after = evaluate(model, f, n, c, focus), evaluate(model, f, n2, c2, focus)
    assert after.near_mm <= before.near_mm
    assert after.far_mm >= before.far_mm
    assert after.hyperfocal_mm <= before.hyperfocal_mm or model == "thin-sensor"


@given(scenes(), st.sampled_from([1e-12, 1e-9, 1e-6]))
@SETTINGS
def test_continuous_across_the_hyperfocal_distance(scene: tuple[str, float, float, float, float], delta: float) -> None:
    model, f, n, c, _ = scene
    hyper = plane_hyperfocal(model, f, n, c)
    below_focus, above_focus = hyper * (1 - delta), hyper * (1 + delta)
    assume(below_focus >= closest_focus(model, f) and above_focus <= 1e15)
    below = assert_sound(model, f, n, c, below_focus)
    above = assert_sound(model, f, n, c, above_focus)
    assert above.far_mm == INF
    # the near limit passes H/2 smoothly; d ln near/d ln u ≤ 1, times the fold of the sensor plane
    fold = _kappa_fold(model, f, hyper)
    assert below.near_mm == pytest.approx(above.near_mm, rel=4 * delta * (1 + fold) + 64 * EPS * fold)
    # the far limit grows without bound: ≈ H₀/δ' with δ' = (H − u)/H ≤ κ_fold·δ
    h0 = hyperfocal_mm(f, n, c, plus_f=False)
    assert below.far_mm >= min(0.1 * h0 / (fold * delta), 1e300)
    closer = evaluate(model, f, n, c, hyper * (1 - 10 * delta))
    assert closer.far_mm <= below.far_mm or closer.far_mm == INF


@given(scenes(), st.sampled_from([1e-14, 1e-11, 1e-8]))
@SETTINGS
def test_continuous_at_the_closest_focus(scene: tuple[str, float, float, float, float], epsilon: float) -> None:
    model, f, n, c, _ = scene
    closest = closest_focus(model, f)
    at, beyond = assert_sound(model, f, n, c, closest), assert_sound(model, f, n, c, closest * (1 + epsilon))
    # from the lens the limits are smooth in u; from the sensor u moves by about √(D − 4f)
    step = 4 * math.sqrt(epsilon) if model == "thin-sensor" else 4 * epsilon
    assert beyond.near_mm == pytest.approx(at.near_mm, rel=step + 64 * EPS)
    assert beyond.magnification == pytest.approx(at.magnification, rel=step + 64 * EPS)
    hyper = plane_hyperfocal(model, f, n, c)
    if hyper > 2 * closest:  # far of the limits' well-conditioned side: κ_far ≤ 1 + 2H/(H − u) ≤ 5
        assert beyond.far_mm == pytest.approx(at.far_mm, rel=5 * step + 64 * EPS)


# -- named extreme cases ------------------------------------------------------------------------------

Focus = Callable[[str, float, float, float], float]


def just_beyond_closest(model: str, f: float, n: float, c: float) -> float:
    return math.nextafter(closest_focus(model, f), INF)


def at_hyperfocal_times(factor: float) -> Focus:
    return lambda model, f, n, c: plane_hyperfocal(model, f, n, c) * factor


def fixed(distance: float) -> Focus:
    return lambda model, f, n, c: distance


EXTREMES = [
    ("closest-focus", 50.0, 8.0, 0.03, just_beyond_closest),
    ("closest-focus-exactly", 50.0, 8.0, 0.03, lambda model, f, n, c: closest_focus(model, f)),
    ("closest-focus-tele", 5000.0, 0.7, 0.0005, just_beyond_closest),
    ("hyperfocal-minus-1e-12", 50.0, 8.0, 0.03, at_hyperfocal_times(1 - 1e-12)),
    ("hyperfocal-plus-1e-12", 50.0, 8.0, 0.03, at_hyperfocal_times(1 + 1e-12)),
    ("hyperfocal-exactly", 50.0, 8.0, 0.03, at_hyperfocal_times(1.0)),
    ("hyperfocal-minus-1e-12-wide", 14.0, 2.8, 0.03, at_hyperfocal_times(1 - 1e-12)),
    ("f1-at-1e15", 1.0, 2.0, 0.002, fixed(1e15)),
    ("f1-at-inf", 1.0, 2.0, 0.002, fixed(INF)),
    ("f1-N0.7-c5e-4-at-1e15", 1.0, 0.7, 0.0005, fixed(1e15)),
    ("N1024", 50.0, 1024.0, 0.03, fixed(3000.0)),
    ("N1024-c1-pinhole", 1.0, 1024.0, 1.0, fixed(4.5)),
    ("N1024-c1-f5000", 5000.0, 1024.0, 1.0, fixed(1e6)),
    ("c5e-4", 50.0, 8.0, 0.0005, fixed(3000.0)),
    ("c5e-4-N0.7", 50.0, 0.7, 0.0005, fixed(1e6)),
    ("f5000", 5000.0, 8.0, 0.03, fixed(1e6)),
    ("f5000-at-1e15", 5000.0, 8.0, 0.03, fixed(1e15)),
    ("f5000-N0.7-c5e-4-near-H", 5000.0, 0.7, 0.0005, at_hyperfocal_times(1 - 1e-9)),
]


@pytest.mark.parametrize("model", MODELS)
@pytest.mark.parametrize(
    ("f", "n", "c", "focus"), [pytest.param(*row[1:], id=row[0]) for row in EXTREMES]
)
def test_extreme_cases(model: str, f: float, n: float, c: float, focus: Focus) -> None:
    distance = focus(model, f, n, c)
    assert_sound(model, f, n, c, distance)
    assert_close_to_mpmath(model, f, n, c, distance)


def test_the_far_limit_is_ill_conditioned_only_near_the_hyperfocal_distance() -> None:
    # the numerical κ used above against the analytic one of the module docstring
    f = 50.0
    h0 = hyperfocal_mm(f, 8.0, 0.03, plus_f=False)
    h = h0 + f
    for fraction in (0.01, 0.5, 0.9, 0.999, 1 - 1e-9):
        u = h * fraction
        analytic = h / (h - u) + 2 * abs(1 - h0 / (h - u)) + abs(2 - (2 * h0 + f) / (h - u))
        assert condition("thin-lens", (f, 8.0, 0.03, u), 1) == pytest.approx(analytic, rel=1e-6)
        assert condition("thin-lens", (f, 8.0, 0.03, u), 0) < 3
