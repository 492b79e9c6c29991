"""The standard streams as camtool writes to them: ASCII stand-ins, a closed output, a reader that went away.

A terminal or pipe that only takes ASCII (``PYTHONIOENCODING=ascii``,
``LANG=C``) gets ASCII stand-ins for camtool's few non-ASCII characters
instead of a traceback; standard output that is closed (``camtool ... >&-``)
is an error to write to, not a traceback; a reader that goes away
(``camtool ... | head -1``) is a normal end, exit 0, while output that cannot
be written (a full disk) is one line on stderr and exit 1; Ctrl-C is one
line and exit 130 wherever it lands.
"""

from __future__ import annotations

import errno
import io
import os
import sys

ASCII = {"∞": "inf", "·": "-", "━": "=", "┃": "|", "▶": ">", "─": "-", "≤": "<=", "≥": ">=", "±": "+/-",
         "×": "x", "°": "deg", "µ": "u", "–": "-", "—": "-", "…": "...", "²": "^2", "√": "sqrt", "≈": "~",
         "→": "->", "⁰": "^0", "¹": "^1", "³": "^3", "⁶": "^6", "⁷": "^7"}
"""What a terminal or pipe that only takes ASCII gets instead of camtool's few non-ASCII characters."""


def _ascii_fallback(error: UnicodeError) -> tuple[str, int]:
    assert isinstance(error, UnicodeEncodeError)
    text = error.object[error.start:error.end]
    return "".join(ASCII.get(char, "?") for char in text), error.end


def degrade_to_ascii() -> None:
    """Give an ASCII-only stdout/stderr ASCII stand-ins (:data:`ASCII`), not a traceback."""
    for stream in (sys.stdout, sys.stderr):
        encoding = getattr(stream, "encoding", None) or "utf-8"
        try:
            "∞━·".encode(encoding)
        except (UnicodeEncodeError, LookupError):
            import codecs

            codecs.register_error("camtool-ascii", _ascii_fallback)
            reconfigure = getattr(stream, "reconfigure", None)
            if reconfigure is not None:
                reconfigure(errors="camtool-ascii")


class ClosedOutput(io.StringIO):
    """Standard output when it is closed (``camtool ... >&-``): writing to it is an error, not a traceback."""

    def write(self, text: str) -> int:
        if text:
            raise OSError(errno.EBADF, "standard output is closed")
        return 0


def discard_stdout() -> None:
    """Send the rest of standard output nowhere, so that the interpreter's final flush does not raise again."""
    if isinstance(sys.stdout, ClosedOutput):
        return
    try:
        devnull = os.open(os.devnull, os.O_WRONLY)
        os.dup2(devnull, sys.stdout.fileno())
    except (OSError, ValueError, AttributeError):
        sys.stdout = None


def write_failure(error: OSError) -> tuple[int, str | None]:
    """(exit status, the line for stderr or None) after a write error: 0 and no line for a reader that went away."""
    discard_stdout()
    if isinstance(error, BrokenPipeError) or error.errno == errno.EPIPE:
        return 0, None
    if error.filename is None:
        reason = error.strerror or str(error)
        return 1, f"Error: cannot write the output: {reason[:1].lower() + reason[1:]}"
    return 1, f"Error: {error.filename}: {error.strerror or error}"


def interrupted() -> None:
    """Ctrl-C: one line and exit 130 (128 + SIGINT), as shells expect, wherever it landed."""
    discard_stdout()
    from camtool.render.progress import stop_all

    stop_all()
    try:
        sys.stderr.write("camtool: interrupted\n")
        sys.stderr.flush()
    except (OSError, ValueError):
        pass
    os._exit(130)
