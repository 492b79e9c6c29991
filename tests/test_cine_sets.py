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
}

# Canon's own close focus in feet and inches, as the table's notes on the Sumire rows quote it ('Canon table: ...
# CF 1'6"'): the metric figures above agree with them to within 2 cm (Canon rounds its metric figures).
SUMIRE_FEET = {24: (1, 0), 35: (1, 6), 50: (1, 6), 85: (3, 2), 135: (3, 3)}

# Each zoom's row: (short end, long end, 'tStop', 'minFocusMeters'), from the row's name and fields.
CITED_ZOOMS = {
    "fujinon-premista-19-45mm-t2.9": (19, 45, 2.9, 0.6),  # 'Fujinon Premista 19-45mm T2.9'
    "dzofilm-pictor-20-55mm-t2.8": (20, 55, 2.8, 0.6),  # 'DZOFILM Pictor 20-55mm T2.8'
    "dzofilm-pictor-50-125mm-t2.8": (50, 125, 2.8, 1.1),  # 'DZOFILM Pictor 50-125mm T2.8'
    "canon-cn-e-14-35mm-t1.7-flex-zoom": (14, 35, 1.7, 0.6),  # 'Canon CN-E Flex Zoom 14-35mm T1.7'
    "canon-cn-e-31.5-95mm-t1.7-flex-zoom": (31.5, 95, 1.7, 1.0),  # 'Canon CN-E Flex Zoom 31.5-95mm T1.7'
    "arri-fujinon-alura-15.5-45mm-t2.8": (15.5, 45, 2.8, 0.6),  # 'ARRI/FUJINON Alura 15.5-45mm T2.8'
    "arri-fujinon-alura-30-80mm-t2.8": (30, 80, 2.8, 0.6),  # 'ARRI/FUJINON Alura 30-80mm T2.8'
    "angenieux-optimo-15-40mm-t2.6": (15, 40, 2.6, 0.61),  # 'Angénieux Optimo 15-40mm T2.6'
    "angenieux-optimo-45-120mm-t2.8": (45, 120, 2.8, 0.94),  # 'Angénieux Optimo 45-120mm T2.8'
    "fujinon-mk-18-55mm-t2.9": (18, 55, 2.9, 0.9),  # 'Fujinon MK18-55mm T2.9'
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
    assert lens.is_zoom and not lens.members and lens.category == "cine" and lens.approximate
    assert (lens.focal_min_mm, lens.focal_max_mm, lens.t_number_min) == (short, long, stop)
    assert lens.min_focus_mm == pytest.approx(1000.0 * metres, rel=1e-12)


@pytest.mark.parametrize("lens_id", sorted(CITED_SETS) + sorted(CITED_ZOOMS))
def test_each_entry_cites_the_table_and_says_what_is_unconfirmed(lens_id):
    record = RECORDS[lens_id]
    source, notes = (" ".join(record[key].split()) for key in ("source", "notes"))
    assert TABLE in source and COMMIT in source and "gearList.js" in source
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


@pytest.mark.parametrize(("set_id", "focal", "stop", "metres"),
                         [(s, f, t, m) for s, rows in sorted(CITED_SETS.items()) for f, t, m in rows])
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
