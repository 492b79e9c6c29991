"""Fuzzing the whole command line: every input a right answer or a clear error.

Command lines are generated from the click definitions themselves (every command and subcommand, every
option, every argument, ``stack``, ``exif`` and ``chart`` included), with values that mix units, lists,
``inf``, absurd magnitudes, preset names and files, good and hostile, in every output (the table, JSON,
CSV, ``--field``), under odd ``COLUMNS`` and ``CAMTOOL_FORMAT``. ``exif`` reads the files of
``tests/data/exif`` and ``../shared/reference/exif-samples`` (when present) and mutated copies of them:
bytes flipped, overwritten with extreme integers, truncated, and tags rewritten with python-exiv2 to
hostile values (zero, huge and negative rationals, APEX extremes, terminal escapes, newlines). Every lens
preset is also run systematically: at infinity, by magnification, with a teleconverter and with an
extension tube, at both ends of a zoom, in each output.

Each command line runs as the console script does (``camtool.cli.main``) in a forked child of the test
process, with its standard streams in files, a time limit (``CAMTOOL_FUZZ_TIMEOUT``, 20 s) and an
address-space limit, and must keep these promises:

- no traceback, no "internal error", no crash (a signal), no hang (the time limit);
- exit status 0, 1 or 2; a failing run prints one line on standard error, ``Error: ...``, naming an
  option the user typed (or the argument), or, where the command goes on past bad items (``exif``'s
  files, ``--on-error skip``), one line per bad item naming it;
- no ``nan`` and no control character (a terminal escape, a stray newline inside a value) in any output;
- with ``--format json``: JSON without NaN or Infinity, no negative ``*_mm`` length, near ≤ focus ≤ far,
  no ``null`` where a number belongs (a limit, an f-number, a focal length, a CoC: null stands for
  infinity or for a row with a ``reason``), and ``exif`` values inside the ranges of the options they
  stand for.

The quick profile runs in ``make check``; the deep one is marked ``slow``::

    python -m pytest -m slow tests/test_cli_fuzz.py                        # 5,000 command lines
    CAMTOOL_FUZZ_EXAMPLES=50000 CAMTOOL_FUZZ_SEED=7 python -m pytest -m slow tests/test_cli_fuzz.py

``CAMTOOL_FUZZ_EXAMPLES`` sets the number of generated command lines of whichever profile runs, and
``CAMTOOL_FUZZ_SEED`` draws another reproducible set (the command lines and the mutated files). A failure
lists each defect class with its shortest command line and the last frame of the traceback.
"""

from __future__ import annotations

import contextlib
import dataclasses
import json
import math
import os
import random
import re
import resource
import shutil
import signal
import stat
import sys
import tempfile
import traceback
import warnings
from collections.abc import Iterator
from pathlib import Path
from typing import Any

import click
import pytest
from hypothesis import HealthCheck, Phase, given, seed, settings
from hypothesis import strategies as st

from camtool.cli import cli
from camtool.cli.params import FNumberType, LengthType, NumberType, TimeType
from camtool.core import ranges
from camtool.core.text import printable

QUICK_EXAMPLES = 1000
DEEP_EXAMPLES = 5000
EXIF_MUTANTS = 40  # mutated copies of the exif files, quick profile
EXIF_MUTANTS_DEEP = 400
EXAMPLES = int(os.environ.get("CAMTOOL_FUZZ_EXAMPLES", "0"))
SEED = int(os.environ.get("CAMTOOL_FUZZ_SEED", "20261123"))
TIMEOUT_S = float(os.environ.get("CAMTOOL_FUZZ_TIMEOUT", "20"))
MEMORY_HEADROOM = 3 * 2**30  # address space a child may add to what the test process already maps
OUTPUT_CAP = 4 * 2**20  # bytes of each stream read back
REPO = Path(__file__).resolve().parent.parent
WORKDIR = Path(tempfile.mkdtemp(prefix="fuzz-cwd-", dir=os.environ.get("XDG_CACHE_HOME")))  # conftest's temporary tree
EXIF_DATA = REPO / "tests" / "data" / "exif"
EXIF_SAMPLES = REPO.parent / "shared" / "reference" / "exif-samples"

# --- running one command line ------------------------------------------------------------------


@dataclasses.dataclass
class Outcome:
    argv: list[str]
    env: dict[str, str | None]
    code: int | None  # exit status, None when a signal ended it
    signal: int | None
    stdout: str
    stderr: str
    stdin: bytes = b""
    truncated: bool = False  # standard output was longer than OUTPUT_CAP: only its beginning is checked


Run = tuple[list[str], dict[str, str | None], bytes]  # argv, environment changes (None: unset), standard input
BATCH = 25  # command lines per forked child


def _address_space_limit() -> int:
    with open("/proc/self/status", encoding="ascii") as status:
        for line in status:
            if line.startswith("VmSize:"):
                return int(line.split()[1]) * 1024 + MEMORY_HEADROOM
    return resource.RLIM_INFINITY


def _run_one(argv: list[str], env: dict[str, str | None], out: int, err: int, inp: int) -> int:
    """One command line, as the console script runs it, with its streams on the given descriptors."""
    os.dup2(out, 1)
    os.dup2(err, 2)
    os.dup2(inp, 0)
    saved = {name: os.environ.get(name) for name in env}
    for name, value in env.items():
        if value is None:
            os.environ.pop(name, None)
        else:
            os.environ[name] = value
    sys.stdin = open(0, encoding="utf-8", errors="surrogateescape", closefd=False)  # noqa: SIM115
    sys.stdout = open(1, "w", encoding="utf-8", closefd=False)  # noqa: SIM115
    sys.stderr = open(2, "w", encoding="utf-8", errors="backslashreplace", closefd=False)  # noqa: SIM115
    sys.argv = ["camtool", *argv]
    signal.signal(signal.SIGINT, signal.default_int_handler)
    signal.setitimer(signal.ITIMER_REAL, TIMEOUT_S)
    from camtool.cli import main

    try:
        main()
        code = 0
    except SystemExit as done:
        if done.code is None or isinstance(done.code, int):
            code = done.code or 0
        else:
            print(done.code, file=sys.stderr)
            code = 1
    except BaseException:  # what escapes the entry point: the interpreter would print this traceback
        traceback.print_exc()
        code = 1
    signal.setitimer(signal.ITIMER_REAL, 0)
    for stream in (sys.stdout, sys.stderr):
        with contextlib.suppress(Exception):
            stream.flush()
    for name, value in saved.items():
        if value is None:
            os.environ.pop(name, None)
        else:
            os.environ[name] = value
    return code


def _fork_chunk(chunk: list[Run]) -> list[Outcome]:
    """Run ``chunk`` in one forked child; the outcomes of the runs it finished and of the one that ended it."""
    with contextlib.ExitStack() as stack:
        files = [[stack.enter_context(tempfile.TemporaryFile()) for _ in range(3)] for _ in chunk]
        results = stack.enter_context(tempfile.TemporaryFile())
        for (_, _, stdin), (_, _, inp) in zip(chunk, files):
            inp.write(stdin)
            inp.seek(0)
        sys.stdout.flush()
        sys.stderr.flush()
        with warnings.catch_warnings():
            warnings.simplefilter("ignore", DeprecationWarning)  # fork() with threads: the child starts none
            pid = os.fork()
        if pid == 0:  # pragma: no cover - the child
            status = 70
            try:
                limit = _address_space_limit()
                resource.setrlimit(resource.RLIMIT_AS, (limit, limit))
                signal.signal(signal.SIGALRM, signal.SIG_DFL)  # the time limit ends the child whatever it does
                signal.signal(signal.SIGPIPE, signal.SIG_DFL)
                os.chdir(WORKDIR)  # what a command writes by default (a chart) lands in the session's directory
                for (argv, env, _), (out, err, inp) in zip(chunk, files):
                    code = _run_one(argv, env, out.fileno(), err.fileno(), inp.fileno())
                    os.write(results.fileno(), f"{code}\n".encode())
                status = 0
            finally:
                os._exit(status)
        _, status = os.waitpid(pid, 0)
        results.seek(0)
        codes = [int(line) for line in results.read().split()]
        outcomes = []
        for i, ((argv, env, stdin), (out, err, _)) in enumerate(zip(chunk, files)):
            if i > len(codes):
                break
            out.seek(0)
            err.seek(0)
            raw = out.read(OUTPUT_CAP + 1)
            stdout = raw[:OUTPUT_CAP].decode("utf-8", errors="replace")
            stderr = err.read(OUTPUT_CAP).decode("utf-8", errors="replace")
            if i < len(codes):
                code, killed = codes[i], None
            elif os.WIFSIGNALED(status):
                code, killed = None, os.WTERMSIG(status)
            else:
                code, killed = os.WEXITSTATUS(status), None
            outcomes.append(Outcome(argv, env, code, killed, stdout, stderr, stdin, len(raw) > OUTPUT_CAP))
        return outcomes


def run_many(runs: list[Run]) -> Iterator[Outcome]:
    """Run every command line as the console script does, in forked children (time and memory limited)."""
    done = 0
    while done < len(runs):
        outcomes = _fork_chunk(runs[done:done + BATCH])
        done += len(outcomes)
        yield from outcomes


def run_forked(argv: list[str], env: dict[str, str | None] | None = None, stdin: bytes = b"") -> Outcome:
    """Run ``camtool ARGV`` alone in a forked child."""
    (outcome,) = run_many([(argv, dict(env or {}), stdin)])
    return outcome


# --- values --------------------------------------------------------------------------------------

MAGNITUDES = ["0", "-0", "-1", "-300", "1e-20", "1e-9", "1e-320", "0.0004", "0.03", "0.5", "1", "2", "3", "8", "24",
              "50", "100", "150", "1000", "5000", "5001", "1e7", "1e9", "1e15", "1e16", "1e17", "1e300", "1e304",
              "1e308", "1e309", "nan", "inf", "-inf", "∞", "+inf", "1_000", "0x10", "", " ", "abc", "1/0", "3.", ".5",
              "2,8", "5,6", "5000" * 1250]
UNITS = ["", "", "", "mm", "cm", "m", "km", "in", "ft", "um", "µm", "'", '"', "parsecs", "MM", "M", " m"]


def number() -> st.SearchStrategy[str]:
    log_uniform = st.floats(-25, 25).map(lambda e: f"{10.0 ** e:.6g}")
    return st.one_of(st.sampled_from(MAGNITUDES), log_uniform, st.integers(-10, 10**6).map(str))


def length() -> st.SearchStrategy[str]:
    single = st.one_of(st.tuples(number(), st.sampled_from(UNITS)).map("".join),
                       st.sampled_from(["5ft6in", "5'6\"", "10ft", "inf", "3m", "50mm", "0.5m", "1m", "2m", "3,5ft"]))
    return st.lists(single, min_size=1, max_size=3).map(",".join)


def f_number() -> st.SearchStrategy[str]:
    single = st.one_of(st.sampled_from(["8", "f/8", "f8", "F/2.8", "0.7", "0.69", "1024", "1025", "2048", "1.4",
                                        "22", "f/", "f/nan", "11", "16", "T2", "t/2.8"]), number())
    return st.lists(single, min_size=1, max_size=3).map(",".join)


def time() -> st.SearchStrategy[str]:
    single = st.one_of(st.sampled_from(["1/125", "1/0", "0.004", "2s", "30", "1m30s", "2h30", "2h", "1'30\"",
                                        "1/64000", "1e6", "1e7", "0"]), number())
    return st.lists(single, min_size=1, max_size=2).map(",".join)


def plain_number() -> st.SearchStrategy[str]:
    return st.lists(number(), min_size=1, max_size=2).map(",".join)


SENSORS = ["full-frame", "aps-c", "m43", "4x5", "5x4", "6x6", "6x7", "6x9", "8x10", "36x24", "36x24mm", "5x4in",
           "6x7cm", "0x24", "1e9x3", "nan x 3", "36×24", "unknown-sensor", "FF", "nikon-z-8", "3x2ft"]
CAMERAS = ["nikon-z-8", "canon-eos-5d-mark-iv", "apple-iphone-15-pro", "apple-iphone-16-pro", "fujifilm-x-t5",
           "sony-a7-iv", "no-such-camera"]
LENSES = ["sony-fe-85mm-f1.8", "canon-ef-50mm-f1.8-stm", "canon-ef-70-200mm-f2.8l-is-iii-usm",
          "canon-mp-e-65mm-f2.8-1-5x-macro", "apple-iphone-15-pro-main", "dgauss100-lens", "no-such-lens",
          # an internally focusing macro, a zoom whose smallest aperture closes down, one with no smallest
          # aperture, a lens made for APS-C, a phone module off the main sensor, a patent design, one that
          # publishes its closest focus, a standard zoom
          "canon-ef-100mm-f2.8l-macro-is-usm", "sony-fe-200-600mm-f5.6-6.3-g-oss", "nikon-z-70-180mm-f2.8",
          "fujifilm-xf35mm-f1.4-r", "apple-iphone-16-pro-ultra-wide", "nikon-z-50mm-f1.8-s-patent",
          "nikon-z-24mm-f1.8-s", "sony-fe-24-70mm-f2.8-gm-ii"]
PRESCRIPTIONS = ["dgauss100", "nikon-z50-f1.8", "dgaus100"]  # --prescription by preset name (the last unknown)
SCENES = ["landscape-24", "macro-1to1", "phone-snapshot", "portrait-85", "street-35-zone", "no-such-scene"]
NAMES = SENSORS + CAMERAS + LENSES + SCENES + ["dgauss100", "cellphone", "telephoto127", ""]
COC_RULES = ["d/1500", "d/1730", "d/1442", "d/0", "d/-3", "d/1e300", "px:2", "px:0", "px:1e9", "px:nan",
             "print:8x10in@25cm", "print:0x10in@25cm", "print:8x10in@0cm", "bogus", ""]
KEYS = ["near_mm", "far_mm", "distance_mm", "hyperfocal_mm", "f_number", "nope", "shutter_s", "horizontal_deg",
        "lens", "camera", "file", "total_mm", "working_f_number", "npf_s"]
CHOICE_GARBAGE = ["", "bogus", "ALL", "thn", "feet"]
FORMATS = ["table", "table", "json", "json", "json", "csv", "field"]
ENV_COLUMNS = [None, None, None, "1", "20", "80", "250"]
ENV_FORMAT = [None] * 10 + ["json", "csv", "garbage"]


def files(root: Path) -> dict[str, str]:
    """Preset, prescription and batch files, good and hostile, in ``root``."""
    made = {
        "good.yaml": "sensors:\n  - id: fuzz-sensor\n    width_mm: 20\n    height_mm: 10\n    source: test\n",
        "broken.yaml": "sensors:\n  - id: x\n    width_mm: [1\n",
        "dupkey.yaml": "sensors:\n  - id: d\n    width_mm: 20\n    width_mm: 21\n    height_mm: 10\n",
        "dupid.yaml": "sensors:\n  - {id: a, width_mm: 20, height_mm: 10}\n  - {id: a, width_mm: 21, height_mm: 10}\n",
        "bigint.yaml": "sensors:\n  - id: big\n    width_mm: " + "9" * 5000 + "\n    height_mm: 10\n",
        "bomb.yaml": "a: &a [x, x, x, x, x, x, x, x, x]\n" + "".join(
            f"{chr(98 + i)}: &{chr(98 + i)} [*{chr(97 + i)}, *{chr(97 + i)}, *{chr(97 + i)}, *{chr(97 + i)}, "
            f"*{chr(97 + i)}, *{chr(97 + i)}, *{chr(97 + i)}, *{chr(97 + i)}, *{chr(97 + i)}]\n" for i in range(9)),
        "deep.yaml": "[" * 5000 + "]" * 5000 + "\n",
        "empty.yaml": "",
        "batch.csv": "focal-length,f-number,distance\n50,8,3m\n35,f/2.8,10ft\n0,8,3\n",
        "batch.jsonl": '{"focal-length": 50, "f-number": 8, "distance": "inf"}\n{"focal-length": "nan"}\n',
        "cells.csv": "focal-length,f-number,distance,coc,teleconverter,extension\n50,8,3m,30,1.4,25\n50,8,3m,1e-320,,\n",
        "mixed.jsonl": '{"focal-length": 50, "f-number": 8, "distance_mm": 3000}\n'
                       '{"focal-length": 50, "f-number": 8, "distance": "3m"}\n',
        "escape.yaml": "sensors:\n  - id: esc\n    name: \"\\e[2J\\e]0;title\\a\"\n    width_mm: 20\n    height_mm: 10\n",
    }
    out = {}
    for name, text in made.items():
        (root / name).write_text(text, encoding="utf-8")
        out[name] = str(root / name)
    (root / "latin1.yaml").write_bytes(b"sensors:\n  - id: caf\xe9\n")
    (root / "utf16.yaml").write_bytes("sensors: []\n".encode("utf-16"))
    (root / "a-dir.yaml").mkdir()
    os.mkfifo(root / "fifo.yaml")
    (root / "zero.yaml").symlink_to("/dev/zero")
    shutil.copy(REPO / "lens_db" / "prescriptions" / "dgauss100.yaml", root / "dgauss100.yaml")
    for name in ("latin1.yaml", "utf16.yaml", "a-dir.yaml", "dgauss100.yaml", "fifo.yaml", "zero.yaml"):
        out[name] = str(root / name)
    out["missing"] = str(root / "missing.yaml")
    return out


# --- exif files: the shipped samples and mutated copies --------------------------------------------

EXTREME_INTS = [b"\x00\x00\x00\x00", b"\xff\xff\xff\xff", b"\x7f\xff\xff\xff", b"\x80\x00\x00\x00",
                b"\x00\x00\x00\x01", b"\xff\xff", b"\x00\x00"]


def _hostile_tags() -> list[list[tuple[str, Any]]]:
    import exiv2

    def rational(num: int, den: int = 1) -> Any:
        return exiv2.URationalValue([(num, den)])

    def srational(num: int, den: int = 1) -> Any:
        return exiv2.RationalValue([(num, den)])

    return [
        [("Exif.Photo.ApertureValue", rational(2000))],
        [("Exif.Photo.ShutterSpeedValue", srational(-(2**31)))],
        [("Exif.Photo.ShutterSpeedValue", srational(2**31 - 1))],
        [("Exif.Photo.FNumber", rational(0, 0))],
        [("Exif.Photo.FNumber", rational(65288))],
        [("Exif.Photo.FNumber", rational(3, 200_000_000))],
        [("Exif.Photo.FocalLength", rational(14_500_000))],
        [("Exif.Photo.FocalLength", rational(0))],
        [("Exif.Photo.FocalLengthIn35mmFilm", exiv2.UShortValue([65535]))],
        [("Exif.Photo.FocalPlaneXResolution", rational(1, 1000)), ("Exif.Photo.FocalPlaneResolutionUnit",
                                                                    exiv2.UShortValue([2]))],
        [("Exif.Photo.SubjectDistance", rational(4294967295, 1))],
        [("Exif.Photo.ExposureTime", rational(1, 0))],
        [("Exif.Photo.ISOSpeedRatings", exiv2.UShortValue([0]))],
        [("Exif.Image.Make", "\x1b[2J\x1b]0;owned\x07Canon")],
        [("Exif.Photo.LensModel", "EF 50mm\nf/1.8\nII")],
        [("Exif.Image.Model", "NIKON D850\r\x00\x7f")],
    ]


def exif_pool(root: Path, rng: random.Random, mutants: int) -> list[str]:
    """The exif inputs: tests/data/exif, the reference samples (when present), ``mutants`` mutated copies,
    files written with hostile tags, and paths that are not regular files or not UTF-8."""
    sources = sorted(p for p in EXIF_DATA.iterdir() if p.suffix.lower() in (".jpg", ".jpeg"))
    for sub in ("camera", "hostile"):
        if (EXIF_SAMPLES / sub).is_dir():
            sources += sorted(p for p in (EXIF_SAMPLES / sub).iterdir() if p.is_file())
    pool = [str(p) for p in sources]
    for i in range(mutants):
        source = rng.choice(sources)
        data = bytearray(source.read_bytes())
        kind = rng.choice(["flip", "flip", "int", "int", "truncate", "append"])
        if kind == "flip" and data:
            for _ in range(rng.choice([1, 4, 32])):
                at = rng.randrange(len(data))
                data[at] ^= 1 << rng.randrange(8)
        elif kind == "int" and len(data) > 8:
            for _ in range(rng.choice([1, 3, 10])):
                value = rng.choice(EXTREME_INTS)
                at = rng.randrange(len(data) - len(value))
                data[at:at + len(value)] = value
        elif kind == "truncate":
            del data[rng.randrange(max(1, min(len(data), 4096))):]
        else:
            data += bytes(rng.randrange(256) for _ in range(rng.choice([1, 100, 5000])))
        path = root / f"mutant-{i:03d}-{kind}{source.suffix}"
        path.write_bytes(bytes(data))
        pool.append(str(path))
    with contextlib.suppress(ImportError):
        import exiv2

        for i, tags in enumerate(_hostile_tags()):
            path = root / f"hostile-tags-{i:02d}.jpg"
            apex = any(key.endswith(("ApertureValue", "ShutterSpeedValue")) for key, _ in tags)  # read without FNumber
            base = "sony_apex_lens.jpg" if apex else rng.choice(["nikon.jpg", "canon_bracket.jpg", "sony_apex_lens.jpg"])
            shutil.copy(EXIF_DATA / base, path)
            path.chmod(stat.S_IRUSR | stat.S_IWUSR)
            image = exiv2.ImageFactory.open(str(path))
            image.readMetadata()
            data = image.exifData()
            for key, value in tags:
                data[key] = value
            image.writeMetadata()
            pool.append(str(path))
    os.mkfifo(root / "fifo.jpg")
    (root / "a-dir.jpg").mkdir()
    shutil.copy(EXIF_DATA / "nikon.jpg", root / "a-dir.jpg" / "inside.jpg")
    bad_name = os.fsencode(root) + b"/caf\xe9-\xff.jpg"
    with open(bad_name, "wb") as handle:
        handle.write((EXIF_DATA / "nikon.jpg").read_bytes())
    pool += [str(root / "fifo.jpg"), str(root / "a-dir.jpg"), os.fsdecode(bad_name), str(root / "missing.jpg"),
             "/dev/zero", "-"]
    return pool


# --- command lines from the click definitions ------------------------------------------------------


def commands() -> list[tuple[list[str], click.Command]]:
    """(argv prefix, command) for every leaf command."""
    ctx = click.Context(cli, help_option_names=["-h", "--help"])  # as the command line makes it (click caches it)
    out = []
    for name in cli.list_commands(ctx):
        command = cli.get_command(ctx, name)
        assert command is not None
        if isinstance(command, click.Group):
            sub_ctx = click.Context(command, parent=ctx, help_option_names=["-h", "--help"])
            for sub in command.list_commands(sub_ctx):
                leaf = command.get_command(sub_ctx, sub)
                assert leaf is not None
                out.append(([name, sub], leaf))
        else:
            out.append(([name], command))
    return out


COMMANDS = commands()
LEAVES = {" ".join(prefix): command for prefix, command in COMMANDS}
# the commands with the most paths through them are drawn more often
WEIGHTS = {"dof": 4, "stack": 4, "exif": 3, "hyperfocal": 2, "tilt": 2}
DRAWN = [entry for entry in COMMANDS for _ in range(WEIGHTS.get(" ".join(entry[0]), 1))]


@dataclasses.dataclass
class Inputs:
    paths: dict[str, str]
    exif: list[str]
    out_dir: Path


def values_for(param: click.Parameter, inputs: Inputs) -> st.SearchStrategy[str]:
    name = param.name or ""
    kind = param.type
    paths = inputs.paths
    file_values = st.sampled_from(sorted(paths.values()))
    if name in ("sensor",):
        return st.sampled_from(SENSORS)
    if name == "camera":
        return st.sampled_from(CAMERAS)
    if name == "lens":
        return st.sampled_from(LENSES)
    if name == "scene":
        return st.sampled_from(SCENES)
    if name == "coc_rule":
        return st.sampled_from(COC_RULES)
    if name == "fields":
        return st.sampled_from(KEYS)
    if name == "prescription_file":
        return st.one_of(file_values, st.sampled_from(PRESCRIPTIONS))
    if name in ("files", "paths") or (isinstance(kind, click.Path) and param.nargs == -1):
        return st.sampled_from(inputs.exif)
    if name in ("out", "output", "data") or (isinstance(kind, (click.Path, click.File)) and "w" in str(
            getattr(kind, "mode", ""))):
        fresh = st.integers(0, 10**6).map(lambda n: str(inputs.out_dir / f"out-{n}.svg"))
        return st.one_of(fresh, st.sampled_from(["-", paths["fifo.yaml"], paths["a-dir.yaml"],
                                                 str(inputs.out_dir / "no-dir" / "x.png")]))
    if name in ("preset_files", "batch", "file"):
        return file_values
    if name == "dirs":
        return st.sampled_from([str(Path(paths["good.yaml"]).parent), paths["missing"], paths["fifo.yaml"]])
    if name == "name":
        return st.sampled_from(NAMES)
    if name == "size":
        return st.sampled_from(["8x10in", "30x20cm", "200x200", "1000x1000in", "0x5", "nan x 3", "A4", "1e9x1", ""])
    if isinstance(kind, click.Choice):
        return st.one_of(st.sampled_from(list(kind.choices)), st.sampled_from(CHOICE_GARBAGE))
    if isinstance(kind, FNumberType):
        return f_number()
    if isinstance(kind, TimeType):
        return time()
    if isinstance(kind, LengthType):
        return length()
    if isinstance(kind, NumberType):
        return plain_number()
    if name in ("hiatus",):
        return length()
    if name in ("nd",):
        return st.sampled_from(["ND1000", "ND8", "3", "nd0", "ND-2", "10 stops", "x", "1e9"])
    if name in ("film",):
        return st.sampled_from(["hp5", "tri-x", "portra-400", "no-film"])
    if name in ("light",):
        return st.sampled_from(["sunny", "overcast", "night", "no-light"])
    if name in ("shell",):
        return st.sampled_from(["bash", "zsh", "fish", "tcsh"])
    if isinstance(kind, click.Path):
        return st.one_of(file_values, st.sampled_from(inputs.exif))
    return st.one_of(number(), length(), st.sampled_from(NAMES))


# ordinary values for the cores: every combination of them must be a plan or a clear error
FOCAL = st.sampled_from(["14", "24", "50", "100", "200", "600"])
MAGNIFICATION = st.sampled_from(["0.001", "0.01", "0.1", "0.5", "1", "2", "5"])
APERTURE = st.sampled_from(["1.4", "2.8", "8", "16", "32"])
DEPTH = st.sampled_from(["1mm", "10mm", "10cm", "1m", "10m", "100m"])

BASE: dict[str, list[list[Any]]] = {  # mostly valid cores, so that the other options are exercised past the first error
    "dof": [["-f", "50", "-N", "8", "-s", "3"], ["--lens", "nikon-z-24mm-f1.8-s", "-N", "11", "-s", "inf"],
            ["--camera", "sony-a7-iv", "--lens", "sony-fe-24-70mm-f2.8-gm-ii", "-f", "24", "-N", "8", "-s", "inf"],
            ["-f", "200", "-N", "4", "-s", "inf", "--teleconverter", "1.4"], ["-f", "100", "-N", "8", "-m", "1"]],
    "hyperfocal": [["-f", "24", "-N", "8"]],
    "fov": [["-f", "50"]],
    "focus": [["-f", "100", "-s", "0.5m"]],
    "compose": [["--subject-size", "1.8m", "--fill", "0.8"]],
    "exposure": [["-N", "16", "-t", "1/125"]],
    "stars": [["-f", "24", "-N", "2.8"]],
    "flash": [["--gn", "20", "-s", "5", "--iso", "100"]],
    "equiv": [["-f", "25", "-N", "1.4", "--iso", "200", "--sensor", "m43"]],
    "tilt": [["-f", "90", "-N", "11", "-s", "2m", "--tilt", "3"]],
    "stack": [["-m", "1", "-N", "8", "--depth", "10mm"],
              ["-f", FOCAL, "-m", MAGNIFICATION, "-N", APERTURE, "--depth", DEPTH],
              ["-f", "24", "-N", "11", "--near", "0.5", "--far", "inf"],
              ["-f", FOCAL, "-N", APERTURE, "--near", DEPTH, "--far", st.sampled_from(["3m", "inf", "100m"])],
              ["-f", "100", "-N", "8", "--near", "1m", "--far", "3m"]],
    "chart dof": [["-f", "35", "-N", "8"]],
    "chart blur": [["--subject-size", "1.8m", "--fill", "0.8", "-f", "35,85", "-N", "2.8"]],
    "chart aperture": [["-f", "24", "--near", "2m", "--far", "inf"]],
    "chart trade": [["-N", "8", "-s", "3m", "--lens", "dgauss100-lens"]],
    "chart card": [["-f", "35"]],
}


def with_format(argv: list[str], command: click.Command, fmt: str, field: str) -> list[str]:
    names = {p.name for p in command.params}
    if "--format" in argv or "fmt" not in names:
        return argv
    if fmt == "field":
        return [*argv, "--field", field] if "fields" in names and "--field" not in argv else argv
    return argv if fmt == "table" else [*argv, "--format", fmt]


@st.composite
def command_line(draw: Any, inputs: Inputs) -> tuple[list[str], dict[str, str | None]]:
    prefix, command = draw(st.sampled_from(DRAWN))
    argv = list(prefix)
    cores = BASE.get(" ".join(prefix), [])
    if cores and (draw(st.booleans()) or draw(st.booleans())):
        argv += [part if isinstance(part, str) else draw(part) for part in draw(st.sampled_from(cores))]
    options = [p for p in command.params if isinstance(p, click.Option) and p.name != "help"]
    chosen = draw(st.lists(st.sampled_from(options), max_size=5)) if options else []
    for param in chosen:
        if param.is_flag:
            argv.append(draw(st.sampled_from(param.opts + param.secondary_opts)))
        else:
            argv += [draw(st.sampled_from(param.opts)), draw(values_for(param, inputs))]
    for param in command.params:
        if isinstance(param, click.Argument):
            count = draw(st.integers(1, 3)) if param.nargs == -1 else 1
            argv += [draw(values_for(param, inputs)) for _ in range(count)]
    argv = with_format(argv, command, draw(st.sampled_from(FORMATS)), draw(st.sampled_from(KEYS)))
    env = {"COLUMNS": draw(st.sampled_from(ENV_COLUMNS)), "CAMTOOL_FORMAT": draw(st.sampled_from(ENV_FORMAT)),
           "CAMTOOL_NO_CACHE": draw(st.sampled_from([None, None, "1"]))}
    return argv, env


# --- the promises ------------------------------------------------------------------------------------

OPTION = re.compile(r"'-{1,2}[\w-]+'|'[A-Z]+'|(?<![\w-])--?[A-Za-z][\w-]*")
CONTROL = re.compile(r"[\x00-\x08\x0b-\x1f\x7f-\x9f]")
SIGNED_KEYS = ("at_mm", "above_mm", "below_mm", "across_mm", "hinge_mm")  # tilt's positions have a sign
# a number or null-for-infinity is fine; these are never null in a row without a reason
NEVER_NULL = ("near_mm", "f_number", "focal_length_mm", "coc_mm", "working_f_number", "magnification")
EXIF_RANGES = {"f_number": ranges.F_NUMBER, "focal_length_mm": ranges.FOCAL_LENGTH_MM, "coc_mm": ranges.COC_MM,
               "crop_factor": ranges.CROP_FACTOR, "sensor_width_mm": ranges.SENSOR_SIDE_MM,
               "sensor_height_mm": ranges.SENSOR_SIDE_MM, "focus_distance_mm": ranges.DISTANCE_MM}
TRACEBACK_FRAME = re.compile(r'^\s*File "([^"]+)", line (\d+), in (\S+)', re.M)


def last_frame(stderr: str) -> str:
    frames = TRACEBACK_FRAME.findall(stderr)
    if not frames:
        return ""
    file, line, function = frames[-1]
    return f"{os.path.relpath(file, REPO) if file.startswith(str(REPO)) else file}:{line} in {function}"


def typed_options(argv: list[str]) -> set[str]:
    """Every spelling of every option the command line typed (``-f`` stands for ``--focal-length`` too)."""
    command = LEAVES.get(" ".join(argv[:2])) or LEAVES.get(argv[0] if argv else "")
    typed = {a.split("=", 1)[0] for a in argv if a.startswith("-")}
    if command is None:
        return typed
    for param in command.params:
        spellings = set(getattr(param, "opts", [])) | set(getattr(param, "secondary_opts", []))
        if spellings & typed:
            typed |= spellings
    return typed


def check(outcome: Outcome) -> str:
    """The defect class of one run, with its detail ('' when it kept every promise)."""
    argv, stdout, stderr = outcome.argv, outcome.stdout, outcome.stderr
    if outcome.signal == signal.SIGALRM:
        return f"hang: no answer within {TIMEOUT_S:g} s"
    if outcome.signal is not None:
        return f"crash: signal {signal.Signals(outcome.signal).name}"
    if "Traceback (most recent call last)" in stderr:
        tail = stderr[stderr.rindex("Traceback (most recent call last)"):].splitlines()[1:]
        raised = [line for line in tail if line and not line[0].isspace()] or tail[-1:] or [""]
        return f"traceback: {raised[-1][:160]} at {last_frame(stderr)}"
    if "internal error" in stderr:
        return f"internal error: {stderr.strip()[:200]}"
    if outcome.code not in (0, 1, 2):
        return f"exit status: {outcome.code}"
    image = argv[:1] == ["chart"] and stdout.startswith(("\ufffdPNG", "%PDF", "<?xml"))  # -o -: the chart itself
    if CONTROL.search(stdout) and not image:
        return f"control character in output: {CONTROL.search(stdout).group()!r}"  # type: ignore[union-attr]
    if CONTROL.search(stderr.replace("\n", "")):
        return f"control character in an error: {stderr[:200]!r}"
    if outcome.code:
        return check_error(outcome)
    if re.search(r"\bnan\b", stdout, flags=re.I):
        return "nan printed"
    formats = [argv[i + 1] for i, a in enumerate(argv[:-1]) if a == "--format"]
    command = LEAVES.get(" ".join(argv[:2])) or LEAVES.get(argv[0] if argv else "")
    takes_format = command is not None and "fmt" in {p.name for p in command.params}
    fmt = formats[-1] if formats else (outcome.env.get("CAMTOOL_FORMAT") if takes_format else None) or "table"
    if argv[:1] == ["exif"] and "--field" in argv and fmt == "json":
        files = [a for a in argv[1:] if not a.startswith("-") and os.path.isfile(a)]
        if len(files) == len(argv) - 1 - 2 * argv.count("--field") and len(stdout.splitlines()) > len(files):
            return f"--field row split over lines: {stdout[:200]!r}"
    if fmt != "json" or "--field" in argv or outcome.truncated:
        return ""
    return check_json(argv, stdout)


def check_error(outcome: Outcome) -> str:
    argv, stderr = outcome.argv, outcome.stderr
    lines = stderr.splitlines()
    if argv[:2] == ["presets", "validate"] and outcome.code == 1:
        lines = lines[-1:]  # validate lists every problem of the file, then one summary line
    if outcome.code == 1 and (len(lines) > 1 or stderr.startswith("camtool")):
        # a run that goes on past bad items (--on-error skip, exif's files) reports each on its own line,
        # then maybe a count: each must name what was typed
        for line in lines:
            if re.match(r"camtool( \w+)?: \d+ of \d+ \w+ skipped$", line):
                continue
            if line.startswith("camtool: left out to fit "):  # the table's note on columns it had no room for
                continue
            named = [*argv[1:], *outcome.stdin.decode("utf-8", "surrogateescape").splitlines()]
            named += [printable(a) for a in named]  # a name with bytes that are no text is printed escaped (\xff)
            if line.startswith("camtool") and any(a in line for a in named if a):
                continue
            if line.startswith("Error: ") and OPTION.search(line):
                continue
            return f"error not one line: {line!r} in {stderr[:300]!r}"
        return ""
    if len(lines) != 1 or not lines[0].startswith("Error: "):
        return f"error not one line: {stderr[:300]!r}"
    line = lines[0]
    typed_path = any(len(a) > 1 and a in line for a in argv if "/" in a)  # a FILE argument, named as typed
    if not OPTION.search(line) and not typed_path:
        return f"error names no option: {line}"
    blamed = re.match(r"Error: Invalid value for ('[^']+'(?: / '[^']+')*)", line)
    if blamed:
        named = set(re.findall(r"'(-{1,2}[\w-]+)'", blamed.group(1)))
        if named and not named & typed_options(argv):
            return f"error names an option not typed: {line[:200]}"
    return ""


def check_json(argv: list[str], stdout: str) -> str:
    try:
        rows = json.loads(stdout, parse_constant=lambda c: (_ for _ in ()).throw(ValueError(c)))
    except ValueError as error:
        return f"JSON not parseable or holds NaN/Infinity: {error}"
    signed = argv[:2] == ["presets", "show"] or argv[:1] == ["tilt"]  # cardinal points, tilt's signed positions
    for row in rows if isinstance(rows, list) else [rows]:
        if not isinstance(row, dict):
            continue
        for key, value in row.items():
            if isinstance(value, float) and not math.isfinite(value):
                return f"non-finite {key}"
            if (key.endswith("_mm") and isinstance(value, (int, float)) and value < 0 and not signed
                    and key not in SIGNED_KEYS):
                return f"negative distance: {key} = {value}"
        if argv[:1] == ["exif"]:
            for key, bounds in EXIF_RANGES.items():
                value = row.get(key)
                if isinstance(value, (int, float)) and not ranges.in_range(value, bounds):
                    return f"exif value out of range: {key} = {value}"
            continue
        if not row.get("reason") and not row.get("error") and argv[:1] in (["dof"], ["hyperfocal"], ["stack"]):
            for key in NEVER_NULL:
                if key in row and row[key] is None:
                    return f"null where a number belongs: {key}"
        near, focus, far = row.get("near_mm"), row.get("distance_mm"), row.get("far_mm")
        far = math.inf if far is None and "far_mm" in row else far
        focus = math.inf if focus is None and "distance_mm" in row else focus
        if "wanted_near_mm" not in row and all(isinstance(v, (int, float)) for v in (near, focus, far)):
            assert isinstance(near, (int, float)) and isinstance(focus, (int, float)) and isinstance(far, (int, float))
            if not near <= focus * (1 + 1e-9) or not focus <= far * (1 + 1e-9):
                return f"not near ≤ focus ≤ far: {near}, {focus}, {far}"
    return ""


class Findings:
    """Defects by class, each with its shortest command line."""

    def __init__(self) -> None:
        self.tried = 0
        self.by_class: dict[str, list[str]] = {}

    def record(self, outcome: Outcome) -> None:
        self.tried += 1
        defect = check(outcome)
        if not defect:
            return
        kind = defect.split(":")[0]
        if kind in ("traceback", "error names an option not typed"):
            kind = defect.split(" at ")[-1] if kind == "traceback" else kind  # one class per place it breaks
            kind = f"traceback at {kind}" if defect.startswith("traceback") else kind
        env = " ".join(f"{k}={v}" for k, v in outcome.env.items() if v is not None)
        line = f"{env + ' ' if env else ''}camtool {' '.join(map(quote, outcome.argv))}  ->  {defect}"
        self.by_class.setdefault(kind, []).append(line)

    def report(self) -> str:
        lines = []
        for kind, found in sorted(self.by_class.items()):
            shortest = sorted(found, key=len)
            lines.append(f"{kind} ({len(found)}):\n  " + "\n  ".join(shortest[:3]))
        return f"{sum(map(len, self.by_class.values()))} of {self.tried} command lines failed:\n" + "\n".join(lines)


def quote(arg: str) -> str:
    return arg if re.fullmatch(r"[\w@%+=:,./-]+", arg) else "'" + arg.replace("'", "'\"'\"'") + "'"


# --- the tests ---------------------------------------------------------------------------------------


@pytest.fixture(scope="module")
def inputs(tmp_path_factory: pytest.TempPathFactory) -> Iterator[Inputs]:
    root = tmp_path_factory.mktemp("fuzz")
    for sub in ("files", "exif", "out"):
        (root / sub).mkdir()
    rng = random.Random(SEED)
    yield Inputs(files(root / "files"), exif_pool(root / "exif", rng, EXIF_MUTANTS), root / "out")


@pytest.fixture(autouse=True)
def plain_environment(monkeypatch: pytest.MonkeyPatch) -> None:
    for name in ("COLUMNS", "CAMTOOL_FORMAT", "NO_COLOR", "CAMTOOL_NO_CACHE"):
        monkeypatch.delenv(name, raising=False)


def fuzz(inputs: Inputs, examples: int, fuzz_seed: int) -> Findings:
    runs: list[Run] = []

    @seed(fuzz_seed)
    @settings(max_examples=examples, derandomize=False, database=None, deadline=None,
              phases=[Phase.explicit, Phase.generate], suppress_health_check=list(HealthCheck))
    @given(line=command_line(inputs))
    def draw(line: tuple[list[str], dict[str, str | None]]) -> None:
        argv, env = line
        stdin = b"\n".join(os.fsencode(p) for p in inputs.exif[:3]) + b"\n" if "-" in argv else b""
        runs.append((argv, env, stdin))

    draw()  # the command lines first, then run in batches: one forked child for many
    findings = Findings()
    for outcome in run_many(runs):
        findings.record(outcome)
    return findings


def test_cli_fuzz(inputs: Inputs) -> None:
    examples = EXAMPLES or QUICK_EXAMPLES
    findings = fuzz(inputs, examples, SEED)
    assert not findings.by_class, findings.report()
    assert findings.tried >= examples * 0.9, findings.tried


@pytest.mark.slow
def test_cli_fuzz_deep(inputs: Inputs) -> None:
    examples = EXAMPLES or DEEP_EXAMPLES
    findings = fuzz(inputs, examples, SEED)
    assert not findings.by_class, findings.report()
    assert findings.tried >= examples * 0.9, findings.tried


def lens_lines(deep: bool) -> list[list[str]]:
    """Every lens preset (a zoom at both ends) at infinity as a table, and one of (by magnification in JSON, at
    infinity in JSON, a teleconverter, an extension tube) in turn; ``deep`` runs all four on every preset and adds
    CSV, --field, other distances and --model all."""
    from camtool.presets import load_db

    lines = []
    turn = 0
    for lens in load_db(use_cache=False, lensfun=False).all("lens"):
        zoom = lens.focal_min_mm != lens.focal_max_mm
        for f in ([["-f", f"{lens.focal_min_mm:g}"], ["-f", f"{lens.focal_max_mm:g}"]] if zoom else [[]]):
            base = ["dof", "--lens", lens.id, *f]
            lines.append([*base, "-N", "11", "-s", "inf"])
            others = [
                [*base, "-N", "8", "-m", "0.5", "--format", "json"],
                [*base, "-N", "8", "-s", "inf", "--format", "json"],
                [*base, "-N", "4", "-s", "inf", "--teleconverter", "1.4"],
                [*base, "-N", "8", "-s", "inf", "--extension", "12", "--format", "json"],
            ]
            lines += others if deep else [others[turn % len(others)]]
            turn += 1
            if deep:
                lines += [
                    [*base, "-N", "8", "-s", "inf", "--format", "csv"],
                    [*base, "-N", "8", "-s", "inf", "--field", "near_mm"],
                    [*base, "-N", "8", "-m", "0.5"],
                    [*base, "-N", "4", "-s", "inf", "--teleconverter", "1.4", "--format", "json"],
                    [*base, "-N", "4", "-s", "2m", "--teleconverter", "2"],
                    [*base, "-N", "8", "-s", "0.3m", "--extension", "25", "--format", "json"],
                    [*base, "-N", "8", "-s", "3", "--model", "all", "--diffraction", "--format", "json"],
                    ["stack", "--lens", lens.id, *f, "-N", "8", "--near", "1m", "--far", "inf", "--format", "json"],
                    ["hyperfocal", "--lens", lens.id, *f, "-N", "8", "--format", "json"],
                ]
    return lines


def every_lens(deep: bool) -> None:
    findings = Findings()
    lines = lens_lines(deep)
    assert len(lines) > 1300  # 477 lenses, zooms at both ends
    for outcome in run_many([(argv, {}, b"") for argv in lines]):
        findings.record(outcome)
    assert not findings.by_class, findings.report()


def test_every_lens_preset() -> None:
    every_lens(deep=False)


@pytest.mark.slow
def test_every_lens_preset_deep() -> None:
    every_lens(deep=True)


def test_every_exif_input(inputs: Inputs) -> None:
    """Each exif input alone, in JSON, as a table and with --field; all of them from stdin; a folder with -r."""
    every_exif_input(inputs.exif)


@pytest.mark.slow
def test_every_exif_input_deep(tmp_path: Path) -> None:
    """The same over ten times as many mutated copies (``CAMTOOL_FUZZ_SEED`` draws another set)."""
    every_exif_input(exif_pool(tmp_path, random.Random(SEED + 1), EXIF_MUTANTS_DEEP))


def every_exif_input(pool: list[str]) -> None:
    runs: list[Run] = []
    for path in pool:
        stdin = (os.fsencode(pool[0]) + b"\n") if path == "-" else b""
        runs += [(["exif", path, "--format", "json"], {}, stdin), (["exif", path], {}, stdin),
                 (["exif", path, "--format", "json", "--field", "lens"], {}, stdin)]
    runs.append((["exif", "-r", str(Path(pool[-3]).parent), "--format", "csv"], {}, b""))
    paths = b"\n".join(os.fsencode(p) for p in pool if p != "-") + b"\n"
    runs.append((["exif", "-", "--format", "json"], {}, paths))
    findings = Findings()
    for outcome in run_many(runs):
        findings.record(outcome)
    assert not findings.by_class, findings.report()


def test_the_checks_catch_what_they_promise() -> None:
    """Each check fails on the defect it is there for (a check that cannot fail is no check)."""
    ok = Outcome(["dof"], {}, 0, None, "", "")
    cases = {
        "hang": dataclasses.replace(ok, code=None, signal=signal.SIGALRM),
        "crash": dataclasses.replace(ok, code=None, signal=signal.SIGSEGV),
        "traceback": dataclasses.replace(ok, code=1, stderr='Traceback (most recent call last):\n  File "x.py", '
                                                            'line 3, in f\nValueError: cannot convert float NaN\n'),
        "internal error": dataclasses.replace(ok, code=1, stderr="Error: internal error: a NaN reached the output\n"),
        "exit status": dataclasses.replace(ok, code=3),
        "error not one line": dataclasses.replace(ok, code=2, stderr="Error: Usage: camtool dof\n  -f\n"),
        "error names an option not typed": dataclasses.replace(
            ok, argv=["hyperfocal", "-f", "50", "-N", "8", "--pupil-mag", "0.4"], code=2,
            stderr="Error: Invalid value for '--hiatus': too large\n"),
        "nan printed": dataclasses.replace(ok, stdout="near  nan m\n"),
        "control character in output": dataclasses.replace(ok, stdout="\x1b[2JCanon\n"),
        "JSON not parseable or holds NaN/Infinity": dataclasses.replace(
            ok, argv=["dof", "--format", "json"], stdout='[{"far_mm": Infinity}]'),
        "negative distance": dataclasses.replace(ok, argv=["stack", "--format", "json"], stdout='[{"near_mm": -3}]'),
        "null where a number belongs": dataclasses.replace(
            ok, argv=["dof", "--format", "json"], stdout='[{"near_mm": 1, "working_f_number": null}]'),
        "exif value out of range": dataclasses.replace(
            ok, argv=["exif", "a.jpg", "--format", "json"], stdout='[{"f_number": 65288}]'),
        "not near ≤ focus ≤ far": dataclasses.replace(
            ok, argv=["dof", "--format", "json"], stdout='[{"near_mm": 5, "distance_mm": 3, "far_mm": 9}]'),
    }
    for kind, outcome in cases.items():
        assert check(outcome).startswith(kind), (kind, check(outcome))
    assert check(dataclasses.replace(ok, argv=["dof", "--format", "json"],
                                     stdout='[{"near_mm": 1, "distance_mm": null, "far_mm": null}]')) == ""


def test_the_child_reports_hangs_tracebacks_and_exit_codes(monkeypatch: pytest.MonkeyPatch) -> None:
    """The forked runner sees what a shell would: a real run, its exit status, a traceback, a time-out."""
    good = run_forked(["dof", "-f", "50", "-N", "8", "-s", "3", "--format", "json"])
    assert (good.code, good.stderr) == (0, "") and json.loads(good.stdout)[0]["f_number"] == 8
    bad = run_forked(["dof", "-f", "50", "-N", "8", "-s", "-3"])
    assert bad.code == 2 and check(bad) == ""
    monkeypatch.setattr(sys.modules[__name__], "TIMEOUT_S", 0.5)
    fifo = Path(tempfile.mkdtemp(dir=os.environ.get("TMPDIR"))) / "pipe"
    os.mkfifo(fifo)
    import camtool.cli

    real = camtool.cli.main
    monkeypatch.setattr(camtool.cli, "main", lambda: open(fifo).read())  # noqa: SIM115 - blocks: no writer
    hang = run_forked(["dof"])
    assert check(hang).startswith("hang"), hang
    monkeypatch.setattr(camtool.cli, "main", lambda: 1 / 0)
    broken = run_forked(["dof"])
    assert check(broken).startswith("traceback: ZeroDivisionError") and "test_cli_fuzz.py" in check(broken)
    monkeypatch.setattr(camtool.cli, "main", real)
