"""``camtool focus``: thin-lens focusing, and the inverse -- where to focus for a wanted near and far limit."""

from __future__ import annotations

import click

from camtool.cli.command import Output, camtool_command, combine_params
from camtool.cli.common import f_numbers, footer, required, rows_from
from camtool.cli.equipment import resolve_coc, resolve_sensor
from camtool.cli.lensdata import lens_geometry_options, pupil_and_hiatus
from camtool.cli.options import (
    DISTANCE_M,
    aperture_options,
    coc_options,
    distance_plane_option,
    focal_option,
    library_errors,
    sensor_options,
)
from camtool.cli.params import NumberType, flatten
from camtool.core import ranges
from camtool.dof.inverse import focus_for_limits, focus_for_limits_at
from camtool.geometry.thinlens import focus_setting
from camtool.render.columns import FNUMBER, NUMBER, SMALL, Column

FORWARD_KEYS = ["focal_length_mm", "distance_mm", "image_distance_mm", "extension_mm", "magnification",
                "f_number", "working_f_number", "closest_focus_mm", "distance_from"]
FORWARD_COLUMNS = [
    Column("focal_length_mm", "f", SMALL),
    Column("distance_mm", "focus"),
    Column("image_distance_mm", "image dist.", SMALL),
    Column("extension_mm", "extension", SMALL),
    Column("magnification", "m", NUMBER),
    Column("working_f_number", "working N", FNUMBER),
]
INVERSE_KEYS = ["focal_length_mm", "near_mm", "far_mm", "distance_mm", "f_number", "coc_mm", "distance_from"]
FIXED_KEYS = ["wanted_near_mm", "wanted_far_mm", "needed_f_number"]
INVERSE_COLUMNS = [
    Column("focal_length_mm", "f", SMALL),
    Column("near_mm", "near"),
    Column("far_mm", "far"),
    Column("distance_mm", "focus at"),
    Column("f_number", "N", FNUMBER),
]


@camtool_command("focus", keys=FORWARD_KEYS + INVERSE_KEYS + FIXED_KEYS)
@focal_option
@click.option("-s", "--distance", type=DISTANCE_M, multiple=True,
              help="Focus distance (bare numbers are metres).")
@click.option("-m", "--magnification", type=NumberType(*ranges.MAGNIFICATION), multiple=True,
              help="Wanted magnification (0.5 = 1:2) instead of -s.")
@aperture_options
@click.option("--near", type=DISTANCE_M, multiple=True, help="Inverse: wanted near limit (bare numbers are metres).")
@click.option("--far", type=DISTANCE_M, multiple=True, help="Inverse: wanted far limit (inf allowed).")
@sensor_options
@coc_options
@distance_plane_option
@lens_geometry_options
def focus(ctx: click.Context, focal_length, distance, magnification, f_number, exact_stops, near, far, sensor, crop,
          coc, coc_rule, pixel_pitch, distance_from, pupil_mag, hiatus, fmt, units, preset_files) -> Output:
    """Thin-lens focusing: image distance, extension, magnification, working f-number.

    With lens data (--lens, or --pupil-mag and --hiatus) the working f-number
    is N(1 + m/P) and distances from the sensor include the hiatus.

    With --near and --far it answers the inverse question: where to focus and
    which f-number make exactly that range acceptably sharp. With -N as well
    the f-number is kept: it answers the focus that centres the range (equal
    blur at both ends) and the near and far limits that f-number gives there,
    or says which f-number the range needs.

    \b
    Examples:
      camtool focus -f 100 -s 0.5m -N 8
      camtool focus -f 100 -m 0.5
      camtool focus -f 35 --near 2m --far 10m
      camtool focus -f 24 -N 11 --near 1m --far inf
    """
    focal = required(ctx, focal_length, "-f")
    if near or far:
        return _inverse(ctx, focal, near, far, sensor, crop, coc, coc_rule, pixel_pitch, distance_from, fmt,
                        preset_files, f_numbers(f_number, exact_stops))
    if bool(distance) == bool(magnification):
        raise click.UsageError("give either -s/--distance or -m/--magnification (or --near and --far)", ctx)
    p, delta, lens_note = pupil_and_hiatus(ctx, pupil_mag, hiatus)
    apertures = f_numbers(f_number, exact_stops)
    wanted = flatten(distance) or flatten(magnification)
    count, (f, w, *given_n) = combine_params(ctx, focal, wanted, *([apertures] if apertures else []))
    with library_errors(ctx):
        setting = focus_setting(f, w if distance else None, None if distance else w, distance_from, delta,
                                given_n[0] if given_n else None, p)
    values = {
        "focal_length_mm": f, "distance_mm": setting.distance_mm, "image_distance_mm": setting.image_distance_mm,
        "extension_mm": setting.extension_mm, "magnification": setting.magnification,
        "closest_focus_mm": setting.closest_focus_mm, "distance_from": distance_from,
    }
    keys, columns = list(FORWARD_KEYS), list(FORWARD_COLUMNS)
    if given_n:
        values.update({"f_number": given_n[0], "working_f_number": setting.working_f_number})
    else:
        keys = [k for k in keys if k not in ("f_number", "working_f_number")]
        columns = [c for c in columns if c.key != "working_f_number"]
    rows = rows_from(count, values)
    note = footer("thick" if lens_note else "thin", None, "", "unit focusing, m = v/u", distance_from,
                  lens_note) if fmt == "table" else ""
    return Output(rows, columns, keys, note)


def _inverse(ctx, focal, near, far, sensor, crop, coc, coc_rule, pixel_pitch, distance_from, fmt,
             preset_files, apertures=()) -> Output:
    nears = required(ctx, near, "--near")
    fars = required(ctx, far, "--far")
    chosen = resolve_sensor(ctx, sensor, crop, preset_files)
    cocs, coc_origin = resolve_coc(ctx, list(coc), coc_rule, chosen, pixel_pitch)
    if apertures:  # a fixed f-number: the focus that best uses it, and the limits it gives
        count, (f, a, b, c, n) = combine_params(ctx, focal, nears, fars, cocs, apertures)
        with library_errors(ctx):
            fixed = focus_for_limits_at(f, n, c, a, b, distance_from)
        rows = rows_from(count, {
            "focal_length_mm": f, "near_mm": fixed.near_mm, "far_mm": fixed.far_mm, "distance_mm": fixed.distance_mm,
            "f_number": n, "coc_mm": c, "distance_from": distance_from, "wanted_near_mm": a, "wanted_far_mm": b,
            "needed_f_number": fixed.needed_f_number,
        })
        note = footer("thin", cocs, coc_origin, chosen.label, distance_from,
                      "near/far: the limits at this f-number") if fmt == "table" else ""
        return Output(rows, INVERSE_COLUMNS, INVERSE_KEYS + FIXED_KEYS, note)
    count, (f, a, b, c) = combine_params(ctx, focal, nears, fars, cocs)
    with library_errors(ctx):
        solution = focus_for_limits(f, c, a, b, distance_from)
    rows = rows_from(count, {
        "focal_length_mm": f, "near_mm": a, "far_mm": b, "distance_mm": solution.distance_mm,
        "f_number": solution.f_number, "coc_mm": c, "distance_from": distance_from,
    })
    note = footer("thin", cocs, coc_origin, chosen.label, distance_from) if fmt == "table" else ""
    return Output(rows, INVERSE_COLUMNS, INVERSE_KEYS, note)
