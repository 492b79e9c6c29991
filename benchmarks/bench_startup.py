"""Start-up budget: wall time of single camtool commands against Python's own imports.

docs/design.md §7 and issues 25 and 30: ``camtool dof ... --format json`` (and CSV, ``--field``) within
1.6× of ``python -c "import click"``; the table (drawn by rich, `camtool/render/table.py`) within 2×;
a 10-row table within 2.5×; a short list of f-numbers, ``--help``, ``presets list`` and a lens preset
within 1.6×; a command with a shipped prescription within 1.7× warm and 2.5× cold (every cache empty:
each cold run gets a new, empty ``XDG_CACHE_HOME``, made by ``sh -c 'XDG_CACHE_HOME=$(mktemp -d ...)
exec camtool ...'``, whose few milliseconds count against camtool).
Each command runs ``--repeat`` times, interleaved so that machine noise hits
every candidate alike; the figures are medians and the verdicts are ratios.

Run: ``python benchmarks/bench_startup.py [--repeat 30]``
"""

from __future__ import annotations

import argparse
import os
import shlex
import shutil
import sys
import tempfile

from timing import interleaved_medians, report

PY = sys.executable
CAMTOOL = shutil.which("camtool") or ""
DOF = ["dof", "-f", "50", "-N", "8", "-s", "3m"]
LIST = ["dof", "-f", "50", "-N", "2.8,4,5.6", "-s", "3m", "--format", "json"]
TEN = ["dof", "-f", "50", "-N", "2.8,4,5.6,8,11,16,22,32,1.4,2", "-s", "3m"]
LENS = ["dof", "--lens", "nikon-z-50mm-f1.8-s", "-N", "8", "-s", "3m", "--format", "json"]
PRESCRIPTION = ["dof", "--lens", "dgauss100-lens", "-N", "4", "-s", "2m", "--format", "json"]
CLICK = "python -c 'import click'"


def cases(scratch: str) -> dict[str, list[str]]:
    cold = f"XDG_CACHE_HOME=$(mktemp -d -p {shlex.quote(scratch)}) exec {shlex.join([CAMTOOL, *PRESCRIPTION])}"
    return {
        CLICK: [PY, "-c", "import click"],
        "camtool dof ... --format json": [CAMTOOL, *DOF, "--format", "json"],
        "camtool dof ... --format csv": [CAMTOOL, *DOF, "--format", "csv"],
        "camtool dof ... --field near_mm": [CAMTOOL, *DOF, "--field", "near_mm"],
        "camtool dof ... (table)": [CAMTOOL, *DOF],
        "camtool dof ... --sensor aps-c --format json": [CAMTOOL, *DOF, "--sensor", "aps-c", "--format", "json"],
        "camtool dof -N (3 values) --format json": [CAMTOOL, *LIST],
        "camtool dof -N (10 values), table": [CAMTOOL, *TEN],
        "camtool --help": [CAMTOOL, "--help"],
        "camtool presets list": [CAMTOOL, "presets", "list"],
        "camtool dof --lens nikon-z-50mm-f1.8-s ... --format json": [CAMTOOL, *LENS],
        "camtool dof --lens dgauss100-lens (prescription), warm": [CAMTOOL, *PRESCRIPTION],
        "camtool dof --lens dgauss100-lens (prescription), cold": ["sh", "-c", cold],
    }


BUDGETS = [
    ("camtool dof ... --format json", CLICK, 1.6),
    ("camtool dof ... --format csv", CLICK, 1.6),
    ("camtool dof ... --field near_mm", CLICK, 1.6),
    ("camtool dof ... (table)", CLICK, 2.0),
    ("camtool dof ... --sensor aps-c --format json", CLICK, 2.0),
    ("camtool dof -N (3 values) --format json", CLICK, 1.6),
    ("camtool dof -N (10 values), table", CLICK, 2.5),
    ("camtool --help", CLICK, 1.6),
    ("camtool presets list", CLICK, 1.6),
    ("camtool dof --lens nikon-z-50mm-f1.8-s ... --format json", CLICK, 1.6),
    ("camtool dof --lens dgauss100-lens (prescription), warm", CLICK, 1.7),
    ("camtool dof --lens dgauss100-lens (prescription), cold", CLICK, 2.5),
]


def measure(repeat: int, scratch: str) -> dict[str, float]:
    # An installed camtool has its byte-code compiled (pip does it at install time); a machine that
    # sets PYTHONDONTWRITEBYTECODE would recompile every module on every call, so let one warm-up
    # run write the byte-code first. The warm commands share one cache, filled by their warm-up run.
    env = {k: v for k, v in os.environ.items() if k not in ("PYTHONDONTWRITEBYTECODE", "CAMTOOL_NO_CACHE")}
    env.update(COLUMNS="120", XDG_CACHE_HOME=os.path.join(scratch, "warm"))
    return interleaved_medians(cases(scratch), repeat, env)


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--repeat", type=int, default=30)
    args = parser.parse_args()
    if not CAMTOOL:
        sys.exit("camtool is not on PATH: install the project first")
    with tempfile.TemporaryDirectory(prefix="camtool-bench-") as scratch:
        medians = measure(args.repeat, scratch)
    report(medians, BUDGETS)


if __name__ == "__main__":
    main()
