"""The on-disk caches are never trusted: whatever an entry holds, the answer is the one computed without it.

Both caches (the aberration table of a prescription and the records of a preset file) are poisoned
field by field, in two ways: with the entry re-signed with this user's cache key (so that only the
value checks stand between the poison and the answer), and without (so that the envelope's checksum,
version, source digest and size checks are what refuse it). Every poisoned run must print exactly what
a run with ``CAMTOOL_NO_CACHE=1`` prints, exit 0, write nothing on stderr and finish within a time
bound; the bad entry is then found rewritten with good content. The reference is the uncached run: an
independent computation of the same answer, not a value copied from the cache.
"""

from __future__ import annotations

import copy
import errno
import json
import math
import os
import shutil
import subprocess
import sys
import time
from collections.abc import Callable, Iterator
from pathlib import Path
from typing import Any

import pytest
from cli_helpers import run, time_bound  # noqa: F401  (time_bound: every test here ends within 60 s)

from camtool.core import cache
from camtool.dof import auto

SECONDS = 5.0
"""Time bound of one command, poisoned cache included (a warm run takes well under a second)."""

ABERRATION_COMMAND = ("dof", "--lens", "dgauss100-lens", "-N", "4", "-s", "1m", "--model", "auto", "--format", "json")
PRESET_COMMAND = ("dof", "-f", "50", "-N", "8", "-s", "3m", "--sensor", "aps-c", "--format", "json")
LIST_COMMAND = ("presets", "list", "--kind", "sensor", "--format", "json")


def _point_xdg_at(root: Path, monkeypatch: pytest.MonkeyPatch, config: Path | None = None) -> None:
    for name in ("XDG_CONFIG_HOME", "XDG_DATA_HOME", "XDG_CACHE_HOME"):
        monkeypatch.setenv(name, str(root / name.lower()))
    if config is not None:
        monkeypatch.setenv("XDG_CONFIG_HOME", str(config))
    monkeypatch.setenv("XDG_CONFIG_DIRS", str(root / "etc-xdg"))
    monkeypatch.delenv("CAMTOOL_NO_CACHE", raising=False)


def _user_sensors(root: Path) -> Path:
    """A user configuration holding a copy of the shipped sensors and cameras (the shipped records answer for the
    shipped files themselves, so the preset cache is exercised through user files: ``sensors.yaml-*.json``)."""
    from camtool.presets import paths

    config = root / "xdg_config_home"
    (config / "camtool").mkdir(parents=True)
    for name in ("sensors.yaml", "cameras.yaml"):
        shutil.copyfile(os.path.join(paths.shipped_dir(), name), config / "camtool" / name)
    return config


@pytest.fixture(scope="module")
def template(tmp_path_factory: pytest.TempPathFactory) -> tuple[Path, dict[tuple[str, ...], str]]:
    """A cache filled by one warm run of each command, and each command's answer without any cache.

    Made once per module; each test starts from a copy, so the shipped preset files are parsed twice
    here rather than twice per test.
    """
    root = tmp_path_factory.mktemp("caches")
    with pytest.MonkeyPatch.context() as monkeypatch:
        _point_xdg_at(root, monkeypatch, _user_sensors(root))
        references = {command: answer(command, no_cache=True) for command in (ABERRATION_COMMAND, PRESET_COMMAND,
                                                                                LIST_COMMAND)}
        assert not (root / "xdg_cache_home").exists()  # CAMTOOL_NO_CACHE writes nothing, not even the key
        for command, reference in references.items():
            assert answer(command) == reference
    return root / "xdg_cache_home", references


@pytest.fixture
def references(template: tuple[Path, dict[tuple[str, ...], str]]) -> dict[tuple[str, ...], str]:
    return template[1]


@pytest.fixture
def home(tmp_path: Path, monkeypatch: pytest.MonkeyPatch, template: tuple[Path, Any]) -> Path:
    """XDG directories for one test, the cache a copy of the template's (key included); the user file the template's
    (its entry is bound to its path)."""
    shutil.copytree(template[0], tmp_path / "xdg_cache_home", symlinks=True)
    _point_xdg_at(tmp_path, monkeypatch, template[0].parent / "xdg_config_home")
    return tmp_path / "xdg_cache_home" / "camtool"


@pytest.fixture
def empty_home(tmp_path: Path, monkeypatch: pytest.MonkeyPatch, template: tuple[Path, Any]) -> Path:
    _point_xdg_at(tmp_path, monkeypatch, template[0].parent / "xdg_config_home")
    return tmp_path / "xdg_cache_home" / "camtool"


def answer(args: tuple[str, ...], *, no_cache: bool = False) -> str:
    """stdout of ``camtool ARGS`` in this process, checked: exit 0, nothing on stderr, within :data:`SECONDS`."""
    auto.aberration_table.cache_clear()  # the process-level cache would hide the disk
    start = time.monotonic()
    result = run(*args, env={"CAMTOOL_NO_CACHE": "1" if no_cache else None})
    elapsed = time.monotonic() - start
    assert result.exit_code == 0, result.output
    assert result.stderr == ""
    assert elapsed < SECONDS, elapsed
    return result.stdout


def split(path: Path) -> tuple[dict[str, Any], bytes]:
    raw = path.read_bytes()
    end = raw.index(b"\n")
    return json.loads(raw[:end]), raw[end + 1:]


def temporary_files(root: Path) -> list[Path]:
    return [p for p in root.rglob("*") if p.name.endswith(".tmp")]


# --- the aberration table -------------------------------------------------------------------------------------------


@pytest.fixture
def aberration(home: Path, references: dict[tuple[str, ...], str]) -> Iterator[tuple[str, Path, dict[str, Any], bytes]]:
    """The uncached answer, the path of a freshly written entry, its header and its payload."""
    reference = references[ABERRATION_COMMAND]
    (path,) = (home / "aberrations").glob("*.json")
    header, payload = split(path)
    yield reference, path, header, payload
    assert not temporary_files(home)


def _table_mutations() -> dict[str, Callable[[dict[str, Any]], Any]]:
    def grid(change: Callable[[list[Any]], Any]) -> Callable[[dict[str, Any]], Any]:
        def mutate(data: dict[str, Any]) -> Any:
            data["f_numbers"] = change(data["f_numbers"])
            return data
        return mutate

    def rows(change: Callable[[list[Any]], Any]) -> Callable[[dict[str, Any]], Any]:
        def mutate(data: dict[str, Any]) -> Any:
            data["table"] = change(data["table"])
            return data
        return mutate

    def pair(index: int, value: Any) -> Callable[[dict[str, Any]], Any]:
        def mutate(data: dict[str, Any]) -> Any:
            data["table"][2][1][index] = value
            return data
        return mutate

    def swap(items: list[Any], i: int = 1, j: int = 2) -> list[Any]:
        items[i], items[j] = items[j], items[i]
        return items

    out: dict[str, Callable[[dict[str, Any]], Any]] = {
        "not a mapping": lambda data: [data["f_numbers"], data["table"]],
        "a missing key": lambda data: {"table": data["table"]},
        "an extra key": lambda data: {**data, "more": 1},
        "grid not a list": grid(lambda g: "1,2,4"),
        "grid a number": grid(lambda g: 4.0),
        "grid of strings": grid(lambda g: [str(n) for n in g]),
        "grid of integers": grid(lambda g: [int(n) if n == int(n) else n for n in g]),
        "grid reordered": grid(swap),
        "grid shorter": grid(lambda g: g[:-1]),
        "grid longer": grid(lambda g: [*g, 90.0]),
        "grid scaled": grid(lambda g: [n * 1.01 for n in g]),
        "grid with NaN": grid(lambda g: [math.nan, *g[1:]]),
        "grid with inf": grid(lambda g: [*g[:-1], math.inf]),
        "grid negative": grid(lambda g: [-n for n in g]),
        "table not a list": rows(lambda t: {"0": t[0]}),
        "table shorter": rows(lambda t: t[:-1]),
        "table longer": rows(lambda t: [*t, t[-1]]),
        "a row not a list": rows(lambda t: [t[0], 0.1, *t[2:]]),
        "a row shorter": rows(lambda t: [t[0], t[1][:-1], *t[2:]]),
        "a row longer": rows(lambda t: [t[0], [*t[1], [2.0, 0.1]], *t[2:]]),
        "a row empty": rows(lambda t: [t[0], [], *t[2:]]),
        "pairs reordered": rows(lambda t: [t[0], swap(t[1], 0, 1), *t[2:]]),
        "an entry of four": rows(lambda t: [t[0], [[*t[1][0], 0.0], *t[1][1:]], *t[2:]]),
        "a pair not a list": rows(lambda t: [t[0], [0.0, *t[1][1:]], *t[2:]]),
        "magnification changed": pair(0, 0.06),
        "magnification negative": pair(0, -0.05),
        "magnification NaN": pair(0, math.nan),
        "magnification a string": pair(0, "0.05"),
        "share a string": pair(1, "0.001"),
        "share null": pair(1, None),
        "share true": pair(1, True),
        "share an integer": pair(1, 0),
        "share a list": pair(1, [0.1]),
        "share NaN": pair(1, math.nan),
        "share inf": pair(1, math.inf),
        "share -inf": pair(1, -math.inf),
        "share negative": pair(1, -0.001),
        "an entry of two": rows(lambda t: [t[0], [t[1][0][:2], *t[1][1:]], *t[2:]]),
        "focus shift a string": pair(2, "0.01"),
        "focus shift an integer": pair(2, 0),
        "focus shift null": pair(2, None),
        "focus shift NaN": pair(2, math.nan),
        "focus shift inf": pair(2, math.inf),
    }
    return out


TABLE_MUTATIONS = _table_mutations()


def _dumps(value: Any) -> bytes:
    return json.dumps(value, separators=(",", ":")).encode("utf-8")  # NaN and inf written as JSON extensions


@pytest.mark.parametrize("name", sorted(TABLE_MUTATIONS))
def test_a_resigned_aberration_entry_with_a_bad_value_is_ignored_and_rewritten(aberration, name):
    reference, path, header, payload = aberration
    poisoned = TABLE_MUTATIONS[name](copy.deepcopy(json.loads(payload)))
    assert cache.write(str(path), header["kind"], header["source"], _dumps(poisoned))
    assert cache.read(str(path), header["kind"], header["source"], 1 << 20) == _dumps(poisoned)  # it would be read
    assert answer(ABERRATION_COMMAND) == reference
    assert split(path) == (header, payload)  # rewritten: the same content a fresh calibration wrote


@pytest.mark.parametrize("payload_bytes", [
    b"", b"{", b'{"f_numbers": [1.0, 2.0], "table": [[[0.0, 0.1]', b"null", b"[]", b"\xff\xfe\x00",
    b"[" * 100_000 + b"]" * 100_000, b'{"f_numbers": NaN}',
], ids=["empty", "an opening brace", "truncated", "null", "a list", "not UTF-8", "nested 100,000 deep", "NaN"])
def test_a_resigned_aberration_entry_that_is_not_a_table_is_ignored(aberration, payload_bytes):
    reference, path, header, payload = aberration
    assert cache.write(str(path), header["kind"], header["source"], payload_bytes)
    assert answer(ABERRATION_COMMAND) == reference
    assert split(path) == (header, payload)


@pytest.mark.parametrize("plant", ["shares of 0.5", "rows reordered"])
def test_an_aberration_entry_with_other_valid_values_but_no_valid_checksum_is_refused(aberration, plant):
    # the planted entry of the report: the same layout, other (plausible) shares, the header copied; values no
    # range check can tell from computed ones, so the keyed checksum is what refuses them
    reference, path, header, payload = aberration
    data = json.loads(payload)
    if plant == "rows reordered":
        data["table"][1], data["table"][4] = data["table"][4], data["table"][1]
    else:
        data["table"] = [[[m, 0.5, shift] for m, _, shift in row] for row in data["table"]]
    planted = _dumps(data)
    path.write_bytes(_dumps({**header, "length": len(planted)}) + b"\n" + planted)
    assert answer(ABERRATION_COMMAND) == reference
    assert split(path) == (header, payload)


# --- the envelope, the same for both caches --------------------------------------------------------------------------


def _envelope_mutations() -> dict[str, Callable[[dict[str, Any], bytes], bytes]]:
    def field(key: str, value: Any) -> Callable[[dict[str, Any], bytes], bytes]:
        return lambda header, payload: _dumps({**header, key: value}) + b"\n" + payload

    def without(key: str) -> Callable[[dict[str, Any], bytes], bytes]:
        return lambda header, payload: _dumps({k: v for k, v in header.items() if k != key}) + b"\n" + payload

    def flip(text: str) -> str:
        return ("1" if text[0] != "1" else "2") + text[1:]

    out: dict[str, Callable[[dict[str, Any], bytes], bytes]] = {
        "format 2": field("format", 2),
        "format a string": field("format", "1"),
        "format true": field("format", True),
        "format a float": field("format", 1.0),
        "format NaN": field("format", math.nan),
        "format missing": without("format"),
        "kind other": lambda h, p: _dumps({**h, "kind": "other"}) + b"\n" + p,
        "kind null": field("kind", None),
        "version other": field("version", "0.0.1"),
        "version a number": field("version", 0.1),
        "version missing": without("version"),
        "source of other content": lambda h, p: _dumps({**h, "source": flip(h["source"])}) + b"\n" + p,
        "source a list": field("source", []),
        "length one more": lambda h, p: _dumps({**h, "length": h["length"] + 1}) + b"\n" + p,
        "length negative": field("length", -1),
        "length inf": field("length", math.inf),
        "length a string": lambda h, p: _dumps({**h, "length": str(h["length"])}) + b"\n" + p,
        "checksum flipped": lambda h, p: _dumps({**h, "mac": flip(h["mac"])}) + b"\n" + p,
        "checksum short": lambda h, p: _dumps({**h, "mac": h["mac"][:-2]}) + b"\n" + p,
        "checksum a number": field("mac", 12345),
        "checksum missing": without("mac"),
        "an extra header key": field("extra", 1),
        "header a list": lambda h, p: _dumps(list(h.values())) + b"\n" + p,
        "header nested deep": lambda h, p: b"[" * 500 + b"]" * 500 + b"\n" + p,
        "no header line": lambda h, p: p,
        "header without its newline": lambda h, p: _dumps(h) + p,
        "header of 2 KB": lambda h, p: _dumps({**h, "pad": "x" * 2048}) + b"\n" + p,
        "truncated": lambda h, p: (_dumps(h) + b"\n" + p)[:-7],
        "truncated in the header": lambda h, p: _dumps(h)[:40],
        "payload bit-flipped": lambda h, p: _dumps(h) + b"\n" + p[:20] + bytes([p[20] ^ 0x01]) + p[21:],
        "payload grown by a space": lambda h, p: _dumps({**h, "length": len(p) + 1}) + b"\n" + p + b" ",
        "empty": lambda h, p: b"",
        "binary": lambda h, p: bytes(range(256)) * 8,
    }
    return out


ENVELOPE_MUTATIONS = _envelope_mutations()


def _plant_special(path: Path, what: str) -> None:
    path.unlink()
    if what == "FIFO":
        os.mkfifo(path)
    elif what == "symlink to /dev/zero":
        path.symlink_to("/dev/zero")
    elif what == "symlink to /dev/urandom":
        path.symlink_to("/dev/urandom")
    elif what == "directory":
        path.mkdir()
        (path / "inside").write_text("x")
    elif what == "huge sparse file":
        with open(path, "wb") as handle:
            handle.truncate(2 << 30)  # 2 GiB, no blocks on disk
    elif what == "dangling symlink":
        path.symlink_to(path.with_name("nowhere"))
    elif what == "symlink loop":
        path.symlink_to(path)
    else:
        raise AssertionError(what)


SPECIAL = ["FIFO", "symlink to /dev/zero", "symlink to /dev/urandom", "directory", "huge sparse file",
           "dangling symlink", "symlink loop"]


@pytest.mark.parametrize("name", sorted(ENVELOPE_MUTATIONS))
def test_an_aberration_entry_with_a_bad_envelope_is_ignored_and_rewritten(aberration, name):
    reference, path, header, payload = aberration
    path.write_bytes(ENVELOPE_MUTATIONS[name](header, payload))
    assert answer(ABERRATION_COMMAND) == reference
    assert split(path) == (header, payload)


@pytest.mark.parametrize("what", SPECIAL)
def test_an_aberration_entry_that_is_not_a_regular_file_is_ignored_at_once(aberration, what):
    reference, path, header, payload = aberration
    _plant_special(path, what)
    assert answer(ABERRATION_COMMAND) == reference
    if what != "directory":  # a directory is left alone (and ignored); anything else is replaced
        assert split(path) == (header, payload)


@pytest.mark.parametrize("what", ["removed", "world-readable", "short", "a FIFO", "a directory",
                                  "a symlink to the key"])
def test_a_missing_or_unsafe_key_makes_every_entry_a_miss(aberration, what):
    reference, path, header, payload = aberration
    key = path.parent.parent / cache.KEY_NAME
    if what == "removed":
        key.unlink()
    elif what == "world-readable":
        key.chmod(0o644)
    elif what == "short":
        key.write_bytes(key.read_bytes()[:16])
    elif what == "a FIFO":
        key.unlink()
        os.mkfifo(key)
    elif what == "a directory":
        key.unlink()
        key.mkdir()
    else:
        key.rename(key.with_name("elsewhere"))
        key.symlink_to(key.with_name("elsewhere"))
    assert answer(ABERRATION_COMMAND) == reference
    if what == "removed":  # a new key is made, and the entry written again under it
        assert split(path)[1] == payload and split(path)[0]["mac"] != header["mac"]


def test_no_cache_neither_reads_nor_writes(aberration):
    reference, path, header, payload = aberration
    planted = ENVELOPE_MUTATIONS["checksum flipped"](header, payload)
    path.write_bytes(planted)
    assert answer(ABERRATION_COMMAND, no_cache=True) == reference
    assert path.read_bytes() == planted  # not read (it would have been rewritten) and not written


# --- the preset cache -----------------------------------------------------------------------------------------------


@pytest.fixture
def preset_entry(home: Path, references: dict[tuple[str, ...], str]) -> Iterator[tuple[str, Path, dict[str, Any], bytes]]:
    reference = references[PRESET_COMMAND]
    (path,) = (home / "presets").glob("sensors.yaml-*.json")
    header, payload = split(path)
    yield reference, path, header, payload
    assert not temporary_files(home)


def _sections(payload: bytes) -> tuple[dict[str, list[int]], dict[str, Any]]:
    end = payload.index(b"\n")
    spans = json.loads(payload[:end])
    body = payload[end + 1:]
    return spans, {name: json.loads(body[o:o + n]) for name, (o, n) in spans.items()}


def _pack(parsed: dict[str, Any]) -> bytes:
    spans, blobs, offset = {}, [], 0
    for name, value in parsed.items():
        blob = _dumps(value)
        spans[name] = [offset, len(blob)]
        blobs.append(blob)
        offset += len(blob)
    return _dumps(spans) + b"\n" + b"".join(blobs)


def _aps_c(parsed: dict[str, Any]) -> int:
    return next(i for i, r in enumerate(parsed["sensor"]) if r["id"] == "aps-c")


BAD = {"a string": "x", "null": None, "a list": [], "a mapping": {}, "true": True, "NaN": math.nan, "inf": math.inf,
       "negative": -3.0, "zero": 0.0}
NOT_TEXT = ["null", "a list", "a mapping", "true", "NaN", "inf", "negative", "zero"]
RECORD_FIELDS = {  # the values each field of a cached sensor record must refuse; "missing" where it is required
    "id": [*NOT_TEXT, "a string", "missing"],
    "name": [*NOT_TEXT, "missing"],
    "aliases": [*BAD, "missing"],
    "width_mm": [*BAD, "missing"],
    "height_mm": [*BAD, "missing"],
    "coc_mm": list(BAD),
    "category": NOT_TEXT,
    "approximate": [label for label in BAD if label != "true"],
    "source": NOT_TEXT,
    "_keys": [*BAD, "missing"],
    "_line": [*(label for label in BAD if label != "null"), "missing"],
    "_refs": [*(label for label in BAD if label != "a mapping"), "missing"],
}


def _record_mutations() -> dict[str, Callable[[dict[str, Any]], None]]:
    out: dict[str, Callable[[dict[str, Any]], None]] = {}

    def set_field(key: str, value: Any) -> Callable[[dict[str, Any]], None]:
        def mutate(parsed: dict[str, Any]) -> None:
            parsed["sensor"][_aps_c(parsed)][key] = value
        return mutate

    def drop_field(key: str) -> Callable[[dict[str, Any]], None]:
        def mutate(parsed: dict[str, Any]) -> None:
            del parsed["sensor"][_aps_c(parsed)][key]
        return mutate

    for key, labels in RECORD_FIELDS.items():
        for label in labels:
            out[f"{key} {label}"] = drop_field(key) if label == "missing" else set_field(key, BAD[label])
    out["width 1e400"] = set_field("width_mm", 1e400)
    out["aliases with a non-string"] = set_field("aliases", ["apsc", 5])
    out["_keys not normalized"] = set_field("_keys", ["APS-C"])
    out["_keys of full frame"] = set_field("_keys", ["fullframe"])
    out["_line a float"] = set_field("_line", 3.5)
    out["_refs naming a key"] = set_field("_refs", {"sensor": 3})
    out["an unknown key"] = set_field("width", 36.0)
    out["an unknown private key"] = set_field("_extra", 1)
    out["_data on a sensor"] = set_field("_data", {})

    def keys(change: Callable[[list[Any], int], Any]) -> Callable[[dict[str, Any]], None]:
        def mutate(parsed: dict[str, Any]) -> None:
            parsed["sensor#keys"] = change(parsed["sensor#keys"], _aps_c(parsed))
        return mutate

    out["keys not a list"] = keys(lambda k, i: {"apsc": i})
    out["keys shorter"] = keys(lambda k, i: k[:-1])
    out["keys longer"] = keys(lambda k, i: [*k, ["extra"]])
    out["keys of aps-c given to full frame"] = keys(lambda k, i: [k[i] if j == 0 else (k[0] if j == i else v)
                                                                  for j, v in enumerate(k)])
    out["keys with NaN"] = keys(lambda k, i: [[math.nan] if j == i else v for j, v in enumerate(k)])
    out["keys empty for aps-c"] = keys(lambda k, i: [[] if j == i else v for j, v in enumerate(k)])

    def records(change: Callable[[list[Any]], Any]) -> Callable[[dict[str, Any]], None]:
        def mutate(parsed: dict[str, Any]) -> None:
            parsed["sensor"] = change(parsed["sensor"])
        return mutate

    out["records not a list"] = records(lambda r: {"0": r[0]})
    out["records shorter"] = records(lambda r: r[:-1])
    out["a record a list"] = records(lambda r: [list(x.items()) if x["id"] == "aps-c" else x for x in r])
    out["a record null"] = records(lambda r: [None if x["id"] == "aps-c" else x for x in r])
    return out


RECORD_MUTATIONS = _record_mutations()


@pytest.mark.parametrize("name", sorted(RECORD_MUTATIONS))
def test_a_resigned_preset_entry_with_a_bad_record_is_ignored_and_rewritten(preset_entry, name):
    reference, path, header, payload = preset_entry
    _spans, parsed = _sections(payload)
    RECORD_MUTATIONS[name](parsed)
    poisoned = _pack(parsed)
    assert cache.write(str(path), header["kind"], header["source"], poisoned)
    assert answer(PRESET_COMMAND) == reference
    assert split(path) == (header, payload)


@pytest.mark.parametrize("spans", [
    "[]", '{"sensor": [0, 99999999], "sensor#keys": [0, 1]}', '{"sensor": [-1, 5]}', '{"sensor": [0, 1.5]}',
    '{"sensor": [0], "sensor#keys": [0, 1]}', '{"lens": [0, 2], "sensor": "all"}', '{"nonsense": [0, 2]}',
    '{"sensor": [0, true]}',
], ids=["a list", "past the end", "negative", "a float", "one number", "a string span", "an unknown kind", "true"])
def test_a_resigned_preset_entry_with_bad_sections_is_ignored(preset_entry, spans):
    reference, path, header, payload = preset_entry
    poisoned = spans.encode() + b"\n" + payload.split(b"\n", 1)[1]
    assert cache.write(str(path), header["kind"], header["source"], poisoned)
    assert answer(PRESET_COMMAND) == reference
    assert split(path) == (header, payload)


def test_a_planted_preset_entry_answering_aps_c_as_full_frame_is_refused(preset_entry):
    # valid records (36 x 24 is a valid sensor), the right source digest and version, but no valid checksum
    reference, path, header, payload = preset_entry
    _spans, parsed = _sections(payload)
    record = parsed["sensor"][_aps_c(parsed)]
    record["width_mm"], record["height_mm"] = 36.0, 24.0
    planted = _pack(parsed)
    path.write_bytes(_dumps({**header, "length": len(planted)}) + b"\n" + planted)
    assert answer(PRESET_COMMAND) == reference
    # d/1500 of the 23.6 x 15.6 mm APS-C diagonal (lens_db/sensors.yaml), not of full frame's 43.3 mm
    assert json.loads(reference)[0]["coc_mm"] == pytest.approx(math.hypot(23.6, 15.6) / 1500, rel=1e-12)
    assert split(path) == (header, payload)


def test_an_entry_of_another_preset_file_is_never_used(preset_entry):
    reference, path, header, payload = preset_entry
    cameras = next(path.parent.glob("cameras.yaml-*.json"))
    cameras_header, cameras_payload = split(cameras)
    path.write_bytes(cameras.read_bytes())  # a valid entry, for another file
    assert answer(PRESET_COMMAND) == reference
    assert split(path) == (header, payload)
    assert split(cameras) == (cameras_header, cameras_payload)


@pytest.mark.parametrize("name", sorted(ENVELOPE_MUTATIONS))
def test_a_preset_entry_with_a_bad_envelope_is_ignored_and_rewritten(preset_entry, name):
    reference, path, header, payload = preset_entry
    path.write_bytes(ENVELOPE_MUTATIONS[name](header, payload))
    assert answer(PRESET_COMMAND) == reference
    assert split(path) == (header, payload)


@pytest.mark.parametrize("what", SPECIAL)
def test_a_preset_entry_that_is_not_a_regular_file_is_ignored_at_once(preset_entry, what):
    reference, path, header, payload = preset_entry
    _plant_special(path, what)
    assert answer(PRESET_COMMAND) == reference
    if what != "directory":
        assert split(path) == (header, payload)


def test_a_bad_cached_value_never_reaches_an_error_message(preset_entry):
    # a negative width in the cache would be blamed on --sensor; the entry is refused instead
    reference, path, header, payload = preset_entry
    _spans, parsed = _sections(payload)
    parsed["sensor"][_aps_c(parsed)]["width_mm"] = -3.0
    assert cache.write(str(path), header["kind"], header["source"], _pack(parsed))
    assert answer(PRESET_COMMAND) == reference


# --- writing ----------------------------------------------------------------------------------------------------------


def _failing(monkeypatch: pytest.MonkeyPatch, where: str, error: type[BaseException]) -> None:
    real = getattr(os, where)
    calls = {"n": 0}

    def fail(*args: Any, **kwargs: Any) -> Any:
        # the key file is written first, with os.write and os.link; fail only on the entry
        if where == "write" and calls["n"] == 0 and len(args[1]) == 32:
            calls["n"] += 1
            return real(*args, **kwargs)
        if error is OSError:
            raise OSError(errno.ENOSPC, "No space left on device")
        raise error()

    monkeypatch.setattr(os, where, fail)


@pytest.mark.parametrize("where", ["write", "replace"])
@pytest.mark.parametrize("command", [ABERRATION_COMMAND, PRESET_COMMAND], ids=["aberrations", "presets"])
def test_a_failed_write_leaves_no_temporary_file(empty_home, references, monkeypatch, where, command):
    _failing(monkeypatch, where, OSError)
    assert answer(command) == references[command]
    assert empty_home.exists() and not temporary_files(empty_home)
    assert not list(empty_home.rglob("*.json"))


@pytest.mark.parametrize("where", ["write", "replace"])
def test_an_interrupted_write_leaves_no_temporary_file_and_is_not_swallowed(empty_home, monkeypatch, where):
    _failing(monkeypatch, where, KeyboardInterrupt)
    with pytest.raises(KeyboardInterrupt):
        cache.write(str(empty_home / "aberrations" / "x.json"), "aberrations", "0" * 64, b"{}")
    assert not temporary_files(empty_home)
    assert not (empty_home / "aberrations" / "x.json").exists()


@pytest.mark.skipif(hasattr(os, "geteuid") and os.geteuid() == 0, reason="root writes into read-only directories")
def test_a_read_only_cache_directory_is_skipped(empty_home, references):
    empty_home.mkdir(parents=True)
    empty_home.chmod(0o500)
    try:
        assert answer(ABERRATION_COMMAND) == references[ABERRATION_COMMAND]
        assert not temporary_files(empty_home)
    finally:
        empty_home.chmod(0o700)


def test_a_table_with_a_non_finite_share_is_not_written(empty_home):
    lens = _dgauss()
    grid, table = auto._compute_table(lens)
    bad = (grid, (((0.0, math.nan, 0.0), *table[0][1:]), *table[1:]))
    source = auto._source(lens)
    auto._write_table(auto._cache_path(source), source, bad)
    assert not list(empty_home.rglob("*.json")) and not temporary_files(empty_home)


def _dgauss() -> Any:
    from camtool.presets import load_db

    return load_db(use_cache=False).prescription("dgauss100").optics


def test_a_fresh_table_is_read_back_unchanged(empty_home):
    lens = _dgauss()
    computed = auto._compute_table(lens)
    assert auto._valid_table(json.loads(cache.dumps({"f_numbers": computed[0], "table": computed[1]})), lens) \
        == computed


# --- the command line, end to end, in fresh processes ---------------------------------------------------------------


def _camtool(args: tuple[str, ...], env: dict[str, str]) -> str:
    start = time.monotonic()
    done = subprocess.run([sys.executable, "-m", "camtool", *args], env=env, capture_output=True, text=True,
                          timeout=30)
    assert time.monotonic() - start < 10
    assert done.returncode == 0 and done.stderr == "", done.stderr
    return done.stdout


TABLE_COMMAND = ABERRATION_COMMAND[:-2]  # the table output, as printed


def _environment() -> dict[str, str]:
    env = {**os.environ, "COLUMNS": "200"}
    env.pop("CAMTOOL_FORMAT", None)
    return env


@pytest.fixture(scope="module")
def printed_reference() -> str:
    return _camtool(TABLE_COMMAND, {**_environment(), "CAMTOOL_NO_CACHE": "1"})


@pytest.mark.parametrize("what", ["FIFO", "symlink to /dev/zero", "huge sparse file", "planted"])
def test_the_command_line_answers_as_without_the_cache(home, printed_reference, what):
    for path in [*(home / "aberrations").glob("*.json"), *(home / "presets").glob("*.json")]:
        if what == "planted":
            header, payload = split(path)
            path.write_bytes(_dumps(header) + b"\n" + payload.replace(b"1", b"2"))
        else:
            _plant_special(path, what)
    env = _environment()
    assert _camtool(TABLE_COMMAND, env) == printed_reference
    assert _camtool(TABLE_COMMAND, env) == printed_reference  # and from the rewritten entries


def test_the_digests_are_hashlib_s_sha256_and_keyed_blake2b() -> None:
    import hashlib

    for data in (b"", b"camtool", bytes(range(256)) * 300):
        assert cache.source_digest(data) == hashlib.sha256(data).hexdigest()
        key = hashlib.sha256(data).digest()
        assert cache._mac(key, "presets-10", "s", data) == hashlib.blake2b(
            cache._signed("presets-10", "s", data), key=key, digest_size=32).hexdigest()


# A listing reads a whole kind at once and checks each record as a record looked up is: every mutation is refused.
LISTING_REFUSES = sorted(RECORD_MUTATIONS)


@pytest.mark.parametrize("name", LISTING_REFUSES)
def test_a_listing_refuses_a_resigned_entry_with_a_record_of_the_wrong_shape(preset_entry, references, name):
    _reference, path, header, payload = preset_entry
    _spans, parsed = _sections(payload)
    RECORD_MUTATIONS[name](parsed)
    assert cache.write(str(path), header["kind"], header["source"], _pack(parsed))
    assert answer(LIST_COMMAND) == references[LIST_COMMAND]
    assert split(path) == (header, payload)


def test_a_listing_refuses_a_planted_entry_without_a_valid_checksum(preset_entry, references):
    _reference, path, header, payload = preset_entry
    _spans, parsed = _sections(payload)
    record = parsed["sensor"][_aps_c(parsed)]
    record["width_mm"], record["height_mm"] = 36.0, 24.0  # a sound record, values a fresh parse never gives
    planted = _pack(parsed)
    path.write_bytes(_dumps({**header, "length": len(planted)}) + b"\n" + planted)
    assert answer(LIST_COMMAND) == references[LIST_COMMAND]
    assert split(path) == (header, payload)
