"""The wave rung and the defocused MTF of a perfect circular pupil, against independent values.

- the diffraction-limited MTF against mpmath's quadrature of the overlap area of two unit discs;
- the defocused OTF against mpmath's quadrature of the pupil autocorrelation in its x form (not the θ form
  the code integrates), and Bessel J₁ against mpmath.besselj;
- the quarter-wave depth λ/NA² against the contrast loss Zerene Stacker's author gives for it: "a maximum
  contrast loss of about 26% at the worst level of fine detail, compared to a perfectly focused image"
  (R. Littlefield, photomacrography.net forum, thread "Step Size", on DOF = 0.00055/NA²);
- large defocus (wide apertures) against the geometric thin-lens limits;
- the depth-of-field properties of docs/design.md §6.2.
"""

from __future__ import annotations

import math

import mpmath
import numpy as np
import pytest
from cli_helpers import run

from camtool.dof.closed import thin_dof
from camtool.dof.ladder import depth_of_field
from camtool.dof.wave import (
    DEFAULT_CRITERION,
    ContrastUnreachable,
    Criterion,
    contrast_at,
    largest_contrast_f_number,
    wave_dof,
)
from camtool.optics.transfer import (
    DISC_CONTRAST,
    defocus_at_level,
    defocus_mtf,
    diffraction_mtf,
    frequency_at_level,
    jinc,
)

mpmath.mp.dps = 30


def _autocorrelation(s: float, w: float) -> float:
    """(1/π)∫∫ over the overlap of two unit discs shifted by ±s of cos(2π·4·W·s·x), integrated over y first."""
    s_, w_ = mpmath.mpf(s), mpmath.mpf(w)

    def inner(x):
        return mpmath.cos(8 * mpmath.pi * w_ * s_ * x) * 2 * mpmath.sqrt(1 - (abs(x) + s_) ** 2)

    return float(mpmath.quad(inner, [-(1 - s_), 0, 1 - s_]) / mpmath.pi)


@pytest.mark.parametrize("s", [0.0, 0.05, 0.25, 0.5, 0.8, 0.99])
def test_diffraction_limited_mtf_is_the_overlap_area(s: float) -> None:
    assert diffraction_mtf(s) == pytest.approx(_autocorrelation(s, 0.0), abs=1e-13)
    assert defocus_mtf(s, 0.0) == pytest.approx(diffraction_mtf(s), abs=1e-13)


def test_diffraction_limited_mtf_published_value() -> None:
    # Goodman, Introduction to Fourier Optics, fig. 6.8 / eq. 6-31: 0.391 at half the cut-off
    assert diffraction_mtf(0.5) == pytest.approx(0.391, abs=5e-4)
    assert diffraction_mtf(1.0) == 0.0 and diffraction_mtf(0.0) == 1.0


@pytest.mark.parametrize("s, w", [(0.5, 0.25), (0.1, 3.0), (0.02, 20.0), (0.9, 0.5), (0.3, 1.7), (0.147, 0.85),
                                  (0.7, 0.1)])
def test_defocused_otf_against_mpmath(s: float, w: float) -> None:
    assert defocus_mtf(s, w) == pytest.approx(_autocorrelation(s, w), abs=1e-12)
    assert defocus_mtf(s, -w) == pytest.approx(defocus_mtf(s, w), abs=1e-15)  # even in defocus


@pytest.mark.parametrize("x", [0.0, 0.5, 2.0, math.pi, 3.8317, 7.0, 11.5])
def test_jinc_against_mpmath(x: float) -> None:
    expected = 1.0 if x == 0 else float(2 * mpmath.besselj(1, x) / x)
    assert jinc(x) == pytest.approx(expected, abs=1e-12)
    assert pytest.approx(float(2 * mpmath.besselj(1, mpmath.pi) / mpmath.pi), abs=1e-15) == DISC_CONTRAST


def test_quarter_wave_depth_loses_about_a_quarter_of_the_contrast_at_mid_frequency() -> None:
    # λ/NA² is ±λ/(2NA²) about focus: W₂₀ = Δz·NA²/2 = λ/4 at either end. At half the cut-off the MTF falls
    # from 0.391 to 0.2875: 26.5 % lost. Littlefield's "maximum contrast loss of about 26% at the worst level of
    # fine detail": the largest loss over every frequency is that one, at half the cut-off.
    loss = 1.0 - defocus_mtf(0.5, 0.25) / diffraction_mtf(0.5)
    assert loss == pytest.approx(1.0 - _autocorrelation(0.5, 0.25) / _autocorrelation(0.5, 0.0), abs=1e-12)
    assert 0.255 <= loss <= 0.275
    frequencies = [i / 200 for i in range(1, 200)]
    losses = [1.0 - defocus_mtf(s, 0.25) / diffraction_mtf(s) for s in frequencies]
    worst = max(range(len(losses)), key=losses.__getitem__)
    assert round(losses[worst], 2) == 0.26 and abs(frequencies[worst] - 0.5) <= 0.02


def test_the_quarter_wave_depth_is_the_wave_rungs_depth_at_that_contrast() -> None:
    # A 50 mm lens at f/16 focused at 1:1 (u = 100 mm from the lens): the image-side quarter-wave depth is
    # λ/NA'² = 4λN_w²; the object-side limits whose MTF at half the cut-off is 0.2875 bound that defocus.
    f, n, u, lam = 50.0, 16.0, 100.0, 550e-6
    v = f * u / (u - f)
    n_w = n * v / f
    nu = 0.5 / (lam * n_w)
    level = defocus_mtf(0.5, 0.25)
    r = wave_dof(f, n, 0.03, u, "lens", Criterion(level, nu))
    v_near = f * r.near_mm / (r.near_mm - f)
    v_far = f * r.far_mm / (r.far_mm - f)
    assert v_near - v_far == pytest.approx(4.0 * lam * n_w ** 2 * (1 + 0.0), rel=2e-3)


@pytest.mark.parametrize("s, level", [(0.01, 0.181), (0.2, 0.5), (0.5, 0.2), (0.05, 0.9), (0.6, 0.06)])
def test_defocus_at_level_is_the_first_crossing(s: float, level: float) -> None:
    w = defocus_at_level(s, level)
    assert _autocorrelation(s, w) == pytest.approx(level, abs=1e-10)
    grid = np.linspace(0.0, w, 2001)[:-1]
    assert np.all(defocus_mtf(np.full_like(grid, s), grid) > level)


def test_table_and_direct_solutions_agree() -> None:
    rng = np.random.default_rng(1)
    s = rng.uniform(1e-3, frequency_at_level(0.3) * 0.9999, 5000)
    many = defocus_at_level(s, 0.3)  # the table path (over 4096 scenes)
    few = np.array([defocus_at_level(float(x), 0.3) for x in s[:50]])
    assert np.allclose(many[:50], few, rtol=1e-9)


def test_no_defocus_is_sharp_where_the_in_focus_mtf_is_below_the_level() -> None:
    assert math.isnan(defocus_at_level(0.8, 0.5))
    assert frequency_at_level(0.5) == pytest.approx(0.4040, abs=1e-4)


@pytest.mark.parametrize("n", [0.7, 1.0])
def test_large_defocus_gives_the_geometric_depth_of_field(n: float) -> None:
    # c = 0.2 mm: ν = 5 lp/mm, s = ν·λ·N ≈ 0.003, so the criterion is met tens of waves from focus, where
    # the defocused MTF is the blur disc's 2J₁(πbν)/(πbν), and at the default level b = c: the thin lens.
    for u in (500.0, 3000.0, 20000.0):
        wave = wave_dof(50.0, n, 0.2, u, "lens")
        thin = thin_dof(50.0, n, 0.2, u, "lens")
        assert wave.near_mm == pytest.approx(thin.near_mm, rel=2e-3)
        assert wave.far_mm == pytest.approx(thin.far_mm, rel=4e-3)
        assert wave.hyperfocal_mm == pytest.approx(thin.hyperfocal_mm, rel=4e-3)


def test_the_geometric_limit_is_approached_as_the_aperture_opens() -> None:
    errors = [abs(wave_dof(50.0, n, 0.05, 3000.0, "lens").total_mm / thin_dof(50.0, n, 0.05, 3000.0, "lens").total_mm
                  - 1.0) for n in (8.0, 4.0, 2.0, 1.0)]
    assert errors == sorted(errors, reverse=True) and errors[-1] < 0.01


def test_limits_meet_the_criterion() -> None:
    f, n, c, u = 85.0, 5.6, 0.03, 2500.0
    crit = Criterion(0.3, 25.0)
    r = wave_dof(f, n, c, u, "lens", crit)
    for x in (r.near_mm, r.far_mm):
        assert contrast_at(f, n, u, x, 25.0) == pytest.approx(0.3, abs=1e-9)
    assert contrast_at(f, n, u, u, 25.0) > 0.3


def test_dof_properties_and_planes() -> None:
    f = np.array([24.0, 50.0, 135.0, 50.0])
    n = np.array([2.8, 8.0, 4.0, 11.0])
    s = np.array([1000.0, 5000.0, 30000.0, math.inf])
    lens = wave_dof(f, n, 0.03, s, "lens")
    assert np.all(lens.near_mm <= s) and np.all(lens.far_mm >= s)
    assert np.array_equal(np.isinf(lens.far_mm), s >= lens.hyperfocal_mm)
    for i in range(len(f)):  # scalars agree with the array
        one = wave_dof(float(f[i]), float(n[i]), 0.03, float(s[i]), "lens")
        assert one.near_mm == pytest.approx(lens.near_mm[i], rel=1e-9)
    at_h = wave_dof(50.0, 8.0, 0.03, wave_dof(50.0, 8.0, 0.03, math.inf).hyperfocal_mm)
    assert at_h.far_mm == math.inf
    just_short = wave_dof(50.0, 8.0, 0.03, at_h.hyperfocal_mm * (1 - 1e-6))
    assert math.isfinite(just_short.far_mm) and just_short.far_mm > 1e6
    sensor = wave_dof(50.0, 8.0, 0.03, 3000.0)  # from the sensor: u + v = 3000
    assert sensor.near_mm <= 3000.0 <= sensor.far_mm


def test_nothing_sharp_beyond_the_largest_f_number() -> None:
    largest = largest_contrast_f_number(DEFAULT_CRITERION, 0.03)
    assert largest == pytest.approx(frequency_at_level(DISC_CONTRAST) * 0.03 / 550e-6, rel=1e-12)
    assert wave_dof(50.0, largest * 0.999, 0.03, math.inf).near_mm > 0
    with pytest.raises(ContrastUnreachable) as error:
        wave_dof(50.0, largest * 1.001, 0.03, math.inf)
    assert error.value.param == "f_number" and "nothing is sharp enough" in str(error.value)


def test_auto_runs_wave_for_a_criterion_and_where_diffraction_dominates() -> None:
    assert depth_of_field("auto", 50.0, 8.0, 0.03, 3000.0).model == "thin"
    assert depth_of_field("auto", 50.0, 8.0, 0.03, 3000.0, criterion=Criterion(0.3, 20.0)).model == "wave"
    # Airy 2.44·λ·N: 0.0215 mm at f/16 > 0.03/√2 = 0.0212; 0.0148 mm at f/11 below
    assert depth_of_field("auto", 50.0, 16.0, 0.03, 3000.0, diffraction=True).model == "wave"
    assert depth_of_field("auto", 50.0, 11.0, 0.03, 3000.0, diffraction=True).model == "thin+diffraction"
    mixed = depth_of_field("auto", 50.0, np.array([11.0, 16.0]), 0.03, 3000.0, diffraction=True)
    assert list(mixed.model) == ["thin+diffraction", "wave"]
    single = depth_of_field("auto", 50.0, 16.0, 0.03, 3000.0, diffraction=True)
    assert mixed.limits.near_mm[1] == pytest.approx(single.limits.near_mm, rel=1e-12)


def test_cli_criterion() -> None:
    out = run("dof", "-f", "50", "-N", "8", "-s", "3m", "--criterion", "mtf:0.3@coc", "--format", "json")
    assert out.exit_code == 0 and '"model": "wave"' in out.output
    bad = run("dof", "-f", "50", "-N", "8", "-s", "3m", "--criterion", "mtf:0.3@")
    assert bad.exit_code == 2 and "--criterion" in bad.output
    bad = run("dof", "-f", "50", "-N", "8", "-s", "3m", "--criterion", "mtf:0.3@40", "--model", "thin")
    assert bad.exit_code == 2
    out = run("dof", "-f", "50", "-N", "8", "-s", "3m", "--model", "all", "--format", "json")
    assert '"model": "wave"' in out.output


def test_hyperfocal_by_contrast() -> None:
    from camtool.plans.depth import hyperfocal_plan

    p = hyperfocal_plan(model="auto", focal_length_mm=50.0, f_number=16.0, coc_mm=0.03, diffraction=True,
                        distance_from="lens")
    assert p.model == "wave"
    assert p.hyperfocal_mm == pytest.approx(wave_dof(50.0, 16.0, 0.03, math.inf, "lens").hyperfocal_mm, rel=1e-12)
    assert wave_dof(50.0, 16.0, 0.03, p.hyperfocal_mm, "lens").far_mm == math.inf
    rss = hyperfocal_plan(model="thin", focal_length_mm=50.0, f_number=16.0, coc_mm=0.03, diffraction=True,
                          distance_from="lens")
    assert rss.model == "thin+diffraction"
    # thin + root-sum-square: H = f²/(N·c′) + f with c′ = √(c² − (2.44λN)²)
    usable = math.sqrt(0.03 ** 2 - (2.44 * 550e-6 * 16.0) ** 2)
    assert rss.hyperfocal_mm == pytest.approx(50.0 ** 2 / (16.0 * usable) + 50.0, rel=1e-12)
    out = run("hyperfocal", "-f", "50", "-N", "200", "--diffraction")  # the unattainable H: now an error
    assert out.exit_code == 2 and "below f/37.1" in out.output


def test_contrast_optimum_is_the_best_f_number_and_balances_the_ends() -> None:
    from camtool.dof.wave import contrast_optimum

    r = contrast_optimum(150.0, 2000.0, math.inf, 20.0, "lens")
    assert r.distance_mm == pytest.approx(4000.0, rel=1e-12)  # 1/u = (1/2000 + 0)/2
    for x in (2000.0, 1e30):  # the same contrast at both ends, an mpmath-checked OTF
        assert contrast_at(150.0, r.f_number, r.distance_mm, x, 20.0) == pytest.approx(r.mtf, abs=1e-9)
    for n in (r.f_number * 0.97, r.f_number * 1.03):  # a local maximum
        assert contrast_at(150.0, n, r.distance_mm, 2000.0, 20.0) < r.mtf
    assert r.mtf == pytest.approx(_autocorrelation(20.0 * 550e-6 * r.working_f_number, r.defocus_waves), abs=1e-10)


def test_cli_focus_optimum_by_contrast() -> None:
    import json

    out = run("focus", "-f", "150", "--near", "2m", "--far", "inf", "--optimum", "--criterion", "mtf:0.1@20",
              "--format", "json")
    (row,) = json.loads(out.stdout)
    assert row["mtf"] > row["mtf_level"] == 0.1 and row["frequency_lpmm"] == 20.0 and row["f_number"] > 40
    assert (row["model"], row["wavelength_nm"]) == ("wave", 550.0)


def test_cli_focus_optimum_by_contrast_with_a_prescription_is_the_range_dof_gives() -> None:
    """A lens with a prescription: the real lens's wavefront answers (at its own wavelength), and dof's wave rung,
    set to the f-number, focus and contrast found, gives back the range asked for (one answer two ways)."""
    import json

    out = run("focus", "--lens", "dgauss100-lens", "--near", "2m", "--far", "5m", "--optimum", "--criterion",
              "mtf:0.3@30", "--format", "json")
    (row,) = json.loads(out.stdout)
    assert (row["model"], row["wavelength_nm"]) == ("wave+prescription", 587.6)
    table = run("focus", "--lens", "dgauss100-lens", "--near", "2m", "--far", "5m", "--optimum", "--criterion",
                "mtf:0.3@30")
    assert "by the lens's real wavefront (its prescription) at 587.6 nm" in table.stdout
    level = row["mtf"] * (1 - 1e-9)
    back = run("dof", "--lens", "dgauss100-lens", "-N", repr(row["f_number"]), "-s", f"{row['distance_mm']!r}mm",
               "--criterion", f"mtf:{level!r}@30", "--format", "json")
    (limits,) = json.loads(back.stdout)
    assert limits["model"] == "wave+prescription"
    assert limits["near_mm"] == pytest.approx(2000.0, rel=1e-6) and limits["far_mm"] == pytest.approx(5000.0, rel=1e-6)
    assert limits["working_f_number"] == pytest.approx(row["working_f_number"], rel=1e-12)


def test_contrast_depth_of_a_rail_frame_reduces_to_the_quarter_wave_depth() -> None:
    from camtool.dof.closeup import wave_depth_mm
    from camtool.dof.wave import contrast_depth_mm

    for n, m in ((8.0, 1.0), (4.0, 3.0), (2.8, 0.5)):
        n_w = n * (1.0 + m)
        nu = 0.5 / (550e-6 * n_w)  # half the cut-off, where a quarter wave leaves 0.2875 of contrast
        quarter = Criterion(defocus_mtf(0.5, 0.25), nu)
        assert contrast_depth_mm(n, m, quarter) == pytest.approx(wave_depth_mm(n, m), rel=1e-9)


def test_cli_stack_by_contrast() -> None:
    import json

    from camtool.dof.wave import contrast_depth_mm

    out = run("stack", "-m", "1", "-N", "8", "--depth", "5mm", "--criterion", "mtf:0.3@50", "--overlap", "0",
              "--format", "json")
    rows = json.loads(out.stdout)
    step = contrast_depth_mm(8.0, 1.0, Criterion(0.3, 50.0))
    assert len(rows) == math.ceil(5.0 / step) and rows[1]["step_mm"] == pytest.approx(step, rel=1e-12)
    assert rows[0]["criterion"] == "mtf:0.3@50"
    bad = run("stack", "-f", "24", "-N", "11", "--near", "0.5", "--far", "inf", "--criterion", "mtf:0.3@50")
    assert bad.exit_code == 2 and "rail stack" in bad.output


def test_the_comparison_table_of_docs_wave_md() -> None:
    """Every cell of docs/wave.md's root-sum-square table, recomputed."""
    from pathlib import Path

    from camtool.core.errors import DomainError

    text = (Path(__file__).parent.parent / "docs" / "wave.md").read_text(encoding="utf-8")
    rows = [line for line in text.splitlines() if line.startswith("| ") and line[2].isdigit()]
    assert len(rows) >= 10

    def shown(value: float | None) -> str:
        return "nothing sharp" if value is None else "∞" if math.isinf(value) else f"{value:.4g}"

    for line in rows:
        cells = [cell.strip() for cell in line.strip("|").split("|")]
        f, n, c, s = (float(x) for x in cells[:4])
        totals: list[float | None] = []
        for model, add in (("thin", False), ("thin", True), ("wave", False)):
            try:
                totals.append(float(depth_of_field(model, f, n, c, s, "lens", diffraction=add).limits.total_mm))
            except DomainError:
                totals.append(None)
        assert cells[4:7] == [shown(t) for t in totals], line
        rss, wave = totals[1:]
        if rss is not None and wave is not None and math.isfinite(wave):
            assert cells[7] == f"{(rss / wave - 1) * 100:+.0f} %", line


def test_chart_aperture_marks_the_contrast_optimum() -> None:
    from camtool.dof.wave import contrast_optimum
    from camtool.plans.chart import aperture_chart

    data = aperture_chart(focal_length_mm=100.0, coc_mm=0.03, near_mm=1000.0, far_mm=1500.0,
                          criterion=Criterion(0.3, 20.0))
    expected = contrast_optimum(100.0, 1000.0, 1500.0, 20.0)
    assert data.extra["contrast_f_number"] == pytest.approx(expected.f_number, rel=1e-12)
    assert data.marks[-1].x == pytest.approx(expected.f_number, rel=1e-12) and data.marks[-1].y is None
    plain = aperture_chart(focal_length_mm=100.0, coc_mm=0.03, near_mm=1000.0, far_mm=1500.0)
    assert len(plain.marks) == 2 and "contrast_f_number" not in plain.extra


@pytest.mark.parametrize("n", [1, 2, 3, 48, 49, 96, 768, 3072])
def test_the_gauss_legendre_nodes_are_numpy_s_and_their_weights_mpmath_s(n: int) -> None:
    """The quadrature's nodes against numpy's ``leggauss`` (an eigenproblem) and a few weights against mpmath's
    Legendre polynomials at 40 digits (Newton's method there from our node, then w = 2/((1 − x²)·P′ₙ(x)²))."""
    from camtool.optics.transfer import _gauss

    nodes, weights = _gauss(n)
    if n <= 768:  # numpy's dense eigenproblem takes seconds beyond
        reference, _ = np.polynomial.legendre.leggauss(n)
        assert np.max(np.abs(2.0 * nodes - 1.0 - reference)) < 1e-15
    assert math.fsum(weights) == pytest.approx(1.0, abs=1e-14)
    with mpmath.workdps(40):
        for j in sorted({0, n // 3, n // 2, n - 1}):
            x = mpmath.mpf(2.0 * float(nodes[j]) - 1.0)
            for _ in range(4):
                p, before = mpmath.legendre(n, x), mpmath.legendre(n - 1, x)
                x -= p / (n * (x * p - before) / (x * x - 1))
            slope = n * (x * mpmath.legendre(n, x) - mpmath.legendre(n - 1, x)) / (x * x - 1)
            exact = 1 / ((1 - x * x) * slope * slope)  # on [0, 1]: half of 2/((1 − x²)P′²)
            assert abs(2.0 * nodes[j] - 1.0 - float(x)) < 1e-15
            assert float(abs(weights[j] - exact) / exact) < 1e-9
