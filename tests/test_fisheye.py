"""Fisheye projections: the mappings against mpmath, the shipped fisheyes against their published angles and circles."""

from __future__ import annotations

import math

import mpmath
import numpy as np
import pytest
from cli_helpers import run, run_json
from conftest import point_xdg_at, presets_home

from camtool.core.errors import DomainError
from camtool.geometry.fov import angle_of_view_deg, field_size_mm
from camtool.geometry.projection import (
    PROJECTIONS,
    fisheye_angle_of_view_deg,
    fisheye_field_size_mm,
    half_angle_deg,
    image_height_mm,
)
from camtool.plans.fov import field_of_view
from camtool.presets import PresetFileError, load_db


@pytest.fixture(autouse=True)
def isolated(request, monkeypatch, shared_presets_home):
    root = presets_home(request, shared_presets_home, "tmp_path")
    point_xdg_at(root, monkeypatch)
    return root


MPMATH = {
    # Wikipedia, "Fisheye lens", mapping functions, evaluated with mpmath at 30 digits
    "rectilinear": lambda f, t: f * mpmath.tan(t),
    "equidistant": lambda f, t: f * t,
    "equisolid": lambda f, t: 2 * f * mpmath.sin(t / 2),
    "orthographic": lambda f, t: f * mpmath.sin(t),
    "stereographic": lambda f, t: 2 * f * mpmath.tan(t / 2),
}


@pytest.mark.parametrize("projection", PROJECTIONS)
@pytest.mark.parametrize("angle", [1.0, 20.0, 45.0, 70.0, 89.0])
def test_mappings_against_mpmath_and_their_inverse(projection, angle):
    mpmath.mp.dps = 30
    expected = float(MPMATH[projection](mpmath.mpf(8), mpmath.radians(angle)))
    r = image_height_mm(8.0, angle, projection)
    assert r == pytest.approx(expected, rel=1e-13)
    assert half_angle_deg(r, 8.0, projection) == pytest.approx(angle, rel=1e-12)


def test_arrays_give_the_scalars():
    angles = np.array([10.0, 50.0, 80.0])
    for projection in PROJECTIONS:
        heights = image_height_mm(8.0, angles, projection)
        assert list(heights) == [image_height_mm(8.0, float(a), projection) for a in angles]
        assert list(half_angle_deg(heights, 8.0, projection)) == pytest.approx(list(angles), rel=1e-12)


def test_the_rectilinear_mapping_is_the_angle_of_view_formula():
    # one formula path: the rectilinear projection gives camtool.geometry.fov's 2·atan(h / 2f(1 + m/P))
    for size, f, m, p in ((36.0, 50.0, 0.0, 1.0), (24.0, 100.0, 0.5, 0.5), (43.27, 14.0, 0.1, 2.0)):
        assert fisheye_angle_of_view_deg(size, f, "rectilinear", m, p) == pytest.approx(
            angle_of_view_deg(size, f, m, p), rel=1e-13)
    # and the field at the subject, 2u·tan(α/2) with u = f(1 + 1/m), is the sensor size over m
    for m in (0.01, 0.1, 1.0):
        u = 50.0 * (1 + 1 / m)
        angle = angle_of_view_deg(36.0, 50.0, m)
        assert fisheye_field_size_mm(angle, u) == pytest.approx(field_size_mm(36.0, m), rel=1e-12)


def test_the_edges_of_each_mapping():
    # identities: equisolid reaches r = 2f at 180°, orthographic r = f at 90°, stereographic r = 2f at 90°
    assert image_height_mm(10.0, 180.0, "equisolid") == pytest.approx(20.0, rel=1e-15)
    assert image_height_mm(10.0, 90.0, "orthographic") == pytest.approx(10.0, rel=1e-15)
    assert image_height_mm(10.0, 90.0, "stereographic") == pytest.approx(20.0, rel=1e-15)
    # beyond what the mapping can reach, the whole field it holds lies inside
    assert half_angle_deg(25.0, 10.0, "equisolid") == 180.0
    assert half_angle_deg(12.0, 10.0, "orthographic") == 90.0
    assert fisheye_field_size_mm(180.0, 1000.0) == math.inf
    with pytest.raises(DomainError):
        image_height_mm(8.0, 10.0, "fisheye")


def test_fisheye_nikkor_6mm_against_nikons_manual():
    # Nikon's Fisheye-NIKKOR 6mm f/2.8 manual: 220°, equidistant (y = f·θ), a 23 mm circle
    lens = load_db().lens("fisheye-nikkor-6mm")
    assert (lens.projection, lens.field_max_deg) == ("equidistant", 220.0)
    assert 2 * image_height_mm(6.0, 110.0, "equidistant") == pytest.approx(23.0, rel=0.005)
    assert 2 * half_angle_deg(11.5, 6.0, "equidistant") == pytest.approx(220.0, rel=0.005)
    # on full frame the circle lies inside the frame: every angle is the lens's 220°
    (row,) = run_json("fov", "--lens", "fisheye-nikkor-6mm")
    assert (row["horizontal_deg"], row["vertical_deg"], row["diagonal_deg"]) == (220.0, 220.0, 220.0)
    assert row["projection"] == "equidistant"


def test_op_fisheye_nikkor_is_orthographic_with_a_2f_circle():
    # mir.com.my / nikonschool.it: OP Fisheye-Nikkor 10mm f/5.6, orthographic, circular 180°
    assert 2 * image_height_mm(10.0, 90.0, "orthographic") == pytest.approx(20.0, rel=1e-15)
    (row,) = run_json("fov", "--lens", "op-fisheye-nikkor-10mm")
    assert (row["horizontal_deg"], row["vertical_deg"], row["diagonal_deg"]) == (180.0, 180.0, 180.0)
    # on APS-C (23.6 × 15.6 mm) the 20 mm circle still spans the width but not the height:
    # 2·asin(7.8/10) = 102.5°
    (row,) = run_json("fov", "--lens", "op-fisheye-nikkor-10mm", "--sensor", "aps-c")
    assert row["horizontal_deg"] == 180.0
    assert row["vertical_deg"] == pytest.approx(2 * math.degrees(math.asin(7.8 / 10)), rel=1e-12)


def test_sigma_4_5mm_circle_against_its_review():
    # dc.watch.impress.co.jp: 180° in a 12.3 mm circle on APS-C; an ideal equisolid 4.5 mm draws 12.73 mm
    assert 2 * image_height_mm(4.5, 90.0, "equisolid") == pytest.approx(12.3, rel=0.04)
    (row,) = run_json("fov", "--lens", "sigma-4.5-fisheye", "--sensor", "aps-c")
    assert row["vertical_deg"] == 180.0  # 15.6 mm high: more than the circle


def test_eight_mm_fisheye_on_full_frame_covers_180_degrees():
    # the case: fov -f 8 answered 139.4° (rectilinear); an 8 mm circular fisheye on full frame covers 180°
    (row,) = run_json("fov", "-f", "8")
    assert row["diagonal_deg"] == pytest.approx(2 * math.degrees(math.atan(math.hypot(36, 24) / 16)), rel=1e-12)
    for projection in ("equidistant", "equisolid"):
        (row,) = run_json("fov", "-f", "8", "--projection", projection)
        assert row["diagonal_deg"] == 180.0 and row["horizontal_deg"] == 180.0
    # a full-frame (diagonal) fisheye: 15 mm equisolid across 36 mm, 4·asin(18/30)
    (row,) = run_json("fov", "-f", "15", "--projection", "equisolid")
    assert row["horizontal_deg"] == pytest.approx(4 * math.degrees(math.asin(18 / 30)), rel=1e-12)
    assert row["diagonal_deg"] == 180.0


def test_focus_breathing_and_field_under_a_fisheye():
    # 15 mm equidistant focused at 1 m from the sensor: m from the thin lens, angles through f(1 + m)
    v = field_of_view(focal_length_mm=15.0, sensor_width_mm=36.0, sensor_height_mm=24.0, crop_factor=1.0,
                      wanted=1000.0, projection="equidistant").values
    m = v["magnification"]
    assert v["horizontal_deg"] == pytest.approx(math.degrees(36 / (15 * (1 + m))), rel=1e-12)
    u = 15 * (1 + 1 / m)
    assert v["field_width_mm"] == pytest.approx(2 * u * math.tan(math.radians(v["horizontal_deg"] / 2)), rel=1e-12)
    assert v["field_height_mm"] == pytest.approx(2 * u * math.tan(math.radians(v["vertical_deg"] / 2)), rel=1e-12)
    # a field of 180° or more has no bound at the subject
    (row,) = run_json("fov", "--lens", "fisheye-nikkor-6mm", "-s", "1m")
    assert row["field_width_mm"] is None and row["field_height_mm"] is None


def test_the_option_wins_over_the_preset_and_a_preset_brings_its_own():
    (row,) = run_json("fov", "--lens", "samyang-8-fisheye", "--sensor", "aps-c")
    assert row["projection"] == "stereographic"
    assert row["horizontal_deg"] == pytest.approx(4 * math.degrees(math.atan(11.8 / 16)), rel=1e-12)
    (row,) = run_json("fov", "--lens", "samyang-8-fisheye", "--sensor", "aps-c", "--projection", "rectilinear")
    assert row["projection"] == "rectilinear"
    assert row["horizontal_deg"] == pytest.approx(2 * math.degrees(math.atan(11.8 / 8)), rel=1e-12)
    # a rectilinear lens preset stays rectilinear
    (row,) = run_json("fov", "--lens", "rf-50-1.8")
    assert row["projection"] == "rectilinear"


def test_a_bad_projection_is_one_line_exit_2():
    result = run("fov", "-f", "8", "--projection", "fish")
    assert result.exit_code == 2 and result.stdout == ""
    assert "'--projection'" in result.stderr and result.stderr.count("\n") == 1


@pytest.mark.parametrize(("lines", "key"), [
    ("    projection: fish\n", "projection"),
    ("    projection: equisolid\n    field_max_deg: 0\n", "field_max_deg"),
    ("    projection: equisolid\n    field_max_deg: 400\n", "field_max_deg"),
    ("    field_max_deg: 180\n", "field_max_deg"),  # a field is a fisheye's
])
def test_bad_projection_keys_in_a_preset_file(tmp_path, lines, key):
    path = tmp_path / "bad.yaml"
    path.write_text("lenses:\n  - id: my-fisheye\n    focal_length_mm: 8\n" + lines, encoding="utf-8")
    with pytest.raises(PresetFileError) as caught:
        load_db(extra_files=(path,))
    assert key in str(caught.value) and "\n" not in str(caught.value)


def test_one_answer_for_a_fisheye_angle_whichever_way_it_is_asked(tmp_path):
    # the option, a batch cell, the lens preset and the Python API give the same stereographic angles
    import camtool

    (by_option,) = run_json("fov", "-f", "8", "--sensor", "aps-c", "--projection", "stereographic")
    (by_preset,) = run_json("fov", "--lens", "samyang-8-fisheye", "--sensor", "aps-c")
    batch = tmp_path / "scenes.csv"
    batch.write_text("focal_length,projection\n8,stereographic\n", encoding="utf-8")
    (by_cell,) = run_json("fov", "--batch", str(batch), "--sensor", "aps-c")
    api = camtool.field_of_view(8, 23.6, 15.6, projection="stereographic")
    for row in (by_option, by_preset, by_cell):
        assert (row["horizontal_deg"], row["vertical_deg"], row["diagonal_deg"]) == (
            api.horizontal_deg, api.vertical_deg, api.diagonal_deg)


def test_a_photo_taken_with_a_fisheye_preset_gets_its_angles():
    # camtool exif with --lens: the photo's angles are the fisheye's (the Fisheye-Nikkor 6 mm covers its 220°
    # every way on full frame, the 36 × 24 mm frame the file's focal-plane resolution gives)
    from camtool.exif.reader import Reading
    from camtool.plans.photo import photo_answer

    lens = load_db().lens("fisheye-nikkor-6mm")
    shot = Reading(make="Nikon", model="Z 6", focal_length_mm=6.0, f_number=8.0, plane_width_mm=36.0,
                   plane_height_mm=24.0, focus_distance_mm=1000.0,
                   sources={"sensor": "Photo.FocalPlaneX/YResolution", "f_number": "Photo.FNumber"})
    row = photo_answer(shot, path="f.jpg", lens_preset=lens).values
    assert (row["horizontal_deg"], row["vertical_deg"], row["diagonal_deg"]) == (220.0, 220.0, 220.0)
    row = photo_answer(shot, path="f.jpg").values  # without the preset: rectilinear, 2·atan(18/(6(1 + m)))
    assert row["horizontal_deg"] < 180.0
