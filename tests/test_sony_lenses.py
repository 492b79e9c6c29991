"""lens_db/sony-lenses.yaml: each entry's figures against the sources its `source` quotes (Sony Japan's pages as
transcribed in isamu/lens-database, Sony Japan's lens finder in VepretskiyD/camera-lens-1-preview, and the review
pages named), which entries are confirmed and which approximate, and the magnification the focusing model derives
at the closest focus against the published maximum."""

from __future__ import annotations

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

FILE = DB / "sony-lenses.yaml"
RECORDS = lens_records(FILE)


# (lens, focal length mm, closest focus mm, magnification at that row or None, (widest, smallest f-number or
# None), largest magnification) as isamu/lens-database transcribes Sony Japan's pages (minFocusDistance in m,
# maxMagnification, and the wide/tele and AF/MF closest focus in `note`); each comment quotes the dataset
CITED = [
    # SEL14F18GM: 0.25 m, 0.1倍
    ("sony-fe-14mm-f1.8-gm", 14, 250, 0.1, (1.8, None), 0.1),
    # SEL24F28G: 0.24 m (最短撮影距離はAF時0.24m/MF時0.18m), 0.13倍
    ("sony-fe-24mm-f2.8-g", 24, 240, 0.13, (2.8, None), 0.13),
    # SEL35F14Z: 0.3 m, 0.18倍
    ("sony-fe-35mm-f1.4-za", 35, 300, 0.18, (1.4, None), 0.18),
    # SEL35F28Z: 0.35 m, 0.12倍
    ("sony-fe-35mm-f2.8-za", 35, 350, 0.12, (2.8, None), 0.12),
    # SEL40F25G: 0.28 m (AF時0.28m/MF時0.25m), 0.2倍
    ("sony-fe-40mm-f2.5-g", 40, 280, 0.2, (2.5, None), 0.2),
    # SEL50F12GM: 0.4 m, 0.17倍
    ("sony-fe-50mm-f1.2-gm", 50, 400, 0.17, (1.2, None), 0.17),
    # SEL50F14Z: 0.45 m, 0.15倍
    ("sony-fe-50mm-f1.4-za", 50, 450, 0.15, (1.4, None), 0.15),
    # SEL50F14GM: 0.41 m (AF時0.41m/MF時0.38m), 0.16倍
    ("sony-fe-50mm-f1.4-gm", 50, 410, 0.16, (1.4, None), 0.16),
    # SEL50M28: 0.16 m, 1倍 (等倍マクロ)
    ("sony-fe-50mm-f2.8-macro", 50, 160, 1, (2.8, None), 1),
    # SEL55F18Z: 0.5 m, 0.14倍
    ("sony-fe-55mm-f1.8-za", 55, 500, 0.14, (1.8, None), 0.14),
    # SEL85F14GM: 0.85 m (AF時0.85m/MF時0.8m), 0.12倍
    ("sony-fe-85mm-f1.4-gm", 85, 850, 0.12, (1.4, None), 0.12),
    # SEL85F14GM2: 0.85 m (AF時0.85m/MF時0.8m), 0.11倍
    ("sony-fe-85mm-f1.4-gm-ii", 85, 850, 0.11, (1.4, None), 0.11),
    # SEL100F28GM: 0.57 m, 0.25倍 (マクロ切り換えリング0.57m-1.0m時; 通常域0.85m-∞時は0.85m/0.14倍)
    ("sony-fe-100mm-f2.8-stf-gm-oss", 100, 570, 0.25, (2.8, None), 0.25),
    # SEL135F18GM: 0.7 m, 0.25倍
    ("sony-fe-135mm-f1.8-gm", 135, 700, 0.25, (1.8, None), 0.25),
    # SEL1224G: 0.28 m, 0.14倍
    ("sony-fe-12-24mm-f4-g", 12, 280, None, (4, None), 0.14),
    ("sony-fe-12-24mm-f4-g", 24, 280, None, (4, None), 0.14),
    # SEL1224GM: 0.28 m, 0.14倍
    ("sony-fe-12-24mm-f2.8-gm", 12, 280, None, (2.8, None), 0.14),
    ("sony-fe-12-24mm-f2.8-gm", 24, 280, None, (2.8, None), 0.14),
    # SEL1625G: 0.18 m (AF・ワイド端)/望遠端0.24m, 0.2倍
    ("sony-fe-16-25mm-f2.8-g", 16, 180, None, (2.8, None), 0.2),
    ("sony-fe-16-25mm-f2.8-g", 25, 240, None, (2.8, None), 0.2),
    # SEL1635GM2: 0.22 m, 0.32倍
    ("sony-fe-16-35mm-f2.8-gm-ii", 16, 220, None, (2.8, None), 0.32),
    ("sony-fe-16-35mm-f2.8-gm-ii", 35, 220, None, (2.8, None), 0.32),
    # SEL1635Z: 0.28 m, 0.19倍
    ("sony-fe-16-35mm-f4-za-oss", 16, 280, None, (4, None), 0.19),
    ("sony-fe-16-35mm-f4-za-oss", 35, 280, None, (4, None), 0.19),
    # SELP1635G: 0.28 m, 0.23倍; the tele row is the LensVisualizer analysis's (PZ_16_35_PER_END below), the dataset
    # giving one closest focus for the zoom
    ("sony-fe-pz-16-35mm-f4-g", 16, 280, None, (4, None), 0.23),
    ("sony-fe-pz-16-35mm-f4-g", 35, 240, None, (4, None), 0.23),
    # SEL2070G: 0.3 m (AF・ワイド端)/望遠端0.25m, 0.39倍
    ("sony-fe-20-70mm-f4-g", 20, 300, None, (4, 22), 0.39),
    ("sony-fe-20-70mm-f4-g", 70, 250, None, (4, 22), 0.39),
    # SEL2470Z: 0.4 m, 0.2倍
    ("sony-fe-24-70mm-f4-za-oss", 24, 400, None, (4, None), 0.2),
    ("sony-fe-24-70mm-f4-za-oss", 70, 400, None, (4, None), 0.2),
    # SEL2470GM: 0.38 m, 0.24倍
    ("sony-fe-24-70mm-f2.8-gm", 24, 380, None, (2.8, None), 0.24),
    ("sony-fe-24-70mm-f2.8-gm", 70, 380, None, (2.8, None), 0.24),
    # SEL24240: 0.5 m (ワイド端)/望遠端0.8m, 0.27倍
    ("sony-fe-24-240mm-f3.5-6.3-oss", 24, 500, None, (3.5, None), 0.27),
    ("sony-fe-24-240mm-f3.5-6.3-oss", 240, 800, None, (6.3, None), 0.27),
    # SEL28702: 0.3 m (ワイド端)/望遠端0.45m, 0.19倍
    ("sony-fe-28-70mm-f3.5-5.6-oss-ii", 28, 300, None, (3.5, None), 0.19),
    ("sony-fe-28-70mm-f3.5-5.6-oss-ii", 70, 450, None, (5.6, None), 0.19),
    # SELP28135G: 0.4 m (ワイド端)/望遠端0.95m, 0.15倍
    ("sony-fe-pz-28-135mm-f4-g-oss", 28, 400, None, (4, None), 0.15),
    ("sony-fe-pz-28-135mm-f4-g-oss", 135, 950, None, (4, None), 0.15),
    # SEL50150GM: 0.4 m (ワイド端)/望遠端0.74m, 0.2倍
    ("sony-fe-50-150mm-f2-gm", 50, 400, None, (2, None), 0.2),
    ("sony-fe-50-150mm-f2-gm", 150, 740, None, (2, None), 0.2),
    # SEL70200G2: 0.26 m (ワイド端)/望遠端0.42m, 0.5倍 (ズーム全域最大撮影倍率0.5倍)
    ("sony-fe-70-200mm-f4-macro-g-oss-ii", 70, 260, 0.5, (4, None), 0.5),
    ("sony-fe-70-200mm-f4-macro-g-oss-ii", 200, 420, 0.5, (4, None), 0.5),
    # SEL70200GM: 0.96 m, 0.25倍
    ("sony-fe-70-200mm-f2.8-gm-oss", 70, 960, None, (2.8, None), 0.25),
    ("sony-fe-70-200mm-f2.8-gm-oss", 200, 960, None, (2.8, None), 0.25),
    # SEL100400MC: 0.64 m (ワイド端)/望遠端1.5m, 0.25倍
    ("sony-fe-100-400mm-f4.5-gm-oss", 100, 640, None, (4.5, None), 0.25),
    ("sony-fe-100-400mm-f4.5-gm-oss", 400, 1500, None, (4.5, None), 0.25),
    # SEL400800G: 1.7 m (ワイド端)/望遠端3.5m, 0.23倍
    ("sony-fe-400-800mm-f6.3-8-g-oss", 400, 1700, None, (6.3, None), 0.23),
    ("sony-fe-400-800mm-f6.3-8-g-oss", 800, 3500, None, (8, None), 0.23),
    # SEL11F18: 0.15 m (AF時0.15m/MF時0.12m), 0.13倍
    ("sony-e-11mm-f1.8", 11, 150, 0.13, (1.8, None), 0.13),
    # SEL15F14G: 0.2 m (AF時0.2m/MF時0.17m), 0.12倍
    ("sony-e-15mm-f1.4-g", 15, 200, 0.12, (1.4, None), 0.12),
    # SEL16F28: 0.24 m, 0.078倍
    ("sony-e-16mm-f2.8", 16, 240, 0.078, (2.8, None), 0.078),
    # SEL20F28: 0.2 m, 0.12倍
    ("sony-e-20mm-f2.8", 20, 200, 0.12, (2.8, None), 0.12),
    # SEL24F18Z: 0.16 m, 0.25倍
    ("sony-e-24mm-f1.8-za", 24, 160, 0.25, (1.8, None), 0.25),
    # SEL30M35: 0.095 m, 1.0倍
    ("sony-e-30mm-f3.5-macro", 30, 95, 1, (3.5, None), 1),
    # SEL35F18: 0.3 m, 0.15倍
    ("sony-e-35mm-f1.8-oss", 35, 300, 0.15, (1.8, None), 0.15),
    # SEL50F18: 0.39 m, 0.16倍
    ("sony-e-50mm-f1.8-oss", 50, 390, 0.16, (1.8, None), 0.16),
    # SELP1020G: 0.2 m (AF時0.2m/MF時0.13m(W)-0.17m(T)), 0.14倍
    ("sony-e-pz-10-20mm-f4-g", 10, 200, None, (4, None), 0.14),
    ("sony-e-pz-10-20mm-f4-g", 20, 200, None, (4, None), 0.14),
    # SELP16502: 0.25 m (W)-0.3m (T), 0.215倍
    ("sony-e-pz-16-50mm-f3.5-5.6-oss-ii", 16, 250, None, (3.5, None), 0.215),
    ("sony-e-pz-16-50mm-f3.5-5.6-oss-ii", 50, 300, None, (5.6, None), 0.215),
    # SEL1655G: 0.33 m, 0.2倍
    ("sony-e-16-55mm-f2.8-g", 16, 330, None, (2.8, None), 0.2),
    ("sony-e-16-55mm-f2.8-g", 55, 330, None, (2.8, None), 0.2),
    # SEL1670Z: 0.35 m, 0.23倍
    ("sony-e-16-70mm-f4-za-oss", 16, 350, None, (4, None), 0.23),
    ("sony-e-16-70mm-f4-za-oss", 70, 350, None, (4, None), 0.23),
    # SELP18105G: 0.45 m (W)-0.95m (T), 0.11倍
    ("sony-e-pz-18-105mm-f4-g-oss", 18, 450, None, (4, None), 0.11),
    ("sony-e-pz-18-105mm-f4-g-oss", 105, 950, None, (4, None), 0.11),
    # SELP18110G: 0.4 m (W)-0.95m (T), 0.122倍
    ("sony-e-pz-18-110mm-f4-g-oss", 18, 400, None, (4, None), 0.122),
    ("sony-e-pz-18-110mm-f4-g-oss", 110, 950, None, (4, None), 0.122),
    # SEL18200LE: 0.5 m, 0.27倍
    ("sony-e-18-200mm-f3.5-6.3-oss-le", 18, 500, None, (3.5, None), 0.27),
    ("sony-e-18-200mm-f3.5-6.3-oss-le", 200, 500, None, (6.3, None), 0.27),
    # SELP18200: 0.3 m (W)-0.5m (T), 0.35倍
    ("sony-e-pz-18-200mm-f3.5-6.3-oss", 18, 300, None, (3.5, None), 0.35),
    ("sony-e-pz-18-200mm-f3.5-6.3-oss", 200, 500, None, (6.3, None), 0.35),
    # SEL55210: 1.0 m, 0.225倍
    ("sony-e-55-210mm-f4.5-6.3-oss", 55, 1000, None, (4.5, None), 0.225),
    ("sony-e-55-210mm-f4.5-6.3-oss", 210, 1000, None, (6.3, None), 0.225),
    # SEL70350G: 1.1 m (W)-1.5m (T), 0.23倍
    ("sony-e-70-350mm-f4.5-6.3-g-oss", 70, 1100, None, (4.5, None), 0.23),
    ("sony-e-70-350mm-f4.5-6.3-g-oss", 350, 1500, None, (6.3, None), 0.23),

]

# Sony Japan's lens finder (VepretskiyD/camera-lens-1-preview data.js at 35d61d5e):
# maximum_magnification_ratio, a second source for the magnification
LENS_FINDER = {
    "sony-fe-35mm-f1.4-za": 0.18, "sony-fe-35mm-f2.8-za": 0.12, "sony-fe-50mm-f1.4-za": 0.15,
    "sony-fe-55mm-f1.8-za": 0.14, "sony-fe-85mm-f1.4-gm": 0.12, "sony-fe-135mm-f1.8-gm": 0.25,
    # '0,14 (マクロ切り替えリング「0.85m-∞」時) 0.25（マクロ切り替えリング「0.57m-1.0m」時）'
    "sony-fe-100mm-f2.8-stf-gm-oss": 0.25,
    "sony-fe-12-24mm-f4-g": 0.14, "sony-fe-12-24mm-f2.8-gm": 0.14, "sony-fe-16-35mm-f4-za-oss": 0.19,
    "sony-fe-24-70mm-f4-za-oss": 0.2, "sony-fe-24-70mm-f2.8-gm": 0.24, "sony-fe-24-240mm-f3.5-6.3-oss": 0.27,
    "sony-fe-70-200mm-f2.8-gm-oss": 0.25,
    "sony-e-16mm-f2.8": 0.078, "sony-e-20mm-f2.8": 0.12, "sony-e-24mm-f1.8-za": 0.25, "sony-e-30mm-f3.5-macro": 1,
    "sony-e-35mm-f1.8-oss": 0.15, "sony-e-50mm-f1.8-oss": 0.16, "sony-e-16-55mm-f2.8-g": 0.2,
    "sony-e-16-70mm-f4-za-oss": 0.23, "sony-e-pz-18-105mm-f4-g-oss": 0.11, "sony-e-18-200mm-f3.5-6.3-oss-le": 0.27,
    "sony-e-pz-18-200mm-f3.5-6.3-oss": 0.35, "sony-e-55-210mm-f4.5-6.3-oss": 0.225, "sony-e-70-350mm-f4.5-6.3-g-oss": 0.23,
}

# Closest focus (mm, at each focal length given) printed by a page or a second source, each named in the entry's
# `source`: xov.jp (SEL50F14Z 45cm, SEL55F18Z 50cm), Le Monde de la Photo (the Zeiss 35 mm f/1,4 and f/2,8: 30 and
# 35 cm), videoaktiv.tv (16 Zentimetern), Photo Review (30 cm at 20mm, 25 cm at 70mm), the lens finder's comments
# (最短撮影距離0.2m, 約9.5cm), chatgpt4000.com (FE50mm F1.2 GM: 0.4m), Sony's support article 00020695 (the SEL16F28's
# inscription 0.24m/0.8ft), Le Monde de la Photo's test of the Zeiss E 24 mm (16 cm seulement)
CLOSEST_FOCUS_SECOND_SOURCE = {
    "sony-fe-50mm-f1.2-gm": {50: 400}, "sony-e-16mm-f2.8": {16: 240}, "sony-e-24mm-f1.8-za": {24: 160},
    "sony-fe-35mm-f1.4-za": {35: 300}, "sony-fe-35mm-f2.8-za": {35: 350},
    "sony-fe-50mm-f1.4-za": {50: 450}, "sony-fe-55mm-f1.8-za": {55: 500}, "sony-fe-50mm-f2.8-macro": {50: 160},
    "sony-fe-20-70mm-f4-g": {20: 300, 70: 250}, "sony-e-20mm-f2.8": {20: 200}, "sony-e-30mm-f3.5-macro": {30: 95},
    # the LensVisualizer analyses quoting Sony's specification (LENSVISUALIZER below)
    "sony-fe-14mm-f1.8-gm": {14: 250}, "sony-fe-24mm-f2.8-g": {24: 240}, "sony-fe-50mm-f1.4-gm": {50: 410},
    "sony-fe-85mm-f1.4-gm": {85: 850}, "sony-fe-135mm-f1.8-gm": {135: 700}, "sony-e-50mm-f1.8-oss": {50: 390},
    "sony-fe-12-24mm-f2.8-gm": {12: 280, 24: 280}, "sony-e-18-200mm-f3.5-6.3-oss-le": {18: 500, 200: 500},
    "sony-fe-85mm-f1.4-gm-ii": {85: 850}, "sony-fe-16-35mm-f2.8-gm-ii": {16: 220, 35: 220},
    "sony-fe-16-35mm-f4-za-oss": {16: 280, 35: 280}, "sony-e-16-70mm-f4-za-oss": {16: 350, 70: 350},
}

# ronbuening/LensVisualizer's lens-design analyses (src/lens-data/sony/<file>.analysis.md at the commit named), each
# quoting Sony's published closest focus (m) and, where it does, the maximum magnification: a second source beside
# isamu/lens-database, cited with path and commit in the entry's `source`
LENSVISUALIZER = [
    # "Sony's published production specification gives ... 0.25 m minimum focus distance"
    ("sony-fe-14mm-f1.8-gm", "SonyFE14mmf18GM", "45552be52c68deb88cff1e9ec110386ab6d3ab74", 0.25, None),
    # "Sony publishes 0.18 m minimum focus in MF and 0.24 m in AF"
    ("sony-fe-24mm-f2.8-g", "SonyFE24mmf28G", "3c4ecfc621e6b970cc04c94da5780c643a291de5", 0.24, None),
    # "Sony specifies 0.41 m minimum focus in AF and 0.38 m in MF"
    ("sony-fe-50mm-f1.4-gm", "SonyFE50mmF14GM", "1d8ae14ed1cb6ac0468d66e414d2946531932533", 0.41, None),
    # "Sony specifies AF minimum focus 0.85 m, MF minimum focus 0.8 m, and 0.12x maximum magnification"
    ("sony-fe-85mm-f1.4-gm", "SonyFE85mmF14GM", "84b8ea6e6e4f24ef0b12b62a9179dd405d7e9672", 0.85, 0.12),
    # "Sony's 0.7 m (0.25x magnification) specification"
    ("sony-fe-135mm-f1.8-gm", "SonyFE135mmf18GM", "02d22c22869e50fe8cf3482ebd141e3811d1d1f1", 0.7, 0.25),
    # "Sony markets 0.39 m minimum focus and 0.16x maximum magnification"
    ("sony-e-50mm-f1.8-oss", "SonyE50mmf18OSS", "59eef61956e8cfe28ef3ec6173443801ef439ce1", 0.39, 0.16),
    # "Sony's 0.28 m minimum focus distance" (one figure for the zoom)
    ("sony-fe-12-24mm-f2.8-gm", "SonyFE1224mmf28GM", "23631dc0f77a149cf14f8fa62ff66779dfe16b65", 0.28, None),
    # "Sony specifies a 0.5 m minimum focus distance for SEL18200LE" ... "Sony specifies 0.27x maximum magnification"
    ("sony-e-18-200mm-f3.5-6.3-oss-le", "SonyE18200mmf3563OSSLE", "59eef61956e8cfe28ef3ec6173443801ef439ce1", 0.5, 0.27),
    # "consistent with Sony's published MFD of 0.85 m (AF) / 0.80 m (MF)"
    ("sony-fe-85mm-f1.4-gm-ii", "SonyFE85mmf14GMII", "28fd36e77e69a1ce097fece706d3a32aa98a7b0c", 0.85, None),
    # "Sony's production specification gives a shorter minimum focus distance of 0.22 m and a maximum magnification
    # of 0.32x" (one figure for the zoom)
    ("sony-fe-16-35mm-f2.8-gm-ii", "SonyFE1635mmf28GMII", "6bacd763baa1b4acedb0fdc5a2b506a137382f94", 0.22, 0.32),
    # "Sony specifies a 0.28 m minimum focus distance for the SEL1635Z", "Sony's rounded 0.19x production
    # specification"
    ("sony-fe-16-35mm-f4-za-oss", "SonyVarioTessarTFE1635mmf4ZAOSS", "3e2008a7bdba6b24289ce618b2e7f823d228261c",
     0.28, 0.19),
    # "Sony's published 0.35 m minimum focus distance", "Sony's rounded 0.23x maximum magnification specification"
    ("sony-e-16-70mm-f4-za-oss", "SonyVarioTessarTE1670mmf4ZAOSS", "3e2008a7bdba6b24289ce618b2e7f823d228261c",
     0.35, 0.23),
]

# The FE PZ 16-35mm F4 G: "minimum focusing distances of 0.28 m at the wide end and 0.24 m at the tele end"
# (ronbuening/LensVisualizer src/lens-data/sony/SonyFEPZ1635mmf4G.analysis.md at 22b7f670), where isamu/lens-database
# gives one figure, 0.28 m, for the zoom: the maker's per-end figures as the analysis quotes them
PZ_16_35_PER_END = {16: 280, 35: 240}
# ... and the one quoting Sony's magnification but its closest focus only as "a minimum-focus range of approximately
# 0.40-0.74 m" (not entered as a confirmation: the ends are not named)
LENSVISUALIZER_MAGNIFICATION = [
    ("sony-fe-50-150mm-f2-gm", "SonyFE50150mmF2GM", "3edd4b23f7b60dab6337ec09c0fabf6494f9c989", 0.2),
]
# ... and those quoting Sony's closest focus only as a range whose ends they do not name (cited, not entered as a
# confirmation): "the production lens's marketed 0.26-0.42 m minimum-focus range", "marketed 1.7-3.5 m minimum-focus
# range"; the range's ends are the dataset's wide and tele rows
LENSVISUALIZER_RANGE = [
    ("sony-fe-70-200mm-f4-macro-g-oss-ii", "SonyFE70200mmF4MacroGOSSII", "08e986f74ec525096a384a1b58f074bb1c1bde22",
     (260, 420)),
    ("sony-fe-400-800mm-f6.3-8-g-oss", "SonyFE400800mmF638GOSS", "08e986f74ec525096a384a1b58f074bb1c1bde22",
     (1700, 3500)),
]
# A magnification a page prints: photonique.org, 0.5x across the entire zoom range; ino.lomo.jp, SEL2070G 0.39倍;
# chatgpt4000.com, FE50mm F1.2 GM 0.17倍; Focus Numérique, FE 50 mm f/2,8 Macro: le rapport macro 1:1
MAGNIFICATION_SECOND_SOURCE = {"sony-fe-70-200mm-f4-macro-g-oss-ii": 0.5, "sony-fe-20-70mm-f4-g": 0.39,
                               "sony-fe-50mm-f1.2-gm": 0.17, "sony-fe-50mm-f2.8-macro": 1,
                               # the LensVisualizer analysis (LENSVISUALIZER below)
                               "sony-fe-50-150mm-f2-gm": 0.2, "sony-fe-16-35mm-f2.8-gm-ii": 0.32}

# Sony's manual-focus closest focus (mm), closer than the autofocus one the entry keeps (isamu's notes: MF時)
MANUAL_FOCUS = {
    "sony-fe-24mm-f2.8-g": 180, "sony-fe-40mm-f2.5-g": 250, "sony-fe-50mm-f1.4-gm": 380, "sony-fe-85mm-f1.4-gm": 800,
    "sony-fe-85mm-f1.4-gm-ii": 800, "sony-e-11mm-f1.8": 120, "sony-e-15mm-f1.4-g": 170, "sony-e-pz-10-20mm-f4-g": 130,
}


def test_every_entry_is_checked_against_its_sources():
    check_every_entry_cited(RECORDS, CITED)
    assert len(RECORDS) >= 30


@pytest.mark.parametrize(("lens_id", "focal", "distance", "magnification", "apertures", "largest"), CITED,
                         ids=[f"{c[0]}@{c[1]}" for c in CITED])
def test_figures_against_the_cited_dataset(lens_id, focal, distance, magnification, apertures, largest):
    record = record_of(RECORDS, lens_id)
    check_cited_row(record, focal, distance, magnification, apertures, largest)
    assert record["mount"] == "Sony E"


@pytest.mark.parametrize(("lens_id", "magnification"), sorted(LENS_FINDER.items()))
def test_magnification_against_sonys_lens_finder(lens_id, magnification):
    record = record_of(RECORDS, lens_id)
    assert record["max_magnification"] == pytest.approx(magnification, abs=0.0006)
    assert "maximum_magnification_ratio" in record["source"]


def test_second_sources_agree_and_only_doubly_sourced_entries_are_confirmed():
    for record in RECORDS:
        lens_id = record["id"]
        rows = record.get("close_focus") or [{"focal_length_mm": record["focal_length_mm"],
                                              "min_focus_mm": record["min_focus_mm"]}]
        focus = CLOSEST_FOCUS_SECOND_SOURCE.get(lens_id)
        if focus is not None:
            assert {r["focal_length_mm"]: r["min_focus_mm"] for r in rows} == focus, lens_id
        if lens_id in MAGNIFICATION_SECOND_SOURCE:
            assert record["max_magnification"] == MAGNIFICATION_SECOND_SOURCE[lens_id]
        confirmed = focus is not None and (lens_id in LENS_FINDER or lens_id in MAGNIFICATION_SECOND_SOURCE)
        assert record.get("approximate", False) is not confirmed, lens_id
        if not confirmed:
            assert "from one dataset only" in " ".join(record["notes"].split()), lens_id


# the page each second closest-focus figure above is quoted from, named in the entry's `source`
SECOND_SOURCE_PAGE = {"sony-e-16mm-f2.8": "sony.com/electronics/support/articles/00020695",
                      "sony-e-24mm-f1.8-za": "lemondedelaphoto.com/Prise-en-mains,6217.html",
                      "sony-fe-50mm-f1.2-gm": "chatgpt4000.com", "sony-fe-50mm-f2.8-macro": "videoaktiv.tv"}
# ... and each second magnification's page
SECOND_MAGNIFICATION_PAGE = {"sony-fe-50mm-f2.8-macro": "focus-numerique.com/test-3656",
                             "sony-fe-50mm-f1.2-gm": "chatgpt4000.com"}


@pytest.mark.parametrize(("lens_id", "page"), sorted(SECOND_SOURCE_PAGE.items()) + sorted(SECOND_MAGNIFICATION_PAGE.items()))
def test_the_second_source_is_named(lens_id, page):
    assert page in record_of(RECORDS, lens_id)["source"]


@pytest.mark.parametrize(("lens_id", "stem", "commit", "closest_m", "magnification"), LENSVISUALIZER,
                         ids=[row[0] for row in LENSVISUALIZER])
def test_figures_against_the_lensvisualizer_analyses(lens_id, stem, commit, closest_m, magnification):
    check_against_analysis(record_of(RECORDS, lens_id), closest_m, magnification,
                           f"ronbuening/LensVisualizer src/lens-data/sony/{stem}.analysis.md at {commit}")


def test_pz_16_35_takes_the_per_end_closest_focus_the_analysis_quotes():
    record = record_of(RECORDS, "sony-fe-pz-16-35mm-f4-g")
    assert {row["focal_length_mm"]: row["min_focus_mm"] for row in record["close_focus"]} == PZ_16_35_PER_END
    assert record["min_focus_mm"] == min(PZ_16_35_PER_END.values())
    source = " ".join(record["source"].split())
    assert ("ronbuening/LensVisualizer src/lens-data/sony/SonyFEPZ1635mmf4G.analysis.md at "
            "22b7f67002e217f655ab832364e47f6b6c715e63") in source
    assert "0.28 m, 0.23倍" in source  # the dataset's one figure, kept in the citation
    assert record["approximate"] is True and "0.24 m at the tele end" in " ".join(record["notes"].split())


@pytest.mark.parametrize(("lens_id", "stem", "commit", "magnification"), LENSVISUALIZER_MAGNIFICATION,
                         ids=[row[0] for row in LENSVISUALIZER_MAGNIFICATION])
def test_magnification_against_the_lensvisualizer_analyses(lens_id, stem, commit, magnification):
    record = record_of(RECORDS, lens_id)
    assert record["max_magnification"] == pytest.approx(magnification, abs=0.0006)
    assert record.get("approximate") is True
    source = " ".join(record["source"].split())
    assert f"ronbuening/LensVisualizer src/lens-data/sony/{stem}.analysis.md at {commit}" in source


@pytest.mark.parametrize(("lens_id", "stem", "commit", "ends"), LENSVISUALIZER_RANGE,
                         ids=[row[0] for row in LENSVISUALIZER_RANGE])
def test_a_closest_focus_range_from_the_analyses_matches_the_datasets_ends(lens_id, stem, commit, ends):
    record = record_of(RECORDS, lens_id)
    rows = record["close_focus"]
    assert (rows[0]["min_focus_mm"], rows[-1]["min_focus_mm"]) == ends
    source = " ".join(record["source"].split())
    assert f"ronbuening/LensVisualizer src/lens-data/sony/{stem}.analysis.md at {commit}" in source
    assert f"{ends[0] / 1000:g}-{ends[1] / 1000:g} m" in source
    # still approximate: the range does not say which end is which
    assert record["approximate"] is True and "without naming the ends" in " ".join(record["notes"].split())


@pytest.mark.parametrize(("lens_id", "manual"), sorted(MANUAL_FOCUS.items()))
def test_the_closest_focus_is_the_autofocus_figure(lens_id, manual):
    record = record_of(RECORDS, lens_id)
    assert record["min_focus_mm"] > manual
    assert "autofocus figure" in " ".join(record["notes"].split())


def test_aps_c_lenses_name_their_format():
    for record in RECORDS:
        assert (record.get("sensor") == "aps-c") is record["name"].startswith(("Sony E ", "Sony Sonnar T* E ",
                                                                               "Sony Vario-Tessar T* E ")), record["id"]


def test_every_entry_is_new_and_sonys_own():
    check_entries_are_new(FILE, RECORDS)
    for record in RECORDS:
        assert record["id"].startswith("sony-") and record["name"].startswith("Sony "), record["id"]
        assert record["max_magnification"] and record["min_focus_mm"], record["id"]
        assert "approximate" not in record or record["notes"], record["id"]


@pytest.mark.parametrize("lens_id", [r["id"] for r in RECORDS])
def test_the_model_never_magnifies_more_than_the_source_says(lens_id):
    # at every published row, at both ends, and halfway between neighbouring rows
    check_never_magnifies_more(load_db().lens(lens_id))


def test_half_macro_zoom_reaches_its_published_half_life_size_at_both_ends():
    # Sony: 0.5x over the whole range, at 0.26 m (70 mm) and 0.42 m (200 mm)
    lens = load_db().lens("sony-fe-70-200mm-f4-macro-g-oss-ii")
    for focal, distance in ((70.0, 260.0), (200.0, 420.0)):
        assert internal_focus_at_distance(focus_model(lens, focal), distance)[0] == pytest.approx(0.5, rel=1e-6)


def test_dof_refuses_closer_than_the_published_closest_focus():
    (row,) = run_json("dof", "--lens", "sony-fe-20-70mm-f4-g", "-f", "70", "-N", "4", "-s", "0.3m")
    assert row["near_mm"] < 300.0 < row["far_mm"]
    result = run("dof", "--lens", "sony-fe-20-70mm-f4-g", "-f", "20", "-N", "4", "-s", "0.27m")
    assert result.exit_code == 2
    assert "at least 300 mm" in result.output
    result = run("dof", "--lens", "sony-fe-20-70mm-f4-g", "-f", "35", "-N", "32", "-s", "1m")
    assert result.exit_code == 2
