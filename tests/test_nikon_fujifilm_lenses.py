"""lens_db/nikon-fujifilm-lenses.yaml: each entry's figures against the datasets and pages its `source` quotes, and
the magnification the focusing model derives at the closest focus against the published maximum."""

from __future__ import annotations

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
    name_key,
    record_of,
    taken_elsewhere,
)

from camtool.geometry.closeup import internal_focus_at_distance
from camtool.presets import load_db
from camtool.presets.focusing import focus_model

FILE = DB / "nikon-fujifilm-lenses.yaml"
RECORDS = lens_records(FILE)

# isamu/lens-database (build/data/<maker>/...) gives `minFocusDistance` in metres and `maxMagnification`; the
# commits are named in each entry's source.
# (lens, focal length mm, closest focus mm, magnification at that row or None, (widest, smallest f-number or
# None), largest magnification the sources give for the lens)
CITED = [
    # nikon/z/zoom.js: 0.28, 0.13; smatu.net: 撮像面から0.28m(ズーム全域)
    ("nikon-z-14-24mm-f2.8-s", 14, 280, None, (2.8, None), 0.13),
    ("nikon-z-14-24mm-f2.8-s", 24, 280, None, (2.8, None), 0.13),
    # nikon/z/zoom.js: 0.28, 0.16; smatu.net: 撮像面から0.28m(ズーム全域)
    ("nikon-z-14-30mm-f4-s", 14, 280, None, (4, None), 0.16),
    ("nikon-z-14-30mm-f4-s", 30, 280, None, (4, None), 0.16),
    # review copy (aa-cambodia.com): Minimum aperture: f/22; 0.19m (W) 0.26m (T); nikon/z/zoom.js: 0.19, 0.19
    ("nikon-z-17-28mm-f2.8", 17, 190, None, (2.8, 22), 0.19),
    ("nikon-z-17-28mm-f2.8", 28, 260, None, (2.8, 22), 0.19),
    # Digital Camera World: 0.24m at 24mm and 0.33m at 70mm; 0.21x at 24mm and 0.32x at 70mm; f/2.8-22
    ("nikon-z-24-70mm-f2.8-s-ii", 24, 240, 0.21, (2.8, 22), 0.32),
    ("nikon-z-24-70mm-f2.8-s-ii", 70, 330, 0.32, (2.8, 22), 0.32),
    # LensVisualizer (Nikon's specification): 0.75 m at 100 mm and 0.98 m at 400 mm; nikon/z/zoom.js: 0.75, 0.38;
    # Photography Life review: 0.38x
    ("nikon-z-100-400mm-f4.5-5.6-vr-s", 100, 750, None, (4.5, None), 0.38),
    ("nikon-z-100-400mm-f4.5-5.6-vr-s", 400, 980, None, (5.6, None), 0.38),
    # nikon/z/zoom.js: fStop [4, 7.1], 0.2, 0.5
    ("nikon-z-24-105mm-f4-7.1", 24, 200, None, (4, None), 0.5),
    ("nikon-z-24-105mm-f4-7.1", 105, 200, None, (7.1, None), 0.5),
    # LensVisualizer (Nikon's pages): 0.38 m at 70 and 85 mm, 0.5 m at 105, 0.6 m at 135, 0.8 m at 200; 0.3x at 70 mm,
    # 0.25x at 200 mm; nikon/z/zoom.js: 0.38, 0.3
    ("nikon-z-70-200mm-f2.8-vr-s-ii", 70, 380, 0.3, (2.8, None), 0.3),
    ("nikon-z-70-200mm-f2.8-vr-s-ii", 85, 380, None, (2.8, None), 0.3),
    ("nikon-z-70-200mm-f2.8-vr-s-ii", 105, 500, None, (2.8, None), 0.3),
    ("nikon-z-70-200mm-f2.8-vr-s-ii", 135, 600, None, (2.8, None), 0.3),
    ("nikon-z-70-200mm-f2.8-vr-s-ii", 200, 800, 0.25, (2.8, None), 0.3),
    # nikon/z/zoom.js: 0.15, 0.24
    ("nikon-z-dx-16-50mm-f2.8-vr", 16, 150, None, (2.8, None), 0.24),
    ("nikon-z-dx-16-50mm-f2.8-vr", 50, 150, None, (2.8, None), 0.24),
    # nikon/z/zoom.js: 0.2, 0.33; LensVisualizer (Nikon's published specifications): 0.2 m at 18 mm, 0.4 m at
    # 100-140 mm, 0.33x at the telephoto end
    ("nikon-z-dx-18-140mm-f3.5-6.3-vr", 18, 200, None, (3.5, None), 0.33),
    ("nikon-z-dx-18-140mm-f3.5-6.3-vr", 140, 400, 0.33, (6.3, None), 0.33),
    # nikon/z/prime.js: 0.16, 0.67 (最大撮影倍率0.67倍); hoozuki.net/3679.html quoting Nikon's site: 最短撮影距離 0.16m,
    # 最大撮影倍率 0.67倍, 最小絞り 撮影距離∞:f/16
    ("nikon-z-dx-mc-35mm-f1.7", 35, 160, 0.67, (1.7, 16), 0.67),
    # nikon/z/prime.js: 0.85; Photography Life review: 0.11x
    ("nikon-z-85mm-f1.2-s", 85, 850, 0.11, (1.2, None), 0.11),
    # fujifilm/x/prime.js: 0.267, 0.5; LensVisualizer: 0.5x at 26.7 cm; Admiring Light and kstphotography: 1:2 (0.5)
    ("fujifilm-xf60mm-f2.4-r-macro", 60, 267, 0.5, (2.4, None), 0.5),
    # fujifilm/x/prime.js: 0.39, 0.15; danielm.photo.blog: 39cm; LensVisualizer (Fujifilm's specification page):
    # 0.39 m minimum focus, and 0.15x maximum magnification
    ("fujifilm-xf50mm-f2-r-wr", 50, 390, 0.15, (2, None), 0.15),
    # fujifilm/x/prime.js: 0.1, 1; LensVisualizer (Fujifilm's specifications): 1.0x maximum magnification and a
    # 0.10 m minimum focus distance measured from the focal plane
    ("fujifilm-xf30mm-f2.8-r-lm-wr-macro", 30, 100, 1.0, (2.8, None), 1.0),
    # fujifilm/x/prime.js: 2.75, 0.2
    ("fujifilm-xf500mm-f5.6-r-lm-ois-wr", 500, 2750, 0.2, (5.6, None), 0.2),
    # fujifilm/x/prime.js: 0.2, 0.15; LensVisualizer (Fujifilm's published figures): 0.20 m minimum focus from the
    # focal plane, 0.15x maximum magnification
    ("fujifilm-xf23mm-f2.8-r-wr", 23, 200, 0.15, (2.8, None), 0.15),
    # LensVisualizer (Fujifilm's page): 1.75 m, 0.19x at the telephoto end; fujifilm/x/zoom.js: 1.75
    ("fujifilm-xf100-400mm-f4.5-5.6-r-lm-ois-wr", 100, 1750, None, (4.5, None), 0.19),
    ("fujifilm-xf100-400mm-f4.5-5.6-r-lm-ois-wr", 400, 1750, 0.19, (5.6, None), 0.19),
    # fujifilm/x/xc.js: 0.35, 0.14
    ("fujifilm-xc35mm-f2", 35, 350, 0.14, (2, None), 0.14),
    # fujifilm/x/xc.js: 0.13, 0.24
    ("fujifilm-xc15-45mm-f3.5-5.6-ois-pz", 15, 130, None, (3.5, None), 0.24),
    ("fujifilm-xc15-45mm-f3.5-5.6-ois-pz", 45, 130, None, (5.6, None), 0.24),
    # fujifilm/x/xc.js: 1.1, 0.2; seriouscompacts.com: 1.1 m for .20x; LensVisualizer (Fujifilm's specifications):
    # 1.1 m is the retail minimum focus distance, the retail 0.2x close-up magnification
    ("fujifilm-xc50-230mm-f4.5-6.7-ois-ii", 50, 1100, None, (4.5, None), 0.2),
    ("fujifilm-xc50-230mm-f4.5-6.7-ois-ii", 230, 1100, None, (6.7, None), 0.2),
    # fujifilm/x/xc.js: 0.2, 0.25
    ("fujifilm-xc13-33mm-f3.5-6.3-ois", 13, 200, None, (3.5, None), 0.25),
    ("fujifilm-xc13-33mm-f3.5-6.3-ois", 33, 200, None, (6.3, None), 0.25),
    # LensVisualizer (Fujifilm's pages): 0.6 m at wide, 1.6 m at telephoto, 0.2x at wide; jalangle/ghtns notes: Min
    # Aperture 5.6, Max Aperture 32, 0.6m-∞,1.6m-∞, 0.2x; fujifilm/g/index.js: 0.6
    ("fujifilm-gf100-200mm-f5.6-r-lm-ois-wr", 100, 600, 0.2, (5.6, 32), 0.2),
    ("fujifilm-gf100-200mm-f5.6-r-lm-ois-wr", 200, 1600, None, (5.6, 32), 0.2),
    # fujifilm/g/index.js: 0.43, 0.5
    ("fujifilm-gf110mm-f5.6-t-s-macro", 110, 430, 0.5, (5.6, None), 0.5),
    # LensVisualizer (Fujifilm's pages): a 20 cm minimum focus distance from the focal plane; 0.15x
    ("fujifilm-xf18mm-f1.4-r-lm-wr", 18, 200, 0.15, (1.4, None), 0.15),
    # LensVisualizer (Fujifilm's specification): 0.30 m, 0.21x; fujifilm/x/zoom.js: 0.3
    ("fujifilm-xf16-55mm-f2.8-r-lm-wr-ii", 16, 300, None, (2.8, None), 0.21),
    ("fujifilm-xf16-55mm-f2.8-r-lm-wr-ii", 55, 300, None, (2.8, None), 0.21),
    # LensVisualizer (Fujifilm's pages): 0.6 m, 0.2x at the tele end; fujifilm/x/zoom.js: 0.6
    ("fujifilm-xf18-120mm-f4-lm-pz-wr", 18, 600, None, (4, None), 0.2),
    ("fujifilm-xf18-120mm-f4-lm-pz-wr", 120, 600, 0.2, (4, None), 0.2),
    # fujifilm/x/zoom.js: 1.1; seriouscompacts.com: 1.1m for .18x; LensVisualizer (FUJIFILM's marketed
    # specification): Minimum focus distance 1.1 m, Maximum magnification 0.18x at tele
    ("fujifilm-xf55-200mm-f3.5-4.8-r-lm-ois", 55, 1100, None, (3.5, None), 0.18),
    ("fujifilm-xf55-200mm-f3.5-4.8-r-lm-ois", 200, 1100, 0.18, (4.8, None), 0.18),
    # LensVisualizer (Fujifilm's specifications): 0.45 m, 0.14x; fujifilm/g/index.js: 0.45
    ("fujifilm-gf45mm-f2.8-r-wr", 45, 450, 0.14, (2.8, None), 0.14),
    # LensVisualizer (Fujifilm's page): 0.35 m, 0.28x at the telephoto end; fujifilm/g/index.js: 0.35
    ("fujifilm-gf35-70mm-f4.5-5.6-wr", 35, 350, None, (4.5, None), 0.28),
    ("fujifilm-gf35-70mm-f4.5-5.6-wr", 70, 350, 0.28, (5.6, None), 0.28),
    # LensVisualizer (Fujifilm's specification): 2.75 m, 0.2x; fujifilm/g/index.js: 2.75
    ("fujifilm-gf500mm-f5.6-r-lm-ois-wr", 500, 2750, 0.2, (5.6, None), 0.2),
]

# the entries every figure of which two sources give (a page printing the maker's specification, or two datasets
# transcribing the maker's pages); every other entry has a figure that only one source gives, and is approximate
CONFIRMED = {"nikon-z-24-70mm-f2.8-s-ii", "nikon-z-70-200mm-f2.8-vr-s-ii", "fujifilm-xf60mm-f2.4-r-macro",
             "fujifilm-xf50mm-f2-r-wr", "fujifilm-xf30mm-f2.8-r-lm-wr-macro", "fujifilm-xf23mm-f2.8-r-wr",
             "fujifilm-xf55-200mm-f3.5-4.8-r-lm-ois", "fujifilm-xc50-230mm-f4.5-6.7-ois-ii",
             "nikon-z-dx-mc-35mm-f1.7"}


def test_every_entry_is_checked_against_its_sources():
    check_every_entry_cited(RECORDS, CITED)


@pytest.mark.parametrize(("lens_id", "focal", "distance", "magnification", "apertures", "largest"), CITED,
                         ids=[f"{c[0]}@{c[1]}" for c in CITED])
def test_figures_against_the_cited_sources(lens_id, focal, distance, magnification, apertures, largest):
    record = record_of(RECORDS, lens_id)
    check_cited_row(record, focal, distance, magnification, apertures, largest)
    # the lens's closest focus is the closest of its rows
    if "close_focus" in record:
        assert record["min_focus_mm"] == min(r["min_focus_mm"] for r in record["close_focus"])


def test_every_entry_is_new_names_its_mount_and_says_what_is_unconfirmed():
    check_entries_are_new(FILE, RECORDS)
    for record in RECORDS:
        assert record["mount"] in {"Nikon Z", "Fujifilm X", "Fujifilm G"}, record["id"]
        assert record["max_magnification"] and record["min_focus_mm"], record["id"]
        # a maker's name and mount agree; a DX, X or XC lens names its APS-C sensor, a GF lens the 44 x 33 mm one
        maker = record["id"].split("-")[0]
        assert record["mount"].startswith({"nikon": "Nikon", "fujifilm": "Fujifilm"}[maker]), record["id"]
        if "-dx-" in record["id"] or record["mount"] == "Fujifilm X":
            assert record["sensor"] == "aps-c", record["id"]
        if record["mount"] == "Fujifilm G":
            assert record["sensor"] == "mf-44x33", record["id"]
        assert bool(record.get("approximate")) == (record["id"] not in CONFIRMED), record["id"]
        if record.get("approximate"):
            assert " ".join(record["notes"].split()).startswith("approximate:"), record["id"]
        # every source names the commit of the dataset it quotes
        assert re.search(r"\bat [0-9a-f]{40}\b", " ".join(record["source"].split())), record["id"]


def test_every_published_zoom_row_keeps_its_magnification():
    # a zoom row whose source prints the magnification with the closest focus carries it
    published = {(lens_id, f) for lens_id, f, _d, m, *_ in CITED if m is not None}
    for record in RECORDS:
        for row in record.get("close_focus", []):
            assert ((record["id"], row["focal_length_mm"]) in published) == ("max_magnification" in row)


@pytest.mark.parametrize("lens_id", [r["id"] for r in RECORDS])
def test_the_model_never_magnifies_more_than_the_sources_say(lens_id):
    # at every published row, at both ends, and halfway between neighbouring rows
    check_never_magnifies_more(load_db().lens(lens_id))


def test_z_24_70_ii_reaches_each_published_magnification_at_its_own_distance():
    lens = load_db().lens("nikon-z-24-70mm-f2.8-s-ii")
    for focal, distance, published in ((24.0, 240.0, 0.21), (70.0, 330.0, 0.32)):
        model = focus_model(lens, focal)
        assert model.min_focus_mm == distance
        assert internal_focus_at_distance(model, distance)[0] == pytest.approx(published, rel=1e-6)


def test_z_dx_18_140_quotes_the_analysis_for_the_telephoto_row():
    # LensVisualizer's analysis quoting Nikon: 0.4 m at 100-140 mm and 0.33x at the telephoto end, where the dataset
    # gives the lens one closest focus (0.2 m); the model reaches the 0.33x at 0.4 m and 140 mm
    record = record_of(RECORDS, "nikon-z-dx-18-140mm-f3.5-6.3-vr")
    source = " ".join(record["source"].split())
    assert ("ronbuening/LensVisualizer src/lens-data/nikon/NikonZDX18140mmf3563VR.analysis.md at "
            "0e0fdb75faa403fcb6ff93c07581459fc687b059") in source
    assert "0.2 m at 18 mm (wide), increasing to 0.4 m at 100–140 mm (tele)" in source
    assert "maximum reproduction ratio of 0.33× at the telephoto end" in source
    assert "minFocusDistance 0.2, maxMagnification 0.33" in source
    model = focus_model(load_db().lens("nikon-z-dx-18-140mm-f3.5-6.3-vr"), 140.0)
    assert model.min_focus_mm == 400.0
    assert internal_focus_at_distance(model, 400.0)[0] == pytest.approx(0.33, rel=1e-6)


def test_xf100_400_at_100mm_stays_below_the_telephoto_figure():
    # one closest focus for the zoom: at 100 mm and 1.75 m the model gives less than the 0.19x published at 400 mm
    lens = load_db().lens("fujifilm-xf100-400mm-f4.5-5.6-r-lm-ois-wr")
    model = focus_model(lens, 100.0)
    assert internal_focus_at_distance(model, 1750.0)[0] < 0.19
