"""The merged preset database: tiers of files, an index per kind, lookup by any spelling.

Files are read when the database is loaded (from the JSON cache when it is
fresh); the index of a kind is built the first time a preset of that kind is
looked up, and a preset object is built only when it is asked for.

Lookup ignores case, spaces and punctuation: ``Full Frame``, ``full_frame``,
``FULL-FRAME`` and the alias ``ff`` all find ``full-frame``. Ids and aliases
come first; a preset's display name also matches when no other preset shares
it. Within one tier an id or alias may name only one preset (a clash is an
error naming both files); a later tier replaces an earlier preset with the
same id, aliases and all.
"""

from __future__ import annotations

import os
from collections.abc import Callable, Iterable, Sequence
from typing import Any

from camtool.presets import paths
from camtool.presets.errors import PresetFileError, PresetNotFound
from camtool.presets.kinds import (
    KINDS,
    REFERENCES,
    Camera,
    Film,
    Lens,
    Prescription,
    Preset,
    Scene,
    Sensor,
    kind_of,
    normalize,
    optics_mapping,
)
from camtool.presets.loader import FileData, parse_file, read_file


class _Entry:
    """A record with the file and tier it came from; the record itself is read only when needed."""

    __slots__ = ("_at", "_record", "keys", "path", "tier")

    def __init__(self, record: dict[str, Any] | None, path: str, tier: str, keys: list[str] | None = None,
                 at: tuple[FileData, str, int] | None = None) -> None:
        self._record = record
        self._at = at  # (file, kind, index) of a record read only when needed
        self.keys: list[str] = keys if keys is not None else record["_keys"]  # type: ignore[index]
        self.path = path
        self.tier = tier

    @property
    def record(self) -> dict[str, Any]:
        if self._record is None:
            assert self._at is not None
            data, kind, index = self._at
            self._record = data.record_at(kind, index)
        return self._record

    @property
    def id(self) -> str:
        return str(self.record["id"])


class _Index:
    """Every lookup key of one kind, and the display names that are unambiguous.

    With the shipped files' merged keys (:class:`_ShippedKeys`) an id or alias
    is found without merging every file's keys; the merge is made only when a
    name is not found that way, or every key is wanted.
    """

    def __init__(self, merge: Callable[[], dict[str, _Entry]], shipped: _ShippedKeys | None = None) -> None:
        self._merge = merge
        self._shipped = shipped
        self._keys: dict[str, _Entry] | None = None
        self._names: dict[str, _Entry | None] | None = None
        self._entries: list[_Entry] | None = None

    @property
    def keys(self) -> dict[str, _Entry]:
        """Every lookup key (normalized id or alias) -> its entry."""
        if self._keys is None:
            self._keys = self._merge()
            self._shipped = None
        return self._keys

    @property
    def entries(self) -> list[_Entry]:
        """The presets in effect, sorted by id."""
        if self._entries is None:
            unique = {id(entry): entry for entry in self.keys.values()}
            self._entries = sorted(unique.values(), key=lambda e: e.id)
        return self._entries

    @property
    def names(self) -> dict[str, _Entry | None]:
        """Normalized display name -> entry (None when two presets share the name)."""
        if self._names is None:
            names: dict[str, _Entry | None] = {}
            for entry in self.entries:
                key = normalize(str(entry.record.get("name", "")))
                if key and key not in self.keys:
                    names[key] = None if key in names and names[key] is not entry else entry
            self._names = names
        return self._names

    def find(self, key: str) -> _Entry | None:
        if self._shipped is not None:
            entry = self._shipped.get(key)
            if entry is not None:
                return entry
        return self.keys.get(key) or self.names.get(key)


class _ShippedKeys:
    """One kind's keys merged over the shipped files by the build (:func:`camtool.presets.shipped_records.shipped_key`), an
    entry made only for a key looked up. A key the merged keys cannot answer for, or whose value is not ``[file,
    index]`` of a file read naming a record with that key, is a miss (and the database merges every file's keys)."""

    def __init__(self, names: set[str], paths_by_name: dict[str, str], files: dict[str, FileData], kind: str,
                 tier: str) -> None:
        self.names, self.paths_by_name, self.files, self.kind, self.tier = names, paths_by_name, files, kind, tier
        self._made: dict[tuple[str, int], _Entry] = {}

    def get(self, key: str) -> _Entry | None:
        from camtool.presets.shipped_records import shipped_key

        at = shipped_key(self.names, self.kind, key)
        if not (isinstance(at, list) and len(at) == 2 and isinstance(at[0], str) and type(at[1]) is int
                and at[1] >= 0 and at[0] in self.paths_by_name):
            return None
        name, index = at
        entry = self._made.get((name, index))
        if entry is None:
            path = self.paths_by_name[name]
            data = self.files[path]
            try:
                record = data.record_at(self.kind, index)  # a record's ``_keys`` is a list, as every check holds
            except IndexError:
                return None
            entry = self._made[(name, index)] = _Entry(record, path, self.tier, at=(data, self.kind, index))
        return entry if key in entry.keys else None  # the record must carry the key it was found by


class Database:
    """Presets merged from the tiers of the search order; see :func:`load_db`.

    Look presets up with :meth:`sensor`, :meth:`camera`, :meth:`lens`,
    :meth:`prescription`, :meth:`scene` or :meth:`get`; list them with
    :meth:`names` and :meth:`all`.
    """

    def __init__(self, tiers: Sequence[paths.Tier], files: dict[str, FileData]) -> None:
        self.tiers = list(tiers)
        self._files = files
        self._indexes: dict[str, _Index] = {}
        self._built: dict[tuple[str, int], Any] = {}

    @property
    def files(self) -> list[tuple[str, str]]:
        """``(tier, path)`` of every file read, least important first."""
        return [(tier.name, path) for tier in self.tiers for path in tier.files]

    # --- lookup -----------------------------------------------------------------------------

    def get(self, kind: str, name: str) -> Preset:
        """The preset of ``kind`` (singular or plural) called ``name``, in any spelling.

        Raises :class:`PresetNotFound` (with suggestions) when there is none,
        and :class:`PresetFileError` when the preset names another that does
        not exist.
        """
        kind = kind_of(kind)
        if kind == "lens" and "@" in str(name):
            return self._set_member(str(name))
        entry = self._index(kind).find(normalize(str(name)))
        if entry is None:
            if kind == "sensor":
                camera = self._index("camera").find(normalize(str(name)))
                if camera is not None:
                    return self._build("camera", camera).sensor
            raise PresetNotFound(kind, str(name), self.suggestions(kind, str(name)))
        return self._build(kind, entry)

    def _set_member(self, name: str) -> Lens:
        """``SET@FOCAL``: the member of a lens set at that focal length (``cooke-s4i@50``)."""
        base, _at, focal = name.rpartition("@")
        lens = self.get("lens", base)
        try:
            wanted = float(focal.strip().removesuffix("mm"))
        except ValueError:
            wanted = float("nan")
        found = lens.member(wanted) if wanted > 0 else None  # type: ignore[union-attr]
        if found is None:
            raise PresetNotFound("lens", name, [m.id for m in getattr(lens, "members", ())])
        return found

    def sensor(self, name: str) -> Sensor:
        """A sensor format by name; a camera's name gives that camera's sensor."""
        return self.get("sensor", name)  # type: ignore[return-value]

    def camera(self, name: str) -> Camera:
        """A camera body by name, its sensor resolved."""
        return self.get("camera", name)  # type: ignore[return-value]

    def lens(self, name: str) -> Lens:
        """A lens by name, its prescription (if any) resolved to a mapping."""
        return self.get("lens", name)  # type: ignore[return-value]

    def prescription(self, name: str) -> Prescription:
        """A lens prescription by name."""
        return self.get("prescription", name)  # type: ignore[return-value]

    def scene(self, name: str) -> Scene:
        """A named shot, its camera, sensor and lens resolved."""
        return self.get("scene", name)  # type: ignore[return-value]

    def film(self, name: str) -> Film:
        """A film's reciprocity data by name (the ``films`` kind of preset files)."""
        return self.get("film", name)  # type: ignore[return-value]

    def names(self, kind: str) -> list[str]:
        """The ids of every preset of ``kind`` in effect, sorted (for listings and shell completion)."""
        return [entry.id for entry in self._index(kind_of(kind)).entries]

    def all(self, kind: str) -> list[Preset]:
        """Every preset of ``kind`` in effect, sorted by id."""
        kind = kind_of(kind)
        kinds, wanted = [kind], 0
        while wanted < len(kinds):  # the kind and every kind its presets name (a lens's prescription ...)
            kinds += [k for k in REFERENCES.get(kinds[wanted], {}).values() if k not in kinds]
            wanted += 1
        for data in self._files.values():
            for each in kinds:
                data.records_of(each)  # each file's records of the kind at once (see loader._Cached.all)
        return [self._build(kind, entry) for entry in self._index(kind).entries]

    def shipped_listing(self, kind: str) -> list[list[Any]] | None:
        """``[id, name, aliases, summary, file]`` of every preset of ``kind``, in :meth:`all`'s order, written by the
        package's build (:mod:`camtool.presets.shipped`), when this database holds exactly the shipped files, each
        read for the bytes the build read; otherwise None (build the presets: :meth:`all`)."""
        names = self._shipped_names()
        if len(self.tiers) != 1 or names is None:
            return None
        from camtool.presets.shipped_records import shipped_listing

        rows = shipped_listing(names)
        return None if rows is None else rows.get(kind_of(kind), [])

    def find(self, name: str) -> list[Preset]:
        """The presets of every kind that answer to ``name`` (for ``camtool presets show``)."""
        key = normalize(str(name))
        found = []
        for kind in KINDS:
            entry = self._index(kind).find(key)
            if entry is not None:
                found.append(self._build(kind, entry))
        return found

    def suggestions(self, kind: str, name: str, limit: int = 3) -> list[str]:
        """Ids of the presets whose names are closest to ``name``."""
        index = self._index(kind_of(kind))
        key = normalize(name)
        candidates = {**{k: e for k, e in index.names.items() if e is not None}, **index.keys}
        out: list[str] = []
        import difflib

        for match in difflib.get_close_matches(key, list(candidates), n=limit * 2, cutoff=0.6):
            if candidates[match].id not in out:
                out.append(candidates[match].id)
        if key and len(out) < limit:
            containing = sorted((k for k in candidates if key in k), key=len)
            for match in containing:
                if candidates[match].id not in out:
                    out.append(candidates[match].id)
                if len(out) >= limit:
                    break
        return out[:limit]

    # --- index --------------------------------------------------------------------------------

    def _index(self, kind: str) -> _Index:
        index = self._indexes.get(kind)
        if index is None:
            index = self._indexes[kind] = _Index(lambda: self._merge(kind), self._shipped_keys(kind))
        return index

    def _shipped_names(self) -> set[str] | None:
        """The names under ``lens_db/`` of the first tier's files when it is the shipped tier and each of its files
        was read for the bytes its shipped records were made from (else None)."""
        if not self.tiers or self.tiers[0].name != "shipped":
            return None
        names = {self._files[path].shipped_name for path in self.tiers[0].files}
        if None in names or len(names) != len(self.tiers[0].files):
            return None
        return names  # type: ignore[return-value]

    def _shipped_keys(self, kind: str) -> _ShippedKeys | None:
        """The build's merged keys of ``kind`` (:class:`_ShippedKeys`) when the shipped files, as the build read them,
        are the only files with presets of that kind (else None: the keys of every file are merged)."""
        names = self._shipped_names()
        if names is None or any(self._files[path].keys_of(kind) for tier in self.tiers[1:] for path in tier.files):
            return None
        paths_by_name = {str(self._files[path].shipped_name): path for path in self.tiers[0].files}
        return _ShippedKeys(names, paths_by_name, self._files, kind, self.tiers[0].name)

    def _merge(self, kind: str) -> dict[str, _Entry]:
        keys: dict[str, _Entry] = {}
        for tier in self.tiers:
            tier_keys: dict[str, _Entry] = {}
            for path in tier.files:
                data = self._files[path]
                for index, record_keys in enumerate(data.keys_of(kind)):
                    entry = _Entry(None, path, tier.name, record_keys, (data, kind, index))
                    for position, key in enumerate(record_keys):
                        other = tier_keys.get(key)
                        if other is not None:
                            raise _clash(kind, entry, position, other)
                        tier_keys[key] = entry
            if not keys:  # the first tier with presets of the kind: nothing to replace
                keys = tier_keys
                continue
            for key, entry in tier_keys.items():
                old = keys.get(key)
                # the same (normalized) id: the later tier's preset replaces the earlier, aliases included
                if old is not None and key == entry.keys[0] and old.keys[0] == key:
                    for old_key in old.keys:
                        if keys.get(old_key) is old:
                            del keys[old_key]
            keys.update(tier_keys)
        return keys

    # --- building presets -----------------------------------------------------------------------

    def _build(self, kind: str, entry: _Entry) -> Any:
        memo = (kind, id(entry.record))
        preset = self._built.get(memo)
        if preset is None:
            preset = self._built[memo] = _BUILDERS[kind](self, entry)
        return preset

    def _reference(self, entry: _Entry, kind: str, key: str) -> Any:
        """Resolve the preset that ``key`` of ``entry`` names, or raise naming the entry's file."""
        target = REFERENCES[kind][key]
        name = entry.record[key]
        try:
            return self.get(target, name)
        except PresetNotFound as error:
            raise PresetFileError(entry.path, str(error), line=entry.record["_refs"].get(key) or entry.record["_line"],
                                  kind=kind, preset_id=entry.id, key=key) from None

    def _existing(self, entry: _Entry, kind: str, key: str) -> str:
        """The id of the preset that ``key`` of ``entry`` names, found without building it (else as :meth:`_reference`).

        A camera's lens is looked up this way: the lens's own ``sensor`` may
        name the camera (a compact whose body size has no sensor preset), and
        building one from the other would never end.
        """
        target = REFERENCES[kind][key]
        name = str(entry.record[key])
        found = self._index(target).find(normalize(name))
        if found is None:
            error = PresetNotFound(target, name, self.suggestions(target, name))
            raise PresetFileError(entry.path, str(error), line=entry.record["_refs"].get(key) or entry.record["_line"],
                                  kind=kind, preset_id=entry.id, key=key)
        return found.id


def _clash(kind: str, entry: _Entry, position: int, other: _Entry) -> PresetFileError:
    record = entry.record
    what = "id" if position == 0 else "alias"
    spelled = record["id"] if position == 0 else _alias_for(record, record["_keys"][position])
    where = f"{other.path}:{other.record['_line']}" if other.record.get("_line") else other.path
    return PresetFileError(
        entry.path,
        f"{what} {spelled!r} is already used by {kind} {other.id!r} ({where}); ids and aliases must be unique",
        line=record.get("_line"), kind=kind, preset_id=record["id"], key="id" if position == 0 else "aliases")


def _alias_for(record: dict[str, Any], key: str) -> str:
    return next((a for a in record.get("aliases", ()) if normalize(a) == key), key)


def _common(entry: _Entry) -> dict[str, Any]:
    record = entry.record
    return {"aliases": tuple(record.get("aliases", ())), "source": record.get("source"),
            "notes": record.get("notes"), "origin": entry.path, "tier": entry.tier}


def _build_sensor(db: Database, entry: _Entry) -> Sensor:
    r = entry.record
    return Sensor(r["id"], r["name"], r["width_mm"], r["height_mm"], r.get("coc_mm"),
                  category=r.get("category"), approximate=r.get("approximate", False), **_common(entry))


def _build_camera(db: Database, entry: _Entry) -> Camera:
    r = entry.record
    sensor_value = r["sensor"]
    if isinstance(sensor_value, dict):
        sensor = Sensor(f"{r['id']}-sensor", sensor_value.get("name", f"{r['name']} sensor"),
                        sensor_value["width_mm"], sensor_value["height_mm"], sensor_value.get("coc_mm"),
                        approximate=r.get("approximate", False), source=r.get("source"), origin=entry.path,
                        tier=entry.tier)
    else:
        sensor = db._reference(entry, "camera", "sensor")
    lens_id = db._existing(entry, "camera", "lens") if "lens" in r else None
    return Camera(r["id"], r["name"], sensor, r.get("pixels_w"), r.get("pixels_h"), r.get("mount"),
                  category=r.get("category"), approximate=r.get("approximate", False), lens_id=lens_id,
                  **_common(entry))


def _build_lens(db: Database, entry: _Entry) -> Lens:
    r = entry.record
    if "set" in r:
        return _build_lens_set(entry)
    focal_min = r.get("focal_min_mm", r.get("focal_length_mm"))
    focal_max = r.get("focal_max_mm", r.get("focal_length_mm"))
    assert focal_min is not None and focal_max is not None  # the schema requires one of the two spellings
    prescription = db._reference(entry, "lens", "prescription") if "prescription" in r else None
    sensor = db._reference(entry, "lens", "sensor") if "sensor" in r else None
    sensor_id = sensor.id if sensor else None
    if sensor is not None and db._index("sensor").find(normalize(sensor.id)) is None:
        # the lens names a camera, whose own size has no sensor preset (a compact's): keep the
        # name it was given, which finds that camera's sensor again
        sensor_id = str(r["sensor"])
    return Lens(
        r["id"], r["name"], float(focal_min), float(focal_max), r.get("f_number_min"), r.get("f_number_max"),
        r.get("f_number_min_tele"), r.get("min_focus_mm"), r.get("max_magnification"),
        r.get("pupil_magnification"), r.get("hiatus_mm"),
        prescription_id=prescription.id if prescription else None,
        prescription=prescription.optics if prescription else None,
        sensor_id=sensor_id, mount=r.get("mount"), category=r.get("category"),
        f_number_max_tele=r.get("f_number_max_tele"),
        approximate=r.get("approximate", False), min_magnification=r.get("min_magnification"),
        close_focus=tuple((row["focal_length_mm"], row["min_focus_mm"], row.get("max_magnification"))
                          for row in r.get("close_focus", ())), t_number_min=r.get("t_number_min"),
        tilt_max_deg=r.get("tilt_max_deg"), focus_at_max_magnification_mm=r.get("focus_at_max_magnification_mm"),
        projection=r.get("projection"), field_max_deg=r.get("field_max_deg"), squeeze=r.get("squeeze"),
        **_common(entry))


def _build_lens_set(entry: _Entry) -> Lens:
    """A lens set and its members, each a prime named ``SET-ID@FOCAL`` (``cooke-s4i@50``)."""
    r = entry.record
    common = _common(entry)
    shared = {"mount": r.get("mount"), "category": r.get("category"), "approximate": r.get("approximate", False),
              "squeeze": r.get("squeeze"),
              "sensor_id": str(r["sensor"]) if "sensor" in r else None,
              "source": common["source"], "notes": common["notes"], "origin": common["origin"], "tier": common["tier"]}
    members = tuple(
        Lens(f"{r['id']}@{row['focal_length_mm']:g}", f"{r['name']} {row['focal_length_mm']:g}mm",
             row["focal_length_mm"], row["focal_length_mm"], row.get("f_number_min"), r.get("f_number_max"),
             min_focus_mm=row.get("min_focus_mm"), max_magnification=row.get("max_magnification"),
             t_number_min=row.get("t_number_min"), **shared)
        for row in r["set"])
    return Lens(r["id"], r["name"], members[0].focal_min_mm, members[-1].focal_min_mm, None, r.get("f_number_max"),
                members=members, **{**shared, "aliases": common["aliases"]})


def _build_prescription(db: Database, entry: _Entry) -> Prescription:
    from camtool.optics.prescription import prescription_from_mapping

    r = entry.record
    # validated when the file was read (schema._check_prescription); building it cannot fail
    optics = prescription_from_mapping(optics_mapping(r), source=r["id"])
    return Prescription(r["id"], r["name"], r["_data"], r.get("focal_length_mm"), r.get("f_number"),
                        r.get("wavelength_nm"), **_common(entry), optics=optics)


def _build_scene(db: Database, entry: _Entry) -> Scene:
    r = entry.record
    camera = db._reference(entry, "scene", "camera") if "camera" in r else None
    sensor = db._reference(entry, "scene", "sensor") if "sensor" in r else (camera.sensor if camera else None)
    lens = db._reference(entry, "scene", "lens") if "lens" in r else None
    return Scene(r["id"], r["name"], camera, sensor, lens, r.get("focal_length_mm"), r.get("f_number"),
                 r.get("distance_mm"), r.get("subject_size_mm"), r.get("background_mm"), r.get("coc_mm"),
                 magnification=r.get("magnification"), **_common(entry))


def _build_film(db: Database, entry: _Entry) -> Film:
    r = entry.record
    return Film(r["id"], r["name"], r.get("p"), r.get("threshold_s"), r.get("points", ()), r.get("valid_to_s"),
                **_common(entry))


_BUILDERS = {
    "film": _build_film,
    "sensor": _build_sensor,
    "camera": _build_camera,
    "lens": _build_lens,
    "prescription": _build_prescription,
    "scene": _build_scene,
}


# --- entry points -----------------------------------------------------------------------------


def load_db(extra_files: Iterable[str | os.PathLike[str]] = (), *, use_cache: bool = True,
            lensfun: bool = True) -> Database:
    """Load the preset database in the search order of docs/design.md §5.

    shipped ``lens_db/`` < lensfun import < ``$XDG_CONFIG_DIRS/camtool`` <
    ``$XDG_CONFIG_HOME/camtool`` < each of ``extra_files`` in order; a later
    tier replaces an earlier preset with the same id. Every file is read now
    (a broken one raises :class:`PresetFileError`); parsed files are cached
    under ``$XDG_CACHE_HOME/camtool/presets`` unless ``use_cache`` is false
    or ``CAMTOOL_NO_CACHE`` is set (a cached record is used only after the
    checks of :mod:`camtool.presets.loader`).

    >>> db = load_db(use_cache=False, lensfun=False)
    >>> db.sensor("Full Frame").width_mm, db.sensor("m43").id
    (36.0, 'four-thirds')
    """
    tiers = paths.tiers(tuple(os.fspath(p) for p in extra_files), lensfun=lensfun)
    from camtool.core.cache import enabled

    cache = paths.cache_dir() if use_cache and enabled() else None
    files: dict[str, FileData] = {}
    for tier in tiers:
        for path in tier.files:
            if path not in files:
                files[path] = read_file(path, cache_dir=cache)
    return Database(tiers, files)


def validate_file(path: str | os.PathLike[str]) -> list[str]:
    """Every problem of one preset file, as one-line messages (empty when the file is good).

    Checks the YAML, every key of every preset, ids and aliases that clash
    within the file, and that every name it refers to (a camera's sensor, a
    lens's prescription, a scene's lens ...) exists in the file or in the
    database it would be loaded with (the shipped presets alone when the
    user's other files are broken).
    """
    path = os.fspath(path)
    data = parse_file(path)
    messages = [str(problem.error(path)) for problem in data.problems]
    for kind in KINDS:
        seen: dict[str, _Entry] = {}
        for record in data.records.get(kind, ()):
            entry = _Entry(record, path, "file")
            for position, key in enumerate(record["_keys"]):
                if key in seen:
                    messages.append(str(_clash(kind, entry, position, seen[key])))
                else:
                    seen[key] = entry
    if data.problems and not any(data.records.values()):
        return messages
    target = os.path.abspath(path)
    try:
        base = load_db()
        tiers, files = base.tiers, dict(base._files)
    except PresetFileError:
        tiers = paths.tiers(lensfun=False)[:1]
        files = {p: read_file(p) for tier in tiers for p in tier.files}
    tiers = [paths.Tier(t.name, tuple(f for f in t.files if os.path.abspath(f) != target)) for t in tiers]
    tiers.append(paths.Tier(f"--presets {path}", (path,)))
    files[path] = data
    db = Database(tiers, files)
    for kind in KINDS:
        for record in data.records.get(kind, ()):
            try:
                db._build(kind, _Entry(record, path, "file"))
            except PresetFileError as error:
                messages.append(str(error))
    return list(dict.fromkeys(messages))
