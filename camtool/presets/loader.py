"""Reading one preset file: safe YAML with line numbers, validation, and a JSON cache.

A preset file is a YAML mapping whose keys are sections (``sensors``,
``cameras``, ``lenses``, ``prescriptions``, ``scenes``), each a list of
presets. A file whose top level has ``surfaces`` is a single prescription
(the shape of the shipped ``lens_db/prescriptions/*.yaml``).

Parsing YAML is the slow part of a command that names a preset (PyYAML's
import alone costs about 20 ms), so the validated records of every file are
cached as JSON under ``$XDG_CACHE_HOME/camtool/presets``, bound to the
SHA-256 of the file's path and bytes (recomputed on every read). A warm start
reads only the JSON files and never imports yaml. The shipped files' records
ship with the package (read by :mod:`camtool.presets.shipped_records`), made
by the package's own build from a validated parse; they are used only for the very bytes they were
made from and only when their own SHA-256 is the one the build recorded, and
are then used without a second schema check (the build's parse was that
check); ``CAMTOOL_NO_CACHE`` parses every file. The digest of each shipped
file's bytes is remembered against its ``stat``
(:class:`camtool.core.cache.FileDigests`), so a warm command reads no YAML.

The cache is never trusted: an entry is used only when it passes the checks
of :mod:`camtool.core.cache` (a regular file of bounded size, the camtool
version and record layout that wrote it, the digest of this very file, its
keyed checksum), and every cached record used goes through the same
schema check as a parsed one (:func:`_valid_record`: the record must be
exactly what :func:`camtool.presets.schema.check_record` makes of it, its
lookup keys the ones its id and aliases give), a whole kind read for a
listing too. An
entry that fails is ignored, the file is parsed and the entry rewritten.
"""

from __future__ import annotations

import json
import math
import os
from collections.abc import Callable
from typing import Any

from camtool.core import cache
from camtool.core.files import FileProblem, decode, load_yaml, read_bytes
from camtool.presets.errors import PresetFileError
from camtool.presets.kinds import KINDS, REFERENCES, SECTIONS, normalize
from camtool.presets.shipped_records import (
    CACHE_FORMAT,
    Window,
    real_path,
    shipped_entry,
    shipped_name,
    shipped_real_dir,
)

_CACHE_KIND = f"presets-{CACHE_FORMAT}"

MAX_BYTES = 64 * 1024 * 1024
"""Largest preset file read."""


class Problem:
    """One problem found in a file (see :class:`PresetFileError` for the fields)."""

    __slots__ = ("key", "kind", "line", "preset_id", "problem")

    def __init__(self, problem: str, line: int | None = None, kind: str | None = None,
                 preset_id: str | None = None, key: str | None = None) -> None:
        self.problem = problem
        self.line = line
        self.kind = kind
        self.preset_id = preset_id
        self.key = key

    def error(self, path: str) -> PresetFileError:
        """The problem as an exception naming ``path``."""
        return PresetFileError(path, self.problem, line=self.line, kind=self.kind, preset_id=self.preset_id,
                               key=self.key)


class FileData:
    """The validated records of one file, grouped by kind, read from the cache one kind at a time.

    Each record is a dict of checked values plus ``_line`` (the line of the
    entry), ``_refs`` (line of each key that names another preset) and
    ``_keys`` (its normalized id and aliases, the lookup keys).
    """

    def __init__(self, path: str, records: dict[str, list[dict[str, Any]]] | None = None,
                 cached: _Cached | None = None, pending: Callable[[], _Cached | None] | None = None) -> None:
        self.path = path
        self.problems: list[Problem] = []
        self._records = records if records is not None else {}
        self._entry = cached
        # makes the entry when it is first used (a shipped file's records: most files of a lookup are never used)
        self._pending = pending
        self._handed: dict[str, list[list[str]]] = {}
        # the name under lens_db/ of a shipped file read for the very bytes its shipped records were made from
        self.shipped_name: str | None = None

    @property
    def _cached(self) -> _Cached | None:
        """The cache entry (or shipped records) the records are read from; None once they are parsed."""
        if self._pending is not None:
            pending, self._pending = self._pending, None
            self._entry = pending()
            if self._entry is None:  # not the layout the build writes after all: the file's own bytes are parsed
                self._records = _parse_or_raise(self.path, _read_or_raise(self.path))._records
        return self._entry

    @_cached.setter
    def _cached(self, value: _Cached | None) -> None:
        self._entry, self._pending = value, None

    def records_of(self, kind: str) -> list[dict[str, Any]]:
        """The records of one kind (read from the cache, and checked, on first use)."""
        records = self._records.get(kind)
        if records is None:
            cached = self._cached.all(kind) if self._cached is not None else []
            if cached is None:
                self._refresh()
                return self._records.get(kind, [])
            records = self._records[kind] = cached
        return records

    def keys_of(self, kind: str) -> list[list[str]]:
        """The lookup keys of each record of one kind, in order, without reading the records from the cache.

        A lookup needs every tier's keys but only the one record it finds; a
        large tier (a lensfun import) then costs its keys, not its records.
        """
        if kind not in self._records and self._cached is not None:
            keys = self._cached.keys(kind)
            if keys is not None:
                return keys
            self._refresh()
        return [record["_keys"] for record in self.records_of(kind)]

    def record_at(self, kind: str, index: int) -> dict[str, Any]:
        """The ``index``-th record of one kind (the one whose keys :meth:`keys_of` gave at ``index``)."""
        if kind not in self._records and self._cached is not None:
            record = self._cached.record(kind, index)
            if record is not None:
                return record
            self._refresh()
        records = self.records_of(kind)
        handed = self._handed.get(kind)
        if handed is not None and (index >= len(records) or records[index]["_keys"] != handed[index]):
            # keys given out from an entry that did not match its records: the record those keys name
            match = next((record for record in records if record["_keys"] == handed[index]), None)
            if match is None:
                raise PresetFileError(self.path, "its cache entry named a preset the file does not have; the entry "
                                                 "has been rewritten, run the command again")
            return match
        return records[index]

    @property
    def records(self) -> dict[str, list[dict[str, Any]]]:
        """Every kind's records (kinds without presets left out)."""
        if self._cached is not None:
            for kind in self._cached.kinds():
                self.records_of(kind)
        return {kind: records for kind, records in self._records.items() if records}

    def _refresh(self) -> None:
        """Replace a cache entry that failed a check by a parse of the file's own bytes (and rewrite the entry)."""
        cached = self._cached
        assert cached is not None
        self._cached = None
        self._handed = cached.handed
        raw = cached.raw
        if raw is None:  # shipped records taken on the file's remembered digest: its bytes were not read
            raw = _read_or_raise(self.path)
        data = _parse_or_raise(self.path, raw)
        self._records = data._records
        if cached.source is not None:  # a shipped section that failed its digest has no cache entry to mend
            _write_cache(cached.cache_path, cached.source, self._records, cached.limit)


class _Cached:
    """A cache entry that passed the envelope checks: its sections, parsed and checked on first use."""

    def __init__(self, body: Any, sections: dict[str, list[int]], raw: bytes | None, cache_path: str, source: str | None,
                 limit: int, digests: dict[str, str] | None = None) -> None:
        self.body = body
        self.sections = sections
        self.raw = raw
        self.cache_path = cache_path
        self.source = source
        self.limit = limit
        # the shipped records: each section used only with the digest the build recorded, then without a second
        # schema check (None: a cache entry, every record checked)
        self.digests = digests
        self.handed: dict[str, list[list[str]]] = {}
        self._parsed: dict[str, Any] = {}
        self._checked: dict[tuple[str, int], dict[str, Any]] = {}

    @classmethod
    def parse(cls, payload: Any, raw: bytes | None, cache_path: str, source: str | None, limit: int,
              digests: dict[str, str] | None = None) -> _Cached | None:
        end = payload.find(b"\n")
        if end < 0:
            return None
        try:
            sections = json.loads(payload[:end])
        except (ValueError, RecursionError):
            return None
        body = Window(payload, end + 1, len(payload) - end - 1)  # a section is sliced only when it is used
        if not isinstance(sections, dict):
            return None
        for name, span in sections.items():
            kind = name.removesuffix("#keys").removesuffix("#spans")
            if kind not in KINDS or not (isinstance(span, list) and len(span) == 2
                                         and all(type(n) is int for n in span)):
                return None
            if span[0] < 0 or span[1] < 0 or span[0] + span[1] > len(body):
                return None
        return cls(body, sections, raw, cache_path, source, limit, digests)

    def kinds(self) -> list[str]:
        return [name for name in self.sections if "#" not in name]

    def _section(self, name: str) -> Any:
        if name not in self._parsed:
            value = None
            span = self.sections.get(name)
            if span is not None:
                blob = self.body[span[0]:span[0] + span[1]]
                if self.digests is None or self.digests.get(name) == cache.source_digest(blob):
                    try:
                        value = json.loads(blob)
                    except (ValueError, RecursionError):
                        value = None
            self._parsed[name] = value
        return self._parsed[name]

    def keys(self, kind: str) -> list[list[str]] | None:
        """The cached lookup keys of one kind when they are well formed (remembered, to match the records later)."""
        keys = self._keys(kind)
        if keys is not None:
            self.handed[kind] = keys
        return keys

    def _keys(self, kind: str) -> list[list[str]] | None:
        name = f"{kind}#keys"
        if name in self.sections:
            keys = self._section(name)
        elif kind in self.sections:
            return None  # records without their keys: not an entry this module writes
        else:
            keys = []
        if not isinstance(keys, list) or not (self.digests is not None or all(_valid_keys(k) for k in keys)):
            return None
        return keys

    def record(self, kind: str, index: int) -> dict[str, Any] | None:
        """The ``index``-th record of one kind when it passes :func:`_valid_record` (and matches the keys given out).

        Of the shipped records only that record is read and parsed, where the
        kind's ``#spans`` section says it stands, when its bytes have the
        digest the build recorded there; a cache entry's records section is
        parsed whole, so that every record of it is held to its keys.
        """
        checked = self._checked.get((kind, index))
        if checked is not None:
            return checked
        handed = self.handed.get(kind)
        if self.digests is not None and kind not in self._parsed and f"{kind}#spans" in self.sections:
            spans = self._section(f"{kind}#spans")
            section = self.sections.get(kind)
            if (section is None or not isinstance(spans, list) or not 0 <= index < len(spans)
                    or (handed is not None and len(handed) != len(spans))):
                return None
            span = spans[index]
            if not (isinstance(span, list) and len(span) == 3 and all(type(n) is int and n >= 0 for n in span[:2])
                    and isinstance(span[2], str) and span[0] + span[1] <= section[1]):
                return None
            blob = self.body[section[0] + span[0]:section[0] + span[0] + span[1]]
            if cache.source_digest(blob) != span[2]:  # the record's own digest, as the build recorded it
                return None
            try:
                record = json.loads(blob)
            except (ValueError, RecursionError):
                return None
        else:
            records = self._section(kind) if kind in self.sections else []
            if not isinstance(records, list) or not 0 <= index < len(records):
                return None
            if handed is not None and len(handed) != len(records):
                return None
            record = records[index]
        if not self._valid(kind, record) or (handed is not None and record["_keys"] != handed[index]):
            return None
        self._checked[(kind, index)] = record
        return record

    def _valid(self, kind: str, record: Any) -> bool:
        return isinstance(record, dict) and isinstance(record.get("_keys"), list) if self.digests is not None else \
            _valid_record(kind, record)

    def all(self, kind: str) -> list[dict[str, Any]] | None:
        """Every record of one kind when each passes :func:`_valid_record` (and matches the keys given out), else None.

        A whole kind is read for a listing (``presets list``, matching EXIF
        names); its records are checked as a record looked up by name is
        (:meth:`record`), since their values are used as theirs are.
        """
        records = self._section(kind) if kind in self.sections else []
        keys = self._keys(kind)  # the entry's keys must be its records' keys, one for one
        handed = self.handed.get(kind, keys)
        if not isinstance(records, list) or handed is None or keys != handed or len(handed) != len(records):
            return None
        out = []
        for index, record in enumerate(records):
            checked = self._checked.get((kind, index))
            if checked is None:
                if not self._valid(kind, record) or record["_keys"] != handed[index]:
                    return None
                checked = record
            out.append(checked)
        return out


def _valid_keys(keys: Any) -> bool:
    return (isinstance(keys, list) and bool(keys)
            and all(isinstance(key, str) and key and normalize(key) == key for key in keys))


def _lookup_keys(record: dict[str, Any]) -> list[str]:
    """A record's lookup keys: its normalized id, then each alias not already there."""
    keys = [normalize(record["id"])]
    for alias in record.get("aliases", ()):
        key = normalize(alias)
        if key not in keys:
            keys.append(key)
    return keys


def _line_number(value: Any) -> bool:
    return value is None or (type(value) is int and value >= 1)


def _valid_record(kind: str, record: Any) -> bool:
    """True when a cached record is exactly what a fresh parse would make of its values.

    The record's values (a prescription's ``_data``, the mapping it was
    written as) go through :func:`check_record` again and must come back
    unchanged; its lookup keys must be the ones its id and aliases give, its
    line numbers positive integers, its references the keys it has.
    """
    if not isinstance(record, dict) or not all(isinstance(key, str) for key in record):
        return False
    private = {key for key in record if key.startswith("_")}
    if private != ({"_keys", "_line", "_refs", "_data"} if kind == "prescription" else {"_keys", "_line", "_refs"}):
        return False
    values = {key: value for key, value in record.items() if not key.startswith("_")}
    if kind == "prescription":
        source = record["_data"]
        if not isinstance(source, dict) or any(str(key).startswith("_") for key in source):
            return False
    else:
        source = dict(values)
        for key, value in values.items():
            if kind == "scene" and key.endswith("_mm") and value == math.inf:
                # an infinite distance is written with its unit spelling (distance: inf), which allows it
                del source[key]
                source[key.removesuffix("_mm")] = value
    from camtool.presets.schema import check_record  # the checks: only a cache entry's records need them again

    try:
        fresh, problems = check_record(kind, source)
    except (TypeError, ValueError, ArithmeticError, RecursionError):
        return False
    if problems or not isinstance(fresh.get("id"), str):
        return False
    fresh.setdefault("name", fresh["id"])
    try:
        if json.loads(json.dumps(fresh)) != values:
            return False
    except (TypeError, ValueError, RecursionError):
        return False
    refs = record["_refs"]
    return (record["_keys"] == _lookup_keys(fresh) and _line_number(record["_line"]) and isinstance(refs, dict)
            and set(refs) == {key for key in REFERENCES.get(kind, {}) if key in fresh}
            and all(_line_number(line) for line in refs.values()))


def read_file(path: str, *, cache_dir: str | None = None) -> FileData:
    """Read and validate one preset file, raising :class:`PresetFileError` on the first problem.

    With ``cache_dir`` (and ``CAMTOOL_NO_CACHE`` unset), a cached copy is used
    when its entry is bound to this file's path and bytes (their SHA-256) and
    passes every check (see the module docstring); otherwise the file is
    parsed and its entry written. A file rewritten with the same size and
    modification time is therefore never served stale.
    """
    if not cache_dir or not cache.enabled():
        return _parse_or_raise(path, _read_or_raise(path))
    absolute = os.path.abspath(path)
    real = real_path(absolute)
    digests = _shipped_digests(cache_dir)
    digest = digests.get(absolute)
    known = shipped_entry(real, digest) if digest is not None else None
    if known is not None:  # a shipped file whose bytes have the remembered digest: not read at all
        payload, sections = known
        data = FileData(path, pending=lambda: _Cached.parse(payload, None, "", None, 0, digests=sections))
        data.shipped_name = shipped_name(real)
        return data
    raw = _read_or_raise(path)
    cache_path = _cache_path(cache_dir, absolute)
    limit = _cache_limit(len(raw))
    shipped = _shipped_payload(real, absolute, raw, digests)
    if shipped is not None:
        # the cache's own digest (path and bytes) is needed only if a section fails and the file is parsed
        cached = _Cached.parse(shipped[0], raw, cache_path, None, limit, digests=shipped[1])
        if cached is not None:
            return _shipped_data(path, cached, real)
    source = cache.source_digest(os.fsencode(absolute) + b"\0" + raw)
    payload = cache.read(cache_path, _CACHE_KIND, source, limit)
    if payload is not None:
        cached = _Cached.parse(payload, raw, cache_path, source, limit)
        if cached is not None:
            return FileData(path, cached=cached)
    data = _parse_or_raise(path, raw)
    _write_cache(cache_path, source, data._records, limit)
    return data


def _read_or_raise(path: str) -> bytes:
    """The bytes of the preset file at ``path`` (through the guarded reader), or :class:`PresetFileError`."""
    try:
        return read_bytes(path, MAX_BYTES)
    except FileProblem as problem:
        raise PresetFileError(path, problem.problem, line=problem.line) from None


def _shipped_data(path: str, cached: _Cached, real: str) -> FileData:
    data = FileData(path, cached=cached)
    data.shipped_name = shipped_name(real)
    return data


def shipped_payload(absolute: str, raw: bytes, digests: Any = None) -> tuple[Any, dict[str, str]] | None:
    """The shipped records of the file at ``absolute`` and the digest of each section, when it is a shipped file
    holding exactly ``raw`` (else None). ``digests`` (a :class:`camtool.core.cache.FileDigests`) remembers the digest
    of ``raw`` against the file's ``stat``."""
    return _shipped_payload(real_path(absolute), absolute, raw, digests)


def _shipped_payload(real: str, absolute: str, raw: bytes, digests: Any) -> tuple[Any, dict[str, str]] | None:
    """:func:`shipped_payload` of the file whose real path (already found) is ``real``."""
    if shipped_name(real) is None:
        return None
    return shipped_entry(real, digests.put(absolute, raw) if digests is not None else cache.source_digest(raw))


_file_digests: dict[tuple[str, str], Any] = {}


def _shipped_digests(cache_dir: str) -> Any:
    """The remembered digests of the shipped files (:class:`camtool.core.cache.FileDigests`), one per cache directory
    and shipped directory."""
    directory = shipped_real_dir()
    digests = _file_digests.get((cache_dir, directory))
    if digests is None:
        from camtool.presets import paths

        files = [os.path.abspath(path) for path in paths.shipped_files()]
        name = cache.source_digest(directory.encode("utf-8", "surrogateescape"))[:16]
        entry = os.path.join(cache_dir, f"shipped-digests-{name}.json")
        digests = _file_digests[(cache_dir, directory)] = cache.FileDigests(entry, files)
    return digests


def _parse_or_raise(path: str, raw: bytes) -> FileData:
    """:func:`parse_file` of ``raw``, raising the first problem (with a count of the others)."""
    data = parse_file(path, raw)
    if data.problems:
        first = data.problems[0]
        extra = len(data.problems) - 1
        if extra:
            first = Problem(f"{first.problem} (and {extra} more problem{'s' * (extra > 1)}; "
                            f"camtool presets validate {path} lists them)",
                            first.line, first.kind, first.preset_id, first.key)
        raise first.error(path)
    return data


def parse_file(path: str, raw: bytes | None = None) -> FileData:
    """Parse and validate ``path`` (or its content ``raw``, already read) without the cache, collecting every problem.

    The file goes through the guarded reader of :mod:`camtool.core.files`:
    regular files only, at most :data:`MAX_BYTES`, UTF-8, and YAML within
    the node and depth caps, without repeated keys.
    """
    data = FileData(path)
    try:
        if raw is None:
            raw = read_bytes(path, MAX_BYTES)
        document, node = load_yaml(decode(raw, path), path)
    except FileProblem as problem:
        data.problems.append(Problem(problem.problem, problem.line))
        return data
    _collect(document, node, data)
    return data


def _line(node: Any) -> int | None:
    return None if node is None else node.start_mark.line + 1


def _key_nodes(node: Any) -> dict[str, Any]:
    """Map each key of a mapping node to its key node (for line numbers)."""
    if node is None or not isinstance(node.value, list):
        return {}
    return {str(k.value): k for k, v in node.value if isinstance(k.value, str)} if node.id == "mapping" else {}


def _value_nodes(node: Any) -> dict[str, Any]:
    if node is None or node.id != "mapping":
        return {}
    return {str(k.value): v for k, v in node.value}


def _collect(document: Any, node: Any, data: FileData) -> None:
    """Validate the sections of a parsed document into ``data``."""
    from camtool.presets.schema import show, suggest  # the checks: only parsing a file needs them

    if document is None:
        data.problems.append(Problem("the file is empty; expected sections such as sensors: or lenses:"))
        return
    if not isinstance(document, dict):
        data.problems.append(Problem(f"expected a mapping of sections (sensors:, lenses:, ...), got {show(document)}",
                                     _line(node)))
        return
    if "surfaces" in document:
        _collect_entry("prescription", document, node, data)
        return
    key_nodes, value_nodes = _key_nodes(node), _value_nodes(node)
    for section, entries in document.items():
        name = str(section)
        line = _line(key_nodes.get(name))
        kind = SECTIONS.get(name)
        if kind is None:
            data.problems.append(Problem("unknown section" + suggest(name, SECTIONS.keys())
                                         + f"; sections are {', '.join(SECTIONS)}", line, key=name))
            continue
        if entries is None:
            continue
        if not isinstance(entries, list):
            data.problems.append(Problem(f"expected a list of presets, got {show(entries)}", line, key=name))
            continue
        section_node = value_nodes.get(name)
        item_nodes = section_node.value if section_node is not None and section_node.id == "sequence" else []
        for index, entry in enumerate(entries):
            entry_node = item_nodes[index] if index < len(item_nodes) else None
            if not isinstance(entry, dict):
                data.problems.append(Problem(f"each preset must be a mapping, got {show(entry)}",
                                             _line(entry_node) or line, kind=kind))
                continue
            _collect_entry(kind, entry, entry_node, data)


def _collect_entry(kind: str, entry: dict[Any, Any], node: Any, data: FileData) -> None:
    from camtool.presets.schema import check_record

    key_nodes = _key_nodes(node)
    entry_line = _line(node)
    record, problems = check_record(kind, entry)
    preset_id = record.get("id") if isinstance(record.get("id"), str) else None
    if preset_id is None and isinstance(entry.get("id"), (str, int)):
        preset_id = str(entry["id"])
    for key, problem in problems:
        data.problems.append(Problem(problem, _line(key_nodes.get(key)) or entry_line, kind, preset_id, key))
    if problems:
        return
    record.setdefault("name", record["id"])
    record["_keys"] = _lookup_keys(record)
    record["_line"] = entry_line
    refs = REFERENCES.get(kind, {})
    record["_refs"] = {key: _line(key_nodes.get(key)) for key in refs if key in record}
    if kind == "prescription":
        record["_data"] = {k: v for k, v in entry.items() if not str(k).startswith("_")}
    data._records.setdefault(kind, []).append(record)


def _cache_path(cache_dir: str, path: str) -> str:
    import zlib  # only a file that is not shipped, or no longer the shipped bytes, has a cache entry

    base = os.path.basename(path) or "preset"
    return os.path.join(cache_dir, f"{base}-{zlib.crc32(path.encode('utf-8', 'surrogateescape')):08x}.json")


def _cache_limit(source_bytes: int) -> int:
    """Largest cache entry read for a file of ``source_bytes`` (the records take about 1 to 3 times the YAML)."""
    return min(8 * source_bytes + (1 << 20), 256 << 20)


def _write_cache(cache_path: str, source: str, records: dict[str, list[dict[str, Any]]], limit: int) -> None:
    """Write the cache entry: one JSON line of sections, then one JSON list per kind and one of its keys.

    A lookup then parses only the kinds it needs. An entry that cannot be
    written (or would be too large to be read back) is skipped silently.
    """
    payload = entry_payload(records)
    if payload is not None and len(payload) + 1024 <= limit:
        cache.write(cache_path, _CACHE_KIND, source, payload)


def entry_payload(records: dict[str, list[dict[str, Any]]]) -> bytes | None:
    """The records of one file in the layout of a cache entry (None when a value cannot be written as JSON).

    One JSON line naming each section's span, then per kind: its records (a
    JSON list), their lookup keys (``kind#keys``) and where each record stands
    in the records section and the SHA-256 of its bytes (``kind#spans``,
    ``[offset, length, digest]``: a shipped record is checked alone).
    """
    sections: dict[str, list[int]] = {}
    blobs = []
    offset = 0
    try:
        for kind, kind_records in records.items():
            # the records section is the kind's JSON list, written item by item to know where each record stands
            items = [json.dumps(record, separators=(",", ":")).encode("utf-8") for record in kind_records]
            spans: list[list[Any]] = []
            position = 1
            for item in items:
                spans.append([position, len(item), cache.source_digest(item)])
                position += len(item) + 1
            keys = [record["_keys"] for record in kind_records]
            for section, blob in ((kind, b"[" + b",".join(items) + b"]"),
                                  (f"{kind}#keys", json.dumps(keys, separators=(",", ":")).encode("utf-8")),
                                  (f"{kind}#spans", json.dumps(spans, separators=(",", ":")).encode("utf-8"))):
                sections[section] = [offset, len(blob)]
                blobs.append(blob)
                offset += len(blob)
        header = json.dumps(sections, separators=(",", ":")).encode("utf-8")
    except (TypeError, ValueError, RecursionError):
        return None
    return header + b"\n" + b"".join(blobs)
