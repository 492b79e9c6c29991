"""A circle-of-confusion map from a depth image: which settings, from where, and what each frame gives.

:func:`cocmap` decides, for each frame of a depth image or sequence:

- **settings**: a typed value wins; else the OpenEXR header's standard attribute (``focus`` in metres,
  ``aperture`` or else ``tStop`` standing in for the f-number, ``effectiveFocalLength`` or else
  ``pinholeFocalLength`` or ``nominalFocalLength``, ``entrancePupilOffset``); else a preset's (the lens's focal
  length, the camera's sensor). A header value is range-checked like the option it stands for; one out of range
  is a problem of the file (exit 1). Each summary row says where each value came from (``*_from``).
- **distance planes** (``physical``): depths are distances from the entrance pupil along the axis (a renderer's
  camera-space Z); the focus distance is from the sensor (image) plane, as lens scales and camtool's other
  commands measure it, and is moved to the entrance pupil by the ``entrancePupilOffset`` (the axial distance
  from the image plane to the entrance pupil) when it is known, else through the thick-lens geometry:
  x_f = (u − f) + f/P with u the object distance of the focus from the sensor (docs/design.md §4.2, δ = 0).
  ``blender`` and ``nuke`` take the focus as their nodes do: from the camera, in the depth's own units.
- **depth unit**: what one unit of the stored depth is; an OpenEXR depth defaults to metres (the scene unit of
  renderers and of the ``focus`` attribute), an integer PNG or TIFF has no default (its code values are
  arbitrary): the unit must be stated.
- **bad depths**: a NaN, a depth ≤ 0 (−∞ included) is a problem of the file naming the first pixel (x, y) and
  its value; +∞ (the sky) is a depth.

The summary row of a frame: the fraction of pixels whose CoC is within the limit c, the nearest and farthest
depth among those sharp pixels (mm), and in ``physical`` mode the near and far limits of the depth of field
(docs/design.md §4.5, from the entrance pupil).
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from typing import Any

from camtool.core.errors import DomainError, InputError
from camtool.core.files import FileProblem
from camtool.core.record import NamedTuple

MODES = ("physical", "blender", "nuke")


class Settings(NamedTuple):
    """What every frame of a run uses, with where each value came from (``typed``, ``header``, ``preset``)."""

    mode: str
    focus_mm: float | None
    f_number: float | None
    focal_length_mm: float | None
    pupil_offset_mm: float | None
    pupil_magnification: float
    sensor_width_mm: float
    coc_mm: float
    depth_unit_mm: float | None
    blender_f_stop: float | None
    max_blur_px: float
    z_scale: float | None
    nuke_math: str
    nuke_size: float
    nuke_maximum: float
    channel: str | None


class Frame(NamedTuple):
    """The outcome of one frame: its summary row, and the CoC (mm) and radius (px) maps if kept."""

    row: dict[str, Any]
    coc_mm: Any
    radius_px: Any


def _header_value(path: str, name: str, value: float, bounds: tuple[float, float], unit: str) -> float:
    from camtool.core.ranges import describe

    if not (math.isfinite(value) and bounds[0] <= value <= bounds[1]):
        raise FileProblem(path, f"header attribute {name} = {value:g} is outside the valid range: "
                                f"{describe(bounds, unit)}")
    return value


def frame_settings(path: str, attributes: dict[str, float], s: Settings) -> tuple[dict[str, Any], dict[str, str]]:
    """The focus (mm, from the sensor or the camera), f-number, focal length and pupil offset of one frame, each
    the typed value, else the header's (checked), else None; and where each came from."""
    from camtool.core.ranges import DISTANCE_MM, F_NUMBER, FOCAL_LENGTH_MM

    used: dict[str, Any] = {}
    source: dict[str, str] = {}

    def pick(key: str, typed: Any, names: Sequence[str], bounds: tuple[float, float], unit: str,
             scale: float = 1.0) -> None:
        if typed is not None:
            used[key], source[key] = typed, "typed"
            return
        for name in names:
            if name in attributes:
                value = _header_value(path, name, attributes[name], bounds, unit) * scale
                used[key], source[key] = value, f"header {name}"
                return
        used[key], source[key] = None, ""

    pick("focus_mm", s.focus_mm, ["focus"], (DISTANCE_MM[0] / 1000, DISTANCE_MM[1] / 1000), "m", 1000.0)
    pick("f_number", s.f_number, ["aperture", "tStop"], F_NUMBER, "")
    pick("focal_length_mm", s.focal_length_mm, ["effectiveFocalLength", "pinholeFocalLength", "nominalFocalLength"],
         FOCAL_LENGTH_MM, "mm")
    f = used["focal_length_mm"] or FOCAL_LENGTH_MM[1]
    pick("pupil_offset_mm", s.pupil_offset_mm, ["entrancePupilOffset"], (-10 * f, 1e9), "mm")
    if used["focus_mm"] is not None and used["focus_mm"] <= 0:
        raise FileProblem(path, "header attribute focus is 0: a focus distance is > 0")
    return used, source


def pupil_focus_mm(*, focus_mm: float, focal_length_mm: float, pupil_magnification: float = 1.0,
                   pupil_offset_mm: float | None = None) -> float:
    """The focus distance from the entrance pupil of a focus ``focus_mm`` from the sensor: less the entrance
    pupil's offset from the image plane when known, else (u − f) + f/P with u from the sensor distance.

    >>> pupil_focus_mm(focus_mm=200.0, focal_length_mm=50.0)   # 1:1, u = 100 mm: the pupil at the lens
    100.0
    >>> pupil_focus_mm(focus_mm=3000.0, focal_length_mm=50.0, pupil_offset_mm=80.0)
    2920.0
    """
    if pupil_offset_mm is not None:
        x = focus_mm - pupil_offset_mm
    else:
        from camtool.geometry.thinlens import lens_distances

        u = lens_distances(focal_length_mm, focus_mm).object_mm
        x = (u - focal_length_mm) + focal_length_mm / pupil_magnification
    if not x > focal_length_mm / pupil_magnification:
        raise DomainError("distance", focus_mm, f"a focus beyond f/P = {focal_length_mm / pupil_magnification:g} mm "
                                                "from the entrance pupil")
    return x


def check_depths(path: str, values: Any, *, allow_zero: bool = False) -> None:
    """A NaN or a depth ≤ 0 (< 0 with ``allow_zero``) is one line naming the first such pixel (x, y)."""
    import numpy as np

    low = float(values.min()) if values.size else 1.0
    if low > 0 or (allow_zero and low >= 0):
        return
    if math.isnan(low):
        bad = np.isnan(values)
        what = "a NaN (not a number)"
    else:
        bad = values < 0 if allow_zero else values <= 0
        what = None
    y, x = (int(i) for i in np.unravel_index(int(np.argmax(bad)), values.shape))
    count = int(np.count_nonzero(bad))
    value = what or f"{float(values[y, x]):g}"
    need = "≥ 0" if allow_zero else "> 0"
    raise FileProblem(path, f"depth at pixel ({x}, {y}) is {value}; a depth is {need} "
                            f"({count} pixel{'s' if count != 1 else ''} so)")


def compute_frame(path: str, out: str | None, s: Settings, *, frame: int = 0, keep: bool = False) -> Frame:
    """Read one depth image, compute its CoC and radius maps, write them to ``out`` and summarise."""
    import numpy as np

    from camtool.depthmap.io import read_depth, write_map
    from camtool.dof import cocmap as formulas

    image = read_depth(path, s.channel)
    used, source = frame_settings(path, image.attributes, s)
    unit = s.depth_unit_mm if s.depth_unit_mm is not None else (None if image.integer else 1000.0)
    if unit is None:
        raise InputError("depth_unit", "an integer depth image needs its unit: give {depth_unit} (e.g. 1mm)",
                         usage=True)
    depth = image.values
    height, width = depth.shape
    px_per_mm = width / s.sensor_width_mm
    direct = (s.mode == "nuke" and s.nuke_math in ("direct", "far=0")) or (s.mode == "blender" and s.z_scale)
    check_depths(path, depth, allow_zero=bool(direct))
    needs = ["focal_length_mm", "f_number", "focus_mm"] if s.mode == "physical" else \
        (["focal_length_mm", "f_number", "focus_mm"] if s.mode == "blender" and not s.z_scale else
         (["focus_mm"] if s.mode == "nuke" and s.nuke_math != "direct" else []))
    option = {"focal_length_mm": "focal_length", "f_number": "f_number", "focus_mm": "distance"}
    for key in needs:
        if used[key] is None:
            raise InputError(option[key], f"give {{{option[key]}}}: {path} has no {key.split('_')[0]} "
                                          "attribute", usage=True)
    near = far = None
    f, n = used["focal_length_mm"], used["f_number"]
    to_radius = 0.5 * px_per_mm  # CoC diameter (mm) -> radius (px)
    if s.mode == "physical":
        x_f = pupil_focus_mm(focus_mm=used["focus_mm"], focal_length_mm=f, pupil_magnification=s.pupil_magnification,
                             pupil_offset_mm=used["pupil_offset_mm"])
        first = formulas.physical_coc_mm(depth, focus_mm=x_f, focal_length_mm=f, f_number=n,
                                         pupil_magnification=s.pupil_magnification, depth_unit_mm=unit)
        k = n * s.coc_mm * (x_f - f / s.pupil_magnification)
        near = x_f * f * f / (f * f + k)
        far = x_f * f * f / (f * f - k) if f * f > k else math.inf
    elif s.mode == "blender" and s.z_scale:
        first = formulas.blender_mask_radius_px(depth, z_scale=s.z_scale, max_blur_px=s.max_blur_px)
    elif s.mode == "blender":
        first = formulas.blender_radius_px(depth, focus_mm=used["focus_mm"], focal_length_mm=f,
                                           sensor_width_mm=s.sensor_width_mm, width_px=width,
                                           f_stop=s.blender_f_stop or n, max_blur_px=s.max_blur_px, depth_unit_mm=unit)
    else:
        plane = (used["focus_mm"] / unit) if used["focus_mm"] is not None else 0.0
        if s.nuke_math == "far=0" and plane:
            plane = 1.0 / plane
        first = formulas.nuke_size_px(depth, math=s.nuke_math, focus_plane=plane, size=s.nuke_size,
                                      maximum=s.nuke_maximum)
    is_coc = s.mode == "physical"
    # the statistics on the first map, before the second exists: at most three frames in memory
    sharp = np.less_equal(first, s.coc_mm if is_coc else s.coc_mm * to_radius, out=np.empty(first.shape, bool))
    count = int(np.count_nonzero(sharp))
    largest = float(first.max()) if depth.size else 0.0
    distances = not direct
    sharp_near = float(np.min(depth, where=sharp, initial=np.inf)) * unit if count and distances else None
    sharp_far = float(np.max(depth, where=sharp, initial=-np.inf)) * unit if count and distances else None
    del sharp
    coc, radius = (first, first * np.float32(to_radius)) if is_coc else (first * np.float32(1 / to_radius), first)
    row: dict[str, Any] = {
        "frame": frame, "depth_file": path, "map_file": out, "mode": s.mode, "width_px": width, "height_px": height,
        "depth_unit_mm": unit, "focus_mm": used["focus_mm"], "focus_from": source["focus_mm"] or None,
        "f_number": n, "f_number_from": source["f_number"] or None, "focal_length_mm": f,
        "focal_length_from": source["focal_length_mm"] or None, "pupil_offset_mm": used["pupil_offset_mm"],
        "pupil_magnification": s.pupil_magnification, "sensor_width_mm": s.sensor_width_mm, "coc_mm": s.coc_mm,
        "sharp_fraction": count / depth.size if depth.size else 0.0, "sharp_near_mm": sharp_near,
        "sharp_far_mm": sharp_far, "near_limit_mm": near, "far_limit_mm": far,
        "max_coc_mm": largest if is_coc else largest / to_radius,
        "max_radius_px": largest * to_radius if is_coc else largest,
    }
    if out is not None:
        write_map(out, coc, radius)
    return Frame(row, coc if keep else None, radius if keep else None)


def output_names(frames: Sequence[str], out: str) -> list[str]:
    """Where each frame's map goes: ``out`` itself for one frame, else ``out`` % frame number (a printf pattern)
    or a file of the same stem in the folder ``out``, with the extension of ``out`` (a pattern) or ``.exr``."""
    import os
    import re

    if len(frames) == 1 and not os.path.isdir(out):
        return [out]
    if re.search(r"%0?\d*d", out):
        numbers = [_frame_number(name, i) for i, name in enumerate(frames)]
        return [out % number for number in numbers]
    if os.path.isdir(out):
        return [os.path.join(out, os.path.splitext(os.path.basename(name))[0] + ".exr") for name in frames]
    raise InputError("output", "a sequence needs {output} to be a folder or a printf pattern such as "
                               "coc.%04d.exr", usage=True)


def _frame_number(name: str, index: int) -> int:
    import os
    import re

    found = re.findall(r"\d+", os.path.basename(name))
    return int(found[-1]) if found else index


def _portable(error: BaseException) -> tuple[str, tuple[Any, ...]]:
    """An error of a worker process as a picklable recipe (its class and the arguments that rebuild it)."""
    if isinstance(error, FileProblem):
        return "file", (error.path, error.problem)
    if isinstance(error, InputError):
        return "input", (error.param, error.template, error.usage)
    if isinstance(error, DomainError):
        return "domain", (error.param, error.value, error.valid)
    return "other", (f"{type(error).__name__}: {error}",)


def _rebuilt(recipe: tuple[str, tuple[Any, ...]]) -> BaseException:
    kind, args = recipe
    if kind == "file":
        return FileProblem(*args)
    if kind == "input":
        return InputError(*args)
    if kind == "domain":
        return DomainError(*args)
    return RuntimeError(*args)


def frame_task(task: tuple[int, str, str | None, Settings]) -> tuple[bool, Any]:
    """One frame in a worker process (or a Dask task): (True, its summary row) or (False, the error's recipe)."""
    index, path, out, settings = task
    try:
        return True, compute_frame(path, out, settings, frame=index).row
    except (FileProblem, InputError, DomainError) as error:
        return False, _portable(error)


def run_frames(*, frames: Sequence[str], outputs: Sequence[str | None], settings: Settings, jobs: int = 1,
               scheduler: str | None = None) -> Any:
    """The summary rows of every frame, in order, as they are done: one at a time, over ``jobs`` processes (each
    holds one frame at a time), or on a Dask cluster (``scheduler``: an address, or ``local:N`` for N local
    workers). The first failing frame (in order) raises its error after the rows before it."""
    tasks = [(i, path, out, settings) for i, (path, out) in enumerate(zip(frames, outputs))]
    if scheduler is not None:
        results = _dask_results(tasks, scheduler)
    elif jobs <= 1 or len(tasks) <= 1:
        results = map(frame_task, tasks)
    else:
        from concurrent.futures import ProcessPoolExecutor

        pool = ProcessPoolExecutor(max_workers=min(jobs, len(tasks)))
        try:
            yield from _rows(pool.map(frame_task, tasks))
        finally:
            pool.shutdown(cancel_futures=True)
        return
    yield from _rows(results)


def _rows(results: Any) -> Any:
    for ok, value in results:
        if not ok:
            raise _rebuilt(value)
        yield value


def _dask_results(tasks: list[Any], scheduler: str) -> Any:
    try:
        from dask.distributed import Client, LocalCluster
    except ImportError:
        raise InputError("scheduler", "{scheduler} needs Dask: pip install 'camtool[dask]'", usage=True) from None
    cluster = None
    if scheduler.startswith("local:"):
        count = scheduler.split(":", 1)[1]
        if not count.isdigit() or not 1 <= int(count) <= 1024:
            raise InputError("scheduler", "{scheduler} local:N takes a number of workers from 1 to 1024")
        cluster = LocalCluster(n_workers=int(count), threads_per_worker=1, processes=True, dashboard_address=None)
        client = Client(cluster)
    else:
        import re

        if not re.fullmatch(r"(tcp://)?[A-Za-z0-9_.\-\[\]:]+:\d{1,5}", scheduler):
            raise InputError("scheduler", "{scheduler} is local:N or a scheduler address HOST:PORT "
                                          "(tcp://HOST:PORT)", usage=True)
        try:
            client = Client(scheduler, timeout=10)
        except Exception as error:
            raise InputError("scheduler", f"cannot reach the Dask scheduler at {{scheduler}}: "
                                          f"{' '.join(str(error).split())[:120]}") from None
    try:
        futures = client.map(frame_task, tasks, pure=False)
        for future in futures:
            yield future.result()
    finally:
        client.close()
        if cluster is not None:
            cluster.close()


class CocMap(NamedTuple):
    """A CoC map of depths given as an array: the blur-disc diameters on the sensor, what share of them is within
    the CoC limit, and the near and far limits of the depth of field (all mm, from the entrance pupil)."""

    coc_mm: Any
    sharp_fraction: float
    near_limit_mm: float
    far_limit_mm: float


def coc_map(*, depth_mm: Any, focus_mm: float, focal_length_mm: float, f_number: float, coc_mm: float,
            pupil_magnification: float = 1.0) -> CocMap:
    """The physical mode on an array of depths (mm from the entrance pupil, ``inf`` allowed; the focus too).

    >>> m = coc_map(depth_mm=[2500.0, 5000.0], focus_mm=5000.0, focal_length_mm=50.0, f_number=2.0, coc_mm=0.03)
    >>> [round(float(c), 6) for c in m.coc_mm], m.sharp_fraction   # K·|1 − x_f/x|, K = 50²/(2·4950)
    ([0.252525, 0.0], 0.5)
    """
    import numpy as np

    from camtool.dof import cocmap as formulas

    depth = np.asarray(depth_mm, dtype=float)
    f, p = focal_length_mm, pupil_magnification
    if not focus_mm > f / p:
        raise DomainError("focus_mm", focus_mm, f"> f/P = {f / p:g} mm (the focus beyond the front focal plane)")
    coc = formulas.physical_coc_mm(depth, focus_mm=focus_mm, focal_length_mm=f, f_number=f_number,
                                   pupil_magnification=p)
    k = f_number * coc_mm * (focus_mm - f / p)
    far = focus_mm * f * f / (f * f - k) if f * f > k else math.inf
    sharp = float(np.count_nonzero(coc <= coc_mm)) / coc.size if coc.size else 0.0
    return CocMap(float(coc) if coc.ndim == 0 else coc, sharp, focus_mm * f * f / (f * f + k), far)
