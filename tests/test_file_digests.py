"""The shipped preset files' digests, remembered against their ``stat`` (``camtool.core.cache.FileDigests``).

A command that names a preset binds the shipped records to the very bytes of the YAML they were made from
(``tests/test_presets_shipped.py``). Hashing every shipped file on every command cost about 2 ms, so each
file's SHA-256 is remembered in the cache against its size, modification and change times, inode and device.
These tests hold that a remembered digest is used only for a file that cannot have changed since, never for an
edited one (its modification time put back included), and that a bad entry is only a miss.
"""

from __future__ import annotations

import hashlib
import json
import os
import shutil
import time
from pathlib import Path

import pytest
from conftest import point_xdg_at

from camtool.core import cache
from camtool.presets import load_db, loader, paths


@pytest.fixture()
def cache_home(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> Path:
    point_xdg_at(tmp_path, monkeypatch)
    monkeypatch.delenv("CAMTOOL_NO_CACHE", raising=False)
    monkeypatch.setattr(loader, "_file_digests", {})
    return tmp_path


def _files(tmp_path: Path, count: int = 3) -> list[str]:
    out = []
    for n in range(count):
        path = tmp_path / f"f{n}.yaml"
        path.write_bytes(f"file {n}\n".encode() * (n + 1))
        out.append(str(path))
    return out


def _hash_all(digests: cache.FileDigests) -> None:
    for path in digests.paths:
        digests.put(path, Path(path).read_bytes())


def test_remembered_digests_are_the_files_sha256(cache_home: Path, tmp_path: Path,
                                                 monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setattr(cache, "_SETTLED_NS", 0)
    files = _files(tmp_path)
    entry = str(tmp_path / "digests.json")
    first = cache.FileDigests(entry, files)
    assert all(first.get(path) is None for path in files)  # nothing remembered yet
    _hash_all(first)
    second = cache.FileDigests(entry, files)
    for path in files:
        assert second.get(path) == hashlib.sha256(Path(path).read_bytes()).hexdigest()


def test_a_file_changed_within_two_seconds_is_not_remembered(cache_home: Path, tmp_path: Path) -> None:
    files = _files(tmp_path)  # just written: another write within the same clock tick would keep its times
    entry = tmp_path / "digests.json"
    _hash_all(cache.FileDigests(str(entry), files))
    assert not entry.exists()
    assert all(cache.FileDigests(str(entry), files).get(path) is None for path in files)


def test_an_edited_file_is_never_given_its_old_digest(cache_home: Path, tmp_path: Path,
                                                      monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setattr(cache, "_SETTLED_NS", 0)
    files = _files(tmp_path)
    entry = str(tmp_path / "digests.json")
    _hash_all(cache.FileDigests(entry, files))
    before = os.stat(files[1])
    Path(files[1]).write_bytes(b"FILE 1\n" * 2)  # the same size, its modification time put back
    os.utime(files[1], ns=(before.st_atime_ns, before.st_mtime_ns))
    later = cache.FileDigests(entry, files)
    assert all(later.get(path) is None for path in files)  # the change time moved: the entry is another file set's
    # and a file edited after its digests were read is not given the remembered one either
    _hash_all(later)
    again = cache.FileDigests(entry, files)
    assert again.get(files[0]) is not None
    time.sleep(0.01)
    Path(files[0]).write_bytes(b"FILE 0\n")
    assert again.get(files[0]) is None


@pytest.mark.parametrize("payload", [b"[]", b"{}", b'["x","y","z"]', b"not json", b'["' + b"0" * 64 + b'"]',
                                     json.dumps(["A" * 64] * 3).encode()])
def test_an_entry_of_the_wrong_shape_is_a_miss(payload: bytes, cache_home: Path, tmp_path: Path,
                                               monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setattr(cache, "_SETTLED_NS", 0)
    files = _files(tmp_path)
    entry = str(tmp_path / "digests.json")
    digests = cache.FileDigests(entry, files)
    cache.write(entry, cache.FileDigests.KIND, digests._source, payload)  # signed, bound to these files' stats
    assert all(cache.FileDigests(entry, files).get(path) is None for path in files)


def test_a_damaged_entry_is_a_miss_and_is_written_again(cache_home: Path, tmp_path: Path,
                                                        monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setattr(cache, "_SETTLED_NS", 0)
    files = _files(tmp_path)
    entry = tmp_path / "digests.json"
    _hash_all(cache.FileDigests(str(entry), files))
    data = bytearray(entry.read_bytes())
    data[-5] ^= 1
    entry.write_bytes(bytes(data))
    damaged = cache.FileDigests(str(entry), files)
    assert all(damaged.get(path) is None for path in files)
    _hash_all(damaged)
    assert all(cache.FileDigests(str(entry), files).get(path) is not None for path in files)


def test_a_second_load_reads_no_shipped_file(cache_home: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setattr(cache, "_SETTLED_NS", 0)
    fresh = load_db(use_cache=False, lensfun=False)
    load_db(lensfun=False)
    monkeypatch.setattr(loader, "_file_digests", {})  # as a new process would
    read: list[str] = []
    real_read = loader.read_bytes

    def counting(path, limit):
        read.append(str(path))
        return real_read(path, limit)

    monkeypatch.setattr(loader, "read_bytes", counting)
    second = load_db(lensfun=False)
    shipped = {os.path.abspath(p) for p in paths.shipped_files()}
    assert not shipped & {os.path.abspath(p) for p in read}
    for kind in ("sensor", "camera", "lens", "prescription", "scene"):
        assert second.all(kind) == fresh.all(kind), kind


def test_a_shipped_file_edited_in_place_is_read_again(cache_home: Path, tmp_path: Path,
                                                      monkeypatch: pytest.MonkeyPatch) -> None:
    # a copy of lens_db/ stands for an installed package whose YAML someone edits, keeping size and mtime
    monkeypatch.setattr(cache, "_SETTLED_NS", 0)
    copy = tmp_path / "lens_db"
    shutil.copytree(paths.shipped_dir(), copy)
    monkeypatch.setattr(paths, "shipped_dir", lambda: str(copy))
    assert load_db(lensfun=False).sensor("full-frame").width_mm == 36.0
    monkeypatch.setattr(loader, "_file_digests", {})
    load_db(lensfun=False)  # the digests are now remembered
    sensors = copy / "sensors.yaml"
    before = os.stat(sensors)
    text = sensors.read_text(encoding="utf-8")
    assert "    width_mm: 36.0\n" in text
    sensors.write_text(text.replace("    width_mm: 36.0\n", "    width_mm: 35.9\n", 1), encoding="utf-8")
    os.utime(sensors, ns=(before.st_atime_ns, before.st_mtime_ns))
    assert os.stat(sensors).st_size == before.st_size
    for fresh_process in (False, True):
        if fresh_process:
            monkeypatch.setattr(loader, "_file_digests", {})
        assert load_db(lensfun=False).sensor("full-frame").width_mm == 35.9
