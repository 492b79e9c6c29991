"""``camtool fov``: angle of view, and the field covered at a distance."""

from __future__ import annotations

import click

from camtool.cli.closeup import closeup_options, magnification_option
from camtool.cli.command import Output, camtool_command, combine_params
from camtool.cli.common import required, rows_from
from camtool.cli.equipment import LENS, resolve_sensor
from camtool.cli.lensdata import lens_geometry_options, pupil_and_hiatus
from camtool.cli.options import (
    DISTANCE_M,
    distance_plane_option,
    focal_option,
    library_errors,
    projection_option,
    sensor_options,
    squeeze_option,
)
from camtool.cli.params import flatten
from camtool.cli.rows import joined
from camtool.plans.fov import field_of_view
from camtool.render.views.fov import DISTANCE_KEYS, KEYS, fov_view


@camtool_command("fov", keys=[*KEYS, "squeeze", *DISTANCE_KEYS])
@focal_option
@click.option("-s", "--distance", type=DISTANCE_M, multiple=True,
              help="Focus distance (bare numbers are metres): angles then include focus breathing, "
                   "and the field covered at that distance is shown.")
@magnification_option
@closeup_options
@sensor_options
@squeeze_option
@distance_plane_option
@lens_geometry_options
@projection_option
def fov(ctx: click.Context, focal_length, distance, magnification, extension, teleconverter, sensor, crop, squeeze,
        distance_from, pupil_mag, hiatus, projection, fmt, units, preset_files) -> Output:
    """Angle of view (horizontal, vertical, diagonal) and the field covered at a distance.

    Without -s the angles are for infinity focus, 2·atan(size / 2f). With -s the
    lens "breathes": f(1 + m/P) replaces f (P, the pupil magnification, is 1
    for a thin lens; --lens or --pupil-mag give it), and the field at the
    subject is sensor size / m.

    \b
    Examples:
      camtool fov -f 24,50,85 --sensor aps-c
      camtool fov -f 100 -s 0.5m --format json
      camtool fov -f 100 -m 0.5,1,2
      camtool fov -f 50 --camera arri-alexa-35 --squeeze 2
      camtool fov -f 8,15 --projection equisolid

    With -m the focus is set by the magnification (any m > 0): the lens sits
    f(1 + 1/m) from the subject, and the distance shown is that one (from the
    sensor, f(1 + m)²/m + hiatus). A lens preset with a published closest
    focus focuses internally, and --extension and --teleconverter change the
    lens as in dof and focus (docs/closeup.md §2, §7); the angles are then
    those of the focal length at the focus.

    A fisheye (--projection, or a lens preset's projection: equidistant
    r = fθ, equisolid r = 2f·sin(θ/2), orthographic r = f·sin θ,
    stereographic r = 2f·tan(θ/2)) covers the angle its mapping gives, at
    most its field: an 8 mm circular fisheye on full frame, 180° every way.
    The field at the subject is then 2u·tan(α/2), unbounded from 180°.
    """
    focal = required(ctx, focal_length, "-f")
    wanted_m = flatten(magnification)
    if wanted_m and flatten(distance):
        raise click.UsageError("give either -s/--distance or -m/--magnification, not both", ctx)
    wanted = wanted_m or flatten(distance)
    chosen = resolve_sensor(ctx, sensor, crop, preset_files)
    p, delta, lens_note = pupil_and_hiatus(ctx, pupil_mag, hiatus)
    count, (f, s) = combine_params(ctx, focal, wanted or [float("inf")])
    with library_errors(ctx):
        seen = field_of_view(focal_length_mm=f, sensor_width_mm=chosen.width_mm, sensor_height_mm=chosen.height_mm,
                             crop_factor=chosen.crop_factor, wanted=s if wanted else None,
                             by_magnification=bool(wanted_m), distance_from=distance_from, pupil_magnification=p,
                             hiatus_mm=delta, lens_preset=ctx.meta.get(LENS), extension_mm=extension,
                             teleconverter=teleconverter, squeeze=squeeze, projection=projection)
    columns, keys, note = fov_view(seen, table=fmt == "table", squeeze=squeeze, sensor=chosen, lens_note=lens_note,
                                   distance_from=distance_from)
    return Output(rows_from(count, seen.values), columns, keys, note, redraw=joined)
