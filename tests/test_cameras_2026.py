"""The camera bodies of 2020-2026 added to cameras.yaml, and the lenses of phone-lenses.yaml, against their pages.

Each figure is the one the page named in the entry's ``source`` prints (quoted next to it here); a figure no
page gives is left out of the entry, which is then ``approximate`` with notes naming it.
"""

from __future__ import annotations

import math
import re
from pathlib import Path

import pytest
import yaml
from cli_helpers import run_json
from test_cameras_fifth_pass import PHONES_FIFTH_PASS
from test_phones_2026 import PHONES_2026
from test_phones_vivo_huawei import PHONES_VIVO_HUAWEI

from camtool.presets import load_db

ROOT = Path(__file__).resolve().parents[1]
FULL_FRAME_DIAGONAL_MM = math.hypot(36.0, 24.0)


pytestmark = pytest.mark.usefixtures("no_user_presets")  # the shipped presets alone


# (camera, width mm, height mm, pixels across, pixels down, mount, category) as the cited page prints them.
CONFIRMED = [
    # DPReview (open-product-data/digital-cameras, database/panasonic_dcs5iix.yaml):
    # SensorSize 'Full frame (35.6 x 23.8 mm)', MaxResolution 6000 x 4000, LensMount Leica L.
    ("panasonic-lumix-s5-iix", 35.6, 23.8, 6000, 4000, "L-Mount", None),
    # Digicamdb, Lumix S9 vs Z6 III: sensor size 35.6 x 23.8 mm, max. image resolution 6000 x 4000.
    ("panasonic-lumix-s9", 35.6, 23.8, 6000, 4000, "L-Mount", None),
    # DPReview (database/sony_a7riva.yaml): 'Full frame (35.7 x 23.8 mm)', 9504 x 6336, Sony E.
    ("sony-a7r-iva", 35.7, 23.8, 9504, 6336, "Sony E", None),
    # DPReview (database/fujifilm_xt200.yaml): 'APS-C (23.5 x 15.7 mm)', 6000 x 4000, Fujifilm X.
    ("fujifilm-x-t200", 23.5, 15.7, 6000, 4000, "Fujifilm X", None),
    # DPReview (database/leica_m10_monochrom.yaml): 'Full frame (36 x 24 mm)', 7864 x 5200.
    ("leica-m10-monochrom", 36.0, 24.0, 7864, 5200, "Leica M", None),
    # DPReview (database/panasonic_dcbs1h.yaml): 'Full frame (35.6 x 23.8 mm)', 6000 x 4000, Leica L.
    ("panasonic-lumix-bs1h", 35.6, 23.8, 6000, 4000, "L-Mount", "cine"),
    # DPReview (database/panasonic_dcbgh1.yaml): 'Four Thirds (19.2 x 13 mm)', Micro Four Thirds; its
    # 3680 x 2760 is a 4:3 crop of the multi-aspect sensor and is left out.
    ("panasonic-lumix-bgh1", 19.2, 13.0, None, None, "Micro Four Thirds", "cine"),
    # Camera Sensor Database (data/markdown/blackmagic/pocketcinemacamera6kprog2.md, "Pocket Cinema Camera 6K
    # (Pro/G2)"): 6K 16:9 6144 x 3456, 23.1 x 12.99 mm; no mount in the file.
    ("blackmagic-pocket-6k-pro", 23.1, 12.99, 6144, 3456, None, "cine"),
    ("blackmagic-pocket-6k-g2", 23.1, 12.99, 6144, 3456, None, "cine"),
    # Camera Sensor Database (data/markdown/blackmagic/ursacineimmersive.md): 8K 8160 x 7200, 23.66 x 20.88 mm.
    ("blackmagic-ursa-cine-immersive", 23.66, 20.88, 8160, 7200, None, "cine"),
    # DPReview (database/sony_zv1.yaml): SensorSize '1″ (13.2 x 8.8 mm)', MaxResolution 5472 x 3648.
    ("sony-zv-1", 13.2, 8.8, 5472, 3648, "fixed lens", None),
    # DPReview (database/sony_zv1f.yaml): SensorSize '1″ (13.2 x 8.8 mm)', MaxResolution empty.
    ("sony-zv-1f", 13.2, 8.8, None, None, "fixed lens", None),
    # Notebookcheck: "Dieser 22 Megapixel Sensor im 1,4 Zoll Format misst 18,4 x 12,3 Millimeter".
    ("canon-powershot-v1", 18.4, 12.3, None, None, "fixed lens", None),
    # digitalkamera.de: the 13.2 x 8.8 mm sensor "im Hochformat verbaut und in seiner Höhe auf 11,7 Millimeter
    # beschnitten": an 8.8 x 11.7 mm frame, entered landscape.
    ("fujifilm-x-half", 11.7, 8.8, None, None, "fixed lens", None),
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
    # Domus: Sigma's BF, "una full-frame compatta".
    ("sigma-bf", "full-frame", None),
    # DPReview's GR IV page (open-product-data, main branch): "a 26MP APS-C sensor".
    ("ricoh-gr-iv", "aps-c", None),
    # DPReview's GFX100RF page (open-product-data, main branch): "102MP medium format CMOS sensor".
    ("fujifilm-gfx100rf", "mf-44x33", None),
    # Wex Photo Video: "a full-frame premium compact ... a beefy 61MP sensor".
    ("sony-rx1r-iii", "full-frame", None),
    # fotografia.it: "sensore Quattro Terzi da 21 Mpxl nominali e 17 Mpxl effettivi".
    ("leica-d-lux-8", "four-thirds", None),
    # DOCMA: "Die neue Sony a7 V ... dank eines teilgestapelten Sensors ... 33 Megapixel Raws".
    ("sony-a7-v", "full-frame", None),
]

# (phone, sensor preset of its main module): phones, whose sensor sizes are derived (see the sensor presets).
PHONES = [
    ("xiaomi-15-ultra", "1-inch-phone"),
    ("apple-iphone-air", "1-1.56-inch"),
]


@pytest.mark.parametrize(("camera", "sensor_id"), PHONES)
def test_phones_name_their_main_module(camera, sensor_id):
    db = load_db()
    body = db.camera(camera)
    assert body.category == "phone" and body.mount == "fixed lens" and body.approximate
    assert body.sensor.id == sensor_id
    assert body.lens_id == f"{camera}-main"
    assert db.lens(body.lens_id).sensor_id == sensor_id


# Bodies whose figures come partly from a page and partly from an identity: approximate, notes say which.
DERIVED = ["blackmagic-ursa-mini-pro-12k"]


def added_camera_ids() -> set[str]:
    return ({row[0] for row in CONFIRMED} | {row[0] for row in NOMINAL} | {row[0] for row in PHONES}
            | set(DERIVED))


def camera_records() -> dict[str, dict]:
    """The cameras of lens_db/cameras.yaml by id, as YAML reads them (not camtool)."""
    text = (ROOT / "lens_db" / "cameras.yaml").read_text(encoding="utf-8")
    return {record["id"]: record for record in yaml.safe_load(text)["cameras"]}


def check_confirmed_body(camera, width, height, across, down, mount, category):
    """A body confirmed in every figure: its sensor size, image size, mount and category as the source prints them."""
    body = load_db().camera(camera)
    assert (body.sensor.width_mm, body.sensor.height_mm) == (width, height)
    assert (body.pixels_w, body.pixels_h) == (across, down)
    assert body.mount == mount and body.category == category
    assert not body.approximate
    if across:
        # the published size and image size give square pixels (width / across = height / down)
        assert width / across == pytest.approx(height / down, rel=0.015)


@pytest.mark.parametrize(("camera", "width", "height", "across", "down", "mount", "category"), CONFIRMED)
def test_confirmed_bodies_against_their_pages(camera, width, height, across, down, mount, category):
    check_confirmed_body(camera, width, height, across, down, mount, category)


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
    records = camera_records()
    for camera in added_camera_ids():
        source = " ".join(records[camera]["source"].split())
        # a page's address, DPReview's archived file, or a public repository's file at a named commit
        at_commit = re.search(r"[\w.-]+/[\w.-]+ on GitHub, [\w./-]+\.\w+ at commit [0-9a-f]{40}", source)
        assert "https://" in source or "open-product-data/digital-cameras" in source or at_commit, camera


# --- phone-lenses.yaml -----------------------------------------------------------------------------

# (lens, camera, widest f-number, stated 35 mm equivalent mm) as the cited pages print them.
LENSES = [
    # Trevor Tan and Camera West: "APO-Summicron 43mm f/2 ASPH" on the full-frame Q3 43.
    ("leica-q3-43-lens", "leica-q3-43", 2.0, 43.0),
    # HotHardware: "1-inch 50MP Sony LYT-900 ... 23mm lens ... f/1.63"; "1/2.51-inch Samsung JN5 is now a
    # 14 mm f/2.2 lens"; "1/2.51-inch IMX858 telephoto ... a 75 mm f/1.8 piece"; "200MP Samsung HP9 f/2.6
    # 1/1.4-inch"; Digital Camera World (before the launch): "a 100mm (equivalent) lens with an f/2.6 aperture".
    ("xiaomi-15-ultra-main", "xiaomi-15-ultra", 1.63, 23.0),
    ("xiaomi-15-ultra-ultra-wide", "xiaomi-15-ultra", 2.2, 14.0),
    ("xiaomi-15-ultra-telephoto", "xiaomi-15-ultra", 1.8, 75.0),
    ("xiaomi-15-ultra-periscope", "xiaomi-15-ultra", 2.6, 100.0),
    # DPReview's GR IV page: "a 28mm equiv. F2.8 lens" on the APS-C camera.
    ("ricoh-gr-iv-lens", "ricoh-gr-iv", 2.8, 28.0),
    # DPReview's GFX100RF page: "a 35mm (28mm equiv.) F4 lens" (35 mm stated, not derived).
    ("fujifilm-gfx100rf-lens", "fujifilm-gfx100rf", 4.0, 28.0),
    # The Verge (quoted by Briefly): "a 48-megapixel sensor with a 26mm-equivalent f/1.6 lens".
    ("apple-iphone-air-main", "apple-iphone-air", 1.6, 26.0),
    # Wex Photo Video: "a razor-sharp Zeiss 35mm f2 Sonnar T* lens" on the full-frame RX1R III (35 mm stated).
    ("sony-rx1r-iii-lens", "sony-rx1r-iii", 2.0, 35.0),
    # digitalkamera.de: "einem kleinbildäquivalenten 32mm-Objektiv mit einer Blendenöffnung von F2,8".
    ("fujifilm-x-half-lens", "fujifilm-x-half", 2.8, 32.0),
]

# (sensor preset, optical type in inches as the page names it): sized by the type rule, diagonal = 2/3 inch / type.
TYPE_RULE = [
    ("1-inch-phone", 1.0),  # HotHardware: "1-inch 50MP Sony LYT-900"
    ("1-1.4-inch", 1.4),  # HotHardware: "200MP Samsung HP9 f/2.6 1/1.4-inch sensor"
    ("1-2.51-inch", 2.51),  # HotHardware: "1/2.51-inch IMX858", "1/2.51-inch Samsung JN5"
]


def phone_lens_records() -> dict[str, dict]:
    text = (ROOT / "lens_db" / "phone-lenses.yaml").read_text(encoding="utf-8")
    return {record["id"]: record for record in yaml.safe_load(text)["lenses"]}


@pytest.mark.parametrize(("lens_id", "camera", "f_number", "equivalent"), LENSES)
def test_built_in_lenses_against_their_pages(lens_id, camera, f_number, equivalent):
    db = load_db()
    lens = db.lens(lens_id)
    assert lens.f_number_min == f_number
    assert phone_lens_records()[lens_id]["equivalent_focal_length_mm"] == equivalent
    assert lens.mount == "fixed lens"
    if lens.category == "phone" or lens_id in ("ricoh-gr-iv-lens", "fujifilm-x-half-lens"):  # the RX1R III's 35 mm is stated
        # a module's (and the GR IV's and X half's) focal length is derived from the stated equivalent and the sensor (no page gives it): flagged
        assert lens.approximate and "derived" in lens.notes
    sensor = db.sensor(lens.sensor_id) if lens.sensor_id in {s.id for s in db.all("sensor")} else db.camera(camera).sensor
    crop = FULL_FRAME_DIAGONAL_MM / math.hypot(sensor.width_mm, sensor.height_mm)
    # a derived focal length gives the equivalent back; a stated one (GFX100RF, Q3 43) within the 3 % of the
    # consistency test
    assert lens.focal_min_mm * crop == pytest.approx(equivalent, rel=0.005 if lens.approximate and "derived" in lens.notes else 0.03)


def test_figures_no_page_gives_are_left_out():
    assert load_db().lens("fujifilm-gfx100rf-lens").focal_min_mm == 35.0
    for compact in ("leica-q3-43-lens", "ricoh-gr-iv-lens", "fujifilm-gfx100rf-lens"):
        lens = load_db().lens(compact)
        assert lens.min_focus_mm is None and lens.f_number_max is None
        assert "min_focus_mm not found" in lens.notes and "f_number_max not found" in lens.notes
    periscope = load_db().lens("xiaomi-15-ultra-periscope")
    # the 100 mm was printed only before the launch; the review of the phone as sold gives 4.3x of the 23 mm main
    assert "not confirmed" in periscope.notes.lower()
    equivalent = phone_lens_records()["xiaomi-15-ultra-periscope"]["equivalent_focal_length_mm"]
    assert equivalent == pytest.approx(4.3 * 23, rel=0.02)


@pytest.mark.parametrize(("lens_id", "camera", "f_number", "equivalent"), LENSES)
def test_the_camera_resolves_its_modules_and_their_stated_equivalents(lens_id, camera, f_number, equivalent):
    db = load_db()
    body = db.camera(camera)
    if body.lens_id == lens_id:
        # the camera's own lens: --camera alone brings it
        (row,) = run_json("fov", "--camera", camera)
    else:
        (row,) = run_json("fov", "--camera", camera, "--lens", lens_id)
    assert row["focal_length_mm"] == db.lens(lens_id).focal_min_mm
    # the equivalent fov prints is the published one, within rounding
    assert row["equivalent_focal_length_mm"] == pytest.approx(equivalent, abs=0.5)


@pytest.mark.parametrize(("sensor_id", "inch_type"), TYPE_RULE)
def test_phone_formats_sized_by_their_type(sensor_id, inch_type):
    sensor = load_db().sensor(sensor_id)
    # "approximately the diagonal length of the sensor multiplied by 3/2", at 4:3
    assert sensor.diagonal_mm == pytest.approx(25.4 / inch_type * 2 / 3, rel=0.002)
    assert sensor.width_mm / sensor.height_mm == pytest.approx(4 / 3, rel=0.005)
    assert sensor.approximate and sensor.category == "phone"


def test_phone_lenses_file_holds_only_fixed_lenses_named_by_a_camera():
    lenses = list(phone_lens_records().values())
    # with the flagship phones' modules added since (tests/test_phones_2026.py, tests/test_cameras_fifth_pass.py and
    # tests/test_phones_vivo_huawei.py check those against their pages)
    phones_since = {**PHONES_2026, **PHONES_FIFTH_PASS, **PHONES_VIVO_HUAWEI}
    added_since = {f"{phone}-{suffix}" for phone, suffixes in phones_since.items() for suffix in suffixes}
    assert {lens["id"] for lens in lenses} == {row[0] for row in LENSES} | added_since
    cameras = {row[1] for row in LENSES} | set(phones_since)
    for lens in lenses:
        assert lens["mount"] == "fixed lens", lens["id"]
        assert any(lens["id"].startswith(camera) for camera in cameras), lens["id"]
    # each phone and compact names its main module or its lens
    db = load_db()
    for camera in cameras:
        assert db.camera(camera).lens_id in {lens["id"] for lens in lenses}, camera


# --- the gaps of 2020-2026 added after the comparison with the makers' announcements ----------------

def test_the_12k_height_is_the_identity_of_its_published_width_and_image():
    # telemetry-parser: width 27.03 mm; Digital Trends (mostathmr.com) and es.wtvid.com: 12 288 x 6 480 photosites.
    body = load_db().camera("blackmagic-ursa-mini-pro-12k")
    assert body.sensor.width_mm == 27.03 and (body.pixels_w, body.pixels_h) == (12288, 6480)
    # square photosites: the height is the width scaled by the image's aspect, to the page's two decimals
    assert body.sensor.height_mm == pytest.approx(27.03 * 6480 / 12288, abs=0.005)
    assert body.approximate and "height is not confirmed" in " ".join(body.notes.split())
    assert body.category == "cine" and body.mount is None


def test_compacts_without_a_page_for_their_lens_name_none():
    db = load_db()
    for camera in ("sony-zv-1", "sony-zv-1f", "canon-powershot-v1", "leica-d-lux-8"):
        body = db.camera(camera)
        assert body.mount == "fixed lens" and body.lens_id is None, camera
        assert "not entered" in " ".join(body.notes.split()), camera
    rx1 = db.lens("sony-rx1r-iii-lens")
    assert rx1.min_focus_mm is None and rx1.f_number_max is None
    assert "min_focus_mm not found" in rx1.notes and "f_number_max not found" in rx1.notes


def test_the_x_half_frame_gives_the_pages_crop_factor():
    # digitalkamera.de: the 8.8 x 11.7 mm frame "bedeutet" an effective crop factor of 3
    body = load_db().camera("fujifilm-x-half")
    assert FULL_FRAME_DIAGONAL_MM / math.hypot(body.sensor.width_mm, body.sensor.height_mm) == pytest.approx(3.0, rel=0.02)
    # and the 3:4 aspect of the half frame
    assert body.sensor.height_mm / body.sensor.width_mm == pytest.approx(3 / 4, rel=0.005)
