"""The installed entry point as a subprocess: pipes, head -1, NO_COLOR, completion, batch from stdin."""

from __future__ import annotations

import json
import os
import pty
import re
import shutil
import subprocess
import sys
from collections.abc import Callable

import pytest

CAMTOOL = shutil.which("camtool", path=os.path.dirname(sys.executable)) or shutil.which("camtool")
pytestmark = pytest.mark.skipif(CAMTOOL is None, reason="the camtool entry point is not installed")
ENV = {k: v for k, v in os.environ.items() if k not in ("COLUMNS", "NO_COLOR", "CAMTOOL_FORMAT")}


def sh(script: str, env: dict[str, str] | None = None) -> subprocess.CompletedProcess[str]:
    path = os.path.dirname(CAMTOOL) + os.pathsep + ENV.get("PATH", "")
    return subprocess.run(["bash", "-c", script], capture_output=True, text=True,
                          env={**ENV, "PATH": path, **(env or {})}, timeout=60)


def test_pipe_gets_plain_text_and_errors_go_to_stderr() -> None:
    ok = sh("camtool dof -f 50 -N 8 -s 3m | cat")
    assert ok.returncode == 0 and "\x1b[" not in ok.stdout and ok.stderr == ""
    bad = sh("camtool dof -f 50 -N 8 -s 0.1 | cat")
    assert bad.stdout == "" and bad.stderr.startswith("Error: Invalid value for '-s'")
    code = sh("camtool dof -f 50 -N 8 -s 0.1 > /dev/null; echo $?")
    assert code.stdout.strip() == "2"


def test_head_ends_quietly() -> None:
    rows = "".join(f"50,8,{d}\n" for d in range(1, 20001))
    result = subprocess.run(["bash", "-c", "camtool dof --batch - --format csv | head -1"], input=
                            "focal-length,f-number,distance\n" + rows, capture_output=True, text=True,
                            env={**ENV, "PATH": os.path.dirname(CAMTOOL) + os.pathsep + ENV["PATH"]}, timeout=120)
    assert result.stdout.startswith("focal_length_mm,")
    assert result.stderr == ""


def _in_terminal(args: list[str], env: dict[str, str]) -> str:
    """Run camtool on a pseudo-terminal and return what it drew."""
    pid, fd = pty.fork()
    if pid == 0:  # child
        os.execve(CAMTOOL, [CAMTOOL, *args], {**ENV, "COLUMNS": "200", "TERM": "xterm-256color", **env})
    return drain(pid, fd)[0].decode()


def drain(pid: int, fd: int, on_data: Callable[[bytes], None] | None = None) -> tuple[bytes, int]:
    """What a child on a pseudo-terminal drew, until it closes it (60 s at most), and its exit status.

    ``on_data`` is called with everything drawn so far after each read (to send a signal, say).
    """
    import time

    chunks: list[bytes] = []
    deadline = time.monotonic() + 60
    while time.monotonic() < deadline:
        try:
            data = os.read(fd, 65536)
        except OSError:
            break
        if not data:
            break
        chunks.append(data)
        if on_data is not None:
            on_data(b"".join(chunks))
    _, status = os.waitpid(pid, 0)
    return b"".join(chunks), os.waitstatus_to_exitcode(status)


def test_no_color_is_honoured_on_a_terminal() -> None:
    args = ["dof", "-f", "50", "-N", "8", "-s", "3m"]
    coloured = _in_terminal(args, {})
    plain = _in_terminal(args, {"NO_COLOR": "1"})
    assert "3.000" in coloured and "3.000" in plain
    colour_codes = ("\x1b[3", "\x1b[9", "38;", ";3")
    assert not any(code in plain for code in colour_codes)


def test_columns_is_respected() -> None:
    wide = sh("camtool dof -f 50 -N 8 -s 3m", {"COLUMNS": "200"}).stdout
    narrow = sh("camtool dof -f 50 -N 8 -s 3m", {"COLUMNS": "70"}).stdout
    assert max(len(line) for line in narrow.splitlines()) <= 70
    assert "sharp zone" in wide and "sharp zone" not in narrow


def test_batch_from_stdin_as_subprocess() -> None:
    result = sh("printf 'focal-length,f-number,distance\\n50,8,3\\n' | camtool dof --batch - --format json")
    assert json.loads(result.stdout)[0]["distance_mm"] == 3000.0


def _complete(words: str) -> list[str]:
    script = f'''
eval "$(camtool completion bash)"
COMP_WORDS=({words})
COMP_CWORD=$(( ${{#COMP_WORDS[@]}} - 1 ))
_camtool_completion camtool
printf '%s\\n' "${{COMPREPLY[@]}}"
'''
    result = sh(script)
    assert result.returncode == 0, result.stderr
    return result.stdout.split()


def test_bash_completion_runs() -> None:
    assert "dof" in _complete("camtool d")
    assert _complete("camtool dof --distance-f") == ["--distance-from"]
    assert _complete("camtool dof --distance-from ''") == ["sensor", "lens"]


def test_zsh_and_fish_scripts() -> None:
    for shell, marker in (("zsh", "compdef"), ("fish", "complete")):
        result = sh(f"camtool completion {shell}")
        assert result.returncode == 0 and marker in result.stdout
    assert sh("_CAMTOOL_COMPLETE=bash_source camtool").stdout == sh("camtool completion bash").stdout


def test_man_page_is_installed_beside_the_entry_point() -> None:
    if shutil.which("man") is None:
        pytest.skip("no man on this machine")
    result = sh("man -w camtool-dof", {"MANPATH": ""})
    assert result.returncode == 0
    assert result.stdout.strip().endswith("share/man/man1/camtool-dof.1")


# --- pipes, write errors and hostile batch files, in a real process with time (and memory) bounds ---

def _camtool_env(extra: dict[str, str] | None = None) -> dict[str, str]:
    return {**ENV, "PATH": os.path.dirname(CAMTOOL) + os.pathsep + ENV.get("PATH", ""), **(extra or {})}


MANY = "-N " + ",".join(str(2 + i / 10) for i in range(30)) + " -s " + ",".join(f"{i + 1}m" for i in range(100))


@pytest.mark.parametrize("fmt", ["table", "csv", "json"])
def test_a_closed_pipe_is_a_normal_end(fmt: str) -> None:
    # 3000 rows: far more than a pipe holds, so camtool is still writing when head exits
    script = f"camtool dof -f 50 {MANY} --format {fmt} | head -1; echo \"status=${{PIPESTATUS[0]}}\""
    result = subprocess.run(["bash", "-c", script], capture_output=True, text=True, env=_camtool_env(), timeout=60)
    assert result.stdout.splitlines()[-1] == "status=0"
    assert result.stderr == ""


def test_a_closed_pipe_ends_a_batch_quietly_too() -> None:
    rows = "".join(f"50,8,{d}\n" for d in range(1, 30001))
    for fmt in ("json", "table"):
        result = subprocess.run(["bash", "-c", f"camtool dof --batch - --format {fmt} | head -1; "
                                 "echo \"status=${PIPESTATUS[0]}\""], input="focal-length,f-number,distance\n" + rows,
                                capture_output=True, text=True, env=_camtool_env(), timeout=120)
        assert result.stdout.splitlines()[-1] == "status=0" and result.stderr == ""


@pytest.mark.skipif(not os.path.exists("/dev/full"), reason="no /dev/full here")
@pytest.mark.parametrize("fmt", ["table", "csv", "json"])
def test_a_full_disk_is_a_one_line_error(fmt: str) -> None:
    result = sh(f"camtool dof -f 50 -N 8 -s 3 --format {fmt} > /dev/full")
    assert result.returncode == 1
    assert result.stderr == "Error: cannot write the output: no space left on device\n"


def test_a_closed_stdout_is_a_one_line_error() -> None:
    result = sh("camtool dof -f 50 -N 8 -s 3 >&-")
    assert result.returncode == 1
    assert result.stderr == "Error: cannot write the output: standard output is closed\n"
    # an error in the input is still reported as such
    assert sh("camtool dof -f 50 -N 8 -s 0.01 >&-").returncode == 2


def test_an_ascii_only_stdout_gets_ascii_stand_ins() -> None:
    result = sh("camtool dof -f 24 -N 8,16 -s inf", {"PYTHONIOENCODING": "ascii"})
    assert result.returncode == 0 and result.stderr == ""
    assert result.stdout.isascii()
    lines = result.stdout.splitlines()
    assert lines[2].startswith("-----") and "inf" in lines[3] and "| focus, H hyperfocal, > inf" in lines[-1]
    csv_out = sh("camtool dof -f 24 -N 8 -s inf --format csv", {"PYTHONIOENCODING": "ascii"})
    assert csv_out.returncode == 0 and csv_out.stdout.isascii()


def _bounded(args: list[str], path: str, memory_mib: int = 1024) -> subprocess.CompletedProcess[bytes]:
    """Run camtool on a batch file with an address-space limit and a time limit."""
    import resource

    def limit() -> None:
        resource.setrlimit(resource.RLIMIT_AS, (memory_mib << 20, memory_mib << 20))

    env = _camtool_env({"OPENBLAS_NUM_THREADS": "1", "OMP_NUM_THREADS": "1"})
    return subprocess.run([CAMTOOL, *args, "--batch", path], capture_output=True, env=env, timeout=60,
                          preexec_fn=limit)


def test_hostile_batch_files_are_one_line_errors_in_bounded_time_and_memory(tmp_path) -> None:
    header = b"focal-length,f-number,distance\n"
    files = {
        "latin1.csv": header + "50,8,3\n# caf\xe9\n".encode("latin-1"),  # Excel's "CSV" on Windows
        "utf16-no-bom.csv": (header + b"50,8,3\n").decode().encode("utf-16-le"),
        # a 64 MiB cell with no line break: read in bounded pieces, not whole
        "huge-cell.csv": header + b"50,8," + b"3" * (64 << 20) + b"\n50,8,3\n",
    }
    for name, data in files.items():
        (tmp_path / name).write_bytes(data)
    latin = _bounded(["dof", "--format", "csv"], str(tmp_path / "latin1.csv"))
    assert latin.returncode == 1
    assert latin.stderr.decode() == (f"Error: --batch {tmp_path / 'latin1.csv'}: not UTF-8 text (invalid "
                                     "continuation byte, byte 0xe9); save it as UTF-8 (in Excel: CSV UTF-8)\n")
    utf16 = _bounded(["dof", "--format", "csv"], str(tmp_path / "utf16-no-bom.csv"))
    assert utf16.returncode == 1 and b"UTF-16" in utf16.stderr and utf16.stderr.count(b"\n") == 1
    huge = _bounded(["dof", "--format", "csv", "--on-error", "skip"], str(tmp_path / "huge-cell.csv"), 512)
    assert huge.returncode == 1, huge.stderr
    assert huge.stderr.decode().splitlines() == ["Error: --batch row 1: a cell longer than 128 KiB (skipped)",
                                                 "camtool: 1 of 2 rows skipped"]
    header, row = huge.stdout.decode().splitlines()[:2]
    assert row == "," * header.count(",")
    stop = _bounded(["dof", "--format", "json"], str(tmp_path / "huge-cell.csv"), 512)
    assert stop.returncode == 2 and stop.stdout == b""


def test_utf16_with_its_byte_order_mark_and_a_utf8_bom_are_read(tmp_path) -> None:
    text = "focal-length,f-number,distance\n50,8,3\n"
    expected = sh("camtool dof -f 50 -N 8 -s 3 --format csv").stdout
    for name, data in (("utf16.csv", text.encode("utf-16")), ("bom.csv", text.encode("utf-8-sig"))):
        (tmp_path / name).write_bytes(data)
        result = _bounded(["dof", "--format", "csv"], str(tmp_path / name))
        assert result.returncode == 0 and result.stdout.decode() == expected


def test_a_fifo_is_read_like_a_pipe_and_a_directory_is_an_error(tmp_path) -> None:
    fifo = tmp_path / "scenes"
    os.mkfifo(fifo)
    result = sh(f"printf 'focal-length,f-number,distance\\n50,8,3\\n' > {fifo} & camtool dof --batch {fifo} "
                "--format json; wait")
    assert result.returncode == 0 and json.loads(result.stdout)[0]["distance_mm"] == 3000.0
    directory = sh(f"camtool dof --batch {tmp_path} --format json")
    assert directory.returncode == 1 and directory.stdout == ""
    assert directory.stderr == f"Error: --batch {tmp_path}: is a directory, not a file\n"


def test_a_narrow_terminal_names_the_columns_left_out() -> None:
    drawn = _in_terminal(["dof", "-f", "50", "-N", "2.8,4,8", "-s", "3"], {"COLUMNS": "60"})
    assert "left out to fit 60 columns: front, rear (" in drawn
    table = drawn.split("thin model")[0]
    assert max(len(re.sub(r"\x1b\[[0-9;]*m", "", line)) for line in table.splitlines()) <= 60
    assert "4.078" in drawn  # the far limit at f/8, whole


def test_a_grid_of_a_million_rows_streams_in_bounded_memory_and_time() -> None:
    import resource

    many = ",".join(str(1 + i / 100) for i in range(1000))

    def limit() -> None:  # 400 MiB of address space; the grid built whole took about 1 GB
        resource.setrlimit(resource.RLIMIT_AS, (400 << 20, 400 << 20))

    env = _camtool_env({"OPENBLAS_NUM_THREADS": "1"})
    args = [CAMTOOL, "dof", "-f", "50", "-N", many, "-s", many]
    fields = ["--field", "near_mm", "--field", "far_mm"]
    with subprocess.Popen([*args, *fields], stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True,
                          env=env, preexec_fn=limit) as process:
        assert process.stdout is not None
        count, last = 0, ""
        for line in process.stdout:
            count, last = count + 1, line
        _, errors = process.communicate(timeout=50)
    assert process.returncode == 0, errors
    assert count == 1_000_000
    # the last combination, f/10.99 at 10.99 m, is what the scene computed on its own gives
    alone = subprocess.run([*args[:4], "-N", "10.99", "-s", "10.99", *fields], capture_output=True,
                           text=True, env=env, check=True).stdout
    assert last == alone
