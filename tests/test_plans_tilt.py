"""camtool.plans.tilt called directly: keyword arguments in, named rows out, checked against the published rules.

Independent values: the hinge rule J = f/sin θ and its inverse θ = asin(f/J)
(Merklinger, *Focusing the View Camera*, 1993; docs/tilt.md), the thin-lens
depth of field with H = f²/(N·c) + f (near = u(H − f)/(H + u − 2f), far =
u(H − f)/(H − u), u from the lens) for a lens that is not tilted, and the
geometry of a plane through two points on the ground.
"""

from __future__ import annotations

import math
from types import SimpleNamespace

import pytest

from camtool.dof.ladder import ModelUnavailable
from camtool.plans.tilt import (
    KEYS,
    BeyondLensRange,
    SettingsError,
    TiltError,
    TiltRow,
    check_question,
    solve_tilt,
)


def test_hinge_rule_and_named_rows() -> None:
    answer = solve_tilt(focal_length_mm=[90.0], f_number=[11.0], coc_mm=[0.03], tilt_deg=[3.0], focus_mm=[2000.0])
    (row,) = answer.rows
    assert isinstance(row, TiltRow) and list(row._asdict()) == KEYS
    assert row.hinge_mm == pytest.approx(90.0 / math.sin(math.radians(3.0)), rel=1e-12)
    assert row.focus_mm == pytest.approx(2000.0, rel=1e-12)
    assert (answer.movement, answer.models, row.model) == ("tilt", ("thin",), "thin")
    assert row.near_mm < row.focus_mm < row.far_mm


def test_hinge_gives_the_tilt() -> None:
    (row,) = solve_tilt(focal_length_mm=[90.0], f_number=[11.0], coc_mm=[0.03], hinge_mm=[1600.0],
                        focus_mm=[5000.0]).rows
    assert row.tilt_deg == pytest.approx(math.degrees(math.asin(90.0 / 1600.0)), rel=1e-12)
    assert row.hinge_mm == 1600.0  # reported as given


def test_no_tilt_is_thin_lens_depth_of_field() -> None:
    f, n, c, u = 90.0, 11.0, 0.03, 3000.0
    (row,) = solve_tilt(focal_length_mm=[f], f_number=[n], coc_mm=[c], tilt_deg=[0.0], focus_mm=[u],
                        distance_from="lens").rows
    h = f * f / (n * c) + f
    assert row.near_mm == pytest.approx(u * (h - f) / (h + u - 2 * f), rel=1e-9)
    assert row.far_mm == pytest.approx(u * (h - f) / (h - u), rel=1e-9)
    assert math.isinf(row.hinge_mm)


def test_two_points_on_the_ground() -> None:
    (row,) = solve_tilt(focal_length_mm=[90.0], f_number=[11.0], coc_mm=[0.03],
                        points=[(3000.0, -1600.0), (20000.0, -1600.0)], distance_from="lens").rows
    assert row.hinge_mm == pytest.approx(1600.0, rel=1e-12)  # the ground, 1.6 m below the lens
    assert row.focus_plane_deg == pytest.approx(90.0, abs=1e-9)  # parallel to the line of sight
    assert math.isinf(row.focus_mm)


def test_swing_is_the_same_geometry_and_rows_cover_every_combination() -> None:
    tilted = solve_tilt(focal_length_mm=[90.0], f_number=[8.0, 11.0], coc_mm=[0.03], tilt_deg=[4.0],
                        focus_mm=[3000.0, 5000.0])
    swung = solve_tilt(focal_length_mm=[90.0], f_number=[8.0, 11.0], coc_mm=[0.03], swing_deg=[4.0],
                       focus_mm=[3000.0, 5000.0])
    assert len(tilted.rows) == 4 and swung.movement == "swing"
    assert [r.near_mm for r in swung.rows] == [r.near_mm for r in tilted.rows]
    assert [(r.f_number, round(r.focus_mm)) for r in tilted.rows] == [(8.0, 3000), (8.0, 5000), (11.0, 3000),
                                                                      (11.0, 5000)]


def test_f_number_for_a_wedge() -> None:
    (row,) = solve_tilt(focal_length_mm=[150.0], coc_mm=[0.1], tilt_deg=[7.0], focus_mm=[10_000.0], at_mm=20_000.0,
                        half_depth_mm=1000.0, optimum=True).rows
    assert min(row.above_mm, row.below_mm) == pytest.approx(1000.0, rel=1e-9)
    assert row.f_number == row.f_number_needed < row.f_number_optimum


def test_model_choice() -> None:
    from camtool.dof.ladder import LensData

    lens = LensData(pupil_magnification=2.5, hiatus_mm=-15.0)
    common = {"focal_length_mm": [24.0], "f_number": [8.0], "coc_mm": [0.03], "tilt_deg": [6.0], "focus_mm": [1000.0]}
    assert solve_tilt(**common, lens=lens).models == ("thick",)  # auto: thick when lens data is known
    assert solve_tilt(**common).models == ("thin",)
    assert solve_tilt(**common, lens=lens, model="all").models == ("thin", "thick")
    with pytest.raises(ModelUnavailable):
        solve_tilt(**common, lens=lens, model="raytrace")


@pytest.mark.parametrize(("question", "error"), [
    ({"tilt_deg": [3.0], "swing_deg": [3.0]}, SettingsError),
    ({"tilt_deg": [3.0], "hinge_mm": [1600.0]}, SettingsError),
    ({}, SettingsError),
    ({"points": [(2000.0, -1000.0)]}, TiltError),
    ({"tilt_deg": [3.0], "focus_mm": [2000.0], "hyperfocal": True}, SettingsError),
    ({"tilt_deg": [3.0], "half_depth_mm": 1000.0}, SettingsError),
    ({"tilt_deg": [3.0], "at_mm": 5000.0, "optimum": True}, SettingsError),
])
def test_questions_that_do_not_go_together(question: dict, error: type) -> None:
    with pytest.raises(error):
        check_question(**question)


def test_settings_error_names_the_parameters() -> None:
    with pytest.raises(SettingsError) as caught:
        solve_tilt(f_number=[8.0], coc_mm=[0.03], tilt_deg=[3.0])
    assert caught.value.names == ("focal_length_mm",)


def test_a_tilt_beyond_the_lens_range() -> None:
    # Canon TS-E 24mm f/3.5L II: tilt ±8.5° (Canon's specification)
    preset = SimpleNamespace(tilt_max_deg=8.5, id="ts-e-24-ii")
    common = {"focal_length_mm": [24.0], "f_number": [8.0], "coc_mm": [0.03], "focus_mm": [1000.0],
              "lens_preset": preset}
    assert solve_tilt(**common, tilt_deg=[8.5]).rows[0].tilt_deg == 8.5
    with pytest.raises(BeyondLensRange) as caught:
        solve_tilt(**common, hinge_mm=[100.0])
    assert caught.value.param == "hinge_mm"
    assert caught.value.tilt_deg == pytest.approx(math.degrees(math.asin(24.0 / 100.0)), rel=1e-12)


def test_half_depth_needs_a_tilt() -> None:
    with pytest.raises(TiltError) as caught:
        solve_tilt(focal_length_mm=[24.0], f_number=[8.0], coc_mm=[0.03], tilt_deg=[0.0], focus_mm=[3000.0],
                   at_mm=5000.0, half_depth_mm=100.0)
    assert caught.value.param == "half_depth_mm"


def test_lens_checks_come_before_the_equipment() -> None:
    from camtool.plans.tilt import check_lens

    check_lens(focal_length_mm=[90.0], f_number=[8.0])
    check_lens(focal_length_mm=[90.0], half_depth_mm=1000.0)  # the f-number is what the wedge asks for
    with pytest.raises(SettingsError) as caught:
        check_lens(f_number=[8.0])
    assert caught.value.names == ("focal_length_mm",)
    with pytest.raises(ModelUnavailable):
        check_lens(model="raytrace", focal_length_mm=[90.0], f_number=[8.0])


def test_notes_say_what_the_numbers_mean() -> None:
    answer = solve_tilt(focal_length_mm=[90.0], f_number=[11.0], coc_mm=[0.03], tilt_deg=[0.0], focus_mm=[3000.0],
                        at_mm=5000.0, along="axis", angles_from="horizon", hinge_from="pupil")
    assert answer.notes[0] == "thin model"
    assert any("from the line of sight" in n for n in answer.notes)  # angles from the horizon
    assert any("entrance pupil" in n for n in answer.notes) and any("lens axis" in n for n in answer.notes)
    assert any("no tilt" in n for n in answer.notes) and any("above/below" in n for n in answer.notes)
