"""The ``raytrace`` model against the real-ray reference rows, plus ray-level checks.

Reference: tests/data/oracle-dof.csv (rayoptics 0.9.8 for dgauss100 and cellphone,
optiland 0.6.3 for telephoto127, telecentric36 and wideangle17; definitions in
tests/data/oracle-README.md). Required
agreement: 0.5 % of the front and rear depths (real_defocus) and 1 % of blur_at_focus_mm
(real_rms); the assertions below are far tighter, which the README's ~6e-9 says is possible.
"""

from __future__ import annotations

import contextlib
import csv
import math
from pathlib import Path

import numpy as np
import pytest
import yaml

from camtool.core.errors import DomainError
from camtool.dof.paraxial import paraxial_dof
from camtool.dof.realray import NoDepthOfField, raytrace_dof, real_focus
from camtool.optics.paraxial import first_order
from camtool.optics.prescription import prescription_from_mapping
from camtool.optics.tracer import RayTraceError, real_tracer

DATA = Path(__file__).parent / "data"
LENSES = {
    name: prescription_from_mapping(yaml.safe_load((DATA / "prescriptions" / f"{name}.yaml").read_text()), name)
    for name in ("dgauss100", "telephoto127", "cellphone", "telecentric36", "wideangle17")
}
with open(DATA / "oracle-dof.csv", newline="") as _handle:
    ROWS = list(csv.DictReader(_handle))


def rows(method):
    return [r for r in ROWS if r["method"] == method]


def row_id(r):
    return f"{r['lens']}-f{r['f_number']}-{float(r['focus_distance_mm']):.6g}"


def scene(r):
    return LENSES[r["lens"]], float(r["f_number"]), float(r["coc_mm"]), float(r["focus_distance_mm"])


@pytest.mark.parametrize("row", rows("real_defocus"), ids=row_id)
def test_real_defocus_rows(row):
    # oracle-dof.csv, method = real_defocus (required: 0.5 % of each depth; measured ~3e-9)
    lens, n, c, focus = scene(row)
    result = raytrace_dof(lens, n, c, focus)
    front, rear = focus - float(row["near_mm"]), float(row["far_mm"]) - focus
    assert result.front_mm == pytest.approx(front, rel=1e-7)
    assert result.rear_mm == pytest.approx(rear, rel=1e-7)
    assert result.near_mm <= focus <= result.far_mm
    assert result.magnification == pytest.approx(float(row["magnification"]), rel=1e-9)


@pytest.mark.parametrize("row", rows("real_rms"), ids=row_id)
def test_real_rms_rows(row):
    # oracle-dof.csv, method = real_rms: blur at focus (required 1 %), film position, and the
    # limits where the total blur leaves depth of field (nan rows: none)
    lens, n, c, focus = scene(row)
    at_focus = real_focus(lens, n, focus, criterion="rms")
    assert at_focus.blur_mm == pytest.approx(float(row["blur_at_focus_mm"]), rel=1e-7)
    assert at_focus.film_to_entrance_pupil_mm == pytest.approx(float(row["film_to_entrance_pupil_mm"]), abs=1e-10 * focus)
    assert at_focus.film_to_front_principal_mm == pytest.approx(float(row["film_to_front_principal_mm"]), abs=1e-10 * focus)
    assert at_focus.distance_mm == pytest.approx(focus, rel=1e-12)
    if row["near_mm"] == "nan":
        with pytest.raises(NoDepthOfField) as caught:
            raytrace_dof(lens, n, c, focus, criterion="rms")
        assert caught.value.param == "coc_mm"
        assert caught.value.blur_at_focus_mm == pytest.approx(float(row["blur_at_focus_mm"]), rel=1e-7)
        return
    result = raytrace_dof(lens, n, c, focus, criterion="rms")
    assert result.front_mm == pytest.approx(focus - float(row["near_mm"]), rel=1e-6)
    assert result.rear_mm == pytest.approx(float(row["far_mm"]) - focus, rel=1e-6)


def test_distance_planes_give_the_same_limits():
    # oracle-dof.csv first cellphone real_defocus row, re-measured from the entrance pupil
    row = next(r for r in rows("real_defocus") if r["lens"] == "cellphone")
    lens, n, c, focus = scene(row)
    offset = float(row["film_to_entrance_pupil_mm"])
    pupil = raytrace_dof(lens, n, c, focus - offset, distance_from="entrance_pupil")
    assert pupil.near_mm + offset == pytest.approx(float(row["near_mm"]), rel=1e-9)
    assert pupil.far_mm + offset == pytest.approx(float(row["far_mm"]), rel=1e-9)
    offset_h = float(row["film_to_front_principal_mm"])
    lens_plane = raytrace_dof(lens, n, c, focus - offset_h, distance_from="lens")
    assert lens_plane.front_mm == pytest.approx(focus - float(row["near_mm"]), rel=1e-7)


def test_far_limit_at_infinity_and_hyperfocal():
    # dgauss100 at f/22 (c = 0.03): focus beyond the hyperfocal distance keeps infinity sharp
    lens = LENSES["dgauss100"]
    hyper = raytrace_dof(lens, 22.0, 0.03, 5000.0).hyperfocal_mm
    # paraxial estimate f²/(Nc) + 2f + Nc + δ (docs/design.md §4); real focus shift is small
    fo = first_order(lens)
    assert hyper == pytest.approx(fo.efl_mm**2 / 0.66 + 2 * fo.efl_mm + 0.66 + fo.hiatus_mm, rel=0.02)
    beyond = raytrace_dof(lens, 22.0, 0.03, hyper * 1.000001)
    assert math.isinf(beyond.far_mm) and math.isinf(beyond.rear_mm)
    short = raytrace_dof(lens, 22.0, 0.03, hyper * 0.999)
    assert math.isfinite(short.far_mm) and short.far_mm > 100 * hyper
    at_infinity = raytrace_dof(lens, 22.0, 0.03, math.inf)
    assert math.isinf(at_infinity.far_mm) and math.isinf(at_infinity.front_mm)
    # focused at infinity, the near limit is about the hyperfocal distance (thin lens: H − f)
    assert at_infinity.near_mm == pytest.approx(hyper, rel=0.02)


def test_small_aperture_approaches_paraxial():
    # at f/64 aberrations vanish: real limits → first-order ones (tests/data/oracle-README.md:
    # the paraxial method is the small-aperture limit of the same definitions)
    # cellphone.yaml's odd aspheric terms (a3·|r|³) bend rays at order h² rather than h³, so
    # its approach to the paraxial limit is slower (0.3 % at f/64, 0.05 % at f/256)
    for lens, tolerance in zip(LENSES.values(), (1e-4, 2e-3, 1e-2)):
        f = first_order(lens).efl_mm
        real = raytrace_dof(lens, 64.0, f / 2000, 10 * f)  # well inside the hyperfocal (≈ 31 f)
        para = paraxial_dof(lens, 64.0, f / 2000, 10 * f)
        assert real.front_mm == pytest.approx(para.front_mm, rel=tolerance)
        assert real.rear_mm == pytest.approx(para.rear_mm, rel=tolerance)


def singlet(stop_first=True):
    """Plano-convex singlet (f = 100 mm), curved side first, a flat back; stop first or last."""
    stop = {"radius_mm": "inf", "thickness_mm": 0.0, "n": 1.0, "stop": True}
    glass = {"radius_mm": 51.68, "thickness_mm": 5.0, "n": 1.5168}
    if stop_first:
        back = {"radius_mm": "inf", "thickness_mm": 96.7, "n": 1.0}
        return prescription_from_mapping({"surfaces": [stop, glass, back]})
    back = {"radius_mm": "inf", "thickness_mm": 2.0, "n": 1.0}
    return prescription_from_mapping({"surfaces": [glass, back, {**stop, "thickness_mm": 94.7}]})


@pytest.mark.parametrize("stop_first", [True, False])
def test_synthetic_singlet_extremes(stop_first):
    lens = singlet(stop_first)
    f = first_order(lens).efl_mm
    fo = first_order(lens)
    one_to_one = 4 * f + fo.hiatus_mm
    # focus at (nearly) 1:1 and a pinhole f-number: still ordered, finite, close to paraxial
    for n, distance in ((1024.0, 1.001 * one_to_one), (4.0, 1.05 * one_to_one), (1024.0, 1e7)):
        r = raytrace_dof(lens, n, 0.03, distance)
        p = paraxial_dof(lens, n, 0.03, distance)
        assert 0 < r.near_mm <= distance <= r.far_mm
        # a pinhole-sized stop has no aberrations left; at f/4 the singlet's spherical
        # aberration changes the depth by over 10 %, which is the point of the model
        if n > 1000:
            assert r.front_mm == pytest.approx(p.front_mm, rel=1e-3)
    assert raytrace_dof(lens, 1024.0, 0.03, 1e7).far_mm == math.inf


def test_snell_law_at_a_flat_interface():
    # sin θ′ = sin θ / n (Snell) for a single flat glass surface
    block = prescription_from_mapping(
        {"surfaces": [{"radius_mm": "inf", "thickness_mm": 10.0, "n": 1.5, "stop": True},
                      {"radius_mm": -40.0, "thickness_mm": 80.0, "n": 1.0}]}
    )
    tracer = real_tracer(block)
    sin_in = np.array([0.0, 0.1, 0.5, 0.9])
    _y, _z, m, l = tracer.trace(np.zeros(4), sin_in, np.sqrt(1 - sin_in**2), end=1)
    np.testing.assert_allclose(m, sin_in / 1.5, rtol=1e-15)
    np.testing.assert_allclose(m * m + l * l, 1.0, rtol=1e-15)


@pytest.mark.parametrize("index", range(1, 10))
def test_ray_hits_lie_on_the_aspheric_surfaces(index):
    # the hit points of real rays satisfy the sag formula of cellphone.yaml's header
    lens = LENSES["cellphone"]
    tracer = real_tracer(lens)
    heights = np.linspace(-0.7, 0.7, 15)
    slopes = np.full(15, 0.05)
    y, z, _, _ = tracer.trace(heights, slopes, np.sqrt(1 - slopes**2), end=index + 1)
    surface, vertex = lens.surfaces[index], lens.vertices_mm[index]
    sags = np.array([surface.sag_mm(v) for v in y])
    np.testing.assert_allclose(z - vertex, sags, atol=1e-12)


def test_rays_that_miss_raise_a_clear_error():
    # a strongly curved singlet (R = 10 mm, f = 20 mm) at f/0.1: the beam (100 mm radius) is
    # ten times wider than the sphere; the few rays that hit it are too few to trust
    ball = prescription_from_mapping(
        {"surfaces": [{"radius_mm": "inf", "thickness_mm": 0.0, "n": 1.0, "stop": True},
                      {"radius_mm": 10.0, "thickness_mm": 4.0, "n": 1.5},
                      {"radius_mm": "inf", "thickness_mm": 17.3, "n": 1.0}]}
    )
    with pytest.raises(RayTraceError, match="rays"):
        raytrace_dof(ball, 0.1, 0.03, 1000.0)


@pytest.mark.parametrize(
    "args, param",
    [
        ((0.0, 0.03, 3000.0), "f_number"),
        ((2.0, 0.0, 3000.0), "coc_mm"),
        ((2.0, 0.03, math.nan), "distance_mm"),
        ((2.0, 0.03, -5.0), "distance_mm"),
        ((2.0, 0.03, 300.0), "distance_mm"),  # closer than 1:1 (4f + δ ≈ 369 mm)
    ],
)
def test_domain_errors(args, param):
    with pytest.raises(DomainError) as caught:
        raytrace_dof(LENSES["dgauss100"], *args)
    assert caught.value.param == param


def test_bad_options():
    with pytest.raises(ValueError, match="criterion must be one of defocus, rms"):
        raytrace_dof(LENSES["dgauss100"], 2.0, 0.03, 3000.0, criterion="geometric")
    with pytest.raises(ValueError, match="distance_from"):
        raytrace_dof(LENSES["dgauss100"], 2.0, 0.03, 3000.0, distance_from="film")


def test_array_call_matches_scalar_calls():
    lens = LENSES["telephoto127"]
    distances = np.array([[800.0, 3000.0], [1e4, np.inf]])
    many = raytrace_dof(lens, 5.6, 0.03, distances)
    assert many.near_mm.shape == (2, 2)
    for index in np.ndindex(distances.shape):
        one = raytrace_dof(lens, 5.6, 0.03, float(distances[index]))
        for field in one._fields:
            assert getattr(many, field)[index] == getattr(one, field), field


def test_arrays_of_f_numbers_match_scalar_calls():
    # several f-numbers in one call share one batched trace for their interpolants
    from camtool.dof.realray import _curves

    lens = LENSES["wideangle17"]
    n = np.array([4.0, 4.4, 5.2, 7.1, 9.9, 13.0])
    _curves.cache_clear()
    many = raytrace_dof(lens, n, 0.019, 1500.0)
    _curves.cache_clear()
    for i, value in enumerate(n):
        one = raytrace_dof(lens, float(value), 0.019, 1500.0)
        assert many.front_mm[i] == pytest.approx(one.front_mm, rel=1e-10)
        assert many.rear_mm[i] == pytest.approx(one.rear_mm, rel=1e-10)
        assert many.hyperfocal_mm[i] == pytest.approx(one.hyperfocal_mm, rel=1e-10)


@pytest.mark.parametrize("name, f_number", [("cellphone", 2.8), ("cellphone", 8.0), ("dgauss100", 2.0),
                                            ("dgauss100", 8.0), ("telephoto127", 5.6), ("telephoto127", 8.0)])
def test_focus_at_exactly_the_closest_distance(name, f_number):
    # a root on the scan's last grid point: the scan's vectorised sums and the scalar ones seen by Brent's
    # method differ by round-off there, which must not turn into a bracket without a sign change
    from camtool.dof.realray import _curves, closest_focus_mm

    lens = LENSES[name]
    _curves.cache_clear()
    with contextlib.suppress(NoDepthOfField):  # the total-blur criterion refines the interpolants if need be
        raytrace_dof(lens, f_number, 0.005, 100.0 * first_order(lens).efl_mm, criterion="rms")
    closest = closest_focus_mm(lens, f_number)
    assert real_focus(lens, f_number, closest).distance_mm == pytest.approx(closest, rel=1e-12)
    for coc in (0.005, 0.03):
        defocus = raytrace_dof(lens, f_number, coc, closest)
        assert 0.0 < defocus.near_mm < closest < defocus.far_mm
        try:
            rms = raytrace_dof(lens, f_number, coc, closest, criterion="rms")
        except NoDepthOfField as caught:
            assert caught.blur_at_focus_mm >= coc  # the lens's own blur at this focus exceeds c
        else:
            assert rms.near_mm < closest < rms.far_mm


@pytest.mark.parametrize("name", ["canon-rf50-f1.2", "nikon-z50-f1.8", "cellphone"])
def test_an_even_surface_s_sag_and_slope_in_q_are_the_polynomial_s(name):
    """The sag and slope of a surface with even powers alone, taken in q = y² (camtool.optics.tracer._even_sag),
    against the sag formula evaluated at 40 digits (mpmath) and its derivative by mpmath's own differentiation;
    a surface with an odd power takes the general path."""
    import mpmath

    from camtool.optics import tracer

    shipped = Path(__file__).parent.parent / "lens_db" / "prescriptions" / f"{name}.yaml"
    lens = prescription_from_mapping(yaml.safe_load(shipped.read_text(encoding="utf-8")))
    surfaces = [s for s in real_tracer(lens).surfaces if not s.spherical]
    assert surfaces
    for s in surfaces:
        if any(a != 0.0 for a in s.dense[0::2]):
            assert s.even is None
            continue
        assert s.even is not None
        mpmath.mp.dps = 40
        c, k = mpmath.mpf(s.c), mpmath.mpf(s.k)

        def sag(y, c=c, k=k, s=s):
            r2 = y * y
            return c * r2 / (1 + mpmath.sqrt(1 - (1 + k) * c * c * r2)) + sum(
                mpmath.mpf(a) * abs(y) ** (n + 1) for n, a in enumerate(s.dense))

        heights = np.array([-9.0, -3.3, -0.5, 0.0, 0.7, 4.1, 11.0])
        values, slopes = tracer._even_sag(s, s.even, heights)
        for y, value, slope in zip(heights, values, slopes, strict=True):
            assert value == pytest.approx(float(sag(mpmath.mpf(y))), rel=1e-14, abs=1e-15)
            assert slope == pytest.approx(float(mpmath.diff(sag, mpmath.mpf(y))), rel=1e-12, abs=1e-15)
