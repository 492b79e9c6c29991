"""Cinema decisions: the exposure time of a shutter angle, and the shutter angle of a time.

``camtool exposure --shutter-angle 180 --fps 24`` takes the time a rotary
shutter gives (:func:`camtool.exposure.shutter.shutter_time_s`); with ``--fps``
alone every row also shows the shutter angle of its time to set.
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import Any

from camtool.core.errors import InputError


def shutter_times(*, shutter_angle_deg: Sequence[float] = (), fps: float | None = None,
                  shutter_s: Sequence[float] = ()) -> list[float]:
    """The exposure times to use: ``shutter_s`` as given, or each shutter angle at ``fps`` (t = angle/(360·fps)).

    >>> shutter_times(shutter_angle_deg=[180.0, 90.0], fps=24.0) == [1 / 48, 1 / 96]
    True
    >>> shutter_times(shutter_s=[0.01])
    [0.01]
    """
    if shutter_angle_deg and shutter_s:
        raise InputError("shutter_angle", "give {shutter_angle} or {shutter_s}, not both", usage=True)
    if not shutter_angle_deg:
        return list(shutter_s)
    if fps is None:
        raise InputError("shutter_angle", "{shutter_angle} needs the frame rate, {fps}", usage=True)
    from camtool.exposure.shutter import shutter_time_s

    return [shutter_time_s(float(a), fps) for a in shutter_angle_deg]


def shutter_angles(shutter_s: Any, *, fps: float) -> Any:
    """The shutter angle in degrees of each time at ``fps`` (360·fps·t); above 360° no shutter gives the time.

    >>> shutter_angles(1 / 48, fps=24.0)
    180.0
    """
    from camtool.exposure.shutter import shutter_angle_deg

    if isinstance(shutter_s, (list, tuple)):
        return [shutter_angle_deg(t, fps) for t in shutter_s]
    return shutter_angle_deg(shutter_s, fps)
