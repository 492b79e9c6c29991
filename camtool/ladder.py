"""The model ladder: one dispatcher over the depth-of-field models, cheapest first.

Every model takes (f, N, c, focus distance, distance plane) in mm and returns
:class:`camtool.limits.DofLimits`. ``auto`` picks the model the scene needs.
"""

from __future__ import annotations

from collections.abc import Callable
from typing import Any, NamedTuple

from camtool.dof import approx_dof, thin_dof
from camtool.limits import DofLimits
from camtool.thinlens import focus_geometry


def _approx(f: Any, n: Any, c: Any, s: Any, distance_from: str) -> DofLimits:
    return approx_dof(f, n, c, s)


MODELS: dict[str, Callable[..., DofLimits]] = {"approx": _approx, "thin": thin_dof}
CHOICES = (*MODELS, "auto")


class ModelResult(NamedTuple):
    """The limits, the name of the model that produced them, and its estimated relative error (or None)."""

    limits: DofLimits
    model: str
    error_estimate: Any


def depth_of_field(
    model: str, focal_length_mm: Any, f_number: Any, coc_mm: Any, distance_mm: Any, distance_from: str = "sensor"
) -> ModelResult:
    """Depth of field by the named model (``auto``: the exact thin lens, the most complete rung without lens data).

    Examples
    --------
    >>> depth_of_field("auto", 50.0, 8.0, 0.03, 3000.0).model
    'thin'
    >>> depth_of_field("bogus", 50.0, 8.0, 0.03, 3000.0)
    Traceback (most recent call last):
    ...
    ValueError: unknown model 'bogus'; choose one of approx, thin, auto
    """
    if model not in CHOICES:
        raise ValueError(f"unknown model {model!r}; choose one of {', '.join(CHOICES)}")
    name = "thin" if model == "auto" else model
    if name == "approx":
        # The approximation has no notion of the closest focus; the scene still must be reachable.
        focus_geometry(focal_length_mm, distance_mm, distance_from)
    limits = MODELS[name](focal_length_mm, f_number, coc_mm, distance_mm, distance_from)
    return ModelResult(limits, name, None)
