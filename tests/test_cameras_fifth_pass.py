"""The cameras of the fifth pass over lens_db/cameras.yaml, against the pages and tables their entries cite.

Phones: the Google Pixel 10 and Apple iPhone 17, each with every rear module (phone-lenses.yaml). A module's
f-number and 35 mm equivalent are the ones the cited page prints (quoted next to its row, and the quote must stand
in the entry's ``source``); the real focal length is published by neither maker, so it is derived from the
equivalent and the sensor preset's diagonal and the entry is ``approximate``. Google states no equivalent: the
Pixel 10's are DPReview's and ``equivalent_focal_length_mm`` is left out; Apple's are kept.

Cinema: the Blackmagic URSA Cine 12K LF, confirmed from the camera table of InfraXCoders/iris, which transcribes
Blackmagic's page (its row is quoted below).
"""

from __future__ import annotations

import math

import pytest
from cli_helpers import run_json
from phone_checks import (
    camera_records,
    check_focal_length_gives_the_equivalent,
    check_fov_gives_the_equivalent,
    check_module_against_its_pages,
    check_phone_is_its_main_module,
)

from camtool.presets import load_db

FULL_FRAME_DIAGONAL_MM = math.hypot(36.0, 24.0)
DPREVIEW_PIXEL = "http://ru-foto.ru/the-google-pixel-10s-hidden-tradeoff-the-new-dedicated-25102721400092.htm"
CLUBIC_PIXEL = ("https://www.clubic.com/actualite-576102-pixel-10-pixel-10-pro-et-pixel-10-pro-fold-tout-ce-qu-il-"
                "faut-savoir-sur-les-nouveaux-smartphones-google-bourres-d-ia.html")
NOTEBOOKCHECK_IPHONE = ("http://www.notebookcheck.net/Apple-s-misleading-iPhone-17-Pro-camera-marketing-distracts-"
                        "customers-from-the-real-weaknesses.1112402.0.html")
BRIEFLY_VERGE = "https://briefly.co/anchor/Apple/story/why-does-apple-think-three-lenses-are-eight-lenses"
IRIS = ("InfraXCoders/iris on GitHub (RecceKit/Sources/RecceKit/Data/cameras.csv at commit "
        "8e981396e602920d1ead4eacf52d51619eb50ef9)")

pytestmark = pytest.mark.usefixtures("no_user_presets")  # the shipped presets alone

# Every phone added here and the suffixes of all its rear modules (its camera preset is the main module).
PHONES_FIFTH_PASS = {
    "google-pixel-10": ("main", "ultrawide", "telephoto"),
    "apple-iphone-17": ("main", "ultra-wide"),
}

# (module, widest f-number, smallest f-number, 35 mm equivalent mm, stated by the maker, sensor preset, quotes the
# entry's source must hold, pages it must cite).
MODULES = [
    # DPReview's table: Pixel 10 main "24mm F1.7", "48MP Type 1/2 (31mm²)"; Clubic: "48 mégapixels (1/2.0", f/1.7)".
    ("google-pixel-10-main", 1.7, 1.7, 24.0, False, "1-2-inch-48mp",
     ("24mm F1.7", "48MP Type 1/2 (31mm²)", 'un grand-angle de 48 mégapixels (1/2.0", f/1.7)'),
     (DPREVIEW_PIXEL, CLUBIC_PIXEL)),
    # DPReview: ultrawide "13mm F2.2", "13MP Type 1/3.1 (16.1mm"; Clubic: "13 mégapixels (1/3.1", f/2.2)".
    ("google-pixel-10-ultrawide", 2.2, 2.2, 13.0, False, "1-3.1-inch-13mp",
     ("13mm F2.2", "13MP Type 1/3.1 (16.1mm", 'un ultra grand-angle de 13 mégapixels (1/3.1", f/2.2)'),
     (DPREVIEW_PIXEL, CLUBIC_PIXEL)),
    # DPReview: telephoto "110mm F3.1", "10.8MP"; Clubic: "un téléobjectif 5x de 10,8 mégapixels (1/3.2", f/3.1)".
    ("google-pixel-10-telephoto", 3.1, 3.1, 110.0, False, "1-3.2-inch",
     ("110mm F3.1", 'un téléobjectif 5x de 10,8 mégapixels (1/3.2", f/3.1)'),
     (DPREVIEW_PIXEL, CLUBIC_PIXEL)),
    # The Verge via Briefly: "26mm-equivalent f/1.6 lens. It's the same as the main camera of the regular iPhone
    # 17"; Notebookcheck: "a 1/1.55-inch sensor with an f/1.6 lens on the iPhone 17 and iPhone Air".
    ("apple-iphone-17-main", 1.6, 1.6, 26.0, True, "1-1.56-inch",
     ("26mm-equivalent f/1.6 lens. It's the same as the main camera of the regular iPhone 17",
      "a 1/1.55-inch sensor with an f/1.6 lens on the iPhone 17 and iPhone Air"),
     (BRIEFLY_VERGE, NOTEBOOKCHECK_IPHONE)),
    # Notebookcheck: "a 48 MP f/2.2 ultra-wide-angle camera with a 1/2.55-inch sensor", "13 mm field of view".
    ("apple-iphone-17-ultra-wide", 2.2, 2.2, 13.0, True, "1-2.55-inch-48mp",
     ("Apple installs a 48 MP f/2.2 ultra-wide-angle camera with a 1/2.55-inch sensor",
      "use the full 48 MP sensor and 13 mm field of view"),
     (NOTEBOOKCHECK_IPHONE,)),
]


def module_parameters():
    return pytest.mark.parametrize(
        ("lens_id", "widest", "smallest", "equivalent", "stated", "sensor_id", "quotes", "pages"), MODULES)


def test_the_table_covers_every_module_of_every_phone_added():
    assert sorted(row[0] for row in MODULES) == sorted(
        f"{phone}-{suffix}" for phone, suffixes in PHONES_FIFTH_PASS.items() for suffix in suffixes)


@module_parameters()
def test_modules_against_their_pages(lens_id, widest, smallest, equivalent, stated, sensor_id, quotes, pages):
    check_module_against_its_pages(lens_id, widest, smallest, equivalent, stated, sensor_id, quotes, pages)


@module_parameters()
def test_derived_focal_lengths_give_the_equivalent_back(lens_id, widest, smallest, equivalent, stated, sensor_id,
                                                        quotes, pages):
    # to the rounding of the stored focal length (two decimals of a millimetre: 0.5 % at 1.74 mm)
    check_focal_length_gives_the_equivalent(lens_id, sensor_id, equivalent, 0.005, "focal length")


@module_parameters()
def test_the_phone_brings_each_module_with_its_equivalent(lens_id, widest, smallest, equivalent, stated, sensor_id,
                                                          quotes, pages):
    phone = next(p for p in PHONES_FIFTH_PASS if lens_id.startswith(f"{p}-") and
                 lens_id.removeprefix(f"{p}-") in PHONES_FIFTH_PASS[p])
    check_fov_gives_the_equivalent(phone, lens_id, equivalent, 0.5)


@pytest.mark.parametrize("phone", sorted(PHONES_FIFTH_PASS))
def test_phones_are_their_main_module(phone):
    check_phone_is_its_main_module(phone)


@pytest.mark.parametrize("phone", sorted(PHONES_FIFTH_PASS))
def test_every_rear_module_is_shipped(phone):
    # the phone's modules, and no other lens under its name but another shipped phone's (the Pixel 10 Pro's and
    # iPhone 17 Pro's modules share the prefix)
    others = {c.id for c in load_db().all("camera") if c.category == "phone" and c.id != phone}
    shipped = {lens.id for lens in load_db().all("lens") if lens.id.startswith(f"{phone}-")
               and not any(lens.id.startswith(f"{other}-") for other in others)}
    assert shipped == {f"{phone}-{suffix}" for suffix in PHONES_FIFTH_PASS[phone]}


def test_the_pixel_10_formats_hold_dpreviews_areas():
    # DPReview: main "Type 1/2 (31mm²)", ultrawide "Type 1/3.1 (16.1mm²)", each to the table's rounding
    db = load_db()
    main, wide = db.sensor("1-2-inch-48mp"), db.sensor("1-3.1-inch-13mp")
    assert round(main.width_mm * main.height_mm) == 31
    assert wide.width_mm * wide.height_mm == pytest.approx(16.1, abs=0.05)
    assert wide.width_mm / wide.height_mm == pytest.approx(4 / 3, rel=0.005)
    # the 1/3.1 type by the optical-format rule (2/3 of 25.4 / 3.1 mm across the diagonal) is within its
    # spread of the area's diagonal
    assert wide.diagonal_mm == pytest.approx(25.4 / 3.1 * 2 / 3, rel=0.07)


def test_the_one_3_2_inch_format_follows_the_optical_format_rule():
    sensor = load_db().sensor("1-3.2-inch")
    assert sensor.diagonal_mm == pytest.approx(25.4 / 3.2 * 2 / 3, rel=0.002)
    assert sensor.width_mm / sensor.height_mm == pytest.approx(4 / 3, rel=0.005)
    assert sensor.approximate


def test_the_pixel_10_telephoto_is_googles_rounded_5x():
    # DPReview's 110 mm over its 24 mm main is 4.6x, which Google and Clubic call "5x": within the makers' rounding
    # to the nearest whole factor, which a 70 mm (2.9x) or 130 mm (5.4x) telephoto would not meet
    (tele,) = run_json("fov", "--camera", "google-pixel-10", "--lens", "google-pixel-10-telephoto")
    (main,) = run_json("fov", "--camera", "google-pixel-10")
    assert round(tele["equivalent_focal_length_mm"] / main["equivalent_focal_length_mm"]) == 5


def test_the_iphone_17_main_camera_is_the_iphone_airs():
    # The Verge: the Air's main camera "is the same as the main camera of the regular iPhone 17"
    db = load_db()
    seventeen, air = db.lens("apple-iphone-17-main"), db.lens("apple-iphone-air-main")
    assert (seventeen.focal_min_mm, seventeen.f_number_min, seventeen.sensor_id) == (
        air.focal_min_mm, air.f_number_min, air.sensor_id)
    assert db.camera("apple-iphone-17").sensor == db.camera("apple-iphone-air").sensor


# --- the URSA Cine 12K LF, confirmed ------------------------------------------------------------------------------


def test_the_ursa_cine_12k_lf_is_the_tables():
    # iris: "ursa_cine_12k,Blackmagic Design,URSA Cine 12K LF,PL;EF,open_gate,12K 3:2 open gate (full sensor),35.64,
    # 23.32,12288,8040,https://www.blackmagicdesign.com/products/blackmagicursacine/techspecs,maker effective sensor
    # 35.64 x 23.32 mm"
    body = load_db().camera("blackmagic-ursa-cine-12k-lf")
    assert (body.sensor.width_mm, body.sensor.height_mm) == (35.64, 23.32)
    assert (body.pixels_w, body.pixels_h) == (12288, 8040)
    assert body.mount == "ARRI PL" and body.category == "cine" and not body.approximate
    # square photosites of the table's pitch ("computed from pitch (2.900 um = maker full-sensor width / photosites)")
    assert body.sensor.width_mm / body.pixels_w * 1000 == pytest.approx(2.900, abs=0.0005)
    assert body.sensor.height_mm / body.pixels_h == pytest.approx(body.sensor.width_mm / body.pixels_w, rel=0.002)
    source = " ".join(camera_records()["blackmagic-ursa-cine-12k-lf"]["source"].split())
    assert IRIS in source
    assert "https://www.blackmagicdesign.com/products/blackmagicursacine/techspecs" in source
    assert '"maker effective sensor 35.64 x 23.32 mm"' in source


def test_the_ursa_cine_12k_lf_super_35_window_keeps_its_pitch():
    # iris, from the same page: "9k_3x2_s35,9K 3:2 (Super 35 crop),27.29,18.17,9408,6264", a window read 1:1
    body = load_db().camera("blackmagic-ursa-cine-12k-lf")
    assert "9k_3x2_s35,9K 3:2 (Super 35 crop),27.29,18.17,9408,6264" in " ".join(
        camera_records()["blackmagic-ursa-cine-12k-lf"]["source"].split())
    assert body.sensor.width_mm / body.pixels_w == pytest.approx(27.29 / 9408, rel=0.003)
    assert body.sensor.height_mm / body.pixels_h == pytest.approx(18.17 / 6264, rel=0.003)


def test_the_ursa_cine_12k_lf_shares_the_pyxis_12k_sensor():
    # iris gives the PYXIS 12K the same open gate (35.64 x 23.32 mm, 12288 x 8040) from Blackmagic's PYXIS page
    db = load_db()
    ursa, pyxis = db.camera("blackmagic-ursa-cine-12k-lf"), db.camera("blackmagic-pyxis-12k")
    assert (ursa.sensor.width_mm, ursa.sensor.height_mm, ursa.pixels_w, ursa.pixels_h) == (
        pyxis.sensor.width_mm, pyxis.sensor.height_mm, pyxis.pixels_w, pyxis.pixels_h)
