"""Write what ships precomputed with the package: ``python -m camtool.presets.shipped``.

A first command (every cache empty) would parse each file of ``lens_db/`` as
YAML (PyYAML's pure-Python parser: most of such a command's time) and, with
a prescription, trace rays for its aberration table (numpy and about 20 ms of
tracing). Both are therefore made once, here, from the shipped files:

- :data:`camtool.presets.shipped_records.SHIPPED_RECORDS`, beside its reader: one JSON
  line (the record layout's format number and, for each file of
  ``lens_db/``, the SHA-256 of its bytes, its span and the SHA-256 of each
  section of the span; the span and SHA-256 of the listing and of each kind's
  merged keys), then each file's validated records as a cache entry holds
  them, then the listing: each shipped preset's id, name, aliases, one-line
  summary and file, which ``presets list`` shows when no other file is read;
  then each kind's lookup keys merged over every shipped file, in buckets
  by key, and where each bucket stands (a lookup reads one bucket instead of
  every file's keys), and the listing of the films shipped with their
  reciprocity data (``camtool/exposure/films.yaml``), bound to its bytes;
- :data:`camtool.dof.auto.SHIPPED_TABLES`, beside :mod:`camtool.dof.auto`: the
  aberration table of each prescription of ``lens_db/prescriptions/``, keyed
  by the content digest a cache entry is bound to.

Run this after changing a file of ``lens_db/``, the record layout or the
table's computation (``tests/test_presets_shipped.py`` and
``tests/test_aberration_table.py`` fail until then; an out-of-date file is
only slower, never wrong: other bytes or other content find no match and are
parsed or computed). ``--check`` only says whether both files are current.
"""

from __future__ import annotations

import argparse
import json
import os
import sys
from typing import TYPE_CHECKING, Any

from camtool.core.cache import source_digest
from camtool.core.files import read_bytes
from camtool.presets import loader, paths, shipped_records

if TYPE_CHECKING:
    from camtool.presets.database import Database


def build_records() -> bytes:
    """The shipped records' bytes, every file of ``lens_db/`` parsed afresh (a file with a problem raises)."""
    directory = paths.shipped_dir()
    files: dict[str, list[object]] = {}
    parsed: dict[str, loader.FileData] = {}
    blobs = []
    offset = 0
    for path in paths.shipped_files():
        raw = read_bytes(path, loader.MAX_BYTES)
        parsed[path] = loader._parse_or_raise(path, raw)
        payload = loader.entry_payload(parsed[path]._records)
        if payload is None:
            raise ValueError(f"{path}: its records cannot be written as JSON")
        name = _name(path, directory)
        end = payload.index(b"\n")
        spans = json.loads(payload[:end])
        body = payload[end + 1:]
        digests = {section: source_digest(body[start:start + length]) for section, (start, length) in spans.items()}
        files[name] = [source_digest(raw), offset, len(payload), digests]
        blobs.append(payload)
        offset += len(payload)
    from camtool.presets.database import Database

    database = Database([paths.Tier("shipped", tuple(parsed))], parsed)  # the shipped files alone, as a command reads them
    listing = listing_payload(database, directory)
    keys: dict[str, list[object]] = {}
    tail = [listing]
    listing_at, offset = offset, offset + len(listing)
    for kind, buckets in keys_payloads(database, directory).items():
        spans = []
        for blob in buckets:
            spans.append([offset, len(blob), source_digest(blob)])
            tail.append(blob)
            offset += len(blob)
        table = json.dumps(spans, separators=(",", ":")).encode("utf-8")
        keys[kind] = [offset, len(table), source_digest(table)]
        tail.append(table)
        offset += len(table)
    films = films_payload()
    tail.append(films)
    document = {"format": shipped_records.CACHE_FORMAT, "files": files, "films": [offset, len(films), source_digest(films)],
                "listing": [listing_at, len(listing), source_digest(listing)], "keys": keys}
    index = json.dumps(document, separators=(",", ":"), sort_keys=True)
    return index.encode("utf-8") + b"\n" + b"".join(blobs) + b"".join(tail)


def _name(path: str, directory: str) -> str:
    """The name of a shipped file under ``lens_db/`` (``/``-separated), as the records and listings give it."""
    return os.path.relpath(path, directory).replace(os.sep, "/")


def keys_payloads(database: Database, directory: str) -> dict[str, list[bytes]]:
    """Each kind's lookup keys over every shipped file, merged as the database merges one tier's, in
    :data:`camtool.presets.shipped_records.KEY_BUCKETS` JSON objects ``{key: [file under lens_db/, index of the record in that
    file's records of the kind]}``, a key in bucket :func:`camtool.presets.shipped_records.key_bucket`.

    A lookup in a database of the shipped files alone, each read for the bytes the build read, finds its record
    through its key's bucket instead of merging some twenty files' keys
    (:meth:`camtool.presets.database.Database._index`).
    """
    from camtool.presets.kinds import KINDS

    out = {}
    for kind in KINDS:
        buckets: list[dict[str, list[object]]] = [{} for _ in range(shipped_records.KEY_BUCKETS)]
        for key, entry in database._merge(kind).items():
            assert entry._at is not None  # an entry of the merge: its file, kind and index
            buckets[shipped_records.key_bucket(key)][key] = [_name(entry.path, directory), entry._at[2]]
        out[kind] = [json.dumps(bucket, separators=(",", ":"), sort_keys=True, ensure_ascii=False).encode("utf-8")
                     for bucket in buckets]
    return out


def films_payload() -> bytes:
    """What ``presets list`` shows of the films shipped with their makers' reciprocity data
    (``camtool/exposure/films.yaml``), bound to that file's bytes: one JSON object, ``source`` the SHA-256 of the
    bytes read and ``rows`` each film's ``[id, name, aliases, summary]`` in the order they are listed."""
    from camtool.exposure import films_path, reciprocity
    from camtool.presets.summary import summary

    raw = read_bytes(films_path(), loader.MAX_BYTES)
    rows = [[film.id, film.name, list(film.aliases), summary(film)] for film in reciprocity.load_films().values()]
    return json.dumps({"source": source_digest(raw), "rows": rows}, separators=(",", ":"),
                      ensure_ascii=False).encode("utf-8")


def listing_payload(database: Database, directory: str) -> bytes:
    """What ``presets list`` shows of the shipped presets alone, kind by kind in the database's order.

    One JSON object: each kind's rows ``[id, name, aliases, summary, file under lens_db/]``, from a
    database of the shipped files only (:func:`camtool.presets.summary.summary` of each preset built).
    """
    from camtool.presets.kinds import KINDS
    from camtool.presets.summary import summary

    rows = {kind: [[preset.id, preset.name, list(preset.aliases), summary(preset), _name(str(preset.origin), directory)]
                   for preset in database.all(kind)] for kind in KINDS}
    return json.dumps(rows, separators=(",", ":"), ensure_ascii=False).encode("utf-8")


def prescriptions_by_id() -> dict[str, Any]:
    """Every prescription of ``lens_db/prescriptions/`` by its id (its file's name without ``.yaml``)."""
    return {lens.source: lens for _name, lens in shipped_prescriptions()}


def shipped_prescriptions() -> list[tuple[str, Any]]:
    """``(file name, prescription)`` of every file in ``lens_db/prescriptions/``, in name order."""
    from camtool.optics.prescription import prescription_from_mapping

    out = []
    for path in paths.yaml_files(os.path.join(paths.shipped_dir(), "prescriptions"), ()):
        for record in loader.parse_file(path).records.get("prescription", []):
            out.append((os.path.basename(path), prescription_from_mapping(record["_data"], source=record["id"])))
    return out


def tables_document() -> dict[str, Any]:
    """The shipped tables: each computed afresh (rays traced), keyed by its prescription's source digest."""
    from camtool.dof import auto

    tables: dict[str, Any] = {}
    names: dict[str, str] = {}
    for name, prescription in shipped_prescriptions():
        source = auto._source(prescription)
        grid, rows = auto._compute_table(prescription)
        # each table a JSON text of its own: a command parses the one table of its prescription, not all of them
        tables[source] = json.dumps({"f_numbers": list(grid), "table": [[list(pair) for pair in row] for row in rows]},
                                    separators=(",", ":"), allow_nan=False)
        names[source] = name
    return {"version": auto._TABLE_VERSION, "prescriptions": names, "tables": tables}


def build_tables() -> bytes:
    """The shipped tables' bytes (JSON; floats as Python writes them, so they read back exactly)."""
    return (json.dumps(tables_document(), indent=1, sort_keys=True, allow_nan=False) + "\n").encode("utf-8")


def targets() -> dict[str, str]:
    """Where each shipped file lives: ``{"records": path, "tables": path}``."""
    from camtool.dof import auto

    here = os.path.dirname(os.path.abspath(shipped_records.__file__))
    return {"records": os.path.join(here, shipped_records.SHIPPED_RECORDS),
            "tables": os.path.join(os.path.dirname(os.path.abspath(auto.__file__)), auto.SHIPPED_TABLES)}


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--check", action="store_true", help="exit 1 when a shipped file is not current")
    args = parser.parse_args(argv)
    stale = 0
    for what, build in (("records", build_records), ("tables", build_tables)):
        target = targets()[what]
        data = build()
        try:
            with open(target, "rb") as handle:
                current = handle.read()
        except OSError:
            current = b""
        if args.check:
            print(f"{target}: {'current' if current == data else 'out of date'}")
            stale += current != data
            continue
        with open(target, "wb") as handle:
            handle.write(data)
        print(f"wrote {target} ({len(data):,} bytes)")
    return 1 if stale else 0


if __name__ == "__main__":
    sys.exit(main())
