"""camtool.core.files' guarded writer: regular or new files only, never blocking, one file per target.

Expected texts for system errors are read from os.strerror, not copied from the writer.
"""

from __future__ import annotations

import errno
import os
import sys
from pathlib import Path

import pytest
from cli_helpers import run

from camtool.core.errors import FileError
from camtool.core.files import FileProblem, SameTarget, WriteProblem, check_writable, write_bytes


def test_new_files_in_existing_directories_and_standard_output_pass(tmp_path: Path) -> None:
    check_writable([str(tmp_path / "chart.svg"), None])
    check_writable(["-", str(tmp_path / "data.json")])
    check_writable(["-", "-"])  # standard output is no file: the caller decides whether two may share it


@pytest.mark.parametrize("kind", ["missing directory", "directory", "fifo", "device", "symlink to a device"])
def test_a_target_that_is_not_a_regular_or_new_file_is_refused_with_its_place(tmp_path: Path, kind: str) -> None:
    target = tmp_path / "target"
    if kind == "missing directory":
        target = tmp_path / "none" / "chart.svg"
    elif kind == "directory":
        target.mkdir()
    elif kind == "fifo":
        os.mkfifo(target)
    elif kind == "symlink to a device":
        target.symlink_to("/dev/null")
    else:
        target = Path("/dev/null")
    with pytest.raises(WriteProblem) as caught:
        check_writable([str(tmp_path / "ok.svg"), str(target)])
    what = {"missing directory": "no such directory", "directory": "it is a directory, not a regular file",
            "fifo": "it is a FIFO (named pipe), not a regular file"}.get(kind, "it is a device, not a regular file")
    assert (caught.value.index, caught.value.path, caught.value.problem) == (1, str(target), f"cannot write there: {what}")
    assert isinstance(caught.value, FileProblem) and isinstance(caught.value, FileError)
    assert not (tmp_path / "ok.svg").exists()


def test_one_file_named_twice_by_two_paths_is_refused(tmp_path: Path) -> None:
    (tmp_path / "sub").mkdir()
    first, second = str(tmp_path / "chart.svg"), str(tmp_path / "sub" / ".." / "chart.svg")
    with pytest.raises(SameTarget) as caught:
        check_writable([first, None, second])
    assert (caught.value.path, caught.value.index, caught.value.other) == (second, 2, 0)


def test_an_existing_file_is_replaced_whole(tmp_path: Path) -> None:
    target = tmp_path / "data.json"
    target.write_bytes(b"x" * 100_000)
    write_bytes(target, b"{}\n")
    assert target.read_bytes() == b"{}\n"
    write_bytes(tmp_path / "new.bin", bytes(range(256)) * 1000)
    assert (tmp_path / "new.bin").read_bytes() == bytes(range(256)) * 1000


def test_a_fifo_or_device_in_place_at_write_time_is_refused_without_waiting(tmp_path: Path) -> None:
    fifo = tmp_path / "chart.svg"
    os.mkfifo(fifo)  # no reader: a blocking open for writing would wait for ever
    with pytest.raises(WriteProblem) as caught:
        write_bytes(fifo, b"data")
    # a FIFO without a reader cannot be opened non-blocking for writing (ENXIO); with one it is not a regular file
    assert caught.value.problem in (f"cannot write there: {os.strerror(errno.ENXIO)}",
                                    "cannot write there: it is a FIFO (named pipe), not a regular file")
    with pytest.raises(WriteProblem) as device:
        write_bytes("/dev/null", b"data")
    assert device.value.problem == "cannot write there: it is a device, not a regular file"


def test_a_closed_standard_output_is_one_problem(monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setattr(sys, "stdout", None)
    with pytest.raises(WriteProblem) as caught:
        write_bytes("-", b"data")
    assert str(caught.value) == "cannot write to standard output: it is closed"


def test_chart_names_the_option_of_the_refused_target(tmp_path: Path) -> None:
    # the targets are checked before anything is drawn (or matplotlib is needed)
    scene = ["chart", "dof", "-f", "50", "-N", "8"]
    missing = run(*scene, "-o", str(tmp_path / "none" / "dof.svg"))
    assert (missing.exit_code, missing.stderr) == (
        1, f"Error: -o/--output {tmp_path}/none/dof.svg: cannot write there: no such directory\n")
    (tmp_path / "dir").mkdir()
    directory = run(*scene, "-o", str(tmp_path / "dof.svg"), "--data", str(tmp_path / "dir"))
    assert (directory.exit_code, directory.stderr) == (
        1, f"Error: --data {tmp_path}/dir: cannot write there: it is a directory, not a regular file\n")
    same = run(*scene, "-o", str(tmp_path / "dof.svg"), "--data", f"{tmp_path}/./dof.svg")
    assert (same.exit_code, same.stderr) == (
        1, f"Error: --data {tmp_path}/./dof.svg: the same file as -o/--output; give another name\n")
