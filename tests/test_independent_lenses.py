"""lens_db/independent-lenses.yaml: each entry's figures against the sources its `source` quotes (the makers' pages as
transcribed in isamu/lens-database, and the second sources that confirm some of them), its mounts and sensor, and the
magnification the focusing model derives at the closest focus against the published maximum."""

from __future__ import annotations

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
    name_key,
    record_of,
    taken_elsewhere,
)

from camtool.geometry.closeup import internal_focus_at_distance
from camtool.presets import load_db
from camtool.presets.focusing import focus_model

FILE = DB / "independent-lenses.yaml"
RECORDS = lens_records(FILE)

# (lens, focal length mm, closest focus mm, magnification at that row or None, (widest, smallest f-number or None),
# largest magnification the source gives for the lens), as isamu/lens-database prints them: minFocusDistance (m),
# maxMagnification, fStop, and for Tamron's zooms the note 最短撮影距離はワイド端X m/テレ端Y m (closest focus at
# the wide / tele end); a zoom row's magnification only where a source places it at that focal length.
CITED = [
    # build/data/sigma/e/index.js: full-frame primes
    ("sigma-14mm-f1.4-dg-dn-art", 14, 300, 0.084, (1.4, None), 0.084),  # 0.3, 0.084
    ("sigma-20mm-f1.4-dg-dn-art", 20, 230, 0.164, (1.4, None), 0.164),  # 0.23, 0.164
    ("sigma-24mm-f1.4-dg-dn-art", 24, 250, 0.141, (1.4, None), 0.141),  # 0.25, 0.141
    ("sigma-35mm-f1.4-dg-dn-art", 35, 300, 0.185, (1.4, None), 0.185),  # 0.3, 0.185
    ("sigma-35mm-f1.4-dg-ii-art", 35, 280, 0.185, (1.4, None), 0.185),  # 0.28, 0.185
    ("sigma-35mm-f1.2-dg-ii-art", 35, 280, 0.189, (1.2, 16), 0.189),  # 0.28, 0.189 (LensVisualizer: F16)
    ("sigma-50mm-f1.4-dg-dn-art", 50, 450, 0.147, (1.4, None), 0.147),  # 0.45, 0.147
    ("sigma-85mm-f1.4-dg-dn-art", 85, 850, 0.119, (1.4, None), 0.119),  # 0.85, 0.119
    ("sigma-135mm-f1.4-dg-art", 135, 1100, 0.145, (1.4, None), 0.145),  # 1.1, 0.145
    ("sigma-200mm-f2-dg-os-sports", 200, 1700, 0.132, (2, None), 0.132),  # 1.7, 0.132
    ("sigma-500mm-f5.6-dg-dn-os-sports", 500, 3200, 0.167, (5.6, None), 0.167),  # 3.2, 0.167
    ("sigma-17mm-f4-dg-dn-contemporary", 17, 120, 0.278, (4, None), 0.278),  # 0.12, 0.278
    ("sigma-20mm-f2-dg-dn-contemporary", 20, 220, 0.149, (2, None), 0.149),  # 0.22, 0.149
    ("sigma-24mm-f2-dg-dn-contemporary", 24, 245, 0.149, (2, None), 0.149),  # 0.245, 0.149
    ("sigma-24mm-f3.5-dg-dn-contemporary", 24, 108, 0.5, (3.5, None), 0.5),  # 0.108, 0.5
    ("sigma-35mm-f2-dg-dn-contemporary", 35, 270, 0.175, (2, None), 0.175),  # 0.27, 0.175
    ("sigma-45mm-f2.8-dg-dn-contemporary", 45, 240, 0.25, (2.8, 22), 0.25),  # 0.24, 0.25 (LensVisualizer: F22)
    ("sigma-50mm-f2-dg-dn-contemporary", 50, 450, 0.145, (2, None), 0.145),  # 0.45, 0.145
    ("sigma-65mm-f2-dg-dn-contemporary", 65, 550, 0.147, (2, None), 0.147),  # 0.55, 0.147
    ("sigma-90mm-f2.8-dg-dn-contemporary", 90, 500, 0.2, (2.8, None), 0.2),  # 0.5, 0.2
    # build/data/sigma/{e,x,rf,z}/index.js: APS-C primes, the same figures for every mount
    ("sigma-16mm-f1.4-dc-dn-contemporary", 16, 250, 0.101, (1.4, None), 0.101),  # 0.25, 0.101
    ("sigma-23mm-f1.4-dc-dn-contemporary", 23, 250, 0.137, (1.4, None), 0.137),  # 0.25, 0.137
    ("sigma-30mm-f1.4-dc-dn-contemporary", 30, 300, 0.143, (1.4, None), 0.143),  # 0.3, 0.143
    ("sigma-12mm-f1.4-dc-contemporary", 12, 172, 0.119, (1.4, None), 0.119),  # 0.172, 0.119
    ("sigma-15mm-f1.4-dc-contemporary", 15, 177, 0.127, (1.4, None), 0.127),  # 0.177, 0.127
    # 0.116 m, 0.25 (LensVisualizer: 0.116 m wide, 0.191 m tele); 0.28 m, 0.208 (one figure for the internal zoom;
    # LensVisualizer: 1:4.8 at 40 mm)
    ("sigma-10-18mm-f2.8-dc-dn-contemporary", 10, 116, None, (2.8, None), 0.25),
    ("sigma-10-18mm-f2.8-dc-dn-contemporary", 18, 191, None, (2.8, None), 0.25),
    ("sigma-17-40mm-f1.8-dc-art", 17, 280, None, (1.8, None), 0.208),
    ("sigma-17-40mm-f1.8-dc-art", 40, 280, 0.208, (1.8, None), 0.208),
    # build/data/tamron/mirrorless.js
    # A063: wide 0.18 m / tele 0.38 m, 0.37 (Digital Camera World: 0.18 m at the wide end, 1:2.7, f/22)
    ("tamron-28-75mm-f2.8-di-iii-vxd-g2", 28, 180, 0.37, (2.8, 22), 0.37),
    ("tamron-28-75mm-f2.8-di-iii-vxd-g2", 75, 380, None, (2.8, 22), 0.37),
    # A067: wide 0.25 m (1:2 in MF) / tele 1.5 m (Photography Life: 0.5x at the widest, 0.25x at 400mm)
    ("tamron-50-400mm-f4.5-6.3-di-iii-vc-vxd", 50, 250, 0.5, (4.5, None), 0.5),
    ("tamron-50-400mm-f4.5-6.3-di-iii-vc-vxd", 400, 1500, 0.25, (6.3, None), 0.5),
    # A069: wide 0.22 m (1:2 in MF) / tele 0.9 m (Phototrend: ouverture min f/22-f/32)
    ("tamron-50-300mm-f4.5-6.3-di-iii-vc-vxd", 50, 220, 0.5, (4.5, 22), 0.5),
    ("tamron-50-300mm-f4.5-6.3-di-iii-vc-vxd", 300, 900, 0.323, (6.3, 32), 0.5),  # 1:3.1 (LensVisualizer)
    # A074: wide 0.19 m / tele 0.99 m, 0.36
    ("tamron-28-300mm-f4-7.1-di-iii-vc-vxd", 28, 190, None, (4, None), 0.36),
    ("tamron-28-300mm-f4-7.1-di-iii-vc-vxd", 300, 990, None, (7.1, None), 0.36),
    # A064: wide 0.19 m / tele 0.3 m, 0.19
    ("tamron-16-30mm-f2.8-di-iii-vxd-g2", 16, 190, None, (2.8, None), 0.19),
    ("tamron-16-30mm-f2.8-di-iii-vxd-g2", 30, 300, None, (2.8, None), 0.19),
    # A078: wide 0.22 m / tele 0.65 m, 0.3
    ("tamron-35-100mm-f2.8-di-iii-vxd", 35, 220, None, (2.8, None), 0.3),
    ("tamron-35-100mm-f2.8-di-iii-vxd", 100, 650, None, (2.8, None), 0.3),
    # A084: wide 0.18 m / tele 0.28 m, 0.17
    ("tamron-12-20mm-f2.8", 12, 180, None, (2.8, None), 0.17),
    ("tamron-12-20mm-f2.8", 20, 280, None, (2.8, None), 0.17),
    # B070: wide 0.19 m / tele 0.39 m, 0.21
    ("tamron-17-70mm-f2.8-di-iii-a-vc-rxd", 17, 190, None, (2.8, None), 0.21),
    ("tamron-17-70mm-f2.8-di-iii-a-vc-rxd", 70, 390, None, (2.8, None), 0.21),
    # B061: wide 0.15 m / tele 0.99 m, 0.5
    ("tamron-18-300mm-f3.5-6.3-di-iii-a-vc-vxd", 18, 150, None, (3.5, None), 0.5),
    ("tamron-18-300mm-f3.5-6.3-di-iii-a-vc-vxd", 300, 990, None, (6.3, None), 0.5),
    # F072: 0.23 m, 1 (等倍マクロ)
    ("tamron-90mm-f2.8-di-iii-macro-vxd", 90, 230, 1.0, (2.8, None), 1.0),
]

# Figures a second source confirms, as it prints them: (lens, what, value, source)
CONFIRMED = [
    ("tamron-28-75mm-f2.8-di-iii-vxd-g2", "wide mm", 180, "Digital Camera World: 0.18m at the wide end"),
    ("tamron-28-75mm-f2.8-di-iii-vxd-g2", "max", 1 / 2.7, "Digital Camera World: 1:2.7"),
    ("tamron-28-75mm-f2.8-di-iii-vxd-g2", "f_number_max", 22, "Digital Camera World: minimum aperture f/22"),
    ("tamron-50-400mm-f4.5-6.3-di-iii-vc-vxd", "wide max", 0.5, "Photography Life: 0.5x at the widest"),
    ("tamron-50-400mm-f4.5-6.3-di-iii-vc-vxd", "tele max", 0.25, "Photography Life: 0.25x (1:4) at 400mm"),
    ("tamron-50-300mm-f4.5-6.3-di-iii-vc-vxd", "wide mm", 220, "LensVisualizer: Tamron's MOD 0.22 m at wide"),
    ("tamron-50-300mm-f4.5-6.3-di-iii-vc-vxd", "tele mm", 900, "LensVisualizer: 0.9 m at tele"),
    ("tamron-50-300mm-f4.5-6.3-di-iii-vc-vxd", "wide max", 0.5,
        "LensVisualizer: 'with maximum magnifications of 1:2 and 1:3.1 respectively'"),
    ("tamron-50-300mm-f4.5-6.3-di-iii-vc-vxd", "f_number_max", 22, "Phototrend: ouverture min f/22"),
    ("tamron-50-300mm-f4.5-6.3-di-iii-vc-vxd", "f_number_max_tele", 32, "Phototrend: f/32"),
    ("tamron-28-300mm-f4-7.1-di-iii-vc-vxd", "max", 0.36, "The-Digital-Picture: 0.36x maximum magnification"),
    ("tamron-18-300mm-f3.5-6.3-di-iii-a-vc-vxd", "wide mm", 150, "DPSaver: 0.15m at 18mm"),
    ("tamron-18-300mm-f3.5-6.3-di-iii-a-vc-vxd", "max", 0.5, "DPSaver: a maximum magnification of 1:2"),
    ("sigma-10-18mm-f2.8-dc-dn-contemporary", "wide mm", 116, "LensVisualizer: 0.116 m at the wide end"),
    ("sigma-10-18mm-f2.8-dc-dn-contemporary", "tele mm", 191, "LensVisualizer: 0.191 m at the telephoto end"),
    ("sigma-17-40mm-f1.8-dc-art", "wide mm", 280, "LensVisualizer: 'minimum focus distance as 0.28 m'"),
    ("sigma-17-40mm-f1.8-dc-art", "tele mm", 280, "LensVisualizer: 'minimum focus distance as 0.28 m'"),
    ("sigma-17-40mm-f1.8-dc-art", "tele max", 1 / 4.8, "LensVisualizer: 'maximum magnification as 1:4.8 at 40 mm'"),
    ("sigma-17-40mm-f1.8-dc-art", "max", 1 / 4.8, "LensVisualizer: 'maximum magnification as 1:4.8 at 40 mm'"),
    ("sigma-24mm-f1.4-dg-dn-art", "mm", 250, "LensVisualizer: 'the production minimum focusing distance of 25 cm'"),
    ("sigma-24mm-f1.4-dg-dn-art", "max", 1 / 7.1,
        "LensVisualizer: 'production specification, 1:7.1, governs the user-facing magnification value'"),
    ("sigma-35mm-f1.4-dg-dn-art", "mm", 300, "LensVisualizer: 'the production lens's published 0.30 m MFD'"),
    ("sigma-35mm-f1.2-dg-ii-art", "mm", 280, "LensVisualizer: '0.28 m minimum focus distance'"),
    ("sigma-35mm-f1.2-dg-ii-art", "max", 1 / 5.3, "LensVisualizer: '1:5.3 maximum reproduction'"),
    ("sigma-35mm-f1.2-dg-ii-art", "f_number_max", 16, "LensVisualizer: 'F16 minimum aperture'"),
    ("sigma-50mm-f1.4-dg-dn-art", "mm", 450,
        "LensVisualizer: 'a minimum focus distance of 0.45 m (1:6.8 magnification)'"),
    ("sigma-50mm-f1.4-dg-dn-art", "max", 1 / 6.8,
        "LensVisualizer: 'a minimum focus distance of 0.45 m (1:6.8 magnification)'"),
    ("sigma-135mm-f1.4-dg-art", "mm", 1100, "LensVisualizer: 'Marketed minimum focus is 1.1 m'"),
    ("sigma-24mm-f3.5-dg-dn-contemporary", "mm", 108,
        "LensVisualizer: 'Sigma specifies a 108 mm minimum focus distance'"),
    ("sigma-24mm-f3.5-dg-dn-contemporary", "max", 0.5, "LensVisualizer: 'the marketed 1:2 maximum magnification'"),
    ("sigma-45mm-f2.8-dg-dn-contemporary", "mm", 240, "LensVisualizer: '24 cm minimum focusing distance'"),
    ("sigma-45mm-f2.8-dg-dn-contemporary", "max", 0.25, "LensVisualizer: '1:4 maximum magnification'"),
    ("sigma-45mm-f2.8-dg-dn-contemporary", "f_number_max", 22, "LensVisualizer: 'minimum aperture F22'"),
    ("sigma-65mm-f2-dg-dn-contemporary", "mm", 550,
        "LensVisualizer: 'Sigma's separate 0.55 m minimum-focus specification'"),
    ("sigma-65mm-f2-dg-dn-contemporary", "max", 1 / 6.8,
        "LensVisualizer: 'the manufacturer's approximate 1:6.8 maximum reproduction ratio'"),
    ("sigma-90mm-f2.8-dg-dn-contemporary", "mm", 500, "LensVisualizer: 'the product focuses to 0.5 m at 1:5'"),
    ("sigma-90mm-f2.8-dg-dn-contemporary", "max", 0.2, "LensVisualizer: 'the product focuses to 0.5 m at 1:5'"),
    ("sigma-16mm-f1.4-dc-dn-contemporary", "mm", 250,
        "LensVisualizer: 'Sigma's published 0.25 m / 1:9.9 specification'"),
    ("sigma-16mm-f1.4-dc-dn-contemporary", "max", 1 / 9.9,
        "LensVisualizer: 'Sigma's published 0.25 m / 1:9.9 specification'"),
    ("sigma-23mm-f1.4-dc-dn-contemporary", "mm", 250,
        "LensVisualizer: 'matching Sigma's 0.25 m minimum focusing distance'"),
    ("sigma-23mm-f1.4-dc-dn-contemporary", "max", 1 / 7.3,
        "LensVisualizer: 'Sigma's published 1:7.3 maximum magnification'"),
    ("sigma-12mm-f1.4-dc-contemporary", "mm", 172, "LensVisualizer: 'The marketed minimum focus distance is 172 mm'"),
    ("sigma-12mm-f1.4-dc-contemporary", "max", 1 / 8.4, "LensVisualizer: 'maximum reproduction ratio 1:8.4'"),
    ("tamron-90mm-f2.8-di-iii-macro-vxd", "mm", 230,
        "LensVisualizer: 'The marketed minimum object distance is 0.23 m'"),
    ("tamron-90mm-f2.8-di-iii-macro-vxd", "max", 1.0, "LensVisualizer: 'maximum magnification is 1:1'"),
    ("sigma-24mm-f2-dg-dn-contemporary", "mm", 245, "LensVisualizer: marketed 245 mm minimum focus"),
    ("sigma-85mm-f1.4-dg-dn-art", "mm", 850, "LensVisualizer: 'published minimum focusing distance is 0.85 m'"),
    ("sigma-85mm-f1.4-dg-dn-art", "max", 1 / 8.4, "LensVisualizer: 'a maximum-magnification ratio of 1:8.4'"),
]

# (lens, mounts, sensor) as the sources list them (isamu: one record per mount; LensVisualizer: lensMounts)
MOUNTS = {
    "sigma-24mm-f1.4-dg-dn-art": ({"Sony E", "L-Mount"}, None),
    # LensVisualizer: the production lens's mounts (lensMounts, or the analysis quoting Sigma's page)
    "sigma-35mm-f1.2-dg-ii-art": ({"Sony E", "L-Mount"}, None),
    "sigma-85mm-f1.4-dg-dn-art": ({"Sony E", "L-Mount"}, None),
    "sigma-135mm-f1.4-dg-art": ({"Sony E", "L-Mount"}, None),
    "sigma-24mm-f3.5-dg-dn-contemporary": ({"Sony E", "L-Mount"}, None),
    "sigma-45mm-f2.8-dg-dn-contemporary": ({"Sony E", "L-Mount"}, None),
    "sigma-90mm-f2.8-dg-dn-contemporary": ({"Sony E", "L-Mount"}, None),
    "sigma-50mm-f1.4-dg-dn-art": ({"Sony E", "L-Mount"}, None),  # Macfilos: L-Mount, a Sony E version too
    "sigma-24mm-f2-dg-dn-contemporary": ({"Sony E", "L-Mount"}, None),
    "sigma-65mm-f2-dg-dn-contemporary": ({"Sony E", "L-Mount"}, None),
    "sigma-16mm-f1.4-dc-dn-contemporary": ({"Sony E", "Fujifilm X", "Canon RF", "Nikon Z"}, "aps-c"),
    "sigma-30mm-f1.4-dc-dn-contemporary": ({"Sony E", "Fujifilm X", "Canon RF", "Nikon Z"}, "aps-c"),
    "sigma-23mm-f1.4-dc-dn-contemporary": ({"Sony E", "Fujifilm X", "Canon RF", "L-Mount"}, "aps-c"),
    "sigma-12mm-f1.4-dc-contemporary": ({"Sony E", "Fujifilm X", "Canon RF"}, "aps-c"),
    "sigma-15mm-f1.4-dc-contemporary": ({"Sony E", "Fujifilm X", "Canon RF"}, "aps-c"),
    "sigma-10-18mm-f2.8-dc-dn-contemporary": ({"Sony E", "Fujifilm X", "Canon RF"}, "aps-c"),
    "sigma-17-40mm-f1.8-dc-art": ({"Sony E", "Fujifilm X", "Canon RF", "L-Mount"}, "aps-c"),
    "tamron-28-75mm-f2.8-di-iii-vxd-g2": ({"Sony E", "Nikon Z"}, None),
    "tamron-50-400mm-f4.5-6.3-di-iii-vc-vxd": ({"Sony E", "Nikon Z"}, None),
    "tamron-50-300mm-f4.5-6.3-di-iii-vc-vxd": ({"Sony E"}, None),
    "tamron-28-300mm-f4-7.1-di-iii-vc-vxd": ({"Sony E"}, None),
    "tamron-16-30mm-f2.8-di-iii-vxd-g2": ({"Sony E", "Nikon Z"}, None),
    "tamron-35-100mm-f2.8-di-iii-vxd": ({"Sony E", "Nikon Z"}, None),
    "tamron-12-20mm-f2.8": ({"Sony E", "Nikon Z"}, None),
    "tamron-17-70mm-f2.8-di-iii-a-vc-rxd": ({"Sony E", "Fujifilm X", "Nikon Z", "Canon RF"}, "aps-c"),
    "tamron-18-300mm-f3.5-6.3-di-iii-a-vc-vxd": ({"Sony E", "Fujifilm X", "Nikon Z", "Canon RF"}, "aps-c"),
    "tamron-90mm-f2.8-di-iii-macro-vxd": ({"Sony E", "Nikon Z"}, None),
}


def test_every_entry_is_checked_against_its_source():
    check_every_entry_cited(RECORDS, CITED)
    assert len(RECORDS) >= 30


@pytest.mark.parametrize(("lens_id", "focal", "distance", "magnification", "apertures", "largest"), CITED,
                         ids=[f"{c[0]}@{c[1]}" for c in CITED])
def test_figures_against_the_cited_source(lens_id, focal, distance, magnification, apertures, largest):
    record = record_of(RECORDS, lens_id)
    check_cited_row(record, focal, distance, magnification, apertures, largest)
    # the source is named with its path and commit, and the figures with the maker's page it transcribes
    source = " ".join(record["source"].split())
    assert "isamu/lens-database build/data/" in source and "transcribing the maker's" in source
    assert ("sigma-global.com/jp/lenses/" in source) or ("tamron.com/jp/consumer/lenses/" in source)


@pytest.mark.parametrize(("lens_id", "what", "value", "said"), CONFIRMED, ids=[f"{c[0]}:{c[1]}" for c in CONFIRMED])
def test_figures_a_second_source_confirms(lens_id, what, value, said):
    record = record_of(RECORDS, lens_id)
    rows = record.get("close_focus") or [record]
    row = rows[-1] if what.startswith("tele ") else rows[0]
    if what in ("mm", "wide mm", "tele mm"):
        assert row["min_focus_mm"] == value
    elif what in ("wide max", "tele max"):
        assert row["max_magnification"] == pytest.approx(value, abs=0.0006)
    elif what == "max":
        assert record["max_magnification"] == pytest.approx(value, abs=0.0006)
    else:
        assert what in ("f_number_max", "f_number_max_tele") and record[what] == value
    # the second source is quoted in `source` by name, and a quotation in '' as `source` prints it
    name, _, quoted = said.partition(": '")
    source = " ".join(record["source"].split())
    assert name.split(":")[0].lower().replace("-", "") in source.lower().replace("-", "")
    if quoted:
        assert quoted.rstrip("'") in source


@pytest.mark.parametrize("lens_id", sorted(MOUNTS))
def test_mounts_and_sensor_as_the_sources_list_them(lens_id):
    record = record_of(RECORDS, lens_id)
    mounts, sensor = MOUNTS[lens_id]
    assert {m.strip() for m in record["mount"].split(",")} == mounts
    assert record.get("sensor") == sensor


def figures_of(record):
    """The figures an entry carries, named as in CONFIRMED: a prime's closest focus and magnification, a zoom's
    closest focus at each end, the magnification of a row that carries one (else the lens's), the smallest
    apertures."""
    if "close_focus" in record:
        rows = record["close_focus"]
        figures = {"wide mm", "tele mm"}
        figures |= {f"{end} max" for end, row in (("wide", rows[0]), ("tele", rows[-1])) if "max_magnification" in row}
        if not any(row.get("max_magnification") == record["max_magnification"] for row in rows):
            figures.add("max")
    else:
        figures = {"mm", "max"}
    return figures | {key for key in ("f_number_max", "f_number_max_tele") if key in record}


def test_every_entry_is_new_names_its_mounts_and_says_why_it_is_approximate():
    check_entries_are_new(FILE, RECORDS)
    for record in RECORDS:
        assert record["mount"] and record["mount"] != "various", record["id"]
        assert "Sony E" in record["mount"], record["id"]  # every lens here is sold for Sony E
        assert record["category"] != "fisheye", record["id"]
        # an entry is approximate exactly when a figure on it rests on the dataset alone, and its notes say which;
        # one whose every figure a second source confirms (the table above) is not
        confirmed = {what for lens_id, what, *_ in CONFIRMED if lens_id == record["id"]}
        unconfirmed = figures_of(record) - confirmed
        notes = " ".join(record["notes"].split())
        assert record.get("approximate", False) == bool(unconfirmed), (record["id"], unconfirmed)
        assert notes.startswith("Approximate: ") == bool(unconfirmed), record["id"]
        assert ("Approximate" in notes) == bool(unconfirmed), record["id"]
        lens = load_db().lens(record["id"])
        assert lens.tier == "shipped" and lens.approximate == bool(unconfirmed)


def test_the_approximate_count_of_this_file():
    # 37 entries, 13 of them confirmed figure by figure by a second source (LensVisualizer's design analyses
    # quoting the makers' specifications): 12 Sigma primes and zooms and the Tamron 90mm Macro
    assert len(RECORDS) == 37
    assert sum(1 for record in RECORDS if record.get("approximate")) == 24


def test_full_frame_and_aps_c_lines_are_told_apart():
    # Sigma's DC and Tamron's Di III-A are the APS-C lines, DG and Di III the full-frame ones
    for record in RECORDS:
        aps_c = " DC" in record["name"] or "Di III-A" in record["name"]
        assert (record.get("sensor") == "aps-c") == aps_c, record["id"]


@pytest.mark.parametrize("lens_id", [r["id"] for r in RECORDS])
def test_the_model_never_magnifies_more_than_the_source_says(lens_id):
    # at every published row, at both ends, and halfway between neighbouring rows
    check_never_magnifies_more(load_db().lens(lens_id))


def test_a_zoom_row_without_a_published_magnification_is_modelled_below_the_maximum():
    # Tamron 28-75mm G2: 1:2.7 (0.37x) at 28 mm and 0.18 m; at 75 mm and 0.38 m unit focusing would give 0.371x,
    # more than the published maximum, so the row is capped at it
    lens = load_db().lens("tamron-a063")
    k = 380 / 75 - 2
    unit = (k - (k * k - 4) ** 0.5) / 2
    assert unit == pytest.approx(0.37096, abs=1e-5) and unit > 0.37
    model = focus_model(lens, 75.0)
    assert internal_focus_at_distance(model, 380.0)[0] == pytest.approx(0.37, rel=1e-9)
    # Tamron 16-30mm G2: 0.19x, no focal length given; at 30 mm and 0.3 m unit focusing gives 0.127x, below it
    lens = load_db().lens("tamron-a064")
    k = 300 / 30 - 2
    model = focus_model(lens, 30.0)
    assert internal_focus_at_distance(model, 300.0)[0] == pytest.approx((k - (k * k - 4) ** 0.5) / 2, rel=1e-9)
    assert (k - (k * k - 4) ** 0.5) / 2 < 0.19
    # Tamron 50-400mm: Photography Life's 0.25x at 400 mm and 1.5 m is reached there exactly
    lens = load_db().lens("tamron-a067")
    model = focus_model(lens, 400.0)
    assert internal_focus_at_distance(model, 1500.0)[0] == pytest.approx(0.25, rel=1e-6)


def test_dof_refuses_closer_than_the_published_closest_focus():
    # Tamron 50-400mm: 1.5 m at 400 mm
    (row,) = run_json("dof", "--lens", "tamron-a067", "-f", "400", "-N", "8", "-s", "2m")
    assert row["near_mm"] < 2000.0 < row["far_mm"]
    result = run("dof", "--lens", "tamron-a067", "-f", "400", "-N", "8", "-s", "1.2m")
    assert result.exit_code == 2
    assert "1.5 m" in result.output


def test_tamron_50_300_takes_tamrons_1_to_3_1_at_300mm():
    # LensVisualizer's analysis quoting Tamron: 1:2 at 50 mm and 1:3.1 at 300 mm; the 300 mm row holds 1/3.1 to
    # three places and the model there reaches it, not the 1:2 of the wide end
    record = record_of(RECORDS, "tamron-50-300mm-f4.5-6.3-di-iii-vc-vxd")
    source = " ".join(record["source"].split())
    assert ("ronbuening/LensVisualizer src/lens-data/tamron/TamronA06950300mmf4563.analysis.md at "
            "571c53e5e6f2d99d40fedc011f78d2c89091914d") in source
    tele = record["close_focus"][-1]
    assert tele["focal_length_mm"] == 300 and tele["max_magnification"] == pytest.approx(1 / 3.1, abs=0.0006)
    model = focus_model(load_db().lens(record["id"]), 300.0)
    assert internal_focus_at_distance(model, 900.0)[0] == pytest.approx(tele["max_magnification"], rel=1e-6)
