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

def __getattr__(name: str) -> Any:
    # The public names are written once, as camtool.api.__all__; they (and __all__ itself) are loaded on first
    # use, so a command that never touches the API never imports it.
    if (name.startswith("_") and name != "__all__") or name == "api":
        raise AttributeError(f"module 'camtool' has no attribute {name!r}")
    api = _api()
    if name == "__all__":
        return list(api.__all__)
    if name in api.__all__:
        return getattr(api, name)
    raise AttributeError(f"module 'camtool' has no attribute {name!r}")


def __dir__() -> list[str]:
    return sorted([*globals(), *_api().__all__])


def _api() -> Any:
    import importlib

    return importlib.import_module("camtool.api")
