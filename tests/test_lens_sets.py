"""Lens sets: one preset holding every focal length of a cine prime set, a member chosen by -f or SET@FOCAL."""

from __future__ import annotations

import math
from pathlib import Path

import pytest
import yaml
from cli_helpers import run, run_json
from conftest import point_xdg_at, presets_home

from camtool.core.errors import InputError
from camtool.plans.equipment import set_member
from camtool.presets import PresetFileError, PresetNotFound, load_db


@pytest.fixture(autouse=True)
def isolated(request, monkeypatch, shared_presets_home):
    root = presets_home(request, shared_presets_home, "tmp_path")
    point_xdg_at(root, monkeypatch)
    return root


# lens_db/lenses.yaml, arri-signature-prime (its source: the 'ARRI Signature Prime <f>mm T<t>' rows of
# Hugo9809/cine-power-planner's gear table, src/data/devices/gearList.js at 1a0649d, and the arri_signature_prime_*
# rows of InfraXCoders/iris's lenses.csv at f7b56ce, ARRI's technical data): (focal length, 'tStop', 'minFocusMeters'
# in mm) -- T1.8 from 12 to 150 mm, 0.35 m from 12 to 40 mm, 0.45 m at 47 and 58 mm, ...; T2.5 and 1.8 m at 200 mm,
# T2.8 and 2.5 m at 280 mm
SIGNATURE = [(12, 1.8, 350), (15, 1.8, 350), (18, 1.8, 350), (21, 1.8, 350), (25, 1.8, 350), (29, 1.8, 350),
             (35, 1.8, 350), (40, 1.8, 350), (47, 1.8, 450), (58, 1.8, 450), (75, 1.8, 650), (95, 1.8, 850),
             (125, 1.8, 1000), (150, 1.8, 1500), (200, 2.5, 1800), (280, 2.8, 2500)]


def test_every_member_carries_its_own_stop_and_close_focus():
    lens = load_db().lens("signature-prime")
    assert [(m.focal_min_mm, m.t_number_min, m.min_focus_mm) for m in lens.members] == SIGNATURE
    assert all(not m.is_zoom for m in lens.members) and lens.approximate
    assert not lens.is_zoom and (lens.focal_min_mm, lens.focal_max_mm) == (12.0, 280.0)
    # each close focus leaves room for a real image: object and image at least 4f apart for a thin lens
    assert all(close > 4 * focal for focal, _, close in SIGNATURE)
    records = yaml.safe_load((Path(__file__).resolve().parents[1] / "lens_db" / "lenses.yaml").read_text(encoding="utf-8"))
    source = " ".join(next(r for r in records["lenses"] if r["id"] == "arri-signature-prime")["source"].split())
    assert "1a0649dfdf38d652a175d9ba9dca737677f1d1ff" in source and "f7b56cebe00e52f7842a2758a9efeece84519db8" in source
    # the 47 mm agrees with the single-lens entry that cites the same figures
    single = load_db().lens("arri-signature-prime-47mm-t1.8")
    assert lens.member(47.0).min_focus_mm == single.min_focus_mm
    assert lens.member(47.0).t_number_min == single.t_number_min


def test_a_member_by_name():
    db = load_db()
    member = db.lens("arri-signature-prime@47")
    assert member.id == "arri-signature-prime@47" and member.focal_min_mm == 47.0
    assert db.lens("Signature Prime@47mm") is member  # any spelling of the set, a unit on the focal length
    with pytest.raises(PresetNotFound) as caught:
        db.lens("signature-prime@50")
    assert "arri-signature-prime@47" in caught.value.suggestions
    with pytest.raises(PresetNotFound):
        db.lens("rf-50-1.8@50")  # not a set


def test_the_plan_picks_the_member_at_the_one_focal_length():
    lens = load_db().lens("signature-prime")
    assert set_member(lens, focal_lengths=[35.0]).id == "arri-signature-prime@35"
    assert set_member(lens, focal_lengths=[35.0, 35.0]).id == "arri-signature-prime@35"
    for focal_lengths in ([], [35.0, 47.0], [50.0]):
        with pytest.raises(InputError):
            set_member(lens, focal_lengths=focal_lengths)
    prime = load_db().lens("rf-50-1.8")
    assert set_member(prime, focal_lengths=[]) is prime


def test_the_option_and_the_name_give_the_same_rows():
    by_option = run_json("dof", "--lens", "signature-prime", "-f", "47", "-N", "T1.8", "-s", "2m")
    by_name = run_json("dof", "--lens", "arri-signature-prime@47", "-N", "T1.8", "-s", "2m")
    assert by_option == by_name
    assert by_option[0]["t_stop"] == 1.8 and by_option[0]["focal_length_mm"] == 47.0


@pytest.mark.parametrize(("args", "words"), [
    (["-N", "2", "-s", "2m"], "is a set of lenses"),
    (["-f", "50", "-N", "2", "-s", "2m"], "50 mm is not in the set"),
    (["-f", "35,47", "-N", "2", "-s", "2m"], "one per focal length"),
    (["-f", "35", "-N", "2", "-s", "0.3m"], "0.35 m"),  # the 35 mm's own close focus
    (["-f", "35", "-N", "T1.4", "-s", "2m"], "T1.8"),  # and its own widest T-stop
])
def test_what_a_set_refuses_is_one_line_exit_2(args, words):
    result = run("dof", "--lens", "signature-prime", *args)
    assert result.exit_code == 2 and result.stdout == ""
    assert words in result.stderr and result.stderr.count("\n") == 1


def test_presets_show_and_list_name_the_members():
    (row,) = run_json("presets", "show", "signature-prime")
    assert row["members"][0] == "arri-signature-prime@12" and len(row["members"]) == len(SIGNATURE)
    assert row["members"][-1] == "arri-signature-prime@280"
    (row,) = run_json("presets", "show", "signature-prime@25")
    assert row["min_focus_mm"] == 350.0


@pytest.mark.parametrize(("lines", "key"), [
    ("    set:\n      - {focal_length_mm: 50}\n    focal_length_mm: 50\n", "focal_length_mm"),
    ("    set:\n      - {focal_length_mm: 50}\n      - {focal_length_mm: 35}\n", "set"),
    ("    set:\n      - {focal_length_mm: 50, t_number_min: 1.2, f_number_min: 1.4}\n", "set"),
    ("    set: []\n", "set"),
    ("    set:\n      - {min_focus_mm: 300}\n", "set"),
])
def test_bad_sets_in_a_preset_file(tmp_path, lines, key):
    path = tmp_path / "bad.yaml"
    path.write_text("lenses:\n  - id: my-set\n" + lines, encoding="utf-8")
    with pytest.raises(PresetFileError) as caught:
        load_db(extra_files=(path,))
    assert key in str(caught.value) and "\n" not in str(caught.value)


CINE = Path(__file__).resolve().parents[1] / "lens_db" / "cine-lenses.yaml"
CINE_RECORDS = yaml.safe_load(CINE.read_text(encoding="utf-8"))["lenses"]


def test_the_cine_lens_file_s_sets_load_member_by_member():
    """lens_db/cine-lenses.yaml (read with yaml): each set's members carry their own stop and close focus, and an
    anamorphic set's squeeze reaches every member; an entry not marked approximate cites the page it quotes."""
    db = load_db()
    for record in CINE_RECORDS:
        lens = db.lens(record["id"])
        assert lens.squeeze == record.get("squeeze") and lens.notes
        assert lens.approximate == record.get("approximate", False)
        assert lens.approximate or "http" in lens.source
        if "set" not in record:  # a single cinema lens, or a zoom
            ends = (record.get("focal_min_mm", record.get("focal_length_mm")),
                    record.get("focal_max_mm", record.get("focal_length_mm")))
            assert not lens.members and (lens.focal_min_mm, lens.focal_max_mm) == tuple(map(float, ends))
            assert (lens.t_number_min, lens.min_focus_mm) == (record["t_number_min"], record["min_focus_mm"])
            continue
        rows = [(float(r["focal_length_mm"]), r.get("t_number_min"), r.get("min_focus_mm")) for r in record["set"]]
        assert [(m.focal_min_mm, m.t_number_min, m.min_focus_mm) for m in lens.members] == rows
        assert {m.squeeze for m in lens.members} == {record.get("squeeze")}


# Each set's members as its source prints them: (focal length mm, widest T-stop, closest focus mm or None where
# the source gives none). Figures in metres in the source are written here in mm (0.22 m = 220 mm).
CITED_SETS = {
    # Hugo9809/cine-power-planner gearList.js at 1a0649d, 'ARRI/ZEISS Ultra Prime <f>mm T<t>' rows, minFocusMeters;
    # the 28 mm from InfraXCoders/iris lenses.csv at f7b56ce, row arri_zeiss_ultra_prime_28 (ARRI's page)
    "arri-zeiss-ultra-prime": [
        (8, 2.8, 350), (10, 2.1, 350), (12, 2.0, 300), (14, 1.9, 220), (16, 1.9, 250), (20, 1.9, 280),
        (24, 1.9, 300), (28, 1.9, 280), (32, 1.9, 350), (40, 1.9, 380), (50, 1.9, 600), (65, 1.9, 650), (85, 1.9, 900),
        (100, 1.9, 1000), (135, 1.9, 1500), (180, 1.9, 2600)],
    # the same table, 'ZEISS Master Prime <f>mm T1.3' rows; the 27, 32, 35, 40, 65, 135 and 150 mm close focus from
    # the dataset's arri_zeiss_master_prime_<f> rows (ARRI's page)
    "arri-zeiss-master-prime": [
        (12, 1.3, 400), (14, 1.3, 350), (16, 1.3, 350), (18, 1.3, 350), (21, 1.3, 350), (25, 1.3, 350),
        (27, 1.3, 350), (32, 1.3, 350), (35, 1.3, 350), (40, 1.3, 400), (50, 1.3, 500), (65, 1.3, 650),
        (75, 1.3, 800), (100, 1.3, 1000), (135, 1.3, 950), (150, 1.3, 1500)],
    # the same table, 'Leitz Summicron-C <f>mm T2.0' rows; the dataset's leitz_summicron_c_<f> rows (Leitz's page)
    "leitz-summicron-c": [
        (15, 2.0, 300), (18, 2.0, 300), (21, 2.0, 300), (25, 2.0, 300), (29, 2.0, 300), (35, 2.0, 360),
        (40, 2.0, 450), (50, 2.0, 600), (75, 2.0, 800), (100, 2.0, 1000), (135, 2.0, 1350)],
    # InfraXCoders/iris lenses.csv at f7b56ce, rows cooke_s7i_prime_<f> (Cooke's S7/i sheet), t_stop and close_focus_m
    "cooke-s7i": [
        (16, 2, 400), (18, 2, 400), (21, 2, 400), (25, 2, 350), (27, 2, 350), (32, 2, 350), (40, 2, 450), (50, 2, 500),
        (65, 2, 500), (75, 2, 475), (100, 2, 700), (135, 2, 950), (180, 2, 1300), (300, 3.3, 2100)],
    # SHOOT Online: 'the S8/i FF spherical lenses, at T1.4'; focal lengths from the table's 'Cooke S8/i FF' rows
    "cooke-s8i-ff": [(25, 1.4, None), (32, 1.4, None), (40, 1.4, None), (50, 1.4, None), (75, 1.4, None),
                     (100, 1.4, None)],
    # RedShark News review (2mmachining.com copy): '25, 32, 50, 75, and 100mm focal lengths all at T2.4'; the close
    # focus and the 18 mm from the dataset's cooke_sp3_<f> rows (Cooke's SP3 sheet)
    "cooke-sp3": [(18, 2.4, 250), (25, 2.4, 250), (32, 2.4, 350), (50, 2.4, 500), (75, 2.4, 800), (100, 2.4, 800)],
    # the table's 'ZEISS Nano Prime <f>mm T1.5' rows; the close focus from aku0419/zhuiguang-camera-toolkit
    # src/data/lenses/zeiss-nano-prime-<f>mm-t1-5.json at 3367517 (ZEISS's Technical Data, 'from the sensor plane')
    "zeiss-nano-prime": [(18, 1.5, 250), (24, 1.5, 350), (35, 1.5, 450), (50, 1.5, 500), (75, 1.5, 750),
                         (100, 1.5, 1000)],
}


@pytest.mark.parametrize("set_id", sorted(CITED_SETS))
def test_each_set_holds_its_cited_members(set_id):
    lens = load_db().lens(set_id)
    got = [(m.focal_min_mm, m.t_number_min, m.min_focus_mm) for m in lens.members]
    want = [(float(f), t, None if s is None else float(s)) for f, t, s in CITED_SETS[set_id]]
    assert got == want
    assert all(m.id == f"{set_id}@{m.focal_min_mm:g}" and not m.is_zoom for m in lens.members)


def test_every_cited_close_focus_leaves_room_for_a_real_image():
    """A thin lens of focal length f brings an object to focus on the sensor only when object and image are at least
    4f apart (s = f(1+m)^2/m is smallest, 4f, at m = 1): each published close focus clears it, so a figure typed in
    the wrong unit (cm for mm, feet for metres) would fail here."""
    db = load_db()
    for set_id in CITED_SETS:
        for member in db.lens(set_id).members:
            if member.min_focus_mm is not None:
                assert member.min_focus_mm > 4 * member.focal_min_mm, member.id


@pytest.mark.parametrize(("lens", "focal", "stop", "closest", "closer"), [
    ("ultra-prime", "14", "T1.9", "0.22m", "0.21m"),  # the table's 0.22 m at 14 mm
    ("master-prime", "12", "T1.3", "0.4m", "0.39m"),  # 0.4 m at 12 mm
    ("summicron-c", "25", "T2", "0.3m", "0.29m"),  # 0.3 m at 25 mm
])
def test_a_cited_member_focuses_to_its_close_focus_and_no_closer(lens, focal, stop, closest, closer):
    assert run("dof", "--lens", lens, "-f", focal, "-N", stop, "-s", closest).exit_code == 0
    result = run("dof", "--lens", lens, "-f", focal, "-N", stop, "-s", closer)
    assert result.exit_code == 2 and result.stderr.count("\n") == 1
    assert closest.removesuffix("m").rstrip("0") in result.stderr


@pytest.mark.parametrize(("lens", "focal", "faster", "widest"), [
    ("master-prime", "50", "T1.2", "T1.3"), ("sp3", "32", "T2.2", "T2.4"), ("ultra-prime", "8", "T2.5", "T2.8"),
])
def test_a_member_refuses_a_stop_wider_than_its_own(lens, focal, faster, widest):
    result = run("dof", "--lens", lens, "-f", focal, "-N", faster, "-s", "3m")
    assert result.exit_code == 2 and widest in result.stderr and result.stderr.count("\n") == 1
    assert run("dof", "--lens", lens, "-f", focal, "-N", widest, "-s", "3m").exit_code == 0


# Cinema zooms as the table prints them: (short end, long end, widest T-stop, closest focus mm); its notes say
# 'ARRI technical data' for the Signature Zooms and 'ZEISS (Cinema Zoom) brochure' for the CZ.2s.
CITED_ZOOMS = {
    "arri-signature-zoom-16-32mm-t2.8": (16, 32, 2.8, 450),  # 'MOD = 0.45 m'
    "arri-signature-zoom-24-75mm-t2.8": (24, 75, 2.8, 700),  # minFocusMeters 0.7
    "arri-signature-zoom-45-135mm-t2.8": (45, 135, 2.8, 1000),  # '1 m MOD'
    "arri-signature-zoom-65-300mm-t2.8": (65, 300, 2.8, 1800),  # '1.8 m MOD from sensor plane'
    "zeiss-cz2-15-30mm-t2.9": (15, 30, 2.9, 550),
    "zeiss-cz2-28-80mm-t2.9": (28, 80, 2.9, 830),
    "zeiss-cz2-70-200mm-t2.9": (70, 200, 2.9, 1520),
}


@pytest.mark.parametrize("lens_id", sorted(CITED_ZOOMS))
def test_each_cine_zoom_holds_its_cited_range_stop_and_close_focus(lens_id):
    lens = load_db().lens(lens_id)
    short, long, stop, closest = CITED_ZOOMS[lens_id]
    assert lens.is_zoom and not lens.members and lens.category == "cine"
    assert (lens.focal_min_mm, lens.focal_max_mm, lens.t_number_min, lens.min_focus_mm) == (short, long, stop, closest)
    assert closest > 4 * long  # the thin lens's 4f at the long end, where it is largest
    for focal in (short, long):  # one close focus over the range: reached at both ends, refused 1 cm closer
        args = ("dof", "--lens", lens_id, "-f", str(focal), "-N", f"T{stop}")
        assert run(*args, "-s", f"{closest}mm").exit_code == 0
        assert run(*args, "-s", f"{closest - 10}mm").exit_code == 2


def test_the_vazen_anamorphic_carries_its_squeeze_stop_and_close_focus():
    """Photolari, printing Vazen's figures: 50 mm, T2.1, 1.8x squeeze, minimum focus 1.1 m. With the lens the
    horizontal angle is the de-squeezed one, 2 atan(1.8 w / 2f), on a Super 35 frame 24.89 mm wide."""
    lens = load_db().lens("vazen-50")
    assert (lens.focal_min_mm, lens.t_number_min, lens.min_focus_mm, lens.squeeze) == (50.0, 2.1, 1100.0, 1.8)
    (row,) = run_json("fov", "--lens", "vazen-50", "--sensor", "s35")
    width = load_db().sensor("s35").width_mm
    assert row["horizontal_deg"] == pytest.approx(2 * math.degrees(math.atan(1.8 * width / 100.0)), abs=0.01)
    result = run("dof", "--lens", "vazen-50", "-N", "T2.1", "-s", "1m")
    assert result.exit_code == 2 and "1.1 m" in result.stderr
    assert run("dof", "--lens", "vazen-50", "-N", "T2.1", "-s", "1.1m").exit_code == 0


def test_a_set_member_s_own_close_focus_is_refused_closer():
    # lens_db/cine-lenses.yaml, cooke-s7i: 0.35 m at 25 mm (Cooke's sheet as the dataset transcribes it; the gear
    # table's 0.36 m is not entered)
    result = run("dof", "--lens", "cooke-s7i", "-f", "25", "-N", "T2", "-s", "0.34m")
    assert result.exit_code == 2 and "0.35 m" in result.stderr and result.stderr.count("\n") == 1
    assert run("dof", "--lens", "cooke-s7i", "-f", "25", "-N", "T2", "-s", "0.35m").exit_code == 0
