"""``camtool stack``: the frames of a focus stack, on a macro rail (-m, --depth) or by the focus ring (--near, --far)."""

from __future__ import annotations

from typing import Any

import click

from camtool.cli.closeup import MAGNIFICATION
from camtool.cli.command import GRID, MAX_TABLE_ROWS, Output, camtool_command
from camtool.cli.common import f_numbers, flatten, one_value, required
from camtool.cli.equipment import LENS, resolve_coc, resolve_sensor
from camtool.cli.lensdata import lens_data, model_options, pupil_and_hiatus
from camtool.cli.options import (
    DISTANCE_M,
    FOCAL_MM,
    LENGTH_MM,
    bad_parameter,
    coc_options,
    distance_plane_option,
    domain_message,
    library_errors,
    param_named,
    sensor_options,
)
from camtool.cli.params import CriterionType, FNumberType, NumberType
from camtool.core.errors import DomainError, InputError
from camtool.dof.ladder import model_choices, model_help
from camtool.plans.stack import DEFAULT_OVERLAP, bracket_rows, bracket_stack, rail_rows, rail_stack, stack_mode
from camtool.render.views.common import footer
from camtool.render.views.stack import COLUMNS, KEYS, bracket_note, rail_note


def _one(ctx: click.Context, values: list[float], option: str, name: str) -> float:
    if len(values) != 1:
        raise click.BadParameter("takes one value here", ctx=ctx, param=param_named(ctx, name))
    return float(values[0])


@camtool_command("stack", keys=KEYS, batch=False)
@click.option("-f", "--focal-length", "focal_length", type=FOCAL_MM, multiple=True,
              help="Focal length, e.g. 24 or 24mm (bare numbers are mm); one value. Bracketing mode needs it; "
                   "in rail mode it makes the classic depth exact.")
@click.option("-N", "--f-number", "f_number", type=FNumberType(), multiple=True,
              help="f-number: 8, f/8 or f8; one value.")
@click.option("--exact-stops", is_flag=True,
              help="Read the nominal f-number as the exact 2^(k/6) stop it labels (5.6 -> 5.657).")
@click.option("-m", "--magnification", type=MAGNIFICATION, multiple=True,
              help="Rail mode: the magnification, e.g. 0.5 (1:2), 1 (life size), 5 (5:1); one value.")
@click.option("--depth", type=LENGTH_MM, callback=one_value, metavar="LENGTH",
              help="Rail mode: subject depth to cover at magnification -m, e.g. 10mm (bare numbers are mm).")
@click.option("--near", type=DISTANCE_M, callback=one_value, metavar="DISTANCE",
              help="Bracketing mode: nearest point to cover, e.g. 0.5 (bare numbers are metres), 50cm.")
@click.option("--far", type=DISTANCE_M, callback=one_value, metavar="DISTANCE",
              help="Bracketing mode: farthest point to cover, e.g. 10m or inf.")
@click.option("--overlap", type=NumberType(0.0, 0.99), default=DEFAULT_OVERLAP, show_default=True, callback=one_value,
              help="Fraction of each frame's depth shared with the next (0 to 0.99).")
@click.option("--criterion", type=CriterionType(("classic", "wave")), default=None,
              metavar="classic|wave|mtf:LEVEL@FREQ",
              help="Depth per frame: classic (the CoC), wave (quarter-wave λ/NA², what macro stackers use) or, in "
                   "rail mode, by contrast (docs/wave.md). Default: wave from 1:1 (-m 1) up, classic below and for "
                   "bracketing.")
@sensor_options
@coc_options
@distance_plane_option
@click.option("--model", type=click.Choice([c for c in model_choices() if c != "all"]), default="auto",
              show_default=True, help=model_help().replace("; all: every model the inputs allow, side by side, "
                                                           "with the time each took", ""))
@model_options
def stack(ctx: click.Context, focal_length, f_number, exact_stops, magnification, depth, near, far, overlap,
          criterion, sensor, crop, coc, coc_rule, pixel_pitch, distance_from, model, tolerance, diffraction,
          wavelength, pupil_mag, hiatus, prescription_file, fmt, units, preset_files) -> Output:
    """Plan a focus stack: the frames that cover a depth, with a stated overlap.

    \b
    Examples:
      camtool stack -m 1 -N 8 --depth 10mm
      camtool stack -m 2 -N 5.6 --depth 3mm --criterion classic --overlap 0
      camtool stack -m 1 -N 8 --depth 5mm --criterion mtf:0.3@50
      camtool stack -f 24 -N 11 --near 0.5 --far inf
      camtool stack -f 50 -N 8 --near 1m --far 3m --overlap 0.5 --format json

    Rail mode (-m and --depth; the camera or subject moves at constant
    magnification): every frame has the same depth D, the step is
    D·(1 − overlap) at the subject, ⌈depth/step⌉ frames cover the depth
    and frame 1's near limit is the subject's nearest point; focus, near and far are positions along the subject from its
    nearest point, and extension_step_mm is the same step made by the lens
    focusing instead (m²·step); the depth is the close-up closed form
    (thin, or thick with --pupil-mag). Bracketing mode (-f, --near, --far; the
    focus ring moves): each frame's near limit sits at the previous far
    limit less overlap × that frame's depth; with --far inf the last frame
    is focused at the hyperfocal distance. Distances are in the
    --distance-from plane (the sensor stays put while the lens moves); the
    frames are solved by the --model chosen. More than 10000 frames is an
    error on --near (2000 with thick or paraxial, 25 with raytrace, which
    solve each frame numerically, some ten evaluations of the model a
    frame). A rail plan streams (JSON, CSV, --field) up to 10⁶ frames; a
    table holds at most 100000.
    """
    apertures = required(ctx, f_numbers(f_number, exact_stops), "-N")
    n = _one(ctx, apertures, "-N", "f_number")
    wanted_m = flatten(magnification)
    with library_errors(ctx):
        mode = stack_mode(magnification=wanted_m, depth_mm=depth, near_mm=near, far_mm=far)
    chosen = resolve_sensor(ctx, sensor, crop, preset_files)
    cocs, coc_origin = resolve_coc(ctx, list(coc), coc_rule, chosen, pixel_pitch)
    lens = lens_data(ctx, pupil_mag, hiatus, prescription_file)
    p = pupil_and_hiatus(ctx, pupil_mag, hiatus)[0]
    focal = flatten(focal_length)
    f = _one(ctx, focal, "-f", "focal_length") if focal else None
    if mode == "rail":
        m = _one(ctx, wanted_m, "-m", "magnification")
        try:
            rail = rail_stack(
                depth_mm=float(depth), f_number=n, magnification=m, coc_mm=float(cocs[0]), criterion=criterion,
                overlap=float(overlap), pupil_magnification=p, wavelength_nm=wavelength, focal_length_mm=f,
                diffraction=diffraction, model=model, lens_preset=ctx.meta.get(LENS))
        except (DomainError, InputError) as error:  # the plan's depth_mm is --depth, shown as a length
            raise (click.BadParameter(domain_message(error, "depth"), ctx=ctx, param=param_named(ctx, "depth"))
                   if isinstance(error, DomainError) and error.param == "depth_mm" else bad_parameter(ctx, error)) \
                from None
        return _rail(ctx, rail, fmt, coc_origin)
    from camtool.core.steps import reporting
    from camtool.render.progress import progress

    traced = model in ("raytrace", "paraxial") or (lens is not None and lens.prescription is not None)
    with library_errors(ctx), progress("camtool stack: frames", total=None if traced else 0) as bar, \
            reporting(bar.advance):
        plan = bracket_stack(focal_length_mm=f, f_number=n, coc_mm=float(cocs[0]), near_mm=float(near),
                             far_mm=float(far), overlap=float(overlap), criterion=criterion, model=model, lens=lens,
                             lens_preset=ctx.meta.get(LENS), pupil_magnification=p, wavelength_nm=wavelength,
                             diffraction=diffraction, tolerance=tolerance, distance_from=distance_from,
                             lens_name=ctx.params.get("lens"))
    note = bracket_note(plan, near, far, overlap, ctx.params.get("units", "metric"), footer(
        None, cocs if plan.criterion == "classic" else None, coc_origin, chosen.label, distance_from)) \
        if fmt == "table" else ""
    return Output(bracket_rows(plan), COLUMNS, KEYS, note)


def _rail(ctx: click.Context, rail: Any, fmt: str, coc_origin: str) -> Output:
    """The rail plan's frames, or the current chunk of them: a long plan is written a chunk at a time."""
    plan, depth = rail.plan, rail.depth_mm
    grid = ctx.meta.get(GRID)
    if grid is None or grid.whole:  # a table (or a caller without a grid): every frame at once
        if fmt == "table" and plan.frames > MAX_TABLE_ROWS:
            raise click.BadParameter(
                f"{depth:g} mm is outside the valid range for a table: at most {MAX_TABLE_ROWS:,} frames "
                f"(this plan has {plan.frames:,} of {plan.step_mm:.4g} mm; --format csv or --format json "
                "stream any number)", ctx=ctx, param=param_named(ctx, "depth"))
        start, stop = 0, plan.frames
    else:
        if grid.count is None:
            grid.count = plan.frames
        start, stop = grid.start, grid.stop
    rows = rail_rows(rail, start=start, stop=stop)
    note = rail_note(rail, coc_origin, ctx.params.get("units", "metric")) if fmt == "table" else ""
    return Output(rows, COLUMNS, KEYS, note)
