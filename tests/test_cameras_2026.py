"""The camera bodies of 2020-2026 added to cameras.yaml, and the lenses of phone-lenses.yaml, against their pages.

Each figure is the one the page named in the entry's ``source`` prints (quoted next to it here); a figure no
page gives is left out of the entry, which is then ``approximate`` with notes naming it.
"""

from __future__ import annotations

import math
from pathlib import Path

import pytest
import yaml
from cli_helpers import run_json

from camtool.presets import load_db

ROOT = Path(__file__).resolve().parents[1]
FULL_FRAME_DIAGONAL_MM = math.hypot(36.0, 24.0)


@pytest.fixture(autouse=True)
def no_user_presets(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    for var, sub in (("XDG_CONFIG_HOME", "config"), ("XDG_DATA_HOME", "data"), ("XDG_CACHE_HOME", "cache")):
        monkeypatch.setenv(var, str(tmp_path / sub))
    monkeypatch.setenv("XDG_CONFIG_DIRS", str(tmp_path / "etc"))


# (camera, width mm, height mm, pixels across, pixels down, mount, category) as the cited page prints them.
CONFIRMED = [
    # DPReview (open-product-data/digital-cameras, database/panasonic_dcs5iix.yaml):
    # SensorSize 'Full frame (35.6 x 23.8 mm)', MaxResolution 6000 x 4000, LensMount Leica L.
    ("panasonic-lumix-s5-iix", 35.6, 23.8, 6000, 4000, "L-Mount", None),
    # Digicamdb, Lumix S9 vs Z6 III: sensor size 35.6 x 23.8 mm, max. image resolution 6000 x 4000.
    ("panasonic-lumix-s9", 35.6, 23.8, 6000, 4000, "L-Mount", None),
    # DPReview (database/sony_a7riva.yaml): 'Full frame (35.7 x 23.8 mm)', 9504 x 6336, Sony E.
    ("sony-a7r-iva", 35.7, 23.8, 9504, 6336, "Sony E", None),
    # DPReview (database/leica_m10_monochrom.yaml): 'Full frame (36 x 24 mm)', 7864 x 5200.
    ("leica-m10-monochrom", 36.0, 24.0, 7864, 5200, "Leica M", None),
    # DPReview (database/panasonic_dcbs1h.yaml): 'Full frame (35.6 x 23.8 mm)', 6000 x 4000, Leica L.
    ("panasonic-lumix-bs1h", 35.6, 23.8, 6000, 4000, "L-Mount", "cine"),
    # DPReview (database/panasonic_dcbgh1.yaml): 'Four Thirds (19.2 x 13 mm)', Micro Four Thirds; its
    # 3680 x 2760 is a 4:3 crop of the multi-aspect sensor and is left out.
    ("panasonic-lumix-bgh1", 19.2, 13.0, None, None, "Micro Four Thirds", "cine"),
]

# (camera, nominal format standing in, category): the bodies whose own size and image size no page gives.
NOMINAL = [
    # PetaPixel: "a 24.1-megapixel full-frame partially stacked CMOS image sensor".
    ("panasonic-lumix-s1-ii", "full-frame", None),
    # Galaxus: "CMOS sensor in APS-C format with a resolution of 25.7 megapixels".
    ("pentax-k-3-mark-iii-monochrome", "aps-c", None),
    # rehore.org: the R6 Mark III "uses the same 32MP 3:2 full-frame sensor found in the EOS C50".
    ("canon-eos-c50", "full-frame", "cine"),
    # Trevor Tan: "similar to the previous Q3 with a 60-megapixel BSI full-frame CMOS image sensor".
    ("leica-q3-43", "full-frame", None),
]


def added_camera_ids() -> set[str]:
    return {row[0] for row in CONFIRMED} | {row[0] for row in NOMINAL}


@pytest.mark.parametrize(("camera", "width", "height", "across", "down", "mount", "category"), CONFIRMED)
def test_confirmed_bodies_against_their_pages(camera, width, height, across, down, mount, category):
    body = load_db().camera(camera)
    assert (body.sensor.width_mm, body.sensor.height_mm) == (width, height)
    assert (body.pixels_w, body.pixels_h) == (across, down)
    assert body.mount == mount and body.category == category
    assert not body.approximate
    if across:
        # the published size and image size give square pixels (width / across = height / down)
        assert width / across == pytest.approx(height / down, rel=0.015)


@pytest.mark.parametrize(("camera", "nominal", "category"), NOMINAL)
def test_bodies_known_by_their_format_are_flagged(camera, nominal, category):
    db = load_db()
    body = db.camera(camera)
    preset = db.sensor(nominal)
    assert (body.sensor.width_mm, body.sensor.height_mm) == (preset.width_mm, preset.height_mm)
    assert body.category == category
    # no page gives the image size: left out, and the entry says what was not found
    assert body.pixels_w is None and body.pixels_h is None
    assert body.approximate and "not confirmed" in body.notes.lower()


def test_every_added_body_cites_a_page_or_the_file_read():
    records = {r["id"]: r for r in yaml.safe_load((ROOT / "lens_db" / "cameras.yaml").read_text(encoding="utf-8"))["cameras"]}
    for camera in added_camera_ids():
        source = " ".join(records[camera]["source"].split())
        assert "https://" in source or "open-product-data/digital-cameras" in source, camera


def test_the_bgh1s_crop_does_not_fit_its_sensor():
    # Why the BGH1 has no pixel counts: DPReview's 3680 x 2760 against its 19.2 x 13 mm gives pitches
    # more than the consistency test's 1.5 % apart.
    assert (19.2 / 3680) / (13.0 / 2760) == pytest.approx(1.108, abs=0.001)


# --- phone-lenses.yaml -----------------------------------------------------------------------------

# (lens, focal length mm, widest f-number, stated 35 mm equivalent mm) as the cited pages print them:
# Trevor Tan and Camera West: "APO-Summicron 43mm f/2 ASPH" on the full-frame Q3 43.
LENSES = [
    ("leica-q3-43-lens", 43.0, 2.0, 43.0),
]


@pytest.mark.parametrize(("lens_id", "focal", "f_number", "equivalent"), LENSES)
def test_built_in_lenses_against_their_pages(lens_id, focal, f_number, equivalent):
    lens = load_db().lens(lens_id)
    assert (lens.focal_min_mm, lens.f_number_min) == (focal, f_number)
    assert lens.mount == "fixed lens"
    # left out where no page gives them, and the notes say so
    assert lens.min_focus_mm is None and lens.f_number_max is None
    assert "min_focus_mm not found" in lens.notes and "f_number_max not found" in lens.notes


@pytest.mark.parametrize(("lens_id", "focal", "f_number", "equivalent"), LENSES)
def test_the_camera_brings_its_lens_and_its_stated_equivalent(lens_id, focal, f_number, equivalent):
    db = load_db()
    (camera,) = [c for c in db.all("camera") if c.lens_id == lens_id]
    (row,) = run_json("fov", "--camera", camera.id)
    assert row["focal_length_mm"] == focal
    # the equivalent fov prints is the stated one, within rounding of the published figure
    assert row["equivalent_focal_length_mm"] == pytest.approx(equivalent, abs=0.5)
    crop = FULL_FRAME_DIAGONAL_MM / math.hypot(camera.sensor.width_mm, camera.sensor.height_mm)
    assert focal * crop == pytest.approx(equivalent, rel=0.03)


def test_phone_lenses_file_holds_only_fixed_lenses_named_by_a_camera():
    lenses = yaml.safe_load((ROOT / "lens_db" / "phone-lenses.yaml").read_text(encoding="utf-8"))["lenses"]
    named = {c.lens_id for c in load_db().all("camera") if c.lens_id}
    assert {lens["id"] for lens in lenses} == {row[0] for row in LENSES}
    for lens in lenses:
        assert lens["mount"] == "fixed lens" and lens["id"] in named, lens["id"]
