"""The pinhole: published rules and worked examples, the wave optics behind them, the command and the API.

Independent values: Petzval's rule as Sayanagi (J. Opt. Soc. Am. 57, 1091, 1967) quotes it and the worked examples
of Wikipedia's "Pinhole camera" for it, the worked examples of the Airy rule (d = √(2.44·λ·f): 0.366 mm at 100 mm and 550 nm,
sundial mailing list; 0.03679·√f mm at 555 nm, G. Penate on the pinhole-discussion list, 2002), Rayleigh's
1.9·√(f·λ), Young's single Fresnel zone r² = λ·F (half a wave of path difference), the MTF against mpmath's
pupil autocorrelation, and the optimum constant against a search that does not use the table.
"""

from __future__ import annotations

import json
import math

import mpmath
import numpy as np
import pytest
from cli_helpers import run

from camtool.optics import pinhole as ph
from camtool.optics.transfer import defocus_mtf
from camtool.plans.pinhole import pinhole_plan

mpmath.mp.dps = 25


def test_the_airy_rule_worked_examples() -> None:
    assert ph.rule_diameter_mm(math.sqrt(2.44), 100.0) == pytest.approx(0.366, abs=5e-4)
    for f in (25.0, 100.0, 300.0):  # 2·√(0.61·0.000555·f) = 0.03679·√f
        assert ph.rule_diameter_mm(math.sqrt(2.44), f, wavelength_nm=555.0) == pytest.approx(0.03679 * math.sqrt(f),
                                                                                           rel=5e-4)
    d = ph.rule_diameter_mm(math.sqrt(2.44), 100.0)
    assert ph.airy_mm(d, 100.0) == pytest.approx(d, rel=1e-12)  # the Airy disc as wide as the hole


def test_petzval_s_rule_and_its_worked_examples() -> None:
    # Petzval: the patch is D = d + k·L·λ/d with k = 2, least where dD/dd = 1 - 2·L·λ/d² = 0: d = √2·√(λ·L)
    petzval = next(rule for rule in ph.RULES if rule.name == "petzval")
    length = 100.0
    d = ph.rule_diameter_mm(petzval.constant, length)
    patch = [x + 2 * length * 550e-6 / x for x in (d * 0.99, d, d * 1.01)]
    assert patch[1] < patch[0] and patch[1] < patch[2]
    # Wikipedia, "Pinhole camera": 0.17 mm for a pinhole-to-film distance of 1 inch, 0.23 mm for 5 cm, at 550 nm
    assert round(ph.rule_diameter_mm(petzval.constant, 25.4), 2) == 0.17
    assert round(ph.rule_diameter_mm(petzval.constant, 50.0), 2) == 0.23
    assert ph.defocus_waves(d, length, math.inf) == pytest.approx(0.25, rel=1e-12)  # a quarter wave, k²/8


def test_rayleigh_and_young() -> None:
    assert ph.rule_diameter_mm(1.9, 100.0) == pytest.approx(1.9 * math.sqrt(0.00055 * 100.0), rel=1e-15)
    # Young: one Fresnel zone, radius² = λ·F with 1/F = 1/L + 1/s; the edge is half a wave farther than the centre
    d = ph.rule_diameter_mm(2.0, 80.0, 2000.0)
    assert (d / 2) ** 2 == pytest.approx(550e-6 * 80.0 * 2000.0 / 2080.0, rel=1e-12)
    edge = math.hypot(80.0, d / 2) + math.hypot(2000.0, d / 2) - 2080.0
    assert edge / 550e-6 == pytest.approx(0.5, rel=1e-5)
    assert ph.defocus_waves(d, 80.0, 2000.0) == pytest.approx(0.5, rel=1e-12)


@pytest.mark.parametrize("k", [1.2, 1.562, 1.9, 2.0, 3.0])
def test_the_defocus_of_a_rule_is_k_squared_over_8(k: float) -> None:
    for length, subject in ((50.0, math.inf), (150.0, 2000.0), (400.0, 900.0)):
        assert ph.defocus_waves(ph.rule_diameter_mm(k, length, subject), length, subject) == pytest.approx(k * k / 8)


def test_pinhole_mtf_against_mpmath() -> None:
    d, length, nu = ph.rule_diameter_mm(1.9, 100.0), 100.0, 1.0
    s = nu * 550e-6 * length / d
    w = (d / 2) ** 2 / length / (2 * 550e-6)

    s_, w_ = mpmath.mpf(s), mpmath.mpf(w)

    def integrand(x):
        return mpmath.cos(8 * mpmath.pi * w_ * s_ * x) * 2 * mpmath.sqrt(max(1 - (abs(x) + s_) ** 2, 0))

    expected = float(mpmath.quad(integrand, [-(1 - s_), 0, 1 - s_]) / mpmath.pi)
    assert ph.pinhole_mtf(d, length, nu) == pytest.approx(abs(expected), abs=1e-12)


def _best_k_by_search(level: float) -> float:
    """The k with the highest frequency at the level, each crossing found by bisection on the OTF itself."""
    def reach(k: float) -> float:
        w = k * k / 8.0
        grid = np.linspace(1e-4, 1.0, 400)
        m = defocus_mtf(grid, np.full_like(grid, w))
        i = int(np.argmax(m <= level))
        low, high = grid[i - 1], grid[i]
        for _ in range(50):
            mid = 0.5 * (low + high)
            low, high = (mid, high) if defocus_mtf(mid, w) > level else (low, mid)
        return k * low

    ks = np.linspace(1.0, 2.6, 161)
    i = int(np.argmax([reach(k) for k in ks]))
    a, b = ks[i - 1], ks[i + 1]
    for _ in range(40):
        c1, c2 = b - 0.618 * (b - a), a + 0.618 * (b - a)
        a, b = (a, c2) if reach(c1) >= reach(c2) else (c1, b)
    return 0.5 * (a + b)


@pytest.mark.parametrize("level", [0.1, 0.3, 0.5])
def test_best_constant_against_a_direct_search(level: float) -> None:
    assert ph.best_constant(level) == pytest.approx(_best_k_by_search(level), abs=0.01)


def test_each_rule_is_the_best_at_its_level() -> None:
    levels = [ph.rule_level(rule.constant) for rule in ph.RULES]
    assert all(level is not None for level in levels)
    assert levels == sorted(levels, reverse=True)  # a larger hole is best for fainter detail
    for rule, level in zip(ph.RULES, levels):
        assert ph.best_constant(level) == pytest.approx(rule.constant, abs=2e-3)
    assert ph.rule_level(3.0) is None


def test_the_optimum_resolves_finer_detail_than_every_rule() -> None:
    plan = pinhole_plan(film_distance_mm=100.0, level=0.3)
    best, *rules = plan.rows
    assert best["method"] == "optimum" and best["best_at_level"] == 0.3
    assert all(best["resolution_lpmm"] >= r["resolution_lpmm"] for r in rules)
    d = best["pinhole_mm"]  # the contrast at the optimum's frequency: the level, by the mpmath-checked OTF
    assert ph.pinhole_mtf(d, 100.0, best["resolution_lpmm"]) == pytest.approx(0.3, abs=2e-3)


def test_plan_geometry_and_exposure() -> None:
    plan = pinhole_plan(film_distance_mm=50.0, subject_distance_mm=1000.0, ev100=15.0, iso=100.0)
    row = plan.rows[3]
    assert row["method"] == "rayleigh"
    f_eff = 50.0 * 1000.0 / 1050.0
    assert plan.effective_distance_mm == pytest.approx(f_eff, rel=1e-15)
    assert row["pinhole_mm"] == pytest.approx(1.9 * math.sqrt(550e-6 * f_eff), rel=1e-12)
    assert row["f_number"] == pytest.approx(50.0 / row["pinhole_mm"], rel=1e-15)
    assert row["geometric_blur_mm"] == pytest.approx(row["pinhole_mm"] * 1.05, rel=1e-12)
    assert row["airy_mm"] == pytest.approx(2.44 * 550e-6 * row["f_number"], rel=1e-12)
    assert row["horizontal_deg"] == pytest.approx(math.degrees(2 * math.atan(36.0 / 100.0)), rel=1e-12)
    assert row["shutter_s"] == pytest.approx(row["f_number"] ** 2 / 2 ** 15, rel=1e-12)  # sunny 16: EV100 15
    far = pinhole_plan(film_distance_mm=5000.0)
    assert far.rows[4]["f_number"] > 1024 and far.rows[4]["shutter_s"] is None


def test_the_command() -> None:
    out = run("pinhole", "-f", "50", "--format", "json")
    rows = json.loads(out.stdout)
    assert out.exit_code == 0 and [r["method"] for r in rows] == ["optimum", "petzval", "airy", "rayleigh", "young"]
    assert run("pinhole", "-f", "50", "--contrast", "1.2").exit_code == 2
    assert run("pinhole", "-f", "0.1mm").exit_code == 2
    table = run("pinhole", "-f", "150", "-s", "2m")
    assert table.exit_code == 0 and "rayleigh" in table.stdout


def test_a_scene_or_camera_preset_with_pinhole_answers_or_refuses_in_one_line() -> None:
    """pinhole's -s takes one value: the equipment checks read it as a list of one (a deep fuzz found a traceback)."""
    from tests.cli_helpers import run

    for scene in ("landscape-24", "macro-1to1"):
        result = run("pinhole", "--camera", "apple-iphone-15-pro", "--scene", scene, "--format", "csv",
                     "--film-distance", "1")
        assert result.exit_code in (0, 2) and "Traceback" not in result.output


def test_a_scene_gives_the_subject_distance_a_typed_one_wins() -> None:
    rows = json.loads(run("pinhole", "-f", "50", "--scene", "portrait-85", "--format", "json").stdout)
    assert {r["subject_distance_mm"] for r in rows} == {2000.0}  # the scene's 2 m (F = L·s/(L + s))
    assert rows[1]["pinhole_mm"] == pytest.approx(math.sqrt(2.0) * math.sqrt(550e-6 * 50.0 * 2000.0 / 2050.0), rel=1e-12)
    typed = json.loads(run("pinhole", "-f", "50", "--scene", "portrait-85", "-s", "5m", "--format", "json").stdout)
    assert {r["subject_distance_mm"] for r in typed} == {5000.0}
    alone = json.loads(run("pinhole", "-f", "50", "--format", "json").stdout)
    assert {r["subject_distance_mm"] for r in alone} == {None}  # infinity, null in JSON
