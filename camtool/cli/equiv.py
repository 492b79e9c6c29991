"""``camtool equiv``: the same picture on another format, and teleconverters and focal reducers."""

from __future__ import annotations

import click

from camtool.cli.command import Output, camtool_command, combine_params
from camtool.cli.common import required, rows_from
from camtool.cli.equipment import FULL_FRAME, resolve_sensor
from camtool.cli.exposure import single
from camtool.cli.options import focal_option, library_errors, sensor_options
from camtool.cli.params import FNumberType, NumberType, flatten
from camtool.render.views.equiv import COLUMNS, KEYS, equiv_footer


@camtool_command("equiv", keys=KEYS)
@focal_option
@click.option("-N", "--f-number", "f_number", type=FNumberType(), multiple=True, help="f-number: 8, f/8 or f8.")
@click.option("--iso", type=NumberType(1, 1e7), multiple=True, help="ISO speed (default 100).")
@sensor_options
@click.option("--to-sensor", metavar="NAME|WxH", help="The other format: a sensor preset or WxH in mm "
              "(default full frame).")
@click.option("--to-crop", type=float, help="The other format as a crop factor, instead of --to-sensor.")
@click.option("--teleconverter", type=NumberType(1, 4), help="Teleconverter factor k on the lens: f·k at N·k.")
@click.option("--speed-booster", type=NumberType(0.3, 1), help="Focal reducer factor s (0.71, 0.64): f·s at N·s.")
def equiv(ctx: click.Context, focal_length, f_number, iso, sensor, crop, to_sensor, to_crop, teleconverter,
          speed_booster, fmt, units, preset_files) -> Output:
    """The same picture on another format: focal length, f-number and ISO.

    With r the ratio of the formats' diagonals (the other over this one):
    the same angle of view needs f·r; the same depth of field and
    background blur (the same aperture diameter f/N) needs N·r; the same
    total light, hence the same noise at the same time, needs ISO·r². A
    teleconverter k makes the lens f·k at N·k; a focal reducer s, f·s at
    N·s. "light" is the exposure the other format loses at the same N, time
    and ISO, 2·log2(r) stops.

    \b
    Examples:
      camtool equiv -f 25 -N 1.4 --iso 200 --sensor m43
      camtool equiv -f 50 -N 2.8 --to-crop 1.5
      camtool equiv -f 70 -N 2.8 --teleconverter 1.4 --sensor full-frame --to-sensor full-frame
    """
    from camtool.exposure.equivalence import equivalent_settings

    if teleconverter and speed_booster:
        raise click.UsageError("Give --teleconverter or --speed-booster, not both.", ctx)
    focal = required(ctx, focal_length, "-f")
    apertures = required(ctx, f_number, "-N")
    speeds = flatten(iso) or [100.0]
    source = resolve_sensor(ctx, sensor, crop, preset_files)
    target = FULL_FRAME if to_sensor is None and to_crop is None else _target(ctx, to_sensor, to_crop, preset_files)
    converter = single(ctx, teleconverter) or single(ctx, speed_booster, 1.0)
    count, (f, n, s) = combine_params(ctx, focal, apertures, speeds)
    with library_errors(ctx):
        e = equivalent_settings(f, n, s, source.diagonal_mm, target.diagonal_mm, converter)
    rows = rows_from(count, {"focal_length_mm": f, "f_number": n, "iso": s,
                             "equivalent_focal_length_mm": e.focal_length_mm, "equivalent_f_number": e.f_number,
                             "equivalent_iso": e.iso, "ratio": e.ratio, "aperture_diameter_mm": e.aperture_diameter_mm,
                             "light_stops": e.light_stops, "converter": converter})
    note = equiv_footer(rows, source=source, target=target, converter=converter) if fmt == "table" else ""
    return Output(rows, COLUMNS, KEYS, note)


def _target(ctx: click.Context, to_sensor: str | None, to_crop: float | None, files: tuple[str, ...]):
    """The other format: ``--to-sensor`` or ``--to-crop``, resolved as a sensor is (a camera is the source's)."""
    from camtool.cli.equipment import input_errors, open_presets
    from camtool.core.errors import DomainError, InputError
    from camtool.plans import equipment
    from camtool.presets import PresetNotFound

    renamed = {"sensor": "to_sensor", "crop": "to_crop", "lens": "to_sensor"}
    with input_errors(ctx, files):
        try:
            return equipment.resolve_sensor(sensor=to_sensor, crop=to_crop, database=lambda: open_presets(ctx, files))
        except (DomainError, InputError, PresetNotFound) as error:
            error.param = renamed.get(error.param, error.param)
            if isinstance(error, InputError):
                error.template = error.template.replace("{sensor}", "{to_sensor}").replace("{crop}", "{to_crop}")
            raise
