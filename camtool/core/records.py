"""Rows of a text file of records: CSV with a header row, or JSON lines, read in bounded memory.

The file layer of ``--batch``, beside the guarded reader of whole files
(:mod:`camtool.core.files`). :func:`open_source` opens standard input
(``-``), a file or a FIFO (opened without waiting for a writer; a device or
a directory is refused) and tells the encoding from the first bytes: UTF-8
with or without a byte-order mark, or UTF-16 with one. :func:`records`
reads it a line at a time, no line longer than :data:`LINE_LIMIT`, and
yields one record per row: a list of cells (CSV, the header first) or a
dict (JSON lines, told by a first non-blank ``{``).

A file that cannot be read is a :class:`~camtool.core.files.FileProblem`
naming it; a bad row is not an error here but a problem in words, yielded
in the row's place, so the caller decides whether it stops the run.

>>> import io
>>> for row in records(io.StringIO("f,N\\n50,8\\n50,8,3\\n"), "scenes.csv"):
...     print(row)
(0, ['f', 'N'], None)
(1, ['50', '8'], None)
(2, None, '3 cells, more than the 2 header columns')
"""

from __future__ import annotations

import codecs
import csv
import io
import json
import os
import stat
import sys
from collections.abc import Iterator, Sequence
from itertools import repeat
from typing import IO, Any

from camtool.core.files import FileProblem
from camtool.core.record import NamedTuple

CELL_LIMIT = 128 * 1024
"""Longest cell, in characters (the csv module's limit); a longer one is a bad row."""

LINE_LIMIT = 1024 * 1024
"""Longest line read whole; the rest of a longer one is dropped and the row is bad."""

DROP_LIMIT = 64 * 1024 * 1024
"""Longest over-long line skipped to reach the next row; a longer one ends the read (a :class:`FileProblem`)."""

STDIN = "standard input"
"""The name problems give standard input (``-``)."""

Record = tuple[int, Any, "str | None"]
"""(row number, cells, None) for a row, or (row number, None, problem) for a bad one; row 0 is a CSV header."""


def open_source(source: str) -> tuple[IO[str], str]:
    """The text stream of ``source`` (``-`` is standard input) and the name its problems give it.

    UTF-8 with or without a byte-order mark, or UTF-16 with one; a FIFO
    reads like a pipe; a directory, a device, a socket or an unreadable file
    is a :class:`FileProblem`.
    """
    if source == "-":
        binary: Any = sys.stdin.buffer
        name = STDIN
    else:
        name = source
        try:
            mode = os.stat(source).st_mode
        except OSError as error:
            raise FileProblem(source, f"cannot read it ({error.strerror})") from None
        if stat.S_ISDIR(mode):
            raise FileProblem(source, "is a directory, not a file")
        if not (stat.S_ISREG(mode) or stat.S_ISFIFO(mode)):  # a device (/dev/zero never ends), a socket
            raise FileProblem(source, "is a device or socket, not a file (a file, a pipe or - are read)")
        try:
            binary = _open_nonblocking(source)
        except OSError as error:
            raise FileProblem(source, f"cannot read it ({error.strerror})") from None
    if not hasattr(binary, "peek"):
        binary = io.BufferedReader(binary)
    try:
        head = binary.peek(4)[:4]
    except OSError as error:
        raise FileProblem(name, f"cannot read it ({error.strerror})") from None
    if head.startswith(codecs.BOM_UTF8):
        encoding = "utf-8-sig"
    elif head.startswith((codecs.BOM_UTF16_LE, codecs.BOM_UTF16_BE)):
        encoding = "utf-16"
    else:
        encoding = "utf-8"
    return io.TextIOWrapper(binary, encoding=encoding, newline=""), name


def _open_nonblocking(source: str) -> IO[bytes]:
    """``source`` opened for reading without waiting for a writer: a FIFO nobody writes to reads as empty.

    Opened non-blocking (a FIFO with no writer would block ``open`` for ever), then set to block again, so
    a pipe with a writer (``--batch <(make-scenes)``) is read as it comes and one without ends at once.
    """
    import fcntl

    fd = os.open(source, os.O_RDONLY | os.O_NONBLOCK | getattr(os, "O_CLOEXEC", 0))
    try:
        fcntl.fcntl(fd, fcntl.F_SETFL, fcntl.fcntl(fd, fcntl.F_GETFL) & ~os.O_NONBLOCK)
        return os.fdopen(fd, "rb")
    except BaseException:
        os.close(fd)
        raise


def lines(source: IO[str] | _Prefixed, name: str) -> Iterator[str]:
    """The lines of ``source``, none longer than :data:`LINE_LIMIT` (memory stays bounded).

    An over-long line is cut, its rest dropped, and ends in a newline; text
    that is not in the stream's encoding, a read error, or a "line" longer
    than :data:`DROP_LIMIT` is a :class:`FileProblem` naming ``name``.
    """
    while True:
        try:
            line = source.readline(LINE_LIMIT)
        except UnicodeDecodeError as error:
            raise _not_utf8(name, error) from None
        except OSError as error:  # e.g. standard input redirected from a directory
            raise FileProblem(name, f"cannot read it ({error.strerror or error})") from None
        if not line:
            return
        if len(line) >= LINE_LIMIT and not line.endswith("\n"):
            dropped = 0
            while True:  # drop the rest of the over-long line; what is left fails as a too-long cell
                try:
                    rest = source.readline(LINE_LIMIT)
                except UnicodeDecodeError as error:
                    raise _not_utf8(name, error) from None
                dropped += len(rest)
                if not rest or rest.endswith("\n"):
                    break
                if dropped > DROP_LIMIT:  # a stream with no line ends at all (standard input from /dev/zero)
                    raise FileProblem(name, f"a line longer than {DROP_LIMIT // 2**20} MiB; is it a text file of rows?")
            line += "\n"
        yield line


def _not_utf8(name: str, error: UnicodeDecodeError) -> FileProblem:
    return FileProblem(name, f"not UTF-8 text ({error.reason}, byte 0x{error.object[error.start]:02x}); "
                             "save it as UTF-8 (in Excel: CSV UTF-8)")


def records(source: IO[str], name: str) -> Iterator[Record]:
    """One :data:`Record` per row of ``source``: CSV rows are lists of cells, after the header as row 0; JSON lines are dicts.

    Blank lines are passed over. A row that is not valid CSV or JSON, holds
    more cells than the header, or a JSON value that is not an object is
    yielded as its problem in words; a file that is unreadable, UTF-16
    without a byte-order mark, or has a bad header row is a
    :class:`FileProblem`.
    """
    rows = lines(source, name)
    first = _first_line(rows, name)
    if not first:
        return
    if first.lstrip().startswith("{"):
        yield from _json_rows(_chain(first, rows))
    else:
        reader = csv.reader(_chain(first, rows))
        try:
            header = next(reader)
        except csv.Error as error:
            raise FileProblem(name, f"the header row is {csv_message(error)}") from None
        yield 0, header, None
        yield from _csv_rows(reader, len(header), 0)


def _json_rows(lines: Iterator[str]) -> Iterator[Record]:
    """The records of JSON lines, numbered from 1 (blank lines passed over)."""
    number = 0
    for line in lines:
        if not line.strip():
            continue
        number += 1
        try:
            record = json.loads(line)
        except json.JSONDecodeError as error:
            yield number, None, f"not valid JSON ({error.msg})"
            continue
        if not isinstance(record, dict):
            yield number, None, "expected a JSON object"
            continue
        yield number, record, None


def _csv_rows(reader: Iterator[list[str]], width: int, number: int) -> Iterator[Record]:
    """The records of CSV rows after the header (``width`` columns), numbered on from ``number``."""
    while True:
        try:
            cells = next(reader)
        except StopIteration:
            return
        except csv.Error as error:
            number += 1
            yield number, None, csv_message(error)
            continue
        if not cells:
            continue
        number += 1
        if len(cells) > width:
            yield number, None, f"{len(cells)} cells, more than the {width} header columns"
            continue
        yield number, cells, None


def csv_message(error: csv.Error) -> str:
    """The problem of a row the csv module refused, in words (a too-long cell names the limit)."""
    text = str(error)
    if "field limit" in text:
        return f"a cell longer than {CELL_LIMIT // 1024} KiB"
    return f"not valid CSV ({text})"


def _first_line(rows: Iterator[str], name: str) -> str:
    """The first line of ``rows`` that is not blank ('' for none); one holding a NUL is UTF-16 without a BOM."""
    first = next((line for line in rows if line.strip()), "")
    if "\x00" in first:
        raise FileProblem(name, "looks like UTF-16 text without a byte-order mark; save it as UTF-8 (in Excel: CSV UTF-8)")
    return first


def _chain(first: str, rest: Iterator[str]) -> Iterator[str]:
    yield first
    yield from rest


BLOCK = 1 << 17
"""Characters :func:`chunks` reads at a time (cut at the block's last line end)."""


class Chunk(NamedTuple):
    """Rows of a file of records, at most a chunk's worth.

    ``numbers`` are the rows' numbers (1 = the first data row). Either
    ``rows`` holds each row's record (a list of cells, a dict, or None for a
    bad row, whose problem is in ``problems``), or, for plain CSV rows that
    are all good and all as wide as the header, ``columns`` holds the cells a
    column at a time (in header order) and ``problems`` is None.
    """

    header: list[str] | None
    numbers: Sequence[int]
    rows: list[Any] | None
    columns: list[Sequence[str]] | None
    problems: list[str | None] | None


def chunks(source: IO[str], name: str, size: int, stop: bool = False) -> Iterator[Chunk]:
    """The records of ``source`` (as :func:`records` reads them) in chunks of at most ``size`` rows.

    Plain CSV (no quotes, no carriage returns, every line as wide as the
    header) is split a block at a time into columns, without a row object
    per line; any other block is read row by row, with the same records and
    problems as :func:`records`. With ``stop``, the chunk holding the first
    bad row is the last.

    >>> import io
    >>> [c.columns for c in chunks(io.StringIO("f,N\\n50,8\\n35,2\\n"), "scenes.csv", 10)]
    [[['50', '35'], ['8', '2']]]
    """
    rows = lines(source, name)
    first = _first_line(rows, name)
    if not first:
        return
    if first.lstrip().startswith("{"):
        yield from _gather(_json_rows(_chain(first, rows)), None, size, stop)
        return
    reader = csv.reader(_chain(first, rows) if '"' in first or "\r" in first else [first])
    try:
        header = next(reader)
    except csv.Error as error:
        raise FileProblem(name, f"the header row is {csv_message(error)}") from None
    if '"' in first or "\r" in first:
        yield from _gather(_csv_rows(reader, len(header), 0), header, size, stop)
        return
    width, number, pending = len(header), 0, ""
    while True:
        try:
            text = source.read(BLOCK)
        except UnicodeDecodeError as error:
            raise _not_utf8(name, error) from None
        except OSError as error:
            raise FileProblem(name, f"cannot read it ({error.strerror or error})") from None
        end = text.rfind("\n") + 1
        if text and not end and len(pending) + len(text) <= LINE_LIMIT:
            pending += text
            continue
        body, pending = (pending + text[:end], text[end:]) if end else (pending + text, "")
        found = body.split("\n")
        if found and not found[-1]:
            found.pop()
        longest = max(map(len, found), default=0)
        if '"' in body or "\r" in body or "\x00" in body or (text and not end) or longest >= LINE_LIMIT - 1:
            rest = lines(_Prefixed(body + pending, source), name)  # row by row from here on, as records() reads
            yield from _gather(_csv_rows(csv.reader(rest), width, number), header, size, stop)
            return
        for start in range(0, len(found), size):
            part = found[start:start + size]
            if "" not in part and longest < CELL_LIMIT and \
                    set(map(str.count, part, repeat(","))) == {width - 1}:
                flat = ",".join(part).split(",")
                yield Chunk(header, range(number + 1, number + 1 + len(part)), None,
                            [flat[column::width] for column in range(width)], None)
                number += len(part)
                continue
            for chunk in _gather(_csv_rows(csv.reader(part), width, number), header, size, stop):
                number = chunk.numbers[-1]
                yield chunk
                if stop and any(problem is not None for problem in chunk.problems or ()):
                    return
        if not text:
            return


def _gather(found: Iterator[Record], header: list[str] | None, size: int, stop: bool) -> Iterator[Chunk]:
    """Records in chunks of at most ``size`` rows; with ``stop``, the chunk of the first bad row is the last."""
    numbers: list[int] = []
    rows: list[Any] = []
    problems: list[str | None] = []
    for number, record, problem in found:
        numbers.append(number)
        rows.append(record)
        problems.append(problem)
        if (problem is not None and stop) or len(numbers) >= size:
            yield Chunk(header, numbers, rows, None, problems)
            if problem is not None and stop:
                return
            numbers, rows, problems = [], [], []
    if numbers:
        yield Chunk(header, numbers, rows, None, problems)


class _Prefixed:
    """Text already read, then the rest of a stream, read a line at a time (as :func:`lines` reads)."""

    def __init__(self, text: str, source: IO[str]) -> None:
        self.head, self.source = io.StringIO(text), source

    def readline(self, limit: int = -1) -> str:
        line = self.head.readline(limit)
        if line.endswith("\n") or (limit > 0 and len(line) >= limit):
            return line
        return line + self.source.readline(limit - len(line) if limit > 0 else -1)


def unit_column(cells: Sequence[Any]) -> tuple[Any, str] | None:
    """A column whose cells all end in the same unit (``3.2m``): its numbers and the unit; None otherwise.

    >>> unit_column(["3.2m", "10m"])
    (array([ 3.2, 10. ]), 'm')
    >>> unit_column(["3.2m", "10ft"]) is None
    True
    """
    import numpy as np

    first = cells[0] if cells else None
    if not isinstance(first, str):
        return None
    text = first.rstrip()
    suffix = text[len(text.rstrip("abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ")):]
    if not suffix:
        return None
    try:
        joined = "\n".join(cells) + "\n"
    except TypeError:  # JSON values: numbers among the strings
        return None
    if joined.count("\n") != len(cells) or any(space in joined for space in " \t\v\f\r"):
        if not all(isinstance(cell, str) and cell.rstrip().endswith(suffix) for cell in cells):
            return None
        numbers = [cell.rstrip()[:-len(suffix)] for cell in cells]
    elif joined.count(suffix + "\n") == len(cells):  # every cell (one a line) ends in the unit
        numbers = joined.replace(suffix + "\n", "\n").split("\n")[:-1]
    else:
        return None
    try:
        array = floats(numbers)
    except (ValueError, TypeError):
        return None
    if np.isnan(array).any():
        return None
    return array, suffix


def group_rows(settings: Sequence[Sequence[Any]], errors: Sequence[str | None]) -> dict[tuple[Any, ...], list[int]]:
    """The indices of the rows without an error, grouped by their values of the ``settings`` columns.

    >>> group_rows([["a", "b", "a"]], [None, None, "row 3: bad"])
    {('a',): [0], ('b',): [1]}
    """
    good = [i for i, error in enumerate(errors) if error is None] if any(errors) else list(range(len(errors)))
    if not settings:
        return {(): good} if good else {}
    groups: dict[tuple[Any, ...], list[int]] = {}
    for index in good:
        key = tuple(tuple(v) if isinstance(v := column[index], list) else v for column in settings)
        groups.setdefault(key, []).append(index)
    return groups


def floats(cells: Sequence[Any]) -> Any:
    """A column of cells as a float array, as ``numpy.array(cells, dtype=float)`` reads it (ValueError if it cannot).

    pyarrow's parser reads a column of number strings several times faster;
    what it accepts it reads to the same correctly rounded value as Python's
    ``float`` (only its NaN spellings go further, and a NaN is refused by
    every caller), and anything it refuses (spaces, numbers that are not
    strings) is read by numpy as before; ``1_000``, which Python reads and
    the option parsers refuse, is refused here too.

    >>> floats(["50", "1e3", "2.5"]).tolist()
    [50.0, 1000.0, 2.5]
    """

    try:
        import pyarrow as pa
        import pyarrow.compute as pc
    except ImportError:  # pragma: no cover - the test environment has the batch extra
        return _python_floats(cells)
    try:
        return pc.cast(pa.array(cells, pa.string()), pa.float64()).to_numpy(zero_copy_only=False, writable=True)
    except (ValueError, TypeError, pa.ArrowException):
        return _python_floats(cells)


def _python_floats(cells: Sequence[Any]) -> Any:
    """numpy's reading of the cells, but not ``1_000``: Python's digit separator is no number an option takes."""
    import numpy as np

    if any(isinstance(cell, str) and "_" in cell for cell in cells):
        raise ValueError("a digit separator '_' in a number")
    return np.array(cells, dtype=float)


T_STOP_CELLS = "T"
"""The unit of a column whose bare numbers are T-stops (a camera's ``t_stop``): see :func:`t_stop_cells`."""

CAMERA_DATA_COLUMNS = {"focus": ("distance", None), "t_stop": ("f_number", T_STOP_CELLS)}
"""The columns of a camera's per-frame metadata that name no option (docs/cine.md §5b): the option each stands for
and the unit of its bare numbers. ``focus`` is the focus distance (a bare number in metres, as ``-s``; ``focus_mm``
in mm); ``t_stop`` (also ``t-stop``, ``tstop``: case, dashes and underscores do not matter) holds T-stops, a bare
``2.8`` there being ``T2.8``."""


def camera_cells(cells: Sequence[Any], unit: str | None) -> tuple[Sequence[Any], str | None]:
    """The cells of a column and the unit of its bare numbers, as ``-N`` reads them when the column holds T-stops
    (``unit`` :data:`T_STOP_CELLS`): a bare number ``2.8`` (text or a JSON number) becomes ``T2.8``; a cell already
    written ``T2.8``, an empty cell and anything else stay as they are (and are parsed, or refused, as ``-N``
    would). Any other column is returned as it is.

    >>> camera_cells(["2.8", " 4", "T5.6", "", None, 2, ".7", "f/8"], T_STOP_CELLS)
    (['T2.8', 'T4', 'T5.6', '', None, 'T2', 'T.7', 'f/8'], None)
    >>> camera_cells(["3"], "mm")
    (['3'], 'mm')
    """
    if unit != T_STOP_CELLS:
        return cells, unit
    out: list[Any] = []
    for cell in cells:
        if isinstance(cell, (int, float)) and not isinstance(cell, bool):
            out.append(f"T{cell!r}")
            continue
        text = cell.strip() if isinstance(cell, str) else ""
        out.append(f"T{text}" if text[:1].isdigit() or (text[:1] == "." and text[1:2].isdigit()) else cell)
    return out, None
