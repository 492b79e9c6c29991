"""``camtool tilt``: the hinge line, the plane of sharp focus and the depth-of-field wedge of a tilted lens."""

from __future__ import annotations

import click

from camtool.cli.command import Output, camtool_command
from camtool.cli.common import f_numbers, one_value
from camtool.cli.equipment import LENS, resolve_coc, resolve_sensor
from camtool.cli.lensdata import hiatus_option, lens_data, pupil_mag_option, wavelength_option
from camtool.cli.options import (
    DISTANCE_M,
    FINITE_M,
    LENGTH_MM,
    aperture_options,
    coc_options,
    distance_plane_option,
    focal_option,
    library_errors,
    sensor_options,
)
from camtool.cli.params import AngleType, PointType, flatten
from camtool.plans.tilt import KEYS
from camtool.render.columns import Column
from camtool.render.views.common import footer
from camtool.render.views.tilt import AT_COLUMNS, COLUMNS, MODEL_COLUMN, NEED_COLUMNS, OPTIMUM_COLUMNS


@camtool_command("tilt", keys=KEYS, batch=False)
@focal_option
@aperture_options
@click.option("--tilt", "tilt", type=AngleType(), multiple=True, metavar="ANGLE", help="Lens tilt from the film plane "
              "in degrees (3, 3deg, 3°; negative tilts the other way); a list gives a row each.")
@click.option("--swing", "swing", type=AngleType(), multiple=True, metavar="ANGLE", help="Swing instead of tilt: the "
              "same geometry about the vertical axis (above/below read as the two sides).")
@click.option("--hinge", type=DISTANCE_M, multiple=True, metavar="LENGTH", help="Wanted hinge distance J, e.g. the "
              "camera's height above the ground: 1.6m (bare numbers are metres); gives the tilt asin(f/J).")
@click.option("--point", "points", type=PointType(), multiple=True,
              help="A point the plane of sharp focus must pass through, DIST@HEIGHT (metres; height above the "
                   "lens, negative below), e.g. 2m@-1.5m; give it twice to get the tilt and the focus.")
@click.option("-s", "--distance", type=DISTANCE_M, multiple=True,
              help="Focus: where the plane of sharp focus crosses the line of sight (or the lens axis with "
                   "--along axis), e.g. 5m, inf; a list gives a row each.")
@click.option("--image-distance", type=LENGTH_MM, multiple=True, metavar="LENGTH", help="Focus by the lens-to-film "
              "distance along the lens axis (rear principal point to film, mm).")
@click.option("--hyperfocal", is_flag=True, help="Focus so that the far limit of the wedge is parallel to the line "
              "of sight (or the lens axis with --along axis): sharp from the near limit plane to the horizon.")
@click.option("--at", "at", type=FINITE_M, metavar="DIST", callback=one_value,
              help="Also give the wedge's extent above and below the plane of focus (parallel to the film) at "
                   "this distance along the line of sight, e.g. 20m.")
@click.option("--half-depth", type=FINITE_M, metavar="LENGTH", callback=one_value,
              help="Wanted extent of the wedge on either side of the plane of focus at --at (parallel to the "
                   "film); gives the f-number that needs (metres, e.g. 0.5).")
@click.option("--optimum", is_flag=True, help="With --half-depth: also the f-number that balances the wedge's defocus "
              "blur against diffraction, and the blur there.")
@wavelength_option("for --optimum")
@sensor_options
@coc_options
@distance_plane_option
@click.option("--along", type=click.Choice(["sight", "axis"]), default="sight", show_default=True,
              help="Line along which focus, near, far and the hyperfocal distance are measured: the camera's "
                   "line of sight (Merklinger) or the tilted lens axis.")
@click.option("--angles-from", type=click.Choice(["film", "lens", "horizon"]), default="film", show_default=True,
              help="Plane the angles of the plane of focus and the limit planes are measured from: the film, the "
                   "lens plane, or the line of sight (the horizon with a level camera).")
@click.option("--hinge-from", type=click.Choice(["lens", "pupil"]), default="lens", show_default=True,
              help="Where J is measured from (parallel to the film): the lens (front principal point, where "
                   "J = f/sin θ holds exactly) or the entrance pupil.")
@click.option("--model", type=click.Choice(["thin", "thick", "raytrace", "auto", "all"]), default="auto", show_default=True,
              help="thin: the hinge and Scheimpflug rules with the pupils at the lens; thick: pupil magnification "
                   "and hiatus (--pupil-mag, --hiatus, --lens); raytrace: real rays through --prescription for the "
                   "plane of focus (the wedge from thick); auto: thick when lens data is known, else thin; all: "
                   "each model the inputs allow.")
@pupil_mag_option
@hiatus_option
@click.option("--prescription", "prescription_file", type=click.Path(dir_okay=False), metavar="FILE",
              help="Lens prescription (YAML, or a prescription preset's name) for --model raytrace; its focal "
                   "length, pupils and hiatus are used.")
def tilt(ctx: click.Context, focal_length, f_number, exact_stops, tilt, swing, hinge, points, distance,
         image_distance, hyperfocal, at, half_depth, optimum, wavelength, sensor, crop, coc, coc_rule, pixel_pitch,
         distance_from, along, angles_from, hinge_from, model, pupil_mag, hiatus, prescription_file, fmt, units,
         preset_files) -> Output:
    """Tilt and swing: the hinge line, the plane of sharp focus and the depth-of-field wedge.

    Forward: from -f, --tilt, -N and the focus (-s, --image-distance or
    --hyperfocal) the hinge distance J, the plane of sharp focus and the near
    and far limit planes of the wedge (where they cross the line of sight and
    their angles). Inverse: --hinge gives the tilt, two --point the tilt and
    the focus, --half-depth the f-number a wedge needs (--optimum: balanced
    against diffraction). A tilt of 0 is ordinary depth of field.

    \b
    Examples:
      camtool tilt -f 90 -N 11 -s 2m --tilt 3
      camtool tilt -f 24 -N 8 --hinge 1.6m --hyperfocal --lens ts-e-24-ii
      camtool tilt -f 90 -N 11 --point 2m@-1.6m --point 30m@-1.6m --at 30m
      camtool tilt -f 150 --tilt 7 -s 10m --at 20m --half-depth 1m --optimum --coc 0.1
      camtool tilt -f 90 -N 11 -s 3m --tilt 4 --pupil-mag 0.5 --hiatus 10 --model all
    """
    from camtool.plans import tilt as plan

    question = {"tilt_deg": flatten(tilt), "swing_deg": flatten(swing), "hinge_mm": flatten(hinge), "points": points,
                "focus_mm": flatten(distance), "image_distance_mm": flatten(image_distance), "hyperfocal": hyperfocal}
    with library_errors(ctx):  # in this order: the movement and focus, each option's value, the wedge, the lens, equipment
        plan.check_question(**question)
        question.update(at_mm=at, half_depth_mm=half_depth, optimum=optimum)
        plan.check_question(**question)
        data = lens_data(ctx, pupil_mag, hiatus, prescription_file)
        apertures = f_numbers(f_number, exact_stops)
        plan.check_lens(model=model, lens=data, focal_length_mm=flatten(focal_length), f_number=apertures,
                        half_depth_mm=question["half_depth_mm"])
        chosen = resolve_sensor(ctx, sensor, crop, preset_files)
        cocs, coc_origin = resolve_coc(ctx, list(coc), coc_rule, chosen, pixel_pitch)
        answer = plan.solve_tilt(**question, focal_length_mm=flatten(focal_length),
                                 f_number=apertures, coc_mm=cocs, wavelength_nm=wavelength,
                                 sensor_height_mm=chosen.height_mm, distance_from=distance_from, along=along,
                                 angles_from=angles_from, hinge_from=hinge_from, model=model, lens=data,
                                 lens_preset=ctx.meta.get(LENS))
    rows = [row._asdict() for row in answer.rows]
    columns: list[Column] = [MODEL_COLUMN] * (model == "all") + COLUMNS + AT_COLUMNS * (question["at_mm"] is not None)
    columns += NEED_COLUMNS * (question["half_depth_mm"] is not None) + OPTIMUM_COLUMNS * optimum
    note = " · ".join((*answer.notes, footer(None, cocs, coc_origin, chosen.label, distance_from)))
    return Output(rows, columns, plan.KEYS, note if fmt == "table" else "")

