"""``camtool dof``: near and far limits of acceptable sharpness."""

from __future__ import annotations

import click

from camtool.cli.command import Output, camtool_command, combine_params

from camtool.cli.common import f_numbers, footer, required, rows_from
from camtool.cli.equipment import resolve_coc, resolve_sensor
from camtool.cli.options import (DISTANCE_M, aperture_options, coc_options, distance_plane_option, focal_option,
                                 library_errors, sensor_options)
from camtool.ladder import CHOICES, depth_of_field
from camtool.render.columns import FNUMBER, SMALL, TEXT, Column

KEYS = ["focal_length_mm", "f_number", "distance_mm", "near_mm", "far_mm", "total_mm", "front_mm", "rear_mm",
        "hyperfocal_mm", "coc_mm", "magnification", "model", "error_estimate", "distance_from"]
COLUMNS = [
    Column("focal_length_mm", "f", SMALL),
    Column("f_number", "N", FNUMBER),
    Column("distance_mm", "focus"),
    Column("near_mm", "near"),
    Column("far_mm", "far"),
    Column("total_mm", "depth"),
    Column("front_mm", "front"),
    Column("rear_mm", "rear"),
    Column("hyperfocal_mm", "H"),
    Column("sharp_zone", "sharp zone", TEXT),
]


@camtool_command("dof", keys=KEYS)
@focal_option
@aperture_options
@click.option("-s", "--distance", type=DISTANCE_M, multiple=True,
              help="Focus distance, e.g. 3 (bare numbers are metres), 3m, 10ft, inf; a list gives a row each.")
@sensor_options
@coc_options
@distance_plane_option
@click.option("--model", type=click.Choice(CHOICES), default="auto", show_default=True,
              help="approx: H·s/(H±s); thin: exact thin lens; auto: what the scene needs.")
def dof(ctx: click.Context, focal_length, f_number, exact_stops, distance, sensor, crop, coc, coc_rule,
        pixel_pitch, distance_from, model, fmt, units, preset_files) -> Output:
    """Depth of field: near and far limits, total depth, front/rear split and hyperfocal distance.

    \b
    Examples:
      camtool dof -f 50 -N 8 -s 3m
      camtool dof -f 85 -N 1.8,2.8,4 -s 2 --sensor aps-c --format json
    """
    focal = required(ctx, focal_length, "-f")
    apertures = required(ctx, f_numbers(f_number, exact_stops), "-N")
    distances = required(ctx, distance, "-s")
    chosen = resolve_sensor(ctx, sensor, crop, preset_files)
    cocs, coc_origin = resolve_coc(ctx, list(coc), coc_rule, chosen, pixel_pitch)
    count, (f, n, s, c) = combine_params(ctx, focal, apertures, distances, cocs)
    with library_errors(ctx):
        result = depth_of_field(model, f, n, c, s, distance_from)
    limits = result.limits
    rows = rows_from(count, {
        "focal_length_mm": f, "f_number": n, "distance_mm": s, "near_mm": limits.near_mm, "far_mm": limits.far_mm,
        "total_mm": limits.total_mm, "front_mm": limits.front_mm, "rear_mm": limits.rear_mm,
        "hyperfocal_mm": limits.hyperfocal_mm, "coc_mm": c, "magnification": limits.magnification,
        "model": result.model, "error_estimate": result.error_estimate, "distance_from": distance_from,
    })
    note = ""
    if fmt == "table":
        from camtool.render.bar import axis_range, sharp_zone_bar

        low, high = axis_range([v for r in rows for v in (r["near_mm"], r["far_mm"], r["hyperfocal_mm"])])
        for row in rows:
            row["sharp_zone"] = sharp_zone_bar(row["near_mm"], row["distance_mm"], row["far_mm"],
                                               row["hyperfocal_mm"], low, high, width=24)
        note = footer(result.model, cocs, coc_origin, chosen.label, distance_from, "┃ focus, H hyperfocal, ▶ ∞")
    return Output(rows, COLUMNS, KEYS, note)
