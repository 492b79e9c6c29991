"""``camtool exif`` on files built to break it: out-of-range tags, control characters, FIFOs, odd names, mutations.

Expectations come from outside the reader: the APEX definitions of Exif 2.32
(N = 2^(Av/2), t = 2^(−Tv)), the ranges of the command-line options the tags
stand for (the option itself is run on the same value and must refuse it with
the same range), and invariants every answer must keep (one stderr line per
file, no traceback or hang, no control character, no non-finite or
out-of-range number with exit 0).

The exiv2 project's camera and crash-report files are used in place from
../shared/reference/exif-samples/ (tests skip without it). The mutation loop
is seeded and bounded: CAMTOOL_EXIF_FUZZ=N runs N mutated files instead of the
default (CAMTOOL_EXIF_FUZZ_SEED picks the seed).
"""

from __future__ import annotations

import json
import math
import os
import random
import re
import signal
import stat
from collections.abc import Iterator
from pathlib import Path
from typing import Any

import pytest
from click.testing import CliRunner, Result

from camtool.cli import cli
from camtool.core import domain, ranges
from tests.cli_helpers import exif_image_maker, run, time_limit

exiv2 = pytest.importorskip("exiv2")

DATA = Path(__file__).resolve().parent / "data" / "exif"
SAMPLES = Path(__file__).resolve().parent.parent.parent / "shared" / "reference" / "exif-samples"
HOSTILE = sorted((SAMPLES / "hostile").glob("*")) if SAMPLES.is_dir() else []
CAMERA = sorted((SAMPLES / "camera").glob("*")) if SAMPLES.is_dir() else []
OURS = sorted(DATA.glob("*.jpg"))
CONTROL = re.compile("[\x00-\x08\x0b-\x1f\x7f-\x9f]")  # every C0 but TAB and LF, DEL, C1


IMAGES = exif_image_maker()
BASE: list[tuple[str, Any]] = [
    ("Exif.Image.Make", "Canon"), ("Exif.Image.Model", "Canon EOS 5D"),
    ("Exif.Photo.FocalLength", IMAGES.rational(50)), ("Exif.Photo.FNumber", IMAGES.rational(8)),
    ("Exif.Photo.ExposureTime", IMAGES.rational(1, 125)), ("Exif.Photo.ISOSpeedRatings", IMAGES.ushort(100)),
    ("Exif.Photo.SubjectDistance", IMAGES.rational(3)), ("Exif.Photo.FocalLengthIn35mmFilm", IMAGES.ushort(50)),
]


def image(path: Path, tags: list[tuple[str, Any]], base: bool = True) -> Path:
    """A tiny JPEG at ``path`` holding ``tags`` (over :data:`BASE` unless ``base`` is false), written by exiv2."""
    path.write_bytes(IMAGES.tiny_jpeg())
    handle = exiv2.ImageFactory.open(str(path))
    handle.readMetadata()
    data = handle.exifData()
    chosen = dict(BASE if base else [])
    chosen.update(tags)
    for key, value in chosen.items():
        data[key] = value
    handle.writeMetadata()
    return path


def signed(num: int, den: int = 1) -> Any:
    return exiv2.RationalValue([(num, den)])


@pytest.fixture(autouse=True)
def time_bound() -> Iterator[None]:
    """Every test ends within 120 s: a hang fails instead of stalling the run."""
    yield from time_limit(120)


def exif(*args: str, stdin: bytes | None = None) -> Result:
    return CliRunner().invoke(cli, ["exif", *args], input=stdin, catch_exceptions=False,
                              env={"COLUMNS": None, "CAMTOOL_FORMAT": None, "NO_COLOR": None})


def json_rows(result: Result) -> list[dict[str, Any]]:
    def refuse(token: str) -> None:
        raise AssertionError(f"{token} in the JSON output")

    rows = json.loads(result.stdout, parse_constant=refuse)
    assert isinstance(rows, list)
    return rows


# -- numbers from tags: the option's own range, the tag named ---------------------------------------------

def test_apex_values_by_their_definitions(tmp_path: Path) -> None:
    # Exif 2.32: N = 2^(Av/2), t = 2^(−Tv). Av 3 is f/2^1.5; a signed Tv of −5 is 32 s; Av 0 is f/1, Tv 0 1 s.
    for av, tv, n, t in ((3, -5, 2 ** 1.5, 32.0), (0, 0, 1.0, 1.0), (10, 10, 32.0, 1 / 1024)):
        path = image(tmp_path / f"apex{av}.jpg", [("Exif.Photo.ApertureValue", IMAGES.rational(av)),
                                                   ("Exif.Photo.ShutterSpeedValue", signed(tv))], base=False)
        result = exif(str(path), "--format", "json")
        (row,) = json_rows(result)
        assert row["f_number"] == pytest.approx(n, rel=1e-15) and row["shutter_s"] == pytest.approx(t, rel=1e-15)
        assert row["ev"] == pytest.approx(av + tv, rel=1e-12, abs=1e-12)  # EV = Av + Tv (APEX)


# (tag, value, the option it stands for with a unit suffix, a value the option takes)
OUT_OF_RANGE = [
    ("Exif.Photo.FNumber", IMAGES.rational(65288), "f_number", ["dof", "-f", "50", "-s", "3", "-N", "65288"]),
    ("Exif.Photo.FNumber", IMAGES.rational(3, 200_000_000), "f_number",
     ["dof", "-f", "50", "-s", "3", "-N", "0.000000015"]),
    ("Exif.Photo.FocalLength", IMAGES.rational(14_500_000), "focal_length_mm",
     ["dof", "-f", "14500000", "-N", "8", "-s", "3"]),
    ("Exif.Photo.FocalLength", IMAGES.rational(1, 1000), "focal_length_mm", ["dof", "-f", "0.001", "-N", "8", "-s", "3"]),
    ("Exif.Photo.ExposureTime", signed(-1, 125), "shutter_s", None),
    ("Exif.Photo.ExposureTime", IMAGES.rational(4_000_000), "shutter_s", None),
    ("Exif.Photo.ISOSpeedRatings", IMAGES.ushort(0), "iso", None),  # 0: not recorded, so absent, no problem
]


@pytest.mark.parametrize(("key", "value", "field", "option_run"), OUT_OF_RANGE,
                         ids=[f"{k.rsplit('.', 1)[1]}-{i}" for i, (k, *_) in enumerate(OUT_OF_RANGE)])
def test_a_tag_outside_its_options_range_is_null_and_named(tmp_path: Path, key: str, value: Any, field: str,
                                                           option_run: list[str] | None) -> None:
    path = image(tmp_path / "x.jpg", [(key, value)])
    result = exif(str(path), "--format", "json")
    (row,) = json_rows(result)
    assert row[field] is None
    (line,) = result.stderr.splitlines()
    if field == "iso":  # ISO 0 is Exif's "unknown": missing, not unusable
        assert result.exit_code == 0 and "no ISO" in line and key not in line
        return
    assert result.exit_code == 1
    assert line.startswith(f"camtool exif: {path}: {key} ")
    # the rest of the row is still computed from the usable tags
    assert row["camera"] == "Canon EOS 5D" and row["focus_distance_mm"] == 3000.0
    assert row["crop_factor"] is not None or field == "focal_length_mm"
    if option_run is not None:  # the option refuses the same value with the same range
        typed = run(*option_run)
        assert typed.exit_code == 2
        valid = typed.stderr.strip().splitlines()[-1].rsplit("valid range: ", 1)[1]
        shown = line.split("is outside the valid range: ", 1)[1].split(";")[0]
        bounds = re.findall(r"[0-9.]+", valid)[:2]  # the low and high ends, whatever the wording around them
        assert len(bounds) == 2 and bounds == re.findall(r"[0-9.]+", shown)[:2]


def test_the_edges_of_the_ranges_are_taken(tmp_path: Path) -> None:
    # the ends of -N and -f (core/domain.py, core/ranges.py): f/0.7 = 7/10, f/1024, 1 mm, 5000 mm
    low_n, high_n = domain.F_NUMBER_RANGE
    low_f, high_f = ranges.FOCAL_LENGTH_MM
    for n, f in (((7, 10), (1, 1)), ((int(high_n), 1), (int(high_f), 1))):
        path = image(tmp_path / f"edge{n[0]}.jpg", [("Exif.Photo.FNumber", IMAGES.rational(*n)),
                                                    ("Exif.Photo.FocalLength", IMAGES.rational(*f))])
        (row,) = json_rows(exif(str(path), "--format", "json"))
        assert row["f_number"] == n[0] / n[1] and row["focal_length_mm"] == f[0] / f[1]
    assert (low_n, low_f) == (0.7, 1.0)


def test_aperture_value_2000_and_a_shutter_speed_value_of_minus_2_31(tmp_path: Path) -> None:
    path = image(tmp_path / "apex.jpg", [("Exif.Photo.ApertureValue", IMAGES.rational(2000)),
                                         ("Exif.Photo.ShutterSpeedValue", signed(-2**31))], base=False)
    result = exif(str(path), "--format", "json")
    assert result.exit_code == 1
    (row,) = json_rows(result)
    assert row["f_number"] is None and row["shutter_s"] is None and row["ev"] is None
    (line,) = result.stderr.splitlines()
    assert "Exif.Photo.ApertureValue 2000 " in line and "f/0.7 to f/1024" in line
    assert "Exif.Photo.ShutterSpeedValue -2147483648 " in line


def test_a_bad_fnumber_falls_back_to_the_aperture_value(tmp_path: Path) -> None:
    path = image(tmp_path / "x.jpg", [("Exif.Photo.FNumber", IMAGES.rational(8, 0)),
                                      ("Exif.Photo.ApertureValue", IMAGES.rational(6))])
    result = exif(str(path), "--format", "json")
    (row,) = json_rows(result)
    assert row["f_number"] == 8.0 and row["f_number_source"] == "Photo.ApertureValue"  # 2^(6/2)
    assert result.exit_code == 1 and "Exif.Photo.FNumber 8/0 has a zero denominator" in result.stderr


def test_a_crop_factor_outside_crops_range(tmp_path: Path) -> None:
    # FocalLengthIn35mmFilm 1 over a focal length of 50: a crop factor of 0.02, which --crop refuses
    path = image(tmp_path / "x.jpg", [("Exif.Photo.FocalLengthIn35mmFilm", IMAGES.ushort(1))])
    result = exif(str(path), "--format", "json")
    (row,) = json_rows(result)
    assert row["crop_factor"] is None and row["coc_mm"] is None and row["near_mm"] is None
    assert row["ev100"] is not None  # the exposure does not need the sensor
    assert result.exit_code == 1
    assert f"a crop factor of 0.02 is outside the valid range: {ranges.describe(ranges.CROP_FACTOR)}" in result.stderr


def test_a_coc_outside_cocs_range(tmp_path: Path) -> None:
    path = image(tmp_path / "x.jpg", [])
    result = exif(str(path), "--coc-rule", "d/10", "--format", "json")  # 43.3 mm / 10: beyond --coc's 1 mm
    (row,) = json_rows(result)
    assert row["coc_mm"] is None and row["near_mm"] is None and result.exit_code == 1
    assert "a CoC of 4.3" in result.stderr and ranges.describe(ranges.COC_MM, "mm") in result.stderr


# -- strings from tags and file names: control characters escaped ---------------------------------------

def test_escape_sequences_and_newlines_in_tags(tmp_path: Path) -> None:
    make = "\x1b[2J\x1b]0;title\x07Canon\x9b"
    path = image(tmp_path / "x.jpg", [("Exif.Image.Make", make), ("Exif.Photo.LensModel", "EF\n50mm\r\tf/1.8")])
    (row,) = json_rows(exif(str(path), "--format", "json"))
    assert row["camera"] == "\\x1b[2J\\x1b]0;title\\x07Canon\\x9b Canon EOS 5D"
    assert row["lens"] == "EF\\n50mm\\r\\tf/1.8"
    for fmt in (["--format", "csv"], ["--format", "table"], ["--field", "camera", "--field", "lens"]):
        result = exif(str(path), *fmt)
        assert not CONTROL.search(result.stdout), fmt
        assert fmt[-1] == "table" or ("\\x1b[2J" in result.stdout and "50mm" in result.stdout)  # no tag column
    field = exif(str(path), "--field", "camera", "--field", "lens").stdout
    assert field.count("\n") == 1 and field.split("\t")[1] == "EF\\n50mm\\r\\tf/1.8\n"
    csv_lines = exif(str(path), "--format", "csv").stdout.splitlines()
    assert len(csv_lines) == 2


def _odd_name(directory: Path, suffix: str = ".jpg") -> Path:
    name = os.fsdecode(b"caf\xe9 \x1b[31m" + suffix.encode())
    try:
        path = directory / name
        path.write_bytes(b"")
    except (OSError, UnicodeError):
        pytest.skip("the file system takes no names that are not UTF-8")
    return path


def test_a_name_that_is_not_utf8_escape_and_all(tmp_path: Path) -> None:
    odd = _odd_name(tmp_path)
    odd.write_bytes((DATA / "nikon.jpg").read_bytes())
    shown = f"{tmp_path}/caf\\xe9 \\x1b[31m.jpg"
    expected = json_rows(exif(str(DATA / "nikon.jpg"), "--format", "json"))[0]
    for args, stdin in (([str(odd)], None), (["-r", str(tmp_path)], None), (["-"], os.fsencode(str(odd)) + b"\r\n")):
        result = exif(*args, "--format", "json", stdin=stdin)
        assert result.exit_code == 0, (args, result.stderr)
        (row,) = json_rows(result)
        assert row["file"] == shown
        assert {k: v for k, v in row.items() if k != "file"} == {k: v for k, v in expected.items() if k != "file"}
        assert not CONTROL.search(result.stderr)


# -- files that are not regular files: refused at once ----------------------------------------------------

def test_fifo_device_and_directory_are_refused_at_once(tmp_path: Path) -> None:
    fifo = tmp_path / "pipe.jpg"
    os.mkfifo(fifo)
    (tmp_path / "dir.jpg").mkdir()
    good = tmp_path / "good.jpg"
    good.write_bytes((DATA / "nikon.jpg").read_bytes())
    runs = [
        ([str(fifo), str(good)], None),
        (["-r", str(tmp_path)], None),
        (["-"], f"{fifo}\n{good}\n".encode()),
    ]
    for args, stdin in runs:
        result = exif(*args, "--format", "json", stdin=stdin)
        assert result.exit_code == 1
        rows = {Path(r["file"]).name: r for r in json_rows(result)}
        assert rows["good.jpg"]["near_mm"] is not None
        assert all(v is None for k, v in rows["pipe.jpg"].items() if k != "file")
        lines = result.stderr.splitlines()
        assert [line for line in lines if "pipe.jpg" in line] == [
            f"camtool exif: {fifo}: is a FIFO (named pipe), not a regular file"]
    if stat.S_ISCHR(os.stat("/dev/null").st_mode):
        result = exif("/dev/null")
        assert result.exit_code == 1 and result.stderr == "camtool exif: /dev/null: is a device, not a regular file\n"


# -- hostile and mutated files: one line per file, never a traceback, hang or wrong number ------------------

CHECKS = {
    "focal_length_mm": ranges.FOCAL_LENGTH_MM, "f_number": domain.F_NUMBER_RANGE, "shutter_s": domain.SHUTTER_RANGE_S,
    "iso": domain.ISO_RANGE, "crop_factor": ranges.CROP_FACTOR, "sensor_width_mm": ranges.SENSOR_SIDE_MM,
    "sensor_height_mm": ranges.SENSOR_SIDE_MM, "coc_mm": ranges.COC_MM, "focus_distance_mm": ranges.DISTANCE_MM,
    "focus_distance_min_mm": ranges.DISTANCE_MM, "focus_distance_max_mm": ranges.DISTANCE_MM,
    "near_mm": ranges.DISTANCE_MM, "far_mm": ranges.DISTANCE_MM, "hyperfocal_mm": ranges.DISTANCE_MM,
    "horizontal_deg": (0.0, 180.0), "vertical_deg": (0.0, 180.0), "diagonal_deg": (0.0, 180.0),
    "field_width_mm": ranges.DISTANCE_MM, "ev100": (-100.0, 100.0),
}


def defects(paths: list[Path], args: tuple[str, ...] = ("--format", "json")) -> list[str]:
    """What is wrong with ``camtool exif PATHS ARGS``: empty when every contract holds."""
    found: list[str] = []
    try:
        result = exif(*map(str, paths), *args)
    except TimeoutError:
        raise
    except Exception as error:  # the defect this test looks for
        return [f"{type(error).__name__}: {error}"]
    if result.exit_code not in (0, 1):
        found.append(f"exit {result.exit_code}: {result.output[-300:]}")
    lines = result.stderr.splitlines()
    if len(lines) > len(paths) or any(not line.startswith("camtool exif: ") for line in lines):
        found.append(f"stderr is not one line per file: {result.stderr[:300]!r}")
    if CONTROL.search(result.stdout) or CONTROL.search(result.stderr):
        found.append("a control character reached the output")
    if "--format" not in args or "json" not in args:
        return found
    for row in json_rows(result):
        for key, bounds in CHECKS.items():
            value = row[key]
            if value is not None and not ((math.isfinite(value) and bounds[0] < value <= bounds[1])
                                          or value == bounds[0] > 0):
                found.append(f"{row['file']}: {key} = {value} with exit {result.exit_code}")
        near, focus = row["near_mm"], row["focus_distance_mm"]
        if near is not None and focus is not None and not near <= focus * (1 + 1e-9):
            found.append(f"{row['file']}: near {row['near_mm']} beyond the focus {row['focus_distance_mm']}")
    return found


@pytest.mark.skipif(not HOSTILE, reason="../shared/reference/exif-samples is not there")
@pytest.mark.parametrize("path", HOSTILE, ids=[p.name for p in HOSTILE])
def test_every_hostile_file_gives_one_line(path: Path) -> None:
    assert defects([path]) == []
    result = exif(str(path), "--format", "json")
    assert len(result.stderr.splitlines()) <= 1


@pytest.mark.skipif(not HOSTILE, reason="../shared/reference/exif-samples is not there")
def test_the_hostile_files_together_in_every_format() -> None:
    for args in (("--format", "json"), ("--format", "csv"), ("--format", "table"), ("--field", "file", "--field", "lens"),
                 ("--exiftool", "--format", "json")):
        assert defects(HOSTILE, args) == [], args


# Maker-note values at their edges, for every maker-note tag the reader takes: each file must still be
# answered on one line, every number in its range (or left out and named).
U16, U32 = 0xFFFF, 0xFFFFFFFF
MAKER_EDGES: dict[str, list[tuple[str, Any]]] = {
    "canon_units0": [("Exif.Canon.FocalLength", exiv2.UShortValue([2, U16, U16, 1])),
                     ("Exif.CanonCs.Lens", exiv2.UShortValue([0, 0, 0]))],
    "canon_iso_edges": [("Exif.Photo.ISOSpeedRatings", IMAGES.ushort(0)), ("Exif.CanonCs.ISOSpeed", IMAGES.ushort(0x7FFF)),
                        ("Exif.CanonSi.ISOSpeed", IMAGES.ushort(U16)), ("Exif.CanonSi.AutoISO", IMAGES.ushort(0x7FFF))],
    "canon_iso_flag": [("Exif.Photo.ISOSpeedRatings", IMAGES.ushort(0)), ("Exif.CanonCs.ISOSpeed", IMAGES.ushort(0x4000))],
    "canon_brackets": [("Exif.Photo.SubjectDistance", IMAGES.rational(0)),
                       ("Exif.CanonSi.SubjectDistance", IMAGES.ushort(1)), ("Exif.CanonSi.0x0014", IMAGES.ushort(U16)),
                       ("Exif.CanonCs.DigitalZoom", IMAGES.ushort(3)), ("Exif.CanonCs.ZoomSourceWidth", IMAGES.ushort(1)),
                       ("Exif.CanonCs.ZoomTargetWidth", IMAGES.ushort(U16))],
    "canon_plane_rule": [("Exif.Photo.FocalPlaneXResolution", IMAGES.rational(9999000, 1499)),
                         ("Exif.Photo.FocalPlaneYResolution", IMAGES.rational(480000, 61)),
                         ("Exif.Photo.PixelXDimension", exiv2.ULongValue([U32])),
                         ("Exif.Photo.PixelYDimension", exiv2.ULongValue([1])),
                         ("Exif.CanonPi.ImageWidth", IMAGES.ushort(U16)), ("Exif.CanonPi.ImageHeight", IMAGES.ushort(0))],
    "nikon_edges": [("Exif.Image.Make", "NIKON CORPORATION"), ("Exif.Photo.ISOSpeedRatings", IMAGES.ushort(0)),
                    ("Exif.Photo.FocalLengthIn35mmFilm", IMAGES.ushort(0)),
                    ("Exif.Nikon3.ISOSpeed", exiv2.UShortValue([U16, U16])),
                    ("Exif.Nikon3.SensorPixelSize", exiv2.URationalValue([(U32, 1), (0, 0)]))],
    "olympus_edges": [("Exif.Image.Make", "OLYMPUS CORPORATION"), ("Exif.Photo.FocalLengthIn35mmFilm", IMAGES.ushort(0)),
                      ("Exif.Olympus.FocalPlaneDiagonal", IMAGES.rational(U32, 1)),
                      ("Exif.Photo.SubjectDistance", IMAGES.rational(U32, 1))],
    "olympus_zero": [("Exif.Image.Make", "OLYMPUS CORPORATION"), ("Exif.Photo.FocalLengthIn35mmFilm", IMAGES.ushort(0)),
                     ("Exif.Olympus.FocalPlaneDiagonal", IMAGES.rational(0, 0))],
    "minolta_edges": [("Exif.Image.Make", "Minolta Co., Ltd."), ("Exif.Photo.SubjectDistance", IMAGES.rational(0)),
                      ("Exif.Photo.ISOSpeedRatings", IMAGES.ushort(0)),
                      ("Exif.MinoltaCsNew.ISO", exiv2.ULongValue([U32])),
                      ("Exif.MinoltaCsNew.FocusDistance", exiv2.ULongValue([U32]))],
    "casio_edges": [("Exif.Image.Make", "CASIO COMPUTER CO.,LTD."), ("Exif.Photo.SubjectDistance", IMAGES.rational(0)),
                    ("Exif.Photo.ISOSpeedRatings", IMAGES.ushort(0)), ("Exif.Casio2.ISO", IMAGES.ushort(U16)),
                    ("Exif.Casio2.ObjectDistance", exiv2.ULongValue([0x1FFFFFFF]))],
    "exposure_index_zero": [("Exif.Photo.ISOSpeedRatings", IMAGES.ushort(0)), ("Exif.Photo.ExposureIndex", IMAGES.rational(0, 0))],
}


def maker_edge_files(folder: Path) -> list[Path]:
    return [image(folder / f"{name}.jpg", tags) for name, tags in MAKER_EDGES.items()]


def test_maker_note_edges(tmp_path: Path) -> None:
    paths = maker_edge_files(tmp_path)
    for args in (("--format", "json"), ("--exiftool", "--format", "json")):
        assert defects(paths, args) == [], args


BOUND_SECONDS, BOUND_BYTES = 30, 1 << 31


def _bounded() -> None:
    """In the child, before exec: at most 2 GiB of address space and 30 s of CPU."""
    import resource

    resource.setrlimit(resource.RLIMIT_AS, (BOUND_BYTES, BOUND_BYTES))
    resource.setrlimit(resource.RLIMIT_CPU, (BOUND_SECONDS, BOUND_SECONDS))


@pytest.mark.skipif(not hasattr(os, "fork"), reason="needs resource limits in a child process")
def test_each_hostile_file_alone_within_time_and_memory_bounds(tmp_path: Path) -> None:
    import subprocess
    import sys

    paths = [*HOSTILE, *maker_edge_files(tmp_path)]
    for path in paths:
        for mode in ((), ("--exiftool",)):
            done = subprocess.run([sys.executable, "-m", "camtool", "exif", *mode, "--format", "json", str(path)],
                                  capture_output=True, text=True, timeout=BOUND_SECONDS * 2, preexec_fn=_bounded,
                                  env={**os.environ, "XDG_CACHE_HOME": str(tmp_path / "cache")}, check=False)
            assert done.returncode in (0, 1), (path.name, mode, done.stderr[-500:])
            assert "Traceback" not in done.stderr and len(done.stderr.splitlines()) <= 1, (path.name, done.stderr)
            (row,) = json.loads(done.stdout)
            assert row["file"] == str(path)


@pytest.mark.skipif(not CAMERA, reason="../shared/reference/exif-samples is not there")
def test_real_camera_files_have_no_unusable_tag() -> None:
    # files straight from cameras must not trip a range: every row is read, exit 0, no tag named as unusable
    result = exif(*map(str, CAMERA), "--format", "json")
    assert result.exit_code == 0, result.stderr
    assert " is outside the valid range" not in result.stderr and len(json_rows(result)) == len(CAMERA)


def mutate(data: bytes, rng: random.Random) -> bytes:
    """A bit flip or several, a truncation, or a few bytes set to edge values; mostly in the metadata near the start."""
    out = bytearray(data)
    kind = rng.choice(("flip", "flip", "truncate", "set"))
    if kind == "truncate":
        return bytes(out[:rng.randrange(len(out))])
    for _ in range(rng.randint(1, 8)):
        index = rng.randrange(min(len(out), 4096) if rng.random() < 0.8 else len(out))
        if kind == "flip":
            out[index] ^= 1 << rng.randrange(8)
        else:
            out[index] = rng.choice((0x00, 0x01, 0x7F, 0x80, 0xFF))
    return bytes(out)


def test_mutated_files(tmp_path: Path) -> None:
    count = int(os.environ.get("CAMTOOL_EXIF_FUZZ", "600"))
    rng = random.Random(int(os.environ.get("CAMTOOL_EXIF_FUZZ_SEED", "23")))
    sources = [(p.suffix, p.read_bytes()) for p in CAMERA + OURS]
    found: list[str] = []
    batch: list[Path] = []
    formats = (("--format", "json"), ("--format", "json"), ("--format", "csv"), ("--format", "table"),
               ("--field", "file", "--field", "camera", "--field", "lens", "--field", "f_number"))
    for i in range(count):
        suffix, data = rng.choice(sources)
        path = tmp_path / f"m{i % 10}{suffix}"
        path.write_bytes(mutate(data, rng))
        batch.append(path)
        if len(batch) == 10:
            signal.alarm(60)  # a hang fails the batch, not the run
            found += [f"batch {i // 10}: {d}" for d in defects(batch, formats[(i // 10) % len(formats)])]
            batch = []
    signal.alarm(120)
    assert found == [], found[:10]
