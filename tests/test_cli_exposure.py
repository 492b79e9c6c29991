"""camtool exposure through click: JSON against the library, the table, errors."""

from __future__ import annotations

import pytest
from cli_helpers import run, run_json

from camtool.exposure import metering
from camtool.exposure.equivalents import equivalent_exposures
from camtool.exposure.ev import exposure_value
from camtool.exposure.nd import parse_nd
from camtool.exposure.plan import plan_exposure
from camtool.exposure.reciprocity import corrected_time_s


def test_settings_give_ev_and_ev100() -> None:
    (row,) = run_json("exposure", "-N", "16", "-t", "1/125")
    assert row["ev"] == pytest.approx(exposure_value(16.0, 1 / 125), rel=1e-15)  # 14.97
    assert row["ev100"] == row["ev"]  # ISO 100 by default
    assert (row["solved"], row["iso"]) == ("ev100", 100.0)
    (row,) = run_json("exposure", "-N", "4", "-t", "1/64", "--iso", "200")
    assert (row["ev"], row["ev100"]) == (10.0, 9.0)  # lightmeter-ev-01 / -02


def test_sunny_16_solves_the_time_per_iso() -> None:
    rows = run_json("exposure", "--light", "sunny", "-N", "16", "--iso", "100,200,400")
    assert [r["shutter_s"] for r in rows] == pytest.approx([1 / 100, 1 / 200, 1 / 400], rel=1e-12)
    assert [r["shutter_nominal_s"] for r in rows] == pytest.approx([1 / 100, 1 / 200, 1 / 400])
    assert {r["solved"] for r in rows} == {"shutter_s"}


@pytest.mark.parametrize(
    ("args", "solved", "expected"),
    [
        (["--ev100", "9", "-N", "4", "-t", "1/64"], "iso", 200.0),
        (["--ev100", "10", "-t", "1/64"], "f_number", 4.0),
        (["--ev", "10", "-N", "4"], "shutter_s", 1 / 64),
    ],
)
def test_solve_for_the_missing_setting(args: list[str], solved: str, expected: float) -> None:
    (row,) = run_json("exposure", *args)
    assert row["solved"] == solved
    assert row[solved] == pytest.approx(expected, rel=1e-12)


def test_nd_bellows_and_reciprocity_match_the_library() -> None:
    (row,) = run_json("exposure", "--ev100", "12", "-N", "8", "--nd", "ND1000", "--nd", "0.3D",
                      "--magnification", "1", "--film", "hp5")
    loss = parse_nd("ND1000").stops + parse_nd("0.3D").stops
    plan = plan_exposure(12.0, 8.0, None, 100.0, loss, 1.0, 1.0, 1.31)
    assert row["nd_stops"] == pytest.approx(loss, rel=1e-15)
    assert row["bellows_stops"] == 2.0
    assert row["shutter_s"] == pytest.approx(plan.shutter_s, rel=1e-15)
    assert row["corrected_shutter_s"] == pytest.approx(corrected_time_s(plan.shutter_s, 1.31), rel=1e-15)


def test_meter_readings() -> None:
    (lux,) = run_json("exposure", "--illuminance", "400", "-N", "4")  # lightmeter-shutter-02: 0.1 s
    assert lux["shutter_s"] == pytest.approx(0.1, rel=1e-12)
    (nits,) = run_json("exposure", "--luminance", "4096", "-N", "16", "--meter-k", "12.5")
    assert nits["ev100"] == pytest.approx(metering.ev_from_luminance(4096.0), rel=1e-15)


def test_equivalents_json() -> None:
    rows = run_json("exposure", "--ev100", "15", "-N", "16", "--equivalents", "--step", "full")
    table = equivalent_exposures(15.0, step="full")
    assert [r["f_number_nominal"] for r in rows] == table.f_number_nominal
    assert [r["shutter_nominal_s"] for r in rows] == table.shutter_nominal_s
    assert all(abs(r["ev"] - 15.0) <= 0.5 for r in rows)


def test_csv_header() -> None:
    result = run("exposure", "-N", "8", "-t", "1/250", "--format", "csv")
    assert result.stdout.splitlines()[0].startswith("f_number,shutter_s,iso,ev,ev100,solved,")


TABLE = """\
N      time    ISO      EV   EV100   nearest stops     
───────────────────────────────────────────────────────
f/16   1/100   100   14.64   14.64   f/16 1/100 ISO 100
f/16   1/200   200   15.64   14.64   f/16 1/200 ISO 200
EV = log2(N²/t) of the settings · EV100 = the scene at ISO 100 · solved: time · nearest third stops
"""


def test_table_snapshot() -> None:
    assert run("exposure", "--light", "sunny", "-N", "16", "--iso", "100,200").stdout == TABLE


@pytest.mark.parametrize(
    ("args", "message"),
    [
        (["-N", "8", "-t", "2000000"],
         "Error: Invalid value for '-t' / '--shutter': 2e+06 is outside the valid range: 1/64000 s to 1000000 s"),
        (["--ev100", "26", "-N", "8"],
         "Error: Invalid value for '--ev100': 26 is outside the valid range: -10 to 25"),
        (["--iso", "0.5", "-N", "8", "-t", "1"],
         "Error: Invalid value for '--iso': 0.5 is outside the valid range: 1 to 1e+07"),
        (["--ev100", "25", "-N", "0.7"],  # names the option typed, not the derived time
         "Error: Invalid value for '--ev100': 25 is outside the valid range: a light level these settings can "
         "expose (time within 1/64000 s to 1000000 s) (it needs a time of 1.46031e-08)"),
        (["--light", "dusk", "-N", "8"],
         "Error: Invalid value for '--light': dusk is outside the valid range: one of snow, sunny, slight-overcast, "
         "overcast, heavy-overcast, shade, sunset, after-sunset, full-moon, bright-street, night-street, office, "
         "home-interior, floodlit-buildings, distant-city-lights, moonlight"),
        (["--ev100", "3", "-N", "8", "--nd", "ND-8"],
         "Error: Invalid value for '--nd': ND-8 is outside the valid range: a factor (ND1000, 1000x), "
         "stops (10stops, 10ev) or an optical density (3.0D, OD3, ND.6, ND0.9)"),
        (["-N", "8", "-t", "1/60", "--nd", "1000"],  # issue 15: a bare number is refused, naming --nd
         "Error: Invalid value for '--nd': 1000 is outside the valid range: a factor (ND1000, 1000x), "
         "stops (10stops, 10ev) or an optical density (3.0D, OD3, ND.6, ND0.9) (a bare number could be any of the three)"),
        (["-N", "8", "-t", "2h30"],  # 2h30 was 7230 s
         "Error: Invalid value for '-t' / '--shutter': '2h30' is ambiguous: give every number its unit "
         "(2h30m or 2h30s) or a clock (2:30:00 is h:mm:ss)"),
        (["--ev", "12", "-N", "8", "-t", "1/125"],
         "Error: --ev is the meter's EV at the ISO in use (default 100), so with -N and -t nothing is left to "
         "solve: leave out one of them, or give --ev100 to solve the ISO."),
        (["-N", "8", "-t", "30", "--nd", "20stops"],
         "Error: Invalid value for '-t' / '--shutter': 30 is outside the valid range: a metered value that keeps "
         "the time to set after the corrections within 1/64000 s to 1000000 s (it would be 3.14573e+07)"),
        (["-N", "8", "-t", "1", "--film", "tmax100", "--nd", "10stops"],
         "Error: Invalid value for '--film': kodak-t-max-100 is outside the valid range: Kodak Professional "
         "T-MAX 100 has published data for metered times up to 100 s"),
        (["--ev100", "3", "-N", "8", "--film", "fp5"],
         "Error: Invalid value for '--film': fp5 is outside the valid range: a known film "
         "(did you mean ilford-fp4-plus, ilford-hp5-plus?)"),
        (["-N", "8"],
         "Error: Give a light level (--ev100, --ev, --light, --luminance, --illuminance) or the metered -N and -t."),
        (["--ev100", "3", "--light", "sunny", "-N", "8"], "Error: Give only one light level: --ev100, --light."),
        (["--ev100", "3", "-N", "8", "-t", "1", "--iso", "100"],
         "Error: With a light level, give at most two of -N, -t, --iso: the third is solved."),
    ],
)
def test_errors_are_one_line_exit_2(args: list[str], message: str) -> None:
    result = run("exposure", *args)
    assert result.exit_code == 2
    assert result.stdout == ""
    assert result.stderr == message + "\n"
