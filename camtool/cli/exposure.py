"""``camtool exposure``: exposure value, the missing setting, equivalents, ND, close-up, reciprocity, metering."""

from __future__ import annotations

import contextlib
from collections.abc import Iterator
from typing import Any

import click

from camtool.cli.command import Output, camtool_command, combine_params
from camtool.cli.common import f_numbers, rows_from
from camtool.cli.options import aperture_options, library_errors, param_named
from camtool.cli.params import NumberType, TimeType, flatten
from camtool.core.errors import DomainError
from camtool.render.columns import FNUMBER, NUMBER, TEXT, Column

KEYS = ["f_number", "shutter_s", "iso", "ev", "ev100", "solved", "f_number_nominal", "shutter_nominal_s",
        "iso_nominal", "nd_stops", "bellows_stops", "corrected_shutter_s", "reciprocity_stops"]
COLUMNS = [
    Column("f_number", "N", FNUMBER),
    Column("time", "time", TEXT),
    Column("iso_text", "ISO", TEXT),
    Column("ev", "EV", NUMBER),
    Column("ev100", "EV100", NUMBER),
    Column("nominal", "nearest stops", TEXT),
]
LOSS_COLUMNS = [Column("nd_stops", "ND stops", NUMBER), Column("bellows_stops", "bellows stops", NUMBER)]
RECIPROCITY_COLUMNS = [Column("corrected", "with reciprocity", TEXT)]
EQUIVALENT_KEYS = ["f_number", "f_number_nominal", "shutter_s", "shutter_nominal_s", "shutter_exact_s", "ev",
                   "iso", "ev100"]
EQUIVALENT_COLUMNS = [
    Column("f_number_nominal", "N", FNUMBER),
    Column("time", "time", TEXT),
    Column("exact", "exact time", TEXT),
    Column("ev", "EV", NUMBER),
]
SOLVED_NAMES = {"f_number": "f-number", "shutter_s": "time", "iso": "ISO", "ev100": "scene EV100"}


@contextlib.contextmanager
def _named_value(ctx: click.Context, name: str) -> Iterator[None]:
    """A name that is not known (a film, a light level, an ND spelling) as a usage error on its option."""
    try:
        yield
    except DomainError as error:
        text = f"{error.value} is outside the valid range: {error.valid}"
        raise click.BadParameter(text + (f" ({error.detail})" if error.detail else ""), ctx=ctx,
                                 param=param_named(ctx, name)) from None


def _one(ctx: click.Context, values: dict[str, Any]) -> None:
    given = [option for option, value in values.items() if value]
    if len(given) > 1:
        raise click.UsageError(f"Give only one light level: {', '.join(given)}.", ctx)


# No --batch: a row of this command is a choice among light sources and solved settings, not a grid point.
@camtool_command("exposure", batch=False)
@aperture_options
@click.option("-t", "--shutter", "shutter_s", type=TimeType(), multiple=True,
              help="Shutter time: 1/250, 0.5, 2s, 30, 1m30s; a list gives a row each.")
@click.option("--iso", type=NumberType(1, 1e7), multiple=True, help="ISO speed (1 to 10000000); default 100.")
@click.option("--ev100", type=NumberType(-10, 25), multiple=True,
              help="Scene light level as EV at ISO 100 (-10 to 25); solve for the setting left out.")
@click.option("--ev", type=NumberType(-10, 25), multiple=True,
              help="Light level as the EV a meter reads at the ISO in use (--iso, default 100).")
@click.option("--light", metavar="NAME",
              help="Named light level: sunny, slight-overcast, overcast, heavy-overcast, shade, snow, "
                   "sunset, home-interior, ... (sunny-16 rule and ANSI exposure tables).")
@click.option("--luminance", type=NumberType(1e-9, 1e12),
              help="Reflected-light reading: scene luminance in cd/m² (N²/t = L·S/K).")
@click.option("--illuminance", type=NumberType(1e-9, 1e12),
              help="Incident-light reading: illuminance in lux (N²/t = E·S/C).")
@click.option("--meter-k", type=NumberType(1, 100), default="12.5", show_default=True,
              help="Reflected-light meter calibration constant K.")
@click.option("--meter-c", type=NumberType(1, 10000), default="250", show_default=True,
              help="Incident-light meter calibration constant C.")
@click.option("--nd", multiple=True, metavar="FILTER",
              help="ND filter, repeatable (stacked): 3 or 3stops (stops), ND1000 or 1000x (factor), "
                   "3.0 or ND0.9 (optical density: a number with a decimal point).")
@click.option("--magnification", type=NumberType(0, 100), help="Close-up magnification m (1 = 1:1): bellows factor.")
@click.option("--pupil-mag", "pupil_magnification", type=NumberType(0.01, 100), default="1", show_default=True,
              help="Pupil magnification P of the lens (exit/entrance pupil) for the bellows factor (1 + m/P)².")
@click.option("--film", metavar="NAME", help="Film for reciprocity failure (hp5, fp4, delta-100, ...).")
@click.option("--reciprocity-p", "reciprocity_p", type=NumberType(1, 3),
              help="Schwarzschild exponent p for a film not in the list: t_c = t_m^p beyond 1 s.")
@click.option("--step", type=click.Choice(["full", "half", "third"]), default="third", show_default=True,
              help="Stops the nearest standard values (and --equivalents) use.")
@click.option("--equivalents", is_flag=True,
              help="List equivalent f-number and time pairs for the exposure (over --step stops).")
def exposure(ctx: click.Context, f_number, exact_stops, shutter_s, iso, ev100, ev, light, luminance, illuminance,
             meter_k, meter_c, nd, magnification, pupil_magnification, film, reciprocity_p, step, equivalents,
             fmt, units, preset_files) -> Output:
    """Exposure value and the missing setting; equivalents, ND filters, close-up, reciprocity, metering.

    EV = log2(N²/t) is the exposure value of the settings; EV100 = EV − log2(ISO/100)
    is the scene's light level at ISO 100. Give a light level (--ev100, --ev,
    --light, --luminance or --illuminance) and two of -N, -t, --iso to solve the
    third (ISO 100 when only -N or -t is given); or give -N and -t to get EV and EV100.

    \b
    Examples:
      camtool exposure -N 16 -t 1/125
      camtool exposure --light sunny -N 16 --iso 400
      camtool exposure --ev100 12 -N 8 --nd ND1000 --film hp5
      camtool exposure --light overcast --iso 100 -N 8 --equivalents --step full
    """
    from camtool.exposure import metering
    from camtool.exposure.equivalents import equivalent_exposures
    from camtool.exposure.ev import ev100_from_ev
    from camtool.exposure.light import light_level
    from camtool.exposure.nd import parse_nd, stack_nd
    from camtool.exposure.plan import plan_exposure
    from camtool.exposure.reciprocity import find_film
    from camtool.exposure.timefmt import format_time

    apertures, times, speeds = f_numbers(f_number, exact_stops), flatten(shutter_s), flatten(iso)
    _one(ctx, {"--ev100": ev100, "--ev": ev, "--light": light, "--luminance": luminance, "--illuminance": illuminance})
    if film and reciprocity_p:
        raise click.UsageError("Give --film or --reciprocity-p, not both.", ctx)
    with _named_value(ctx, "light"):
        levels = [light_level(light).ev100] if light else flatten(ev100)
    with _named_value(ctx, "nd"):
        loss = stack_nd([parse_nd(text) for text in nd]).stops
    with _named_value(ctx, "film"):
        p = find_film(film).p if film else (reciprocity_p[0] if reciprocity_p else None)
    with library_errors(ctx):
        if luminance:
            levels = [metering.ev_from_luminance(luminance[0], 100.0, meter_k[0])]
        elif illuminance:
            levels = [metering.ev_from_illuminance(illuminance[0], 100.0, meter_c[0])]
    names = ["f_number", "shutter_s", "iso", "ev100", "ev"]
    given = {name: values for name, values in zip(names, (apertures, times, speeds, levels, flatten(ev))) if values}
    if not given.keys() & {"ev100", "ev"} and not ("f_number" in given and "shutter_s" in given):
        raise click.UsageError("Give a light level (--ev100, --ev, --light, --luminance, --illuminance) "
                               "or both -N and -t.", ctx)
    if given.keys() & {"ev100", "ev"} and {"f_number", "shutter_s", "iso"} <= given.keys():
        raise click.UsageError("With a light level, give at most two of -N, -t, --iso: the third is solved.", ctx)
    count, columns = combine_params(ctx, *given.values())
    value = dict(zip(given, columns))
    with library_errors(ctx):
        if "ev" in value:
            value["ev100"] = ev100_from_ev(value.pop("ev"), value.get("iso", 100.0))
            value.setdefault("iso", 100.0)
        plan = plan_exposure(value.get("ev100"), value.get("f_number"), value.get("shutter_s"),
                                 value.get("iso"), loss, magnification[0] if magnification else 0.0,
                                 pupil_magnification[0], p, step=step)
    rows = rows_from(count, plan._asdict())
    if equivalents:
        if count != 1:
            raise click.UsageError("--equivalents needs a single exposure (one value per option).", ctx)
        with library_errors(ctx):
            table = equivalent_exposures(plan.ev, step=step)
        rows = rows_from(len(table.f_number), {**table._asdict(), "iso": plan.iso, "ev100": plan.ev100})
        for row in rows:
            row["time"], row["exact"] = format_time(row["shutter_nominal_s"]), format_time(row["shutter_exact_s"])
        note = f"EV {plan.ev:.2f} at ISO {plan.iso:g} · {step} stops · exact time before snapping"
        return Output(rows, EQUIVALENT_COLUMNS, EQUIVALENT_KEYS, note if fmt == "table" else "")
    columns_shown = list(COLUMNS)
    if nd or magnification:
        columns_shown += LOSS_COLUMNS
    if p is not None:
        columns_shown += RECIPROCITY_COLUMNS
    for row in rows:
        row["time"] = format_time(row["shutter_s"])
        row["iso_text"] = f"{row['iso']:.4g}"
        row["nominal"] = f"f/{row['f_number_nominal']:g} {format_time(row['shutter_nominal_s'])} " \
                         f"ISO {row['iso_nominal']:g}"
        row["corrected"] = format_time(row["corrected_shutter_s"])
    note = (f"EV = log2(N²/t) of the settings · EV100 = the scene at ISO 100 · "
            f"solved: {SOLVED_NAMES[plan.solved]} · nearest {step} stops")
    if film:
        note += f" · {find_film(film).name}, p = {p:g}"
    return Output(rows, columns_shown, KEYS, note if fmt == "table" else "")
