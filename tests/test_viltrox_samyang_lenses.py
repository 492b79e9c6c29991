"""lens_db/viltrox-samyang-lenses.yaml: each entry's figures against the dataset its `source` quotes
(isamu/lens-database's Viltrox and Samyang records), the pages that confirm another figure (the Viltrox 28mm's fixed
aperture, a mount, the format), its mounts and sensor, and the magnification the focusing model derives at the
closest focus against the published maximum (or, where none is published, against unit focusing)."""

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

FILE = DB / "viltrox-samyang-lenses.yaml"
RECORDS = lens_records(FILE)

VILTROX = "isamu/lens-database build/data/viltrox/"
VILTROX_COMMIT = "026e8e7191685e660b235de3e5d25b0dc4f6eb7d"
SAMYANG = "isamu/lens-database build/data/samyang/index.js"
SAMYANG_COMMIT = "67690d148d423e7b6e292528854fbaa3f226903a"

# (lens, focal length mm, closest focus mm, magnification or None, (widest, smallest f-number or None), largest
# magnification the source gives or None), as isamu/lens-database prints them: focalLength, fStop,
# minFocusDistance (m), maxMagnification where the record has one.
CITED = [
    # build/data/viltrox/{e,z,rf,l,x}/index.js: full-frame primes, the same figures for every mount named
    ("viltrox-af-16mm-f1.8-fe", 16, 270, 0.13, (1.8, None), 0.13),  # 0.27, 0.13
    ("viltrox-af-20mm-f2.8-fe", 20, 190, None, (2.8, None), None),  # 0.19
    ("viltrox-af-24mm-f1.8-fe", 24, 280, None, (1.8, None), None),  # 0.28
    ("viltrox-af-28mm-f4.5-fe", 28, 350, None, (4.5, 4.5), None),  # 0.35; fixed aperture (Rusty Ruin)
    ("viltrox-af-40mm-f2.5-fe", 40, 350, None, (2.5, None), None),  # 0.35
    ("viltrox-af-50mm-f1.8-fe", 50, 500, None, (1.8, None), None),  # 0.5
    ("viltrox-af-85mm-f1.4-fe", 85, 800, None, (1.4, None), None),  # 0.8
    ("viltrox-af-85mm-f1.8-ii", 85, 800, None, (1.8, None), None),  # 0.8
    ("viltrox-af-135mm-f1.8-lab", 135, 720, None, (1.8, None), None),  # 0.72
    # APS-C primes
    ("viltrox-af-13mm-f1.4", 13, 200, None, (1.4, None), None),  # 0.2
    ("viltrox-af-23mm-f1.4", 23, 300, None, (1.4, None), None),  # 0.3
    ("viltrox-af-25mm-f1.7-air", 25, 290, None, (1.7, None), None),  # 0.29
    ("viltrox-af-27mm-f1.2-pro", 27, 280, None, (1.2, None), None),  # 0.28
    ("viltrox-af-33mm-f1.4", 33, 400, None, (1.4, None), None),  # 0.4
    ("viltrox-af-35mm-f1.7-air", 35, 400, None, (1.7, None), None),  # 0.4
    ("viltrox-af-56mm-f1.4", 56, 550, None, (1.4, None), None),  # 0.55
    ("viltrox-af-56mm-f1.7-air", 56, 550, None, (1.7, None), None),  # 0.55
    ("viltrox-af-75mm-f1.2-pro", 75, 700, None, (1.2, None), None),  # 0.7
    # build/data/samyang/index.js: AF primes
    ("samyang-af-14mm-f2.8-fe", 14, 200, None, (2.8, None), None),  # 0.2
    ("samyang-af-18mm-f2.8-fe", 18, 250, None, (2.8, None), None),  # 0.25
    ("samyang-af-24mm-f1.8-fe", 24, 190, 0.15, (1.8, None), 0.15),  # 0.19, 0.15
    ("samyang-af-24mm-f2.8-fe", 24, 240, None, (2.8, None), None),  # 0.24
    ("samyang-af-35mm-f1.4-fe-ii", 35, 280, None, (1.4, None), None),  # 0.28
    ("samyang-af-35mm-f1.8-fe", 35, 290, None, (1.8, None), None),  # 0.29
    ("samyang-af-45mm-f1.8-fe", 45, 450, None, (1.8, None), None),  # 0.45
    ("samyang-af-50mm-f1.4-fe-ii", 50, 400, None, (1.4, None), None),  # 0.4
    ("samyang-af-75mm-f1.8-fe", 75, 690, None, (1.8, None), None),  # 0.69
    ("samyang-af-85mm-f1.4-fe-ii", 85, 850, None, (1.4, None), None),  # 0.85
    ("samyang-af-135mm-f1.8-fe", 135, 690, None, (1.8, None), None),  # 0.69
    ("samyang-af-12mm-f2-e", 12, 200, None, (2, None), None),  # 0.2
]

# The maker's page each Viltrox record names (its `official` URL), as the source quotes it
VILTROX_PAGE = "https://viltroxstore.com/products/"

# Figures a page confirms, as it prints them: (lens, what, value, page quoted in `source`)
CONFIRMED = [
    ("viltrox-af-28mm-f4.5-fe", "f_number_max", 4.5, "rustyruin.blog/tag/viltrox"),  # always operating at f4.5
    ("viltrox-af-28mm-f4.5-fe", "mount", "Fujifilm X", "fstoppers.com/reviews/review-slimmest-fujifilm"),
    ("viltrox-af-85mm-f1.8-ii", "sensor", None, "danadams.photography"),  # the X version is a full frame lens
    ("viltrox-af-27mm-f1.2-pro", "sensor", "aps-c", "optyczne.pl/613.6"),  # a 27 mm lens for APS-C/DX
]

# (mounts, sensor) as the dataset's records list them (one record per mount with the same figures; a record
# asking for its figures to be verified is not counted), and the pages quoted
MOUNTS = {
    "viltrox-af-16mm-f1.8-fe": ({"Sony E", "Nikon Z"}, None),
    "viltrox-af-20mm-f2.8-fe": ({"Sony E", "Nikon Z"}, None),
    "viltrox-af-24mm-f1.8-fe": ({"Sony E", "Nikon Z"}, None),
    "viltrox-af-28mm-f4.5-fe": ({"Sony E", "Nikon Z", "Fujifilm X"}, None),
    "viltrox-af-40mm-f2.5-fe": ({"Sony E", "Nikon Z", "Canon RF"}, None),
    "viltrox-af-50mm-f1.8-fe": ({"Sony E", "Nikon Z", "Canon RF"}, None),
    "viltrox-af-85mm-f1.4-fe": ({"Sony E"}, None),
    "viltrox-af-85mm-f1.8-ii": ({"Sony E", "Fujifilm X", "Nikon Z", "Canon RF"}, None),
    "viltrox-af-135mm-f1.8-lab": ({"Sony E", "Nikon Z", "L-Mount"}, None),
    "viltrox-af-13mm-f1.4": ({"Sony E", "Fujifilm X", "Nikon Z"}, "aps-c"),
    "viltrox-af-23mm-f1.4": ({"Sony E", "Fujifilm X", "Nikon Z"}, "aps-c"),
    "viltrox-af-25mm-f1.7-air": ({"Sony E"}, "aps-c"),
    "viltrox-af-27mm-f1.2-pro": ({"Sony E", "Fujifilm X", "Nikon Z"}, "aps-c"),
    "viltrox-af-33mm-f1.4": ({"Sony E", "Fujifilm X", "Nikon Z"}, "aps-c"),
    "viltrox-af-35mm-f1.7-air": ({"Sony E"}, "aps-c"),
    "viltrox-af-56mm-f1.4": ({"Sony E", "Fujifilm X", "Nikon Z"}, "aps-c"),
    "viltrox-af-56mm-f1.7-air": ({"Sony E"}, "aps-c"),
    "viltrox-af-75mm-f1.2-pro": ({"Sony E", "Fujifilm X", "Nikon Z"}, "aps-c"),
    "samyang-af-14mm-f2.8-fe": ({"Sony E"}, None),
    "samyang-af-18mm-f2.8-fe": ({"Sony E"}, None),
    "samyang-af-24mm-f1.8-fe": ({"Sony E", "Nikon Z"}, None),
    "samyang-af-24mm-f2.8-fe": ({"Sony E"}, None),
    "samyang-af-35mm-f1.4-fe-ii": ({"Sony E"}, None),
    "samyang-af-35mm-f1.8-fe": ({"Sony E"}, None),
    "samyang-af-45mm-f1.8-fe": ({"Sony E"}, None),
    "samyang-af-50mm-f1.4-fe-ii": ({"Sony E"}, None),
    "samyang-af-75mm-f1.8-fe": ({"Sony E"}, None),
    "samyang-af-85mm-f1.4-fe-ii": ({"Sony E"}, None),
    "samyang-af-135mm-f1.8-fe": ({"Sony E"}, None),
    "samyang-af-12mm-f2-e": ({"Sony E", "Fujifilm X"}, "aps-c"),
}


def test_every_entry_is_checked_against_its_source():
    check_every_entry_cited(RECORDS, CITED)
    assert set(MOUNTS) == {r["id"] for r in RECORDS}
    assert len(RECORDS) >= 30


@pytest.mark.parametrize(("lens_id", "focal", "distance", "magnification", "apertures", "largest"), CITED,
                         ids=[f"{c[0]}@{c[1]}" for c in CITED])
def test_figures_against_the_cited_source(lens_id, focal, distance, magnification, apertures, largest):
    record = record_of(RECORDS, lens_id)
    check_cited_row(record, focal, distance, magnification, apertures, largest)
    if largest is None:
        assert "max_magnification" not in record
    source = " ".join(record["source"].split())
    # the dataset is named with its path and commit, and the figures as its record prints them (m, not mm)
    if lens_id.startswith("viltrox-"):
        assert VILTROX in source and VILTROX_COMMIT in source
        assert "transcribing the maker's specification page " + VILTROX_PAGE in source
    else:
        assert SAMYANG in source and SAMYANG_COMMIT in source
        assert "https://www.samyanglensglobal.com/" in source  # the only page the records name
    assert f"minFocusDistance {distance / 1000:g} m" in source
    assert f"focal length {focal} mm, f/{apertures[0]:g}" in source
    if magnification is None:
        assert "maxMagnification" not in source
    else:
        assert f"maxMagnification {magnification:g}" in source


@pytest.mark.parametrize(("lens_id", "what", "value", "page"), CONFIRMED, ids=[f"{c[0]}:{c[1]}" for c in CONFIRMED])
def test_figures_a_page_confirms(lens_id, what, value, page):
    record = record_of(RECORDS, lens_id)
    if what == "mount":
        assert value in {m.strip() for m in record["mount"].split(",")}
    else:
        assert record.get(what) == value
    assert page in " ".join(record["source"].split())


@pytest.mark.parametrize("lens_id", sorted(MOUNTS))
def test_mounts_and_sensor_as_the_sources_list_them(lens_id):
    record = record_of(RECORDS, lens_id)
    mounts, sensor = MOUNTS[lens_id]
    assert {m.strip() for m in record["mount"].split(",")} == mounts
    assert record.get("sensor") == sensor
    # every mount but one a page names (the Viltrox 28mm's Fujifilm X) has its own record in the dataset
    files = {"Sony E": "e", "Fujifilm X": "x", "Nikon Z": "z", "Canon RF": "rf", "L-Mount": "l"}
    source = " ".join(record["source"].split())
    if lens_id.startswith("viltrox-"):
        named = {m for m, f in files.items() if f"{VILTROX}{f}/index.js" in source
                 or f"build/data/viltrox/{f}/index.js" in source}
        assert named == mounts - ({"Fujifilm X"} if lens_id == "viltrox-af-28mm-f4.5-fe" else set())


def test_every_entry_is_new_names_its_mounts_and_says_why_it_is_approximate():
    check_entries_are_new(FILE, RECORDS)
    for record in RECORDS:
        assert record["mount"] and record["mount"] != "various", record["id"]
        assert record["category"] == "prime", record["id"]
        notes = " ".join(record["notes"].split())
        # every entry rests on the dataset alone for its closest focus, and says so and what was searched
        assert record["approximate"] is True and notes.startswith("Approximate:"), record["id"]
        assert "the closest focus" in notes and "dataset's alone" in notes and "searched" in notes, record["id"]
        if "max_magnification" not in record:
            assert "no source read gives a maximum magnification" in notes, record["id"]
        lens = load_db().lens(record["id"])
        assert lens.tier == "shipped" and lens.approximate


def test_full_frame_and_aps_c_lines_are_told_apart():
    # the dataset's format: Full-Frame for Viltrox's FE/LAB primes and Samyang's FE ones, APS-C for the rest
    for record in RECORDS:
        source = " ".join(record["source"].split())
        aps_c = "format APS-C" in source
        assert aps_c != ("format Full-Frame" in source), record["id"]
        assert (record.get("sensor") == "aps-c") == aps_c, record["id"]


def unit_focusing(focal: float, distance: float) -> float:
    """The magnification of a thin lens of ``focal`` focused by extension at ``distance`` (object to image):
    D = f (2 + m + 1/m), the smaller root."""
    k = distance / focal - 2
    return (k - math.sqrt(k * k - 4)) / 2


@pytest.mark.parametrize("lens_id", [r["id"] for r in RECORDS])
def test_the_model_never_magnifies_more_than_the_source_says(lens_id):
    lens = load_db().lens(lens_id)
    model = focus_model(lens, lens.focal_length_mm)
    m, _ = internal_focus_at_distance(model, model.min_focus_mm)
    if lens.max_magnification is not None:
        # a published maximum: reached exactly at the closest focus, never exceeded
        check_never_magnifies_more(lens)
    else:
        # none published: unit focusing stopped at the published closest focus
        assert model.min_focus_mm == lens.min_focus_mm
        assert m == pytest.approx(unit_focusing(lens.focal_length_mm, lens.min_focus_mm), rel=1e-9)


def test_published_magnifications_against_unit_focusing():
    # Viltrox 16mm: 0.13x at 0.27 m is more than unit focusing gives (0.0675x), a lens focusing to a longer
    # focal length; Samyang 24mm F1.8: 0.15x at 0.19 m is less (0.174x), internal focusing shortening it to about
    # 21.5 mm (listed in tests/test_presets_consistency.py)
    assert unit_focusing(16, 270) == pytest.approx(0.06753, abs=1e-5) and unit_focusing(16, 270) < 0.13
    assert unit_focusing(24, 190) == pytest.approx(0.17414, abs=1e-5) and unit_focusing(24, 190) > 0.15
    implied = 190 / (2 + 0.15 + 1 / 0.15)
    assert implied == pytest.approx(21.55, abs=0.01)
    lens = load_db().lens("samyang-af-24-1.8")
    model = focus_model(lens, 24.0)
    assert internal_focus_at_distance(model, 190.0)[0] == pytest.approx(0.15, rel=1e-6)


def test_dof_refuses_closer_than_the_published_closest_focus():
    # Viltrox AF 135mm F1.8 LAB: 0.72 m
    (row,) = run_json("dof", "--lens", "viltrox-135-1.8", "-N", "2.8", "-s", "1m")
    assert row["near_mm"] < 1000.0 < row["far_mm"]
    result = run("dof", "--lens", "viltrox-135-1.8", "-N", "2.8", "-s", "0.6m")
    assert result.exit_code == 2
    assert "0.72 m" in result.output


def test_a_fixed_aperture_lens_refuses_another_f_number():
    # Viltrox AF 28mm F4.5: no aperture mechanism (f/4.5 only)
    (row,) = run_json("dof", "--lens", "viltrox-28-4.5", "-N", "4.5", "-s", "2m")
    assert row["near_mm"] < 2000.0 < row["far_mm"]
    assert run("dof", "--lens", "viltrox-28-4.5", "-N", "8", "-s", "2m").exit_code == 2
