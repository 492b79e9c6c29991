"""The records of the shipped preset files ship with the package: current, used only for their very bytes, checked.

``camtool/presets/shipped-records.json`` (``python -m camtool.presets.shipped``) spares a first command
(every cache empty) the YAML parse of ``lens_db/``. These tests hold it to a fresh parse of the files,
and hold that a shipped record which fails the checks of a cache entry's records is never used. (A shipped
record with other values that pass every check -- 36 × 24 mm for APS-C -- cannot be told from the file
without parsing it: the file is the package's own data, as trusted as its code, and the first test holds
it to a fresh parse.)
"""

from __future__ import annotations

import json
import os
import subprocess
import sys
from pathlib import Path

import pytest
from conftest import point_xdg_at

from camtool.presets import PresetNotFound, load_db, loader, paths, shipped, shipped_records


def test_the_shipped_records_are_a_fresh_parse_of_the_shipped_files() -> None:
    current = Path(shipped.targets()["records"]).read_bytes()
    assert current == shipped.build_records(), \
        "camtool/presets/shipped-records.json is out of date: run python -m camtool.presets.shipped"
    index = json.loads(current.split(b"\n", 1)[0])
    assert sorted(index["files"]) == sorted(os.path.relpath(p, paths.shipped_dir()).replace(os.sep, "/")
                                            for p in paths.shipped_files())


@pytest.fixture()
def cache_home(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> Path:
    point_xdg_at(tmp_path, monkeypatch)
    monkeypatch.delenv("CAMTOOL_NO_CACHE", raising=False)
    return tmp_path


def test_shipped_records_answer_only_for_the_bytes_they_were_made_from(tmp_path: Path) -> None:
    sensors = os.path.join(paths.shipped_dir(), "sensors.yaml")
    raw = Path(sensors).read_bytes()
    assert loader.shipped_payload(sensors, raw) is not None
    assert loader.shipped_payload(sensors, raw + b"\n# edited\n") is None  # the same file, other bytes
    copy = tmp_path / "sensors.yaml"
    copy.write_bytes(raw)
    assert loader.shipped_payload(str(copy), raw) is None  # the same bytes, not a shipped file


def test_a_first_load_from_the_shipped_records_is_the_parsed_database(cache_home: Path) -> None:
    fresh = load_db(use_cache=False, lensfun=False)
    first = load_db(lensfun=False)  # every cache empty: the shipped records answer, no cache entry is written
    assert not list((cache_home / "xdg_cache_home" / "camtool" / "presets").glob("sensors.yaml-*.json"))
    for kind in ("sensor", "camera", "lens", "prescription", "scene"):
        assert first.all(kind) == fresh.all(kind), kind


def _poison(monkeypatch: pytest.MonkeyPatch, change) -> None:
    index, body = shipped_records._shipped_records()
    start, length = index["sensors.yaml"][1:3]
    payload = body[start:start + length]
    end = payload.index(b"\n")
    spans = json.loads(payload[:end])
    sections = {name: json.loads(payload[end + 1 + o:end + 1 + o + n]) for name, (o, n) in spans.items()}
    change(sections)
    new_spans, blobs, offset = {}, [], 0
    for name, value in sections.items():
        blob = json.dumps(value).encode()
        new_spans[name] = [offset, len(blob)]
        blobs.append(blob)
        offset += len(blob)
    poisoned = json.dumps(new_spans).encode() + b"\n" + b"".join(blobs)
    # the sections' recorded digests stay the build's: the poisoned sections do not have them
    files = {**index, "sensors.yaml": [index["sensors.yaml"][0], len(body), len(poisoned), index["sensors.yaml"][3]]}
    monkeypatch.setattr(shipped_records, "_shipped_index", {"index": files, "body": body[0:len(body)] + poisoned})


def _aps_c(sections) -> dict:
    return next(r for r in sections["sensor"] if r["id"] == "aps-c")


@pytest.mark.parametrize("change", [
    lambda s: _aps_c(s).update(width_mm=-1.0),
    lambda s: _aps_c(s).update(width_mm="23.6"),
    lambda s: _aps_c(s).update(_keys=["fullframe"]),
    lambda s: _aps_c(s).update(extra=1),
    lambda s: s.update(sensor={"0": 1}),
    lambda s: s.update({"sensor#keys": s["sensor#keys"][:-1]}),
    lambda s: s.update({"sensor#spans": [s["sensor#spans"][0]] * len(s["sensor#spans"])}),
    lambda s: s.update({"sensor#spans": s["sensor#spans"][:-1]}),
], ids=["a negative width", "a width as text", "another preset's keys", "an unknown key", "not a list",
        "keys shorter", "every span the first record's", "spans shorter"])
def test_a_shipped_record_that_is_not_its_file_is_never_used(change, cache_home: Path,
                                                              monkeypatch: pytest.MonkeyPatch) -> None:
    expected = load_db(use_cache=False, lensfun=False).sensor("aps-c")
    _poison(monkeypatch, change)
    got = load_db(lensfun=False).sensor("aps-c")
    assert (got.width_mm, got.height_mm) == (expected.width_mm, expected.height_mm) == (23.6, 15.6)


def test_a_lookup_parses_only_the_record_it_finds(cache_home: Path) -> None:
    # only the one record's span is read, checked against the digest the build recorded for it, and parsed
    fresh = load_db(use_cache=False, lensfun=False)
    database = load_db(lensfun=False)
    assert database.lens("nikon-z-50mm-f1.8-s") == fresh.lens("nikon-z-50mm-f1.8-s")
    path = next(p for p in database._files if p.endswith(os.sep + "lenses.yaml"))
    cached = database._files[path]._cached
    assert cached is not None and cached.digests is not None
    assert "lens" not in cached._parsed and "lens#keys" not in cached._parsed  # neither the records nor the keys
    assert len(cached._checked) == 1  # one record, not the file's 168


def test_a_first_command_parses_no_yaml(tmp_path: Path) -> None:
    code = ("import sys\n"
            "sys.argv = ['camtool', 'dof', '--lens', 'dgauss100-lens', '-N', '4', '-s', '2m', '--format', 'json']\n"
            "from camtool.cli import main\n"
            "try:\n    main()\nexcept SystemExit as done:\n    assert not done.code, done.code\n"
            "print(sorted(m for m in ('yaml', 'numpy') if m in sys.modules), file=sys.stderr)\n")
    env = {**os.environ, "XDG_CACHE_HOME": str(tmp_path / "cache"), "XDG_CONFIG_HOME": str(tmp_path / "config"),
           "XDG_DATA_HOME": str(tmp_path / "data")}
    env.pop("CAMTOOL_NO_CACHE", None)
    run = subprocess.run([sys.executable, "-c", code], env=env, capture_output=True, text=True, check=True)
    assert run.stderr.strip().splitlines()[-1] == "[]"  # every cache empty: no YAML parse, no ray trace


def test_the_shipped_records_are_used_on_their_digest_without_a_second_schema_check(cache_home: Path,
                                                                                   monkeypatch: pytest.MonkeyPatch):
    # the build's parse checked every record; a span with the digest the build recorded is that parse's output
    fresh = load_db(use_cache=False, lensfun=False)

    def refuse(kind, record):
        raise AssertionError("a shipped record went through the cache's schema check again")

    monkeypatch.setattr(loader, "_valid_record", refuse)
    first = load_db(lensfun=False)
    for kind in ("sensor", "camera", "lens", "prescription", "scene"):
        assert first.all(kind) == fresh.all(kind), kind


def _built_rows(database, **kwargs):
    """The listing made preset by preset (the database's shipped listing not used)."""
    from camtool.plans.presets import list_presets

    class Building:
        def __getattr__(self, name):
            return getattr(database, name)

        def shipped_listing(self, kind):
            return None

    return list_presets(database=Building(), **kwargs)


@pytest.mark.parametrize("kwargs", [{}, {"kind": "lens"}, {"kind": "camera", "search": "nikon"}, {"search": "50mm"}])
def test_the_shipped_listing_is_the_listing_built_preset_by_preset(cache_home: Path, kwargs) -> None:
    from camtool.plans.presets import list_presets

    database = load_db(lensfun=False)
    assert database.shipped_listing("lens")  # the shipped files alone: the build's listing answers
    rows = list_presets(database=database, **kwargs)
    assert rows and rows == _built_rows(load_db(lensfun=False), **kwargs)


def _user_full_frame(cache_home: Path) -> None:
    """A user's preset file (in $XDG_CONFIG_HOME/camtool) giving full frame as 35.8 x 23.9 mm."""
    config = cache_home / "xdg_config_home" / "camtool"
    config.mkdir(parents=True)
    (config / "mine.yaml").write_text("sensors:\n  - id: full-frame\n    name: Full frame\n    width_mm: 35.8\n"
                                      "    height_mm: 23.9\n", encoding="utf-8")


def test_the_shipped_listing_is_not_used_beside_another_file(cache_home: Path) -> None:
    from camtool.plans.presets import list_presets

    _user_full_frame(cache_home)
    database = load_db(lensfun=False)
    assert database.shipped_listing("camera") is None
    rows = list_presets(database=database)
    assert rows == _built_rows(database)
    assert [r.summary for r in rows if r.kind == "sensor" and r.id == "full-frame"] == ["35.8 × 23.9 mm"]
    # a shipped camera on that sensor is listed with the user's size
    z8 = next(r for r in rows if r.kind == "camera" and r.id == "nikon-z-8")
    assert "35.8 × 23.9 mm" in z8.summary


def test_the_shipped_listing_is_not_used_for_an_edited_or_an_added_file(cache_home: Path, tmp_path: Path,
                                                                     monkeypatch: pytest.MonkeyPatch) -> None:
    import shutil

    from camtool.plans.presets import list_presets

    copy = tmp_path / "lens_db"
    shutil.copytree(paths.shipped_dir(), copy)
    monkeypatch.setattr(paths, "shipped_dir", lambda: str(copy))
    assert load_db(lensfun=False).shipped_listing("sensor")
    sensors = copy / "sensors.yaml"
    sensors.write_text(sensors.read_text(encoding="utf-8").replace("    width_mm: 36.0\n", "    width_mm: 35.9\n", 1),
                       encoding="utf-8")
    database = load_db(lensfun=False)
    assert database.shipped_listing("sensor") is None
    rows = list_presets(database=database, kind="sensor")
    assert next(r.summary for r in rows if r.id == "full-frame") == "35.9 × 24 mm"
    sensors.write_bytes((Path(paths.__file__).parents[2] / "lens_db" / "sensors.yaml").read_bytes())
    assert load_db(lensfun=False).shipped_listing("sensor")  # the file as shipped again
    (copy / "extra.yaml").write_text("scenes:\n  - id: my-scene\n    name: Mine\n    distance: 3m\n", encoding="utf-8")
    database = load_db(lensfun=False)
    assert database.shipped_listing("scene") is None
    assert "my-scene" in [r.id for r in list_presets(database=database, kind="scene")]


def test_a_listing_without_its_digest_is_not_used(cache_home: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    from camtool.plans.presets import list_presets

    index, body = shipped_records._shipped_records()
    start, length, digest = shipped_records._shipped_index["listing"]
    blob = body[start:start + length].replace(b'"36 \\u00d7 24 mm"', b'"99 \\u00d7 24 mm"').replace(
        "36 × 24 mm".encode(), "99 × 24 mm".encode())
    assert blob != body[start:start + length]
    monkeypatch.setattr(shipped_records, "_shipped_index", {"index": index, "body": body[0:len(body)] + blob,
                                                   "listing": [len(body), len(blob), digest]})
    database = load_db(lensfun=False)
    assert database.shipped_listing("sensor") is None
    rows = list_presets(database=database, kind="sensor")
    assert next(r.summary for r in rows if r.id == "full-frame") == "36 × 24 mm"


def test_the_shipped_records_file_is_read_by_span_and_only_when_regular(tmp_path: Path) -> None:
    data = b'{"files":{}}\n' + bytes(range(256)) * 8
    regular = tmp_path / "records.json"
    regular.write_bytes(data)
    spans = shipped_records._open_spans(str(regular), 1 << 20)
    assert spans is not None and len(spans) == len(data)
    window = shipped_records.Window(spans, 13, len(data) - 13)
    assert window[0:5] == data[13:18] and window[2040:99999] == data[13 + 2040:]
    assert shipped_records.Window(spans, 0, len(data)).find(b"\n") == 12 and window.find(b"\xff\x00\x01") == 255
    regular.write_bytes(data[:100])  # shorter than when opened: a span past the end comes back short
    assert window[0:200] == data[13:100]
    assert shipped_records._open_spans(str(regular), 50) is None  # larger than the limit
    assert shipped_records._open_spans(str(tmp_path), 1 << 20) is None  # a directory
    assert shipped_records._open_spans(str(tmp_path / "missing.json"), 1 << 20) is None
    os.mkfifo(tmp_path / "fifo")
    assert shipped_records._open_spans(str(tmp_path / "fifo"), 1 << 20) is None  # opened without blocking, refused


def test_a_shipped_file_behind_a_symbolic_link_is_found_by_its_real_path(tmp_path: Path,
                                                                          monkeypatch: pytest.MonkeyPatch) -> None:
    # the shipped directory's files are taken as their own real paths with one lstat; a link is resolved
    import shutil

    copy = tmp_path / "lens_db"
    shutil.copytree(paths.shipped_dir(), copy)
    outside = tmp_path / "elsewhere"
    outside.mkdir()
    (copy / "sensors.yaml").rename(outside / "sensors.yaml")
    (copy / "sensors.yaml").symlink_to(outside / "sensors.yaml")
    shutil.move(str(copy / "prescriptions"), str(outside / "prescriptions"))
    (copy / "prescriptions").symlink_to(outside / "prescriptions")
    monkeypatch.setattr(paths, "shipped_dir", lambda: str(copy))
    for path in [copy / "sensors.yaml", copy / "cameras.yaml", copy / "prescriptions" / "dgauss100.yaml"]:
        assert shipped_records.real_path(str(path)) == os.path.realpath(path)
    raw = (outside / "sensors.yaml").read_bytes()
    assert loader.shipped_payload(str(copy / "sensors.yaml"), raw) is None  # really a file outside lens_db/
    assert loader.shipped_payload(str(copy / "cameras.yaml"), (copy / "cameras.yaml").read_bytes()) is not None


KINDS = ("sensor", "camera", "lens", "prescription", "scene", "film")


def test_the_merged_keys_find_what_every_file_merged_finds(cache_home: Path) -> None:
    # every id and alias of every kind, found through the build's merged keys, is the preset the merge of every
    # file's keys finds (the same file and record); a name that is no key is left to the merge
    fresh = load_db(use_cache=False, lensfun=False)
    database = load_db(lensfun=False)
    for kind in KINDS:
        merged = fresh._merge(kind)
        index = database._index(kind)
        assert index._shipped is not None, kind
        for key, entry in merged.items():
            found = index._shipped.get(key)
            assert found is not None and (found.path, found.id) == (entry.path, entry.id), (kind, key)
        assert index._keys is None  # found without merging
    assert database._index("lens")._shipped.get("no-such-lens-at-all") is None


def test_a_lookup_through_the_merged_keys_reads_one_file(cache_home: Path) -> None:
    fresh = load_db(use_cache=False, lensfun=False)
    database = load_db(lensfun=False)
    assert database.lens("NIKKOR Z 50mm f/1.8 S") == fresh.lens("nikon-z-50mm-f1.8-s")  # by display name: merged
    assert database._indexes["lens"]._keys is not None
    database = load_db(lensfun=False)
    assert database.lens("Nikon Z 50mm F1.8 S") == fresh.lens("nikon-z-50mm-f1.8-s")  # by id, in another spelling
    assert database._indexes["lens"]._keys is None  # no file's keys merged
    touched = [path for path, data in database._files.items() if data._cached is not None and data._cached._checked]
    assert [os.path.basename(p) for p in touched] == ["lenses.yaml"]
    for data in database._files.values():
        assert data._cached is None or not any(name.endswith("#keys") for name in data._cached._parsed)


def test_the_merged_keys_are_not_used_beside_a_file_with_presets_of_the_kind(cache_home: Path) -> None:
    _user_full_frame(cache_home)
    database = load_db(lensfun=False)
    assert database._index("sensor")._shipped is None
    assert database.sensor("full-frame").width_mm == 35.8  # the user's preset replaces the shipped one
    assert database._index("camera")._shipped is not None  # no camera in the user's file: the merged keys answer
    assert database.camera("nikon-z-8").sensor.width_mm == 35.8  # a shipped camera on the user's sensor
    with pytest.raises(PresetNotFound, match="unknown sensor 'ff'"):
        database.sensor("ff")  # aliases and all


@pytest.mark.parametrize("change", ["bucket digest", "table digest", "another record", "a file not read",
                                    "not a pair"])
def test_merged_keys_that_are_not_the_build_s_are_a_miss(change, cache_home: Path,
                                                         monkeypatch: pytest.MonkeyPatch) -> None:
    expected = load_db(use_cache=False, lensfun=False).lens("nikon-z-50mm-f1.8-s")
    key = loader.normalize("nikon-z-50mm-f1.8-s")
    assert load_db(lensfun=False).lens(key) == expected
    bucket = shipped_records.key_bucket(key)
    state = shipped_records._shipped_index
    assert state is not None
    table = state["merged"]["lens"]
    monkeypatch.setitem(state, "merged", {})
    if change == "bucket digest":
        spans = [list(span) for span in table]
        spans[bucket][2] = "0" * 64
        monkeypatch.setitem(state["merged"], "lens", spans)
    elif change == "table digest":
        monkeypatch.setitem(state, "keys", {**state["keys"], "lens": [*state["keys"]["lens"][:2], "0" * 64]})
    else:
        value = {"another record": ["lenses.yaml", 0], "a file not read": ["elsewhere.yaml", 3],
                 "not a pair": ["lenses.yaml"]}[change]
        monkeypatch.setitem(state["merged"], "lens", table)
        monkeypatch.setitem(state["merged"], ("lens", bucket), {key: value})
    database = load_db(lensfun=False)
    assert database.lens(key) == expected
    assert database._indexes["lens"]._keys is not None  # answered by merging every file's keys


def test_the_shipped_films_are_listed_as_the_build_listed_them_only_for_its_bytes(
        cache_home: Path, tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    import camtool.exposure
    from camtool.exposure import films_path, reciprocity
    from camtool.plans.presets import list_presets

    database = load_db(lensfun=False)
    raw = Path(films_path()).read_bytes()
    assert shipped_records.shipped_films(raw) is not None
    assert shipped_records.shipped_films(raw + b"\n") is None  # other bytes
    rows = list_presets(database=database, kind="film")
    assert rows == _built_rows(database, kind="film") and len(rows) == len(reciprocity.load_films())
    assert list_presets(database=database, kind="film", search="hp5") == _built_rows(database, kind="film",
                                                                                      search="hp5")
    # films.yaml edited: its films are read and listed one by one, with the edit
    edited = tmp_path / "films.yaml"
    edited.write_bytes(raw.replace(b"name: Ilford HP5 Plus", b"name: Ilford HP5 Plus (edited)", 1))
    assert edited.read_bytes() != raw
    monkeypatch.setattr(camtool.exposure, "films_path", lambda: str(edited))
    monkeypatch.setattr(reciprocity, "films_path", lambda: str(edited))
    reciprocity.load_films.cache_clear()
    try:
        names = [r.name for r in list_presets(database=database, kind="film")]
    finally:
        reciprocity.load_films.cache_clear()
    assert "Ilford HP5 Plus (edited)" in names
    # a films listing without the digest the build recorded is not used
    monkeypatch.setattr(camtool.exposure, "films_path", films_path)
    state = shipped_records._shipped_index
    assert state is not None
    monkeypatch.setitem(state, "films", [*state["films"][:2], "0" * 64])
    assert shipped_records.shipped_films(raw) is None
