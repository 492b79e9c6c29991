"""``camtool focus``: thin-lens focusing, and the inverse -- where to focus for a wanted near and far limit."""

from __future__ import annotations

import click

from camtool.cli.closeup import closeup_options
from camtool.cli.command import Output, camtool_command, combine_params
from camtool.cli.common import f_numbers, required, rows_from
from camtool.cli.equipment import LENS, resolve_coc, resolve_sensor
from camtool.cli.lensdata import (
    criterion_option,
    lens_data,
    lens_geometry_options,
    pupil_and_hiatus,
    wavelength_option,
)
from camtool.cli.options import (
    DISTANCE_M,
    LENGTH_MM,
    aperture_options,
    coc_options,
    distance_plane_option,
    focal_option,
    library_errors,
    sensor_options,
)
from camtool.cli.params import NumberType, flatten
from camtool.core import ranges
from camtool.plans import focus as plans
from camtool.plans.closeup import CLOSE_UP
from camtool.plans.equipment import solved_t_stops
from camtool.render.views.common import footer, t_stop_columns
from camtool.render.views.focus import (
    CONTRAST_COLUMNS,
    CONTRAST_KEYS,
    DEPTH_COLUMNS,
    DEPTH_KEYS,
    FIXED_KEYS,
    FORWARD_KEYS,
    INVERSE_COLUMNS,
    INVERSE_KEYS,
    OPTIMUM_COLUMNS,
    OPTIMUM_KEYS,
    forward_view,
    hansma_note,
)


@camtool_command("focus", keys=list(dict.fromkeys([*FORWARD_KEYS, *INVERSE_KEYS, *FIXED_KEYS, *OPTIMUM_KEYS, *DEPTH_KEYS,
                                                   *CONTRAST_KEYS, "t_stop"])))
@focal_option
@click.option("-s", "--distance", type=DISTANCE_M, multiple=True,
              help="Focus distance (bare numbers are metres).")
@click.option("-m", "--magnification", type=NumberType(*ranges.MAGNIFICATION), multiple=True,
              help="Wanted magnification (0.5 = 1:2) instead of -s.")
@aperture_options
@click.option("--near", type=DISTANCE_M, multiple=True, help="Inverse: wanted near limit (bare numbers are metres).")
@click.option("--far", type=DISTANCE_M, multiple=True, help="Inverse: wanted far limit (inf allowed).")
@click.option("--optimum", is_flag=True,
              help="With --near/--far or --focus-spread: the f-number balancing defocus against diffraction "
                   "(Hansma), and the blur it leaves.")
@click.option("--focus-spread", "focus_spread", type=LENGTH_MM, multiple=True, metavar="LENGTH",
              help="With --optimum: the rail travel between focusing on the near and the far point, e.g. 3mm.")
@click.option("--depth", type=LENGTH_MM, multiple=True, metavar="LENGTH",
              help="With -m: the wanted total depth of field, e.g. 0.2mm; gives the CoC (with -N) or the f-number "
                   "(with --coc).")
@wavelength_option("for --optimum")
@criterion_option
@closeup_options
@sensor_options
@coc_options
@distance_plane_option
@lens_geometry_options
def focus(ctx: click.Context, focal_length, distance, magnification, f_number, exact_stops, near, far, optimum,
          focus_spread, depth, wavelength, criterion, extension, teleconverter, sensor, crop, coc, coc_rule, pixel_pitch,
          distance_from, pupil_mag, hiatus, fmt, units, preset_files) -> Output:
    """Thin-lens focusing: image distance, extension, magnification, working f-number.

    With lens data (--lens, or --pupil-mag and --hiatus) the working f-number
    is N(1 + m/P) and distances from the sensor include the hiatus.

    With --near and --far it answers the inverse question: where to focus and
    which f-number make exactly that range acceptably sharp. With -N as well
    the f-number is kept: it answers the focus that centres the range (equal
    blur at both ends) and the near and far limits that f-number gives there,
    or says which f-number the range needs.

    A lens preset with a published closest focus focuses internally
    (docs/closeup.md §2): its focal length at the focus is shown, and a
    distance or magnification it cannot reach is refused with its range.
    From the sensor, a distance that is also reached at m > 1 is answered at
    m ≤ 1 and the other magnification is given (give -m for it).

    With --optimum it gives the f-number that makes the worst point sharpest
    (defocus against diffraction, Hansma's rule in the working f-number) and
    the blur left; with -m and --depth, the CoC (with -N) or the f-number
    (with --coc) that give that depth (docs/closeup.md §4, §6). With
    --criterion the optimum is by contrast (docs/wave.md), and a --lens with
    a prescription answers by its real wavefront, as dof's wave model does.

    \b
    Examples:
      camtool focus -f 100 -s 0.5m -N 8
      camtool focus -f 100 -m 0.5
      camtool focus -f 35 --near 2m --far 10m
      camtool focus -f 24 -N 11 --near 1m --far inf
      camtool focus --lens mp-e-65 -m 1,5 -N 2.8
      camtool focus -f 150 --near 2m --far inf --optimum
      camtool focus -f 150 --near 2m --far inf --optimum --criterion mtf:0.1@20
      camtool focus --lens dgauss100-lens --near 2m --far 5m --optimum --criterion mtf:0.3@30
      camtool focus --focus-spread 3mm --optimum
      camtool focus -m 2.5 --depth 0.2mm -N 4
    """
    if depth:
        return _depth(ctx, magnification, depth, f_number, exact_stops, coc, pupil_mag, hiatus, fmt)
    if optimum and focus_spread:
        p = pupil_and_hiatus(ctx, pupil_mag, hiatus)[0]
        count, (d, m) = combine_params(ctx, flatten(focus_spread), flatten(magnification) or [0.0])
        with library_errors(ctx):
            values = plans.spread_optimum(focus_spread_mm=d, magnification=m, pupil_magnification=p,
                                          wavelength_nm=wavelength)
        return Output(rows_from(count, values), [c for c in OPTIMUM_COLUMNS if c.key in values], list(values),
                      hansma_note(wavelength) if fmt == "table" else "")
    if optimum and not (near and far):
        raise click.UsageError("--optimum needs --near and --far, or --focus-spread", ctx)
    focal = required(ctx, focal_length, "-f")
    if optimum and criterion is not None:
        cocs, _ = resolve_coc(ctx, list(coc), coc_rule, resolve_sensor(ctx, sensor, crop, preset_files), pixel_pitch)
        count, (f, a, b, c) = combine_params(ctx, focal, required(ctx, near, "--near"), required(ctx, far, "--far"),
                                             cocs)
        lens = lens_data(ctx)
        from camtool.core.steps import reporting
        from camtool.render.progress import progress

        traced = lens is not None and lens.prescription is not None  # the real lens: half a second a row
        with library_errors(ctx), progress("camtool focus: ranges", total=max(count, 1) if traced else 0) as bar, \
                reporting(bar.advance):
            values = plans.contrast_optimum(focal_length_mm=f, near_mm=a, far_mm=b, criterion=criterion, coc_mm=c,
                                            distance_from=distance_from, wavelength_nm=wavelength, lens=lens)
        real = " by the lens's real wavefront (its prescription)" if values["model"] != "wave" else ""
        note = f"optimum aperture by contrast ({criterion.label()}, docs/wave.md){real} at {values['wavelength_nm']:g} nm"
        return Output(rows_from(count, values), CONTRAST_COLUMNS, CONTRAST_KEYS, note if fmt == "table" else "")
    if optimum:
        p, delta, lens_note = pupil_and_hiatus(ctx, pupil_mag, hiatus)
        count, (f, a, b) = combine_params(ctx, focal, required(ctx, near, "--near"), required(ctx, far, "--far"))
        with library_errors(ctx):
            values = plans.optimum(focal_length_mm=f, near_mm=a, far_mm=b, distance_from=distance_from,
                                   pupil_magnification=p, hiatus_mm=delta, wavelength_nm=wavelength)
        note = footer(None, None, "", hansma_note(wavelength), distance_from, lens_note) if fmt == "table" else ""
        return Output(rows_from(count, values), OPTIMUM_COLUMNS, OPTIMUM_KEYS, note)
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
        found = plans.forward(focal_length_mm=f, wanted=w, by_magnification=not distance,
                              f_number=given_n[0] if given_n else None, distance_from=distance_from,
                              pupil_magnification=p, hiatus_mm=delta, lens_preset=ctx.meta.get(LENS),
                              extension_mm=extension, teleconverter=teleconverter)
    rows = found.rows if found.rows is not None else rows_from(count, found.values or {})
    columns, keys, note = forward_view(found, rows, f_number_given=bool(given_n), table=fmt == "table",
                                       close_up=CLOSE_UP, extension=extension, teleconverter=teleconverter,
                                       lens_note=lens_note, distance_from=distance_from)
    return Output(rows, columns, keys, note)


def _depth(ctx, magnification, depth, f_number, exact_stops, coc, pupil_mag, hiatus, fmt) -> Output:
    wanted_m = required(ctx, magnification, "-m")
    apertures, cocs = f_numbers(f_number, exact_stops), flatten(coc)
    if bool(apertures) == bool(cocs):
        raise click.UsageError("--depth needs -N (to find the CoC) or --coc (to find the f-number)", ctx)
    p = pupil_and_hiatus(ctx, pupil_mag, hiatus)[0]
    count, (m, d, given) = combine_params(ctx, wanted_m, flatten(depth), apertures or cocs)
    with library_errors(ctx):
        values = plans.depth(magnification=m, depth_mm=d, pupil_magnification=p,
                             **({"f_number": given} if apertures else {"coc_mm": given}))
    note = "depth = 2·N·c·(1 + m/P)/m² (docs/closeup.md §6)" if fmt == "table" else ""
    return Output(rows_from(count, values), DEPTH_COLUMNS, DEPTH_KEYS, note)


def _inverse(ctx, focal, near, far, sensor, crop, coc, coc_rule, pixel_pitch, distance_from, fmt,
             preset_files, apertures=()) -> Output:
    nears = required(ctx, near, "--near")
    fars = required(ctx, far, "--far")
    chosen = resolve_sensor(ctx, sensor, crop, preset_files)
    cocs, coc_origin = resolve_coc(ctx, list(coc), coc_rule, chosen, pixel_pitch)
    count, (f, a, b, c, *n) = combine_params(ctx, focal, nears, fars, cocs, *([apertures] if apertures else []))
    with library_errors(ctx):
        found = plans.inverse(focal_length_mm=f, near_mm=a, far_mm=b, coc_mm=c, f_number=n[0] if n else None,
                              distance_from=distance_from)
    cine = solved_t_stops(found.values["f_number"], lens=ctx.meta.get(LENS)) if not found.fixed else None
    t_key = ["t_stop"] if cine and cine.note else []
    note = footer("thin", cocs, coc_origin, chosen.label, distance_from, "near/far: the limits at this f-number"
                  if found.fixed else (cine.note if cine else "")) if fmt == "table" else ""
    rows = rows_from(count, {**found.values, **({"t_stop": cine.t_stops} if cine and t_key else {})})
    return Output(rows, t_stop_columns(rows, INVERSE_COLUMNS) if t_key else INVERSE_COLUMNS,
                  INVERSE_KEYS + FIXED_KEYS if found.fixed else INVERSE_KEYS + t_key, note)
