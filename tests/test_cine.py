"""The cinema workflow: T-stops shown as T-stops, the cine CoC, shutter angles, ND densities as cinematographers
write them."""

from __future__ import annotations

import math

import numpy as np
import pytest
from cli_helpers import run, run_json

from camtool.core.errors import DomainError, InputError
from camtool.exposure.nd import parse_nd
from camtool.exposure.shutter import shutter_angle_deg, shutter_time_s
from camtool.geometry.coc import coc_from_rule
from camtool.plans.cine import shutter_times

# Wikipedia, "Depth of field", circle of confusion criterion (after Ray 2000): "generally 35 mm productions set it
# at 0.025 mm (0.001 in)". 0.001 in is 0.0254 mm; the convention rounds it to 0.025 mm.
CINE_COC_MM = 0.025


def test_cine_rule_is_the_published_value_on_any_sensor() -> None:
    for w, h in ((27.99, 19.22), (36.0, 24.0), (54.12, 25.58)):
        assert coc_from_rule("cine", w, h).coc_mm == CINE_COC_MM
    assert abs(CINE_COC_MM - 0.001 * 25.4) < 0.001  # 0.001 in, to the convention's rounding


def test_cine_camera_defaults_to_the_cine_rule_and_a_typed_rule_wins() -> None:
    row = run_json("dof", "--camera", "arri-alexa-35", "-f", "50", "-N", "2.8", "-s", "3m")[0]
    assert row["coc_mm"] == CINE_COC_MM
    d = math.hypot(27.99, 19.22)  # ALEXA 35 open gate (the preset's cited size)
    row = run_json("dof", "--camera", "arri-alexa-35", "-f", "50", "-N", "2.8", "-s", "3m", "--coc-rule", "d/1500")[0]
    assert row["coc_mm"] == pytest.approx(d / 1500, rel=1e-12)
    row = run_json("dof", "--camera", "nikon-z8", "-f", "50", "-N", "2.8", "-s", "3m")[0]  # a stills camera
    assert row["coc_mm"] != CINE_COC_MM


def test_typed_t_stop_is_shown_as_a_t_stop_in_the_table() -> None:
    result = run("dof", "--camera", "arri-alexa-35", "--lens", "cooke-s4i-50mm-t2", "-N", "T2.8", "-s", "4ft")
    assert result.exit_code == 0, result.output
    header, _, row = result.stdout.splitlines()[1:4]
    assert "T" in header.split() and "T2.8" in row.split()
    plain = run("dof", "-f", "50", "-N", "2.8", "-s", "4ft").stdout
    assert "T2.8" not in plain and "N used" not in plain


def test_solved_aperture_on_a_cine_lens_is_given_as_a_t_stop() -> None:
    rows = run_json("focus", "--camera", "arri-alexa-35", "--lens", "cooke-s4i-50mm-t2", "--near", "3m", "--far", "5m")
    # the preset has no f-number, so T stands in for N (the footer says so): the same number
    assert rows[0]["t_stop"] == rows[0]["f_number"]
    table = run("focus", "--camera", "arri-alexa-35", "--lens", "cooke-s4i-50mm-t2", "--near", "3m", "--far", "5m")
    assert f"T{rows[0]['t_stop']:.3g}" in table.stdout
    assert "t_stop" not in run_json("focus", "-f", "50", "--near", "3m", "--far", "5m")[0]


def test_solved_t_stop_with_a_known_transmittance() -> None:
    from types import SimpleNamespace

    from camtool.plans.equipment import solved_t_stops

    # Wikipedia, "F-number", T-stop: an f/2.0 lens of 75 % transmittance is T2.3
    lens = SimpleNamespace(id="x", t_number_min=2.31, transmittance=0.75)
    assert solved_t_stops(2.0, lens=lens).t_stops == pytest.approx(2.0 / math.sqrt(0.75), rel=1e-15)


@pytest.mark.parametrize(("angle", "fps", "time_s"), [(180.0, 24.0, 1 / 48), (172.8, 24.0, 1 / 50),
                                                       (144.0, 24.0, 1 / 60), (90.0, 6.0, 1 / 24), (45.0, 6.0, 1 / 48)])
def test_shutter_angle_published_pairs(angle: float, fps: float, time_s: float) -> None:
    # Wikipedia, "Shutter speed", cinematographic shutter formula (Brown 2002): 180° at 24 fps = 1/48 s,
    # 172.8° = 1/50 s, 144° = 1/60 s; D. Mullen ASC on cinematography.com: 90° and 45° at 6 fps = 1/24, 1/48 s
    assert shutter_time_s(angle, fps) == pytest.approx(time_s, rel=1e-14)
    assert shutter_angle_deg(time_s, fps) == pytest.approx(angle, rel=1e-14)


@pytest.mark.parametrize(("angle", "fps"), [(0.0, 24.0), (361.0, 24.0), (math.nan, 24.0), (180.0, 0.0),
                                            (180.0, math.inf), (180.0, -24.0)])
def test_shutter_angle_bounds(angle: float, fps: float) -> None:
    with pytest.raises(DomainError):
        shutter_time_s(angle, fps)


def test_shutter_times_plan() -> None:
    with pytest.raises(InputError):
        shutter_times(shutter_angle_deg=[180.0])
    with pytest.raises(InputError):
        shutter_times(shutter_angle_deg=[180.0], fps=24.0, shutter_s=[0.01])


def test_exposure_with_a_shutter_angle_equals_the_time() -> None:
    by_angle = run_json("exposure", "--ev100", "12", "-N", "T2.8", "--shutter-angle", "180", "--fps", "24")[0]
    by_time = run_json("exposure", "--ev100", "12", "-N", "T2.8", "-t", str(1 / 48))[0]
    assert by_angle["iso"] == pytest.approx(by_time["iso"], rel=1e-12)
    assert by_angle["shutter_angle_deg"] == pytest.approx(180.0, rel=1e-12)
    row = run_json("exposure", "--ev100", "10", "-N", "2.8", "--iso", "800", "--fps", "24")[0]
    assert row["shutter_angle_deg"] == pytest.approx(360 * 24 * row["corrected_shutter_s"], rel=1e-15)
    for args in (["--shutter-angle", "180"], ["--shutter-angle", "180", "--fps", "24", "-t", "1/50"],
                 ["--shutter-angle", "400", "--fps", "24"], ["--fps", "0", "-t", "1/50"]):
        result = run("exposure", "-N", "4", *args)
        assert result.exit_code == 2 and len(result.output.strip().splitlines()) == 1, result.output


def test_nd_density_notation_through_the_one_parser() -> None:
    # Kodak Wratten 2 #96 (B&H listing): ND .30 = 1 stop, ND .60 = 2, ND .90 = 3, ND 3.0 = 10 stops
    for text, density in (("ND.3", 0.3), ("ND.6", 0.6), ("ND0.9", 0.9), ("ND1.2", 1.2), ("ND 3.0", 3.0)):
        assert parse_nd(text).density == pytest.approx(density, rel=1e-15)
        assert parse_nd(text).stops == pytest.approx(parse_nd(f"{density}D").stops, rel=1e-15)
    assert parse_nd("ND8").stops == pytest.approx(3.0)  # ND with a whole number stays the factor
    stacked = run_json("exposure", "-N", "4", "-t", "1/50", "--nd", "ND.9", "--nd", "ND.6")[0]
    assert stacked["nd_stops"] == pytest.approx(1.5 / math.log10(2), rel=1e-12)


def test_squeeze_horizontal_angle_from_the_desqueezed_width() -> None:
    # Wikipedia, "Angle of view": 2·atan(d/2f); an anamorphic's horizontal angle covers the de-squeezed width S·w
    for squeeze in (1.3, 1.5, 1.8, 2.0):
        row = run_json("fov", "-f", "50", "--sensor", "27.99x19.22", "--squeeze", str(squeeze))[0]
        assert row["horizontal_deg"] == pytest.approx(math.degrees(2 * math.atan(squeeze * 27.99 / 100)), rel=1e-12)
        assert row["vertical_deg"] == pytest.approx(math.degrees(2 * math.atan(19.22 / 100)), rel=1e-12)
        assert row["sensor_width_mm"] == 27.99 and row["squeeze"] == squeeze
        # the horizontal angle of a spherical f/S on the same sensor (the horizontal focal length)
        same = run_json("fov", "-f", str(50 / squeeze), "--sensor", "27.99x19.22")[0]
        assert row["horizontal_deg"] == pytest.approx(same["horizontal_deg"], rel=1e-12)
    for bad in ("0.5", "5", "nan", "2,1.5"):
        result = run("fov", "-f", "50", "--squeeze", bad)
        assert result.exit_code == 2 and len(result.output.strip().splitlines()) == 1, result.output


def test_squeeze_dof_horizontal_is_the_dof_of_f_over_squeeze() -> None:
    # Maxwell (Cooke): vertical depth of a 2x 100 mm is that of 100 mm, horizontal that of 50 mm
    row = run_json("dof", "-f", "100", "-N", "2.8", "-s", "3m", "--coc", "0.025", "--squeeze", "2", "--model", "thin")[0]
    spherical = run_json("dof", "-f", "100", "-N", "2.8", "-s", "3m", "--coc", "0.025", "--model", "thin")[0]
    assert (row["near_mm"], row["far_mm"]) == (spherical["near_mm"], spherical["far_mm"])
    # the thin lens (design §4.4): H = f²/(Nc) + f of the horizontal focal length 50 mm
    h = 50.0**2 / (2.8 * 0.025) + 50.0
    from camtool.dof.closed import thin_dof

    half = thin_dof(50.0, 2.8, 0.025, 3000.0, "sensor")
    assert (row["near_horizontal_mm"], row["far_horizontal_mm"]) == (half.near_mm, half.far_mm)
    assert row["near_horizontal_mm"] < row["near_mm"] and row["far_horizontal_mm"] > row["far_mm"]
    # from the lens the far limit is u·H₀/(H − u) (design §4.4), here checked by hand at u = 3 m
    lens = run_json("dof", "-f", "100", "-N", "2.8", "-s", "3m", "--coc", "0.025", "--squeeze", "2", "--model", "thin",
                    "--distance-from", "lens")[0]
    assert lens["far_horizontal_mm"] == pytest.approx(3000.0 * (h - 50.0) / (h - 3000.0), rel=1e-13)
    assert lens["hyperfocal_horizontal_mm"] == pytest.approx(h, rel=1e-13)


def test_squeeze_compose_fills_the_desqueezed_width() -> None:
    rows = run_json("compose", "--subject-size", "4m", "--fill", "0.9", "--fill-axis", "width", "--sensor",
                    "27.99x19.22", "--squeeze", "2", "-f", "40", "--distance-from", "lens")
    # m = fill·(S·w)/size: the subject covers 0.9 of the de-squeezed 55.98 mm
    assert rows[0]["magnification"] == pytest.approx(0.9 * 2 * 27.99 / 4000.0, rel=1e-12)
    assert rows[0]["field_width_mm"] == pytest.approx(4000.0 / 0.9, rel=1e-12)


def test_marks_sheet_is_the_dof_commands_answer(tmp_path) -> None:
    pytest.importorskip("matplotlib")
    import json as _json

    data = tmp_path / "marks.json"
    result = run("chart", "marks", "-f", "25,75", "--lenses", "cooke-s4i-50mm-t2", "-N", "T2.8", "-s", "4ft,10ft",
                 "--camera", "arri-alexa-35", "--units", "imperial", "-o", str(tmp_path / "m.svg"), "--data", str(data))
    assert result.exit_code == 0, result.output
    sheet = _json.loads(data.read_text())["extra"]
    assert sheet["lenses"] == ["25 mm", "75 mm", "cooke-s4i-50mm-t2"] and sheet["focal_lengths_mm"] == [25.0, 75.0, 50.0]
    for col, f in enumerate(sheet["focal_lengths_mm"]):
        rows = run_json("dof", "-f", f"{f:g}", "-N", "T2.8", "-s", "4ft,10ft", "--camera", "arri-alexa-35")
        for row, answer in zip(range(2), rows):
            assert sheet["near_mm"][row][col] == pytest.approx(answer["near_mm"], rel=1e-12)
            assert sheet["far_mm"][row][col] == pytest.approx(answer["far_mm"], rel=1e-12)
    assert _json.loads(data.read_text())["title"] == "Focus marks · T2.8"
    bad = run("chart", "marks", "--lenses", "no-such-lens", "-N", "2", "-o", str(tmp_path / "x.svg"))
    assert bad.exit_code == 2 and "--lenses" in bad.output and len(bad.output.strip().splitlines()) == 1


def test_shot_envelope_is_dof_batch_over_the_same_frames(tmp_path) -> None:
    pytest.importorskip("matplotlib")
    import json as _json

    from camtool.plans.chart import read_shot

    csv = tmp_path / "shot.csv"  # a camera's per-frame CSV, as dof --batch reads it (T-stops written T2.8)
    csv.write_text("frame,distance,focal_length,f_number\n1,1.5m,50,T2.8\n2,2m,50,T2.8\n3,10ft,75,T4\n4,inf,75,T4\n")
    data = tmp_path / "shot.json"
    result = run("chart", "shot", "--frames", str(csv), "--camera", "arri-alexa-35", "-o", str(tmp_path / "s.svg"),
                 "--data", str(data))
    assert result.exit_code == 0, result.output
    curves = {c["role"]: c for c in _json.loads(data.read_text())["curves"]}
    batch = run("dof", "--batch", str(csv), "--camera", "arri-alexa-35", "--format", "json")
    rows = _json.loads(batch.stdout)
    assert curves["near"]["x"] == [1.0, 2.0, 3.0, 4.0] == [float(r["frame"]) for r in rows]
    assert curves["near"]["y"] == [r["near_mm"] for r in rows]
    assert curves["far"]["y"] == [r["far_mm"] for r in rows]  # None (JSON null) for infinity in both
    assert curves["focus"]["y"][:3] == [r["distance_mm"] for r in rows][:3]
    assert [r["f_number_from"] for r in rows] == ["t-stop"] * 4
    shot = read_shot(str(csv))
    assert [type(a).__name__ for a in shot.apertures] == ["TStop"] * 4
    bare = tmp_path / "bare.csv"
    bare.write_text("frame,focus,focal_length,t_stop\n1,1.5m,50,2.8\n")
    assert [type(a).__name__ for a in read_shot(str(bare)).apertures] == ["TStop"]  # a t_stop column's bare number


@pytest.mark.parametrize(("text", "said"), [
    ("frame,focus,focal_length,t_stop\n1,-2m,50,2.8\n", "row 1, column focus"),
    ("frame,focus,focal_length,t_stop\n1,2m,50,0.1\n", "row 1, column aperture"),
    ("frame,focus,focal_length,t_stop\n1,2m,50,2.8\n2,2m,nan,2.8\n", "row 2, column focal_length"),
    ("frame,focus,t_stop\n1,2m,2.8\n", "no focal_length column"),
    ("frame,focus,focal_length,t_stop\n1,2m,50,2.8,9\n", "row 1"),
])
def test_shot_bad_cells_are_one_line(tmp_path, text: str, said: str) -> None:
    pytest.importorskip("matplotlib")
    csv = tmp_path / "bad.csv"
    csv.write_text(text)
    result = run("chart", "shot", "--frames", str(csv), "-o", str(tmp_path / "s.svg"))
    assert result.exit_code == 2 and said in result.output and len(result.output.strip().splitlines()) == 1, \
        result.output
    missing = run("chart", "shot", "--frames", str(tmp_path / "none.csv"), "-o", str(tmp_path / "s.svg"))
    assert missing.exit_code == 1 and len(missing.output.strip().splitlines()) == 1


def test_chart_dof_squeeze_adds_the_horizontal_limits_of_f_over_squeeze() -> None:
    from camtool.dof.closed import thin_dof
    from camtool.plans.chart import dof_chart

    data = dof_chart(focal_lengths_mm=[100.0], f_numbers=[2.8], coc_mm=0.025, model="thin", squeeze=2.0)
    vertical_near, vertical_far, near, far = data.curves
    assert near.label == "f/2.8 horizontal near" and near.group != vertical_near.group
    expected = thin_dof(50.0, 2.8, 0.025, np.asarray(near.x), "sensor")
    assert near.y == [float(v) for v in expected.near_mm] and far.y == [float(v) for v in expected.far_mm]
    assert vertical_far.y == [float(v) for v in thin_dof(100.0, 2.8, 0.025, np.asarray(near.x), "sensor").far_mm]
    with pytest.raises(DomainError):
        dof_chart(focal_lengths_mm=[100.0], f_numbers=[2.8], coc_mm=0.025, squeeze=9.0)


def test_an_unreadable_frames_file_is_one_line_naming_the_option(tmp_path) -> None:
    result = run("chart", "shot", "-o", str(tmp_path / "shot.svg"), "--frames", str(tmp_path / "none.csv"))
    assert result.exit_code == 1
    assert result.stderr.startswith("Error: --frames ") and len(result.stderr.splitlines()) == 1


# --- anamorphic lens presets (docs/cine.md §5a) -------------------------------------------------

def test_an_anamorphic_preset_brings_its_squeeze_and_a_typed_squeeze_wins() -> None:
    # lens_db/cine-lenses.yaml, cooke-anamorphic-i: 2x (StudioDaily, April 2014)
    scene = ["-f", "50", "--camera", "arri-alexa-35"]
    (preset,) = run_json("fov", "--lens", "cooke-anamorphic-i", *scene)
    (typed,) = run_json("fov", "--squeeze", "2", *scene)
    assert preset == typed and preset["squeeze"] == 2.0
    # the horizontal angle covers the de-squeezed width S·w (Wikipedia, "Angle of view": 2·atan(d/2f))
    assert preset["horizontal_deg"] == pytest.approx(math.degrees(2 * math.atan(2 * 27.99 / 100)), rel=1e-12)
    (wins,) = run_json("fov", "--lens", "cooke-anamorphic-i", "--squeeze", "1.5", *scene)
    assert wins == run_json("fov", "--squeeze", "1.5", *scene)[0]
    (spherical,) = run_json("fov", "--lens", "cooke-anamorphic-i", "--squeeze", "1", *scene)
    assert spherical["horizontal_deg"] == pytest.approx(math.degrees(2 * math.atan(27.99 / 100)), rel=1e-12)
    (plain,) = run_json("fov", "--lens", "cooke-s7i", *scene)
    assert "squeeze" not in plain  # a spherical preset brings none


def test_the_squeeze_plan_takes_the_one_bound() -> None:
    from types import SimpleNamespace

    from camtool.core.ranges import SQUEEZE
    from camtool.plans.equipment import lens_squeeze

    assert lens_squeeze(SimpleNamespace(squeeze=2.0)) == 2.0
    assert lens_squeeze(SimpleNamespace(squeeze=2.0), squeeze=1.3) == 1.3
    assert lens_squeeze(None) is None and lens_squeeze(SimpleNamespace()) is None
    for value in SQUEEZE:
        assert lens_squeeze(None, squeeze=value) == value
    for value in (SQUEEZE[0] * (1 - 1e-9), SQUEEZE[1] * (1 + 1e-9)):
        with pytest.raises(DomainError) as caught:
            lens_squeeze(SimpleNamespace(squeeze=value))
        assert caught.value.param == "squeeze"


@pytest.mark.parametrize(("value", "ok"), [("1", True), ("4", True), ("0.99", False), ("4.01", False),
                                           ("two", False), (".nan", False)])
def test_a_preset_squeeze_is_checked_against_the_option_s_range(tmp_path, value: str, ok: bool) -> None:
    path = tmp_path / "ana.yaml"
    path.write_text(f"lenses:\n  - id: my-ana\n    focal_length_mm: 50\n    squeeze: {value}\n    source: mine\n")
    option = run("fov", "-f", "50", "--squeeze", value, "--format", "json")
    preset = run("fov", "--presets", str(path), "--lens", "my-ana", "--format", "json")
    assert (option.exit_code == 0) == (preset.exit_code == 0) == ok, (option.output, preset.output)
    if not ok:
        assert "squeeze" in preset.stderr and preset.stderr.count("\n") == 1


def test_dof_compose_and_chart_take_the_preset_s_squeeze(tmp_path) -> None:
    common = ["--camera", "arri-alexa-35", "-f", "75"]
    (by_preset,) = run_json("dof", "--lens", "cooke-anamorphic-i", *common, "-N", "T2.8", "-s", "10ft")
    (by_option,) = run_json("dof", "--squeeze", "2", *common, "-N", "T2.8", "-s", "10ft")
    # the member's own close focus (1.0 m at 75 mm, cine-lenses.yaml) rules out the other conjugate (38.6x, nearer than
    # it), which a bare --squeeze cannot know; every other key is the same
    assert by_preset.pop("other_magnification") is None and by_option.pop("other_magnification") > 1
    assert by_preset == by_option and by_preset["horizontal_focal_length_mm"] == 37.5
    framing = ["--subject-size", "4m", "--fill", "0.9", "--fill-axis", "width", "-N", "T2.8"]
    assert (run_json("compose", "--lens", "cooke-anamorphic-i", *common, *framing)
            == run_json("compose", "--squeeze", "2", *common, *framing))
    pytest.importorskip("matplotlib")
    import json as _json

    for name, extra in (("preset", ["--lens", "cooke-anamorphic-i"]), ("option", ["--squeeze", "2"])):
        result = run("chart", "dof", *extra, *common, "-N", "T2.8", "--model", "thin", "-o",
                     str(tmp_path / f"{name}.svg"), "--data", str(tmp_path / f"{name}.json"))
        assert result.exit_code == 0, result.output
    preset, option = (_json.loads((tmp_path / f"{n}.json").read_text()) for n in ("preset", "option"))
    assert preset["curves"] == option["curves"] and preset["extra"]["squeeze"] == 2.0


# --- a camera's per-frame columns in dof --batch (docs/cine.md §5b) ------------------------------

def test_dof_batch_reads_focus_and_t_stop_columns_as_distance_and_t_stops(tmp_path) -> None:
    named = tmp_path / "named.csv"
    named.write_text("frame,distance,focal_length,f_number\n1,1.5,50,T2.8\n2,2,50,T4\n3,inf,75,T2\n")
    camera = tmp_path / "camera.csv"
    camera.write_text("frame,focus,focal_length,t_stop\n1,1.5,50,2.8\n2,2,50,4\n3,inf,75,T2\n")
    dashed = tmp_path / "dashed.csv"
    dashed.write_text("frame,focus_mm,focal_length,T-Stop\n1,1500,50,2.8\n2,2000,50,4\n3,inf,75,2\n")
    lines = tmp_path / "frames.jsonl"
    lines.write_text('{"frame": 1, "focus": 1.5, "focal_length": 50, "t_stop": 2.8}\n'
                     '{"frame": 2, "focus": 2, "focal_length": 50, "t_stop": 4}\n'
                     '{"frame": 3, "focus": "inf", "focal_length": 75, "t_stop": "T2"}\n')
    rows = [[{k: v for k, v in row.items() if k != "frame"}  # passed through: "1" from CSV, 1 from JSON
             for row in run_json("dof", "--batch", str(path), "--camera", "arri-alexa-35")]
            for path in (named, camera, dashed, lines)]
    assert rows[0] == rows[1] == rows[2] == rows[3]
    assert [r["t_stop"] for r in rows[1]] == [2.8, 4.0, 2.0] and {r["f_number_from"] for r in rows[1]} == {"t-stop"}
    assert [r["distance_mm"] for r in rows[1]] == [1500.0, 2000.0, None]  # bare focus in metres, as -s


def test_a_bad_t_stop_cell_is_one_line_naming_its_row(tmp_path) -> None:
    camera = tmp_path / "camera.csv"
    camera.write_text("frame,focus,focal_length,t_stop\n1,1.5,50,2.8\n2,2,50,0.1\n")
    result = run("dof", "--batch", str(camera), "--format", "json")
    assert result.exit_code == 2 and "row 2" in result.stderr and "t_stop" in result.stderr
    assert result.stderr.count("\n") == 1
