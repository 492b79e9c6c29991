"""A fixed lens brings its focal length and f-number: every camera with a built-in lens names it.

The figures of the lens presets added for the compacts are checked against the pages their
``source`` cites, and the 35 mm equivalents the makers state against focal length x crop factor.
"""

from __future__ import annotations

import math

import pytest
from cli_helpers import run, run_json
from test_cameras_fifth_pass import PHONES_FIFTH_PASS
from test_phones_2026 import PHONES_2026
from test_phones_vivo_huawei import PHONES_VIVO_HUAWEI

from camtool.plans.equipment import resolve_equipment
from camtool.presets import PresetFileError, load_db, validate_file

FULL_FRAME_DIAGONAL_MM = math.hypot(36.0, 24.0)


pytestmark = pytest.mark.usefixtures("no_user_presets")  # the shipped presets alone


# Cameras with mount: fixed lens that name no lens, and why.
NO_LENS_PRESET = {
    # A zoom: DPReview's spec page gives 24-200 mm equivalent, F2.8-4.5 and 8 cm at the wide end, but
    # no page read gives the closest focus at the long end, which every shipped zoom must have
    # (tests/test_presets_consistency.py, test_every_shipped_zoom_has_per_focal_length_rows).
    "sony-rx100-vii",
    # Zooms too, and no page read gives their closest focus (nor, for the ZV-1 and PowerShot V1, their real focal
    # lengths): DPReview's ZV-1 page (24-70 mm equivalent, 5 cm without its plane), Notebookcheck's PowerShot V1
    # (16-50 mm equivalent), fotografia.it's D-Lux 8 (10.9-34 mm).
    "sony-zv-1",
    "canon-powershot-v1",
    "leica-d-lux-8",
    # A prime whose page gives a 22 mm equivalent in its specifications and 20 mm in its conclusion, and no real
    # focal length (DPReview's ZV-1F page).
    "sony-zv-1f",
    # DPReview's archived pages give these compacts' 35 mm equivalents and a closest focus without its plane, not
    # their real focal lengths (tests/test_cameras_second_pass.py); the Q2 Monochrom and TG-7 carry their
    # predecessors' figures.
    "canon-powershot-g7-x-mark-iii", "canon-powershot-g5-x-mark-ii", "canon-powershot-g9-x-mark-ii",
    "canon-powershot-g1-x-mark-iii", "panasonic-lumix-zs200", "fujifilm-x100f", "fujifilm-xf10", "leica-q2",
    "leica-q2-monochrom", "olympus-tough-tg-6", "om-system-tough-tg-7",
}


def fixed_lens_cameras():
    return [camera for camera in load_db().all("camera") if camera.mount == "fixed lens"]


def test_every_fixed_lens_camera_names_its_lens():
    cameras = fixed_lens_cameras()
    # with the Leica Q3 43, Ricoh GR IV, Fujifilm GFX100RF, Xiaomi 15 Ultra, iPhone Air, Sony RX1R III and Fujifilm
    # X half (their lenses in phone-lenses.yaml), and the Sony ZV-1 and ZV-1F, Canon PowerShot V1 and Leica D-Lux 8
    # (no lens preset, above), and the eleven compacts of the second comparison (no lens preset either), and the
    # flagship phones of tests/test_phones_2026.py, tests/test_cameras_fifth_pass.py and tests/test_phones_vivo_huawei.py
    assert len(cameras) == 40 + len(PHONES_2026) + len(PHONES_FIFTH_PASS) + len(PHONES_VIVO_HUAWEI)
    named = {camera.id for camera in cameras if camera.lens_id is not None}
    assert named == {camera.id for camera in cameras} - NO_LENS_PRESET
    db = load_db()
    for camera in cameras:
        if camera.lens_id is None:
            continue
        lens = db.lens(camera.lens_id)
        assert lens.mount == "fixed lens", camera.id
        # the lens is made for this camera's sensor: the same format, found by the lens's own reference
        own = db.sensor(lens.sensor_id)
        assert (own.width_mm, own.height_mm) == (camera.sensor.width_mm, camera.sensor.height_mm), camera.id
        if camera.category == "phone":
            assert camera.lens_id == f"{camera.id}-main"


def test_no_camera_with_an_interchangeable_lens_names_one():
    for camera in load_db().all("camera"):
        if camera.mount != "fixed lens":
            assert camera.lens_id is None, camera.id


@pytest.mark.parametrize("camera", sorted(c.id for c in fixed_lens_cameras() if c.id not in NO_LENS_PRESET))
def test_a_fixed_lens_camera_needs_no_focal_length(camera):
    db = load_db()
    lens = db.lens(db.camera(camera).lens_id)
    # a lens whose aperture no launch page gives (the Vivo X200 Ultra's modules) takes any f-number in camtool's range
    widest = lens.f_number_min if lens.f_number_min is not None else 2.8
    # With the f-number given, the focal length is the lens's own.
    (row,) = run_json("dof", "--camera", camera, "-N", f"{widest:g}", "-s", "2m")
    assert row["focal_length_mm"] == lens.focal_length_mm
    # The same answer as naming the lens and its focal length by hand.
    (by_hand,) = run_json("dof", "--camera", camera, "--lens", lens.id, "-f", f"{lens.focal_length_mm!r}",
                          "-N", f"{widest:g}", "-s", "2m")
    assert row == by_hand
    if lens.f_number_min is not None and lens.f_number_max == lens.f_number_min:
        # One aperture: neither -f nor -N.
        (bare,) = run_json("dof", "--camera", camera, "-s", "2m")
        assert bare == row


def test_ricoh_gr_iii_without_focal_length():
    # Ricoh GR III: 18.3 mm f/2.8 (tekgenius.pt; DPReview F2.8-16).
    (row,) = run_json("dof", "--camera", "ricoh-gr-iii", "-N", "2.8", "-s", "2m")
    assert row["focal_length_mm"] == 18.3 and row["f_number"] == 2.8
    # its sensor is the camera's 23.5 x 15.6 mm (DPReview), the CoC d/1500 of its diagonal
    assert row["coc_mm"] == pytest.approx(math.hypot(23.5, 15.6) / 1500)
    # the camera's pixel pitch stays in use: 6000 px across 23.5 mm
    (px,) = run_json("dof", "--camera", "ricoh-gr-iii", "-N", "2.8", "-s", "2m", "--coc-rule", "px:2")
    assert px["coc_mm"] == pytest.approx(2 * 23.5 / 6000)
    # without -N a built-in lens with a range of apertures answers wide open (f/2.8, DPReview)
    (bare,) = run_json("dof", "--camera", "ricoh-gr-iii", "-s", "2m")
    assert bare == row


def test_a_fixed_lens_refuses_what_it_cannot_do():
    wide = run("dof", "--camera", "ricoh-gr-iii", "-f", "50", "-N", "4", "-s", "2m")
    assert wide.exit_code == 2 and "18.3 mm" in wide.stderr and wide.stderr.count("\n") == 1
    small = run("dof", "--camera", "ricoh-gr-iii", "-N", "22", "-s", "2m")
    assert small.exit_code == 2 and "f/2.8 to f/16" in small.stderr


def test_a_named_lens_wins_over_the_cameras_own():
    (row,) = run_json("dof", "--camera", "ricoh-gr-iii", "--lens", "nikon-z-24mm-f1.8-s", "-N", "4", "-s", "2m")
    assert row["focal_length_mm"] == 24.0
    db = load_db
    found = resolve_equipment(camera="google-pixel-8-pro", lens="google-pixel-8-pro-telephoto", database=db)
    assert found.lens.id == "google-pixel-8-pro-telephoto"
    assert resolve_equipment(camera="google-pixel-8-pro", database=db).lens.id == "google-pixel-8-pro-main"
    assert resolve_equipment(camera="nikon-z-8", database=db).lens is None


def test_a_scene_lens_counts_as_named(tmp_path):
    presets = tmp_path / "scene.yaml"
    presets.write_text("scenes:\n  - id: gr-with-a-z-lens\n    source: test\n    camera: ricoh-gr-iii\n"
                       "    lens: nikon-z-24mm-f1.8-s\n", encoding="utf-8")
    db = load_db([presets])
    found = resolve_equipment(scene="gr-with-a-z-lens", sensor_given=False, database=lambda: db)
    assert found.camera.id == "ricoh-gr-iii" and found.lens.id == "nikon-z-24mm-f1.8-s"


def test_an_unknown_camera_lens_names_the_camera_and_key(tmp_path):
    presets = tmp_path / "mine.yaml"
    presets.write_text("cameras:\n  - id: my-compact\n    source: test\n    sensor: 1-inch\n"
                       "    mount: fixed lens\n    lens: no-such-lens\n", encoding="utf-8")
    messages = validate_file(presets)
    assert len(messages) == 1 and "my-compact" in messages[0] and "lens" in messages[0]
    with pytest.raises(PresetFileError) as error:
        load_db([presets]).camera("my-compact")
    assert error.value.key == "lens" and "no-such-lens" in str(error.value)


def test_a_lens_whose_sensor_is_its_camera_builds(tmp_path):
    # The camera names the lens and the lens names the camera (for its sensor): no endless build.
    presets = tmp_path / "mine.yaml"
    presets.write_text("cameras:\n  - id: my-compact\n    source: test\n    sensor: {width_mm: 13.2, height_mm: 8.8}\n"
                       "    mount: fixed lens\n    lens: my-compact-lens\n"
                       "lenses:\n  - id: my-compact-lens\n    source: test\n    focal_length_mm: 10\n"
                       "    f_number_min: 2.8\n    f_number_max: 2.8\n    mount: fixed lens\n    sensor: my-compact\n",
                       encoding="utf-8")
    assert validate_file(presets) == []
    (row,) = run_json("dof", "--presets", str(presets), "--camera", "my-compact", "-s", "2m")
    assert row["focal_length_mm"] == 10.0 and row["f_number"] == 2.8
    assert row["coc_mm"] == pytest.approx(math.hypot(13.2, 8.8) / 1500)


# --- the new figures against the pages cited in each entry ---------------------------------------

# (lens, key, value) as the page named in the entry's source gives it.
CITED = [
    # tekgenius.pt, GR III announcement: "prime de 18.3mm f/2.8-f/16".
    ("ricoh-gr-iii-lens", "focal_length_mm", 18.3),
    # DPReview's GR III page (open-product-data/digital-cameras, database/ricoh_griii.yaml):
    # MaximumAperture F2.8-16, MacroFocusRange 6 cm.
    ("ricoh-gr-iii-lens", "f_number_min", 2.8),
    ("ricoh-gr-iii-lens", "f_number_max", 16),
    ("ricoh-gr-iii-lens", "min_focus_mm", 60),
    # Better Photography, X100VI launch: "23mm f2.0 lens"; note.com (chocog_1225): closest focus 10 cm.
    ("fujifilm-x100vi-lens", "focal_length_mm", 23),
    ("fujifilm-x100vi-lens", "f_number_min", 2),
    ("fujifilm-x100vi-lens", "min_focus_mm", 100),
]


@pytest.mark.parametrize(("lens_id", "key", "value"), CITED)
def test_fixed_lens_figures_against_the_cited_pages(lens_id, key, value):
    lens = load_db().lens(lens_id)
    attribute = {"focal_length_mm": "focal_min_mm"}.get(key, key)
    assert getattr(lens, attribute) == value


def test_unconfirmed_figures_are_left_out_or_flagged():
    db = load_db()
    x100 = db.lens("fujifilm-x100vi-lens")
    # no page gives the X100VI's smallest aperture or a magnification that fits its closest focus
    assert x100.f_number_max is None and "f_number_max not found" in x100.notes
    assert x100.max_magnification is None and x100.approximate
    gr = db.lens("ricoh-gr-iii-lens")
    assert gr.max_magnification is None and gr.approximate and "measured from" in gr.notes


# (camera, 35 mm-equivalent focal length the maker states), from the pages cited in the lens entry.
STATED_EQUIVALENT = [
    ("ricoh-gr-iii", 28.0),  # DPReview FocalLengthEquiv 28 mm
    ("fujifilm-x100vi", 35.0),  # Better Photography, Wikipedia: 35 mm equivalent
    ("leica-q3", 28.0),  # Summilux 28: a full-frame lens, its equivalent is itself
    ("apple-iphone-16-pro", 24.0),  # Apple: 48 MP Fusion 24 mm
]


@pytest.mark.parametrize(("camera", "equivalent"), STATED_EQUIVALENT)
def test_stated_equivalent_against_focal_length_times_crop(camera, equivalent):
    db = load_db()
    body = db.camera(camera)
    lens = db.lens(body.lens_id)
    crop = FULL_FRAME_DIAGONAL_MM / math.hypot(body.sensor.width_mm, body.sensor.height_mm)
    assert lens.focal_min_mm * crop == pytest.approx(equivalent, rel=0.03)
