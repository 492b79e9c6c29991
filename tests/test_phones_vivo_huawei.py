"""The flagship phones of Vivo and Huawei, and Samsung's Galaxy S25 Edge, against the pages their entries cite.

Each phone is its main module (cameras.yaml) plus one lens preset per rear module a page printed after the launch gives
with its 35 mm equivalent and sensor type (phone-lenses.yaml). A module's f-numbers and equivalent are the ones the
cited page prints (quoted next to its row, and the quote must stand in the entry's ``source``); its real focal length
is published by no maker, so it is derived from the equivalent and the sensor preset's diagonal and the entry is
``approximate``. A figure printed only before the launch (a leak) is left out: the Vivo X200 Ultra's modules carry no
aperture. A rear module whose sensor no launch page gives is not entered, and its phone's notes name it.
"""

from __future__ import annotations

import math

import pytest
from cli_helpers import run, run_json
from phone_checks import (
    check_focal_length_gives_the_equivalent,
    check_fov_gives_the_equivalent,
    check_module_against_its_pages,
    check_phone_is_its_main_module,
    phone_lens_records,
)

from camtool.presets import load_db

FULL_FRAME_DIAGONAL_MM = math.hypot(36.0, 24.0)

CAMERA_BATTLE = "https://newsbuzznow.com/camera-battle-vivo-x200-ultra-vs-x100-ultra"
VIVO_REVIEW = "https://rehmaan1011.wixsite.com/website/post/vivo-x200-ultra-phone-design-and-build-quality"
TECHYMN_DXOMARK = "https://techymn.com/vivo-x200-ultra-secures-second-place-in-global-camera-rankings-by-dxomark"
DIGITEC_PURA = "https://www.digitec.ch/en/page/huawei-pura-80-ultra-one-sensor-for-two-cameras-38334"
PHONEARENA_PURA = ("https://www.phonearena.com/news/the-best-camera-phone-you-probably-wont-own-the-huawei-pura-80-ultra_"
                   "id172347")
NEWSY_PURA = "https://www.newsy-today.com/huawei-pura-80-ultra-top-smartphone-camera-dxomark-ranking"
REALHACKER_PURA = "https://realhacker.news/huawei-pura-80-ultra-smartphone-has-wild-lens-swapping-tech"
TEKMONO_PURA = "https://tekmono.com/?p=1588"
PHONEARENA_EDGE = "https://www.phonearena.com/news/galaxy-s25-edge-compromises_id170336"
ELIFE_EDGE = "https://www.3elife.net/Art/test/202506/29/103022_6.html"
IDNES_EDGE = ("https://www.idnes.cz/mobil/telefony/samsung-galaxy-s25-edge-dxo-mark-hodnoceni-fotomobilu."
              "A250902_164756_telefony_vok")

# Pages read that print the Vivo X200 Ultra's apertures, all before the launch (leaks): never a source.
VIVO_LEAKS = (
    "notebookcheck.com/Vivo-X200-Ultra-Ungewoehnlichstes-Kamera-Flaggschiff-des-Jahres",
    "notebookcheck.com/Vivo-X200-Ultra-35mm-Zeiss-Kamera",
    "notebookcheck.com/Vivo-X200-Ultra-mit-doppelter",
    "en.adminso.com",
)

pytestmark = pytest.mark.usefixtures("no_user_presets")  # the shipped presets alone

# Every phone added here and the suffixes of all its entered rear modules (its camera preset is the main module).
PHONES_VIVO_HUAWEI = {
    "vivo-x200-ultra": ("main", "ultra-wide", "telephoto"),
    "huawei-pura-80-ultra": ("main", "telephoto"),
    "samsung-galaxy-s25-edge": ("main", "ultra-wide"),
}

# (module, widest f-number, smallest f-number, 35 mm equivalent mm, stated as the maker's, sensor preset, quotes the
# entry's source must hold, pages it must cite). An f-number no launch page gives is None.
MODULES = [
    # GSMArena's Camera battle: "the new 35mm main shooter with a still impressively large 1/1.28-inch sensor";
    # Techymn on DXOMARK's ranking: "A 50MP primary camera with a 1/1.28-inch sensor".
    ("vivo-x200-ultra-main", None, None, 35.0, False, "1-1.28-inch",
     ("the new 35mm main shooter with a still impressively large 1/1.28-inch sensor",
      "A 50MP primary camera with a 1/1.28-inch sensor"),
     (CAMERA_BATTLE, VIVO_REVIEW, TECHYMN_DXOMARK)),
    # Camera battle: "the new 14mm ultrawide with the same 1/1.28-inch sensor".
    ("vivo-x200-ultra-ultra-wide", None, None, 14.0, False, "1-1.28-inch",
     ("the new 14mm ultrawide with the same 1/1.28-inch sensor",),
     (CAMERA_BATTLE, VIVO_REVIEW)),
    # GSMArena's review: "The 200MP 1/1.4" sensor on the 85mm telephoto"; Camera battle: "14mm, 35mm, and 85mm".
    ("vivo-x200-ultra-telephoto", None, None, 85.0, False, "1-1.4-inch",
     ('The 200MP 1/1.4" sensor on the 85mm telephoto', "it brings 14mm, 35mm, and 85mm lenses"),
     (VIVO_REVIEW, CAMERA_BATTLE)),
    # digitec, Huawei's figures: "focal lengths of 13, 22.5, 83 and 212 millimetres in 35 mm format"; PhoneArena:
    # "a 1-inch, 50MP main sensor", "a variable aperture covering the f/1.6-4.0 range"; Newsy Today: "(f/1.6-f/4.0)".
    ("huawei-pura-80-ultra-main", 1.6, 4.0, 22.5, True, "1-inch-phone",
     ("focal lengths of 13, 22.5, 83 and 212 millimetres in 35 mm format", "it features a 1-inch, 50MP main sensor",
      "a variable aperture covering the f/1.6-4.0 range", "the variable aperture (f/1.6-f/4.0)"),
     (DIGITEC_PURA, PHONEARENA_PURA, NEWSY_PURA)),
    # digitec: "The 83 and 212 millimetres share the sensor and correspond to a 3.7x and 9.4x optical zoom", "different
    # apertures of f/2.4 and f/3.6"; realhacker: "an 83mm f/2.4 equivalent portrait prime", "a Type 1/1.28 sensor".
    ("huawei-pura-80-ultra-telephoto", 2.4, 2.4, 83.0, True, "1-1.28-inch",
     ("The 83 and 212 millimetres share the sensor and correspond to a 3.7x and 9.4x optical zoom",
      "different apertures of f/2.4 and f/3.6", "the shorter lens is an 83mm f/2.4 equivalent portrait prime",
      "It is a Type 1/1.28 sensor", "the relatively large 1/1.28-inch-type sensor used for this telephoto system"),
     (DIGITEC_PURA, REALHACKER_PURA, TEKMONO_PURA)),
    # PhoneArena: "the same 200 MP ISOCELL HP2 sensor"; 3elife: "2亿像素、1/1.3英寸" (200 MP, 1/1.3-inch), "F1.7等效光圈和
    # 24mm等效焦距" (f/1.7, 24 mm equivalent); iDNES.cz: "světelností f/1.7". Samsung states no equivalent.
    ("samsung-galaxy-s25-edge-main", 1.7, 1.7, 24.0, False, "1-1.3-inch",
     ("the same 200 MP ISOCELL HP2 sensor", "2亿像素、1/1.3英寸的三星自研HM3传感器", "具备F1.7等效光圈和24mm等效焦距",
      "světelností f/1.7"),
     (PHONEARENA_EDGE, ELIFE_EDGE, IDNES_EDGE)),
    # 3elife: "1200万像素、1/2.55英寸、F2.2和13mm的规格" (12 MP, 1/2.55-inch, f/2.2, 13 mm); PhoneArena: "12 MP ultra-wide".
    ("samsung-galaxy-s25-edge-ultra-wide", 2.2, 2.2, 13.0, False, "1-2.55-inch",
     ("1200万像素、1/2.55英寸、F2.2和13mm的规格", "Then comes the 12 MP ultra-wide camera"),
     (ELIFE_EDGE, PHONEARENA_EDGE)),
]

# Rear modules a launch page names but that are not entered, and the words the phone's notes use for each.
NOT_ENTERED: dict[str, tuple[str, ...]] = {
    # the 40 MP ultra wide (13 mm, f/2.2: its sensor type is on no page read) and the 9.4x telephoto (212 mm, f/3.6:
    # 12.5 MP of the 3.7x module's sensor, over an area no page read gives)
    "huawei-pura-80-ultra": ("Not entered: the 40 MP ultra wide (13 mm, f/2.2", "the 9.4x (212 mm, f/3.6) telephoto"),
}

# The launch pages' zoom factors against the ratio of the printed equivalents to the main module's: (module, factor).
# digitec: "correspond to a 3.7x and 9.4x optical zoom" (83 / 22.5 = 3.69).
ZOOM_FACTORS = [
    ("huawei-pura-80-ultra-telephoto", 3.7),
]


def module_parameters():
    return pytest.mark.parametrize(
        ("lens_id", "widest", "smallest", "equivalent", "stated", "sensor_id", "quotes", "pages"), MODULES)


def phone_of(lens_id: str) -> str:
    return next(p for p, suffixes in PHONES_VIVO_HUAWEI.items() if lens_id.removeprefix(f"{p}-") in suffixes
                and lens_id.startswith(f"{p}-"))


def test_the_table_covers_every_module_of_every_phone_added():
    assert sorted(row[0] for row in MODULES) == sorted(
        f"{phone}-{suffix}" for phone, suffixes in PHONES_VIVO_HUAWEI.items() for suffix in suffixes)


@module_parameters()
def test_modules_against_their_pages(lens_id, widest, smallest, equivalent, stated, sensor_id, quotes, pages):
    check_module_against_its_pages(lens_id, widest, smallest, equivalent, stated, sensor_id, quotes, pages,
                                   never=tuple(VIVO_LEAKS))


@module_parameters()
def test_derived_focal_lengths_give_the_equivalent_back(lens_id, widest, smallest, equivalent, stated, sensor_id,
                                                        quotes, pages):
    # to the rounding of the stored focal length (two decimals of a millimetre: 0.25 % at 2.12 mm)
    check_focal_length_gives_the_equivalent(lens_id, sensor_id, equivalent, 0.003, "real focal length was not found")


@module_parameters()
def test_an_aperture_no_launch_page_gives_is_left_out_and_said(lens_id, widest, smallest, equivalent, stated,
                                                               sensor_id, quotes, pages):
    notes = " ".join(load_db().lens(lens_id).notes.split())
    assert (widest is None) == ("f_number_min not found" in notes)


@module_parameters()
def test_the_phone_brings_each_module_with_its_equivalent(lens_id, widest, smallest, equivalent, stated, sensor_id,
                                                          quotes, pages):
    row = check_fov_gives_the_equivalent(phone_of(lens_id), lens_id, equivalent, 0.25)
    sensor = load_db().sensor(sensor_id)
    assert (row["sensor_width_mm"], row["sensor_height_mm"]) == (sensor.width_mm, sensor.height_mm)


@pytest.mark.parametrize("phone", sorted(PHONES_VIVO_HUAWEI))
def test_phones_are_their_main_module(phone):
    check_phone_is_its_main_module(phone)


@pytest.mark.parametrize("phone", sorted(PHONES_VIVO_HUAWEI))
def test_every_entered_module_is_shipped_and_the_others_are_named(phone):
    shipped = {lens.id for lens in load_db().all("lens") if lens.id.startswith(f"{phone}-")}
    assert shipped == {f"{phone}-{suffix}" for suffix in PHONES_VIVO_HUAWEI[phone]}
    notes = " ".join(load_db().camera(phone).notes.split())
    for words in NOT_ENTERED.get(phone, ()):
        assert words in notes, words


def test_the_vivo_x200_ultra_main_and_ultra_wide_share_their_sensor():
    # Camera battle: the 14 mm ultra wide has "the same 1/1.28-inch sensor" as the 35 mm main camera; their focal
    # lengths then stand as their equivalents do, 35 / 14 = 2.5
    db = load_db()
    main, wide = db.lens("vivo-x200-ultra-main"), db.lens("vivo-x200-ultra-ultra-wide")
    assert main.sensor_id == wide.sensor_id
    assert main.focal_min_mm / wide.focal_min_mm == pytest.approx(35 / 14, rel=0.003)


@pytest.mark.parametrize(("lens_id", "factor"), ZOOM_FACTORS)
def test_printed_equivalents_agree_with_the_printed_zoom_factors(lens_id, factor):
    records = phone_lens_records()
    main = records[f"{phone_of(lens_id)}-main"]["equivalent_focal_length_mm"]
    # to the factor's one decimal: 83 / 22.5 = 3.69 is "3.7x", which the 212 mm lens (9.4x) or a 70 mm one (3.1x) is not
    assert records[lens_id]["equivalent_focal_length_mm"] / main == pytest.approx(factor, abs=0.05)


def test_the_pura_80_ultra_main_aperture_is_variable_over_its_stated_range():
    # PhoneArena: "a variable aperture covering the f/1.6-4.0 range"; camtool accepts -N between the two and no wider
    (row,) = run_json("dof", "--camera", "huawei-pura-80-ultra", "-N", "2.8", "-s", "2m")
    assert row["f_number"] == 2.8 and row["focal_length_mm"] == 8.81
    assert run("dof", "--camera", "huawei-pura-80-ultra", "-N", "1.4", "-s", "2m").exit_code == 2
    assert run("dof", "--camera", "huawei-pura-80-ultra", "-N", "5.6", "-s", "2m").exit_code == 2


def test_the_s25_edge_main_camera_is_the_s25_ultras_sensor_and_aperture():
    # PhoneArena: "the same 200 MP ISOCELL HP2 sensor" as the S25 Ultra; iDNES.cz: the main camera comes "rovnou ze
    # špičkového typu S25 Ultra" with f/1.7. The two modules share the sensor preset and the aperture; their focal
    # lengths come from different published figures (the Ultra's 85 degree field, the Edge's 24 mm) and agree to 2 %
    db = load_db()
    edge, ultra = db.lens("samsung-galaxy-s25-edge-main"), db.lens("samsung-galaxy-s25-ultra-main")
    assert edge.sensor_id == ultra.sensor_id == "1-1.3-inch"
    assert (edge.f_number_min, edge.f_number_max) == (ultra.f_number_min, ultra.f_number_max) == (1.7, 1.7)
    assert edge.focal_min_mm == pytest.approx(ultra.focal_min_mm, rel=0.02)
    assert "isocell-hp2" in db.sensor("1-1.3-inch").aliases


@pytest.mark.parametrize(("lens_id", "sensor_id", "inch_type"), [
    ("vivo-x200-ultra-main", "1-1.28-inch", 1.28), ("vivo-x200-ultra-telephoto", "1-1.4-inch", 1.4),
    ("huawei-pura-80-ultra-main", "1-inch-phone", 1.0), ("samsung-galaxy-s25-edge-ultra-wide", "1-2.55-inch", 2.55),
])
def test_the_sensor_presets_stand_for_the_printed_types(lens_id, sensor_id, inch_type):
    # the optical-format rule (the diagonal about 2/3 of 25.4 mm over the type) holds each preset to the type the page
    # prints, within the 7 % spread it shows for the phone formats whose size is known otherwise
    assert load_db().lens(lens_id).sensor_id == sensor_id
    assert load_db().sensor(sensor_id).diagonal_mm == pytest.approx(25.4 / inch_type * 2 / 3, rel=0.075)
