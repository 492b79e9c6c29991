"""``camtool exif``: the depth of field, angle of view and exposure of photos, from their metadata.

Reading is python-exiv2's (the optional ``exif`` extra), imported only when this command runs; the rules that
turn a photo's metadata into a row are :mod:`camtool.plans.photo`'s; see docs/exif.md. A file that cannot be
read, or holds a value outside its option's range, is named on stderr and makes the exit status 1.
"""

from __future__ import annotations

import os
import sys
from typing import Any

import click

from camtool.cli.command import Output, camtool_command
from camtool.cli.common import one_value, single
from camtool.cli.equipment import CAMERA, LENS, open_presets, resolve_sensor
from camtool.cli.lensdata import lens_data, model_options
from camtool.cli.options import DISTANCE_M, coc_options, distance_plane_option, file_completion, param_named, sensor_options
from camtool.core.text import printable
from camtool.dof.ladder import model_choices
from camtool.plans.photo import KEYS, names_from_lines
from camtool.render.views.exif import COLUMNS, exif_footer


@camtool_command("exif", keys=KEYS, batch=False)
@click.argument("paths", nargs=-1, metavar="FILE...", shell_complete=file_completion)
@click.option("-r", "--recursive", is_flag=True,
              help="Descend into directories given as FILE (files with an image or raw suffix, sorted).")
@click.option("-s", "--distance", type=DISTANCE_M, default=None, metavar="LENGTH", callback=one_value,
              help="Focus distance to use instead of the recorded one: 3 (bare numbers are metres), 3m, 10ft, inf.")
@sensor_options
@coc_options
@distance_plane_option
@click.option("--model", type=click.Choice([m for m in model_choices() if m != "all"]), default="auto", show_default=True,
              help="Depth-of-field model (see camtool dof --help); --model thin --distance-from lens "
                   "--coc-rule d/1440 gives ExifTool's Composite:DOF.")
@click.option("--exiftool", is_flag=True,
              help="Answer as ExifTool 12.57's composite tags (ScaleFactor35efl, CircleOfConfusion, "
                   "HyperfocalDistance, DOF, FOV, LightValue): its sensor rules, CoC d/1440, thin lens from the lens "
                   "(not with --model, --distance-from, --coc-rule).")
@model_options
def exif(ctx: click.Context, paths, recursive, distance, sensor, crop, coc, coc_rule, pixel_pitch, distance_from,
         model, exiftool, tolerance, diffraction, wavelength, pupil_mag, hiatus, prescription_file, fmt, units,
         preset_files) -> Output:
    """Depth of field, angle of view and exposure of photos, from the metadata the camera wrote.

    One row per FILE (JPEG, TIFF, HEIC, AVIF, CR3 and raw files: whatever
    libexiv2 reads; a file it cannot read gets one line saying why);
    - reads a list of paths from stdin, one per line. Focal length, f-number,
    shutter time and ISO come from Exif or the maker note; the sensor size from
    the focal-plane resolution, else the maker note (Canon, Olympus, Nikon),
    else the 35 mm-equivalent focal length, else a camera preset matching Make
    and Model; the focus distance from the maker note (Canon, Nikon, Olympus,
    Minolta, Casio) or Exif SubjectDistance. Each *_source key names the tag
    used; a value the file lacks is null and named on stderr; where an answer
    rests on a guess (a resized or cropped file, an inferred sensor) the
    warnings key and the stderr line say what was assumed. --exiftool answers
    as ExifTool's composite tags do. --lens, --camera, --sensor/--crop and -s
    override what the file says. A file that cannot be read, or is not a
    regular file, gives a row of nulls and a line on stderr, and the exit
    status is 1; so does a value outside the range of its option (f/65288),
    named with its tag on that line, the rest of the row computed. Control
    characters in file names and tags are escaped (\\x1b, \\n). Needs the
    exif extra: pip install 'camtool[exif]'. See docs/exif.md.

    \b
    Examples:
      camtool exif canon_bracket.jpg nikon.jpg
      camtool exif --format json --field near_mm --field far_mm nikon.jpg
      camtool exif canon_bracket.jpg --model thin --distance-from lens --coc-rule d/1440
      camtool exif --exiftool --format json nikon.jpg
      camtool exif -r . --format csv
    """
    from camtool.exif.reader import ExifUnavailable, UnreadableFile, read_file, require_exiv2
    from camtool.plans import photo

    try:
        require_exiv2()
    except ExifUnavailable as error:
        raise click.ClickException(str(error)) from None
    if not paths:
        raise click.UsageError("give at least one FILE (or - to read paths from standard input)", ctx)
    coc = single(ctx, coc, "--coc")
    if exiftool:
        _only_exiftool(ctx)
    names = [name for path in paths for name in (_stdin_names() if path == "-" else [path])]
    found = photo.photo_files(names, recursive=recursive)
    answers = [photo.unreadable_answer(path, reason) for path, reason in found.failed]
    # the options resolved before any file is read: an error of theirs is the run's one line (exit 2)
    settings = _settings(ctx, sensor, crop, coc, coc_rule, prescription_file, preset_files)
    index = photo.PresetIndex(lambda: open_presets(ctx, preset_files))
    for answer in answers:
        _warn(answer)
    from camtool.render.progress import progress

    with progress("camtool exif: files", total=len(found.files) if len(found.files) > 100 else 0) as bar:
        for number, path in enumerate(found.files, 1):
            try:
                reading = read_file(path)
            except UnreadableFile as error:
                answer = photo.unreadable_answer(path, str(error))
            else:
                answer = photo.photo_answer(
                    reading, path=path, distance_mm=distance, coc_mm=coc, coc_rule=coc_rule,
                    pixel_pitch_mm=pixel_pitch[0] if isinstance(pixel_pitch, list) else pixel_pitch,
                    distance_from=distance_from, model=model, tolerance=tolerance, diffraction=diffraction,
                    wavelength_nm=wavelength, pupil_magnification=pupil_mag, hiatus_mm=hiatus,
                    lens_preset=ctx.meta.get(LENS), presets=index, convention="exiftool" if exiftool else "camtool",
                    **settings)
            _warn(answer)
            answers.append(answer)
            if number % 100 == 0:  # a step per hundred files: drawing costs more than reading one
                bar.advance(100)
    if not all(answer.ok for answer in answers):
        ctx.call_on_close(_exit_one)
    from camtool.geometry.coc import DEFAULT_RULE

    note = exif_footer(coc_mm=coc, coc_rule=coc_rule or DEFAULT_RULE, distance_from=distance_from, model=model)
    return Output([answer.values for answer in answers], COLUMNS, photo.KEYS, note if fmt == "table" else "")


GIVEN_AS = {"lens_preset": "--lens", "distance_mm": "-s", "coc_mm": "--coc"}
"""How the *_source keys name what the options gave."""
SHOWN = {"sensor": "--sensor", "crop": "--crop", "distance_mm": "-s", "coc_rule": "--coc-rule",
         "pixel_pitch_mm": "--pixel-pitch"}
"""The options that would supply what a file lacks, as its message names them."""


def _settings(ctx: click.Context, sensor: str | None, crop: float | None, coc: float | None, coc_rule: str | None,
              prescription_file: str | None, preset_files: tuple[str, ...]) -> dict[str, Any]:
    """The sensor, the CoC rule and the prescription the options give, checked once, before any file is read."""
    from camtool.core.units import UnitError
    from camtool.plans.photo import check_coc_rule

    given: dict[str, Any] = {"sensor_mm": None, "prescription": None, "given_as": GIVEN_AS}
    if sensor is not None or crop is not None or ctx.meta.get(CAMERA) is not None:
        chosen = resolve_sensor(ctx, sensor, crop, preset_files)
        given["sensor_mm"] = (chosen.width_mm, chosen.height_mm)
        option = "--sensor" if sensor is not None else "--crop" if crop is not None else "--camera"
        given["given_as"] = {**GIVEN_AS, "sensor_mm": option}
    if coc is None:
        try:
            check_coc_rule(coc_rule)
        except UnitError as error:
            raise click.BadParameter(str(error), ctx=ctx, param=param_named(ctx, "coc_rule")) from None
    if prescription_file is not None:
        given["prescription"] = getattr(lens_data(ctx, prescription_file=prescription_file), "prescription", None)
    return given


def _only_exiftool(ctx: click.Context) -> None:
    """Refuse the options --exiftool fixes (its model, plane and CoC rule), when given too."""
    from click.core import ParameterSource

    for name in ("model", "distance_from", "coc_rule", "pixel_pitch"):
        if ctx.get_parameter_source(name) not in (ParameterSource.DEFAULT, None):
            param = param_named(ctx, name)
            raise click.UsageError(f"--exiftool fixes what {param.opts[-1] if param else name} sets: give one", ctx)


def _exit_one() -> None:
    raise click.exceptions.Exit(1)


def _warn(answer: Any) -> None:
    """The file's one line on stderr, if it has a problem."""
    message = answer.message(SHOWN)
    if message:
        click.echo(f"camtool exif: {answer.values['file']}: {printable(message)}", err=True)


def _stdin_names() -> list[str]:
    """The paths standard input lists, one a line (bytes decoded as the file system does)."""
    return names_from_lines(getattr(sys.stdin, "buffer", None) or [os.fsencode(line) for line in sys.stdin])
