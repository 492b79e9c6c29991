"""``camtool chart KIND``: depth-of-field questions drawn as PNG, SVG or PDF.

Each kind takes the same inputs, presets, units and models as the command
it draws (``dof``, ``compose``, the model ladder), computes its numbers with
the library (:mod:`camtool.render.chartdata`) and hands them to the plotting
layer (:mod:`camtool.render.chartplot`), which needs matplotlib, an optional
extra (``pip install 'camtool[chart]'``) imported only here.

``python -m camtool.cli.chart docs/charts`` regenerates the example charts
shown in the README (an SVG and a JSON file of its data each); a test
checks the committed data for drift.
"""

from __future__ import annotations

import functools
import json
import math
import os
import re
import stat
import sys
from collections.abc import Callable, Sequence
from pathlib import Path
from typing import Any

import click

from camtool.cli.command import equipment_options, presets_option
from camtool.cli.common import f_numbers, footer, required, single
from camtool.cli.equipment import apply_equipment, resolve_coc, resolve_sensor
from camtool.cli.lensdata import (
    WavelengthType,
    ladder_errors,
    lens_data,
    model_options,
    pupil_mag_option,
)
from camtool.cli.options import (
    DISTANCE_M,
    aperture_options,
    coc_options,
    distance_plane_option,
    focal_option,
    library_errors,
    param_named,
    sensor_options,
    stack,
)
from camtool.cli.params import LengthType, NumberType, flatten
from camtool.dof.ladder import model_choices

IMAGE_FORMATS = ("png", "svg", "pdf")
DEFAULT_SIZE_IN = (8.0, 5.0)
POINTS = 161
INSTALL_HINT = "camtool chart needs matplotlib, an optional extra: pip install 'camtool[chart]' (or pip install matplotlib)"
PAPER_HELP = "a6 (148 × 105 mm) or letter-quarter (5.5 × 4.25 in), landscape"
CARD_DISTANCES_M = [0.5, 0.7, 1.0, 1.5, 2.0, 3.0, 5.0, 7.0, 10.0, 20.0, math.inf]
CARD_F_NUMBERS = [2.8, 4.0, 5.6, 8.0, 11.0, 16.0, 22.0]
BLUR_FOCAL_LENGTHS_MM = [24.0, 35.0, 50.0, 85.0, 135.0, 200.0]
SIZE_M = LengthType("m")
MODELS = [name for name in model_choices() if name != "all"]

EXAMPLES = {
    "dof": "camtool chart dof -f 50 -N 2.8,8,22 -o docs/charts/dof.svg",
    "blur": "camtool chart blur --subject-size 1.8m --fill 0.8 -f 35,50,85,135 -N 2.8 -o docs/charts/blur.svg",
    "aperture": "camtool chart aperture -f 24 --near 2m --far inf -o docs/charts/aperture.svg",
    "trade": "camtool chart trade -N 8 -s 3m --lens dgauss100-lens -o docs/charts/trade.svg",
    "card": "camtool chart card -f 35 --paper a6 -o docs/charts/card.svg",
}
"""The charts committed under docs/charts/ and shown in the README, by kind."""


class SizeType(click.ParamType):
    """A figure size ``WxH`` in inches (``8x5``), or with a unit: ``20x12cm``, ``160x100mm``, ``8x5in``."""

    name = "size"
    _pattern = re.compile(r"^\s*(\d+(?:\.\d*)?)\s*[x×X]\s*(\d+(?:\.\d*)?)\s*(in|cm|mm)?\s*$")

    def convert(self, value: Any, param: click.Parameter | None, ctx: click.Context | None) -> tuple[float, float]:
        if isinstance(value, tuple):
            return value
        match = self._pattern.match(str(value))
        if not match:
            self.fail(f"{value!r} is not a size (examples: 8x5, 8x5in, 20x12cm)", param, ctx)
        per_inch = {"in": 1.0, None: 1.0, "cm": 2.54, "mm": 25.4}[match.group(3)]
        w, h = float(match.group(1)) / per_inch, float(match.group(2)) / per_inch
        if not (1.0 <= w <= 40.0 and 1.0 <= h <= 40.0):
            self.fail(f"{value} is outside the valid range: 1 to 40 inches a side", param, ctx)
        return w, h


chart_output_options = stack(
    click.option("-o", "--output", required=True, metavar="FILE",
                 help="The chart file: its extension (.png, .svg, .pdf) picks the format; - writes to standard "
                      "output (with --image-format)."),
    click.option("--image-format", type=click.Choice(IMAGE_FORMATS),
                 help="png, svg or pdf; needed with -o -, otherwise taken from the file's extension."),
    click.option("--size", type=SizeType(), metavar="WxH", help="Figure size in inches (8x5) or with a unit "
                 "(20x12cm). Default: 8x5 in; for card, the --paper size."),
    click.option("--dpi", type=NumberType(20, 1200), default="150", show_default=True,
                 help="Pixels per inch of a PNG (SVG and PDF are vector); a PNG has at most 144 megapixels "
                      "(40x40 in at 300 dpi)."),
    click.option("--data", "data_file", metavar="FILE",
                 help="Also write the plotted numbers as JSON (mm, f-numbers, seconds; infinity as null)."),
    click.option("--units", type=click.Choice(["metric", "imperial"]), default="metric", show_default=True,
                 help="Units of the distances shown (blur discs stay in mm on the sensor)."),
    presets_option,
)
"""The options every chart shares: where and how to write it."""


def _image_format(ctx: click.Context, output: str, given: str | None) -> str:
    """The format from --image-format or the -o file's extension; a one-line error when neither says."""
    suffix = Path(output).suffix.lower().lstrip(".") if output != "-" else ""
    if output == "-" and given is None:
        raise click.UsageError("-o - writes to standard output: give --image-format png, svg or pdf.", ctx)
    if given is not None:
        if suffix and suffix != given:
            raise click.BadParameter(f"{output} has the extension .{suffix} but --image-format is {given}",
                                     ctx=ctx, param=param_named(ctx, "output"))
        return given
    if suffix not in IMAGE_FORMATS:
        shown = f".{suffix}" if suffix else "no extension"
        raise click.BadParameter(f"{output} has {shown}: use .png, .svg or .pdf, or give --image-format",
                                 ctx=ctx, param=param_named(ctx, "output"))
    return suffix


def plotting(ctx: click.Context | None = None) -> Any:
    """The plotting layer, or a one-line error (exit 1) saying what to install when matplotlib is missing."""
    try:
        import matplotlib  # noqa: F401
    except ImportError:
        raise click.ClickException(INSTALL_HINT) from None
    from camtool.render import chartplot

    return chartplot


def chart_command(name: str, default_size: Callable[[dict[str, Any]], tuple[float, float]] | None = None
                  ) -> Callable[[Callable[..., Any]], click.Command]:
    """Make a chart subcommand of a function that returns the chart's :class:`ChartData`."""

    def decorate(compute: Callable[..., Any]) -> click.Command:
        @functools.wraps(compute)
        def run(ctx: click.Context, /, **params: Any) -> None:
            output, given = params.pop("output"), params.pop("image_format")
            size, dpi, data_file = params.pop("size"), params.pop("dpi"), params.pop("data_file")
            fmt = _image_format(ctx, output, given)
            resolution = float(single(ctx, dpi, "--dpi"))
            if output == "-" and data_file == "-":
                raise click.UsageError("-o - and --data - would both write to standard output.", ctx)
            _check_targets(output, data_file)
            plot = plotting(ctx)
            params = apply_equipment(ctx, params)
            width, height = size or (default_size(params) if default_size else DEFAULT_SIZE_IN)
            if fmt == "png":
                _check_pixels(ctx, (width, height), resolution)
            data = compute(ctx, **params)
            figure = plot.draw(data, width, height, params["units"])
            notes: list[str] = []
            image = plot.to_bytes(figure, fmt, resolution, notes)
            _write(output, "-o/--output", image)
            if notes:
                click.echo(f"Warning: the chart is too small for its labels at {width:.3g} × {height:.3g} in; "
                           "some may overlap (give a larger --size)", err=True)
            if data_file is not None:
                text = json.dumps(data.to_json(), allow_nan=False, ensure_ascii=False, indent=1) + "\n"
                _write(data_file, "--data", text.encode("utf-8"))

        command = click.command(name)(click.pass_context(equipment_options(chart_output_options(run))))
        return command

    return decorate


def _check_pixels(ctx: click.Context, size: tuple[float, float], dpi: float) -> None:
    """Refuse, before anything is computed, a PNG with more pixels than :data:`MAX_PIXELS`."""
    from camtool.render.chartdata import MAX_PIXELS, raster_pixels

    width, height = size
    across, down = raster_pixels(width, height, dpi)
    if across * down <= MAX_PIXELS:
        return
    raise click.BadParameter(
        f"{dpi:g} with --size {width:g}x{height:g} in is {across} × {down} pixels ({across * down / 1e6:.1f} "
        f"megapixels); a PNG chart has at most {MAX_PIXELS / 1e6:.0f} megapixels (40x40 in at 300 dpi): "
        "give a smaller --dpi or --size", ctx=ctx, param=param_named(ctx, "dpi"))


def _check_targets(output: str, data_file: str | None) -> None:
    """Refuse at once an output that cannot be written: no such directory, or not a regular file."""
    for target, option in ((output, "-o/--output"), (data_file, "--data")):
        if target is None or target == "-":
            continue
        try:
            info = os.stat(target)
        except FileNotFoundError:
            if not Path(target).resolve().parent.is_dir():
                raise click.ClickException(f"{option} {target}: cannot write there: no such directory") from None
            continue
        except OSError as error:
            raise click.ClickException(f"{option} {target}: cannot write there: {error.strerror or error}") from None
        if not stat.S_ISREG(info.st_mode):
            raise click.ClickException(f"{option} {target}: cannot write there: {_not_regular(info.st_mode)}")
    if output != "-" and data_file not in (None, "-") and os.path.realpath(output) == os.path.realpath(data_file):
        raise click.ClickException(f"--data {data_file}: the same file as -o/--output; give another name")


def _not_regular(mode: int) -> str:
    kind = ("a directory" if stat.S_ISDIR(mode) else "a FIFO (named pipe)" if stat.S_ISFIFO(mode)
            else "a socket" if stat.S_ISSOCK(mode) else "a device" if stat.S_ISCHR(mode) or stat.S_ISBLK(mode)
            else "not a regular file")
    return f"it is {kind}, not a regular file" if kind != "not a regular file" else "it is not a regular file"


def _write(target: str, option: str, payload: bytes) -> None:
    """Write ``payload`` to standard output (``-``) or to the regular file ``target``, created if missing.

    The file is opened without blocking and checked again once open, so a FIFO
    or device put in its place after the first check is refused, not waited on.
    """
    if target == "-":
        stream = getattr(sys.stdout, "buffer", None)
        if stream is None:  # standard output closed (camtool chart ... -o - >&-)
            raise click.ClickException("cannot write to standard output: it is closed")
        try:
            stream.write(payload)
            stream.flush()
        except ValueError:  # the stream was closed under us
            raise click.ClickException("cannot write to standard output: it is closed") from None
        return
    flags = os.O_WRONLY | os.O_CREAT | getattr(os, "O_NONBLOCK", 0) | getattr(os, "O_CLOEXEC", 0)
    try:
        fd = os.open(target, flags, 0o666)
    except OSError as error:
        raise click.ClickException(f"{option} {target}: cannot write there: {error.strerror or error}") from None
    try:
        info = os.fstat(fd)
        if not stat.S_ISREG(info.st_mode):
            raise click.ClickException(f"{option} {target}: cannot write there: {_not_regular(info.st_mode)}")
        os.ftruncate(fd, 0)
        view = memoryview(payload)
        while view:
            view = view[os.write(fd, view):]
    except OSError as error:
        raise click.ClickException(f"{option} {target}: cannot write there: {error.strerror or error}") from None
    finally:
        os.close(fd)


def _one_list(ctx: click.Context, focal: Sequence[float], apertures: Sequence[float]) -> None:
    if len(focal) > 1 and len(apertures) > 1:
        raise click.UsageError("Give several f-numbers or several focal lengths (-N or -f), not both: "
                               "each curve is one of them.", ctx)


def _coc(ctx: click.Context, coc: Any, coc_rule: Any, chosen: Any, pixel_pitch: Any) -> tuple[float, list[float], str]:
    cocs, origin = resolve_coc(ctx, list(coc or ()), coc_rule, chosen, pixel_pitch)
    if len(cocs) > 1:
        raise click.UsageError("Option '--coc' takes one value here.", ctx)
    return cocs[0], cocs, origin


def _lens_label(focal: Sequence[float]) -> str:
    return ", ".join(f"{f:g}" for f in focal) + " mm"


def _range(ctx: click.Context, low: float, high: float, option: str) -> None:
    if not low < high:
        raise click.BadParameter(f"{high:g} is outside the valid range: more than --from ({low:g})", ctx=ctx,
                                 param=param_named(ctx, option))


@click.group("chart", context_settings={"help_option_names": ["-h", "--help"]})
def chart() -> None:
    """Charts of depth of field, background blur, aperture, the model ladder and a printable DOF card.

    Each kind writes PNG, SVG or PDF (from the -o file's extension; -o - with
    --image-format writes to standard output) with the inputs, presets, units
    and models of the matching command. Colours are the Okabe–Ito
    colour-blind-safe palette, each curve with its own line style as well, for
    grey-scale print. A chart is a picture, so there is no --format (nor
    CAMTOOL_FORMAT): --data FILE writes the plotted numbers as JSON. Needs
    matplotlib: pip install 'camtool[chart]'.

    \b
    Examples:
      camtool chart dof -f 50 -N 2.8,8,22 -o dof.png
      camtool chart blur --subject-size 1.8m --fill 0.8 -f 35,85,135 -N 2.8 -o blur.svg
      camtool chart aperture -f 100 --near 1m --far 1.5m -o aperture.pdf
      camtool chart trade -N 8 -s 3m --lens dgauss100-lens -o trade.svg
      camtool chart card -f 35 --units imperial --paper letter-quarter -o card.pdf
      camtool chart dof -f 35 -N 8 -o - --image-format svg > dof.svg
    """


@chart_command("dof")
@focal_option
@aperture_options
@click.option("--from", "low", type=DISTANCE_M, help="Nearest focus distance charted (default: 10 × the longest "
              "focal length, at least 0.3 m).")
@click.option("--to", "high", type=DISTANCE_M, help="Farthest focus distance charted (default: twice the longest "
              "hyperfocal distance, at least 10 m).")
@sensor_options
@coc_options
@distance_plane_option
@click.option("--model", type=click.Choice(MODELS), default="auto", show_default=True,
              help="Depth-of-field model, as for camtool dof (auto: the cheapest the scene needs within --tolerance).")
@model_options
def chart_dof(ctx: click.Context, focal_length, f_number, exact_stops, low, high, sensor, crop, coc, coc_rule,
              pixel_pitch, distance_from, model, tolerance, diffraction, wavelength, pupil_mag, hiatus,
              prescription_file, units, preset_files) -> Any:
    """Near and far limits against focus distance (log axes), one band per f-number or focal length, H marked."""
    from camtool.dof.ladder import focal_lengths, hyperfocal
    from camtool.render.chartdata import dof_data, log_space

    lens = lens_data(ctx, pupil_mag, hiatus, prescription_file)
    with library_errors(ctx):
        focal = required(ctx, focal_lengths(lens, flatten(focal_length)), "-f")
    apertures = required(ctx, f_numbers(f_number, exact_stops), "-N")
    _one_list(ctx, focal, apertures)
    chosen = resolve_sensor(ctx, sensor, crop, preset_files)
    c, cocs, origin = _coc(ctx, coc, coc_rule, chosen, pixel_pitch)
    start = single(ctx, low, "--from")
    stop = single(ctx, high, "--to")
    if start is None:
        start = max(300.0, 10.0 * max(focal))
    if stop is None:
        with library_errors(ctx):
            longest = max(float(hyperfocal("thin", f, n, c, distance_from).hyperfocal_mm)
                          for f in focal for n in apertures)
        stop = max(10_000.0, 2.0 * longest)
    if math.isinf(stop):
        raise click.BadParameter("inf is outside the valid range: a finite distance", ctx=ctx,
                                 param=param_named(ctx, "high"))
    _range(ctx, start, stop, "high")
    with library_errors(ctx), ladder_errors(ctx):
        data = dof_data(focal, apertures, c, log_space(start, stop, POINTS), model, distance_from, lens, diffraction,
                        wavelength, tolerance)
    used = " / ".join(data.extra["models"])
    data.scene = f"{_lens_label(focal)} · " + footer(used, cocs, origin, chosen.label, distance_from)
    return data


@chart_command("blur")
@focal_option
@click.option("--subject-size", type=SIZE_M, help="Subject size along --fill-axis, e.g. 1.8m (bare numbers are metres).")
@click.option("--fill", type=NumberType(0.001, 10), help="Fraction of the frame the subject fills, e.g. 0.8.")
@click.option("--fill-axis", type=click.Choice(["height", "width"]), default="height", show_default=True,
              help="Frame dimension --fill refers to.")
@click.option("--magnification", type=NumberType(1e-9, 10), help="Magnification, instead of --subject-size and --fill.")
@aperture_options
@click.option("--from", "low", type=SIZE_M, help="Nearest background distance behind the subject (default 0.1 m).")
@click.option("--to", "high", type=SIZE_M, help="Farthest background distance behind the subject (default 100 m).")
@sensor_options
def chart_blur(ctx: click.Context, focal_length, subject_size, fill, fill_axis, magnification, f_number, exact_stops,
               low, high, sensor, crop, units, preset_files) -> Any:
    """Background blur disc (mm and % of the frame width) against distance behind the subject, framing kept.

    One curve per focal length, each standing where it frames the subject the
    same (camtool compose's question), or per f-number with one focal length;
    dotted lines are the blur of a background at infinity, f·m/N.
    """
    from camtool.geometry.compose import magnification_for_fill
    from camtool.render.chartdata import blur_data, log_space

    focal = flatten(focal_length) or BLUR_FOCAL_LENGTHS_MM
    apertures = required(ctx, f_numbers(f_number, exact_stops), "-N")
    _one_list(ctx, focal, apertures)
    size, share = single(ctx, subject_size, "--subject-size"), single(ctx, fill, "--fill")
    given_m = single(ctx, magnification, "--magnification")
    if (given_m is None) == (size is None or share is None):
        raise click.UsageError("Give --subject-size and --fill, or --magnification.", ctx)
    chosen = resolve_sensor(ctx, sensor, crop, preset_files)
    frame = chosen.height_mm if fill_axis == "height" else chosen.width_mm
    start = single(ctx, low, "--from") or 100.0
    stop = single(ctx, high, "--to") or 100_000.0
    _range(ctx, start, stop, "high")
    with library_errors(ctx):
        m = given_m if given_m is not None else magnification_for_fill(size, share, frame)
        subject = f"m = {m:.4g}" if given_m is not None else f"subject {size / 1000:g} m fills {share:g} of the {fill_axis}"
        scene = " · ".join([_lens_label(focal), f"f/{', '.join(f'{n:g}' for n in apertures)}", subject, chosen.label,
                            "thin lens", "background distance from the subject"])
        return blur_data(focal, apertures, m, chosen.width_mm, log_space(start, stop, POINTS), scene)


@chart_command("aperture")
@focal_option
@click.option("--near", type=DISTANCE_M, help="Nearest point of the scene that must be sharp (bare numbers are metres).")
@click.option("--far", type=DISTANCE_M, help="Farthest point of the scene that must be sharp (inf allowed).")
@click.option("-s", "--distance", type=DISTANCE_M, multiple=True,
              help="Focus distance (default: half-way between the images of --near and --far, as for the optimum).")
@click.option("--from", "low", type=NumberType(0.7, 1024), default="1.4", show_default=True,
              help="Widest f-number charted.")
@click.option("--to", "high", type=NumberType(0.7, 1024), default="64", show_default=True,
              help="Narrowest f-number charted.")
@sensor_options
@coc_options
@distance_plane_option
@click.option("--wavelength", type=WavelengthType(), default="550", show_default=True, metavar="NM",
              help="Wavelength for the Airy disc: 550, 550nm or 0.55um.")
@pupil_mag_option
def chart_aperture(ctx: click.Context, focal_length, near, far, distance, low, high, sensor, crop, coc, coc_rule,
                   pixel_pitch, distance_from, wavelength, pupil_mag, units, preset_files) -> Any:
    """Blur at the scene's near and far limits from defocus and from diffraction against f-number, optimum marked.

    Defocus blur (thin lens) of points at --near and --far falls as 1/N; the
    Airy disc 2.44·λ·N(1 + m/P) grows as N. The optimum aperture is marked:
    focused half-way between the near and far images (Hansma's rule, the
    default focus; -s sets another), the f-number where the two are equal and
    their root-sum-square is smallest, the sharpest the whole scene can be.
    """
    from camtool.render.chartdata import aperture_data, log_space

    focal = required(ctx, focal_length, "-f")
    f = single(ctx, focal, "-f")
    n_low, n_high = single(ctx, low, "--from"), single(ctx, high, "--to")
    _range(ctx, n_low, n_high, "high")
    closest, farthest = single(ctx, near, "--near"), single(ctx, far, "--far")
    if closest is None or farthest is None:
        raise click.UsageError("Give the scene's --near and --far.", ctx)
    focus = single(ctx, distance, "-s")
    chosen = resolve_sensor(ctx, sensor, crop, preset_files)
    c, cocs, origin = _coc(ctx, coc, coc_rule, chosen, pixel_pitch)
    scene = f"{f:g} mm · " + footer("thin", cocs, origin, chosen.label, distance_from, f"λ {wavelength:g} nm")
    with library_errors(ctx):
        return aperture_data(f, c, closest, farthest, log_space(n_low, n_high, POINTS), focus, distance_from,
                             pupil_mag if pupil_mag is not None else 1.0, wavelength, scene)


@chart_command("trade")
@focal_option
@aperture_options
@click.option("-s", "--distance", type=DISTANCE_M, multiple=True, help="Focus distance, e.g. 3 (bare numbers are metres).")
@sensor_options
@coc_options
@distance_plane_option
@model_options
def chart_trade(ctx: click.Context, focal_length, f_number, exact_stops, distance, sensor, crop, coc, coc_rule,
                pixel_pitch, distance_from, tolerance, diffraction, wavelength, pupil_mag, hiatus, prescription_file,
                units, preset_files) -> Any:
    """Every rung of the model ladder for your scene: error against the most complete rung versus time per evaluation.

    The rungs the lens data allow (a prescription, from --prescription or a
    --lens that has one, allows all five), timed on the spot on this machine
    (best of three runs), as camtool dof --model all measures them.
    """
    from camtool.dof.ladder import focal_lengths
    from camtool.render.chartdata import trade_data

    lens = lens_data(ctx, pupil_mag, hiatus, prescription_file)
    with library_errors(ctx):
        focal = focal_lengths(lens, flatten(focal_length))
    f = single(ctx, required(ctx, focal, "-f"), "-f")
    n = single(ctx, required(ctx, f_numbers(f_number, exact_stops), "-N"), "-N")
    s = single(ctx, required(ctx, distance, "-s"), "-s")
    chosen = resolve_sensor(ctx, sensor, crop, preset_files)
    c, cocs, origin = _coc(ctx, coc, coc_rule, chosen, pixel_pitch)
    shown = f"{s / 1000:.4g} m" if units == "metric" else f"{s / 304.8:.4g} ft"
    scene = f"{f:.4g} mm f/{n:g} at {shown} · " + footer(None, cocs, origin, chosen.label, distance_from)
    with library_errors(ctx), ladder_errors(ctx):
        return trade_data(f, n, c, s, distance_from, lens, diffraction, wavelength, scene=scene)


def _paper_size(params: dict[str, Any]) -> tuple[float, float]:
    from camtool.render.chartdata import PAPERS

    return PAPERS[params.get("paper") or "a6"]


@chart_command("card", default_size=_paper_size)
@focal_option
@click.option("-N", "--f-number", "f_number", type=NumberType(0.7, 1024), multiple=True,
              help="f-numbers of the columns (default 2.8, 4, 5.6, 8, 11, 16, 22).")
@click.option("--exact-stops", is_flag=True, help="Read nominal f-numbers as the exact 2^(k/6) stops they label.")
@click.option("-s", "--distance", type=DISTANCE_M, multiple=True,
              help="Focus distances of the rows (default 0.5, 0.7, 1, 1.5, 2, 3, 5, 7, 10, 20 m and inf; "
                   "with --units imperial 2, 3, 4, 5, 7, 10, 15, 25, 50 ft and inf).")
@click.option("--paper", type=click.Choice(["a6", "letter-quarter"]), default="a6", show_default=True,
              help=f"Card size: {PAPER_HELP}.")
@sensor_options
@coc_options
@distance_plane_option
@click.option("--model", type=click.Choice(MODELS), default="auto", show_default=True,
              help="Depth-of-field model, as for camtool dof.")
def chart_card(ctx: click.Context, focal_length, f_number, exact_stops, distance, paper, sensor, crop, coc, coc_rule,
               pixel_pitch, distance_from, model, units, preset_files) -> Any:
    """A printable depth-of-field card for one lens: near–far limits for each focus distance and f-number.

    Rows are focus distances, columns f-numbers, each cell the near and far
    limits in the chosen units; the last row is the hyperfocal distance.
    Sized for the camera bag: A6 or a quarter of US Letter.
    """
    from camtool.render.chartdata import card_data

    lens = lens_data(ctx, None, None, None)
    f = single(ctx, required(ctx, focal_length, "-f"), "-f")
    given = flatten(f_number)
    apertures = ([_exact(n) for n in given] if exact_stops else given) or CARD_F_NUMBERS
    distances = flatten(distance) or (
        [v * 304.8 for v in (2.0, 3.0, 4.0, 5.0, 7.0, 10.0, 15.0, 25.0, 50.0)] + [math.inf] if units == "imperial"
        else [v * 1000.0 for v in CARD_DISTANCES_M])
    chosen = resolve_sensor(ctx, sensor, crop, preset_files)
    c, cocs, origin = _coc(ctx, coc, coc_rule, chosen, pixel_pitch)
    with library_errors(ctx), ladder_errors(ctx):
        data = card_data(f, apertures, distances, c, model, distance_from, lens)
    data.scene = footer(" / ".join(data.extra["models"]), cocs, origin, chosen.label, distance_from)
    return data


def _exact(n: float) -> float:
    from camtool.core.units import exact_f_number

    return float(exact_f_number(n))


for _command in (chart_dof, chart_blur, chart_aperture, chart_trade, chart_card):
    chart.add_command(_command, _command.name)


def regenerate(directory: Path) -> list[Path]:
    """Write every example chart (SVG) and its data (JSON) into ``directory``: the README's pictures."""
    import shlex

    from camtool.cli import cli

    directory.mkdir(parents=True, exist_ok=True)
    written = []
    for kind, line in EXAMPLES.items():
        args = shlex.split(line)[1:]
        target = directory / f"{kind}.svg"
        args[args.index("-o") + 1] = str(target)
        args += ["--data", str(directory / f"{kind}.json")]
        try:
            cli.main(args, prog_name="camtool")
        except SystemExit as done:  # the group exits with the command's status
            if done.code not in (0, None):
                raise
        written += [target, directory / f"{kind}.json"]
    return written


if __name__ == "__main__":
    for path in regenerate(Path(sys.argv[1] if len(sys.argv) > 1 else "docs/charts")):
        print(path)
