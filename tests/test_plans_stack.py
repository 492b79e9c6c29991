"""camtool.plans.stack called directly: keyword arguments, named results, numbers checked independently."""

from __future__ import annotations

import math
import time

import pytest

from camtool.core.errors import DomainError, InputError
from camtool.plans.depth import hyperfocal_setting
from camtool.plans.stack import bracket_rows, bracket_stack, most_frames, rail_chunks, rail_rows, rail_stack, stack_mode
from camtool.presets import load_db

INF = math.inf


def test_the_mode_follows_what_was_given() -> None:
    assert stack_mode(magnification=[1.0], depth_mm=5.0, near_mm=None, far_mm=None) == "rail"
    assert stack_mode(magnification=[], depth_mm=None, near_mm=500.0, far_mm=INF) == "bracket"
    with pytest.raises(InputError) as both:
        stack_mode(magnification=[1.0], depth_mm=5.0, near_mm=500.0, far_mm=None)
    assert both.value.usage and "not both" in str(both.value)
    with pytest.raises(InputError):
        stack_mode(magnification=[1.0], depth_mm=None, near_mm=None, far_mm=None)


def test_a_rail_stack_at_life_size_uses_the_wave_depth() -> None:
    # λ/NA² with NA = 1/(2·N·(1 + m)) at P = 1: 4·λ·N²·(1 + m)² = 4 × 550e-6 × 64 × 4 mm (Zerene Stacker's step size)
    r = rail_stack(depth_mm=10.0, f_number=8.0, magnification=1.0, coc_mm=0.03, overlap=0.0)
    assert r.criterion == "wave"
    assert r.plan.step_mm == pytest.approx(4 * 550e-6 * 64 * 4, rel=1e-12)
    assert r.frames == math.ceil(10.0 / (4 * 550e-6 * 64 * 4))
    below = rail_stack(depth_mm=10.0, f_number=8.0, magnification=0.5, coc_mm=0.03, overlap=0.0)
    # the macro rule 2·N·c·(1 + m/P)/m² (docs/closeup.md): 2 × 8 × 0.03 × 1.5 / 0.25
    assert below.criterion == "classic" and below.plan.step_mm == pytest.approx(2 * 8 * 0.03 * 1.5 / 0.25, rel=1e-12)


def test_rail_rows_stream_in_chunks_with_the_same_values() -> None:
    r = rail_stack(depth_mm=10.0, f_number=8.0, magnification=1.0, coc_mm=0.03, overlap=0.2)
    whole = rail_rows(r)
    chunks = list(rail_chunks(r, size=7))
    assert sum(c.size for c in chunks) == whole.size == r.frames
    near = [v for c in chunks for v in c.columns["near_mm"]]
    assert near == list(whole.columns["near_mm"])
    assert near[3] == 3 * r.plan.step_mm  # frame k's near limit is (k − 1)·step


def test_a_rail_stack_refuses_what_the_lens_cannot_do() -> None:
    mpe = load_db().get("lens", "mp-e-65")
    with pytest.raises(DomainError) as beyond:
        rail_stack(depth_mm=1.0, f_number=2.8, magnification=6.0, coc_mm=0.03, lens_preset=mpe)
    assert beyond.value.param == "magnification" and "0 to 5" in beyond.value.valid
    with pytest.raises(InputError):
        rail_stack(depth_mm=1.0, f_number=8.0, magnification=1.0, coc_mm=0.03, model="raytrace")


@pytest.mark.parametrize("plane", ["lens", "sensor"])
def test_a_bracket_to_infinity_ends_at_the_hyperfocal_setting(plane: str) -> None:
    s = bracket_stack(focal_length_mm=24.0, f_number=11.0, coc_mm=0.03, near_mm=500.0, far_mm=INF, overlap=0.0,
                      distance_from=plane)
    h = hyperfocal_setting(model="thin", focal_length_mm=24.0, f_number=11.0, coc_mm=0.03, distance_from=plane)
    assert s.model == "thin" and s.frames[-1].distance_mm == h.hyperfocal_mm and s.frames[-1].far_mm == INF
    if plane == "lens":  # Wikipedia, "Hyperfocal distance": H = f²/(N·c) + f
        assert h.hyperfocal_mm == pytest.approx(24.0**2 / (11.0 * 0.03) + 24.0, rel=1e-12)
    rows = bracket_rows(s)
    assert rows[0]["step_mm"] == 0.0 and rows[1]["step_mm"] == rows[1]["distance_mm"] - rows[0]["distance_mm"]


def test_an_internally_focusing_lens_ends_at_its_own_hyperfocal_setting() -> None:
    preset = load_db().get("lens", "ef-100-macro-l")
    s = bracket_stack(focal_length_mm=100.0, f_number=8.0, coc_mm=0.03, near_mm=500.0, far_mm=INF, model="thin",
                      lens_preset=preset, distance_from="lens")
    # the thin model's closed form (tests/test_one_answer.py): f = f₀ − κ·N·c at m = N·c/(f₀ − κ·N·c), κ = 1/3
    f_h = 100.0 - 0.24 / 3.0
    assert s.frames[-1].distance_mm == pytest.approx(f_h**2 / 0.24 + f_h, rel=1e-12)
    assert s.focal_range_mm is not None and s.focal_range_mm[1] == pytest.approx(f_h, rel=1e-12)


def test_the_frame_limit_of_a_ray_traced_plan_follows_its_evaluation_cap() -> None:
    assert most_frames("thin") == most_frames("approx") == 10_000
    assert most_frames("thick") == 2_000 and most_frames("raytrace") == 25
    from camtool.plans.equipment import lens_data, load_prescription

    lens = lens_data(prescription=load_prescription("canon-rf50-f1.2"))
    start = time.perf_counter()
    with pytest.raises(DomainError) as error:  # the thin lens's count is far beyond 25: refused before any trace
        bracket_stack(focal_length_mm=51.0998, f_number=1.0, coc_mm=0.03, near_mm=600.0, far_mm=9660.0,
                      overlap=0.684, lens=lens)
    assert time.perf_counter() - start < 5.0
    assert error.value.param == "near_mm" and "at most 25 frames" in error.value.valid
