"""lens_db/maker-lenses.yaml: each entry's figures against the page its `source` quotes, and the figures the
model derives from them against what the pages say of the lens in use."""

from __future__ import annotations

import math

import pytest
from cli_helpers import run, run_json
from lens_checks import (  # noqa: F401 - isolated: an autouse fixture
    DB,
    check_cited_row,
    check_never_magnifies_more,
    isolated,
    lens_records,
    name_key,
    record_of,
    taken_elsewhere,
)

from camtool.presets import load_db
from camtool.presets.focusing import row_magnification

FILE = DB / "maker-lenses.yaml"
RECORDS = lens_records(FILE)


# (lens, focal length mm, closest focus mm, magnification or None, f-number range) as the page each entry's
# source names gives them; ranges are (widest, smallest) at the short end and, for a zoom whose apertures
# change, at the long end (None: the page gives none). The last item is the largest magnification the page
# gives for the lens as a whole, which every row of a zoom must stay within.
CITED = [
    # Ticker News: 6.56 feet (two meters), 0.16x; Photography Life: 2 m
    ("sony-fe-300mm-f2.8-gm-oss", 300, 2000, 0.16, (2.8, None), 0.16),
    # Digimanie.cz: 30 cm at the widest angle, 45 cm at the longest, 0.16x; F4.0 to F5.6, F22 to F32
    ("sony-fe-28-60mm-f4-5.6", 28, 300, None, (4, 22), 0.16),
    ("sony-fe-28-60mm-f4-5.6", 60, 450, None, (5.6, 32), 0.16),
    # Photography Life: 0.2 m at 28mm, 1.2 m at 400mm, 0.35x at 28mm (1:2.9); f/4-8; f/22 at 28mm, f/45 at 400mm
    ("nikon-z-28-400mm-f4-8-vr", 28, 200, 0.35, (4, 22), 0.35),
    ("nikon-z-28-400mm-f4-8-vr", 400, 1200, None, (8, 45), 0.35),
    # Photography Life: 0.19 meters and 0.21x (1:4.8), no focal length given (the distance entered at both ends);
    # f/3.5 and f/16 at 12mm, f/5.6 and f/25 at 28mm
    ("nikon-z-dx-12-28mm-f3.5-5.6-pz-vr", 12, 190, None, (3.5, 16), 0.21),
    ("nikon-z-dx-12-28mm-f3.5-5.6-pz-vr", 28, 190, None, (5.6, 25), 0.21),
    # review copy: 0.7m, or 28 inches, 0.08x; f/1
    ("fujifilm-xf50mm-f1-r-wr", 50, 700, 0.08, (1, None), 0.08),
    # Head Topics: 0.8 meters at 200mm and 3.3m at 800mm, 0.25x at 200mm and 0.2x at 800mm; f/6.3-9
    ("canon-rf-200-800mm-f6.3-9-is-usm", 200, 800, 0.25, (6.3, None), 0.25),
    ("canon-rf-200-800mm-f6.3-9-is-usm", 800, 3300, 0.2, (9, None), 0.25),
    # Ken Rockwell: 5.9'/1.8m close focus, 0.16x macro ratio; The Digital Picture: 0.16x; f/2.8
    ("canon-rf-100-300mm-f2.8l-is-usm", 100, 1800, None, (2.8, None), 0.16),
    ("canon-rf-100-300mm-f2.8l-is-usm", 300, 1800, None, (2.8, None), 0.16),
    # Wikipedia: aperture 4.5 (32.0) - 5.6 (40.0); close-dist 0.98 m; max-mag (0.35x)
    ("sony-fe-100-400mm-f4.5-5.6-gm-oss", 100, 980, None, (4.5, 32), 0.35),
    ("sony-fe-100-400mm-f4.5-5.6-gm-oss", 400, 980, None, (5.6, 40), 0.35),
    # Wikipedia: aperture 4.5 - 22.0; close-dist 0.9 m; max-mag 1:3 (0.31x); f/5.6 at 300 mm from the name
    ("sony-fe-70-300mm-f4.5-5.6-g-oss", 70, 900, None, (4.5, 22), 0.31),
    ("sony-fe-70-300mm-f4.5-5.6-g-oss", 300, 900, None, (5.6, 22), 0.31),
]


def test_every_entry_is_checked_against_its_page():
    assert {lens_id for lens_id, *_ in CITED} == {r["id"] for r in RECORDS}


@pytest.mark.parametrize(("lens_id", "focal", "distance", "magnification", "apertures", "largest"), CITED,
                         ids=[f"{c[0]}@{c[1]}" for c in CITED])
def test_figures_against_the_cited_pages(lens_id, focal, distance, magnification, apertures, largest):
    record = record_of(RECORDS, lens_id)
    check_cited_row(record, focal, distance, magnification, apertures)
    assert record["max_magnification"] == pytest.approx(largest, abs=0.0006)


def test_every_entry_names_its_mount_and_is_new():
    # lens_db/README.md: within one tier an id or alias names one preset; the makers' lenses already in
    # lenses.yaml (the RF 24-105 F4-7.1, the Z 24-120, the FE 24-70 GM II ...) are not entered again
    taken, names = taken_elsewhere(FILE)
    for record in RECORDS:
        assert not ({record["id"], *record.get("aliases", [])} & taken), record["id"]
        assert name_key(record["name"]) not in names, record["name"]
        assert record["mount"] and record["mount"] != "various", record["id"]
        assert record.get("max_magnification"), record["id"]  # an entry needs its published maximum
        assert load_db().lens(record["id"]).tier == "shipped"


@pytest.mark.parametrize("lens_id", [r["id"] for r in RECORDS])
def test_the_model_never_magnifies_more_than_the_page_says(lens_id):
    # every row of a zoom (and every focal length between two rows) reaches at its closest focus no more
    # than the page's maximum; a prime reaches exactly its published figure there
    check_never_magnifies_more(load_db().lens(lens_id))


def test_unpublished_rows_follow_unit_focusing_where_it_stays_below_the_maximum():
    # Sony FE 28-60 at 28 mm: Digimanie gives 0.30 m and no magnification there; unit focusing of a 28 mm
    # lens at 300 mm gives m = ((D/f - 2) - sqrt((D/f - 2)^2 - 4)) / 2 = 0.116x, below Sony's 0.16x
    lens = load_db().lens("sony-fe-28-60mm-f4-5.6")
    x = 300 / 28 - 2
    unit = (x - math.sqrt(x * x - 4)) / 2
    assert unit == pytest.approx(0.1163, abs=5e-4)
    assert row_magnification(lens, 28.0, 300.0, None) == pytest.approx(unit, rel=1e-9)
    # at 60 mm and 0.45 m unit focusing would give 0.188x, more than the page's maximum: the cap holds it
    x = 450 / 60 - 2
    assert (x - math.sqrt(x * x - 4)) / 2 > 0.16
    assert row_magnification(lens, 60.0, 450.0, None) == pytest.approx(0.16)


def test_dof_refuses_closer_than_the_published_closest_focus():
    # Photography Life: the Z 28-400 focuses to 1.2 m at 400 mm
    (row,) = run_json("dof", "--lens", "nikon-z-28-400mm-f4-8-vr", "-f", "400", "-N", "8", "-s", "1.5m")
    assert row["near_mm"] < 1500.0 < row["far_mm"]
    result = run("dof", "--lens", "nikon-z-28-400mm-f4-8-vr", "-f", "400", "-N", "8", "-s", "1m")
    assert result.exit_code == 2
    assert "1.2 m" in result.output


def test_apertures_outside_the_published_range_are_refused():
    # Photography Life: f/8 is the widest aperture at 400 mm, f/45 the smallest
    assert run("dof", "--lens", "z-28-400", "-f", "400", "-N", "5.6", "-s", "5m").exit_code == 2
    assert run("dof", "--lens", "z-28-400", "-f", "400", "-N", "64", "-s", "5m").exit_code == 2
    (row,) = run_json("dof", "--lens", "z-28-400", "-f", "400", "-N", "45", "-s", "5m")
    assert row["near_mm"] < 5000.0 < row["far_mm"]

