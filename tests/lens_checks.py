"""The checks every lens file of lens_db/ gets against the pages its entries cite, shared by the modules that test
one file each (test_third_party_lenses.py, test_maker_lenses.py, test_current_lenses.py and the others)."""

from __future__ import annotations

from itertools import pairwise
from pathlib import Path
from typing import Any

import pytest
import yaml
from conftest import point_xdg_at, presets_home

from camtool.geometry.closeup import internal_focus_at_distance
from camtool.presets.focusing import focus_model, row_magnification

DB = Path(__file__).resolve().parents[1] / "lens_db"


@pytest.fixture(autouse=True)
def isolated(request, monkeypatch, shared_presets_home):
    """The shipped presets alone (a module imports this fixture to use it)."""
    root = presets_home(request, shared_presets_home, "tmp_path")
    point_xdg_at(root, monkeypatch)
    return root


def lens_records(path: Path) -> list[dict[str, Any]]:
    """The `lenses` section of a lens_db file, as YAML reads it (not camtool)."""
    return yaml.safe_load(path.read_text(encoding="utf-8"))["lenses"]


def record_of(records: list[dict[str, Any]], lens_id: str) -> dict[str, Any]:
    return next(r for r in records if r["id"] == lens_id)


def check_cited_row(record: dict[str, Any], focal: float, distance: float | None, magnification: float | None,
                    apertures: tuple[float, float | None], largest: float | None = None) -> None:
    """The entry's row at ``focal`` (a prime's own figures) holds the page's closest focus and magnification, and the
    lens its widest and smallest f-number (at the long end of a zoom whose apertures change); a smallest aperture
    the page does not give is said in the notes to be "not found"."""
    zoom = "focal_min_mm" in record
    long_end = zoom and focal == record["focal_max_mm"]
    if zoom:
        row = next(r for r in record["close_focus"] if r["focal_length_mm"] == focal)
    else:
        assert record["focal_length_mm"] == focal
        row = record
    assert row.get("min_focus_mm") == distance
    if magnification is None:
        assert "max_magnification" not in row
    else:
        assert row["max_magnification"] == pytest.approx(magnification, abs=0.0006)  # stored to three places
    widest, smallest = apertures
    assert record["f_number_min_tele" if long_end and "f_number_min_tele" in record else "f_number_min"] == widest
    key = "f_number_max_tele" if long_end and "f_number_max_tele" in record else "f_number_max"
    assert record.get(key) == smallest
    if smallest is None:
        assert "f_number_max not found" in " ".join(record["notes"].split())
    if largest is not None:  # the largest magnification the source gives for the lens
        assert record["max_magnification"] == pytest.approx(largest, abs=0.0006)


def check_against_analysis(record: dict[str, Any], closest_m: float, magnification: float | None,
                           citation: str) -> None:
    """The entry's closest focus (every row of a zoom) and largest magnification are the ones a lens-design analysis
    quotes from the maker, and its ``source`` cites the analysis (``citation``: repository, path and commit)."""
    rows = record.get("close_focus") or [{"min_focus_mm": record["min_focus_mm"]}]
    assert {row["min_focus_mm"] for row in rows} == {round(closest_m * 1000)}
    assert record["min_focus_mm"] == round(closest_m * 1000)
    if magnification is not None:
        assert record["max_magnification"] == pytest.approx(magnification, abs=0.0006)
    assert citation in " ".join(record["source"].split())


def check_every_entry_cited(records: list[dict[str, Any]], cited: list[tuple[Any, ...]]) -> None:
    """Every entry of a file has its rows in ``cited`` (lens id, focal length, ...), a zoom one per published row."""
    assert {lens_id for lens_id, *_ in cited} == {r["id"] for r in records}
    for record in records:
        if "focal_min_mm" in record:
            focals = sorted(f for lens_id, f, *_ in cited if lens_id == record["id"])
            assert focals == [row["focal_length_mm"] for row in record["close_focus"]], record["id"]


def check_entries_are_new(path: Path, records: list[dict[str, Any]]) -> None:
    """No id, alias or display name of the file is in another lens_db file, and each entry loads as shipped."""
    from camtool.presets import load_db

    taken, names = taken_elsewhere(path)
    database = load_db()
    for record in records:
        assert not ({record["id"], *record.get("aliases", [])} & taken), record["id"]
        assert name_key(record.get("name", record["id"])) not in names, record["id"]
        assert database.lens(record["id"]).tier == "shipped", record["id"]


def name_key(name: str) -> str:
    """A display name with case, spaces and punctuation left out."""
    return "".join(ch for ch in name.lower() if ch.isalnum())


def taken_elsewhere(path: Path) -> tuple[set[str], set[str]]:
    """The ids and aliases, and the display names (by :func:`name_key`), of the lenses of every other lens_db file."""
    taken, names = set(), set()
    for other in sorted(DB.glob("*.yaml")):
        if other != path:
            for record in (yaml.safe_load(other.read_text(encoding="utf-8")) or {}).get("lenses") or []:
                taken |= {record["id"], *record.get("aliases", [])}
                names.add(name_key(record.get("name", record["id"])))
    return taken, names


def check_never_magnifies_more(lens: Any) -> None:
    """At its closest focus the model reaches no more than the lens's published maximum: at every row of a zoom, at
    both ends and halfway between neighbours; a prime exactly its published figure; a row with a published
    magnification exactly that."""
    if lens.is_zoom:
        stops = sorted({*(f for f, _d, _m in lens.close_focus), lens.focal_min_mm, lens.focal_max_mm})
        focals = sorted({*stops, *((a + b) / 2 for a, b in pairwise(stops))})
    else:
        focals = [lens.focal_length_mm]
    for f in focals:
        model = focus_model(lens, f)
        m, _ = internal_focus_at_distance(model, model.min_focus_mm)
        assert 0 < m <= lens.max_magnification * 1.001, (lens.id, f, m)
        if not lens.is_zoom:
            assert m == pytest.approx(lens.max_magnification, rel=1e-6)
    for f, distance, published in lens.close_focus:
        modelled = row_magnification(lens, f, distance, published)
        assert modelled is not None and modelled <= lens.max_magnification + 1e-12
        if published is not None:
            assert modelled == pytest.approx(published, rel=1e-9)
