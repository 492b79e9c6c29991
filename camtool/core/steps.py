"""Steps of long work, reported to whoever listens: the hook a progress bar hangs on.

A formula that loops over slow steps (the frames of a traced stack plan, the
rungs of a timed trade chart) calls :func:`step` after each; the command line
listens with :func:`reporting` and draws a bar; nobody listening costs a
context-variable read. Nothing here draws or prints.

>>> seen = []
>>> with reporting(seen.append):
...     step(); step(2)
>>> seen
[1, 2]
>>> step()  # no one listening: nothing happens
"""

from __future__ import annotations

import contextlib
from collections.abc import Callable, Iterator
from contextvars import ContextVar

_HOOK: ContextVar[Callable[[int], None] | None] = ContextVar("camtool_steps", default=None)


@contextlib.contextmanager
def reporting(hook: Callable[[int], None]) -> Iterator[None]:
    """Within the block, every :func:`step` calls ``hook(count)``."""
    token = _HOOK.set(hook)
    try:
        yield
    finally:
        _HOOK.reset(token)


def step(count: int = 1) -> None:
    """``count`` more steps of long work are done."""
    hook = _HOOK.get()
    if hook is not None:
        hook(count)
