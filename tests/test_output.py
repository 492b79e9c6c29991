"""One writer for every path: the same scenes give the same bytes as options or as a batch; tables that never crop."""

from __future__ import annotations

import json
import re
from pathlib import Path

import pytest
from cli_helpers import run, time_bound  # noqa: F401 - an autouse fixture
from click.testing import CliRunner

from camtool.cli import cli
from camtool.dof.closed import thin_dof

SCENES = ["dof", "-f", "50", "-s", "3"]




def batch(text: str, *args: str, env: dict[str, str | None] | None = None) -> tuple[int, str, str]:
    base: dict[str, str | None] = {"COLUMNS": None, "CAMTOOL_FORMAT": None, "NO_COLOR": None, **(env or {})}
    result = CliRunner().invoke(cli, [*args, "--batch", "-"], input=text, env=base)
    return result.exit_code, result.stdout, result.stderr


@pytest.mark.parametrize("output", [["--format", "table"], ["--format", "json"], ["--format", "csv"],
                                    ["--field", "near_mm", "--field", "far_mm"], ["--units", "imperial"]])
def test_options_and_batch_give_the_same_bytes(output: list[str], tmp_path: Path) -> None:
    single = run(*SCENES, "-N", "2.8,4,8", *output)
    assert single.exit_code == 0
    for text in ("f-number\n2.8\n4\n8\n", '{"f_number": 2.8}\n{"f_number": "f/4"}\n{"f_number": 8}\n'):
        code, out, err = batch(text, *SCENES, *output)
        assert code == 0, err
        assert out == single.stdout
    scenes = tmp_path / "scenes.csv"
    scenes.write_text("f-number\n2.8\n4\n8\n", encoding="utf-8")
    from_file = run(*SCENES, *output, "--batch", str(scenes))
    assert from_file.exit_code == 0 and from_file.stdout == single.stdout


def test_json_layout_is_one_row_per_line_in_an_array() -> None:
    out = run(*SCENES, "-N", "2.8,8", "--format", "json").stdout
    lines = out.splitlines()
    assert lines[0] == "[" and lines[-1] == "]" and len(lines) == 4
    assert lines[1].endswith("},") and not lines[2].endswith(",")
    near = thin_dof(50.0, 8.0, 43.266615305567875 / 1500, 3000.0).near_mm
    assert json.loads(lines[2])["near_mm"] == pytest.approx(near, rel=1e-13)
    code, empty, _ = batch("f-number,distance\n", "dof", "-f", "50", "--format", "json")
    assert code == 0 and empty == "[]\n"


def test_json_is_a_complete_document_when_a_row_after_the_first_chunk_is_bad(
        monkeypatch: pytest.MonkeyPatch) -> None:
    from camtool.cli import batch as batch_module

    monkeypatch.setattr(batch_module, "CHUNK", 5)
    text = "f-number,distance\n" + "".join("x,3\n" if i == 12 else f"8,{i + 1}\n" for i in range(17))
    code, out, err = batch(text, "dof", "-f", "50", "--format", "json")
    assert code == 2 and "row 13, column 'f-number'" in err
    assert [row["distance_mm"] for row in json.loads(out)] == [1000.0 * (i + 1) for i in range(12)]
    code, out, _ = batch(text, "dof", "-f", "50", "--format", "json", "--on-error", "skip")
    rows = json.loads(out)
    assert code == 1 and len(rows) == 17 and rows[12]["near_mm"] is None and "error" in rows[12]
    code, out, _ = batch(text.replace("x,3", "8,0.01"), "dof", "-f", "50", "--format", "json")
    assert code == 2 and len(json.loads(out)) == 12


def test_a_utf8_bom_is_accepted() -> None:
    code, out, err = batch("\ufefffocal-length,f-number,distance\n50,8,3\n", "dof", "--format", "json",
                           "--on-error", "skip")
    assert code == 0 and err == ""
    assert json.loads(out)[0]["distance_mm"] == 3000.0


def _row_tokens(out: str) -> list[list[str]]:
    lines = out.splitlines()
    rule = next(i for i, line in enumerate(lines) if line.startswith("─"))
    return [line.split("   ") for line in lines[rule + 1:rule + 4]]


@pytest.mark.parametrize(("width", "named"), [(45, "depth, front, rear"), (60, "front, rear"), (80, "")])
def test_a_narrow_table_leaves_out_whole_columns_and_says_so(width: int, named: str) -> None:
    wide = run(*SCENES, "-N", "2.8,4,8")
    narrow = run(*SCENES, "-N", "2.8,4,8", env={"COLUMNS": str(width)})
    assert narrow.exit_code == 0
    # every cell printed whole: each narrow row is the wide row less the columns left out, cell for cell, and the
    # columns that identify a row (f, N, focus) and hold its answer (near, far, H) are always there
    gone = {"depth": 5, "front": 6, "rear": 7}
    for short, full in zip(_row_tokens(narrow.stdout), _row_tokens(wide.stdout)):
        short = [cell.strip() for cell in short if cell.strip()]
        full = [cell.strip() for cell in full if cell.strip()]
        dropped = {gone[name] for name in named.split(", ") if name}
        assert short == [cell for index, cell in enumerate(full[:9]) if index not in dropped]
    table = narrow.stdout.split("thin model")[0]
    assert max(len(line) for line in table.splitlines()) <= width
    # the columns with values are named, with the way to get them; a picture gives way quietly
    assert narrow.stderr == (f"camtool: left out to fit {width} columns: {named} (a wider terminal or COLUMNS shows "
                             "them; --format csv or json gives every value)\n" if named else "")
    assert "sharp zone" not in narrow.stdout
    # the picture's legend goes with the picture
    assert "H hyperfocal" not in narrow.stdout and "H hyperfocal" in wide.stdout


def test_compose_columns_asked_for_are_named_when_left_out() -> None:
    args = ["compose", "--subject-size", "1.8m", "--fill", "0.8", "-N", "2.8", "--background", "20m"]
    result = run(*args, env={"COLUMNS": "80"})
    assert "bg blur" in result.stderr and "left out" in result.stderr
    assert "bg blur" in run(*args).stdout


@pytest.mark.parametrize("columns", ["0", "-3", "wide"])
def test_columns_that_is_not_a_positive_number_is_ignored(columns: str) -> None:
    result = run(*SCENES, "-N", "8", env={"COLUMNS": columns})
    assert result.exit_code == 0 and result.stdout == run(*SCENES, "-N", "8").stdout != ""


def test_imperial_table_uses_one_notation_for_every_distance() -> None:
    out = run("dof", "-f", "50", "-N", "8", "-s", "2m", "--units", "imperial", "--model", "thin").stdout
    lines = out.splitlines()
    assert lines[1].count("(ft in)") == 7  # focus, near, far, depth, front, rear, H
    cells = re.findall(r"\S+' \S+\"|\S+\"|∞", lines[3])
    assert len(cells) == 7
    # the front depth, 0.62 m = 24.5 in (1 in = 25.4 mm exactly), in inches with its mark
    front = thin_dof(50.0, 8.0, 43.266615305567875 / 1500, 2000.0).front_mm
    assert f"{front / 25.4:.2f}\"" in cells


def test_a_table_above_the_limit_is_refused_with_a_hint() -> None:
    many = ",".join(str(1 + i / 100) for i in range(1000))
    result = run("dof", "-f", "50", "-N", many, "-s", many.replace(",", "m,") + "m")
    assert result.exit_code == 2
    assert result.stderr == ("Error: the list options ask for 1000 × 1000 = 1,000,000 combinations; a table holds "
                             "at most 100,000 rows (use --format csv or --format json, which stream any number)\n")


@pytest.mark.parametrize("output", [["--format", "json"], ["--format", "csv"], ["--field", "near_mm",
                                                                                 "--field", "file"]])
def test_column_writer_and_row_writer_give_the_same_bytes(output: list[str], monkeypatch: pytest.MonkeyPatch) -> None:
    # two sensors (two groups computed apart, interleaved), a bad cell, a scene too close, a passed-through column
    text = ("file,focal-length,f-number,distance,sensor\n"
            "a,50,8,3m,36x24\nb,25,4,3m,18x12\nc,50,x,3m,36x24\nd,50,11,0.01m,36x24\ne,24,8,inf,18x12\n"
            'f,"35",f/2.8,10ft,36x24\n')
    code, fast, fast_err = batch(text, "dof", *output, "--on-error", "skip")
    monkeypatch.setattr("camtool.render.columnar.ColumnRows.materialised", property(lambda self: True))
    code2, slow, slow_err = batch(text, "dof", *output, "--on-error", "skip")
    assert (code, fast, fast_err) == (code2, slow, slow_err)
    assert code == 1 and fast_err.count("(skipped)") == 2
    if "json" in output:
        rows = json.loads(fast)
        assert [row["file"] for row in rows] == list("abcdef")
        assert rows[4]["far_mm"] is None and rows[2]["near_mm"] is None and "error" in rows[3]
