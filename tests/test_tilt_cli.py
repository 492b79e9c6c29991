"""``camtool tilt`` on the command line: forward and inverse, conventions named, the ladder, errors."""

from __future__ import annotations

import math
import re
import shlex
from pathlib import Path

import pytest
import yaml

from camtool.cli.tilt import tilt as tilt_command
from camtool.dof.ladder import LensData, depth_of_field
from camtool.dof.tilt import TiltLens, film_for_focus, tilt_wedge
from camtool.optics.prescription import prescription_from_mapping
from tests.cli_helpers import run, run_json

ROOT = Path(__file__).resolve().parent.parent
DGAUSS = str(Path(__file__).parent / "data" / "prescriptions" / "dgauss100.yaml")


def test_forward_row_names_its_conventions() -> None:
    (row,) = run_json("tilt", "-f", "90", "-N", "11", "-s", "2m", "--tilt", "3")
    assert row["hinge_mm"] == pytest.approx(90.0 / math.sin(math.radians(3.0)), rel=1e-12)
    assert row["focus_mm"] == pytest.approx(2000.0, rel=1e-12)  # from the sensor, along the line of sight
    assert row["near_mm"] < row["focus_mm"] < row["far_mm"]
    assert row["near_plane_deg"] < row["focus_plane_deg"] < row["far_plane_deg"]
    assert (row["along"], row["angles_from"], row["hinge_from"], row["distance_from"]) == \
        ("sight", "film", "lens", "sensor")
    assert "Merklinger" in row["hyperfocal_definition"]
    table = run("tilt", "-f", "90", "-N", "11", "-s", "2m", "--tilt", "3").stdout
    for words in ("from the film plane", "J from the lens", "along the line of sight", "hyperfocal:"):
        assert words in table


def test_cli_matches_the_library() -> None:
    (row,) = run_json("tilt", "-f", "150", "-N", "11", "--coc", "0.1", "-s", "10m", "--tilt", "5",
                      "--distance-from", "lens")
    lens = TiltLens(150.0)
    w = tilt_wedge(lens, 11.0, 0.1, 5.0, film_for_focus(lens, 5.0, 10_000.0))
    assert row["near_mm"] == pytest.approx(1 / w.k_near, rel=1e-12)
    assert row["far_mm"] == pytest.approx(1 / w.k_far, rel=1e-12)
    assert row["focus_plane_deg"] == pytest.approx(w.focus_deg, rel=1e-12)


def test_no_tilt_is_the_dof_command() -> None:
    (row,) = run_json("tilt", "-f", "90", "-N", "11", "-s", "3m", "--tilt", "0", "--coc", "0.03")
    (dof,) = run_json("dof", "-f", "90", "-N", "11", "-s", "3m", "--model", "thin", "--coc", "0.03")
    assert row["near_mm"] == pytest.approx(dof["near_mm"], rel=1e-9)
    assert row["far_mm"] == pytest.approx(dof["far_mm"], rel=1e-9)
    assert row["hinge_mm"] is None  # infinity: JSON has no inf
    assert "ordinary depth of field" in run("tilt", "-f", "90", "-N", "11", "-s", "3m", "--tilt", "0").stdout


def test_hinge_gives_the_tilt_and_swing_is_the_same_geometry() -> None:
    (row,) = run_json("tilt", "-f", "90", "-N", "11", "--hinge", "1.6m", "-s", "5m")
    assert row["tilt_deg"] == pytest.approx(math.degrees(math.asin(90.0 / 1600.0)), rel=1e-12)
    (swung,) = run_json("tilt", "-f", "90", "-N", "11", "--swing", str(row["tilt_deg"]), "-s", "5m")
    assert swung["movement"] == "swing"
    assert swung["near_mm"] == pytest.approx(row["near_mm"], rel=1e-12)


def test_two_points_put_the_plane_through_them() -> None:
    (row,) = run_json("tilt", "-f", "90", "-N", "11", "--point", "3m@-1.6m", "--point", "20m@-1.6m",
                      "--distance-from", "lens", "--at", "20m")
    # the ground: 1.6 m below the lens at every distance, the plane of focus parallel to the line of sight
    assert row["hinge_mm"] == pytest.approx(1600.0, rel=1e-12)
    assert row["focus_plane_deg"] == pytest.approx(90.0, abs=1e-9)
    assert row["focus_mm"] is None  # parallel to the line of sight: crosses it at infinity
    (row,) = run_json("tilt", "-f", "90", "-N", "11", "--point", "2m@-1.5m", "--point", "8m@0.5m",
                      "--distance-from", "lens")
    j, k = row["hinge_mm"], 1 / row["focus_mm"]
    for x, height in ((2000.0, -1500.0), (8000.0, 500.0)):
        assert j * (1 - k * x) == pytest.approx(-height, rel=1e-9)


def test_points_from_the_sensor_account_for_the_lens_position() -> None:
    (row,) = run_json("tilt", "-f", "90", "-N", "11", "--point", "3m@-1m", "--point", "9m@-1m")
    lens_plane = row["image_distance_mm"] * math.cos(math.radians(row["tilt_deg"]))
    assert row["hinge_mm"] == pytest.approx(1000.0, rel=1e-12)
    assert row["far_mm"] is None and row["near_mm"] > lens_plane


def test_angle_conventions() -> None:
    args = ["tilt", "-f", "90", "-N", "11", "-s", "4m", "--tilt", "5"]
    (film,) = run_json(*args)
    (lens,) = run_json(*args, "--angles-from", "lens")
    (horizon,) = run_json(*args, "--angles-from", "horizon")
    assert lens["focus_plane_deg"] == pytest.approx(film["focus_plane_deg"] - 5.0, rel=1e-12)
    assert horizon["focus_plane_deg"] == pytest.approx(90.0 - film["focus_plane_deg"], rel=1e-12)


def test_along_the_axis_focus_is_the_lens_equation() -> None:
    (row,) = run_json("tilt", "-f", "90", "-N", "11", "-s", "4m", "--tilt", "5", "--along", "axis",
                      "--distance-from", "lens")
    assert row["focus_mm"] == pytest.approx(4000.0, rel=1e-12)
    assert row["image_distance_mm"] == pytest.approx(1 / (1 / 90.0 - 1 / 4000.0), rel=1e-12)


def test_hinge_from_the_entrance_pupil() -> None:
    args = ["tilt", "-f", "24", "-N", "8", "-s", "2m", "--tilt", "6", "--pupil-mag", "2.5"]
    (lens,) = run_json(*args)
    (pupil,) = run_json(*args, "--hinge-from", "pupil")
    e = 24.0 * (1 - 1 / 2.5)
    assert lens["hinge_mm"] - pupil["hinge_mm"] == pytest.approx(e * math.sin(math.radians(6.0)), rel=1e-9)
    (back,) = run_json("tilt", "-f", "24", "-N", "8", "-s", "2m", "--hinge", f"{pupil['hinge_mm']}mm",
                       "--pupil-mag", "2.5", "--hinge-from", "pupil")
    assert back["tilt_deg"] == pytest.approx(6.0, rel=1e-9)


def test_f_number_for_a_wedge_and_the_optimum() -> None:
    (row,) = run_json("tilt", "-f", "150", "--coc", "0.1", "--tilt", "7", "-s", "10m", "--at", "20m",
                      "--half-depth", "1m", "--optimum")
    assert min(row["above_mm"], row["below_mm"]) == pytest.approx(1000.0, rel=1e-9)
    assert row["f_number"] == row["f_number_needed"]
    assert row["f_number_optimum"] > row["f_number_needed"]


def test_hyperfocal_far_limit_reaches_the_horizon() -> None:
    (row,) = run_json("tilt", "-f", "24", "-N", "8", "--tilt", "4", "--hyperfocal", "--distance-from", "lens")
    assert row["far_mm"] is None  # infinity
    assert row["focus_mm"] == pytest.approx(row["hyperfocal_mm"], rel=1e-12)
    assert row["near_mm"] == pytest.approx(row["focus_mm"] / 2, rel=1e-9)


def test_model_all_with_a_prescription() -> None:
    rows = run_json("tilt", "-N", "8", "-s", "3m", "--tilt", "4", "--prescription", DGAUSS, "--model", "all")
    assert [r["model"] for r in rows] == ["thin", "thick", "raytrace"]
    thin, thick, traced = rows
    assert thick["near_mm"] != thin["near_mm"]
    assert traced["near_mm"] == thick["near_mm"]  # the wedge comes from the thick model
    assert traced["hinge_mm"] != thick["hinge_mm"]  # the real plane across the picture


def test_raytrace_wedge_along_the_axis_is_the_raytrace_rung() -> None:
    rows = run_json("tilt", "-N", "8", "-s", "3m", "--tilt", "4", "--prescription", DGAUSS, "--model", "all",
                    "--along", "axis", "--distance-from", "lens")
    thick, traced = rows[1], rows[2]
    data = LensData(prescription=prescription_from_mapping(yaml.safe_load(Path(DGAUSS).read_text())))
    f = data.focal_length_mm
    axis_focus = 1 / (1 / f - math.cos(math.radians(4.0)) / (thick["image_distance_mm"] * math.cos(math.radians(4.0))))
    limits = depth_of_field("raytrace", f, 8.0, thick["coc_mm"], axis_focus, "lens", lens=data).limits
    assert traced["near_mm"] == pytest.approx(limits.near_mm, rel=1e-12)
    assert traced["far_mm"] == pytest.approx(limits.far_mm, rel=1e-12)
    assert traced["near_mm"] == pytest.approx(thick["near_mm"], rel=0.01)  # a well-corrected lens at f/8


def test_retrofocus_model_all_shows_the_difference() -> None:
    rows = run_json("tilt", "-f", "24", "-N", "8", "-s", "1m", "--tilt", "6", "--pupil-mag", "2.5",
                    "--hiatus", "-15", "--model", "all")
    thin, thick = rows
    assert abs(thick["near_mm"] / thin["near_mm"] - 1) > 1e-3


@pytest.mark.parametrize(("args", "option", "words"), [
    (["--tilt", "10", "--lens", "ts-e-24-ii"], "--tilt", "±8.5°"),  # Canon TS-E 24mm f/3.5L II: tilt ±8.5°
    (["--hinge", "10mm"], "--hinge", "at least the focal length"),
    (["--tilt", "95"], "--tilt", "-89° to 89°"),
    (["--point", "2m@-1m", "--point", "2m@-1m"], "--point", "two different points"),
    (["--point", "2m@-0.01m", "--point", "3m@-0.01m"], "--point", "hinge line"),
    (["--point", "2m@-1m"], "--point", "give exactly two"),
    (["--tilt", "3", "-s", "0.05"], "--distance", "from the sensor"),
    (["--tilt", "abc"], "--tilt", "not an angle"),
    (["--point", "2m"], "--point", "DIST@HEIGHT"),
    (["--tilt", "3", "--image-distance", "20"], "--image-distance", "at least the focal length"),
    (["--tilt", "3", "-s", "3", "--pupil-mag", "0.1", "--coc", "0.5"], "--coc", "smaller than the exit pupil"),
    (["--tilt", "3", "-s", "3", "--at", "0.01"], "--at", "beyond the lens"),
    (["--tilt", "0", "-s", "3", "--at", "5", "--half-depth", "0.1"], "--half-depth", "needs a tilt"),
])
def test_errors_name_the_option(args: list[str], option: str, words: str) -> None:
    result = run("tilt", "-f", "24", "-N", "8", *args)
    assert result.exit_code == 2
    assert option in result.output and words in result.output
    assert "Traceback" not in result.output and len(result.output.strip().splitlines()) == 1


def test_tilt_within_the_lens_range_is_accepted() -> None:
    (row,) = run_json("tilt", "--lens", "ts-e-24-ii", "-N", "8", "--tilt", "8.5", "-s", "1m")
    assert row["focal_length_mm"] == 24.0


def test_usage_errors() -> None:
    assert run("tilt", "-f", "90", "-N", "8", "-s", "2").exit_code == 2  # no tilt
    assert run("tilt", "-f", "90", "-N", "8", "--tilt", "2", "--swing", "2").exit_code == 2
    assert run("tilt", "-f", "90", "--tilt", "2", "-s", "2").exit_code == 2  # no f-number
    assert run("tilt", "-f", "90", "-N", "8", "--tilt", "2", "-s", "2", "--half-depth", "1").exit_code == 2


def test_field_output() -> None:
    result = run("tilt", "-f", "90", "--hinge", "1.6m", "-N", "8", "--field", "tilt_deg")
    assert result.exit_code == 0
    assert float(result.stdout) == pytest.approx(math.degrees(math.asin(90 / 1600)), rel=1e-12)


def _examples(text: str) -> list[list[str]]:
    return [shlex.split(line.split("#")[0])[1:] for line in text.splitlines()
            if line.strip().startswith("camtool tilt ")]


def test_help_and_readme_examples_run(monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.chdir(ROOT)  # the examples name files relative to the repository
    examples = _examples(tilt_command.help or "") + _examples((ROOT / "README.md").read_text(encoding="utf-8"))
    examples += _examples((ROOT / "docs" / "tilt.md").read_text(encoding="utf-8"))
    assert len(examples) >= 8
    for args in examples:
        result = run(*args)
        assert result.exit_code == 0, (args, result.output)
        assert not re.search(r"\bnan\b", result.output)
