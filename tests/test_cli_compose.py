"""camtool compose through click: JSON against the library, the table, errors."""

from __future__ import annotations

import math

import pytest
from cli_helpers import run, run_json

from camtool.dof.ladder import depth_of_field
from camtool.geometry.compose import composition, magnification_for_fill, plane_view

FF_COC_D1500 = math.hypot(36, 24) / 1500  # the default CoC rule on the default sensor (36 × 24 mm)


def test_default_focal_lengths_and_dolly_zoom() -> None:
    rows = run_json("compose", "--subject-size", "1.8m", "--fill", "0.8")
    assert [r["focal_length_mm"] for r in rows] == [24.0, 35.0, 50.0, 85.0, 135.0, 200.0]  # issue 4's default list
    m = magnification_for_fill(1800.0, 0.8, 24.0)
    for r in rows:
        expected = composition(r["focal_length_mm"], m, 36.0, 24.0)
        assert r["distance_mm"] == pytest.approx(expected.distance_mm, rel=1e-15)
        assert r["horizontal_deg"] == pytest.approx(expected.horizontal_deg, rel=1e-15)
        assert r["field_height_mm"] == pytest.approx(1800.0 / 0.8, rel=1e-12)  # constant down the table
        assert r["near_mm"] is None and r["background_blur_mm"] is None
        assert r["distance_from"] == "sensor"


def test_lens_plane_and_width_axis() -> None:
    (row,) = run_json("compose", "--subject-size", "3.6", "--fill", "1", "--fill-axis", "width", "-f", "50",
                      "--distance-from", "lens")
    # 3.6 m across 36 mm: m = 0.01, s = f(1 + 1/m) = 5050 mm from the lens.
    assert row["magnification"] == pytest.approx(0.01, rel=1e-15)
    assert row["distance_mm"] == pytest.approx(5050.0, rel=1e-15)
    assert row["distance_from"] == "lens"


def test_background_and_limits_match_the_library() -> None:
    rows = run_json("compose", "--subject-size", "1.8m", "--fill", "0.8", "-N", "2.8", "--background", "20m",
                    "-f", "35,85,200")
    m = magnification_for_fill(1800.0, 0.8, 24.0)
    for r in rows:
        f = r["focal_length_mm"]
        view = plane_view(f, 2.8, m, 36.0, 20000.0, reference_focal_length_mm=35.0)
        limits = depth_of_field("thin", f, 2.8, FF_COC_D1500, r["distance_mm"], "sensor").limits
        assert r["background_scale"] == pytest.approx(view.scale, rel=1e-15)
        assert r["background_blur_mm"] == pytest.approx(view.blur_mm, rel=1e-15)
        assert r["background_blur_pct"] == pytest.approx(view.blur_pct, rel=1e-15)
        assert r["near_mm"] == pytest.approx(limits.near_mm, rel=1e-14)
        assert r["far_mm"] == pytest.approx(limits.far_mm, rel=1e-14)
    assert rows[0]["background_scale"] == 1.0


def test_background_at_infinity_and_foreground() -> None:
    rows = run_json("compose", "--magnification", "0.02", "-N", "4", "--background", "inf", "--foreground", "1m",
                    "-f", "50,100")
    assert [r["background_blur_mm"] for r in rows] == pytest.approx([0.25, 0.5])  # f·m/N, scaling with f
    assert rows[0]["background_width_mm"] is None  # infinite: null in JSON
    assert rows[1]["background_scale"] == pytest.approx(2.0)  # f/f_ref for a plane at infinity
    view = plane_view(100.0, 4.0, 0.02, 36.0, -1000.0, reference_focal_length_mm=50.0)
    assert rows[1]["foreground_blur_mm"] == pytest.approx(view.blur_mm, rel=1e-15)


TABLE = """\
   f   distance             horizontal   vertical   field width   field height
(mm)        (m)         m          (°)        (°)           (m)            (m)
──────────────────────────────────────────────────────────────────────────────
  24      2.298   0.01067        73.16      52.65         3.375          2.250
  85      8.140   0.01067        23.67      15.90         3.375          2.250
full frame 36 × 24 mm · from the sensor plane · subject 1.8 m fills 0.8 of the height
"""


def test_table_snapshot() -> None:
    assert run("compose", "--subject-size", "1.8m", "--fill", "0.8", "-f", "24,85").stdout == TABLE


@pytest.mark.parametrize(
    ("args", "message"),
    [
        (["-f", "50"], "Error: Give --subject-size and --fill, or --magnification."),
        (["--subject-size", "1.8", "--fill", "0"],
         "Error: Invalid value for '--fill': 0 is outside the valid range: 0.001 to 10"),
        (["--subject-size", "1.8", "--fill", "0.8", "--background", "5"],
         "Error: --background and --foreground need -N for the blur disc."),
        (["--magnification", "0.02", "-N", "4", "--foreground", "3m", "-f", "50"],
         "Error: Invalid value for '--foreground': 3 m is outside the valid range: "
         "less than the distance from the subject to the lens's front focal point"),
        (["--subject-size", "1.8", "--fill", "0.8", "-f", "0"],
         "Error: Invalid value for '-f' / '--focal-length': 0 is outside the valid range: 1 to 5000 mm"),
        (["--subject-size", "1.8", "--fill", "0.8", "-N", "0.5"],
         "Error: Invalid value for '-N' / '--f-number': 0.5 is outside the valid range: 0.7 to 1024 "
         "(written 8, f/8 or f8)"),
    ],
)
def test_errors_are_one_line_exit_2(args: list[str], message: str) -> None:
    result = run("compose", *args)
    assert result.exit_code == 2
    assert result.stdout == ""
    assert result.stderr == message + "\n"
