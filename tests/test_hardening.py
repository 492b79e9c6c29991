"""Regression tests for "every input a right answer or a clear error": one or more per defect found.

Expected numbers come from the thin-lens formulas evaluated here independently
(H = f²/(N·c) + f from the lens, plus the image distance f + N·c from the
sensor; c = d/1500 of the sensor diagonal d), from the sizes the shipped
presets carry, and from identities of the thin-lens limits.
"""

from __future__ import annotations

import errno
import json
import math
import os
from pathlib import Path

import pytest
from cli_helpers import run, run_json

from camtool.core import ranges
from camtool.core.files import FileProblem, check_yaml, load_yaml
from camtool.dof.inverse import focus_for_limits_at


@pytest.fixture(autouse=True)
def isolated(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    for name in ("XDG_CONFIG_HOME", "XDG_DATA_HOME", "XDG_CACHE_HOME"):
        monkeypatch.setenv(name, str(tmp_path / name.lower()))
    monkeypatch.setenv("XDG_CONFIG_DIRS", str(tmp_path / "etc-xdg"))


def error_line(*args: str, code: int = 2) -> str:
    result = run(*args)
    assert result.exit_code == code, (result.exit_code, result.stdout, result.stderr)
    assert result.stdout == "" and result.stderr.count("\n") == 1 and result.stderr.startswith("Error: ")
    return result.stderr.strip()


def hyperfocal_from_sensor(f: float, n: float, w: float, h: float) -> float:
    c = math.hypot(w, h) / 1500
    return f * f / (n * c) + f + f + n * c


# --- --sensor: presets win over inline sizes ------------------------------------------------------------


@pytest.mark.parametrize("name", ["4x5", "5x4", "6x6", "6x7", "6x9", "8x10"])
def test_film_format_names_are_presets_not_millimetres(name: str) -> None:
    from camtool.presets import load_db

    preset = load_db(use_cache=False).sensor(name)
    w, h = preset.width_mm, preset.height_mm
    assert w > 50  # a film format, not a chip of a few millimetres
    (row,) = run_json("hyperfocal", "-f", "150", "-N", "22", "--sensor", name)
    assert row["hyperfocal_mm"] == pytest.approx(hyperfocal_from_sensor(150, 22, w, h), rel=1e-12)
    assert row["coc_mm"] == pytest.approx(math.hypot(w, h) / 1500, rel=1e-12)
    # read as millimetres, 4x5 gave H = 239.9 m at f/22 with 150 mm; the preset gives about 10 m
    assert row["hyperfocal_mm"] < 0.1 * hyperfocal_from_sensor(150, 22, 5, 4)
    table = run("hyperfocal", "-f", "150", "-N", "22", "--sensor", name).stdout
    assert f"--sensor {name} is the preset; write {name}mm for a size in mm" in table


@pytest.mark.parametrize(("text", "w", "h"), [("5x4in", 127.0, 101.6), ("4x5mm", 5.0, 4.0), ("6x7cm", 70.0, 60.0),
                                              ("36mm x 24mm", 36.0, 24.0), ("1.5inx1in", 38.1, 25.4)])
def test_inline_sizes_take_units(text: str, w: float, h: float) -> None:
    result = run("fov", "-f", "50", "--sensor", text, "--format", "json")
    assert result.exit_code == 0, result.stderr
    (row,) = json.loads(result.stdout)
    assert (row["sensor_width_mm"], row["sensor_height_mm"]) == pytest.approx((w, h), rel=1e-12)


def test_inline_size_out_of_range_names_sensor_and_range() -> None:
    assert error_line("fov", "-f", "50", "--sensor", "1e9x3") == (
        "Error: Invalid value for '--sensor': 1e9x3 is outside the valid range: each side 0.5 to 2000 mm")


# --- infinity focus is a distance everywhere ---------------------------------------------------------------


def test_fov_at_infinity_focus() -> None:
    (inf_row, near_row) = run_json("fov", "-f", "50", "-s", "inf,3")
    (plain,) = run_json("fov", "-f", "50")
    assert inf_row["magnification"] == 0.0 and inf_row["field_width_mm"] is None  # inf is null in JSON
    assert inf_row["horizontal_deg"] == plain["horizontal_deg"]
    assert near_row["field_width_mm"] > 0


def test_fov_at_infinity_in_a_batch(tmp_path: Path) -> None:
    batch = tmp_path / "rows.csv"
    batch.write_text("focal-length,distance\n50,inf\n50,3\n")
    result = run("fov", "--batch", str(batch), "--format", "json")
    assert result.exit_code == 0, result.stderr
    assert [row["magnification"] == 0.0 for row in json.loads(result.stdout)] == [True, False]


# --- the inverse with a fixed f-number ----------------------------------------------------------------------


def test_focus_keeps_the_f_number_given() -> None:
    (row,) = run_json("focus", "-f", "24", "-N", "11", "--near", "1m", "--far", "inf")
    (free,) = run_json("focus", "-f", "24", "--near", "1m", "--far", "inf")
    assert row["f_number"] == 11.0 and row["needed_f_number"] == pytest.approx(free["f_number"], rel=1e-12)
    assert row["distance_mm"] == pytest.approx(free["distance_mm"], rel=1e-12)
    assert row["near_mm"] < 1000.0 and row["far_mm"] is None  # deeper than asked on the near side, to infinity


@pytest.mark.parametrize(("n", "near", "far"), [(16.0, 2000.0, 4000.0), (8.0, 3000.0, 3500.0), (64.0, 1000.0, math.inf)])
def test_fixed_f_number_focus_identities(n: float, near: float, far: float) -> None:
    f, c = 50.0, 0.03
    s = focus_for_limits_at(f, n, c, near, far, distance_from="lens")
    # the focus is the harmonic mean of the wanted limits
    assert 2.0 / s.distance_mm == pytest.approx(1.0 / near + 1.0 / far, rel=1e-12)
    # thin-lens limits from the lens: 1/near = 1/u + K(1 − f/u), 1/far = max(1/u − K(1 − f/u), 0), K = N·c/f²
    k = n * c * (1.0 - f / s.distance_mm) / f**2
    assert 1.0 / s.near_mm == pytest.approx(1.0 / s.distance_mm + k, rel=1e-12)
    assert 1.0 / s.far_mm == pytest.approx(max(1.0 / s.distance_mm - k, 0.0), rel=1e-9, abs=1e-18)
    assert s.near_mm <= near and s.far_mm >= far


def test_fixed_f_number_too_wide_names_n_and_what_it_needs() -> None:
    line = error_line("focus", "-f", "24", "-N", "8", "--near", "1m", "--far", "inf")
    assert line.startswith("Error: Invalid value for '-N' / '--f-number': 8 is outside the valid range: f/10.4 or more")
    assert "at f/8 the best focus gives" in line


# --- --presets files -------------------------------------------------------------------------------------------


def test_missing_presets_file_is_exit_1_even_unused() -> None:
    assert error_line("dof", "-f", "50", "-N", "8", "-s", "3", "--presets", "/nonexistent.yaml", code=1) == (
        "Error: Invalid value for '--presets': /nonexistent.yaml: cannot read the file: " + os.strerror(errno.ENOENT))  # the C library's words


def test_broken_presets_file_is_exit_1_with_line_even_unused(tmp_path: Path) -> None:
    broken = tmp_path / "broken.yaml"
    broken.write_text("sensors:\n  - id: x\n    width_mm: [1\n")
    line = error_line("dof", "-f", "50", "-N", "8", "-s", "3", "--presets", str(broken), code=1)
    assert line.startswith(f"Error: Invalid value for '--presets': {broken}:")


# --- every error names the option typed -------------------------------------------------------------------------


# These three ended in "Invalid value: ..." naming no option. Close-up focusing beyond 1:1 now answers
# two of them; whichever way each goes, an error must name the option typed.
@pytest.mark.parametrize(("args", "blamed"), [
    (["hyperfocal", "-f", "24", "-N", "1024", "--distance-from", "lens"], "'-N' / '--f-number': 1024"),
    (["hyperfocal", "-f", "24", "-N", "1024", "--model", "approx"], "'-N' / '--f-number': 1024 gives"),
    (["compose", "--magnification", "2", "-f", "50", "--distance-from", "lens", "-N", "8"], "'--magnification': 2"),
])
def test_derived_values_answer_or_blame_the_option_typed(args: list[str], blamed: str) -> None:
    result = run(*args, "--format", "json")
    if result.exit_code == 0:
        for row in json.loads(result.stdout):
            assert all(v >= 0 for k, v in row.items() if k.endswith("_mm") and isinstance(v, float))
    else:
        assert result.exit_code == 2
        assert result.stderr.startswith(f"Error: Invalid value for {blamed}") and result.stderr.count("\n") == 1


def test_coc_rule_px_0_blames_coc_rule() -> None:
    line = error_line("dof", "-f", "50", "-N", "8", "-s", "3", "--coc-rule", "px:0", "--pixel-pitch", "4")
    assert line.startswith("Error: Invalid value for '--coc-rule': px:0 gives a CoC of 0 mm")


# --- units and the physical domain ------------------------------------------------------------------------------


def test_bare_pixel_pitch_is_micrometres() -> None:
    (row,) = run_json("dof", "-f", "50", "-N", "8", "-s", "3", "--coc-rule", "px:2", "--pixel-pitch", "4.3")
    assert row["coc_mm"] == pytest.approx(2 * 4.3e-3, rel=1e-12)
    (same,) = run_json("dof", "-f", "50", "-N", "8", "-s", "3", "--coc-rule", "px:2", "--pixel-pitch", "4.3um")
    assert same["coc_mm"] == row["coc_mm"]
    assert error_line("dof", "-f", "50", "-N", "8", "-s", "3", "--coc-rule", "px:2", "--pixel-pitch", "4.3mm") == (
        "Error: Invalid value for '--pixel-pitch': 4.3mm is outside the valid range: 0.2 to 100 µm")


@pytest.mark.parametrize(("args", "message"), [
    (["-f", "1e-20"], "Error: Invalid value for '-f' / '--focal-length': 1e-20 is outside the valid range: 1 to 5000 mm"),
    (["-f", "5001"], "Error: Invalid value for '-f' / '--focal-length': 5001 is outside the valid range: 1 to 5000 mm"),
    (["--coc", "1e17"], "Error: Invalid value for '--coc': 1e17 is outside the valid range: 0.0005 to 1 mm"),
    (["-N", "2048"], "Error: Invalid value for '-N' / '--f-number': 2048 is outside the valid range: 0.7 to 1024 "
                     "(written 8, f/8 or f8)"),
    (["-s", "1e16m"], "Error: Invalid value for '-s' / '--distance': 1e16m is outside the valid range: "
                      "> 0 to 1e+12 m, or inf"),
    (["--hiatus", "-300"], "Error: Invalid value for '--hiatus': -300 mm is outside the valid range: more than -50 mm "
                           "(the entrance pupil in front of the sensor) and at most 500 mm (10 × focal length) for "
                           "f = 50 mm"),
])
def test_absurd_values_are_domain_errors(args: list[str], message: str) -> None:
    base = {"-f": "50", "-N": "8", "-s": "3"}
    base.pop(args[0], None)
    assert error_line("dof", *[x for kv in base.items() for x in kv], *args) == message


def test_domain_bounds_come_from_the_library_constants() -> None:
    from camtool.cli.options import COC_MM, FOCAL_MM

    assert FOCAL_MM.bounds == ranges.FOCAL_LENGTH_MM and COC_MM.bounds == ranges.COC_MM
    assert ranges.F_NUMBER == (0.7, 1024.0)  # docs/design.md §6.1


# --- the guarded reader and the preset cache ---------------------------------------------------------------------


def test_duplicate_keys_name_both_lines() -> None:
    with pytest.raises(FileProblem) as raised:
        load_yaml("sensors:\n  - id: a\n    width_mm: 20\n    height_mm: 10\n    width_mm: 21\n", "f.yaml")
    assert str(raised.value) == "f.yaml:5: duplicate key 'width_mm' (lines 3 and 5)"


def test_same_key_in_different_mappings_is_fine() -> None:
    check_yaml("a: {x: 1}\nb: {x: 2}\nc: [{x: 1}, {x: 2}]\n", "f.yaml")


def test_alias_bomb_is_refused_from_the_event_stream() -> None:
    bomb = "a: &a [x, x, x, x, x, x, x, x, x]\n" + "".join(
        f"{chr(98 + i)}: &{chr(98 + i)} [" + ", ".join([f"*{chr(97 + i)}"] * 9) + "]\n" for i in range(9))
    with pytest.raises(FileProblem, match="expands to more than 2,000,000 nodes"):
        check_yaml(bomb, "bomb.yaml")


def test_cache_follows_content_not_size_and_mtime(tmp_path: Path) -> None:
    path = tmp_path / "mine.yaml"
    path.write_text("sensors:\n  - {id: mine, width_mm: 20, height_mm: 10}\n")
    stamp = os.stat(path)
    (first,) = run_json("fov", "-f", "50", "--sensor", "mine", "--presets", str(path))
    path.write_text("sensors:\n  - {id: mine, width_mm: 30, height_mm: 10}\n")  # same size
    os.utime(path, ns=(stamp.st_atime_ns, stamp.st_mtime_ns))
    assert os.stat(path).st_size == stamp.st_size and os.stat(path).st_mtime_ns == stamp.st_mtime_ns
    (second,) = run_json("fov", "-f", "50", "--sensor", "mine", "--presets", str(path))
    assert (first["sensor_width_mm"], second["sensor_width_mm"]) == (20.0, 30.0)


# --- man pages ----------------------------------------------------------------------------------------------------


def test_man_pages_describe_once_and_list_output_keys() -> None:
    from camtool.cli.manpage import key_unit, pages

    generated = pages()
    top = generated["camtool.1"]
    assert "\\fBcamtool\\fR [\\fIOPTIONS\\fR] \\fICOMMAND\\fR [\\fIARGS\\fR]..." in top
    description = top.split(".SH DESCRIPTION\n", 1)[1].split(".SH ", 1)[0]
    assert "    " not in description and description.count("Lengths take") == 0
    assert top.count("Lengths take a unit") == 1
    for page, keys in (("camtool-dof.1", ["near_mm", "far_mm", "hyperfocal_mm", "f_number", "model"]),
                       ("camtool-fov.1", ["horizontal_deg", "field_width_mm"]),
                       ("camtool-exposure.1", ["shutter_s", "ev100"])):
        section = generated[page].split(".SH OUTPUT KEYS\n", 1)[1].split(".SH ", 1)[0]
        for key in keys:
            assert f"\\fB{key.replace('_', '_')}\\fR\n{key_unit(key).replace('-', chr(92) + '-')}" in section
    assert key_unit("near_mm") == "millimetres" and key_unit("horizontal_deg") == "degrees"
