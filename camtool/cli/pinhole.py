"""``camtool pinhole``: the pinhole's diameter by contrast, the published rules, their blur and exposure."""

from __future__ import annotations

import math

import click

from camtool.cli.command import Output, camtool_command
from camtool.cli.equipment import resolve_sensor
from camtool.cli.lensdata import wavelength_option
from camtool.cli.options import DISTANCE_M, FOCAL_MM, library_errors, sensor_options
from camtool.cli.params import NumberType, one_value
from camtool.core import ranges
from camtool.plans.pinhole import DEFAULT_LEVEL, pinhole_plan
from camtool.render.views.pinhole import COLUMNS, KEYS


@camtool_command("pinhole", keys=KEYS)
@click.option("-f", "--film-distance", "film_distance", type=FOCAL_MM, required=True, callback=one_value,
              help="Pinhole-to-film distance (the focal length), e.g. 50 or 5cm (bare numbers are mm).")
@click.option("-s", "--distance", type=DISTANCE_M, callback=one_value,
              help="Subject distance from the pinhole (bare numbers are metres); default: a --scene's, else inf.")
@click.option("--contrast", type=NumberType(*ranges.MTF_LEVEL), default=DEFAULT_LEVEL, show_default=True, callback=one_value,
              help="The MTF level the optimum resolves the finest detail at (0.5: MTF50).")
@wavelength_option()
@click.option("--ev100", type=NumberType(-10, 25), default=15.0, show_default=True, callback=one_value,
              help="Scene brightness for the exposure time (15: sunny, the sunny-16 rule).")
@click.option("--iso", type=NumberType(1, 1e7), default=100.0, show_default=True, callback=one_value, help="ISO speed.")
@sensor_options
def pinhole(ctx: click.Context, film_distance, distance, contrast, wavelength, ev100, iso, sensor, crop, fmt, units,
            preset_files) -> Output:
    """Pinhole camera: the diameter that resolves the finest detail, beside the published rules.

    Each row is a diameter d = k·√(λ·F), F = L·s/(L + s): the optimum for
    --contrast (the k whose MTF reaches that contrast at the highest
    frequency on the film), then Petzval's rule (k = √2), the Airy rule
    (k = 1.562), Rayleigh's 1.9 and Young's one Fresnel zone (2). Each shows its f-number L/d, the
    hole's shadow d(1 + L/s), the Airy disc 2.44·λ·L/d, the defocus k²/8
    waves, the frequency at which its MTF falls to the contrast, the
    contrast at which that rule is itself the best, and the exposure time
    at its f-number for --ev100 and --iso (docs/wave.md).

    \b
    Examples:
      camtool pinhole -f 50
      camtool pinhole -f 150 -s 2m --contrast 0.2 --format json
    """
    chosen = resolve_sensor(ctx, sensor, crop, preset_files)
    with library_errors(ctx):
        plan = pinhole_plan(film_distance_mm=film_distance, subject_distance_mm=math.inf if distance is None else distance,
                            wavelength_nm=wavelength,
                            level=contrast, sensor_width_mm=chosen.width_mm, sensor_height_mm=chosen.height_mm,
                            ev100=ev100, iso=iso)
    angle = plan.rows[0]
    note = (f"d = k·√(λ·F), F = {plan.effective_distance_mm:.4g} mm, λ {wavelength:g} nm · lp/mm at MTF "
            f"{plan.level:g} · {chosen.label}: {angle['horizontal_deg']:.3g}° × {angle['vertical_deg']:.3g}°, "
            f"{angle['diagonal_deg']:.3g}° diagonal · EV100 {ev100:g}, ISO {iso:g}")
    return Output(plan.rows, COLUMNS, KEYS, note if fmt == "table" else "")
