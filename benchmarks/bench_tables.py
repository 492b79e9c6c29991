"""Tables for people against output for scripts: what drawing with rich costs, as ratios in one run.

- JSON, CSV and ``--field`` output import no rich and stay within 1.6× ``python -c "import click"``;
- a 10-row table drawn as on a terminal (colour and a width: ``FORCE_COLOR=1 COLUMNS=120``) within 2.5×
  of the same;
- a 10⁴-row table (drawn a line at a time above ``camtool.render.table.RICH_ROWS`` rows) within 3× of
  the same rows as CSV.

Each command runs ``--repeat`` times, interleaved (A B C A B C …) so machine noise hits every one alike;
the figures are medians.

Run: ``python benchmarks/bench_tables.py [--repeat 20]``
"""

from __future__ import annotations

import argparse
import os
import shutil
import sys

from timing import interleaved_medians, report

PY = sys.executable
CAMTOOL = shutil.which("camtool") or ""
ONE = ["dof", "-f", "50", "-N", "8", "-s", "3m"]
TEN = ["dof", "-f", "50", "-N", "2,2.8,4,5.6,8", "-s", "3m,10m"]
HUNDRED = ",".join(f"{1 + i / 10:g}" for i in range(100))
MANY = ["dof", "-f", "50", "-N", HUNDRED, "-s", ",".join(f"{1 + i / 10:g}m" for i in range(100)), "--model", "thin"]

CASES = {
    "python -c 'import click'": [PY, "-c", "import click"],
    "dof (1 row) --format json": [CAMTOOL, *ONE, "--format", "json"],
    "dof (1 row) --format csv": [CAMTOOL, *ONE, "--format", "csv"],
    "dof (1 row) --field near_mm": [CAMTOOL, *ONE, "--field", "near_mm"],
    "dof (10 rows) table, colour": [CAMTOOL, *TEN],
    "dof (10^4 rows) table, colour": [CAMTOOL, *MANY],
    "dof (10^4 rows) --format csv": [CAMTOOL, *MANY, "--format", "csv"],
}
BUDGETS = [
    ("dof (1 row) --format json", "python -c 'import click'", 1.6),
    ("dof (1 row) --format csv", "python -c 'import click'", 1.6),
    ("dof (1 row) --field near_mm", "python -c 'import click'", 1.6),
    ("dof (10 rows) table, colour", "python -c 'import click'", 2.5),
    ("dof (10^4 rows) table, colour", "dof (10^4 rows) --format csv", 3.0),
]


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--repeat", type=int, default=20)
    args = parser.parse_args()
    if not CAMTOOL:
        sys.exit("camtool is not on PATH: install the project first")
    env = {k: v for k, v in os.environ.items() if k not in ("PYTHONDONTWRITEBYTECODE", "NO_COLOR")}
    env.update(FORCE_COLOR="1", COLUMNS="120")
    medians = interleaved_medians(CASES, args.repeat, env)
    report(medians, BUDGETS)


if __name__ == "__main__":
    main()
