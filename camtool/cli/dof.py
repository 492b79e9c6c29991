"""``camtool dof``: near and far limits of acceptable sharpness, by any rung of the model ladder."""

from __future__ import annotations

import math
from typing import Any

import click

from camtool.cli.closeup import (
    CLOSE_UP,
    CLOSEUP_COLUMNS,
    CLOSEUP_KEYS,
    DIFFRACTION_COLUMNS,
    DIFFRACTION_KEYS,
    FOCUS_COLUMN,
    branch_note,
    closeup_options,
    dof_rows,
    has_focus_model,
    magnification_option,
    plan_focus,
)
from camtool.cli.command import Output, camtool_command, combine_params
from camtool.cli.common import f_numbers, flatten, footer, required, rows_from
from camtool.cli.equipment import resolve_coc, resolve_sensor
from camtool.cli.lensdata import ladder_errors, lens_data, model_options, pupil_and_hiatus
from camtool.cli.options import (
    DISTANCE_M,
    aperture_options,
    coc_options,
    distance_plane_option,
    focal_option,
    library_errors,
    param_named,
    sensor_options,
)
from camtool.cli.rows import ZIP
from camtool.dof.ladder import compare_models, depth_of_field, focal_lengths, model_choices, model_help
from camtool.render.columns import FNUMBER, SMALL, TEXT, Column

KEYS = ["focal_length_mm", "f_number", "distance_mm", "near_mm", "far_mm", "total_mm", "front_mm", "rear_mm",
        "hyperfocal_mm", "coc_mm", "magnification", "model", "error_estimate", "distance_from"]
FAR_KEYS = [*KEYS, "difference_pct", "time_per_evaluation_s"]
"""``--model all`` away from close-up: what every rung computes (no close-up or diffraction columns to leave null)."""
ALL_KEYS = [*FAR_KEYS, *CLOSEUP_KEYS, *DIFFRACTION_KEYS]
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
    Column("sharp_zone", "sharp zone", TEXT, legend="┃ focus, H hyperfocal, ▶ ∞"),
]
ALL_COLUMNS = [
    Column("model", "model", TEXT),
    Column("focal_length_mm", "f", SMALL),
    Column("f_number", "N", FNUMBER),
    Column("distance_mm", "focus"),
    Column("near_mm", "near"),
    Column("far_mm", "far"),
    Column("total_mm", "depth"),
    Column("difference_shown", "difference", TEXT),
    Column("estimate_shown", "est. error", TEXT),
    Column("time_shown", "time/eval", TEXT),
]
MODEL_HELP = model_help()


@camtool_command("dof", keys=ALL_KEYS)
@focal_option
@aperture_options
@click.option("-s", "--distance", type=DISTANCE_M, multiple=True,
              help="Focus distance, e.g. 3 (bare numbers are metres), 3m, 10ft, inf; a list gives a row each. "
                   "From the sensor, a distance also reached at m > 1 is answered at m ≤ 1 (give -m for the other).")
@magnification_option
@closeup_options
@sensor_options
@coc_options
@distance_plane_option
@click.option("--model", type=click.Choice(model_choices()), default="auto", show_default=True, help=MODEL_HELP)
@model_options
def dof(ctx: click.Context, focal_length, f_number, exact_stops, distance, magnification, extension, teleconverter,
        sensor, crop, coc, coc_rule, pixel_pitch, distance_from, model, tolerance, diffraction, wavelength, pupil_mag,
        hiatus, prescription_file, fmt, units, preset_files) -> Output:
    """Depth of field: near and far limits, total depth, front/rear split and hyperfocal distance.

    \b
    Examples:
      camtool dof -f 50 -N 8 -s 3m
      camtool dof -f 85 -N 1.8,2.8,4 -s 2 --sensor aps-c --format json
      camtool dof -N 2 -s 1m --prescription dgauss100 --model all
      camtool dof -f 100 -N 11,22 -s 0.5 --pupil-mag 0.8 --diffraction
      camtool dof -f 100 -N 8 -m 0.5,1,2
      camtool dof --lens mp-e-65 -N 2.8 -m 1,2,5 --diffraction
      camtool dof -f 100 -N 8,16 -s 400mm --diffraction
      camtool dof -f 50 -N 8 -s 1m --extension 25mm --teleconverter 1.4

    With -m (any m > 0) or close up, the table shows the magnification and
    the working f-number N(1 + m/P). A lens preset with a published closest
    focus focuses internally (docs/closeup.md): it is accepted down to that
    closest focus and reaches its published magnification there. With
    --diffraction every row gets its Airy disc, the f-number at which it
    fills the CoC and the wave-optics depth λ/NA²; rows where nothing can
    be sharp show a reason, and the command fails only if no row has an answer.
    """
    lens = lens_data(ctx, pupil_mag, hiatus, prescription_file)
    with library_errors(ctx):
        focal = required(ctx, focal_lengths(lens, flatten(focal_length)), "-f")
    if teleconverter not in (None, 1.0) and lens is not None and lens.prescription is not None:
        # a prescription is the lens alone: the converter behind it is not traced, so the rungs that trace it
        # cannot answer, and its pupils and hiatus are not those of lens and converter together
        if model in ("paraxial", "raytrace"):
            raise click.BadParameter(f"{teleconverter:g} is not part of the lens prescription, which --model {model} "
                                     "traces; use --model thin, thick or auto", ctx=ctx,
                                     param=param_named(ctx, "teleconverter"))
        from camtool.dof.rungs import LensData

        lens = LensData(pupil_magnification=pupil_mag, hiatus_mm=hiatus) if (pupil_mag, hiatus) != (None, None) else None
    apertures = required(ctx, f_numbers(f_number, exact_stops), "-N")
    wanted_m = flatten(magnification)
    if wanted_m and flatten(distance):
        if not ctx.meta.get(ZIP):
            raise click.UsageError("give either -s/--distance or -m/--magnification, not both", ctx)
        wanted_m = []  # a batch row with both (camtool's own CSV fed back) is read by its distance
    distances = wanted_m or required(ctx, distance, "-s")
    chosen = resolve_sensor(ctx, sensor, crop, preset_files)
    cocs, coc_origin = resolve_coc(ctx, list(coc), coc_rule, chosen, pixel_pitch)
    count, (f, n, s, c) = combine_params(ctx, focal, apertures, distances, cocs)
    closeup = bool(wanted_m or extension or teleconverter or diffraction) or has_focus_model(ctx)
    by_rays = lens is not None and lens.prescription is not None
    if closeup and not (by_rays and not (wanted_m or extension or teleconverter or diffraction)):
        if model == "all":
            return _closeup_all_models(ctx, f, n, s, c, bool(wanted_m), extension, teleconverter, distance_from,
                                       lens, diffraction, wavelength, tolerance, pupil_mag, hiatus, fmt, cocs,
                                       coc_origin, chosen.label)
        return _closeup(ctx, model, f, n, s, c, bool(wanted_m), extension, teleconverter, distance_from, lens,
                        diffraction, wavelength, tolerance, pupil_mag, hiatus, fmt, cocs, coc_origin, chosen.label)
    if model == "all":
        return _all_models(ctx, count, f, n, s, c, distance_from, lens, diffraction, wavelength, fmt, cocs,
                           coc_origin, chosen.label)
    with library_errors(ctx), ladder_errors(ctx):
        result = depth_of_field(model, f, n, c, s, distance_from, lens, diffraction, wavelength, tolerance)
    limits = result.limits
    p = pupil_and_hiatus(ctx, pupil_mag, hiatus)[0]
    rows = rows_from(count, {
        "focal_length_mm": f, "f_number": n, "distance_mm": s, "near_mm": limits.near_mm, "far_mm": limits.far_mm,
        "total_mm": limits.total_mm, "front_mm": limits.front_mm, "rear_mm": limits.rear_mm,
        "hyperfocal_mm": limits.hyperfocal_mm, "coc_mm": c, "magnification": limits.magnification,
        "model": result.model, "error_estimate": result.error_estimate, "distance_from": distance_from,
    })
    # JSON and CSV always carry the close-up keys (a batch and a single call agree); the table shows them close up
    close = any(row["magnification"] >= CLOSE_UP for row in rows)
    keys, columns = [*KEYS, *CLOSEUP_KEYS], list(COLUMNS)
    for row in rows:
        m = row["magnification"]
        row["working_f_number"] = row["f_number"] * (1.0 + m / p)
        row["other_magnification"] = 1.0 / m if distance_from == "sensor" and 0.0 < m < 1.0 else None
        row["focal_length_at_focus_mm"] = row["focal_length_mm"]
    if close:
        columns[3:3] = CLOSEUP_COLUMNS
    note = ""
    if fmt == "table":
        from camtool.render.bar import axis_range, sharp_zone_bar

        low, high = axis_range([v for r in rows for v in (r["near_mm"], r["far_mm"], r["hyperfocal_mm"])])
        for row in rows:
            row["sharp_zone"] = sharp_zone_bar(row["near_mm"], row["distance_mm"], row["far_mm"],
                                               row["hyperfocal_mm"], low, high, width=24)
        # The estimate is of what the model leaves out of the lens data given; 0 (nothing left out) is not shown.
        worst = max(row["error_estimate"] for row in rows)
        used = " / ".join(dict.fromkeys(row["model"] for row in rows))
        label = f"{used} model" + (f" (est. error ≤ {_percent(worst)})" if worst > 0 else "") + _h_note(
            model, lens, rows)
        extra = branch_note(rows) if close else ""
        note = label + " · " + footer(None, cocs, coc_origin, chosen.label, distance_from, extra)
    return Output(rows, columns, keys, note)


def _closeup(ctx, model, f, n, w, c, by_m, extension, teleconverter, distance_from, lens, diffraction, wavelength,
             tolerance, pupil_mag, hiatus, fmt, cocs, coc_origin, sensor_label) -> Output:
    """Rows through the close-up planner: any magnification, internal focus, extension, teleconverter."""
    known = lens.thick_parameters() if lens is not None else None  # a prescription's own P and δ included
    p, delta = (float(v) for v in known) if known is not None else pupil_and_hiatus(ctx, pupil_mag, hiatus)[:2]
    with library_errors(ctx):
        setting = plan_focus(ctx, f, n, w, by_m, distance_from, delta, extension, teleconverter)
    direct = not by_m and not setting.modelled
    k = teleconverter or 1.0
    nominal = [k * float(v) for v in (f if hasattr(f, "__len__") else [f])]
    rows = dof_rows(ctx, model, setting, c, distance_from, lens, diffraction, wavelength, tolerance, p, delta,
                    direct, nominal)
    close = by_m or setting.modelled or any(r["magnification"] >= CLOSE_UP for r in rows)
    keys = [*KEYS, *CLOSEUP_KEYS, *(DIFFRACTION_KEYS if diffraction else [])]
    columns = list(COLUMNS)
    if close:
        columns[3:3] = CLOSEUP_COLUMNS
    if any(abs(r["focal_length_at_focus_mm"] - r["focal_length_mm"]) > 1e-9 * r["focal_length_mm"] for r in rows):
        columns[1:1] = [FOCUS_COLUMN]
    if diffraction:
        columns[-1:-1] = DIFFRACTION_COLUMNS
    note = ""
    if fmt == "table":
        from camtool.render.bar import axis_range, sharp_zone_bar

        answered = [r for r in rows if r["near_mm"] is not None]
        low, high = axis_range([v for r in answered for v in (r["near_mm"], r["far_mm"], r["hyperfocal_mm"])])
        for row in rows:
            row["sharp_zone"] = (sharp_zone_bar(row["near_mm"], row["distance_mm"], row["far_mm"],
                                                row["hyperfocal_mm"], low, high, width=24)
                                 if row["near_mm"] is not None else row["reason"])
        worst = max(row["error_estimate"] for row in answered)
        used = " / ".join(dict.fromkeys(row["model"] for row in answered))
        label = f"{used} model" + (f" (est. error ≤ {_percent(worst)})" if worst > 0 else "") + _h_note(
            model, lens, answered)
        extra = " · ".join(part for part in (branch_note(rows) if not by_m else "",
                                             "-s is the lens's own focus setting; focus is where the subject then is"
                                             if (extension or teleconverter) and not by_m else "",
                                             _dominance(rows) if diffraction else "") if part)
        note = label + " · " + footer(None, cocs, coc_origin, sensor_label, distance_from, extra)
    return Output(rows, columns, keys, note)


def _h_note(model: str, lens: Any, rows: Any) -> str:
    """Under auto, when some row's limits came from a cheaper rung: the one rung the H column is computed by."""
    from camtool.dof.ladder import hyperfocal_rung

    rung = hyperfocal_rung(lens)
    if model != "auto" or all(str(row["model"]).split("+")[0] == rung for row in rows):
        return ""
    return f"; H by the {rung} model"


def _dominance(rows: list[dict[str, Any]]) -> str:
    kinds = {row["depth_dominated_by"] for row in rows if row.get("depth_dominated_by")}
    if kinds == {"wave"}:
        return "wave-optics depth λ/NA² exceeds the geometric depth"
    if kinds == {"geometric"}:
        return "geometric depth exceeds the wave-optics depth λ/NA²"
    return "depth dominated by the wave-optics or geometric term, row by row"


def _percent(fraction: float | None) -> str:
    if fraction is None:  # a row with no depth of field (diffraction fills the CoC): no estimate either
        return "—"
    return f"{fraction:.2%}".replace("%", " %") if fraction >= 1e-4 else "0.01 %" if fraction > 0 else "0 %"


def _all_models(ctx, count, f, n, s, c, distance_from, lens, diffraction, wavelength, fmt, cocs, coc_origin,
                sensor_label) -> Output:
    """``--model all``: one row per scene and model, the most complete model last."""
    with library_errors(ctx), ladder_errors(ctx):
        rungs = compare_models(f, n, c, s, distance_from, lens, diffraction, wavelength)
    rows: list[dict[str, Any]] = []
    per_model = []
    for rung in rungs:
        limits = rung.result.limits
        per_model.append(rows_from(count, {
            "focal_length_mm": f, "f_number": n, "distance_mm": s, "near_mm": limits.near_mm,
            "far_mm": limits.far_mm, "total_mm": limits.total_mm, "front_mm": limits.front_mm,
            "rear_mm": limits.rear_mm, "hyperfocal_mm": limits.hyperfocal_mm, "coc_mm": c,
            "magnification": limits.magnification, "model": rung.result.model,
            "error_estimate": rung.result.error_estimate, "distance_from": distance_from,
            "difference_pct": rung.difference * 100.0, "time_per_evaluation_s": rung.time_per_evaluation_s,
        }))
    for i in range(count):  # scene by scene, every model of one scene together
        rows.extend(model_rows[i] for model_rows in per_model)
    note = _comparison_note(rows, rungs[-1].result.model, "", cocs, coc_origin, sensor_label,
                            distance_from) if fmt == "table" else ""
    return Output(rows, ALL_COLUMNS, FAR_KEYS, note)


def _closeup_all_models(ctx, f, n, w, c, by_m, extension, teleconverter, distance_from, lens, diffraction, wavelength,
                        tolerance, pupil_mag, hiatus, fmt, cocs, coc_origin, sensor_label) -> Output:
    """``--model all`` for close-up scenes: every rung through the close-up planner, the most complete last.

    Each rung places the subject the same way (the planner's focus: -m, the
    lens's focusing model, extension, teleconverter) and differs only in the
    depth of field it computes there; the time per evaluation includes the
    planning, best of three runs.
    """
    import time
    from types import SimpleNamespace

    from camtool.dof.auto import depth_error
    from camtool.dof.ladder import NO_LENS, available_models

    per_model = []
    for rung in available_models(lens or NO_LENS):
        best = math.inf
        for _ in range(3):
            start = time.perf_counter()
            out = _closeup(ctx, rung, f, n, w, c, by_m, extension, teleconverter, distance_from, lens, diffraction,
                           wavelength, tolerance, pupil_mag, hiatus, "json", cocs, coc_origin, sensor_label)
            best = min(best, time.perf_counter() - start)
        per_model.append((out.rows, best / max(len(out.rows), 1)))
    reference = per_model[-1][0]
    rows: list[dict[str, Any]] = []
    for i, ref in enumerate(reference):  # scene by scene, every model of one scene together
        for model_rows, seconds in per_model:
            row = dict(model_rows[i])
            answered = row["near_mm"] is not None and ref["near_mm"] is not None
            row["difference_pct"] = (100.0 * float(depth_error(SimpleNamespace(**_limits(row)),
                                                                SimpleNamespace(**_limits(ref))))
                                     if answered else None)
            row["time_per_evaluation_s"] = seconds
            rows.append(row)
    note = _comparison_note(rows, reference[0]["model"] if reference else "", ", focus planning included", cocs,
                            coc_origin, sensor_label, distance_from) if fmt == "table" else ""
    columns = list(ALL_COLUMNS)
    columns[4:4] = CLOSEUP_COLUMNS  # after the focus: m and the working f-number
    if any(abs(r["focal_length_at_focus_mm"] - r["focal_length_mm"]) > 1e-9 * r["focal_length_mm"] for r in rows):
        columns[2:2] = [FOCUS_COLUMN]
    return Output(rows, columns, ALL_KEYS, note)


def _comparison_note(rows: list[dict[str, Any]], most: str, timed: str, cocs: Any, coc_origin: str,
                     sensor_label: str, distance_from: str) -> str:
    """Fill the shown columns of ``--model all`` rows and return the table's footer."""
    for row in rows:
        row["difference_shown"] = "—" if row["difference_pct"] is None else f"{row['difference_pct']:.3g} %"
        row["estimate_shown"] = _percent(row["error_estimate"])
        row["time_shown"] = _duration(row["time_per_evaluation_s"])
    return (f"difference from {most}, the most complete model; time per evaluation{timed} · "
            + footer(None, cocs, coc_origin, sensor_label, distance_from))


def _limits(row: dict[str, Any]) -> dict[str, float]:
    far = row["far_mm"]
    return {"near_mm": float(row["near_mm"]), "far_mm": math.inf if far is None else float(far)}


def _duration(seconds: float) -> str:
    if seconds >= 1e-3:
        return f"{seconds * 1e3:.3g} ms"
    return f"{seconds * 1e6:.3g} µs"
