"""A rotary shutter: the exposure time of a shutter angle at a frame rate, and the reverse.

A motion-picture shutter is a disc open over ``angle`` degrees of the turn it
makes each frame, so each frame is exposed for angle/360 of the frame interval:
t = angle / (360 · fps) (Wikipedia, "Shutter speed", cinematographic shutter
formula E = F·360°/S, after Blain Brown, *Cinematography: Theory and Practice*,
2002, p. 125: 180° at 24 fps is 1/48 s; 1/50 s is 172.8° and 1/60 s is 144°).
"""

from __future__ import annotations

from typing import Any

from camtool.core.errors import require
from camtool.core.ranges import FRAME_RATE_FPS, SHUTTER_ANGLE_DEG, describe


def _check_fps(fps: Any) -> None:
    require("fps", fps, (fps >= FRAME_RATE_FPS[0]) & (fps <= FRAME_RATE_FPS[1]), describe(FRAME_RATE_FPS, "fps"))


def shutter_time_s(shutter_angle_deg: Any, fps: Any) -> Any:
    """Exposure time in s of a shutter open ``shutter_angle_deg`` at ``fps`` frames per second.

    >>> shutter_time_s(180.0, 24.0) == 1 / 48
    True
    >>> round(1 / shutter_time_s(172.8, 24.0), 9), round(1 / shutter_time_s(144.0, 24.0), 9)  # Wikipedia
    (50.0, 60.0)
    """
    require("shutter_angle", shutter_angle_deg,
            (shutter_angle_deg >= SHUTTER_ANGLE_DEG[0]) & (shutter_angle_deg <= SHUTTER_ANGLE_DEG[1]),
            describe(SHUTTER_ANGLE_DEG, "°"))
    _check_fps(fps)
    return shutter_angle_deg / (360.0 * fps)


def shutter_angle_deg(shutter_s: Any, fps: Any) -> Any:
    """The shutter angle in degrees that exposes each frame for ``shutter_s`` at ``fps``: 360 · fps · t.

    Above 360° the time is longer than a frame lasts: no shutter angle gives it.

    >>> shutter_angle_deg(1 / 48, 24.0)
    180.0
    >>> shutter_angle_deg(1 / 50, 25.0)
    180.0
    """
    _check_fps(fps)
    require("shutter_s", shutter_s, shutter_s > 0, "> 0 s")
    return 360.0 * fps * shutter_s
