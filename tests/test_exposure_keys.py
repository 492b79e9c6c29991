"""``camtool exposure``: every key a row carries is documented, in the man page and in docs/exposure.md.

The keys are collected from what the command emits in each of its modes (a
metered exposure corrected, a scene solved, the settings' EV, equivalents),
not from the lists the documentation is generated from, so a key added to a
row without its documentation fails here.
"""

from __future__ import annotations

import json
import re
from pathlib import Path

import pytest
from cli_helpers import run

from camtool.cli.manpage import pages

ROOT = Path(__file__).resolve().parent.parent

MODES = [
    ["-N", "8", "-t", "1/60", "--nd", "ND1000", "--film", "hp5"],  # metered, the time solved
    ["-N", "8", "-t", "30", "--iso", "800", "--to-iso", "100", "--solve", "f-number"],  # metered, the f-number
    ["--ev100", "12", "-N", "8", "--nd", "ND1000", "--film", "hp5"],  # a scene solved
    ["-N", "16", "-t", "1/125"],  # the settings' EV
    ["--ev100", "12", "--iso", "100", "--equivalents"],  # equivalents
    ["--lens", "cooke-s4i-50mm-t2", "--ev100", "12", "-t", "1/50"],  # a T-stop
    ["--ev100", "12", "-N", "T2.8", "--shutter-angle", "180", "--fps", "24"],  # a shutter angle
]


def _emitted() -> set[str]:
    keys: set[str] = set()
    for args in MODES:
        result = run("exposure", *args, "--format", "json")
        assert result.exit_code == 0, (args, result.stderr)
        for row in json.loads(result.stdout):
            keys |= set(row)
        csv = run("exposure", *args, "--format", "csv")
        assert csv.exit_code == 0, (args, csv.stderr)
        keys |= set(csv.stdout.splitlines()[0].split(","))
    return keys


def _man_keys(page: str) -> set[str]:
    section = page.split(".SH OUTPUT KEYS", 1)[1].split("\n.SH ", 1)[0]
    return {key.replace("\\-", "-") for key in re.findall(r"^\\fB([^\\]+(?:\\-[^\\]+)*)\\fR$", section, flags=re.M)}


def _doc_keys() -> set[str]:
    text = (ROOT / "docs" / "exposure.md").read_text(encoding="utf-8")
    section = text.split("\n## Output keys\n", 1)[1].split("\n## ", 1)[0]
    return set(re.findall(r"^\| `([a-z0-9_]+)` \|", section, flags=re.M))


@pytest.fixture(scope="module")
def emitted() -> set[str]:
    return _emitted()


def test_the_modes_emit_the_settings_corrections_and_apex_values(emitted: set[str]) -> None:
    # What each mode must carry by its definition (docs/exposure.md, "Four questions" and "Meters and APEX").
    assert {"f_number", "shutter_s", "iso", "ev", "ev100", "nd_stops", "bellows_stops", "reciprocity_stops",
            "corrected_shutter_s", "av", "tv", "sv", "bv", "shutter_exact_s"} <= emitted


def test_every_emitted_key_is_in_the_man_page(emitted: set[str]) -> None:
    documented = _man_keys(pages()["camtool-exposure.1"])
    committed = _man_keys((ROOT / "man" / "man1" / "camtool-exposure.1").read_text(encoding="utf-8"))
    assert sorted(emitted - documented) == []
    assert sorted(emitted - committed) == []
    assert sorted(documented - emitted) == []  # and nothing documented that no row carries


def test_every_emitted_key_is_in_the_docs(emitted: set[str]) -> None:
    documented = _doc_keys()
    assert sorted(emitted - documented) == []
    assert sorted(documented - emitted) == []
