"""The plane a focus distance is measured from: one type, one check, one error text.

``sensor`` is the focal-plane mark (lens scales and specifications),
``lens`` the front principal plane (the thin lens itself) and
``entrance_pupil`` the lens's entrance pupil (for the thick, paraxial and
real-ray models, which know where it is). docs/design.md §4.
"""

from __future__ import annotations

from typing import Literal

__all__ = ["FOCUS_PLANES", "PLANES", "DistancePlane", "check_plane"]

DistancePlane = Literal["sensor", "lens", "entrance_pupil"]
"""A plane distances are measured from."""

PLANES: tuple[DistancePlane, ...] = ("sensor", "lens", "entrance_pupil")
"""Every plane; the models that know the lens's pupils accept all three."""

FOCUS_PLANES: tuple[DistancePlane, ...] = ("sensor", "lens")
"""The planes a thin lens knows, and the choices of ``--distance-from``."""


def check_plane(distance_from: str, allowed: tuple[str, ...] = PLANES) -> DistancePlane:
    """Return ``distance_from`` if it is one of ``allowed``, else raise ValueError with the one message.

    Examples
    --------
    >>> check_plane("lens")
    'lens'
    >>> check_plane("entrance_pupil", FOCUS_PLANES)
    Traceback (most recent call last):
    ...
    ValueError: distance_from must be one of sensor, lens, not 'entrance_pupil'
    """
    if distance_from not in allowed:
        raise ValueError(f"distance_from must be one of {', '.join(allowed)}, not {distance_from!r}")
    return distance_from  # type: ignore[return-value]
