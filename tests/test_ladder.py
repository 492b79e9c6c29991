"""The ladder dispatcher: lens data, unavailable models, the focal length of a prescription, thick = thin."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest
import yaml
from hypothesis import given, settings
from hypothesis import strategies as st

from camtool.core.errors import DomainError
from camtool.dof.closed import thin_dof
from camtool.dof.ladder import (
    LensData,
    ModelUnavailable,
    available_models,
    compare_models,
    depth_of_field,
)
from camtool.optics.prescription import prescription_from_mapping

PATH = Path(__file__).parent / "data" / "prescriptions" / "dgauss100.yaml"
DGAUSS = LensData(prescription=prescription_from_mapping(yaml.safe_load(PATH.read_text()), source=PATH.name))


@settings(max_examples=200, deadline=None)
@given(f=st.floats(1.0, 5000.0), n=st.floats(0.7, 1024.0), c=st.floats(0.0005, 1.0), k=st.floats(1.0001, 1e6),
       plane=st.sampled_from(["sensor", "lens"]))
def test_thick_with_unit_pupils_and_no_hiatus_is_thin(f, n, c, k, plane) -> None:
    s = (4.0 if plane == "sensor" else 2.0) * f * k
    thick = depth_of_field("thick", f, n, c, s, plane, LensData(pupil_magnification=1.0, hiatus_mm=0.0)).limits
    thin = thin_dof(f, n, c, s, plane)
    for a, b in zip(thick[:3], thin[:3]):
        assert a == pytest.approx(b, rel=1e-9)


@pytest.mark.parametrize(("model", "lens", "missing"), [
    ("thick", None, "pupil magnification or hiatus"),
    ("paraxial", LensData(pupil_magnification=0.8), "prescription"),
    ("raytrace", None, "prescription"),
])
def test_models_the_inputs_do_not_allow_name_what_is_missing(model, lens, missing) -> None:
    with pytest.raises(ModelUnavailable, match=missing):
        depth_of_field(model, 50.0, 8.0, 0.03, 3000.0, lens=lens)


def test_available_models() -> None:
    assert available_models() == ("approx", "thin")
    assert available_models(LensData(hiatus_mm=5.0)) == ("approx", "thin", "thick")
    assert available_models(DGAUSS) == ("approx", "thin", "paraxial", "raytrace")
    assert available_models(LensData(pupil_magnification=1.1, prescription=DGAUSS.prescription))[2] == "thick"


def test_prescription_supplies_the_focal_length_and_refuses_a_different_one() -> None:
    efl = DGAUSS.focal_length_mm
    a = depth_of_field("paraxial", None, 4.0, 0.03, 3000.0, lens=DGAUSS)
    b = depth_of_field("paraxial", 100.5, 4.0, 0.03, 3000.0, lens=DGAUSS)
    assert a.limits == b.limits
    thin = depth_of_field("thin", 100.5, 4.0, 0.03, 3000.0, lens=DGAUSS)
    assert thin.limits.near_mm == pytest.approx(thin_dof(efl, 4.0, 0.03, 3000.0).near_mm, rel=1e-15)
    with pytest.raises(DomainError, match=r"within 1 % of 100.004 mm.*dgauss100") as caught:
        depth_of_field("thin", 90.0, 4.0, 0.03, 3000.0, lens=DGAUSS)
    assert caught.value.param == "focal_length_mm" and caught.value.value == 90.0


def test_thick_from_a_prescription_equals_paraxial() -> None:
    lens = LensData(prescription=DGAUSS.prescription)
    thick = depth_of_field("thick", None, 2.8, 0.03, 1500.0, lens=lens).limits
    paraxial = depth_of_field("paraxial", None, 2.8, 0.03, 1500.0, lens=lens).limits
    assert thick == paraxial


def test_compare_models_rows_and_differences() -> None:
    rows = compare_models(None, 4.0, 0.03, 2000.0, lens=DGAUSS, repeat=1)
    assert [r.result.model for r in rows] == ["approx", "thin", "paraxial", "raytrace", "wave+prescription"]
    assert rows[-2].difference == 0.0  # against raytrace, the most complete geometric rung; wave follows it
    assert all(r.time_per_evaluation_s > 0 for r in rows)
    assert rows[0].difference > rows[2].difference
    # wide open the real lens's in-focus contrast is below the default criterion: no wave row, the ladder alone
    wide = compare_models(None, 2.8, 0.03, 2000.0, lens=DGAUSS, repeat=1)
    assert [r.result.model for r in wide] == ["approx", "thin", "paraxial", "raytrace"]


def test_arrays_and_scalars_agree() -> None:
    lens = LensData(pupil_magnification=0.6, hiatus_mm=20.0)
    s = np.array([[500.0, 2000.0, 1e4], [1e5, 1e7, np.inf]])
    many = depth_of_field("auto", 85.0, 4.0, 0.03, s, lens=lens, diffraction=True)
    for i, d in np.ndenumerate(s):
        one = depth_of_field("auto", 85.0, 4.0, 0.03, float(d), lens=lens, diffraction=True)
        assert one.model == many.model[i]  # each scene gets the rung a single call would pick
        assert many.limits.near_mm[i] == pytest.approx(one.limits.near_mm, rel=1e-12)
        assert many.error_estimate[i] == pytest.approx(one.error_estimate, rel=1e-12)


def test_unknown_model() -> None:
    with pytest.raises(ValueError, match="unknown model 'bogus'"):
        depth_of_field("bogus", 50.0, 8.0, 0.03, 3000.0)
