"""``camtool exif`` on the tiny images of tests/data/exif (made by make_images.py there).

Expected values are derived here from the published definitions, not from
camtool: ExifTool's Composite tags (https://exiftool.org/TagNames/Composite.html
and their ValueConv in Image::ExifTool::Exif, quoted beside each test), the
Exif 2.32 standard (CIPA DC-008) for the tags, and the makers' encodings
(tests/test_exif_makernotes.py).
"""

from __future__ import annotations

import json
import math
import os
import re
import subprocess
import sys
from pathlib import Path

import pytest

from tests.cli_helpers import run

pytest.importorskip("exiv2")

DATA = Path(__file__).resolve().parent / "data" / "exif"
GOOD = ["canon_bracket.jpg", "canon_infinity.jpg", "nikon.jpg", "olympus.jpg", "fujifilm_subject.jpg",
        "sony_apex_lens.jpg", "resized_high_iso.jpg", "canon_shotinfo.jpg"]
BAD = ["no_metadata.jpg", "not_an_image.jpg", "truncated.jpg"]
EXIFTOOL_MODE = ["--coc-rule", "d/1440", "--distance-from", "lens", "--model", "thin"]
FULL_FRAME_DIAGONAL = math.sqrt(24 * 24 + 36 * 36)  # ExifTool's CircleOfConfusion: sqrt(24*24+36*36)


def rows(*args: str, code: int = 0) -> list[dict]:
    result = run("exif", *args, "--format", "json")
    assert result.exit_code == code, result.output
    return json.loads(result.stdout)


def one(name: str, *args: str) -> dict:
    (row,) = rows(str(DATA / name), *args)
    return row


# -- ExifTool's composite tags, by their definitions ----------------------------------------------------

def exiftool_dof(f: float, n: float, c: float, d_m: float) -> tuple[float, float]:
    """Composite:DOF: t = N·c·(1000·d − f)/f²; near = d/(1 + t), far = d/(1 − t) (0 when t ≥ 1: infinity); metres."""
    t = n * c * (d_m * 1000 - f) / (f * f)
    far = d_m / (1 - t)
    return d_m / (1 + t), (far if far >= 0 else math.inf)


def exiftool_fov(f: float, scale: float, d_m: float | None) -> float:
    """Composite:FOV: corr = 1 + f/(1000·d − f); 2·atan2(36, 2·f·scale·corr) in degrees, with ExifTool's 3.14159."""
    corr = 1.0
    if d_m:
        d = 1000 * d_m - f
        if d > 0:
            corr += f / d
    return math.atan2(36, 2 * f * scale * corr) * 360 / 3.14159


def test_canon_bracket_matches_exiftool_composites() -> None:
    row = one("canon_bracket.jpg", *EXIFTOOL_MODE)
    # the file: 50 mm, f/8, 1/125 s, ISO 400; 5616 px at 5616/(36/25.4) px/in: 36 mm wide, so ScaleFactor35efl 1
    assert row["crop_factor"] == pytest.approx(1.0, rel=1e-12)
    assert (row["sensor_width_mm"], row["sensor_height_mm"]) == pytest.approx((36.0, 24.0), rel=1e-12)
    # Composite:CircleOfConfusion = sqrt(24²+36²)/(ScaleFactor35efl·1440)
    c = FULL_FRAME_DIAGONAL / 1440
    assert row["coc_mm"] == pytest.approx(c, rel=1e-12)
    # Canon FocusDistanceUpper 350, Lower 320 (cm); DOF takes their mean when no FocusDistance is recorded
    assert (row["focus_distance_min_mm"], row["focus_distance_max_mm"]) == (3200.0, 3500.0)
    assert row["focus_distance_mm"] == 3350.0
    near, far = exiftool_dof(50, 8, c, 3.35)
    assert row["near_mm"] == pytest.approx(near * 1000, rel=1e-12)
    assert row["far_mm"] == pytest.approx(far * 1000, rel=1e-12)
    # Composite:LightValue = log2(N²/t · 100/ISO)
    assert row["ev100"] == pytest.approx(math.log2(8**2 * 125 * 100 / 400), rel=1e-12)
    assert row["ev"] == pytest.approx(math.log2(8**2 * 125), rel=1e-12)
    # Composite:FOV with the focus correction (3.14159 for π: a relative 8.4e-7)
    assert row["horizontal_deg"] == pytest.approx(exiftool_fov(50, 1.0, 3.35), rel=2e-6)
    assert row["model"] == "thin" and row["distance_from"] == "lens"


def test_hyperfocal_matches_exiftool_with_approx() -> None:
    # Composite:HyperfocalDistance = f²/(N·c·1000) m, c the CircleOfConfusion
    row = one("canon_bracket.jpg", "--coc-rule", "d/1440", "--distance-from", "lens", "--model", "approx")
    c = FULL_FRAME_DIAGONAL / 1440
    assert row["hyperfocal_mm"] == pytest.approx(50**2 / (8 * c), rel=1e-12)


def test_scale_factor_from_the_35mm_equivalent() -> None:
    # ScaleFactor35efl = FocalLengthIn35mmFormat / FocalLength: 48/30 (Canon), 50/25 (Olympus), 52/35 (Fujifilm)
    for name, scale, f, focus_m in (("olympus.jpg", 2.0, 25, 2.5), ("fujifilm_subject.jpg", 52 / 35, 35, 3.5)):
        row = one(name, *EXIFTOOL_MODE)
        assert row["crop_factor"] == pytest.approx(scale, rel=1e-12)
        c = FULL_FRAME_DIAGONAL / (scale * 1440)
        assert row["coc_mm"] == pytest.approx(c, rel=1e-12)
        near, far = exiftool_dof(f, row["f_number"], c, focus_m)
        assert (row["near_mm"], row["far_mm"]) == pytest.approx((near * 1000, far * 1000), rel=1e-12)
        # the sensor keeps the image's aspect ratio and the diagonal 43.27/scale
        w, h = row["sensor_width_mm"], row["sensor_height_mm"]
        assert math.hypot(w, h) == pytest.approx(FULL_FRAME_DIAGONAL / scale, rel=1e-12)
    olympus = one("olympus.jpg")
    assert olympus["sensor_width_mm"] / olympus["sensor_height_mm"] == pytest.approx(4 / 3, rel=1e-12)
    # ExifTool's FOV takes 36/scale as the width, exact for a 3:2 frame (Fujifilm's 6240 × 4160)
    fuji = one("fujifilm_subject.jpg", "--distance-from", "lens")
    assert fuji["horizontal_deg"] == pytest.approx(exiftool_fov(35, 52 / 35, 3.5), rel=2e-6)


def test_maker_distances_and_their_sources() -> None:
    nikon = one("nikon.jpg")
    assert nikon["focus_distance_mm"] == pytest.approx(10 * 10 ** (100 / 40), rel=1e-12)  # 0.01 m·10^(raw/40)
    assert nikon["focus_distance_source"] == "NikonLd2.FocusDistance"
    # no focal-plane data, no 35 mm equivalent: the camera preset for Make/Model NIKON D850 (35.9 × 23.9 mm)
    assert (nikon["sensor_width_mm"], nikon["sensor_height_mm"]) == (35.9, 23.9)
    assert nikon["sensor_source"] == "camera preset nikon-d850"
    olympus = one("olympus.jpg")
    assert olympus["focus_distance_mm"] == 2500.0 and olympus["focus_distance_source"] == "OlympusFi.FocusDistance"
    fuji = one("fujifilm_subject.jpg")
    assert fuji["focus_distance_mm"] == 3500.0 and fuji["focus_distance_source"] == "Photo.SubjectDistance"
    shotinfo = one("canon_shotinfo.jpg")  # ShotInfo 0x13 = 250 cm; no bracket, so no *_min/_max
    assert shotinfo["focus_distance_mm"] == 2500.0 and shotinfo["focus_distance_source"] == "CanonSi.SubjectDistance"
    assert shotinfo["focus_distance_min_mm"] is None and shotinfo["near_min_mm"] is None
    canon = one("canon_bracket.jpg")
    assert canon["sensor_source"] == "Photo.FocalPlaneX/YResolution"
    assert canon["f_number_source"] == "Photo.FNumber" and canon["iso_source"] == "Photo.ISOSpeedRatings"


def test_apex_values() -> None:
    # Exif 2.32: N = 2^(Av/2), t = 2^(−Tv): Av 6 is f/8, Tv 7 is 1/128 s
    row = one("sony_apex_lens.jpg", "--model", "thin")
    assert row["f_number"] == 8.0 and row["shutter_s"] == 1 / 128
    assert row["f_number_source"] == "Photo.ApertureValue" and row["shutter_source"] == "Photo.ShutterSpeedValue"
    assert row["ev"] == pytest.approx(13.0, rel=1e-12)  # 2·log2 8 + 7
    assert row["ev100"] == pytest.approx(12.0, rel=1e-12)  # ISO 200: one stop less


def test_an_implausible_focal_plane_and_a_16_bit_iso_are_passed_over() -> None:
    row = one("resized_high_iso.jpg")
    # 100 px at 5184/22.3 px/mm is 0.43 mm: not a sensor (ExifTool too wants a diagonal of 1 to 100 mm)
    assert row["sensor_source"] == "Photo.FocalLengthIn35mmFilm / FocalLength"
    assert row["crop_factor"] == pytest.approx(48 / 30, rel=1e-12)
    # ISOSpeedRatings 65535 means "65535 or more": the RecommendedExposureIndex, 102400, is the value
    assert row["iso"] == 102400 and row["iso_source"] == "Photo.RecommendedExposureIndex"
    assert row["ev100"] == pytest.approx(math.log2(16 * 1000 * 100 / 102400), rel=1e-12)


def test_the_bracket_ends_bound_the_limits() -> None:
    row = one("canon_bracket.jpg", *EXIFTOOL_MODE)
    c = FULL_FRAME_DIAGONAL / 1440
    for end, metres in (("min", 3.2), ("max", 3.5)):
        near, far = exiftool_dof(50, 8, c, metres)
        assert row[f"near_{end}_mm"] == pytest.approx(near * 1000, rel=1e-12)
        assert row[f"far_{end}_mm"] == pytest.approx(far * 1000, rel=1e-12)
    assert row["near_min_mm"] < row["near_mm"] < row["near_max_mm"]
    assert row["far_min_mm"] < row["far_mm"] < row["far_max_mm"]


def test_a_bracket_open_to_infinity() -> None:
    # Canon FocusDistanceUpper 65535 is infinity: the far end of the bracket and the focus are infinite
    # (null in JSON, as every camtool infinity); the near end, 10 m, still bounds the near limit
    row = one("canon_infinity.jpg", "--distance-from", "lens", "--model", "thin", "--coc-rule", "d/1440")
    assert row["focus_distance_min_mm"] == 10000.0
    assert row["focus_distance_mm"] is None and row["focus_distance_max_mm"] is None and row["far_mm"] is None
    # focused at infinity the near limit of a thin lens is f²/(N·c) from the lens (ExifTool's d/(1 + t) as d → ∞)
    assert row["near_mm"] == pytest.approx(30**2 / (11 * FULL_FRAME_DIAGONAL / (1.6 * 1440)), rel=1e-12)
    near, _ = exiftool_dof(30, 11, FULL_FRAME_DIAGONAL / (1.6 * 1440), 10.0)
    assert row["near_min_mm"] == pytest.approx(near * 1000, rel=1e-12)
    field = run("exif", str(DATA / "canon_infinity.jpg"), "--field", "focus_distance_mm")
    assert field.stdout == "inf\n"


def test_default_plane_is_the_sensor() -> None:
    # Distance scales, which the recorded distances follow, are marked from the sensor: a thin lens focused
    # at s from the sensor has u + v = s, u·v = f·s... so the near limit differs from the lens-plane reading
    sensor = one("fujifilm_subject.jpg", "--model", "thin")
    lens = one("fujifilm_subject.jpg", "--model", "thin", "--distance-from", "lens")
    assert sensor["distance_from"] == "sensor"
    assert sensor["near_mm"] != pytest.approx(lens["near_mm"], rel=1e-6)


def test_a_lens_preset_matched_by_name_brings_its_prescription() -> None:
    row = one("sony_apex_lens.jpg")
    assert row["lens_source"] == "Photo.LensModel = preset dgauss100-lens"
    assert row["model"] in {"paraxial", "raytrace"}  # a prescription lets auto climb past the closed forms
    thin = one("sony_apex_lens.jpg", "--model", "thin")
    assert thin["near_mm"] != pytest.approx(row["near_mm"], rel=1e-4)


def test_options_override_the_file() -> None:
    row = one("nikon.jpg", "--crop", "1.5", "-s", "2", "--coc", "0.02")  # bare distances are metres, as in dof
    assert row["crop_factor"] == pytest.approx(1.5) and row["sensor_source"] == "--crop"
    assert row["focus_distance_mm"] == 2000.0 and row["focus_distance_source"] == "-s"
    assert row["coc_mm"] == 0.02 and row["coc_source"] == "--coc"
    lens = one("sony_apex_lens.jpg", "--lens", "dgauss100-lens")
    assert lens["lens"] == "Double Gauss 100 mm f/2 (design)" and lens["lens_source"] == "--lens"


@pytest.mark.parametrize("name", BAD)
def test_unreadable_files_give_a_row_of_nulls_and_exit_1(name: str) -> None:
    result = run("exif", str(DATA / name), "--format", "json")
    assert result.exit_code == 1
    (row,) = json.loads(result.stdout)
    assert row["file"] == str(DATA / name)
    assert all(value is None for key, value in row.items() if key != "file")
    (line,) = result.stderr.splitlines()
    assert line.startswith(f"camtool exif: {DATA / name}: ")
    assert "Traceback" not in result.output


def test_messages_say_what_is_wrong() -> None:
    result = run("exif", *(str(DATA / n) for n in BAD), str(DATA / "missing.jpg"), str(DATA))
    lines = result.stderr.splitlines()
    assert result.exit_code == 1
    assert any(line.endswith("no_metadata.jpg: no Exif metadata") for line in lines)
    assert any(line.endswith("not_an_image.jpg: not an image libexiv2 can read") for line in lines)
    assert any("truncated.jpg: truncated or corrupt" in line for line in lines)
    assert any(line.endswith("missing.jpg: cannot be opened") for line in lines)
    assert any("is a directory (give --recursive" in line for line in lines)


def test_no_file_is_a_usage_error() -> None:
    result = run("exif")
    assert result.exit_code == 2
    assert result.stderr.splitlines()[-1] == "Error: give at least one FILE (or - to read paths from standard input)"


def test_partial_metadata_is_null_where_missing_and_named_on_stderr() -> None:
    result = run("exif", str(DATA / "partial.jpg"), "--format", "json")
    assert result.exit_code == 0
    (row,) = json.loads(result.stdout)
    assert row["focal_length_mm"] == 50.0 and row["camera"] == "Acme Pinhole 1"
    for key in ("f_number", "near_mm", "far_mm", "coc_mm", "crop_factor", "horizontal_deg", "ev100"):
        assert row[key] is None, key
    (line,) = result.stderr.splitlines()
    assert line.startswith(f"camtool exif: {DATA / 'partial.jpg'}: no sensor size")
    assert "no f-number" in line and "no focus distance" in line


def test_one_bad_file_among_good_ones() -> None:
    got = rows(str(DATA / "nikon.jpg"), str(DATA / "truncated.jpg"), code=1)
    assert [Path(r["file"]).name for r in got] == ["nikon.jpg", "truncated.jpg"]
    assert got[0]["near_mm"] is not None


def test_paths_from_stdin_and_recursive() -> None:
    listing = "".join(str(DATA / n) + "\n" for n in GOOD)
    result = run_with_input(["exif", "-", "--field", "file"], listing)
    assert result.exit_code == 0 and result.stdout.splitlines() == [str(DATA / n) for n in GOOD]
    recursive = run("exif", "--recursive", str(DATA), "--field", "file")
    names = [Path(p).name for p in recursive.stdout.splitlines()]
    assert names == sorted(p.name for p in DATA.glob("*.jpg"))
    assert recursive.exit_code == 1  # the bad files are there too


def run_with_input(args: list[str], text: str):
    from click.testing import CliRunner

    from camtool.cli import cli

    return CliRunner().invoke(cli, args, input=text, env={"COLUMNS": None, "CAMTOOL_FORMAT": None},
                              catch_exceptions=False)


def test_table_and_csv() -> None:
    table = run("exif", *(str(DATA / n) for n in GOOD))
    assert table.exit_code == 0 and "canon_bracket.jpg" in table.stdout and "h. angle" in table.stdout
    csv_out = run("exif", str(DATA / "nikon.jpg"), "--format", "csv")
    header, line = csv_out.stdout.splitlines()
    assert header.split(",")[:3] == ["file", "camera", "lens"] and "NIKON D850" in line


def test_missing_exiv2_is_a_one_line_error(monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setitem(sys.modules, "exiv2", None)  # import exiv2 now raises ImportError
    result = run("exif", str(DATA / "nikon.jpg"))
    assert result.exit_code == 1
    assert result.stderr == ("Error: camtool exif needs python-exiv2: pip install 'camtool[exif]' "
                             "(or pip install exiv2)\n")


def test_other_commands_do_not_import_exiv2() -> None:
    code = ("import sys; from camtool.cli import cli\n"
            "try:\n    cli.main(['dof', '-f', '50', '-N', '8', '-s', '3', '--format', 'json'], standalone_mode=False)\n"
            "finally:\n    print(sorted(m for m in sys.modules if m == 'exiv2' or m.startswith('camtool.exif')))")
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True).stdout
    assert out.strip().splitlines()[-1] == "[]"


def test_help_examples_run() -> None:
    from camtool.cli.exif import exif

    examples = re.findall(r"^\s+(camtool exif .+)$", exif.help or "", re.MULTILINE)
    assert len(examples) >= 3
    for example in examples:
        done = subprocess.run([sys.executable, "-m", "camtool", *example.split()[1:]], cwd=DATA,
                              capture_output=True, text=True, env={**os.environ, "COLUMNS": "120"})
        assert "Traceback" not in done.stderr, example
        assert done.returncode == (1 if " -r " in f" {example} " else 0), (example, done.stderr)


def test_readme_examples_run() -> None:
    root = DATA.parent.parent.parent
    text = (root / "README.md").read_text(encoding="utf-8")
    section = text.split("## Photos: what depth of field did I have?", 1)[1].split("\n## ", 1)[0]
    block = section.split("```sh\n", 1)[1].split("```", 1)[0]
    lines = [line for line in block.splitlines() if line.strip()]
    assert len(lines) == 5
    for line in lines:
        done = subprocess.run(["bash", "-c", line.replace("camtool ", f"{sys.executable} -m camtool ")], cwd=root,
                              capture_output=True, text=True)
        assert "Traceback" not in done.stderr and done.stdout, line
        assert done.returncode == (1 if "exit 1" in line else 0), (line, done.stderr)


def test_a_scene_s_distance_fills_the_one_value_of_s() -> None:
    # exif's -s takes one value; a --scene fills it with one number, not a list (a deep fuzz found a traceback)
    path = str(Path(__file__).parent / "data" / "exif" / "fujifilm_subject.jpg")
    by_scene = run("exif", "--scene", "portrait-85", "--lens", "sony-fe-85mm-f1.8", path, "--format", "json")
    typed = run("exif", "--scene", "portrait-85", "--lens", "sony-fe-85mm-f1.8", "-s", "2m", path, "--format", "json")
    assert by_scene.exit_code == typed.exit_code == 0, by_scene.stderr
    (row,), (same,) = json.loads(by_scene.stdout), json.loads(typed.stdout)
    assert row["focus_distance_mm"] == same["focus_distance_mm"] == 2000.0  # the scene's 2 m
