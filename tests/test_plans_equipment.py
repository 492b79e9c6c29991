"""camtool.plans.equipment called directly: keyword arguments, named results, the precedence rules written once."""

from __future__ import annotations

import math

import pytest
from cli_helpers import run, run_json, time_bound  # noqa: F401

from camtool.core.errors import DomainError, InputError
from camtool.plans import equipment
from camtool.presets import PresetNotFound, load_db

DB = load_db


def test_crop_gives_the_full_frame_sides_divided() -> None:
    choice = equipment.resolve_sensor(crop=1.5, database=DB)
    assert (choice.width_mm, choice.height_mm) == (24.0, 16.0)
    assert math.isclose(choice.crop_factor, 1.5)


def test_sensor_and_crop_together_is_a_usage_error_naming_both() -> None:
    with pytest.raises(InputError) as caught:
        equipment.resolve_sensor(sensor="aps-c", crop=1.5, database=DB)
    assert caught.value.usage and caught.value.render(lambda n: f"--{n}") == "give --sensor or --crop, not both"


def test_a_crop_outside_its_range_is_a_domain_error_on_crop() -> None:
    with pytest.raises(DomainError) as caught:
        equipment.resolve_sensor(crop=1000.0, database=DB)
    assert caught.value.param == "crop"


def test_a_phone_lens_keeps_its_own_format_beside_a_camera_and_the_camera_its_sensor_otherwise() -> None:
    db = DB()
    phone = db.lens("apple-iphone-16-pro-ultra-wide")
    body = db.camera("sony-a7-iv")
    own = equipment.resolve_sensor(camera=body, lens=phone, database=DB)
    assert "the lens's own format" in own.label and own.width_mm < 36
    on_body = equipment.resolve_sensor(camera=body, lens=db.lens("sony-fe-24-70mm-f2.8-gm-ii"), database=DB)
    assert (on_body.width_mm, on_body.height_mm) == (body.sensor.width_mm, body.sensor.height_mm)


def test_coc_precedence_coc_then_rule_then_preset_then_d1500() -> None:
    sensor = equipment.SensorChoice(36.0, 24.0, "x", coc_mm=0.029)
    assert equipment.resolve_coc(coc=[0.02], coc_rule="d/1730", sensor=sensor).coc_mm == [0.02]
    by_rule = equipment.resolve_coc(coc_rule="d/1730", sensor=sensor)
    assert math.isclose(by_rule.coc_mm[0], math.hypot(36, 24) / 1730)  # the rule's definition
    assert equipment.resolve_coc(sensor=sensor).coc_mm == [0.029]
    plain = equipment.resolve_coc(sensor=equipment.FULL_FRAME)
    assert math.isclose(plain.coc_mm[0], math.hypot(36, 24) / 1500)


def test_a_px_rule_without_a_pitch_is_an_input_error_on_the_rule() -> None:
    with pytest.raises(InputError) as caught:
        equipment.resolve_coc(coc_rule="px:2", sensor=equipment.FULL_FRAME)
    assert caught.value.param == "coc_rule"


def test_an_unknown_lens_names_the_lens_input() -> None:
    with pytest.raises(PresetNotFound) as caught:
        equipment.resolve_equipment(lens="no-such-lens", database=DB)
    assert caught.value.param == "lens"


def test_a_scene_fills_only_what_is_empty() -> None:
    db = DB()
    scene = db.all("scene")[0]
    found = equipment.resolve_equipment(scene=scene.id, empty=["f_number"], sensor_given=True, database=DB)
    assert set(found.filled) <= {"f_number"}


def test_a_fixed_aperture_lens_brings_its_f_number_and_a_prime_its_focal_length() -> None:
    db = DB()
    phone = db.lens("apple-iphone-16-pro-main")
    assert equipment.lens_defaults(phone, focal_lengths=[], f_numbers=[]) == {
        "focal_length": phone.focal_min_mm, "f_number": 1.78}  # Apple's published f/1.78
    zoom = db.lens("nikon-z-24-70mm-f4-s")
    with pytest.raises(InputError) as caught:
        equipment.lens_defaults(zoom, focal_lengths=[], f_numbers=[8.0])
    assert caught.value.usage and caught.value.param == "focal_length"
    assert equipment.lens_defaults(db.lens("nikon-z-24mm-f1.8-s"), focal_lengths=[], f_numbers=[]) == {"focal_length": 24.0}


def test_every_phone_module_needs_neither_f_nor_n_on_the_command_line() -> None:
    db = DB()
    for lens in db.all("lens"):
        if lens.category != "phone" or lens.prescription is not None:  # a textbook design, not a phone's module
            continue
        if lens.f_number_min is None:
            # a module whose aperture no launch page gives (the Vivo X200 Ultra's) needs -N, and says so in one line
            refused = run("dof", "--lens", lens.id, "-s", "2m")
            assert refused.exit_code == 2 and "Missing option '-N'" in refused.output, lens.id
            (row,) = run_json("dof", "--lens", lens.id, "-s", "2m", "-N", "2.8")
            assert math.isclose(row["focal_length_mm"], lens.focal_min_mm) and row["f_number"] == 2.8
            continue
        (row,) = run_json("dof", "--lens", lens.id, "-s", "2m")
        assert math.isclose(row["focal_length_mm"], lens.focal_min_mm) and math.isclose(row["f_number"], lens.f_number_min)


def test_a_built_in_lens_with_a_range_of_apertures_answers_wide_open() -> None:
    db = DB()
    q3 = db.lens("leica-summilux-28mm-f1.7-asph-q3")  # Leica: Summilux 28 f/1.7 ASPH., built in
    assert equipment.lens_defaults(q3, focal_lengths=[], f_numbers=[]) == {"focal_length": 28.0, "f_number": 1.7}
    interchangeable = db.lens("nikon-z-24mm-f1.8-s")
    assert "f_number" not in equipment.lens_defaults(interchangeable, focal_lengths=[], f_numbers=[])


DOF_INPUTS = {"focal_length": [], "f_number": [], "distance": [], "coc": [], "magnification": [], "sensor": None,
              "distance_from": "sensor", "hiatus": None, "pupil_mag": None, "prescription_file": None}


def test_apply_equipment_fills_from_the_scene_then_the_lens_in_that_order() -> None:
    found = equipment.apply_equipment(scene="portrait-85", camera=None, lens=None, inputs=dict(DOF_INPUTS), database=DB)
    assert found.values == {"f_number": 1.8, "distance": 2000.0, "focal_length": 85.0}  # the scene's, then the lens's f
    assert (found.camera.id, found.lens.id, found.sensor) == ("sony-a7-iv", "sony-fe-85mm-f1.8", None)
    typed = equipment.apply_equipment(scene="portrait-85", camera=None, lens=None, database=DB,
                                      inputs={**DOF_INPUTS, "f_number": [4.0], "distance": [3000.0]})
    assert typed.values == {"focal_length": 85.0}  # a value typed is never filled over


def test_apply_equipment_says_when_the_value_a_lens_refuses_came_from_the_scene() -> None:
    with pytest.raises(InputError) as caught:  # the scene's f/1.8 on an f/4 zoom
        equipment.apply_equipment(scene="portrait-85", camera=None, lens="nikon-z-24-70mm-f4-s", database=DB,
                                  inputs={**DOF_INPUTS, "focal_length": [50.0]})
    assert (caught.value.param, getattr(caught.value, "scene", None)) == ("f_number", "portrait-85")
    with pytest.raises(InputError) as typed:
        equipment.apply_equipment(scene=None, camera=None, lens="nikon-z-24-70mm-f4-s", database=DB,
                                  inputs={**DOF_INPUTS, "focal_length": [50.0], "f_number": [1.8]})
    assert (typed.value.param, getattr(typed.value, "scene", None)) == ("f_number", None)
    with pytest.raises(InputError) as hiatus:  # checked against the focal length the lens brought
        equipment.apply_equipment(scene=None, camera=None, lens="nikon-z-24mm-f1.8-s", database=DB,
                                  inputs={**DOF_INPUTS, "hiatus": -1000.0})
    assert hiatus.value.param == "hiatus"
