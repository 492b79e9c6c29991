"""Text from outside the process, made safe to print: one escape for every control character.

A string read from a file (an EXIF tag, a preset name, a batch cell, a file
name) may hold terminal escape sequences, line breaks or bidirectional
controls. Every string cell of every output format and every error line
passes through :func:`printable`, so such a string cannot move the cursor,
clear the screen, reorder a line or split one ``--field`` row into two.
"""

from __future__ import annotations

import os  # noqa: F401 - used by the doctest

_NAMED = {"\n": "\\n", "\r": "\\r", "\t": "\\t"}
# line and paragraph separators and the bidirectional controls: invisible, and they reorder or break lines
_INVISIBLE = frozenset("\u2028\u2029\u200e\u200f\u202a\u202b\u202c\u202d\u202e\u2066\u2067\u2068\u2069")


def _escape(char: str) -> str:
    code = ord(char)
    if char in _NAMED:
        return _NAMED[char]
    if code < 0x20 or 0x7F <= code <= 0x9F:
        return f"\\x{code:02x}"
    if 0xDC80 <= code <= 0xDCFF:  # a byte that is not UTF-8, as os.fsdecode and surrogateescape carry it
        return f"\\x{code - 0xDC00:02x}"
    if 0xD800 <= code <= 0xDFFF or char in _INVISIBLE:
        return f"\\u{code:04x}"
    return char


def printable(text: str) -> str:
    r"""``text`` with every control character in one visible form: ``\n``, ``\r``, ``\t``, else ``\xNN``.

    Escaped: C0 (U+0000 to U+001F, ESC among them), DEL, C1 (U+0080 to
    U+009F); a byte of a file name that is not UTF-8 (carried as a lone
    surrogate by :func:`os.fsdecode`) as ``\xNN`` of that byte; other lone
    surrogates, the line and paragraph separators and the bidirectional
    controls as ``\uNNNN``. Everything else, backslashes included, is kept.

    Examples
    --------
    >>> printable("\x1b[2JCanon")
    '\\x1b[2JCanon'
    >>> printable("EF\n50mm\tf/1.8\x9b")
    'EF\\n50mm\\tf/1.8\\x9b'
    >>> printable(os.fsdecode(b"caf\xe9.jpg")), printable("café")
    ('caf\\xe9.jpg', 'café')
    """
    if text.isprintable():
        return text
    return "".join(_escape(char) if not char.isprintable() or char in _INVISIBLE else char for char in text)
