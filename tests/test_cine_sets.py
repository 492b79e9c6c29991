"""The cinema lens sets and zooms added to lens_db/cine-lenses.yaml from a public camera-gear table, each figure
checked against the table's row as it prints it."""

from __future__ import annotations

from pathlib import Path

import pytest
import yaml
from cli_helpers import run, run_json
from conftest import point_xdg_at, presets_home

from camtool.presets import load_db


@pytest.fixture(autouse=True)
def isolated(request, monkeypatch, shared_presets_home):
    root = presets_home(request, shared_presets_home, "tmp_path")
    point_xdg_at(root, monkeypatch)
    return root


CINE = Path(__file__).resolve().parents[1] / "lens_db" / "cine-lenses.yaml"
RECORDS = {r["id"]: r for r in yaml.safe_load(CINE.read_text(encoding="utf-8"))["lenses"]}

# The table read: Hugo9809/cine-power-planner, src/data/devices/gearList.js at this commit.
TABLE = "Hugo9809/cine-power-planner"
COMMIT = "1a0649dfdf38d652a175d9ba9dca737677f1d1ff"

# Each set's rows as the table prints them: (focal length in mm from the row's name, its 'tStop', its
# 'minFocusMeters' in metres).
CITED_SETS = {
    # 'Canon Sumire Prime <f>mm T<t>' rows (mount 'PL / EF (convertible)')
    "canon-sumire-prime": [(14, 3.1, 0.203), (20, 1.5, 0.3), (24, 1.5, 0.3), (35, 1.5, 0.46), (50, 1.3, 0.46),
                           (85, 1.3, 0.95), (135, 2.2, 1.0)],
    # 'Leitz Elsie <f>mm T2.1' rows (mount 'LPL (Cooke /i, LDS-2)')
    "leitz-elsie": [(15, 2.1, 0.35), (18, 2.1, 0.35), (21, 2.1, 0.35), (25, 2.1, 0.35), (29, 2.1, 0.35),
                    (35, 2.1, 0.35), (40, 2.1, 0.35), (65, 2.1, 0.65), (75, 2.1, 0.75), (100, 2.1, 0.85),
                    (150, 2.1, 1.5)],
    # 'Leitz Thalia <f>mm T<t>' rows ('Specs from Leitz THALIA datasheet'); the '90mm T2.2 (Thalia-T variant)' row
    # is not a member of the set
    "leitz-thalia": [(24, 3.6, 0.2), (30, 2.9, 0.5), (35, 2.6, 0.55), (45, 2.9, 0.6), (55, 2.8, 0.3), (70, 2.6, 0.5),
                     (100, 2.2, 0.7), (120, 2.6, 0.57), (180, 3.6, 1.5)],
    # 'Cooke Speed Panchro TLS <f>mm T<t>' rows (mount 'PL'); the table's 'P+S rehousing' rows give no close focus
    "cooke-speed-panchro-tls": [(18, 2.2, 0.2), (25, 2.2, 0.2), (32, 2.3, 0.23), (40, 2.3, 0.33), (50, 2.3, 0.38)],
}

# The second source: a public dataset of the makers' own specification pages (each row with its source_url), read at
# this commit. Each set's rows as the dataset prints them: (row id, focal_mm, t_stop, close_focus_m), and the set's
# squeeze (the rows' 'squeeze' column; None where it is 1, a spherical lens).
DATASET = "InfraXCoders/iris"
DATASET_PATH = "RecceKit/Sources/RecceKit/Data/lenses.csv"
DATASET_COMMIT = "f7b56cebe00e52f7842a2758a9efeece84519db8"
DATASET_SETS = {
    "zeiss-cp3": (None, [
        ("zeiss_cp3_15", 15, 2.9, 0.3), ("zeiss_cp3_18", 18, 2.9, 0.3), ("zeiss_cp3_21", 21, 2.9, 0.24),
        ("zeiss_cp3_25", 25, 2.1, 0.26), ("zeiss_cp3_28", 28, 2.1, 0.24), ("zeiss_cp3_35", 35, 2.1, 0.3),
        ("zeiss_cp3_50", 50, 2.1, 0.45), ("zeiss_cp3_85", 85, 2.1, 1), ("zeiss_cp3_100", 100, 2.1, 0.7),
        ("zeiss_cp3_135", 135, 2.1, 1)]),
    "zeiss-supreme-prime": (None, [
        ("zeiss_supreme_prime_15", 15, 1.8, 0.35), ("zeiss_supreme_prime_18", 18, 1.5, 0.35),
        ("zeiss_supreme_prime_21", 21, 1.5, 0.35), ("zeiss_supreme_prime_25", 25, 1.5, 0.26),
        ("zeiss_supreme_prime_29", 29, 1.5, 0.33), ("zeiss_supreme_prime_35", 35, 1.5, 0.32),
        ("zeiss_supreme_prime_40", 40, 1.5, 0.42), ("zeiss_supreme_prime_50", 50, 1.5, 0.45),
        ("zeiss_supreme_prime_65", 65, 1.5, 0.6), ("zeiss_supreme_prime_85", 85, 1.5, 0.84),
        ("zeiss_supreme_prime_100", 100, 1.5, 1.1), ("zeiss_supreme_prime_135", 135, 1.5, 1.4),
        ("zeiss_supreme_prime_150", 150, 1.8, 1.5), ("zeiss_supreme_prime_200", 200, 2.2, 2)]),
    "cooke-s4i": (None, [
        ("cooke_s4i_prime_12", 12, 2, 0.225), ("cooke_s4i_prime_14", 14, 2, 0.225),
        ("cooke_s4i_prime_16", 16, 2, 0.225), ("cooke_s4i_prime_18", 18, 2, 0.25),
        ("cooke_s4i_prime_21", 21, 2, 0.25), ("cooke_s4i_prime_25", 25, 2, 0.25),
        ("cooke_s4i_prime_27", 27, 2, 0.25), ("cooke_s4i_prime_32", 32, 2, 0.325),
        ("cooke_s4i_prime_35", 35, 2, 0.35), ("cooke_s4i_prime_40", 40, 2, 0.45),
        ("cooke_s4i_prime_50", 50, 2, 0.55), ("cooke_s4i_prime_65", 65, 2, 0.7), ("cooke_s4i_prime_75", 75, 2, 0.8),
        ("cooke_s4i_prime_100", 100, 2, 0.95), ("cooke_s4i_prime_135", 135, 2, 0.85),
        ("cooke_s4i_prime_150", 150, 2, 1.05), ("cooke_s4i_prime_180", 180, 2, 1.3),
        ("cooke_s4i_prime_300", 300, 2.8, 2.1)]),
    "cooke-panchro-i-classic-ff": (None, [
        ("cooke_panchro_i_classic_ff_18", 18, 2.2, 0.3), ("cooke_panchro_i_classic_ff_21", 21, 2.2, 0.3),
        ("cooke_panchro_i_classic_ff_25", 25, 2.2, 0.35), ("cooke_panchro_i_classic_ff_27", 27, 2.2, 0.35),
        ("cooke_panchro_i_classic_ff_32", 32, 2.2, 0.35), ("cooke_panchro_i_classic_ff_40", 40, 2.2, 0.35),
        ("cooke_panchro_i_classic_ff_50", 50, 2.2, 0.4), ("cooke_panchro_i_classic_ff_65_macro", 65, 2.4, 0.325),
        ("cooke_panchro_i_classic_ff_75", 75, 2.2, 0.7), ("cooke_panchro_i_classic_ff_100", 100, 2.6, 0.6),
        ("cooke_panchro_i_classic_ff_135", 135, 2.8, 0.85), ("cooke_panchro_i_classic_ff_152", 152, 3, 1.1)]),
    "sigma-cine-ff-high-speed": (None, [
        ("sigma_ff_high_speed_14", 14, 2, 0.27), ("sigma_ff_high_speed_20", 20, 1.5, 0.28),
        ("sigma_ff_high_speed_24", 24, 1.5, 0.25), ("sigma_ff_high_speed_28", 28, 1.5, 0.28),
        ("sigma_ff_high_speed_35", 35, 1.5, 0.3), ("sigma_ff_high_speed_40", 40, 1.5, 0.4),
        ("sigma_ff_high_speed_50", 50, 1.5, 0.4), ("sigma_ff_high_speed_65", 65, 1.5, 0.65),
        ("sigma_ff_high_speed_85", 85, 1.5, 0.85), ("sigma_ff_high_speed_105", 105, 1.5, 1),
        ("sigma_ff_high_speed_135", 135, 2, 0.88)]),
    "tokina-vista-prime": (None, [
        ("tokina_vista_18", 18, 1.5, 0.45), ("tokina_vista_21", 21, 1.5, 0.36), ("tokina_vista_25", 25, 1.5, 0.35),
        ("tokina_vista_29", 29, 1.5, 0.35), ("tokina_vista_35", 35, 1.5, 0.41), ("tokina_vista_40", 40, 1.5, 0.45),
        ("tokina_vista_50", 50, 1.5, 0.48), ("tokina_vista_65", 65, 1.5, 0.69), ("tokina_vista_85", 85, 1.5, 0.95),
        ("tokina_vista_105", 105, 1.5, 1.15), ("tokina_vista_135", 135, 1.5, 1.4)]),
    "leitz-summilux-c": (None, [
        ("leitz_summilux_c_16", 16, 1.4, 0.45), ("leitz_summilux_c_18", 18, 1.4, 0.45),
        ("leitz_summilux_c_21", 21, 1.4, 0.38), ("leitz_summilux_c_25", 25, 1.4, 0.38),
        ("leitz_summilux_c_29", 29, 1.4, 0.45), ("leitz_summilux_c_35", 35, 1.4, 0.45),
        ("leitz_summilux_c_40", 40, 1.4, 0.45), ("leitz_summilux_c_50", 50, 1.4, 0.6),
        ("leitz_summilux_c_65", 65, 1.4, 0.45), ("leitz_summilux_c_75", 75, 1.4, 0.79),
        ("leitz_summilux_c_100", 100, 1.4, 0.99), ("leitz_summilux_c_135", 135, 1.4, 1.25)]),
    "arri-zeiss-master-anamorphic": (2, [
        ("arri_zeiss_master_anamorphic_28", 28, 1.9, 0.65), ("arri_zeiss_master_anamorphic_35", 35, 1.9, 0.75),
        ("arri_zeiss_master_anamorphic_40", 40, 1.9, 0.7), ("arri_zeiss_master_anamorphic_50", 50, 1.9, 0.75),
        ("arri_zeiss_master_anamorphic_60", 60, 1.9, 0.9), ("arri_zeiss_master_anamorphic_75", 75, 1.9, 0.9),
        ("arri_zeiss_master_anamorphic_100", 100, 1.9, 0.95), ("arri_zeiss_master_anamorphic_135", 135, 1.9, 1.2),
        ("arri_zeiss_master_anamorphic_180", 180, 2.8, 1.5)]),
    "atlas-orion": (2, [
        ("atlas_orion_18", 18, 2, 0.45), ("atlas_orion_21", 21, 2, 0.45), ("atlas_orion_25", 25, 2, 0.45),
        ("atlas_orion_28", 28, 2, 0.53), ("atlas_orion_32", 32, 2, 0.56), ("atlas_orion_40", 40, 2, 0.76),
        ("atlas_orion_50", 50, 2, 0.84), ("atlas_orion_65", 65, 2, 0.91), ("atlas_orion_80", 80, 2, 0.91),
        ("atlas_orion_100", 100, 2, 1.1), ("atlas_orion_135", 135, 2.2, 1.1), ("atlas_orion_200", 200, 3.2, 1.1)]),
    "cooke-anamorphic-i": (2, [
        ("cooke_anamorphic_i_s35_25", 25, 2.3, 1), ("cooke_anamorphic_i_s35_32", 32, 2.3, 0.85),
        ("cooke_anamorphic_i_s35_40", 40, 2.3, 0.85), ("cooke_anamorphic_i_s35_50", 50, 2.3, 0.85),
        ("cooke_anamorphic_i_s35_65", 65, 2.6, 0.44), ("cooke_anamorphic_i_s35_75", 75, 2.3, 1),
        ("cooke_anamorphic_i_s35_100", 100, 2.3, 1.2), ("cooke_anamorphic_i_s35_135", 135, 2.3, 1.4),
        ("cooke_anamorphic_i_s35_180", 180, 2.8, 2), ("cooke_anamorphic_i_s35_300", 300, 3.5, 3)]),
    "cooke-anamorphic-i-ff-plus": (1.8, [
        ("cooke_anamorphic_i_ff_32", 32, 2.3, 0.9), ("cooke_anamorphic_i_ff_40", 40, 2.3, 0.9),
        ("cooke_anamorphic_i_ff_50", 50, 2.3, 0.85), ("cooke_anamorphic_i_ff_75", 75, 2.3, 1),
        ("cooke_anamorphic_i_ff_85", 85, 2.8, 0.55), ("cooke_anamorphic_i_ff_100", 100, 2.3, 1.2),
        ("cooke_anamorphic_i_ff_135", 135, 2.3, 1.5), ("cooke_anamorphic_i_ff_180", 180, 2.9, 2.1)]),
}

# Sets and zooms a second, independent transcription of the maker's figures confirms in full: no longer approximate
# (each checked against that second source in tests/test_cine_confirmations.py).
CONFIRMED_SETS = {"cooke-panchro-i-classic-ff", "sigma-cine-ff-high-speed", "zeiss-cp3", "zeiss-supreme-prime",
                  "arri-fujinon-alura-15.5-45mm-t2.8", "arri-fujinon-alura-30-80mm-t2.8",
                  "angenieux-optimo-15-40mm-t2.6", "fujinon-mk-50-135mm-t2.9"}


# Canon's own close focus in feet and inches, as the table's notes on the Sumire rows quote it ('Canon table: ...
# CF 1'6"'): the metric figures above agree with them to within 2 cm (Canon rounds its metric figures).
SUMIRE_FEET = {24: (1, 0), 35: (1, 6), 50: (1, 6), 85: (3, 2), 135: (3, 3)}

# Each zoom's row: (short end, long end, 'tStop', 'minFocusMeters'), from the row's name and fields.
CITED_ZOOMS = {
    "fujinon-premista-19-45mm-t2.9": (19, 45, 2.9, 0.6),  # 'Fujinon Premista 19-45mm T2.9'
    # the 'DZOFILM Pictor' zooms' 0.6 and 1.1 m gave way to DZOFilm's 0.8 m as a second dataset quotes it
    # (tests/test_cine_confirmations.py)
    "canon-cn-e-14-35mm-t1.7-flex-zoom": (14, 35, 1.7, 0.6),  # 'Canon CN-E Flex Zoom 14-35mm T1.7'
    "canon-cn-e-31.5-95mm-t1.7-flex-zoom": (31.5, 95, 1.7, 1.0),  # 'Canon CN-E Flex Zoom 31.5-95mm T1.7'
    "arri-fujinon-alura-15.5-45mm-t2.8": (15.5, 45, 2.8, 0.6),  # 'ARRI/FUJINON Alura 15.5-45mm T2.8'
    "arri-fujinon-alura-30-80mm-t2.8": (30, 80, 2.8, 0.6),  # 'ARRI/FUJINON Alura 30-80mm T2.8'
    "angenieux-optimo-15-40mm-t2.6": (15, 40, 2.6, 0.61),  # 'Angénieux Optimo 15-40mm T2.6'
    "angenieux-optimo-45-120mm-t2.8": (45, 120, 2.8, 0.94),  # 'Angénieux Optimo 45-120mm T2.8'
    # the 'Fujinon MK18-55mm T2.9' row's 0.9 m gave way to Fujifilm's 0.85 m as a second dataset quotes it
    # (tests/test_cine_confirmations.py)
    "fujinon-mk-50-135mm-t2.9": (50, 135, 2.9, 1.2),  # 'Fujinon MK50-135mm T2.9'
}


@pytest.mark.parametrize("set_id", sorted(CITED_SETS))
def test_each_set_holds_the_table_s_rows(set_id):
    lens = load_db().lens(set_id)
    got = [(m.focal_min_mm, m.t_number_min, m.min_focus_mm) for m in lens.members]
    assert got == [(float(f), t, pytest.approx(1000.0 * metres, rel=1e-12)) for f, t, metres in CITED_SETS[set_id]]
    assert all(m.id == f"{set_id}@{m.focal_min_mm:g}" and not m.is_zoom and m.squeeze is None for m in lens.members)
    assert lens.category == "cine" and lens.approximate


@pytest.mark.parametrize("lens_id", sorted(CITED_ZOOMS))
def test_each_zoom_holds_the_table_s_row(lens_id):
    lens = load_db().lens(lens_id)
    short, long, stop, metres = CITED_ZOOMS[lens_id]
    assert lens.is_zoom and not lens.members and lens.category == "cine"
    assert lens.approximate == (lens_id not in CONFIRMED_SETS)
    assert (lens.focal_min_mm, lens.focal_max_mm, lens.t_number_min) == (short, long, stop)
    assert lens.min_focus_mm == pytest.approx(1000.0 * metres, rel=1e-12)


@pytest.mark.parametrize("lens_id", sorted(CITED_SETS) + sorted(CITED_ZOOMS))
def test_each_entry_cites_the_table_and_says_what_is_unconfirmed(lens_id):
    record = RECORDS[lens_id]
    source, notes = (" ".join(record[key].split()) for key in ("source", "notes"))
    assert TABLE in source and COMMIT in source and "gearList.js" in source
    if lens_id in CONFIRMED_SETS:
        assert "approximate" not in record and "Not confirmed" not in notes
    else:
        assert record["approximate"] is True and "Not confirmed" in notes
    assert "image (sensor) plane" in notes  # the plane the close focus is taken from, said
    assert "max_magnification" not in record and all("max_magnification" not in m for m in record.get("set", []))


def test_the_sumire_metres_agree_with_canon_s_feet_and_inches():
    members = {int(f): metres for f, _, metres in CITED_SETS["canon-sumire-prime"]}
    for focal, (feet, inches) in SUMIRE_FEET.items():
        assert abs((12 * feet + inches) * 0.0254 - members[focal]) <= 0.02, focal


def test_every_close_focus_leaves_room_for_a_real_image():
    """A thin lens brings an object to focus on the sensor only when object and image are at least 4f apart (the
    least of f(1+m)^2/m, at m = 1): each figure clears it at its focal length (a zoom at its long end), so one typed
    in the wrong unit would fail here."""
    for set_id, rows in CITED_SETS.items():
        for focal, _, metres in rows:
            assert 1000.0 * metres > 4 * focal, (set_id, focal)
    for lens_id, (_, long, _, metres) in CITED_ZOOMS.items():
        assert 1000.0 * metres > 4 * long, lens_id


EVERY_MEMBER = ([(s, f, t, m) for s, rows in sorted(CITED_SETS.items()) for f, t, m in rows]
                + [(s, f, t, m) for s, (_, rows) in sorted(DATASET_SETS.items()) for _, f, t, m in rows])


@pytest.mark.parametrize(("set_id", "focal", "stop", "metres"), EVERY_MEMBER)
def test_each_member_focuses_to_its_close_focus_at_its_stop_and_no_further(set_id, focal, stop, metres):
    closest = round(1000.0 * metres)
    args = ("dof", "--lens", f"{set_id}@{focal}", "--format", "json")
    assert run(*args, "-N", f"T{stop:g}", "-s", f"{closest}mm").exit_code == 0
    closer = run(*args, "-N", f"T{stop:g}", "-s", f"{closest - 10}mm")
    assert closer.exit_code == 2 and closer.stderr.count("\n") == 1 and "closest focus" in closer.stderr
    wider = run(*args, "-N", f"T{stop - 0.1:g}", "-s", "3m")  # a stop wider than the member's own
    assert wider.exit_code == 2 and f"T{stop:g}" in wider.stderr and wider.stderr.count("\n") == 1


@pytest.mark.parametrize("lens_id", sorted(CITED_ZOOMS))
def test_each_zoom_focuses_to_its_close_focus_at_both_ends_and_no_further(lens_id):
    short, long, stop, metres = CITED_ZOOMS[lens_id]
    closest = round(1000.0 * metres)
    for focal in (short, long):
        args = ("dof", "--lens", lens_id, "-f", f"{focal:g}", "-N", f"T{stop:g}", "--format", "json")
        assert run(*args, "-s", f"{closest}mm").exit_code == 0
        assert run(*args, "-s", f"{closest - 10}mm").exit_code == 2


def test_a_set_is_chosen_by_focal_length_and_shown_with_its_members():
    (row,) = run_json("presets", "show", "sumire")
    assert row["members"] == [f"canon-sumire-prime@{f}" for f, _, _ in CITED_SETS["canon-sumire-prime"]]
    by_option = run_json("dof", "--lens", "thalia", "-f", "55", "-N", "T2.8", "-s", "0.5m")
    by_name = run_json("dof", "--lens", "leitz-thalia@55", "-N", "T2.8", "-s", "0.5m")
    assert by_option == by_name and by_option[0]["t_stop"] == 2.8


@pytest.mark.parametrize("set_id", sorted(DATASET_SETS))
def test_each_dataset_set_holds_the_dataset_s_rows(set_id):
    squeeze, rows = DATASET_SETS[set_id]
    lens = load_db().lens(set_id)
    got = [(m.focal_min_mm, m.t_number_min, m.min_focus_mm, m.squeeze) for m in lens.members]
    assert got == [(float(f), t, pytest.approx(1000.0 * metres, rel=1e-12), squeeze) for _, f, t, metres in rows]
    assert all(m.id == f"{set_id}@{m.focal_min_mm:g}" and not m.is_zoom for m in lens.members)
    assert lens.category == "cine" and lens.approximate == (set_id not in CONFIRMED_SETS) and lens.squeeze == squeeze


@pytest.mark.parametrize("set_id", sorted(DATASET_SETS))
def test_each_dataset_entry_cites_its_rows_and_says_what_is_unconfirmed(set_id):
    _, rows = DATASET_SETS[set_id]
    record = RECORDS[set_id]
    source, notes = (" ".join(record[key].split()) for key in ("source", "notes"))
    assert DATASET in source and DATASET_PATH in source and DATASET_COMMIT in source and "http" in source
    prefix = rows[0][0].rsplit("_", 1)[0]  # the row ids named in the source: zeiss_cp3_<f>
    assert f"{prefix}_<f>" in source
    for _, focal, stop, metres in rows:  # every figure quoted in the source, as the dataset prints it
        assert f"{focal} mm T{stop:g} {metres:g} m" in source, (set_id, focal)
    if set_id in CONFIRMED_SETS:
        assert "approximate" not in record and "Not confirmed" not in notes
    else:
        assert record["approximate"] is True and "Not confirmed" in notes and "searched the pages corpus" in notes
    assert "image (sensor) plane" in notes
    assert "max_magnification" not in record and all("max_magnification" not in m for m in record["set"])


def test_every_dataset_close_focus_leaves_room_for_a_real_image():
    """As for the table's figures: object and image at least 4f apart for a thin lens, so a figure in the wrong unit
    (cm for m) would fail; the macros (the Panchro/i Classic 65 mm at 0.325 m, the Anamorphic/i FF 85 mm at 0.55 m)
    clear it too."""
    for set_id, (_, rows) in DATASET_SETS.items():
        for _, focal, _, metres in rows:
            assert 1000.0 * metres > 4 * focal, (set_id, focal)


@pytest.mark.parametrize(("set_id", "single"), [
    ("zeiss-supreme-prime", "zeiss-supreme-prime-50mm-t1.5"),  # lenses.yaml: T1.5, 0.45 m
    ("sigma-cine-ff-high-speed", "sigma-50mm-t1.5-ff-cine"),  # lenses.yaml: T1.5, 0.40 m
    ("arri-zeiss-master-prime", "zeiss-supreme-prime-50mm-t1.5"),  # a control: the sets differ (T1.3, 0.5 m)
])
def test_a_set_s_50mm_against_the_single_lens_entry(set_id, single):
    db = load_db()
    member, lens = db.lens(f"{set_id}@50"), db.lens(single)
    same = (member.t_number_min, member.min_focus_mm) == (lens.t_number_min, lens.min_focus_mm)
    assert same == (set_id != "arri-zeiss-master-prime")


@pytest.mark.parametrize("set_id", [s for s, (squeeze, _) in sorted(DATASET_SETS.items()) if squeeze])
def test_an_anamorphic_dataset_set_brings_its_squeeze_to_every_member(set_id):
    """With the set's member the horizontal focal length is f / squeeze (docs/cine.md §5a), as with --squeeze typed."""
    squeeze, rows = DATASET_SETS[set_id]
    for _, focal, stop, metres in (rows[0], rows[-1]):
        args = ("dof", "-N", f"T{stop:g}", "-s", f"{round(1000 * metres) + 500}mm")
        (row,) = run_json(*args, "--lens", f"{set_id}@{focal}")
        assert row["squeeze"] == squeeze and row["horizontal_focal_length_mm"] == pytest.approx(focal / squeeze)
        (typed,) = run_json(*args, "-f", str(focal), "--squeeze", f"{squeeze:g}", "--coc", str(row["coc_mm"]))
        assert typed["near_horizontal_mm"] == pytest.approx(row["near_horizontal_mm"], rel=1e-12)
