"""Diffraction as an add-on: RSS identities and the largest f-number that still leaves depth of field."""

from __future__ import annotations

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from camtool.dof.closed import thin_dof
from camtool.dof.diffraction import (
    NothingSharp,
    airy_diameter_mm,
    largest_sharp_f_number,
    usable_coc_mm,
)
from camtool.dof.ladder import LensData, depth_of_field
from camtool.geometry.thinlens import focus_geometry


def test_airy_diameter() -> None:
    # 2.44 · 550 nm · f/8 = 10.736 µm
    assert airy_diameter_mm(8.0, 550.0) == pytest.approx(0.010736)


@settings(max_examples=100, deadline=None)
@given(f=st.floats(10.0, 500.0), n=st.floats(1.0, 32.0), k=st.floats(1.01, 1e4))
def test_vanishing_airy_disc_recovers_the_geometric_model(f, n, k) -> None:
    s = 4.0 * f * k
    geometric = depth_of_field("thin", f, n, 0.03, s).limits
    tiny = depth_of_field("thin", f, n, 0.03, s, diffraction=True, wavelength_nm=1e-9).limits
    assert tiny.near_mm == pytest.approx(geometric.near_mm, rel=1e-12)


def test_total_blur_is_the_root_sum_square() -> None:
    c, n, s = 0.03, 11.0, 3000.0
    m = focus_geometry(50.0, s).magnification
    usable = usable_coc_mm(c, n, m)
    airy = airy_diameter_mm(n * (1 + m))
    assert usable**2 + airy**2 == pytest.approx(c**2, rel=1e-12)
    with_diffraction = depth_of_field("thin", 50.0, n, c, s, diffraction=True)
    assert with_diffraction.model == "thin+diffraction"
    assert with_diffraction.limits.near_mm == pytest.approx(thin_dof(50.0, n, usable, s).near_mm, rel=1e-14)


@pytest.mark.parametrize(("f", "s", "p"), [(50.0, 3000.0, 1.0), (100.0, 450.0, 0.6), (24.0, float("inf"), 2.0)])
def test_largest_f_number_leaves_depth_and_slightly_more_does_not(f, s, p) -> None:
    lens = LensData(pupil_magnification=p, hiatus_mm=0.0)
    m = focus_geometry(f, s).magnification
    largest = largest_sharp_f_number(0.03, m, p)
    just_below = depth_of_field("thick", f, largest * 0.999, 0.03, s, lens=lens, diffraction=True).limits
    assert just_below.total_mm > 0
    with pytest.raises(NothingSharp) as caught:
        depth_of_field("thick", f, largest * 1.001, 0.03, s, lens=lens, diffraction=True)
    assert caught.value.largest_f_number == pytest.approx(largest)
    assert "nothing is acceptably sharp" in str(caught.value)


def test_close_focus_lowers_the_largest_f_number() -> None:
    # working f-number N(1 + m/P): at 1:1 the Airy disc is twice as large
    assert largest_sharp_f_number(0.03, 1.0) == pytest.approx(largest_sharp_f_number(0.03, 0.0) / 2)
