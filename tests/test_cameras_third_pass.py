"""The cinema cameras added to cameras.yaml on the third pass, against the files and pages they cite.

Every figure is the one the cited table prints (quoted next to it here): InfraXCoders/iris's camera table
(RecceKit/Sources/RecceKit/Data/cameras.csv), each row of which names the maker's page it transcribes, and
where a second table agrees (NiYien/telemetry-parser, Hugo9809/cine-power-planner) the body is confirmed. A
body whose figures only that one table gives is ``approximate`` with notes saying so; one whose figures are
its sibling's is checked against the sibling.
"""

from __future__ import annotations

import math

import pytest
from cli_helpers import run_json
from test_cameras_2026 import camera_records, check_confirmed_body

from camtool.presets import load_db

FULL_FRAME_DIAGONAL_MM = math.hypot(36.0, 24.0)
IRIS = "InfraXCoders/iris on GitHub, RecceKit/Sources/RecceKit/Data/cameras.csv at commit " \
       "8e981396e602920d1ead4eacf52d51619eb50ef9"

pytestmark = pytest.mark.usefixtures("no_user_presets")  # the shipped presets alone


# (camera, width mm, height mm, pixels across, pixels down, mount, category): two tables agree.
CONFIRMED = [
    # iris: "red_v_raptor_8k_s35,RED,V-RAPTOR 8K S35,RF,8k_17x9,8K 17:9 (full sensor),26.21,13.82,8192,4320,
    # ...,spec: 26.21 x 13.82 mm"; telemetry-parser camera_db/red.json: "V-RAPTOR 8K S35": { "sw": 26.21 }.
    ("red-v-raptor-8k-s35", 26.21, 13.82, 8192, 4320, "Canon RF", "cine"),
    # iris: "arri_alexa_35_xtreme,ARRI,ALEXA 35 Xtreme,LPL;PL,open_gate,4.6K 3:2 Open Gate,27.99,19.22,4608,3164";
    # cine-power-planner src/data/devices/cameras.js: "Arri Alexa 35 Xtreme", "requiredImageCircleMm": 33.9,
    # "4608x3164", lens mount "LPL (LBUS)" native.
    ("arri-alexa-35-xtreme", 27.99, 19.22, 4608, 3164, "ARRI LPL", "cine"),
]

# (camera, width mm, height mm, pixels across, pixels down, mount): iris alone.
ONE_DATASET = [
    # "canon_c400,Canon,EOS C400,RF,ff_6k,Full frame 6K / DCI 4K,36,19,6000,3164"
    ("canon-eos-c400", 36.0, 19.0, 6000, 3164, "Canon RF"),
    # "canon_c80,Canon,EOS C80,RF,ff_6k,Full frame 6K / DCI 4K,36,19,6000,3164"
    ("canon-eos-c80", 36.0, 19.0, 6000, 3164, "Canon RF"),
    # "canon_c300_mkiii,Canon,EOS C300 Mark III,EF,s35_dci_4k,Super 35 DCI 4K / 2K,26.2,13.8,4096,2160"
    ("canon-eos-c300-mark-iii", 26.2, 13.8, 4096, 2160, "Canon EF"),
    # "canon_c500_mkii,Canon,EOS C500 Mark II,EF,ff_5_9k,Full frame 5.9K / DCI 4K,38.1,20.1,5952,3140"
    ("canon-eos-c500-mark-ii", 38.1, 20.1, 5952, 3140, "Canon EF"),
    # "bm_pyxis_12k,Blackmagic Design,PYXIS 12K,L-Mount;EF;PL,open_gate,12K 3:2 open gate (full sensor),35.64,
    # 23.32,12288,8040" (the mount is per model variant: left out)
    ("blackmagic-pyxis-12k", 35.64, 23.32, 12288, 8040, None),
    # "ursa_cine_17k_65,Blackmagic Design,URSA Cine 17K 65,PL;LPL,open_gate,17K 2.2:1 open gate (full sensor),
    # 50.81,23.32,17520,8040"
    ("blackmagic-ursa-cine-17k-65", 50.81, 23.32, 17520, 8040, None),
]

# (camera, the shipped body whose sensor it carries, width mm, height mm, pixels across, pixels down, mount):
# iris's own figures for the body, the same as its sibling's.
CARRIED = [
    # "red_komodo_x_6k,RED,KOMODO-X 6K,RF,6k_17x9,6K 17:9 (full sensor),27.03,14.26,6144,3240,...,spec: 27.03 x
    # 14.26 mm"; the KOMODO 6K's in the Camera Sensor Database (red/komodo6kog.md): "6K 17:9 | 6144 x 3240 |
    # 27.03 x 14.26".
    ("red-komodo-x", "red-komodo-6k", 27.03, 14.26, 6144, 3240, "Canon RF"),
    # "red_v_raptor_xl_8k_vv,RED,V-RAPTOR XL 8K VV,PL;EF,8k_17x9,8K 17:9 (full sensor),40.96,21.60,8192,4320";
    # the V-RAPTOR 8K VV's in the Camera Sensor Database (red/vraptor8kvv.md): 8192 x 4320, 40.96 x 21.6 mm.
    ("red-v-raptor-xl-8k-vv", "red-v-raptor-8k-vv", 40.96, 21.60, 8192, 4320, None),
    # "red_v_raptor_x_8k_vv,RED,V-RAPTOR [X] 8K VV,RF,8k_17x9,8K 17:9 (full sensor),40.96,21.60,8192,4320"
    ("red-v-raptor-x-8k-vv", "red-v-raptor-8k-vv", 40.96, 21.60, 8192, 4320, "Canon RF"),
    # "red_v_raptor_xl_x_8k_vv,RED,V-RAPTOR XL [X] 8K VV,PL;EF,8k_17x9,8K 17:9 (full sensor),40.96,21.60,8192,4320"
    ("red-v-raptor-xl-x-8k-vv", "red-v-raptor-8k-vv", 40.96, 21.60, 8192, 4320, None),
]

# (camera, a smaller mode's width mm, its pixels across, the mode as `source` quotes it): modes read 1:1 from a
# window of the sensor keep the photosite pitch of the largest area.
WINDOWS = [
    # iris, from RED's KOMODO 6K format table: "6k_16x9,6K 16:9,25.34,14.26,5760,3240"
    ("red-komodo-x", 25.34, 5760, "6K 16:9 25.34 x 14.26 mm at 5760 x 3240"),
    # iris, from RED's V-RAPTOR [X] 8K VV format table: "6k_17x9,6K 17:9 (S35 crop),30.72,16.20,6144,3240"
    ("red-v-raptor-xl-8k-vv", 30.72, 6144, "6K 17:9 30.72 x 16.20 mm at 6144 x 3240"),
    ("red-v-raptor-x-8k-vv", 30.72, 6144, "6K 17:9 30.72 x 16.20 mm at 6144 x 3240"),
    # iris, from ARRI's Xtreme poster: "4k_16x9,4K 16:9,24.88,14.00,4096,2304"
    ("arri-alexa-35-xtreme", 24.88, 4096, '"4K 16:9", 24.88 x 14.00 mm, 4096 x 2304'),
    # iris, from Blackmagic's 17K sheet: "12k_3x2_lf,12K 3:2 (LF crop),35.64,23.32,12288,8040,...,window"
    ("blackmagic-ursa-cine-17k-65", 35.64, 12288, "12K 3:2 (LF crop) 35.64 x 23.32 mm at 12288 x 8040"),
    # iris, from Blackmagic's PYXIS page: "9k_3x2_s35,9K 3:2 (Super 35 crop),27.29,18.17,9408,6264,...,window"
    ("blackmagic-pyxis-12k", 27.29, 9408, "9K 3:2 (Super 35 crop) 27.29 x 18.17 mm at 9408 x 6264"),
]


def added_camera_ids() -> set[str]:
    return {row[0] for row in CONFIRMED} | {row[0] for row in ONE_DATASET} | {row[0] for row in CARRIED}


@pytest.mark.parametrize(("camera", "width", "height", "across", "down", "mount", "category"), CONFIRMED)
def test_confirmed_bodies_against_their_tables(camera, width, height, across, down, mount, category):
    check_confirmed_body(camera, width, height, across, down, mount, category)


@pytest.mark.parametrize(("camera", "width", "height", "across", "down", "mount"), ONE_DATASET)
def test_cinema_cameras_from_one_table(camera, width, height, across, down, mount):
    body = load_db().camera(camera)
    assert (body.sensor.width_mm, body.sensor.height_mm) == (width, height)
    assert (body.pixels_w, body.pixels_h) == (across, down)
    assert body.mount == mount and body.category == "cine"
    assert body.approximate and "one dataset" in " ".join(body.notes.split()).lower()
    # the table's sizes, rounded to its decimals, give square photosites
    assert width / across == pytest.approx(height / down, rel=0.005)


@pytest.mark.parametrize(("camera", "sibling", "width", "height", "across", "down", "mount"), CARRIED)
def test_carried_sensors_are_the_siblings_and_flagged(camera, sibling, width, height, across, down, mount):
    db = load_db()
    body, before = db.camera(camera), db.camera(sibling)
    assert (body.sensor.width_mm, body.sensor.height_mm) == (width, height)
    assert (before.sensor.width_mm, before.sensor.height_mm) == pytest.approx((width, height))
    assert (body.pixels_w, body.pixels_h) == (before.pixels_w, before.pixels_h) == (across, down)
    assert body.mount == mount and body.category == before.category == "cine"
    assert not before.approximate
    notes = " ".join(body.notes.split())
    assert body.approximate and "not confirmed" in notes.lower() and sibling in notes


@pytest.mark.parametrize(("camera", "mode_width", "mode_across", "quote"), WINDOWS)
def test_windowed_modes_keep_the_photosite_pitch(camera, mode_width, mode_across, quote):
    body = load_db().camera(camera)
    assert quote in " ".join(camera_records()[camera]["source"].split())
    # pitch of the largest area against the window's, to the tables' two decimals of a millimetre
    assert body.sensor.width_mm / body.pixels_w == pytest.approx(mode_width / mode_across, rel=0.003)


@pytest.mark.parametrize(("camera", "diagonal"), [
    # iris, quoting Canon: "maker-stated effective screen size (40.7 mm diag)", "(43.1 mm diag)"
    ("canon-eos-c400", 40.7), ("canon-eos-c80", 40.7), ("canon-eos-c500-mark-ii", 43.1),
    # cine-power-planner: "Arri Alexa 35 Xtreme", "requiredImageCircleMm": 33.9
    ("arri-alexa-35-xtreme", 33.9),
])
def test_the_stated_diagonal_is_the_areas(camera, diagonal):
    body = load_db().camera(camera)
    assert math.hypot(body.sensor.width_mm, body.sensor.height_mm) == pytest.approx(diagonal, abs=0.06)
    assert str(diagonal) in camera_records()[camera]["source"]


def test_the_c300_iii_area_gives_canons_lens_magnification():
    # iris, quoting Canon for Super 35 DCI 4K: "x1.460" (the full-frame diagonal over the area's)
    body = load_db().camera("canon-eos-c300-mark-iii")
    crop = FULL_FRAME_DIAGONAL_MM / math.hypot(body.sensor.width_mm, body.sensor.height_mm)
    assert crop == pytest.approx(1.460, abs=0.005)


def test_the_v_raptor_s35_width_is_the_second_tables():
    # telemetry-parser camera_db/red.json: "V-RAPTOR 8K S35": { "sw": 26.21 }; its "V-RAPTOR 8K VV": 40.96
    db = load_db()
    assert db.camera("red-v-raptor-8k-s35").sensor.width_mm == 26.21
    assert db.camera("red-v-raptor-8k-vv").sensor.width_mm == 40.96


def test_every_added_body_cites_the_table_read_and_the_makers_page():
    records = camera_records()
    for camera in added_camera_ids():
        source = " ".join(records[camera]["source"].split())
        assert IRIS in source, camera
        assert "https://" in source, camera  # the maker's page (or its rehosted sheet) the table transcribes


def test_no_body_is_entered_twice():
    # each added body is new: no earlier entry carries its id or its aliases
    db = load_db()
    for camera in added_camera_ids():
        for alias in camera_records()[camera].get("aliases", []):
            assert db.camera(alias).id == camera, alias


def test_a_cine_preset_of_the_third_pass_takes_the_cinema_coc():
    (row,) = run_json("dof", "--camera", "komodo-x", "-f", "35", "-N", "2.8", "-s", "3m")
    assert row["coc_mm"] == pytest.approx(0.025)


def test_the_c400_equivalent_follows_from_its_area():
    # 50 mm on 36 x 19 mm: 50 x 43.27 / 40.71 = 53.1 mm in 35 mm terms
    (row,) = run_json("fov", "--camera", "canon-eos-c400", "-f", "50")
    assert row["equivalent_focal_length_mm"] == pytest.approx(50 * FULL_FRAME_DIAGONAL_MM / math.hypot(36, 19),
                                                              abs=0.05)
