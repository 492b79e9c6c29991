"""lens_db/current-lenses.yaml: each entry's figures against the pages its `source` quotes, and the
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

FILE = DB / "current-lenses.yaml"
RECORDS = lens_records(FILE)


# (lens, focal length mm, closest focus mm, magnification at that row or None, (widest, smallest f-number or
# None), largest magnification the page gives for the lens) as the pages each entry's source names print them
CITED = [
    # Canon's Japanese pages (polynomial/camera canon_mtf_data): 最短撮影距離 / 最大撮影倍率 / 最小絞り
    # 0.39m, 0.18倍, 22; a second page places the 0.18x at the 70mm end
    ("canon-rf-28-70mm-f2l-usm", 28, 390, None, (2, 22), 0.18),
    ("canon-rf-28-70mm-f2l-usm", 70, 390, 0.18, (2, 22), 0.18),
    # 0.13m, 0.26倍, 22
    ("canon-rf-16mm-f2.8-stm", 16, 130, 0.26, (2.8, 22), 0.26),
    # 0.2m, 0.19倍, 16
    ("canon-rf-20mm-f1.4l-vcm", 20, 200, 0.19, (1.4, 16), 0.19),
    # 0.28m, 0.18倍, 16
    ("canon-rf-35mm-f1.4l-vcm", 35, 280, 0.18, (1.4, 16), 0.18),
    # 4.5m, 0.14倍, F11 fixed
    ("canon-rf-600mm-f11-is-stm", 600, 4500, 0.14, (11, 11), 0.14),
    # 0.25m, 0.12倍 at 20mm, 22
    ("canon-rf-10-20mm-f4l-is-stm", 10, 250, None, (4, 22), 0.12),
    ("canon-rf-10-20mm-f4l-is-stm", 20, 250, 0.12, (4, 22), 0.12),
    # 0.2m, 0.38倍, 22
    ("canon-rf-14-35mm-f4l-is-usm", 14, 200, None, (4, 22), 0.38),
    ("canon-rf-14-35mm-f4l-is-usm", 35, 200, None, (4, 22), 0.38),
    # 0.3m and 0.11倍 at 24mm, 0.35m and 0.19倍 at 50mm; 22 and 32
    ("canon-rf-24-50mm-f4.5-6.3-is-stm", 24, 300, 0.11, (4.5, 22), 0.19),
    ("canon-rf-24-50mm-f4.5-6.3-is-stm", 50, 350, 0.19, (6.3, 32), 0.19),
    # 0.6m, 0.28倍 at 200mm, 32
    ("canon-rf-70-200mm-f4l-is-usm", 70, 600, None, (4, 32), 0.28),
    ("canon-rf-70-200mm-f4l-is-usm", 200, 600, 0.28, (4, 32), 0.28),
    # 0.49m and 0.2倍 at 70mm, 0.68m and 0.3倍 at 200mm; 22
    ("canon-rf-70-200mm-f2.8l-is-usm-z", 70, 490, 0.2, (2.8, 22), 0.3),
    ("canon-rf-70-200mm-f2.8l-is-usm-z", 200, 680, 0.3, (2.8, 22), 0.3),
    # 0.4m, 0.15倍, 16
    ("canon-rf-50mm-f1.4l-vcm", 50, 400, 0.15, (1.4, 16), 0.15),
    # 0.85m, 0.12倍, 16
    ("canon-rf-85mm-f1.2l-usm-ds", 85, 850, 0.12, (1.2, 16), 0.12),
    # 0.70m, 0.26倍, 22
    ("canon-rf-135mm-f1.8l-is-usm", 135, 700, 0.26, (1.8, 22), 0.26),
    # 4.3m, 0.29倍, 64
    ("canon-rf-1200mm-f8l-is-usm", 1200, 4300, 0.29, (8, 64), 0.29),
    # 2.5m, 0.17倍, 32
    ("canon-rf-400mm-f2.8l-is-usm", 400, 2500, 0.17, (2.8, 32), 0.17),
    # notes quoting Fujifilm's pages (jalangle/ghtns photogear): F5.6 (Wide) - F8 (Telephoto), F22, 2.4m,
    # 0.24x (Telephoto)
    ("fujifilm-xf150-600mm-f5.6-8-r-lm-ois-wr", 150, 2400, None, (5.6, 22), 0.24),
    ("fujifilm-xf150-600mm-f5.6-8-r-lm-ois-wr", 600, 2400, 0.24, (8, 22), 0.24),
    # 3.5, 32, 32cm, 0.15x; ronbuening/LensVisualizer's analysis (GF30_ANALYSIS): 0.32 m, 0.15x, no smallest aperture
    ("fujifilm-gf30mm-f3.5-r-wr", 30, 320, 0.15, (3.5, 32), 0.15),
]

# the second source for the GF30mm's closest focus and magnification: "the production minimum-focus endpoint at
# 0.32 m ... Fujifilm's published minimum focus distance", "Fujifilm's rounded 0.15x production specification"
GF30_ANALYSIS = ("ronbuening/LensVisualizer src/lens-data/fujifilm/FujifilmFujinonGf30mmf35RWR.analysis.md at "
                 "2fdb614d56ce2f6297545e2279af61a3bafbdc19")


def test_gf30_closest_focus_and_magnification_have_a_second_source_and_only_f32_stays_open():
    record = record_of(RECORDS, "fujifilm-gf30mm-f3.5-r-wr")
    assert (record["min_focus_mm"], record["max_magnification"]) == (0.32 * 1000, 0.15)
    assert GF30_ANALYSIS in " ".join(record["source"].split())
    notes = " ".join(record["notes"].split())
    assert record["approximate"] is True and "f/32" in notes and "no second source" in notes


def test_every_entry_is_checked_against_its_pages():
    check_every_entry_cited(RECORDS, CITED)


@pytest.mark.parametrize(("lens_id", "focal", "distance", "magnification", "apertures", "largest"), CITED,
                         ids=[f"{c[0]}@{c[1]}" for c in CITED])
def test_figures_against_the_cited_pages(lens_id, focal, distance, magnification, apertures, largest):
    record = record_of(RECORDS, lens_id)
    assert distance is not None
    check_cited_row(record, focal, distance, magnification, apertures, largest)


def test_every_entry_is_new_and_names_its_mount():
    check_entries_are_new(FILE, RECORDS)
    for record in RECORDS:
        assert record["mount"], record["id"]
        assert record["max_magnification"] and record["min_focus_mm"], record["id"]
        assert "approximate" not in record or record["notes"], record["id"]


@pytest.mark.parametrize("lens_id", [r["id"] for r in RECORDS])
def test_the_model_never_magnifies_more_than_the_page_says(lens_id):
    # at every published row, at both ends, and halfway between neighbouring rows
    check_never_magnifies_more(load_db().lens(lens_id))


def test_rf_28_70_reaches_its_published_maximum_at_70mm_and_less_at_28mm():
    # the page gives 0.18x at the 70mm end; at 28 mm and the same 0.39 m the model stays well below it
    lens = load_db().lens("canon-rf-28-70mm-f2l-usm")
    model = focus_model(lens, 70.0)
    assert internal_focus_at_distance(model, 390.0)[0] == pytest.approx(0.18, rel=1e-6)
    model = focus_model(lens, 28.0)
    assert internal_focus_at_distance(model, 390.0)[0] < 0.18


def test_dof_refuses_closer_than_the_published_closest_focus():
    (row,) = run_json("dof", "--lens", "canon-rf-28-70mm-f2l-usm", "-f", "70", "-N", "2", "-s", "0.5m")
    assert row["near_mm"] < 500.0 < row["far_mm"]
    result = run("dof", "--lens", "canon-rf-28-70mm-f2l-usm", "-f", "70", "-N", "2", "-s", "0.3m")
    assert result.exit_code == 2
    assert "0.39 m" in result.output
