"""``camtool hyperfocal``: the hyperfocal distance and its near limit, per aperture."""

from __future__ import annotations

import click

from camtool.cli.command import Output, camtool_command, combine_params
from camtool.cli.common import f_numbers, footer, required, rows_from
from camtool.cli.equipment import resolve_coc, resolve_sensor
from camtool.cli.lensdata import ladder_errors, lens_geometry_options, pupil_and_hiatus
from camtool.cli.options import (
    aperture_options,
    coc_options,
    distance_plane_option,
    focal_option,
    library_errors,
    sensor_options,
)
from camtool.dof.ladder import LensData, depth_of_field
from camtool.render.columns import FNUMBER, SMALL, Column

KEYS = ["focal_length_mm", "f_number", "hyperfocal_mm", "near_mm", "coc_mm", "model", "distance_from"]
COLUMNS = [
    Column("focal_length_mm", "f", SMALL),
    Column("f_number", "N", FNUMBER),
    Column("hyperfocal_mm", "hyperfocal"),
    Column("near_mm", "sharp from"),
    Column("coc_mm", "CoC", SMALL),
]


@camtool_command("hyperfocal", keys=KEYS)
@focal_option
@aperture_options
@sensor_options
@coc_options
@distance_plane_option
@click.option("--model", type=click.Choice(["approx", "thin", "thick", "auto"]), default="auto", show_default=True,
              help="approx: H = f²/(N·c); thin: H = f²/(N·c) + f, exact; thick: with the lens's pupil "
                   "magnification and hiatus (--lens, --pupil-mag, --hiatus); auto: thick when that lens data is "
                   "known, else thin.")
@lens_geometry_options
def hyperfocal(ctx: click.Context, focal_length, f_number, exact_stops, sensor, crop, coc, coc_rule, pixel_pitch,
               distance_from, model, pupil_mag, hiatus, fmt, units, preset_files) -> Output:
    """Hyperfocal distance: focus there and everything from the near limit to infinity is sharp.

    \b
    Examples:
      camtool hyperfocal -f 24 -N 8,11,16
      camtool hyperfocal -f 35 -N 8 --sensor aps-c --format json
    """
    focal = required(ctx, focal_length, "-f")
    apertures = required(ctx, f_numbers(f_number, exact_stops), "-N")
    chosen = resolve_sensor(ctx, sensor, crop, preset_files)
    cocs, coc_origin = resolve_coc(ctx, list(coc), coc_rule, chosen, pixel_pitch)
    count, (f, n, c) = combine_params(ctx, focal, apertures, cocs)
    with library_errors(ctx), ladder_errors(ctx):
        # The hyperfocal distance in the chosen plane is where the far limit first reaches infinity;
        # the limits of a focus at infinity carry it, and focusing there gives the near limit.
        # auto is the most complete closed form the lens data allow: the hyperfocal distance itself is the
        # answer here, not a depth of field whose error could be weighed against a tolerance
        p, delta, _ = pupil_and_hiatus(ctx, pupil_mag, hiatus)
        lens = LensData(pupil_magnification=p, hiatus_mm=delta) if (p, delta) != (1.0, 0.0) else None
        rung = ("thick" if lens else "thin") if model == "auto" else model
        at_infinity = depth_of_field(rung, f, n, c, float("inf"), distance_from, lens=lens)
        h = at_infinity.limits.hyperfocal_mm
        at_h = depth_of_field(rung, f, n, c, h, distance_from, lens=lens)
    rows = rows_from(count, {
        "focal_length_mm": f, "f_number": n, "hyperfocal_mm": h, "near_mm": at_h.limits.near_mm, "coc_mm": c,
        "model": at_h.model, "distance_from": distance_from,
    })
    note = footer(at_h.model, cocs, coc_origin, chosen.label, distance_from) if fmt == "table" else ""
    return Output(rows, COLUMNS, KEYS, note)
