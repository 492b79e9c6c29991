"""The flagship phones added in 2026 and every one of their rear modules, against the pages their entries cite.

Each module's f-numbers and stated 35 mm equivalent are the ones the page printed at or after the phone's launch
(quoted next to the row, and the quote must stand in the entry's ``source``); its real focal length is not published,
so it is derived from the equivalent and the sensor preset's diagonal and the entry is ``approximate`` and says so.
Leaks and rumours are not sources. These phones ship with every rear module; a phone entered later may leave out a
module no launch page sizes (its notes name it) or an aperture no launch page gives (lens_db/README.md,
tests/test_phones_vivo_huawei.py).
"""

from __future__ import annotations

import math
from pathlib import Path

import pytest
from cli_helpers import run_json
from phone_checks import check_phone_is_its_main_module, phone_lens_records

from camtool.presets import load_db

ROOT = Path(__file__).resolve().parents[1]
FULL_FRAME_DIAGONAL_MM = math.hypot(36.0, 24.0)

pytestmark = pytest.mark.usefixtures("no_user_presets")  # the shipped presets alone

AMATEUR_PHOTOGRAPHER_14_ULTRA = ("https://amateurphotographer.com/latest/photo-news/"
                                 "xiaomi-14-ultra-variable-aperture-1-inch-sensor-and-more/")

# (module, phone, widest f-number, smallest f-number, stated 35 mm equivalent mm, sensor preset, quote the entry's
# source must hold, page the entry's source must cite).
MODULES = [
    # Amateur Photographer at the launch (MWC 2024): "f/1.63 main, 23mm, 1x optical zoom"; "50Mp Sony LYT-900
    # 1-inch sensor". The Business Standard (2024-03-02): "a variable aperture ranging from f/1.63 to f/4.0".
    ("xiaomi-14-ultra-main", "xiaomi-14-ultra", 1.63, 4.0, 23.0, "1-inch-phone",
     "f/1.63 main, 23mm", AMATEUR_PHOTOGRAPHER_14_ULTRA),
    # "f/1.8 ultra wide, 12mm, 0.5x optical zoom, OIS"; "50Mp Sony IMX858 sensors are used across the other
    # cameras" (the IMX858 is "1/2.51-inch", HotHardware).
    ("xiaomi-14-ultra-ultra-wide", "xiaomi-14-ultra", 1.8, 1.8, 12.0, "1-2.51-inch",
     "f/1.8 ultra wide, 12mm", AMATEUR_PHOTOGRAPHER_14_ULTRA),
    # "f/1.8 floating telephoto, 75mm, 3.2x optical zoom, OIS".
    ("xiaomi-14-ultra-telephoto", "xiaomi-14-ultra", 1.8, 1.8, 75.0, "1-2.51-inch",
     "f/1.8 floating telephoto, 75mm", AMATEUR_PHOTOGRAPHER_14_ULTRA),
    # "f/2.5 periscope telephoto, 120mm, 5x optical zoom, OIS".
    ("xiaomi-14-ultra-periscope", "xiaomi-14-ultra", 2.5, 2.5, 120.0, "1-2.51-inch",
     "f/2.5 periscope telephoto, 120mm", AMATEUR_PHOTOGRAPHER_14_ULTRA),
]

# Every phone added here and the suffixes of all its rear modules (its camera preset is the main module).
PHONES_2026 = {
    "xiaomi-14-ultra": ("main", "ultra-wide", "telephoto", "periscope"),
}

# The stated zoom factors of the launch pages, against the ratio of the stated equivalents to the main module's:
# (module, factor), Amateur Photographer: "0.5x", "3.2x", "5x".
ZOOM_FACTORS = [
    ("xiaomi-14-ultra-ultra-wide", 0.5),
    ("xiaomi-14-ultra-telephoto", 3.2),
    ("xiaomi-14-ultra-periscope", 5.0),
]


def test_the_table_covers_every_module_of_every_phone_added():
    assert sorted(row[0] for row in MODULES) == sorted(
        f"{phone}-{suffix}" for phone, suffixes in PHONES_2026.items() for suffix in suffixes)


@pytest.mark.parametrize(("lens_id", "phone", "widest", "smallest", "equivalent", "sensor_id", "quote", "page"),
                         MODULES)
def test_modules_against_their_pages(lens_id, phone, widest, smallest, equivalent, sensor_id, quote, page):
    db = load_db()
    lens = db.lens(lens_id)
    record = phone_lens_records()[lens_id]
    assert (lens.f_number_min, lens.f_number_max) == (widest, smallest)
    assert record["equivalent_focal_length_mm"] == equivalent
    assert lens.sensor_id == sensor_id
    assert lens.mount == "fixed lens" and lens.category == "phone"
    source = " ".join(record["source"].split())
    assert quote in source and page in source


@pytest.mark.parametrize(("lens_id", "phone", "widest", "smallest", "equivalent", "sensor_id", "quote", "page"),
                         MODULES)
def test_derived_focal_lengths_give_the_stated_equivalent_back(lens_id, phone, widest, smallest, equivalent,
                                                                sensor_id, quote, page):
    db = load_db()
    lens = db.lens(lens_id)
    sensor = db.sensor(sensor_id)
    # focal length x crop factor (full-frame diagonal over the sensor's) is the stated equivalent, to the
    # rounding of the stored focal length
    assert lens.focal_min_mm * FULL_FRAME_DIAGONAL_MM / sensor.diagonal_mm == pytest.approx(equivalent, rel=0.005)
    notes = " ".join(lens.notes.split())
    assert lens.approximate and "derived from the stated" in notes and "real focal length was not found" in notes


@pytest.mark.parametrize(("lens_id", "factor"), ZOOM_FACTORS)
def test_stated_equivalents_agree_with_the_stated_zoom_factors(lens_id, factor):
    records = phone_lens_records()
    phone = next(p for p in PHONES_2026 if lens_id.startswith(p))
    ratio = records[lens_id]["equivalent_focal_length_mm"] / records[f"{phone}-main"]["equivalent_focal_length_mm"]
    # the makers round the factor (75 / 23 = 3.26 is "3.2x", 12 / 23 = 0.52 is "0.5x", 120 / 23 = 5.22 is "5x"):
    # within 5 %, which a wrong equivalent (14 mm for 12 mm, 100 mm for 120 mm) is not
    assert ratio == pytest.approx(factor, rel=0.05)


@pytest.mark.parametrize("phone", sorted(PHONES_2026))
def test_phones_are_their_main_module(phone):
    check_phone_is_its_main_module(phone)


@pytest.mark.parametrize("phone", sorted(PHONES_2026))
def test_every_rear_module_is_shipped_and_nothing_else_under_the_phone(phone):
    shipped = {lens.id for lens in load_db().all("lens") if lens.id.startswith(f"{phone}-")}
    assert shipped == {f"{phone}-{suffix}" for suffix in PHONES_2026[phone]}


@pytest.mark.parametrize(("lens_id", "phone", "widest", "smallest", "equivalent", "sensor_id", "quote", "page"),
                         MODULES)
def test_the_phone_brings_each_module_with_its_stated_equivalent(lens_id, phone, widest, smallest, equivalent,
                                                                 sensor_id, quote, page):
    db = load_db()
    if db.camera(phone).lens_id == lens_id:
        (row,) = run_json("fov", "--camera", phone)
    else:
        (row,) = run_json("fov", "--camera", phone, "--lens", lens_id)
    assert row["focal_length_mm"] == db.lens(lens_id).focal_min_mm
    assert row["equivalent_focal_length_mm"] == pytest.approx(equivalent, abs=0.5)
