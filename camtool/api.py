"""camtool's public Python API: the main calculations, with units in every parameter name.

Every function takes plain floats or numpy arrays (broadcast together) and
returns a named result. Lengths are millimetres, angles degrees, times
seconds. Distances are measured from the sensor (focal) plane unless
``distance_from="lens"`` says otherwise, as on the command line (see
``docs/design.md`` §2). A value outside a formula's physical domain raises
:class:`camtool.core.errors.DomainError`, a :class:`ValueError` naming the
parameter, the value and the valid range; so does an argument of the wrong
type (a string, None or a bool where a number belongs, a list holding
anything but numbers) and a NaN or infinity where no infinite value is
meaningful. Every public function checks its arguments the same way, by the
kind its annotation names (:data:`Number`, :data:`FocalLength`, :data:`DistanceOrInf`, ...), before
anything is computed; nothing else escapes but :class:`~camtool.core.errors.CamtoolError`.

Examples
--------
>>> import camtool
>>> r = camtool.depth_of_field(focal_length_mm=50, f_number=8, coc_mm=0.03, distance_mm=3000, model="thin")
>>> round(r.near_mm), round(r.far_mm), r.model
(2358, 4137, 'thin')
>>> round(camtool.hyperfocal_distance(focal_length_mm=50, f_number=8, coc_mm=0.03, model="thin").hyperfocal_mm)
10517
"""

from __future__ import annotations

import functools
import inspect
import math
import numbers
import sys
import typing
from collections.abc import Callable
from dataclasses import dataclass
from typing import Annotated, Any, TypeVar

from camtool.core.domain import ISO_RANGE, SHUTTER_RANGE_S
from camtool.core.errors import DomainError
from camtool.core.ranges import (
    CHART_DPI,
    CHART_SIDE_IN,
    COC_MM,
    CROP_FACTOR,
    DISTANCE_MM,
    F_NUMBER,
    FOCAL_LENGTH_MM,
    FRAME_RATE_FPS,
    MAGNIFICATION,
    MTF_LEVEL,
    PIXEL_PITCH_UM,
    PUPIL_MAGNIFICATION,
    SENSOR_SIDE_MM,
    SHUTTER_ANGLE_DEG,
    TILT_DEG,
    TOLERANCE,
    WAVELENGTH_NM,
    describe,
)
from camtool.core.record import NamedTuple
from camtool.dof.ladder import LensData
from camtool.dof.limits import DofLimits
from camtool.exposure.equivalence import Equivalent
from camtool.exposure.flash import Flash
from camtool.exposure.plan import ExposurePlan
from camtool.exposure.stars import StarLimits
from camtool.geometry.compose import Composition
from camtool.geometry.fov import FieldOfView
from camtool.geometry.thinlens import FocusGeometry
from camtool.plans.cine import RotaryShutter
from camtool.plans.cocmap import CocMap
from camtool.plans.photo import PhotoAnswer
from camtool.plans.pinhole import PinholePlan
from camtool.plans.stack import BracketStack, RailStack
from camtool.plans.tilt import TiltAnswer
from camtool.render.chartdata import ChartData

__all__ = [
    "BracketStack",
    "ChartData",
    "CocMap",
    "Composition",
    "DepthOfField",
    "DofLimits",
    "Equivalent",
    "ExposurePlan",
    "FieldOfView",
    "Flash",
    "FocusGeometry",
    "FocusPlan",
    "HyperfocalDistance",
    "LensData",
    "PhotoAnswer",
    "PinholePlan",
    "RailStack",
    "RotaryShutter",
    "StarLimits",
    "TiltAnswer",
    "bracket_stack",
    "chart",
    "circle_of_confusion",
    "coc_map",
    "composition",
    "depth_of_field",
    "equivalent_settings",
    "field_of_view",
    "film_time",
    "flash_exposure",
    "focus_for_limits",
    "focus_for_magnification",
    "hyperfocal_distance",
    "photo",
    "pinhole",
    "plan_exposure",
    "preset",
    "preset_names",
    "rail_stack",
    "rotary_shutter",
    "save_chart",
    "star_trail_limits",
    "tilt",
]

@dataclass(frozen=True)
class _Kind:
    """What a public function's parameter takes; :func:`_checked` checks each argument against it."""

    what: str  # "number", "choice", "text", "flag", "points", "chart", "prescription"
    optional: bool = False  # None allowed (it then means "not given")
    allow_inf: bool = False  # +inf allowed (a distance at infinity)
    scalar: bool = False  # one number only, no array
    positive: bool = False  # > 0 (a ratio such as a pupil magnification, which divides)
    bounds: tuple[float, float] | None = None  # the closed range of the option it stands for (a low 0 is open)
    zero_ok: bool = False  # a low bound of 0 is closed (a magnification of 0: the subject at infinity)
    unit: str = ""
    choices: tuple[str, ...] = ()

    def describe(self) -> str:
        if self.what == "number":
            text = ("a number" if self.bounds else "a finite number") + (" > 0" if self.positive else "") + (
                "" if self.scalar else " or an array of them")
            if self.bounds is not None:
                shown = describe(self.bounds, self.unit, self.allow_inf)
                text = f"{shown.removeprefix('> ') if self.zero_ok else shown} ({text})"
            elif self.allow_inf:
                text += " (+inf allowed)"
        elif self.what == "choice":
            text = "one of " + ", ".join(repr(c) for c in self.choices)
        elif self.what == "text":
            text = "a string"
        elif self.what == "flag":
            text = "True or False"
        elif self.what == "points":
            text = "two (distance_mm, height_mm) pairs"
        elif self.what == "chart":
            text = "a camtool.ChartData (from camtool.chart)"
        else:
            text = "a camtool.optics.prescription.Prescription"
        return text + (", or None" if self.optional else "")


Number = Annotated[Any, _Kind("number")]
"""A finite float or int (not a bool), or an array or (nested) list of them."""
OptionalNumber = Annotated[Any, _Kind("number", optional=True)]
"""As :data:`Number`, or None for "not given"."""
Real = Annotated[float, _Kind("number", scalar=True)]
"""One finite float or int (not a bool, not an array)."""
OptionalReal = Annotated[Any, _Kind("number", scalar=True, optional=True)]
"""As :data:`Real`, or None for "not given"."""

# The optical inputs within the ranges their command-line options take (camtool.core.ranges).
FocalLength = Annotated[Any, _Kind("number", bounds=FOCAL_LENGTH_MM, unit="mm")]
OptionalFocalLength = Annotated[Any, _Kind("number", optional=True, bounds=FOCAL_LENGTH_MM, unit="mm")]
FNumber = Annotated[Any, _Kind("number", bounds=F_NUMBER)]
CoC = Annotated[Any, _Kind("number", bounds=COC_MM, unit="mm")]
Distance = Annotated[Any, _Kind("number", bounds=DISTANCE_MM, unit="mm")]
DistanceOrInf = Annotated[Any, _Kind("number", allow_inf=True, bounds=DISTANCE_MM, unit="mm")]
SensorSide = Annotated[Any, _Kind("number", bounds=SENSOR_SIDE_MM, unit="mm")]
SensorSideReal = Annotated[float, _Kind("number", scalar=True, bounds=SENSOR_SIDE_MM, unit="mm")]
Magnification = Annotated[Any, _Kind("number", bounds=MAGNIFICATION)]
MagnificationOrZero = Annotated[Any, _Kind("number", bounds=(0.0, MAGNIFICATION[1]), zero_ok=True)]
"""A magnification, or 0 for a subject at infinity (closed at 0, unlike :data:`Magnification`)."""
PupilMagnification = Annotated[Any, _Kind("number", bounds=PUPIL_MAGNIFICATION)]
OptionalPupilMagnification = Annotated[Any, _Kind("number", scalar=True, optional=True, bounds=PUPIL_MAGNIFICATION)]
Wavelength = Annotated[Any, _Kind("number", bounds=WAVELENGTH_NM, unit="nm")]
"""A wavelength, as ``--wavelength`` takes it: near ultraviolet to near infrared."""
Tolerance = Annotated[float, _Kind("number", scalar=True, bounds=TOLERANCE)]
"""A relative tolerance, one number above 0 and below 1 (100 %)."""
PixelPitch = Annotated[Any, _Kind("number", scalar=True, optional=True,
                                  bounds=(PIXEL_PITCH_UM[0] / 1000.0, PIXEL_PITCH_UM[1] / 1000.0), unit="mm")]
Flag = Annotated[bool, _Kind("flag")]
ISO = Annotated[Any, _Kind("number", bounds=ISO_RANGE)]
OptionalISO = Annotated[Any, _Kind("number", optional=True, bounds=ISO_RANGE)]
ISOReal = Annotated[float, _Kind("number", scalar=True, bounds=ISO_RANGE)]
OptionalFNumber = Annotated[Any, _Kind("number", optional=True, bounds=F_NUMBER)]
OptionalPositive = Annotated[Any, _Kind("number", optional=True, positive=True)]
Positive = Annotated[Any, _Kind("number", positive=True)]
Crop = Annotated[Any, _Kind("number", bounds=CROP_FACTOR)]
Declination = Annotated[Any, _Kind("number", bounds=(-89.0, 89.0), unit="°", zero_ok=True)]
OptionalPixelPitchUm = Annotated[Any, _Kind("number", optional=True, bounds=PIXEL_PITCH_UM, unit="µm")]
ShutterTime = Annotated[Any, _Kind("number", bounds=SHUTTER_RANGE_S, unit="s")]
Diagonal = Annotated[Any, _Kind("number", bounds=(0.5, 2000.0 * math.sqrt(2.0)), unit="mm")]
DistanceFrom = Annotated[str, _Kind("choice", choices=("sensor", "lens"))]
Projection = Annotated[str, _Kind("choice", choices=("rectilinear", "equidistant", "equisolid", "orthographic",
                                                     "stereographic"))]
OptionalFieldDeg = Annotated[Any, _Kind("number", scalar=True, optional=True, bounds=(1e-9, 360.0), unit="°")]
Model = Annotated[str, _Kind("choice", choices=("auto", "approx", "thin", "thick", "paraxial", "raytrace", "wave"))]
ContrastLevel = Annotated[float, _Kind("number", scalar=True, bounds=MTF_LEVEL)]
"""A contrast (MTF) level, as ``pinhole --contrast`` takes it: 0.05 to 0.95."""
RealFilmDistance = Annotated[float, _Kind("number", scalar=True, bounds=FOCAL_LENGTH_MM, unit="mm")]
EV100 = Annotated[float, _Kind("number", scalar=True, bounds=(-10.0, 25.0), zero_ok=True)]
Text = Annotated[str, _Kind("text")]
OptionalAngle = Annotated[Any, _Kind("number", scalar=True, optional=True, bounds=TILT_DEG, unit="°", zero_ok=True)]
OptionalDistance = Annotated[Any, _Kind("number", scalar=True, optional=True, bounds=DISTANCE_MM, unit="mm")]
OptionalDistanceOrInf = Annotated[Any, _Kind("number", scalar=True, optional=True, allow_inf=True,
                                             bounds=DISTANCE_MM, unit="mm")]
OptionalCoC = Annotated[Any, _Kind("number", scalar=True, optional=True, bounds=COC_MM, unit="mm")]
OptionalRealFNumber = Annotated[Any, _Kind("number", scalar=True, optional=True, bounds=F_NUMBER)]
RealFocalLength = Annotated[Any, _Kind("number", scalar=True, optional=True, bounds=FOCAL_LENGTH_MM, unit="mm")]
RealCoC = Annotated[float, _Kind("number", scalar=True, bounds=COC_MM, unit="mm")]
Points = Annotated[Any, _Kind("points", optional=True)]
TiltModel = Annotated[str, _Kind("choice", choices=("auto", "thin", "thick", "raytrace", "all"))]
Along = Annotated[str, _Kind("choice", choices=("sight", "axis"))]
AnglesFrom = Annotated[str, _Kind("choice", choices=("film", "lens", "horizon"))]
HingeFrom = Annotated[str, _Kind("choice", choices=("lens", "pupil"))]
OptionalRule = Annotated[Any, _Kind("text", optional=True)]
Overlap = Annotated[float, _Kind("number", scalar=True, bounds=(0.0, 0.99), zero_ok=True)]
Criterion = Annotated[Any, _Kind("choice", optional=True, choices=("classic", "defocus", "wave"))]
RealMagnification = Annotated[float, _Kind("number", scalar=True, bounds=MAGNIFICATION)]
RealDistance = Annotated[float, _Kind("number", scalar=True, bounds=DISTANCE_MM, unit="mm")]
RealDistanceOrInf = Annotated[float, _Kind("number", scalar=True, allow_inf=True, bounds=DISTANCE_MM, unit="mm")]
RealFNumber = Annotated[float, _Kind("number", scalar=True, bounds=F_NUMBER)]
RealPupilMagnification = Annotated[float, _Kind("number", scalar=True, bounds=PUPIL_MAGNIFICATION)]
RealWavelength = Annotated[float, _Kind("number", scalar=True, bounds=WAVELENGTH_NM, unit="nm")]
OptionalSensorSide = Annotated[Any, _Kind("number", scalar=True, optional=True, bounds=SENSOR_SIDE_MM, unit="mm")]
OptionalText = Annotated[Any, _Kind("text", optional=True)]
OptionalPrescription = Annotated[Any, _Kind("prescription", optional=True)]

FULL_FRAME_DIAGONAL = math.hypot(36.0, 24.0)
PRESET_KINDS = ("sensor", "camera", "lens", "prescription", "scene", "film")

_F = TypeVar("_F", bound=Callable[..., Any])


def _kinds(function: Callable[..., Any]) -> dict[str, _Kind]:
    hints = typing.get_type_hints(function, include_extras=True)
    kinds = {}
    for name in inspect.signature(function).parameters:
        meta = [m for m in getattr(hints.get(name), "__metadata__", ()) if isinstance(m, _Kind)]
        if not meta:
            raise TypeError(f"{function.__name__}: parameter {name} has no checked kind")
        kinds[name] = meta[0]
    return kinds


def _checked(function: _F) -> _F:
    """Check every argument of a public function against the kind its annotation names, then call it.

    A wrong type or a non-finite number raises :class:`DomainError` naming the
    parameter as the function spells it; an error from the calculation that
    is not a :class:`CamtoolError` is a defect, so it is not disguised here.
    """
    signature = inspect.signature(function)
    kinds = _kinds(function)

    @functools.wraps(function)
    def call(*args: Any, **kwargs: Any) -> Any:
        try:
            bound = signature.bind(*args, **kwargs)
        except TypeError as error:  # a missing, unknown or repeated argument
            raise _call_error(function, signature, args, kwargs, error) from None
        for name, value in bound.arguments.items():
            bound.arguments[name] = _check(name, value, kinds[name])
        _broadcast(bound.arguments)
        try:
            return function(*bound.args, **bound.kwargs)
        except DomainError as error:
            if error.param in kinds:
                raise
            raise _renamed(error, bound.arguments, kinds) from None

    return typing.cast(_F, call)


def _broadcast(arguments: dict[str, Any]) -> None:
    """Raise :class:`DomainError` naming the first array whose shape does not broadcast with those before it."""
    numpy = sys.modules.get("numpy")
    if numpy is None:
        return
    shape: tuple[int, ...] = ()
    for name, value in arguments.items():
        if isinstance(value, numpy.ndarray):
            try:
                shape = numpy.broadcast_shapes(shape, value.shape)
            except ValueError:
                raise DomainError(name, f"an array of shape {value.shape}", f"an array that broadcasts with shape "
                                  f"{shape} (the arrays given before it)") from None


def _renamed(error: DomainError, arguments: dict[str, Any], kinds: dict[str, _Kind]) -> DomainError:
    """The error of a formula that spells a parameter its own way (``sensor_mm``), naming the caller's argument.

    The argument named is the one holding the offending value (``sensor_height_mm=0``); when none holds it
    (a rule about several arguments), the first number given.
    """
    numbers_given = [name for name, kind in kinds.items() if kind.what == "number" and arguments.get(name) is not None]
    for name in numbers_given:
        if _holds(arguments[name], error.value):
            return DomainError(name, error.value, error.valid, error.detail, error.limit)
    name = numbers_given[0] if numbers_given else next(iter(kinds))
    return DomainError(name, arguments.get(name), error.valid, error.detail, error.limit)


def _holds(argument: Any, value: Any) -> bool:
    if not isinstance(value, (int, float)) or isinstance(value, bool):
        return False
    if isinstance(argument, (int, float)):
        return bool(argument == value)
    import numpy as np

    return bool(np.any(np.asarray(argument) == value))


def _call_error(function: Callable[..., Any], signature: inspect.Signature, args: tuple[Any, ...],
                kwargs: dict[str, Any], error: TypeError) -> DomainError:
    names = list(signature.parameters)
    for name in kwargs:
        if name not in signature.parameters:
            return DomainError(name, kwargs[name], f"a parameter of {function.__name__}: " + ", ".join(names),
                               "no such parameter")
    positional = [p.name for p in signature.parameters.values()
                  if p.kind in (p.POSITIONAL_ONLY, p.POSITIONAL_OR_KEYWORD)]
    if len(args) > len(positional):
        return DomainError(names[-1], args[len(positional)], f"at most {len(positional)} positional arguments "
                           f"({', '.join(positional)}); give the others by name", "too many positional arguments")
    for name in positional[:len(args)]:
        if name in kwargs:
            return DomainError(name, kwargs[name], "given once", "given both by position and by name")
    missing = [p.name for p in signature.parameters.values()
               if p.default is p.empty and p.name not in kwargs and p.name not in positional[:len(args)]]
    return DomainError(missing[0] if missing else names[0], None, "a value is required", str(error))


def _check(name: str, value: Any, kind: _Kind) -> Any:
    """``value`` if it is of ``kind`` (a list of numbers as a float array), else :class:`DomainError` naming ``name``."""
    if value is None:
        if kind.optional:
            return None
        raise DomainError(name, None, kind.describe(), "missing")
    if kind.what == "number":
        return _check_number(name, value, kind)
    if kind.what == "choice":
        if not isinstance(value, str) or value not in kind.choices:
            raise DomainError(name, _shown(value), kind.describe())
    elif kind.what == "text":
        if not isinstance(value, str):
            raise DomainError(name, _shown(value), kind.describe(), f"a {type(value).__name__}")
    elif kind.what == "points":
        return _check_points(name, value)
    elif kind.what == "flag":
        numpy = sys.modules.get("numpy")
        if not (isinstance(value, bool) or (numpy is not None and isinstance(value, numpy.bool_))):
            raise DomainError(name, _shown(value), kind.describe(), f"a {type(value).__name__}")
    elif kind.what == "chart":
        if not isinstance(value, ChartData):
            raise DomainError(name, _shown(value), kind.describe(), f"a {type(value).__name__}")
    else:
        from camtool.optics.prescription import Prescription

        if not isinstance(value, Prescription):
            raise DomainError(name, _shown(value), kind.describe(), f"a {type(value).__name__}")
    return value


def _check_points(name: str, value: Any) -> tuple[tuple[float, float], ...]:
    """Two (distance_mm, height_mm) pairs, each a finite number (a distance > 0), as a tuple of float pairs."""
    valid = "two (distance_mm, height_mm) pairs of finite numbers, distances > 0"
    try:
        pairs = tuple((float(d), float(h)) for d, h in value)
    except (TypeError, ValueError, OverflowError):
        raise DomainError(name, _shown(value), valid) from None
    if len(pairs) != 2 or any(isinstance(x, bool) for pair in value for x in pair) or not all(
            math.isfinite(d) and math.isfinite(h) and d > 0 for d, h in pairs):
        raise DomainError(name, _shown(value), valid)
    return pairs


def _shown(value: Any) -> Any:
    """The value as an error message shows it: a string quoted, a long text cut short."""
    text = repr(value) if isinstance(value, (str, bytes)) else value
    if isinstance(text, str) and len(text) > 60:
        text = text[:57] + "..."
    return text


def _finite(name: str, number: float, kind: _Kind) -> None:
    if math.isnan(number) or (math.isinf(number) and not (kind.allow_inf and number > 0)) or (
            kind.positive and not number > 0) or (kind.bounds is not None and not _within(number, kind)):
        raise DomainError(name, number, kind.describe())


def _within(number: Any, kind: _Kind) -> Any:
    """Whether ``number`` (a float or an array) lies in ``kind.bounds``: closed, but a low bound of 0 is open."""
    assert kind.bounds is not None
    low, high = kind.bounds
    inside = ((number > low) if low == 0 and not kind.zero_ok else (number >= low)) & (number <= high)
    return inside | (number == math.inf) if kind.allow_inf else inside


def _check_number(name: str, value: Any, kind: _Kind) -> Any:
    if isinstance(value, bool):
        raise DomainError(name, value, kind.describe(), "a bool is not a number")
    if isinstance(value, (int, float)):
        try:
            number = float(value)
        except OverflowError:  # only an int can be too large for a float
            raise DomainError(name, f"an integer of {int(value).bit_length()} bits", kind.describe(),
                              "too large for a float") from None
        _finite(name, number, kind)
        return value
    numpy = sys.modules.get("numpy")
    if not (numpy is not None and isinstance(value, (numpy.ndarray, numpy.generic))) and not isinstance(
            value, (list, tuple)):
        if isinstance(value, numbers.Real):  # a Fraction, a Decimal-like real: say which type to give
            raise DomainError(name, _shown(str(value)), kind.describe(), f"a {type(value).__name__}; give a float")
        raise DomainError(name, _shown(value), kind.describe(), f"a {type(value).__name__}")
    import numpy as np

    try:
        array = np.asarray(value)
    except (ValueError, TypeError, OverflowError):  # a ragged list, or something numpy cannot hold
        raise DomainError(name, _shown(str(value)), kind.describe(), "not a rectangular array") from None
    if array.dtype.kind not in "iuf" or (isinstance(value, (list, tuple)) and _holds_bool(value)):
        held = {"b": "bools", "c": "complex numbers", "O": "objects", "U": "strings", "S": "bytes"}
        what = held.get(array.dtype.kind, "bools" if array.dtype.kind in "iuf" else "non-numbers")
        raise DomainError(name, _shown(str(value)), kind.describe(), f"holds {what}")
    if kind.scalar and array.ndim:
        raise DomainError(name, _shown(str(value)), kind.describe(), "an array; give one number")
    if array.size == 0:
        raise DomainError(name, _shown(str(value)), kind.describe(), "an empty array")
    if array.dtype.kind != "f":
        array = array.astype(float)  # integer arithmetic would wrap around (uint8: 200 + 100 = 44)
    bad = np.isnan(array) | (np.isinf(array) & ~((array > 0) & kind.allow_inf)) | (kind.positive & ~(array > 0))
    if kind.bounds is not None:
        bad |= ~_within(array, kind)
    if bool(bad.any()):
        raise DomainError(name, float(array[bad].flat[0]), kind.describe())
    return float(array) if array.ndim == 0 else array


def _holds_bool(value: Any) -> bool:
    if isinstance(value, (list, tuple)):
        return any(_holds_bool(item) for item in value)
    numpy = sys.modules.get("numpy")
    return isinstance(value, bool) or (numpy is not None and isinstance(value, numpy.bool_))


class DepthOfField(NamedTuple):
    """The result of :func:`depth_of_field`, distances in mm from the plane the focus was given in.

    ``far_mm``, ``rear_mm`` and ``total_mm`` are ``inf`` when everything beyond the focus is sharp;
    ``model`` names the rung that ran (``+diffraction`` when the Airy disc was added) and
    ``error_estimate`` its estimated relative error.
    """

    near_mm: Any
    far_mm: Any
    front_mm: Any
    rear_mm: Any
    total_mm: Any
    hyperfocal_mm: Any
    magnification: Any
    model: Any
    error_estimate: Any


def _focal_or_prescription(focal_length_mm: Any, prescription: Any) -> None:
    """A focal length is given, or a prescription gives one."""
    if focal_length_mm is None and prescription is None:
        raise DomainError("focal_length_mm", None, describe(FOCAL_LENGTH_MM, "mm"), "None only with a prescription")


def _lens(pupil_magnification: Any, hiatus_mm: Any, prescription: Any, focal_length_mm: Any = 0.0) -> LensData | None:
    _focal_or_prescription(focal_length_mm, prescription)
    if pupil_magnification is None and hiatus_mm is None and prescription is None:
        return None
    return LensData(pupil_magnification=pupil_magnification, hiatus_mm=hiatus_mm, prescription=prescription)


@_checked
def depth_of_field(
    focal_length_mm: OptionalFocalLength,
    f_number: FNumber,
    coc_mm: CoC,
    distance_mm: DistanceOrInf,
    *,
    distance_from: DistanceFrom = "sensor",
    model: Model = "auto",
    pupil_magnification: OptionalPupilMagnification = None,
    hiatus_mm: OptionalReal = None,
    prescription: OptionalPrescription = None,
    diffraction: Flag = False,
    wavelength_nm: Wavelength = 550.0,
    tolerance: Tolerance = 0.01,
    contrast_criterion: OptionalText = None,
    lens: OptionalText = None,
) -> DepthOfField:
    """Near and far limits of acceptable sharpness in mm, by a rung of the model ladder.

    Parameters
    ----------
    focal_length_mm : float or array, 1 to 5000 mm (ignored with a ``prescription``: pass None)
    f_number : float or array, the nominal (marked) f-number, 0.7 to 1024
    coc_mm : float or array, the circle of confusion on the sensor, mm
    distance_mm : float or array, focus distance from the plane ``distance_from``; ``inf`` allowed
    distance_from : ``"sensor"`` (default) or ``"lens"``
    model : ``"approx"``, ``"thin"``, ``"thick"``, ``"paraxial"``, ``"raytrace"``, ``"wave"`` or ``"auto"``
        (the cheapest rung whose estimated error stays within ``tolerance``)
    pupil_magnification, hiatus_mm : lens data for the ``thick`` rung (P = exit/entrance pupil diameter)
    prescription : a :class:`camtool.optics.prescription.Prescription` for ``paraxial``, ``raytrace`` and
        ``wave`` (which then computes the real lens's wavefront and FFT MTF: model ``wave+prescription``)
    diffraction : bool, add the Airy disc to the blur (λ = ``wavelength_nm``)
    contrast_criterion : str or None, ``mtf:LEVEL@FREQ`` as ``--criterion`` takes it: the ``wave`` rung's
        criterion (given, ``auto`` runs ``wave``; docs/wave.md)
    lens : str or None, a lens preset's name, as ``camtool dof --lens`` takes it: its pupil magnification,
        hiatus and prescription unless given, a prime's focal length when ``focal_length_mm`` is None, its
        ranges of focal length, f-number and focus; one that focuses internally answers at the focal length in
        effect at each focus, with its own hyperfocal distance (docs/closeup.md)

    Returns
    -------
    DepthOfField
        near, far, front, rear, total and hyperfocal distances in mm, the magnification, the ``model``
        that ran and its ``error_estimate`` (relative).

    Examples
    --------
    >>> r = depth_of_field(50, 8, 0.03, 3000, model="thin")
    >>> round(r.total_mm)
    1779
    >>> depth_of_field(50, 8, 0.03, 3000, contrast_criterion="mtf:0.3@coc").model
    'wave'
    """
    from camtool.dof.ladder import depth_of_field as run

    criterion = _criterion(contrast_criterion)
    if lens is not None:
        data, preset_lens, focal_length_mm = _lens_with_preset(lens, pupil_magnification, hiatus_mm, prescription,
                                                               focal_length_mm, f_number, distance_mm, distance_from)
        return _preset_depth_of_field(model, focal_length_mm, f_number, coc_mm, distance_mm, distance_from, data,
                                      preset_lens, pupil_magnification, hiatus_mm, diffraction, wavelength_nm,
                                      tolerance, criterion)
    ladder_lens = _lens(pupil_magnification, hiatus_mm, prescription, focal_length_mm)
    result = run(model, focal_length_mm, f_number, coc_mm, distance_mm, distance_from, ladder_lens, diffraction,
                 wavelength_nm, tolerance, criterion)
    return DepthOfField(*result.limits, result.model, result.error_estimate)


def _preset_depth_of_field(model: str, focal_length_mm: Any, f_number: Any, coc_mm: Any, distance_mm: Any,
                           distance_from: str, data: LensData | None, preset_lens: Any, pupil_magnification: Any,
                           hiatus_mm: Any, diffraction: bool, wavelength_nm: float, tolerance: float,
                           criterion: Any) -> DepthOfField:
    """:func:`depth_of_field` with a lens preset: the rows ``camtool dof --lens`` computes
    (:func:`camtool.plans.dof.dof_table`: internal focusing, its hyperfocal distance), one per scene."""
    from camtool.dof.ladder import focal_lengths
    from camtool.plans.dof import dof_table

    inputs = (focal_length_mm, f_number, coc_mm, distance_mm)
    scalar = all(not hasattr(value, "shape") or value.shape == () for value in inputs if value is not None)
    if scalar:
        shape: tuple[int, ...] = ()
        flat = [None if value is None else [float(value)] for value in inputs]
    else:
        import numpy as np

        shape = np.broadcast_shapes(*(np.shape(value) for value in inputs if value is not None))
        flat = [None if value is None else np.broadcast_to(np.asarray(value, dtype=float), shape).ravel().tolist()
                for value in inputs]
    given_f, *rest = flat
    count = len(rest[0] or ())
    focal = focal_lengths(data, given_f or [])
    if len(focal) != count:  # the prescription's one focal length, for every scene
        focal = focal * count
    columns: list[Any] = [focal, *rest]
    if scalar:  # one scene: plain floats, as the command computes a single row
        f, n, c, s = (values[0] for values in columns)
    else:
        f, n, c, s = (np.asarray(values, dtype=float) for values in columns)
    table = dof_table(model=model, focal_length_mm=f, f_number=n, wanted=s, coc_mm=c, distance_from=distance_from,
                      lens=data, pupil_magnification=pupil_magnification, hiatus_mm=hiatus_mm,
                      lens_preset=preset_lens, diffraction=diffraction, wavelength_nm=wavelength_nm,
                      tolerance=tolerance, criterion=criterion)
    rows = list(table.rows)
    for row in rows:
        if row.get("near_mm") is None:  # nothing sharp (the Airy disc fills the CoC), as the ladder raises it
            raise DomainError("f_number", row["f_number"], "an f-number that leaves depth of field",
                              detail=str(row.get("reason")))
    keys = ("near_mm", "far_mm", "front_mm", "rear_mm", "total_mm", "hyperfocal_mm", "magnification", "model",
            "error_estimate")
    if scalar:
        return DepthOfField(*(rows[0][key] for key in keys))
    import numpy as np

    return DepthOfField(*(np.array([row[key] for row in rows], dtype=object if key == "model" else float)
                          .reshape(shape) for key in keys))


def _criterion(text: str | None) -> Any:
    """A ``mtf:LEVEL@FREQ`` criterion read by the one parser (:func:`camtool.core.units.parse_criterion`)."""
    if text is None:
        return None
    from camtool.core.units import UnitError, parse_criterion
    from camtool.dof.wave import Criterion

    try:
        return Criterion(*parse_criterion(text))
    except UnitError as error:
        raise DomainError("contrast_criterion", text, "mtf:LEVEL@FREQ, e.g. mtf:0.3@40 or mtf:0.181@coc",
                          detail=str(error)) from None


class HyperfocalDistance(NamedTuple):
    """The result of :func:`hyperfocal_distance`: H and the near limit when focused there (mm), and the model."""

    hyperfocal_mm: Any
    near_mm: Any
    model: Any


@_checked
def hyperfocal_distance(
    focal_length_mm: OptionalFocalLength,
    f_number: FNumber,
    coc_mm: CoC,
    *,
    distance_from: DistanceFrom = "sensor",
    model: Model = "auto",
    pupil_magnification: OptionalPupilMagnification = None,
    hiatus_mm: OptionalReal = None,
    prescription: OptionalPrescription = None,
    lens: OptionalText = None,
) -> HyperfocalDistance:
    """The hyperfocal distance in mm and the near limit when focused there: the answer of ``camtool hyperfocal``.

    ``hyperfocal_mm`` is the closest focus at which the far limit reaches
    infinity; ``near_mm`` is the near limit with that focus (half the
    hyperfocal distance for the ``approx`` rung). ``auto`` means what it means
    on the command line (:func:`camtool.dof.ladder.hyperfocal_rung`: ``thick``
    with pupil data, else ``thin``); ``paraxial`` and ``raytrace`` find H with
    that rung's own limits. ``lens`` names a lens preset: one that focuses
    internally has its H where its far limit reaches infinity at the focal
    length in effect there, as ``camtool hyperfocal --lens`` gives it.

    Examples
    --------
    >>> h = hyperfocal_distance(24, 11, 0.03, model="approx")
    >>> round(h.hyperfocal_mm), h.model  # f²/(N·c) = 576/0.33, plus the lens-to-sensor spacing f + N·c
    (1745, 'approx')
    """
    data, preset_lens, focal_length_mm = _lens_with_preset(lens, pupil_magnification, hiatus_mm, prescription,
                                                           focal_length_mm, f_number)
    if model in ("paraxial", "raytrace"):
        from camtool.dof.ladder import depth_of_field as run

        first = run(model, focal_length_mm, f_number, coc_mm, float("inf"), distance_from, data)
        at_h = run(model, focal_length_mm, f_number, coc_mm, first.limits.hyperfocal_mm, distance_from, data)
        return HyperfocalDistance(at_h.limits.hyperfocal_mm, at_h.limits.near_mm, at_h.model)
    from camtool.plans.depth import hyperfocal_plan

    if focal_length_mm is None and data is not None and data.prescription is not None:
        from camtool.dof.ladder import prescription_focal_length

        focal_length_mm = prescription_focal_length(data)
    plan = hyperfocal_plan(model=model, focal_length_mm=focal_length_mm, f_number=f_number, coc_mm=coc_mm,
                           distance_from=distance_from, lens=data, lens_preset=preset_lens)
    return HyperfocalDistance(plan.hyperfocal_mm, plan.near_mm, plan.model)


@_checked
def field_of_view(
    focal_length_mm: FocalLength,
    sensor_width_mm: SensorSide,
    sensor_height_mm: SensorSide,
    *,
    magnification: MagnificationOrZero = 0.0,
    pupil_magnification: PupilMagnification = 1.0,
    projection: Projection = "rectilinear",
    field_max_deg: OptionalFieldDeg = None,
) -> FieldOfView:
    """Horizontal, vertical and diagonal angles of view in degrees (with focus breathing at ``magnification``).

    ``projection`` is the lens's mapping (a fisheye's: ``equidistant``,
    ``equisolid``, ``orthographic``, ``stereographic``); a fisheye covers at
    most ``field_max_deg`` (180° when None), docs/design.md §4.2.

    Examples
    --------
    >>> round(field_of_view(50, 36, 24).horizontal_deg, 2)  # 2·atan(18/50)
    39.6
    >>> field_of_view(8, 36, 24, projection="equisolid").diagonal_deg  # a circular fisheye: its 180°
    180.0
    """
    if projection != "rectilinear" or field_max_deg is not None:
        from camtool.geometry.projection import fisheye_field_of_view

        return FieldOfView(*fisheye_field_of_view(sensor_width_mm, sensor_height_mm, focal_length_mm, projection,
                                                  magnification, pupil_magnification, field_max_deg))
    from camtool.geometry.fov import field_of_view as run

    return run(sensor_width_mm, sensor_height_mm, focal_length_mm, magnification, pupil_magnification)


class FocusPlan(NamedTuple):
    """Where to focus and which f-number makes the depth of field run from ``near_mm`` to ``far_mm``."""

    distance_mm: Any
    f_number: Any


@_checked
def focus_for_limits(
    focal_length_mm: FocalLength, coc_mm: CoC, near_mm: Distance, far_mm: DistanceOrInf, *,
    distance_from: DistanceFrom = "sensor"
) -> FocusPlan:
    """The focus distance in mm and the f-number whose thin-lens depth of field is exactly [near, far].

    Examples
    --------
    >>> p = focus_for_limits(24, 0.03, 1000, float("inf"))
    >>> round(p.distance_mm, 1), round(p.f_number, 2)
    (1975.7, 9.96)
    """
    from camtool.dof.inverse import focus_for_limits as run

    solution = run(focal_length_mm, coc_mm, near_mm, far_mm, distance_from)
    return FocusPlan(solution.distance_mm, solution.f_number)


@_checked
def focus_for_magnification(focal_length_mm: FocalLength, magnification: Magnification, *,
                            hiatus_mm: Number = 0.0) -> FocusGeometry:
    """Object and image distances in mm (and the sensor-plane focus distance) for a magnification m > 0.

    Examples
    --------
    >>> round(focus_for_magnification(100, 1.0).sensor_distance_mm)
    400
    """
    from camtool.geometry.thinlens import focus_for_magnification as run

    return run(focal_length_mm, magnification, hiatus_mm)


@_checked
def circle_of_confusion(sensor_width_mm: SensorSideReal, sensor_height_mm: SensorSideReal, rule: Text = "d/1500",
                        *, pixel_pitch_mm: PixelPitch = None) -> float:
    """The circle of confusion in mm from a rule (``d/1500``, ``d/1730``, ``px:2``, ``print:8x10in@25cm``).

    Examples
    --------
    >>> round(circle_of_confusion(36, 24), 4)
    0.0288
    """
    from camtool.core.units import UnitError
    from camtool.geometry.coc import coc_from_rule

    try:
        return coc_from_rule(rule, sensor_width_mm, sensor_height_mm, pixel_pitch_mm).coc_mm
    except UnitError as error:  # the rule could not be read
        raise DomainError("rule", _shown(rule), "d/N, px:K or print:WxH@DISTANCE", str(error)) from None


@_checked
def composition(focal_length_mm: FocalLength, magnification: Magnification, sensor_width_mm: SensorSide,
                sensor_height_mm: SensorSide, *, projection: Projection = "rectilinear",
                field_max_deg: OptionalFieldDeg = None) -> Composition:
    """Where to stand for a framing: the distance, field and angles at a magnification (see ``camtool compose``).

    A fisheye ``projection`` (at most ``field_max_deg``, 180° when None) gives the angles :func:`field_of_view`
    gives at that magnification and the fields 2u·tan(α/2); the distances are the thin lens's at the centre.

    Examples
    --------
    >>> c = composition(100, 0.02, 36, 24)  # u = f(1 + 1/m), v = f(1 + m), field = 36/m
    >>> c.lens_distance_mm, c.distance_mm, c.field_width_mm
    (5100.0, 5202.0, 1800.0)
    """
    from camtool.geometry.compose import composition as run
    from camtool.geometry.compose import fisheye_composition

    shot = run(focal_length_mm, magnification, sensor_width_mm, sensor_height_mm)
    if projection == "rectilinear":
        return shot
    return fisheye_composition(shot, sensor_width_mm, sensor_height_mm, projection, field_max_deg)


@_checked
def plan_exposure(
    *,
    ev100: OptionalNumber = None,
    f_number: OptionalNumber = None,
    shutter_s: OptionalNumber = None,
    iso: OptionalNumber = None,
    nd_stops: Number = 0.0,
    magnification: MagnificationOrZero = 0.0,
    pupil_magnification: PupilMagnification = 1.0,
) -> ExposurePlan:
    """A whole exposure: from a light level (EV100) and two settings, the third; or the EV100 of settings.

    Examples
    --------
    >>> p = plan_exposure(ev100=15, f_number=16, iso=100)  # t = N²/2^EV = 256/32768
    >>> round(1 / p.shutter_s)
    128
    """
    from camtool.exposure.plan import plan_exposure as run

    return run(ev100, f_number, shutter_s, iso, nd_stops, magnification, pupil_magnification)


@_checked
def star_trail_limits(focal_length_mm: FocalLength, f_number: FNumber, *, crop_factor: Crop = 1.0,
                      pixel_pitch_um: OptionalPixelPitchUm = None, declination_deg: Declination = 0.0,
                      rule_constant: Annotated[float, _Kind("number", scalar=True, bounds=(100.0, 1000.0))] = 500.0,
                      npf_k: Annotated[float, _Kind("number", scalar=True, bounds=(0.1, 10.0))] = 1.0) -> StarLimits:
    """The longest exposure in seconds before stars trail, as ``camtool stars`` gives it: the 500 rule and the NPF rule.

    ``rule500_s`` = constant/(f·crop); ``npf_simple_s`` and ``npf_s`` (F. Michaud's NPF rule) need the pixel
    pitch in µm and are None without it.

    Examples
    --------
    >>> s = star_trail_limits(24, 2.8, pixel_pitch_um=4.3)
    >>> round(s.rule500_s, 2), round(s.npf_s, 2)  # 500/24; (16.856·2.8 + 0.0997·24 + 13.713·4.3)/24
    (20.83, 4.52)
    """
    from camtool.exposure.stars import star_limits

    return star_limits(focal_length_mm, f_number, crop_factor, pixel_pitch_um, declination_deg, rule_constant, npf_k)


@_checked
def flash_exposure(*, guide_number_m: OptionalPositive = None, distance_mm: OptionalPositive = None,
                   f_number: OptionalFNumber = None, iso: OptionalISO = None, guide_number_iso: ISOReal = 100.0) -> Flash:
    """Give three of guide number (metres, quoted at ``guide_number_iso``), distance, f-number and ISO; get the fourth.

    As ``camtool flash``: GN = distance × N at the quoted ISO, × √(ISO/quoted) at another. The result's
    ``distance_m`` is in metres, like the guide number; exactly one of the four must be left out.

    Examples
    --------
    >>> round(flash_exposure(guide_number_m=40, f_number=8, iso=400).distance_m, 6)  # 40·√4/8
    10.0
    """
    from camtool.plans.flash import solve

    return solve(guide_number_m=guide_number_m, distance_mm=distance_mm, f_number=f_number, iso=iso,
                 quoted_iso=guide_number_iso)


@_checked
def equivalent_settings(focal_length_mm: FocalLength, f_number: FNumber, iso: ISO, *,
                        sensor_diagonal_mm: Diagonal, target_diagonal_mm: Diagonal = FULL_FRAME_DIAGONAL,
                        converter: Annotated[Any, _Kind("number", bounds=(0.1, 10.0))] = 1.0) -> Equivalent:
    """The same picture on another format, as ``camtool equiv``: focal length × r, f-number × r, ISO × r².

    r is the ratio of the diagonals (source over target; full frame's 43.27 mm by default).

    Examples
    --------
    >>> e = equivalent_settings(25, 1.4, 200, sensor_diagonal_mm=21.6)  # Micro Four Thirds: r = 43.27/21.6
    >>> round(e.focal_length_mm, 1), round(e.f_number, 2), round(e.iso)
    (50.1, 2.8, 802)
    """
    from camtool.exposure.equivalence import equivalent_settings as run

    return run(focal_length_mm, f_number, iso, sensor_diagonal_mm, target_diagonal_mm, converter)


@_checked
def film_time(film: Text, metered_s: ShutterTime) -> Any:
    """The exposure time in seconds a film needs for a metered time, with its reciprocity failure.

    ``film`` is a film preset's name (``camtool presets list --kind film``); below its threshold the metered
    time stands.

    Examples
    --------
    >>> film_time("hp5", 0.5)  # under a second: no correction (Ilford's HP5 Plus datasheet)
    0.5
    """
    from camtool.exposure.reciprocity import film_time_s, find_film

    try:
        chosen = find_film(film)
    except ValueError as error:
        raise DomainError("film", _shown(film), "a film preset's name", str(error)) from None
    return film_time_s(chosen, metered_s)


def _lens_with_preset(lens: str | None, pupil_magnification: Any, hiatus_mm: Any, prescription: Any,
                      focal_length_mm: Any, f_number: Any, distance_mm: Any = None,
                      distance_from: str = "sensor") -> tuple[LensData | None, Any, Any]:
    """The lens data for the ladder, the lens preset ``lens`` names and the focal length, as ``--lens`` gives them on
    the command line: the preset's pupil magnification, hiatus and prescription unless given
    (:func:`camtool.plans.equipment.lens_data`), a prime's focal length where none is given (:func:`_lens_preset`).
    """
    preset_lens, focal_length_mm = _lens_preset(lens, focal_length_mm, f_number, distance_mm, distance_from)
    if preset_lens is None:
        return _lens(pupil_magnification, hiatus_mm, prescription, focal_length_mm), None, focal_length_mm
    from camtool.plans.equipment import lens_data

    _focal_or_prescription(focal_length_mm,
                           prescription if prescription is not None else getattr(preset_lens, "prescription", None))
    return lens_data(pupil_magnification=pupil_magnification, hiatus_mm=hiatus_mm, prescription=prescription,
                     lens_preset=preset_lens), preset_lens, focal_length_mm


def _lens_preset(lens: str | None, focal_length_mm: Any, f_number: Any, distance_mm: Any = None,
                 distance_from: str = "sensor") -> tuple[Any, Any]:
    """The lens preset ``lens`` names (None for None) and the focal length, as ``--lens`` applies it on the command
    line (:func:`camtool.plans.equipment.apply_equipment`'s steps): a lens set's member at the focal length given, a
    prime's focal length where none is given (unless its prescription gives one), and the lens's own ranges holding
    every focal length, f-number and focus distance given (:func:`camtool.plans.equipment.check_lens`)."""
    if lens is None:
        return None, focal_length_mm
    from camtool.plans import equipment

    def values(given: Any) -> list[float]:
        return [] if given is None else list(map(float, getattr(given, "ravel", lambda: [given])()))

    found = equipment.set_member(preset("lens", lens), focal_lengths=values(focal_length_mm))
    if focal_length_mm is None and getattr(found, "prescription", None) is None:
        focal_length_mm = equipment.lens_defaults(found, focal_lengths=[], f_numbers=values(f_number))["focal_length"]
    equipment.check_lens(found, focal_lengths=values(focal_length_mm), f_numbers=values(f_number),
                         distances_mm=values(distance_mm), distance_from=distance_from)
    return found, focal_length_mm


@_checked
def preset(kind: Annotated[str, _Kind("choice", choices=PRESET_KINDS)], name: Text) -> Any:
    """The preset of ``kind`` called ``name`` (any spelling of its id or aliases), from the shipped database and the
    user's files, as the command line finds it.

    An unknown name raises :class:`~camtool.core.errors.DomainError` on ``name``, with the closest names.

    Examples
    --------
    >>> lens = preset("lens", "NIKKOR Z 24mm f/1.8 S")  # its name as Nikon writes it
    >>> lens.id, lens.focal_min_mm, lens.f_number_min
    ('nikon-z-24mm-f1.8-s', 24.0, 1.8)
    """
    from camtool.presets import PresetNotFound, load_db

    try:
        return load_db().get(kind, name)
    except PresetNotFound as error:
        raise DomainError("name", _shown(name), f"the name of a {kind} preset", str(error)) from None


@_checked
def preset_names(kind: Annotated[str, _Kind("choice", choices=PRESET_KINDS)]) -> list[str]:
    """The ids of every preset of ``kind``, as ``camtool presets list --kind KIND`` lists them.

    Examples
    --------
    >>> "full-frame" in preset_names("sensor")
    True
    """
    from camtool.presets import load_db

    return load_db().names(kind)


@_checked
def tilt(
    focal_length_mm: RealFocalLength,
    f_number: OptionalRealFNumber,
    coc_mm: RealCoC,
    *,
    tilt_deg: OptionalAngle = None,
    swing_deg: OptionalAngle = None,
    hinge_mm: OptionalDistance = None,
    points: Points = None,
    focus_mm: OptionalDistanceOrInf = None,
    image_distance_mm: OptionalDistance = None,
    hyperfocal: Flag = False,
    at_mm: OptionalDistance = None,
    half_depth_mm: OptionalDistance = None,
    optimum: Flag = False,
    model: TiltModel = "auto",
    along: Along = "sight",
    angles_from: AnglesFrom = "film",
    hinge_from: HingeFrom = "lens",
    distance_from: DistanceFrom = "sensor",
    sensor_height_mm: SensorSideReal = 24.0,
    pupil_magnification: OptionalPupilMagnification = None,
    hiatus_mm: OptionalReal = None,
    prescription: OptionalPrescription = None,
) -> TiltAnswer:
    """Tilt or swing, as ``camtool tilt``: the hinge, the plane of sharp focus and the depth-of-field wedge.

    One of ``tilt_deg``, ``swing_deg``, ``hinge_mm`` or two ``points`` ((distance, height) in mm) sets the
    movement; ``focus_mm``, ``image_distance_mm``, ``hyperfocal`` or the two points set the focus; ``at_mm``
    gives the wedge's extent there, ``half_depth_mm`` the f-number it needs (``f_number`` may then be None),
    ``optimum`` the f-number that balances it against diffraction. The conventions (``along``,
    ``angles_from``, ``hinge_from``, ``distance_from``) are those of the command (docs/tilt.md). Returns the
    plan's :class:`~camtool.plans.tilt.TiltAnswer`: one ``TiltRow`` per model, and the words for the footer.

    Examples
    --------
    >>> row = tilt(90, 11, 0.03, tilt_deg=3, focus_mm=2000).rows[0]
    >>> round(row.hinge_mm, 1)  # Merklinger's hinge rule J = f/sin θ = 90/sin 3°
    1719.7
    """
    from camtool.plans.tilt import solve_tilt

    def listed(value: Any) -> list[float]:
        return [] if value is None else [float(value)]

    data = _lens(pupil_magnification, hiatus_mm, prescription, focal_length_mm)
    return solve_tilt(focal_length_mm=listed(focal_length_mm), f_number=listed(f_number), coc_mm=[coc_mm],
                      tilt_deg=listed(tilt_deg), swing_deg=listed(swing_deg), hinge_mm=listed(hinge_mm),
                      points=points or (), focus_mm=listed(focus_mm), image_distance_mm=listed(image_distance_mm),
                      hyperfocal=hyperfocal, at_mm=at_mm, half_depth_mm=half_depth_mm, optimum=optimum,
                      sensor_height_mm=sensor_height_mm, distance_from=distance_from, along=along,
                      angles_from=angles_from, hinge_from=hinge_from, model=model, lens=data)


@_checked
def photo(
    path: Text,
    *,
    distance_mm: OptionalDistanceOrInf = None,
    coc_mm: OptionalCoC = None,
    coc_rule: OptionalRule = None,
    pixel_pitch_mm: PixelPitch = None,
    sensor_width_mm: OptionalSensorSide = None,
    sensor_height_mm: OptionalSensorSide = None,
    distance_from: DistanceFrom = "sensor",
    model: Model = "auto",
    lens: OptionalText = None,
) -> PhotoAnswer:
    """What a photo's metadata says and the depth of field, field of view and exposure it gives, as ``camtool exif``.

    Needs the ``exif`` extra (python-exiv2). Every number read from a tag passes the range of the option it
    stands for or is left out and named in the answer's ``unusable`` problems; a file that cannot be read
    (not a regular file, not an image) raises :class:`~camtool.core.errors.FileError`. What is given here wins
    over what the file says (``lens`` names a lens preset). The answer's ``values`` hold every key of
    ``camtool exif --format json``.
    """
    from camtool.core.errors import FileError
    from camtool.exif.reader import UnreadableFile, read_file
    from camtool.plans.photo import PresetIndex, photo_answer
    from camtool.presets import load_db

    if (sensor_width_mm is None) != (sensor_height_mm is None):
        raise DomainError("sensor_height_mm" if sensor_height_mm is None else "sensor_width_mm", None,
                          "given with the other side of the sensor, or both left out")
    lens_preset = preset("lens", lens) if lens is not None else None
    try:
        reading = read_file(path)
    except (FileError, UnreadableFile) as error:
        raise DomainError("path", _shown(path), "a readable image file", str(error)) from None
    sensor = None if sensor_width_mm is None else (float(sensor_width_mm), float(sensor_height_mm))
    return photo_answer(reading, path=path, distance_mm=distance_mm, sensor_mm=sensor, coc_mm=coc_mm,
                        coc_rule=coc_rule, pixel_pitch_mm=pixel_pitch_mm, distance_from=distance_from, model=model,
                        lens_preset=lens_preset, presets=PresetIndex(load_db))


@_checked
def rail_stack(depth_mm: RealDistance, f_number: RealFNumber, magnification: RealMagnification, coc_mm: RealCoC, *,
               criterion: Criterion = None, overlap: Overlap = 0.2, pupil_magnification: RealPupilMagnification = 1.0,
               wavelength_nm: RealWavelength = 550.0, focal_length_mm: RealFocalLength = None,
               diffraction: Flag = False) -> RailStack:
    """A focus stack on a macro rail, as ``camtool stack -m M --depth D``: how many frames and the rail step.

    The criterion is ``wave`` (the wave-optics depth) from 1:1 up unless named; the plan's ``frames`` and
    ``plan.step_mm`` are the answer (``camtool.plans.stack.rail_rows`` gives every frame, a chunk at a time).

    Examples
    --------
    >>> s = rail_stack(10.0, 8.0, 1.0, 0.03, criterion="classic", overlap=0.0)
    >>> s.frames, round(s.plan.step_mm, 4)  # the classic depth at 1:1, 2·N·c·(1 + m)/m² = 0.96 mm a frame
    (11, 0.96)
    """
    from camtool.plans.stack import rail_stack as plan

    return plan(depth_mm=depth_mm, f_number=f_number, magnification=magnification, coc_mm=coc_mm, criterion=criterion,
                overlap=overlap, pupil_magnification=pupil_magnification, wavelength_nm=wavelength_nm,
                focal_length_mm=focal_length_mm, diffraction=diffraction)


@_checked
def bracket_stack(focal_length_mm: RealFocalLength, f_number: RealFNumber, coc_mm: RealCoC, near_mm: RealDistance,
                  far_mm: RealDistanceOrInf, *, overlap: Overlap = 0.2, criterion: Criterion = None,
                  model: Model = "auto", distance_from: DistanceFrom = "sensor",
                  pupil_magnification: OptionalPupilMagnification = None, hiatus_mm: OptionalReal = None,
                  prescription: OptionalPrescription = None, lens: OptionalText = None) -> BracketStack:
    """Focus distances that cover ``near_mm`` to ``far_mm`` by the focus ring, as ``camtool stack --near --far``.

    Each frame's far limit meets the next frame's near limit (less ``overlap``); a bracket to infinity ends
    at the hyperfocal distance :func:`hyperfocal_distance` gives for the same lens, model and CoC. ``lens``
    names a lens preset (one that focuses internally is bracketed at its own focal length per frame).

    Examples
    --------
    >>> s = bracket_stack(24, 11, 0.03, 500, float("inf"), overlap=0.0, distance_from="lens")
    >>> len(s.frames), s.frames[-1].distance_mm == 24 ** 2 / (11 * 0.03) + 24  # ends at H = f²/(Nc) + f
    (2, True)
    """
    from camtool.plans.stack import bracket_stack as plan

    data, preset_lens, focal_length_mm = _lens_with_preset(lens, pupil_magnification, hiatus_mm, prescription,
                                                           focal_length_mm, f_number)
    pupil = data.pupil_magnification if data is not None and data.pupil_magnification is not None else 1.0
    return plan(focal_length_mm=focal_length_mm, f_number=f_number, coc_mm=coc_mm, near_mm=near_mm, far_mm=far_mm,
                overlap=overlap, criterion=criterion, model=model, lens=data, lens_preset=preset_lens,
                pupil_magnification=pupil, distance_from=distance_from, lens_name=lens)


ChartKind = Annotated[str, _Kind("choice", choices=("dof", "blur", "aperture", "trade", "card"))]
Units = Annotated[str, _Kind("choice", choices=("metric", "imperial"))]
OptionalFNumbers = Annotated[Any, _Kind("number", optional=True, bounds=F_NUMBER)]
OptionalFocalLengths = Annotated[Any, _Kind("number", optional=True, bounds=FOCAL_LENGTH_MM, unit="mm")]
OptionalDistances = Annotated[Any, _Kind("number", optional=True, allow_inf=True, bounds=DISTANCE_MM, unit="mm")]
OptionalFill = Annotated[Any, _Kind("number", scalar=True, optional=True, bounds=(0.0, 1.0))]
FillAxis = Annotated[str, _Kind("choice", choices=("height", "width"))]
Inches = Annotated[float, _Kind("number", scalar=True, bounds=CHART_SIDE_IN, unit="in")]
Dpi = Annotated[float, _Kind("number", scalar=True, bounds=CHART_DPI)]


def _listed(value: Any) -> list[float]:
    import numpy as np

    return [] if value is None else [float(v) for v in np.atleast_1d(np.asarray(value, dtype=float))]


@_checked
def chart(kind: ChartKind, *, coc_mm: RealCoC, focal_length_mm: OptionalFocalLengths = None,
          f_number: OptionalFNumbers = None, distance_mm: OptionalDistances = None,
          near_mm: OptionalDistance = None, far_mm: OptionalDistanceOrInf = None, model: Model = "auto",
          distance_from: DistanceFrom = "sensor", sensor_width_mm: SensorSideReal = 36.0,
          sensor_height_mm: SensorSideReal = 24.0, sensor_label: Text = "36 × 24 mm",
          magnification: OptionalPositive = None, subject_size_mm: OptionalDistance = None,
          fill: OptionalFill = None, fill_axis: FillAxis = "height", pupil_magnification: OptionalPupilMagnification = None,
          wavelength_nm: RealWavelength = 550.0, diffraction: Flag = False, units: Units = "metric") -> ChartData:
    """The numbers of a ``camtool chart KIND``: curves and marks in mm (draw them with :func:`save_chart`).

    ``dof`` takes focal lengths and f-numbers (lists or arrays) and plots near and far against the focus
    distance; ``blur`` background blur behind a subject (``magnification``, or ``subject_size_mm`` and
    ``fill``); ``aperture`` defocus and diffraction blur against f-number for a scene from ``near_mm`` to
    ``far_mm``; ``trade`` every rung's error against its time for one scene (``distance_mm``); ``card`` a
    printable card's cells (f-numbers across, ``distance_mm`` rows). The defaults and ranges are the
    command's (:mod:`camtool.plans.chart`).

    Examples
    --------
    50 mm f/8, c = 0.03 mm, 3 m from the lens: near 2337.9 mm, far 4185.3 mm (Wikipedia, "Depth of field"):

    >>> card = chart("card", coc_mm=0.03, focal_length_mm=50, f_number=8, distance_mm=3000, model="thin",
    ...              distance_from="lens")
    >>> [round(card.extra[k][0][0], 1) for k in ("near_mm", "far_mm")]
    [2337.9, 4185.3]
    """
    from camtool.plans import chart as plan

    focal, apertures, distances = _listed(focal_length_mm), _listed(f_number), _listed(distance_mm)
    if kind == "dof":
        from camtool.core.errors import InputError
        from camtool.core.errors import braced as _braced

        ends = {"low": "near_mm", "high": "far_mm"}  # the chart's range, as the plan (and --from/--to) names it
        try:
            return plan.dof_chart(focal_lengths_mm=focal, f_numbers=apertures or [8.0], coc_mm=coc_mm, model=model,
                                  distance_from=distance_from, diffraction=diffraction, wavelength_nm=wavelength_nm,
                                  from_mm=near_mm, to_mm=far_mm)
        except DomainError as error:
            if error.param not in ends:
                raise
            raise DomainError(ends[error.param], far_mm if error.param == "high" else near_mm, error.valid,
                              error.detail, error.limit) from None
        except InputError as error:
            if error.param not in ends:
                raise
            raise InputError(ends[error.param], _braced(error.render(lambda name: ends.get(name, name)))) from None
    if kind == "blur":
        return plan.blur_chart(f_numbers=apertures or [2.8], focal_lengths_mm=focal, magnification=magnification,
                               subject_size_mm=subject_size_mm, fill=fill, fill_axis=fill_axis,
                               sensor_width_mm=sensor_width_mm, sensor_height_mm=sensor_height_mm,
                               sensor_label=sensor_label)
    if kind == "aperture":
        return plan.aperture_chart(focal_length_mm=_one("focal_length_mm", focal), coc_mm=coc_mm, near_mm=near_mm,
                                   far_mm=far_mm, distance_from=distance_from,
                                   pupil_magnification=pupil_magnification, wavelength_nm=wavelength_nm)
    if kind == "trade":
        return plan.trade_chart(focal_length_mm=_one("focal_length_mm", focal), f_number=_one("f_number", apertures),
                                coc_mm=coc_mm, distance_mm=_one("distance_mm", distances), distance_from=distance_from,
                                diffraction=diffraction, wavelength_nm=wavelength_nm)
    return plan.card_chart(focal_length_mm=_one("focal_length_mm", focal), coc_mm=coc_mm, f_numbers=apertures,
                           distances_mm=distances, units=units, model=model, distance_from=distance_from)


def _one(name: str, values: list[float]) -> float:
    if len(values) != 1:
        raise DomainError(name, values or None, "one number for this chart")
    return values[0]


@_checked
def save_chart(data: Annotated[Any, _Kind("chart")], output: Text, *, width_in: Inches = 8.0, height_in: Inches = 5.0,
               dpi: Dpi = 150.0, units: Units = "metric") -> None:
    """Draw a :func:`chart`'s data to the file ``output`` (PNG, SVG or PDF by its extension), as ``camtool chart`` does.

    Needs matplotlib (the ``chart`` extra). The file carries no date, so the same data give the same bytes.
    """
    from camtool.core.errors import InputError
    from camtool.core.files import WriteProblem, check_writable, write_bytes
    from camtool.plans.chart import check_pixels, image_format
    from camtool.render import chartplot

    try:
        fmt = image_format(output=output, given=None)
    except InputError:
        raise DomainError("output", output, "a file name ending in .png, .svg or .pdf") from None
    if fmt == "png":
        check_pixels(size_in=(width_in, height_in), dpi=dpi)
    try:
        check_writable([output])
        write_bytes(output, chartplot.to_bytes(chartplot.draw(data, width_in, height_in, units), fmt, dpi))
    except WriteProblem as problem:
        raise DomainError("output", output, "a file that can be written", problem.problem) from None
@_checked
def rotary_shutter(*, fps: Annotated[Any, _Kind("number", bounds=FRAME_RATE_FPS, unit="fps")],
                   shutter_angle_deg: Annotated[Any, _Kind("number", optional=True, bounds=SHUTTER_ANGLE_DEG,
                                                           unit="°")] = None,
                   shutter_s: Annotated[Any, _Kind("number", optional=True, bounds=SHUTTER_RANGE_S, unit="s")] = None,
                   ) -> RotaryShutter:
    """A rotary shutter, as ``camtool exposure --shutter-angle --fps``: t = angle/(360·fps), or the angle of a time.

    Give ``fps`` and one of ``shutter_angle_deg`` and ``shutter_s`` (docs/cine.md §3).

    Examples
    --------
    >>> rotary_shutter(fps=24, shutter_angle_deg=180).shutter_s == 1 / 48   # Wikipedia, "Shutter speed"
    True
    """
    from camtool.plans.cine import rotary_shutter as run

    return run(fps=fps, shutter_angle_deg=shutter_angle_deg, shutter_s=shutter_s)


@_checked
def coc_map(depth_mm: DistanceOrInf, *, focus_mm: RealDistance, focal_length_mm: Annotated[
        float, _Kind("number", scalar=True, bounds=FOCAL_LENGTH_MM, unit="mm")], f_number: RealFNumber,
            coc_mm: RealCoC = 0.025, pupil_magnification: RealPupilMagnification = 1.0) -> CocMap:
    """The blur disc on the sensor (mm) of every depth of an array, as ``camtool cocmap``'s physical mode.

    Depths and the focus are distances from the entrance pupil (docs/cine.md §6): c = f²·|x − x_f|/(N·x·(x_f − f/P)).
    The result also has the share of depths within ``coc_mm`` and the depth of field's near and far limits.

    Examples
    --------
    >>> m = coc_map([2500.0, 5000.0, float("inf")], focus_mm=5000.0, focal_length_mm=50, f_number=2.0)
    >>> [round(float(c), 4) for c in m.coc_mm], round(m.near_limit_mm), round(m.far_limit_mm)
    ([0.2525, 0.0, 0.2525], 4550, 5549)
    """
    from camtool.plans.cocmap import coc_map as run

    return run(depth_mm=depth_mm, focus_mm=focus_mm, focal_length_mm=focal_length_mm, f_number=f_number,
               coc_mm=coc_mm, pupil_magnification=pupil_magnification)
@_checked
def pinhole(film_distance_mm: RealFilmDistance, *, subject_distance_mm: RealDistanceOrInf = math.inf,
            wavelength_nm: RealWavelength = 550.0, contrast_level: ContrastLevel = 0.5,
            sensor_width_mm: SensorSideReal = 36.0, sensor_height_mm: SensorSideReal = 24.0, ev100: EV100 = 15.0,
            iso: ISOReal = 100.0) -> PinholePlan:
    """The pinhole camera, as ``camtool pinhole``: the best diameter by contrast and the published rules beside it.

    ``rows`` holds the optimum (the diameter whose MTF reaches ``contrast_level`` at the highest frequency on
    the film) and the Airy, Rayleigh and Young rules, each with its f-number, blur, defocus in waves, the
    frequency at that contrast, the contrast at which it is itself best, the exposure time at ``ev100`` and
    ``iso`` and the angles of view (docs/wave.md).

    Examples
    --------
    >>> p = pinhole(100.0)
    >>> [row["method"] for row in p.rows]
    ['optimum', 'petzval', 'airy', 'rayleigh', 'young']
    >>> round(p.rows[3]["pinhole_mm"], 4)  # Rayleigh: 1.9·√(0.00055 mm × 100 mm)
    0.4456
    """
    from camtool.plans.pinhole import pinhole_plan

    return pinhole_plan(film_distance_mm=film_distance_mm, subject_distance_mm=subject_distance_mm,
                        wavelength_nm=wavelength_nm, level=contrast_level, sensor_width_mm=sensor_width_mm,
                        sensor_height_mm=sensor_height_mm, ev100=ev100, iso=iso)
