"""``camtool hyperfocal``: the hyperfocal distance and its near limit, per aperture."""

from __future__ import annotations

import click

from camtool.cli.closeup import teleconverter_option
from camtool.cli.command import Output, camtool_command, combine_params
from camtool.cli.common import f_numbers, required, rows_from
from camtool.cli.equipment import LENS, resolve_coc, resolve_sensor
from camtool.cli.lensdata import criterion_option, diffraction_options, lens_data, lens_geometry_options
from camtool.cli.options import (
    aperture_options,
    coc_options,
    distance_plane_option,
    focal_option,
    library_errors,
    sensor_options,
)
from camtool.cli.rows import joined
from camtool.dof.ladder import hyperfocal_choices, hyperfocal_help
from camtool.plans.depth import hyperfocal_plan
from camtool.render.views.common import footer
from camtool.render.views.hyperfocal import COLUMNS, KEYS


@camtool_command("hyperfocal", keys=KEYS)
@focal_option
@aperture_options
@sensor_options
@coc_options
@distance_plane_option
@click.option("--model", type=click.Choice(hyperfocal_choices()), default="auto", show_default=True,
              help=hyperfocal_help())
@lens_geometry_options
@teleconverter_option
@diffraction_options
@criterion_option
def hyperfocal(ctx: click.Context, focal_length, f_number, exact_stops, sensor, crop, coc, coc_rule, pixel_pitch,
               distance_from, model, pupil_mag, hiatus, teleconverter, diffraction, wavelength, criterion, fmt, units,
               preset_files) -> Output:
    """Hyperfocal distance: focus there and everything from the near limit to infinity is sharp.

    \b
    Examples:
      camtool hyperfocal -f 24 -N 8,11,16
      camtool hyperfocal -f 35 -N 8 --sensor aps-c --format json
      camtool hyperfocal -f 300 -N 4 --teleconverter 1.4
      camtool hyperfocal -f 50 -N 16,22,32 --diffraction

    With --teleconverter K the lens is taken as K·f at K·N (docs/closeup.md §7);
    the rows show those. A lens preset with a published closest focus focuses
    internally: H is its focus setting whose far limit is infinite with the
    focal length in effect there. Focusing dof at the exact value of
    --field hyperfocal_mm gives a far limit of ∞ (the table rounds it).
    With --diffraction (or --criterion) auto takes H by contrast, the wave
    model (docs/wave.md); --model thin --diffraction keeps the root-sum-square.
    """
    focal = required(ctx, focal_length, "-f")
    apertures = required(ctx, f_numbers(f_number, exact_stops), "-N")
    chosen = resolve_sensor(ctx, sensor, crop, preset_files)
    cocs, coc_origin = resolve_coc(ctx, list(coc), coc_rule, chosen, pixel_pitch)
    count, (f, n, c) = combine_params(ctx, focal, apertures, cocs)
    with library_errors(ctx):
        result = hyperfocal_plan(model=model, focal_length_mm=f, f_number=n, coc_mm=c, distance_from=distance_from,
                                 lens=lens_data(ctx, pupil_mag, hiatus), lens_preset=ctx.meta.get(LENS),
                                 teleconverter=teleconverter, diffraction=diffraction, wavelength_nm=wavelength,
                                 criterion=criterion)
    f, n = result.focal_length_mm, result.f_number
    rows = rows_from(count, {
        "focal_length_mm": f, "f_number": n, "hyperfocal_mm": result.hyperfocal_mm, "near_mm": result.near_mm,
        "coc_mm": c, "model": result.model, "distance_from": distance_from,
    })
    note = footer(result.model, cocs, coc_origin, chosen.label, distance_from) if fmt == "table" else ""
    return Output(rows, COLUMNS, KEYS, note, redraw=joined)
