"""Progress on long work: a rich bar on standard error, only when standard error is a terminal.

Long work (a ``--batch`` file or an option grid of thousands of rows, a
traced stack plan, ``focus --optimum --criterion`` by a real lens's wavefront,
``exif -r`` over a folder, a lensfun import, a traced ``chart trade`` or
``--model all`` grid) reports its steps to a
:class:`Progress`; the bar is drawn on stderr only when stderr is a terminal
(and ``TERM`` is not ``dumb``), never on a pipe and never on stdout, and it is
updated as the work reports — once per chunk, never per row. It disappears
when the work ends; Ctrl-C during it removes it before the one-line
``camtool: interrupted`` (:func:`camtool.render.terminal.interrupted`).

>>> with progress("rows", total=3) as bar:  # not a terminal here: nothing is drawn
...     bar.advance(3)
>>> bar.done
3.0
"""

from __future__ import annotations

import contextlib
import os
import sys
from typing import IO, Any

_ACTIVE: list[Any] = []
"""The live rich displays, stopped by :func:`stop_all` on Ctrl-C."""


class Progress:
    """Steps of long work; draws a rich bar on ``stream`` when it is a terminal (see the module)."""

    def __init__(self, label: str, total: float | None = None, stream: IO[str] | None = None,
                 unit: str = "") -> None:
        self.label, self.total, self.unit = label, total, unit
        self.stream = stream if stream is not None else sys.stderr
        self.done = 0.0
        self._bar: Any = None
        self._task: Any = None

    def __enter__(self) -> Progress:
        if self.total != 0 and _shows(self.stream):  # a total of 0: too little work to show
            from rich.console import Console
            from rich.progress import BarColumn, MofNCompleteColumn, TextColumn, TimeElapsedColumn
            from rich.progress import Progress as Bar

            console = Console(file=self.stream, highlight=False, markup=False, emoji=False,
                              color_system=None if os.environ.get("NO_COLOR") else "auto")
            columns = [TextColumn("{task.description}"), BarColumn(), MofNCompleteColumn(), TimeElapsedColumn()]
            # drawn when the work reports (no refresh thread): nothing can redraw it after Ctrl-C clears it
            self._bar = Bar(*columns, console=console, transient=True, redirect_stdout=False,
                            redirect_stderr=False, auto_refresh=False)
            self._task = self._bar.add_task(self.label, total=self.total)
            _ACTIVE.append(self._bar)  # first: Ctrl-C during the first drawing still clears it
            try:
                self._bar.start()
            except BaseException:
                stop_all()
                raise
        return self

    def advance(self, steps: float = 1) -> None:
        """``steps`` more done (a chunk's rows, a file, a frame)."""
        self.done += steps
        if self._bar is not None:
            self._bar.update(self._task, completed=self.done, refresh=True)

    def grow(self, total: float) -> None:
        """The work turned out to have ``total`` steps (e.g. a grid's size once known)."""
        self.total = total
        if self._bar is not None:
            self._bar.update(self._task, total=total, refresh=True)

    def __exit__(self, kind: object, *exc: object) -> None:
        if self._bar is not None and kind is None:
            self._bar.stop()
            if self._bar in _ACTIVE:
                _ACTIVE.remove(self._bar)
        elif self._bar is not None:  # an error or Ctrl-C: taken off by stop_all, or by the error's own line
            stop_all()
        self._bar = None


def progress(label: str, total: float | None = None, stream: IO[str] | None = None) -> Progress:
    """A :class:`Progress` for ``label`` over ``total`` steps (None: not known yet)."""
    return Progress(label, total, stream)


def _shows(stream: IO[str]) -> bool:
    if os.environ.get("TERM") == "dumb":
        return False
    try:
        return stream.isatty()
    except (AttributeError, ValueError, OSError):
        return False


def stop_all() -> None:
    """Take a bar off the screen at once (Ctrl-C): clear its line and show the cursor again.

    Written as escape codes, not through rich, which may hold its display's lock when the signal lands.
    """
    if _ACTIVE:
        _ACTIVE.clear()
        with contextlib.suppress(OSError, ValueError):
            sys.stderr.write("\r\x1b[2K\x1b[?25h")
