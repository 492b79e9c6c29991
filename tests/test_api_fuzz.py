"""The public Python API under hostile arguments: a right answer or the one library error, naming the argument.

Every public function in ``camtool.__all__`` is called with arguments drawn
per parameter: mostly values a photographer would pass, and for some of the
parameters a value of the wrong type (a string, None, a bool, a list of
strings, a dict, a complex number), a non-finite or extreme number (NaN,
±inf, 0, subnormals, ±1e308, integers too large for a float) or an array
holding such values. Each call must either return a result with no NaN (and
no infinity outside the fields where infinity means "everything beyond is
sharp") or raise :class:`camtool.core.errors.CamtoolError` naming one of the
function's own parameters; any other exception is a defect.

The default run is short (``CAMTOOL_API_FUZZ_EXAMPLES``, 150 calls a
function); a deep run sets it higher, e.g. ``CAMTOOL_API_FUZZ_EXAMPLES=20000``,
and ``CAMTOOL_API_FUZZ_SEED`` picks another seed.
"""

from __future__ import annotations

import dataclasses
import inspect
import math
import os
import re
import tempfile
from decimal import Decimal
from fractions import Fraction
from pathlib import Path
from typing import Any

import numpy as np
import pytest
from hypothesis import HealthCheck, Phase, given, seed, settings
from hypothesis import strategies as st
from hypothesis.extra import numpy as hnp

import camtool
from camtool.core.errors import CamtoolError, DomainError
from camtool.core.record import Record
from camtool.core.record import fields as record_fields

EXAMPLES = int(os.environ.get("CAMTOOL_API_FUZZ_EXAMPLES", "150"))
_OUT = tempfile.mkdtemp(prefix="camtool-api-fuzz-")
SEED = int(os.environ.get("CAMTOOL_API_FUZZ_SEED", "20261127"))

FUNCTIONS = {name: getattr(camtool, name) for name in camtool.__all__ if inspect.isfunction(getattr(camtool, name))}

# Values in each parameter's physical domain, from the documented ranges (docs/design.md §6.1), not from the code.
VALID: dict[str, st.SearchStrategy[Any]] = {
    "focal_length_mm": st.floats(1.0, 5000.0),
    "f_number": st.floats(0.7, 1024.0),
    "coc_mm": st.floats(0.0005, 1.0),
    "distance_mm": st.one_of(st.floats(10.0, 1e9), st.just(math.inf)),
    "near_mm": st.floats(50.0, 1e6),
    "far_mm": st.one_of(st.floats(1e3, 1e9), st.just(math.inf)),
    "sensor_width_mm": st.floats(0.5, 2000.0),
    "sensor_height_mm": st.floats(0.5, 2000.0),
    "magnification": st.floats(1e-6, 10.0),
    "pupil_magnification": st.floats(0.2, 5.0),
    "hiatus_mm": st.floats(-50.0, 50.0),
    "wavelength_nm": st.floats(380.0, 780.0),
    "tolerance": st.floats(1e-4, 0.5),
    "ev100": st.floats(-10.0, 25.0),
    "shutter_s": st.floats(1e-5, 3600.0),
    "iso": st.floats(1.0, 1e6),
    "nd_stops": st.floats(0.0, 20.0),
    "pixel_pitch_mm": st.floats(0.0002, 0.1),
    "model": st.sampled_from(["auto", "approx", "thin", "thick", "paraxial", "raytrace", "wave"]),
    "contrast_criterion": st.sampled_from([None, "mtf:0.3@40", "mtf:0.181@coc", "mtf:2@40", "mtf:0.3@"]),
    "contrast_level": st.floats(0.05, 0.95),
    "film_distance_mm": st.floats(1.0, 5000.0),
    "subject_distance_mm": st.one_of(st.floats(10.0, 1e9), st.just(math.inf)),
    "distance_from": st.sampled_from(["sensor", "lens"]),
    "projection": st.sampled_from(["rectilinear", "equidistant", "equisolid", "orthographic", "stereographic"]),
    "field_max_deg": st.one_of(st.none(), st.floats(1.0, 360.0)),
    "rule": st.sampled_from(["d/1500", "d/1730", "px:2", "print:8x10in@25cm", "d/1000"]),
    "diffraction": st.booleans(),
    "prescription": st.sampled_from([None, "dgauss100"]).map(lambda name: name and _prescription(name)),
    "crop_factor": st.floats(0.1, 100.0),
    "pixel_pitch_um": st.one_of(st.none(), st.floats(0.2, 100.0)),
    "declination_deg": st.floats(-89.0, 89.0),
    "rule_constant": st.floats(100.0, 1000.0),
    "npf_k": st.floats(0.1, 10.0),
    "guide_number_m": st.one_of(st.none(), st.floats(1.0, 100.0)),
    "guide_number_iso": st.floats(25.0, 400.0),
    "sensor_diagonal_mm": st.floats(1.0, 100.0),
    "target_diagonal_mm": st.floats(1.0, 100.0),
    "converter": st.floats(0.5, 2.0),
    "film": st.sampled_from(["hp5", "tri-x", "portra-400", "velvia-50", "no-such-film"]),
    "metered_s": st.floats(1e-4, 1e4),
    "kind": st.sampled_from(["sensor", "camera", "lens", "prescription", "scene", "film"]),
    "depth_mm": st.floats(0.1, 100.0),
    "criterion": st.sampled_from([None, "classic", "defocus", "wave"]),
    "overlap": st.floats(0.0, 0.9),
    "tilt_deg": st.one_of(st.none(), st.floats(-30.0, 30.0)),
    "swing_deg": st.one_of(st.none(), st.floats(-30.0, 30.0)),
    "hinge_mm": st.one_of(st.none(), st.floats(100.0, 1e5)),
    "points": st.one_of(st.none(), st.tuples(st.tuples(st.floats(500.0, 5e3), st.floats(-2e3, -100.0)),
                                             st.tuples(st.floats(1e4, 5e4), st.floats(-2e3, -100.0)))),
    "focus_mm": st.one_of(st.none(), st.floats(500.0, 1e5)),
    "image_distance_mm": st.one_of(st.none(), st.floats(20.0, 500.0)),
    "hyperfocal": st.booleans(),
    "at_mm": st.one_of(st.none(), st.floats(500.0, 1e5)),
    "half_depth_mm": st.one_of(st.none(), st.floats(10.0, 5e3)),
    "optimum": st.booleans(),
    "along": st.sampled_from(["sight", "axis"]),
    "angles_from": st.sampled_from(["film", "lens", "horizon"]),
    "hinge_from": st.sampled_from(["lens", "pupil"]),
    "path": st.sampled_from([str(p) for p in sorted((Path(__file__).parent / "data" / "exif").iterdir())[:4]]
                            + ["/nonexistent.jpg", "/dev/null", str(Path(__file__))]),
    "coc_rule": st.sampled_from([None, "d/1500", "d/1440", "px:2", "nonsense"]),
    "lens": st.sampled_from([None, "nikon-z-24mm-f1.8-s", "sony-fe-85mm-f1.8", "nikon-z-24-70mm-f4-s", "no-such-lens"]),
    "fps": st.floats(1.0, 1000.0),
    "shutter_angle_deg": st.one_of(st.none(), st.floats(1.0, 360.0)),
    "name": st.sampled_from(["full-frame", "nikon-z-8", "nikon-z-24mm-f1.8-s", "dgauss100", "hp5", "Full Frame",
                             "no-such-preset"]),
    "sensor_label": st.sampled_from(["36 × 24 mm", "APS-C", ""]),
    "subject_size_mm": st.one_of(st.none(), st.floats(10.0, 1e4)),
    "fill": st.one_of(st.none(), st.floats(0.05, 1.0)),
    "fill_axis": st.sampled_from(["height", "width"]),
    "units": st.sampled_from(["metric", "imperial"]),
    "data": st.just(None).map(lambda _: _chart()),
    "output": st.sampled_from([str(Path(_OUT) / name) for name in ("c.svg", "c.png", "c.pdf", "c.txt", "c")]
                              + [_OUT, "/nonexistent/dir/c.svg"]),
    "width_in": st.floats(1.0, 12.0),
    "height_in": st.floats(1.0, 12.0),
    "dpi": st.floats(20.0, 200.0),
}
# per function, where a parameter's name means something else there
VALID_IN = {"chart": {"kind": st.sampled_from(["dof", "blur", "aperture", "trade", "card"])}}

def _chart() -> Any:
    """One chart's data, made once (for save_chart)."""
    if not _CHARTS:
        _CHARTS.append(camtool.chart("dof", coc_mm=0.03, focal_length_mm=50, f_number=[4, 8], model="thin"))
    return _CHARTS[0]


_CHARTS: list[Any] = []


def _prescription(name: str) -> Any:
    """A shipped lens prescription (the double Gauss 100 mm), loaded once."""
    if name not in _PRESCRIPTIONS:
        from camtool.presets.database import load_db

        _PRESCRIPTIONS[name] = load_db(use_cache=False).prescription(name).optics
    return _PRESCRIPTIONS[name]


_PRESCRIPTIONS: dict[str, Any] = {}

HOSTILE = [
    None, True, False, "50", "", "nan", "inf", b"8", [], ["a"], [1.0, "a"], [[1.0, 2.0], [3.0]], [None],
    [True, 2.0], {"a": 1}, {1.0}, object(), 1j, Fraction(1, 3), Decimal("1.5"), Decimal("nan"),
    math.nan, math.inf, -math.inf, 0, 0.0, -0.0, -1, -1e-300, 5e-324, 1e-308, 1e-30, 1e30, 1e308, -1e308,
    10**400, -(10**400), 2**63, 2**1023 * 2 - 1, np.nan, np.float32("nan"), np.float64("inf"), np.int64(5),
    np.bool_(True), np.array([]), np.array([np.nan]), np.array([1.0, np.inf]), np.array([-np.inf, 2.0]),
    np.array(["a", "b"]), np.array([True, False]), np.array([1 + 2j]), np.array([None, 1.0], dtype=object),
    np.array(1e308), np.array([[1e-300, 1e300]]), np.zeros((2, 3)), np.full(3, 1e308), np.arange(4, dtype=np.uint8),
]

WRONG_TEXT = [None, 1, 1.5, True, b"thin", ["thin"], "", "THIN", "d/0", "d/-5", "d/nan", "d/inf", "px:0", "px:nan",
              "print:0x0in@0cm", "print:8x10in@-1cm", "nonsense", "d/1e400", "px:1e400", "\x00", "é" * 100]

# Where an infinite result is a right answer: the far limit and what follows from it when the far limit is
# at infinity, the front depth when the focus is at infinity; a distance at infinity for a subject there.
INFINITE_OK = {"subject_distance_mm", "front_mm", "far_mm", "rear_mm", "total_mm", "distance_mm", "hyperfocal_mm", "lens_distance_mm",
               "sensor_distance_mm", "object_distance_mm", "image_distance_mm",
               "radius_mm",  # a prescription's flat surface
               "y",  # a chart curve's far limit beyond the hyperfocal distance
               "distances_mm",  # a DOF card's last row, focused at infinity
               "step_mm", "extension_step_mm", "covered_mm",  # a rail frame sharp to infinity: one frame covers all
               "focus_distance_mm", "focus_distance_max_mm", "far_max_mm", "far_min_mm",  # a photo focused at infinity
               "far_limit_mm"}  # a CoC map focused beyond the hyperfocal distance


def hostile_arrays() -> st.SearchStrategy[Any]:
    shapes = hnp.array_shapes(min_dims=0, max_dims=2, max_side=3)
    return (hnp.arrays(np.float64, shapes, elements=st.floats()) | hnp.arrays(np.float32, shapes)
            | hnp.arrays(np.int64, shapes) | hnp.arrays(np.uint8, shapes))


def argument(name: str, function: str = "") -> st.SearchStrategy[Any]:
    valid = VALID_IN.get(function, {}).get(name, VALID[name])
    if name in ("model", "distance_from", "projection", "rule", "diffraction", "prescription", "film", "kind",
                "name", "lens", "along", "angles_from", "hinge_from", "path", "coc_rule", "hyperfocal", "optimum",
                "points", "criterion", "contrast_criterion", "sensor_label", "fill_axis", "units", "data", "output"):
        bad = st.sampled_from(WRONG_TEXT) | st.text(max_size=12) | st.sampled_from(HOSTILE)
    else:
        bad = (st.sampled_from(HOSTILE) | st.floats() | st.integers(-(10**400), 10**400) | hostile_arrays()
               | st.lists(valid, min_size=1, max_size=3)
               | hnp.arrays(np.float64, 2, elements=valid.filter(lambda v: v is not None)))
    return st.integers(0, 3).flatmap(lambda pick: bad if pick == 0 else valid)


def arguments(function: Any) -> st.SearchStrategy[dict[str, Any]]:
    parameters = inspect.signature(function).parameters
    return st.fixed_dictionaries({name: argument(name, function.__name__) for name in parameters})


def _values(result: Any, field: str = "") -> list[tuple[str, Any]]:
    """Every (field, number) in a result: named tuples, dataclasses, presets and arrays opened up."""
    if isinstance(result, tuple) and hasattr(result, "_fields"):
        return [v for name in result._fields for v in _values(getattr(result, name), name)]
    if isinstance(result, Record):
        return [v for f in record_fields(result) for v in _values(getattr(result, f.name), f.name)]
    if dataclasses.is_dataclass(result) and not isinstance(result, type):
        return [v for f in dataclasses.fields(result) for v in _values(getattr(result, f.name), f.name)]
    if isinstance(result, (str, bytes, type(None), bool)):
        return []
    if isinstance(result, (list, tuple)):
        return [v for item in result for v in _values(item, field)]
    if isinstance(result, dict):  # a preset's raw record, as its file gives it
        return [v for key, item in result.items() for v in _values(item, f"{field}.{key}")]
    if isinstance(result, np.ndarray) and result.dtype.kind in "USO":  # the model that ran, per element
        return [v for item in result.ravel().tolist() for v in _values(item, field)]
    if isinstance(result, (int, float, np.ndarray, np.generic)):
        return [(field, float(x)) for x in np.asarray(result, dtype=float).ravel()]
    return [(field, result)]


def defect(function: Any, kwargs: dict[str, Any]) -> str | None:
    """None when the call behaves; otherwise what went wrong, in one line."""
    names = list(inspect.signature(function).parameters)
    try:
        result = function(**kwargs)
    except DomainError as error:
        return None if error.param in names else f"DomainError names {error.param!r}, not a parameter: {error}"
    except CamtoolError as error:
        named = any(re.search(rf"\b{re.escape(n)}\b", str(error)) for n in names)
        return None if named else f"{type(error).__name__} names no parameter: {error}"
    except Exception as error:  # anything else is the defect this test looks for
        return f"{type(error).__name__}: {str(error)[:200]}"
    for field, value in _values(result):
        if not isinstance(value, float):
            return f"{field} is a {type(value).__name__}"
        if math.isnan(value):
            return f"{field} is NaN"
        if math.isinf(value) and (value < 0 or field.split(".")[-1] not in INFINITE_OK) \
                and not _unbounded_field(result, field):
            return f"{field} is {value}"
    return None


# A fisheye's field at the subject is unbounded from 180°: infinite exactly where its angle is 180° or more.
FIELD_ANGLES = {"field_width_mm": "horizontal_deg", "field_height_mm": "vertical_deg"}


def _unbounded_field(result: Any, field: str) -> bool:
    angle = FIELD_ANGLES.get(field)
    if angle is None or not hasattr(result, angle):
        return False
    size, degrees = np.broadcast_arrays(np.asarray(getattr(result, field), float), np.asarray(getattr(result, angle)))
    return bool(np.all(degrees[np.isinf(size)] >= 180.0))


def _shown(kwargs: dict[str, Any]) -> str:
    return ", ".join(f"{k}={np.array2string(v, threshold=6) if isinstance(v, np.ndarray) else repr(v)[:60]}"
                     for k, v in kwargs.items())


@pytest.mark.parametrize("name", sorted(FUNCTIONS))
@pytest.mark.filterwarnings("ignore::RuntimeWarning")  # numpy's overflow warnings: the answer is what is checked
def test_every_public_function_answers_or_names_the_argument(name: str) -> None:
    function = FUNCTIONS[name]
    failures: list[str] = []
    tried = [0]

    @seed(SEED)
    @settings(max_examples=EXAMPLES, derandomize=False, database=None, deadline=None,
              phases=[Phase.explicit, Phase.generate], suppress_health_check=list(HealthCheck))
    @given(kwargs=arguments(function))
    def call(kwargs: dict[str, Any]) -> None:
        tried[0] += 1
        found = defect(function, kwargs)
        if found:
            failures.append(f"{name}({_shown(kwargs)})  ->  {found}")

    call()
    assert not failures, f"{len(failures)} of {tried[0]} calls failed:\n  " + "\n  ".join(failures[:12])
    assert tried[0] >= EXAMPLES * 0.9


def test_the_fuzz_covers_every_public_function_and_parameter() -> None:
    expected = {"circle_of_confusion", "composition", "depth_of_field", "field_of_view", "focus_for_limits",
                "focus_for_magnification", "hyperfocal_distance", "plan_exposure", "equivalent_settings", "film_time",
                "flash_exposure", "preset", "preset_names", "star_trail_limits", "photo", "tilt", "rail_stack",
                "bracket_stack", "chart", "save_chart", "rotary_shutter", "coc_map", "pinhole"}
    assert set(FUNCTIONS) == expected
    for function in FUNCTIONS.values():
        assert set(inspect.signature(function).parameters) <= set(VALID)


@pytest.mark.parametrize(("call", "param"), [
    (lambda: camtool.depth_of_field("50", 8, 0.03, 3000), "focal_length_mm"),
    (lambda: camtool.depth_of_field(50, None, 0.03, 3000), "f_number"),
    (lambda: camtool.depth_of_field(None, 8, 0.03, 3000), "focal_length_mm"),  # None only with a prescription
    (lambda: camtool.depth_of_field(50, True, 0.03, 3000), "f_number"),
    (lambda: camtool.depth_of_field(50, 8, math.nan, 3000), "coc_mm"),
    (lambda: camtool.depth_of_field(50, 8, 0.03, -math.inf), "distance_mm"),
    (lambda: camtool.depth_of_field(50, 8, 0.03, ["1m", "2m"]), "distance_mm"),
    (lambda: camtool.depth_of_field(50, 8, 0.03, 3000, model="thn"), "model"),
    (lambda: camtool.depth_of_field(50, 8, 0.03, 3000, diffraction="yes"), "diffraction"),
    (lambda: camtool.depth_of_field(50, 8, 0.03, 3000, prescription="dgauss100"), "prescription"),
    (lambda: camtool.hyperfocal_distance(50, 8, 0.03, pupil_magnification=0.0), "pupil_magnification"),
    (lambda: camtool.field_of_view(50, 36, 24, magnification=math.inf), "magnification"),
    (lambda: camtool.field_of_view(8, 36, 24, projection="fish"), "projection"),
    (lambda: camtool.field_of_view(8, 36, 24, projection="equisolid", field_max_deg=400), "field_max_deg"),
    (lambda: camtool.focus_for_limits(50, 0.03, 2000, math.nan), "far_mm"),
    (lambda: camtool.focus_for_magnification(100, 10**400), "magnification"),
    (lambda: camtool.circle_of_confusion(36, 24, rule=1500), "rule"),
    (lambda: camtool.circle_of_confusion(36, 24, rule="print:0x0in@0cm"), "rule"),
    (lambda: camtool.circle_of_confusion(36, 0.0, rule="print:8x10in@25cm"), "sensor_height_mm"),
    (lambda: camtool.composition(100, 0.02, 36, 1e308), "sensor_height_mm"),
    (lambda: camtool.composition(100, 0.02, 0, 24), "sensor_width_mm"),
    (lambda: camtool.plan_exposure(ev100=12, f_number=8, shutter_s=Fraction(1, 125), iso=100), "shutter_s"),
    (lambda: camtool.plan_exposure(ev100=12, f_number=8, iso=100, pupil_magnification=4e-209, magnification=2),
     "pupil_magnification"),
    (lambda: camtool.depth_of_field(50, np.array([8.0, 11.0]), 0.03, np.array([1e3, 2e3, 3e3])), "distance_mm"),
    (lambda: camtool.depth_of_field(50, 8, 0.03, 3000, focal_mm=50), "focal_mm"),
])
def test_a_bad_argument_is_a_domain_error_naming_it(call: Any, param: str) -> None:
    with pytest.raises(DomainError) as caught:
        call()
    assert caught.value.param == param and str(caught.value).startswith(f"{param}=")


def test_valid_calls_answer_as_the_formulas_say() -> None:
    # Thin lens, focus from the sensor s = 3000 mm: H = f²/(N c) + f from the lens, u from s = u + v with
    # 1/u + 1/v = 1/f; near = u(H - f)/(H + u - 2f) from the lens; the sensor-plane values add the image distance.
    f, n, c, s = 50.0, 8.0, 0.03, 3000.0
    u = (s + math.sqrt(s * s - 4 * f * s)) / 2
    h = f * f / (n * c) + f
    r = camtool.depth_of_field(f, n, c, s, model="thin")
    assert r.near_mm == pytest.approx(u * (h - f) / (h + u - 2 * f) + (s - u), rel=1e-9)
    assert r.hyperfocal_mm == pytest.approx(h + f * h / (h - f), rel=1e-12)
    # A list of numbers is an array, element by element the scalar answers; integers are numbers.
    both = camtool.depth_of_field([50, 85], 8, 0.03, 3000, model="thin")
    assert isinstance(both.near_mm, np.ndarray)
    assert both.near_mm[0] == pytest.approx(r.near_mm, rel=1e-12)
    assert both.near_mm[1] == pytest.approx(camtool.depth_of_field(85.0, 8.0, 0.03, 3000.0, model="thin").near_mm,
                                            rel=1e-12)
    # An 8-bit integer array is read as numbers, not wrapped around (uint8: 200 + 100 would be 44).
    fov = camtool.field_of_view(np.array([200], dtype=np.uint8), 36, 24)
    assert fov.horizontal_deg[0] == pytest.approx(2 * math.degrees(math.atan(18 / 200)), rel=1e-12)
    # Infinity stays meaningful where it is: focused at infinity, the far limit is infinite.
    assert camtool.depth_of_field(50, 8, 0.03, math.inf, model="thin").far_mm == math.inf


def test_the_checks_cost_no_numpy_import_for_plain_numbers() -> None:
    import subprocess
    import sys

    code = ("import sys, camtool\n"
            "try:\n    camtool.depth_of_field('50', 8, 0.03, 3000)\nexcept camtool.api.DomainError:\n    pass\n"
            "camtool.plan_exposure(ev100=12, f_number=8, iso=100)\nprint('numpy' in sys.modules)")
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True, timeout=60).stdout
    assert out.strip() == "False"
