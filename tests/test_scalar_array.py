"""One implementation for scalars and arrays: the same numbers either way, plain floats for scalars,
numpy only when arrays come in, and domain errors for bad input on both paths."""

from __future__ import annotations

import math
import subprocess
import sys
from collections.abc import Callable
from typing import Any

import numpy as np
import pytest

from camtool.core.errors import DomainError
from camtool.dof.closed import approx_dof, hyperfocal_mm, thin_dof
from camtool.dof.inverse import focus_for_limits
from camtool.geometry.fov import (
    angle_of_view_deg,
    field_of_view,
    field_size_mm,
    focal_length_for_angle_mm,
)
from camtool.geometry.thinlens import (
    blur_diameter_mm,
    closest_focus_mm,
    extension_mm,
    focus_for_magnification,
    focus_geometry,
    image_distance_mm,
    lens_distances,
    magnification,
    sensor_distance_mm,
)

INF = math.inf

# six rows per argument, with infinities where a function accepts them
F = [24.0, 50.0, 85.0, 1.0, 5000.0, 200.0]
N = [1.4, 8.0, 16.0, 0.7, 1024.0, 2.8]
C = [0.03, 0.02, 0.0005, 1.0, 0.03, 0.015]
FOCUS = [3000.0, 1e6, INF, 10.0, 1e15, 2000.0]  # from the sensor: all ≥ 4f
FOCUS_LENS = [3000.0, 1e6, INF, 2.0, 1e15, 400.0]  # from the lens: all ≥ 2f
OBJECT = [3000.0, 1e6, 500.0, 10.0, 1e15, INF]
NEAR = [2000.0, 1e4, 1000.0, 250.0, 4e4, 1500.0]
FAR = [4000.0, INF, 3000.0, 300.0, 1e7, 2000.0]
M = [0.01, 0.5, 1.0, 2.0, 0.001, 0.1]
ANGLE = [39.6, 90.0, 1.0, 120.0, 0.5, 27.0]

CASES: list[tuple[str, Callable[..., Any], list[list[float]], dict[str, Any]]] = [
    ("image_distance", image_distance_mm, [F, OBJECT], {}),
    ("magnification", magnification, [F, OBJECT], {}),
    ("extension", extension_mm, [F, OBJECT], {}),
    ("closest_focus", closest_focus_mm, [F], {}),
    ("lens_distances", lens_distances, [F, FOCUS], {}),
    ("sensor_distance", sensor_distance_mm, [F, OBJECT], {}),
    ("blur_diameter", blur_diameter_mm, [F, N, FOCUS_LENS, OBJECT], {}),
    ("focus_geometry_sensor", focus_geometry, [F, FOCUS], {}),
    ("focus_geometry_lens", focus_geometry, [F, FOCUS_LENS], {"distance_from": "lens"}),
    ("focus_for_magnification", focus_for_magnification, [F, M], {}),
    ("angle_of_view", angle_of_view_deg, [C, F, M], {}),
    ("field_of_view", field_of_view, [F, C, N], {}),
    ("field_size", field_size_mm, [F, M], {}),
    ("focal_length_for_angle", focal_length_for_angle_mm, [F, ANGLE], {}),
    ("hyperfocal", hyperfocal_mm, [F, N, C], {}),
    ("hyperfocal_no_f", hyperfocal_mm, [F, N, C], {"plus_f": False}),
    ("approx_dof", approx_dof, [F, N, C, FOCUS], {}),
    ("thin_dof_sensor", thin_dof, [F, N, C, FOCUS], {}),
    ("thin_dof_lens", thin_dof, [F, N, C, FOCUS_LENS], {"distance_from": "lens"}),
    ("focus_for_limits_lens", focus_for_limits, [[50.0] * 6, C[:3] + [0.03] * 3, NEAR, FAR], {"distance_from": "lens"}),
    ("focus_for_limits_sensor", focus_for_limits, [[50.0] * 6, C[:3] + [0.03] * 3, NEAR, FAR], {}),
]


def _fields(result: Any) -> tuple[Any, ...]:
    return tuple(result) if isinstance(result, tuple) else (result,)


@pytest.mark.parametrize(("function", "columns", "kwargs"), [c[1:] for c in CASES], ids=[c[0] for c in CASES])
@pytest.mark.parametrize("shape", [(6,), (2, 3)], ids=["6", "2x3"])
def test_scalar_and_array_calls_agree(
    function: Callable[..., Any], columns: list[list[float]], kwargs: dict[str, Any], shape: tuple[int, ...]
) -> None:
    scalars = [_fields(function(*row, **kwargs)) for row in zip(*columns)]
    for fields in scalars:
        for value in fields:
            assert type(value) is float  # a plain float, not numpy.float64
    arrays = _fields(function(*(np.array(col).reshape(shape) for col in columns), **kwargs))
    assert len(arrays) == len(scalars[0])
    for k, array in enumerate(arrays):
        assert isinstance(array, np.ndarray) and array.shape == shape
        expected = np.array([fields[k] for fields in scalars]).reshape(shape)
        np.testing.assert_allclose(array, expected, rtol=1e-14, atol=0)


def test_arrays_broadcast_against_scalars() -> None:
    r = thin_dof(50.0, np.array([2.8, 8.0, 16.0]), 0.03, np.array([[1000.0], [5000.0]]))
    assert r.near_mm.shape == r.hyperfocal_mm.shape == (2, 3)
    assert r.near_mm[1, 2] == pytest.approx(thin_dof(50.0, 16.0, 0.03, 5000.0).near_mm, rel=1e-15)


def test_integer_scalars_give_floats() -> None:
    for value in thin_dof(50, 8, 1, 3000) + approx_dof(50, 8, 1, 3000):
        assert type(value) is float
    assert type(hyperfocal_mm(50, 8, 1)) is float
    assert type(closest_focus_mm(50)) is float


@pytest.mark.parametrize(
    "call",
    [
        "camtool.dof.closed.thin_dof(50., 8., .03, 3000.)",
        "camtool.dof.closed.thin_dof(50., 8., .03, float('inf'), distance_from='lens')",
        "camtool.dof.closed.approx_dof(50., 8., .03, 3000.)",
        "camtool.dof.closed.hyperfocal_mm(50., 8., .03)",
        "camtool.geometry.fov.field_of_view(36., 24., 50.)",
        "camtool.dof.inverse.focus_for_limits(50., .03, 2000., 4000.)",
        "camtool.geometry.thinlens.lens_distances(50., 3000.)",
    ],
)
def test_scalar_calls_do_not_import_numpy(call: str) -> None:
    module = call.split("(")[0].rsplit(".", 1)[0]
    code = f"import {module}, sys; {call}; print('numpy' in sys.modules)"
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True)
    assert out.stdout.strip() == "False"


# -- domain errors name the parameter ----------------------------------------------------------------

BAD = [0.0, -1.0, math.nan, INF]


@pytest.mark.parametrize("bad", BAD, ids=["zero", "negative", "nan", "inf"])
@pytest.mark.parametrize(
    ("name", "call", "param"),
    [
        ("thin-f", lambda x: thin_dof(x, 8.0, 0.03, 3000.0), "focal_length_mm"),
        ("thin-N", lambda x: thin_dof(50.0, x, 0.03, 3000.0), "f_number"),
        ("thin-c", lambda x: thin_dof(50.0, 8.0, x, 3000.0), "coc_mm"),
        ("thin-lens-f", lambda x: thin_dof(x, 8.0, 0.03, 3000.0, distance_from="lens"), "focal_length_mm"),
        ("approx-f", lambda x: approx_dof(x, 8.0, 0.03, 3000.0), "focal_length_mm"),
        ("approx-N", lambda x: approx_dof(50.0, x, 0.03, 3000.0), "f_number"),
        ("approx-c", lambda x: approx_dof(50.0, 8.0, x, 3000.0), "coc_mm"),
        ("hyperfocal-f", lambda x: hyperfocal_mm(x, 8.0, 0.03), "focal_length_mm"),
        ("hyperfocal-N", lambda x: hyperfocal_mm(50.0, x, 0.03), "f_number"),
        ("hyperfocal-c", lambda x: hyperfocal_mm(50.0, 8.0, x), "coc_mm"),
        ("lens_distances-f", lambda x: lens_distances(x, 3000.0), "focal_length_mm"),
        ("image_distance-f", lambda x: image_distance_mm(x, 3000.0), "focal_length_mm"),
        ("inverse-f", lambda x: focus_for_limits(x, 0.03, 2000.0, 4000.0), "focal_length_mm"),
        ("inverse-c", lambda x: focus_for_limits(50.0, x, 2000.0, 4000.0), "coc_mm"),
    ],
)
def test_domain_errors_name_the_parameter(name: str, call: Callable[[float], Any], param: str, bad: float) -> None:
    with pytest.raises(DomainError) as raised:
        call(bad)
    assert raised.value.param == param
    assert param in str(raised.value) and "valid range" in str(raised.value)


@pytest.mark.parametrize(
    ("call", "param", "limit"),
    [
        (lambda: thin_dof(50.0, 8.0, 0.03, 199.9), "distance_mm", 200.0),  # closer than 4f from the sensor
        (lambda: thin_dof(50.0, 8.0, 0.03, 49.9, distance_from="lens"), "distance_mm", 50.0),  # f from the lens
        (lambda: thin_dof(50.0, 8.0, 0.03, math.nan), "distance_mm", 200.0),
        (lambda: thin_dof(50.0, 8.0, 0.03, math.nan, distance_from="lens"), "distance_mm", None),
        (lambda: thin_dof(50.0, 8.0, 0.03, -3000.0, distance_from="lens"), "distance_mm", None),
        (lambda: approx_dof(50.0, 8.0, 0.03, 0.0), "distance_mm", None),
        (lambda: approx_dof(50.0, 8.0, 0.03, math.nan), "distance_mm", None),
        (lambda: lens_distances(50.0, 150.0), "distance_mm", 200.0),
        (lambda: image_distance_mm(50.0, 50.0), "object_distance_mm", None),
        (lambda: focus_geometry(50.0, 49.0, distance_from="lens"), "distance_mm", 50.0),
        (lambda: focus_for_limits(50.0, 0.03, 150.0, 4000.0), "near_mm", 200.0),
        (lambda: focus_for_limits(50.0, 0.03, 90.0, 4000.0, distance_from="lens"), "near_mm", 100.0),
        (lambda: focus_for_limits(50.0, 0.03, 4000.0, 2000.0), "far_mm", 4000.0),
        (lambda: focus_for_limits(50.0, 0.03, 2000.0, math.nan), "far_mm", None),
    ],
)
def test_focus_closer_than_possible(call: Callable[[], Any], param: str, limit: float | None) -> None:
    with pytest.raises(DomainError) as raised:
        call()
    assert raised.value.param == param
    if limit is not None:
        assert raised.value.limit == pytest.approx(limit)


def test_array_domain_error_names_the_first_bad_value() -> None:
    with pytest.raises(DomainError) as raised:
        thin_dof(np.array([50.0, -5.0, 0.0]), 8.0, 0.03, 3000.0)
    assert raised.value.param == "focal_length_mm" and raised.value.value == -5.0
    with pytest.raises(DomainError) as raised:
        thin_dof(50.0, 8.0, 0.03, np.array([3000.0, 150.0]))
    assert raised.value.param == "distance_mm" and raised.value.value == 150.0 and raised.value.limit == 200.0
    with pytest.raises(DomainError) as raised:
        approx_dof(50.0, np.array([8.0, math.nan]), 0.03, 3000.0)
    assert raised.value.param == "f_number"


def test_unknown_distance_plane() -> None:
    with pytest.raises(ValueError, match="distance_from"):
        thin_dof(50.0, 8.0, 0.03, 3000.0, distance_from="film")
    with pytest.raises(ValueError, match="distance_from"):
        focus_for_limits(50.0, 0.03, 2000.0, 4000.0, distance_from="film")
