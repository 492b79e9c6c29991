"""Per-pixel blur from a depth image: camtool's physical circle of confusion, and the blur Blender's Defocus node
and Nuke's ZDefocus derive from their own inputs.

Every function takes numpy arrays (a depth image) and works in place where it can, in float32, because a
4096 × 2160 frame is 8.8 million pixels; scalars are checked by the plan before they get here.

**physical** (:func:`physical_coc_mm`). Distances x from the entrance pupil, along the axis (a renderer's
camera-space Z: its pinhole is the entrance pupil). A lens of focal length f, f-number N and pupil magnification
P focused at x_f images a point at x as a blur disc on the sensor of diameter

    c(x) = f² · |x − x_f| / (N · x · (x_f − f/P)) = K · |1 − x_f/x|,  K = f² / (N · (x_f − f/P))

(the cone through the entrance pupil, of diameter f/N, imaged by the exit pupil, P times as large; with P = 1 the
thin-lens blur (f/N)·|v_f − v|/v of :func:`camtool.geometry.thinlens.blur_diameter_mm`). Its limits c(x) = c are
the ``thick`` rung's near_E = x_f·f²/(f² + N·c·(x_f − f/P)) and far_E = x_f·f²/(f² − N·c·(x_f − f/P))
(docs/design.md §4.5). At x = ∞ the blur is K.

**blender** (:func:`blender_radius_px`). The Defocus node with "Use Z-Buffer": the scene camera's focal length
and sensor width in mm, its focus distance and the Z pass in scene units (metres), and the node's F-Stop, which
"controls the amount of focal blur in the same way as a real camera"; "the default value 128 is assumed to be
infinity: everything is in perfect focus. Half the value will double the amount of blur"; Max Blur "limits the
amount of blur by setting a maximum blur radius" (Blender manual, Compositing › Defocus Node; Python API
CompositorNodeDefocus: ``f_stop`` "128 (infinity) is perfect focus, half the value doubles the blur radius",
``blur_max`` "maximum CoC radius", 0 no limit). The radius is the thin-lens blur disc (P = 1) halved, in pixels
of the sensor width; F-Stop ≥ 128 gives 0. Without a Z-buffer the node reads its input as a mask: radius =
Z · Z-Scale ("controls maximum blur designated by the color white or input value 1"), clipped at Max Blur.

**nuke** (:func:`nuke_size_px`). ZDefocus with ``math`` set to ``depth``: the depth channel holds distances in
any unit and ``size`` is the defocus "for pixels at infinity" (Foundry, Nuke reference guide, ZDefocus; as its
math is explained by Pixelfudger, "when 'math' is set to 'depth' the 'size' knob represents the amount of
defocus for pixels at 'infinity'"), so for a focus plane C the blur is size · |1 − C/z|, the thin-lens shape
above, clipped at ``maximum``. ``far = 0`` reads 1/z (ScanlineRender's depth: "brighter is closer"), and
``direct`` takes the channel as the blur size itself. The ``depth of field`` knob (a sharp band around the focus
plane) is taken as 0.
"""

from __future__ import annotations

from typing import Any

BLENDER_F_STOP_INFINITY = 128.0
"""Blender's Defocus F-Stop at which "everything is in perfect focus"."""


def physical_coc_mm(depth: Any, *, focus_mm: float, focal_length_mm: float, f_number: float,
                    pupil_magnification: float = 1.0, depth_unit_mm: float = 1.0, out: Any = None) -> Any:
    """Blur-disc diameter on the sensor in mm of each depth (from the entrance pupil, in units of
    ``depth_unit_mm``; ``inf`` allowed), so the image is never rescaled.

    ``focus_mm`` is the focus distance from the entrance pupil, > f/P (the plan checks the scalars and the depth).

    >>> import numpy as np
    >>> c = physical_coc_mm(np.array([2500.0, 5000.0, np.inf]), focus_mm=5000.0, focal_length_mm=50.0,
    ...                     f_number=2.0)
    >>> [round(float(v), 6) for v in c]  # K = 50²/(2·4950): at ∞ the blur of blur_diameter_mm(50, 2, 5050, ∞)
    [0.252525, 0.0, 0.252525]
    """
    import numpy as np

    k = focal_length_mm * focal_length_mm / (f_number * (focus_mm - focal_length_mm / pupil_magnification))
    values = np.asarray(depth)
    kx = k * focus_mm / depth_unit_mm  # K·|1 − x_f/x| = |K·x_f/x − K|: three passes over the image
    result = np.asarray(np.divide(np.float32(kx) if values.dtype == np.float32 else kx, values, out=out))
    result -= np.float32(k) if result.dtype == np.float32 else k
    return np.abs(result, out=result)


def blender_radius_px(depth: Any, *, focus_mm: float, focal_length_mm: float, sensor_width_mm: float,
                      width_px: int, f_stop: float, max_blur_px: float = 0.0, depth_unit_mm: float = 1000.0,
                      out: Any = None) -> Any:
    """The blur radius in pixels Blender's Defocus node gives each Z (scene units, metres by default), as the
    module says; ``focus_mm`` is the camera's focus distance.

    >>> import numpy as np
    >>> r = blender_radius_px(np.array([np.inf, 5.05]), focus_mm=5050.0, focal_length_mm=50.0, sensor_width_mm=36.0,
    ...                       width_px=3600, f_stop=2.0)
    >>> [round(float(v), 6) for v in r]  # the 0.25 mm disc at ∞, halved, at 100 px/mm
    [12.5, 0.0]
    >>> float(blender_radius_px(np.array([1.0]), focus_mm=5000.0, focal_length_mm=50.0, sensor_width_mm=36.0,
    ...                         width_px=3600, f_stop=128.0)[0])
    0.0
    """
    import numpy as np

    depth = np.asarray(depth)
    if f_stop >= BLENDER_F_STOP_INFINITY:
        result = np.zeros_like(depth) if out is None else out
        result[...] = 0.0
        return result
    result = physical_coc_mm(depth, focus_mm=focus_mm, focal_length_mm=focal_length_mm, f_number=f_stop,
                             depth_unit_mm=depth_unit_mm, out=out)
    result *= 0.5 * width_px / sensor_width_mm
    if max_blur_px > 0:
        np.minimum(result, max_blur_px, out=result)
    return result


def blender_mask_radius_px(value: Any, *, z_scale: float, max_blur_px: float = 0.0, out: Any = None) -> Any:
    """Blender's Defocus without a Z-buffer: radius = value · Z-Scale, clipped at Max Blur (0: no limit).

    >>> import numpy as np
    >>> [float(v) for v in blender_mask_radius_px(np.array([0.0, 0.5, 1.0]), z_scale=20.0, max_blur_px=15.0)]
    [0.0, 10.0, 15.0]
    """
    import numpy as np

    result = np.multiply(value, z_scale, out=out)
    if max_blur_px > 0:
        np.minimum(result, max_blur_px, out=result)
    return result


NUKE_MATHS = ("depth", "far=0", "direct")


def nuke_size_px(value: Any, *, math: str, focus_plane: float, size: float, maximum: float, out: Any = None) -> Any:
    """The blur size ZDefocus gives each depth-channel value, for ``math`` depth, far=0 or direct (module notes).

    ``focus_plane`` is in the channel's own terms (a distance for depth, 1/distance for far=0).

    >>> import numpy as np
    >>> [float(v) for v in nuke_size_px(np.array([np.inf, 4.0, 2.0, 1.0]), math="depth", focus_plane=2.0,
    ...                                 size=10.0, maximum=15.0)]
    [10.0, 5.0, 0.0, 10.0]
    >>> [float(v) for v in nuke_size_px(np.array([0.0, 0.25, 0.5]), math="far=0", focus_plane=0.5, size=10.0,
    ...                                 maximum=100.0)]
    [10.0, 5.0, 0.0]
    """
    import numpy as np

    v = np.asarray(value)
    if math == "direct":
        result = np.abs(v, out=out)
    elif math == "far=0":  # the channel holds 1/z: |1 − C/z| = |1 − z_stored/C_stored|
        result = np.divide(v, focus_plane, out=out)
        result -= 1.0
        np.abs(result, out=result)
        result *= size
    else:
        result = np.divide(np.float32(focus_plane) if v.dtype == np.float32 else focus_plane, v, out=out)
        result -= 1.0
        np.abs(result, out=result)
        result *= size
    np.minimum(result, maximum, out=result)
    return result
