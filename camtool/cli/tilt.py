"""``camtool tilt``: the hinge line, the plane of sharp focus and the depth-of-field wedge of a tilted lens."""

from __future__ import annotations

import itertools
import math
from typing import Any

import click

from camtool.cli.command import Output, camtool_command
from camtool.cli.common import f_numbers, footer, required
from camtool.cli.equipment import LENS, resolve_coc, resolve_sensor
from camtool.cli.lensdata import WavelengthType, hiatus_option, lens_data, pupil_mag_option
from camtool.cli.options import (
    DISTANCE_M,
    LENGTH_MM,
    aperture_options,
    coc_options,
    distance_plane_option,
    focal_option,
    library_errors,
    param_named,
    sensor_options,
)
from camtool.cli.params import flatten
from camtool.core.errors import DomainError
from camtool.core.units import UnitError, parse_length
from camtool.render.columns import ANGLE, FNUMBER, SMALL, TEXT, Column

KEYS = ["model", "movement", "focal_length_mm", "f_number", "coc_mm", "tilt_deg", "hinge_mm", "image_distance_mm",
        "focus_mm", "near_mm", "far_mm", "focus_plane_deg", "near_plane_deg", "far_plane_deg", "wedge_deg",
        "at_mm", "above_mm", "below_mm", "across_mm", "hyperfocal_mm", "hyperfocal_near_mm",
        "half_depth_mm", "f_number_needed", "f_number_optimum", "blur_optimum_mm",
        "along", "angles_from", "hinge_from", "distance_from", "hyperfocal_definition"]
COLUMNS = [
    Column("focal_length_mm", "f", SMALL),
    Column("f_number", "N", FNUMBER),
    Column("tilt_deg", "tilt", ANGLE),
    Column("hinge_mm", "hinge J"),
    Column("focus_mm", "focus"),
    Column("near_mm", "near"),
    Column("far_mm", "far"),
    Column("focus_plane_deg", "focus plane", ANGLE),
    Column("near_plane_deg", "near plane", ANGLE),
    Column("far_plane_deg", "far plane", ANGLE),
    Column("hyperfocal_mm", "hyperfocal"),
]
AT_COLUMNS = [Column("at_mm", "at"), Column("above_mm", "above"), Column("below_mm", "below")]
NEED_COLUMNS = [Column("half_depth_mm", "± wanted"), Column("f_number_needed", "needs", FNUMBER)]
OPTIMUM_COLUMNS = [Column("f_number_optimum", "optimum", FNUMBER), Column("blur_optimum_mm", "blur there", SMALL)]
MODEL_COLUMN = Column("model", "model", TEXT)

ALONG_TEXT = {"sight": "along the line of sight (the film's normal through the lens)", "axis": "along the lens axis"}
ANGLE_TEXT = {"film": "from the film plane", "lens": "from the lens plane", "horizon": "from the line of sight"}
HINGE_TEXT = {"lens": "J from the lens (front principal point), parallel to the film",
              "pupil": "J from the entrance pupil, parallel to the film"}
HYPERFOCAL_TEXT = {"sight": "far limit plane parallel to the line of sight (Merklinger)",
                   "axis": "far limit plane parallel to the lens axis"}
TILT_MAX = 89.0


class AngleType(click.ParamType):
    """Angles in degrees: ``3``, ``3deg``, ``3°``, ``-2.5``; comma-separated lists; |θ| < 89°."""

    name = "angle"

    def convert(self, value: Any, param: click.Parameter | None, ctx: click.Context | None) -> list[float]:
        if isinstance(value, list):
            return value
        out = []
        for item in str(value).split(","):
            text = item.strip().lower().replace("°", "").replace("degrees", "").replace("deg", "").strip()
            try:
                number = float(text)
            except ValueError:
                self.fail(f"{item.strip()!r} is not an angle (examples: 3, 3deg, 3°, -2.5)", param, ctx)
            if not (abs(number) <= TILT_MAX and math.isfinite(number)):
                self.fail(f"{item.strip()} is outside the valid range: -{TILT_MAX:g}° to {TILT_MAX:g}°", param, ctx)
            out.append(number)
        return out


class PointType(click.ParamType):
    """A point of the scene, ``DIST@HEIGHT``: distance along the line of sight, height above the lens (metres)."""

    name = "DIST@HEIGHT"

    def convert(self, value: Any, param: click.Parameter | None, ctx: click.Context | None) -> tuple[float, float]:
        if isinstance(value, tuple):
            return value
        text = str(value).strip()
        if text.count("@") != 1:
            self.fail(f"{text!r} is not a point: write DIST@HEIGHT, e.g. 3m@-1.6m (1.6 m below the lens)",
                      param, ctx)
        left, right = (part.strip() for part in text.split("@"))
        try:
            distance = parse_length(left, "m")
            sign = -1.0 if right.startswith("-") else 1.0
            height = sign * parse_length(right.lstrip("+-") or "x", "m")
        except UnitError as error:
            self.fail(f"{text}: {error}", param, ctx)
        if not (distance > 0 and math.isfinite(distance) and math.isfinite(height)):
            self.fail(f"{text} is outside the valid range: a finite distance > 0 and a finite height", param, ctx)
        return distance, height


@camtool_command("tilt", keys=KEYS, batch=False)
@focal_option
@aperture_options
@click.option("--tilt", "tilt", type=AngleType(), multiple=True, metavar="ANGLE",
              help="Lens tilt from the film plane in degrees (3, 3deg, 3°; negative tilts the other way); "
                   "a list gives a row each.")
@click.option("--swing", "swing", type=AngleType(), multiple=True, metavar="ANGLE",
              help="Swing instead of tilt: the same geometry about the vertical axis (above/below read "
                   "as the two sides).")
@click.option("--hinge", type=DISTANCE_M, multiple=True, metavar="LENGTH",
              help="Wanted hinge distance J, e.g. the camera's height above the ground: 1.6m (bare numbers "
                   "are metres); gives the tilt asin(f/J).")
@click.option("--point", "points", type=PointType(), multiple=True,
              help="A point the plane of sharp focus must pass through, DIST@HEIGHT (metres; height above the "
                   "lens, negative below), e.g. 2m@-1.5m; give it twice to get the tilt and the focus.")
@click.option("-s", "--distance", type=DISTANCE_M, multiple=True,
              help="Focus: where the plane of sharp focus crosses the line of sight (or the lens axis with "
                   "--along axis), e.g. 5m, inf; a list gives a row each.")
@click.option("--image-distance", type=LENGTH_MM, multiple=True, metavar="LENGTH",
              help="Focus by the lens-to-film distance along the lens axis (rear principal point to film, mm).")
@click.option("--hyperfocal", is_flag=True,
              help="Focus so that the far limit of the wedge is parallel to the line of sight (or the lens axis "
                   "with --along axis): sharp from the near limit plane to the horizon.")
@click.option("--at", "at", type=DISTANCE_M, metavar="DIST",
              help="Also give the wedge's extent above and below the plane of focus (parallel to the film) at "
                   "this distance along the line of sight, e.g. 20m.")
@click.option("--half-depth", type=DISTANCE_M, metavar="LENGTH",
              help="Wanted extent of the wedge on either side of the plane of focus at --at (parallel to the "
                   "film); gives the f-number that needs (metres, e.g. 0.5).")
@click.option("--optimum", is_flag=True,
              help="With --half-depth: also the f-number that balances the wedge's defocus blur against "
                   "diffraction, and the blur there.")
@click.option("--wavelength", type=WavelengthType(), default="550", show_default=True, metavar="NM",
              help="Wavelength for --optimum: 550, 550nm or 0.55um.")
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
@click.option("--model", type=click.Choice(["thin", "thick", "raytrace", "auto", "all"]), default="auto",
              show_default=True,
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
    movement = "swing" if swing else "tilt"
    if swing and tilt:
        raise click.UsageError("give --tilt or --swing, not both", ctx)
    focus_ways = sum(bool(x) for x in (distance, image_distance, hyperfocal, len(points) == 2))
    if focus_ways > 1:
        raise click.UsageError("give one focus: -s, --image-distance, --hyperfocal or two --point", ctx)
    if points and len(points) != 2:
        raise click.BadParameter(f"{len(points)} points given: give exactly two", ctx=ctx,
                                 param=param_named(ctx, "points"))
    angles = flatten(swing or tilt)
    hinges = flatten(hinge)
    if points and (angles or hinges):
        raise click.UsageError("two --point set the tilt themselves: drop --tilt/--swing/--hinge", ctx)
    if angles and hinges:
        raise click.UsageError("give --tilt (or --swing) or --hinge, not both", ctx)
    if not (angles or hinges or points):
        raise click.UsageError("Missing option '--tilt' (or --swing, --hinge, or two --point).", ctx)
    at = _single(ctx, at, "at")
    half_depth = _single(ctx, half_depth, "half_depth")
    if (half_depth is not None or optimum) and at is None:
        raise click.UsageError("--half-depth needs --at (the distance where the wedge must reach that far)", ctx)
    if optimum and half_depth is None:
        raise click.UsageError("--optimum needs --half-depth (the wedge to balance against diffraction)", ctx)
    data = lens_data(ctx, pupil_mag, hiatus, prescription_file)
    lenses = _models(ctx, model, data)
    if data is not None and data.prescription is not None:
        with library_errors(ctx):
            from camtool.dof.ladder import prescription_focal_length

            given: list[float | None] = list(flatten(focal_length)) or [None]
            focal = [prescription_focal_length(data, f) for f in given]
    else:
        focal = required(ctx, focal_length, "-f")
    apertures = f_numbers(f_number, exact_stops)
    if not apertures and half_depth is None:
        raise click.UsageError("Missing option '-N' (or --half-depth with --at to get the f-number).", ctx)
    chosen = resolve_sensor(ctx, sensor, crop, preset_files)
    cocs, coc_origin = resolve_coc(ctx, list(coc), coc_rule, chosen, pixel_pitch)
    settings = angles or hinges or [math.nan]
    focuses: list[Any] = flatten(distance) or flatten(image_distance) or [None]
    scenes = list(itertools.product(focal, apertures or [math.nan], cocs, settings,
                                    [math.nan if v is None else v for v in focuses]))
    limit = _tilt_limit(ctx)
    conventions = {"along": along, "angles_from": angles_from, "hinge_from": hinge_from,
                   "distance_from": distance_from, "hyperfocal_definition": HYPERFOCAL_TEXT[along]}
    rows: list[dict[str, Any]] = []
    for f, n, c, setting, focus in scenes:
        for name, lens in lenses:
            row = _scene(ctx, name, lens, data, f, n, c, setting, bool(angles), points, focus,
                         "image" if image_distance else "distance" if distance else
                         "hyperfocal" if hyperfocal else "points" if points else None,
                         at, half_depth, optimum, wavelength, chosen, limit, conventions)
            row["movement"] = movement
            rows.append(row)
    columns: list[Column] = list(COLUMNS)
    if at is not None:
        columns += AT_COLUMNS
    if half_depth is not None:
        columns += NEED_COLUMNS
    if optimum:
        columns += OPTIMUM_COLUMNS
    if model == "all":
        columns.insert(0, MODEL_COLUMN)
    note = ""
    if fmt == "table":
        used = " / ".join(dict.fromkeys(str(r["model"]) for r in rows))
        parts = [f"{used} model", f"{movement} θ and angles {ANGLE_TEXT[angles_from]}", HINGE_TEXT[hinge_from],
                 f"focus, near, far {ALONG_TEXT[along]}", f"hyperfocal: {HYPERFOCAL_TEXT[along]}"]
        if any(r["tilt_deg"] == 0 for r in rows):
            parts.append("no tilt: the wedge is ordinary depth of field (hinge at infinity)")
        if at is not None:
            parts.append("above/below: the wedge either side of the plane of focus, parallel to the film")
        if any(str(r["model"]) == "raytrace" for r in rows):
            parts.append("raytrace: film at the real focus, plane of focus by real rays across the picture's height, "
                         + ("wedge along the axis by real rays" if along == "axis" else "wedge from thick"))
        note = " · ".join(parts) + " · " + footer(None, cocs, coc_origin, chosen.label, distance_from)
    return Output(rows, columns, KEYS, note)


def _single(ctx: click.Context, values: Any, name: str) -> float | None:
    """The one value of a length option that takes no list."""
    flat = flatten([values]) if values else []
    if len(flat) > 1:
        raise click.BadParameter(f"{len(flat)} values given: give one", ctx=ctx, param=param_named(ctx, name))
    if flat and math.isinf(flat[0]):
        raise click.BadParameter("inf is outside the valid range: a finite distance", ctx=ctx,
                                 param=param_named(ctx, name))
    return flat[0] if flat else None


def _models(ctx: click.Context, model: str, data: Any) -> list[tuple[str, Any]]:
    """(name, TiltLens factory input) per model row: thin always, thick with lens data, raytrace with a prescription."""
    thick = data is not None and data.thick_parameters() is not None
    traced = data is not None and data.prescription is not None
    if model == "raytrace" and not traced:
        raise click.BadParameter("raytrace is not available here: it needs --prescription (or a --lens with one)",
                                 ctx=ctx, param=param_named(ctx, "model"))
    if model == "auto":
        return [("thick", True)] if thick else [("thin", False)]
    if model == "all":
        return [("thin", False)] + ([("thick", True)] if thick else []) + ([("raytrace", True)] if traced else [])
    return [(model, model != "thin")]


def _tilt_limit(ctx: click.Context) -> float | None:
    """The tilt range (±degrees) of the --lens preset, if it records one (key ``tilt_max_deg``)."""
    lens = ctx.meta.get(LENS)
    if lens is None:
        return None
    value = getattr(lens, "tilt_max_deg", None)
    return None if value is None else float(value)


def _tilt_lens(data: Any, f: float, thick: bool) -> Any:
    from camtool.dof.tilt import TiltLens

    if not thick or data is None:
        return TiltLens(f)
    p, delta = data.thick_parameters()
    return TiltLens(f, float(p), float(delta))


def _scene(ctx: click.Context, model: str, thick: bool, data: Any, f: float, n: float, c: float, setting: float,
           is_angle: bool, points: tuple[tuple[float, float], ...], focus: float, how: str | None,
           at: float | None, half_depth: float | None, optimum: bool, wavelength: float, sensor: Any,
           limit: float | None, conventions: dict[str, str]) -> dict[str, Any]:
    from camtool.dof import tilt as model_lib

    lens = _tilt_lens(data, f, thick)
    along, distance_from = conventions["along"], conventions["distance_from"]
    with library_errors(ctx):
        try:
            if points:
                try:
                    theta, v0 = _from_points(lens, points, distance_from)
                except DomainError as error:
                    typed = " and ".join(f"{x / 1000:g} m@{h / 1000:g} m" for x, h in points)
                    raise DomainError("point", typed, error.valid) from None
                option = "points"
            elif is_angle:
                theta, v0, option = setting, None, "swing" if ctx.params.get("swing") else "tilt"
            else:
                theta, v0, option = _tilt_for_hinge(lens, setting, conventions["hinge_from"]), None, "hinge"
        except DomainError as error:
            _raise(ctx, error)
        if limit is not None and abs(theta) > limit * (1 + 1e-9):
            lens_name = ctx.meta[LENS].id
            raise click.BadParameter(f"{theta:.3g}° is outside the valid range of --lens {lens_name}: "
                                     f"±{limit:g}°", ctx=ctx, param=param_named(ctx, option))
        if v0 is None and how is not None:
            try:
                if how == "image":
                    if focus < f:
                        raise DomainError("film_mm", focus, "at least the focal length, {limit} (focus at "
                                          "infinity along the axis)", limit=f)
                    v0 = focus * _cos(theta)
                elif how == "distance":
                    v0 = model_lib.film_for_focus(lens, theta, focus, along, distance_from)
                elif how == "hyperfocal":
                    if not math.isfinite(n):
                        raise click.UsageError("--hyperfocal needs -N", ctx)
                    v0 = model_lib.hyperfocal_film(lens, n, c, theta, along)
            except DomainError as error:
                _raise(ctx, error)
        row: dict[str, Any] = {"model": model, "focal_length_mm": f, "f_number": n if math.isfinite(n) else None,
                               "coc_mm": c, "tilt_deg": theta, **conventions}
        # a hinge given is reported as given (not through asin and back)
        row["hinge_mm"] = setting if option == "hinge" else abs(_hinge_from(lens, theta, conventions["hinge_from"]))
        for key in ("image_distance_mm", "focus_mm", "near_mm", "far_mm", "focus_plane_deg", "near_plane_deg",
                    "far_plane_deg", "wedge_deg", "at_mm", "above_mm", "below_mm", "across_mm", "hyperfocal_mm",
                    "hyperfocal_near_mm", "half_depth_mm", "f_number_needed", "f_number_optimum",
                    "blur_optimum_mm"):
            row[key] = None
        if v0 is None:
            return row
        try:
            _fill(ctx, row, model_lib, lens, n, c, theta, v0, at, half_depth, optimum, wavelength, conventions)
        except DomainError as error:
            _raise(ctx, error)
        if model == "raytrace":
            _traced(ctx, row, data, lens, theta, v0, sensor, conventions)
    return row


def _raise(ctx: click.Context, error: DomainError) -> None:
    """A library error on the option the user typed."""
    from camtool.cli.options import domain_message

    name = {"point": "points", "hinge_mm": "hinge", "tilt_deg": "tilt", "film_mm": "image_distance",
            "half_depth_mm": "half_depth", "pupil_magnification": "pupil_mag", "hiatus_mm": "hiatus",
            "coc_mm": "coc", "f_number": "f_number", "distance_mm": "distance",
            "focal_length_mm": "focal_length"}.get(error.param, error.param)
    if name == "coc" and not ctx.params.get("coc"):
        name = "f_number"
    raise click.BadParameter(domain_message(error, name), ctx=ctx, param=param_named(ctx, name)) from None


def _cos(theta: float) -> float:
    return math.cos(math.radians(theta))


def _pupil_y(lens: Any, theta: float) -> float:
    """Height (y) of the entrance pupil above H's line of sight: e·sin θ."""
    return lens.entrance_pupil_mm * math.sin(math.radians(theta))


def _hinge_from(lens: Any, theta: float, hinge_from: str) -> float:
    from camtool.geometry.tilt import hinge_distance_mm

    j = hinge_distance_mm(lens.focal_length_mm, theta)
    return j - _pupil_y(lens, theta) if hinge_from == "pupil" and math.isfinite(j) else j


def _tilt_for_hinge(lens: Any, hinge: float, hinge_from: str) -> float:
    """Tilt for a hinge J from the lens (asin(f/J)) or from the entrance pupil (e·s² + J·s − f = 0)."""
    from camtool.geometry.tilt import tilt_for_hinge_deg

    e = lens.entrance_pupil_mm
    if hinge_from == "lens" or e == 0 or math.isinf(hinge):
        return float(tilt_for_hinge_deg(lens.focal_length_mm, hinge))
    f = lens.focal_length_mm
    disc = hinge * hinge + 4.0 * e * f
    sin = (-hinge + math.sqrt(disc)) / (2.0 * e) if disc >= 0 else 2.0
    if not 0 < sin <= 1:
        raise DomainError("hinge_mm", hinge, "far enough from the entrance pupil for a tilt below 90°")
    return math.degrees(math.asin(sin))


def _from_points(lens: Any, points: tuple[tuple[float, float], ...], distance_from: str) -> tuple[float, float]:
    """Tilt and film distance v for the plane through two points (from the sensor: iterate the lens position)."""
    from camtool.geometry.tilt import plane_through_points

    f = lens.focal_length_mm
    shift = 0.0
    solution = None
    for _ in range(60 if distance_from == "sensor" else 1):
        (x1, h1), (x2, h2) = points
        solution = plane_through_points(f, x1 - shift, -h1, x2 - shift, -h2)
        cos = _cos(solution.tilt_deg)
        v0 = 1.0 / (cos / f - solution.reciprocal_mm)
        new_shift = v0 + lens.hiatus_mm * cos
        if abs(new_shift - shift) < 1e-12 * max(1.0, new_shift):
            break
        shift = new_shift
    assert solution is not None
    cos = _cos(solution.tilt_deg)
    return solution.tilt_deg, 1.0 / (cos / f - solution.reciprocal_mm)


def _fill(ctx: click.Context, row: dict[str, Any], lib: Any, lens: Any, n: float, c: float, theta: float, v0: float,
          at: float | None, half_depth: float | None, optimum: bool, wavelength: float,
          conventions: dict[str, str]) -> None:
    """The wedge's distances and angles in the conventions asked for."""
    f = lens.focal_length_mm
    cos = _cos(theta)
    along, sensor = conventions["along"], conventions["distance_from"] == "sensor"

    def distance(k: float) -> float:
        return _distance_at(f, theta, k, v0, lens, along, sensor)

    def angle(phi: float) -> float:
        return {"film": phi, "lens": phi - theta, "horizon": 90.0 - phi}[conventions["angles_from"]]

    row["image_distance_mm"] = v0 / cos
    plane = lib.tilt_wedge(lens, n, c, theta, v0) if math.isfinite(n) else None
    # the focus needs no f-number
    k_focus = cos / f - 1.0 / v0
    row["focus_mm"] = distance(k_focus)
    from camtool.geometry.tilt import plane_angle_deg

    row["focus_plane_deg"] = angle(float(plane_angle_deg(f, theta, k_focus)))
    sight_offset = v0 + lens.hiatus_mm * cos if sensor else 0.0
    at_h = None
    if at is not None:
        at_h = at - sight_offset
        if not at_h > 0:
            raise click.BadParameter(f"{at / 1000:.4g} m is outside the valid range: beyond the lens "
                                     f"({sight_offset / 1000:.4g} m from the sensor)", ctx=ctx,
                                     param=param_named(ctx, "at"))
        row["at_mm"] = at
    if half_depth is not None and at_h is not None:
        row["half_depth_mm"] = half_depth
        if theta == 0:
            raise click.BadParameter("needs a tilt: with none the wedge is a slab parallel to the film, "
                                     "unbounded above and below", ctx=ctx, param=param_named(ctx, "half_depth"))
        needed = lib.required_f_number(lens, c, theta, v0, at_h, half_depth)
        row["f_number_needed"] = needed
        if optimum:
            m = abs(f / (1.0 / (1.0 / f - 1.0 / (v0 / cos)) - f)) if v0 / cos > f else 0.0
            best, blur = lib.optimum_f_number(needed, c, wavelength, m, lens.pupil_magnification)
            row["f_number_optimum"], row["blur_optimum_mm"] = best, blur
        if not math.isfinite(n):
            n = needed
            row["f_number"] = needed
            plane = lib.tilt_wedge(lens, n, c, theta, v0)
    if plane is None:
        return
    row["near_mm"], row["far_mm"] = distance(plane.k_near), distance(plane.k_far)
    row["near_plane_deg"], row["far_plane_deg"] = angle(plane.near_deg), angle(plane.far_deg)
    row["wedge_deg"] = abs(plane.near_deg - plane.far_deg)
    if at_h is not None:
        s = math.sin(math.radians(abs(theta)))
        if s == 0:
            row["above_mm"] = row["below_mm"] = math.inf
            row["across_mm"] = (1.0 / plane.k_far if plane.k_far > 0 else math.inf) - 1.0 / plane.k_near
        else:
            row["above_mm"] = f / s * at_h * (plane.k_near - plane.k_focus)
            row["below_mm"] = f / s * at_h * (plane.k_focus - plane.k_far)
            row["across_mm"] = sum(f * at_h * abs(plane.k_focus - k) / math.hypot(s, f * k)
                                   for k in (plane.k_near, plane.k_far))
    v_h = lib.hyperfocal_film(lens, n, c, theta, along)
    hyper = lib.tilt_wedge(lens, n, c, theta, v_h)
    # distances of the hyperfocal setting: its own lens-to-film spacing
    row["hyperfocal_mm"] = _distance_at(f, theta, hyper.k_focus, v_h, lens, along, sensor)
    row["hyperfocal_near_mm"] = _distance_at(f, theta, hyper.k_near, v_h, lens, along, sensor)


def _distance_at(f: float, theta: float, k: float, v0: float, lens: Any, along: str, sensor: bool) -> float:
    from camtool.geometry.tilt import axis_reciprocal

    cos = _cos(theta)
    recip = axis_reciprocal(f, theta, k) if along == "axis" else k
    if recip <= 1e-13 / f:  # parallel to the line (to rounding) or crossing it behind the lens
        return math.inf
    offset = (v0 / cos + lens.hiatus_mm if along == "axis" else v0 + lens.hiatus_mm * cos) if sensor else 0.0
    return 1.0 / recip + offset


def _traced(ctx: click.Context, row: dict[str, Any], data: Any, lens: Any, theta: float, v0: float, sensor: Any,
            conventions: dict[str, str]) -> None:
    """Real rays: the film at the real best focus of the point where the plane of focus crosses the lens axis;
    the plane of focus through the picture's top and bottom edges; the wedge along the axis by the raytrace rung."""
    from camtool.dof.ladder import depth_of_field
    from camtool.dof.realray import real_focus
    from camtool.optics.tilted import traced_plane_of_focus
    from camtool.optics.tracer import RayTraceError

    f = lens.focal_length_mm
    cos = _cos(theta)
    n, c = row["f_number"], row["coc_mm"]
    z_hp = data.first_order.z_h_prime_mm
    axis_focus = 1.0 / (1.0 / f - cos / v0) if v0 > f * cos else math.inf
    sensor_plane = conventions["distance_from"] == "sensor"
    try:
        if n is not None:
            v0 = (real_focus(data.prescription, n, axis_focus, "lens").film_z_mm - z_hp) * cos
        k_model = cos / f - 1.0 / v0
        field = math.degrees(math.atan(sensor.height_mm / 2.0 / v0))
        traced = traced_plane_of_focus(data.prescription, theta, v0, k_model, field_deg=field)
        if n is not None and conventions["along"] == "axis":
            limits = depth_of_field("raytrace", f, n, c, axis_focus, "lens", lens=data).limits
            offset = (v0 / cos + lens.hiatus_mm) if sensor_plane else 0.0
            row["near_mm"], row["far_mm"] = limits.near_mm + offset, limits.far_mm + offset
    except RayTraceError as error:
        raise click.ClickException(str(error)) from None
    except DomainError as error:
        _raise(ctx, error)
    row["image_distance_mm"] = v0 / cos
    row["focus_mm"] = _traced_distance(traced, f, theta, v0, lens, conventions["along"], sensor_plane)
    phi = traced.focus_deg
    row["focus_plane_deg"] = {"film": phi, "lens": phi - theta, "horizon": 90.0 - phi}[conventions["angles_from"]]
    j = abs(traced.hinge_mm)
    if conventions["hinge_from"] == "pupil" and math.isfinite(j):
        j = abs(traced.hinge_mm - _pupil_y(lens, theta))
    row["hinge_mm"] = j


def _traced_distance(traced: Any, f: float, theta: float, v0: float, lens: Any, along: str, sensor: bool) -> float:
    """Where the traced plane crosses the line of sight (or the lens axis) in the plane asked for."""
    cos = _cos(theta)
    if along == "sight":
        k = traced.k_focus
        if not k > 0:
            return math.inf
        return 1.0 / k + ((v0 + lens.hiatus_mm * cos) if sensor else 0.0)
    # the traced line through (0, J) and (1/k, 0) met by t·(cos θ, sin θ)
    j, k = traced.hinge_mm, traced.k_focus
    s = math.sin(math.radians(theta))
    denominator = s + j * k * cos
    if not (math.isfinite(j) and denominator * j > 0):
        return math.inf
    return j / denominator + ((v0 / cos + lens.hiatus_mm) if sensor else 0.0)
