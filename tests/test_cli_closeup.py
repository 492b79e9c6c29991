"""Close-up and macro on the command line: the commands of issue 12 give the right answers.

Expected values come from the library functions that tests/test_closeup.py checks against
published figures and mpmath, from Canon's published MP-E 65 figures, or from identities.
"""

from __future__ import annotations

import json
import math
from pathlib import Path

import pytest
from cli_helpers import run, run_json
from click.testing import CliRunner

from camtool.cli import cli
from camtool.dof.closeup import (
    closeup_dof,
    coc_for_depth,
    f_number_for_depth,
    optimum_aperture,
    optimum_for_limits,
    wave_depth_mm,
)

FF_COC = math.hypot(36.0, 24.0) / 1500.0  # the default CoC: full-frame diagonal / 1500


def test_dof_at_a_magnification():
    (row,) = run_json("dof", "-f", "100", "-m", "1", "-N", "8")
    exact = closeup_dof(100.0, 8.0, FF_COC, 1.0)
    assert row["magnification"] == 1.0 and row["working_f_number"] == 16.0
    assert row["distance_mm"] == pytest.approx(400.0, rel=1e-15)
    assert row["total_mm"] == pytest.approx(exact.total_mm, rel=1e-12)
    assert row["near_mm"] == pytest.approx(exact.near_mm, rel=1e-13)


def test_magnification_list_gives_a_row_each():
    rows = run_json("dof", "-f", "100", "-N", "8", "-m", "0.5,1,2,5,20")
    assert [r["magnification"] for r in rows] == [0.5, 1.0, 2.0, 5.0, 20.0]
    for r in rows:
        assert r["total_mm"] == pytest.approx(closeup_dof(100.0, 8.0, FF_COC, r["magnification"]).total_mm, rel=1e-11)


def test_lens_plane_distance_between_f_and_2f_is_5_to_1():
    (row,) = run_json("dof", "-f", "65", "-N", "2.8", "-s", "78mm", "--distance-from", "lens")
    assert row["magnification"] == pytest.approx(5.0, rel=1e-13)
    exact = closeup_dof(65.0, 2.8, FF_COC, 5.0, distance_from="lens")
    assert row["near_mm"] == pytest.approx(exact.near_mm, rel=1e-13)
    assert row["total_mm"] == pytest.approx(exact.total_mm, rel=1e-10)


def test_sensor_distance_takes_m_below_1_and_names_the_other_branch():
    (focused,) = run_json("focus", "-f", "65", "-m", "3")
    assert focused["distance_mm"] == pytest.approx(65.0 * 16.0 / 3.0, rel=1e-15)
    (row,) = run_json("dof", "-f", "65", "-N", "2.8", "-s", "346.67mm")
    assert row["magnification"] == pytest.approx(1.0 / 3.0, rel=1e-4)
    assert row["other_magnification"] == pytest.approx(3.0, rel=1e-4)
    assert round(row["total_mm"], 2) == 1.94
    table = run("dof", "-f", "65", "-N", "2.8", "-s", "346.67mm").stdout
    assert "also reached at m = 3" in table and "working N" in table
    (high,) = run_json("dof", "-f", "65", "-N", "2.8", "-m", "3")
    assert round(high["total_mm"], 2) == 0.07


def test_compose_magnification_2_has_the_depth_of_2_to_1():
    (row,) = run_json("compose", "--magnification", "2", "-f", "65", "-N", "8")
    assert row["magnification"] == 2.0
    assert round(row["far_mm"] - row["near_mm"], 2) == 0.35


def test_macro_presets_focus_to_their_published_closest_focus():
    # Canon EF 100mm f/2.8L Macro IS USM: closest focus 0.30 m, 1.0x (lens_db source)
    (row,) = run_json("dof", "--lens", "ef-100-macro-l", "-N", "8", "-s", "300mm")
    assert row["magnification"] == pytest.approx(1.0, rel=0.02)
    assert row["focal_length_mm"] == 100.0 and row["focal_length_at_focus_mm"] < 100.0
    closer = run("dof", "--lens", "ef-100-macro-l", "-N", "8", "-s", "280mm")
    assert closer.exit_code == 2 and closer.stderr.count("\n") == 1 and "0.3 m" in closer.stderr


def test_wide_angle_preset_reaches_its_published_magnification():
    # Canon TS-E 24mm f/3.5L II: closest focus 0.21 m, max. magnification 0.34x (lens_db source); its model
    # is unit focusing with an effective hiatus (docs/closeup.md §2), and all commands place 0.34x at 0.21 m
    lens = "canon-ts-e-24mm-f3.5l-ii"
    (row,) = run_json("dof", "--lens", lens, "-N", "8", "-s", "0.21m")
    assert row["magnification"] == pytest.approx(0.34, rel=1e-12)
    assert row["near_mm"] < 210.0 < row["far_mm"]
    for command in ("focus", "fov"):
        (row,) = run_json(command, "--lens", lens, "-m", "0.34")
        assert row["distance_mm"] == pytest.approx(210.0, rel=1e-12)


def test_shipped_macro_scene_runs_at_life_size():
    (row,) = run_json("dof", "--scene", "macro")
    assert row["magnification"] == pytest.approx(1.0, rel=1e-12)
    assert row["f_number"] == 8.0


def test_mp_e_65_published_distance_and_range():
    # Canon MP-E 65mm f/2.8 1-5x Macro Photo (Wikipedia's infobox): 1x to 5x; 240 mm at 1x, 313 mm at 5x
    (row,) = run_json("focus", "--lens", "mp-e-65", "-m", "5")
    assert row["distance_mm"] == pytest.approx(313.0, rel=1e-12)
    (row,) = run_json("focus", "--lens", "mp-e-65", "-m", "1")
    assert row["distance_mm"] == pytest.approx(240.0, rel=1e-12)
    for args, option in ((["-s", "1m"], "'-s' / '--distance'"), (["-m", "6"], "'-m' / '--magnification'"),
                         (["-m", "0.5"], "'-m' / '--magnification'")):
        result = run("focus", "--lens", "mp-e-65", *args)
        assert result.exit_code == 2 and result.stdout == ""
        assert result.stderr.startswith(f"Error: Invalid value for {option}") and "1× to 5×" in result.stderr
        assert result.stderr.count("\n") == 1


def test_diffraction_per_row_keeps_the_sharp_row():
    # 1:1: f/5.6 works at f/11.2 (Airy 0.015 mm, below c/√2: root-sum-square); f/22 at f/44 misses even the
    # contrast criterion the wave rung would use (in focus, below f/18.3 at 1:1)
    result = run("dof", "-f", "100", "-N", "5.6,22", "-s", "400mm", "--diffraction", "--format", "json")
    assert result.exit_code == 0
    sharp, blurred = json.loads(result.stdout)
    for row in (sharp, blurred):
        assert row["airy_mm"] == pytest.approx(2.44 * 550e-6 * row["working_f_number"], rel=1e-12)
        assert row["diffraction_limit_f_number"] == pytest.approx(FF_COC / (2.44 * 550e-6 * 2.0), rel=1e-12)
        assert row["wave_dof_mm"] == pytest.approx(wave_depth_mm(row["f_number"], 1.0), rel=1e-9)
    assert sharp["near_mm"] is not None and sharp["reason"] is None and sharp["model"].endswith("+diffraction")
    assert blurred["near_mm"] is None and blurred["total_mm"] is None and "contrast" in blurred["reason"]
    assert sharp["depth_dominated_by"] == "geometric" and blurred["depth_dominated_by"] == "wave"
    table = run("dof", "-f", "100", "-N", "5.6,22", "-s", "400mm", "--diffraction")
    assert table.exit_code == 0 and "nothing sharp" in table.stdout


def test_diffraction_with_no_sharp_row_is_an_error():
    result = run("dof", "-f", "100", "-N", "22", "-m", "2", "--diffraction")
    assert result.exit_code == 2 and result.stdout == "" and result.stderr.count("\n") == 1
    assert "nothing is sharp enough" in result.stderr  # auto: by contrast (docs/wave.md)
    result = run("dof", "-f", "100", "-N", "22", "-m", "2", "--diffraction", "--model", "thin")
    assert result.exit_code == 2 and result.stdout == "" and result.stderr.count("\n") == 1
    assert "Airy disc" in result.stderr


def test_optimum_aperture_from_near_and_far():
    (row,) = run_json("focus", "-f", "150", "--near", "2m", "--far", "inf", "--optimum")
    expected = optimum_for_limits(150.0, 2000.0, math.inf)
    assert row["f_number"] == pytest.approx(expected.optimum.f_number, rel=1e-14)
    assert row["blur_mm"] == pytest.approx(expected.optimum.blur_mm, rel=1e-14)
    assert row["focus_spread_mm"] == pytest.approx(expected.focus_spread_mm, rel=1e-14)


def test_optimum_aperture_from_focus_spread():
    rows = run_json("focus", "--focus-spread", "1mm,3mm", "--optimum")
    assert [round(r["f_number"], 1) for r in rows] == [19.3, 33.4]
    (close,) = run_json("focus", "--focus-spread", "3mm", "-m", "1", "--optimum")
    assert close["f_number"] == pytest.approx(optimum_aperture(3.0).f_number / 2.0, rel=1e-14)


def test_inverse_close_up_depth():
    (row,) = run_json("focus", "-m", "2.5", "--depth", "0.2mm", "-N", "4")
    assert row["coc_mm"] == pytest.approx(coc_for_depth(4.0, 2.5, 0.2), rel=1e-15)
    (row,) = run_json("focus", "-m", "2.5", "--depth", "0.2mm", "--coc", "0.03")
    assert row["f_number"] == pytest.approx(f_number_for_depth(0.03, 2.5, 0.2), rel=1e-15)
    both = run("focus", "-m", "2.5", "--depth", "0.2mm")
    assert both.exit_code == 2


def test_extension_and_teleconverter():
    # at infinity a 25 mm tube behind a 100 mm lens gives m = 25/100
    (row,) = run_json("focus", "-f", "100", "-s", "inf", "--extension", "25mm")
    assert row["magnification"] == pytest.approx(0.25, rel=1e-15)
    (row,) = run_json("dof", "-f", "100", "-N", "4", "-m", "1", "--teleconverter", "1.4")
    assert row["focal_length_mm"] == pytest.approx(140.0) and row["f_number"] == pytest.approx(5.6)
    assert row["total_mm"] == pytest.approx(closeup_dof(140.0, 5.6, FF_COC, 1.0).total_mm, rel=1e-11)
    short = run("dof", "-f", "100", "-N", "8", "-m", "0.1", "--extension", "25mm")
    assert short.exit_code == 2 and "0.25" in short.stderr


def test_fov_at_a_magnification():
    (row,) = run_json("fov", "-f", "100", "-m", "1")
    assert row["field_width_mm"] == pytest.approx(36.0, rel=1e-14)
    assert row["distance_mm"] == pytest.approx(400.0, rel=1e-15)


def test_batch_magnification_column():
    text = "focal-length,f-number,magnification\n100,8,1\n65,2.8,5\n"
    result = CliRunner().invoke(cli, ["dof", "--format", "json", "--batch", "-"], input=text, env={"COLUMNS": None})
    assert result.exit_code == 0, result.output
    rows = json.loads(result.stdout)
    assert [r["magnification"] for r in rows] == [1.0, 5.0]
    assert rows[1]["total_mm"] == pytest.approx(closeup_dof(65.0, 2.8, FF_COC, 5.0).total_mm, rel=1e-11)


def _examples(text: str) -> list[list[str]]:
    import shlex

    lines = []
    for line in text.splitlines():
        line = line.split("  #")[0].strip()
        if line.startswith("camtool ") and "FILE" not in line and ".yaml" not in line and ".csv" not in line:
            lines.append(shlex.split(line)[1:])
    return lines


def test_readme_close_up_examples_run():
    from pathlib import Path

    readme = (Path(__file__).parent.parent / "README.md").read_text(encoding="utf-8")
    section = readme.split("### Close-up and macro", 1)[1].split("```", 2)[1]
    examples = _examples(section)
    assert len(examples) >= 8
    for args in examples:
        result = run(*args)
        assert result.exit_code == 0, (args, result.output)


@pytest.mark.parametrize("command", ["dof", "focus", "fov", "compose"])
def test_help_examples_run(command):
    help_text = run(command, "--help").stdout
    examples = [args for args in _examples(help_text.split("Examples:", 1)[1]) if args[0] == command]
    assert examples
    for args in examples:
        result = run(*args)
        assert result.exit_code == 0, (args, result.output)


def test_teleconverter_in_hyperfocal_and_compose():
    # the lens with a K× converter is the lens K·f at K·N (docs/closeup.md §7): the same rows as typing those
    assert run_json("hyperfocal", "-f", "300", "-N", "4", "--teleconverter", "1.4") == \
        run_json("hyperfocal", "-f", "420", "-N", "5.6")
    assert run_json("compose", "-m", "1", "-f", "100", "-N", "8", "--teleconverter", "2") == \
        run_json("compose", "-m", "1", "-f", "200", "-N", "16")


def test_a_magnification_beyond_the_ray_traces_closest_focus_blames_dash_m() -> None:
    # dgauss100 (f = 100.0038 mm) is traced by unit focusing down to 1:1: its closest focus from H
    # is 2f = 200.008 mm (tests/data/oracle-README.md), so m = 2 is out of the raytrace model's range.
    prescription = str(Path(__file__).parent / "data" / "prescriptions" / "dgauss100.yaml")
    result = CliRunner().invoke(cli, ["dof", "--prescription", prescription, "-m", "0.5,2", "-N", "8",
                                      "--model", "raytrace"])
    assert result.exit_code == 2
    lines = result.output.strip().splitlines()
    assert len(lines) == 1
    assert "'-m' / '--magnification': 2 is outside the valid range" in lines[0]
    assert "200 mm from the lens here, m ≤ 1" in lines[0]


def test_diffraction_answers_each_row_of_a_prescription_too() -> None:
    # dgauss100 at 1 m: f/8 is sharp; at f/64 the Airy disc 2.44·λ·N_w (0.095 mm at 550 nm) fills the
    # full-frame CoC (0.0288 mm), so that row has null limits and a reason while the f/8 row prints
    prescription = str(Path(__file__).parent / "data" / "prescriptions" / "dgauss100.yaml")
    result = CliRunner().invoke(cli, ["dof", "--prescription", prescription, "-N", "8,64", "-s", "1m",
                                      "--diffraction", "--format", "json"])
    assert result.exit_code == 0
    sharp, blurred = json.loads(result.output)
    assert sharp["distance_mm"] == 1000.0 and sharp["near_mm"] < 1000.0 < sharp["far_mm"]
    assert blurred["near_mm"] is None and blurred["far_mm"] is None and "nothing sharp" in blurred["reason"]
    assert sharp["model"].endswith("+diffraction")


def test_the_other_branch_is_named_once_per_magnification() -> None:
    result = CliRunner().invoke(cli, ["dof", "-f", "100", "-N", "8,11", "-s", "1m", "--diffraction"],
                                env={"COLUMNS": None})  # the table as wide as it needs, whatever the caller's terminal
    assert result.exit_code == 0
    footer = result.stdout.strip().splitlines()[-1]
    assert footer.count("7.87") == 1


def test_extension_has_a_physical_range() -> None:
    result = CliRunner().invoke(cli, ["dof", "-f", "50", "-N", "8", "-s", "3m", "--extension", "1e17M"])
    assert result.exit_code == 2
    assert result.output.strip().splitlines()[-1] == (
        "Error: Invalid value for '--extension': 1e17M is outside the valid range: > 0 to 10000 mm")


def test_a_focusing_lens_preset_answers_a_list_with_infinity_row_by_row() -> None:
    # the EF 100 L focuses internally; at infinity it is its own 100 mm at m = 0, 2·atan(18/100) = 20.41°
    rows = json.loads(CliRunner().invoke(cli, ["fov", "--lens", "ef-100-macro-l", "-s", "1m,inf",
                                               "--format", "json"]).output)
    assert [r["distance_mm"] for r in rows] == [1000.0, None]
    assert rows[1]["magnification"] == 0.0
    assert math.isclose(rows[1]["horizontal_deg"], 2 * math.degrees(math.atan(18 / 100)), rel_tol=1e-12)
    assert 0 < rows[0]["magnification"] < 1
    scene = CliRunner().invoke(cli, ["fov", "--scene", "landscape-24", "-s", "inf", "--format", "json"])
    assert scene.exit_code == 0 and json.loads(scene.output)[0]["magnification"] == 0.0


@pytest.mark.parametrize("args", [
    ["-f", "100", "-N", "8", "-m", "0.5,1"],
    ["--lens", "ef-100-macro-l", "-N", "8", "-s", "0.5m", "--pupil-mag", "0.6"],
    ["-N", "8", "-m", "0.5", "--prescription", "tests/data/prescriptions/dgauss100.yaml"],
])
def test_model_all_close_up_is_every_model_on_its_own(args):
    # --model all with -m or a focusing lens: one row per scene and rung, the most complete rung last; each
    # row is what `--model <that rung>` gives alone, and its difference is the vergence error against the last
    # (camtool.dof.auto.depth_error, recomputed here from the single-model rows)
    rows = run_json("dof", *args, "--model", "all")
    models = list(dict.fromkeys(row["model"] for row in rows))
    assert models[-1] in ("thin", "thick", "raytrace") and len(rows) % len(models) == 0
    alone = {model: run_json("dof", *args, "--model", model) for model in models}
    for i, row in enumerate(rows):
        scene, model = divmod(i, len(models))
        single = alone[models[model]][scene]
        assert {k: row[k] for k in single if k not in ("time_per_evaluation_s",)} == single
        ref = alone[models[-1]][scene]
        near, far = 1 / single["near_mm"], 1 / single["far_mm"]
        error = max(abs(near - 1 / ref["near_mm"]), abs(far - 1 / ref["far_mm"])) / (1 / ref["near_mm"] - 1 / ref["far_mm"])
        assert row["difference_pct"] == pytest.approx(100 * error, abs=1e-9)
        assert row["time_per_evaluation_s"] > 0
    table = run("dof", *args, "--model", "all")
    assert table.exit_code == 0 and "focus planning included" in table.stdout and "working N" in table.stdout


@pytest.mark.parametrize("extra", [["--teleconverter", "1"], ["--extension", "12mm"], ["-N", "8", "--extension", "12mm"]])
def test_planned_focus_rows_broadcast_a_single_value(extra):
    # two focal lengths and one distance through the close-up planner: one row per focal length, each the
    # row a call with that focal length alone gives (the planner once stopped at the shortest list)
    both = run_json("focus", "-f", "100,25.4", "-s", "0.5m", *extra)
    alone = [run_json("focus", "-f", f, "-s", "0.5m", *extra)[0] for f in ("100", "25.4")]
    assert both == alone
