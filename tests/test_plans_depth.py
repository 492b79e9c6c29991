"""The depth-of-field plans called directly: keyword arguments, named results, checked against independent values.

camtool.plans.dof (the dof table), camtool.plans.focus, camtool.plans.fov,
camtool.plans.compose and camtool.plans.equipment.lens_data. Each number is
a published formula or an identity, never the code's own output.
"""

from __future__ import annotations

import math

import pytest

from camtool.core.errors import InputError
from camtool.dof.ladder import LensData
from camtool.plans import compose, equipment, focus
from camtool.plans.dof import dof_table, lens_behind_converter
from camtool.plans.fov import field_of_view
from camtool.presets import load_db


def _thin_limits(f: float, n: float, c: float, s: float) -> tuple[float, float]:
    """Near and far limits from the lens plane (Wikipedia, "Depth of field": s(H − f)/(H + s − 2f), s(H − f)/(H − s))."""
    h = f * f / (n * c) + f
    return s * (h - f) / (h + s - 2 * f), s * (h - f) / (h - s)


def test_a_distant_scene_goes_straight_to_the_ladder_with_the_textbook_limits() -> None:
    table = dof_table(model="thin", focal_length_mm=50.0, f_number=8.0, wanted=3000.0, coc_mm=0.03,
                      distance_from="lens")
    near, far = _thin_limits(50.0, 8.0, 0.03, 3000.0)
    row = table.rows[0]
    assert table.path == "direct" and not table.close
    assert math.isclose(row["near_mm"], near, rel_tol=1e-12) and math.isclose(row["far_mm"], far, rel_tol=1e-12)
    assert row["working_f_number"] == 8.0 * (1.0 + row["magnification"])  # N(1 + m/P), P = 1
    assert row["focal_length_at_focus_mm"] == 50.0


def test_a_magnification_goes_through_the_close_up_planner() -> None:
    # 100 mm at 1:1: u = f(1 + 1/m) = 200 mm from the lens, working f-number N(1 + m/P) = 2N
    table = dof_table(model="thin", focal_length_mm=100.0, f_number=8.0, wanted=1.0, coc_mm=0.03,
                      by_magnification=True, distance_from="lens")
    row = table.rows[0]
    assert table.path == "closeup" and table.close and table.by_magnification
    assert math.isclose(row["distance_mm"], 200.0, rel_tol=1e-12)
    assert math.isclose(row["working_f_number"], 16.0, rel_tol=1e-12)
    near, far = _thin_limits(100.0, 8.0, 0.03, 200.0)
    assert math.isclose(row["near_mm"], near, rel_tol=1e-9) and math.isclose(row["far_mm"], far, rel_tol=1e-9)


def test_model_all_ends_each_scene_with_the_most_complete_rung_at_zero_difference() -> None:
    table = dof_table(model="all", focal_length_mm=50.0, f_number=8.0, wanted=3000.0, coc_mm=0.03)
    models = [row["model"] for row in table.rows]
    assert models[-1] == "wave"  # beside the geometric ladder, after its most complete rung
    assert models[-2] == table.reference_model and table.rows[-2]["difference_pct"] == 0.0
    assert all(row["time_per_evaluation_s"] > 0 for row in table.rows)


def test_diffraction_says_which_depth_dominates() -> None:
    # 100 mm f/4 at 1:1, c = 0.03 mm: geometric depth about 2·N·c·(1 + m)/m² = 0.48 mm, the wave-optics
    # depth λ/NA² = 4·λ·N_w² = 4 · 0.00055 · 8² = 0.14 mm
    table = dof_table(model="thin", focal_length_mm=100.0, f_number=4.0, wanted=1.0, coc_mm=0.03,
                      by_magnification=True, diffraction=True)
    assert table.dominated_by == frozenset({"geometric"})


def test_a_prescription_behind_a_teleconverter_is_dropped_and_not_traced() -> None:
    lens = equipment.lens_data(prescription="dgauss100", database=load_db)
    assert lens is not None and lens.prescription is not None
    with pytest.raises(InputError) as caught:
        lens_behind_converter(lens, teleconverter=1.4, model="raytrace")
    assert caught.value.param == "teleconverter"
    assert caught.value.render(lambda name: f"--{name}").endswith("use --model thin, thick or auto")
    assert lens_behind_converter(lens, teleconverter=1.4, model="auto") is None
    kept = lens_behind_converter(lens, teleconverter=1.4, model="thin", pupil_magnification=0.7)
    assert kept == LensData(pupil_magnification=0.7)
    assert lens_behind_converter(lens, teleconverter=None, model="raytrace") is lens


def test_lens_data_values_given_win_over_the_presets() -> None:
    preset = load_db().lens("mp-e-65")
    both = equipment.lens_data(pupil_magnification=0.9, lens_preset=preset)
    assert both is not None and both.pupil_magnification == 0.9 and both.hiatus_mm == preset.hiatus_mm
    assert equipment.lens_data() is None


def test_an_unknown_prescription_name_is_an_input_error_naming_close_ones() -> None:
    with pytest.raises(InputError) as caught:
        equipment.lens_data(prescription="dgauss10", database=load_db)
    assert caught.value.param == "prescription" and "did you mean" in str(caught.value)


def test_focus_forward_by_magnification_is_unit_focusing() -> None:
    # m = 0.5, f = 100: v = f(1 + m) = 150, u = f(1 + 1/m) = 300, from the sensor u + v = 450
    found = focus.forward(focal_length_mm=100.0, wanted=0.5, by_magnification=True, f_number=8.0)
    assert found.values is not None and not found.planned
    assert math.isclose(found.values["image_distance_mm"], 150.0) and math.isclose(found.values["distance_mm"], 450.0)
    assert math.isclose(found.values["working_f_number"], 12.0)


def test_focus_forward_from_the_sensor_names_the_other_magnification() -> None:
    # u + v = s from the sensor has the two roots m and 1/m (unit focusing, no hiatus)
    found = focus.forward(focal_length_mm=100.0, wanted=450.0, by_magnification=False)
    assert found.values is not None
    (m,), (other,) = [found.values["magnification"]], found.values["other_magnification"]
    assert math.isclose(float(m), 0.5, rel_tol=1e-12) and math.isclose(other, 2.0, rel_tol=1e-12)


def test_focus_inverse_without_an_f_number_focuses_at_the_harmonic_mean() -> None:
    found = focus.inverse(focal_length_mm=35.0, near_mm=2000.0, far_mm=10000.0, coc_mm=0.03, distance_from="lens")
    assert not found.fixed
    assert math.isclose(found.values["distance_mm"], 2 * 2000.0 * 10000.0 / 12000.0, rel_tol=1e-9)


def test_focus_depth_inverts_the_close_up_depth_formula() -> None:
    # depth = 2·N·c·(1 + m/P)/m²: 2 · 4 · c · 3.5 / 6.25 = 0.2 mm gives c = 0.2 · 6.25 / 28
    by_n = focus.depth(magnification=2.5, depth_mm=0.2, f_number=4.0)
    assert math.isclose(by_n["coc_mm"], 0.2 * 6.25 / 28.0, rel_tol=1e-12)
    by_c = focus.depth(magnification=2.5, depth_mm=0.2, coc_mm=by_n["coc_mm"])
    assert math.isclose(by_c["f_number"], 4.0, rel_tol=1e-12)


def test_field_of_view_at_infinity_and_by_magnification() -> None:
    far = field_of_view(focal_length_mm=50.0, sensor_width_mm=36.0, sensor_height_mm=24.0, crop_factor=1.0)
    assert not far.at_distance
    assert math.isclose(far.values["horizontal_deg"], math.degrees(2 * math.atan(18.0 / 50.0)), rel_tol=1e-12)
    near = field_of_view(focal_length_mm=100.0, sensor_width_mm=36.0, sensor_height_mm=24.0, crop_factor=1.0,
                         wanted=0.5, by_magnification=True)
    assert near.at_distance and math.isclose(near.values["field_width_mm"], 72.0, rel_tol=1e-12)  # 36 / m


def test_compose_places_the_camera_at_f_times_one_plus_one_over_m() -> None:
    chosen = compose.lenses(focal_lengths_mm=[50.0], f_numbers=[4.0], teleconverter=1.4)
    assert chosen.focal_lengths_mm == [70.0] and math.isclose(chosen.f_numbers[0], 5.6, rel_tol=1e-15)
    assert compose.lenses(focal_lengths_mm=[], f_numbers=[], teleconverter=2.0).focal_lengths_mm[0] == 24.0
    row = compose.compose(focal_length_mm=70.0, magnification=0.1, sensor_width_mm=36.0, sensor_height_mm=24.0,
                          reference_focal_length_mm=70.0, distance_from="lens")
    assert math.isclose(row["distance_mm"], 770.0, rel_tol=1e-12)
    assert math.isclose(row["field_width_mm"], 360.0, rel_tol=1e-12)


def test_compose_refuses_a_foreground_beyond_the_front_focal_point() -> None:
    from camtool.core.errors import DomainError

    # 100 mm at 1:10: the subject is 1100 mm from the lens, its front focal point 1000 mm from the subject
    with pytest.raises(DomainError) as caught:
        compose.compose(focal_length_mm=100.0, magnification=0.1, sensor_width_mm=36.0, sensor_height_mm=24.0,
                        reference_focal_length_mm=100.0, f_number=8.0, coc_mm=0.03, foreground_mm=1500.0)
    assert caught.value.param == "foreground_mm" and caught.value.value == 1500.0
