"""Drawing ``camtool chart``'s figures with matplotlib: the plotting layer only draws.

The numbers come from :mod:`camtool.render.chartdata` (the library's
results, in mm); this module converts lengths to the user's units, picks
colours and line styles and writes PNG, SVG or PDF. matplotlib is an
optional dependency (``pip install 'camtool[chart]'``) imported only here,
and only ``camtool chart`` imports this module. The non-interactive Agg
canvas is used explicitly (no pyplot, no window, no global figure state).

Readable in print and for colour-blind readers: the Okabe–Ito palette
(M. Okabe and K. Ito, "Color Universal Design (CUD): how to make figures and
presentations that are friendly to colorblind people", J*Fly, 2002/2008,
https://jfly.uni-koeln.de/color/), with a line style per group as well as a
colour, so that a grey-scale print still tells the curves apart.

Output is deterministic for a given matplotlib: SVG ids are salted with a
fixed string and no creation date is written; SVG text stays text.
"""

from __future__ import annotations

import io
import math
from typing import IO, Any

import matplotlib

matplotlib.use("Agg")

from matplotlib.backends.backend_agg import FigureCanvasAgg
from matplotlib.figure import Figure
from matplotlib.ticker import FuncFormatter, LogLocator, NullLocator
from matplotlib.transforms import Bbox

from camtool.core.errors import DomainError
from camtool.render.chartdata import MAX_PIXELS, ChartData, raster_pixels
from camtool.render.numfmt import feet_inches, significant

__all__ = ["FORMATS", "OKABE_ITO", "STYLES", "draw", "save"]

OKABE_ITO = ["#0072B2", "#D55E00", "#009E73", "#CC79A7", "#E69F00", "#56B4E9", "#000000", "#F0E442"]
"""Okabe–Ito colours: blue, vermillion, bluish green, reddish purple, orange, sky blue, black, yellow.

The yellow, faint on white paper, comes last."""

STYLES = ["-", "--", "-.", ":", (0, (5, 1, 1, 1, 1, 1)), (0, (1, 1)), (0, (8, 2)), (0, (3, 1, 1, 1))]
"""One line style per group, with the colour: solid, dashed, dash-dot, dotted and longer patterns."""

MARKERS = ["o", "s", "^", "D", "v", "P", "X", "*"]

FORMATS = ("png", "svg", "pdf")

FULL_STOPS = [0.7, 1.0, 1.4, 2.0, 2.8, 4.0, 5.6, 8.0, 11.0, 16.0, 22.0, 32.0, 45.0, 64.0, 90.0, 128.0, 180.0, 256.0,
              360.0, 512.0, 720.0, 1024.0]
"""The f-number axis is labelled at the nominal full stops."""

RC: dict[Any, Any] = {
    "svg.fonttype": "none",  # text stays text in SVG: searchable, and the tests read the labels
    "svg.hashsalt": "camtool",  # stable ids, so the same chart is the same file
    "font.size": 9.0,
    "axes.titlesize": 10.0,
    "axes.labelsize": 9.0,
    "legend.fontsize": 8.0,
    "lines.linewidth": 1.6,
}

LENGTH_UNITS = {"metric": ("m", 1000.0), "imperial": ("ft", 304.8)}


def colour(group: int) -> str:
    """The Okabe–Ito colour of a group."""
    return OKABE_ITO[group % len(OKABE_ITO)]


def style(group: int) -> Any:
    """The line style of a group."""
    return STYLES[group % len(STYLES)]


def _length(units: str) -> tuple[str, float]:
    return LENGTH_UNITS["imperial" if units == "imperial" else "metric"]


def _tick(value: float, _pos: Any = None) -> str:
    return f"{value:.4g}"


def _plain_tick(value: float, _pos: Any = None) -> str:
    return f"{value:.0f}" if value >= 1 else f"{value:.2g}"


def _log_axis(axis: Any) -> None:
    """Log axis ticks at 1, 2, 5 per decade, written as plain numbers (0.5, 1, 2, 5, 10); no minor ticks."""
    axis.set_major_locator(LogLocator(base=10.0, subs=(1.0, 2.0, 5.0)))
    axis.set_major_formatter(FuncFormatter(_tick))
    axis.set_minor_locator(NullLocator())


def draw(data: ChartData, width_in: float, height_in: float, units: str = "metric") -> Figure:
    """A figure of ``width_in`` × ``height_in`` inches showing ``data``; lengths in ``units``."""
    with matplotlib.rc_context(RC):
        figure = Figure(figsize=(width_in, height_in), layout="constrained")
        FigureCanvasAgg(figure)
        drawer = {"dof": _dof, "blur": _blur, "aperture": _aperture, "trade": _trade, "card": _card,
                  "marks": _marks, "shot": _shot}[data.kind]
        drawer(figure, data, units)
    return figure


def save(figure: Figure, target: IO[bytes] | str, fmt: str, dpi: float = 150.0) -> list[str]:
    """Write ``figure`` as PNG, SVG or PDF to a path or binary stream, without a date (reproducible).

    Returns matplotlib's warnings (a figure too small for its labels), for the caller to pass on in its own words.
    """
    import warnings

    if fmt == "png":
        width_in, height_in = figure.get_size_inches()
        across, down = raster_pixels(float(width_in), float(height_in), dpi)
        if across * down > MAX_PIXELS:
            raise DomainError("dpi", dpi, f"at most {MAX_PIXELS:,} pixels for this figure size",
                              f"{across} × {down} pixels")
    metadata: dict[str, Any] = {"png": {"Software": None}, "svg": {"Date": None},
                                "pdf": {"CreationDate": None, "ModDate": None}}[fmt]
    with matplotlib.rc_context(RC), warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always", UserWarning)
        figure.savefig(target, format=fmt, dpi=dpi, metadata=metadata)
    return [str(w.message) for w in caught]


def to_bytes(figure: Figure, fmt: str, dpi: float = 150.0, notes: list[str] | None = None) -> bytes:
    """The file ``save`` would write, as bytes; matplotlib's warnings are appended to ``notes``."""
    buffer = io.BytesIO()
    caught = save(figure, buffer, fmt, dpi)
    if notes is not None:
        notes.extend(caught)
    return buffer.getvalue()


def _titles(figure: Figure, axes: Any, data: ChartData) -> None:
    axes.set_title(data.title, loc="left", fontweight="bold")
    figure.suptitle(data.scene, fontsize=7.5, x=0.01, ha="left", color="#333333")


def _dof(figure: Figure, data: ChartData, units: str) -> None:
    name, size = _length(units)
    axes = figure.add_subplot()
    _titles(figure, axes, data)
    xs = [v / size for c in data.curves for v in c.x]
    low, high = min(xs), max(xs)
    finite = [v / size for c in data.curves for v in c.y if math.isfinite(v)]
    bottom = min(min(finite), low) / 1.25
    top = high * 4.0
    axes.set_xscale("log")
    axes.set_yscale("log")
    axes.set_xlim(low, high)
    axes.set_ylim(bottom, top)
    axes.plot([low, high], [low, high], color="#777777", lw=0.8, ls=":", label="focus distance")
    for near, far in zip(data.curves[0::2], data.curves[1::2]):
        g = near.group
        x = [v / size for v in near.x]
        y_near = [v / size for v in near.y]
        y_far = [min(v / size, top * 10.0) for v in far.y]  # ∞ drawn past the top edge
        axes.fill_between(x, y_near, y_far, color=colour(g), alpha=0.12, lw=0)
        label = near.label.removesuffix(" near")
        axes.plot(x, y_near, color=colour(g), ls=style(g), label=label)
        axes.plot(x, y_far, color=colour(g), ls=style(g))
    for mark in data.marks:
        if mark.x is not None and math.isfinite(mark.x) and low <= mark.x / size <= high:
            h = mark.x / size
            axes.axvline(h, color=colour(mark.group), ls=(0, (1, 2)), lw=1.0)
            axes.annotate(f"H {_distance_text(mark.x, units)}", (h, bottom), xytext=(2, 3), textcoords="offset points",
                          rotation=90, fontsize=7, color=colour(mark.group), va="bottom")
    _log_axis(axes.xaxis)
    _log_axis(axes.yaxis)
    axes.set_xlabel(f"focus distance ({name})")
    axes.set_ylabel(f"near and far limits ({name}); far above the top edge = ∞")
    axes.grid(True, which="major", color="#dddddd", lw=0.6)
    axes.legend(loc="upper left", frameon=False)


def _distance_text(mm: float, units: str) -> str:
    if math.isinf(mm):
        return "∞"
    if units == "imperial":
        return feet_inches(mm)
    return f"{significant(mm / 1000.0, 3)} m"


def _blur(figure: Figure, data: ChartData, units: str) -> None:
    name, size = _length(units)
    axes = figure.add_subplot()
    _titles(figure, axes, data)
    finite_x = [v / size for c in data.curves for v in c.x if math.isfinite(v)]
    for curve in data.curves:
        g = curve.group
        points = [(x / size, y) for x, y in zip(curve.x, curve.y) if math.isfinite(x)]
        axes.plot([p[0] for p in points], [p[1] for p in points], color=colour(g), ls=style(g), label=curve.label)
    for mark in data.marks:
        if mark.y is not None:
            axes.axhline(mark.y, color=colour(mark.group), ls=(0, (1, 3)), lw=0.8)
    axes.set_xscale("log")
    axes.set_xlim(min(finite_x), max(finite_x))
    axes.set_ylim(bottom=0.0)
    _log_axis(axes.xaxis)
    width = float(data.extra["width_mm"])
    def to_percent(blur: Any) -> Any:
        return 100.0 * blur / width

    def to_mm(share: Any) -> Any:
        return share * width / 100.0

    percent = axes.secondary_yaxis("right", functions=(to_percent, to_mm))
    percent.set_ylabel("blur disc (% of the frame width)")
    axes.set_xlabel(f"background distance behind the subject ({name})")
    axes.set_ylabel("blur disc on the sensor (mm)")
    axes.grid(True, which="major", color="#dddddd", lw=0.6)
    axes.legend(loc="upper left", frameon=False, title="thin dotted lines: background at ∞", title_fontsize=7)


def _aperture(figure: Figure, data: ChartData, units: str) -> None:
    axes = figure.add_subplot()
    _titles(figure, axes, data)
    same = data.curves[0].y == data.curves[1].y or all(
        math.isclose(a, b, rel_tol=1e-9) for a, b in zip(data.curves[0].y, data.curves[1].y))
    for index, curve in enumerate(data.curves):
        if same and index == 1:
            continue
        label = "defocus at the near and far limits" if same and index == 0 else curve.label
        axes.plot(curve.x, curve.y, color=colour(curve.group), ls=style(curve.group), label=label)
    crossing, coc = data.marks[0], data.marks[1]
    assert crossing.x is not None and crossing.y is not None and coc.y is not None
    axes.plot([crossing.x], [crossing.y], marker="o", color=colour(crossing.group), ls="none", label=crossing.label)
    axes.axvline(crossing.x, color=colour(crossing.group), ls=(0, (1, 2)), lw=0.8)
    axes.axhline(coc.y, color="#555555", ls=(0, (5, 2, 1, 2)), lw=0.9, label=coc.label)
    for mark in data.marks[2:]:  # the contrast optimum, when a criterion was given
        assert mark.x is not None
        axes.axvline(mark.x, color=colour(mark.group), ls=(0, (4, 2)), lw=0.9, label=mark.label)
    axes.set_xscale("log")
    axes.set_yscale("log")
    xs = data.curves[0].x
    axes.set_xlim(min(xs), max(xs))
    axes.set_xticks([n for n in FULL_STOPS if min(xs) <= n <= max(xs)])
    axes.xaxis.set_major_formatter(FuncFormatter(lambda v, _p: f"f/{v:g}"))
    axes.xaxis.set_minor_locator(NullLocator())
    _log_axis(axes.yaxis)
    axes.set_xlabel("f-number")
    axes.set_ylabel("blur disc on the sensor (mm)")
    focus = _distance_text(float(data.extra["focus_mm"]), units)
    near, far = (_distance_text(float(data.extra[k]), units) for k in ("near_mm", "far_mm"))
    axes.text(0.99, 0.02, f"near {near}, far {far}, focus {focus}", transform=axes.transAxes, ha="right",
              va="bottom", fontsize=7)
    axes.grid(True, which="major", color="#dddddd", lw=0.6)
    axes.legend(loc="best", frameon=False, fontsize=7)


def _trade(figure: Figure, data: ChartData, units: str) -> None:
    axes = figure.add_subplot()
    _titles(figure, axes, data)
    errors = [c.y[0] for c in data.curves if c.y[0] > 0] + [e for e in data.extra["estimates"] if e > 0]
    floor = min(errors, default=1e-4) / 10.0 * 100.0
    for curve in data.curves:
        g = curve.group
        value = curve.y[0] * 100.0
        shown = value if value > 0 else floor
        label = curve.label + (" (reference)" if value == 0 else "")
        axes.plot([curve.x[0] * 1e6], [shown], marker=MARKERS[g % len(MARKERS)], ms=7, color=colour(g),
                  ls="none", label=label)
        axes.annotate(label, (curve.x[0] * 1e6, shown), xytext=(6, 4), textcoords="offset points", fontsize=7.5)
        estimate = data.extra["estimates"][g] * 100.0
        if estimate > 0:
            axes.plot([curve.x[0] * 1e6], [estimate], marker=MARKERS[g % len(MARKERS)], ms=7, ls="none",
                      markerfacecolor="none", markeredgecolor=colour(g),
                      label="hollow: auto's estimate; filled: measured" if g == 0 else None)
    axes.set_xscale("log")
    axes.set_yscale("log")
    axes.set_ylim(floor / 2.0, max(errors, default=1e-2) * 100.0 * 3.0)
    axes.axhline(floor, color="#777777", lw=0.7, ls="--")
    axes.annotate("0 %: the reference", (0.0, floor), xycoords=("axes fraction", "data"), xytext=(3, 3),
                  textcoords="offset points", fontsize=7, color="#555555")
    axes.set_xlabel("time per evaluation (µs, measured on this machine)")
    axes.set_ylabel(f"difference from {data.extra['reference']} (%)")
    _log_axis(axes.xaxis)
    _log_axis(axes.yaxis)
    axes.xaxis.set_major_formatter(FuncFormatter(_plain_tick))
    axes.yaxis.set_major_formatter(FuncFormatter(lambda v, _p: "" if v < floor * 1.5 else _tick(v)))
    axes.margins(x=0.25)
    axes.grid(True, which="major", color="#dddddd", lw=0.6)
    axes.legend(handles=[h for h in axes.get_lines() if h.get_label() == "hollow: auto's estimate; filled: measured"],
                loc="upper right", frameon=False, fontsize=7)


def _card_cell(near: float, far: float, units: str) -> str:
    if units == "imperial":
        return f"{_short_ft(near)}–{_short_ft(far)}"
    return f"{_short_m(near)}–{_short_m(far)}"


def _short_m(mm: float) -> str:
    if math.isinf(mm):
        return "∞"
    return significant(mm / 1000.0, 3) if mm < 100_000 else f"{mm / 1000.0:.0f}"


def _short_ft(mm: float) -> str:
    if math.isinf(mm):
        return "∞"
    feet = mm / 304.8
    return significant(feet, 3) if feet < 1000 else f"{feet:.0f}"


def _row_label(mm: float, units: str) -> str:
    if math.isinf(mm):
        return "∞"
    return f"{mm / (304.8 if units == 'imperial' else 1000.0):.3g}"


def _card(figure: Figure, data: ChartData, units: str) -> None:
    extra = data.extra
    name = "ft" if units == "imperial" else "m"
    axes = figure.add_subplot()
    axes.axis("off")
    axes.set_title(f"{data.title} · near–far ({name})", loc="left", fontweight="bold", fontsize=9)
    figure.suptitle(data.scene, fontsize=6, x=0.01, ha="left", color="#333333")
    short = _short_ft if units == "imperial" else _short_m
    header = ["focus", *(f"f/{n:g}" for n in extra["f_numbers"])]
    cells = [[_row_label(s, units), *(_card_cell(a, b, units) for a, b in zip(near, far))]
             for s, near, far in zip(extra["distances_mm"], extra["near_mm"], extra["far_mm"])]
    cells.append(["H", *(short(h) for h in extra["hyperfocal_mm"])])
    _print_table(axes, cells, header, 6.5)


def _print_table(axes: Any, cells: list[list[str]], header: list[str], fontsize: float) -> None:
    """A printed table filling ``axes``: bold header row and first column, every other row shaded."""
    table = axes.table(cellText=cells, colLabels=header, bbox=Bbox.from_bounds(0.0, 0.0, 1.0, 1.0), cellLoc="center")
    table.auto_set_font_size(False)
    table.set_fontsize(fontsize)
    for (row, col), cell in table.get_celld().items():
        cell.set_linewidth(0.4)
        if row == 0 or col == 0:
            cell.set_text_props(fontweight="bold")
        if row > 0 and row % 2 == 0:
            cell.set_facecolor("#f0f0f0")


def _marks(figure: Figure, data: ChartData, units: str) -> None:
    """The focus-pull sheet: one row per mark, one column per lens, each cell near – far in feet and inches or m."""
    from camtool.render.numfmt import feet_inches

    extra = data.extra
    axes = figure.add_subplot()
    axes.axis("off")
    name = "ft in" if units == "imperial" else "m"
    axes.set_title(f"{data.title} · near – far ({name})", loc="left", fontweight="bold", fontsize=9)
    figure.suptitle(data.scene, fontsize=6, x=0.01, ha="left", color="#333333")

    def shown(mm: float) -> str:
        return feet_inches(mm) if units == "imperial" else _short_m(mm)

    cells = [[shown(mark), *(f"{shown(a)} – {shown(b)}" for a, b in zip(near, far))]
             for mark, near, far in zip(extra["marks_mm"], extra["near_mm"], extra["far_mm"])]
    _print_table(axes, cells, ["mark", *extra["lenses"]], 7)


def _shot(figure: Figure, data: ChartData, units: str) -> None:
    """The envelope of a shot: near and far (a band, ∞ drawn past the top) and the focus, against the frame."""
    name, size = _length(units)
    axes = figure.add_subplot()
    _titles(figure, axes, data)
    focus, near, far = data.curves
    finite = [v / size for c in data.curves for v in c.y if math.isfinite(v)]
    bottom, top = min(finite) / 1.25, max(finite) * 4.0
    axes.set_yscale("log")
    axes.set_ylim(bottom, top)
    y_far = [min(v / size, top * 10.0) for v in far.y]
    axes.fill_between(far.x, [v / size for v in near.y], y_far, color=colour(1), alpha=0.18, lw=0, label="sharp zone")
    axes.plot(near.x, [v / size for v in near.y], color=colour(1), lw=0.9, label="near, far")
    axes.plot(far.x, y_far, color=colour(1), lw=0.9)
    axes.plot(focus.x, [v / size for v in focus.y], color=colour(0), ls=style(0), lw=1.2, label="focus")
    axes.set_xlabel("frame")
    axes.set_ylabel(f"distance ({name})")
    _log_axis(axes.yaxis)
    axes.legend(loc="upper right", frameon=False, fontsize=7)
