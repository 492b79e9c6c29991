"""``camtool cocmap``: a circle-of-confusion map from a depth image (:mod:`camtool.plans.cocmap` decides)."""

from __future__ import annotations

import os
from typing import Any

import click

from camtool.cli.command import Output, camtool_command
from camtool.cli.common import f_numbers
from camtool.cli.equipment import LENS, resolve_coc, resolve_sensor
from camtool.cli.exposure import single
from camtool.cli.lensdata import lens_geometry_options, pupil_and_hiatus
from camtool.cli.options import DISTANCE_M, FOCAL_MM, coc_options, library_errors, sensor_options
from camtool.cli.params import FNumberType, LengthType, NumberType, one_value
from camtool.dof.cocmap import NUKE_MATHS
from camtool.plans.cocmap import MODES
from camtool.render.views.cocmap import COLUMNS, KEYS

ONE: dict[str, Any] = {"callback": one_value}


@camtool_command("cocmap", keys=KEYS, batch=False)
@click.argument("depth", metavar="DEPTH")
@click.option("-o", "--output", required=True, help="Map file (.exr, .png, .npy); for a sequence a folder or coc.%04d.exr.")
@click.option("--mode", type=click.Choice(MODES), default="physical", show_default=True,
              help="camtool's thin/thick lens, Blender's Defocus node or Nuke's ZDefocus (docs/cine.md).")
@click.option("-s", "--distance", type=DISTANCE_M, multiple=True, help="Focus from the sensor (bare: m); default: header.")
@click.option("-N", "--f-number", "f_number", type=FNumberType(t_stops=True), multiple=True, help="f-number or T-stop.")
@click.option("-f", "--focal-length", "focal_length", type=FOCAL_MM, multiple=True, help="Focal length (default: header).")
@click.option("--depth-unit", type=LengthType("m"), **ONE, help="What one stored depth unit is (1m, 1mm); EXR default 1m.")
@click.option("--channel", help="The EXR depth channel (default: Z, depth.Z, depth or Depth).")
@click.option("--pupil-offset", type=LengthType("mm", bounds=(-1e5, 1e9)), **ONE,
              help="Entrance pupil's distance in front of the sensor (default: the header's entrancePupilOffset).")
@click.option("--f-stop", type=NumberType(0.5, 128), **ONE, help="blender: the node's F-Stop (default -N).")
@click.option("--max-blur", type=NumberType(0, 10000), default="0", **ONE, help="blender: Max Blur radius, px (0: none).")
@click.option("--z-scale", type=NumberType(0, 1000), **ONE, help="blender: no Z-buffer; radius = value · Z-Scale.")
@click.option("--math", type=click.Choice(NUKE_MATHS), default="depth", help="nuke: ZDefocus math.")
@click.option("--size", type=NumberType(0, 10000), default="10", **ONE, help="nuke: blur size at infinity, px.")
@click.option("--maximum", type=NumberType(0, 10000), default="100", **ONE, help="nuke: largest blur, px.")
@click.option("--jobs", type=click.IntRange(1, 1024), help="Frames at once, in processes (default: one per core).")
@click.option("--scheduler", help="Spread frames over Dask: ADDRESS or local:N (needs camtool[dask]).")
@sensor_options
@coc_options
@lens_geometry_options
def cocmap(ctx: click.Context, depth, output, mode, distance, f_number, focal_length, depth_unit, channel, pupil_offset,
           f_stop, max_blur, z_scale, math, size, maximum, jobs, scheduler, sensor, crop, coc, coc_rule, pixel_pitch,
           pupil_mag, hiatus, fmt, units, preset_files) -> Output:
    """Circle of confusion (mm on the sensor) and blur radius (px) of every pixel of a depth image.

    DEPTH is an OpenEXR file (a Z or depth channel; its focus, aperture, tStop, focal length and
    entrancePupilOffset attributes are used unless typed), a 16-bit PNG or TIFF (with --depth-unit), a
    folder of them or a printf pattern (shot.%04d.exr). One summary row per frame: the fraction of pixels
    within the CoC, the nearest and farthest sharp depth and, in physical mode, the near and far limits
    (from the entrance pupil). Depths are from the entrance pupil; -s from the sensor (docs/cine.md).

    \b
    Examples:
      camtool cocmap tests/data/depth/ramp-lens.exr -o coc.exr
      camtool cocmap tests/data/depth/ramp.exr -o coc.npy -f 50 -N T2.8 -s 10ft --camera arri-alexa-35
      camtool cocmap tests/data/depth/ramp.exr -o coc.png --mode nuke -s 3m --size 20
    """
    from camtool.depthmap.io import frames as list_frames
    from camtool.plans.cocmap import Settings, output_names, run_frames

    chosen = resolve_sensor(ctx, sensor, crop, preset_files)
    cocs, _ = resolve_coc(ctx, list(coc), coc_rule, chosen, pixel_pitch)
    p, _, _ = pupil_and_hiatus(ctx, pupil_mag, None)
    lens = ctx.meta.get(LENS)
    apertures = f_numbers(f_number, False)
    f = single(ctx, focal_length, lens.focal_min_mm if lens is not None and lens.focal_min_mm == lens.focal_max_mm
               else None)
    settings = Settings(mode, single(ctx, distance), single(ctx, [apertures]), f, pupil_offset, p, chosen.width_mm,
                        cocs[0], depth_unit, f_stop, max_blur, z_scale, math, size, maximum, channel)
    from camtool.core.files import FileProblem

    with library_errors(ctx):
        found = list_frames(depth)
        if not found:
            raise click.BadParameter(f"no depth images match {depth!r}", ctx=ctx, param_hint="'DEPTH'")
        try:
            rows = list(run_frames(frames=found, outputs=output_names(found, output), settings=settings,
                                   jobs=jobs or os.cpu_count() or 1, scheduler=scheduler))
        except FileProblem as problem:  # a depth file that cannot be read: named as DEPTH, exit 1
            raise click.ClickException(f"'DEPTH' {problem}") from None
    return Output(rows, COLUMNS, KEYS, f"{mode} mode · CoC {cocs[0]:.4g} mm · {chosen.label} · depths from the "
                  "entrance pupil" if fmt == "table" else "")
