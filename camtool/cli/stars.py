"""``camtool stars``: the longest exposure before stars trail (500 rule, NPF rule)."""

from __future__ import annotations

import math

import click

from camtool.cli.command import Output, camtool_command, combine_params
from camtool.cli.common import required, rows_from
from camtool.cli.equipment import resolve_sensor
from camtool.cli.exposure import single
from camtool.cli.options import PIXEL_PITCH_UM, focal_option, library_errors, sensor_options
from camtool.cli.params import FNumberType, NumberType, flatten
from camtool.render.views.stars import COLUMNS, KEYS, stars_footer


@camtool_command("stars", keys=KEYS)
@focal_option
@click.option("-N", "--f-number", "f_number", type=FNumberType(), multiple=True,
              help="f-number (the NPF rule needs it; the 500 rule does not); a list gives a row each.")
@sensor_options
@click.option("--pixel-pitch", type=PIXEL_PITCH_UM, multiple=True,
              help="Pixel pitch, e.g. 4.3 or 4.3um (bare numbers are µm, as spec sheets give it and as everywhere in "
                   "camtool; default: from --camera); a list gives a row each.")
@click.option("--declination", type=NumberType(-89, 89), multiple=True, default=["0"], show_default=True,
              help="Declination of the stars in degrees (0: the celestial equator, where they move fastest).")
@click.option("--rule-constant", type=NumberType(100, 1000), default="500", show_default=True,
              help="The constant of the 500 rule (600 and 450 are common variants).")
@click.option("--npf-k", type=NumberType(0.1, 10), default="1", show_default=True,
              help="Tolerance factor k of the full NPF rule (1 as published).")
def stars(ctx: click.Context, focal_length, f_number, sensor, crop, pixel_pitch, declination, rule_constant, npf_k,
          fmt, units, preset_files) -> Output:
    """Longest exposure before stars trail, on a fixed tripod: the 500 rule and the NPF rule.

    500 rule: t = 500 / (f · crop). NPF rule (F. Michaud, 2016), N the
    f-number, p the pixel pitch in µm, f the real focal length in mm, δ the
    declination: simple form t = (35·N + 30·p) / (f·cos δ) (PhotoPills'
    default accuracy); full form t = k·(16.856·N + 0.0997·f + 13.713·p) /
    (f·cos δ). The pixel pitch comes from --camera or --pixel-pitch; without
    it only the 500 rule is given.

    \b
    Examples:
      camtool stars -f 24 -N 2.8 --pixel-pitch 4.3um
      camtool stars -f 14,24,50 -N 2.8 --crop 1.5 --pixel-pitch 3.9um --declination 30
      camtool stars -f 50
    """
    from camtool.exposure.stars import star_limits
    from camtool.plans.equipment import pixel_pitches

    focal = required(ctx, focal_length, "-f")
    chosen = resolve_sensor(ctx, sensor, crop, preset_files)
    pitches = [p * 1000.0 for p in pixel_pitches(flatten(pixel_pitch), chosen)]
    apertures = flatten(f_number)
    if pitches and not apertures:
        raise click.UsageError("The NPF rule needs the f-number: give -N (or leave out the pixel pitch).", ctx)
    count, (f, n, p, dec) = combine_params(ctx, focal, apertures or [math.nan], pitches or [math.nan],
                                           flatten(declination))
    with library_errors(ctx):
        limits = star_limits(f, n, chosen.crop_factor, p if pitches else None, dec, single(ctx, rule_constant),
                             single(ctx, npf_k))
    pitch_um = p if pitches else None
    rows = rows_from(count, {"focal_length_mm": f, "f_number": n if apertures else None,
                             "crop_factor": chosen.crop_factor, "pixel_pitch_um": pitch_um,
                             "declination_deg": dec, "rule500_s": limits.rule500_s,
                             "npf_simple_s": limits.npf_simple_s, "npf_s": limits.npf_s})
    if fmt != "table":
        return Output(rows, COLUMNS, KEYS, "")
    note = stars_footer(rows, apertures_given=bool(apertures), pitches_um=pitches, sensor=chosen,
                        rule_constant=single(ctx, rule_constant))
    return Output(rows, COLUMNS, KEYS, note)
