"""Every shipped preset, of every kind, names its source (lens_db/README.md, "Where the numbers come from").

The files are read here with yaml, not camtool, so an entry the loader would drop or merge is still
seen; the loaded database is checked too, so a source the loader loses is caught as well.
"""

from __future__ import annotations

import re
from pathlib import Path

import pytest
import yaml

from camtool.presets import load_db
from camtool.presets.schema import KINDS, SECTIONS

ROOT = Path(__file__).resolve().parents[1]
DB = ROOT / "lens_db"


def shipped_entries() -> list[tuple[str, str, dict]]:
    """(file, kind, record) for every preset in lens_db/*.yaml and lens_db/prescriptions/*.yaml."""
    out = []
    for path in sorted(DB.glob("*.yaml")) + sorted((DB / "prescriptions").glob("*.yaml")):
        data = yaml.safe_load(path.read_text(encoding="utf-8"))
        name = path.relative_to(DB).as_posix()
        if "surfaces" in data:  # a prescription file is one preset
            out.append((name, "prescription", data))
            continue
        for section, records in data.items():
            out.extend((name, SECTIONS[section], record) for record in records)
    return out


ENTRIES = shipped_entries()

# A source names where the figures were read: a few words at least, never a placeholder.
PLACEHOLDER = re.compile(r"\b(todo|tbd|fixme|unknown|n/?a|none|placeholder|various|see above)\b", re.IGNORECASE)


def test_every_kind_is_read():
    kinds = {kind for _, kind, _ in ENTRIES}
    assert kinds == {"sensor", "camera", "lens", "prescription", "scene"}
    # The files read here are the ones the loader reads: the same number of shipped presets of each kind.
    db = load_db()
    for kind in KINDS:
        here = sum(1 for _, k, _ in ENTRIES if k == kind)
        loaded = sum(1 for preset in db.all(kind) if preset.tier == "shipped")
        assert here == loaded, kind


@pytest.mark.parametrize(("path", "kind", "record"), ENTRIES, ids=[f"{p}:{r['id']}" for p, _, r in ENTRIES])
def test_every_entry_names_a_source(path, kind, record):
    source = " ".join(str(record.get("source") or "").split())
    assert len(source.split()) >= 5, f"{path}: {kind} {record['id']} names no source"
    assert not PLACEHOLDER.search(source), f"{path}: {kind} {record['id']}: source {source!r}"


def test_the_loaded_database_keeps_every_source():
    db = load_db()
    for kind in KINDS:
        for preset in db.all(kind):
            if preset.tier == "shipped":
                assert (preset.source or "").strip(), (kind, preset.id)


def test_every_approximate_entry_says_why():
    for path, kind, record in ENTRIES:
        if record.get("approximate"):
            assert len(str(record.get("notes") or "").split()) >= 5, f"{path}: {kind} {record['id']}"


# A reference work is cited with the file that was read in it, so the figure can be found again.
CITED_FILES = [
    ("open-product-data/digital-cameras", re.compile(r"database/[a-z0-9_.\-]+\.yaml")),
    ("Camera Sensor Database", re.compile(r"data/markdown/[a-z0-9]+/[a-z0-9]+\.md")),
]


@pytest.mark.parametrize(("work", "pattern"), CITED_FILES, ids=[work for work, _ in CITED_FILES])
def test_reference_works_are_cited_with_the_file_read(work, pattern):
    citing = [(path, record) for path, _, record in ENTRIES if work in str(record.get("source", ""))]
    assert citing, work
    for path, record in citing:
        assert pattern.search(" ".join(str(record["source"]).split())), f"{path}: {record['id']}"


def test_a_dpreview_citation_agrees_with_the_entry():
    # Where a camera cites DPReview's SensorSize 'Format (W x H mm)' and MaxResolution W x H, the entry's own
    # figures are those numbers (a copy error between the source text and the keys is caught here).
    size = re.compile(r"SensorSize '[^(']*\(([\d.]+) x ([\d.]+) mm\)'")
    resolution = re.compile(r"MaxResolution (\d+) x (\d+)")
    checked = 0
    db = load_db()
    for _, kind, record in ENTRIES:
        source = " ".join(str(record.get("source", "")).split())
        if kind != "camera" or "open-product-data" not in source:
            continue
        camera = db.camera(record["id"])
        found = size.search(source)
        if found:
            assert (camera.sensor.width_mm, camera.sensor.height_mm) == pytest.approx(
                (float(found.group(1)), float(found.group(2)))), record["id"]
            checked += 1
        found = resolution.search(source)
        if found:
            assert (camera.pixels_w, camera.pixels_h) == (int(found.group(1)), int(found.group(2))), record["id"]
    assert checked >= 70
