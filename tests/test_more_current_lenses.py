"""lens_db/more-current-lenses.yaml: each entry's figures against the dataset records and pages its `source` quotes,
and the magnification the focusing model derives at the closest focus against the published maximum."""

from __future__ import annotations

import math

import pytest
from cli_helpers import run, run_json
from lens_checks import (  # noqa: F401 - isolated: an autouse fixture
    DB,
    check_cited_row,
    check_entries_are_new,
    check_every_entry_cited,
    check_never_magnifies_more,
    isolated,
    lens_records,
    record_of,
)

from camtool.geometry.closeup import internal_focus_at_distance
from camtool.presets import load_db
from camtool.presets.focusing import focus_model

FILE = DB / "more-current-lenses.yaml"
RECORDS = lens_records(FILE)

# (lens, focal length mm, closest focus mm, magnification at that row or None, (widest, smallest f-number or None),
# largest magnification the source gives for the lens) as the sources each entry names print them:
# isamu/lens-database's records of jp.omsystem.com and nij.nikon.com (minFocusDistance in m, maxMagnification, the
# other end of a zoom from the record's note; Micro Four Thirds magnifications are the actual ratio, not the 35 mm
# equivalent one), and the pages cited beside them
CITED = [
    # minFocusDistance 0.2, maxMagnification 0.12
    ("om-m-zuiko-7-14mm-f2.8-pro", 7, 200, None, (2.8, None), 0.12),
    ("om-m-zuiko-7-14mm-f2.8-pro", 14, 200, None, (2.8, None), 0.12),
    # minFocusDistance 0.23, maxMagnification 0.21; Camera Man: 最短23cm
    ("om-m-zuiko-8-25mm-f4-pro", 8, 230, None, (4, None), 0.21),
    ("om-m-zuiko-8-25mm-f4-pro", 25, 230, None, (4, None), 0.21),
    # minFocusDistance 0.25, maxMagnification 0.1 at the long end, 0.05 at the wide end (Wide端0.05倍)
    ("om-m-zuiko-9-18mm-f4-5.6-ii", 9, 250, 0.05, (4, None), 0.1),
    ("om-m-zuiko-9-18mm-f4-5.6-ii", 18, 250, 0.1, (5.6, None), 0.1),
    # minFocusDistance 0.5, maxMagnification 0.22
    ("om-m-zuiko-14-150mm-f4-5.6-ii", 14, 500, None, (4, None), 0.22),
    ("om-m-zuiko-14-150mm-f4-5.6-ii", 150, 500, None, (5.6, None), 0.22),
    # minFocusDistance 0.7, maxMagnification 0.21
    ("om-m-zuiko-40-150mm-f2.8-pro", 40, 700, None, (2.8, None), 0.21),
    ("om-m-zuiko-40-150mm-f2.8-pro", 150, 700, None, (2.8, None), 0.21),
    # minFocusDistance 0.7, maxMagnification 0.21
    ("om-m-zuiko-40-150mm-f4-pro", 40, 700, None, (4, None), 0.21),
    ("om-m-zuiko-40-150mm-f4-pro", 150, 700, None, (4, None), 0.21),
    # minFocusDistance 0.9, maxMagnification 0.16
    ("om-m-zuiko-40-150mm-f4-5.6-r", 40, 900, None, (4, None), 0.16),
    ("om-m-zuiko-40-150mm-f4-5.6-r", 150, 900, None, (5.6, None), 0.16),
    # minFocusDistance 0.78, maxMagnification 0.25
    ("om-m-zuiko-50-200mm-f2.8-is-pro", 50, 780, None, (2.8, None), 0.25),
    ("om-m-zuiko-50-200mm-f2.8-is-pro", 200, 780, None, (2.8, None), 0.25),
    # 0.9 m at 75 mm, 1.5 m at every other focal length (75mm時0.9m、それ以外の焦点距離では1.5m), maxMagnification 0.18
    ("om-m-zuiko-75-300mm-f4.8-6.7-ii", 75, 900, None, (4.8, None), 0.18),
    ("om-m-zuiko-75-300mm-f4.8-6.7-ii", 300, 1500, None, (6.7, None), 0.18),
    # minFocusDistance 0.37; Camera Man: 最短撮影距離:0.37m, 最大撮影倍率:0.17, 最小絞り:F16
    ("nikon-z-50mm-f1.4", 50, 370, 0.17, (1.4, 16), 0.17),
    # minFocusDistance 0.18; hoozuki.net, from Nikon's site: 0.18m, 0.19倍, f/1.7, f/11
    ("nikon-z-dx-24mm-f1.7", 24, 180, 0.19, (1.7, 11), 0.19),
]

# the entries whose every figure a page printing the maker's specifications gives, and the page
CONFIRMED = {
    "nikon-z-50mm-f1.4": "cameraman.motormagazine.co.jp/_amp/_ct/17721947",
    "nikon-z-dx-24mm-f1.7": "hoozuki.net/3679.html",
}

# approximate entries of which a page confirms a figure: the page named in `source`, the closest focus it prints (mm)
# and the figure the entry's notes must still name as unconfirmed
PARTLY_CONFIRMED = {
    "om-m-zuiko-8-25mm-f4-pro": ("cameraman.motormagazine.co.jp/_ct/17458530", 230, "maximum magnification 0.21x"),
    # ronbuening/LensVisualizer's analysis: "the production lens specifies an MFD of 0.7 m"
    "om-m-zuiko-40-150mm-f2.8-pro": ("ronbuening/LensVisualizer src/lens-data/olympus/"
                                     "OlympusMZuiko40150mmf28PRO.analysis.md at 0e0fdb75faa403fcb6ff93c07581459fc687b059",
                                     700, "maximum magnification 0.21x"),
}


def test_every_entry_is_checked_against_its_sources():
    check_every_entry_cited(RECORDS, CITED)
    assert len(RECORDS) == len({lens_id for lens_id, *_ in CITED})


@pytest.mark.parametrize(("lens_id", "focal", "distance", "magnification", "apertures", "largest"), CITED,
                         ids=[f"{c[0]}@{c[1]}" for c in CITED])
def test_figures_against_the_cited_sources(lens_id, focal, distance, magnification, apertures, largest):
    check_cited_row(record_of(RECORDS, lens_id), focal, distance, magnification, apertures, largest)


def test_every_entry_is_new_and_names_its_mount_and_format():
    check_entries_are_new(FILE, RECORDS)
    for record in RECORDS:
        assert record["mount"] in {"Micro Four Thirds", "Nikon Z"}, record["id"]
        assert record["max_magnification"] and record["min_focus_mm"], record["id"]
        if record["mount"] == "Micro Four Thirds":
            assert record["sensor"] == "four-thirds", record["id"]
    assert record_of(RECORDS, "nikon-z-dx-24mm-f1.7")["sensor"] == "aps-c"
    assert "sensor" not in record_of(RECORDS, "nikon-z-50mm-f1.4")


def test_ids_and_aliases_are_unique_within_the_file():
    names = [n for r in RECORDS for n in (r["id"], *r.get("aliases", []))]
    assert len(names) == len(set(names))


def test_a_figure_from_the_dataset_alone_is_approximate_and_a_confirmed_one_is_not():
    for record in RECORDS:
        assert "isamu/lens-database" in record["source"], record["id"]
        assert bool(record.get("approximate")) == (record["id"] not in CONFIRMED), record["id"]
        if record.get("approximate"):
            assert record["notes"].startswith("Approximate:"), record["id"]
            assert "one dataset only" in " ".join(record["notes"].split()), record["id"]
    for lens_id, page in CONFIRMED.items():
        assert page in record_of(RECORDS, lens_id)["source"], lens_id


@pytest.mark.parametrize(("lens_id", "page", "distance", "open_figure"),
                         [(k, *v) for k, v in sorted(PARTLY_CONFIRMED.items())])
def test_a_partly_confirmed_entry_names_its_page_and_what_is_still_open(lens_id, page, distance, open_figure):
    record = record_of(RECORDS, lens_id)
    assert page in " ".join(record["source"].split())
    assert all(row["min_focus_mm"] == distance for row in record["close_focus"])
    assert record["approximate"] is True
    assert open_figure in " ".join(record["notes"].split())


def test_micro_four_thirds_magnifications_are_the_actual_ratio():
    # OM System prints both; the entry holds the ratio on the sensor and its notes say the 35 mm equivalent one
    # (twice it) is not used: no zoom here reaches half life size on the sensor
    for record in RECORDS:
        if record["mount"] == "Micro Four Thirds":
            notes = " ".join(record["notes"].split())
            assert "actual reproduction ratio" in notes and "35 mm equivalent" in notes, record["id"]
            assert record["max_magnification"] < 0.5, record["id"]


@pytest.mark.parametrize("lens_id", [r["id"] for r in RECORDS])
def test_the_model_never_magnifies_more_than_the_source_says(lens_id):
    # at every published row, at both ends, and halfway between neighbouring rows
    check_never_magnifies_more(load_db().lens(lens_id))


def test_the_9_18mm_meets_both_published_magnifications():
    # 0.05x at 9 mm and 0.1x at 18 mm, both at 0.25 m; a unit-focusing 9 mm lens would reach less at 0.25 m
    # (D = f (2 + m + 1/m), the root below 1), so the row's published figure is what the model gives
    lens = load_db().lens("om-m-zuiko-9-18mm-f4-5.6-ii")
    k = 250.0 / 9.0 - 2.0
    assert (k - math.sqrt(k * k - 4.0)) / 2.0 < 0.05
    for focal, published in ((9.0, 0.05), (18.0, 0.1)):
        m, _ = internal_focus_at_distance(focus_model(lens, focal), 250.0)
        assert m == pytest.approx(published, rel=1e-6)


def test_a_long_end_row_without_a_magnification_is_capped_at_the_published_maximum():
    # the 40-150mm F2.8 PRO at 150 mm and 0.7 m: a unit-focusing 150 mm lens would reach about 0.451x, more than the
    # published 0.21x, so the model is capped there; at 40 mm it is the unit-focusing figure, below the maximum
    k = 700.0 / 150.0 - 2.0
    assert (k - math.sqrt(k * k - 4.0)) / 2.0 == pytest.approx(0.4514, abs=5e-4)
    lens = load_db().lens("om-m-zuiko-40-150mm-f2.8-pro")
    assert internal_focus_at_distance(focus_model(lens, 150.0), 700.0)[0] == pytest.approx(0.21, rel=1e-6)
    k = 700.0 / 40.0 - 2.0
    unit = (k - math.sqrt(k * k - 4.0)) / 2.0
    assert unit < 0.21
    assert internal_focus_at_distance(focus_model(lens, 40.0), 700.0)[0] == pytest.approx(unit, rel=1e-6)


def test_the_z_50mm_f1_4_focuses_internally():
    # 0.37 m with 0.17x: a unit-focusing 50 mm lens would reach about 0.192x there, more than Nikon's figure; the pair
    # implies about 46 mm at the closest focus (D = f (2 + m + 1/m)), the figure its notes and the consistency
    # exception name, and the model meets the published 0.17x there
    record = record_of(RECORDS, "nikon-z-50mm-f1.4")
    distance, m = record["min_focus_mm"], record["max_magnification"]
    k = distance / record["focal_length_mm"] - 2.0
    assert (k - math.sqrt(k * k - 4.0)) / 2.0 == pytest.approx(0.1919, abs=5e-4)
    implied = distance / (2 + m + 1 / m)
    assert implied == pytest.approx(45.95, abs=0.01)
    assert "about 46 mm" in record["notes"]
    lens = load_db().lens("nikon-z-50mm-f1.4")
    assert internal_focus_at_distance(focus_model(lens, 50.0), 370.0)[0] == pytest.approx(0.17, rel=1e-6)


def test_dof_refuses_closer_than_the_published_closest_focus():
    (row,) = run_json("dof", "--lens", "nikon-z-dx-24mm-f1.7", "-N", "1.7", "-s", "0.5m")
    assert row["near_mm"] < 500.0 < row["far_mm"]
    result = run("dof", "--lens", "nikon-z-dx-24mm-f1.7", "-N", "1.7", "-s", "0.15m")
    assert result.exit_code == 2
    assert "0.18 m" in result.output
