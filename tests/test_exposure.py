"""Exposure formulas: EV, solving, light levels, stops, equivalents, ND, bellows, reciprocity, metering."""

from __future__ import annotations

import math

import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st

from camtool.core.errors import DomainError
from camtool.core.units import parse_time
from camtool.exposure import metering, reciprocity
from camtool.exposure.bellows import bellows_factor, bellows_stops
from camtool.exposure.equivalents import equivalent_exposures, shift_time_s
from camtool.exposure.ev import ev100 as ev100_of_settings
from camtool.exposure.ev import (
    ev100_from_ev,
    ev_from_ev100,
    exposure_value,
    shutter_for_ev100,
    solve_exposure,
)
from camtool.exposure.light import LIGHT_LEVELS, light_level
from camtool.exposure.nd import (
    nd_from_density,
    nd_from_factor,
    nd_from_stops,
    parse_nd,
    stack_nd,
)
from camtool.exposure.plan import plan_exposure
from camtool.exposure.stops import snap_f_number, snap_iso, snap_shutter_s
from camtool.exposure.timefmt import format_time

f_numbers = st.floats(0.7, 1024.0)
times = st.floats(1 / 64000, 1e6)
isos = st.floats(1.0, 1e7)


# --- EV and EV100 ---------------------------------------------------------


def test_f16_at_1_125_is_ev_14_97() -> None:
    # log2(16² · 125) = 14.966; the "EV 15" of exposure tables is this, rounded
    # (Wikipedia, "Exposure value": "1/125 s at f/16 ... 15").
    assert round(exposure_value(16.0, 1 / 125), 2) == 14.97


@pytest.mark.parametrize(
    ("f_number", "shutter_s", "iso", "ev", "ev100"),
    [
        (1.0, 1.0, 100.0, 0.0, 0.0),  # definition: EV 0 is f/1 at 1 s (ISO 2720)
        (4.0, 1 / 64, 200.0, 10.0, 9.0),  # one stop of ISO moves EV100 by one
        (8.0, 1 / 256, 400.0, 14.0, 12.0),  # 2·3 + 8 = 14; minus log2(4)
    ],
)
def test_ev_and_ev100_conventions(f_number: float, shutter_s: float, iso: float, ev: float, ev100: float) -> None:
    assert exposure_value(f_number, shutter_s) == ev
    assert ev100_of_settings(f_number, shutter_s, iso) == ev100
    assert ev_from_ev100(ev100, iso) == ev


def test_scalar_and_array_agree() -> None:
    # The colour-science habit: a scalar call equals the same values tiled into (6,) and (2, 3).
    n = np.array([1.4, 2.0, 2.8, 4.0, 5.6, 8.0])
    t = np.array([1 / 1000, 1 / 60, 0.5, 2.0, 30.0, 1 / 8000])
    flat = exposure_value(n, t)
    assert flat.shape == (6,)
    np.testing.assert_array_equal(exposure_value(n.reshape(2, 3), t.reshape(2, 3)), flat.reshape(2, 3))
    assert [exposure_value(float(a), float(b)) for a, b in zip(n, t)] == pytest.approx(list(flat), rel=1e-15)
    assert isinstance(exposure_value(2.0, 0.5), float)


@given(ev100=st.floats(-10, 25), f_number=st.floats(1.0, 64.0), iso=st.floats(25.0, 6400.0))
def test_solve_round_trips(ev100: float, f_number: float, iso: float) -> None:
    try:
        e = solve_exposure(ev100, f_number=f_number, iso=iso)
    except DomainError:
        return  # the needed time lies outside 1/64000 s .. 10⁶ s
    assert ev100_of_settings(e.f_number, e.shutter_s, e.iso) == pytest.approx(ev100, abs=1e-9)
    assert solve_exposure(ev100, shutter_s=e.shutter_s, iso=iso).f_number == pytest.approx(f_number, rel=1e-12)
    assert solve_exposure(ev100, f_number=f_number, shutter_s=e.shutter_s).iso == pytest.approx(iso, rel=1e-12)


def test_solve_needs_exactly_one_missing() -> None:
    with pytest.raises(DomainError, match="exactly one of"):
        solve_exposure(12.0, f_number=8.0)
    with pytest.raises(DomainError, match="exactly one of"):
        solve_exposure(12.0, f_number=8.0, shutter_s=0.01, iso=100.0)


@pytest.mark.parametrize(
    ("call", "param"),
    [
        (lambda: exposure_value(8.0, 1 / 100000), "shutter_s"),  # faster than 1/64000 s
        (lambda: exposure_value(8.0, 2e6), "shutter_s"),  # longer than 10⁶ s
        (lambda: exposure_value(0.5, 1.0), "f_number"),  # below f/0.7
        (lambda: exposure_value(2048.0, 1.0), "f_number"),  # above f/1024
        (lambda: exposure_value(float("nan"), 1.0), "f_number"),
        (lambda: ev100_of_settings(8.0, 1.0, 0.5), "iso"),  # below ISO 1
        (lambda: ev100_of_settings(8.0, 1.0, 2e7), "iso"),  # above ISO 10⁷
        (lambda: shutter_for_ev100(26.0, 8.0, 100.0), "ev100"),  # above EV 25
        (lambda: shutter_for_ev100(-11.0, 8.0, 100.0), "ev100"),  # below EV −10
        (lambda: shutter_for_ev100(25.0, 0.7, 100.0), "shutter_s"),  # needs 1/68000 s
        (lambda: equivalent_exposures(30.0), "ev"),
        (lambda: exposure_value(np.array([2.0, 4000.0]), 1.0), "f_number"),
    ],
)
def test_domain_errors(call, param: str) -> None:
    with pytest.raises(DomainError) as info:
        call()
    assert info.value.param == param


def test_domain_error_message() -> None:
    with pytest.raises(DomainError) as info:
        exposure_value(8.0, 2e6)
    assert str(info.value) == "shutter_s=2000000 is outside the valid range: 1/64000 s to 1000000 s"
    with pytest.raises(DomainError) as info:
        shutter_for_ev100(25.0, 0.7, 100.0)
    assert "the shutter time this light level needs" in str(info.value)


def test_domain_edges_are_inside() -> None:
    assert exposure_value(0.7, 1 / 64000) == pytest.approx(2 * math.log2(0.7) + math.log2(64000))
    assert exposure_value(1024.0, 1e6) == pytest.approx(20 - math.log2(1e6))


# --- light levels -----------------------------------------------------------


@pytest.mark.parametrize("iso", [100.0, 200.0, 400.0])
def test_sunny_16(iso: float) -> None:
    # Sunny-16 rule: in bright sun, f/16 at 1/ISO s (Wikipedia, "Sunny 16 rule").
    e = solve_exposure(light_level("sunny").ev100, f_number=16.0, iso=iso)
    assert e.shutter_s == pytest.approx(1.0 / iso, rel=1e-12)
    assert snap_shutter_s(e.shutter_s).nominal == pytest.approx(1.0 / iso)  # 1/100, 1/200, 1/400


@pytest.mark.parametrize(
    ("name", "f_number"),
    # Wikipedia, "Sunny 16 rule": snow f/22, sunny f/16, slight overcast f/11,
    # overcast f/8, heavy overcast f/5.6, open shade f/4, all at 1/ISO.
    [("snow", 22), ("sunny", 16), ("slight-overcast", 11), ("overcast", 8), ("heavy-overcast", 5.6), ("shade", 4)],
)
def test_sunny_16_family(name: str, f_number: float) -> None:
    e = solve_exposure(light_level(name).ev100, shutter_s=1 / 100, iso=100.0)
    assert snap_f_number(e.f_number, "full").nominal == f_number


def test_light_levels_cite_their_source() -> None:
    for name, level in LIGHT_LEVELS.items():
        assert level.source and level.description, name
        assert -10 <= level.ev100 <= 25
    assert light_level("Heavy Overcast") is LIGHT_LEVELS["heavy-overcast"]


# --- stops, labels, time formatting -----------------------------------------


@pytest.mark.parametrize(
    ("step", "labels"),
    [
        # Full-stop f-number scale (Wikipedia, "F-number").
        ("full", [0.7, 1.0, 1.4, 2.0, 2.8, 4.0, 5.6, 8.0, 11.0, 16.0, 22.0, 32.0, 45.0, 64.0, 90.0, 128.0,
                  180.0, 256.0, 360.0, 512.0, 720.0, 1024.0]),
        # Third stops from f/2.8 to f/8, as marked on lenses.
        ("third", [2.8, 3.2, 3.5, 4.0, 4.5, 5.0, 5.6, 6.3, 7.1, 8.0]),
    ],
)
def test_f_number_labels(step: str, labels: list[float]) -> None:
    n = {"full": 1, "third": 3}[step]
    first = round(2 * n * math.log2(labels[0] if labels[0] != 0.7 else 2**-0.5))
    exact = [2 ** ((first + k) / (2 * n)) for k in range(len(labels))]
    assert [snap_f_number(x, step).nominal for x in exact] == labels


def test_shutter_labels_full_and_third() -> None:
    # ISO 516 full-stop series, and the third-stop series of current camera displays.
    full = [snap_shutter_s(2.0**-k, "full").nominal for k in range(-6, 17)]
    assert [format_time(t) for t in full] == [
        "1m", "30s", "15s", "8s", "4s", "2s", "1s", "0.5s", "1/4", "1/8", "1/15", "1/30", "1/60", "1/125",
        "1/250", "1/500", "1/1000", "1/2000", "1/4000", "1/8000", "1/16000", "1/32000", "1/64000"]
    thirds = [snap_shutter_s(2.0 ** (-k / 3), "third").nominal for k in range(18, 25)]
    assert [format_time(t) for t in thirds] == ["1/60", "1/80", "1/100", "1/125", "1/160", "1/200", "1/250"]


def test_iso_labels() -> None:
    # ISO 12232 arithmetic speed series.
    assert [snap_iso(100.0 * 2 ** (k / 3)).nominal for k in range(-6, 22)] == [
        25, 32, 40, 50, 64, 80, 100, 125, 160, 200, 250, 320, 400, 500, 640, 800, 1000, 1250, 1600, 2000,
        2500, 3200, 4000, 5000, 6400, 8000, 10000, 12800]


def test_snap_keeps_the_exact_value() -> None:
    s = snap_shutter_s(1 / 300)
    assert s.value == 1 / 300
    assert s.exact == 2.0**-8.333333333333334 or s.exact == pytest.approx(2 ** (-25 / 3))
    assert s.nominal == 1 / 320
    assert s.error_stops == pytest.approx(math.log2(300) - 25 / 3)


def test_snap_arrays() -> None:
    s = snap_f_number(np.array([[1.4, 5.7], [11.0, 22.0]]))
    np.testing.assert_array_equal(s.nominal, [[1.4, 5.6], [11.0, 22.0]])


@pytest.mark.parametrize(
    ("seconds", "text"),
    [
        (1 / 250, "1/250"), (1 / 8, "1/8"), (0.5, "0.5s"), (2.0, "2s"), (90.0, "1m 30s"), (4 * 3600.0, "4h"),
        (1 / 64000, "1/64000"), (1e6, "277h 46m 40s"), (59.7, "59.7s"), (3599.9, "1h"), (9.97, "10s"), (0.3, "1/3.3"),
        (2185.0, "36m 25s"), (16.67, "16.7s"), (68.0, "1m 8s"),  # bulb times exactly, never ' and "
    ],
)
def test_format_time(seconds: float, text: str) -> None:
    assert format_time(seconds) == text


@given(times)
def test_format_time_reads_back(seconds: float) -> None:
    # Display rounding is at most ~5 % (two significant digits) or half a second/minute.
    back = parse_time(format_time(seconds).replace("h", "h "))
    assert back == pytest.approx(seconds, rel=0.06, abs=0.5 if seconds < 3600 else 30.0)


# --- equivalents ----------------------------------------------------------


@pytest.mark.parametrize("step", ["full", "half", "third"])
@pytest.mark.parametrize("ev", [-4.0, 3.3, 9.0, 15.0, 21.7])
def test_equivalents_share_one_ev_within_their_snapping(step: str, ev: float) -> None:
    n = {"full": 1, "half": 2, "third": 3}[step]
    eq = equivalent_exposures(ev, 1.0, 64.0, step)
    assert eq.f_number, "some rows inside the domain"
    for got in eq.ev:
        assert abs(got - ev) <= 0.5 / n + 1e-9
    for exact, n_exact in zip(eq.shutter_exact_s, eq.f_number):
        assert exposure_value(n_exact, exact) == pytest.approx(ev, abs=1e-9)


def test_equivalents_table() -> None:
    # EV 15 ("sunny 16" at ISO 100, rounded): f/16 at 1/125, f/8 at 1/500, f/4 at 1/2000.
    eq = equivalent_exposures(15.0, 4.0, 16.0)
    assert list(zip(eq.f_number_nominal, map(format_time, eq.shutter_nominal_s))) == [
        (4.0, "1/2000"), (5.6, "1/1000"), (8.0, "1/500"), (11.0, "1/250"), (16.0, "1/125")]


def test_equivalents_drop_rows_outside_the_domain() -> None:
    eq = equivalent_exposures(25.0, 1.0, 64.0)
    assert min(eq.shutter_s) >= 1 / 64000 / 2 ** 0.5
    assert eq.f_number_nominal[0] > 1.0


# --- ND filters -------------------------------------------------------------


@pytest.mark.parametrize(
    ("text", "stops"),
    [
        ("ND1000", 9.97),  # log2(1000) (Wikipedia, "Neutral-density filter")
        ("3.0D", 9.97),  # 3.0/log10(2)
        ("3.0 d", 9.97),
        ("OD3", 9.97),
        ("OD 0.9", 2.99),  # 0.9 ND: "3 stops" nominally
        ("1000x", 9.97),
        ("x8", 3.0),
        ("nd8", 3.0),
        ("3stops", 3.0),
        ("10stops", 10.0),
        ("1.5 stops", 1.5),
        ("0.6D", 1.99),
        ("6ev", 6.0),
        # the cinema's density notation: Kodak Wratten 2 #96 (B&H listing): ND .30 = 1 stop, .60 = 2, .90 = 3,
        # ND 3.0 = 10 stops (density / log10 2: 0.9 -> 2.99)
        ("ND.3", 1.0),
        ("ND.6", 1.99),
        ("ND0.9", 2.99),
        ("ND1.2", 3.99),
        ("nd 3.0", 9.97),
    ],
)
def test_nd_spellings(text: str, stops: float) -> None:
    assert round(parse_nd(text).stops, 2) == stops


@pytest.mark.parametrize("text", ["", "ND", "three", "-3", "ND-8", "3 stop 2", "0.5x", "3", "3.0", "1000", "ND.",
                                  "ND0.9.1", "0.9ND"])
def test_nd_bad_spellings(text: str) -> None:
    with pytest.raises(DomainError) as info:
        parse_nd(text)
    assert info.value.param == "nd" or info.value.param == "nd_factor"


def test_nd_descriptions_agree() -> None:
    f = nd_from_factor(1000.0)
    assert f.density == pytest.approx(3.0)
    assert nd_from_density(3.0).factor == pytest.approx(1000.0)
    assert nd_from_stops(10.0).factor == 1024.0
    stacked = stack_nd([parse_nd("ND8"), parse_nd("ND64")])
    assert stacked.stops == pytest.approx(9.0)
    assert stacked.factor == pytest.approx(512.0)
    assert shift_time_s(1 / 125, parse_nd("ND1000").stops) == pytest.approx(8.0)


# --- bellows factor ---------------------------------------------------------


def test_bellows_plus_two_stops_at_one_to_one() -> None:
    # (1 + m/P)² = 4 at m = 1, P = 1: two stops (Ray, Applied Photographic Optics).
    assert bellows_factor(1.0, 1.0) == 4.0
    assert bellows_stops(1.0, 1.0) == 2.0
    assert bellows_stops(0.0) == 0.0
    # A telephoto-type lens (P = 0.5) at 1:1 needs (1 + 2)² = 9.
    assert bellows_factor(1.0, 0.5) == 9.0
    np.testing.assert_allclose(bellows_stops(np.array([0.0, 1.0, 3.0])), [0.0, 2.0, 4.0])


def test_bellows_domain() -> None:
    with pytest.raises(DomainError):
        bellows_factor(-0.1)
    with pytest.raises(DomainError):
        bellows_factor(1.0, 0.0)


# --- reciprocity ------------------------------------------------------------


def test_hp5_plus_10_s_metered_is_20_4_s() -> None:
    # Ilford, "Reciprocity Law Failure Compensation": HP5 Plus, 10 s metered → 20.4 s.
    film = reciprocity.find_film("HP5 Plus")
    assert round(reciprocity.corrected_time_s(10.0, film.p), 1) == 20.4


@pytest.mark.parametrize(
    ("name", "p"),
    # Ilford's published Schwarzschild exponents (same technical information sheet).
    [("HP5 Plus", 1.31), ("FP4 Plus", 1.26), ("Pan F Plus", 1.33), ("Delta 100", 1.26), ("Delta 400", 1.41),
     ("Delta 3200", 1.33), ("SFX", 1.43), ("XP2", 1.31)],
)
def test_shipped_films(name: str, p: float) -> None:
    assert reciprocity.find_film(name).p == p


def test_film_lookup_ignores_case_and_punctuation() -> None:
    assert reciprocity.find_film("hp5+").id == "ilford-hp5-plus"
    assert reciprocity.find_film("ILFORD_HP5_PLUS").id == "ilford-hp5-plus"
    with pytest.raises(DomainError, match="did you mean ilford-fp4-plus"):
        reciprocity.find_film("fp5")


def test_reciprocity_below_threshold_and_continuity() -> None:
    assert reciprocity.corrected_time_s(1.0, 1.31) == 1.0
    assert reciprocity.corrected_time_s(1 / 60, 1.5) == 1 / 60
    assert reciprocity.corrected_time_s(1.0 + 1e-9, 1.31) == pytest.approx(1.0, abs=1e-8)
    got = reciprocity.corrected_time_s(np.array([0.5, 1.0, 10.0, 100.0]), 1.31)
    np.testing.assert_allclose(got, [0.5, 1.0, 10**1.31, 100**1.31])
    with pytest.raises(DomainError):
        reciprocity.corrected_time_s(10.0, 0.9)


# --- metering ---------------------------------------------------------------


def test_meter_table_values() -> None:
    # Wikipedia, "Exposure value", EV vs luminance (K = 12.5) and illuminance (C = 250) at ISO 100:
    # EV 0 → 0.125 cd/m², 2.5 lx; EV 15 → 4096 cd/m², 81920 lx.
    assert metering.luminance_from_ev100(0.0) == 0.125
    assert metering.illuminance_from_ev100(0.0) == 2.5
    assert metering.luminance_from_ev100(15.0) == 4096.0
    assert metering.illuminance_from_ev100(15.0) == 81920.0


@given(ev100=st.floats(-10, 25), iso=isos, k=st.floats(10.0, 15.0))
def test_luminance_round_trip(ev100: float, iso: float, k: float) -> None:
    # N²/t = L·S/K: light level → luminance → EV at ISO S → light level and luminance again.
    luminance = metering.luminance_from_ev100(ev100, k)
    back = ev100_from_ev(metering.ev_from_luminance(luminance, iso, k), iso)
    assert back == pytest.approx(ev100, abs=1e-9)
    assert metering.luminance_from_ev100(min(max(back, -10.0), 25.0), k) == pytest.approx(luminance, rel=1e-12)


@given(ev100=st.floats(-10, 25), iso=isos, c=st.floats(200.0, 400.0))
def test_illuminance_round_trip(ev100: float, iso: float, c: float) -> None:
    # N²/t = E·S/C, the same way round.
    illuminance = metering.illuminance_from_ev100(ev100, c)
    back = ev100_from_ev(metering.ev_from_illuminance(illuminance, iso, c), iso)
    assert back == pytest.approx(ev100, abs=1e-9)
    assert metering.illuminance_from_ev100(min(max(back, -10.0), 25.0), c) == pytest.approx(illuminance, rel=1e-12)


@given(f_number=f_numbers, shutter_s=times, iso=isos)
def test_settings_to_light_and_back(f_number: float, shutter_s: float, iso: float) -> None:
    luminance = metering.luminance_from_exposure(f_number, shutter_s, iso)
    illuminance = metering.illuminance_from_exposure(f_number, shutter_s, iso)
    ev = exposure_value(f_number, shutter_s)
    assert metering.ev_from_luminance(luminance, iso) == pytest.approx(ev, abs=1e-9)
    assert metering.ev_from_illuminance(illuminance, iso) == pytest.approx(ev, abs=1e-9)
    # E/L = C/K = 20 for the default constants.
    assert illuminance / luminance == pytest.approx(20.0, rel=1e-12)


def test_meter_domain() -> None:
    with pytest.raises(DomainError):
        metering.ev_from_luminance(0.0)
    with pytest.raises(DomainError):
        metering.ev_from_illuminance(-1.0)
    with pytest.raises(DomainError):
        metering.ev_from_luminance(np.array([1.0, float("nan")]))


# --- a whole exposure -----------------------------------------------------------


def test_plan_from_settings_adds_the_light_lost_at_the_lens() -> None:
    # f/8 at 1/125 s through a 3-stop ND at 1:1 (2 stops): the scene must be 5 stops brighter.
    p = plan_exposure(f_number=8.0, shutter_s=1 / 125, nd_stops=3.0, magnification=1.0)
    assert p.solved == "ev100"
    assert p.ev100 == pytest.approx(exposure_value(8.0, 1 / 125) + 5.0)
    assert p.iso == 100.0


def test_plan_from_light_solves_with_filters_and_film() -> None:
    # EV100 12 at f/8, ISO 100: 1/64 s; 10 stops of ND make it 16 s; HP5 Plus then needs 16^1.31 s.
    p = plan_exposure(12.0, f_number=8.0, nd_stops=10.0, reciprocity_p=1.31)
    assert p.shutter_s == pytest.approx(16.0, rel=1e-12)
    assert p.corrected_shutter_s == pytest.approx(16.0**1.31, rel=1e-12)
    assert p.reciprocity_stops == pytest.approx(0.31 * 4.0, rel=1e-12)
    assert (p.shutter_nominal_s, p.f_number_nominal, p.iso_nominal) == (15.0, 8.0, 100.0)


def test_plan_on_arrays() -> None:
    p = plan_exposure(np.array([10.0, 12.0]), f_number=4.0, iso=np.array([100.0, 400.0]))
    np.testing.assert_allclose(p.shutter_s, [1 / 64, 1 / 1024])
    np.testing.assert_array_equal(p.shutter_nominal_s, [1 / 60, 1 / 1000])


def test_plan_needs_light_or_both_settings() -> None:
    with pytest.raises(DomainError, match="both needed"):
        plan_exposure(f_number=8.0)
