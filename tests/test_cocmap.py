"""``camtool cocmap``: the physical CoC against independent formulas, Blender's and Nuke's documented behaviour,
header round-trips, bad depth files in one line, and a sequence on Dask byte for byte equal to the serial run."""

from __future__ import annotations

import json
import os

import numpy as np
import pytest
from cli_helpers import run

from camtool.dof import cocmap as formulas
from camtool.dof.thick import thick_dof
from camtool.geometry.thinlens import blur_diameter_mm
from camtool.plans.cocmap import pupil_focus_mm

OpenEXR = pytest.importorskip("OpenEXR")

HEADER = {"compression": OpenEXR.NO_COMPRESSION, "type": OpenEXR.scanlineimage}


def _exr(path: os.PathLike[str] | str, channels: dict[str, np.ndarray], **attributes: float) -> str:
    OpenEXR.File({**HEADER, **attributes}, channels).write(str(path))
    return str(path)


def _ramp(width: int = 200, height: int = 4) -> np.ndarray:
    return np.tile(np.geomspace(0.3, 80.0, width, dtype=np.float32), (height, 1))


# --- the physical mode against independent formulas -------------------------------------------------------------

def test_physical_coc_is_the_thin_lens_blur_disc() -> None:
    # P = 1: the entrance pupil is the lens; geometry.thinlens.blur_diameter_mm (f/N)·|v_s − v_o|/v_o
    depth_mm = np.geomspace(150.0, 1e6, 400)
    for f, n, s in ((50.0, 2.8, 3000.0), (24.0, 1.4, 800.0), (135.0, 8.0, 20000.0)):
        coc = formulas.physical_coc_mm(depth_mm, focus_mm=s, focal_length_mm=f, f_number=n)
        k = f * f / (n * (s - f))  # the blur at infinity: near the focus the difference cancels to ~ε·K
        assert np.allclose(coc, blur_diameter_mm(f, n, s, depth_mm), rtol=1e-12, atol=1e-13 * k)
    at_inf = formulas.physical_coc_mm(np.array([np.inf]), focus_mm=5050.0, focal_length_mm=50.0, f_number=2.0)
    assert at_inf[0] == pytest.approx(0.25, rel=1e-15)  # blur_diameter_mm's own example


@pytest.mark.parametrize("p", [0.4, 0.7, 1.0, 1.6, 3.0])
def test_physical_coc_equals_the_limit_at_the_thick_rungs_near_and_far(p: float) -> None:
    # the thick rung (design §4.5, an independent closed form): at its near and far limits from the entrance pupil
    # the blur is exactly c
    f, n, c, x_f = 85.0, 2.0, 0.025, 4000.0
    limits = thick_dof(f, n, c, x_f, pupil_magnification=p, distance_from="entrance_pupil")
    coc = formulas.physical_coc_mm(np.array([limits.near_mm, limits.far_mm]), focus_mm=x_f, focal_length_mm=f,
                                   f_number=n, pupil_magnification=p)
    assert np.allclose(coc, c, rtol=1e-12)


def test_depth_unit_does_not_change_the_answer() -> None:
    metres = formulas.physical_coc_mm(np.array([1.5, 7.0]), focus_mm=3000.0, focal_length_mm=50.0, f_number=4.0,
                                      depth_unit_mm=1000.0)
    mm = formulas.physical_coc_mm(np.array([1500.0, 7000.0]), focus_mm=3000.0, focal_length_mm=50.0, f_number=4.0)
    assert np.allclose(metres, mm, rtol=1e-14)


def test_focus_from_the_sensor_to_the_pupil() -> None:
    # thin lens (design §4.2): D = u + v; from the sensor 3 m with f = 50: u = L/2(1 + √(1 − 4f/L))
    u = 1500.0 * (1 + np.sqrt(1 - 200.0 / 3000.0))
    assert pupil_focus_mm(focus_mm=3000.0, focal_length_mm=50.0) == pytest.approx(u, rel=1e-14)
    # P ≠ 1: x = (u − f) + f/P (design §4.2)
    assert pupil_focus_mm(focus_mm=3000.0, focal_length_mm=50.0, pupil_magnification=0.5) == \
        pytest.approx(u - 50.0 + 100.0, rel=1e-14)


def test_synthetic_ramp_map_and_summary_against_the_analytic_coc(tmp_path) -> None:
    z = _ramp()
    depth = _exr(tmp_path / "ramp.exr", {"Z": z})
    out = tmp_path / "coc.npy"
    rows = json.loads(run("cocmap", depth, "-o", str(out), "-f", "50", "-N", "2.8", "-s", "3m", "--sensor",
                          "36x24", "--coc", "0.03", "--format", "json").stdout)
    coc, radius = np.load(out)
    x_f = pupil_focus_mm(focus_mm=3000.0, focal_length_mm=50.0)
    expected = blur_diameter_mm(50.0, 2.8, x_f, z.astype(np.float64) * 1000.0)
    assert np.allclose(coc, expected, rtol=2e-6, atol=1e-6 * expected.max())  # float32 map
    assert np.allclose(radius, coc * 0.5 * 200 / 36.0, rtol=1e-6)
    row = rows[0]
    sharp = expected <= 0.03
    assert row["sharp_fraction"] == pytest.approx(np.count_nonzero(sharp) / z.size)
    limits = thick_dof(50.0, 2.8, 0.03, x_f, distance_from="entrance_pupil")
    assert (row["near_limit_mm"], row["far_limit_mm"]) == pytest.approx((limits.near_mm, limits.far_mm), rel=1e-12)
    assert row["near_limit_mm"] <= row["sharp_near_mm"] <= row["sharp_far_mm"] <= row["far_limit_mm"]


@pytest.mark.parametrize("p", [0.5, 2.0])
def test_pupil_magnification_typed_moves_the_limits_as_the_thick_rung_does(tmp_path, p: float) -> None:
    # --pupil-mag reaches the physical map: the summary's limits are the thick rung's, from the entrance pupil,
    # at x_f = (u − f) + f/P (the deep command-line fuzz found the option raising a TypeError here)
    depth = _exr(tmp_path / "ramp.exr", {"Z": _ramp()})
    result = run("cocmap", depth, "-o", str(tmp_path / "coc.npy"), "-f", "50", "-N", "2.8", "-s", "3m", "--sensor",
                 "36x24", "--coc", "0.03", "--pupil-mag", repr(p), "--format", "json")
    assert result.exit_code == 0, result.output
    row = json.loads(result.stdout)[0]
    x_f = pupil_focus_mm(focus_mm=3000.0, focal_length_mm=50.0, pupil_magnification=p)
    limits = thick_dof(50.0, 2.8, 0.03, x_f, pupil_magnification=p, distance_from="entrance_pupil")
    assert (row["near_limit_mm"], row["far_limit_mm"]) == pytest.approx((limits.near_mm, limits.far_mm), rel=1e-12)


# --- Blender's Defocus node, as documented ------------------------------------------------------------------------

def test_blender_f_stop_128_is_perfect_focus_and_half_doubles_the_radius() -> None:
    z = np.array([0.5, 1.0, 10.0, np.inf], dtype=np.float64)
    args = {"focus_mm": 3000.0, "focal_length_mm": 35.0, "sensor_width_mm": 36.0, "width_px": 1920}
    assert not np.any(formulas.blender_radius_px(z, f_stop=128.0, **args))
    r8, r4 = formulas.blender_radius_px(z, f_stop=8.0, **args), formulas.blender_radius_px(z, f_stop=4.0, **args)
    assert np.allclose(r4, 2 * r8, rtol=1e-14)
    capped = formulas.blender_radius_px(z, f_stop=1.0, max_blur_px=5.0, **args)
    assert capped.max() == 5.0 and np.all(capped <= 5.0)
    # the radius is half the thin-lens disc in pixels of the sensor width
    assert np.allclose(r8, blur_diameter_mm(35.0, 8.0, 3000.0, z * 1000.0) / 2 * 1920 / 36.0, rtol=1e-12)


def test_blender_without_z_buffer_scales_the_input() -> None:
    r = formulas.blender_mask_radius_px(np.array([0.0, 0.25, 1.0]), z_scale=16.0, max_blur_px=10.0)
    assert list(r) == [0.0, 4.0, 10.0]


# --- Nuke's ZDefocus, as documented ---------------------------------------------------------------------------------

def test_nuke_depth_size_is_the_blur_at_infinity_zero_at_the_focus_plane() -> None:
    z = np.array([np.inf, 1e12, 5.0, 2.5], dtype=np.float64)
    size = formulas.nuke_size_px(z, math="depth", focus_plane=5.0, size=12.0, maximum=1e9)
    assert size[0] == 12.0 and size[1] == pytest.approx(12.0) and size[2] == 0.0 and size[3] == 12.0
    # far=0 holds 1/z: the same blur; direct is the channel itself; maximum clips
    inverse = formulas.nuke_size_px(1.0 / z, math="far=0", focus_plane=1 / 5.0, size=12.0, maximum=1e9)
    assert np.allclose(inverse, size, rtol=1e-12)
    assert list(formulas.nuke_size_px(np.array([3.0, 40.0]), math="direct", focus_plane=0, size=0, maximum=30)) == \
        [3.0, 30.0]


def test_modes_through_the_command(tmp_path) -> None:
    depth = _exr(tmp_path / "ramp.exr", {"Z": _ramp()})
    nuke = tmp_path / "n.npy"
    result = run("cocmap", depth, "-o", str(nuke), "--mode", "nuke", "--size", "20", "--maximum", "50", "-s", "3m",
                 "--format", "json")
    assert result.exit_code == 0, result.output
    expected = formulas.nuke_size_px(_ramp().astype(np.float64), math="depth", focus_plane=3.0, size=20.0,
                                     maximum=50.0)
    assert np.allclose(np.load(nuke)[1], expected, rtol=1e-6, atol=1e-5 * 20)  # float32 map
    blender = tmp_path / "b.npy"
    result = run("cocmap", depth, "-o", str(blender), "--mode", "blender", "-f", "35", "-N", "4", "-s", "3m",
                 "--max-blur", "30", "--format", "json")
    assert result.exit_code == 0, result.output
    ref = formulas.blender_radius_px(_ramp().astype(np.float64), focus_mm=3000.0, focal_length_mm=35.0,
                                     sensor_width_mm=36.0, width_px=200, f_stop=4.0, max_blur_px=30.0)
    assert np.allclose(np.load(blender)[1], ref, rtol=1e-6, atol=1e-5 * 30)


# --- headers, formats ---------------------------------------------------------------------------------------------

def test_header_attributes_are_used_and_typed_options_win(tmp_path) -> None:
    depth = _exr(tmp_path / "lens.exr", {"Z": _ramp()}, focus=3.0, aperture=2.8, effectiveFocalLength=50.0,
                 entrancePupilOffset=120.0)
    row = json.loads(run("cocmap", depth, "-o", str(tmp_path / "a.exr"), "--format", "json").stdout)[0]
    assert (row["focus_mm"], row["focal_length_mm"], row["pupil_offset_mm"]) == (3000.0, 50.0, 120.0)
    assert row["f_number"] == pytest.approx(2.8, rel=1e-7)  # a float attribute
    assert (row["focus_from"], row["f_number_from"]) == ("header focus", "header aperture")
    limits = thick_dof(50.0, row["f_number"], row["coc_mm"], 3000.0 - 120.0, distance_from="entrance_pupil")
    assert row["near_limit_mm"] == pytest.approx(limits.near_mm, rel=1e-12)
    typed = json.loads(run("cocmap", depth, "-o", str(tmp_path / "b.exr"), "-N", "4", "--format", "json").stdout)[0]
    assert (typed["f_number"], typed["f_number_from"]) == (4.0, "typed")


def test_exr_png_and_npy_maps_agree(tmp_path) -> None:
    depth = _exr(tmp_path / "d.exr", {"depth.Z": _ramp()})
    args = ["-f", "50", "-N", "2", "-s", "2m"]
    for name in ("m.exr", "m.npy", "m.png"):
        assert run("cocmap", depth, "-o", str(tmp_path / name), *args).exit_code == 0
    coc, radius = np.load(tmp_path / "m.npy")
    channels = OpenEXR.File(str(tmp_path / "m.exr")).channels()
    assert np.array_equal(channels["coc_mm"].pixels, coc) and np.array_equal(channels["radius_px"].pixels, radius)
    imageio = pytest.importorskip("imageio.v3")
    png = imageio.imread(tmp_path / "m.png")
    assert png.dtype == np.uint16 and np.array_equal(png, np.rint(np.minimum(radius * 100, 65535)).astype(np.uint16))


def test_png16_depth_with_its_unit(tmp_path) -> None:
    imageio = pytest.importorskip("imageio.v3")
    codes = np.tile(np.arange(300, 60000, 300, dtype=np.uint16), (3, 1))
    imageio.imwrite(tmp_path / "d.png", codes)
    out = tmp_path / "m.npy"
    result = run("cocmap", str(tmp_path / "d.png"), "-o", str(out), "-f", "50", "-N", "2", "-s", "2m",
                 "--depth-unit", "1mm")
    assert result.exit_code == 0, result.output
    x_f = pupil_focus_mm(focus_mm=2000.0, focal_length_mm=50.0)
    expected = blur_diameter_mm(50.0, 2.0, x_f, codes.astype(np.float64))
    assert np.allclose(np.load(out)[0], expected, rtol=2e-6, atol=1e-6 * expected.max())
    missing = run("cocmap", str(tmp_path / "d.png"), "-o", str(out), "-f", "50", "-N", "2", "-s", "2m")
    assert missing.exit_code == 2 and "--depth-unit" in missing.output


# --- bad depth files: one line each ---------------------------------------------------------------------------------

def _one_line(result, code: int) -> str:
    assert result.exit_code == code, result.output
    lines = result.output.strip().splitlines()
    assert len(lines) == 1 and lines[0].startswith("Error: ") and "Traceback" not in result.output, result.output
    return lines[0]


def test_bad_depth_files(tmp_path) -> None:
    args = ["-o", str(tmp_path / "m.npy"), "-f", "50", "-N", "2", "-s", "2m"]
    rgb = _exr(tmp_path / "rgb.exr", {"R": _ramp(), "G": _ramp()})
    assert "no Z or depth channel (its channels: G, R)" in _one_line(run("cocmap", rgb, *args), 1)
    z = _ramp()
    z[2, 7] = np.nan
    assert "pixel (7, 2) is a NaN" in _one_line(run("cocmap", _exr(tmp_path / "nan.exr", {"Z": z}), *args), 1)
    for value, shown in ((-1.5, "-1.5"), (0.0, "0"), (-np.inf, "-inf")):
        z = _ramp()
        z[1, 3] = value
        line = _one_line(run("cocmap", _exr(tmp_path / "neg.exr", {"Z": z}), *args), 1)
        assert f"pixel (3, 1) is {shown}" in line
    whole = (tmp_path / "neg.exr").read_bytes()
    (tmp_path / "cut.exr").write_bytes(whole[: len(whole) // 2])
    assert "cannot read it as OpenEXR" in _one_line(run("cocmap", str(tmp_path / "cut.exr"), *args), 1)
    (tmp_path / "junk.exr").write_bytes(b"not an image at all")
    _one_line(run("cocmap", str(tmp_path / "junk.exr"), *args), 1)
    assert "No such file" in _one_line(run("cocmap", str(tmp_path / "none.exr"), *args), 1)
    (tmp_path / "x.jpg").write_bytes(b"\xff\xd8")
    assert "unknown image type .jpg" in _one_line(run("cocmap", str(tmp_path / "x.jpg"), *args), 1)
    os.mkfifo(tmp_path / "fifo.exr")
    assert "FIFO" in _one_line(run("cocmap", str(tmp_path / "fifo.exr"), *args), 1)
    imageio = pytest.importorskip("imageio.v3")
    imageio.imwrite(tmp_path / "rgb.png", np.zeros((4, 4, 3), np.uint8))
    assert "one channel" in _one_line(run("cocmap", str(tmp_path / "rgb.png"), *args, "--depth-unit", "1mm"), 1)
    imageio.imwrite(tmp_path / "grey8.png", np.ones((4, 4), np.uint8))
    assert "8-bit" in _one_line(run("cocmap", str(tmp_path / "grey8.png"), *args, "--depth-unit", "1mm"), 1)


def test_bad_header_attribute_is_one_line(tmp_path) -> None:
    depth = _exr(tmp_path / "h.exr", {"Z": _ramp()}, focus=3.0, aperture=0.1, effectiveFocalLength=50.0)
    line = _one_line(run("cocmap", depth, "-o", str(tmp_path / "m.npy")), 1)
    assert "aperture = 0.1 is outside the valid range" in line


# --- sequences -----------------------------------------------------------------------------------------------------

def _sequence(folder) -> str:
    for i in range(3):
        _exr(folder / f"shot.{i + 1:04d}.exr", {"Z": _ramp() * (1 + i)}, focus=2.0 + i, aperture=2.8,
             effectiveFocalLength=50.0)
    return str(folder / "shot.%04d.exr")


def _outputs(folder) -> dict[str, bytes]:
    return {name: (folder / name).read_bytes() for name in sorted(os.listdir(folder))}


def test_sequence_over_processes_equals_serial(tmp_path) -> None:
    pattern = _sequence(tmp_path)
    for jobs in ("1", "2"):
        (tmp_path / jobs).mkdir()
        result = run("cocmap", pattern, "-o", str(tmp_path / jobs / "coc.%04d.exr"), "--jobs", jobs, "--format", "csv")
        assert result.exit_code == 0, result.output
    assert _outputs(tmp_path / "1") == _outputs(tmp_path / "2") and len(_outputs(tmp_path / "1")) == 3


def test_sequence_on_a_two_worker_dask_cluster_equals_serial(tmp_path) -> None:
    pytest.importorskip("dask.distributed")
    pattern = _sequence(tmp_path)
    (tmp_path / "serial").mkdir()
    (tmp_path / "dask").mkdir()
    serial = run("cocmap", pattern, "-o", str(tmp_path / "serial"), "--jobs", "1", "--format", "csv")
    assert serial.exit_code == 0, serial.output
    spread = run("cocmap", pattern, "-o", str(tmp_path / "dask"), "--scheduler", "local:2", "--format", "csv")
    assert spread.exit_code == 0, spread.output
    assert spread.stdout.replace("/dask/", "/serial/") == serial.stdout
    assert _outputs(tmp_path / "dask") == _outputs(tmp_path / "serial") and len(_outputs(tmp_path / "serial")) == 3
