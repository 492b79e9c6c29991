"""The preset counts the READMEs print are the shipped database's own (read here with yaml, not camtool)."""

from __future__ import annotations

import re
from pathlib import Path

import yaml

ROOT = Path(__file__).resolve().parents[1]
DB = ROOT / "lens_db"


def shipped_counts() -> dict[str, int]:
    counts = {kind: len(yaml.safe_load((DB / f"{kind}.yaml").read_text(encoding="utf-8"))[kind])
              for kind in ("sensors", "cameras", "lenses", "scenes")}
    for name in ("compact-lenses", "third-party-lenses", "cine-lenses"):
        counts[name] = len(yaml.safe_load((DB / f"{name}.yaml").read_text(encoding="utf-8"))["lenses"])
    counts["prescriptions"] = len(list((DB / "prescriptions").glob("*.yaml")))
    return counts


def shipped_lenses() -> list[dict]:
    """Every lens entry of every shipped file with a ``lenses`` section."""
    return [lens for path in DB.glob("*.yaml")
            for lens in (yaml.safe_load(path.read_text(encoding="utf-8")) or {}).get("lenses") or []]


def test_readme_counts_the_shipped_presets():
    text = " ".join((ROOT / "README.md").read_text(encoding="utf-8").split())
    match = re.search(r"`lens_db/` ships (\d+) sensor and film formats, (\d+) cameras, (\d+) lenses \(.*?\), "
                      r"(\d+) lens prescriptions (?:\(.*?\) )?and (\d+) scenes", text)
    assert match, "README.md no longer says what lens_db/ ships"
    said = dict(zip(("sensors", "cameras", "lenses", "prescriptions", "scenes"), map(int, match.groups()), strict=True))
    counts = shipped_counts()
    assert said == {kind: counts[kind] for kind in said}
    compacts = re.search(r"and (\d+) built-in lenses of compacts \(`compact-lenses\.yaml`\)", text)
    assert compacts and int(compacts.group(1)) == counts["compact-lenses"]
    third = re.search(r"(\d+) lenses of the independent lens makers \(`third-party-lenses\.yaml`", text)
    assert third and int(third.group(1)) == counts["third-party-lenses"]
    sets = re.search(r"(\d+) cinema lens sets \(`cine-lenses\.yaml`", text)
    assert sets and int(sets.group(1)) == counts["cine-lenses"]


def test_lens_db_readme_table_counts_the_shipped_presets():
    text = (DB / "README.md").read_text(encoding="utf-8")
    counts = shipped_counts()
    for kind in ("sensors", "cameras", "compact-lenses", "third-party-lenses", "cine-lenses", "lenses", "scenes"):
        row = re.search(rf"^\| `{kind}\.yaml` \|.*\| (\d+) \|$", text, re.MULTILINE)
        assert row and int(row.group(1)) == counts[kind], kind
    row = re.search(r"^\| `prescriptions/\*\.yaml` \|.*\| (\d+) \|$", text, re.MULTILINE)
    assert row and int(row.group(1)) == counts["prescriptions"]


def test_every_shipped_file_has_a_row_in_the_table():
    # a preset file added to lens_db/ is listed, with its count, in lens_db/README.md's table
    text = (DB / "README.md").read_text(encoding="utf-8")
    for path in sorted(DB.glob("*.yaml")):
        assert re.search(rf"^\| `{re.escape(path.name)}` \|.*\| \d+ \|$", text, re.MULTILINE), path.name


def test_shipped_lens_count_floor():
    # Floor on the lenses of every shipped file together (every file with a `lenses` section): 569 entries,
    # 816 lenses when each member of a cinema set counts. Raise it as entries are added; it never goes down unnoticed.
    lenses = shipped_lenses()
    assert len(lenses) >= 587
    assert sum(len(lens["set"]) if "set" in lens else 1 for lens in lenses) >= 834


def test_the_cine_sets_the_issue_asks_for_stay_shipped():
    """Floors: the cinema lens sets and the anamorphic set shipped in cine-lenses.yaml are not lost."""
    lenses = yaml.safe_load((DB / "cine-lenses.yaml").read_text(encoding="utf-8"))["lenses"]
    sets = [lens for lens in lenses if "set" in lens]
    assert len(sets) >= 24 and sum(len(lens["set"]) for lens in sets) >= 256
    assert sum(1 for lens in sets if lens.get("squeeze")) >= 4
    cameras = yaml.safe_load((DB / "cameras.yaml").read_text(encoding="utf-8"))["cameras"]
    assert len(cameras) >= 238 and sum(1 for c in cameras if c.get("category") == "cine") >= 47


def test_readme_counts_every_lens_and_the_approximate_entries():
    text = " ".join((ROOT / "README.md").read_text(encoding="utf-8").split())
    match = re.search(r"(\d+) lens entries in all, (\d+) lenses counting each member of a cinema set\. (\d+) lens "
                      r"entries and (\d+) cameras are marked `approximate`", text)
    assert match, "README.md no longer totals the shipped lenses"
    lenses = shipped_lenses()
    cameras = yaml.safe_load((DB / "cameras.yaml").read_text(encoding="utf-8"))["cameras"]
    assert tuple(map(int, match.groups())) == (
        len(lenses), sum(len(lens["set"]) if "set" in lens else 1 for lens in lenses),
        sum(1 for lens in lenses if lens.get("approximate")), sum(1 for camera in cameras if camera.get("approximate")))


def test_lens_db_readme_counts_the_kinds_of_body():
    text = " ".join((DB / "README.md").read_text(encoding="utf-8").split())
    match = re.search(r"The (\d+) bodies are (\d+) interchangeable-lens stills bodies, (\d+) compacts, (\d+) phones "
                      r"and (\d+) cinema and video cameras", text)
    assert match, "lens_db/README.md no longer counts the kinds of body"
    cameras = yaml.safe_load((DB / "cameras.yaml").read_text(encoding="utf-8"))["cameras"]
    phones = sum(1 for c in cameras if c.get("category") == "phone")
    cine = sum(1 for c in cameras if c.get("category") == "cine")
    compacts = sum(1 for c in cameras if c.get("category") not in ("phone", "cine") and c.get("mount") == "fixed lens")
    assert tuple(map(int, match.groups())) == (len(cameras), len(cameras) - phones - cine - compacts, compacts, phones,
                                               cine)


def test_lens_db_readme_counts_the_smallest_apertures():
    text = " ".join((DB / "README.md").read_text(encoding="utf-8").split())
    match = re.search(r"The smallest aperture \(`f_number_max`\) is given for (\d+) lens entries.*?\((\d+) entries carry "
                      r"\"f_number_max not found\"", text)
    assert match, "lens_db/README.md no longer counts the smallest apertures"
    lenses = shipped_lenses()
    missing = sum(1 for lens in lenses if "f_number_max not found" in " ".join(str(lens.get("notes", "")).split()))
    assert (int(match.group(1)), int(match.group(2))) == (sum(1 for lens in lenses if lens.get("f_number_max")), missing)


def test_lens_db_readme_counts_the_approximate_entries_now():
    # the "now" columns of lens_db/README.md's table of approximate entries: sensors.yaml, cameras.yaml and
    # lenses.yaml, each with how many of its approximate entries are phone figures
    text = (DB / "README.md").read_text(encoding="utf-8")
    for kind in ("sensors", "cameras", "lenses"):
        match = re.search(rf"^\| {kind} \| (\d+) \| \d+ \| \d+ \| (\d+) \| (\d+) \|$", text, re.MULTILINE)
        assert match, f"lens_db/README.md no longer counts the approximate {kind}"
        entries = yaml.safe_load((DB / f"{kind}.yaml").read_text(encoding="utf-8"))[kind]
        approximate = [entry for entry in entries if entry.get("approximate")]
        phones = sum(1 for entry in approximate if entry.get("category") == "phone")
        assert tuple(map(int, match.groups())) == (len(entries), len(approximate), phones), kind
