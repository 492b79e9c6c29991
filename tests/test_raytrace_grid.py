"""The ``raytrace`` model never fails to trace over a grid of scenes on every shared lens.

Every prescription in tests/data/prescriptions (the reference data's five lenses, among them
the retrofocus ``wideangle17`` with its front principal plane 3.1 f behind the first vertex and
the nearly image-telecentric ``telecentric36``, both with pupil magnifications above 7), at CoC
0.005 to 0.1 mm, at every f-number from the design value to f/32, focused anywhere from the
closest focus to infinity. Each result must be ordered and physical: the near limit in front of
the lens and of the focus, the far limit behind the focus, and infinity within the depth of field
once the focus passes the hyperfocal distance.
"""

from __future__ import annotations

import math
from pathlib import Path

import pytest
import yaml

from camtool.dof import realray
from camtool.dof.realray import NoDepthOfField, closest_focus_mm, raytrace_dof, real_focus
from camtool.optics.paraxial import first_order
from camtool.optics.prescription import prescription_from_mapping

DATA = Path(__file__).parent / "data" / "prescriptions"
NAMES = ("dgauss100", "telephoto127", "cellphone", "telecentric36", "wideangle17")
COCS = (0.005, 0.019, 0.1)


def load(name):
    return prescription_from_mapping(yaml.safe_load((DATA / f"{name}.yaml").read_text()), name)


def f_numbers(lens):
    design = lens.f_number
    return sorted({design, design * 1.4, *(n for n in (5.6, 11.0, 22.0, 32.0) if n > design)})


def focus_distances(lens, n, c):
    closest = closest_focus_mm(lens, n)
    f = first_order(lens).efl_mm
    hyper = f * f / (n * c)
    distances = [closest, closest * 1.0001, closest * 1.05, closest * 1.5, 3 * closest, 0.3 * hyper, hyper, 10 * hyper]
    return [*sorted(d for d in distances if d >= closest), math.inf]


@pytest.mark.parametrize("name", NAMES)
def test_every_scene_traces(name):
    lens = load(name)
    for n in f_numbers(lens):
        for c in COCS:
            for distance in focus_distances(lens, n, c):
                where = f"{name} f/{n:g} c={c} at {distance:.6g} mm"
                r = raytrace_dof(lens, n, c, distance)
                film = real_focus(lens, n, distance).film_z_mm  # the first vertex is `film` from the film
                assert 0.0 < film * (1 - 1e-12) <= r.near_mm <= distance <= r.far_mm, where
                assert r.front_mm >= 0.0 and r.rear_mm >= 0.0, where
                assert r.hyperfocal_mm > 0.0 and math.isfinite(r.hyperfocal_mm), where
                if distance > r.hyperfocal_mm * (1 + 1e-9):
                    assert math.isinf(r.far_mm), where
                if math.isfinite(distance) and distance < r.hyperfocal_mm * (1 - 1e-9):
                    assert math.isfinite(r.far_mm), where
                assert all(not math.isnan(v) for v in r), where


def test_retrofocus_closest_focus_puts_the_object_at_the_first_vertex():
    # wideangle17: 1:1 would put the object 19.1 mm behind the first surface (oracle-README.md),
    # so the closest focus is the object at the first vertex, in front of the focal point F
    lens = load("wideangle17")
    focus = real_focus(lens, 4.0, closest_focus_mm(lens, 4.0))
    assert focus.object_z_mm == 0.0
    assert focus.magnification < 0.47  # oracle-README.md: m stays below 0.47 in front of the lens
    # the near limit cannot lie closer than the lens: at the closest focus it is the first vertex
    r = raytrace_dof(lens, 4.0, 0.019, closest_focus_mm(lens, 4.0))
    assert r.near_mm == pytest.approx(focus.film_z_mm, rel=1e-12)
    with pytest.raises(Exception, match="distance_mm"):
        raytrace_dof(lens, 4.0, 0.019, 0.99 * closest_focus_mm(lens, 4.0))


@pytest.mark.parametrize("name", NAMES)
def test_total_blur_criterion_traces_too(name):
    # the rms criterion over part of the grid: limits in order, or NoDepthOfField where the lens's
    # own blur at the focus already reaches c (a legitimate answer, not a failure to trace)
    lens = load(name)
    for n in (lens.f_number, 11.0):
        for c in (0.019, 0.1):
            for distance in focus_distances(lens, n, c)[::2]:
                try:
                    r = raytrace_dof(lens, n, c, distance, criterion="rms")
                except NoDepthOfField as caught:
                    assert caught.blur_at_focus_mm >= c
                    continue
                assert 0.0 < r.near_mm <= distance <= r.far_mm, (name, n, c, distance)


def test_polished_roots_agree_with_the_interpolated_ones(monkeypatch):
    # with the interpolants distrusted, every root is polished by Newton steps on direct traces:
    # both paths give the same limits (to the precision of the roots, ~1e-12 of the depth)
    scenes = [("dgauss100", 2.0, 0.03, 700.0), ("wideangle17", 4.0, 0.019, 1500.0), ("cellphone", 3.5, 0.0048, 300.0),
              ("telecentric36", 2.0, 0.0095, 250.0)]
    fast = [raytrace_dof(load(name), n, c, d) for name, n, c, d in scenes]
    monkeypatch.setattr(realray, "_TRUST", 0.0)
    realray._curves.cache_clear()
    try:
        for (name, n, c, d), one in zip(scenes, fast):
            slow = raytrace_dof(load(name), n, c, d)
            assert slow.front_mm == pytest.approx(one.front_mm, rel=1e-9), name
            assert slow.rear_mm == pytest.approx(one.rear_mm, rel=1e-9), name
            assert slow.hyperfocal_mm == pytest.approx(one.hyperfocal_mm, rel=1e-9), name
    finally:
        realray._curves.cache_clear()
