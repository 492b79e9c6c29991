"""Equipment resolution: which sensor, which circle of confusion and why, and what a lens allows.

Every command that takes ``--scene``, ``--camera``, ``--lens``, ``--sensor``,
``--crop``, ``--coc``, ``--coc-rule`` or ``--pixel-pitch`` (and the Python
API) asks these functions; the precedence rules live here and nowhere else:

- **sensor**: ``sensor`` (a preset name or an inline ``WxH``) or ``crop`` >
  a fixed or phone lens's own format > the camera's sensor > an
  interchangeable lens's own format > full frame 36 × 24 mm;
- **CoC**: ``coc`` > ``coc_rule`` > the sensor preset's own CoC > ``cine`` (0.025 mm) for a
  camera preset of the ``cine`` category > d/1500,
  with the pixel pitch from ``pixel_pitch`` or else the camera's;
- **scene**: a scene preset fills every input left empty (what is given wins),
  and brings its camera (unless a sensor is given) and lens;
- **lens**: a prime's focal length and a single-aperture lens's f-number fill
  what is left empty; focal lengths, f-numbers and focus distances outside
  what the lens does are refused;
- **squeeze**: ``squeeze`` given > an anamorphic lens preset's ``squeeze`` >
  none (spherical); a squeeze given is checked against the one bound either way.

The preset database is opened only when a preset is named (``database`` is
called then): the default sensor and an inline size need no YAML at all.
Errors are :class:`~camtool.core.errors.InputError` (or ``DomainError`` and
``PresetNotFound``) naming the input by its parameter name; the command line
spells it as the option, the API as the argument.
"""

from __future__ import annotations

import math
import re
from collections.abc import Callable, Sequence
from typing import Any

from camtool.core.errors import DomainError, InputError, braced
from camtool.core.record import NamedTuple
from camtool.core.units import TStop, UnitError
from camtool.geometry.coc import CINE_RULE, DEFAULT_RULE, coc_from_rule

FULL_FRAME_DIAGONAL_MM = math.hypot(36.0, 24.0)
_SIDE = r"(\d+(?:\.\d*)?(?:[eE][+-]?\d+)?|\.\d+(?:[eE][+-]?\d+)?)\s*([a-zA-Zµ\"]*)"
_INLINE = rf"^\s*{_SIDE}\s*[x×X*]\s*{_SIDE}\s*$"  # compiled on first use (re's cache)

Database = Callable[[], Any]
"""A function returning the preset database, called only when a preset is named."""


class SensorChoice(NamedTuple):
    """The sensor in use: size in mm, a label for the footer, and preset extras."""

    width_mm: float
    height_mm: float
    label: str
    coc_mm: float | None = None
    pixel_pitch_mm: float | None = None

    @property
    def diagonal_mm(self) -> float:
        """The sensor's diagonal."""
        return math.hypot(self.width_mm, self.height_mm)

    @property
    def crop_factor(self) -> float:
        """Ratio of the 36 × 24 mm diagonal to this sensor's diagonal.

        >>> round(SensorChoice(23.5, 15.6, "APS-C").crop_factor, 4)
        1.5339
        """
        return FULL_FRAME_DIAGONAL_MM / self.diagonal_mm


FULL_FRAME = SensorChoice(36.0, 24.0, "full frame 36 × 24 mm")


class CocChoice(NamedTuple):
    """The circles of confusion in mm (one per value given, else one) and where they came from."""

    coc_mm: list[float]
    origin: str


def find(database: Database, kind: str, name: str, param: str) -> Any:
    """The preset of ``kind`` called ``name``; an unknown name is ``PresetNotFound`` naming input ``param``."""
    from camtool.presets import PresetNotFound

    try:
        return database().get(kind, name)
    except PresetNotFound as error:
        error.param = param
        raise


def resolve_sensor(*, sensor: str | None = None, crop: float | None = None, camera: Any = None, lens: Any = None,
                   database: Database) -> SensorChoice:
    """The sensor in use, by the precedence in the module docstring.

    >>> resolve_sensor(crop=2.0, database=lambda: None)
    SensorChoice(width_mm=18.0, height_mm=12.0, label='crop 2 (18 × 12 mm)', coc_mm=None, pixel_pitch_mm=None)
    >>> resolve_sensor(sensor="36x24", database=lambda: _NoSensors())
    SensorChoice(width_mm=36.0, height_mm=24.0, label='36 × 24 mm', coc_mm=None, pixel_pitch_mm=None)
    """
    if sensor is not None and crop is not None:
        raise InputError("crop", "give {sensor} or {crop}, not both", usage=True)
    if crop is not None:
        from camtool.core.ranges import CROP_FACTOR, describe

        if not CROP_FACTOR[0] <= crop <= CROP_FACTOR[1]:
            raise DomainError("crop", crop, describe(CROP_FACTOR))
        w, h = 36.0 / crop, 24.0 / crop
        return SensorChoice(w, h, f"crop {crop:g} ({w:.4g} × {h:.4g} mm)")
    fixed = getattr(lens, "sensor_id", None)
    built_in = getattr(lens, "mount", None) == "fixed lens"
    own_lens = camera is not None and lens is not None and getattr(camera, "lens_id", None) == lens.id
    if sensor is None and fixed is not None and (camera is None or built_in) and not own_lens:
        # a lens's own format (the one it is made for) beats the full-frame default; a fixed or phone
        # lens's beats the camera's too (a phone's other modules are not on the camera preset's main
        # sensor), while an interchangeable lens is on the body's sensor; a sensor given beats both
        own = find(database, "sensor", fixed, "lens")
        same = camera is not None and camera.sensor.id == own.id
        return SensorChoice(own.width_mm, own.height_mm,
                            f"{own.name} {own.width_mm:g} × {own.height_mm:g} mm (the lens's own format)", own.coc_mm,
                            camera.pixel_pitch_mm if same and camera is not None else None)
    if sensor is None and camera is not None:
        body = camera.sensor
        return SensorChoice(body.width_mm, body.height_mm, f"{camera.name} ({body.width_mm:g} × {body.height_mm:g} mm)",
                            body.coc_mm, camera.pixel_pitch_mm)
    if sensor is None:
        return FULL_FRAME
    match = re.match(_INLINE, sensor)
    unitless = match is not None and not match.group(2) and not match.group(4)
    preset = _sensor_preset(database, sensor, quiet=match is not None)
    if preset is not None:
        pitch = camera.pixel_pitch_mm if camera is not None else None
        label = f"{preset.name} {preset.width_mm:g} × {preset.height_mm:g} mm"
        sides = sorted((float(match.group(1)), float(match.group(3)))) if unitless and match else []
        if sides and sides != sorted((preset.width_mm, preset.height_mm)):
            label += f" (--sensor {sensor.strip()} is the preset; write {sensor.strip()}mm for a size in mm)"
        return SensorChoice(preset.width_mm, preset.height_mm, label, preset.coc_mm, pitch)
    assert match is not None  # a name that is no preset raised above
    w = _side(sensor, match.group(1), match.group(2) or match.group(4))
    h = _side(sensor, match.group(3), match.group(4) or match.group(2))
    return SensorChoice(max(w, h), min(w, h), f"{max(w, h):g} × {min(w, h):g} mm")


class _NoSensors:
    """A database with no sensor presets (for the doctest of an inline size)."""

    def get(self, kind: str, name: str) -> Any:
        from camtool.presets import PresetNotFound

        raise PresetNotFound(kind, name)


def _sensor_preset(database: Database, name: str, quiet: bool) -> Any:
    """The sensor preset called ``name``, or None when there is none and ``quiet`` (an inline size)."""
    from camtool.presets import PresetNotFound

    if not quiet:
        return find(database, "sensor", name, "sensor")
    try:
        return database().get("sensor", name)
    except PresetNotFound:
        return None


def _side(sensor: str, number: str, unit: str) -> float:
    """One side of an inline sensor size in mm (a bare number is mm), checked against its range."""
    from camtool.core.ranges import SENSOR_SIDE_MM, describe
    from camtool.core.units import parse_length

    try:
        mm = parse_length(number + (unit or ""), "mm")
    except UnitError as error:
        raise InputError("sensor", braced(str(error))) from None
    if not SENSOR_SIDE_MM[0] <= mm <= SENSOR_SIDE_MM[1]:
        raise DomainError("sensor", sensor, f"each side {describe(SENSOR_SIDE_MM, 'mm')}")
    return mm


def pixel_pitches(given_mm: Sequence[float], sensor: SensorChoice) -> list[float]:
    """The pixel pitches in mm: those given, else the camera's (through the sensor in use), else none."""
    if given_mm:
        return list(given_mm)
    return [sensor.pixel_pitch_mm] if sensor.pixel_pitch_mm is not None else []


def resolve_coc(*, coc: Sequence[float] = (), coc_rule: str | None = None, sensor: SensorChoice,
                pixel_pitch_mm: Sequence[float] | None = None, camera: Any = None) -> CocChoice:
    """The CoC values in mm and where they came from (the precedence in the module docstring).

    >>> resolve_coc(sensor=FULL_FRAME)
    CocChoice(coc_mm=[0.028844410203711916], origin='d/1500 of 43.3 mm')
    >>> resolve_coc(coc=[0.03], sensor=FULL_FRAME).origin
    '--coc'
    """
    if coc:
        return CocChoice(list(coc), "--coc")
    if coc_rule is None and sensor.coc_mm is not None:
        return CocChoice([sensor.coc_mm], f"{sensor.label} preset")
    if coc_rule is None and getattr(camera, "category", None) == "cine":
        coc_rule = CINE_RULE
    pitch = next(iter(pixel_pitches(pixel_pitch_mm or [], sensor)), None)
    try:
        choice = coc_from_rule(coc_rule or DEFAULT_RULE, sensor.width_mm, sensor.height_mm, pitch)
    except UnitError as error:
        text = str(error)
        if pitch is None and camera is not None:  # the lens's own sensor is not the camera's
            text = text.replace("give --camera or --pixel-pitch",
                                "--camera's is its main sensor's, not this lens's; give --pixel-pitch")
        raise InputError("coc_rule", braced(text)) from None
    from camtool.core.ranges import COC_MM, describe

    if not COC_MM[0] <= choice.coc_mm <= COC_MM[1]:
        shown = coc_rule or DEFAULT_RULE
        param = "coc_rule" if coc_rule is not None else ("pixel_pitch" if pixel_pitch_mm else "sensor")
        raise InputError(param, braced(f"{shown} gives a CoC of {choice.coc_mm:.4g} mm, outside the valid range: "
                                        f"{describe(COC_MM, 'mm')}"))
    return CocChoice([choice.coc_mm], choice.origin)


SCENE_FIELDS = {
    "focal_length_mm": "focal_length", "f_number": "f_number", "distance_mm": "distance",
    "subject_size_mm": "subject_size", "background_mm": "background", "coc_mm": "coc",
    "magnification": "magnification",
}
"""Scene preset fields -> the input each one fills."""


class Equipment(NamedTuple):
    """The presets in use: a scene's values for the inputs left empty, its camera, lens and sensor name."""

    filled: dict[str, Any]
    camera: Any
    lens: Any
    sensor: str | None


def resolve_equipment(*, scene: str | None = None, camera: str | None = None, lens: str | None = None,
                      empty: Sequence[str] = (), sensor_given: bool = True, prescription_given: bool = False,
                      database: Database) -> Equipment:
    """The scene, camera and lens presets named, and what the scene fills.

    ``empty`` are the inputs left empty that this command has (a scene
    fills only those); ``sensor_given`` is whether a sensor was given (a
    scene's camera is then not used, nor its sensor); a camera's own lens is
    in use when no lens is named and no prescription given (a prescription
    is the lens then). A camera with a lens
    of its own (a compact's, a phone's main module) brings that lens when no
    lens is named; a lens named, or a scene's, wins.
    """
    filled: dict[str, Any] = {}
    sensor_name = None
    if scene:
        preset = find(database, "scene", scene, "scene")
        for field, name in SCENE_FIELDS.items():
            value = getattr(preset, field, None)
            if value is not None and name in empty:
                filled[name] = value
        if preset.camera is not None:  # the scene's sensor is its camera's: a camera or sensor given wins over both
            if camera is None and not sensor_given:
                camera = preset.camera.id
        elif preset.sensor is not None and not sensor_given:
            sensor_name = preset.sensor.id
        if preset.lens is not None and lens is None:
            lens = preset.lens.id
    body = find(database, "camera", camera, "camera") if camera else None
    if lens:
        glass = find(database, "lens", lens, "lens")
    elif body is not None and getattr(body, "lens_id", None) is not None and not prescription_given:
        glass = find(database, "lens", body.lens_id, "camera")
    else:
        glass = None
    return Equipment(filled, body, glass, sensor_name)


def set_member(lens: Any, *, focal_lengths: Sequence[float]) -> Any:
    """The lens in use: a lens set's member at the one focal length given, any other lens as it is.

    A set (a cine prime set, ``lens_db/README.md``) is one preset holding each
    of its focal lengths; ``--lens SET -f 50`` picks its 50 mm, as does the
    name ``SET@50``. No focal length, one the set does not have, or several
    (each would be another lens) are refused, naming the members.
    """
    members = getattr(lens, "members", ())
    if not members:
        return lens
    names = ", ".join(f"{m.focal_min_mm:g}" for m in members)
    wanted = sorted(set(focal_lengths))
    if len(wanted) != 1:
        what = "is a set of lenses" if not wanted else "is a set of lenses, one per focal length"
        raise InputError("focal_length", f"{{lens}} {lens.id} {what} ({names} mm): give one focal length with "
                                         f"{{focal_length}}, or name the member, as {members[0].id}", usage=True)
    found = lens.member(wanted[0])
    if found is None:
        raise InputError("focal_length", f"{wanted[0]:g} mm is not in the set {{lens}} {lens.id}: {names} mm")
    return found


def lens_squeeze(lens: Any, *, squeeze: float | None = None) -> float | None:
    """The anamorphic squeeze in use: ``squeeze`` given, else the ``lens`` preset's own, else None (spherical).

    A squeeze given wins over the preset's, as every value typed wins over a
    preset (``--squeeze 1`` asks an anamorphic lens for the spherical answer of
    its marked focal length); both are in the one range of ``--squeeze``,
    :data:`camtool.core.ranges.SQUEEZE` (docs/cine.md §5a).

    >>> from types import SimpleNamespace
    >>> orion = SimpleNamespace(squeeze=2.0)
    >>> lens_squeeze(orion), lens_squeeze(orion, squeeze=1.5), lens_squeeze(None), lens_squeeze(None, squeeze=1.3)
    (2.0, 1.5, None, 1.3)
    """
    from camtool.core.ranges import SQUEEZE, describe

    chosen = squeeze if squeeze is not None else getattr(lens, "squeeze", None)
    if chosen is not None and not SQUEEZE[0] <= chosen <= SQUEEZE[1]:
        raise DomainError("squeeze", chosen, describe(SQUEEZE))
    return chosen


def lens_defaults(lens: Any, *, focal_lengths: Sequence[float], f_numbers: Sequence[Any]) -> dict[str, float]:
    """What a lens brings that was left empty: a prime's focal length; a single-aperture lens's f-number, and a
    fixed (built-in) lens's widest.

    A zoom needs its focal length given. An interchangeable lens with a range
    of apertures needs the f-number given; a camera's built-in lens (a
    compact's, a phone's) answers wide open, where its depth of field is
    least, at the widest aperture every focal length asked for reaches.
    """
    out: dict[str, float] = {}
    if not focal_lengths:
        if lens.is_zoom:
            raise InputError("focal_length", f"{{lens}} {lens.id} is a zoom ({lens.focal_min_mm:g}–{lens.focal_max_mm:g} "
                                             "mm): give the focal length with {focal_length}", usage=True)
        out["focal_length"] = lens.focal_min_mm
    if f_numbers or lens.f_number_min is None:
        return out
    single = lens.f_number_max == lens.f_number_min and lens.f_number_max_tele in (None, lens.f_number_min)
    if single:
        out["f_number"] = lens.f_number_min  # a phone module or a fixed-aperture lens: one f-number
    elif lens.mount == "fixed lens":
        focal = list(focal_lengths) or [out.get("focal_length", lens.focal_min_mm)]
        out["f_number"] = max(lens.widest_f_number(f) or lens.f_number_min for f in focal)
    return out


def check_lens(lens: Any, *, focal_lengths: Sequence[float], f_numbers: Sequence[Any], distances_mm: Sequence[float],
               distance_from: str = "sensor", camera: Any = None) -> None:
    """Refuse a focal length, f-number (or T-stop) or focus distance the lens cannot do.

    ``camera``: the camera whose own lens this is, when no lens was named (the
    messages then name the camera, which is what was given).
    """
    own = camera is not None and getattr(camera, "lens_id", None) == lens.id
    who = f"{{camera}} {camera.id}'s lens" if own else f"{{lens}} {lens.id}"
    for f in focal_lengths:
        if not lens.focal_min_mm * 0.995 <= f <= lens.focal_max_mm * 1.005:
            span = f"{lens.focal_min_mm:g}–{lens.focal_max_mm:g} mm" if lens.is_zoom else f"{lens.focal_min_mm:g} mm"
            raise InputError("focal_length", f"{f:g} mm is outside the valid range of {who}: {span}")
    focal = list(focal_lengths) or [lens.focal_min_mm]
    for n in f_numbers:
        if isinstance(n, TStop):
            _check_t_stop(lens, n, who)
            continue
        for f in focal:
            widest = lens.widest_f_number(f) or n
            # A preset without a smallest aperture (none published) bounds the f-number from below only.
            smallest = lens.smallest_f_number(f)
            slowest = smallest or n
            if not widest * 0.99 <= n <= slowest * 1.01:
                span = f"f/{widest:g} to f/{slowest:g}" if smallest else f"from f/{widest:g}"
                raise InputError("f_number", f"f/{n:g} is outside the valid range of {who} at {f:g} mm: {span}")
    if lens.min_focus_mm and distance_from == "sensor":
        for d in distances_mm:
            if d < lens.min_focus_mm:
                raise InputError("distance", f"{d / 1000:.4g} m is outside the valid range of {who}: at least its "
                                             f"closest focus, {lens.min_focus_mm / 1000:.4g} m from the sensor")


def _check_t_stop(lens: Any, t: float, who: str) -> None:
    """Refuse a T-stop below the lens's widest T-stop (or its widest f-number: T is never below N)."""
    widest = lens.t_number_min or lens.f_number_min
    if widest is not None and t < widest * 0.99:
        span = f"T{widest:g}" if lens.t_number_min else f"f/{widest:g} (a T-stop is never below the f-number)"
        raise InputError("f_number", f"T{t:g} is outside the valid range of {who}: from {span}")


def check_hiatus(hiatus_mm: float | None, *, focal_lengths: Sequence[float], pupil_magnification: float | None) -> None:
    """A hiatus must keep every distance positive, whichever model uses it.

    From the sensor the entrance pupil lies δ + v + f(1 − 1/P) in front of
    it; the smallest image distance v is f (focus at infinity), so δ must
    exceed −f(2 − 1/P). Retrofocus and telephoto designs reach several focal
    lengths, so |δ| is allowed up to :data:`camtool.core.ranges.HIATUS_FOCAL_LENGTHS` × f.
    """
    if hiatus_mm is None:
        return
    from camtool.core.ranges import HIATUS_FOCAL_LENGTHS

    p = pupil_magnification or 1.0
    for f in focal_lengths:
        low, high = -f * (2.0 - 1.0 / p), HIATUS_FOCAL_LENGTHS * f
        if not low < hiatus_mm <= high:
            raise InputError("hiatus", f"{hiatus_mm:g} mm is outside the valid range: more than {low:.4g} mm (the "
                                       f"entrance pupil in front of the sensor) and at most {high:.4g} mm "
                                       f"({HIATUS_FOCAL_LENGTHS:g} × focal length) for f = {f:g} mm")


class Applied(NamedTuple):
    """What ``--scene``, ``--camera`` and ``--lens`` put in a command's inputs, and the presets in use."""

    values: dict[str, Any]  # input name -> the value a scene or a lens brings (one number for a list input)
    camera: Any
    lens: Any
    sensor: str | None  # a sensor preset's name the scene names, else None


LIST_INPUTS = frozenset({"focal_length", "f_number", "distance", "coc", "magnification"})
"""The inputs that take a list of values (a scene or a lens fills them with one)."""


def apply_equipment(*, scene: str | None, camera: str | None, lens: str | None, inputs: dict[str, Any],
                    database: Database) -> Applied:
    """Resolve the presets named into a command's ``inputs`` (its parameters by name, a list input flat).

    In this order: the scene fills the inputs left empty and names the camera
    and lens (:func:`resolve_equipment`); a lens set gives its member for the
    focal length (:func:`set_member`); an anamorphic lens its squeeze
    (:func:`lens_squeeze`); the lens brings its focal length and
    f-number where none is given (:func:`lens_defaults`) and refuses what it
    cannot do (:func:`check_lens`); then the hiatus is checked against the
    focal lengths (:func:`check_hiatus`). A refusal of a value the scene gave
    carries ``scene`` (the scene's name) on the :class:`InputError`.
    """
    def empty(name: str) -> bool:
        value = inputs.get(name)
        return value is None or (isinstance(value, (list, tuple)) and not value)

    found = resolve_equipment(scene=scene, camera=camera, lens=lens,
                              empty=[name for name in SCENE_FIELDS.values() if name in inputs and empty(name)],
                              sensor_given="sensor" not in inputs or not empty("sensor"),
                              prescription_given=inputs.get("prescription_file") is not None, database=database)
    values = dict(found.filled)
    now = {**inputs, **{name: [v] if name in LIST_INPUTS else v for name, v in values.items()}}
    has = {name: name in inputs for name in ("focal_length", "f_number")}
    glass = found.lens and set_member(found.lens, focal_lengths=now["focal_length"] if has["focal_length"] else [])
    if "squeeze" in inputs:  # an anamorphic lens brings its squeeze; a --squeeze typed wins
        squeeze = lens_squeeze(glass, squeeze=inputs["squeeze"])
        if squeeze != inputs["squeeze"]:
            values["squeeze"] = now["squeeze"] = squeeze
    if glass is not None:
        brought = lens_defaults(glass, focal_lengths=now["focal_length"] if has["focal_length"] else [glass.focal_min_mm],
                                f_numbers=now["f_number"] if has["f_number"] else [0])
        for name, value in brought.items():
            if name in inputs:
                values[name] = value
                now[name] = [value] if name in LIST_INPUTS else value
        try:
            check_lens(glass, focal_lengths=now["focal_length"] if has["focal_length"] else [],
                       f_numbers=now.get("f_number") or [], distances_mm=now.get("distance") or [],
                       distance_from=now.get("distance_from", "sensor"), camera=found.camera)
        except InputError as error:
            if error.param in found.filled:  # a value the scene gave, not one typed
                error.scene = scene  # type: ignore[attr-defined]
            raise
    if has["focal_length"]:
        check_hiatus(now.get("hiatus"), focal_lengths=now["focal_length"], pupil_magnification=now.get("pupil_mag"))
    return Applied(values, found.camera, glass, found.sensor)


PRESCRIPTION_MAX_BYTES = 1024 * 1024
"""Largest prescription file read (a 30-surface lens takes about 3 KB)."""


def lens_data(*, pupil_magnification: float | None = None, hiatus_mm: float | None = None,
              prescription: Any = None, lens_preset: Any = None, database: Database | None = None) -> Any:
    """The lens data for the model ladder (:class:`camtool.dof.ladder.LensData`), or None when nothing is known.

    Decides the precedence: a pupil magnification or hiatus given wins over
    the lens preset's; a prescription given (a validated optics prescription,
    a YAML file's path or a prescription preset's name, see
    :func:`load_prescription`) wins over the preset's own. None when neither
    the inputs nor the preset know anything beyond the focal length.

    >>> lens_data() is None
    True
    >>> lens_data(pupil_magnification=0.5).thick_parameters()
    (0.5, 0.0)
    """
    from camtool.dof.ladder import LensData

    p = pupil_magnification if pupil_magnification is not None else getattr(lens_preset, "pupil_magnification", None)
    delta = hiatus_mm if hiatus_mm is not None else getattr(lens_preset, "hiatus_mm", None)
    if isinstance(prescription, str):
        prescription = load_prescription(prescription, database=database)
    elif prescription is None:
        # validated once, when the preset was built: camtool.optics.prescription.Prescription
        prescription = getattr(lens_preset, "prescription", None)
    if p is None and delta is None and prescription is None:
        return None
    return LensData(pupil_magnification=p, hiatus_mm=delta, prescription=prescription)


def load_prescription(source: str, *, database: Database | None = None) -> Any:
    """The optics prescription in the YAML file ``source``, or that of the prescription preset named ``source``.

    A ``source`` that is no existing path, has no directory and does not end
    in ``.yaml``/``.yml`` is a preset name (``dgauss100``, ``nikon-z50-f1.8``),
    looked up in ``database()``. The file is read through the guarded reader.

    Raises
    ------
    camtool.core.files.FileProblem
        The file cannot be read or is not YAML.
    InputError
        On ``prescription``: the file is no valid prescription, or no preset has that name.
    """
    import os

    if not os.path.exists(source) and not os.path.dirname(source) and not source.endswith((".yaml", ".yml")):
        return _prescription_preset(source, database)
    from camtool.core.files import load_yaml, read_text
    from camtool.optics.prescription import PrescriptionError, prescription_from_mapping

    data, _ = load_yaml(read_text(source, PRESCRIPTION_MAX_BYTES), source)
    try:
        return prescription_from_mapping(data, source=source.rsplit("/", 1)[-1])
    except PrescriptionError as error:
        raise InputError("prescription", braced(str(error))) from None


def _prescription_preset(name: str, database: Database | None) -> Any:
    """The optics of the prescription preset called ``name``; an :class:`InputError` naming close names if none."""
    from camtool.presets import PresetNotFound, load_db

    db = (database or load_db)()
    try:
        return db.prescription(name).optics
    except PresetNotFound:
        close = db.suggestions("prescription", name)
    hint = f"; did you mean {', '.join(close)}?" if close else " (camtool presets list --kind prescription)"
    raise InputError("prescription", braced(f"no file or prescription preset is named {name!r}{hint}"))


class Apertures(NamedTuple):
    """The f-numbers depth of field uses for the apertures given, and how each was found when T-stops were given."""

    f_numbers: list[float]
    choices: list[Any] | None
    """One :class:`camtool.exposure.ev.FNumberChoice` per aperture when a T-stop was given (or ``t_stops``),
    else None: f-numbers alone add no keys and no footer note."""


def apertures(values: Sequence[float], *, exact_stops: bool = False, lens: Any = None,
              t_stops: bool = False) -> Apertures:
    """The f-number of each aperture given: an f-number as given, a T-stop (:class:`camtool.core.units.TStop`)
    as N = T·√τ with the transmittance τ of ``lens`` when the preset has both its widest f-number and T-stop,
    else the T-stop stands in for the f-number (:func:`camtool.exposure.ev.resolve_f_number`).

    ``exact_stops`` first maps each nominal value to the exact 2^(k/6) stop it
    labels (a T-stop stays a T-stop); ``t_stops`` keeps the choices even when
    no value is a T-stop (a --batch column that holds some).

    >>> from types import SimpleNamespace
    >>> from camtool.core.units import TStop
    >>> found = apertures([TStop(2 / 0.75 ** 0.5)], lens=SimpleNamespace(transmittance=0.75))
    >>> round(found.f_numbers[0], 12), found.choices[0].source   # f/2 at 75 % is T2.3 (Wikipedia, F-number)
    (2.0, 'transmittance')
    >>> apertures([5.6], exact_stops=True)
    Apertures(f_numbers=[5.656854249492381], choices=None)
    """
    from camtool.core.units import exact_f_number

    flat = list(values)
    if exact_stops:
        flat = [TStop(exact_f_number(n)) if isinstance(n, TStop) else exact_f_number(n) for n in flat]
    if not t_stops and TStop not in set(map(type, flat)):  # TStop has no subclass: its type is the test
        return Apertures(flat, None)
    from camtool.exposure.ev import resolve_f_number

    transmittance = getattr(lens, "transmittance", None) if lens is not None else None
    choices = [resolve_f_number(n, isinstance(n, TStop), transmittance) for n in flat]
    return Apertures([c.f_number for c in choices], choices)


def t_stop_rows(choices: Sequence[Any], *, row_f_numbers: Sequence[Any]) -> list[Any]:
    """Which choice of :func:`apertures` each output row shows (None for a row it cannot be told), from the row's
    f-number: the same f-number, or, when a command scaled every f-number (a teleconverter's k·N), the one in the
    same order; a single choice goes with every row.

    >>> from camtool.exposure.ev import resolve_f_number
    >>> t2, t4 = resolve_f_number(2.0, True), resolve_f_number(4.0, True)
    >>> [c.t_stop for c in t_stop_rows([t2, t4], row_f_numbers=[2.8, 5.6, 2.8])]  # ×1.4: in order
    [2.0, 4.0, 2.0]
    """
    by_n = {round(c.f_number, 9): c for c in choices}
    shown = list(dict.fromkeys(round(float(n or 0.0), 9) for n in row_f_numbers))
    if not set(shown) <= set(by_n) and len(shown) == len(choices):
        by_n = dict(zip(shown, choices))
    out = []
    for n in row_f_numbers:
        choice = by_n.get(round(float(n), 9)) if isinstance(n, (int, float)) else None
        if choice is None and len(by_n) == 1:
            choice = choices[0]
        out.append(choice)
    return out


class TStopNote(NamedTuple):
    """The facts a footer states about the T-stops given: the lens transmittance used, or the stand-in's bounds."""

    transmittance: float | None
    """τ from the lens preset (N = T·√τ, taken as constant when stopped down), or None: T stands in for N."""
    lens_id: str | None
    lens_f_number_min: float | None
    lens_t_number_min: float | None
    below_low: float
    """How far N lies below T for τ = 0.9 (1 − √0.9) ..."""
    below_high: float
    """... and for τ = 0.7 (1 − √0.7)."""
    overstated_low: float
    """How much a stand-in T overstates N for τ = 0.9 (1/√0.9 − 1) ..."""
    overstated_high: float
    """... and for τ = 0.7 (1/√0.7 − 1)."""


def t_stop_note(choices: Sequence[Any], *, lens: Any = None) -> TStopNote:
    """What the footer says of the T-stops: the transmittance of ``lens`` when any f-number came from it, else the
    range by which a T-stop standing in for the f-number overstates it (τ 0.9 to 0.7, typical of cine lenses).

    >>> from camtool.exposure.ev import resolve_f_number
    >>> note = t_stop_note([resolve_f_number(2.0, True)])
    >>> note.transmittance, round(note.below_low, 4), round(note.overstated_high, 4)  # 1 − √0.9, 1/√0.7 − 1
    (None, 0.0513, 0.1952)
    """
    from camtool.exposure.ev import T_STOP_ERROR_HIGH, T_STOP_ERROR_LOW

    over_low, over_high = 1 / (1 - T_STOP_ERROR_LOW) - 1, 1 / (1 - T_STOP_ERROR_HIGH) - 1
    tau = next((c.transmittance for c in choices if c.source == "transmittance" and c.transmittance is not None), None)
    if tau is None or lens is None:
        return TStopNote(None, None, None, None, T_STOP_ERROR_LOW, T_STOP_ERROR_HIGH, over_low, over_high)
    return TStopNote(tau, lens.id, lens.f_number_min, lens.t_number_min, T_STOP_ERROR_LOW, T_STOP_ERROR_HIGH,
                     over_low, over_high)


class ExposureApertures(NamedTuple):
    """The apertures ``camtool exposure`` uses: as given (T-stops used as they are), or a cine lens's widest T-stop."""

    f_numbers: list[float]
    t_stop: bool
    """Whether they are T-stops (then all are)."""
    widest_t_stop: float | None
    """The lens's widest T-stop when it was taken because no aperture was given, else None."""


def exposure_apertures(values: Sequence[float], *, lens: Any = None, exact_stops: bool = False,
                       solving: bool = False, equivalents: bool = False) -> ExposureApertures:
    """The apertures of an exposure: all f-numbers or all T-stops (a mix is refused, on ``f_number``); none given
    with a cine ``lens`` (one with a widest T-stop) is that lens wide open, unless ``equivalents`` are listed or
    the aperture is ``solving`` (solved from a light level, a time and an ISO). ``exact_stops`` maps each to the
    exact 2^(k/6) stop it labels.

    >>> from types import SimpleNamespace
    >>> exposure_apertures([], lens=SimpleNamespace(t_number_min=2.0))
    ExposureApertures(f_numbers=[2.0], t_stop=True, widest_t_stop=2.0)
    >>> round(exposure_apertures([22.0], exact_stops=True).f_numbers[0], 4)  # 2^(9/2)
    22.6274
    """
    from camtool.core.units import exact_f_number

    flat, widest = list(values), None
    if not flat and lens is not None and getattr(lens, "t_number_min", None) and not equivalents and not solving:
        widest = lens.t_number_min
        flat = [TStop(widest)]  # the lens wide open, as a cinematographer reads it
    t_stop = any(isinstance(n, TStop) for n in flat)
    if t_stop and not all(isinstance(n, TStop) for n in flat):
        raise InputError("f_number", "give all f-numbers or all T-stops, not a mix")
    numbers = [float(n) for n in flat]
    return ExposureApertures([exact_f_number(n) for n in numbers] if exact_stops else numbers, t_stop, widest)


class SolvedTStops(NamedTuple):
    """The T-stop to set for each solved f-number on a cine lens, and how it was found."""

    t_stops: Any
    """T = N/√τ (float or array, as the f-numbers), or None when the lens is not a cine lens."""
    note: str
    """What the footer says: the transmittance used, or that T stands in for N."""


def solved_t_stops(f_numbers: Any, *, lens: Any = None) -> SolvedTStops:
    """The T-stops a focus puller sets for f-numbers solved for a depth of field, on a cine lens (one whose preset
    gives its widest T-stop): T = N/√τ with the lens's transmittance τ = (f_number_min/t_number_min)², else T = N
    (an understatement of up to 1/√τ, as a T-stop standing in for N overstates it).

    >>> from types import SimpleNamespace
    >>> lens = SimpleNamespace(id="x", t_number_min=2.3, transmittance=0.75)
    >>> round(solved_t_stops(2.0, lens=lens).t_stops, 1)  # Wikipedia, F-number: f/2.0 at 75 % is T2.3
    2.3
    >>> solved_t_stops(2.0).t_stops is None
    True
    """
    if lens is None or getattr(lens, "t_number_min", None) is None:
        return SolvedTStops(None, "")
    tau = getattr(lens, "transmittance", None)
    if tau is None:
        return SolvedTStops(f_numbers, f"T-stop: N stands in (lens transmittance τ unknown; T is up to "
                                       f"{1 / math.sqrt(0.7) - 1:.0%} above N for τ ≥ 0.7)")
    from camtool.exposure.ev import t_stop

    return SolvedTStops(t_stop(f_numbers, tau), f"T-stop: T = N/√τ, τ = {tau:.3g} from --lens {lens.id}")
