"""Hostile files: every file camtool reads goes through one guarded reader and fails fast, in one line.

Each case runs ``python -m camtool`` in a subprocess under an address-space
limit (``resource.setrlimit`` in ``preexec_fn``) and a wall-clock timeout, and
asserts the time it took: before the guarded reader, a 1 KB alias bomb given
as ``--prescription`` ran past 60 s and 3.3 GB, YAML nested 30,000 deep
crashed the interpreter with SIGSEGV (exit 139), and a FIFO blocked forever.
"""

from __future__ import annotations

import os
import re
import resource
import subprocess
import sys
import time
from pathlib import Path

import pytest

MEMORY_LIMIT = 1536 * 2**20  # address space, bytes: numpy and PyYAML start in about 600 MB of it
TIME_LIMIT_S = 15.0  # each case takes well under a second; the limit leaves room for a loaded machine

BOMB = "a: &a [x, x, x, x, x, x, x, x, x]\n" + "".join(
    f"{chr(98 + i)}: &{chr(98 + i)} [" + ", ".join([f"*{chr(97 + i)}"] * 9) + "]\n" for i in range(9))
DEEP = "[" * 30_000 + "]" * 30_000 + "\n"
DEEP_MAPPING = "".join(" " * i + f"k{i}:\n" for i in range(500)) + " " * 500 + "v\n"


def _limit() -> None:
    resource.setrlimit(resource.RLIMIT_AS, (MEMORY_LIMIT, MEMORY_LIMIT))


def camtool(tmp_path: Path, *args: str) -> tuple[int, str, str, float]:
    env = {**os.environ, "OPENBLAS_NUM_THREADS": "1", "OMP_NUM_THREADS": "1"}
    for name in ("XDG_CONFIG_HOME", "XDG_DATA_HOME", "XDG_CACHE_HOME"):
        env[name] = str(tmp_path / name.lower())
    env["XDG_CONFIG_DIRS"] = str(tmp_path / "etc-xdg")
    start = time.monotonic()
    done = subprocess.run([sys.executable, "-m", "camtool", *args], capture_output=True, text=True,
                          timeout=TIME_LIMIT_S * 2, preexec_fn=_limit, env=env, cwd=tmp_path)
    elapsed = time.monotonic() - start
    assert elapsed < TIME_LIMIT_S, f"took {elapsed:.1f} s"
    assert "Traceback" not in done.stderr, done.stderr
    return done.returncode, done.stdout, done.stderr, elapsed


def one_line_error(stderr: str, *parts: str) -> None:
    lines = stderr.splitlines()
    assert len(lines) == 1 and lines[0].startswith("Error: "), stderr
    for part in parts:
        assert part in lines[0], (part, lines[0])


DOF = ("dof", "-f", "100", "-N", "8", "-s", "3")


def uses(kind: str, path: Path) -> tuple[str, ...]:
    """The command line that reads ``path`` as ``kind``."""
    if kind == "--presets":
        return (*DOF, "--presets", str(path))
    if kind == "--prescription":
        return (*DOF, "--prescription", str(path), "--model", "paraxial")
    return ("presets", "validate", str(path))


READERS = ["--presets", "--prescription", "validate"]


@pytest.mark.parametrize("reader", READERS)
@pytest.mark.parametrize(("content", "expected"), [
    (BOMB, "expands to more than"),
    # flow nesting: PyYAML (6.0.4 on) refuses it with its own words before camtool's depth check sees it, so
    # only the contract is checked (exit 1, one line, the file and line, the option)
    (DEEP, None),
    (DEEP_MAPPING, "nested more than"),
    ("surfaces:\n  - {radius: " + "9" * 5000 + "}\n", "a number of 5000 characters"),
    ("sensors:\n  - id: d\n    width_mm: 20\n    width_mm: 21\n    height_mm: 10\n", "duplicate key 'width_mm' (lines 3 and 4)"),
])
def test_hostile_yaml_fails_fast_in_one_line(tmp_path: Path, reader: str, content: str, expected: str | None) -> None:
    path = tmp_path / "hostile.yaml"
    path.write_text(content, encoding="utf-8")
    code, stdout, stderr, _ = camtool(tmp_path, *uses(reader, path))
    assert code == 1 and stdout == ""
    wording = () if expected is None else (expected,)
    if reader == "validate":
        stderr = stderr.splitlines()[0] + "\n"
        assert stderr.startswith(f"{path}:"), stderr
        assert all(part in stderr for part in wording), stderr
    else:
        one_line_error(stderr, str(path), *wording, reader)
    assert re.search(re.escape(str(path)) + r":[1-9][0-9]*\b", stderr), stderr  # the line it stopped at


@pytest.mark.parametrize("reader", READERS)
def test_fifo_is_refused_not_waited_on(tmp_path: Path, reader: str) -> None:
    fifo = tmp_path / "pipe.yaml"
    os.mkfifo(fifo)
    code, _, stderr, elapsed = camtool(tmp_path, *uses(reader, fifo))
    assert code == 1 and elapsed < TIME_LIMIT_S
    assert "a FIFO (named pipe), not a regular file" in stderr and str(fifo) in stderr


@pytest.mark.parametrize("reader", READERS)
@pytest.mark.parametrize(("raw", "expected"), [
    ("surfaces: []\n".encode("utf-16"), "UTF-16"),
    (b"name: caf\xe9\nsurfaces: []\n", "not UTF-8 text (byte 9: 0xe9)"),
])
def test_non_utf8_is_one_line(tmp_path: Path, reader: str, raw: bytes, expected: str) -> None:
    path = tmp_path / "encoded.yaml"
    path.write_bytes(raw)
    code, _, stderr, _ = camtool(tmp_path, *uses(reader, path))
    assert code == 1
    assert expected in stderr.splitlines()[0] and str(path) in stderr.splitlines()[0]


@pytest.mark.parametrize("command", [("presets", "list"), ("presets", "show", "a"), DOF])
def test_duplicate_ids_are_one_line(tmp_path: Path, command: tuple[str, ...]) -> None:
    path = tmp_path / "dup.yaml"
    path.write_text("sensors:\n  - {id: a, width_mm: 20, height_mm: 10}\n  - {id: a, width_mm: 21, height_mm: 10}\n")
    code, _, stderr, _ = camtool(tmp_path, *command, "--presets", str(path))
    assert code == 1
    one_line_error(stderr, f"{path}:3", "id 'a' is already used by sensor 'a'", f"{path}:2")


@pytest.mark.parametrize("layout", ["entry", "directory", "subdirectory"])
def test_symlink_loop_in_config_dir_breaks_no_lookup(tmp_path: Path, layout: str) -> None:
    config = tmp_path / "xdg_config_home" / "camtool"
    if layout == "directory":
        config.parent.mkdir(parents=True)
        config.symlink_to(config)
    else:
        config.mkdir(parents=True)
        (config / "mine.yaml").write_text("sensors:\n  - {id: mine, width_mm: 20, height_mm: 10}\n")
        if layout == "entry":
            (config / "a.yaml").symlink_to(config / "b.yaml")
            (config / "b.yaml").symlink_to(config / "a.yaml")
        else:
            (config / "presets").symlink_to(config / "presets")
    code, stdout, stderr, _ = camtool(tmp_path, *DOF, "--sensor", "aps-c", "--format", "json")
    assert (code, stderr) == (0, "") and '"coc_mm"' in stdout
    if layout != "directory":
        code, _, stderr, _ = camtool(tmp_path, *DOF, "--sensor", "mine")
        assert (code, stderr) == (0, "")


def test_symlink_loop_named_directly_is_one_line(tmp_path: Path) -> None:
    loop = tmp_path / "loop.yaml"
    loop.symlink_to(loop)
    code, _, stderr, _ = camtool(tmp_path, *DOF, "--presets", str(loop))
    assert code == 1
    one_line_error(stderr, "--presets", str(loop), "a loop of symbolic links")


def test_oversized_prescription_is_refused_before_reading(tmp_path: Path) -> None:
    path = tmp_path / "huge.yaml"
    with open(path, "wb") as handle:
        handle.truncate(2 * 2**20)  # sparse: 2 MiB of zeros, over the 1 MiB cap for a prescription
    code, _, stderr, _ = camtool(tmp_path, *uses("--prescription", path))
    assert code == 1
    one_line_error(stderr, "--prescription", "larger than 1 MiB")
