"""camtool.plans.photo called directly: a reader's record and keyword arguments in, a named answer per file out.

Independent values: ExifTool's Composite tags (https://exiftool.org/TagNames/Composite.html:
CircleOfConfusion = √(24² + 36²)/(ScaleFactor35efl·1440), DOF near = d/(1 + t), far =
d/(1 − t) with t = N·c·(d − f)/f², LightValue = log2(N²/t·100/ISO)), the crop
factor as the ratio of diagonals, and the px:K rule (K pixel pitches). The
records are built here, so no python-exiv2 is needed.
"""

from __future__ import annotations

import math
from pathlib import Path
from types import SimpleNamespace

import pytest

from camtool.core.units import UnitError
from camtool.exif.reader import Reading
from camtool.plans.photo import (
    KEYS,
    PresetIndex,
    check_coc_rule,
    names_from_lines,
    photo_answer,
    photo_files,
    unreadable_answer,
)

FULL_FRAME_DIAGONAL = math.hypot(36.0, 24.0)
EXIFTOOL = {"coc_rule": "d/1440", "distance_from": "lens", "model": "thin"}


def reading(**fields: object) -> Reading:
    base: dict[str, object] = {"make": "Canon", "model": "Canon EOS 5D", "focal_length_mm": 50.0, "f_number": 8.0,
                               "shutter_s": 1 / 125, "iso": 400.0, "plane_width_mm": 36.0, "plane_height_mm": 24.0,
                               "focus_distance_mm": 3350.0,
                               "sources": {"sensor": "Photo.FocalPlaneX/YResolution", "f_number": "Photo.FNumber"}}
    base.update(fields)
    return Reading(**base)  # type: ignore[arg-type]


def test_exiftool_composites() -> None:
    answer = photo_answer(reading(), path="a.jpg", **EXIFTOOL)
    row = answer.values
    assert list(row) == KEYS and answer.ok and answer.message() == ""
    c = FULL_FRAME_DIAGONAL / 1440
    assert row["coc_mm"] == pytest.approx(c, rel=1e-12) and row["coc_source"].startswith("d/1440")
    t = 8 * c * (3350 - 50) / 50**2
    assert row["near_mm"] == pytest.approx(3350 / (1 + t), rel=1e-12)
    assert row["far_mm"] == pytest.approx(3350 / (1 - t), rel=1e-12)
    assert row["ev100"] == pytest.approx(math.log2(8**2 * 125 * 100 / 400), rel=1e-12)
    assert row["sensor_source"] == "Photo.FocalPlaneX/YResolution" and row["f_number_source"] == "Photo.FNumber"
    assert row["camera"] == "Canon EOS 5D"  # the make is not repeated


def test_crop_factor_from_the_35mm_equivalent() -> None:
    # ScaleFactor35efl = 50/25 = 2: the diagonal 43.27/2 mm with the image's 4:3 aspect ratio
    answer = photo_answer(reading(plane_width_mm=None, plane_height_mm=None, focal_length_mm=25.0,
                                  focal_length_35mm=50.0, pixels_w=4000, pixels_h=3000), path="o.jpg", **EXIFTOOL)
    row = answer.values
    assert row["crop_factor"] == pytest.approx(2.0, rel=1e-12)
    assert math.hypot(row["sensor_width_mm"], row["sensor_height_mm"]) == pytest.approx(FULL_FRAME_DIAGONAL / 2)
    assert row["sensor_width_mm"] / row["sensor_height_mm"] == pytest.approx(4 / 3, rel=1e-12)
    assert row["coc_mm"] == pytest.approx(FULL_FRAME_DIAGONAL / (2 * 1440), rel=1e-12)


def test_what_the_caller_gives_wins() -> None:
    answer = photo_answer(reading(focus_distance_min_mm=3200.0, focus_distance_max_mm=3500.0), path="a.jpg",
                          sensor_mm=(24.0, 16.0), coc_mm=0.02, distance_mm=2000.0,
                          given_as={"sensor_mm": "--crop", "coc_mm": "--coc", "distance_mm": "-s"})
    row = answer.values
    assert row["crop_factor"] == pytest.approx(1.5, rel=1e-12) and row["sensor_source"] == "--crop"
    assert (row["coc_mm"], row["coc_source"]) == (0.02, "--coc")
    assert (row["focus_distance_mm"], row["focus_distance_source"]) == (2000.0, "-s")
    assert row["focus_distance_min_mm"] is None and row["near_min_mm"] is None  # the file's bracket is dropped
    default = photo_answer(reading(), path="a.jpg", distance_mm=2000.0).values
    assert default["focus_distance_source"] == "distance_mm"  # the parameter's name without a label


def test_the_bracket_ends_bound_the_limits() -> None:
    row = photo_answer(reading(focus_distance_min_mm=3200.0, focus_distance_max_mm=3500.0), path="a.jpg",
                       **EXIFTOOL).values
    c = FULL_FRAME_DIAGONAL / 1440
    for end, d in (("min", 3200.0), ("max", 3500.0)):
        t = 8 * c * (d - 50) / 50**2
        assert row[f"near_{end}_mm"] == pytest.approx(d / (1 + t), rel=1e-12)
        assert row[f"far_{end}_mm"] == pytest.approx(d / (1 - t), rel=1e-12)


def test_px_rule_takes_the_pitch_from_the_image() -> None:
    # 36 mm over 6000 px: a 6 µm pitch; px:2 is two pitches
    row = photo_answer(reading(pixels_w=6000, pixels_h=4000), path="a.jpg", coc_rule="px:2").values
    assert row["coc_mm"] == pytest.approx(0.012, rel=1e-12)
    lacking = photo_answer(reading(), path="a.jpg", coc_rule="px:2")
    assert lacking.values["coc_mm"] is None and lacking.ok  # a file's lack, not an unusable value
    shown = {"coc_rule": "--coc-rule", "pixel_pitch_mm": "--pixel-pitch"}
    assert lacking.message(shown).startswith("no pixel pitch for --coc-rule px:2 ")
    assert lacking.message(shown).endswith("give --pixel-pitch")


def test_missing_values_are_named_with_what_would_supply_them() -> None:
    answer = photo_answer(Reading(focal_length_mm=35.0), path="p.jpg")
    assert answer.ok and all(answer.values[k] is None for k in ("f_number", "coc_mm", "near_mm", "ev"))
    text = answer.message({"sensor": "--sensor", "crop": "--crop", "distance_mm": "-s"})
    assert text.startswith("no sensor size") and "give --sensor or --crop" in text
    assert "no f-number" in text and "give -s" in text
    assert "{" not in answer.message()  # unnamed parameters show their own names
    assert "give sensor or crop" in answer.message()


def test_unusable_values_are_the_files_problem() -> None:
    # FocalLengthIn35mmFilm 1 over a 50 mm focal length: a crop factor of 0.02, outside --crop's range
    answer = photo_answer(reading(plane_width_mm=None, plane_height_mm=None, focal_length_35mm=1.0), path="x.jpg")
    assert not answer.ok and answer.values["crop_factor"] is None
    assert answer.message().startswith("Exif.Photo.FocalLengthIn35mmFilm 1 over FocalLength 50 mm: a crop factor")
    assert "no sensor size" not in answer.message()  # named once
    # d/10 on a full-frame sensor is 4.33 mm, beyond --coc's 1 mm
    wide = photo_answer(reading(), path="x.jpg", coc_rule="d/10")
    assert not wide.ok and wide.values["coc_mm"] is None and "is outside the valid range" in wide.message()


def test_a_rule_that_does_not_parse_is_the_callers_error() -> None:
    check_coc_rule(None)
    with pytest.raises(UnitError):
        check_coc_rule("nonsense")
    with pytest.raises(UnitError):
        photo_answer(reading(), path="a.jpg", coc_rule="nonsense")


def test_lens_and_camera_presets_matched_by_name() -> None:
    lens = SimpleNamespace(id="acme-50", name="Acme 50mm f/2", aliases=(), is_zoom=False, focal_min_mm=50.0,
                           pupil_magnification=None, hiatus_mm=None, prescription=None)
    body = SimpleNamespace(id="acme-one", name="Acme One", aliases=(), sensor=SimpleNamespace(width_mm=23.5,
                                                                                              height_mm=15.6))
    loads: list[str] = []

    def load() -> SimpleNamespace:
        loads.append("db")
        return SimpleNamespace(all=lambda kind: [lens] if kind == "lens" else [body])

    index = PresetIndex(load)
    record = Reading(make="Acme", model="One", lens="ACME 50MM F2", f_number=2.0, sources={"lens": "Photo.LensModel"})
    row = photo_answer(record, path="a.jpg", presets=index).values
    assert row["lens_source"] == "Photo.LensModel = preset acme-50"
    assert (row["focal_length_mm"], row["focal_length_source"]) == (50.0, "lens preset acme-50")
    assert row["sensor_source"] == "camera preset acme-one"
    assert row["crop_factor"] == pytest.approx(FULL_FRAME_DIAGONAL / math.hypot(23.5, 15.6), rel=1e-12)
    photo_answer(record, path="b.jpg", presets=index)
    assert loads == ["db", "db"]  # once per kind, kept for the next file


def test_unreadable_file_is_a_row_of_nulls() -> None:
    answer = unreadable_answer("bad\x1b.jpg", "truncated or corrupt")
    assert answer.values["file"] == "bad\\x1b.jpg" and not answer.ok
    assert all(v is None for k, v in answer.values.items() if k != "file")
    assert answer.message() == "truncated or corrupt"


def test_files_from_paths(tmp_path: Path) -> None:
    (tmp_path / "sub").mkdir()
    for name in ("b.JPG", "a.nef", "notes.txt", "sub/c.jpg"):
        (tmp_path / name).write_bytes(b"")
    found = photo_files([str(tmp_path), "x.jpg"], recursive=True)
    assert [Path(p).relative_to(tmp_path).as_posix() for p in found.files[:-1]] == ["a.nef", "b.JPG", "sub/c.jpg"]
    assert found.files[-1] == "x.jpg" and found.failed == ()
    flat = photo_files([str(tmp_path)])
    assert flat.files == () and "is a directory" in flat.failed[0][1]
    assert names_from_lines([b"one.jpg\r\n", b"  \n", b"caf\xe9.jpg\n"]) == ["one.jpg", "caf\udce9.jpg"]
