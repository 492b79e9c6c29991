"""Reading one preset file: safe YAML with line numbers, validation, and a JSON cache.

A preset file is a YAML mapping whose keys are sections (``sensors``,
``cameras``, ``lenses``, ``prescriptions``, ``scenes``), each a list of
presets. A file whose top level has ``surfaces`` is a single prescription
(the shape of the shipped ``lens_db/prescriptions/*.yaml``).

Parsing YAML is the slow part of a command that names a preset (PyYAML's
import alone costs about 20 ms), so the validated records of every file are
cached as JSON under ``$XDG_CACHE_HOME/camtool/presets``, keyed by the file's
path and a digest of its content. A warm start reads only the JSON files and
never imports yaml.
"""

from __future__ import annotations

import contextlib
import json
import os
import zlib
from typing import Any

from camtool.core.files import FileProblem, decode, load_yaml, read_bytes
from camtool.presets.errors import PresetFileError
from camtool.presets.schema import (
    REFERENCES,
    SECTIONS,
    check_record,
    normalize,
    show,
    suggest,
)

CACHE_FORMAT = 6
"""Bumped whenever the record layout changes, so old cache files are ignored."""

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
                 cached: tuple[str, int, dict[str, list[int]]] | None = None) -> None:
        self.path = path
        self.problems: list[Problem] = []
        self._records = records if records is not None else {}
        self._cached = cached

    def records_of(self, kind: str) -> list[dict[str, Any]]:
        """The records of one kind (read from the cache on first use)."""
        records = self._records.get(kind)
        if records is None:
            records = self._records[kind] = self._load_kind(kind)
        return records

    def keys_of(self, kind: str) -> list[list[str]]:
        """The lookup keys of each record of one kind, in order, without reading the records from the cache.

        A lookup needs every tier's keys but only the one record it finds; a
        large tier (a lensfun import) then costs its keys, not its records.
        """
        if kind in self._records or self._cached is None or f"{kind}#keys" not in self._cached[2]:
            return [record["_keys"] for record in self.records_of(kind)]
        keys = self._read_section(f"{kind}#keys")
        return keys if keys is not None else [record["_keys"] for record in self.records_of(kind)]

    def record_at(self, kind: str, index: int) -> dict[str, Any]:
        """The ``index``-th record of one kind."""
        return self.records_of(kind)[index]

    def _read_section(self, section: str) -> Any:
        assert self._cached is not None
        cache_path, body_start, sections = self._cached
        offset, length = sections[section]
        try:
            with open(cache_path, "rb") as handle:
                handle.seek(body_start + offset)
                return json.loads(handle.read(length))
        except (OSError, ValueError):
            return None

    @property
    def records(self) -> dict[str, list[dict[str, Any]]]:
        """Every kind's records (kinds without presets left out)."""
        if self._cached is not None:
            for kind in self._cached[2]:
                if "#" not in kind:
                    self.records_of(kind)
        return {kind: records for kind, records in self._records.items() if records}

    def _load_kind(self, kind: str) -> list[dict[str, Any]]:
        if self._cached is None:
            return []
        cache_path, body_start, sections = self._cached
        if kind not in sections:
            return []
        offset, length = sections[kind]
        try:
            with open(cache_path, "rb") as handle:
                handle.seek(body_start + offset)
                records = json.loads(handle.read(length))
            if isinstance(records, list):
                return records
        except (OSError, ValueError):
            pass
        # The cache vanished or changed under us: parse the file itself.
        fresh = read_file(self.path)
        self._records, self._cached = fresh._records, None
        return self._records.get(kind, [])


def read_file(path: str, *, cache_dir: str | None = None) -> FileData:
    """Read and validate one preset file, raising :class:`PresetFileError` on the first problem.

    With ``cache_dir``, a cached copy is used when the file's content (a
    BLAKE2 digest of its bytes) matches the one cached, and a fresh parse is
    written back; a file rewritten with the same size and modification time
    is therefore never served stale.
    """
    try:
        raw = read_bytes(path, MAX_BYTES)
    except FileProblem as problem:
        raise PresetFileError(path, problem.problem, line=problem.line) from None
    cache_path = _cache_path(cache_dir, os.path.abspath(path)) if cache_dir else None
    stamp: list[Any] = []
    if cache_path:
        import hashlib

        stamp = [CACHE_FORMAT, os.path.abspath(path), len(raw), hashlib.blake2b(raw, digest_size=20).hexdigest()]
        cached = _read_cache(cache_path, stamp)
        if cached is not None:
            return FileData(path, cached=cached)
    data = parse_file(path, raw)
    if data.problems:
        first = data.problems[0]
        extra = len(data.problems) - 1
        if extra:
            first = Problem(f"{first.problem} (and {extra} more problem{'s' * (extra > 1)}; "
                            f"camtool presets validate {path} lists them)",
                            first.line, first.kind, first.preset_id, first.key)
        raise first.error(path)
    if cache_path:
        _write_cache(cache_path, stamp, data._records)
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
    keys = [normalize(record["id"])]
    for alias in record.get("aliases", ()):
        key = normalize(alias)
        if key not in keys:
            keys.append(key)
    record["_keys"] = keys
    record["_line"] = entry_line
    refs = REFERENCES.get(kind, {})
    record["_refs"] = {key: _line(key_nodes.get(key)) for key in refs if key in record}
    if kind == "prescription":
        record["_data"] = {k: v for k, v in entry.items() if not str(k).startswith("_")}
    data._records.setdefault(kind, []).append(record)


def _cache_path(cache_dir: str, path: str) -> str:
    base = os.path.basename(path) or "preset"
    return os.path.join(cache_dir, f"{base}-{zlib.crc32(path.encode('utf-8', 'surrogateescape')):08x}.json")


def _read_cache(cache_path: str, stamp: list[Any]) -> tuple[str, int, dict[str, list[int]]] | None:
    """The header of a fresh cache file: its path, where the records start, and each kind's byte range.

    The cache holds one JSON header line followed by one JSON list per kind,
    so a lookup parses only the kinds it needs.
    """
    try:
        with open(cache_path, "rb") as handle:
            header_line = handle.readline()
        header = json.loads(header_line)
    except (OSError, ValueError):
        return None
    if not isinstance(header, dict) or header.get("stamp") != stamp or not isinstance(header.get("sections"), dict):
        return None
    return cache_path, len(header_line), header["sections"]


def _write_cache(cache_path: str, stamp: list[Any], records: dict[str, list[dict[str, Any]]]) -> None:
    """Write the cache atomically; a cache that cannot be written is silently skipped."""
    temporary = f"{cache_path}.{os.getpid()}.tmp"
    try:
        sections: dict[str, list[int]] = {}
        blobs = []
        offset = 0
        for kind, kind_records in records.items():
            keys = [record["_keys"] for record in kind_records]
            for section, value in ((kind, kind_records), (f"{kind}#keys", keys)):
                blob = json.dumps(value, separators=(",", ":")).encode("utf-8")
                sections[section] = [offset, len(blob)]
                blobs.append(blob)
                offset += len(blob)
        header = json.dumps({"stamp": stamp, "sections": sections}, separators=(",", ":")).encode("utf-8")
        os.makedirs(os.path.dirname(cache_path), exist_ok=True)
        with open(temporary, "wb") as handle:
            handle.write(header + b"\n")
            handle.writelines(blobs)
        os.replace(temporary, cache_path)
    except (OSError, TypeError, ValueError):
        with contextlib.suppress(OSError):
            os.unlink(temporary)
