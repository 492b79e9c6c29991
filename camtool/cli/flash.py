"""``camtool flash``: guide-number arithmetic, GN = distance × f-number at ISO 100."""

from __future__ import annotations

import click

from camtool.cli.command import Output, camtool_command, combine_params
from camtool.cli.common import rows_from
from camtool.cli.exposure import single
from camtool.cli.options import DISTANCE_M, library_errors
from camtool.cli.params import FNumberType, NumberType, _ListType, flatten
from camtool.core.units import parse_guide_number
from camtool.render.views.flash import COLUMNS, KEYS, flash_footer


class GuideNumberType(_ListType):
    """A guide number in metres (a bare number or 40m) or feet (131ft)."""

    name = "guide number"
    valid = "> 0 (metres, or feet with ft: 40, 40m, 131ft)"

    def parse(self, text: str) -> float:
        return parse_guide_number(text)


@camtool_command("flash", keys=KEYS)
@click.option("--gn", "guide_number", type=GuideNumberType(), multiple=True,
              help="Guide number in metres (40, 40m) or feet (131ft), at --gn-iso.")
@click.option("--gn-iso", type=NumberType(1, 1e7), default="100", show_default=True,
              help="The ISO the guide number is quoted at (makers quote ISO 100, some ISO 200).")
@click.option("-s", "--distance", type=DISTANCE_M, multiple=True,
              help="Flash-to-subject distance (bare numbers are metres; 10ft).")
@click.option("-N", "--f-number", "f_number", type=FNumberType(), multiple=True, help="f-number: 8, f/8 or f8.")
@click.option("--iso", type=NumberType(1, 1e7), multiple=True, help="ISO speed in use.")
def flash(ctx: click.Context, guide_number, gn_iso, distance, f_number, iso, fmt, units, preset_files) -> Output:
    """Flash guide numbers: give three of --gn, -s, -N, --iso and get the fourth.

    GN = distance × f-number at the ISO the guide number is quoted at (100);
    at ISO S the guide number is GN·√(S/100), so four times the ISO doubles
    the distance or the f-number. Guide numbers are in metres (feet with ft).

    \b
    Examples:
      camtool flash --gn 20 -s 5 --iso 100
      camtool flash --gn 51 --gn-iso 200 -s 9 --iso 800
      camtool flash --gn 40 -N 8 --iso 400
      camtool flash -s 3 -N 5.6 --iso 100
    """
    from camtool.plans import flash as plan

    lists = dict(zip(plan.INPUTS, (flatten(guide_number), flatten(distance), flatten(f_number), flatten(iso))))
    given = {name: values for name, values in lists.items() if values}
    count, columns = combine_params(ctx, *given.values()) if len(given) == 3 else (0, [])
    with library_errors(ctx):
        result = plan.solve(**{name: (column if len(given) == 3 else values[0])
                               for (name, values), column in zip(given.items(), columns or given.values())},
                            quoted_iso=single(ctx, gn_iso, 100.0))
    rows = rows_from(count, {"guide_number_m": result.guide_number_m, "guide_number_at_iso_m":
                             result.guide_number_at_iso_m, "distance_mm": result.distance_m * 1000.0,
                             "f_number": result.f_number, "iso": result.iso, "solved": result.solved})
    note = flash_footer(rows, solved=result.solved, imperial=units == "imperial") if fmt == "table" else ""
    return Output(rows, COLUMNS, KEYS, note)
