"""Close-up and macro: published macro values, the exact thin formulas against mpmath, the lens presets.

Sources are given where each value is used. Where a published table is
rounded, the test allows that rounding and no more.
"""

from __future__ import annotations

import math

import mpmath
import numpy as np
import pytest

from camtool.core.errors import DomainError
from camtool.dof.closed import thin_dof
from camtool.dof.closeup import (
    closeup_dof,
    coc_for_depth,
    diffraction_row,
    f_number_for_depth,
    focus_spread_mm,
    macro_depth_mm,
    optimum_aperture,
    wave_depth_mm,
)
from camtool.dof.thick import thick_dof
from camtool.geometry.closeup import (
    internal_focus,
    internal_focus_at_distance,
    internal_focus_at_magnification,
    magnification_branches,
    with_extension,
)
from camtool.presets import load_db
from camtool.presets.focusing import focus_model

mpmath.mp.dps = 50


def _two_significant(x: float) -> float:
    return float(f"{x:.2g}")


# --- published macro values ---------------------------------------------------------------------

def test_zerene_worked_example_classic_and_wave_depth():
    # Zerene Stacker, "DOF Calculator" (zerenesystems.com/cms/stacker/docs/dofcalculator):
    # "Magnification = 1, nominal lens aperture f/16 giving effective f/32, calculates diffraction
    # limited wave optics DOF = 2.253 mm" and, adding CoC 0.030 mm, "classic DOF = 1.92 mm".
    assert round(wave_depth_mm(16.0, 1.0), 3) == 2.253
    assert round(macro_depth_mm(16.0, 0.03, 1.0), 2) == 1.92
    assert diffraction_row(16.0, 0.03, 1.0).working_f_number == 32.0


# Zerene Stacker, "DOF Estimates For Macro/Micro", revision of 2020-01-07
# (zerenesystems.com/cms/stacker/docs/tables/macromicrodof): rows of the step-size table, one per
# magnification, columns nominal f/2, 2.8, 4, 5.6, 8, 11, 16, 22, printed to two significant
# figures. The calculator page says its wave-optics DOF "reproduces an entry in Table 2-A".
ZERENE_TABLE = {
    2.0: [0.020, 0.039, 0.079, 0.16, 0.32, 0.60, 1.3, 2.4],
    2.5: [0.017, 0.034, 0.069],
    5.0: [0.013, 0.025, 0.051, 0.099],
    14.0: [0.010, 0.020, 0.040, 0.079, 0.16, 0.31, 0.65, 1.2],
    20.0: [0.0097, 0.019, 0.039, 0.076, 0.16, 0.29, 0.62, 1.2],
}
COLUMNS = [2.0, 2.8, 4.0, 5.6, 8.0, 11.0, 16.0, 22.0]


@pytest.mark.parametrize("m", sorted(ZERENE_TABLE))
def test_wave_depth_reproduces_zerene_table(m):
    for n, published in zip(COLUMNS, ZERENE_TABLE[m]):
        assert _two_significant(wave_depth_mm(n, m)) == published, (m, n)


@pytest.mark.parametrize("m", [1.0, 2.0, 3.0, 4.0, 5.0])
@pytest.mark.parametrize("n", [2.8, 8.0, 16.0])
def test_depth_at_m_1_to_5_against_the_macro_rule(m, n):
    # Cambridge in Colour, "Macro photography: depth of field": DOF = 2·N·c·(m + 1)/m²
    # (also Zerene Stacker's "classic" DOF); the exact thin lens differs by 1/(1 − (Nc/(fm))²).
    c, f = 0.03, 100.0
    rule = 2.0 * n * c * (m + 1.0) / (m * m)
    assert macro_depth_mm(n, c, m) == pytest.approx(rule, rel=1e-15)
    exact = closeup_dof(f, n, c, m).total_mm
    assert exact == pytest.approx(rule / (1.0 - (n * c / (f * m)) ** 2), rel=1e-13)
    assert exact == pytest.approx(rule, rel=2.0 * (n * c / (f * m)) ** 2)


def test_airy_diameter_and_diffraction_limit():
    # The Airy disc's first dark ring is at radius j₁,₁/π · λN (j₁,₁ the first zero of J₁; Born & Wolf
    # §8.5.2): the diameter 2·j₁,₁/π·λ·N_w, which the rounded factor 2.44 matches within 0.03 %.
    diameter = 2.0 * float(mpmath.besseljzero(1, 1)) / math.pi * 550e-6 * 32.0
    row = diffraction_row(16.0, 0.03, 1.0)
    assert row.airy_mm == pytest.approx(diameter, rel=3e-4)
    # at the limit f-number the Airy disc equals the CoC (a physical identity of the definition)
    limit = diffraction_row(8.0, 0.03, 2.0, 0.5).limit_f_number
    assert diffraction_row(limit, 0.03, 2.0, 0.5).airy_mm == pytest.approx(0.03, rel=1e-14)


def test_quarter_wave_depth_is_lambda_over_na_squared():
    # Rayleigh quarter-wave depth ±λ/(2·NA²) about focus, NA = m/(2·N_w) on the subject side
    # (Born & Wolf §8.8): λ/NA² in all.
    for m, n, p in [(1.0, 8.0, 1.0), (5.0, 2.8, 0.6), (20.0, 4.0, 1.0)]:
        na = m / (2.0 * n * (1.0 + m / p))
        assert wave_depth_mm(n, m, p) == pytest.approx(550e-6 / na**2, rel=1e-14)


# Hansma's table of optimum f-stop against focus spread D, as reprinted by Q.-T. Luong, "How to
# select the f-stop" (Large Format Page, largeformatphotography.info/fstop.html):
# D(mm) 1 → 16.6, 2 → 22.6, 3 → 32.2, 4 → 32.6, 5 → 32.9, 6 → 45.2, 7 → 45.4, 8 → 45.6, 9 → 45.8, 10 → 64,
# read as "f/x plus y tenths of a stop" (each doubling of D adds exactly one stop down the table,
# as N ∝ √D requires).
HANSMA = {1: (16, 0.6), 2: (22, 0.6), 3: (32, 0.2), 4: (32, 0.6), 5: (32, 0.9), 6: (45, 0.2), 7: (45, 0.4),
          8: (45, 0.6), 9: (45, 0.8), 10: (64, 0.0)}
FULL_STOPS = {16: 16.0, 22: 2**4.5, 32: 32.0, 45: 2**5.5, 64: 64.0}


@pytest.mark.parametrize("spread", sorted(HANSMA))
def test_optimum_aperture_against_hansma_table(spread):
    stop, tenths = HANSMA[spread]
    published = FULL_STOPS[stop] * 2.0 ** (tenths / 2.0)
    ours = optimum_aperture(float(spread)).f_number
    # within 0.15 stop: the table's tenth-of-a-stop rounding plus Hansma's λ, which runs about
    # 0.06 stop smaller than 550 nm's (the offset is the same on every row)
    assert abs(2.0 * math.log2(ours / published)) <= 0.15


def test_optimum_balances_defocus_and_diffraction():
    # At the optimum the defocus blur Δ/(2N_w) equals the Airy disc, and both the root-sum-square
    # and the plain sum are at their minimum: checked against a brute-force scan.
    spread, m = 3.0, 2.0
    best = optimum_aperture(spread, m)
    per_n = 2.44 * 550e-6
    assert spread / (2.0 * best.working_f_number) == pytest.approx(per_n * best.working_f_number, rel=1e-14)
    grid = np.linspace(5.0, 200.0, 200001)
    rss = np.hypot(spread / (2.0 * grid), per_n * grid)
    assert grid[np.argmin(rss)] == pytest.approx(best.working_f_number, abs=2e-3)
    assert best.blur_mm == pytest.approx(rss.min(), rel=1e-9)
    assert best.f_number == pytest.approx(best.working_f_number / 3.0, rel=1e-15)


def test_focus_spread_is_the_image_distance_difference():
    f, near, far = 150.0, 2000.0, 8000.0
    v = lambda u: mpmath.mpf(f) * u / (u - f)  # noqa: E731
    assert focus_spread_mm(f, near, far) == pytest.approx(float(v(near) - v(far)), rel=1e-14)


def test_inverse_close_up_round_trips():
    c = coc_for_depth(4.0, 2.5, 0.2)
    assert macro_depth_mm(4.0, c, 2.5) == pytest.approx(0.2, rel=1e-15)
    n = f_number_for_depth(0.015, 2.5, 0.2, 0.7)
    assert macro_depth_mm(n, 0.015, 2.5, 0.7) == pytest.approx(0.2, rel=1e-15)


# --- exact thin formulas against mpmath ------------------------------------------------------------

def _mp_limits(f, n, c, m):
    f, n, c, m = (mpmath.mpf(x) for x in (f, n, c, m))
    u = f * (1 + 1 / m)
    v = f * (1 + m)
    near = u * f**2 / (f**2 + n * c * (u - f))
    denominator = f**2 - n * c * (u - f)
    far = u * f**2 / denominator if denominator > 0 else mpmath.inf
    return u, v, near, far


MAGNIFICATIONS = [0.01, 0.03, 0.1, 0.3, 0.5, 0.9, 1.0, 1.1, 2.0, 3.0, 5.0, 10.0, 20.0]


@pytest.mark.parametrize("m", MAGNIFICATIONS)
@pytest.mark.parametrize("plane", ["lens", "sensor"])
def test_closeup_limits_against_mpmath(m, plane):
    f, n, c = 65.0, 2.8, 0.03
    _u, v, near, far = _mp_limits(f, n, c, m)
    shift = v if plane == "sensor" else 0
    r = closeup_dof(f, n, c, m, distance_from=plane)
    assert r.near_mm == pytest.approx(float(near + shift), rel=1e-14)
    assert r.far_mm == pytest.approx(float(far + shift), rel=1e-14)
    assert r.total_mm == pytest.approx(float(far - near), rel=1e-11)
    assert r.magnification == m


@pytest.mark.parametrize("m", MAGNIFICATIONS)
def test_thin_model_at_lens_plane_distance_between_f_and_2f(m):
    # the ladder's thin model reached through a lens-plane distance u = f(1 + 1/m), any m
    f, n, c = 65.0, 2.8, 0.03
    u, _v, near, _far = _mp_limits(f, n, c, m)
    r = thin_dof(f, n, c, float(u), distance_from="lens")
    assert r.near_mm == pytest.approx(float(near), rel=1e-13)
    assert r.front_mm == pytest.approx(float(u - near), rel=1e-9)
    assert r.magnification == pytest.approx(m, rel=1e-12)


@pytest.mark.parametrize("m", [0.01, 0.1, 0.5, 0.9])
def test_sensor_distance_has_both_branches(m):
    f = 65.0
    d = f * (1 + m) ** 2 / m
    low, high = magnification_branches(f, d)
    assert low == pytest.approx(m, rel=1e-12)
    assert high == pytest.approx(1.0 / m, rel=1e-12)
    # the thin model from the sensor answers the m ≤ 1 branch; the other branch matches mpmath
    assert thin_dof(f, 8.0, 0.03, d).magnification == pytest.approx(m, rel=1e-10)
    _u, v, near, _far = _mp_limits(f, 8.0, 0.03, 1.0 / m)
    assert closeup_dof(f, 8.0, 0.03, high).near_mm == pytest.approx(float(near + v), rel=1e-12)


def test_issue_example_65mm_at_3x_and_one_third():
    # `camtool focus -f 65 -m 3` puts the subject 65·16/3 = 346.67 mm from the sensor; at f/2.8 with
    # the full-frame CoC (diagonal/1500) the same distance has 0.07 mm of depth at m = 3 and 1.94 mm
    # at m = 1/3; at f/8, 1:2 has 2.77 mm and 2:1 0.35 mm (the figures of the issue).
    c = math.hypot(36.0, 24.0) / 1500.0
    d = 65.0 * 16.0 / 3.0
    low, high = magnification_branches(65.0, d)
    assert round(closeup_dof(65.0, 2.8, c, high).total_mm, 2) == 0.07
    assert round(closeup_dof(65.0, 2.8, c, low).total_mm, 2) == 1.94
    assert round(closeup_dof(65.0, 8.0, c, 0.5).total_mm, 2) == 2.77
    assert round(closeup_dof(65.0, 8.0, c, 2.0).total_mm, 2) == 0.35


def test_thick_at_magnification_matches_the_closed_form():
    f, n, c, p = 100.0, 8.0, 0.03, 0.6
    for m in (0.2, 1.0, 3.0, 12.0):
        u = f * (1 + 1 / m)
        thick = thick_dof(f, n, c, u, pupil_magnification=p, distance_from="lens")
        ours = closeup_dof(f, n, c, m, p, distance_from="lens")
        assert ours.front_mm == pytest.approx(thick.front_mm, rel=1e-11)
        assert ours.rear_mm == pytest.approx(thick.rear_mm, rel=1e-11)


def test_arrays_match_scalars():
    m = np.array([0.05, 1.0, 5.0, 20.0])
    arr = closeup_dof(100.0, 8.0, 0.03, m)
    for i, mi in enumerate(m):
        one = closeup_dof(100.0, 8.0, 0.03, float(mi))
        assert arr.near_mm[i] == one.near_mm and arr.far_mm[i] == one.far_mm


def test_extension_adds_e_over_f():
    # v = f(1 + m) + e  ⇒  m' = (v − f)/f = m + e/f (thin lens)
    assert with_extension(100.0, 0.5, 25.0) == 0.75


# --- internal focus and the lens presets -----------------------------------------------------------

MACROS = [lens for lens in load_db().all("lens") if lens.category == "macro"]


@pytest.mark.parametrize("lens", MACROS, ids=lambda lens: lens.id)
def test_every_macro_preset_reaches_its_published_magnification_at_its_closest_focus(lens):
    # lens_db/lenses.yaml: each maker's closest focus and maximum magnification (source: field)
    model = focus_model(lens, lens.focal_min_mm)
    # a lens whose subject moves away as it magnifies (the MP-E 65) publishes that distance apart
    closest = lens.focus_at_max_magnification_mm or lens.min_focus_mm
    m, _f = internal_focus_at_distance(model, closest)
    assert m == pytest.approx(lens.max_magnification, rel=0.02)
    assert internal_focus_at_magnification(model, lens.max_magnification)[1] == pytest.approx(closest, rel=0.02)
    with pytest.raises(DomainError):
        internal_focus_at_distance(model, lens.min_focus_mm * 0.95)


def test_mp_e_65_range_and_canon_distance():
    # Canon MP-E 65mm f/2.8 1-5x Macro Photo (Wikipedia's infobox of Canon's figures): 1x to 5x, closest
    # distance 240 mm (the lens collapsed, 1x), farthest 313 mm (extended, 5x).
    lens = load_db().get("lens", "mp-e-65")
    model = focus_model(lens, 65.0)
    assert internal_focus_at_magnification(model, 1.0)[1] == pytest.approx(240.0, rel=1e-12)
    assert internal_focus_at_magnification(model, 5.0)[1] == pytest.approx(313.0, rel=1e-12)
    assert internal_focus_at_distance(model, 313.0)[0] == pytest.approx(5.0, rel=1e-9)
    assert internal_focus_at_distance(model, 240.0)[0] == pytest.approx(1.0, rel=1e-9)
    for bad in (0.5, 5.5):
        with pytest.raises(DomainError, match="1× to 5×"):
            internal_focus_at_magnification(model, bad)
    with pytest.raises(DomainError, match="1× to 5×"):
        internal_focus_at_distance(model, 1000.0)


def test_unit_focusing_is_kappa_zero():
    model = internal_focus(50.0, 200.0, 1.0)
    assert model.kappa == pytest.approx(0.0, abs=1e-15)
    m, _f = internal_focus_at_distance(model, 5000.0)
    assert m == pytest.approx(magnification_branches(50.0, 5000.0).low, rel=1e-13)


def test_zoom_rows_are_used_per_focal_length():
    # lens_db: RF 24-70 F2.8: 0.21 m at 24 mm and 0.38 m at 70 mm (close_focus rows, no magnification)
    lens = load_db().get("lens", "rf-24-70-2.8")
    assert focus_model(lens, 24.0).min_focus_mm == 210.0
    assert focus_model(lens, 70.0).min_focus_mm == 380.0


def _published_pairs():
    for lens in load_db().all("lens"):
        for f, distance, m in lens.close_focus:
            if m is not None:
                yield pytest.param(lens, f, distance, m, id=f"{lens.id}@{f:g}")
        if not lens.is_zoom and lens.min_focus_mm and lens.max_magnification and lens.prescription is None:
            if lens.focus_at_max_magnification_mm:  # both ends published (the MP-E 65)
                yield pytest.param(lens, lens.focal_min_mm, lens.min_focus_mm, lens.min_magnification,
                                   id=f"{lens.id}-least")
                yield pytest.param(lens, lens.focal_min_mm, lens.focus_at_max_magnification_mm,
                                   lens.max_magnification, id=lens.id)
                continue
            yield pytest.param(lens, lens.focal_min_mm, lens.min_focus_mm, lens.max_magnification, id=lens.id)


@pytest.mark.parametrize(("lens", "focal", "closest", "published"), list(_published_pairs()))
def test_every_published_closest_focus_gives_its_magnification(lens, focal, closest, published):
    # lens_db/lenses.yaml: each lens's (or zoom row's) published closest focus and magnification (its source: field)
    model = focus_model(lens, focal)
    m, _f = internal_focus_at_distance(model, closest)
    assert m == pytest.approx(published, rel=0.02)
    with pytest.raises(DomainError):  # nothing closer than the model's closest focus (the published one but the MP-E's)
        internal_focus_at_distance(model, min(closest, model.min_focus_mm) * 0.97)
    if lens.min_magnification is None:  # focusing out from the closest focus lowers the magnification
        assert internal_focus_at_distance(model, closest * 1.05)[0] < m


def test_prescription_rungs_at_a_magnification():
    # through every rung with a prescription: m = 1 is u = f(1 + 1/m) from the front principal plane
    from pathlib import Path

    import yaml

    from camtool.cli.lensdata import LensData
    from camtool.dof.ladder import depth_of_field
    from camtool.optics.prescription import prescription_from_mapping

    data = yaml.safe_load((Path(__file__).parent / "data" / "prescriptions" / "dgauss100.yaml").read_text())
    lens = LensData(prescription=prescription_from_mapping(data, source="dgauss100.yaml"))
    f = lens.focal_length_mm
    u = f * 2.0
    thick = depth_of_field("paraxial", f, 2.8, 0.03, u, "lens", lens).limits
    p, _delta = lens.thick_parameters()
    assert thick.total_mm == pytest.approx(closeup_dof(f, 2.8, 0.03, 1.0, p, "lens").total_mm, rel=1e-9)
    real = depth_of_field("raytrace", f, 2.8, 0.03, u, "lens", lens).limits
    assert real.total_mm == pytest.approx(thick.total_mm, rel=0.05)  # aberrations: a few per cent at 1:1
