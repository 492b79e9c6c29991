"""``auto`` over arrays gives every scene exactly what a call for that scene alone gives.

The same rung, the same limits to the last bit and the same error estimate, over a varied grid
(lens data of every kind, both distance planes, diffraction, several tolerances, focus distances
from close up to beyond the hyperfocal distance and infinity, arrays broadcast against numbers and
2-D); and the same again when the scenes run a block at a time (camtool.dof.ladder._BLOCK), errors
included, and with diffraction asked for (a scene at or beyond the hyperfocal distance that does
not add diffraction reports its share as left out, and each sum is added in one order).
"""

from __future__ import annotations

import numpy as np
import pytest

from camtool.core.errors import CamtoolError
from camtool.dof import ladder
from camtool.dof.ladder import LensData, depth_of_field

LENSES = {
    "none": LensData(),
    "P 0.8, hiatus 10": LensData(pupil_magnification=0.8, hiatus_mm=10.0),
    "P 2.5, hiatus -15": LensData(pupil_magnification=2.5, hiatus_mm=-15.0),
    "P 0.6": LensData(pupil_magnification=0.6),
    "hiatus 5": LensData(hiatus_mm=5.0),
    "P 1": LensData(pupil_magnification=1.0),
}


def scenes(count: int, seed: int) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    """f, N, c and focus distances from beyond the closest focus to infinity, with some at or about H."""
    rng = np.random.default_rng(seed)
    f = rng.uniform(14.0, 200.0, count)
    n = rng.choice([1.4, 2.0, 2.8, 5.6, 11.0, 22.0], count)
    c = rng.choice([0.03, 0.02, 0.0048], count)
    s = 4.6 * f + 40.0 + f * np.exp(rng.uniform(0.0, 9.0, count))
    h = f * f / (n * c) + f
    s[5::11] = h[5::11] * rng.uniform(0.97, 1.03, s[5::11].size)  # about the hyperfocal distance
    s[7::13] = (h + f + n * c)[7::13]  # at the thin lens's H from the sensor
    s[9::13] = h[9::13]  # at its H from the lens
    s[::17] = np.inf
    return f, n, c, s


def bits(value: object) -> bytes:
    return np.float64(value).tobytes()


def same_answers(many: ladder.ModelResult, one: ladder.ModelResult, i: tuple[int, ...] | int,
                 estimates: bool = True) -> None:
    assert many.model[i] == one.model
    assert [bits(field[i]) for field in many.limits] == [bits(field) for field in one.limits]
    if estimates:
        assert bits(many.error_estimate[i]) == bits(one.error_estimate)


def compare(name: str, plane: str, diffraction: bool, estimates: bool) -> None:
    lens = LENSES[name]
    f, n, c, s = scenes(90, seed=len(name))
    if diffraction:  # apertures where the Airy disc stays below the CoC (the wave rung is tested elsewhere)
        n, c = np.minimum(n, 5.6), np.maximum(c, 0.02)
    for tolerance in (0.001, 0.01, 0.05):
        many = depth_of_field("auto", f, n, c, s, plane, lens=lens, diffraction=diffraction, tolerance=tolerance)
        for i in range(s.size):
            one = depth_of_field("auto", float(f[i]), float(n[i]), float(c[i]), float(s[i]), plane, lens=lens,
                                 diffraction=diffraction, tolerance=tolerance)
            same_answers(many, one, i, estimates)


@pytest.mark.parametrize("plane", ["sensor", "lens"])
@pytest.mark.parametrize("name", list(LENSES))
def test_each_scene_of_an_array_gets_its_single_answer(name: str, plane: str) -> None:
    compare(name, plane, False, True)


@pytest.mark.parametrize("plane", ["sensor", "lens"])
@pytest.mark.parametrize("name", list(LENSES))
def test_with_diffraction_each_scene_gets_its_single_answer(name: str, plane: str) -> None:
    compare(name, plane, True, True)


@pytest.mark.parametrize("plane", ["sensor", "lens"])
def test_broadcast_and_two_dimensional_arrays_give_the_single_answers(plane: str) -> None:
    lens = LENSES["P 0.8, hiatus 10"]
    s = np.geomspace(400.0, 2e6, 24).reshape(4, 6)
    s[0, 0] = np.inf
    many = depth_of_field("auto", 50.0, 4.0, 0.03, s, plane, lens=lens)
    assert many.model.shape == s.shape and many.limits.near_mm.shape == s.shape
    for i, d in np.ndenumerate(s):
        same_answers(many, depth_of_field("auto", 50.0, 4.0, 0.03, float(d), plane, lens=lens), i)


@pytest.mark.parametrize("plane", ["sensor", "lens"])
@pytest.mark.parametrize("name", ["none", "P 0.8, hiatus 10", "P 2.5, hiatus -15"])
def test_blocks_give_the_whole_arrays_answers(name: str, plane: str, monkeypatch: pytest.MonkeyPatch) -> None:
    lens = LENSES[name]
    f, n, c, s = scenes(1000, seed=7)
    whole = depth_of_field("auto", f, n, c, s, plane, lens=lens)
    for block in (1, 7, 64, 999):
        monkeypatch.setattr(ladder, "_BLOCK", block)
        blocks = depth_of_field("auto", f, n, c, s, plane, lens=lens)
        assert blocks.model.dtype == whole.model.dtype == object
        assert list(blocks.model) == list(whole.model)
        for mine, theirs in zip(blocks.limits, whole.limits, strict=True):
            assert mine.tobytes() == theirs.tobytes()
        assert blocks.error_estimate.tobytes() == whole.error_estimate.tobytes()
    for i in range(0, s.size, 37):
        same_answers(blocks, depth_of_field("auto", float(f[i]), float(n[i]), float(c[i]), float(s[i]), plane,
                                            lens=lens), i)


def _error(*args: object, **kwargs: object) -> str:
    with pytest.raises(CamtoolError) as caught:
        depth_of_field(*args, **kwargs)  # type: ignore[arg-type]
    return f"{type(caught.value).__name__}: {caught.value}"


@pytest.mark.parametrize("plane", ["sensor", "lens"])
def test_blocks_raise_the_error_of_the_whole_arrays(plane: str, monkeypatch: pytest.MonkeyPatch) -> None:
    f, n, c, s = scenes(300, seed=3)
    s[250] = 0.5 * f[250]  # closer than the closest focus (and than f from the lens)
    s[40] = -1.0  # not a distance
    f[120] = 0.0  # not a focal length
    lens = LensData(pupil_magnification=0.5, hiatus_mm=10.0)
    cases = [(f, n, c, s), (np.where(np.arange(300) == 120, 50.0, f), n, c, s),
             (np.where(np.arange(300) == 120, 50.0, f), n, c, np.where(np.arange(300) == 40, 900.0, s))]
    for inputs, names in zip(cases, ("focal_length_mm", "distance_mm", "distance_mm=" + f"{s[250]:g}"), strict=True):
        monkeypatch.setattr(ladder, "_BLOCK", 1 << 30)
        whole = _error("auto", *inputs, plane, lens=lens)
        assert names in whole
        monkeypatch.setattr(ladder, "_BLOCK", 16)
        assert _error("auto", *inputs, plane, lens=lens) == whole
