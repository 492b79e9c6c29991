"""``camtool exposure``: parse, call :func:`camtool.exposure.calculator.work_out`, render."""

from __future__ import annotations

from typing import Any

import click

from camtool.cli.command import Output, camtool_command, combine_params
from camtool.cli.common import rows_from
from camtool.cli.options import completion, library_errors, preset_names
from camtool.cli.params import FNumberType, NumberType, PupilMagnificationType, TimeType, flatten
from camtool.core import ranges, units
from camtool.core.units import UnitError
from camtool.exposure.calculator import KEYS as ROW_KEYS
from camtool.render.views.exposure import EQUIVALENT_KEYS, exposure_view

KEYS = [*ROW_KEYS, *(key for key in EQUIVALENT_KEYS if key not in ROW_KEYS)]
"""Every key a row of the command can carry: a worked-out exposure's, then what --equivalents adds."""


class ApertureType(FNumberType):
    """f-numbers (8, f/8, f8) or T-stops (T2, T/2.8, returned as :class:`TStop`), named so in its messages."""

    valid = f"{FNumberType.valid.split(' (')[0]} (written 8, f/8, f8, or a T-stop T2)"

    def __init__(self) -> None:
        super().__init__(t_stops=True)

    def parse(self, text: str) -> float:
        try:
            return super().parse(text)
        except UnitError:
            raise UnitError(f"{text!r} is not an f-number or T-stop (examples: 8, f/8, f8, T2)") from None


class IlluminanceType(NumberType):
    """Illuminance in lux (a bare number, 400lx) or foot-candles (37fc): :func:`units.parse_illuminance`."""

    name = "illuminance"
    parse = staticmethod(units.parse_illuminance)

    def __init__(self, low: float, high: float) -> None:
        super().__init__(low, high)
        self.valid = f"{low:g} to {high:g} lx (written 400, 400lx or 37fc)"


def single(ctx: click.Context, values: Any, default: float | None = None) -> Any:
    """The one value of a list option that must not vary between rows (in a batch too), or ``default``.

    A batch hands every list option over as a column; a column that holds
    different values in different rows is a usage error.
    """
    flat = flatten(values) if values else []
    if not flat:
        return default
    if any(v != flat[0] for v in flat[1:]):
        message = f"Give one value, not {', '.join(f'{v:g}' for v in flat)}, for a setting that applies to every row."
        param = next((p for p in ctx.command.params if p.name and ctx.params.get(p.name) is values), None)
        if param is not None:  # the option typed, by name
            raise click.BadParameter(message[0].lower() + message[1:], ctx=ctx, param=param)
        raise click.UsageError(message, ctx)
    return flat[0]


# No --batch: a row of this command is a choice among light sources and solved settings, not a grid point.
def _light_names() -> list[str]:
    from camtool.exposure.light import LIGHT_LEVELS

    return list(LIGHT_LEVELS)


def _film_names() -> list[str]:
    from camtool.exposure.reciprocity import load_films

    shipped = [name for film in load_films().values() for name in (film.id, *film.aliases)]
    return shipped + preset_names("film")


@camtool_command("exposure", keys=[*KEYS, "shutter_angle_deg"], batch=False)
@click.option("-N", "--f-number", "f_number", type=ApertureType(), multiple=True,
              help="f-number (8, f/8, f8) or T-stop (T2; exposure uses it as is); a list 2.8,4 gives a row each. "
                   "Without a light level: the metered f-number. Left out with --lens of a cinema lens: its "
                   "widest T-stop.")
@click.option("--exact-stops", is_flag=True,
              help="Read nominal f-numbers as the exact 2^(k/6) stops they label (5.6 -> 5.657, 22 -> 22.627).")
@click.option("-t", "--shutter", "shutter_s", type=TimeType(), multiple=True,
              help="Time: 1/250, 0.5, 2s, 90s, 1m30s, 1:30, 2h5m (every number with its unit; 2h30 is refused). "
                   "Without a light level: the metered time.")
@click.option("--shutter-angle", type=NumberType(*ranges.SHUTTER_ANGLE_DEG), multiple=True,
              help="Shutter angle in degrees (with --fps): the time is angle/(360·fps), 180 at 24 fps is 1/48 s.")
@click.option("--fps", type=NumberType(*ranges.FRAME_RATE_FPS), help="Frame rate: with it every row gets the "
              "shutter_angle_deg of its time to set (360·fps·t; above 360 no shutter gives it).")
@click.option("--iso", type=NumberType(1, 1e7), multiple=True,
              help="ISO speed (1 to 10000000); default 100. Without a light level: the metered ISO.")
@click.option("--ev100", type=NumberType(-10, 25), multiple=True,
              help="Scene light level as EV at ISO 100 (-10 to 25): solves the setting left out, or lists "
                   "the equivalents when both -N and -t are left out.")
@click.option("--ev", type=NumberType(-10, 25), multiple=True,
              help="Light level as the EV a meter reads at the ISO in use (--iso, default 100).")
@click.option("--light", metavar="NAME", shell_complete=completion(_light_names),
              help="Named light level: sunny, slight-overcast, overcast, heavy-overcast, shade, snow, "
                   "sunset, home-interior, ... (sunny-16 rule and ANSI exposure tables).")
@click.option("--luminance", type=NumberType(1e-9, 1e12),
              help="Reflected-light reading: scene luminance in cd/m² (N²/t = L·S/K).")
@click.option("--illuminance", type=IlluminanceType(1e-9, 1e12),
              help="Incident-light reading: illuminance in lux (400, 400lx) or foot-candles (37fc); N²/t = E·S/C.")
@click.option("--meter-k", type=NumberType(1, 100), default="12.5", show_default=True,
              help="Reflected-light meter calibration constant K in cd·s/m² (ISO 2720: 10.6 to 13.4; Minolta 14).")
@click.option("--meter-c", type=IlluminanceType(1, 10000), default="250", show_default=True,
              help="Incident-light meter calibration constant C in lx·s (250 flat receptor, 320-340 dome); "
                   "or in fc·s with fc (23.2fc).")
@click.option("--nd", multiple=True, metavar="FILTER",
              help="ND filter, repeatable (stacked): a factor ND1000 or 1000x, stops 10stops or 10ev, an optical "
                   "density 3.0D or OD3 (a bare number is refused: it could be any of the three).")
@click.option("--magnification", type=NumberType(0, 100), help="Close-up magnification m (1 = 1:1): bellows factor.")
@click.option("--pupil-mag", "pupil_magnification", type=PupilMagnificationType(), default="1", show_default=True,
              help="Pupil magnification P of the lens (exit/entrance pupil) for the bellows factor (1 + m/P)².")
@click.option("--film", metavar="NAME", shell_complete=completion(_film_names),
              help="Film for reciprocity failure, from its maker's data (hp5, tmax100, tri-x, velvia50, acros, "
                   "800t, ...; `camtool presets list --kind film` lists them) or a films preset.")
@click.option("--reciprocity-p", "reciprocity_p", type=NumberType(1, 3),
              help="Schwarzschild exponent p for a film not in the list: t_c = t_m^p beyond 1 s.")
@click.option("--to-iso", "new_iso", type=NumberType(1, 1e7),
              help="Move the metered exposure (-N, -t, --iso) to this ISO.")
@click.option("--to-f-number", "new_f_number", type=ApertureType(),
              help="Move the metered exposure to this f-number.")
@click.option("--solve", type=click.Choice(["time", "f-number", "iso"]), default="time", show_default=True,
              help="With metered settings: the setting to answer (the others stay as metered or moved).")
@click.option("--step", type=click.Choice(["full", "half", "third"]), default="third", show_default=True,
              help="Stops the nearest standard values (and --equivalents) use; bulb times (> 30 s) are not snapped.")
@click.option("--equivalents", is_flag=True,
              help="List equivalent f-number and time pairs for the exposure (over --step stops).")
def exposure(ctx: click.Context, f_number, exact_stops, shutter_s, shutter_angle, fps, iso, ev100, ev, light, luminance,
             illuminance, meter_k, meter_c, nd, magnification, pupil_magnification, film, reciprocity_p, new_iso, new_f_number,
             solve, step, equivalents, fmt, units, preset_files) -> Output:
    """Exposure: correct a metered exposure, solve a scene, list equivalents, meter readings.

    Metered settings in, settings out: give what the meter said without the
    filter (-N, -t, --iso) and the change (--nd, --magnification, --film,
    --to-iso, --to-f-number): the answer is the time to set (--solve for the
    f-number or ISO), each correction in stops. Or give a light level (--ev100,
    --ev, --light, --luminance, --illuminance) and two of -N, -t, --iso to solve
    the third (ISO 100 when only -N or -t is given); with both -N and -t left
    out, the equivalent f-number and time pairs. -N and -t alone give their EV
    and the scene's EV100. EV = log2(N²/t) is the settings'; EV100 = EV −
    log2(ISO/100) the scene's. Times over 30 s are bulb times, shown exactly.
    JSON and CSV rows carry every setting, correction and APEX value (each
    key listed in camtool-exposure(1) and docs/exposure.md); --equivalents
    rows carry the f-number, times and EV of each pair.

    \b
    Examples:
      camtool exposure -N 8 -t 1/60 --nd ND1000
      camtool exposure -N 8 -t 30 --iso 800 --to-iso 100
      camtool exposure -N 11 -t 4 --film hp5 --nd 6stops
      camtool exposure -N 16 -t 1/125
      camtool exposure --light sunny -N 16 --iso 400
      camtool exposure --ev100 12 -N 8 --nd ND1000 --film hp5
      camtool exposure --ev100 12 --iso 100 --equivalents
      camtool exposure --illuminance 37fc -N 4 --iso 400
      camtool exposure --lens cooke-s4i-50mm-t2 --ev100 12
      camtool exposure --light sunny --shutter-angle 180 --fps 24 --iso 800 --nd ND1.2
      camtool exposure --ev100 10 -N T2.8 --iso 800 --fps 24
    """
    from camtool.cli.equipment import LENS
    from camtool.exposure.calculator import work_out
    from camtool.plans.cine import shutter_angles, shutter_times
    from camtool.plans.equipment import exposure_apertures

    light_given = any((ev100, ev, light, luminance, illuminance))
    with library_errors(ctx):
        shutter_s = shutter_times(shutter_angle_deg=flatten(shutter_angle), fps=fps[0] if fps else None,
                                  shutter_s=flatten(shutter_s))
        chosen = exposure_apertures(flatten(f_number), lens=ctx.meta.get(LENS), exact_stops=exact_stops,
                                    solving=bool(light_given and shutter_s and iso), equivalents=equivalents)
    apertures, t_stop = chosen.f_numbers, chosen.t_stop
    lens_note = "" if chosen.widest_t_stop is None else \
        f" · T{chosen.widest_t_stop:g}: the widest T-stop of --lens {ctx.meta[LENS].id}"
    film_data = _film(ctx, film, preset_files) if film else None
    lists = {"f_number": apertures, "shutter_s": shutter_s, "iso": flatten(iso), "ev100": flatten(ev100),
             "ev": flatten(ev), "luminance": flatten(luminance), "illuminance": flatten(illuminance)}
    given = {name: values for name, values in lists.items() if values}
    count, columns = combine_params(ctx, *given.values()) if given else (1, ())
    value = dict(zip(given, columns))
    with library_errors(ctx):
        answer = work_out(
            **value, light=light, meter_k=meter_k[0], meter_c=meter_c[0], nd=nd,
            magnification=magnification[0] if magnification else 0.0,
            pupil_magnification=pupil_magnification, film=film_data,
            reciprocity_p=reciprocity_p[0] if reciprocity_p else None,
            new_iso=new_iso[0] if new_iso else None,
            new_f_number=float(new_f_number[0]) if new_f_number else None,
            solve=solve.replace("-", "_"), t_stop=t_stop, step=step, equivalents=equivalents, count=count)
    time_key = "shutter_exact_s" if answer.mode == "equivalents" else "corrected_shutter_s"
    angles = {"shutter_angle_deg": shutter_angles(answer.values[time_key], fps=fps[0])} if fps else {}
    rows = rows_from(answer.rows, {**answer.values, **angles})
    shown, keys, note = exposure_view(answer, rows, t_stop=t_stop, step=step, film=film_data, angles=list(angles))
    return Output(rows, shown, keys, note + (lens_note if answer.mode != "equivalents" else "") if fmt == "table" else "")


def _film(ctx: click.Context, name: str, preset_files: tuple[str, ...]) -> Any:
    """The film named by --film (:func:`camtool.plans.presets.film`); an unknown name is one line on --film."""
    from camtool.cli.equipment import open_presets
    from camtool.cli.options import bad_parameter
    from camtool.core.errors import DomainError
    from camtool.plans.presets import film

    try:
        return film(name, database=lambda: open_presets(ctx, preset_files))
    except DomainError as error:
        raise bad_parameter(ctx, error) from None
