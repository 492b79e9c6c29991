"""Metered exposure in, settings out; times, ND spellings, T-stops, films, meters and APEX (issue 15)."""

from __future__ import annotations

import math

import pytest
from cli_helpers import run, run_json

from camtool.core.units import UnitError, parse_t_stop, parse_time
from camtool.exposure import metering
from camtool.exposure.calculator import work_out
from camtool.exposure.ev import ev100
from camtool.exposure.reciprocity import film_time_s, find_film


def test_metered_time_behind_an_nd1000() -> None:
    # Issue 15: 1/60 s metered at f/8, ND1000 on: 1/60 · 1000 = 16.7 s (the factor is 1000, not 2^10).
    (row,) = run_json("exposure", "-N", "8", "-t", "1/60", "--nd", "ND1000")
    assert row["corrected_shutter_s"] == pytest.approx(1000 / 60, rel=1e-12)
    assert row["metered_shutter_s"] == pytest.approx(1 / 60)
    assert row["nd_stops"] == pytest.approx(math.log2(1000))
    assert "16.7s" in run("exposure", "-N", "8", "-t", "1/60", "--nd", "ND1000").stdout


def test_metered_30s_at_iso_800_moved_to_iso_100() -> None:
    # Three stops slower film: 30 s · 8 = 240 s, shown as a bulb time "4m".
    (row,) = run_json("exposure", "-N", "8", "-t", "30", "--iso", "800", "--to-iso", "100")
    assert row["shutter_s"] == pytest.approx(240.0, rel=1e-12)
    assert row["iso_change_stops"] == pytest.approx(3.0)
    assert "4m" in run("exposure", "-N", "8", "-t", "30", "--iso", "800", "--to-iso", "100").stdout


def test_metered_new_f_number_and_solving_the_aperture() -> None:
    (row,) = run_json("exposure", "-N", "8", "-t", "1/60", "--to-f-number", "16")
    assert row["shutter_s"] == pytest.approx(4 / 60, rel=1e-12)  # two stops more time
    (row,) = run_json("exposure", "-N", "8", "-t", "1", "--nd", "2stops", "--solve", "f-number")
    assert row["f_number"] == pytest.approx(4.0, rel=1e-12) and row["shutter_s"] == 1.0
    (row,) = run_json("exposure", "-N", "8", "-t", "1", "--nd", "2stops", "--solve", "iso")
    assert row["iso"] == pytest.approx(400.0, rel=1e-12)


def test_metered_with_film_reciprocity_last() -> None:
    # Ilford's worked example: HP5 Plus, 10 s metered -> 10^1.31 = 20.4 s; the ND comes first.
    (row,) = run_json("exposure", "-N", "11", "-t", "10/1024", "--nd", "10stops", "--film", "hp5")
    assert row["shutter_s"] == pytest.approx(10.0, rel=1e-12)
    assert row["corrected_shutter_s"] == pytest.approx(10**1.31, rel=1e-12)


@pytest.mark.parametrize(("iso", "n", "t"), [(100.0, 8.0, 1 / 125), (400.0, 2.8, 30.0), (3200.0, 16.0, 1 / 4000)])
def test_round_trip_settings_ev100_settings(iso: float, n: float, t: float) -> None:
    level = ev100(n, t, iso)
    back = work_out(ev100=level, f_number=n, iso=iso)
    assert back.values["shutter_s"] == pytest.approx(t, rel=1e-12)
    back = work_out(ev100=level, shutter_s=t, iso=iso)
    assert back.values["f_number"] == pytest.approx(n, rel=1e-12)
    back = work_out(ev100=level, f_number=n, shutter_s=t)
    assert back.values["iso"] == pytest.approx(iso, rel=1e-12)


@pytest.mark.parametrize("args", [["--ev100", "12", "--iso", "100", "--equivalents"], ["--ev100", "12", "--iso", "200"],
                                  ["--light", "sunny", "--iso", "400"]])
def test_two_open_settings_answer_equivalents(args: list[str]) -> None:
    rows = run_json("exposure", *args)
    assert len(rows) > 5
    for row in rows:  # every pair exposes the same EV (exactly, before snapping)
        assert 2 * math.log2(row["f_number"]) - math.log2(row["shutter_exact_s"]) == pytest.approx(
            row["ev100"] + math.log2(row["iso"] / 100), abs=1e-9)


@pytest.mark.parametrize(("text", "seconds"), [("1m30s", 90.0), ("90s", 90.0), ("1:30", 90.0), ("1:02:03", 3723.0),
                                               ("36m 25s", 2185.0), ("2h5m", 7500.0), ("1/250", 0.004)])
def test_times_as_people_write_them(text: str, seconds: float) -> None:
    assert parse_time(text) == pytest.approx(seconds, rel=1e-15)


@pytest.mark.parametrize("text", ["2h30", "1m30", "30s1m", "1:75", "1:5", "2h2h"])
def test_ambiguous_times_are_refused(text: str) -> None:
    with pytest.raises(UnitError):
        parse_time(text)


def test_bulb_time_shown_exactly_never_snapped() -> None:
    # 36 min 25 s was shown "nearest 32'" (a third stop); bulb times stay exact.
    (row,) = run_json("exposure", "-N", "8", "-t", "2185/1024", "--nd", "10stops")
    assert row["shutter_nominal_s"] == 2185.0
    table = run("exposure", "-N", "8", "-t", "2185/1024", "--nd", "10stops").stdout
    assert "36m 25s" in table and "'" not in table and '"' not in table


def test_t_stops() -> None:
    assert parse_t_stop("T2") == 2.0 and parse_t_stop("t/2.8") == 2.8 and parse_t_stop("2.8") is None
    (row,) = run_json("exposure", "-N", "T2", "-t", "1/50")
    assert row["aperture_kind"] == "T" and row["f_number"] == 2.0
    assert row["ev"] == pytest.approx(math.log2(4 * 50))  # exposure uses the T-stop as the f-number
    assert run("exposure", "-N", "T2", "-t", "1/50").stdout.splitlines()[2].startswith("T2")


# --- films: the makers' published figures ------------------------------------


@pytest.mark.parametrize(
    ("film", "metered", "corrected"),
    [
        ("hp5", 10.0, 10**1.31),  # Ilford reciprocity sheet: HP5+ 10 s -> 20.4 s
        ("kentmere-400", 10.0, 10**1.30),  # Ilford/Harman sheet: Kentmere 400 p = 1.30
        ("tmax100", 10.0, 15.0),  # Kodak F-4016: T-MAX 100, 10 s -> 15 s
        ("tmax100", 100.0, 200.0),  # Kodak F-4016: 100 s -> 200 s
        ("tmax400", 100.0, 300.0),  # Kodak F-4016: T-MAX 400, 100 s -> 300 s
        ("tmax100", 1.0, 2 ** (1 / 3)),  # Kodak F-4016: 1 s, +1/3 stop
        ("tri-x", 1.0, 2.0),  # Kodak F-4017: Tri-X 1 s -> 2 s
        ("tri-x", 10.0, 50.0),  # Kodak F-4017: 10 s -> 50 s
        ("velvia50", 4.0, 4 * 2 ** (1 / 3)),  # Fujifilm Velvia 50: 4 s, +1/3 stop
        ("velvia50", 32.0, 64.0),  # 32 s, +1 stop
        ("acros", 120.0, 120.0),  # Acros: no correction up to 120 s
        ("800t", 10.0, 10**1.3),  # CineStill's guide, t^1.3
    ],
)
def test_published_reciprocity(film: str, metered: float, corrected: float) -> None:
    assert film_time_s(find_film(film), metered) == pytest.approx(corrected, rel=1e-12)


def test_table_films_refuse_times_beyond_their_data() -> None:
    with pytest.raises(Exception, match="up to 32 s"):
        film_time_s(find_film("velvia50"), 64.0)


def test_unknown_film_gets_no_misleading_suggestion() -> None:
    result = run("exposure", "-N", "8", "-t", "30", "--film", "portra-400")
    assert result.exit_code == 2 and "did you mean" not in result.stderr and "--reciprocity-p" in result.stderr


# --- meters and APEX -----------------------------------------------------------


def test_meter_constants_imply_the_published_reflectance() -> None:
    # Wikipedia, "Light meter", Calibrated reflectance: R = pi*K/C; K 12.5, C 250 -> 15.7 %; K 14 -> 17.6 %.
    for k, c, reflectance in ((12.5, 250.0, 0.157), (14.0, 250.0, 0.176)):
        lux = 1000.0
        luminance = reflectance * lux / math.pi  # a matte card of that reflectance
        reflected = metering.ev_from_luminance(luminance, 100.0, k)
        incident = metering.ev_from_illuminance(lux, 100.0, c)
        assert reflected == pytest.approx(incident, abs=0.01)


def test_foot_candles_and_apex() -> None:
    (lux,) = run_json("exposure", "--illuminance", "400", "-N", "4")
    (fc,) = run_json("exposure", "--illuminance", f"{400 * 0.09290304!r}fc", "-N", "4")
    assert fc["shutter_s"] == pytest.approx(lux["shutter_s"], rel=1e-12)
    assert lux["shutter_s"] == pytest.approx(0.1, rel=1e-12)  # lightmeter-shutter-02
    (row,) = run_json("exposure", "-N", "4", "-t", "1/64", "--iso", "200")
    # APEX: Av + Tv = Bv + Sv; ISO 100 is Sv 5 (ASA PH2.5-1960).
    assert (row["av"], row["tv"], row["sv"]) == (4.0, 6.0, pytest.approx(6.0))
    assert row["av"] + row["tv"] == pytest.approx(row["bv"] + row["sv"])


# --- films in preset files -------------------------------------------------------


def test_films_preset_kind(tmp_path) -> None:  # type: ignore[no-untyped-def]
    good = tmp_path / "films.yaml"
    good.write_text("films:\n  - id: my-pan-100\n    name: My Pan 100\n    p: 1.35\n"
                    "  - id: my-slide\n    points: [[1, '+0 stops'], [10, 20]]\n", encoding="utf-8")
    (row,) = run_json("exposure", "-N", "8", "-t", "10", "--film", "my-pan-100", "--presets", str(good))
    assert row["corrected_shutter_s"] == pytest.approx(10**1.35, rel=1e-12)
    (row,) = run_json("exposure", "-N", "8", "-t", "10", "--film", "my-slide", "--presets", str(good))
    assert row["corrected_shutter_s"] == pytest.approx(20.0, rel=1e-12)
    result = run("exposure", "-N", "8", "-t", "30", "--film", "my-slide", "--presets", str(good))
    assert result.exit_code == 2 and "up to 10 s" in result.stderr


@pytest.mark.parametrize(
    ("entry", "problem"),
    [
        ("p: 0.5", "p: must be from 1 to 3"),
        ("points: [[10, 5]]", "shorter than the metered"),
        ("points: [[10, 20], [5, 8]]", "metered times must increase"),
        ("points: [[1, 'lots']]", "a correction is written"),
        ("p: 1.3\n    points: [[1, 2]]", "give p (an exponent) or points"),
        ("name: nothing", "give p (an exponent) or points"),
    ],
)
def test_films_preset_validation(tmp_path, entry: str, problem: str) -> None:  # type: ignore[no-untyped-def]
    bad = tmp_path / "bad.yaml"
    bad.write_text(f"films:\n  - id: bad-film\n    {entry}\n", encoding="utf-8")
    result = run("presets", "validate", str(bad))
    assert result.exit_code == 1 and problem in result.stdout + result.stderr


def test_t_stop_and_f_number() -> None:
    from camtool.exposure.ev import f_number_from_t_stop, t_stop

    assert t_stop(2.0, 0.75) == pytest.approx(2.309, abs=5e-4)  # Wikipedia, "F-number", T-stop: f/2.0 at 75 % is T2.3
    assert t_stop(4.0, 0.5) == pytest.approx(4 * math.sqrt(2))  # idigitalphoto.com, "T-number": f/4 at 50 % is T5.6
    assert f_number_from_t_stop(t_stop(2.8, 0.9), 0.9) == pytest.approx(2.8, rel=1e-15)


def test_two_step_equals_one_step() -> None:
    # Issue 15: "--ev100 $(camtool exposure -N 8 -t 1/60 --field ev100) -N 8 --nd ND1000" was the workaround.
    level = run("exposure", "-N", "8", "-t", "1/60", "--field", "ev100").stdout.strip()
    (two,) = run_json("exposure", "--ev100", level, "-N", "8", "--nd", "ND1000")
    (one,) = run_json("exposure", "-N", "8", "-t", "1/60", "--nd", "ND1000")
    assert two["shutter_s"] == pytest.approx(one["corrected_shutter_s"], rel=1e-9)


def test_metered_equivalents_include_the_filter() -> None:
    rows = run_json("exposure", "-N", "8", "-t", "1/60", "--nd", "ND1000", "--equivalents", "--step", "full")
    row = next(r for r in rows if r["f_number_nominal"] == 8.0)
    assert row["shutter_exact_s"] == pytest.approx(1000 / 60 * 64 / 2 ** (2 * math.log2(8)), rel=1e-9)


def test_meter_c_in_foot_candle_seconds() -> None:
    # C = 250 lx·s is 250 × 0.09290304 = 23.23 fc·s: the same answer (lightmeter-shutter-02: 400 lx, f/4 -> 0.1 s).
    (row,) = run_json("exposure", "--illuminance", "400", "-N", "4", "--meter-c", f"{250 * 0.09290304!r}fc")
    assert row["shutter_s"] == pytest.approx(0.1, rel=1e-12)
    (k14,) = run_json("exposure", "--luminance", "4096", "-N", "16", "--meter-k", "14")
    assert k14["ev100"] == pytest.approx(math.log2(4096 * 100 / 14), rel=1e-15)


@pytest.mark.parametrize(
    ("args", "option", "value"),
    [
        (["-N", "8", "-t", "30", "--nd", "20stops", "--equivalents"], "'-t' / '--shutter'", "30"),
        (["--ev100", "-10", "--iso", "100", "--nd", "20stops"], "'--ev100'", "-10"),
        (["--light", "moonlight", "-N", "16", "--nd", "ND1000"], "'--light'", "moonlight"),
    ],
)
def test_errors_name_the_option_and_value_typed(args: list[str], option: str, value: str) -> None:
    result = run("exposure", *args)
    assert result.exit_code == 2
    assert result.stderr.startswith(f"Error: Invalid value for {option}: {value} is outside the valid range: ")
    assert len(result.stderr.splitlines()) == 1


@pytest.mark.parametrize(
    ("kwargs", "says"),
    [
        ({"ev100": 12.0, "light": "sunny", "f_number": 8.0}, "Give only one light level: {ev100}, {light}."),
        ({"f_number": 8.0, "shutter_s": 1.0, "film": find_film("hp5"), "reciprocity_p": 1.3}, "not both"),
        ({"ev100": 12.0, "f_number": 8.0, "new_iso": 400.0}, "{new_iso} moves metered settings"),
        ({"f_number": 8.0, "shutter_s": 1.0, "new_iso": 400.0, "solve": "iso"}, "give one of them"),
        ({"ev100": 12.0, "f_number": 8.0, "shutter_s": 1.0, "iso": 100.0}, "give at most two"),
        ({"shutter_s": 1.0}, "or the metered {f_number} and {shutter_s}"),
    ],
)
def test_questions_that_need_other_settings(kwargs: dict, says: str) -> None:  # type: ignore[type-arg]
    from camtool.exposure.calculator import SettingsError

    with pytest.raises(SettingsError) as info:
        work_out(**kwargs)
    assert says in info.value.template
