"""The one translator of library errors (camtool.cli.options.bad_parameter) names the option the user typed."""

from __future__ import annotations

from pathlib import Path

from cli_helpers import run

# A strongly curved singlet (R = 10 mm) at f/0.7: the rays of a tilted lens miss its surface
# (the same lens tests/test_raytrace.py uses for rays that miss).
BALL = """id: ball
name: ball
surfaces:
  - {radius_mm: .inf, thickness_mm: 0.0, n: 1.0, stop: true}
  - {radius_mm: 10.0, thickness_mm: 4.0, n: 1.5}
  - {radius_mm: .inf, thickness_mm: 17.3, n: 1.0}
"""


def test_a_ray_trace_that_fails_on_a_typed_prescription_is_a_bad_value(tmp_path: Path) -> None:
    lens = tmp_path / "ball.yaml"
    lens.write_text(BALL, encoding="utf-8")
    result = run("tilt", "-N", "0.7", "-s", "1m", "--tilt", "3", "--prescription", str(lens), "--model", "raytrace")
    assert result.exit_code == 2
    assert result.stderr == ("Error: Invalid value for '--prescription': rays near the chief ray of the tilted lens "
                             "miss a surface\n")


def test_tilt_keeps_its_own_placements() -> None:
    # --at is shown in metres, whatever its size; two movements are one refused combination
    result = run("tilt", "-f", "90", "-N", "11", "-s", "2m", "--tilt", "3", "--at", "0.01m")
    assert result.exit_code == 2 and result.stderr.startswith("Error: Invalid value for '--at': 0.01 m is outside")
    result = run("tilt", "-f", "90", "-N", "11", "-s", "2m", "--tilt", "3", "--swing", "2")
    assert result.exit_code == 2 and "--tilt or --swing, not both" in result.stderr


def test_settings_errors_spell_the_options() -> None:
    result = run("exposure", "-N", "8", "-t", "1/60", "--film", "hp5", "--reciprocity-p", "1.3")
    assert result.exit_code == 2 and result.stderr == "Error: Give --film or --reciprocity-p, not both.\n"


def test_an_unavailable_model_names_the_options_this_command_has() -> None:
    result = run("tilt", "-f", "90", "-N", "11", "-s", "2m", "--tilt", "3", "--model", "raytrace")
    assert result.exit_code == 2
    assert result.stderr == ("Error: Invalid value for '--model': raytrace is not available here: it needs "
                             "--prescription (or a --lens with one)\n")
