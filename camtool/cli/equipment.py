"""Resolve the equipment options (sensor, crop, CoC) into numbers for the formula core.

The preset database is loaded only when a preset is named: the default
sensor and an inline size such as ``36x24`` need no YAML at all.
"""

from __future__ import annotations

import math
import re
from typing import Any, NamedTuple

import click

from camtool.cli.options import param_named
from camtool.cli.params import flatten
from camtool.core.units import TStop, UnitError
from camtool.geometry.coc import DEFAULT_RULE, coc_from_rule

FULL_FRAME_DIAGONAL_MM = math.hypot(36.0, 24.0)
_SIDE = r"(\d+(?:\.\d*)?(?:[eE][+-]?\d+)?|\.\d+(?:[eE][+-]?\d+)?)\s*([a-zA-Zµ\"]*)"
_INLINE = re.compile(rf"^\s*{_SIDE}\s*[x×X*]\s*{_SIDE}\s*$")


class SensorChoice(NamedTuple):
    """The sensor in use: size in mm, a label for the footer, and preset extras."""

    width_mm: float
    height_mm: float
    label: str
    coc_mm: float | None = None
    pixel_pitch_mm: float | None = None

    @property
    def crop_factor(self) -> float:
        """Ratio of the 36 × 24 mm diagonal to this sensor's diagonal."""
        return FULL_FRAME_DIAGONAL_MM / math.hypot(self.width_mm, self.height_mm)


FULL_FRAME = SensorChoice(36.0, 24.0, "full frame 36 × 24 mm")


def open_presets(ctx: click.Context, preset_files: tuple[str, ...]) -> Any:
    """The preset database with the user's files, loaded once per command; a broken file exits 1."""
    if ctx.obj is not None and "db" in ctx.obj:
        return ctx.obj["db"]
    from camtool.presets import PresetFileError, load_db

    try:
        db = load_db(extra_files=tuple(preset_files))
    except PresetFileError as error:
        raise _preset_file_error(ctx, error, preset_files) from None
    if preset_files:  # ids and aliases that clash within the user's files: an error even when no preset is used
        from camtool.presets.schema import KINDS

        try:
            for kind in KINDS:
                db.names(kind)
        except PresetFileError as error:
            raise _preset_file_error(ctx, error, preset_files) from None
    ctx.ensure_object(dict)["db"] = db
    return db


def lookup(ctx: click.Context, kind: str, name: str, option: str, preset_files: tuple[str, ...]) -> Any:
    """Find a preset by name; an unknown name is a usage error on ``option`` with a suggestion."""
    from camtool.presets import PresetFileError, PresetNotFound

    db = open_presets(ctx, preset_files)
    try:
        return db.get(kind, name)
    except PresetNotFound as error:
        raise click.BadParameter(str(error), ctx=ctx, param=param_named(ctx, option)) from None
    except PresetFileError as error:
        raise _preset_file_error(ctx, error, preset_files) from None


def _preset_file_error(ctx: click.Context, error: Exception, preset_files: tuple[str, ...]) -> click.ClickException:
    """A broken preset file, exit 1: on ``--presets`` when it is one of the user's, else naming the file alone."""
    from camtool.cli.options import file_error

    if getattr(error, "path", None) in preset_files and param_named(ctx, "preset_files") is not None:
        return file_error(ctx, "preset_files", error)
    return click.ClickException(str(error))


def resolve_sensor(
    ctx: click.Context, sensor: str | None, crop: float | None, preset_files: tuple[str, ...] = ()
) -> SensorChoice:
    """The sensor named by ``--sensor`` (preset or WxH) or ``--crop``, else a fixed lens's own format, else
    ``--camera``'s; full frame when none is given."""
    if sensor is not None and crop is not None:
        raise click.UsageError("give --sensor or --crop, not both", ctx)
    if crop is not None:
        from camtool.core.ranges import CROP_FACTOR, describe

        if not CROP_FACTOR[0] <= crop <= CROP_FACTOR[1]:
            raise click.BadParameter(f"{crop:g} is outside the valid range: {describe(CROP_FACTOR)}", ctx=ctx,
                                     param=param_named(ctx, "crop"))
        w, h = 36.0 / crop, 24.0 / crop
        return SensorChoice(w, h, f"crop {crop:g} ({w:.4g} × {h:.4g} mm)")
    camera = ctx.meta.get(CAMERA)
    lens = ctx.meta.get(LENS)
    fixed = getattr(lens, "sensor_id", None)
    built_in = getattr(lens, "mount", None) == "fixed lens"
    if sensor is None and fixed is not None and (camera is None or built_in):
        # a lens's own format (the one it is made for) beats the full-frame default; a fixed or phone
        # lens's beats --camera too (a phone's other modules are not on the camera preset's main
        # sensor), while an interchangeable lens is on the body's sensor; --sensor beats both
        own = lookup(ctx, "sensor", fixed, "lens", preset_files)
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
    match = _INLINE.match(sensor)
    unitless = match is not None and not match.group(2) and not match.group(4)
    preset = _sensor_preset(ctx, sensor, preset_files, quiet=match is not None)
    if preset is not None:
        pitch = camera.pixel_pitch_mm if camera is not None else None
        label = f"{preset.name} {preset.width_mm:g} × {preset.height_mm:g} mm"
        sides = sorted((float(match.group(1)), float(match.group(3)))) if unitless and match else []
        if sides and sides != sorted((preset.width_mm, preset.height_mm)):
            label += f" (--sensor {sensor.strip()} is the preset; write {sensor.strip()}mm for a size in mm)"
        return SensorChoice(preset.width_mm, preset.height_mm, label, preset.coc_mm, pitch)
    if match is None:
        lookup(ctx, "sensor", sensor, "sensor", preset_files)  # raises the error with its suggestions
        raise AssertionError("unreachable")
    w, h = _side(ctx, sensor, match.group(1), match.group(2) or match.group(4)), \
        _side(ctx, sensor, match.group(3), match.group(4) or match.group(2))
    return SensorChoice(max(w, h), min(w, h), f"{max(w, h):g} × {min(w, h):g} mm")


def _sensor_preset(ctx: click.Context, name: str, preset_files: tuple[str, ...], quiet: bool) -> Any:
    """The sensor preset called ``name``, or None when there is none and ``quiet`` (an inline size)."""
    from camtool.presets import PresetNotFound

    if not quiet:
        return lookup(ctx, "sensor", name, "sensor", preset_files)
    db = open_presets(ctx, preset_files)
    try:
        return db.get("sensor", name)
    except PresetNotFound:
        return None


def _side(ctx: click.Context, sensor: str, number: str, unit: str) -> float:
    """One side of an inline sensor size in mm (a bare number is mm), checked against its range."""
    from camtool.core.ranges import SENSOR_SIDE_MM, describe
    from camtool.core.units import parse_length

    try:
        mm = parse_length(number + (unit or ""), "mm")
    except UnitError as error:
        raise click.BadParameter(str(error), ctx=ctx, param=param_named(ctx, "sensor")) from None
    if not SENSOR_SIDE_MM[0] <= mm <= SENSOR_SIDE_MM[1]:
        raise click.BadParameter(f"{sensor} is outside the valid range: each side {describe(SENSOR_SIDE_MM, 'mm')}",
                                 ctx=ctx, param=param_named(ctx, "sensor"))
    return mm


def resolve_coc(
    ctx: click.Context, coc: list[float], rule: str | None, sensor: SensorChoice, pixel_pitch: list[float] | None
) -> tuple[list[float], str]:
    """The CoC values in mm and a footer note saying where they came from.

    Precedence: ``--coc`` > ``--coc-rule`` > the sensor preset's own CoC > d/1500.
    """
    if coc:
        return flatten(coc), "--coc"
    if rule is None and sensor.coc_mm is not None:
        return [sensor.coc_mm], f"{sensor.label} preset"
    pitch = pixel_pitch[0] if pixel_pitch else sensor.pixel_pitch_mm
    try:
        choice = coc_from_rule(rule or DEFAULT_RULE, sensor.width_mm, sensor.height_mm, pitch)
    except UnitError as error:
        text = str(error)
        if pitch is None and ctx.meta.get(CAMERA) is not None:  # the lens's own sensor is not the camera's
            text = text.replace("give --camera or --pixel-pitch",
                                "--camera's is its main sensor's, not this lens's; give --pixel-pitch")
        raise click.BadParameter(text, ctx=ctx, param=param_named(ctx, "coc_rule")) from None
    from camtool.core.ranges import COC_MM, describe

    if not COC_MM[0] <= choice.coc_mm <= COC_MM[1]:
        shown = rule or DEFAULT_RULE
        option = "coc_rule" if rule is not None else ("pixel_pitch" if pixel_pitch else "sensor")
        raise click.BadParameter(f"{shown} gives a CoC of {choice.coc_mm:.4g} mm, outside the valid range: "
                                 f"{describe(COC_MM, 'mm')}", ctx=ctx, param=param_named(ctx, option))
    return [choice.coc_mm], choice.origin



CAMERA, LENS = "camtool.camera", "camtool.lens"  # where the resolved presets are kept in ctx.meta

# Scene preset fields -> (command parameter, value for the parameter)
_SCENE_FIELDS = {
    "focal_length_mm": "focal_length", "f_number": "f_number", "distance_mm": "distance",
    "subject_size_mm": "subject_size", "background_mm": "background", "coc_mm": "coc",
    "magnification": "magnification",
}
_LIST_PARAMS = {"focal_length", "f_number", "distance", "coc", "magnification"}


def _empty(value: Any) -> bool:
    return value is None or (isinstance(value, (list, tuple)) and not value)


def apply_equipment(ctx: click.Context, params: dict[str, Any]) -> dict[str, Any]:
    """Resolve ``--scene``, ``--camera`` and ``--lens`` into the command's own parameters.

    A scene fills every parameter the user left empty (explicit options win);
    a camera supplies the sensor and pixel pitch; a lens supplies the focal
    length of a prime and is checked against the focal length, f-number and
    focus distance asked for. The resolved camera and lens are kept in
    ``ctx.meta`` for the sensor and lens-data helpers.
    """
    params = dict(params)
    scene_name, camera_name, lens_name = params.pop("scene", None), params.pop("camera", None), params.pop("lens", None)
    files = tuple(params.get("preset_files") or ())
    ctx.meta[CAMERA] = ctx.meta[LENS] = None
    if files:
        open_presets(ctx, files)  # a --presets file that cannot be read is an error even when no preset is used
    if scene_name:
        scene = lookup(ctx, "scene", scene_name, "scene", files)
        for field, name in _SCENE_FIELDS.items():
            value = getattr(scene, field, None)
            if value is not None and name in params and _empty(params[name]):
                option = param_named(ctx, name)
                if name in _LIST_PARAMS and option is not None and not getattr(option, "multiple", False):
                    params[name] = [value]  # a list option given once (exposure's --magnification)
                else:
                    params[name] = [[value]] if name in _LIST_PARAMS else value
        if scene.camera is not None and camera_name is None and _empty(params.get("sensor")):
            camera_name = scene.camera.id
        elif scene.sensor is not None and "sensor" in params and _empty(params.get("sensor")):
            params["sensor"] = scene.sensor.id
        if scene.lens is not None and lens_name is None:
            lens_name = scene.lens.id
    if camera_name:
        ctx.meta[CAMERA] = lookup(ctx, "camera", camera_name, "camera", files)
    if lens_name:
        lens = lookup(ctx, "lens", lens_name, "lens", files)
        ctx.meta[LENS] = lens
        _check_lens(ctx, lens, params)
    _check_hiatus(ctx, params)
    return params


def _check_hiatus(ctx: click.Context, params: dict[str, Any]) -> None:
    """A typed --hiatus must keep every distance positive, whichever model uses it.

    From the sensor the entrance pupil lies δ + v + f(1 − 1/P) in front of
    it; the smallest image distance v is f (focus at infinity), so δ must
    exceed −f(2 − 1/P). Retrofocus and telephoto designs reach several focal
    lengths, so |δ| is allowed up to :data:`camtool.core.ranges.HIATUS_FOCAL_LENGTHS` × f.
    """
    hiatus = params.get("hiatus")
    if hiatus is None or "focal_length" not in params:
        return
    from camtool.core.ranges import HIATUS_FOCAL_LENGTHS

    p = params.get("pupil_mag") or 1.0
    for f in flatten(params.get("focal_length")):
        low, high = -f * (2.0 - 1.0 / p), HIATUS_FOCAL_LENGTHS * f
        if not low < hiatus <= high:
            raise click.BadParameter(
                f"{hiatus:g} mm is outside the valid range: more than {low:.4g} mm (the entrance pupil in front of "
                f"the sensor) and at most {high:.4g} mm ({HIATUS_FOCAL_LENGTHS:g} × focal length) for f = {f:g} mm",
                ctx=ctx, param=param_named(ctx, "hiatus"))


def _check_lens(ctx: click.Context, lens: Any, params: dict[str, Any]) -> None:
    """Fill a prime's focal length; refuse a focal length, f-number or distance the lens cannot do."""
    if "focal_length" in params:
        focal = flatten(params["focal_length"])
        if not focal:
            if lens.is_zoom:
                raise click.UsageError(f"--lens {lens.id} is a zoom ({lens.focal_min_mm:g}–{lens.focal_max_mm:g} mm): "
                                       "give the focal length with -f", ctx)
            params["focal_length"] = [[lens.focal_min_mm]]
            focal = [lens.focal_min_mm]
        for f in focal:
            if not lens.focal_min_mm * 0.995 <= f <= lens.focal_max_mm * 1.005:
                span = (f"{lens.focal_min_mm:g}–{lens.focal_max_mm:g} mm" if lens.is_zoom
                        else f"{lens.focal_min_mm:g} mm")
                raise click.BadParameter(f"{f:g} mm is outside the valid range of --lens {lens.id}: {span}",
                                         ctx=ctx, param=param_named(ctx, "focal_length"))
    else:
        focal = [lens.focal_min_mm]
    for n in flatten(params.get("f_number")):
        if isinstance(n, TStop):
            _check_t_stop(ctx, lens, n)
            continue
        for f in focal:
            widest = lens.widest_f_number(f) or n
            # A preset without a smallest aperture (none published) bounds the f-number from below only.
            smallest = lens.smallest_f_number(f)
            slowest = smallest or n
            if not widest * 0.99 <= n <= slowest * 1.01:
                span = f"f/{widest:g} to f/{slowest:g}" if smallest else f"from f/{widest:g}"
                raise click.BadParameter(
                    f"f/{n:g} is outside the valid range of --lens {lens.id} at {f:g} mm: {span}",
                    ctx=ctx, param=param_named(ctx, "f_number"))
    if lens.min_focus_mm and params.get("distance_from", "sensor") == "sensor":
        for d in flatten(params.get("distance")):
            if d < lens.min_focus_mm:
                raise click.BadParameter(
                    f"{d / 1000:.4g} m is outside the valid range of --lens {lens.id}: at least its closest focus, "
                    f"{lens.min_focus_mm / 1000:.4g} m from the sensor", ctx=ctx, param=param_named(ctx, "distance"))


def _check_t_stop(ctx: click.Context, lens: Any, t: float) -> None:
    """Refuse a T-stop below the lens's widest T-stop (or its widest f-number: T is never below N)."""
    widest = lens.t_number_min or lens.f_number_min
    if widest is not None and t < widest * 0.99:
        span = f"T{widest:g}" if lens.t_number_min else f"f/{widest:g} (a T-stop is never below the f-number)"
        raise click.BadParameter(f"T{t:g} is outside the valid range of --lens {lens.id}: from {span}",
                                 ctx=ctx, param=param_named(ctx, "f_number"))
