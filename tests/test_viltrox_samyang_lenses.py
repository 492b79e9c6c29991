"""lens_db/viltrox-samyang-lenses.yaml: each entry's figures against the sources its `source` quotes (the makers'
pages as transcribed in isamu/lens-database, the makers' marketed figures as quoted by the lens-design files of
ronbuening/LensVisualizer, and the pages that confirm another figure), its mounts and sensor, and the magnification
the focusing model derives at the closest focus against the published maximum (or, where none is published, against
unit focusing)."""

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

ISAMU_VILTROX = ("isamu/lens-database build/data/viltrox/", "026e8e7191685e660b235de3e5d25b0dc4f6eb7d")
ISAMU_SAMYANG = ("isamu/lens-database build/data/samyang/index.js", "67690d148d423e7b6e292528854fbaa3f226903a")
LV = "ronbuening/LensVisualizer src/lens-data/"

# (lens, focal length mm, closest focus mm, magnification or None, (widest, smallest f-number or None), largest
# magnification the sources give or None): the entry's own figures, each from the tables below
CITED = [
    ("viltrox-af-16mm-f1.8-fe", 16, 270, 0.13, (1.8, None), 0.13),
    ("viltrox-af-20mm-f2.8-fe", 20, 190, None, (2.8, None), None),
    ("viltrox-af-24mm-f1.8-fe", 24, 280, None, (1.8, None), None),
    ("viltrox-af-28mm-f4.5-fe", 28, 350, None, (4.5, 4.5), None),  # fixed aperture (Rusty Ruin)
    ("viltrox-af-40mm-f2.5-fe", 40, 350, None, (2.5, None), None),
    ("viltrox-af-50mm-f1.8-fe", 50, 500, None, (1.8, None), None),
    ("viltrox-af-85mm-f1.4-fe", 85, 800, None, (1.4, None), None),
    ("viltrox-af-85mm-f1.8-ii", 85, 800, None, (1.8, None), None),
    ("viltrox-af-135mm-f1.8-lab", 135, 720, None, (1.8, None), None),
    ("viltrox-af-35mm-f1.8-fe", 35, 400, None, (1.8, None), None),
    ("viltrox-af-14mm-f4-air", 14, 130, None, (4, None), None),
    ("viltrox-af-13mm-f1.4", 13, 200, None, (1.4, None), None),
    ("viltrox-af-23mm-f1.4", 23, 300, None, (1.4, None), None),
    ("viltrox-af-25mm-f1.7-air", 25, 290, None, (1.7, None), None),
    ("viltrox-af-27mm-f1.2-pro", 27, 280, 0.15, (1.2, None), 0.15),  # the analysis quoting Viltrox
    ("viltrox-af-33mm-f1.4", 33, 400, None, (1.4, None), None),
    ("viltrox-af-56mm-f1.4", 56, 600, 0.1, (1.4, None), 0.1),  # the analysis quoting Viltrox
    ("viltrox-af-56mm-f1.7-air", 56, 550, None, (1.7, None), None),
    ("viltrox-af-75mm-f1.2-pro", 75, 880, None, (1.2, None), None),
    ("samyang-af-14mm-f2.8-fe", 14, 200, None, (2.8, None), None),
    ("samyang-af-18mm-f2.8-fe", 18, 250, None, (2.8, None), None),
    ("samyang-af-24mm-f1.8-fe", 24, 190, 0.21, (1.8, None), 0.21),  # the maker's 0.21x, not the dataset's 0.15x
    ("samyang-af-24mm-f2.8-fe", 24, 240, 0.13, (2.8, None), 0.13),  # the analysis quoting Samyang
    ("samyang-af-35mm-f2.8-fe", 35, 350, 0.12, (2.8, None), 0.12),
    ("samyang-af-35mm-f1.4-fe-ii", 35, 280, None, (1.4, None), None),
    ("samyang-af-35mm-f1.8-fe", 35, 290, None, (1.8, None), None),
    ("samyang-af-45mm-f1.8-fe", 45, 450, None, (1.8, None), None),
    ("samyang-af-50mm-f1.4-fe-ii", 50, 400, None, (1.4, None), None),
    ("samyang-af-75mm-f1.8-fe", 75, 690, None, (1.8, None), None),
    ("samyang-af-85mm-f1.4-fe-ii", 85, 850, None, (1.4, None), None),
    ("samyang-af-135mm-f1.8-fe", 135, 690, None, (1.8, None), None),
    ("samyang-af-12mm-f2-e", 12, 200, None, (2, None), None),
]

# isamu/lens-database, as its records print them: minFocusDistance (m), maxMagnification where given, and the
# maker's page the record names (Viltrox: its store page of the lens; Samyang: the store front only)
DATASET = {
    "viltrox-af-16mm-f1.8-fe": (0.27, 0.13, "viltrox-af-16mm-f1-8"),
    "viltrox-af-20mm-f2.8-fe": (0.19, None, "viltrox-af-20mm-f2-8"),
    "viltrox-af-24mm-f1.8-fe": (0.28, None, "viltrox-af-24mm-f1-8"),
    "viltrox-af-28mm-f4.5-fe": (0.35, None, "viltrox-af-28mm-f4-5"),
    "viltrox-af-40mm-f2.5-fe": (0.35, None, "viltrox-af-40mm-f2-5"),
    "viltrox-af-50mm-f1.8-fe": (0.5, None, "viltrox-af-50mm-f1-8"),
    "viltrox-af-85mm-f1.4-fe": (0.8, None, "viltrox-af-85mm-f1-4"),
    "viltrox-af-85mm-f1.8-ii": (0.8, None, "viltrox-af-85mm-f1-8-ii"),
    "viltrox-af-135mm-f1.8-lab": (0.72, None, "viltrox-af-135mm-f1-8-lab"),
    "viltrox-af-13mm-f1.4": (0.2, None, "viltrox-af-13mm-f1-4"),
    "viltrox-af-23mm-f1.4": (0.3, None, "viltrox-af-23mm-f1-4"),
    "viltrox-af-25mm-f1.7-air": (0.29, None, "viltrox-af-25mm-f1-7-air"),
    "viltrox-af-27mm-f1.2-pro": (0.28, None, "viltrox-af-27mm-f1-2-pro"),
    "viltrox-af-33mm-f1.4": (0.4, None, "viltrox-af-33mm-f1-4"),
    "viltrox-af-56mm-f1.4": (0.55, None, "viltrox-af-56mm-f1-4"),
    "viltrox-af-56mm-f1.7-air": (0.55, None, "viltrox-af-56mm-f1-7-air"),
    "viltrox-af-75mm-f1.2-pro": (0.7, None, "viltrox-af-75mm-f1-2-pro"),
    "samyang-af-14mm-f2.8-fe": (0.2, None, None),
    "samyang-af-18mm-f2.8-fe": (0.25, None, None),
    "samyang-af-24mm-f1.8-fe": (0.19, 0.15, None),
    "samyang-af-24mm-f2.8-fe": (0.24, None, None),
    "samyang-af-35mm-f1.4-fe-ii": (0.28, None, None),
    "samyang-af-35mm-f1.8-fe": (0.29, None, None),
    "samyang-af-45mm-f1.8-fe": (0.45, None, None),
    "samyang-af-50mm-f1.4-fe-ii": (0.4, None, None),
    "samyang-af-75mm-f1.8-fe": (0.69, None, None),
    "samyang-af-85mm-f1.4-fe-ii": (0.85, None, None),
    "samyang-af-135mm-f1.8-fe": (0.69, None, None),
    "samyang-af-12mm-f2-e": (0.2, None, None),
}

# ronbuening/LensVisualizer: (file, closeFocusM, the maker's marketed closest focus its header or metadata quotes,
# in m, or None where it quotes only a patent's focus state)
DESIGN_FILES = {
    "viltrox-af-50mm-f1.8-fe": ("viltrox/ViltroxAF50mmf18FE.data.ts", 0.5, None),  # not asserted as production
    "viltrox-af-35mm-f1.8-fe": ("viltrox/ViltroxAF35mmf18FE.data.ts", 0.3, 0.4),  # 'marketed ... 0.4 m'
    "viltrox-af-14mm-f4-air": ("viltrox/ViltroxAF14mmf4Air.data.ts", 0.13, 0.13),  # 'Viltrox's marketed 0.13 m'
    "viltrox-af-27mm-f1.2-pro": ("viltrox/ViltroxAF27mmf12XF.data.ts", 0.28, 0.28),  # 'Viltrox's 0.28 m'
    "viltrox-af-33mm-f1.4": ("viltrox/ViltroxAF33mmf14E.data.ts", 0.4, None),  # the patent's 0.4 m state
    "viltrox-af-56mm-f1.4": ("viltrox/ViltroxAF56mmf14E.data.ts", 0.63, 0.6),  # 'markets ... at 0.6 m MFD'
    "viltrox-af-75mm-f1.2-pro": ("viltrox/ViltroxAF75mmf12STMEDIF.data.ts", 0.88, 0.88),  # 'production 0.88 m'
    "samyang-af-14mm-f2.8-fe": ("samyang/SamyangAF14mmf28FE.data.ts", 0.2, None),  # TL=0.2 m state
    "samyang-af-18mm-f2.8-fe": ("samyang/SamyangAF18mmf28.data.ts", 0.25, None),  # 'to 0.25 m'
    "samyang-af-24mm-f1.8-fe": ("samyang/SamyangAF24mmf18FE.data.ts", 0.19, 0.19),  # 'production endpoint'
    "samyang-af-24mm-f2.8-fe": ("samyang/SamyangAF24mmf28FE.data.ts", 0.24, 0.24),  # 'Production MFD'
    "samyang-af-35mm-f2.8-fe": ("samyang/SamyangAF35mmf28FE.data.ts", 0.35, 0.35),  # 'publishes ... 0.35 m MFD'
}
# a maximum magnification a lens-design file quotes from the maker: Samyang AF 35mm F2.8 FE, '0.12x'
DESIGN_MAGNIFICATION = {"samyang-af-35mm-f2.8-fe": 0.12}
# a maximum magnification a design analysis quotes from the maker where the dataset gives another: (file, commit,
# the words it prints, the figure entered)
ANALYSIS_MAGNIFICATION = {
    "samyang-af-24mm-f1.8-fe": ("samyang/SamyangAF24mmf18FE.analysis.md", "5bf4fdb3169356d8292cc0f63d9196eda27e21ef",
                                "near the manufacturer's rounded 0.21× maximum magnification", 0.21),
}

# a maximum magnification no dataset gives, quoted by a design analysis as the maker's: (file, commit, the words it
# prints, the figure entered)
ANALYSIS_QUOTED = {
    "viltrox-af-27mm-f1.2-pro": ("viltrox/ViltroxAF27mmf12XF.analysis.md", "56c99ef6bf15cc3a3f49902ac4a9b6142b46ed7c",
                                 "Viltrox's 0.28 m minimum shooting distance and 0.15× maximum magnification", 0.15),
    "viltrox-af-56mm-f1.4": ("viltrox/ViltroxAF56mmf14E.analysis.md", "56c99ef6bf15cc3a3f49902ac4a9b6142b46ed7c",
                             "Viltrox markets the production lens with a 0.6 m minimum focus distance and 0.1× maximum "
                             "magnification", 0.1),
    "samyang-af-24mm-f2.8-fe": ("samyang/SamyangAF24mmf28FE.analysis.md", "8555a3ed879bb45b038d770ad922cf36f5bfa7a5",
                                "Samyang specifies a 0.24 m minimum focus distance and 0.13× maximum magnification",
                                0.13),
}

# Figures a page confirms, as it prints them: (lens, what, value, page quoted in `source`)
CONFIRMED = [
    ("viltrox-af-28mm-f4.5-fe", "f_number_max", 4.5, "rustyruin.blog/tag/viltrox"),  # always operating at f4.5
    ("viltrox-af-28mm-f4.5-fe", "mount", "Fujifilm X", "fstoppers.com/reviews/review-slimmest-fujifilm"),
    ("viltrox-af-85mm-f1.8-ii", "sensor", None, "danadams.photography"),  # the X version is a full frame lens
    ("viltrox-af-27mm-f1.2-pro", "sensor", "aps-c", "optyczne.pl/613.6"),  # a 27 mm lens for APS-C/DX
]

# (mounts, sensor) as the sources list them (isamu: one record per mount with the same figures, a record asking
# for its figures to be verified not counted; LensVisualizer: lensMounts; the pages above)
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
    "viltrox-af-35mm-f1.8-fe": ({"Sony E"}, None),
    "viltrox-af-14mm-f4-air": ({"Sony E", "Nikon Z"}, None),
    "viltrox-af-13mm-f1.4": ({"Sony E", "Fujifilm X", "Nikon Z"}, "aps-c"),
    "viltrox-af-23mm-f1.4": ({"Sony E", "Fujifilm X", "Nikon Z"}, "aps-c"),
    "viltrox-af-25mm-f1.7-air": ({"Sony E"}, "aps-c"),
    "viltrox-af-27mm-f1.2-pro": ({"Sony E", "Fujifilm X", "Nikon Z"}, "aps-c"),
    "viltrox-af-33mm-f1.4": ({"Sony E", "Fujifilm X", "Nikon Z"}, "aps-c"),
    "viltrox-af-56mm-f1.4": ({"Sony E", "Fujifilm X", "Nikon Z"}, "aps-c"),
    "viltrox-af-56mm-f1.7-air": ({"Sony E"}, "aps-c"),
    "viltrox-af-75mm-f1.2-pro": ({"Sony E", "Fujifilm X", "Nikon Z"}, "aps-c"),
    "samyang-af-14mm-f2.8-fe": ({"Sony E"}, None),
    "samyang-af-18mm-f2.8-fe": ({"Sony E"}, None),
    "samyang-af-24mm-f1.8-fe": ({"Sony E", "Nikon Z"}, None),
    "samyang-af-24mm-f2.8-fe": ({"Sony E"}, None),
    "samyang-af-35mm-f2.8-fe": ({"Sony E"}, None),
    "samyang-af-35mm-f1.4-fe-ii": ({"Sony E"}, None),
    "samyang-af-35mm-f1.8-fe": ({"Sony E"}, None),
    "samyang-af-45mm-f1.8-fe": ({"Sony E"}, None),
    "samyang-af-50mm-f1.4-fe-ii": ({"Sony E"}, None),
    "samyang-af-75mm-f1.8-fe": ({"Sony E"}, None),
    "samyang-af-85mm-f1.4-fe-ii": ({"Sony E"}, None),
    "samyang-af-135mm-f1.8-fe": ({"Sony E"}, None),
    "samyang-af-12mm-f2-e": ({"Sony E", "Fujifilm X"}, "aps-c"),
}


def source_of(record):
    return " ".join(record["source"].split())


@pytest.mark.parametrize("lens_id", sorted(ANALYSIS_QUOTED))
def test_a_design_analysis_quoting_the_makers_magnification(lens_id):
    # the magnification no dataset gives, entered as the design analysis quotes the maker's figure, and the
    # entry still approximate with the notes naming it as the one source's
    record = record_of(RECORDS, lens_id)
    path, commit, words, entered = ANALYSIS_QUOTED[lens_id]
    assert f"{LV}{path} at {commit}" in source_of(record) and words in source_of(record)
    assert f"{entered:g}× maximum magnification" in words
    assert record["max_magnification"] == entered and DATASET[lens_id][1] is None
    assert record["approximate"] is True and f"magnification ({entered:g}x)" in " ".join(record["notes"].split())


def test_every_entry_is_checked_against_its_source():
    check_every_entry_cited(RECORDS, CITED)
    ids = {r["id"] for r in RECORDS}
    assert set(MOUNTS) == ids and set(DATASET) | set(DESIGN_FILES) == ids
    assert len(RECORDS) >= 30


@pytest.mark.parametrize(("lens_id", "focal", "distance", "magnification", "apertures", "largest"), CITED,
                         ids=[f"{c[0]}@{c[1]}" for c in CITED])
def test_figures_against_the_cited_source(lens_id, focal, distance, magnification, apertures, largest):
    record = record_of(RECORDS, lens_id)
    check_cited_row(record, focal, distance, magnification, apertures, largest)
    if largest is None:
        assert "max_magnification" not in record
    # the entry's closest focus: the maker's marketed figure where a lens-design file quotes one, else the dataset's
    production = (DESIGN_FILES.get(lens_id) or (None, None, None))[2]
    expected = production if production is not None else DATASET[lens_id][0]
    assert distance == round(expected * 1000)
    # its magnification: the maker's as a design analysis quotes it where the dataset disagrees, else the
    # dataset's, or the maker's as a lens-design file quotes it
    published = ((ANALYSIS_MAGNIFICATION.get(lens_id) or ANALYSIS_QUOTED.get(lens_id) or (None,) * 4)[3]
                 or DATASET.get(lens_id, (None, None))[1] or DESIGN_MAGNIFICATION.get(lens_id))
    assert magnification == published


@pytest.mark.parametrize("lens_id", sorted(DATASET))
def test_the_dataset_is_quoted_as_it_prints_its_figures(lens_id):
    record = record_of(RECORDS, lens_id)
    source = source_of(record)
    metres, magnification, slug = DATASET[lens_id]
    focal, widest = record["focal_length_mm"], record["f_number_min"]
    repository, commit = ISAMU_VILTROX if lens_id.startswith("viltrox-") else ISAMU_SAMYANG
    assert repository in source and commit in source
    assert f"focal length {focal:g} mm, f/{widest:g}, minFocusDistance {metres:g} m" in source
    assert ("maxMagnification" in source) == (magnification is not None)
    if magnification is not None:
        assert f"maxMagnification {magnification:g}" in source
    if slug:  # Viltrox's store page of the lens, as the record names it
        assert f"transcribing the maker's specification page https://viltroxstore.com/products/{slug}:" in source
    else:  # Samyang's records name only the store front
        assert "name only the maker's store front https://www.samyanglensglobal.com/" in source
    notes = " ".join(record["notes"].split())
    if round(metres * 1000) != record["min_focus_mm"]:
        # a dataset figure the entry does not use is said in the notes, with the reason
        assert f"gives {metres:g} m" in notes or f"dataset's {metres:g} m" in notes, lens_id
        assert "not used" in notes
    if magnification is not None and magnification != record["max_magnification"]:
        assert f"dataset gives {magnification:g}x, which is not used" in notes, lens_id
        assert record["approximate"] is True


@pytest.mark.parametrize("lens_id", sorted(ANALYSIS_MAGNIFICATION))
def test_a_design_analysis_quoting_another_magnification(lens_id):
    record = record_of(RECORDS, lens_id)
    path, commit, words, entered = ANALYSIS_MAGNIFICATION[lens_id]
    assert f"{LV}{path} at {commit}" in source_of(record) and words in source_of(record)
    assert record["max_magnification"] == entered


@pytest.mark.parametrize("lens_id", sorted(DESIGN_FILES))
def test_the_lens_design_files_are_quoted_as_they_print_their_figures(lens_id):
    record = record_of(RECORDS, lens_id)
    source = source_of(record)
    path, close, production = DESIGN_FILES[lens_id]
    assert f"{LV}{path} at " in source
    assert f"closeFocusM {close:g}" in source
    if production is not None and production != close:
        assert f"{production:g} m" in source  # the marketed figure, quoted next to the patent's state
    if lens_id in DESIGN_MAGNIFICATION:
        assert f"{DESIGN_MAGNIFICATION[lens_id]:g}x maximum magnification" in source


@pytest.mark.parametrize(("lens_id", "what", "value", "page"), CONFIRMED, ids=[f"{c[0]}:{c[1]}" for c in CONFIRMED])
def test_figures_a_page_confirms(lens_id, what, value, page):
    record = record_of(RECORDS, lens_id)
    if what == "mount":
        assert value in {m.strip() for m in record["mount"].split(",")}
    else:
        assert record.get(what) == value
    assert page in source_of(record)


@pytest.mark.parametrize("lens_id", sorted(MOUNTS))
def test_mounts_and_sensor_as_the_sources_list_them(lens_id):
    record = record_of(RECORDS, lens_id)
    mounts, sensor = MOUNTS[lens_id]
    assert {m.strip() for m in record["mount"].split(",")} == mounts
    assert record.get("sensor") == sensor
    # every Viltrox mount has its own record in the dataset, or the lens-design file or a page names it
    source = source_of(record)
    files = {"Sony E": "e", "Fujifilm X": "x", "Nikon Z": "z", "Canon RF": "rf", "L-Mount": "l"}
    design = {"Sony E": "sony-fe", "Fujifilm X": "fujifilm-x", "Nikon Z": "nikon-z"}
    if lens_id.startswith("viltrox-"):
        for mount in mounts:
            assert (f"build/data/viltrox/{files[mount]}/index.js" in source
                    or (mount in design and design[mount] in source)
                    or (lens_id, "mount", mount) in {c[:3] for c in CONFIRMED}), (lens_id, mount)


def test_every_entry_is_new_names_its_mounts_and_says_why_it_is_approximate():
    check_entries_are_new(FILE, RECORDS)
    for record in RECORDS:
        assert record["mount"] and record["mount"] != "various", record["id"]
        assert record["category"] == "prime", record["id"]
        notes = " ".join(record["notes"].split())
        # no page confirms a closest focus or magnification, and a lens without a published magnification stays
        # approximate (tests/test_presets_db.py): every entry says which figure is unconfirmed and what was searched
        assert record["approximate"] is True and notes.startswith("Approximate: "), record["id"]
        first = notes.split(". ")[0]
        assert "the closest focus" in first or "magnification" in first, record["id"]
        assert "Searched the pages and docs corpora" in notes, record["id"]
        if "max_magnification" not in record:
            assert "No source read gives a maximum magnification" in notes, record["id"]
        # where the dataset and a lens-design file's quotation of the maker's closest focus agree and no
        # magnification is published, the notes say the closest focus is in both and the magnification is missing
        dataset = DATASET.get(record["id"], (None, None, None))[0]
        production = (DESIGN_FILES.get(record["id"]) or (None, None, None))[2]
        if dataset is not None and dataset == production and "max_magnification" not in record:
            assert first == "Approximate: the magnification is unconfirmed", record["id"]
            assert "in both the dataset and the lens-design file" in notes, record["id"]
        lens = load_db().lens(record["id"])
        assert lens.tier == "shipped" and lens.approximate


def test_the_approximate_count_of_this_file():
    # all 32 entries: no page read confirms a closest focus, and the two whose closest focus both sources give
    # (the Viltrox AF 27mm F1.2 Pro and the Samyang AF 24mm F2.8 FE) have no published magnification
    assert len(RECORDS) == 32 and all(record.get("approximate") for record in RECORDS)


def test_full_frame_and_aps_c_lines_are_told_apart():
    # the sources' format: the dataset's Full-Frame / APS-C, the lens-design files' imageFormat
    for record in RECORDS:
        source = source_of(record)
        aps_c = "format APS-C" in source
        if record["id"] in DATASET:
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
    # Viltrox 16mm: 0.13x at 0.27 m and Samyang 24mm F1.8: 0.21x at 0.19 m are more than unit focusing gives
    # (0.0675x, 0.174x, which the patent trace's 0.202x also exceeds), lenses focusing to a longer focal length;
    # Samyang 35mm F2.8 (0.12x at 0.35 m against 0.127x) gives less, internal focusing shortening it to about
    # 33.5 mm (tests/test_presets_consistency.py)
    assert unit_focusing(16, 270) == pytest.approx(0.06753, abs=1e-5) and unit_focusing(16, 270) < 0.13
    assert unit_focusing(24, 190) == pytest.approx(0.17414, abs=1e-5) and unit_focusing(24, 190) < 0.202 < 0.21
    assert unit_focusing(35, 350) == pytest.approx(0.12702, abs=1e-5) and unit_focusing(35, 350) > 0.12
    implied = 350 / (2 + 0.12 + 1 / 0.12)  # D = f (2 + m + 1/m)
    assert implied == pytest.approx(33.49, abs=0.01)
    for alias, focal, distance, published in (("samyang-af-24-1.8", 24.0, 190.0, 0.21),
                                              ("samyang-af-35-2.8", 35.0, 350.0, 0.12)):
        model = focus_model(load_db().lens(alias), focal)
        assert internal_focus_at_distance(model, distance)[0] == pytest.approx(published, rel=1e-6)


def test_dof_refuses_closer_than_the_published_closest_focus():
    # Viltrox AF 75mm F1.2 Pro: 0.88 m, the production figure (not the patent's 0.7 m)
    (row,) = run_json("dof", "--lens", "viltrox-75-1.2", "-N", "2", "-s", "1m")
    assert row["near_mm"] < 1000.0 < row["far_mm"]
    result = run("dof", "--lens", "viltrox-75-1.2", "-N", "2", "-s", "0.75m")
    assert result.exit_code == 2
    assert "0.88 m" in result.output


def test_a_fixed_aperture_lens_refuses_another_f_number():
    # Viltrox AF 28mm F4.5: no aperture mechanism (f/4.5 only)
    (row,) = run_json("dof", "--lens", "viltrox-28-4.5", "-N", "4.5", "-s", "2m")
    assert row["near_mm"] < 2000.0 < row["far_mm"]
    assert run("dof", "--lens", "viltrox-28-4.5", "-N", "8", "-s", "2m").exit_code == 2
