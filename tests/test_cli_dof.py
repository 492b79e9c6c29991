"""camtool dof through click: JSON against the library, the table, errors."""

from __future__ import annotations

import math

import pytest
from cli_helpers import run, run_json

from camtool.dof.closed import approx_dof, thin_dof

FF_COC_D1500 = math.hypot(36, 24) / 1500  # the default CoC rule on the default sensor


def test_json_matches_library_sensor_plane() -> None:
    (row,) = run_json("dof", "-f", "50", "-N", "8", "-s", "3m", "--coc", "0.03")
    expected = thin_dof(50.0, 8.0, 0.03, 3000.0, "sensor")
    assert row["near_mm"] == pytest.approx(expected.near_mm, rel=1e-15)
    assert row["far_mm"] == pytest.approx(expected.far_mm, rel=1e-15)
    assert row["total_mm"] == pytest.approx(expected.total_mm, rel=1e-15)
    assert row["hyperfocal_mm"] == pytest.approx(expected.hyperfocal_mm, rel=1e-15)
    assert row["distance_from"] == "sensor"
    assert row["model"] == "thin"
    assert row["coc_mm"] == 0.03


def test_bare_distance_is_metres_and_units_parse() -> None:
    metres = run_json("dof", "-f", "50", "-N", "8", "-s", "3")
    feet = run_json("dof", "-f", "50", "-N", "8", "-s", "10ft")
    assert metres[0]["distance_mm"] == 3000.0
    assert feet[0]["distance_mm"] == pytest.approx(3048.0)  # 1 ft = 304.8 mm exactly


def test_default_coc_is_d1500_of_full_frame() -> None:
    (row,) = run_json("dof", "-f", "50", "-N", "8", "-s", "3")
    assert row["coc_mm"] == pytest.approx(FF_COC_D1500)


def test_grid_rows_in_order_from_one_call() -> None:
    rows = run_json("dof", "-f", "35,50", "-N", "2.8", "-N", "8", "-s", "2,inf", "--distance-from", "lens",
                    "--coc", "0.03", "--model", "thin")
    assert [(r["focal_length_mm"], r["f_number"], r["distance_mm"]) for r in rows] == [
        (35.0, 2.8, 2000.0), (35.0, 2.8, None), (35.0, 8.0, 2000.0), (35.0, 8.0, None),
        (50.0, 2.8, 2000.0), (50.0, 2.8, None), (50.0, 8.0, 2000.0), (50.0, 8.0, None),
    ]
    for r in rows:
        s = r["distance_mm"] if r["distance_mm"] is not None else math.inf
        expected = thin_dof(r["focal_length_mm"], r["f_number"], 0.03, s, "lens")
        assert r["near_mm"] == pytest.approx(expected.near_mm, rel=1e-14)
        # infinity is null in JSON
        assert r["far_mm"] is None if math.isinf(expected.far_mm) else r["far_mm"] == pytest.approx(expected.far_mm)


def test_approx_model() -> None:
    (row,) = run_json("dof", "-f", "50", "-N", "8", "-s", "3", "--coc", "0.03", "--model", "approx")
    expected = approx_dof(50.0, 8.0, 0.03, 3000.0)
    assert row["model"] == "approx"
    assert row["near_mm"] == pytest.approx(expected.near_mm)
    assert row["hyperfocal_mm"] == pytest.approx(50.0**2 / (8 * 0.03))


def test_exact_stops() -> None:
    (row,) = run_json("dof", "-f", "50", "-N", "5.6", "-s", "3", "--exact-stops")
    assert row["f_number"] == pytest.approx(2 ** (15 / 6))


def test_crop_and_inline_sensor() -> None:
    (crop,) = run_json("dof", "-f", "50", "-N", "8", "-s", "3", "--crop", "2")
    (inline,) = run_json("dof", "-f", "50", "-N", "8", "-s", "3", "--sensor", "18x12")
    assert crop["coc_mm"] == pytest.approx(math.hypot(18, 12) / 1500)
    assert inline["coc_mm"] == pytest.approx(crop["coc_mm"])


def test_csv_has_header_and_empty_infinity() -> None:
    result = run("dof", "-f", "24", "-N", "16", "-s", "inf", "--format", "csv")
    header, line = result.stdout.strip().splitlines()
    keys = header.split(",")
    assert keys[:5] == ["focal_length_mm", "f_number", "distance_mm", "near_mm", "far_mm"]
    values = dict(zip(keys, line.split(",")))
    assert values["far_mm"] == "" and values["distance_mm"] == ""


def test_env_sets_format() -> None:
    result = run("dof", "-f", "50", "-N", "8", "-s", "3", env={"CAMTOOL_FORMAT": "csv"})
    assert result.stdout.startswith("focal_length_mm,")


TABLE = """\
   f         focus    near     far   depth   front    rear       H                           
(mm)     N     (m)     (m)     (m)     (m)    (mm)     (m)     (m)   sharp zone              
─────────────────────────────────────────────────────────────────────────────────────────────
  50   f/8   3.000   2.377   4.078   1.700   622.6   1.078   10.93   ····━━┃━━━·········H····
thin model · CoC 0.0288 mm (d/1500 of 43.3 mm) · full frame 36 × 24 mm · from the sensor plane · ┃ focus, H hyperfocal, ▶ ∞
"""


def test_table_snapshot() -> None:
    assert run("dof", "-f", "50", "-N", "8", "-s", "3m").stdout == TABLE


@pytest.mark.parametrize(
    ("args", "message"),
    [
        (["-N", "0"], "Error: Invalid value for '-N' / '--f-number': 0 is outside the valid range: 0.7 to 1024 (written 8, f/8 or f8)"),
        (["-f", "-50"], "Error: Invalid value for '-f' / '--focal-length': -50 is outside the valid range: 1 to 5000 mm"),
        (["--coc", "0"], "Error: Invalid value for '--coc': 0 is outside the valid range: 0.0005 to 1 mm"),
        (["-s", "0.1"], "Error: Invalid value for '-s' / '--distance': 100 mm is outside the valid range: at least 200 mm from the sensor (the closest focus, 1:1: 4 × focal length)"),
        (["-s", "0.05", "--distance-from", "lens"], "Error: Invalid value for '-s' / '--distance': 50 mm is outside the valid range: more than 50 mm from the lens (the focal length; between f and 2f the magnification is above 1)"),
        (["-s", "3parsecs"], "Error: Invalid value for '-s' / '--distance': '3parsecs' has an unknown unit 'parsecs' (use mm, cm, m, km, in or ft)"),
        (["-s", "nan"], "Error: Invalid value for '-s' / '--distance': 'nan' is not a length (examples: 50mm, 3.5cm, 3m, 10ft, 6in, inf)"),
        (["-N", "f/x"], "Error: Invalid value for '-N' / '--f-number': 'f/x' is not an f-number (examples: 8, f/8, f8)"),
        (["--coc-rule", "px:2"], "Error: Invalid value for '--coc-rule': 'px:2' needs the pixel pitch: give --camera or --pixel-pitch"),
        (["--crop", "0"], "Error: Invalid value for '--crop': 0 is outside the valid range: 0.1 to 100"),
        (["--sensor", "0x24"], "Error: Invalid value for '--sensor': 0x24 is outside the valid range: each side 0.5 to 2000 mm"),
    ],
)
def test_errors_are_one_line_exit_2(args: list[str], message: str) -> None:
    base = {"-f": "50", "-N": "8", "-s": "3"}
    for i in range(len(args) - 1):
        if args[i] in base:
            base.pop(args[i])
    flat = [x for kv in base.items() for x in kv]
    result = run("dof", *flat, *args)
    assert result.exit_code == 2
    assert result.stdout == ""
    assert result.stderr == message + "\n"


def test_missing_option() -> None:
    result = run("dof", "-N", "8", "-s", "3")
    assert (result.exit_code, result.stderr) == (2, "Error: Missing option '-f'.\n")
