"""The installed entry point as a subprocess: pipes, head -1, NO_COLOR, completion, batch from stdin."""

from __future__ import annotations

import json
import os
import pty
import shutil
import subprocess
import sys

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
    chunks = []
    while True:
        try:
            data = os.read(fd, 65536)
        except OSError:
            break
        if not data:
            break
        chunks.append(data)
    os.waitpid(pid, 0)
    return b"".join(chunks).decode()


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
