"""ExifTool's rules in camtool.exif.sensor and camtool.plans.photo, called directly on readings built here.

Expected values are ExifTool 12.57's definitions, computed here by hand from
``Image::ExifTool::Exif::CalcScaleFactor35efl``, ``Image::ExifTool::Canon::CalcSensorDiag``
and the Composite tags' ValueConv (https://exiftool.org/TagNames/Composite.html), quoted
beside each test; not from camtool.
"""

from __future__ import annotations

import math

import pytest

from camtool.exif.reader import Reading
from camtool.exif.sensor import canon_plane_ok, exiftool_scale_factor
from camtool.plans.photo import photo_answer

DIAGONAL = math.sqrt(36 * 36 + 24 * 24)


def test_the_35mm_equivalent_comes_first() -> None:
    # "return $foc35 / $focal if $focal and $foc35": before any focal-plane data
    scale = exiftool_scale_factor(focal_length_mm=28.0, focal_length_35mm=42.0, diagonal_mm=9.04,
                                  px_per_mm=(100.0, 100.0), sizes=((3000, 2000, "Exif"),))
    assert scale is not None and scale.factor == 1.5


def test_canon_sensor_before_olympus_diagonal_and_digital_zoom() -> None:
    # the Canon diagonal replaces any other; times Canon's digital zoom ratio
    scale = exiftool_scale_factor(focal_length_mm=50.0, focal_length_35mm=None, digital_zoom=2.0,
                                  diagonal_mm=9.04, canon_sensor_mm=(22.5, 15.0))
    assert scale is not None and scale.factor == pytest.approx(DIAGONAL * 2 / math.hypot(22.5, 15.0), rel=1e-15)


def test_canon_plane_size_only_at_4_3_or_3_2() -> None:
    # "abs($a-1.3333) < .1 or abs($a-1.5) < .1"
    assert canon_plane_ok(4.0, 3.0) and canon_plane_ok(3.0, 2.0) and not canon_plane_ok(16.0, 9.0)
    scale = exiftool_scale_factor(focal_length_mm=7.0, focal_length_35mm=None, plane_size_mm=(7.2644, 5.461))
    assert scale is not None and scale.factor == pytest.approx(DIAGONAL / math.hypot(7.2644, 5.461), rel=1e-15)
    # a 16:9 pair is passed over for the focal-plane resolution
    scale = exiftool_scale_factor(focal_length_mm=7.0, focal_length_35mm=None, plane_size_mm=(16.0, 9.0),
                                  px_per_mm=(200.0, 200.0), sizes=((4000, 3000, "Exif"),))
    assert scale is not None and scale.factor == pytest.approx(DIAGONAL / math.hypot(20.0, 15.0), rel=1e-15)


def test_resolution_takes_the_first_size_of_a_sane_aspect_and_a_sane_diagonal() -> None:
    # sizes with w/h outside 0.5 to 2 are skipped; then diag = hypot(w/xres, h/yres) must lie in (1, 100) mm
    scale = exiftool_scale_factor(focal_length_mm=7.0, focal_length_35mm=None, px_per_mm=(200.0, 200.0),
                                  sizes=((8000, 1, "Exif"), (4000, 3000, "Canon"), (300, 200, "image size")))
    assert scale is not None and scale.factor == pytest.approx(DIAGONAL / 25.0, rel=1e-15)
    assert "Canon" in scale.source
    assert exiftool_scale_factor(focal_length_mm=7.0, focal_length_35mm=None, px_per_mm=(2000.0, 2000.0),
                                 sizes=((150, 91, "image size"),)) is None  # 0.09 mm: "return undef"
    assert exiftool_scale_factor(focal_length_mm=7.0, focal_length_35mm=None) is None


def _reading(**fields: object) -> Reading:
    base: dict[str, object] = {"focal_length_mm": 50.0, "f_number": 8.0, "shutter_s": 1 / 125, "iso": 400.0,
                               "focal_length_35mm": 75.0, "sources": {}}
    base.update(fields)
    return Reading(**base)  # type: ignore[arg-type]


def exiftool_dof(f: float, n: float, c: float, d_mm: float) -> tuple[float, float]:
    """Composite:DOF in mm: t = N·c·(d − f)/f², near d/(1 + t), far d/(1 − t) (infinity when t ≥ 1)."""
    t = n * c * (d_mm - f) / (f * f)
    return d_mm / (1 + t), (d_mm / (1 - t) if t < 1 else math.inf)


def test_exiftool_distances_focus_tag_subject_distance_and_canon_mean() -> None:
    c = DIAGONAL / 1.5 / 1440
    # a FocusDistance tag: the DOF's distance and the FOV's correction, corr = 1 + f/(d − f)
    row = photo_answer(_reading(focus_tag_mm=5000.0, subject_distance_mm=9000.0), path="a.jpg",
                       convention="exiftool").values
    near, far = exiftool_dof(50, 8, c, 5000.0)
    assert (row["near_mm"], row["far_mm"]) == (pytest.approx(near, rel=1e-12), pytest.approx(far, rel=1e-12))
    corr = 1 + 50 / (5000 - 50)
    assert row["horizontal_deg"] == pytest.approx(math.degrees(2 * math.atan2(36, 2 * 50 * 1.5 * corr)), rel=1e-6)
    # the field width 2·d·tan(FOV/2) at d = 5 m
    assert row["field_width_mm"] == pytest.approx(2 * 5000 * 36 / (2 * 50 * 1.5 * corr), rel=1e-12)
    # SubjectDistance: the DOF's distance, no FOV correction
    row = photo_answer(_reading(subject_distance_mm=9000.0), path="a.jpg", convention="exiftool").values
    assert row["near_mm"] == pytest.approx(exiftool_dof(50, 8, c, 9000.0)[0], rel=1e-12)
    assert row["horizontal_deg"] == pytest.approx(math.degrees(2 * math.atan2(36, 2 * 50 * 1.5)), rel=1e-12)
    assert row["field_width_mm"] is None
    # Canon's pair in ExifTool's metres: upper 655.35 (65535, infinity), lower 5.46; d = their mean
    row = photo_answer(_reading(bracket_m=(655.35, 5.46)), path="a.jpg", convention="exiftool").values
    assert row["focus_distance_mm"] == pytest.approx((655.35 + 5.46) / 2 * 1000, rel=1e-15)
    assert row["near_mm"] == pytest.approx(exiftool_dof(50, 8, c, (655.35 + 5.46) / 2 * 1000)[0], rel=1e-12)
    # HyperfocalDistance f²/(N·c), LightValue log2(N²/t · 100/ISO), with or without a distance
    assert row["hyperfocal_mm"] == pytest.approx(50 * 50 / (8 * c), rel=1e-12)
    assert row["ev100"] == pytest.approx(math.log2(64 * 125 * 100 / 400), rel=1e-12)
    assert row["convention"] == "exiftool" and row["distance_from"] == "lens" and row["model"] == "thin"


def test_exiftool_iso_is_the_tag_as_written() -> None:
    row = photo_answer(_reading(iso=102400.0, iso_speed_ratings=65535.0), path="a.jpg", convention="exiftool").values
    assert row["ev100"] == pytest.approx(math.log2(64 * 125 * 100 / 65535), rel=1e-12)
    row = photo_answer(_reading(iso=102400.0, iso_speed_ratings=65535.0), path="a.jpg").values
    assert row["ev100"] == pytest.approx(math.log2(64 * 125 * 100 / 102400), rel=1e-12)


def test_an_unknown_convention_is_refused() -> None:
    with pytest.raises(ValueError, match="unknown convention"):
        photo_answer(_reading(), path="a.jpg", convention="darktable")


def test_warnings_name_what_was_assumed() -> None:
    answer = photo_answer(_reading(pixels_w=6000, pixels_h=4000, stored_w=300, stored_h=200,
                                   sources={"pixels": "Photo.PixelXDimension/PixelYDimension"}), path="a.jpg")
    assert answer.ok and len(answer.warnings) == 2
    assert "holds 300×200 px where its metadata" in answer.warnings[0]
    assert "35 mm-equivalent" in answer.warnings[1] and "1.5:1" in answer.warnings[1]
    assert answer.values["warnings"] == "; ".join(answer.warnings)
    assert answer.message().count("warning: ") == 2
    # a sensor given by the caller is no guess
    given = photo_answer(_reading(), path="a.jpg", sensor_mm=(36.0, 24.0))
    assert given.warnings == () and given.values["warnings"] is None


def test_a_raw_file_is_not_called_resized() -> None:
    # libexiv2's pixel size of a raw file may be its embedded preview's: no resize warning for one
    reading = _reading(pixels_w=6000, pixels_h=4000, stored_w=160, stored_h=120,
                       sources={"pixels": "Photo.PixelXDimension/PixelYDimension"})
    assert any("resized" in w for w in photo_answer(reading, path="a.JPG").warnings)
    assert not any("resized" in w for w in photo_answer(reading, path="a.CR2").warnings)
