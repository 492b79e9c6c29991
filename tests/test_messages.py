"""Errors name what the user typed, and say what they need: a decimal comma, a unit apart from its number, a near-miss
choice, a bad CAMTOOL_FORMAT, an option left at its default, Ctrl-C."""

from __future__ import annotations

import os
import signal
import subprocess
import sys
import time

import pytest
from cli_helpers import run, time_bound  # noqa: F401


def _one_line_error(result, code: int = 2) -> str:
    assert result.exit_code == code, result.output
    assert result.stderr.count("\n") == 1 and result.stderr.startswith("Error: "), result.stderr
    return result.stderr


@pytest.mark.parametrize(("value", "reading"), [("2,8", "f/2.8"), ("5,6", "f/5.6"), ("1,4", "f/1.4"), ("4,5", "f/4.5")])
def test_a_decimal_comma_f_number_is_an_error_with_both_readings(value: str, reading: str) -> None:
    message = _one_line_error(run("dof", "-f", "50", "-s", "3m", "-N", value))
    first, second = value.split(",")
    assert reading in message and f"f{first},f{second}" in message and "-N" in message


@pytest.mark.parametrize("value", ["8,11", "2.8,4", "f2,f8", "1.4,2,2.8", "16,22"])
def test_lists_that_cannot_be_a_decimal_comma_stay_lists(value: str) -> None:
    result = run("dof", "-f", "50", "-s", "3m", "-N", value, "--format", "csv")
    assert result.exit_code == 0, result.output
    assert len(result.stdout.splitlines()) == 1 + len(value.split(","))


def test_the_written_alternatives_give_what_they_say() -> None:
    # the message's two spellings are the two readings: one row at f/2.8, or rows at f/2 and f/8
    one = run("dof", "-f", "50", "-s", "3m", "-N", "2.8", "--field", "f_number")
    two = run("dof", "-f", "50", "-s", "3m", "-N", "f2,f8", "--field", "f_number")
    assert one.stdout.split() == ["2.8"] and two.stdout.split() == ["2.0", "8.0"]


@pytest.mark.parametrize("value", ["3,5ft", "1,5m"])
def test_a_decimal_comma_length_with_a_unit_is_an_error(value: str) -> None:
    message = _one_line_error(run("dof", "-f", "50", "-N", "8", "-s", value))
    assert "ambiguous" in message and "-s" in message


def test_a_unit_apart_from_its_number_gets_a_hint() -> None:
    message = _one_line_error(run("dof", "-f", "50", "-N", "8", "-s", "3", "m"))
    assert "one word" in message and "3m" in message


@pytest.mark.parametrize(("option", "value", "meant"), [("--model", "thn", "thin"), ("--units", "feet", "imperial"),
                                                        ("--format", "jsn", "json")])
def test_a_near_miss_choice_gets_a_suggestion(option: str, value: str, meant: str) -> None:
    message = _one_line_error(run("dof", "-f", "50", "-N", "8", "-s", "3m", option, value))
    assert f"Did you mean '{meant}'" in message and option in message


def test_a_bad_camtool_format_is_named_as_the_variable_not_as_an_option() -> None:
    message = _one_line_error(run("dof", "-f", "50", "-N", "8", "-s", "3m", env={"CAMTOOL_FORMAT": "garbage"}))
    assert "CAMTOOL_FORMAT='garbage'" in message and "Invalid value for '--format'" not in message
    assert run("dof", "-f", "50", "-N", "8", "-s", "3m", "--format", "json",
               env={"CAMTOOL_FORMAT": "garbage"}).exit_code == 0


def test_an_option_at_its_default_is_not_blamed_the_one_typed_is() -> None:
    for command in (["hyperfocal", "-f", "50", "-N", "8"], ["dof", "-f", "50", "-N", "8", "-s", "3m", "--model", "thick"]):
        message = _one_line_error(run(*command, "--pupil-mag", "0.4"))
        assert "'--pupil-mag'" in message and "--hiatus at its default" in message


def test_an_error_quoting_a_control_character_prints_it_escaped() -> None:
    message = _one_line_error(run("dof", "-f", "50", "-N", "8", "-s", "3m", "--model", "thin\x1b[2J"))
    assert "\x1b" not in message and "\\x1b[2J" in message


def test_ctrl_c_during_a_batch_is_one_line_and_exit_130(tmp_path) -> None:
    scenes = tmp_path / "scenes.csv"
    scenes.write_text("focal-length,f-number,distance\n" + "50,8,3m\n" * 2_000_000)
    process = subprocess.Popen([sys.executable, "-m", "camtool", "dof", "--batch", os.fspath(scenes), "--format", "json",
                                "--units", "metric"], stdout=subprocess.DEVNULL,
                               stderr=subprocess.PIPE, text=True)
    time.sleep(2.0)
    process.send_signal(signal.SIGINT)
    _, stderr = process.communicate(timeout=30)
    assert process.returncode == 130 and stderr == "camtool: interrupted\n", stderr


def test_a_teleconverter_behind_a_prescription_lens_is_answered_by_the_rungs_that_do_not_trace_it() -> None:
    answered = run("dof", "--lens", "dgauss100-lens", "-N", "4", "-s", "inf", "--teleconverter", "1.4",
                   "--format", "json")
    assert answered.exit_code == 0, answered.output
    message = _one_line_error(run("dof", "--lens", "dgauss100-lens", "-N", "4", "-s", "3m", "--teleconverter", "1.4",
                                  "--model", "raytrace"))
    assert "'--teleconverter'" in message and "raytrace" in message


def test_an_unreachable_focus_from_an_extension_names_the_extension() -> None:
    message = _one_line_error(run("dof", "--lens", "cellphone-lens", "-N", "8", "-s", "inf", "--extension", "12"))
    assert "'--extension'" in message


def test_a_hinge_no_tilt_reaches_names_the_hinge_that_was_typed() -> None:
    # J = f/sin θ (Merklinger): a hinge at the focal length needs θ = 90°, which no lens tilts
    message = _one_line_error(run("tilt", "-f", "24", "-N", "8", "--hinge", "24mm", "-s", "3"))
    assert "'--hinge'" in message and "'--tilt'" not in message


@pytest.mark.parametrize(("args", "option"), [(["--to-crop", "0"], "'--to-crop'"), (["--to-sensor", "nosuch"], "'--to-sensor'")])
def test_equiv_names_the_target_option_typed_not_the_source_one(args: list[str], option: str) -> None:
    message = _one_line_error(run("equiv", "-f", "25", "-N", "1.4", "--sensor", "m43", *args))
    assert option in message and "'--crop'" not in message and "'--sensor'" not in message


def test_a_solved_setting_out_of_range_names_what_was_typed() -> None:
    message = _one_line_error(run("exposure", "-N", "16", "-t", "1/125", "--illuminance", "1e9"))
    assert "'--illuminance'" in message and "'--iso'" not in message


def test_a_scene_s_value_a_lens_refuses_names_the_scene() -> None:
    message = _one_line_error(run("fov", "--lens", "apple-iphone-15-pro-main", "--scene", "landscape-24"))
    assert "'--scene'" in message and "'-f'" not in message


def test_a_batch_file_that_is_a_device_is_refused_at_once(tmp_path) -> None:
    (tmp_path / "zero.csv").symlink_to("/dev/zero")
    result = run("equiv", "--batch", str(tmp_path / "zero.csv"))
    assert result.exit_code == 1 and result.stderr.count("\n") == 1 and "device" in result.stderr


def test_an_unknown_field_is_refused_before_any_work(tmp_path) -> None:
    message = _one_line_error(run("dof", "-f", "50", "-N", "8", "-s", "3m", "--field", "nope"))
    assert "'--field'" in message


def test_a_fifo_nobody_writes_to_is_an_empty_batch_not_a_hang(tmp_path) -> None:
    import os

    fifo = tmp_path / "scenes.csv"
    os.mkfifo(fifo)
    result = run("fov", "-f", "50", "--batch", str(fifo), "--format", "json")
    assert result.exit_code == 0 and result.stdout == "[]\n"


def test_stack_auto_is_the_ladder_s_auto() -> None:
    # a hiatus of 0 is the thin lens's own: auto needs no thick data for it (it asked for --model thick, not typed)
    result = run("stack", "-f", "100", "-N", "8", "--near", "1m", "--far", "3m", "--hiatus", "0")
    assert result.exit_code == 0 and "thin model" in result.stdout, result.output


def test_a_list_where_one_value_applies_to_every_row_names_the_option() -> None:
    message = _one_line_error(run("flash", "--gn", "20", "-s", "5", "--iso", "100", "--gn-iso", "100,200"))
    assert "'--gn-iso'" in message


def test_a_prescription_is_the_lens_beside_a_camera_with_a_lens_of_its_own() -> None:
    result = run("dof", "--prescription", "nikon-z50-f1.8", "--camera", "apple-iphone-15-pro", "-N", "4", "-s", "3m",
                 "--format", "json")
    assert result.exit_code == 0, result.output


def test_a_scene_s_value_a_prescription_refuses_names_the_scene() -> None:
    message = _one_line_error(run("dof", "--scene", "landscape-24", "--prescription", "dgauss100", "--format", "json"))
    assert "'--scene'" in message and "'--model'" not in message


def test_a_flash_answer_beyond_the_largest_float_is_one_line() -> None:
    message = _one_line_error(run("flash", "--gn", "20", "--iso", "100", "-s", "10ft,1e-320m"))
    assert "'-s'" in message


def test_a_scene_with_a_camera_beside_a_typed_camera_does_not_look_its_sensor_up() -> None:
    result = run("dof", "--camera", "nikon-z-8", "--scene", "macro-1to1", "--format", "json")
    assert result.exit_code in (0, 2) and "unknown sensor" not in result.stderr, result.output


def test_a_crop_that_gives_too_small_a_coc_names_the_crop() -> None:
    message = _one_line_error(run("dof", "-f", "24", "-N", "8", "-s", "3m", "--crop", "100"))
    assert "'--crop'" in message and "'--sensor'" not in message


def test_a_very_long_list_item_is_a_range_error_not_a_decimal_comma_crash() -> None:
    message = _one_line_error(run("dof", "-f", "35", "-s", "3m", "-N", "5" * 400 + ",5"))
    assert "'-N'" in message
