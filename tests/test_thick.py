"""The ``thick`` model: reference rows, the thin-lens limit, stability and scalar/array agreement.

References: tests/data/oracle-dof.csv `paraxial` rows (rayoptics 0.9.8 / optiland 0.6.3,
see tests/data/README.md); the exact thin-lens formulas of docs/design.md §4; mpmath at
50 digits for the same closed form.
"""

from __future__ import annotations

import csv
import math
from pathlib import Path

import mpmath
import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from camtool.core.errors import DomainError
from camtool.dof.thick import thick_dof, working_f_number

DATA = Path(__file__).parent / "data"

with open(DATA / "oracle-dof.csv", newline="") as _handle:
    PARAXIAL_ROWS = [row for row in csv.DictReader(_handle) if row["method"] == "paraxial"]


@pytest.mark.parametrize("row", PARAXIAL_ROWS, ids=lambda r: f"{r['lens']}-f{r['f_number']}-{r['focus_distance_mm']}")
def test_thick_reproduces_paraxial_rows_from_the_entrance_pupil(row):
    # oracle-dof.csv paraxial rows; oracle-README.md: with x = focus − film_to_entrance_pupil,
    # the thick-lens pupil formulas reproduce them to ~1e-9 in relative depth
    f, n, c = float(row["efl_mm"]), float(row["f_number"]), float(row["coc_mm"])
    p, offset = float(row["pupil_mag"]), float(row["film_to_entrance_pupil_mm"])
    focus, near, far = float(row["focus_distance_mm"]), float(row["near_mm"]), float(row["far_mm"])
    result = thick_dof(f, n, c, focus - offset, pupil_magnification=p, distance_from="entrance_pupil")
    # the depths are differences of 12-digit numbers: allow their rounding (5e-12 of each) on top
    rounding = 1e-11 * focus
    assert result.front_mm == pytest.approx(focus - near, rel=1e-9, abs=rounding)
    assert result.rear_mm == pytest.approx(far - focus, rel=1e-9, abs=rounding)
    assert result.near_mm + offset == pytest.approx(near, rel=1e-11)  # 12-digit table
    assert result.magnification == pytest.approx(float(row["magnification"]), rel=1e-9)


def thin_near_far(f, n, c, s):
    """Exact thin lens, distances from the lens (docs/design.md §4, the seed lecture)."""
    near = s * f * f / (f * f + n * c * (s - f))
    denominator = f * f - n * c * (s - f)
    return near, (math.inf if denominator <= 0 else s * f * f / denominator)


THIN_CASES = [  # (f, N, c, u from the lens)
    (50.0, 8.0, 0.03, 3000.0),
    (50.0, 1.4, 0.03, 100.0),  # 1:1
    (24.0, 11.0, 0.02, 1500.0),
    (300.0, 4.0, 0.03, 10000.0),
    (5.0, 2.0, 0.005, 1e6),
    (100.0, 1024.0, 0.03, 300.0),  # pinhole-like f-number
    (35.0, 16.0, 0.03, 1e15),
]


@pytest.mark.parametrize("f, n, c, u", THIN_CASES)
def test_unit_pupil_and_no_hiatus_is_the_exact_thin_lens(f, n, c, u):
    # docs/design.md §4: near = s f²/(f² + Nc(s − f)), far = s f²/(f² − Nc(s − f)); D = u + v
    near, far = thin_near_far(f, n, c, u)
    lens = thick_dof(f, n, c, u, distance_from="lens")
    assert lens.near_mm == pytest.approx(near, rel=4e-15)
    assert lens.far_mm == pytest.approx(far, rel=1e-14) if math.isfinite(far) else math.isinf(lens.far_mm)
    v = f * u / (u - f)
    sensor = thick_dof(f, n, c, u + v)
    assert sensor.near_mm == pytest.approx(near + v, rel=1e-14)
    assert sensor.far_mm == pytest.approx(far + v, rel=1e-14) if math.isfinite(far) else math.isinf(sensor.far_mm)
    assert sensor.magnification == pytest.approx(v / u, rel=1e-12)


def test_hyperfocal_boundary_is_exact():
    # docs/design.md §6: far = ∞ exactly when focus ≥ hyperfocal, finite just below
    for plane in ("sensor", "lens", "entrance_pupil"):
        h = thick_dof(50.0, 8.0, 0.03, 3000.0, pupil_magnification=0.8, hiatus_mm=5.0, distance_from=plane).hyperfocal_mm
        assert math.isinf(thick_dof(50.0, 8.0, 0.03, h, 0.8, 5.0, plane).far_mm)
        below = thick_dof(50.0, 8.0, 0.03, math.nextafter(h, 0.0), 0.8, 5.0, plane)
        assert math.isfinite(below.far_mm) and below.far_mm > 1e6
    # thin lens from the lens: H = f²/(Nc) + f (Wikipedia, "Hyperfocal distance")
    assert thick_dof(50.0, 8.0, 0.03, 3000.0, distance_from="lens").hyperfocal_mm == pytest.approx(2500 / 0.24 + 50)


def test_focus_at_infinity_and_at_one_to_one():
    # infinity: near limit from E → f²/(Nc) (thin lens: the hyperfocal distance without +f)
    inf = thick_dof(50.0, 8.0, 0.03, math.inf, distance_from="entrance_pupil")
    assert inf.near_mm == pytest.approx(2500 / 0.24, rel=1e-14) and math.isinf(inf.far_mm)
    assert inf.magnification == 0.0
    # 1:1 from the sensor: D = 4f + δ gives m = 1 (thin lens: u = v = 2f)
    one = thick_dof(50.0, 4.0, 0.03, 4 * 50.0 + 7.0, pupil_magnification=1.5, hiatus_mm=7.0)
    assert one.magnification == pytest.approx(1.0, rel=1e-12)
    assert one.near_mm < 207.0 < one.far_mm


@pytest.mark.parametrize(
    "args, kwargs, param",
    [
        ((0.0, 8.0, 0.03, 3000.0), {}, "focal_length_mm"),
        ((-50.0, 8.0, 0.03, 3000.0), {}, "focal_length_mm"),
        ((50.0, 0.0, 0.03, 3000.0), {}, "f_number"),
        ((50.0, 8.0, -0.03, 3000.0), {}, "coc_mm"),
        ((50.0, 8.0, 0.03, 3000.0), {"pupil_magnification": 0.0}, "pupil_magnification"),
        ((50.0, 8.0, 0.03, math.nan), {}, "distance_mm"),
        ((math.nan, 8.0, 0.03, 3000.0), {}, "focal_length_mm"),
        ((50.0, 8.0, 0.03, 3000.0), {"hiatus_mm": math.nan}, "hiatus_mm"),
        ((50.0, 8.0, 0.03, 199.0), {}, "distance_mm"),  # closer than 1:1 (4f)
        ((50.0, 8.0, 0.03, 49.0), {"distance_from": "lens"}, "distance_mm"),  # closer than f
        ((50.0, 8.0, 0.03, 3000.0), {"pupil_magnification": 0.3, "hiatus_mm": 0.0}, "hiatus_mm"),  # E behind sensor
    ],
)
def test_domain_errors_name_the_parameter(args, kwargs, param):
    with pytest.raises(DomainError) as caught:
        thick_dof(*args, **kwargs)
    assert caught.value.param == param


def test_unknown_plane_lists_valid_ones():
    with pytest.raises(ValueError, match="sensor, lens, entrance_pupil"):
        thick_dof(50.0, 8.0, 0.03, 3000.0, distance_from="film")


def test_working_f_number():
    # Wikipedia, "f-number", working f-number N(1 + m/P)
    assert working_f_number(2.8, 1.0) == pytest.approx(5.6)
    assert working_f_number(4.0, 0.5, pupil_magnification=0.5) == pytest.approx(8.0)
    assert working_f_number(4.0, 0.0, 3.0) == 4.0


SCALAR_CASE = (85.0, 2.0, 0.03, 2500.0, 1.3, -12.0)


@pytest.mark.parametrize("shape", [(6,), (2, 3)])
@pytest.mark.parametrize("plane", ["sensor", "lens", "entrance_pupil"])
def test_scalar_and_array_calls_agree(shape, plane):
    # STYLE.md (colour-science habit): a scalar call equals the same values tiled into arrays
    scalar = thick_dof(*SCALAR_CASE[:4], pupil_magnification=SCALAR_CASE[4], hiatus_mm=SCALAR_CASE[5], distance_from=plane)
    tiled = [np.full(shape, v) for v in SCALAR_CASE]
    array = thick_dof(*tiled[:4], pupil_magnification=tiled[4], hiatus_mm=tiled[5], distance_from=plane)
    for field, value in zip(scalar._fields, scalar):
        assert isinstance(value, float), field
        assert np.shape(getattr(array, field)) == shape, field
        np.testing.assert_array_equal(getattr(array, field), np.full(shape, value), err_msg=field)


def test_array_mixes_infinite_and_beyond_hyperfocal_rows():
    result = thick_dof(50.0, 8.0, 0.03, np.array([3000.0, 20000.0, np.inf]), pupil_magnification=1.2, hiatus_mm=-5.0)
    assert np.isfinite(result.far_mm[0]) and np.isinf(result.far_mm[1:]).all()
    assert np.all(np.isfinite(result.near_mm)) and np.isinf(result.front_mm[2])


# -- properties over the whole domain (docs/design.md §6) -----------------------------------

focal = st.floats(1.0, 5000.0)
f_numbers = st.floats(0.7, 1024.0)
cocs = st.floats(0.0005, 1.0)
pupils = st.floats(0.3, 8.0)


@st.composite
def scenes(draw):
    f, n, c, p = draw(focal), draw(f_numbers), draw(cocs), draw(pupils)
    # hiatus large enough that the entrance pupil lies in front of the sensor: v + δ + f(1 − 1/P) > 0
    hiatus = f * (1.0 / p - 1.0) + f * draw(st.floats(-0.5, 2.0))
    # strictly beyond 1:1 (D = 4f + δ exactly is pinned in test_focus_at_infinity_and_at_one_to_one;
    # a sum rounded a hair below it is rightly refused)
    beyond = draw(st.one_of(st.floats(1e-6, 1e3), st.floats(1e3, 1e12), st.just(math.inf)))
    distance = 4.0 * f + hiatus + f * beyond
    return f, n, c, p, hiatus, distance


@settings(max_examples=300, deadline=None)
@given(scenes())
def test_limits_are_ordered_finite_and_positive(scene):
    f, n, c, p, hiatus, distance = scene
    r = thick_dof(f, n, c, distance, pupil_magnification=p, hiatus_mm=hiatus)
    values = [r.near_mm, r.far_mm, r.front_mm, r.rear_mm, r.total_mm, r.hyperfocal_mm, r.magnification]
    assert not any(math.isnan(v) for v in values)
    assert all(v >= 0.0 for v in values)
    assert 0.0 < r.near_mm <= distance <= r.far_mm
    assert math.isinf(r.far_mm) == (distance >= r.hyperfocal_mm)
    assert 0.0 <= r.magnification <= 1.0 + 1e-12


@settings(max_examples=200, deadline=None)
@given(scenes())
def test_entrance_pupil_plane_gives_the_same_depths(scene):
    f, n, c, p, hiatus, distance = scene
    sensor = thick_dof(f, n, c, distance, pupil_magnification=p, hiatus_mm=hiatus)
    if math.isinf(distance):
        return
    span = distance - hiatus
    root = math.sqrt(max(1.0 - 4.0 * f / span, 0.0))
    v = 2.0 * f / (1.0 + root)
    offset = v + hiatus + f * (1.0 - 1.0 / p)  # film → entrance pupil
    pupil = thick_dof(f, n, c, distance - offset, pupil_magnification=p, hiatus_mm=hiatus, distance_from="entrance_pupil")
    assert pupil.front_mm == pytest.approx(sensor.front_mm, rel=1e-9)
    if sensor.far_mm < 0.5 * sensor.hyperfocal_mm:  # well away from the ill-conditioned hyperfocal
        assert pupil.rear_mm == pytest.approx(sensor.rear_mm, rel=1e-6)


mpmath.mp.dps = 50


def reference(f, n, c, p, hiatus, distance):
    """The same closed form at 50 digits (sensor plane)."""
    f, n, c, p, hiatus, d = (mpmath.mpf(v) for v in (f, n, c, p, hiatus, distance))
    span = d - hiatus
    u = span / 2 * (1 + mpmath.sqrt(1 - 4 * f / span))
    x = u - f * (1 - 1 / p)
    k = n * c * (u - f)
    front = x * k / (f * f + k)
    rear = x * k / (f * f - k) if f * f > k else mpmath.inf
    return front, rear, f * f - k


def condition(scene, which):
    """Σ over the inputs of |∂ ln(result)/∂ ln(input)|, by 50-digit finite differences."""
    base = reference(*scene)[which]
    total = mpmath.mpf(0)
    for i, value in enumerate(scene):
        if value == 0:
            continue
        bumped = list(scene)
        bumped[i] = mpmath.mpf(value) * (1 + mpmath.mpf("1e-25"))
        total += abs(reference(*bumped)[which] / base - 1) / mpmath.mpf("1e-25")
    return float(total)


@settings(max_examples=200, deadline=None)
@given(scenes())
def test_float64_agrees_with_mpmath_within_the_condition_number(scene):
    # docs/design.md §6: relative error ≤ small multiple of (1 + condition number) × eps
    f, n, c, p, hiatus, distance = scene
    if math.isinf(distance):
        return
    r = thick_dof(f, n, c, distance, pupil_magnification=p, hiatus_mm=hiatus)
    front, rear, gap = reference(*scene)
    eps = 2.0**-52
    assert abs(r.front_mm - front) <= 16 * eps * (1 + condition(scene, 0)) * abs(front)
    if math.isfinite(r.rear_mm) and gap > 0:
        assert abs(r.rear_mm - rear) <= 16 * eps * (1 + condition(scene, 1)) * abs(rear)
