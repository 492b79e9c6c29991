"""The tilted lens: published hinge and wedge figures, the Scheimpflug and hinge identities (mpmath),
the limit of no tilt, and the thick-lens geometry against real rays through a tilted prescription."""

from __future__ import annotations

import math
from pathlib import Path

import mpmath
import pytest
import yaml

from camtool.core.errors import DomainError
from camtool.dof.closed import thin_dof
from camtool.dof.thick import thick_dof
from camtool.dof.tilt import (
    TiltLens,
    film_for_focus,
    hyperfocal_film,
    optimum_f_number,
    required_f_number,
    tilt_wedge,
)
from camtool.geometry.tilt import (
    axis_reciprocal,
    hinge_distance_mm,
    plane_through_points,
    scheimpflug_line_mm,
    sight_reciprocal,
    tilt_for_hinge_deg,
)
from camtool.optics.paraxial import first_order
from camtool.optics.prescription import prescription_from_mapping
from camtool.optics.tilted import traced_axial_blur_mm, traced_plane_of_focus

FOOT = 304.8
DATA = Path(__file__).parent / "data" / "prescriptions"
mpmath.mp.dps = 40


# --- published figures -----------------------------------------------------------------------

def test_merklinger_hinge_for_a_tilt_and_tilt_for_a_hinge() -> None:
    # H. M. Merklinger, "View Camera Focus and Depth of Field, Part I", View Camera, July/August 1996,
    # pp. 55-57, with a 150 mm Symmar-S: "J was 4.2 feet, and so the tilt angle was, near enough, 7°";
    # "we increased the lens tilt to 14°. ... the distance J must now be just over 2 feet".
    assert round(tilt_for_hinge_deg(150.0, 4.2 * FOOT)) == 7
    j = hinge_distance_mm(150.0, 14.0)
    assert 2.0 * FOOT < j < 2.1 * FOOT


def test_merklinger_hyperfocal_wedge_extends_j_either_side() -> None:
    # Merklinger, "View Camera Focus and Depth of Field, Part II", View Camera, Sept/Oct 1996, pp. 56-58:
    # "The hyperfocal distance for a 150 mm lens at f/11 is about 67 feet. This assumes a 0.1 millimeter
    # permissible circle of confusion", and "at the hyperfocal distance the depth of field extends a
    # distance J on either side of the subject plane, measured in the same direction we originally
    # measured J. J is always measured in a direction parallel to the film plane."
    lens = TiltLens(150.0)
    for tilt in (2.0, 7.0, 14.0):
        v = hyperfocal_film(lens, 11.0, 0.1, tilt)
        w = tilt_wedge(lens, 11.0, 0.1, tilt, v)
        at = 1.0 / w.k_focus  # the hyperfocal distance along the line of sight
        assert round((at * math.cos(math.radians(tilt)) - 150.0) / FOOT) == 67  # H = f²/(N·c), cos-projected
        above = w.hinge_mm * at * (w.k_near - w.k_focus)
        below = w.hinge_mm * at * (w.k_focus - w.k_far)
        assert above == pytest.approx(w.hinge_mm, rel=1e-12)
        assert below == pytest.approx(w.hinge_mm, rel=1e-12)
        assert abs(w.k_far) < 1e-15  # the far limit is parallel to the line of sight
        assert 1.0 / w.k_near == pytest.approx(at / 2, rel=1e-12)  # and the near limit at half the distance


def test_merklinger_wedge_grows_as_j_times_d_over_h() -> None:
    # Merklinger, Part II (as above): the wedge's half-height at distance D is about J·D/H (H = f²/(N·c)),
    # the v ≈ f approximation of the exact J·D·N·c/(f·v).
    lens, n, c, tilt = TiltLens(150.0), 11.0, 0.1, 5.0
    v = film_for_focus(lens, tilt, 20_000.0)
    w = tilt_wedge(lens, n, c, tilt, v)
    h = 150.0**2 / (n * c)
    for d in (5_000.0, 20_000.0, 60_000.0):
        above = w.hinge_mm * d * (w.k_near - w.k_focus)
        assert above == pytest.approx(w.hinge_mm * d * n * c / (150.0 * v), rel=1e-12)
        assert above == pytest.approx(w.hinge_mm * d / h, rel=0.02)


# --- identities ------------------------------------------------------------------------------

SCENES = [(f, tilt, s) for f in (24.0, 90.0, 210.0) for tilt in (0.5, 3.0, 8.5, 20.0) for s in (1500.0, 8000.0, 1e5)]


@pytest.mark.parametrize(("f", "tilt", "s"), SCENES)
def test_scheimpflug_and_hinge_lines(f: float, tilt: float, s: float) -> None:
    """Film, lens plane and plane of focus meet in one line; the plane of focus passes the hinge line."""
    lens = TiltLens(f)
    v = film_for_focus(lens, tilt, s)
    w = tilt_wedge(lens, 8.0, 0.03, tilt, v)
    t = mpmath.radians(tilt)
    j = mpmath.mpf(f) / mpmath.sin(t)
    assert w.hinge_mm == pytest.approx(float(j), rel=1e-14)
    # the hinge line lies on the front focal plane: its projection on the lens axis is f
    assert float(j * mpmath.sin(t)) == pytest.approx(f, rel=1e-14)
    # Scheimpflug line: the film x = −v meets the lens plane x·cos θ + y·sin θ = 0 at y = v·cot θ
    sy = mpmath.mpf(v) * mpmath.cot(t)
    assert scheimpflug_line_mm(tilt, v) == pytest.approx(float(sy), rel=1e-13)
    # ... and that point lies on the plane of focus y = J·(1 − k·x)
    on_plane = j * (1 - mpmath.mpf(w.k_focus) * (-mpmath.mpf(v)))
    assert float(on_plane) == pytest.approx(float(sy), rel=1e-9)


@pytest.mark.parametrize(("f", "tilt", "s"), SCENES[::3])
def test_every_point_of_the_plane_of_focus_is_imaged_on_the_film(f: float, tilt: float, s: float) -> None:
    """Image points of the plane of focus by the thin lens (in mpmath) lie on the film; those of the limit
    planes lie where the blur across the tilt is exactly c."""
    n, c = 8.0, 0.03
    lens = TiltLens(f)
    v = film_for_focus(lens, tilt, s)
    w = tilt_wedge(lens, n, c, tilt, v)
    t = mpmath.radians(tilt)
    ca, sa = mpmath.cos(t), mpmath.sin(t)
    j = mpmath.mpf(f) / sa
    d = mpmath.mpf(f) / n

    def image_x(x: mpmath.mpf, k: float) -> mpmath.mpf:
        y = j * (1 - mpmath.mpf(k) * x)
        along = x * ca + y * sa  # distance in front of the lens along its axis
        across = -x * sa + y * ca
        behind = f * along / (along - f)
        height = -across * behind / along
        return -behind * ca - height * sa  # camera x of the image point

    for x in (mpmath.mpf(s) / 3, mpmath.mpf(s), mpmath.mpf(s) * 4):
        assert float(image_x(x, w.k_focus)) == pytest.approx(-v, rel=1e-9)
        for k, sign in ((w.k_near, 1), (w.k_far, -1)):
            behind_film = -image_x(x, k)
            blur = d * sign * (behind_film - v) / behind_film
            assert float(blur) == pytest.approx(c, rel=1e-8)


@pytest.mark.parametrize("tilt", [0.0, 1e-9])
@pytest.mark.parametrize(("p", "delta"), [(1.0, 0.0), (0.6, 12.0), (2.4, -20.0)])
def test_no_tilt_is_ordinary_depth_of_field(tilt: float, p: float, delta: float) -> None:
    f, n, c, s = 50.0, 8.0, 0.03, 3000.0
    lens = TiltLens(f, p, delta)
    v = film_for_focus(lens, tilt, s)
    w = tilt_wedge(lens, n, c, tilt, v)
    if p == 1.0 and delta == 0.0:
        ordinary = thin_dof(f, n, c, s, distance_from="lens")
    else:
        ordinary = thick_dof(f, n, c, s, p, delta, distance_from="lens")
    assert 1.0 / w.k_near == pytest.approx(ordinary.near_mm, rel=1e-9)
    assert 1.0 / w.k_far == pytest.approx(ordinary.far_mm, rel=1e-9)
    if tilt == 0.0:
        assert w.hinge_mm == math.inf and w.focus_deg == w.near_deg == w.far_deg == 0.0


def test_no_tilt_from_the_sensor_matches_thick_dof() -> None:
    lens = TiltLens(85.0, 0.7, 15.0)
    v = film_for_focus(lens, 0.0, 4000.0, distance_from="sensor")
    w = tilt_wedge(lens, 4.0, 0.03, 0.0, v)
    ordinary = thick_dof(85.0, 4.0, 0.03, 4000.0, 0.7, 15.0, distance_from="sensor")
    offset = v + 15.0  # the film to H
    assert 1.0 / w.k_near + offset == pytest.approx(ordinary.near_mm, rel=1e-12)
    assert 1.0 / w.k_far + offset == pytest.approx(ordinary.far_mm, rel=1e-12)


@pytest.mark.parametrize("along", ["sight", "axis"])
def test_focus_distance_from_the_sensor(along: str) -> None:
    lens, tilt, d = TiltLens(90.0, 1.8, -6.0), 6.0, 2500.0
    v = film_for_focus(lens, tilt, d, along, "sensor")
    cos = math.cos(math.radians(tilt))
    k = cos / 90.0 - 1.0 / v
    if along == "sight":
        assert 1.0 / k + v - 6.0 * cos == pytest.approx(d, rel=1e-13)
    else:
        assert 1.0 / axis_reciprocal(90.0, tilt, k) + v / cos - 6.0 == pytest.approx(d, rel=1e-13)
        # along the axis it is the ordinary lens equation 1/s + 1/s′ = 1/f
        s = 1.0 / axis_reciprocal(90.0, tilt, k)
        assert 1.0 / s + cos / v == pytest.approx(1.0 / 90.0, rel=1e-13)


def test_axis_and_sight_reciprocals_invert() -> None:
    for tilt in (-10.0, 0.0, 4.0, 30.0):
        for k in (-1e-4, 0.0, 3e-4):
            assert sight_reciprocal(50.0, tilt, axis_reciprocal(50.0, tilt, k)) == pytest.approx(k, abs=1e-18)


def test_tilt_for_hinge_inverts_hinge_distance() -> None:
    for tilt in (0.1, 1.0, 8.5, 45.0, -3.0):
        assert tilt_for_hinge_deg(24.0, hinge_distance_mm(24.0, tilt)) == pytest.approx(tilt, rel=1e-12)
    assert tilt_for_hinge_deg(24.0, math.inf) == 0.0


def test_plane_through_two_points() -> None:
    f = 90.0
    for (x1, y1), (x2, y2) in [((2000.0, 1600.0), (30000.0, 1600.0)), ((1500.0, 900.0), (6000.0, -400.0)),
                               ((3000.0, -2000.0), (5000.0, -1000.0))]:
        r = plane_through_points(f, x1, y1, x2, y2)
        for x, y in ((x1, y1), (x2, y2)):
            assert r.hinge_mm * (1.0 - r.reciprocal_mm * x) == pytest.approx(y, rel=1e-12)
        assert hinge_distance_mm(f, r.tilt_deg) == pytest.approx(r.hinge_mm, rel=1e-12)
    flat = plane_through_points(f, 3000.0, 100.0, 3000.0, -200.0)
    assert flat.tilt_deg == 0.0 and 1.0 / flat.reciprocal_mm == 3000.0


@pytest.mark.parametrize(("points", "words"), [
    (((2000.0, 10.0), (2000.0, 10.0)), "two different"),
    (((2000.0, 50.0), (4000.0, 40.0)), "hinge line"),
    (((-100.0, 50.0), (4000.0, 40.0)), "in front"),
    (((2000.0, 0.0), (4000.0, 0.0)), "hinge line"),
])
def test_points_no_plane_can_pass(points: tuple[tuple[float, float], ...], words: str) -> None:
    (x1, y1), (x2, y2) = points
    with pytest.raises(DomainError, match=words):
        plane_through_points(90.0, x1, y1, x2, y2)


def test_hinge_closer_than_f_is_refused() -> None:
    with pytest.raises(DomainError, match="at least the focal length"):
        tilt_for_hinge_deg(90.0, 60.0)


@pytest.mark.parametrize(("p", "delta"), [(1.0, 0.0), (0.5, 10.0), (2.6, -30.0)])
def test_required_f_number_gives_the_wedge(p: float, delta: float) -> None:
    lens, c, tilt, d, h = TiltLens(90.0, p, delta), 0.03, 4.0, 15_000.0, 400.0
    v = film_for_focus(lens, tilt, 4000.0)
    n = required_f_number(lens, c, tilt, v, d, h)
    w = tilt_wedge(lens, n, c, tilt, v)
    above = w.hinge_mm * d * (w.k_near - w.k_focus)
    below = w.hinge_mm * d * (w.k_focus - w.k_far)
    assert min(above, below) == pytest.approx(h, rel=1e-9)  # the tighter side is met exactly
    assert max(above, below) >= h * (1 - 1e-12)
    if p == 1.0:
        assert n == pytest.approx(h * 90.0 * v / (w.hinge_mm * d * c), rel=1e-12)


def test_optimum_f_number_minimises_the_total_blur() -> None:
    needed, c = 16.0, 0.03
    best, blur = optimum_f_number(needed, c, 550.0)

    def total(n: float) -> float:
        return math.hypot(c * needed / n, 2.44 * 550e-6 * n)

    assert total(best) == pytest.approx(blur, rel=1e-12)
    assert total(best * 1.02) > blur and total(best / 1.02) > blur


def test_retrofocus_pupils_move_the_wedge() -> None:
    """P well above 1 (a retrofocus design) changes the wedge at the same lens-to-film setting."""
    thin, retro = TiltLens(24.0), TiltLens(24.0, 2.5, 0.0)
    v = film_for_focus(thin, 5.0, 3000.0)
    a, b = tilt_wedge(thin, 8.0, 0.03, 5.0, v), tilt_wedge(retro, 8.0, 0.03, 5.0, v)
    assert a.hinge_mm == b.hinge_mm and a.k_focus == b.k_focus  # the plane of focus does not depend on P
    assert b.k_near != pytest.approx(a.k_near, rel=1e-3)


def test_arrays_give_the_scalar_results() -> None:
    import numpy as np

    lens = TiltLens(90.0, 0.8, 5.0)
    tilts = np.array([0.0, 2.0, 8.5])
    distances = np.array([1500.0, 4000.0, np.inf])
    v = film_for_focus(lens, tilts, distances, "sight", "sensor")
    w = tilt_wedge(lens, 11.0, 0.03, tilts, v)
    for i in range(3):
        vi = film_for_focus(lens, float(tilts[i]), float(distances[i]), "sight", "sensor")
        wi = tilt_wedge(lens, 11.0, 0.03, float(tilts[i]), vi)
        assert v[i] == pytest.approx(vi, rel=1e-15)
        for got, want in zip(w, wi):
            assert float(got[i]) == pytest.approx(want, rel=1e-13)
    with pytest.raises(DomainError):
        film_for_focus(lens, tilts, np.array([1500.0, 50.0, 3000.0]))


def test_wedge_errors() -> None:
    lens = TiltLens(50.0)
    with pytest.raises(DomainError):
        tilt_wedge(lens, 8.0, 10.0, 3.0, 51.0)  # a CoC larger than the aperture
    with pytest.raises(DomainError):
        film_for_focus(lens, 3.0, 40.0)  # inside the focal length
    with pytest.raises(DomainError):
        hinge_distance_mm(50.0, 90.0)


# --- the thick geometry against real rays ----------------------------------------------------

def _shared(name: str):
    return prescription_from_mapping(yaml.safe_load((DATA / f"{name}.yaml").read_text()), source=name)


@pytest.mark.parametrize("name", ["dgauss100", "telephoto127"])
@pytest.mark.parametrize("tilt", [1.0, 4.0, -6.0])
def test_thick_tilt_geometry_against_real_rays(name: str, tilt: float) -> None:
    """Tilt the prescription and trace real rays about its axis: as the field shrinks the real plane of
    focus converges (quadratically: it is the field curvature) on the thick model's hinge and focus."""
    rx = _shared(name)
    fo = first_order(rx)
    lens = TiltLens(fo.efl_mm, fo.pupil_magnification, fo.hiatus_mm)
    v = film_for_focus(lens, tilt, 3000.0, "axis", "sensor")
    model = tilt_wedge(lens, 8.0, 0.03, tilt, v)
    errors = []
    for field in (1.0, 0.25):
        traced = traced_plane_of_focus(rx, tilt, v, model.k_focus, field_deg=field, about="axis")
        errors.append(abs(traced.hinge_mm / model.hinge_mm - 1))
        assert traced.k_focus == pytest.approx(model.k_focus, rel=5e-3)
        assert traced.focus_deg == pytest.approx(model.focus_deg, abs=0.05)
    assert errors[1] < 1e-4
    assert errors[1] < errors[0] / 8  # ~16 for a quadratic error


@pytest.mark.parametrize("name", ["dgauss100", "telephoto127"])
@pytest.mark.parametrize("n", [22.0, 32.0])
def test_wedge_limits_blur_c_by_real_rays(name: str, n: float) -> None:
    """On the tilted lens's axis, real rays through the stop's edge blur the near and far limits of the
    thick model's wedge by c across the tilt (their mean: the spherical aberration's focus shift cancels to
    first order); with the pupils put at the lens (P = 1) they do not: the pupils are what place the wedge."""
    rx = _shared(name)
    fo = first_order(rx)
    c, tilt = 0.03, 4.0
    errors = {}
    for p in (fo.pupil_magnification, 1.0):
        lens = TiltLens(fo.efl_mm, p, fo.hiatus_mm)
        v = film_for_focus(lens, tilt, 600.0, "axis", "sensor")
        w = tilt_wedge(lens, n, c, tilt, v)
        blurs = [traced_axial_blur_mm(rx, tilt, v, 1.0 / axis_reciprocal(fo.efl_mm, tilt, k), n)
                 for k in (w.k_near, w.k_far)]
        errors[p] = abs((blurs[0] + blurs[1]) / 2 / c - 1)
    assert errors[fo.pupil_magnification] < 0.003
    assert errors[1.0] > 0.02
