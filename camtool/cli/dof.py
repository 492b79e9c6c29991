"""``camtool dof``: near and far limits of acceptable sharpness, by any rung of the model ladder."""

from __future__ import annotations

import click

from camtool.cli.closeup import closeup_options, magnification_option, unreachable_errors
from camtool.cli.command import Output, camtool_command, combine_params
from camtool.cli.common import f_numbers, flatten, required
from camtool.cli.equipment import LENS, input_errors, resolve_coc, resolve_sensor
from camtool.cli.lensdata import criterion_option, lens_data, model_options
from camtool.cli.options import (
    DISTANCE_M,
    aperture_options,
    coc_options,
    distance_plane_option,
    focal_option,
    library_errors,
    sensor_options,
    squeeze_option,
)
from camtool.cli.rows import ZIP
from camtool.dof.ladder import focal_lengths, model_choices, model_help
from camtool.plans.cine import ANAMORPHIC_KEYS, with_anamorphic
from camtool.plans.closeup import CLOSE_UP
from camtool.plans.dof import DofTable, dof_table, lens_behind_converter, merge_tables
from camtool.render.views.closeup import CLOSEUP_KEYS, DIFFRACTION_KEYS
from camtool.render.views.common import footer
from camtool.render.views.dof import FAR_KEYS, dof_view

ALL_KEYS = [*FAR_KEYS, *CLOSEUP_KEYS, *DIFFRACTION_KEYS]
MODEL_HELP = model_help()


@camtool_command("dof", keys=[*ALL_KEYS, *ANAMORPHIC_KEYS])
@focal_option
@aperture_options
@click.option("-s", "--distance", type=DISTANCE_M, multiple=True,
              help="Focus distance, e.g. 3 (bare numbers are metres), 3m, 10ft, inf; a list gives a row each. "
                   "From the sensor, a distance also reached at m > 1 is answered at m ≤ 1 (give -m for the other).")
@magnification_option
@closeup_options
@sensor_options
@coc_options
@squeeze_option
@distance_plane_option
@click.option("--model", type=click.Choice(model_choices()), default="auto", show_default=True, help=MODEL_HELP)
@model_options
@criterion_option
def dof(ctx: click.Context, focal_length, f_number, exact_stops, distance, magnification, extension, teleconverter,
        sensor, crop, coc, coc_rule, pixel_pitch, squeeze, distance_from, model, tolerance, diffraction, wavelength,
        pupil_mag, hiatus, prescription_file, criterion, fmt, units, preset_files) -> Output:
    """Depth of field: near and far limits, total depth, front/rear split and hyperfocal distance.

    \b
    Examples:
      camtool dof -f 50 -N 8 -s 3m
      camtool dof --camera arri-alexa-35 -f 100 -N T2.8 -s 10ft --squeeze 2
      camtool dof -f 85 -N 1.8,2.8,4 -s 2 --sensor aps-c --format json
      camtool dof -N 2 -s 1m --prescription dgauss100 --model all
      camtool dof -f 100 -N 11,22 -s 0.5 --pupil-mag 0.8 --diffraction
      camtool dof -f 100 -N 8 -m 0.5,1,2
      camtool dof --lens mp-e-65 -N 2.8 -m 1,2,5 --diffraction
      camtool dof -f 100 -N 8,16 -s 400mm --diffraction
      camtool dof -f 50 -N 8 -s 1m --extension 25mm --teleconverter 1.4
      camtool dof -f 50 -N 8,16,22 -s 3m --criterion mtf:0.3@coc

    With -m (any m > 0) or close up, the table shows the magnification and
    the working f-number N(1 + m/P). A lens preset with a published closest
    focus focuses internally (docs/closeup.md): it is accepted down to that
    closest focus and reaches its published magnification there. With
    --diffraction every row gets its Airy disc, the f-number at which it
    fills the CoC and the wave-optics depth λ/NA²; rows where nothing can
    be sharp show a reason, and the command fails only if no row has an answer.
    """
    lens = lens_data(ctx, pupil_mag, hiatus, prescription_file)
    with input_errors(ctx, preset_files):
        focal = required(ctx, focal_lengths(lens, flatten(focal_length)), "-f")
        lens = lens_behind_converter(lens, teleconverter=teleconverter, model=model, pupil_magnification=pupil_mag,
                                     hiatus_mm=hiatus)
    apertures = required(ctx, f_numbers(f_number, exact_stops), "-N")
    wanted_m = flatten(magnification)
    if wanted_m and flatten(distance):
        if not ctx.meta.get(ZIP):
            raise click.UsageError("give either -s/--distance or -m/--magnification, not both", ctx)
        wanted_m = []  # a batch row with both (camtool's own CSV fed back) is read by its distance
    distances = wanted_m or required(ctx, distance, "-s")
    chosen = resolve_sensor(ctx, sensor, crop, preset_files)
    cocs, coc_origin = resolve_coc(ctx, list(coc), coc_rule, chosen, pixel_pitch)
    _, (f, n, s, c) = combine_params(ctx, focal, apertures, distances, cocs)
    with library_errors(ctx), unreachable_errors(ctx):
        table = dof_table(model=model, focal_length_mm=f, f_number=n, wanted=s, coc_mm=c,
                          by_magnification=bool(wanted_m), distance_from=distance_from, lens=lens,
                          pupil_magnification=pupil_mag, hiatus_mm=hiatus, lens_preset=ctx.meta.get(LENS),
                          extension_mm=extension, teleconverter=teleconverter, diffraction=diffraction,
                          wavelength_nm=wavelength, tolerance=tolerance, criterion=criterion)
    where = footer(None, cocs, coc_origin, chosen.label, distance_from)
    if squeeze and model != "all":
        where += f" · {squeeze:g}× anamorphic: near/far for vertical blur (f as marked), horizontal of f/{squeeze:g}"

    def drawn(table: DofTable) -> Output:
        rows = table.rows
        if squeeze and model != "all":
            with library_errors(ctx):
                rows = with_anamorphic(rows, squeeze=squeeze, distance_from=distance_from)
        columns, keys, note = dof_view(table, rows, model=model, anamorphic_keys=ANAMORPHIC_KEYS if squeeze else [],
                                       diffraction=diffraction, where=where, table_shown=fmt == "table",
                                       close_up=CLOSE_UP)
        return Output(rows, columns, keys, note, table, redraw)

    def redraw(outputs: list[Output]) -> Output | None:
        merged = merge_tables([out.plan for out in outputs])
        return None if merged is None else drawn(merged)

    return drawn(table)
