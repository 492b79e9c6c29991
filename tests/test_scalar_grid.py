"""A short list of option values is computed one combination at a time with plain floats (no numpy); its output
(JSON, CSV, --field, and a table drawn from the combinations' plans merged) is the vectorised path's, byte for
byte, on every documented example with a list."""

from __future__ import annotations

import os
import re
import shlex
import subprocess
import sys

import pytest
from cli_helpers import run
from conftest import point_xdg_at, presets_home
from test_cli_grid import GRIDS
from test_doc_examples import help_examples

from camtool.plans import grid as grid_module

# every --help example that gives a list option and computes rows (not a file-writing or stdin example)
LISTED = sorted({line for _, line in help_examples()
                 if "," in line and "--batch" not in line and "-o " not in line and "--output" not in line
                 and "|" not in line and "#" not in line and "<" not in line})
EXTRA = [
    "camtool dof -f 50 -N 2.8,4,5.6 -s 3m",
    "camtool dof -f 24,50,85 -N 2.8,8 -s 1m,3m,inf --model auto",
    "camtool dof -f 100 -N 2.8,8,22 -s 0.4m,1m --pupil-mag 0.6 --model thick --diffraction",
    "camtool dof --lens dgauss100-lens -N 2,4,8 -s 1m,5m --model auto",
    "camtool dof --lens dgauss100-lens -N 2,8 -s 1m,5m --model all",
    # a traced lens imports numpy anyway: its grid is computed at once (its interpolants are built in one batch)
    "camtool dof --lens dgauss100-lens -N 2,2.8,4,5.6,8,11,16,22 -s 1m,1.7m,2.4m,3.1m,3.8m,10m --model raytrace",
    "camtool dof --lens telephoto127-lens -N 8,11,16 -s 2m,5m,20m --criterion mtf:0.3@coc",
    "camtool dof -f 50 -N 2.8,8 -s 1m,3m --model all --diffraction",
    "camtool dof -f 35 -N 2,4 -s 2m --camera arri-alexa-35 --squeeze 2",
    "camtool dof -f 50 -N 1.4,2.8,8,16,22,32 -s 0.5m,2m,10m,inf --model auto --pupil-mag 0.7 --hiatus 5",
    "camtool dof -f 50 -N T2,T2.8 -s 2m --lens zeiss-supreme-prime-radiance",
    "camtool dof -f 100 -N 2.8,32 -s 0.3m,0.45m,1m --diffraction --model auto",
    "camtool dof -f 50 -N 8 -s 0.6m,1m --extension 25mm",
    "camtool dof -f 24,50 -N 4 -s 3m --criterion mtf:0.3@coc --units imperial",
    "camtool dof -f 50 -N 8 -m 0.5,1,2 --diffraction",
    "camtool fov -f 8,24,50,85 --sensor aps-c",
    "camtool hyperfocal -f 14,24,35 -N 2.8,11",
    "camtool equiv -f 25,50 -N 1.4,2.8 --iso 200 --sensor m43",
    "camtool flash --gn 40 -N 4,8,16 --iso 100,400",
    "camtool flash --gn 20 -s 2,5,9 --iso 100",
    "camtool exposure -N 8,11 -t 1/60,1/30 --iso 400",
    "camtool focus -f 100 -s 0.5m,1m -N 8,16",
    "camtool focus -f 50 -m 0.1,0.5",
    "camtool stars -f 14,24 -N 2.8,4 --pixel-pitch 4um",
    "camtool compose --subject-size 1.8m --fill 0.8 -N 2.8,8 -f 50,85 --background 20m",
]


@pytest.fixture(autouse=True)
def isolated(request, monkeypatch, shared_presets_home):
    root = presets_home(request, shared_presets_home, "tmp_path")
    point_xdg_at(root, monkeypatch)
    return root


def _args(line: str) -> list[str]:
    words = shlex.split(line)
    return words[words.index("camtool") + 1:]


def test_the_examples_give_lists() -> None:
    assert len(LISTED) >= 10, LISTED  # the test below runs over enough of them to mean something


@pytest.mark.parametrize("line", LISTED + EXTRA + [shlex.join(["camtool", *grid]) for grid in GRIDS])
@pytest.mark.parametrize("output", [["--format", "json"], ["--format", "csv"], ["--format", "table"]],
                         ids=["json", "csv", "table"])
def test_a_short_list_gives_the_vectorised_bytes(line: str, output: list[str],
                                                  monkeypatch: pytest.MonkeyPatch) -> None:
    args = [a for a in _args(line) if a not in ("--format", "table", "json")] + output
    env = {"COLUMNS": "200", "NO_COLOR": "1"}
    one_at_a_time = run(*args, env=env)
    monkeypatch.setattr(grid_module, "SCALAR_ROWS", 1)  # every grid vectorised
    vectorised = run(*args, env=env)
    assert (one_at_a_time.exit_code, _untimed(one_at_a_time.stdout), one_at_a_time.stderr) == \
        (vectorised.exit_code, _untimed(vectorised.stdout), vectorised.stderr)


def _untimed(out: str) -> str:
    """``--model all``'s time per evaluation (a measurement, different on every run) left out."""
    out = re.sub(r'"time_per_evaluation_s": [0-9.e+-]+', '"time_per_evaluation_s": T', out)
    header = out.split("\n", 1)[0].split(",")
    if "time_per_evaluation_s" in header:  # CSV
        at = header.index("time_per_evaluation_s")
        out = "\n".join(",".join([*cells[:at], "T", *cells[at + 1:]]) if len(cells) > at else line
                        for line in out.split("\n") for cells in [line.split(",")])
    out = re.sub(r"[0-9.]+ [µm]?s\b", "T", out)
    return re.sub("─+", "─", re.sub(" +", " ", out)) if "time/eval" in out else out  # a time's width moves columns


def test_the_field_of_a_short_list_is_the_same_too(monkeypatch: pytest.MonkeyPatch) -> None:
    args = ["dof", "-f", "35,50", "-N", "2,5.6,16", "-s", "2m", "--field", "near_mm", "--field", "model"]
    scalar = run(*args).stdout
    monkeypatch.setattr(grid_module, "SCALAR_ROWS", 1)
    assert scalar == run(*args).stdout and len(scalar.splitlines()) == 6


def test_a_bad_row_of_a_short_list_ends_the_output_as_a_long_list_does(monkeypatch: pytest.MonkeyPatch) -> None:
    args = ["dof", "--lens", "nikon-z-50mm-f1.8-s", "-N", "2,4,32", "-s", "3m", "--format", "json"]
    scalar = run(*args)
    monkeypatch.setattr(grid_module, "SCALAR_ROWS", 1)
    vectorised = run(*args)
    assert scalar.exit_code == vectorised.exit_code == 2
    assert scalar.stderr == vectorised.stderr and scalar.stdout == vectorised.stdout


DOF = ["dof", "-f", "50", "-N", "2.8,4,5.6", "-s", "3m,5m"]
FOV = ["fov", "-f", "24,50,85", "-s", "2m,5m"]
HYPERFOCAL = ["hyperfocal", "-f", "24,35", "-N", "8,11,16"]


@pytest.mark.parametrize("command", [
    [*DOF, "--format", "json"], [*DOF, "--format", "csv"], [*DOF, "--field", "near_mm"], [*DOF, "--format", "table"],
    [*DOF, "--model", "auto", "--pupil-mag", "0.7"], [*FOV, "--format", "json"], [*FOV, "--field", "horizontal_deg"],
    FOV, HYPERFOCAL, [*HYPERFOCAL, "--format", "csv"]], ids=lambda c: " ".join(c))
def test_a_short_list_imports_no_numpy(command: list[str]) -> None:
    code = ("import atexit, sys; from camtool.cli import main; "
            "atexit.register(lambda: print('numpy' in sys.modules, file=sys.stderr)); "
            "sys.argv = ['camtool', *sys.argv[1:]]; main()")
    done = subprocess.run([sys.executable, "-c", code, *command], capture_output=True, text=True, check=True,
                          env={**os.environ, "COLUMNS": "200"})
    assert done.stderr.strip() == "False" and len(done.stdout.splitlines()) >= 6
