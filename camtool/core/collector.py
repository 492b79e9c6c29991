"""The cyclic garbage collector around start-up and imports (docs/design.md §7).

Importing a module makes objects that live as long as the process (functions,
classes, constants); the cyclic collector walks them again and again and finds
no garbage. A command starts by importing click and camtool's modules: the
process's entry point (:func:`camtool.__main__.main`) pauses the collector
before the first import, :func:`camtool.cli.main` keeps it paused while the
command is found and its options read (:func:`pause`), and :func:`resume`, called
as a command's work begins, freezes what exists (:func:`gc.freeze`: never walked
again) and turns the collector back on, so the work's own cycles (a skipped
batch row's error and its frames) are collected. A module imported during the
work (rich for a table, say) is imported inside :func:`importing`: paused, then
frozen when the process's entry point owns the collector.

A caller in its own process (the API, a test calling :func:`camtool.cli.main`)
gets its collector back as it was, nothing frozen.
"""

from __future__ import annotations

import contextlib
import gc
from collections.abc import Iterator

__all__ = ["importing", "pause", "resume"]

_paused = False
"""Whether :func:`pause` turned the collector off (and :func:`resume` turns it back on)."""
_owned = False
"""Whether the process's entry point paused it: objects made until then are frozen."""


def pause(collecting: bool | None = None, *, owned: bool = False) -> None:
    """Turn the collector off until :func:`resume`; ``collecting``: whether it was on before the caller turned it off
    (None: now); ``owned``: the caller is the process's entry point."""
    global _paused, _owned
    _paused = gc.isenabled() if collecting is None else collecting
    _owned = owned
    gc.disable()


def resume() -> None:
    """Turn the collector back on if :func:`pause` turned it off, first freezing what exists when the process's entry
    point paused it."""
    global _paused
    if _paused:
        _paused = False
        if _owned:
            gc.freeze()
        gc.enable()


@contextlib.contextmanager
def importing() -> Iterator[None]:
    """Import modules inside: the collector paused, what they made frozen afterwards when the process's entry point
    owns the collector (nothing changes while :func:`pause` holds it off)."""
    if _paused or not gc.isenabled():
        yield
        return
    gc.disable()
    try:
        yield
    finally:
        if _owned:
            gc.freeze()
        gc.enable()
