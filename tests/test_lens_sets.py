"""Lens sets: one preset holding every focal length of a cine prime set, a member chosen by -f or SET@FOCAL."""

from __future__ import annotations

import pytest
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


# lens_db/lenses.yaml, arri-signature-prime (its source: the Signature Prime rows of
# Hugo9809/cine-power-planner's gear table): T1.8; 0.35 m from 12 to 40 mm, 0.45 m at 47 mm
SIGNATURE = [(12, 350), (15, 350), (18, 350), (21, 350), (25, 350), (29, 350), (35, 350), (40, 350), (47, 450)]


def test_every_member_carries_its_own_stop_and_close_focus():
    lens = load_db().lens("signature-prime")
    assert [(m.focal_min_mm, m.min_focus_mm) for m in lens.members] == SIGNATURE
    assert all(m.t_number_min == 1.8 and not m.is_zoom for m in lens.members)
    assert not lens.is_zoom and (lens.focal_min_mm, lens.focal_max_mm) == (12.0, 47.0)
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
    assert row["members"][0] == "arri-signature-prime@12" and len(row["members"]) == 9
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


def test_the_cine_lens_file_s_sets_load_member_by_member():
    """lens_db/cine-lenses.yaml (read with yaml): each set's members carry their own stop and close focus, and an
    anamorphic set's squeeze reaches every member."""
    from pathlib import Path

    import yaml

    path = Path(__file__).resolve().parents[1] / "lens_db" / "cine-lenses.yaml"
    db = load_db()
    for record in yaml.safe_load(path.read_text(encoding="utf-8"))["lenses"]:
        lens = db.lens(record["id"])
        rows = [(float(r["focal_length_mm"]), r.get("t_number_min"), r.get("min_focus_mm")) for r in record["set"]]
        assert [(m.focal_min_mm, m.t_number_min, m.min_focus_mm) for m in lens.members] == rows
        assert {m.squeeze for m in lens.members} == {record.get("squeeze")} and lens.squeeze == record.get("squeeze")
        assert lens.approximate and lens.notes


def test_a_set_member_s_own_close_focus_is_refused_closer():
    # lens_db/cine-lenses.yaml, cooke-s7i: 0.36 m at 25 mm (its cited table)
    result = run("dof", "--lens", "cooke-s7i", "-f", "25", "-N", "T2", "-s", "0.35m")
    assert result.exit_code == 2 and "0.36 m" in result.stderr and result.stderr.count("\n") == 1
    assert run("dof", "--lens", "cooke-s7i", "-f", "25", "-N", "T2", "-s", "0.36m").exit_code == 0
