"""Star-trail limits, flash guide numbers and format equivalence against published examples."""

from __future__ import annotations

import math

import pytest
from cli_helpers import run, run_json

from camtool.core.errors import DomainError
from camtool.exposure.equivalence import equivalent_settings
from camtool.exposure.flash import guide_number_at_iso, solve_flash
from camtool.exposure.stars import npf_s, npf_simple_s, rule_500_s

# --- stars -------------------------------------------------------------------


def test_500_rule_published_examples() -> None:
    assert rule_500_s(50.0) == 10.0  # cag-creations.com, "NPF Rule": 500 / 50 mm = 10 s
    assert rule_500_s(20.0) == 25.0  # fichtelgard.com, "Photography: 500 rule": 500 / 20 = 25 s
    assert rule_500_s(14.0, 1.5) == pytest.approx(23.8, abs=0.05)  # 14 mm on 1.5x: 500/21 = 23.8 s
    assert rule_500_s(18.0) == pytest.approx(28, abs=0.5)  # Photo Plus, "500 Rule": 500/18 = 28 s
    assert rule_500_s(200.0, 1.0, 600.0) == 3.0  # 600 variant, 200 mm: 3 s (leagueslider.com)


def test_npf_simple_published_example() -> None:
    # theprimecalculator.com, "Exposure time for stars": 200 mm f/4, 3.75 µm, celestial equator -> 1.26 s.
    assert npf_simple_s(4.0, 3.75, 200.0) == pytest.approx(252.5 / 200.0, rel=1e-15)


def test_npf_full_matches_the_rounded_published_coefficients() -> None:
    # celestialprogramming.com prints the rule with 16.9, 0.1 and 13.7: within 0.5 % of 16.856, 0.0997, 13.713.
    for n, p, f in ((2.8, 4.3, 24.0), (1.4, 5.9, 14.0), (4.0, 3.76, 200.0)):
        rounded = (16.9 * n + 0.1 * f + 13.7 * p) / f
        assert npf_s(n, p, f) == pytest.approx(rounded, rel=0.005)


def test_declination_scales_both_npf_forms_by_one_over_cos() -> None:
    assert npf_s(2.8, 4.3, 24.0, 60.0) == pytest.approx(2 * npf_s(2.8, 4.3, 24.0), rel=1e-12)
    assert npf_simple_s(2.8, 4.3, 24.0, -60.0) == pytest.approx(2 * npf_simple_s(2.8, 4.3, 24.0), rel=1e-12)
    with pytest.raises(DomainError):
        npf_s(2.8, 4.3, 24.0, 90.0)


def test_stars_command() -> None:
    (row,) = run_json("stars", "-f", "24", "-N", "2.8", "--pixel-pitch", "4.3um")
    assert row["rule500_s"] == pytest.approx(500 / 24)
    assert row["npf_simple_s"] == pytest.approx((35 * 2.8 + 30 * 4.3) / 24)
    (row,) = run_json("stars", "-f", "50")
    assert row["rule500_s"] == 10.0 and row["npf_s"] is None
    assert run("stars", "-f", "24", "--pixel-pitch", "4.3um").exit_code == 2  # NPF needs -N


# --- flash -------------------------------------------------------------------


def test_flash_published_examples() -> None:
    # Contax RTS manual: GN 20 (ISO 100, m), 5 m -> f/4.
    assert solve_flash(20.0, 5.0, iso=100.0).f_number == 4.0
    # idigitalphoto.com, "guide number": GN 45, 5 m, ISO 100 -> f/9.
    assert solve_flash(45.0, 5.0, iso=100.0).f_number == 9.0
    # Kodak DCS 600 manual: GN 51 at ISO 200, 9 m -> f/5.67; at ISO 800 the GN is 102.
    assert solve_flash(51.0, 9.0, iso=200.0, quoted_iso=200.0).f_number == pytest.approx(5.67, abs=0.005)
    assert guide_number_at_iso(51.0, 800.0, 200.0) == 102.0
    # Pentax K100D manual: GN 15.6 at ISO 200, f/4 -> 3.9 m.
    assert solve_flash(15.6, f_number=4.0, iso=200.0, quoted_iso=200.0).distance_m == pytest.approx(3.9)
    # everything2.com: GN 118 ft, 10 ft, ISO 100 -> f/11 (11.8).
    assert solve_flash(118.0, 10.0, iso=100.0).f_number == pytest.approx(11.8)


def test_flash_solves_each_of_the_four() -> None:
    gn, d, n, s = 40.0, 7.0, 8.0, 100.0 * (8.0 * 7.0 / 40.0) ** 2
    assert solve_flash(None, d, n, s).guide_number_m == pytest.approx(gn)
    assert solve_flash(gn, None, n, s).distance_m == pytest.approx(d)
    assert solve_flash(gn, d, None, s).f_number == pytest.approx(n)
    assert solve_flash(gn, d, n, None).iso == pytest.approx(s)


def test_flash_command_feet_and_errors() -> None:
    (row,) = run_json("flash", "--gn", "131.2ft", "-s", "10m", "--iso", "100")
    assert row["f_number"] == pytest.approx(131.2 * 0.3048 / 10)
    result = run("flash", "--gn", "20", "-s", "5")
    assert result.exit_code == 2 and "left out: -N, --iso" in result.stderr


# --- equivalence ----------------------------------------------------------------


@pytest.mark.parametrize(("crop", "focal", "f_number"), [(1.6, 31.0, 1.8), (1.5, 33.0, 1.9), (1.0, 50.0, 2.8)])
def test_equivalence_published_example(crop: float, focal: float, f_number: float) -> None:
    # J. James, "Equivalence": 25 mm f/1.4 on mFT (crop 2) = 31 mm f/1.8 on 1.6x = 33 mm f/1.9 on 1.5x
    # = 50 mm f/2.8 on FF, all with an aperture of 25/1.4 = 18 mm.
    e = equivalent_settings(25.0, 1.4, 100.0, 1 / 2.0, 1 / crop)
    assert e.focal_length_mm == pytest.approx(focal, abs=0.5)
    assert e.f_number == pytest.approx(f_number, abs=0.06)  # published values rounded to the f-number scale
    assert e.aperture_diameter_mm == pytest.approx(18.0, abs=0.2)


def test_equivalence_iso_and_converters() -> None:
    # dpreview (KenBalbari): 300 mm f/6.7 ISO 200 on mFT = 600 mm f/13.4 ISO 800 on full frame.
    e = equivalent_settings(300.0, 6.7, 200.0, 1.0, 2.0)
    assert (e.focal_length_mm, e.f_number, e.iso) == (600.0, 13.4, 800.0)
    assert e.light_stops == 2.0
    t = equivalent_settings(70.0, 2.8, 100.0, 1.0, 1.0, 1.4)  # a 1.4x teleconverter: 98 mm f/3.92, one stop
    assert (t.focal_length_mm, t.f_number) == pytest.approx((98.0, 3.92))
    assert 2 * math.log2(t.f_number / 2.8) == pytest.approx(2 * math.log2(1.4))


def test_equiv_command() -> None:
    (row,) = run_json("equiv", "-f", "25", "-N", "1.4", "--iso", "200", "--crop", "2")
    assert (row["equivalent_focal_length_mm"], row["equivalent_f_number"], row["equivalent_iso"]) == \
        pytest.approx((50.0, 2.8, 800.0))


def test_batch_rows(tmp_path) -> None:  # type: ignore[no-untyped-def]
    scenes = tmp_path / "stars.csv"
    scenes.write_text("focal_length,f_number,pixel_pitch,declination\n24,2.8,4.3um,0\n50,1.8,4.3um,60\n",
                      encoding="utf-8")
    rows = run_json("stars", "--batch", str(scenes))
    assert [r["npf_simple_s"] for r in rows] == pytest.approx([(35 * 2.8 + 30 * 4.3) / 24,
                                                               2 * (35 * 1.8 + 30 * 4.3) / 50])
    flashes = tmp_path / "flash.csv"
    flashes.write_text("gn,distance,iso,gn_iso\n20,5,100,100\n51,9,800,200\n", encoding="utf-8")
    rows = run_json("flash", "--batch", str(flashes))
    assert [r["f_number"] for r in rows] == pytest.approx([4.0, 102 / 9])
