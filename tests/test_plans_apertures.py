"""camtool.plans.equipment's T-stop decisions called directly: which transmittance, exact stops, the rows' keys,
the footer's facts, and the apertures of an exposure (a cine lens's widest T-stop, no mix of T-stops and f-numbers).

Every number is checked against a published value or an identity: Wikipedia, "F-number", T-stop (an f/2.0 lens
of 75 % transmittance is T2.3: T = N/√τ); idigitalphoto.com, "T-number" (f/4 at 50 % is T5.6); the exact stop
f/5.6 = 2^(5/2); N = T·√τ lies 1 − √τ below T.
"""

from __future__ import annotations

import math
from types import SimpleNamespace

import pytest

from camtool.core.errors import InputError
from camtool.core.units import TStop
from camtool.plans import equipment
from camtool.presets import load_db

WIKI_T = 2.0 / math.sqrt(0.75)  # Wikipedia: f/2.0 at 75 % transmittance
WIKI_LENS = SimpleNamespace(id="wiki-t-lens", transmittance=0.75, f_number_min=2.0, t_number_min=WIKI_T)


def test_a_t_stop_takes_the_lens_transmittance() -> None:
    found = equipment.apertures([TStop(WIKI_T), TStop(4 * math.sqrt(2))], lens=WIKI_LENS)
    assert found.f_numbers[0] == pytest.approx(2.0, rel=1e-12)
    assert found.f_numbers[1] == pytest.approx(4 * math.sqrt(2) * math.sqrt(0.75), rel=1e-12)  # N = T·√τ
    assert [c.source for c in found.choices] == ["transmittance", "transmittance"]
    half = equipment.apertures([TStop(4 * math.sqrt(2))], lens=SimpleNamespace(transmittance=0.5))
    assert half.f_numbers[0] == pytest.approx(4.0, rel=1e-12)  # idigitalphoto.com: f/4 at 50 % is T5.6


def test_without_a_transmittance_the_t_stop_stands_in() -> None:
    cine = load_db().lens("cooke-s4i-50mm-t2")  # a T-stop but no f-number: no transmittance
    for lens in (None, cine):
        found = equipment.apertures([TStop(2.8)], lens=lens)
        assert found.f_numbers == [2.8] and found.choices[0].source == "t-stop" and found.choices[0].t_stop == 2.8


def test_f_numbers_alone_keep_no_choices_unless_a_column_holds_t_stops() -> None:
    assert equipment.apertures([2.8, 4.0]) == equipment.Apertures([2.8, 4.0], None)
    kept = equipment.apertures([2.8], t_stops=True)
    assert kept.f_numbers == [2.8] and kept.choices[0].source == "typed" and kept.choices[0].t_stop is None


def test_exact_stops_map_each_value_and_keep_a_t_stop_a_t_stop() -> None:
    found = equipment.apertures([5.6, TStop(5.6)], exact_stops=True)
    assert found.f_numbers == [pytest.approx(2 ** 2.5, rel=1e-15)] * 2  # f/5.6 labels 2^(5/2)
    assert found.choices[1].t_stop == pytest.approx(2 ** 2.5, rel=1e-15) and found.choices[0].t_stop is None


def test_rows_find_their_choice_by_f_number_or_in_order_when_scaled() -> None:
    t2, t4 = (equipment.apertures([TStop(t)]).choices[0] for t in (2.0, 4.0))
    assert equipment.t_stop_rows([t2, t4], row_f_numbers=[4.0, 2.0, 4.0]) == [t4, t2, t4]
    k = 1.4  # a teleconverter multiplies every f-number by k: the rows keep the order of the choices
    assert equipment.t_stop_rows([t2, t4], row_f_numbers=[2.0 * k, 4.0 * k]) == [t2, t4]
    assert equipment.t_stop_rows([t2], row_f_numbers=[None, 8.0]) == [t2, t2]  # one choice: every row
    assert equipment.t_stop_rows([t2, t4], row_f_numbers=[None, 2.0, 4.0]) == [None, t2, t4]


def test_the_note_states_the_transmittance_or_the_stand_in_bounds() -> None:
    with_lens = equipment.t_stop_note(equipment.apertures([TStop(WIKI_T)], lens=WIKI_LENS).choices, lens=WIKI_LENS)
    assert with_lens.transmittance == pytest.approx(0.75, rel=1e-12) and with_lens.lens_id == "wiki-t-lens"
    assert (with_lens.lens_f_number_min, with_lens.lens_t_number_min) == (2.0, WIKI_T)
    alone = equipment.t_stop_note(equipment.apertures([TStop(2.0)]).choices)
    assert alone.transmittance is None and alone.lens_id is None
    for tau, below, over in ((0.9, alone.below_low, alone.overstated_low), (0.7, alone.below_high,
                                                                               alone.overstated_high)):
        assert below == pytest.approx(1 - math.sqrt(tau), rel=1e-12)  # N = T·√τ
        assert over == pytest.approx(1 / math.sqrt(tau) - 1, rel=1e-12)  # T over N


def test_exposure_takes_a_cine_lens_wide_open_unless_solving_or_listing() -> None:
    cine = load_db().lens("cooke-s4i-50mm-t2")
    assert equipment.exposure_apertures([], lens=cine) == equipment.ExposureApertures([2.0], True, 2.0)
    assert equipment.exposure_apertures([], lens=cine, equivalents=True) == equipment.ExposureApertures([], False, None)
    assert equipment.exposure_apertures([], lens=cine, solving=True).f_numbers == []
    assert equipment.exposure_apertures([8.0], lens=cine) == equipment.ExposureApertures([8.0], False, None)
    assert equipment.exposure_apertures([], lens=load_db().lens("nikon-z-24mm-f1.8-s")).f_numbers == []
    exact = equipment.exposure_apertures([TStop(5.6)], exact_stops=True)
    assert exact.t_stop and exact.f_numbers == [pytest.approx(2 ** 2.5, rel=1e-15)]


def test_exposure_refuses_a_mix_of_t_stops_and_f_numbers_on_the_f_number() -> None:
    with pytest.raises(InputError) as caught:
        equipment.exposure_apertures([TStop(2.0), 4.0])
    assert caught.value.param == "f_number" and not caught.value.usage
    assert str(caught.value) == "give all f-numbers or all T-stops, not a mix"
