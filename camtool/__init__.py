"""camtool: depth of field, field of view, focusing and exposure for photographers.

The public calculations are importable from here (``camtool.depth_of_field``,
``camtool.hyperfocal_distance``, ...; the list is ``camtool.__all__``) and are
documented in :mod:`camtool.api`. They work in millimetres, degrees and
seconds and accept plain floats (computed with :mod:`math`, no numpy import)
or numpy arrays (broadcast together). They are loaded on first use, so
``import camtool`` stays as cheap as the command line needs it to be.
"""

from __future__ import annotations

from typing import Any

__version__ = "0.1.0"

__all__ = [
    "Composition",
    "DepthOfField",
    "DofLimits",
    "ExposurePlan",
    "FieldOfView",
    "FocusGeometry",
    "FocusPlan",
    "LensData",
    "circle_of_confusion",
    "composition",
    "depth_of_field",
    "field_of_view",
    "focus_for_limits",
    "focus_for_magnification",
    "hyperfocal_distance",
    "plan_exposure",
]


def __getattr__(name: str) -> Any:
    if name in __all__:
        from camtool import api

        return getattr(api, name)
    raise AttributeError(f"module 'camtool' has no attribute {name!r}")


def __dir__() -> list[str]:
    return sorted([*globals(), *__all__])
