"""camtool dof with the model ladder: lens data options, --model all, diffraction, errors."""

from __future__ import annotations

import errno
import os
from pathlib import Path

import pytest
from cli_helpers import run, run_json

from camtool.cli.lensdata import lens_data

DGAUSS = str(Path(__file__).parent / "data" / "prescriptions" / "dgauss100.yaml")


def test_model_all_rows_structure() -> None:
    rows = run_json("dof", "-N", "4", "-s", "2", "--coc", "0.03", "--prescription", DGAUSS, "--model", "all")
    assert [r["model"] for r in rows] == ["approx", "thin", "paraxial", "raytrace", "wave+prescription"]
    for row in rows:
        assert {"model", "error_estimate", "difference_pct", "time_per_evaluation_s", "near_mm", "far_mm",
                "total_mm"} <= set(row)
        assert row["time_per_evaluation_s"] > 0
    assert rows[-2]["difference_pct"] == 0.0  # raytrace, the reference; wave follows
    assert rows[0]["focal_length_mm"] == pytest.approx(100.00375702793)


def test_model_all_table_names_the_reference() -> None:
    out = run("dof", "-f", "50", "-N", "8", "-s", "3", "--pupil-mag", "0.7", "--model", "all").stdout
    assert "difference from thick, the most complete model" in out
    for name in ("approx", "thin", "thick"):
        assert name in out


def test_model_all_over_several_scenes_groups_models_per_scene() -> None:
    rows = run_json("dof", "-f", "50", "-N", "4,8", "-s", "3", "--model", "all")
    assert [(r["f_number"], r["model"]) for r in rows] == [(4.0, "approx"), (4.0, "thin"), (4.0, "wave"),
                                                          (8.0, "approx"), (8.0, "thin"), (8.0, "wave")]


def test_footer_names_model_and_estimate() -> None:
    out = run("dof", "-f", "50", "-N", "8", "-s", "3", "--model", "approx").stdout
    assert "approx model (est. error ≤ 4.34 %)" in out


def test_diffraction_and_wavelength_units() -> None:
    # f/11: the Airy disc (0.0148 mm) is below c/√2 (0.0204 mm), so auto keeps the root-sum-square add-on
    (a,) = run_json("dof", "-f", "50", "-N", "11", "-s", "3", "--diffraction", "--wavelength", "0.55um")
    (b,) = run_json("dof", "-f", "50", "-N", "11", "-s", "3", "--diffraction", "--wavelength", "550nm")
    (plain,) = run_json("dof", "-f", "50", "-N", "11", "-s", "3")
    assert a == b and a["model"] == "thin+diffraction"
    assert a["total_mm"] < plain["total_mm"]


def test_tolerance_forms() -> None:
    a = run_json("dof", "-N", "2", "-s", "5", "--prescription", DGAUSS, "--tolerance", "5%")
    b = run_json("dof", "-N", "2", "-s", "5", "--prescription", DGAUSS, "--tolerance", "0.05")
    assert a == b and a[0]["model"] == "thin"  # the effects thin leaves out here are below 5 %
    strict = run_json("dof", "-N", "2", "-s", "5", "--prescription", DGAUSS, "--tolerance", "0.1%")
    assert strict[0]["model"] == "raytrace"


def test_thick_by_hand() -> None:
    (row,) = run_json("dof", "-f", "100", "-N", "4", "-s", "0.6", "--pupil-mag", "0.6", "--hiatus", "-12mm",
                      "--model", "thick")
    assert row["model"] == "thick" and row["error_estimate"] == 0.0


def test_lens_data_helper_takes_a_preset() -> None:
    class Preset:
        pupil_magnification = 0.8
        hiatus_mm = 5.0
        prescription = None

    import click

    ctx = click.Context(click.Command("dof"))
    data = lens_data(ctx, None, -3.0, None, Preset())
    assert (data.pupil_magnification, data.hiatus_mm) == (0.8, -3.0)
    assert lens_data(ctx, None, None, None) is None


@pytest.mark.parametrize(("args", "message"), [
    (["--model", "thick"], "Error: Invalid value for '--model': thick is not available here: it needs the lens's "
     "pupil magnification or hiatus (--pupil-mag, --hiatus, a --lens that has them, or --prescription)"),
    (["--model", "raytrace"], "Error: Invalid value for '--model': raytrace is not available here: it needs a lens "
     "prescription (--prescription FILE, or a --lens that has one)"),
    (["--prescription", DGAUSS], "Error: Invalid value for '-f' / '--focal-length': 50 mm is outside the valid "
     "range: within 1 % of 100.004 mm, the paraxial focal length of dgauss100"),
    # auto with --diffraction judges by contrast where the Airy disc dominates (docs/wave.md): f/64 is past even that
    (["-N", "64", "--diffraction"], "Error: Invalid value for '-N' / '--f-number': 64 is outside the valid range: "
     "below f/36.5 for any depth of field by mtf:0.181@coc at 550 nm (nothing is sharp enough: even in focus the MTF "
     "at 34.7 lp/mm is below 0.181)"),
    (["-N", "32", "--diffraction", "--model", "thin"], "Error: Invalid value for '-N' / '--f-number': 32 is outside "
     "the valid range: below f/21.1 for any depth of field with diffraction at 550 nm (nothing is acceptably sharp: "
     "the Airy disc, 0.0437 mm, fills the 0.0288 mm circle of confusion)"),
    (["--tolerance", "2"], "Error: Invalid value for '--tolerance': 2 is outside the valid range: above 0 and below "
     "100 % (1 % = 0.01)"),
    (["--wavelength", "5nm"], "Error: Invalid value for '--wavelength': 5nm is outside the valid range: 200 to 2000 nm"),
    (["--pupil-mag", "0"], "Error: Invalid value for '--pupil-mag': 0 is outside the valid range: 0.05 to 20 "
     "(exit over entrance pupil diameter)"),
    (["--hiatus", "2parsecs"], "Error: Invalid value for '--hiatus': '2parsecs' has an unknown unit 'parsecs' "
     "(use mm, cm, m, km, in or ft)"),
])
def test_errors_are_one_line_exit_2(args: list[str], message: str) -> None:
    base = {"-f": "50", "-N": "8", "-s": "3"}
    for i in range(len(args) - 1):
        base.pop(args[i], None)
    result = run("dof", *[x for kv in base.items() for x in kv], *args)
    assert (result.exit_code, result.stdout, result.stderr) == (2, "", message + "\n")


def test_unreadable_prescription_is_exit_1_naming_option_and_file() -> None:
    result = run("dof", "-f", "50", "-N", "8", "-s", "3", "--prescription", "/nonexistent.yaml")
    assert (result.exit_code, result.stdout, result.stderr) == (
        1, "", "Error: Invalid value for '--prescription': /nonexistent.yaml: cannot read the file: "
               f"{os.strerror(errno.ENOENT)}\n")  # the C library's words for ENOENT


def test_a_prescription_not_in_air_is_refused_by_the_traced_models_and_used_by_the_others(tmp_path) -> None:
    # object space of index 1.333 (a lens under water): the paraxial, real-ray and wavefront paths assume air; they are
    # unavailable (one line on --model, exit 2) where a ValueError's traceback used to come out, and auto, thick and the
    # perfect-lens wave rung answer with the prescription's first-order data
    text = Path(DGAUSS).read_text(encoding="utf-8")
    water = tmp_path / "water.yaml"
    water.write_text(text.replace("object_index: 1.0", "object_index: 1.333") if "object_index:" in text
                     else text.replace("\nsurfaces:", "\nobject_index: 1.333\nsurfaces:", 1), encoding="utf-8")
    base = ["-N", "4", "-s", "3m", "--prescription", str(water)]
    for model in ("raytrace", "paraxial"):
        result = run("dof", *base, "--model", model)
        assert result.exit_code == 2 and result.stderr.startswith("Error: Invalid value for '--model'"), result.stderr
        assert result.stderr.count("\n") == 1 and "in air" in result.stderr
    for model, answered in (("auto", None), ("thick", "thick"), ("wave", "wave")):
        (row,) = run_json("dof", *base, "--model", model)
        assert row["near_mm"] > 0 and (answered is None or row["model"] == answered), row
    tilted = run("tilt", "-N", "8", "-s", "3m", "--tilt", "2", "--prescription", str(water), "--model", "raytrace")
    assert tilted.exit_code == 2 and "in air" in tilted.stderr and tilted.stderr.count("\n") == 1
