"""--batch and --field: one output row per input row, in order; bad rows named by number and column."""

from __future__ import annotations

import json
import random

import pytest
from cli_helpers import run, run_json, time_bound  # noqa: F401 - an autouse fixture

from camtool.dof.closed import thin_dof
from camtool.dof.ladder import depth_of_field


def batch(text: str, *args: str) -> tuple[int, str, str]:
    from click.testing import CliRunner

    from camtool.cli import cli

    result = CliRunner().invoke(cli, [*args, "--batch", "-"], input=text, env={"COLUMNS": None})
    return result.exit_code, result.stdout, result.stderr


def test_csv_batch_matches_single_calls_for_1000_random_scenes() -> None:
    rng = random.Random(20261122)
    scenes = []
    for _ in range(1000):
        f = rng.choice([14, 24, 35, 50, 85, 135, 200, 400])
        n = rng.choice(["1.4", "f/2", "f2.8", "4", "5.6", "8", "11", "16", "22"])
        s = rng.choice([f"{rng.uniform(0.1, 100):.3f}m", f"{rng.uniform(5, 300):.1f}ft", "inf"])
        scenes.append((f, n, s))
    # keep only reachable focus distances (at least 4f from the sensor)
    from camtool.core.units import parse_length

    scenes = [sc for sc in scenes if parse_length(sc[2], "m") >= 4 * sc[0] * 1.0001]
    text = "focal-length,f-number,distance\n" + "".join(f"{f},{n},{s}\n" for f, n, s in scenes)
    code, out, err = batch(text, "dof", "--format", "json")
    assert code == 0, err
    rows = json.loads(out)
    assert len(rows) == len(scenes)
    for (f, _n, s), row in zip(scenes, rows):
        expected = depth_of_field("auto", float(f), row["f_number"], row["coc_mm"], parse_length(s, "m"))
        assert row["model"] == expected.model
        assert row["near_mm"] == pytest.approx(expected.limits.near_mm, rel=1e-13)
    # a sample of true single invocations (all 1000 would only repeat the same path)
    for (f, n, s), row in list(zip(scenes, rows))[::97]:
        (single,) = run_json("dof", "-f", str(f), "-N", n, "-s", s)
        assert single == row


def test_jsonl_batch_with_per_row_sensor_keeps_order() -> None:
    text = "\n".join(json.dumps(r) for r in [
        {"focal_length": 50, "f_number": 8, "distance": "3m", "sensor": "36x24"},
        {"focal_length": 25, "f_number": 4, "distance": "3m", "sensor": "18x12"},
        {"focal_length": 50, "f_number": 11, "distance": "5m", "sensor": "36x24"},
    ]) + "\n"
    code, out, _ = batch(text, "dof", "--format", "json")
    rows = json.loads(out)
    assert code == 0
    assert [r["f_number"] for r in rows] == [8.0, 4.0, 11.0]
    assert rows[1]["coc_mm"] == pytest.approx(rows[0]["coc_mm"] / 2)


def test_command_line_options_apply_to_every_row_and_csv_feeds_back() -> None:
    code, out, _ = batch("distance\n2\n3\n", "dof", "-f", "50", "-N", "8", "--format", "csv")
    assert code == 0 and len(out.strip().splitlines()) == 3
    _code2, again, _ = batch(out, "dof", "--format", "csv")
    assert again == out


def test_bad_row_stops_with_its_number_and_column() -> None:
    code, out, err = batch("f-number,distance\n8,3\nx,3\n", "dof", "-f", "50", "--format", "json")
    # the rows before the bad one, as a complete JSON document
    assert code == 2 and [row["f_number"] for row in json.loads(out)] == [8.0]
    assert err == ("Error: --batch row 2, column 'f-number': Invalid value for '-N' / '--f-number': "
                   "'x' is not an f-number (examples: 8, f/8, f8)\n")


def test_skip_keeps_each_bad_row_in_its_place_reports_in_order_and_exits_1() -> None:
    text = "f-number,distance\n8,3\nx,3\n8,0.01\n4,2\n"
    code, out, err = batch(text, "dof", "-f", "50", "--format", "json", "--on-error", "skip")
    assert code == 1
    rows = json.loads(out)
    assert [r["f_number"] for r in rows] == [8.0, None, None, 4.0]
    assert rows[1]["near_mm"] is None and rows[1]["error"].startswith("--batch row 2, column 'f-number'")
    assert rows[2]["error"].startswith("--batch row 3: Invalid value for '-s'")
    assert "error" not in rows[0] and "error" not in rows[3]
    # a parse error (row 2) and a computing error (row 3) on stderr in row order, then a count
    lines = err.splitlines()
    assert [line.split(":")[1].strip().split(",")[0] for line in lines[:2]] == ["--batch row 2", "--batch row 3"]
    assert lines[2] == "camtool: 2 of 4 rows skipped"
    code, out, _ = batch(text, "dof", "-f", "50", "--format", "csv", "--on-error", "skip")
    lines = out.splitlines()
    # an empty cell for each of the header's columns
    assert code == 1 and len(lines) == 5 and lines[2] == lines[3] == "," * lines[0].count(",")
    code, out, _ = batch(text, "dof", "-f", "50", "--field", "f_number", "--on-error", "skip")
    assert code == 1 and out == "8.0\n\n\n4.0\n"


def test_extra_cells_and_bad_json_lines_are_skippable() -> None:
    code, out, err = batch("f-number,distance\n8,3\n8,3,4\n4,2\n", "dof", "-f", "50", "--field", "f_number",
                           "--on-error", "skip")
    assert code == 1 and out == "8.0\n\n4.0\n" and "row 2: 3 cells, more than the 2 header columns" in err
    text = '{"f_number": 8, "distance": 3}\n{"f_number": 8,\n[1]\n{"f_number": 4, "distance": 2}\n'
    code, out, err = batch(text, "dof", "-f", "50", "--field", "f_number", "--on-error", "skip")
    assert code == 1 and out == "8.0\n\n\n4.0\n"
    assert "row 2: not valid JSON" in err and "row 3: expected a JSON object" in err


def test_other_columns_pass_through_so_results_join_back() -> None:
    # exiftool -csv -FocalLength -FNumber writes SourceFile first and "50.0 mm" cells
    text = "SourceFile,FocalLength,FNumber\na.jpg,50.0 mm,8.0\nb.jpg,85.0 mm,x\nc.jpg,24.0 mm,4.0\n"
    code, out, _ = batch(text, "dof", "-s", "3m", "--format", "csv", "--on-error", "skip")
    lines = out.splitlines()
    assert code == 1
    assert lines[0].startswith("SourceFile,focal_length_mm,f_number,")
    assert lines[1].startswith("a.jpg,50.0,8.0,") and lines[2] == "b.jpg" + "," * lines[0].count(",")
    assert lines[3].startswith("c.jpg,24.0,4.0,")
    code, out, _ = batch('{"file": "a.jpg", "focal_length": 50, "f_number": 8}\n', "dof", "-s", "3", "--format",
                         "json")
    assert code == 0 and json.loads(out)[0]["file"] == "a.jpg"


def test_near_miss_of_an_option_name_is_an_error_not_a_passed_column() -> None:
    code, _, err = batch("focal-lenght,f-number\n50,8\n", "dof", "-s", "3")
    assert code == 2
    assert err == ("Error: --batch: column 'focal-lenght' names no option; did you mean --focal-length? (a column "
                   "that names no option is passed through to the output: rename it to keep it)\n")


def test_field_values_for_shell() -> None:
    result = run("dof", "-f", "24", "-N", "8,16", "-s", "inf", "--field", "near_mm", "--field", "far_mm")
    lines = result.stdout.splitlines()
    assert len(lines) == 2 and all(line.endswith("\tinf") for line in lines)
    assert float(lines[0].split("\t")[0]) == pytest.approx(thin_dof(24.0, 8.0, 43.266615305567875 / 1500,
                                                                    float("inf")).near_mm)


def test_unknown_field_lists_keys() -> None:
    result = run("hyperfocal", "-f", "24", "-N", "8", "--field", "far_mm")
    assert result.exit_code == 2
    assert result.stderr.startswith("Error: Invalid value for '--field': 'far_mm' is not a key of this output; "
                                    "valid: focal_length_mm, f_number, hyperfocal_mm")


def test_stop_names_the_bad_row_not_the_first_of_its_group() -> None:
    # rows 1-3 share their settings and run as one vectorised group; only row 3 is too close to focus
    code, out, err = batch("f-number,distance\n8,3\n11,2\n8,0.01\n", "dof", "-f", "50", "--format", "json")
    assert code == 2 and [row["f_number"] for row in json.loads(out)] == [8.0, 11.0]
    assert err.startswith("Error: --batch row 3: Invalid value for '-s' / '--distance': 10 mm is outside")


def test_the_rows_a_failed_range_check_names_are_set_aside_without_halving(monkeypatch: pytest.MonkeyPatch) -> None:
    """A chunk of 2,000 rows with 40 focus distances inside the closest focus: the range check names the bad rows,
    each is computed alone for its message and the rest in one call (a few dozen calls where halving made over a
    thousand), and the output is byte for byte the one halving gives."""
    from camtool.cli import batch as batch_module

    rng = random.Random(5)
    lines = ["focal_length,f_number,distance"]
    for row in range(2000):
        distance = "0.01m" if row % 50 == 7 else f"{rng.uniform(1, 30):.3f}m"
        lines.append(f"{rng.choice((24, 50, 85))},{rng.choice((2.8, 8))},{distance}")
    text = "\n".join(lines) + "\n"
    calls = []
    owner = batch_module._Batch
    compute = owner._compute_group

    def counted(self, members, values):  # type: ignore[no-untyped-def]
        calls.append(len(members))
        return compute(self, members, values)

    monkeypatch.setattr(owner, "_compute_group", counted)
    named = batch(text, "dof", "--format", "csv", "--on-error", "skip")
    named_calls = len(calls)
    calls.clear()
    monkeypatch.setattr(batch_module, "_named_rows", lambda error, size: None)  # halving alone
    halved = batch(text, "dof", "--format", "csv", "--on-error", "skip")
    assert named == halved and named[0] == 1 and named[2].count("skipped") >= 1
    assert named_calls <= 45 < 400 < len(calls), (named_calls, len(calls))
