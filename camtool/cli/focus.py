"""``camtool focus``: thin-lens focusing, and the inverse -- where to focus for a wanted near and far limit."""

from __future__ import annotations

import click

from camtool.cli.closeup import closeup_options, has_focus_model, plan_focus
from camtool.cli.command import Output, camtool_command, combine_params
from camtool.cli.common import f_numbers, footer, required, rows_from
from camtool.cli.equipment import resolve_coc, resolve_sensor
from camtool.cli.lensdata import WavelengthType, lens_geometry_options, pupil_and_hiatus
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
from camtool.dof.inverse import focus_for_limits, focus_for_limits_at
from camtool.geometry.thinlens import focus_setting
from camtool.render.columns import FNUMBER, NUMBER, SMALL, Column

FORWARD_KEYS = ["focal_length_mm", "distance_mm", "image_distance_mm", "extension_mm", "magnification",
                "f_number", "working_f_number", "closest_focus_mm", "distance_from", "other_magnification",
                "focal_length_at_focus_mm"]
FORWARD_COLUMNS = [
    Column("focal_length_mm", "f", SMALL),
    Column("distance_mm", "focus"),
    Column("image_distance_mm", "image dist.", SMALL),
    Column("extension_mm", "extension", SMALL),
    Column("magnification", "m", NUMBER),
    Column("working_f_number", "working N", FNUMBER),
]
INVERSE_KEYS = ["focal_length_mm", "near_mm", "far_mm", "distance_mm", "f_number", "coc_mm", "distance_from"]
FIXED_KEYS = ["wanted_near_mm", "wanted_far_mm", "needed_f_number"]
OPTIMUM_KEYS = ["focal_length_mm", "near_mm", "far_mm", "distance_mm", "magnification", "focus_spread_mm",
                "f_number", "working_f_number", "blur_mm", "blur_sum_mm", "distance_from"]
OPTIMUM_COLUMNS = [
    Column("focal_length_mm", "f", SMALL),
    Column("near_mm", "near"),
    Column("far_mm", "far"),
    Column("distance_mm", "focus at"),
    Column("magnification", "m", NUMBER),
    Column("focus_spread_mm", "spread", SMALL),
    Column("f_number", "optimum N", FNUMBER),
    Column("working_f_number", "working N", FNUMBER),
    Column("blur_mm", "blur", SMALL),
]
DEPTH_KEYS = ["magnification", "depth_mm", "f_number", "coc_mm", "working_f_number"]
DEPTH_COLUMNS = [
    Column("magnification", "m", NUMBER),
    Column("depth_mm", "depth"),
    Column("f_number", "N", FNUMBER),
    Column("coc_mm", "CoC", SMALL),
    Column("working_f_number", "working N", FNUMBER),
]
INVERSE_COLUMNS = [
    Column("focal_length_mm", "f", SMALL),
    Column("near_mm", "near"),
    Column("far_mm", "far"),
    Column("distance_mm", "focus at"),
    Column("f_number", "N", FNUMBER),
]


@camtool_command("focus", keys=list(dict.fromkeys(FORWARD_KEYS + INVERSE_KEYS + FIXED_KEYS + OPTIMUM_KEYS + DEPTH_KEYS)))
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
@click.option("--wavelength", type=WavelengthType(), default="550", show_default=True, metavar="NM",
              help="Wavelength for --optimum: 550, 550nm or 0.55um.")
@closeup_options
@sensor_options
@coc_options
@distance_plane_option
@lens_geometry_options
def focus(ctx: click.Context, focal_length, distance, magnification, f_number, exact_stops, near, far, optimum,
          focus_spread, depth, wavelength, extension, teleconverter, sensor, crop, coc, coc_rule, pixel_pitch,
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
    (with --coc) that give that depth (docs/closeup.md §4, §6).

    \b
    Examples:
      camtool focus -f 100 -s 0.5m -N 8
      camtool focus -f 100 -m 0.5
      camtool focus -f 35 --near 2m --far 10m
      camtool focus -f 24 -N 11 --near 1m --far inf
      camtool focus --lens mp-e-65 -m 1,5 -N 2.8
      camtool focus -f 150 --near 2m --far inf --optimum
      camtool focus --focus-spread 3mm --optimum
      camtool focus -m 2.5 --depth 0.2mm -N 4
    """
    if depth:
        return _depth(ctx, magnification, depth, f_number, exact_stops, coc, pupil_mag, hiatus, fmt)
    if optimum and focus_spread:
        return _spread(ctx, focus_spread, magnification, pupil_mag, hiatus, wavelength, fmt)
    if optimum and not (near and far):
        raise click.UsageError("--optimum needs --near and --far, or --focus-spread", ctx)
    focal = required(ctx, focal_length, "-f")
    if optimum:
        return _optimum(ctx, focal, near, far, distance_from, pupil_mag, hiatus, wavelength, fmt)
    if near or far:
        return _inverse(ctx, focal, near, far, sensor, crop, coc, coc_rule, pixel_pitch, distance_from, fmt,
                        preset_files, f_numbers(f_number, exact_stops))
    if bool(distance) == bool(magnification):
        raise click.UsageError("give either -s/--distance or -m/--magnification (or --near and --far)", ctx)
    p, delta, lens_note = pupil_and_hiatus(ctx, pupil_mag, hiatus)
    apertures = f_numbers(f_number, exact_stops)
    wanted = flatten(distance) or flatten(magnification)
    count, (f, w, *given_n) = combine_params(ctx, focal, wanted, *([apertures] if apertures else []))
    if extension or teleconverter or has_focus_model(ctx):
        return _planned(ctx, count, f, w, given_n, not distance, distance_from, p, delta, extension, teleconverter,
                        lens_note, fmt)
    with library_errors(ctx):
        setting = focus_setting(f, w if distance else None, None if distance else w, distance_from, delta,
                                given_n[0] if given_n else None, p)
    values = {
        "focal_length_mm": f, "distance_mm": setting.distance_mm, "image_distance_mm": setting.image_distance_mm,
        "extension_mm": setting.extension_mm, "magnification": setting.magnification,
        "closest_focus_mm": setting.closest_focus_mm, "distance_from": distance_from,
        "focal_length_at_focus_mm": f,
    }
    keys, columns = list(FORWARD_KEYS), list(FORWARD_COLUMNS)
    if given_n:
        values.update({"f_number": given_n[0], "working_f_number": setting.working_f_number})
    else:
        keys = [k for k in keys if k not in ("f_number", "working_f_number")]
        columns = [c for c in columns if c.key != "working_f_number"]
    rows = rows_from(count, values)
    for row in rows:  # the other magnification at the same distance from the sensor (m and 1/m, without hiatus)
        m = row["magnification"]
        row["other_magnification"] = (1.0 / m if distance and distance_from == "sensor" and 0.0 < m < 1.0 and not delta
                                      else None)
    note = footer("thick" if lens_note else "thin", None, "", "unit focusing, m = v/u", distance_from,
                  lens_note) if fmt == "table" else ""
    if fmt == "table":
        from camtool.cli.closeup import branch_note

        note = " · ".join(part for part in (note, branch_note(rows)) if part)
    return Output(rows, columns, keys, note)


def _planned(ctx, count, f, w, given_n, by_m, distance_from, p, delta, extension, teleconverter, lens_note,
             fmt) -> Output:
    """Focusing through the close-up planner: a preset's internal focus, extension, teleconverter."""
    from camtool.cli.closeup import FOCUS_COLUMN, branch_note, focus_models

    n = given_n[0] if given_n else 1.0
    with library_errors(ctx):
        setting = plan_focus(ctx, f, n, w, by_m, distance_from, delta, extension, teleconverter)
    k = teleconverter or 1.0
    models = focus_models(ctx)
    focal = [float(v) for v in (f if hasattr(f, "__len__") else [f])]
    rows = []
    for i in range(count):
        fe, m = setting.focal_length_mm[i], setting.magnification[i]
        model = models(focal[i])
        closest = model.min_focus_mm if model is not None else 4.0 * fe + delta
        if distance_from == "lens":
            closest = closest - delta - fe * (1.0 + (model.max_magnification if model is not None else 1.0))
        row = {
            "focal_length_mm": k * focal[i], "focal_length_at_focus_mm": fe,
            "distance_mm": setting.sensor_distance_mm[i] if distance_from == "sensor" else setting.lens_distance_mm[i],
            "image_distance_mm": fe * (1.0 + m), "extension_mm": fe * m, "magnification": m,
            "closest_focus_mm": closest, "distance_from": distance_from,
            "other_magnification": None if setting.other_magnification[i] != setting.other_magnification[i]
            else setting.other_magnification[i],
        }
        if given_n:
            row.update({"f_number": setting.f_number[i], "working_f_number": setting.f_number[i] * (1.0 + m / p)})
        rows.append(row)
    keys, columns = list(FORWARD_KEYS), list(FORWARD_COLUMNS)
    if any(abs(r["focal_length_at_focus_mm"] - r["focal_length_mm"]) > 1e-9 * r["focal_length_mm"] for r in rows):
        columns.insert(1, FOCUS_COLUMN)
    if not given_n:
        keys = [k for k in keys if k not in ("f_number", "working_f_number")]
        columns = [c for c in columns if c.key != "working_f_number"]
    note = ""
    if fmt == "table":
        parts = ["internal focus (docs/closeup.md)" if models(focal[0]) is not None else "unit focusing",
                 f"extension {extension:g} mm" if extension else "",
                 f"teleconverter ×{teleconverter:g}" if teleconverter else "",
                 "-s is the lens's own focus setting; focus is where the subject then is"
                 if (extension or teleconverter) and not by_m else "", branch_note(rows)]
        note = footer("thick" if lens_note else "thin", None, "", " · ".join(x for x in parts if x), distance_from,
                      lens_note)
    return Output(rows, columns, keys, note)


def _optimum(ctx, focal, near, far, distance_from, pupil_mag, hiatus, wavelength, fmt) -> Output:
    from camtool.dof.closeup import optimum_for_limits

    p, delta, lens_note = pupil_and_hiatus(ctx, pupil_mag, hiatus)
    count, (f, a, b) = combine_params(ctx, focal, required(ctx, near, "--near"), required(ctx, far, "--far"))
    with library_errors(ctx):
        r = optimum_for_limits(f, a, b, distance_from, delta, p, wavelength)
    rows = rows_from(count, {
        "focal_length_mm": f, "near_mm": a, "far_mm": b, "distance_mm": r.distance_mm, "magnification": r.magnification,
        "focus_spread_mm": r.focus_spread_mm, "f_number": r.optimum.f_number,
        "working_f_number": r.optimum.working_f_number, "blur_mm": r.optimum.blur_mm,
        "blur_sum_mm": r.optimum.blur_sum_mm, "distance_from": distance_from,
    })
    note = footer(None, None, "", f"optimum aperture (Hansma): defocus = diffraction at {wavelength:g} nm; "
                  "blur: root-sum-square", distance_from, lens_note) if fmt == "table" else ""
    return Output(rows, OPTIMUM_COLUMNS, OPTIMUM_KEYS, note)


def _spread(ctx, focus_spread, magnification, pupil_mag, hiatus, wavelength, fmt) -> Output:
    from camtool.dof.closeup import optimum_aperture

    p = pupil_and_hiatus(ctx, pupil_mag, hiatus)[0]
    count, (d, m) = combine_params(ctx, flatten(focus_spread), flatten(magnification) or [0.0])
    with library_errors(ctx):
        r = optimum_aperture(d, m, p, wavelength)
    keys = ["focus_spread_mm", "magnification", "f_number", "working_f_number", "blur_mm", "blur_sum_mm"]
    rows = rows_from(count, {"focus_spread_mm": d, "magnification": m, "f_number": r.f_number,
                             "working_f_number": r.working_f_number, "blur_mm": r.blur_mm,
                             "blur_sum_mm": r.blur_sum_mm})
    columns = [c for c in OPTIMUM_COLUMNS if c.key in keys]
    note = (f"optimum aperture (Hansma): defocus = diffraction at {wavelength:g} nm; blur: root-sum-square"
            if fmt == "table" else "")
    return Output(rows, columns, keys, note)


def _depth(ctx, magnification, depth, f_number, exact_stops, coc, pupil_mag, hiatus, fmt) -> Output:
    from camtool.dof.closeup import coc_for_depth, f_number_for_depth

    wanted_m = required(ctx, magnification, "-m")
    apertures, cocs = f_numbers(f_number, exact_stops), flatten(coc)
    if bool(apertures) == bool(cocs):
        raise click.UsageError("--depth needs -N (to find the CoC) or --coc (to find the f-number)", ctx)
    p = pupil_and_hiatus(ctx, pupil_mag, hiatus)[0]
    count, (m, d, given) = combine_params(ctx, wanted_m, flatten(depth), apertures or cocs)
    with library_errors(ctx):
        if apertures:
            n, c = given, coc_for_depth(given, m, d, p)
        else:
            n, c = f_number_for_depth(given, m, d, p), given
    rows = rows_from(count, {"magnification": m, "depth_mm": d, "f_number": n, "coc_mm": c,
                             "working_f_number": n * (1.0 + m / p)})
    note = "depth = 2·N·c·(1 + m/P)/m² (docs/closeup.md §6)" if fmt == "table" else ""
    return Output(rows, DEPTH_COLUMNS, DEPTH_KEYS, note)


def _inverse(ctx, focal, near, far, sensor, crop, coc, coc_rule, pixel_pitch, distance_from, fmt,
             preset_files, apertures=()) -> Output:
    nears = required(ctx, near, "--near")
    fars = required(ctx, far, "--far")
    chosen = resolve_sensor(ctx, sensor, crop, preset_files)
    cocs, coc_origin = resolve_coc(ctx, list(coc), coc_rule, chosen, pixel_pitch)
    if apertures:  # a fixed f-number: the focus that best uses it, and the limits it gives
        count, (f, a, b, c, n) = combine_params(ctx, focal, nears, fars, cocs, apertures)
        with library_errors(ctx):
            fixed = focus_for_limits_at(f, n, c, a, b, distance_from)
        rows = rows_from(count, {
            "focal_length_mm": f, "near_mm": fixed.near_mm, "far_mm": fixed.far_mm, "distance_mm": fixed.distance_mm,
            "f_number": n, "coc_mm": c, "distance_from": distance_from, "wanted_near_mm": a, "wanted_far_mm": b,
            "needed_f_number": fixed.needed_f_number,
        })
        note = footer("thin", cocs, coc_origin, chosen.label, distance_from,
                      "near/far: the limits at this f-number") if fmt == "table" else ""
        return Output(rows, INVERSE_COLUMNS, INVERSE_KEYS + FIXED_KEYS, note)
    count, (f, a, b, c) = combine_params(ctx, focal, nears, fars, cocs)
    with library_errors(ctx):
        solution = focus_for_limits(f, c, a, b, distance_from)
    rows = rows_from(count, {
        "focal_length_mm": f, "near_mm": a, "far_mm": b, "distance_mm": solution.distance_mm,
        "f_number": solution.f_number, "coc_mm": c, "distance_from": distance_from,
    })
    note = footer("thin", cocs, coc_origin, chosen.label, distance_from) if fmt == "table" else ""
    return Output(rows, INVERSE_COLUMNS, INVERSE_KEYS, note)
