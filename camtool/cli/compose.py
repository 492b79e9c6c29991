"""``camtool compose``: keep the subject the same size in the frame while focal length and distance change."""

from __future__ import annotations

from typing import Any

import click

from camtool.cli.closeup import teleconverter_option
from camtool.cli.command import Output, camtool_command, combine_params
from camtool.cli.common import f_numbers, rows_from, single
from camtool.cli.equipment import LENS, resolve_coc, resolve_sensor
from camtool.cli.options import (
    DISTANCE_M,
    aperture_options,
    coc_options,
    distance_plane_option,
    focal_option,
    library_errors,
    projection_option,
    sensor_options,
    squeeze_option,
)
from camtool.cli.params import LengthType, NumberType, flatten
from camtool.plans import compose as plans
from camtool.plans.cine import desqueezed_width_mm
from camtool.plans.compose import lenses
from camtool.plans.fov import lens_projection
from camtool.render.views.compose import KEYS, compose_view

SIZE_M = LengthType("m")


# No --batch: rows compare focal lengths with the first one, which a batch of unrelated scenes would not.
@camtool_command("compose", keys=KEYS, batch=False)
@focal_option
@click.option("--subject-size", type=SIZE_M, help="Subject size along --fill-axis, e.g. 1.8m (bare numbers are metres).")
@click.option("--fill", type=NumberType(0.001, 10), help="Fraction of the frame the subject fills, e.g. 0.8.")
@click.option("--fill-axis", type=click.Choice(["height", "width"]), default="height", show_default=True,
              help="Frame dimension --fill refers to.")
@click.option("-m", "--magnification", type=NumberType(1e-9, 1000), multiple=True,
              help="Magnification (any m > 0), instead of --subject-size and --fill; a list 0.5,1,2 gives a row each "
                   "with one focal length.")
@aperture_options
@click.option("--background", type=DISTANCE_M,
              help="Distance of a background plane behind the subject (bare numbers are metres; inf allowed).")
@click.option("--foreground", type=SIZE_M,
              help="Distance of a foreground plane in front of the subject (bare numbers are metres).")
@sensor_options
@coc_options
@squeeze_option
@distance_plane_option
@teleconverter_option
@projection_option
def compose(ctx: click.Context, focal_length, subject_size, fill, fill_axis, magnification, f_number, exact_stops,
            background, foreground, sensor, crop, coc, coc_rule, pixel_pitch, squeeze, distance_from, teleconverter,
            projection, fmt, units, preset_files) -> Output:
    """Perspective composition: where to stand with each focal length to frame the subject the same.

    For each focal length (default 24, 35, 50, 85, 135, 200 mm): the camera
    distance s = f(1 + 1/m) (+ the image distance, from the sensor), angles of
    view and field at the subject; with -N the near and far limits; with
    --background/--foreground (and -N) how large that plane's objects look
    relative to the first focal length, how much of it is visible and its blur
    disc b = (f·m/N)·x/(s ± x) in mm and % of the frame width.

    A fisheye (--projection, or a --lens preset's) frames the subject where
    its mapping puts the subject's edges: at r = fill·h/2 from the centre, so
    a subject filling 0.8 of the height stands where its edges make the angle
    the mapping gives for r; the angles and fields are those of `camtool fov`
    at that distance, the magnification and blur those at the centre.

    \b
    Examples:
      camtool compose --subject-size 1.8m --fill 0.8
      camtool compose --subject-size 1.8m --fill 0.8 -N 2.8 --background 20m -f 35,85,200
      camtool compose --subject-size 4m --fill 0.9 --fill-axis width --camera arri-alexa-35 --squeeze 2 -f 40,75
      camtool compose --subject-size 1.8m --fill 0.8 --lens sigma-15mm-f1.4-dg-dn-diagonal-fisheye-art
    """
    focal, apertures = lenses(focal_lengths_mm=flatten(focal_length), f_numbers=f_numbers(f_number, exact_stops),
                              teleconverter=teleconverter)
    size, share = single(ctx, subject_size, "--subject-size"), single(ctx, fill, "--fill")
    given_ms = flatten(magnification)
    given_m = given_ms[0] if given_ms else None
    behind, before = single(ctx, background, "--background"), single(ctx, foreground, "--foreground")
    if (given_m is None) == (size is None or share is None):
        raise click.UsageError("Give --subject-size and --fill, or --magnification.", ctx)
    if (behind is not None or before is not None) and not apertures:
        raise click.UsageError("--background and --foreground need -N for the blur disc.", ctx)
    chosen = resolve_sensor(ctx, sensor, crop, preset_files)
    cocs, coc_origin = resolve_coc(ctx, list(coc), coc_rule, chosen, pixel_pitch) if apertures else (None, "")
    optical: list[Any] = [apertures, cocs] if apertures else []
    count, columns = combine_params(ctx, focal, given_ms or [0.0], *optical)
    f, m, n, c = ((*columns, None, None))[:4]
    with library_errors(ctx):
        mapping, field_max = lens_projection(projection, ctx.meta.get(LENS))
        width = desqueezed_width_mm(chosen.width_mm, squeeze)  # an anamorphic's frame is its de-squeezed width
        values = plans.compose(focal_length_mm=f, sensor_width_mm=width, sensor_height_mm=chosen.height_mm,
                               reference_focal_length_mm=focal[0], magnification=m if given_m is not None else None,
                               subject_size_mm=size, fill=share,
                               frame_mm=chosen.height_mm if fill_axis == "height" else width,
                               f_number=n, coc_mm=c, distance_from=distance_from, background_mm=behind,
                               foreground_mm=before, projection=mapping, field_max_deg=field_max)
    shown, note = compose_view(apertures=bool(apertures), background=behind is not None,
                               foreground=before is not None, table=fmt == "table", magnifications=given_ms,
                               subject_size_mm=size, fill=share, fill_axis=fill_axis, reference_mm=focal[0], cocs=cocs,
                               coc_origin=coc_origin, sensor_label=chosen.label, distance_from=distance_from,
                               squeeze=squeeze, projection=mapping)
    return Output(rows_from(count, values), shown, KEYS, note)
