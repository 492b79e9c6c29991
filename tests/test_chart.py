"""``camtool chart``: every kind in every format, the numbers handed to the plotting layer, the committed examples.

Figures are drawn small (3 × 2 in at 40 dpi) to keep the suite fast. The
numbers are checked against direct library calls and physical identities;
one rendered PNG is checked pixel by pixel where the axes transform puts a
known point of a curve.
"""

from __future__ import annotations

import json
import math
import os
import re
import shlex
import shutil
import struct
import subprocess
import sys
import xml.etree.ElementTree as ET
from pathlib import Path
from typing import Any

import pytest
from cli_helpers import run

pytest.importorskip("matplotlib")

from camtool.cli.chart import EXAMPLES
from camtool.dof.ladder import compare_models, depth_of_field
from camtool.render import chartdata, chartplot

ROOT = Path(__file__).resolve().parent.parent
DOCS = ROOT / "docs" / "charts"
README = (ROOT / "README.md").read_text(encoding="utf-8")
SMALL = ["--size", "3x2", "--dpi", "40"]

# One quick scene per kind (the trade scene without a prescription: two rungs, no ray trace).
SCENES = {
    "dof": ["-f", "50", "-N", "2.8,8"],
    "blur": ["--subject-size", "1.8m", "--fill", "0.8", "-f", "35,85", "-N", "2.8"],
    "aperture": ["-f", "100", "--near", "1m", "--far", "1.5m"],
    "trade": ["-f", "50", "-N", "8", "-s", "3m"],
    "card": ["-f", "35", "-N", "4,8", "-s", "1m,3m,inf"],
}
# What the SVG must say: the title and the axis labels (text stays text: svg.fonttype none).
LABELS = {
    "dof": ["Depth of field against focus distance", "focus distance (m)", "near and far limits (m)"],
    "blur": ["Background blur against distance behind the subject", "background distance behind the subject (m)",
             "blur disc on the sensor (mm)", "blur disc (% of the frame width)"],
    "aperture": ["Defocus and diffraction blur against f-number", "f-number", "blur disc on the sensor (mm)",
                 "optimum aperture f/"],
    "trade": ["Model ladder: error against time per evaluation", "time per evaluation (µs",
              "difference from thin (%)"],
    "card": ["Depth of field · 35 mm · near–far (m)", "focus", "f/4", "f/8"],
}


def chart(*args: str) -> Any:
    return run("chart", *args)


def _png_size(data: bytes) -> tuple[int, int]:
    assert data[:8] == b"\x89PNG\r\n\x1a\n" and data[12:16] == b"IHDR"
    width, height = struct.unpack(">II", data[16:24])
    return width, height


def _svg_size(text: str) -> tuple[float, float]:
    root = ET.fromstring(text)
    assert root.tag.endswith("svg")
    return float(root.attrib["width"].removesuffix("pt")), float(root.attrib["height"].removesuffix("pt"))


def _pdf_size(data: bytes) -> tuple[float, float]:
    assert data.startswith(b"%PDF-") and data.rstrip().endswith(b"%%EOF")
    box = re.search(rb"/MediaBox\s*\[\s*0\s+0\s+([\d.]+)\s+([\d.]+)\s*\]", data)
    assert box is not None
    return float(box.group(1)), float(box.group(2))


@pytest.mark.parametrize("kind", sorted(SCENES))
@pytest.mark.parametrize("fmt", ["png", "svg", "pdf"])
def test_each_kind_renders_in_each_format_at_the_stated_size(tmp_path: Path, kind: str, fmt: str) -> None:
    target = tmp_path / f"{kind}.{fmt}"
    result = chart(kind, *SCENES[kind], *SMALL, "-o", str(target))
    assert result.exit_code == 0, result.output
    assert result.stdout == ""
    data = target.read_bytes()
    if fmt == "png":
        assert _png_size(data) == (120, 80)  # 3 × 2 in at 40 dpi
    elif fmt == "svg":
        text = data.decode("utf-8")
        assert _svg_size(text) == (216.0, 144.0)  # 72 pt to the inch
        plain = text.replace("&#8211;", "–")
        for label in LABELS[kind]:
            assert label in plain, label
    else:
        assert _pdf_size(data) == (216.0, 144.0)


def test_svg_is_reproducible_and_stdout_takes_the_image_format() -> None:
    args = ["dof", *SCENES["dof"], *SMALL, "-o", "-", "--image-format", "svg"]
    first, second = chart(*args), chart(*args)
    assert first.exit_code == 0 and first.stdout_bytes == second.stdout_bytes
    assert b"<dc:date>" not in first.stdout_bytes
    _svg_size(first.stdout)


def test_card_sizes_are_a6_and_a_quarter_letter(tmp_path: Path) -> None:
    # ISO 216 A6 is 148 × 105 mm; a quarter of US Letter (8.5 × 11 in) is 5.5 × 4.25 in; 72 pt to the inch.
    for paper, size in (("a6", (148 / 25.4 * 72, 105 / 25.4 * 72)), ("letter-quarter", (396.0, 306.0))):
        target = tmp_path / f"{paper}.pdf"
        assert chart("card", *SCENES["card"], "--paper", paper, "-o", str(target)).exit_code == 0
        assert _pdf_size(target.read_bytes()) == pytest.approx(size, abs=0.01)


class Capture:
    """Stands in for the plotting layer's ``draw``, keeping the data it is handed."""

    def __init__(self) -> None:
        self.data: list[chartdata.ChartData] = []
        self.draw = chartplot.draw

    def __call__(self, data: chartdata.ChartData, *args: Any, **kwargs: Any) -> Any:
        self.data.append(data)
        return self.draw(data, *args, **kwargs)


def handed(monkeypatch: pytest.MonkeyPatch, tmp_path: Path, *args: str) -> chartdata.ChartData:
    capture = Capture()
    monkeypatch.setattr(chartplot, "draw", capture)
    result = chart(*args, *SMALL, "-o", str(tmp_path / "chart.svg"))
    assert result.exit_code == 0, result.output
    return capture.data[0]


def test_dof_data_are_the_ladders_numbers(monkeypatch: pytest.MonkeyPatch, tmp_path: Path) -> None:
    data = handed(monkeypatch, tmp_path, "dof", "-f", "50", "-N", "2.8,8", "--coc", "0.03", "--model", "thin",
                  "--from", "1m", "--to", "40m")
    assert [c.label for c in data.curves] == ["f/2.8 near", "f/2.8 far", "f/8 near", "f/8 far"]
    import numpy as np

    for near, far, n in ((data.curves[0], data.curves[1], 2.8), (data.curves[2], data.curves[3], 8.0)):
        assert near.x[0] == pytest.approx(1000.0) and near.x[-1] == pytest.approx(40000.0)
        limits = depth_of_field("thin", 50.0, n, 0.03, np.asarray(near.x)).limits
        assert near.y == pytest.approx(list(limits.near_mm), rel=1e-12)
        assert far.y == pytest.approx(list(limits.far_mm), rel=1e-12)
    # Physical identity: beyond the hyperfocal distance the far limit is infinite, before it finite.
    for mark, far in zip(data.marks, data.curves[1::2]):
        assert mark.x is not None
        assert all(math.isinf(y) == (x >= mark.x * (1 + 1e-9)) for x, y in zip(far.x, far.y) if abs(x / mark.x - 1) > 1e-6)
    # Hyperfocal of the thin lens from the sensor at f/8, c = 0.03: H = f²/(Nc) + f from the lens (10 466.7 mm)
    # plus the image distance f·H/(H − f) (Wikipedia, "Hyperfocal distance"; Gaussian lens formula).
    h_lens = 50.0**2 / (8.0 * 0.03) + 50.0
    assert data.marks[1].x == pytest.approx(h_lens + 50.0 * h_lens / (h_lens - 50.0), rel=1e-9)


def test_dof_bands_per_focal_length_and_imperial_axes(monkeypatch: pytest.MonkeyPatch, tmp_path: Path) -> None:
    data = handed(monkeypatch, tmp_path, "dof", "-f", "35,85", "-N", "8", "--units", "imperial")
    assert [c.label for c in data.curves[::2]] == ["35 mm near", "85 mm near"]
    svg = (tmp_path / "chart.svg").read_text(encoding="utf-8")
    assert "focus distance (ft)" in svg and "near and far limits (ft)" in svg


def test_blur_data_are_plane_view_and_tend_to_fm_over_n(monkeypatch: pytest.MonkeyPatch, tmp_path: Path) -> None:
    from camtool.geometry.compose import plane_view

    data = handed(monkeypatch, tmp_path, "blur", "--magnification", "0.02", "-f", "50,100", "-N", "2",
                  "--from", "0.5m", "--to", "1000m")
    assert [c.label for c in data.curves] == ["50 mm", "100 mm"]
    for curve, f in zip(data.curves, (50.0, 100.0)):
        for x, y in zip(curve.x[::40], curve.y[::40]):
            assert y == pytest.approx(plane_view(f, 2.0, 0.02, 36.0, x).blur_mm, rel=1e-12)
    # b = f·m/N·x/(s + x) with s = f(1 + 1/m) (Wikipedia, "Depth of field", foreground and background blur):
    # at infinity f·m/N, 0.5 mm and 1 mm; 1000 m behind the subject nearly that.
    assert [m.y for m in data.marks] == pytest.approx([0.5, 1.0], rel=1e-12)
    s = 100.0 * (1 + 1 / 0.02)
    assert data.curves[1].y[-1] == pytest.approx(1.0 * 1e6 / (s + 1e6), rel=1e-12)
    assert data.extra["blur_pct"][1][-1] == pytest.approx(100.0 * data.curves[1].y[-1] / 36.0)


def test_aperture_data_defocus_airy_and_the_optimum(monkeypatch: pytest.MonkeyPatch, tmp_path: Path) -> None:
    from camtool.dof.closeup import optimum_for_limits

    data = handed(monkeypatch, tmp_path, "aperture", "-f", "24", "--near", "2m", "--far", "inf", "--coc", "0.03",
                  "--distance-from", "lens", "--from", "2", "--to", "64")
    near, far, airy, total = data.curves
    best = optimum_for_limits(24.0, 2000.0, math.inf, "lens")
    assert data.extra["focus_mm"] == pytest.approx(best.distance_mm, rel=1e-12)
    assert (data.marks[0].x, data.marks[0].y) == pytest.approx((best.optimum.f_number, best.optimum.blur_mm), rel=1e-12)
    # Airy disc 2.44·λ·N·(1 + m), m = f/(u − f) (Born & Wolf §8.5.2; Gaussian lens formula).
    m = 24.0 / (best.distance_mm - 24.0)
    assert airy.y[10] == pytest.approx(2.44 * 550e-6 * airy.x[10] * (1 + m), rel=1e-12)
    assert total.y[10] == pytest.approx(math.hypot(max(near.y[10], far.y[10]), airy.y[10]), rel=1e-12)
    # Two independent routes to the optimum agree: where the thin-lens defocus curve meets the Airy disc
    # (the smallest root-sum-square, no charted f-number does better), and Hansma's Δ/(2·N_w) rule.
    crossing = data.extra["crossing_f_number"]
    assert crossing == pytest.approx(best.optimum.f_number, rel=0.02)
    assert min(total.y) >= math.sqrt(2) * data.extra["crossing_blur_mm"] * (1 - 1e-12)
    assert near.y == pytest.approx(far.y, rel=0.02)  # half-way between the images: nearly equal blur
    assert data.marks[1].y == 0.03


def test_aperture_focused_where_the_limits_just_fit_blurs_them_by_the_coc(monkeypatch: pytest.MonkeyPatch,
                                                                         tmp_path: Path) -> None:
    from camtool.dof.inverse import focus_for_limits

    plan = focus_for_limits(100.0, 0.03, 1000.0, 1500.0, "lens")
    data = handed(monkeypatch, tmp_path, "aperture", "-f", "100", "--near", "1m", "--far", "1.5m", "--coc", "0.03",
                  "--distance-from", "lens", "-s", f"{plan.distance_mm}mm")
    near, far = data.curves[:2]
    # At the f-number the inverse solution gives, the defocus blur at both limits is the CoC.
    assert near.y[0] * near.x[0] / plan.f_number == pytest.approx(0.03, rel=1e-9)
    assert far.y == pytest.approx(near.y, rel=1e-9)


def test_trade_data_are_compare_models(monkeypatch: pytest.MonkeyPatch, tmp_path: Path) -> None:
    data = handed(monkeypatch, tmp_path, "trade", "-f", "50", "-N", "8", "-s", "3m", "--coc", "0.03",
                  "--pupil-mag", "0.7")
    rows = compare_models(50.0, 8.0, 0.03, 3000.0, lens=chartdata.LensData(pupil_magnification=0.7), repeat=1)
    assert [c.label for c in data.curves] == ["approx", "thin", "thick", "wave"]
    assert [c.y[0] for c in data.curves] == pytest.approx([float(r.difference) for r in rows], rel=1e-12)
    assert data.curves[-2].y == [0.0] and data.extra["reference"] == "thick"
    assert data.extra["estimates"] == pytest.approx([float(r.result.error_estimate) for r in rows], rel=1e-12)
    assert all(0 < c.x[0] < 1 for c in data.curves)


def test_card_data_are_the_ladders_numbers(monkeypatch: pytest.MonkeyPatch, tmp_path: Path) -> None:
    data = handed(monkeypatch, tmp_path, "card", "-f", "35", "-N", "4,8", "-s", "1m,3m,inf", "--model", "thin",
                  "--coc", "0.03")
    extra = data.extra
    assert extra["f_numbers"] == [4.0, 8.0] and extra["distances_mm"] == [1000.0, 3000.0, math.inf]
    for i, s in enumerate(extra["distances_mm"]):
        for j, n in enumerate(extra["f_numbers"]):
            limits = depth_of_field("thin", 35.0, n, 0.03, s).limits
            assert (extra["near_mm"][i][j], extra["far_mm"][i][j]) == pytest.approx((limits.near_mm, limits.far_mm))
    svg = (tmp_path / "chart.svg").read_text(encoding="utf-8")
    assert "∞" in svg and "H" in svg


def test_card_imperial_rows_are_in_feet(monkeypatch: pytest.MonkeyPatch, tmp_path: Path) -> None:
    data = handed(monkeypatch, tmp_path, "card", "-f", "35", "-N", "8", "--units", "imperial")
    assert data.extra["distances_mm"][:3] == pytest.approx([2 * 304.8, 3 * 304.8, 4 * 304.8])
    assert "near–far (ft)" in (tmp_path / "chart.svg").read_text(encoding="utf-8")


def test_a_rendered_curve_sits_where_the_axes_put_its_data() -> None:
    """Draw the dof chart, find a near-limit point through the axes transform, and read the PNG there."""
    import io

    import matplotlib.image as mpimg

    data = chartdata.dof_data([50.0], [8.0], 0.03, chartdata.log_space(500.0, 20000.0, 161), model="thin")
    figure = chartplot.draw(data, 4.0, 3.0)
    png = chartplot.to_bytes(figure, "png", dpi=figure.dpi)
    pixels = mpimg.imread(io.BytesIO(png))
    height = pixels.shape[0]
    axes = figure.axes[0]
    near = data.curves[0]
    for index in (40, 80, 120):
        x, y = near.x[index] / 1000.0, near.y[index] / 1000.0  # drawn in metres
        px, py = axes.transData.transform((x, y))
        row, col = round(height - py), round(px)
        patch = pixels[row - 2:row + 3, col - 2:col + 3, :3].reshape(-1, 3)
        blue = [0x00 / 255, 0x72 / 255, 0xB2 / 255]  # Okabe–Ito blue, the first group's colour
        distance = min(sum((a - b) ** 2 for a, b in zip(p, blue)) for p in patch)
        assert distance < 0.02, (index, patch)
    # and away from every curve (halfway up the log axis between near and focus) there is no line colour
    x = near.x[80] / 1000.0
    px, py = axes.transData.transform((x, math.sqrt(near.y[80] * near.x[80]) / 1000.0 * 0.8))
    assert (abs(pixels[round(height - py), round(px), :3] - [0.0, 0.447, 0.698]).sum()) > 0.2


def test_dof_json_imports_no_plotting_module() -> None:
    result = subprocess.run([sys.executable, "-X", "importtime", "-m", "camtool", "dof", "-f", "50", "-N", "8", "-s",
                             "3", "--format", "json"], capture_output=True, text=True, timeout=60,
                            env={k: v for k, v in os.environ.items() if k != "CAMTOOL_FORMAT"})
    assert result.returncode == 0 and json.loads(result.stdout)[0]["f_number"] == 8
    imported = [line.rsplit("|", 1)[-1].strip() for line in result.stderr.splitlines() if "|" in line]
    assert "camtool.dof.ladder" in imported  # the command ran, with the import log on
    assert not [name for name in imported if name.startswith(("matplotlib", "camtool.render.chart", "camtool.cli.chart"))]


def test_missing_matplotlib_is_a_one_line_error(monkeypatch: pytest.MonkeyPatch, tmp_path: Path) -> None:
    monkeypatch.setitem(sys.modules, "matplotlib", None)  # import matplotlib now raises ImportError
    result = chart("dof", *SCENES["dof"], "-o", str(tmp_path / "dof.png"))
    assert result.exit_code == 1
    assert result.stderr == ("Error: camtool chart needs matplotlib, an optional extra: pip install 'camtool[chart]' "
                             "(or pip install matplotlib)\n")
    assert not (tmp_path / "dof.png").exists()


@pytest.mark.parametrize(("args", "message"), [
    (["-o", "dof.jpg"], "Error: Invalid value for '-o' / '--output': dof.jpg has .jpg: use .png, .svg or .pdf, "
                        "or give --image-format\n"),
    (["-o", "-"], "Error: -o - writes to standard output: give --image-format png, svg or pdf.\n"),
    (["-o", "dof.png", "--image-format", "svg"],
     "Error: Invalid value for '-o' / '--output': dof.png has the extension .png but --image-format is svg\n"),
    (["-o", "dof.png", "-f", "85"], "Error: Give several f-numbers or several focal lengths (-N or -f), not both: "
                                    "each curve is one of them.\n"),
    (["-o", "dof.png", "--from", "5m", "--to", "2m"],
     "Error: Invalid value for '--to': 2000 is outside the valid range: more than --from (5000)\n"),
    (["-o", "dof.png", "--size", "0x3"], "Error: Invalid value for '--size': 0x3 is outside the valid range: "
                                         "1 to 40 inches a side\n"),
])
def test_bad_input_is_one_line_exit_2(tmp_path: Path, monkeypatch: pytest.MonkeyPatch, args: list[str],
                                      message: str) -> None:
    monkeypatch.chdir(tmp_path)
    result = chart("dof", *SCENES["dof"], *args)
    assert (result.exit_code, result.stderr) == (2, message)
    assert list(tmp_path.iterdir()) == []


def test_unwritable_output_is_exit_1(tmp_path: Path) -> None:
    result = chart("dof", *SCENES["dof"], *SMALL, "-o", str(tmp_path / "missing" / "dof.png"))
    assert (result.exit_code, result.stderr) == (1, f"Error: -o/--output {tmp_path}/missing/dof.png: cannot write there: no such directory\n")



def test_the_largest_png_is_refused_up_front_in_one_line(tmp_path: Path) -> None:
    # 40 × 40 in at 1200 dpi is 48000 × 48000 pixels (2.3 gigapixels, 9.2 GB of RGBA): refused before drawing.
    result = chart("dof", *SCENES["dof"], "--size", "40x40", "--dpi", "1200", "-o", str(tmp_path / "big.png"))
    assert result.exit_code == 2 and result.stdout == ""
    assert result.stderr.count("\n") == 1 and result.stderr.startswith("Error: Invalid value for '--dpi': 1200 ")
    assert "48000 × 48000 pixels" in result.stderr and "--size" in result.stderr
    assert list(tmp_path.iterdir()) == []


def test_the_pixel_bound_is_a_print_at_300_dpi_and_vector_formats_are_not_bound(tmp_path: Path) -> None:
    # 40 in × 300 dpi = 12000 px a side, the stated bound (144 megapixels); one pixel more across is refused.
    assert chartdata.MAX_PIXELS == 12_000 * 12_000
    assert chartdata.raster_pixels(40.0, 40.0, 300.0) == (12_000, 12_000)
    wider = chart("dof", *SCENES["dof"], "--size", "40x40", "--dpi", "300.03", "-o", str(tmp_path / "x.png"))
    assert (wider.exit_code, wider.stderr.count("\n")) == (2, 1) and "12001 × 12001 pixels" in wider.stderr
    # SVG and PDF are vector: --dpi does not size them, so any accepted --size and --dpi draws.
    svg = chart("dof", *SCENES["dof"], "--size", "40x40", "--dpi", "1200", "-o", str(tmp_path / "big.svg"))
    assert svg.exit_code == 0, svg.stderr
    assert _svg_size((tmp_path / "big.svg").read_text()) == (2880.0, 2880.0)  # 40 in × 72 pt


def test_the_library_save_refuses_too_many_pixels_too() -> None:
    from camtool.core.errors import DomainError

    figure = chartplot.draw(chartdata.dof_data([50.0], [8.0], 0.03, chartdata.log_space(1e3, 1e4, 5), "thin",
                                               "sensor", None, False, 550.0, 0.01), 40.0, 40.0)
    with pytest.raises(DomainError) as caught:
        chartplot.to_bytes(figure, "png", dpi=301.0)
    assert caught.value.param == "dpi"


def test_a_list_of_dpi_values_is_refused_not_cut_to_the_first(tmp_path: Path) -> None:
    result = chart("dof", *SCENES["dof"], "--size", "3x2", "--dpi", "40,80", "-o", str(tmp_path / "x.png"))
    assert (result.exit_code, result.stderr) == (2, "Error: Option '--dpi' takes one value here.\n")


@pytest.mark.parametrize("option", ["-o", "--data"])
@pytest.mark.parametrize("kind", ["fifo", "directory", "device", "symlink to a device"])
def test_an_output_that_is_not_a_regular_file_is_refused_at_once(tmp_path: Path, option: str, kind: str) -> None:
    target = tmp_path / "target.png"
    if kind == "fifo":
        os.mkfifo(target)
    elif kind == "directory":
        target.mkdir()
    elif kind == "symlink to a device":
        target.symlink_to("/dev/null")
    else:
        target = Path("/dev/null")
    image = ["-o", str(target), "--image-format", "png"] if option == "-o" else ["-o", str(tmp_path / "chart.svg"), "--data", str(target)]
    result = chart("dof", *SCENES["dof"], *SMALL, *image)  # a FIFO with no reader would block: the alarm fails it
    shown = "-o/--output" if option == "-o" else "--data"
    what = {"fifo": "a FIFO (named pipe)", "directory": "a directory"}.get(kind, "a device")
    assert (result.exit_code, result.stderr) == (
        1, f"Error: {shown} {target}: cannot write there: it is {what}, not a regular file\n")
    assert not (tmp_path / "chart.svg").exists()


def test_data_and_chart_in_the_same_file_is_refused(tmp_path: Path) -> None:
    target = str(tmp_path / "chart.svg")
    result = chart("dof", *SCENES["dof"], *SMALL, "-o", target, "--data", target)
    assert (result.exit_code, result.stderr.count("\n")) == (1, 1) and "--data" in result.stderr
    assert not Path(target).exists()


def test_an_existing_file_is_replaced_whole(tmp_path: Path) -> None:
    target = tmp_path / "chart.json"
    target.write_text("x" * 10**6)  # longer than the data: nothing of it may remain
    result = chart("dof", *SCENES["dof"], *SMALL, "-o", str(tmp_path / "chart.svg"), "--data", str(target))
    assert result.exit_code == 0, result.stderr
    assert json.loads(target.read_text())["kind"] == "dof"


@pytest.mark.parametrize("image", [["-o", "-", "--image-format", "svg"], ["-o", "chart.svg", "--data", "-"]])
def test_standard_output_closed_is_one_line_exit_1(tmp_path: Path, image: list[str]) -> None:
    result = subprocess.run([sys.executable, "-m", "camtool", "chart", "dof", *SCENES["dof"], *SMALL, *image],
                            cwd=tmp_path, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True, timeout=60,
                            preexec_fn=lambda: os.close(1))
    assert (result.returncode, result.stderr) == (1, "Error: cannot write to standard output: it is closed\n")


def _drift_free(data: dict[str, Any]) -> dict[str, Any]:
    """The chart data without what is measured on the spot (the trade chart's times)."""
    if data["kind"] == "trade":
        data = {**data, "curves": [{**c, "x": None} for c in data["curves"]]}
    return data


def _close(a: Any, b: Any) -> bool:
    if isinstance(a, float) and isinstance(b, float):
        return math.isclose(a, b, rel_tol=1e-7, abs_tol=1e-12)
    if isinstance(a, list) and isinstance(b, list):
        return len(a) == len(b) and all(_close(x, y) for x, y in zip(a, b))
    if isinstance(a, dict) and isinstance(b, dict):
        return a.keys() == b.keys() and all(_close(a[k], b[k]) for k in a)
    return bool(a == b)


def _no_drawing(monkeypatch: pytest.MonkeyPatch) -> None:
    """Skip the drawing (tested above) where only the numbers or the command line are checked."""
    monkeypatch.setattr(chartplot, "draw", lambda *args, **kwargs: None)
    monkeypatch.setattr(chartplot, "to_bytes", lambda *args, **kwargs: b"")


@pytest.mark.parametrize("kind", sorted(EXAMPLES))
def test_committed_example_charts_have_not_drifted(tmp_path: Path, kind: str, monkeypatch: pytest.MonkeyPatch) -> None:
    """docs/charts/KIND.json is what the README's command computes today; regenerate with the documented command."""
    _no_drawing(monkeypatch)
    args = shlex.split(EXAMPLES[kind])[2:]
    args[args.index("-o") + 1] = str(tmp_path / f"{kind}.svg")
    result = chart(*args, "--data", str(tmp_path / f"{kind}.json"))
    assert result.exit_code == 0, result.output
    fresh = _drift_free(json.loads((tmp_path / f"{kind}.json").read_text(encoding="utf-8")))
    committed = _drift_free(json.loads((DOCS / f"{kind}.json").read_text(encoding="utf-8")))
    assert _close(fresh, committed), f"docs/charts/{kind} drifted; run: python -m camtool.cli.chart docs/charts"
    assert (DOCS / f"{kind}.svg").is_file()
    assert f"docs/charts/{kind}.svg" in README


def test_readme_documents_the_regeneration_and_its_chart_commands_run(tmp_path: Path,
                                                                     monkeypatch: pytest.MonkeyPatch) -> None:
    assert "python -m camtool.cli.chart docs/charts" in README
    assert "pip install '.[chart]'" in README
    section = README.split("\n## Charts\n", 1)[1].split("\n## ", 1)[0]
    lines = [line.strip() for line in section.splitlines() if line.strip().startswith("camtool chart")]
    assert len(lines) >= 5
    monkeypatch.chdir(tmp_path)
    _no_drawing(monkeypatch)
    for line in lines:
        if "docs/charts/" in line:
            continue  # the committed examples, checked above
        result = chart(*shlex.split(line)[2:], *SMALL)
        assert result.exit_code == 0, (line, result.output)


def test_help_examples_run(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    from camtool.cli.chart import chart as group

    monkeypatch.chdir(tmp_path)
    (tmp_path / "tests" / "data").mkdir(parents=True)  # the shot example's per-frame data
    shutil.copy(Path(__file__).parent / "data" / "shot.csv", tmp_path / "tests" / "data" / "shot.csv")
    _no_drawing(monkeypatch)  # the command lines parse and compute; the drawing is tested above
    examples = [line.strip() for line in (group.help or "").split("Examples:")[1].splitlines() if line.strip()]
    assert len(examples) == 8
    for line in examples:
        words = shlex.split(line.split(">")[0])
        result = chart(*words[2:], *SMALL)
        assert result.exit_code == 0, (line, result.output)


def test_a_figure_too_small_for_its_labels_is_one_warning_line(tmp_path: Path) -> None:
    result = chart("dof", *SCENES["dof"], "--size", "1x1", "--dpi", "20", "-o", str(tmp_path / "tiny.png"))
    assert result.exit_code == 0
    assert result.stderr == ("Warning: the chart is too small for its labels at 1 × 1 in; some may overlap "
                             "(give a larger --size)\n")
    assert _png_size((tmp_path / "tiny.png").read_bytes()) == (20, 20)


def test_a_focus_sheet_without_lenses_is_a_usage_line_naming_what_to_give(tmp_path: Path) -> None:
    # not "Invalid value for '-f'" when -f was not typed: a usage error saying to give -f or --lenses
    result = run("chart", "marks", "--f-number", "2.8", "--output", str(tmp_path / "sheet.svg"))
    assert result.exit_code == 2 and result.stderr.count("\n") == 1
    assert "Invalid value" not in result.stderr and "-f (a list) or --lenses" in result.stderr
    assert not (tmp_path / "sheet.svg").exists()


def test_the_api_names_a_dof_charts_range_by_its_own_arguments() -> None:
    # the plan names the range as --from/--to do (low, high); the Python API names near_mm and far_mm
    # (the API fuzz found "more than low" on chart(kind="dof", near_mm=681805.6, far_mm=64000))
    import camtool
    from camtool.core.errors import DomainError, InputError

    with pytest.raises(InputError, match=r"^64000 is outside the valid range: more than near_mm \(681806\)$") as caught:
        camtool.chart(kind="dof", focal_length_mm=50, coc_mm=0.03, near_mm=681805.59, far_mm=64000.0)
    assert caught.value.param == "far_mm"
    with pytest.raises(DomainError, match="far_mm=inf") as caught_inf:
        camtool.chart(kind="dof", focal_length_mm=50, coc_mm=0.03, near_mm=1000.0, far_mm=math.inf)
    assert caught_inf.value.param == "far_mm"
    result = run("chart", "dof", "-f", "50", "-N", "8", "--from", "600m", "--to", "64m", "-o", "x.svg")
    assert result.exit_code == 2 and "--to" in result.stderr and "--from" in result.stderr
