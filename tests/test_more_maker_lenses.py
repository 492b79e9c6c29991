"""lens_db/more-maker-lenses.yaml: each entry's figures against the scrapes and pages its `source` quotes, and the
magnification the focusing model derives at the closest focus against the published maximum."""

from __future__ import annotations

import math

import pytest
from cli_helpers import run, run_json
from lens_checks import (  # noqa: F401 - isolated: an autouse fixture
    DB,
    check_against_analysis,
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

FILE = DB / "more-maker-lenses.yaml"
RECORDS = lens_records(FILE)


# (lens, focal length mm, closest focus mm, magnification at that row or None, (widest, smallest f-number or
# None), largest magnification the source gives for the lens) as the sources each entry names print them:
# isamu/lens-database's records of personal.canon.jp, panasonic.jp and jp.omsystem.com (minFocusDistance in m,
# maxMagnification, the other end of a zoom from the record's note; Micro Four Thirds magnifications are the
# actual ratio, not the 35 mm equivalent one), and the pages cited beside them
CITED = [
    # minFocusDistance 0.45, maxMagnification 0.13
    ("canon-rf-45mm-f1.2-stm", 45, 450, 0.13, (1.2, None), 0.13),
    # minFocusDistance 0.15, maxMagnification 0.5
    ("panasonic-lumix-s-14-28mm-f4-5.6-macro", 14, 150, None, (4, None), 0.5),
    ("panasonic-lumix-s-14-28mm-f4-5.6-macro", 28, 150, None, (5.6, None), 0.5),
    # minFocusDistance 0.25, maxMagnification 0.23
    ("panasonic-lumix-s-pro-16-35mm-f4", 16, 250, None, (4, None), 0.23),
    ("panasonic-lumix-s-pro-16-35mm-f4", 35, 250, None, (4, None), 0.23),
    # 0.15 m from the wide end to 21mm, 0.35 m at the long end, maxMagnification 0.28
    ("panasonic-lumix-s-18-40mm-f4.5-6.3", 18, 150, None, (4.5, None), 0.28),
    ("panasonic-lumix-s-18-40mm-f4.5-6.3", 21, 150, None, (4.5, None), 0.28),
    ("panasonic-lumix-s-18-40mm-f4.5-6.3", 40, 350, None, (6.3, None), 0.28),
    # 0.19 m to 30mm, 0.33 m at 60mm; 0.25x at 24mm, 0.3x at 30mm, 0.22x at 60mm
    ("panasonic-lumix-s-24-60mm-f2.8", 24, 190, 0.25, (2.8, None), 0.3),
    ("panasonic-lumix-s-24-60mm-f2.8", 30, 190, 0.3, (2.8, None), 0.3),
    ("panasonic-lumix-s-24-60mm-f2.8", 60, 330, 0.22, (2.8, None), 0.3),
    # minFocusDistance 0.37, maxMagnification 0.25; Le Monde de la Photo: 37 cm at every focal length
    ("panasonic-lumix-s-pro-24-70mm-f2.8", 24, 370, None, (2.8, None), 0.25),
    ("panasonic-lumix-s-pro-24-70mm-f2.8", 70, 370, None, (2.8, None), 0.25),
    # 0.14 m and 0.5x at the wide end, 0.65 m at the long end
    ("panasonic-lumix-s-28-200mm-f4-7.1-macro-ois", 28, 140, 0.5, (4, None), 0.5),
    ("panasonic-lumix-s-28-200mm-f4-7.1-macro-ois", 200, 650, None, (7.1, None), 0.5),
    # minFocusDistance 0.95, maxMagnification 0.21
    ("panasonic-lumix-s-pro-70-200mm-f2.8-ois", 70, 950, None, (2.8, None), 0.21),
    ("panasonic-lumix-s-pro-70-200mm-f2.8-ois", 200, 950, None, (2.8, None), 0.21),
    # minFocusDistance 0.92, maxMagnification 0.25
    ("panasonic-lumix-s-pro-70-200mm-f4-ois", 70, 920, None, (4, None), 0.25),
    ("panasonic-lumix-s-pro-70-200mm-f4-ois", 200, 920, None, (4, None), 0.25),
    # 0.54 m at the wide end, 0.74 m at the long end, maxMagnification 0.5
    ("panasonic-lumix-s-70-300mm-f4.5-5.6-macro-ois", 70, 540, None, (4.5, None), 0.5),
    ("panasonic-lumix-s-70-300mm-f4.5-5.6-macro-ois", 300, 740, None, (5.6, None), 0.5),
    # 0.8 m and 0.16x at the wide end, 1.50 m and 0.36x at the long end
    ("panasonic-lumix-s-100-500mm-f5-7.1-ois", 100, 800, 0.16, (5, None), 0.36),
    ("panasonic-lumix-s-100-500mm-f5-7.1-ois", 500, 1500, 0.36, (7.1, None), 0.36),
    # minFocusDistance 0.18, maxMagnification 0.2
    ("panasonic-lumix-s-18mm-f1.8", 18, 180, 0.2, (1.8, None), 0.2),
    # minFocusDistance 0.24, maxMagnification 0.15
    ("panasonic-lumix-s-24mm-f1.8", 24, 240, 0.15, (1.8, 22), 0.15),
    # minFocusDistance 0.24, maxMagnification 0.22
    ("panasonic-lumix-s-35mm-f1.8", 35, 240, 0.22, (1.8, None), 0.22),
    # minFocusDistance 0.3, maxMagnification 0.17
    ("panasonic-lumix-s-40mm-f2", 40, 300, 0.17, (2, None), 0.17),
    # minFocusDistance 0.44, maxMagnification 0.15; Les Numériques: Ouverture minimale f/16, Rapport de reproduction
    # 0.15 x
    ("panasonic-lumix-s-pro-50mm-f1.4", 50, 440, 0.15, (1.4, 16), 0.15),
    # minFocusDistance 0.45, maxMagnification 0.14
    ("panasonic-lumix-s-50mm-f1.8", 50, 450, 0.14, (1.8, None), 0.14),
    # minFocusDistance 0.8, maxMagnification 0.13
    ("panasonic-lumix-s-85mm-f1.8", 85, 800, 0.13, (1.8, None), 0.13),
    # minFocusDistance 0.25, maxMagnification 0.14, F8 fixed
    ("panasonic-lumix-s-26mm-f8", 26, 250, 0.14, (8, 8), 0.14),
    # minFocusDistance 0.204, maxMagnification 1 (等倍)
    ("panasonic-lumix-s-100mm-f2.8-macro", 100, 204, 1, (2.8, None), 1),
    # 0.24 m, 1:5 (0.2x)
    ("leica-apo-summicron-sl-28mm-f2-asph", 28, 240, 0.2, (2, None), 0.2),
    # 0.35 m, 1:5 (0.2x)
    ("leica-apo-summicron-sl-50mm-f2-asph", 50, 350, 0.2, (2, 22), 0.2),
    # 0.27 m, 1:5 (0.2x)
    ("leica-apo-summicron-sl-35mm-f2-asph", 35, 270, 0.2, (2, None), 0.2),
    # 0.5 m, 1:5 (0.2x)
    ("leica-apo-summicron-sl-75mm-f2-asph", 75, 500, 0.2, (2, None), 0.2),
    # 0.6 m, 1:5 (0.2x)
    ("leica-apo-summicron-sl-90mm-f2-asph", 90, 600, 0.2, (2, None), 0.2),
    # minFocusDistance 0.095, maxMagnification 0.25
    ("panasonic-leica-dg-summilux-9mm-f1.7", 9, 95, 0.25, (1.7, None), 0.25),
    # minFocusDistance 0.2, maxMagnification 0.1
    ("panasonic-leica-dg-summilux-12mm-f1.4", 12, 200, 0.1, (1.4, None), 0.1),
    # minFocusDistance 0.2, maxMagnification 0.1; i-kyon1521.com: 絞り値: F1.7~F16, 最短撮影距離: 20cm
    ("panasonic-leica-dg-summilux-15mm-f1.7", 15, 200, 0.1, (1.7, 16), 0.1),
    # minFocusDistance 0.3, maxMagnification 0.11
    ("panasonic-leica-dg-summilux-25mm-f1.4-ii", 25, 300, 0.11, (1.4, None), 0.11),
    # minFocusDistance 0.2, maxMagnification 0.13
    ("panasonic-lumix-g-20mm-f1.7-ii", 20, 200, 0.13, (1.7, None), 0.13),
    # minFocusDistance 0.25, maxMagnification 0.14
    ("panasonic-lumix-g-25mm-f1.7", 25, 250, 0.14, (1.7, None), 0.14),
    # minFocusDistance 0.31, maxMagnification 0.2; FotografiDigitali: 31cm, 0.2x (0.4x equivalenti), f/22
    ("panasonic-lumix-g-42.5mm-f1.7", 42.5, 310, 0.2, (1.7, 22), 0.2),
    # minFocusDistance 0.18, maxMagnification 0.1
    ("panasonic-lumix-g-14mm-f2.5-ii", 14, 180, 0.1, (2.5, None), 0.1),
    # 0.5 m, 0.1x; aperture 1.2 / 16
    ("panasonic-leica-dg-nocticron-42.5mm-f1.2", 42.5, 500, 0.1, (1.2, 16), 0.1),
    # 0.15 m, 1.0x (35 mm equivalent 2.0x), F22
    ("panasonic-leica-dg-macro-elmarit-45mm-f2.8", 45, 150, 1, (2.8, 22), 1),
    # minFocusDistance 0.105, maxMagnification 1 (35 mm equivalent 2.0)
    ("panasonic-lumix-g-macro-30mm-f2.8", 30, 105, 1, (2.8, None), 1),
    # minFocusDistance 0.23, maxMagnification 0.12; Wikipedia: aperture 2.8-4.0 / 22, close-dist 0.23 m, max-mag 0.12
    ("panasonic-leica-dg-vario-elmarit-8-18mm-f2.8-4", 8, 230, None, (2.8, 22), 0.12),
    ("panasonic-leica-dg-vario-elmarit-8-18mm-f2.8-4", 18, 230, None, (4, 22), 0.12),
    # minFocusDistance 0.28, maxMagnification 0.14
    ("panasonic-leica-dg-vario-summilux-10-25mm-f1.7", 10, 280, None, (1.7, None), 0.14),
    ("panasonic-leica-dg-vario-summilux-10-25mm-f1.7", 25, 280, None, (1.7, None), 0.14),
    # 0.2 m at the wide end, 0.3 m at the long end, maxMagnification 0.13
    ("panasonic-lumix-g-vario-12-32mm-f3.5-5.6", 12, 200, None, (3.5, None), 0.13),
    ("panasonic-lumix-g-vario-12-32mm-f3.5-5.6", 32, 300, None, (5.6, None), 0.13),
    # 0.15 m from the wide end to 17mm, 0.25 m at the long end, maxMagnification 0.21
    ("panasonic-leica-dg-vario-elmarit-12-35mm-f2.8", 12, 150, None, (2.8, None), 0.21),
    ("panasonic-leica-dg-vario-elmarit-12-35mm-f2.8", 17, 150, None, (2.8, None), 0.21),
    ("panasonic-leica-dg-vario-elmarit-12-35mm-f2.8", 35, 250, None, (2.8, None), 0.21),
    # 0.20 m at the wide end, 0.24 m at the long end, maxMagnification 0.3
    ("panasonic-leica-dg-vario-elmarit-12-60mm-f2.8-4", 12, 200, None, (2.8, None), 0.3),
    ("panasonic-leica-dg-vario-elmarit-12-60mm-f2.8-4", 60, 240, None, (4, None), 0.3),
    # 0.2 m at the wide end, 0.25 m at the long end, maxMagnification 0.27
    ("panasonic-lumix-g-vario-12-60mm-f3.5-5.6", 12, 200, None, (3.5, None), 0.27),
    ("panasonic-lumix-g-vario-12-60mm-f3.5-5.6", 60, 250, None, (5.6, None), 0.27),
    # 0.2 m at the wide end, 0.3 m at the long end, maxMagnification 0.17
    ("panasonic-lumix-g-x-vario-pz-14-42mm-f3.5-5.6", 14, 200, None, (3.5, None), 0.17),
    ("panasonic-lumix-g-x-vario-pz-14-42mm-f3.5-5.6", 42, 300, None, (5.6, None), 0.17),
    # 0.3 m at the wide end, 0.5 m at the long end, maxMagnification 0.25
    ("panasonic-lumix-g-vario-14-140mm-f3.5-5.6-ii", 14, 300, None, (3.5, None), 0.25),
    ("panasonic-lumix-g-vario-14-140mm-f3.5-5.6-ii", 140, 500, None, (5.6, None), 0.25),
    # 0.28 m at the wide end, 0.31 m at the long end, maxMagnification 0.21; The Phoblographer, Panasonic's table:
    # Minimum Aperture F16, 0.28m (at focal length 25mm) / 0.31m (at focal length 50mm), 0.21x
    ("panasonic-leica-dg-vario-summilux-25-50mm-f1.7", 25, 280, None, (1.7, 16), 0.21),
    ("panasonic-leica-dg-vario-summilux-25-50mm-f1.7", 50, 310, None, (1.7, 16), 0.21),
    # minFocusDistance 0.85, maxMagnification 0.1
    ("panasonic-leica-dg-vario-elmarit-35-100mm-f2.8", 35, 850, None, (2.8, None), 0.1),
    ("panasonic-leica-dg-vario-elmarit-35-100mm-f2.8", 100, 850, None, (2.8, None), 0.1),
    # minFocusDistance 0.9, maxMagnification 0.11
    ("panasonic-lumix-g-vario-35-100mm-f4-5.6", 35, 900, None, (4, None), 0.11),
    ("panasonic-lumix-g-vario-35-100mm-f4-5.6", 100, 900, None, (5.6, None), 0.11),
    # minFocusDistance 0.2, maxMagnification 0.15
    ("om-m-zuiko-17mm-f1.2-pro", 17, 200, 0.15, (1.2, None), 0.15),
    # minFocusDistance 0.25, maxMagnification 0.11
    ("om-m-zuiko-20mm-f1.4-pro", 20, 250, 0.11, (1.4, None), 0.11),
    # minFocusDistance 0.3, maxMagnification 0.11
    ("om-m-zuiko-25mm-f1.2-pro", 25, 300, 0.11, (1.2, None), 0.11),
    # minFocusDistance 0.5, maxMagnification 0.1
    ("om-m-zuiko-45mm-f1.2-pro", 45, 500, 0.1, (1.2, None), 0.1),
    # minFocusDistance 1.4, maxMagnification 0.24
    ("om-m-zuiko-300mm-f4-is-pro", 300, 1400, 0.24, (4, None), 0.24),
    # minFocusDistance 0.84, maxMagnification 0.1
    ("om-m-zuiko-75mm-f1.8", 75, 840, 0.1, (1.8, None), 0.1),
    # minFocusDistance 0.25, maxMagnification 0.08
    ("om-m-zuiko-17mm-f1.8-ii", 17, 250, 0.08, (1.8, None), 0.08),
    # minFocusDistance 0.25, maxMagnification 0.12
    ("om-m-zuiko-25mm-f1.8-ii", 25, 250, 0.12, (1.8, None), 0.12),
    # minFocusDistance 1.3, maxMagnification 0.29; 365photo.de: 1,3 Meter
    ("om-m-zuiko-150-400mm-f4.5-tc1.25x-is-pro", 150, 1300, None, (4.5, None), 0.29),
    ("om-m-zuiko-150-400mm-f4.5-tc1.25x-is-pro", 400, 1300, None, (4.5, None), 0.29),
    # 0.56 m and 0.35x at the wide end, 2.8 m and 0.20x at the long end
    ("om-m-zuiko-150-600mm-f5-6.3-is", 150, 560, 0.35, (5, None), 0.35),
    ("om-m-zuiko-150-600mm-f5-6.3-is", 600, 2800, 0.2, (6.3, None), 0.35),
]


def test_every_entry_is_checked_against_its_sources():
    check_every_entry_cited(RECORDS, CITED)
    assert len(RECORDS) >= 30


@pytest.mark.parametrize(("lens_id", "focal", "distance", "magnification", "apertures", "largest"), CITED,
                         ids=[f"{c[0]}@{c[1]}" for c in CITED])
def test_figures_against_the_cited_sources(lens_id, focal, distance, magnification, apertures, largest):
    record = record_of(RECORDS, lens_id)
    assert distance is not None
    check_cited_row(record, focal, distance, magnification, apertures, largest)


def test_every_entry_is_new_and_names_its_mount():
    check_entries_are_new(FILE, RECORDS)
    for record in RECORDS:
        assert record["mount"] in {"Canon RF", "L-Mount", "Micro Four Thirds"}, record["id"]
        assert record["max_magnification"] and record["min_focus_mm"], record["id"]
        assert "approximate" not in record or record["notes"].startswith("Approximate:"), record["id"]


def test_ids_and_aliases_are_unique_within_the_file():
    names = [n for r in RECORDS for n in (r["id"], *r.get("aliases", []))]
    assert len(names) == len(set(names))


# the entries whose figures a second page confirms, and the site that page is on: the Leica DG Macro-Elmarit 45mm
# (Panasonic's operating instructions), the Nocticron 42.5mm and the Vario-Elmarit 8-18mm (Wikipedia's data of the
# lens), the Lumix G 42.5mm F1.7 (FotografiDigitali), the Vario-Summilux 25-50mm (Panasonic's table as The
# Phoblographer prints it), the Lumix S 100mm Macro (Miss Numerique), the Lumix S 24mm F1.8 (Expeditions in
# Light), the APO-Summicron-SL 28 (Leica Society International) and 50 (Macfilos, Fstoppers)
CONFIRMED = {
    "panasonic-leica-dg-macro-elmarit-45mm-f2.8": "emanuals.org",
    "panasonic-leica-dg-nocticron-42.5mm-f1.2": "en.wikipedia.org/wiki/Nocticron",
    "panasonic-leica-dg-vario-elmarit-8-18mm-f2.8-4": "en.wikipedia.org/wiki/Panasonic_Leica_DG_Vario-Elmarit_8-18_mm",
    "panasonic-lumix-g-42.5mm-f1.7": "fotografidigitali.it/articoli/4434",
    "panasonic-leica-dg-vario-summilux-25-50mm-f1.7": "thephoblographer.com/2021/07/07",
    "panasonic-lumix-s-100mm-f2.8-macro": "missnumerique.com",
    "panasonic-lumix-s-24mm-f1.8": "expeditionsinlight.com",
    "leica-apo-summicron-sl-28mm-f2-asph": "leicasocietyinternational.org",
    "leica-apo-summicron-sl-50mm-f2-asph": "fstoppers.com",
    # the LensVisualizer lens-design analyses quoting Panasonic's figures (LENSVISUALIZER below)
    "panasonic-lumix-s-pro-24-70mm-f2.8": "PanasonicLumixSPro2470mmf28.analysis.md",
    "panasonic-lumix-s-pro-70-200mm-f2.8-ois": "PanasonicLumixSPro70200mmf28OIS.analysis.md",
    "panasonic-lumix-s-pro-50mm-f1.4": "PanasonicSPro50mmf14.analysis.md",
    "panasonic-leica-dg-summilux-12mm-f1.4": "PanasonicDGSummilux12mmf14.analysis.md",
    "panasonic-lumix-g-14mm-f2.5-ii": "PanasonicG14mmf25II.analysis.md",
    "panasonic-lumix-g-25mm-f1.7": "PanasonicLumixG25mmf17.analysis.md",
    "om-m-zuiko-75mm-f1.8": "OlympusMZuiko75mmf18.analysis.md",
}

# ronbuening/LensVisualizer src/lens-data/<maker>/<file> at the commit named: the maker's closest focus (m, one
# figure for the zoom) and maximum magnification as each analysis quotes them ("Panasonic specifies a 0.37 m closest
# focusing distance and approximately 0.25x maximum magnification"; "Panasonic markets ... 0.95 m closest focus,
# approximately 0.21x maximum magnification")
LENSVISUALIZER = [
    ("panasonic-lumix-s-pro-24-70mm-f2.8", "panasonic/PanasonicLumixSPro2470mmf28.analysis.md",
     "4e142ee8eff255f820438679aee8906800b33432", 0.37, 0.25),
    ("panasonic-lumix-s-pro-70-200mm-f2.8-ois", "panasonic/PanasonicLumixSPro70200mmf28OIS.analysis.md",
     "68d18c304a871fedf2d37fe5b8df4ac30802d500", 0.95, 0.21),
    # "matches the published 0.44 m", "matches the published 0.15x"
    ("panasonic-lumix-s-pro-50mm-f1.4", "panasonic/PanasonicSPro50mmf14.analysis.md",
     "1e0d09a310a3a4297fd3745ca79ed4f7058d2a26", 0.44, 0.15),
    # "Panasonic's official specification gives ... 0.20 m closest focusing distance, approximately 0.1x maximum
    # magnification"
    ("panasonic-leica-dg-summilux-12mm-f1.4", "panasonic/PanasonicDGSummilux12mmf14.analysis.md",
     "84580191e3db943b3155bccdeb889dc7de716849", 0.2, 0.1),
    # "Panasonic's published H-H014A specification gives ... 0.18 m closest focusing distance, and approximately
    # 0.10x maximum magnification"
    ("panasonic-lumix-g-14mm-f2.5-ii", "panasonic/PanasonicG14mmf25II.analysis.md",
     "db0caf206caf4004d33c6cc4346e3d501579ba3a", 0.18, 0.1),
    # "The production specification gives ... 0.25 m minimum focus, 0.14x maximum magnification"
    ("panasonic-lumix-g-25mm-f1.7", "panasonic/PanasonicLumixG25mmf17.analysis.md",
     "10f5e4e2eaea63f8cb43943dcdda6ea0f2903232", 0.25, 0.14),
    # "The production specification states 0.84 m minimum focus and 0.1x maximum magnification"
    ("om-m-zuiko-75mm-f1.8", "olympus/OlympusMZuiko75mmf18.analysis.md",
     "62b8fb8168a021cadd55996b45795ffecba8c808", 0.84, 0.1),
    # "0.24 m (9.5") in Panasonic's specification" (no magnification: the 0.22x stays open, PARTLY_CONFIRMED)
    ("panasonic-lumix-s-35mm-f1.8", "panasonic/PanasonicS35mmf18.analysis.md",
     "1e0d09a310a3a4297fd3745ca79ed4f7058d2a26", 0.24, None),
]


@pytest.mark.parametrize(("lens_id", "name", "commit", "closest_m", "magnification"), LENSVISUALIZER,
                         ids=[row[0] for row in LENSVISUALIZER])
def test_figures_against_the_lensvisualizer_analyses(lens_id, name, commit, closest_m, magnification):
    check_against_analysis(record_of(RECORDS, lens_id), closest_m, magnification,
                           f"ronbuening/LensVisualizer src/lens-data/{name} at {commit}")


def test_the_s_pro_50mm_keeps_its_page_for_the_magnification_and_smallest_aperture():
    # Les Numériques: Rapport de reproduction 0.15 x, f/16
    record = record_of(RECORDS, "panasonic-lumix-s-pro-50mm-f1.4")
    assert "lesnumeriques.com" in record["source"]
    assert (record["max_magnification"], record["f_number_max"]) == (0.15, 16)


def test_the_24_70mm_keeps_its_page_for_the_closest_focus():
    # Le Monde de la Photo: "La distance minimale de mise au point se situe à 37 cm, quelle que soit la focale"
    record = record_of(RECORDS, "panasonic-lumix-s-pro-24-70mm-f2.8")
    assert "lemondedelaphoto.com" in record["source"]
    assert {row["focal_length_mm"]: row["min_focus_mm"] for row in record["close_focus"]} == {24: 370, 70: 370}

# approximate entries of which a page confirms some figures, not all: the site named in `source`, the closest focus
# (mm at each focal length) and the maximum magnification it prints (None where it prints none), and the figure the
# entry's notes must still name as unconfirmed. The Leica DG Summilux 15mm (i-kyon1521.com: 最短撮影距離: 20cm), the
# Vario-Elmarit 12-35mm (The Phoblographer: 0.15m on the wide end and 0.25 on the longer end; nothing at 17 mm), the
# M.Zuiko 300mm (ayton.id.au: close focus of only 1.4m), the Lumix S 35mm F1.8 (the LensVisualizer analysis: 0.24 m
# in Panasonic's specification)
PARTLY_CONFIRMED = {
    "panasonic-leica-dg-summilux-15mm-f1.7": ("i-kyon1521.com", {15: 200}, None, "maximum magnification 0.1x"),
    "panasonic-leica-dg-vario-elmarit-12-35mm-f2.8": ("thephoblographer.com/2022/12/14", {12: 150, 35: 250}, None,
                                                      "the 17 mm row"),
    "om-m-zuiko-300mm-f4-is-pro": ("ayton.id.au", {300: 1400}, None, "maximum magnification 0.24x"),
    "panasonic-lumix-s-35mm-f1.8": ("PanasonicS35mmf18.analysis.md", {35: 240}, None, "maximum magnification 0.22x"),
}


@pytest.mark.parametrize(("lens_id", "page", "focus", "magnification", "open_figure"),
                         [(k, *v) for k, v in sorted(PARTLY_CONFIRMED.items())])
def test_a_partly_confirmed_entry_names_its_page_and_what_is_still_open(lens_id, page, focus, magnification,
                                                                        open_figure):
    record = record_of(RECORDS, lens_id)
    assert page in record["source"]
    rows = {r["focal_length_mm"]: r["min_focus_mm"] for r in record.get("close_focus", [])} or {
        record["focal_length_mm"]: record["min_focus_mm"]}
    for focal, distance in focus.items():
        assert rows[focal] == distance, (lens_id, focal)
    if magnification is not None:
        assert record["max_magnification"] == magnification
    assert record["approximate"] is True
    assert open_figure in " ".join(record["notes"].split()), lens_id


def test_a_figure_from_one_dataset_is_approximate_and_a_confirmed_one_is_not():
    for record in RECORDS:
        assert "isamu/lens-database" in record["source"], record["id"]
        assert bool(record.get("approximate")) == (record["id"] not in CONFIRMED), record["id"]
    for lens_id, site in CONFIRMED.items():
        # the second source beside the dataset, named in `source`
        assert site in record_of(RECORDS, lens_id)["source"], lens_id


def test_the_apo_summicron_sl_28_takes_the_pages_magnification_not_the_datasets():
    # the dataset records 0.14x; the review (and the 1:5 of the series) 0.2x, which the entry holds
    record = record_of(RECORDS, "leica-apo-summicron-sl-28mm-f2-asph")
    assert "maxMagnification 0.14" in record["source"] and "0.2x" in record["source"]
    assert record["max_magnification"] == 0.2


def test_micro_four_thirds_magnifications_are_the_actual_ratio():
    # the makers print both; the entry holds the ratio on the sensor, and its notes say the 35 mm equivalent one
    # (twice it) is not used. The 1:1 macros are the check: 1.0x, not their printed 2.0x equivalent.
    mft = [r for r in RECORDS if r["mount"] == "Micro Four Thirds"]
    assert len(mft) >= 20
    for record in mft:
        assert record["sensor"] == "four-thirds", record["id"]
        notes = " ".join(record["notes"].split())
        assert "actual reproduction ratio" in notes and "35 mm equivalent" in notes, record["id"]
        assert record["max_magnification"] <= 1.0, record["id"]
    for lens_id in ("panasonic-leica-dg-macro-elmarit-45mm-f2.8", "panasonic-lumix-g-macro-30mm-f2.8"):
        assert record_of(RECORDS, lens_id)["max_magnification"] == 1.0


@pytest.mark.parametrize("lens_id", [r["id"] for r in RECORDS])
def test_the_model_never_magnifies_more_than_the_source_says(lens_id):
    # at every published row, at both ends, and halfway between neighbouring rows
    check_never_magnifies_more(load_db().lens(lens_id))


def test_a_row_without_a_published_magnification_is_the_unit_focusing_one_below_the_maximum():
    # the Lumix G 14-140mm II at 14 mm: 0.3 m, no magnification placed there; a thin 14 mm lens focused as a unit
    # at 0.3 m from the sensor (D = f (2 + m + 1/m), the root below 1), well under the 0.25x of the lens
    lens = load_db().lens("panasonic-lumix-g-vario-14-140mm-f3.5-5.6-ii")
    k = 300.0 / 14.0 - 2.0
    unit = (k - math.sqrt(k * k - 4.0)) / 2.0
    assert unit < 0.25
    assert internal_focus_at_distance(focus_model(lens, 14.0), 300.0)[0] == pytest.approx(unit, rel=1e-6)


def test_a_zoom_with_published_magnifications_at_each_row_meets_them():
    # the S 24-60mm F2.8: 0.25x at 24 mm and 0.3x at 30 mm (0.19 m), 0.22x at 60 mm (0.33 m)
    lens = load_db().lens("panasonic-lumix-s-24-60mm-f2.8")
    for focal, distance, published in ((24.0, 190.0, 0.25), (30.0, 190.0, 0.3), (60.0, 330.0, 0.22)):
        m, _ = internal_focus_at_distance(focus_model(lens, focal), distance)
        assert m == pytest.approx(published, rel=1e-6)


def test_dof_refuses_closer_than_the_published_closest_focus():
    (row,) = run_json("dof", "--lens", "panasonic-leica-dg-nocticron-42.5mm-f1.2", "-N", "1.2", "-s", "0.6m")
    assert row["near_mm"] < 600.0 < row["far_mm"]
    result = run("dof", "--lens", "panasonic-leica-dg-nocticron-42.5mm-f1.2", "-N", "1.2", "-s", "0.4m")
    assert result.exit_code == 2
    assert "0.5 m" in result.output


def test_the_25_50mm_places_no_magnification_at_its_long_end_since_unit_focusing_would_exceed_it():
    # Panasonic's table puts 0.21x at 50 mm and 0.31 m; a 50 mm lens focused as a unit at 0.31 m from the sensor
    # (D = f (2 + m + 1/m), the root below 1) would reach about 0.25x, more than the published maximum, so the lens
    # focuses internally and the row carries no magnification: the model is capped at 0.21x there.
    k = 310.0 / 50.0 - 2.0
    unit = (k - math.sqrt(k * k - 4.0)) / 2.0
    assert unit == pytest.approx(0.2534, abs=5e-4) and unit > 0.21
    record = record_of(RECORDS, "panasonic-leica-dg-vario-summilux-25-50mm-f1.7")
    assert all("max_magnification" not in row for row in record["close_focus"])
    lens = load_db().lens("panasonic-leica-dg-vario-summilux-25-50mm-f1.7")
    m, _ = internal_focus_at_distance(focus_model(lens, 50.0), 310.0)
    assert m == pytest.approx(0.21, rel=1e-6)
