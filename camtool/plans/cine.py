"""Cinema decisions: the exposure time of a shutter angle, and the shutter angle of a time.

``camtool exposure --shutter-angle 180 --fps 24`` takes the time a rotary
shutter gives (:func:`camtool.exposure.shutter.shutter_time_s`); with ``--fps``
alone every row also shows the shutter angle of its time to set.
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import Any

from camtool.core.errors import InputError
from camtool.core.record import NamedTuple


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


class Anamorphic(NamedTuple):
    """The horizontal depth of field of an anamorphic lens (the vertical one is the spherical answer as marked)."""

    near_horizontal_mm: Any
    far_horizontal_mm: Any
    hyperfocal_horizontal_mm: Any
    horizontal_focal_length_mm: Any


def desqueezed_width_mm(sensor_width_mm: float, squeeze: float | None) -> float:
    """The width the horizontal angle of an anamorphic lens covers: the sensor width × squeeze (docs/cine.md).

    >>> desqueezed_width_mm(24.0, 2.0), desqueezed_width_mm(24.0, None)
    (48.0, 24.0)
    """
    if squeeze is None:
        return sensor_width_mm
    from camtool.core.errors import require
    from camtool.core.ranges import SQUEEZE, describe

    require("squeeze", squeeze, SQUEEZE[0] <= squeeze <= SQUEEZE[1], describe(SQUEEZE))
    return sensor_width_mm * squeeze


def anamorphic_dof(*, focal_length_mm: Any, f_number: Any, coc_mm: Any, distance_mm: Any, squeeze: float,
                   distance_from: str = "sensor") -> Anamorphic:
    """The depth of field for horizontal detail of an anamorphic lens of ``squeeze``: the thin-lens limits of its
    horizontal focal length f/squeeze at the same f-number, CoC and focus distance.

    This is the convention of Cooke's anamorphic notes (J. Maxwell, "The aesthetic role of depth of field in
    anamorphic cinematography"): the vertical depth of field is that of the marked focal length (the spherical
    answer, the shallower one), the horizontal that of the horizontal focal length; a 2× 100 mm lens behaves as a
    100 mm vertically and a 50 mm horizontally, so about four times the depth horizontally.

    >>> a = anamorphic_dof(focal_length_mm=100.0, f_number=2.8, coc_mm=0.025, distance_mm=3000.0, squeeze=2.0,
    ...                    distance_from="lens")
    >>> round(a.horizontal_focal_length_mm, 3), round(a.hyperfocal_horizontal_mm, 3)  # (f/2)²/(Nc) + f/2
    (50.0, 35764.286)
    """
    from camtool.dof.closed import thin_dof

    desqueezed_width_mm(1.0, squeeze)  # the bound
    fh = focal_length_mm / squeeze
    limits = thin_dof(fh, f_number, coc_mm, distance_mm, distance_from)
    return Anamorphic(limits.near_mm, limits.far_mm, limits.hyperfocal_mm, fh)


ANAMORPHIC_KEYS = ["squeeze", "horizontal_focal_length_mm", "near_horizontal_mm", "far_horizontal_mm",
                   "hyperfocal_horizontal_mm"]
"""The keys :func:`with_anamorphic` adds to each row of a depth-of-field table."""


def with_anamorphic(rows: Any, *, squeeze: float, distance_from: str = "sensor") -> Any:
    """Each row of a depth-of-field table (keys ``focal_length_mm``, ``f_number``, ``coc_mm``, ``distance_mm``) with
    the horizontal limits of :func:`anamorphic_dof` added (None in a row that has no answer)."""
    for row in rows:
        values: list[Any] = [squeeze, None, None, None, None]
        if row.get("near_mm") is not None and row.get("distance_mm") is not None:
            found = anamorphic_dof(focal_length_mm=float(row["focal_length_mm"]), f_number=float(row["f_number"]),
                                   coc_mm=float(row["coc_mm"]), distance_mm=float(row["distance_mm"]),
                                   squeeze=squeeze, distance_from=distance_from)
            values = [squeeze, found.horizontal_focal_length_mm, found.near_horizontal_mm, found.far_horizontal_mm,
                      found.hyperfocal_horizontal_mm]
        row.update(zip(ANAMORPHIC_KEYS, values))
    return rows


class RotaryShutter(NamedTuple):
    """A rotary shutter's exposure time (s), its angle (degrees) and the frame rate (frames per second)."""

    shutter_s: Any
    shutter_angle_deg: Any
    fps: Any


def rotary_shutter(*, fps: Any, shutter_angle_deg: Any = None, shutter_s: Any = None) -> RotaryShutter:
    """The time of a shutter angle at ``fps``, or the angle of a time: give one of ``shutter_angle_deg`` and
    ``shutter_s``.

    >>> rotary_shutter(fps=24.0, shutter_angle_deg=180.0).shutter_s == 1 / 48
    True
    >>> rotary_shutter(fps=24.0, shutter_s=1 / 50).shutter_angle_deg   # 172.8° (Wikipedia, "Shutter speed")
    172.8
    """
    from camtool.exposure.shutter import shutter_angle_deg as angle_of
    from camtool.exposure.shutter import shutter_time_s

    if (shutter_angle_deg is None) == (shutter_s is None):
        raise InputError("shutter_angle_deg", "give one of {shutter_angle_deg} and {shutter_s}", usage=True)
    if shutter_angle_deg is not None:
        return RotaryShutter(shutter_time_s(shutter_angle_deg, fps), shutter_angle_deg, fps)
    return RotaryShutter(shutter_s, angle_of(shutter_s, fps), fps)
