"""``camtool stack``: the frames of a focus stack, on a macro rail (-m, --depth) or by the focus ring (--near, --far)."""

from __future__ import annotations

import math
from typing import Any

import click

from camtool.cli.closeup import MAGNIFICATION, focus_models, has_focus_model
from camtool.cli.command import GRID, MAX_TABLE_ROWS, Output, camtool_command
from camtool.cli.common import f_numbers, flatten, footer, one_value, required
from camtool.cli.equipment import resolve_coc, resolve_sensor
from camtool.cli.grid import CHUNK
from camtool.cli.lensdata import ladder_errors, lens_data, model_options, pupil_and_hiatus
from camtool.cli.options import (
    DISTANCE_M,
    FOCAL_MM,
    LENGTH_MM,
    coc_options,
    distance_plane_option,
    domain_message,
    library_errors,
    param_named,
    sensor_options,
)
from camtool.cli.params import FNumberType, NumberType
from camtool.dof.ladder import focal_lengths, model_choices, model_help
from camtool.render.columnar import ColumnRows
from camtool.render.columns import NUMBER, TEXT, Column

KEYS = ["frame", "distance_mm", "near_mm", "far_mm", "magnification", "step_mm", "extension_step_mm",
        "criterion", "mode", "distance_from"]
COLUMNS = [
    Column("frame", "frame", TEXT),
    Column("distance_mm", "focus"),
    Column("near_mm", "near"),
    Column("far_mm", "far"),
    Column("magnification", "m", NUMBER),
    Column("step_mm", "step"),
]
DEFAULT_OVERLAP = 0.2
"""A fifth of each frame's depth shared with the next: margin for rail and focus-ring error."""
MAX_FRAMES = 10_000
"""The most frames a bracketing plan may have on the command line (thin and approx models, in closed form)."""
SOLVED_FRAMES = {"thick": 2_000, "paraxial": 2_000, "raytrace": 250}
"""The most frames of a plan whose every frame is solved numerically through a rung of the model ladder.

Each frame there costs many evaluations of the model (a few ms for thick and
paraxial, some 40 ms for raytrace), so the plan is bounded in time as well
as in frames: about ten seconds at most on one core.
"""
WAVE_FROM = 1.0
"""From this magnification on (life size), the default criterion is the wave-optics depth."""


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
@click.option("--criterion", type=click.Choice(["classic", "wave"]), default=None,
              help="Depth per frame: classic (the CoC) or wave (quarter-wave λ/NA², what macro stackers use). "
                   "Default: wave from 1:1 (-m 1) up, classic below and for bracketing.")
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
    error on --near (2000 with thick or paraxial, 250 with raytrace, which
    solve each frame numerically). A rail plan streams (JSON, CSV, --field) up
    to 10⁷ frames; a table holds at most 100000.
    """
    apertures = required(ctx, f_numbers(f_number, exact_stops), "-N")
    n = _one(ctx, apertures, "-N", "f_number")
    wanted_m = flatten(magnification)
    rail = bool(wanted_m) or depth is not None
    if rail and (near is not None or far is not None):
        raise click.UsageError("give -m and --depth (rail) or --near and --far (bracketing), not both", ctx)
    chosen = resolve_sensor(ctx, sensor, crop, preset_files)
    cocs, coc_origin = resolve_coc(ctx, list(coc), coc_rule, chosen, pixel_pitch)
    c = float(cocs[0])
    lens = lens_data(ctx, pupil_mag, hiatus, prescription_file)
    p = pupil_and_hiatus(ctx, pupil_mag, hiatus)[0]
    if rail:
        if depth is None:
            raise click.UsageError("Missing option '--depth' (the subject depth for rail mode).", ctx)
        if not wanted_m:
            raise click.UsageError("Missing option '-m' (the magnification for rail mode).", ctx)
        m = _one(ctx, wanted_m, "-m", "magnification")
        _check_magnification(ctx, m)
        if model in ("paraxial", "raytrace"):
            raise click.BadParameter(f"{model} is not available in rail mode: the frames use the close-up closed "
                                     "form (thin, or thick with the pupil magnification); it applies to --near/--far",
                                     ctx=ctx, param=param_named(ctx, "model"))
        focal = flatten(focal_length)
        f = _one(ctx, focal, "-f", "focal_length") if focal else None
        chosen_criterion = criterion or ("wave" if m >= WAVE_FROM else "classic")
        return _rail(ctx, float(depth), n, m, chosen_criterion, c, float(overlap), p, wavelength, f, diffraction,
                     fmt, cocs, coc_origin, chosen.label, distance_from)
    if near is None or far is None:
        raise click.UsageError("give -m and --depth (rail mode) or --near and --far (bracketing mode)", ctx)
    with library_errors(ctx):
        focal = required(ctx, focal_lengths(lens, flatten(focal_length)), "-f")
    f = _one(ctx, focal, "-f", "focal_length")
    chosen_criterion = criterion or "classic"
    return _bracket(ctx, f, n, c, float(near), float(far), float(overlap), chosen_criterion, model, lens, p,
                    wavelength, diffraction, tolerance, distance_from, fmt, cocs, coc_origin, chosen.label)


def _usable(ctx: click.Context, n: float, c: float, m: float, p: float, wavelength: float) -> float:
    """The CoC left for defocus by the Airy disc, or a one-line error on -N when nothing is sharp."""
    from camtool.dof.closeup import diffraction_row

    d = diffraction_row(n, c, m, p, wavelength)
    if not d.sharp:
        raise click.BadParameter(f"f/{n:g} is outside the valid range: below f/{d.limit_f_number:.3g} (the Airy disc, "
                                 f"{d.airy_mm:.3g} mm, fills the CoC {c:.3g} mm: nothing is sharp)",
                                 ctx=ctx, param=param_named(ctx, "f_number"))
    return float(d.usable_coc_mm)


def _rail(ctx, depth, n, m, criterion, c, overlap, p, wavelength, f, diffraction, fmt, cocs, coc_origin,
          sensor_label, distance_from) -> Output:
    """The rail plan's frames, or the current chunk of them: a long plan is written a chunk at a time."""
    from camtool.core.errors import DomainError
    from camtool.dof.stack import rail_plan

    if diffraction and criterion == "classic":
        c = _usable(ctx, n, c, m, p, wavelength)
    with library_errors(ctx):
        try:
            plan = rail_plan(depth, n, m, criterion, c, overlap, p, wavelength, f)
        except DomainError as error:
            if error.param != "depth_mm":
                raise
            raise click.BadParameter(domain_message(error, "depth"), ctx=ctx, param=param_named(ctx, "depth")) \
                from None
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
    rows = _rail_rows(plan, m, start, stop)
    note = ""
    if fmt == "table":
        frame_depth = plan.front_mm + plan.rear_mm
        what = (f"{criterion} depth " + ("λ/NA²" if criterion == "wave" else f"(CoC {c:.3g} mm, {coc_origin})"))
        if math.isinf(plan.rear_mm):
            note = (f"1 frame · sharp from {plan.front_mm:.4g} mm in front of its focus to infinity behind it "
                    f"(the subject at {m:g}× is at or beyond the hyperfocal distance): it covers any depth · "
                    f"total depth {depth:.4g} mm · {what} · positions along the subject from its nearest point")
        else:
            note = (f"{plan.frames} frames · step {plan.step_mm:.4g} mm at the subject ({plan.extension_step_mm:.4g} "
                    f"mm of lens extension) · total depth {depth:.4g} mm · {what} · frame depth {frame_depth:.4g} mm, "
                    f"overlap {overlap:g} · positions along the subject from its nearest point")
    return Output(rows, COLUMNS, KEYS, note)


def _rail_rows(plan: Any, m: float, start: int, stop: int) -> ColumnRows:
    """Frames ``start + 1`` to ``stop`` of a rail plan, as columns: frame k's near limit is (k − 1)·step.

    A plan of more than one chunk is computed as arrays (the writer turns a
    float array into text in one pass); the values are the same products
    k·step either way.
    """
    count = max(0, stop - start)
    front, depth = plan.front_mm, plan.front_mm + plan.rear_mm
    step: Any
    extension: Any
    if math.isinf(plan.step_mm):  # one frame, sharp to infinity behind its focus: no step
        near: Any = [0.0] * count
        step = extension = [0.0] * count
        focus: Any = [front] * count
        far: Any = [math.inf] * count
    elif plan.frames <= CHUNK:
        near = [k * plan.step_mm for k in range(start, stop)]
        step, extension = [plan.step_mm] * count, [plan.extension_step_mm] * count
        if start == 0 and count:
            step[0] = extension[0] = 0.0
        focus, far = [x + front for x in near], [x + depth for x in near]
    else:
        import numpy as np

        near = np.arange(start, stop, dtype=np.float64) * plan.step_mm
        step, extension = np.full(count, plan.step_mm), np.full(count, plan.extension_step_mm)
        if start == 0:
            step[0] = extension[0] = 0.0
        focus, far = near + front, near + depth
    columns = {"frame": list(range(start + 1, stop + 1)), "distance_mm": focus, "near_mm": near, "far_mm": far,
               "magnification": float(m), "step_mm": step, "extension_step_mm": extension,
               "criterion": plan.criterion, "mode": "rail", "distance_from": "subject"}
    return ColumnRows(count, columns)


def _bracket(ctx, f, n, c, near, far, overlap, criterion, model, lens, p, wavelength, diffraction, tolerance,
             distance_from, fmt, cocs, coc_origin, sensor_label) -> Output:
    from camtool.dof.stack import bracket_plan, wave_coc_mm

    if criterion == "wave":
        c = float(wave_coc_mm(n, 0.0, p, wavelength))
    elif diffraction:
        c = _usable(ctx, n, c, 0.0, p, wavelength)
    delta = float(lens.hiatus_mm) if lens is not None and lens.hiatus_mm is not None else 0.0
    rung = _rung(model, lens)
    focusing = focus_models(ctx)(f) if has_focus_model(ctx) else None
    limits = hyper = None
    if focusing is not None:  # the lens focuses internally: each frame at its own focal length, as dof has it
        from camtool.dof.stack import internal_bracket_plan

        if focusing.min_magnification > 0.0:
            raise click.BadParameter(
                f"{ctx.params.get('lens')} is outside the valid range: a lens that focuses to infinity (this one "
                f"works from {focusing.min_magnification:g}× to {focusing.max_magnification:g}×: stack it on a rail "
                "with -m and --depth)", ctx=ctx, param=param_named(ctx, "lens"))

        by_rung = None if rung in ("thin", "approx") else _ladder_limits_at(ctx, rung, n, c, lens, tolerance)
        with library_errors(ctx):
            if by_rung is not None:
                _bounded(ctx, rung, lambda most: internal_bracket_plan(focusing, n, c, near, far, overlap, "thin",
                                                                       most, None, distance_from))
            plan = internal_bracket_plan(focusing, n, c, near, far, overlap, rung, _most_frames(rung), by_rung,
                                         distance_from)
    else:
        if rung not in ("thin", "approx"):
            with library_errors(ctx):
                _bounded(ctx, rung, lambda most: bracket_plan(f, n, c, near, far, overlap, "thin", most, None, None,
                                                              distance_from, delta))
            limits, hyper = _ladder_limits(ctx, rung, f, n, c, lens, tolerance)
        with library_errors(ctx):
            plan = bracket_plan(f, n, c, near, far, overlap, rung, _most_frames(rung), limits, hyper, distance_from,
                                delta)
        _check_closest_focus(ctx, plan.frames[0].distance_mm, f, distance_from, delta)
    rows = []
    previous = None
    for k, frame in enumerate(plan.frames, 1):
        rows.append({"frame": k, "distance_mm": frame.distance_mm, "near_mm": frame.near_mm,
                     "far_mm": frame.far_mm, "magnification": frame.magnification,
                     "step_mm": 0.0 if previous is None else frame.distance_mm - previous, "extension_step_mm": None,
                     "criterion": criterion, "mode": "bracket", "distance_from": distance_from})
        previous = frame.distance_mm
    note = ""
    if fmt == "table":
        what = f"{criterion} depth" + (" (λ/NA², as a CoC of 2λN)" if criterion == "wave" else "")
        end = "∞" if math.isinf(far) else f"{far / 1000:.4g} m"
        if focusing is not None:
            focal = [focusing.focal_length_mm / (1.0 + focusing.kappa * r["magnification"]) for r in rows]
            what += f" · the lens focuses internally: f {min(focal):.4g} to {max(focal):.4g} mm"
        note = (f"{len(rows)} frames · {near / 1000:.4g} m to {end} · {what} · {rung} model · overlap {overlap:g} · "
                + footer(None, cocs if criterion == "classic" else None, coc_origin, sensor_label, distance_from))
    return Output(rows, COLUMNS, KEYS, note)


def _most_frames(rung: str) -> int:
    """The most frames of a bracketing plan by this model: fewer where each frame is solved numerically."""
    return SOLVED_FRAMES.get(rung, MAX_FRAMES)


def _bounded(ctx: click.Context, rung: str, thin_plan: Any) -> None:
    """Refuse at once a plan the thin lens puts past the ``rung``'s frame limit, before solving any frame by it.

    The thin lens's frames (closed form, a few µs each) stand in for the
    count: a plan whose every frame is solved through a numerical rung takes
    milliseconds a frame, so one far beyond the limit is refused without
    spending seconds to find out. A count near the limit is settled by the
    rung's own plan, which stops at the same limit.
    """
    from camtool.core.errors import DomainError

    most = _most_frames(rung)
    try:
        thin_plan(most + most // 10)  # a margin: the rung's own count may be a little lower
    except DomainError as error:
        if error.param == "near_mm" and "frames" in error.detail:
            near = float(ctx.params.get("near") or 0.0)
            raise click.BadParameter(
                f"{near / 1000:.4g} m is outside the valid range: far enough that at most {most} frames reach "
                f"--far with the {rung} model (it solves each frame numerically; the thin and approx models plan up "
                f"to {MAX_FRAMES})", ctx=ctx, param=param_named(ctx, "near")) from None
        # any other error is the rung's own to report


def _check_closest_focus(ctx: click.Context, first: float, f: float, plane: str, delta: float) -> None:
    """A one-line error on --near when frame 1 would focus closer than the --lens preset's closest focus."""
    from camtool.cli.equipment import LENS

    preset = ctx.meta.get(LENS)
    closest = getattr(preset, "min_focus_mm", None)
    if not closest or getattr(preset, "is_zoom", False):
        return
    sensor = first if plane == "sensor" else first + f * first / (first - f) + delta
    if sensor < closest * (1.0 - 1e-9):
        near = float(ctx.params.get("near") or first)
        raise click.BadParameter(f"{near / 1000:.4g} m is outside the valid range: frame 1 would focus at "
                                 f"{sensor / 1000:.4g} m from the sensor, closer than the lens's closest focus "
                                 f"({closest / 1000:.4g} m); give a farther --near", ctx=ctx,
                                 param=param_named(ctx, "near"))


def _check_magnification(ctx: click.Context, m: float) -> None:
    """A one-line error on -m beyond the --lens preset's published largest magnification."""
    from camtool.cli.equipment import LENS

    largest = getattr(ctx.meta.get(LENS), "max_magnification", None)
    if largest and m > largest * (1.0 + 1e-9):
        raise click.BadParameter(f"{m:g} is outside the valid range: 0 to {largest:g} (the lens's largest "
                                 "magnification)", ctx=ctx, param=param_named(ctx, "magnification"))


def _rung(model: str, lens: Any) -> str:
    if model != "auto":
        return model
    if lens is None:
        return "thin"
    return "raytrace" if lens.prescription is not None else "thick"


def _ladder_limits_at(ctx: click.Context, rung: str, n: float, c: float, lens: Any,
                      tolerance: float) -> Any:
    """(f, u) -> (near, far) from the lens by one rung of the ladder, for a lens whose focal length changes."""
    from camtool.dof.ladder import depth_of_field

    def limits(f: float, u: float) -> tuple[float, float]:
        with library_errors(ctx), ladder_errors(ctx):
            r = depth_of_field(rung, f, n, c, u, "lens", lens, False, 550.0, tolerance).limits
        return float(r.near_mm), float(r.far_mm)

    return limits


def _ladder_limits(ctx: click.Context, rung: str, f: float, n: float, c: float, lens: Any,
                   tolerance: float) -> tuple[Any, float]:
    """u -> (near, far) from the lens by one rung of the ladder, and that rung's hyperfocal distance."""
    from camtool.dof.ladder import depth_of_field

    def limits(u: float) -> tuple[float, float]:
        with library_errors(ctx), ladder_errors(ctx):
            r = depth_of_field(rung, f, n, c, u, "lens", lens, False, 550.0, tolerance).limits
        return float(r.near_mm), float(r.far_mm)

    with library_errors(ctx), ladder_errors(ctx):
        first = depth_of_field(rung, f, n, c, 10.0 * f, "lens", lens, False, 550.0, tolerance).limits
    return limits, float(first.hyperfocal_mm)
