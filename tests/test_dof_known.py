"""Depth of field and hyperfocal distance: worked examples and the peer vectors of tests/data."""

from __future__ import annotations

import math
from pathlib import Path
from typing import Any

import pytest
import yaml

from camtool.dof.closed import approx_dof, hyperfocal_mm, thin_dof
from camtool.dof.inverse import focus_for_limits
from camtool.geometry.fov import (
    angle_of_view_deg,
    field_size_mm,
    focal_length_for_angle_mm,
)
from camtool.geometry.thinlens import magnification

VECTORS = yaml.safe_load((Path(__file__).parent / "data" / "peer-vectors-dof.yaml").read_text(encoding="utf-8"))
TESTED = [v for v in VECTORS if "untested" not in v]

MM_PER = {"mm": 1.0, "m": 1000.0, "ft": 304.8}  # 1 ft = 0.3048 m exactly (the vectors' convention)


# -- worked examples ---------------------------------------------------------------------------


@pytest.mark.parametrize(
    ("f", "n", "c", "plus_f", "expected"),
    [
        (50.0, 8.0, 0.03, True, 10_467),  # H = f²/(Nc) + f = 2500/0.24 + 50 (Wikipedia, "Hyperfocal distance")
        (50.0, 8.0, 0.03, False, 10_417),  # H = f²/(Nc) = 2500/0.24
        (24.0, 16.0, 0.03, True, 1224),  # 576/0.48 + 24
        (35.0, 2.0, 0.03, True, 20_452),  # 1225/0.06 + 35
    ],
)
def test_hyperfocal_worked_examples(f: float, n: float, c: float, plus_f: bool, expected: int) -> None:
    assert round(hyperfocal_mm(f, n, c, plus_f=plus_f)) == expected


@pytest.mark.parametrize(
    ("f", "n", "c", "u", "near", "far"),
    [
        # D_N = u f²/(f² + Nc(u − f)), D_F = u f²/(f² − Nc(u − f)) (thin-lens lecture), by hand:
        (50.0, 8.0, 0.03, 3000.0, 7.5e6 / 3208, 7.5e6 / 1792),  # f² = 2500, Nc(u − f) = 0.24·2950 = 708
        (50.0, 2.0, 0.03, 1050.0, 2.625e6 / 2560, 2.625e6 / 2440),  # Nc(u − f) = 0.06·1000 = 60
        (100.0, 4.0, 0.025, 2100.0, 2.1e7 / 10200, 2.1e7 / 9800),  # f² = 1e4, 0.1·2000 = 200
        (24.0, 16.0, 0.03, 1224.0, 612.0, math.inf),  # focused at H = 1224: near = H/2, far = ∞
        (50.0, 8.0, 0.03, math.inf, 2500 / 0.24, math.inf),  # at infinity: near = H − f
    ],
)
def test_thin_limits_lecture_equations(f: float, n: float, c: float, u: float, near: float, far: float) -> None:
    r = thin_dof(f, n, c, u, distance_from="lens")
    assert r.near_mm == pytest.approx(near, rel=1e-14)
    assert r.far_mm == pytest.approx(far, rel=1e-14)
    if math.isfinite(u):
        assert r.front_mm == pytest.approx(u - near, rel=1e-13)
        assert r.total_mm == pytest.approx(far - near, rel=1e-13)


@pytest.mark.parametrize(
    ("f", "n", "c", "s", "near", "far"),
    [
        # near = H₀s/(H₀ + s), far = H₀s/(H₀ − s) with H₀ = f²/(Nc) (Wikipedia, "Depth of field")
        (50.0, 8.0, 0.03, 3000.0, 2500 / 0.24 * 3000 / (2500 / 0.24 + 3000), 2500 / 0.24 * 3000 / (2500 / 0.24 - 3000)),
        (24.0, 16.0, 0.03, 600.0, 1200 * 600 / 1800, 1200 * 600 / 600),  # H₀ = 1200, s = H₀/2: far = H₀
        (24.0, 16.0, 0.03, 1200.0, 600.0, math.inf),  # s = H₀: near = H₀/2, far = ∞
    ],
)
def test_approx_limits(f: float, n: float, c: float, s: float, near: float, far: float) -> None:
    r = approx_dof(f, n, c, s)
    assert r.near_mm == pytest.approx(near, rel=1e-14)
    assert r.far_mm == pytest.approx(far, rel=1e-14)


# -- peer vectors --------------------------------------------------------------------------------


def _length_mm(values: dict[str, Any], name: str) -> float:
    """The value of ``name_mm``, ``name_m`` or ``name_ft`` in mm."""
    for unit, scale in MM_PER.items():
        if f"{name}_{unit}" in values:
            return float(values[f"{name}_{unit}"]) * scale
    raise KeyError(name)


def _expected(vector: dict[str, Any]) -> dict[str, tuple[float, float]]:
    """Expected lengths in mm with their tolerance in mm, keyed by quantity (near, far, ...)."""
    out = {}
    tolerance = vector["tolerance"]
    for key, value in vector["expected"].items():
        name, _, unit = key.rpartition("_")
        if unit in MM_PER:
            out[name] = (float(value) * MM_PER[unit], float(tolerance["abs"]) * MM_PER[unit])
    return out


def _coc_mm(vector: dict[str, Any]) -> float:
    inputs = vector["inputs"]
    if "coc_mm" in inputs:
        return float(inputs["coc_mm"])
    # patik/dof: c = round(0.03/crop_factor, 3 decimals)
    return round(0.03 / float(inputs["crop_factor"]), 3)


def _plus_f(vector: dict[str, Any]) -> bool:
    # tooo-dof-* report H without +f; sympy's hyperfocal_distance is f²/(Nc); the others add f
    return not (vector["id"].startswith("tooo-") or vector["id"].startswith("sympy-"))


def _check_dof(vector: dict[str, Any]) -> None:
    inputs = vector["inputs"]
    f, n, c = float(inputs["focal_length_mm"]), float(inputs["f_number"]), _coc_mm(vector)
    if "coc_mm" in vector["expected"]:
        assert c == vector["expected"]["coc_mm"]
    # every DOF vector measures the focus distance from the lens (its convention says so)
    r = thin_dof(f, n, c, _length_mm(inputs, "distance"), distance_from="lens")
    got = {
        "near": r.near_mm,
        "far": r.far_mm,
        "dof": r.total_mm,
        "hyperfocal": hyperfocal_mm(f, n, c, plus_f=_plus_f(vector)),
    }
    if _plus_f(vector):
        assert r.hyperfocal_mm == got["hyperfocal"]  # the lens-plane H of thin_dof is f²/(Nc) + f
    if vector["id"].startswith("dofbot-") and math.isfinite(r.far_mm):
        # dofbot's dof is round(far − near, 2) of the near and far it already rounded to 2 dp (metres)
        got["dof"] = (round(r.far_mm / 1000, 2) - round(r.near_mm / 1000, 2)) * 1000
    for name, (value, tolerance) in _expected(vector).items():
        if name == "coc":
            continue  # checked above
        if math.isinf(value):
            assert got[name] == math.inf, name
        else:
            assert got[name] == pytest.approx(value, abs=tolerance, rel=0), name


def _check_hyperfocal(vector: dict[str, Any]) -> None:
    inputs = vector["inputs"]
    if vector["id"].startswith("sympy-"):  # unit-free inputs: any consistent length unit
        got = hyperfocal_mm(inputs["focal_length"], inputs["f_number"], inputs["coc"], plus_f=False)
        assert got == pytest.approx(vector["expected"]["hyperfocal"], abs=vector["tolerance"]["abs"], rel=0)
        return
    got = hyperfocal_mm(float(inputs["focal_length_mm"]), float(inputs["f_number"]), _coc_mm(vector))
    for name, (value, tolerance) in _expected(vector).items():
        assert name == "hyperfocal"
        assert got == pytest.approx(value, abs=tolerance, rel=0)


def _check_fov(vector: dict[str, Any]) -> None:
    inputs, expected, tolerance = vector["inputs"], vector["expected"], vector["tolerance"]
    width, f = float(inputs["sensor_width_mm"]), float(inputs["focal_length_mm"])
    assert angle_of_view_deg(width, f) == pytest.approx(expected["hfov_deg"], abs=tolerance["abs_deg"], rel=0)
    # the vector's w·d/f neglects f against d; camtool's field is w/m = w·(d − f)/f, inside the tolerance
    field_m = field_size_mm(width, magnification(f, float(inputs["distance_mm"]))) / 1000.0
    assert field_m == pytest.approx(expected["hfov_width_m"], abs=tolerance["abs_m"], rel=0)


def _check_focal_length_from_fov(vector: dict[str, Any]) -> None:
    inputs = vector["inputs"]
    got = focal_length_for_angle_mm(float(inputs["sensor_mm"]), float(inputs["fov_deg"]))
    assert got == pytest.approx(vector["expected"]["focal_length_mm"], abs=vector["tolerance"]["abs"], rel=0)


def _check_aperture_from_dof(vector: dict[str, Any]) -> None:
    inputs = vector["inputs"]
    f, c = float(inputs["focal_length_mm"]), _coc_mm(vector)
    near = _length_mm(inputs, "near")
    far = near + _length_mm(inputs, "dof")
    solution = focus_for_limits(f, c, near, far, distance_from="lens")
    # the exact limits put the focus at their harmonic mean: the vector's own focus distance
    assert solution.distance_mm == pytest.approx(_length_mm(inputs, "distance"), rel=1e-12)
    assert solution.f_number == pytest.approx(vector["expected"]["f_number"], abs=vector["tolerance"]["abs"], rel=0)


CHECKS = {
    "dof": _check_dof,
    "hyperfocal": _check_hyperfocal,
    "fov": _check_fov,
    "focal_length_from_fov": _check_focal_length_from_fov,
    "aperture_from_dof": _check_aperture_from_dof,
}


@pytest.mark.parametrize("vector", TESTED, ids=[v["id"] for v in TESTED])
def test_peer_vector(vector: dict[str, Any]) -> None:
    CHECKS[vector["quantity"]](vector)


def test_untested_peer_vectors_are_only_those_camtool_has_no_function_for() -> None:
    untested = {v["id"] for v in VECTORS if "untested" in v}
    assert untested == {"patik-inverse-02", "patik-inverse-03", "patik-inverse-04"}
    assert len({v["id"] for v in VECTORS}) == len(VECTORS)
    assert {v["quantity"] for v in TESTED} == set(CHECKS)


def test_every_dof_hyperfocal_and_fov_vector_of_the_shared_file_is_here() -> None:
    shared = Path(__file__).resolve().parents[2] / "shared" / "reference" / "peer-vectors.yaml"
    if not shared.exists():
        pytest.skip("the shared reference data is not next to this checkout")
    wanted = {
        v["id"]
        for v in yaml.safe_load(shared.read_text(encoding="utf-8"))
        if v["quantity"] in {"dof", "hyperfocal", "fov", "focal_length_from_fov"} or v["id"].startswith("patik-inverse")
    }
    assert wanted == {v["id"] for v in VECTORS}
