"""Reading the shipped records: the file ``python -m camtool.presets.shipped`` writes beside this module.

The records of every file of ``lens_db/``, their lookup keys merged over the
files, the listing ``presets list`` shows and the shipped films' rows, each
section bound to the bytes it was made from and read, a span at a time, only
when it has the SHA-256 the build recorded (see :data:`SHIPPED_RECORDS`).
:mod:`camtool.presets.loader` hands a file's records to a command from here
when the file's bytes are the build's; anything else is read and parsed
there.
"""

from __future__ import annotations

import json
import os
from typing import Any

from camtool.core import cache
from camtool.core.files import FileProblem, read_bytes
from camtool.presets.kinds import KINDS

CACHE_FORMAT = 13
"""The record layout's format number (a cache entry's and the shipped records'): bumped whenever the layout
changes, so old cache files and shipped records of another layout are ignored."""

SHIPPED_RECORDS = "shipped-records.json"
"""The records of the shipped preset files (``lens_db/``), beside this module.

Written by ``python -m camtool.presets.shipped`` from a validated parse of
each file: one JSON line mapping each file's name under ``lens_db/`` to the
SHA-256 of the bytes it was made from, its span in the rest of the file and
the SHA-256 of each section of the span (a kind's records, a kind's keys,
where each record stands in the records),
and the span and SHA-256 of the listing; then each file's records in the
layout of a cache entry, then the listing (:func:`shipped_listing`). A command reads
these instead of parsing the YAML or reading the cache, each only for the
very bytes it was made from and each section only when it still has its
recorded digest (then without :func:`camtool.presets.loader._valid_record`: the
build's parse checked every record, ``tests/test_presets_shipped.py`` that
the file is the build's). An edited file, or a span that is not what the
build wrote, finds no match: the cache or a parse answers.
"""

_shipped_index: dict[str, Any] | None = None


class Window:
    """The bytes ``[offset, offset + length)`` of ``base`` (bytes, or another window), sliced on demand.

    A slice is read (or copied) alone, so a lookup that needs two small
    sections of a file's records never copies the rest; ``find`` reads a
    chunk at a time.
    """

    __slots__ = ("base", "length", "offset")

    def __init__(self, base: Any, offset: int, length: int) -> None:
        self.base, self.offset, self.length = base, offset, length

    def __len__(self) -> int:
        return self.length

    def __getitem__(self, part: slice) -> bytes:
        start, stop, _ = part.indices(self.length)
        return bytes(self.base[self.offset + start:self.offset + max(start, stop)])

    def find(self, sub: bytes, chunk: int = 512) -> int:
        position = 0
        while position < self.length:
            data = self[position:position + chunk + len(sub) - 1]
            found = data.find(sub)
            if found >= 0:
                return position + found
            position += chunk
        return -1


class _FileSpans:
    """A regular file read by span (``os.pread``) instead of whole: ``len`` and slices, as bytes have them.

    A span of a file that is shorter than it was when opened comes back
    short; the digest it is checked against then fails, as for any other
    change.
    """

    __slots__ = ("fd", "size")

    def __init__(self, fd: int, size: int) -> None:
        self.fd, self.size = fd, size

    def __len__(self) -> int:
        return self.size

    def __getitem__(self, part: slice) -> bytes:
        start, stop, _ = part.indices(self.size)
        try:
            return os.pread(self.fd, max(0, stop - start), start)
        except OSError:
            return b""


def _open_spans(path: str, limit: int) -> Any:
    """``path`` as :class:`_FileSpans` (a regular file of at most ``limit`` bytes, opened without blocking, kept
    open for the process), or its whole bytes where ``os.pread`` is missing; None when it cannot be read."""
    import stat

    if not hasattr(os, "pread"):
        try:
            return read_bytes(path, limit)
        except FileProblem:
            return None
    try:
        fd = os.open(path, os.O_RDONLY | getattr(os, "O_CLOEXEC", 0) | getattr(os, "O_NONBLOCK", 0))
    except OSError:
        return None
    try:
        info = os.fstat(fd)
    except OSError:
        info = None
    if info is None or not stat.S_ISREG(info.st_mode) or info.st_size > limit:
        os.close(fd)
        return None
    return _FileSpans(fd, info.st_size)


def _shipped_records() -> tuple[dict[str, Any], Any]:
    """The index line and the body of :data:`SHIPPED_RECORDS` (empty when missing or not the expected shape).

    The body is read a span at a time, when a section is used (a lookup reads
    the index, the lookup keys of each file and the records of one file:
    about a fifth of the file, where reading and copying it whole cost about
    a thousand page faults).
    """
    global _shipped_index
    if _shipped_index is None:
        _shipped_index = {"index": {}, "body": b""}
        spans = _open_spans(os.path.join(os.path.dirname(os.path.abspath(__file__)), SHIPPED_RECORDS), 64 << 20)
        if spans is None:
            return {}, b""
        whole = Window(spans, 0, len(spans))
        end = whole.find(b"\n", 1 << 16)
        try:
            index = json.loads(whole[:end]) if end > 0 else None
        except (ValueError, RecursionError):
            index = None
        if isinstance(index, dict) and index.get("format") == CACHE_FORMAT and isinstance(index.get("files"), dict):
            _shipped_index = {"index": index["files"], "body": Window(spans, end + 1, len(spans) - end - 1),
                              "listing": index.get("listing"), "keys": index.get("keys"),
                              "films": index.get("films")}
    return _shipped_index["index"], _shipped_index["body"]


def shipped_listing(names: set[str]) -> dict[str, list[list[Any]]] | None:
    """The listing of the shipped presets (see :mod:`camtool.presets.shipped`) when ``names``, the files under
    ``lens_db/`` a database read (each for the bytes its shipped records were made from), are exactly the files
    it was made from and it has the SHA-256 the build recorded (else None). Like a shipped section, it is then
    the build's own output, used without a second check of every row."""
    index, body = _shipped_records()
    if names != set(index) or _shipped_index is None:
        return None
    if "rows" not in _shipped_index:  # read and checked once a process
        rows = _checked_json(body, _shipped_index.get("listing"))
        shaped = isinstance(rows, dict) and set(rows) <= set(KINDS) and all(isinstance(v, list) for v in rows.values())
        _shipped_index["rows"] = rows if shaped else None
    return _shipped_index["rows"]


KEY_BUCKETS = 64
"""How many buckets each kind's merged shipped keys are written in (a lookup checks and parses one)."""


def key_bucket(key: str) -> int:
    """The bucket of the merged shipped keys that holds ``key`` (the same in every process: no salted hash)."""
    return sum(key.encode("utf-8", "surrogatepass")) % KEY_BUCKETS


def shipped_key(names: set[str], kind: str, key: str) -> Any:
    """Where the shipped files, merged as one tier, have the preset of ``kind`` whose id or alias is ``key``:
    ``[file under lens_db/, index among that file's records of the kind]``, or None when not there. False when the
    merged keys cannot answer: ``names`` are not exactly the files they were made from (see
    :func:`shipped_listing`), or the bucket or the table of buckets lacks the SHA-256 the build recorded. The value
    is checked where it is used (:class:`camtool.presets.database.Database`)."""
    index, body = _shipped_records()
    if names != set(index) or _shipped_index is None:
        return False
    made = _shipped_index.setdefault("merged", {})
    table = made.get(kind)
    if table is None:  # read and checked once a process
        spans = _shipped_index.get("keys")
        span = spans.get(kind) if isinstance(spans, dict) else None
        table = made[kind] = _checked_json(body, span)
        if not (isinstance(table, list) and len(table) == KEY_BUCKETS):
            table = made[kind] = False
    if table is False:
        return False
    bucket = key_bucket(key)
    keys = made.get((kind, bucket))
    if keys is None:
        keys = made[(kind, bucket)] = _checked_json(body, table[bucket])
        if not isinstance(keys, dict):
            keys = made[(kind, bucket)] = False
    return False if keys is False else keys.get(key)


def _checked_json(body: Any, span: Any) -> Any:
    """The JSON value at ``span`` (``[offset, length, SHA-256]``) of the shipped records' body when it has that
    digest (else None)."""
    if not (isinstance(span, list) and len(span) == 3 and isinstance(span[2], str)
            and all(type(n) is int and n >= 0 for n in span[:2]) and span[0] + span[1] <= len(body)):
        return None
    blob = body[span[0]:span[0] + span[1]]
    try:
        return json.loads(blob) if cache.source_digest(blob) == span[2] else None
    except (ValueError, RecursionError):
        return None


def shipped_films(raw: bytes) -> list[list[Any]] | None:
    """``[id, name, aliases, summary]`` of each film shipped with its reciprocity data, as the build listed them,
    when ``raw`` (the bytes of ``camtool/exposure/films.yaml`` now) are the bytes the build read and the listing has
    the SHA-256 the build recorded (else None: the films are read and listed one by one)."""
    _shipped_records()
    if _shipped_index is None:
        return None
    films = _checked_json(_shipped_index["body"], _shipped_index.get("films"))
    if not (isinstance(films, dict) and films.get("source") == cache.source_digest(raw)
            and isinstance(films.get("rows"), list)):
        return None
    return films["rows"]


def real_path(absolute: str) -> str:
    """``os.path.realpath(absolute)``, found with one ``lstat`` for a file of the shipped directory (or of its
    ``prescriptions``) that is no symbolic link, where the shipped directory's own real path is known."""
    directory = shipped_real_dir()
    folder = os.path.join(os.path.dirname(absolute), "")
    if ((folder == directory or (folder == os.path.join(directory, "prescriptions", "")
                                 and not os.path.islink(folder.rstrip(os.sep))))
            and not os.path.islink(absolute)):
        return absolute
    return os.path.realpath(absolute)


def shipped_name(real: str) -> str | None:
    """The name under ``lens_db/`` of the file whose real path is ``real`` (None: not a shipped file)."""
    directory = shipped_real_dir()
    return real[len(directory):].replace(os.sep, "/") if real.startswith(directory) else None


_real_dirs: dict[str, str] = {}


def shipped_real_dir() -> str:
    """The real path of the shipped directory, with a trailing separator (resolved once per directory)."""
    from camtool.presets import paths

    directory = paths.shipped_dir()
    real = _real_dirs.get(directory)
    if real is None:
        real = _real_dirs[directory] = os.path.join(os.path.realpath(directory), "")
    return real


def shipped_entry(real: str, digest: str) -> tuple[Any, dict[str, str]] | None:
    """The shipped records of the file whose real path is ``real`` when they were made from bytes of SHA-256
    ``digest``."""
    name = shipped_name(real)
    if name is None:
        return None
    index, body = _shipped_records()
    entry = index.get(name)
    if not (isinstance(entry, list) and len(entry) == 4 and isinstance(entry[0], str)
            and all(type(n) is int and n >= 0 for n in entry[1:3]) and entry[1] + entry[2] <= len(body)
            and isinstance(entry[3], dict) and all(isinstance(d, str) for d in entry[3].values())):
        return None
    if entry[0] != digest:
        return None
    return Window(body, entry[1], entry[2]), entry[3]
