"""``camtool chart KIND``: depth-of-field questions drawn as PNG, SVG or PDF.

Each kind takes the same inputs, presets, units and models as the command
it draws (``dof``, ``compose``, the model ladder); its decisions (ranges,
defaults, the format and size) are :mod:`camtool.plans.chart`, which computes
the numbers with :mod:`camtool.render.chartdata`, and the plotting layer
(:mod:`camtool.render.chartplot`), which needs matplotlib, an optional extra
(``pip install 'camtool[chart]'``), is imported only here. The command parses
options, makes one call and writes through its one writer.

``python -m camtool.cli.chart docs/charts`` regenerates the example charts
shown in the README (an SVG and a JSON file of its data each); a test
checks the committed data for drift.
"""

from __future__ import annotations

import functools
import json
import sys
from collections.abc import Callable
from pathlib import Path
from typing import Any

import click

from camtool.cli.command import equipment_options, presets_option
from camtool.cli.common import f_numbers, required, single
from camtool.cli.equipment import LENS, apply_equipment, resolve_coc, resolve_sensor
from camtool.cli.lensdata import criterion_option, lens_data, model_options, pupil_mag_option, wavelength_option
from camtool.cli.options import (
    DISTANCE_M,
    aperture_options,
    bad_parameter,
    coc_options,
    distance_plane_option,
    focal_option,
    library_errors,
    sensor_options,
    squeeze_option,
    stack,
)
from camtool.cli.params import FNumberType, LengthType, NumberType, Parsed, flatten
from camtool.core import collector, ranges
from camtool.core.errors import InputError
from camtool.core.files import SameTarget, WriteProblem, check_writable, write_bytes
from camtool.core.record import NamedTuple
from camtool.core.units import parse_figure_size
from camtool.dof.ladder import focal_lengths, model_choices
from camtool.plans.chart import (
    IMAGE_FORMATS,
    aperture_chart,
    blur_chart,
    card_chart,
    check_pixels,
    dof_chart,
    figure_size,
    image_format,
    marks_chart,
    read_shot,
    shot_chart,
    trade_chart,
)
from camtool.render.views.common import footer

INSTALL_HINT = "camtool chart needs matplotlib, an optional extra: pip install 'camtool[chart]' (or pip install matplotlib)"
PAPER_HELP = "a6 (148 × 105 mm) or letter-quarter (5.5 × 4.25 in), landscape"
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


chart_output_options = stack(
    click.option("-o", "--output", required=True, metavar="FILE",
                 help="The chart file: its extension (.png, .svg, .pdf) picks the format; - writes to standard "
                      "output (with --image-format)."),
    click.option("--image-format", type=click.Choice(IMAGE_FORMATS),
                 help="png, svg or pdf; needed with -o -, otherwise taken from the file's extension."),
    click.option("--size", type=Parsed("size", parse_figure_size, tuple), metavar="WxH",
                 help="Figure size in inches (8x5) or with a unit (20x12cm). Default: 8x5 in; for card, the --paper size."),
    click.option("--dpi", type=NumberType(*ranges.CHART_DPI), default="150", show_default=True,
                 help="Pixels per inch of a PNG (SVG and PDF are vector); a PNG has at most 144 megapixels "
                      "(40x40 in at 300 dpi)."),
    click.option("--data", "data_file", metavar="FILE",
                 help="Also write the plotted numbers as JSON (mm, f-numbers, seconds; infinity as null)."),
    click.option("--units", type=click.Choice(["metric", "imperial"]), default="metric", show_default=True,
                 help="Units of the distances shown (blur discs stay in mm on the sensor)."),
    presets_option,
)
"""The options every chart shares: where and how to write it."""


def plotting(ctx: click.Context | None = None) -> Any:
    """The plotting layer, or a one-line error (exit 1) saying what to install when matplotlib is missing."""
    try:
        import matplotlib  # noqa: F401
    except ImportError:
        raise click.ClickException(INSTALL_HINT) from None
    from camtool.render import chartplot

    return chartplot


def chart_command(name: str, card: bool = False) -> Callable[[Callable[..., Any]], click.Command]:
    """Make a chart subcommand of a function that returns the chart's :class:`ChartData`."""

    def decorate(compute: Callable[..., Any]) -> click.Command:
        @functools.wraps(compute)
        def run(ctx: click.Context, /, **params: Any) -> None:
            output, given = params.pop("output"), params.pop("image_format")
            size, dpi, data_file = params.pop("size"), params.pop("dpi"), params.pop("data_file")
            fmt = _inputs(ctx, lambda: image_format(output=output, given=given))
            resolution = float(single(ctx, dpi, "--dpi"))
            if output == "-" and data_file == "-":
                raise click.UsageError("-o - and --data - would both write to standard output.", ctx)
            _check_targets(output, data_file)
            plot = plotting(ctx)
            params = apply_equipment(ctx, params)
            scene = _scene(ctx, params)
            width, height = figure_size(size_in=size, paper=params.get("paper") or "a6" if card else None)
            if fmt == "png":
                _inputs(ctx, lambda: check_pixels(size_in=(width, height), dpi=resolution))
            from camtool.core.steps import reporting
            from camtool.render.progress import progress

            # trade times every rung, traced ones included: long work, shown on a terminal
            with library_errors(ctx), progress(f"camtool chart {name}: models", total=None if name == "trade" else 0) \
                    as bar, reporting(bar.advance):
                data = _inputs(ctx, lambda: compute(ctx, scene, **params))
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


TARGETS = ("-o/--output", "--data")
"""The options that name the files a chart writes, in the order given to :func:`check_writable`."""


def _check_targets(output: str, data_file: str | None) -> None:
    """Refuse at once an output that cannot be written: no such directory, not a regular file, both the same."""
    try:
        check_writable([output, data_file])
    except SameTarget as problem:
        raise click.ClickException(f"{TARGETS[problem.index or 0]} {problem.path}: the same file as "
                                   f"{TARGETS[problem.other]}; give another name") from None
    except WriteProblem as problem:
        raise click.ClickException(f"{TARGETS[problem.index or 0]} {problem}") from None


def _write(target: str, option: str, payload: bytes) -> None:
    """Write ``payload`` to standard output (``-``) or to the file ``target`` (:func:`write_bytes`)."""
    try:
        write_bytes(target, payload)
    except WriteProblem as problem:
        raise click.ClickException(str(problem) if problem.path == "-" else f"{option} {problem}") from None


def _inputs(ctx: click.Context, decide: Callable[[], Any]) -> Any:
    """``decide()``, its input errors spelled as this command's options (the one translator)."""
    try:
        return decide()
    except InputError as error:
        raise bad_parameter(ctx, error) from None


class Scene(NamedTuple):
    """A chart's sensor and circle of confusion, resolved as ``camtool dof`` resolves them, and its footer."""

    sensor: Any
    coc_mm: float
    cocs: list[float]
    origin: str
    distance_from: str | None

    def footer(self, model: str | None = None, extra: str = "", data: Any = None) -> str:
        """The footer line of the chart's scene (the rungs that answered, from ``data``, when given)."""
        model = " / ".join(data.extra["models"]) if data is not None else model
        return footer(model, self.cocs, self.origin, self.sensor.label, self.distance_from, extra)


def _scene(ctx: click.Context, params: dict[str, Any]) -> Scene | None:
    """The sensor (and CoC) of a chart with those options, taken out of ``params``."""
    if "sensor" not in params:
        return None
    chosen = resolve_sensor(ctx, params.pop("sensor"), params.pop("crop"), params["preset_files"])
    if "coc" not in params:
        return Scene(chosen, 0.0, [], "", None)
    cocs, origin = resolve_coc(ctx, list(params.pop("coc") or ()), params.pop("coc_rule"), chosen,
                               params.pop("pixel_pitch"))
    if len(cocs) > 1:
        raise click.UsageError("Option '--coc' takes one value here.", ctx)
    return Scene(chosen, cocs[0], cocs, origin, params.get("distance_from"))


@click.group("chart", context_settings={"help_option_names": ["-h", "--help"]})
def chart() -> None:
    """Charts of depth of field, blur, aperture, the model ladder, a DOF card, a focus-pull sheet and a shot.

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
      camtool chart marks -f 25,32,50,75 -N T2.8 --camera arri-alexa-35 --units imperial -o marks.pdf
      camtool chart shot --frames tests/data/shot.csv --camera arri-alexa-35 -o shot.svg
    """
    collector.resume()  # the chart's work begins (camtool.cli.main)


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
@squeeze_option
def chart_dof(ctx: click.Context, scene: Scene, focal_length, f_number, exact_stops, low, high, distance_from, model,
              tolerance, diffraction, wavelength, pupil_mag, hiatus, prescription_file, squeeze, units,
              preset_files) -> Any:
    """Near and far limits against focus distance (log axes), one band per f-number or focal length, H marked."""
    lens = lens_data(ctx, pupil_mag, hiatus, prescription_file)
    apertures = required(ctx, f_numbers(f_number, exact_stops), "-N")
    data = dof_chart(focal_lengths_mm=flatten(focal_length), f_numbers=apertures, coc_mm=scene.coc_mm,
                     from_mm=single(ctx, low, "--from"), to_mm=single(ctx, high, "--to"), model=model,
                     distance_from=distance_from, lens=lens, diffraction=diffraction, wavelength_nm=wavelength,
                     tolerance=tolerance, squeeze=squeeze)
    data.scene += (f" · {squeeze:g}× anamorphic" if squeeze else "") + " · " + scene.footer(data=data)
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
def chart_blur(ctx: click.Context, scene: Scene, focal_length, subject_size, fill, fill_axis, magnification, f_number,
               exact_stops, low, high, units, preset_files) -> Any:
    """Background blur disc (mm and % of the frame width) against distance behind the subject, framing kept.

    One curve per focal length, each standing where it frames the subject the
    same (camtool compose's question), or per f-number with one focal length;
    dotted lines are the blur of a background at infinity, f·m/N.
    """
    chosen = scene.sensor
    return blur_chart(f_numbers=required(ctx, f_numbers(f_number, exact_stops), "-N"), sensor_width_mm=chosen.width_mm,
                      sensor_height_mm=chosen.height_mm, sensor_label=chosen.label, focal_lengths_mm=flatten(focal_length),
                      subject_size_mm=single(ctx, subject_size, "--subject-size"), fill=single(ctx, fill, "--fill"),
                      fill_axis=fill_axis, magnification=single(ctx, magnification, "--magnification"),
                      from_mm=single(ctx, low, "--from"), to_mm=single(ctx, high, "--to"))


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
@wavelength_option("for the Airy disc")
@pupil_mag_option
@criterion_option
def chart_aperture(ctx: click.Context, scene: Scene, focal_length, near, far, distance, low, high, distance_from,
                   wavelength, pupil_mag, criterion, units, preset_files) -> Any:
    """Blur at the scene's near and far limits from defocus and from diffraction against f-number, optimum marked.

    Defocus blur (thin lens) of points at --near and --far falls as 1/N; the
    Airy disc 2.44·λ·N(1 + m/P) grows as N. The optimum aperture is marked:
    focused half-way between the near and far images (Hansma's rule, the
    default focus; -s sets another), the f-number where the two are equal and
    their root-sum-square is smallest, the sharpest the whole scene can be.
    With --criterion the contrast optimum is marked as well: the f-number
    with the most MTF at the criterion's frequency at both limits (docs/wave.md).
    """
    f = single(ctx, required(ctx, focal_length, "-f"), "-f")
    n_low, n_high = single(ctx, low, "--from"), single(ctx, high, "--to")
    closest, farthest = single(ctx, near, "--near"), single(ctx, far, "--far")
    focus = single(ctx, distance, "-s")
    data = aperture_chart(focal_length_mm=f, coc_mm=scene.coc_mm, near_mm=closest, far_mm=farthest, from_f_number=n_low,
                          to_f_number=n_high, focus_mm=focus, distance_from=distance_from,
                          pupil_magnification=pupil_mag, wavelength_nm=wavelength, criterion=criterion)
    data.scene = f"{f:g} mm · " + scene.footer("thin", f"λ {wavelength:g} nm")
    return data


@chart_command("trade")
@focal_option
@aperture_options
@click.option("-s", "--distance", type=DISTANCE_M, multiple=True, help="Focus distance, e.g. 3 (bare numbers are metres).")
@sensor_options
@coc_options
@distance_plane_option
@model_options
def chart_trade(ctx: click.Context, scene: Scene, focal_length, f_number, exact_stops, distance, distance_from,
                tolerance, diffraction, wavelength, pupil_mag, hiatus, prescription_file, units, preset_files) -> Any:
    """Every rung of the model ladder for your scene: error against the most complete rung versus time per evaluation.

    The rungs the lens data allow (a prescription, from --prescription or a
    --lens that has one, allows all five), timed on the spot on this machine
    (best of three runs), as camtool dof --model all measures them.
    """
    lens = lens_data(ctx, pupil_mag, hiatus, prescription_file)
    with library_errors(ctx):
        focal = focal_lengths(lens, flatten(focal_length))
    f = single(ctx, required(ctx, focal, "-f"), "-f")
    n = single(ctx, required(ctx, f_numbers(f_number, exact_stops), "-N"), "-N")
    s = single(ctx, required(ctx, distance, "-s"), "-s")
    data = trade_chart(focal_length_mm=f, f_number=n, coc_mm=scene.coc_mm, distance_mm=s, distance_from=distance_from, lens=lens,
                       diffraction=diffraction, wavelength_nm=wavelength)
    shown = f"{s / 1000:.4g} m" if units == "metric" else f"{s / 304.8:.4g} ft"
    data.scene = f"{f:.4g} mm f/{n:g} at {shown} · " + scene.footer()
    return data


@chart_command("card", card=True)
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
def chart_card(ctx: click.Context, scene: Scene, focal_length, f_number, exact_stops, distance, paper, distance_from,
               model, units, preset_files) -> Any:
    """A printable depth-of-field card for one lens: near–far limits for each focus distance and f-number.

    Rows are focus distances, columns f-numbers, each cell the near and far
    limits in the chosen units; the last row is the hyperfocal distance.
    Sized for the camera bag: A6 or a quarter of US Letter.
    """
    lens = lens_data(ctx, None, None, None)
    f = single(ctx, required(ctx, focal_length, "-f"), "-f")
    data = card_chart(focal_length_mm=f, coc_mm=scene.coc_mm, f_numbers=flatten(f_number), exact_stops=exact_stops,
                      distances_mm=flatten(distance), units=units, model=model, distance_from=distance_from, lens=lens)
    data.scene = scene.footer(data=data)
    return data


@chart_command("marks", card=True)
@click.option("-f", "--focal-length", "focal_length", type=LengthType("mm"), multiple=True, help="Focal lengths of a set.")
@click.option("--lenses", multiple=True, metavar="NAME,...", help="Lens presets of a set, one column each.")
@click.option("-N", "--f-number", "f_number", type=FNumberType(t_stops=True), multiple=True, help="The stop (T2.8).")
@click.option("-s", "--distance", type=DISTANCE_M, multiple=True, help="The marks (default 3–50 ft or 1–15 m).")
@click.option("--paper", type=click.Choice(["a6", "letter-quarter"]), default="a6", show_default=True, help=PAPER_HELP)
@sensor_options
@coc_options
@distance_plane_option
def chart_marks(ctx: click.Context, scene: Scene, focal_length, lenses, f_number, distance, paper, distance_from, units,
                preset_files) -> Any:
    """A printable focus-pull sheet: near and far around each focus mark, one column per lens of a set.

    Cells in feet and inches with --units imperial, else metres; a T-stop
    is used as the f-number it stands for (as in camtool dof).
    """
    from camtool.cli.equipment import lookup

    names = [n.strip() for group in lenses for n in group.split(",") if n.strip()]
    found = [(n, lookup(ctx, "lens", n, "lenses", preset_files)) for n in names]
    sets = [(f"{v:g} mm", v, None) for v in flatten(focal_length)] + [(n, lens.focal_min_mm, None) for n, lens in found]
    n = single(ctx, required(ctx, f_numbers(f_number, False), "-N"), "-N")
    typed = flatten(f_number)[0]
    label = f"T{float(typed):g}" if type(typed).__name__ == "TStop" else f"f/{n:g}"
    data = marks_chart(lenses=sets, f_number=n, coc_mm=scene.coc_mm, marks_mm=flatten(distance), units=units,
                       distance_from=distance_from, aperture_label=label)
    data.scene = scene.footer(data=data)
    return data


@chart_command("shot")
@click.option("--frames", required=True, metavar="CSV", help="Per-frame camera data: frame, distance (or focus), "
              "focal_length and f_number (T2.8) or t_stop columns; bare focus in m.")
@sensor_options
@coc_options
@distance_plane_option
@click.option("--model", type=click.Choice(MODELS), default="auto", show_default=True, help="As for camtool dof.")
def chart_shot(ctx: click.Context, scene: Scene, frames, distance_from, model, units, preset_files) -> Any:
    """The near/far envelope of a shot over its frames, from the camera's per-frame focus, focal length and stop.

    Each frame is what camtool dof --batch answers for that row (a T-stop
    stands in for the f-number unless --lens gives the transmittance).
    """
    from camtool.core.files import FileProblem
    from camtool.plans.equipment import apertures

    try:
        shot = read_shot(frames)
    except FileProblem as error:  # named as --batch names its file: the option, then the file and its problem
        raise click.ClickException(f"--frames {error}") from None
    found = apertures(shot.apertures, lens=ctx.meta.get(LENS))
    data = shot_chart(shot=shot, f_numbers=found.f_numbers, coc_mm=scene.coc_mm, model=model,
                      distance_from=distance_from, lens=lens_data(ctx, None, None, None))
    data.scene = scene.footer(data=data)
    return data


for _command in (chart_dof, chart_blur, chart_aperture, chart_trade, chart_card, chart_marks, chart_shot):
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
