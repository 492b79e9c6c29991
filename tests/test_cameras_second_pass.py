"""The bodies added to cameras.yaml on the second comparison with the makers' lines, against their sources.

Each figure is the one the page or file named in the entry's ``source`` prints (quoted next to it here);
a figure carried over from a predecessor, or read in one dataset only, leaves the entry ``approximate``
with notes naming it.
"""

from __future__ import annotations

import math
import re
from pathlib import Path

import pytest
from cli_helpers import run_json
from test_cameras_2026 import camera_records, check_confirmed_body

from camtool.presets import load_db

ROOT = Path(__file__).resolve().parents[1]
FULL_FRAME_DIAGONAL_MM = math.hypot(36.0, 24.0)

pytestmark = pytest.mark.usefixtures("no_user_presets")  # the shipped presets alone


# (camera, width mm, height mm, pixels across, pixels down, mount, category) as the cited file prints them.
CONFIRMED = [
    # DPReview (open-product-data/digital-cameras, database/canon_g7xiii.yaml): SensorSize '1″ (13.2 x 8.8 mm)',
    # MaxResolution 5472 x 3648, no LensMount (a compact).
    ("canon-powershot-g7-x-mark-iii", 13.2, 8.8, 5472, 3648, "fixed lens", None),
    # DPReview (database/canon_g5xii.yaml): '1″ (13.2 x 8.8 mm)', 5472 x 3648.
    ("canon-powershot-g5-x-mark-ii", 13.2, 8.8, 5472, 3648, "fixed lens", None),
    # DPReview (database/canon_eosm200.yaml): 'APS-C (22.3 x 14.9 mm)', 6000 x 4000, LensMount Canon EF-M.
    ("canon-eos-m200", 22.3, 14.9, 6000, 4000, "Canon EF-M", None),
    # DPReview (database/fujifilm_xa7.yaml): 'APS-C (23.5 x 15.7 mm)', 6000 x 4000, LensMount Fujifilm X.
    ("fujifilm-x-a7", 23.5, 15.7, 6000, 4000, "Fujifilm X", None),
    # DPReview (database/panasonic_dcg95.yaml): 'Four Thirds (17.3 x 13 mm)', 5184 x 3888, Micro Four Thirds.
    ("panasonic-lumix-g95", 17.3, 13.0, 5184, 3888, "Micro Four Thirds", None),
    # DPReview (database/leica_q2.yaml): 'Full frame (36 x 24 mm)', 8368 x 5584; DigitalRev: "8368×5584 pixels".
    ("leica-q2", 36.0, 24.0, 8368, 5584, "fixed lens", None),
    # DPReview (database/canon_g9xii.yaml): '1″ (13.2 x 8.8 mm)', 5472 x 3648.
    ("canon-powershot-g9-x-mark-ii", 13.2, 8.8, 5472, 3648, "fixed lens", None),
    # DPReview (database/canon_g1xiii.yaml): 'APS-C (22.3 x 14.9 mm)', 6000 x 4000.
    ("canon-powershot-g1-x-mark-iii", 22.3, 14.9, 6000, 4000, "fixed lens", None),
    # DPReview (database/panasonic_dczs200.yaml): '1″ (13.2 x 8.8 mm)', 5472 x 3648.
    ("panasonic-lumix-zs200", 13.2, 8.8, 5472, 3648, "fixed lens", None),
    # DPReview (database/fujifilm_x100f.yaml): 'APS-C (23.6 x 15.6 mm)', 6000 x 4000.
    ("fujifilm-x100f", 23.6, 15.6, 6000, 4000, "fixed lens", None),
    # DPReview (database/fujifilm_xf10.yaml): 'APS-C (23.5 x 15.7 mm)', 6000 x 4000.
    ("fujifilm-xf10", 23.5, 15.7, 6000, 4000, "fixed lens", None),
    # DPReview (database/olympus_tg6.yaml): '1/2.3" (6.17 x 4.55 mm)'; its 4000 x 3000 is left out (see below).
    ("olympus-tough-tg-6", 6.17, 4.55, None, None, "fixed lens", None),
    # Camera Sensor Database (blackmagic/ursaminipro46kg2.md): 4.6K 16:9 4608 x 2592, 25.34 x 14.25 mm;
    # telemetry-parser (camera_db/blackmagic.json): "URSA Mini Pro 4.6K G2" sw 25.34. No mount in either.
    ("blackmagic-ursa-mini-pro-46k-g2", 25.34, 14.25, 4608, 2592, None, "cine"),
    # Camera Sensor Database (sony/venice.md): "6K Full Frame Mode 6K 3:2 | 6048 x 4032 | 35.9 x 24.0".
    ("sony-venice", 35.9, 24.0, 6048, 4032, None, "cine"),
]

# (camera, the body whose figures it carries, what the page says of them)
CARRIED = [
    # moognyk.jp: the TG-7's image sensor (1/2.3-type, 12 MP) "はTG-6から据え置き"; Vice: "12-megapixel, 1/2.3".
    ("om-system-tough-tg-7", "olympus-tough-tg-6"),
    # New Atlas: "It has the same pixel count" as the Q2; ymcinema: "a full-frame 47.3MP compact camera".
    ("leica-q2-monochrom", "leica-q2"),
]

# (camera, nominal format standing in, mount)
NOMINAL = [
    # telemetry-parser (camera_db/leica.json): "SL3-S" sw 35.9, the width it gives the full-frame SL3 and SL2-S.
    ("leica-sl3-s", "full-frame", "L-Mount"),
    # mtazamonews.com: "The S1 IIE ... a standard 24MP BSI CMOS sensor", under 'Panasonic unveils new full-frame cameras'.
    ("panasonic-lumix-s1-iie", "full-frame", "L-Mount"),
]

# (camera, width mm, height mm, pixels across, pixels down): the Camera Sensor Database alone
# (dji/zenmusex98k.md: "17:9 Full Frame | 8192 x 4320 | 36 x 19"; dji/zenmusex96k.md:
# "17:9 Full Frame | 6008 x 3168 | 35.7 x 18.8"), each its largest recording area.
ONE_DATASET = [
    ("dji-ronin-4d-x9-8k", 36.0, 19.0, 8192, 4320),
    ("dji-ronin-4d-x9-6k", 35.7, 18.8, 6008, 3168),
]


def added_camera_ids() -> set[str]:
    return ({row[0] for row in CONFIRMED} | {row[0] for row in CARRIED} | {row[0] for row in NOMINAL}
            | {row[0] for row in ONE_DATASET})


@pytest.mark.parametrize(("camera", "width", "height", "across", "down", "mount", "category"), CONFIRMED)
def test_confirmed_bodies_against_their_files(camera, width, height, across, down, mount, category):
    check_confirmed_body(camera, width, height, across, down, mount, category)


@pytest.mark.parametrize(("camera", "multiplier"), [
    # DPReview's FocalLengthMultiplier, printed beside the sensor size: 1.6×, 1.5×, 2×.
    ("canon-eos-m200", 1.6), ("fujifilm-x-a7", 1.5), ("panasonic-lumix-g95", 2.0),
])
def test_the_pages_crop_factor_follows_from_the_size(camera, multiplier):
    body = load_db().camera(camera)
    crop = FULL_FRAME_DIAGONAL_MM / math.hypot(body.sensor.width_mm, body.sensor.height_mm)
    # the page rounds its multiplier to one decimal (1.61, 1.53, 2.00 from the diagonals)
    assert crop == pytest.approx(multiplier, abs=0.05)


def test_the_tg6_image_size_would_not_give_square_pixels_on_its_nominal_size():
    # DPReview's MaxResolution 4000 x 3000 on its 6.17 x 4.55 mm: the pitches differ by more than the
    # 1.5 % the database allows, so the image size is left out and the notes say why.
    assert abs((6.17 / 4000) / (4.55 / 3000) - 1) > 0.015
    body = load_db().camera("olympus-tough-tg-6")
    assert body.pixels_w is None and "4000 x 3000" in " ".join(body.notes.split())


def test_the_g2_height_is_its_width_scaled_by_its_image():
    # 25.34 mm across 4608 photosites, 2592 down: square photosites give the file's 14.25 mm
    body = load_db().camera("blackmagic-ursa-mini-pro-46k-g2")
    assert body.sensor.height_mm == pytest.approx(25.34 * 2592 / 4608, abs=0.005)


@pytest.mark.parametrize(("camera", "sibling"), CARRIED)
def test_carried_figures_are_the_predecessors_and_flagged(camera, sibling):
    db = load_db()
    body, before = db.camera(camera), db.camera(sibling)
    assert (body.sensor.width_mm, body.sensor.height_mm) == (before.sensor.width_mm, before.sensor.height_mm)
    assert (body.pixels_w, body.pixels_h) == (before.pixels_w, before.pixels_h)
    assert body.mount == before.mount == "fixed lens"
    assert not before.approximate
    assert body.approximate and "not confirmed" in body.notes.lower()


@pytest.mark.parametrize(("camera", "nominal", "mount"), NOMINAL)
def test_bodies_known_by_their_format_are_flagged(camera, nominal, mount):
    db = load_db()
    body, preset = db.camera(camera), db.sensor(nominal)
    assert (body.sensor.width_mm, body.sensor.height_mm) == (preset.width_mm, preset.height_mm)
    assert body.mount == mount and body.category is None
    assert body.pixels_w is None and body.pixels_h is None
    assert body.approximate and "not confirmed" in body.notes.lower()


def test_the_dataset_width_of_the_sl3s_is_full_frame():
    # telemetry-parser's 35.9 mm for the SL3-S is within 0.3 % of the 36 mm the full-frame preset stands in with
    assert load_db().camera("leica-sl3-s").sensor.width_mm == pytest.approx(35.9, rel=0.003)


@pytest.mark.parametrize(("camera", "width", "height", "across", "down"), ONE_DATASET)
def test_cinema_cameras_from_one_dataset(camera, width, height, across, down):
    body = load_db().camera(camera)
    assert (body.sensor.width_mm, body.sensor.height_mm) == (width, height)
    assert (body.pixels_w, body.pixels_h) == (across, down)
    assert body.category == "cine" and body.mount is None
    assert body.approximate and "one dataset" in body.notes.lower()
    # the file's one-decimal sizes still give square photosites
    assert width / across == pytest.approx(height / down, rel=0.005)


def test_every_added_body_cites_a_page_or_the_file_read():
    records = camera_records()
    for camera in added_camera_ids():
        source = " ".join(records[camera]["source"].split())
        at_commit = re.search(r"[\w.-]+/[\w.-]+ on GitHub, \(?[\w./-]+\.\w+ at commit [0-9a-f]{40}", source)
        dpreview = re.search(r"open-product-data/digital-cameras.*database/\w+\.yaml at commit [0-9a-f]{40}", source)
        assert "https://" in source or dpreview or at_commit, camera


def test_a_cine_preset_takes_the_cinema_coc():
    # a cine camera preset's circle of confusion is the cinema 0.025 mm, whatever the sensor
    (row,) = run_json("dof", "--camera", "dji-ronin-4d-x9-8k", "-f", "50", "-N", "2.8", "-s", "3m")
    assert row["coc_mm"] == pytest.approx(0.025)


def test_a_full_frame_compact_gives_its_focal_length_back_as_the_equivalent():
    # on the Q2's 36 x 24 mm the 35 mm-equivalent of its 28 mm is 28 mm (DPReview: FocalLengthEquiv 28 mm)
    (row,) = run_json("fov", "--camera", "leica-q2", "-f", "28")
    assert row["equivalent_focal_length_mm"] == pytest.approx(28.0, abs=0.05)


@pytest.mark.parametrize("camera", [row[0] for row in CONFIRMED if row[5] == "fixed lens"])
def test_compacts_whose_lens_no_page_gives_name_none(camera):
    # the pages give the built-in lens's 35 mm equivalent, not its real focal length and closest focus:
    # the lens is not entered, and the notes say so
    body = load_db().camera(camera)
    assert body.lens_id is None
    assert "not entered" in " ".join(body.notes.split())


def test_the_venice_and_venice_2_6k_record_the_same_raster_on_the_same_area():
    # sony/venice.md: 6048 x 4032 on 35.9 x 24.0 mm; sony/venice26k.md: 6048 x 4032 on 35.93 x 23.95 mm
    db = load_db()
    first, second = db.camera("sony-venice"), db.camera("sony-venice-2-6k")
    assert (first.pixels_w, first.pixels_h) == (second.pixels_w, second.pixels_h)
    # within the rounding of the two files: one decimal (±0.05 mm) against two (±0.005 mm)
    assert first.sensor.width_mm == pytest.approx(second.sensor.width_mm, abs=0.055)
    assert first.sensor.height_mm == pytest.approx(second.sensor.height_mm, abs=0.055)
