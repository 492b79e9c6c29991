"""lens_db/late-additions-lenses.yaml: each entry's figures against the dataset records and lens-design analyses its
`source` quotes, what each approximate entry still names as open, and the magnification the focusing model derives at
the closest focus against the published maximum."""

from __future__ import annotations

import math
import re

import pytest
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

FILE = DB / "late-additions-lenses.yaml"
RECORDS = lens_records(FILE)

# (lens, focal length mm, closest focus mm, magnification at that row or None, (widest, smallest f-number or None),
# largest magnification the sources give or None) as the sources each entry names print them: isamu/lens-database
# (minFocusDistance in m, maxMagnification) and the LensVisualizer analyses quoting the makers' specifications
CITED = [
    # olympus/microfourthirds/index.js: minFocusDistance 0.15, maxMagnification 0.3; OlympusMZuiko12100mmf4ISPRO
    # .analysis.md: "specified at 0.15 m minimum focus distance at the wide end and 0.45 m at the tele end"
    ("om-m-zuiko-12-100mm-f4-is-pro", 12, 150, None, (4, None), 0.3),
    ("om-m-zuiko-12-100mm-f4-is-pro", 100, 450, None, (4, None), 0.3),
    # nikon/z/prime.js: minFocusDistance 0.25; NikonZ35f18S.analysis.md: "0.25 m Nikon spec"; no magnification
    ("nikon-z-35mm-f1.8-s", 35, 250, None, (1.8, None), None),
    # nikon/z/prime.js: minFocusDistance 0.3; NikonNikkorZ35mmf12S.analysis.md: production "0.30 m at 0.20×"
    ("nikon-z-35mm-f1.2-s", 35, 300, 0.2, (1.2, None), 0.2),
    # nikon/z/prime.js: minFocusDistance 0.5; NikonZ58f095SNoct.analysis.md: Nikon Spec Sheet "0.194×", "0.5 m"
    ("nikon-z-58mm-f0.95-s-noct", 58, 500, 0.194, (0.95, None), 0.194),
    # fujifilm/x/prime.js: minFocusDistance 1.8; FujifilmXF200mmf2R.analysis.md: "Close focus distance | 1.57 m | **1.8
    # m**", "Min aperture | — (not tabulated) | f/22"; no magnification
    ("fujifilm-xf200mm-f2-r-lm-ois-wr", 200, 1800, None, (2, 22), None),
    # fujifilm/g/index.js: minFocusDistance 0.7; FujifilmGF80mmf17R.analysis.md: "Production: 0.7 m"; no magnification
    ("fujifilm-gf80mm-f1.7-r-wr", 80, 700, None, (1.7, None), None),
]

# what each approximate entry's notes must name as open (every entry here has a figure one source alone gives)
OPEN = {
    "om-m-zuiko-12-100mm-f4-is-pro": ("the 0.45 m at 100 mm", "maximum magnification 0.3x is from one dataset only"),
    "nikon-z-35mm-f1.8-s": ("the maximum magnification is unconfirmed",),
    "nikon-z-35mm-f1.2-s": ("the maximum magnification (0.2x) is the analysis's quotation",),
    "nikon-z-58mm-f0.95-s-noct": ("the maximum magnification (0.194x) is the analysis's quotation",),
    "fujifilm-xf200mm-f2-r-lm-ois-wr": ("the maximum magnification is unconfirmed", "f/22, is the analysis's quotation"),
    "fujifilm-gf80mm-f1.7-r-wr": ("the maximum magnification is unconfirmed",),
}


def test_every_entry_is_checked_against_its_sources():
    check_every_entry_cited(RECORDS, CITED)
    assert len(RECORDS) == len({lens_id for lens_id, *_ in CITED})


@pytest.mark.parametrize(("lens_id", "focal", "distance", "magnification", "apertures", "largest"), CITED,
                         ids=[f"{c[0]}@{c[1]}" for c in CITED])
def test_figures_against_the_cited_sources(lens_id, focal, distance, magnification, apertures, largest):
    record = record_of(RECORDS, lens_id)
    check_cited_row(record, focal, distance, magnification, apertures, largest)
    if largest is None:
        assert "max_magnification" not in record


def test_every_entry_is_new_names_its_sources_and_what_is_open():
    check_entries_are_new(FILE, RECORDS)
    for record in RECORDS:
        source = " ".join(record["source"].split())
        assert "isamu/lens-database" in source and "ronbuening/LensVisualizer" in source, record["id"]
        assert len(re.findall(r"\bat [0-9a-f]{40}\b", source)) == 2, record["id"]
        notes = " ".join(record["notes"].split())
        assert record["approximate"] is True and notes.startswith("Approximate:"), record["id"]
        for words in OPEN[record["id"]]:
            assert words in notes, (record["id"], words)
        assert record["mount"] in {"Micro Four Thirds", "Nikon Z", "Fujifilm X", "Fujifilm G"}, record["id"]
    assert set(OPEN) == {r["id"] for r in RECORDS}
    assert record_of(RECORDS, "om-m-zuiko-12-100mm-f4-is-pro")["sensor"] == "four-thirds"
    assert record_of(RECORDS, "fujifilm-xf200mm-f2-r-lm-ois-wr")["sensor"] == "aps-c"
    assert record_of(RECORDS, "fujifilm-gf80mm-f1.7-r-wr")["sensor"] == "mf-44x33"


@pytest.mark.parametrize("lens_id", [r["id"] for r in RECORDS if "max_magnification" in r])
def test_the_model_never_magnifies_more_than_the_sources_say(lens_id):
    check_never_magnifies_more(load_db().lens(lens_id))


def test_the_12_100mm_long_end_is_capped_and_its_wide_end_is_unit_focusing():
    # at 100 mm and 0.45 m a unit-focusing 100 mm lens would reach 0.5x (D/f = 4.5 = 2 + m + 1/m), more than the
    # published 0.3x, so the model is capped there; at 12 mm and 0.15 m it gives the unit-focusing figure, about 0.1x
    lens = load_db().lens("om-m-zuiko-12-100mm-f4-is-pro")
    k = 450.0 / 100.0 - 2.0
    assert (k - math.sqrt(k * k - 4.0)) / 2.0 == pytest.approx(0.5)
    assert internal_focus_at_distance(focus_model(lens, 100.0), 450.0)[0] == pytest.approx(0.3, rel=1e-6)
    k = 150.0 / 12.0 - 2.0
    unit = (k - math.sqrt(k * k - 4.0)) / 2.0
    assert unit == pytest.approx(0.0961, abs=5e-4)
    assert internal_focus_at_distance(focus_model(lens, 12.0), 150.0)[0] == pytest.approx(unit, rel=1e-6)
    # and the model refuses to focus the long end closer than OM System's 0.45 m
    assert focus_model(lens, 100.0).min_focus_mm == 450.0


@pytest.mark.parametrize(("lens_id", "focal", "distance", "about"), [
    # D/f = 2 + m + 1/m: the NIKKOR Z 35mm f/1.8 S at 0.25 m, the XF200mm at 1.8 m, the GF80mm at 0.7 m
    ("nikon-z-35mm-f1.8-s", 35.0, 250.0, 0.20), ("fujifilm-xf200mm-f2-r-lm-ois-wr", 200.0, 1800.0, 0.146),
    ("fujifilm-gf80mm-f1.7-r-wr", 80.0, 700.0, 0.152)])
def test_a_prime_without_a_published_magnification_is_unit_focusing_at_its_closest_focus(lens_id, focal, distance,
                                                                                          about):
    record = record_of(RECORDS, lens_id)
    assert f"about {about:.2f}" in " ".join(record["notes"].split()) or f"about {about:.3f}" in " ".join(
        record["notes"].split())
    lens = load_db().lens(lens_id)
    k = distance / focal - 2.0
    unit = (k - math.sqrt(k * k - 4.0)) / 2.0
    assert unit == pytest.approx(about, abs=0.003)
    assert internal_focus_at_distance(focus_model(lens, focal), distance)[0] == pytest.approx(unit, rel=1e-6)


def test_the_published_pairs_reach_more_than_unit_focusing():
    # 0.2x at 0.3 m (35 mm) and 0.194x at 0.5 m (58 mm) are more than a unit-focusing lens of that focal length reaches
    # there (about 0.165x and 0.163x), as for most fast primes focused by a floating group; the model meets both
    for lens_id, f, d, m in (("nikon-z-35mm-f1.2-s", 35.0, 300.0, 0.2), ("nikon-z-58mm-f0.95-s-noct", 58.0, 500.0, 0.194)):
        k = d / f - 2.0
        assert (k - math.sqrt(k * k - 4.0)) / 2.0 < m
        assert internal_focus_at_distance(focus_model(load_db().lens(lens_id), f), d)[0] == pytest.approx(m, rel=1e-6)
