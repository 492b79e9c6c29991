"""The cyclic garbage collector is paused while a command starts and on for its work (docs/design.md §7)."""

from __future__ import annotations

import gc
import json
import subprocess
import sys
from pathlib import Path
from typing import Any

import pytest

# each command's work records whether the collector was on just before and after it was resumed, and how many
# objects were frozen; at exit whether it is on
_SCRIPT = """
import atexit, gc, json, sys
from camtool.core import collector
seen = []
resume = collector.resume
def recorded():
    before = gc.isenabled()
    resume()
    seen.append([before, gc.isenabled(), gc.get_freeze_count()])
collector.resume = recorded
atexit.register(lambda: print(json.dumps({"seen": seen, "at_exit": gc.isenabled(), "frozen": gc.get_freeze_count()}),
                              file=sys.stderr))
sys.argv = ["camtool", *ARGV]
ENTRY
"""


def _run(argv: list[str], entry: str, tmp_path: Path, status: int = 0) -> tuple[dict[str, Any], str]:
    code = _SCRIPT.replace("ARGV", repr(argv)).replace("ENTRY", entry)
    done = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, timeout=60,
                          env={"XDG_CACHE_HOME": str(tmp_path), "PATH": "/usr/bin:/bin", "CAMTOOL_FORMAT": ""})
    assert done.returncode == status, done.stderr
    return json.loads(done.stderr.strip().splitlines()[-1]), done.stdout


def test_importing_the_command_line_leaves_the_collector_as_it_was() -> None:
    assert gc.isenabled()
    import camtool.cli  # noqa: F401

    assert gc.isenabled()


@pytest.mark.parametrize("argv", [["dof", "-f", "50", "-N", "8", "-s", "3m", "--format", "json"],
                                  ["dof", "--lens", "nikon-z-50mm-f1.8-s", "-N", "8", "-s", "3m", "--format", "json"]])
def test_the_entry_point_pauses_the_collector_until_the_work_and_freezes_what_start_up_made(argv: list[str], tmp_path: Path) -> None:
    record, out = _run(argv, "from camtool.__main__ import main\nmain()", tmp_path)
    (before, after, frozen), _at_the_end = record["seen"]  # as the work begins, then main's own last word
    assert (before, after, record["at_exit"]) == (False, True, True)
    assert frozen > 10_000  # the modules, classes and functions of the start-up
    assert json.loads(out)[0]["near_mm"] > 0


def test_an_in_process_caller_gets_its_collector_back_with_nothing_frozen(tmp_path: Path) -> None:
    record, _ = _run(["dof", "-f", "50", "-N", "8", "-s", "3m", "--format", "json"],
                     "from camtool.cli import main\nmain()", tmp_path)
    assert record["seen"] == [[False, True, 0], [True, True, 0]] and record["at_exit"] and record["frozen"] == 0


def test_a_batch_runs_its_rows_with_the_collector_on(tmp_path: Path) -> None:
    batch = tmp_path / "scenes.csv"
    batch.write_text("focal_length,f_number,distance\n50,8,3m\n50,x,3m\n35,4,2m\n", encoding="utf-8")
    record, out = _run(["dof", "--batch", str(batch), "--on-error", "skip", "--format", "json"],
                       "from camtool.__main__ import main\nmain()", tmp_path, status=1)  # a row skipped: exit 1
    assert record["seen"] and all(after for _, after, _ in record["seen"]) and record["at_exit"]
    assert [row.get("focal_length_mm") for row in json.loads(out)] == [50.0, None, 35.0]  # the skipped row stays, empty


def test_a_command_that_never_reaches_its_work_turns_the_collector_back_on(tmp_path: Path) -> None:
    record, out = _run(["presets", "list", "--kind", "sensor", "--format", "json"],
                       "from camtool.__main__ import main\nmain()", tmp_path)
    assert record["at_exit"] and json.loads(out)


def test_a_table_s_renderer_is_imported_paused_and_frozen(tmp_path: Path) -> None:
    record, out = _run(["dof", "-f", "50", "-N", "8", "-s", "3m"], "from camtool.__main__ import main\nmain()",
                       tmp_path)
    (_, _, frozen_at_work), _ = record["seen"]
    assert record["frozen"] > frozen_at_work + 5_000  # rich's modules, frozen once imported
    assert "near" in out.lower() and "far" in out.lower()  # the table drawn


def test_importing_in_process_pauses_and_freezes_nothing() -> None:
    from camtool.core import collector

    frozen = gc.get_freeze_count()
    with collector.importing():
        assert not gc.isenabled()
        import fractions  # noqa: F401
    assert gc.isenabled() and gc.get_freeze_count() == frozen
