"""No NaN, no raw control character, ever reaches the output: the row writer's last line of defence, and the paths
that used to feed it (a lens focused at infinity through the close-up planner)."""

from __future__ import annotations

import io
import json
import math

import numpy as np
import pytest
from cli_helpers import run, run_json, time_bound  # noqa: F401

from camtool.presets import load_db
from camtool.render.columnar import ColumnRows
from camtool.render.columns import TEXT, Column
from camtool.render.output import RowWriter
from camtool.render.serial import ERROR, printable

COLUMNS = [Column("a", "a"), Column("b", "b", TEXT)]
HOSTILE = "Canon\x1b]0;owned\x07\x1b[2J\r\nEOS\x9b1m\u2028x"


def _written(fmt: str, rows, fields=()) -> str:
    out = io.StringIO()
    writer = RowWriter(fmt, fields=fields, stream=out)
    writer.write(rows, COLUMNS, ["a", "b"])
    writer.close()
    return out.getvalue()


def _no_control(text: str, structure: str = "\n") -> bool:
    # the writers' own structure (newlines between rows, tabs between fields) aside, no control character at all
    return not any((ord(ch) < 0x20 and ch not in structure) or 0x7F <= ord(ch) <= 0x9F or ch in "\u2028\u2029" for ch in text)


@pytest.mark.parametrize("fmt", ["table", "json", "csv"])
@pytest.mark.parametrize("columnar", [False, True])
def test_a_nan_is_withheld_with_a_reason_in_every_format(fmt: str, columnar: bool) -> None:
    rows = (ColumnRows(3, {"a": np.array([1.0, np.nan, 2.0]), "b": "x"}) if columnar
            else [{"a": 1.0, "b": "x"}, {"a": float("nan"), "b": "x"}, {"a": 2.0, "b": "x"}])
    text = _written(fmt, rows)
    assert "nan" not in text.lower()
    if fmt == "json":
        data = json.loads(text)
        assert [row["a"] for row in data] == [1.0, None, 2.0]
        assert "no answer for a" in data[1][ERROR] and ERROR not in data[0]
    elif fmt == "csv":
        assert text.splitlines()[2].split(",")[0] == ""
    else:
        assert "row 2: no answer for a" in text


@pytest.mark.parametrize("fmt", ["table", "json", "csv", "field"])
def test_control_characters_from_a_string_cell_are_escaped(fmt: str) -> None:
    fields = ("b", "a") if fmt == "field" else ()
    text = _written("json" if fmt == "field" else fmt, [{"a": 1.0, "b": HOSTILE}], fields)
    assert _no_control(text, "\n\t" if fmt == "field" else "\n")
    shown = json.loads(text)[0]["b"] if fmt == "json" else text
    assert "\\x1b]0;owned\\x07" in shown
    if fmt == "field":
        assert text.count("\n") == 1 and text.count("\t") == 1  # one row, one line, two fields


def test_printable_escapes_every_control_character_and_keeps_the_rest() -> None:
    for code in [*range(0x20), *range(0x7F, 0xA0), 0x2028, 0x2029]:
        shown = printable(f"a{chr(code)}b")
        assert shown.startswith("a\\") and shown.endswith("b") and _no_control(shown)
    assert printable("50 mm f/1.8 × ∞ µm") == "50 mm f/1.8 × ∞ µm"


def _focusing_lenses() -> list[str]:
    """Every shipped lens preset that publishes a closest focus (the close-up planner's internal-focus path)."""
    return sorted(lens.id for lens in load_db().all("lens")
                  if lens.prescription is None and (lens.close_focus or lens.min_focus_mm) and not lens.min_magnification)


def test_a_macro_only_lens_at_infinity_is_one_line_naming_the_distance() -> None:
    result = run("dof", "--lens", "canon-mp-e-65mm-f2.8-1-5x-macro", "-N", "8", "-s", "inf")
    assert result.exit_code == 2 and result.stderr.count("\n") == 1 and "-s" in result.stderr, result.stderr


@pytest.mark.parametrize("lens", _focusing_lenses())
def test_every_focusing_lens_focused_at_infinity_has_its_hyperfocal_distance_as_near_limit(lens: str) -> None:
    # Thin lens focused at infinity: the near limit u·f²/(f² + Nc(u − f)) tends to f²/(Nc) from the lens, with the
    # focal length in effect at infinity (tests/test_one_answer.py checks the hyperfocal distance itself, solved at
    # the focal length in effect there). Neither may be a NaN or a traceback, in JSON or in the table.
    preset = load_db().lens(lens)
    args = ["dof", "--lens", lens, "-s", "inf", "--model", "thin"]
    if preset.is_zoom:
        args += ["-f", repr(preset.focal_min_mm)]
    n = max(8.0, preset.f_number_min or 1.0)
    args += ["-N", repr(min(n, preset.f_number_max) if preset.f_number_max else n)]  # a fixed f/4.5 takes only f/4.5
    for plane in ("lens", "sensor"):
        for row in run_json(*args, "--distance-from", plane):
            assert row["far_mm"] is None  # infinity
            f, n, c = row["focal_length_at_focus_mm"], row["f_number"], row["coc_mm"]
            if plane == "lens":
                assert math.isclose(row["near_mm"], f * f / (n * c), rel_tol=1e-9)
            assert 0 < row["near_mm"] < math.inf and 0 < row["hyperfocal_mm"] < math.inf
    table = run(*args)
    assert table.exit_code == 0, table.output
    assert "∞" in table.stdout


@pytest.mark.parametrize("k", ["1.4", "2"])
def test_a_teleconverter_at_infinity_answers(k: str) -> None:
    (row,) = run_json("dof", "-f", "200", "-N", "4", "-s", "inf", "--teleconverter", k, "--model", "thin",
                      "--distance-from", "lens")
    f, n, c = row["focal_length_at_focus_mm"], row["f_number"], row["coc_mm"]
    assert row["far_mm"] is None and math.isclose(row["near_mm"], f * f / (n * c), rel_tol=1e-9)
    assert math.isclose(row["focal_length_mm"], 200 * float(k)) and math.isclose(row["f_number"], 4 * float(k))


def test_model_all_with_a_row_where_nothing_is_sharp_prints_every_row() -> None:
    # f/64 at 1:1 on a 0.0288 mm CoC: the Airy disc, 2.44·λ·N(1 + m) = 2.44 × 550e-6 × 128 ≈ 0.17 mm, fills it
    for fmt in ("table", "json"):
        result = run("dof", "-f", "100", "-N", "8,64", "-s", "400mm", "--diffraction", "--model", "all", "--format", fmt)
        assert result.exit_code == 0, result.output
    rows = run_json("dof", "-f", "100", "-N", "8,64", "-s", "400mm", "--diffraction", "--model", "all")
    assert {row["f_number"] for row in rows if row["near_mm"] is None} == {64.0}
    assert all(row["reason"] for row in rows if row["near_mm"] is None)


def test_model_all_claims_no_key_it_leaves_null() -> None:
    for row in run_json("dof", "-f", "50", "-N", "8", "-s", "3m", "--model", "all"):
        assert None not in row.values(), row


@pytest.mark.parametrize("command", [
    "dof -f 50 -N 8 -s 3m", "fov -f 24,50", "hyperfocal -f 24 -N 8", "exposure -N 8 -t 1/60 --nd ND1000",
    "stars -f 24 -N 2.8 --pixel-pitch 4.3", "flash --gn 40 -N 8 --iso 400", "equiv -f 25 -N 1.4 --sensor m43",
    "compose --subject-size 1.8m --fill 0.8 -N 2.8", "focus -f 100 -s 0.5m -N 8", "tilt -f 90 -N 11 -s 2m --tilt 3",
    "stack -m 1 -N 8 --depth 10mm", "presets list --kind sensor"])
@pytest.mark.parametrize("columns", ["1", "20", "45"])
def test_a_narrow_terminal_leaves_columns_out_but_never_crops_a_number(command: str, columns: str) -> None:
    wide = run(*command.split())
    narrow = run(*command.split(), env={"COLUMNS": columns})
    assert wide.exit_code == narrow.exit_code == 0, narrow.output
    shown = set(wide.stdout.split())
    # (a table too narrow for its answers becomes blocks of "header (unit): value"; the labels are headers)
    assert [word for word in narrow.stdout.split() if word not in shown and any(ch.isdigit() for ch in word)
            and not word.endswith(":")] == []


def test_the_quick_nan_check_of_many_rows_is_the_row_by_row_one() -> None:
    # the rows of a table are checked for a NaN in one pass (camtool.render.serial.any_unanswered) before any is
    # withheld: the same verdict as unanswered() row by row, whatever the values and their types
    import random

    from camtool.render.serial import any_unanswered, unanswered

    kinds = [1.0, -0.0, math.inf, math.nan, np.float64(2.0), np.float64("nan"), np.float32("nan"), "nan", None, 3,
             [math.nan], True]
    chooser = random.Random(7)
    for _ in range(500):
        keys = chooser.sample(["a", "b", "c", "d"], chooser.randint(0, 4))
        rows = [{key: chooser.choice(kinds) for key in chooser.sample(["a", "b", "c", "d", "e"], chooser.randint(0, 5))}
                for _ in range(chooser.randint(0, 4))]
        assert any_unanswered(rows, keys) == any(unanswered(row, keys) for row in rows), (rows, keys)
