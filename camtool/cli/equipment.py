"""The equipment options on the command line: ``--scene``, ``--camera``, ``--lens``, the sensor and the CoC.

Every decision (precedence, defaults, what a lens refuses) is made by
:mod:`camtool.plans.equipment`; this module opens the preset database once
per command (only when a preset is named), keeps the camera and lens in use
for the other helpers, and turns a plan's error into one line on the option
the user typed.
"""

from __future__ import annotations

import contextlib
import sys
from collections.abc import Iterator
from typing import Any

import click

from camtool.cli.options import param_named
from camtool.cli.params import flatten, one_value
from camtool.core.errors import DomainError, InputError
from camtool.plans import equipment
from camtool.plans.equipment import FULL_FRAME, SensorChoice

__all__ = ["CAMERA", "FULL_FRAME", "LENS", "SensorChoice", "apply_equipment", "input_errors", "lookup", "open_presets",
           "resolve_coc", "resolve_sensor"]


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
        from camtool.presets import KINDS

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
    """The sensor in use (:func:`camtool.plans.equipment.resolve_sensor` decides), errors on the option typed."""
    with input_errors(ctx, preset_files):
        return equipment.resolve_sensor(sensor=sensor, crop=crop, camera=ctx.meta.get(CAMERA), lens=ctx.meta.get(LENS),
                                        database=lambda: open_presets(ctx, preset_files))


def resolve_coc(
    ctx: click.Context, coc: list[float], rule: str | None, sensor: SensorChoice, pixel_pitch: list[float] | None
) -> tuple[list[float], str]:
    """The CoC values in mm and where they came from (:func:`camtool.plans.equipment.resolve_coc` decides)."""
    with input_errors(ctx, ()):
        choice = equipment.resolve_coc(coc=flatten(coc), coc_rule=rule, sensor=sensor, pixel_pitch_mm=pixel_pitch,
                                       camera=ctx.meta.get(CAMERA))
    return choice.coc_mm, choice.origin


@contextlib.contextmanager
def input_errors(ctx: click.Context, preset_files: tuple[str, ...]) -> Iterator[None]:
    """A plan's error as one line on the option typed: an unknown preset, a bad input, a broken preset file."""
    try:
        yield
    except Exception as error:
        if "camtool.presets" in sys.modules:  # a preset error can only come from the database once it is loaded
            from camtool.presets import PresetFileError, PresetNotFound

            if isinstance(error, PresetNotFound):
                raise click.BadParameter(str(error), ctx=ctx, param=param_named(ctx, error.param)) from None
            if isinstance(error, PresetFileError):
                raise _preset_file_error(ctx, error, preset_files) from None
        if isinstance(error, (InputError, DomainError)):
            from camtool.cli.options import bad_parameter

            raise bad_parameter(ctx, error) from None
        raise


CAMERA, LENS = "camtool.camera", "camtool.lens"  # where the resolved presets are kept in ctx.meta

def apply_equipment(ctx: click.Context, params: dict[str, Any]) -> dict[str, Any]:
    """Resolve ``--scene``, ``--camera`` and ``--lens`` into the command's own parameters.

    :func:`camtool.plans.equipment.apply_equipment` decides (what a scene
    fills, which camera and lens are in use, what a lens brings and refuses);
    this puts the values in the shape of each option and keeps the camera and
    lens in ``ctx.meta`` for the sensor and lens-data helpers.
    """
    params = dict(params)
    scene_name, camera_name, lens_name = params.pop("scene", None), params.pop("camera", None), params.pop("lens", None)
    files = tuple(params.get("preset_files") or ())
    ctx.meta[CAMERA] = ctx.meta[LENS] = None
    if files:
        open_presets(ctx, files)  # a --presets file that cannot be read is an error even when no preset is used
    inputs = {name: flatten(value) if name in equipment.LIST_INPUTS else value for name, value in params.items()}
    with input_errors(ctx, files):
        try:
            found = equipment.apply_equipment(scene=scene_name, camera=camera_name, lens=lens_name, inputs=inputs,
                                              database=lambda: open_presets(ctx, files))
        except InputError as error:
            if getattr(error, "scene", None) is None:
                raise
            from camtool.cli.options import bad_parameter

            text = bad_parameter(ctx, error).message
            raise click.BadParameter(f"{scene_name} gives {text}", ctx=ctx, param=param_named(ctx, "scene")) from None
    for name, value in found.values.items():
        _fill(ctx, params, name, value)
    if found.sensor is not None:
        params["sensor"] = found.sensor
    ctx.meta[CAMERA], ctx.meta[LENS] = found.camera, found.lens
    return params


def _fill(ctx: click.Context, params: dict[str, Any], name: str, value: Any) -> None:
    """Put ``value`` in ``params[name]`` in the shape of its option (a list of lists for a repeatable list)."""
    option = param_named(ctx, name)
    if option is not None and getattr(option, "callback", None) is one_value:
        params[name] = value  # an option of one value (exif's -s)
    elif name in equipment.LIST_INPUTS and option is not None and not getattr(option, "multiple", False):
        params[name] = [value]  # a list option given once (exposure's --magnification)
    else:
        params[name] = [[value]] if name in equipment.LIST_INPUTS else value


