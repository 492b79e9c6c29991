"""``camtool fov``: angle of view, and the field covered at a distance."""

from __future__ import annotations

import click

from camtool.cli.closeup import closeup_options, has_focus_model, magnification_option
from camtool.cli.command import Output, camtool_command, combine_params
from camtool.cli.common import footer, required, rows_from
from camtool.cli.equipment import resolve_sensor
from camtool.cli.lensdata import lens_geometry_options, pupil_and_hiatus
from camtool.cli.options import (
    DISTANCE_M,
    distance_plane_option,
    focal_option,
    library_errors,
    sensor_options,
)
from camtool.cli.params import flatten
from camtool.geometry.fov import view
from camtool.render.columns import ANGLE, NUMBER, SMALL, Column

KEYS = ["focal_length_mm", "horizontal_deg", "vertical_deg", "diagonal_deg", "equivalent_focal_length_mm",
        "crop_factor", "sensor_width_mm", "sensor_height_mm"]
DISTANCE_KEYS = ["distance_mm", "magnification", "field_width_mm", "field_height_mm", "distance_from"]
COLUMNS = [
    Column("focal_length_mm", "f", SMALL),
    Column("equivalent_focal_length_mm", "35mm eq.", SMALL),
    Column("horizontal_deg", "horizontal", ANGLE),
    Column("vertical_deg", "vertical", ANGLE),
    Column("diagonal_deg", "diagonal", ANGLE),
]
DISTANCE_COLUMNS = [
    Column("distance_mm", "distance"),
    Column("field_width_mm", "field width"),
    Column("field_height_mm", "field height"),
    Column("magnification", "m", NUMBER),
]


@camtool_command("fov", keys=KEYS + DISTANCE_KEYS)
@focal_option
@click.option("-s", "--distance", type=DISTANCE_M, multiple=True,
              help="Focus distance (bare numbers are metres): angles then include focus breathing, "
                   "and the field covered at that distance is shown.")
@magnification_option
@closeup_options
@sensor_options
@distance_plane_option
@lens_geometry_options
def fov(ctx: click.Context, focal_length, distance, magnification, extension, teleconverter, sensor, crop, distance_from,
        pupil_mag, hiatus, fmt, units, preset_files) -> Output:
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

    With -m the focus is set by the magnification (any m > 0): the lens sits
    f(1 + 1/m) from the subject, and the distance shown is that one (from the
    sensor, f(1 + m)²/m + hiatus). A lens preset with a published closest
    focus focuses internally, and --extension and --teleconverter change the
    lens as in dof and focus (docs/closeup.md §2, §7); the angles are then
    those of the focal length at the focus.
    """
    focal = required(ctx, focal_length, "-f")
    wanted_m = flatten(magnification)
    if wanted_m and flatten(distance):
        raise click.UsageError("give either -s/--distance or -m/--magnification, not both", ctx)
    distances = flatten(distance)
    if wanted_m or extension or teleconverter or (distances and has_focus_model(ctx)):
        return _planned(ctx, focal, wanted_m or distances or [float("inf")], bool(wanted_m), extension, teleconverter,
                        sensor, crop, distance_from, pupil_mag, hiatus, preset_files, fmt)
    chosen = resolve_sensor(ctx, sensor, crop, preset_files)
    p, delta, lens_note = pupil_and_hiatus(ctx, pupil_mag, hiatus)
    count, (f, s) = combine_params(ctx, focal, distances or [float("inf")])
    with library_errors(ctx):
        seen = view(chosen.width_mm, chosen.height_mm, f, s if distances else None, distance_from, p, delta,
                    chosen.crop_factor)
    angles = seen.angles
    values = {
        "focal_length_mm": f, "horizontal_deg": angles.horizontal_deg, "vertical_deg": angles.vertical_deg,
        "diagonal_deg": angles.diagonal_deg, "equivalent_focal_length_mm": seen.equivalent_focal_length_mm,
        "crop_factor": chosen.crop_factor, "sensor_width_mm": chosen.width_mm, "sensor_height_mm": chosen.height_mm,
    }
    keys, columns = list(KEYS), list(COLUMNS)
    if distances:
        values.update({"distance_mm": s, "magnification": seen.magnification, "field_width_mm": seen.field_width_mm,
                       "field_height_mm": seen.field_height_mm, "distance_from": distance_from})
        keys += DISTANCE_KEYS
        columns += DISTANCE_COLUMNS
    rows = rows_from(count, values)
    note = footer(None, None, "", f"{chosen.label} (crop {chosen.crop_factor:.3g})",
                  distance_from if distances else None, lens_note) if fmt == "table" else ""
    return Output(rows, columns, keys, note)


def _planned(ctx, focal, wanted, by_m, extension, teleconverter, sensor, crop, distance_from, pupil_mag, hiatus,
             preset_files, fmt) -> Output:
    """``fov -m`` (and a focus model, extension, teleconverter): the view at the lens-plane distance u = f(1 + 1/m)."""
    import numpy as np

    from camtool.cli.closeup import plan_focus

    chosen = resolve_sensor(ctx, sensor, crop, preset_files)
    p, delta, lens_note = pupil_and_hiatus(ctx, pupil_mag, hiatus)
    count, (f, w) = combine_params(ctx, focal, wanted)
    with library_errors(ctx):
        # a lens preset with a published closest focus focuses internally: its focal length at m (docs/closeup.md §2)
        ones = 1.0 if count == 1 else np.ones(count)  # no f-number here: one placeholder per row
        setting = plan_focus(ctx, f, ones, w, by_m, distance_from, delta, extension, teleconverter)
        pick = (lambda values: values[0]) if count == 1 else np.asarray
        fe, m, u = pick(setting.focal_length_mm), pick(setting.magnification), pick(setting.lens_distance_mm)
        seen = view(chosen.width_mm, chosen.height_mm, fe, u, "lens", p, delta, chosen.crop_factor)
    angles = seen.angles
    rows = rows_from(count, {
        "focal_length_mm": f * (teleconverter or 1.0), "horizontal_deg": angles.horizontal_deg,
        "vertical_deg": angles.vertical_deg,
        "diagonal_deg": angles.diagonal_deg, "equivalent_focal_length_mm": seen.equivalent_focal_length_mm,
        "crop_factor": chosen.crop_factor, "sensor_width_mm": chosen.width_mm, "sensor_height_mm": chosen.height_mm,
        "distance_mm": pick(setting.sensor_distance_mm) if distance_from == "sensor" else u, "magnification": m,
        "field_width_mm": seen.field_width_mm, "field_height_mm": seen.field_height_mm,
        "distance_from": distance_from,
    })
    note = footer(None, None, "", f"{chosen.label} (crop {chosen.crop_factor:.3g})", distance_from,
                  lens_note) if fmt == "table" else ""
    return Output(rows, list(COLUMNS) + list(DISTANCE_COLUMNS), KEYS + DISTANCE_KEYS, note)
