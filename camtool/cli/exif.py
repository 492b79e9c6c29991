"""``camtool exif``: the depth of field, angle of view and exposure of photos, from their metadata.

Reading is python-exiv2's (the optional ``exif`` extra), imported only when
this command runs; see :mod:`camtool.exif` and docs/exif.md. One row per file;
a file that cannot be read (or is not a regular file) gives a row of nulls, a
one-line message on stderr and exit status 1; a value the file does not carry
is null and named on stderr, and the rest of the row is still computed; a
value the file carries but that lies outside the range of the option it
stands for is null too, named with its tag on the same line, and makes the
exit status 1. File names and tag strings are printed with their control
characters escaped (``\\x1b``, ``\\n``).
"""

from __future__ import annotations

import math
import os
import sys
from typing import Any

import click

from camtool.cli.command import Output, camtool_command
from camtool.cli.equipment import CAMERA, LENS, open_presets
from camtool.cli.lensdata import lens_data, model_options
from camtool.cli.options import DISTANCE_M, coc_options, distance_plane_option, sensor_options
from camtool.dof.ladder import model_choices
from camtool.render.columns import ANGLE, FNUMBER, NUMBER, SMALL, TEXT, Column

BRACKET_KEYS = ["near_min_mm", "near_max_mm", "far_min_mm", "far_max_mm"]
KEYS = [
    "file", "camera", "lens", "focal_length_mm", "f_number", "shutter_s", "iso", "crop_factor",
    "sensor_width_mm", "sensor_height_mm", "coc_mm", "focus_distance_mm", "focus_distance_min_mm",
    "focus_distance_max_mm", "near_mm", "far_mm", "total_mm", "hyperfocal_mm", *BRACKET_KEYS,
    "horizontal_deg", "vertical_deg", "diagonal_deg", "ev", "ev100", "model", "distance_from",
    "focal_length_source", "f_number_source", "shutter_source", "iso_source", "sensor_source", "coc_source",
    "focus_distance_source", "lens_source",
]
COLUMNS = [
    Column("file", "file", TEXT),
    Column("focal_length_mm", "f", SMALL),
    Column("f_number", "N", FNUMBER),
    Column("focus_distance_mm", "focus"),
    Column("near_mm", "near"),
    Column("far_mm", "far"),
    Column("total_mm", "depth"),
    Column("hyperfocal_mm", "H"),
    Column("horizontal_deg", "h. angle", ANGLE),
    Column("ev100", "EV100", NUMBER),
]
IMAGE_SUFFIXES = frozenset({
    ".jpg", ".jpeg", ".jpe", ".tif", ".tiff", ".heic", ".heif", ".avif", ".png", ".webp", ".jxl", ".dng",
    ".cr2", ".cr3", ".crw", ".nef", ".nrw", ".arw", ".srf", ".sr2", ".orf", ".rw2", ".raf", ".pef", ".srw",
    ".x3f", ".mrw", ".3fr", ".erf", ".kdc", ".mef", ".mos", ".iiq", ".rwl", ".exv",
})


@camtool_command("exif", keys=KEYS, batch=False)
@click.argument("paths", nargs=-1, metavar="FILE...")
@click.option("-r", "--recursive", is_flag=True,
              help="Descend into directories given as FILE (files with an image or raw suffix, sorted).")
@click.option("-s", "--distance", type=DISTANCE_M, default=None, metavar="LENGTH",
              help="Focus distance to use instead of the recorded one: 3 (bare numbers are metres), 3m, 10ft, inf.")
@sensor_options
@coc_options
@distance_plane_option
@click.option("--model", type=click.Choice([m for m in model_choices() if m != "all"]),
              default="auto", show_default=True,
              help="Depth-of-field model (see camtool dof --help); --model thin --distance-from lens "
                   "--coc-rule d/1440 gives ExifTool's Composite:DOF.")
@model_options
def exif(ctx: click.Context, paths, recursive, distance, sensor, crop, coc, coc_rule, pixel_pitch, distance_from,
         model, tolerance, diffraction, wavelength, pupil_mag, hiatus, prescription_file, fmt, units,
         preset_files) -> Output:
    """Depth of field, angle of view and exposure of photos, from the metadata the camera wrote.

    One row per FILE (JPEG, TIFF, HEIC and raw files: whatever libexiv2 reads);
    - reads a list of paths from stdin, one per line. Focal length, f-number,
    shutter time and ISO come from Exif; the sensor size from the focal-plane
    resolution, else the 35 mm-equivalent focal length, else a camera preset
    matching Make and Model; the focus distance from the maker note (Canon,
    Nikon, Olympus) or Exif SubjectDistance. Each *_source key names the tag
    used; a value the file lacks is null and named on stderr. --lens, --camera,
    --sensor/--crop and -s override what the file says. A file that cannot be
    read, or is not a regular file, gives a row of nulls and a line on stderr,
    and the exit status is 1; so does a value outside the range of its option
    (f/65288), named with its tag on that line, the rest of the row computed.
    Control characters in file names and tags are escaped (\\x1b, \\n).
    Needs the exif extra: pip install 'camtool[exif]'. See docs/exif.md.

    \b
    Examples:
      camtool exif canon_bracket.jpg nikon.jpg
      camtool exif --format json --field near_mm --field far_mm nikon.jpg
      camtool exif canon_bracket.jpg --model thin --distance-from lens --coc-rule d/1440
      camtool exif -r . --format csv
    """
    from camtool.exif.reader import ExifUnavailable, require_exiv2

    try:
        require_exiv2()
    except ExifUnavailable as error:
        raise click.ClickException(str(error)) from None
    if not paths:
        raise click.UsageError("give at least one FILE (or - to read paths from standard input)", ctx)
    files, failed = _expand(paths, recursive)
    settings = {
        "distance": _single(ctx, distance, "distance"), "sensor": sensor, "crop": crop,
        "coc": [_single(ctx, coc, "coc")] if coc else [], "coc_rule": coc_rule,
        "pixel_pitch": pixel_pitch[0] if isinstance(pixel_pitch, list) else pixel_pitch,
        "distance_from": distance_from, "model": model, "tolerance": tolerance, "diffraction": diffraction,
        "wavelength": wavelength, "pupil_mag": pupil_mag, "hiatus": hiatus, "prescription_file": prescription_file,
        "preset_files": preset_files,
    }
    rows: list[dict[str, Any]] = [_failed_row(path, reason) for path, reason in failed]
    bad = len(failed)
    for path in files:
        row, ok = _one(ctx, path, settings)
        rows.append(row)
        bad += not ok
    if bad:
        ctx.call_on_close(_exit_one)
    note = ""
    if fmt == "table":
        from camtool.geometry.coc import DEFAULT_RULE

        criterion = f"CoC {settings['coc'][0]:g} mm" if settings["coc"] else f"CoC {coc_rule or DEFAULT_RULE} of each sensor"
        note = (f"distances from the {distance_from} · {criterion} · model {model} · "
                "JSON/CSV carry every key and its *_source")
    return Output(rows, COLUMNS, KEYS, note)


def _single(ctx: click.Context, value: Any, name: str) -> float | None:
    """The one value of a length option (a list type: ``3m`` parses as [3000.0]); a list is an error here."""
    from camtool.cli.options import param_named
    from camtool.cli.params import flatten

    values = flatten(value if isinstance(value, (list, tuple)) and value and isinstance(value[0], list)
                     else [value] if value is not None else None)
    if len(values) > 1:
        raise click.BadParameter(f"one value per run here, not {len(values)}", ctx=ctx, param=param_named(ctx, name))
    return values[0] if values else None


def _exit_one() -> None:
    raise click.exceptions.Exit(1)


def _warn(path: str, message: str) -> None:
    from camtool.exif.reader import printable

    click.echo(f"camtool exif: {printable(path)}: {printable(message)}", err=True)


def _expand(paths: tuple[str, ...], recursive: bool) -> tuple[list[str], list[tuple[str, str]]]:
    """The files to read, in the order given; (path, reason) for arguments that are not files."""
    names: list[str] = []
    for path in paths:
        if path == "-":
            # bytes, decoded as the file system does (a name that is not UTF-8 keeps its bytes as surrogates);
            # one name a line, a CRLF line end is a line end
            stream = getattr(sys.stdin, "buffer", None)
            lines = [os.fsencode(line) for line in sys.stdin] if stream is None else list(stream)
            names.extend(os.fsdecode(line.rstrip(b"\n").removesuffix(b"\r")) for line in lines if line.strip())
        else:
            names.append(path)
    files: list[str] = []
    failed: list[tuple[str, str]] = []
    for name in names:
        if os.path.isdir(name):
            if not recursive:
                failed.append((name, "is a directory (give --recursive to read the images in it)"))
                continue

            def unreadable(error: OSError, top: str = name) -> None:
                failed.append((error.filename or top, f"cannot be read: {error.strerror or error}"))

            for root, dirs, entries in os.walk(name, onerror=unreadable):
                dirs.sort()
                files.extend(os.path.join(root, e) for e in sorted(entries)
                             if os.path.splitext(e)[1].lower() in IMAGE_SUFFIXES)
        else:
            files.append(name)
    return files, failed


def _failed_row(path: str, reason: str) -> dict[str, Any]:
    from camtool.exif.reader import printable

    _warn(path, reason)
    return dict.fromkeys(KEYS) | {"file": printable(path)}


def _one(ctx: click.Context, path: str, settings: dict[str, Any]) -> tuple[dict[str, Any], bool]:
    """One file's row, and whether it was read without a problem (every value present either usable or absent).

    A value present but unusable (outside its option's range) is named with its tag on the file's one line,
    before the values the file lacks.
    """
    from camtool.exif.reader import UnreadableFile, read_file

    try:
        reading = read_file(path)
    except UnreadableFile as error:
        return _failed_row(path, str(error)), False
    unusable: list[str] = [message for _, message in reading.problems]
    missing: list[str] = []
    row = _compute(ctx, path, reading, settings, missing, unusable)
    if unusable or missing:
        _warn(path, "; ".join(unusable + missing))
    return row, not unusable


def _compute(ctx: click.Context, path: str, reading: Any, settings: dict[str, Any], missing: list[str],
             unusable: list[str]) -> dict[str, Any]:
    from camtool.exif.reader import printable
    from camtool.exif.sensor import camera_names, from_crop, from_plane, match_preset, normalise

    sources = reading.sources
    row: dict[str, Any] = dict.fromkeys(KEYS)
    row["file"] = printable(path)
    camera = " ".join(p for p in (reading.make, reading.model) if p) or None
    if reading.make and reading.model and reading.model.lower().startswith(reading.make.split()[0].lower()):
        camera = reading.model
    row["camera"] = camera
    named = {field for field, _ in reading.problems}  # a value named as unusable is not named again as missing
    f, n = reading.focal_length_mm, reading.f_number
    row["focal_length_source"] = sources.get("focal_length_mm")
    row["f_number_source"] = sources.get("f_number")
    row["shutter_source"] = sources.get("shutter_s")
    row["iso_source"] = sources.get("iso")

    # the lens: --lens, else a preset whose name matches the file's lens name
    lens_preset = ctx.meta.get(LENS)
    row["lens"], row["lens_source"] = reading.lens, sources.get("lens")
    if lens_preset is not None:
        row["lens"], row["lens_source"] = lens_preset.name, "--lens"
    elif reading.lens:
        found = match_preset(_index(ctx, settings, "lens"), [normalise(reading.lens)])
        if found is not None:
            lens_preset = found
            row["lens_source"] = f"{sources.get('lens')} = preset {found.id}"
    if f is None and lens_preset is not None and not lens_preset.is_zoom:
        f, row["focal_length_source"] = lens_preset.focal_min_mm, f"lens preset {lens_preset.id}"
    row["focal_length_mm"], row["f_number"] = f, n
    row["shutter_s"], row["iso"] = reading.shutter_s, reading.iso

    size = _sensor(ctx, reading, settings, f, from_crop, from_plane, camera_names, match_preset, unusable, named)
    if size is None:
        if "sensor" not in named:
            missing.append("no sensor size (FocalPlaneResolution, FocalLengthIn35mmFilm or a camera preset): "
                           "give --sensor or --crop")
    else:
        row["sensor_width_mm"], row["sensor_height_mm"] = size.width_mm, size.height_mm
        row["crop_factor"], row["sensor_source"] = size.crop_factor, size.source

    c = _coc(ctx, settings, size, reading, row, missing, unusable)
    if f is None and "focal_length_mm" not in named:
        missing.append("no focal length (FocalLength)")
    if n is None and "f_number" not in named:
        missing.append("no f-number (FNumber, ApertureValue)")

    s, s_min, s_max = reading.focus_distance_mm, reading.focus_distance_min_mm, reading.focus_distance_max_mm
    row["focus_distance_source"] = sources.get("focus_distance")
    if settings["distance"] is not None:
        s, s_min, s_max, row["focus_distance_source"] = settings["distance"], None, None, "-s"
    if s is None and "focus_distance" not in named:
        missing.append("no focus distance (maker note or SubjectDistance): give -s")
    row["focus_distance_mm"], row["focus_distance_min_mm"], row["focus_distance_max_mm"] = s, s_min, s_max
    row["distance_from"] = settings["distance_from"]

    lens = lens_data(ctx, settings["pupil_mag"], settings["hiatus"], settings["prescription_file"], lens_preset)
    if f is not None and n is not None and c is not None and s is not None:
        _depth(row, f, n, c, s, s_min, s_max, lens, settings, missing)
    if f is not None and size is not None:
        _angles(row, f, s, size, lens, settings, missing)
    _exposure(row, n, reading.shutter_s, reading.iso, missing, named)
    return row


def _sensor(ctx, reading, settings, f, from_crop, from_plane, camera_names, match_preset, unusable, named):
    """The sensor: --sensor/--crop/--camera, else the file's focal plane, 35 mm equivalent, camera preset.

    A crop factor from the 35 mm equivalent passes --crop's range and its sensor's sides --sensor's, or it is
    named in ``unusable`` and the camera preset is tried.
    """
    from camtool.exif.reader import outside, show

    if settings["sensor"] is not None or settings["crop"] is not None or ctx.meta.get(CAMERA) is not None:
        from camtool.cli.equipment import resolve_sensor

        chosen = resolve_sensor(ctx, settings["sensor"], settings["crop"], settings["preset_files"])
        option = "--sensor" if settings["sensor"] is not None else "--crop" if settings["crop"] is not None else "--camera"
        return from_plane(chosen.width_mm, chosen.height_mm, option)
    if reading.plane_width_mm is not None and reading.plane_height_mm is not None:
        return from_plane(reading.plane_width_mm, reading.plane_height_mm, reading.sources["sensor"])
    if reading.focal_length_35mm is not None and f is not None:
        crop = reading.focal_length_35mm / f
        size = from_crop(crop, reading.pixels_w, reading.pixels_h, "Photo.FocalLengthIn35mmFilm / FocalLength")
        valid = outside("crop", crop)
        side = outside("sensor_side", min(size.width_mm, size.height_mm)) or \
            outside("sensor_side", max(size.width_mm, size.height_mm))
        if valid is None and side is None:
            return size
        named.add("sensor")
        unusable.append(f"Exif.Photo.FocalLengthIn35mmFilm {show(reading.focal_length_35mm)} over FocalLength "
                        f"{show(f)} mm: " + (f"a crop factor of {show(crop)} is outside the valid range: {valid}"
                                            if valid is not None else
                                            f"a sensor of {show(size.width_mm)} × {show(size.height_mm)} mm has a "
                                            f"side outside the valid range: {side}"))
    body = match_preset(_index(ctx, settings, "camera"), camera_names(reading.make, reading.model))
    if body is not None:
        return from_plane(body.sensor.width_mm, body.sensor.height_mm, f"camera preset {body.id}")
    return None


def _index(ctx: click.Context, settings: dict[str, Any], kind: str) -> dict[str, list[Any]]:
    """The presets of ``kind`` by normalised name, built on first use and kept for the run."""
    from camtool.exif.sensor import name_index

    cache = ctx.meta.setdefault("camtool.exif.index", {})
    if kind not in cache:
        cache[kind] = name_index(open_presets(ctx, settings["preset_files"]).all(kind))
    return cache[kind]


def _coc(ctx, settings, size, reading, row, missing, unusable) -> float | None:
    """--coc, else the --coc-rule (d/1500 by default) applied to the sensor; the CoC passes --coc's range.

    The pixel pitch a ``px:K`` rule needs is --pixel-pitch, else the sensor width over the image's long side
    if that lies in --pixel-pitch's range. A rule that does not parse is an error of --coc-rule (exit 2);
    a file without a usable pitch, or whose CoC falls outside --coc's range, is a problem of that file.
    """
    from camtool.core.units import UnitError
    from camtool.exif.reader import outside, show
    from camtool.geometry.coc import DEFAULT_RULE, coc_from_rule

    if settings["coc"]:
        row["coc_mm"], row["coc_source"] = settings["coc"][0], "--coc"
        return float(row["coc_mm"])
    rule = settings["coc_rule"] or DEFAULT_RULE
    try:  # the rule itself, on a full-frame sensor with a 5 µm pitch: a rule that does not parse fails every file
        coc_from_rule(rule, 36.0, 24.0, 0.005)
    except UnitError as error:
        from camtool.cli.options import param_named

        raise click.BadParameter(str(error), ctx=ctx, param=param_named(ctx, "coc_rule")) from None
    if size is None:
        return None
    pitch = settings["pixel_pitch"]
    if pitch is None and reading.pixels_w:
        derived = size.width_mm / max(reading.pixels_w, reading.pixels_h or 0)
        pitch = derived if outside("pixel_pitch", derived) is None else None
    try:
        choice = coc_from_rule(rule, size.width_mm, size.height_mm, pitch)
    except UnitError:
        missing.append(f"no pixel pitch for --coc-rule {rule} (the image size gives none in range): "
                       "give --pixel-pitch")
        return None
    valid = outside("coc", choice.coc_mm)
    if valid is not None:
        unusable.append(f"a CoC of {show(choice.coc_mm)} mm ({choice.origin}, sensor from {size.source}) "
                        f"is outside the valid range: {valid}")
        return None
    row["coc_mm"], row["coc_source"] = choice.coc_mm, choice.origin
    return choice.coc_mm


def _depth(row, f, n, c, s, s_min, s_max, lens, settings, missing) -> None:
    from camtool.core.errors import DomainError
    from camtool.dof.ladder import ModelUnavailable, depth_of_field, focal_lengths

    def run(distance: float) -> Any:
        focal = focal_lengths(lens, [f])[0]
        return depth_of_field(settings["model"], focal, n, c, distance, settings["distance_from"], lens,
                              settings["diffraction"], settings["wavelength"], settings["tolerance"])

    try:
        result = run(s)
    except (DomainError, ModelUnavailable, ValueError) as error:
        missing.append(f"no depth of field ({_one_line(error)})")
        return
    limits = result.limits
    row.update(near_mm=limits.near_mm, far_mm=limits.far_mm, total_mm=limits.total_mm,
               hyperfocal_mm=limits.hyperfocal_mm, model=result.model)
    if s_min is not None and s_max is not None:
        try:
            low, high = run(s_min).limits, run(s_max).limits
        except (DomainError, ModelUnavailable, ValueError) as error:
            missing.append(f"no limits for the focus bracket ({_one_line(error)})")
            return
        row.update(near_min_mm=low.near_mm, far_min_mm=low.far_mm, near_max_mm=high.near_mm, far_max_mm=high.far_mm)


def _angles(row, f, s, size, lens, settings, missing) -> None:
    from camtool.core.errors import DomainError
    from camtool.geometry.fov import view

    p, delta = (lens.thick_parameters() if lens is not None else None) or (1.0, 0.0)
    distance = s if s is not None and math.isfinite(s) else None
    try:
        angles = view(size.width_mm, size.height_mm, f, distance, settings["distance_from"], p, delta).angles
    except (DomainError, ValueError) as error:
        missing.append(f"no angle of view ({_one_line(error)})")
        return
    row.update(horizontal_deg=angles.horizontal_deg, vertical_deg=angles.vertical_deg,
               diagonal_deg=angles.diagonal_deg)


def _exposure(row, n, t, iso, missing, named) -> None:
    from camtool.core.errors import DomainError
    from camtool.exposure.ev import ev100, exposure_value

    if t is None and "shutter_s" not in named:
        missing.append("no shutter time (ExposureTime, ShutterSpeedValue)")
    if iso is None and "iso" not in named:
        missing.append("no ISO (ISOSpeedRatings)")
    if n is None or t is None:
        return
    try:
        row["ev"] = exposure_value(n, t)
        if iso is not None:
            row["ev100"] = ev100(n, t, iso)
    except DomainError as error:
        missing.append(f"no EV ({_one_line(error)})")


def _one_line(error: Exception) -> str:
    return str(error).splitlines()[0] if str(error) else type(error).__name__
