"""fov, focus, hyperfocal and the command group through click."""

from __future__ import annotations

import math

import pytest
from cli_helpers import run, run_json

from camtool.cli import COMMANDS, cli
from camtool.dof.closed import hyperfocal_mm, thin_dof
from camtool.dof.inverse import focus_for_limits
from camtool.geometry.fov import field_of_view
from camtool.geometry.thinlens import focus_geometry


def test_hyperfocal_json_both_planes() -> None:
    lens = run_json("hyperfocal", "-f", "50", "-N", "8", "--coc", "0.03", "--distance-from", "lens")
    sensor = run_json("hyperfocal", "-f", "50", "-N", "8", "--coc", "0.03")
    approx = run_json("hyperfocal", "-f", "50", "-N", "8", "--coc", "0.03", "--model", "approx")
    # 50 mm f/8 c = 0.03 mm: H = 10,467 mm with +f, 10,417 mm without (the worked example)
    assert lens[0]["hyperfocal_mm"] == pytest.approx(10466.6667, abs=1e-3)
    assert lens[0]["near_mm"] == pytest.approx(lens[0]["hyperfocal_mm"] / 2, rel=1e-15)
    assert approx[0]["hyperfocal_mm"] == pytest.approx(10416.6667, abs=1e-3)
    # from the sensor the lens-sensor spacing at that focus, f + Nc, is added
    assert sensor[0]["hyperfocal_mm"] == pytest.approx(hyperfocal_mm(50.0, 8.0, 0.03) + 50 + 8 * 0.03, rel=1e-15)
    assert thin_dof(50.0, 8.0, 0.03, sensor[0]["hyperfocal_mm"]).far_mm == math.inf


def test_fov_json_matches_library_and_breathing() -> None:
    rows = run_json("fov", "-f", "24,50")
    for row in rows:
        angles = field_of_view(36.0, 24.0, row["focal_length_mm"])
        assert row["horizontal_deg"] == pytest.approx(angles.horizontal_deg, rel=1e-15)
        assert row["diagonal_deg"] == pytest.approx(angles.diagonal_deg, rel=1e-15)
    (near,) = run_json("fov", "-f", "100", "-s", "0.4m")  # 1:1 from the sensor: 4f
    assert near["magnification"] == pytest.approx(1.0)
    # at 1:1 the image distance is 2f, so the angle is 2·atan(36/400) and the field equals the sensor
    assert near["horizontal_deg"] == pytest.approx(2 * math.degrees(math.atan(36 / 400)))
    assert near["field_width_mm"] == pytest.approx(36.0)


def test_fov_crop_factor_and_equivalent() -> None:
    (row,) = run_json("fov", "-f", "50", "--crop", "1.5")
    assert row["crop_factor"] == pytest.approx(1.5)
    assert row["equivalent_focal_length_mm"] == pytest.approx(75.0)


def test_focus_forward_and_magnification() -> None:
    (row,) = run_json("focus", "-f", "100", "-s", "0.5m", "-N", "8")
    geometry = focus_geometry(100.0, 500.0)
    assert row["image_distance_mm"] == pytest.approx(geometry.image_mm)
    assert row["working_f_number"] == pytest.approx(8 * (1 + geometry.magnification))
    (half,) = run_json("focus", "-f", "100", "-m", "0.5")
    # u = f(1 + 1/m) = 300, v = f(1 + m) = 150: 450 mm from the sensor
    assert half["distance_mm"] == pytest.approx(450.0)
    assert half["extension_mm"] == pytest.approx(50.0)
    assert "working_f_number" not in half


def test_focus_inverse_round_trips() -> None:
    (row,) = run_json("focus", "-f", "35", "--near", "2m", "--far", "10m", "--coc", "0.03")
    expected = focus_for_limits(35.0, 0.03, 2000.0, 10000.0)
    assert row["distance_mm"] == pytest.approx(expected.distance_mm)
    limits = thin_dof(35.0, row["f_number"], 0.03, row["distance_mm"])
    assert limits.near_mm == pytest.approx(2000.0, rel=1e-12)
    assert limits.far_mm == pytest.approx(10000.0, rel=1e-12)


def test_focus_needs_one_of_distance_or_magnification() -> None:
    result = run("focus", "-f", "50")
    assert result.exit_code == 2
    assert result.stderr == "Error: give either -s/--distance or -m/--magnification (or --near and --far)\n"


def test_focus_inverse_far_must_exceed_near() -> None:
    result = run("focus", "-f", "35", "--near", "2m", "--far", "1m")
    assert result.exit_code == 2
    assert result.stderr == ("Error: Invalid value for '--far': 1 m is outside the valid range: "
                             "greater than the near limit 2 m\n")


HYPERFOCAL_TABLE = """\
   f          hyperfocal   sharp from    CoC
(mm)      N          (m)          (m)   (mm)
────────────────────────────────────────────
  24    f/8        2.448        1.236   0.03
  24   f/16        1.248       0.6365   0.03
thin model · CoC 0.03 mm (--coc) · full frame 36 × 24 mm · from the sensor plane
"""

FOV_TABLE = """\
   f   35mm eq.   horizontal   vertical   diagonal
(mm)       (mm)          (°)        (°)        (°)
──────────────────────────────────────────────────
  24         24        73.74      53.13      84.06
  50         50        39.60      26.99      46.79
full frame 36 × 24 mm (crop 1)
"""

FOCUS_TABLE = """\
   f   focus   image dist.   extension                     
(mm)    (mm)          (mm)        (mm)        m   working N
───────────────────────────────────────────────────────────
 100   500.0         138.2        38.2   0.3820      f/11.1
thin model · unit focusing, m = v/u · from the sensor plane · the same distance is also reached at m = 2.62 \
(give -m for that branch)
"""


@pytest.mark.parametrize(
    ("args", "table"),
    [
        (["hyperfocal", "-f", "24", "-N", "8,16", "--coc", "0.03"], HYPERFOCAL_TABLE),
        (["fov", "-f", "24,50"], FOV_TABLE),
        (["focus", "-f", "100", "-s", "0.5m", "-N", "8"], FOCUS_TABLE),
    ],
    ids=["hyperfocal", "fov", "focus"],
)
def test_table_snapshots(args: list[str], table: str) -> None:
    assert run(*args).stdout == table


def test_imperial_table_uses_feet_and_inches() -> None:
    out = run("dof", "-f", "50", "-N", "8", "-s", "10ft", "--units", "imperial", "--model", "thin").stdout
    assert "(ft in)" in out.splitlines()[1] and "(m)" not in out
    # focus 10 ft = 3048 mm exactly; the near limit from thin_dof, in feet and inches (1 in = 25.4 mm)
    near = thin_dof(50.0, 8.0, math.hypot(36, 24) / 1500, 3048.0).near_mm
    inches = round(near / 25.4, 1)
    assert f"{int(inches // 12)}' {inches % 12:.1f}\"" in out.splitlines()[3]
    assert "10' 0.0\"" in out.splitlines()[3]


def test_unknown_command_suggests() -> None:
    result = run("hyperfocl")
    assert result.exit_code == 2
    assert result.stderr == "Error: No such command 'hyperfocl'. Did you mean 'hyperfocal'?\n"


def test_every_command_is_documented() -> None:
    for name in cli.list_commands(None):  # type: ignore[arg-type]
        command = cli.get_command(None, name)  # type: ignore[arg-type]
        assert command is not None and command.help and "Examples" in command.help, name
        assert name in COMMANDS
        result = run(name, "--help")
        assert result.exit_code == 0
        assert "--format" in result.stdout or name in ("presets", "completion")


def test_focus_with_lens_data_uses_pupil_magnification_and_hiatus() -> None:
    (row,) = run_json("focus", "-f", "100", "-s", "0.5m", "-N", "8", "--pupil-mag", "0.5", "--hiatus", "10")
    # from the sensor: u + v = D − δ = 490 mm with 1/u + 1/v = 1/100 (thin-lens geometry between principal planes)
    geometry = focus_geometry(100.0, 500.0, hiatus_mm=10.0)
    assert geometry.object_mm + geometry.image_mm == pytest.approx(490.0)
    assert row["magnification"] == pytest.approx(geometry.magnification)
    # working f-number N(1 + m/P) (Wikipedia, "f-number": working f-number with pupil magnification)
    assert row["working_f_number"] == pytest.approx(8 * (1 + geometry.magnification / 0.5))
    (thin,) = run_json("focus", "-f", "100", "-s", "0.5m", "-N", "8", "--pupil-mag", "1", "--hiatus", "0")
    (plain,) = run_json("focus", "-f", "100", "-s", "0.5m", "-N", "8")
    assert thin == plain  # P = 1, δ = 0 is the thin lens


def test_fov_breathing_with_a_prescription_lens() -> None:
    (row,) = run_json("fov", "--lens", "telephoto127-lens", "-s", "1m")
    # telephoto127: P = 0.734585838879, hiatus z_H' − z_H = 17.6095986414 mm (oracle-README first-order table)
    p, delta, f = 0.734585838879, -20.4991216982 - -38.1087203396, 127.016601138
    geometry = focus_geometry(f, 1000.0, hiatus_mm=delta)
    expected = 2 * math.degrees(math.atan(36.0 / (2 * f * (1 + geometry.magnification / p))))
    assert row["magnification"] == pytest.approx(geometry.magnification, rel=1e-6)
    assert row["horizontal_deg"] == pytest.approx(expected, rel=1e-6)


def test_hyperfocal_with_lens_data_is_thick_and_thin_without() -> None:
    from camtool.dof.thick import thick_dof

    (row,) = run_json("hyperfocal", "-f", "100", "-N", "8", "--coc", "0.03", "--pupil-mag", "0.5", "--hiatus", "10")
    assert row["model"] == "thick"
    # focused at the reported hyperfocal distance the thick model's far limit is infinite, and its near limit
    # is the one reported (camtool.dof.thick, validated against the reference paraxial rows)
    at_h = thick_dof(100.0, 8.0, 0.03, row["hyperfocal_mm"], pupil_magnification=0.5, hiatus_mm=10.0)
    assert at_h.far_mm == math.inf
    assert row["near_mm"] == pytest.approx(at_h.near_mm, rel=1e-12)
    (same,) = run_json("hyperfocal", "-f", "100", "-N", "8", "--coc", "0.03", "--pupil-mag", "1", "--hiatus", "0")
    assert same["model"] == "thin"
    unavailable = run("hyperfocal", "-f", "50", "-N", "8", "--model", "thick")
    assert unavailable.exit_code == 2 and unavailable.stderr.startswith("Error: Invalid value for '--model': thick")
