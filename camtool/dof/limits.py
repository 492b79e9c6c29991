"""The result every depth-of-field model returns."""

from __future__ import annotations

from typing import Any

from camtool.core.record import NamedTuple


class DofLimits(NamedTuple):
    """Near and far limits of acceptable sharpness around a focus distance.

    All distances are in millimetres and measured from the same reference
    plane as the focus distance that was given (sensor plane or lens); depths
    (``front_mm``, ``rear_mm``, ``total_mm``) are the same in every plane.
    Scalars for scalar input, arrays (broadcast together) for array input.

    ``far_mm`` and ``rear_mm`` and ``total_mm`` are ``inf`` when everything
    beyond the focus is acceptably sharp; ``hyperfocal_mm`` is the focus
    distance (in the same plane) at which that starts.
    """

    near_mm: Any
    far_mm: Any
    front_mm: Any
    rear_mm: Any
    total_mm: Any
    hyperfocal_mm: Any
    magnification: Any
