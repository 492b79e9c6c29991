"""What a prescription costs a command: start-up of a single scene, and batches of f-numbers.

1. Start-up (docs/design.md §7 budget: ``camtool dof ... --format json`` within 2x of
   ``python -c "import click"``): a single scene with ``--lens dgauss100-lens`` (a preset with a
   prescription) under ``auto``, ``--model paraxial`` and ``--model thin``, against
   ``import click``. Runs are interleaved so machine noise hits every command alike; the figures
   are medians and the verdicts ratios. The aberration estimate of the prescription is cached on
   disk after the first command (it runs once here before timing, in a fresh cache directory).
2. A batch of scenes with that preset: continuous f-numbers (every row its own, uniform in
   log N from f/2 to f/22) against eight f-numbers, at 2,000 and 10,000 rows, ``auto`` model;
   the ratio of wall times is the verdict (budget 1.2x). One warm-up run of each first. The
   same comparison in this process (the ``auto`` dispatcher over arrays) removes the noise of
   process start-up.

Run: ``python benchmarks/bench_prescription.py [--repeat 20]``
"""

from __future__ import annotations

import argparse
import os
import random
import shutil
import subprocess
import sys
import tempfile
import time

from timing import interleaved_medians

PY = sys.executable
CAMTOOL = shutil.which("camtool") or ""
SCENE = ["dof", "--lens", "dgauss100-lens", "-N", "5.6", "-s", "3m", "--format", "json"]
CASES = {
    "python -c 'import click'": [PY, "-c", "import click"],
    "dof -f 50 -N 8 -s 3m (no lens data)": [CAMTOOL, "dof", "-f", "50", "-N", "8", "-s", "3m", "--format", "json"],
    "dof --lens dgauss100-lens (auto)": [CAMTOOL, *SCENE],
    "dof --lens dgauss100-lens --model paraxial": [CAMTOOL, *SCENE, "--model", "paraxial"],
    "dof --lens dgauss100-lens --model thin": [CAMTOOL, *SCENE, "--model", "thin"],
}
STOPS = (2.0, 2.8, 4.0, 5.6, 8.0, 11.0, 16.0, 22.0)


def startup(repeat: int, env: dict[str, str]) -> dict[str, float]:
    # the warm-up run writes byte-code and the prescription's aberration table once
    return interleaved_medians(CASES, repeat, env)


def write_batch(path: str, rows: int, continuous: bool) -> None:
    rng = random.Random(7)
    with open(path, "w", encoding="utf-8") as out:
        out.write("f-number,distance\n")
        for _ in range(rows):
            n = 2.0 * 11.0 ** rng.random() if continuous else rng.choice(STOPS)
            out.write(f"{n:.6f},{rng.uniform(1.0, 30.0):.4f}m\n")


def batch_time(path: str, env: dict[str, str], repeat: int) -> float:
    argv = [CAMTOOL, "dof", "--lens", "dgauss100-lens", "--batch", path, "--format", "csv"]
    subprocess.run(argv, check=True, stdout=subprocess.DEVNULL, env=env)
    best = float("inf")
    for _ in range(repeat):
        start = time.perf_counter()
        subprocess.run(argv, check=True, stdout=subprocess.DEVNULL, env=env)
        best = min(best, time.perf_counter() - start)
    return best


def estimate_time(rows: int, continuous: bool, repeat: int) -> float:
    """Best time of the effect estimates alone (aberration share included) over the batch's scenes."""
    import numpy as np
    import yaml

    from camtool.dof import auto
    from camtool.optics.paraxial import first_order
    from camtool.optics.prescription import prescription_from_mapping

    path = os.path.join(os.path.dirname(__file__), "..", "tests", "data", "prescriptions", "dgauss100.yaml")
    with open(path, encoding="utf-8") as handle:
        lens = prescription_from_mapping(yaml.safe_load(handle), "dgauss100")
    fo = first_order(lens)
    rng = random.Random(7)
    n = np.array([rng.choice(STOPS) * (1.0 + 0.02 * (rng.random() - 0.5) if continuous else 1.0) for _ in range(rows)])
    s = np.array([rng.uniform(1000.0, 30000.0) for _ in range(rows)])
    best = float("inf")
    for _ in range(repeat):
        auto.aberration_table.cache_clear()
        start = time.perf_counter()
        auto.estimate_effects(fo.efl_mm, n, 0.03, s, "sensor", fo.pupil_magnification, fo.hiatus_mm, 0.0, lens)
        best = min(best, time.perf_counter() - start)
    return best


def library_time(rows: int, continuous: bool, repeat: int) -> float:
    """Best time of one ``depth_of_field("auto", ...)`` call over the batch's scenes, in this process.

    The interpolants of the ray trace and the in-memory aberration tables are dropped before each
    run (the on-disk table stays, as it would for a command). Continuous f-numbers here are the
    eight stops each moved by up to ±1 %: the same scenes for ``auto``'s choice, every row its own
    f-number.
    """
    import numpy as np
    import yaml

    from camtool.dof import auto, realray
    from camtool.dof.ladder import depth_of_field
    from camtool.dof.rungs import LensData
    from camtool.optics.prescription import prescription_from_mapping

    path = os.path.join(os.path.dirname(__file__), "..", "tests", "data", "prescriptions", "dgauss100.yaml")
    with open(path, encoding="utf-8") as handle:
        lens = LensData(prescription=prescription_from_mapping(yaml.safe_load(handle), "dgauss100"))
    rng = random.Random(7)
    # continuous: each stop moved by up to ±1 %, so that both batches ask auto for the same mix of models
    n = np.array([rng.choice(STOPS) * (1.0 + 0.02 * (rng.random() - 0.5) if continuous else 1.0) for _ in range(rows)])
    s = np.array([rng.uniform(1000.0, 30000.0) for _ in range(rows)])
    best = float("inf")
    for _ in range(repeat):
        realray._curves.cache_clear()
        auto.aberration_table.cache_clear()
        start = time.perf_counter()
        depth_of_field("auto", None, n, 0.03, s, lens=lens)
        best = min(best, time.perf_counter() - start)
    return best


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--repeat", type=int, default=20)
    args = parser.parse_args()
    if not CAMTOOL:
        sys.exit("camtool is not on PATH: install the project first")
    with tempfile.TemporaryDirectory() as cache:
        env = {k: v for k, v in os.environ.items() if k != "PYTHONDONTWRITEBYTECODE"}
        env["XDG_CACHE_HOME"] = cache
        medians = startup(args.repeat, env)
        click = medians["python -c 'import click'"]
        print("| command | median wall time (ms) | / import click (budget 2x) |\n|---|---:|---:|")
        for name, value in medians.items():
            print(f"| `{name}` | {value * 1000:.1f} | {value / click:.2f} |")
        print("\n| rows | 8 f-numbers (s) | continuous f-numbers (s) | ratio (budget 1.2x) |\n|---:|---:|---:|---:|")
        with tempfile.TemporaryDirectory() as work:
            for rows in (2000, 10000):
                few, many = os.path.join(work, "few.csv"), os.path.join(work, "many.csv")
                write_batch(few, rows, continuous=False)
                write_batch(many, rows, continuous=True)
                t_few = batch_time(few, env, max(3, args.repeat // 5))
                t_many = batch_time(many, env, max(3, args.repeat // 5))
                print(f"| {rows} | {t_few:.3f} | {t_many:.3f} | {t_many / t_few:.2f} |")
        os.environ["XDG_CACHE_HOME"] = cache
        print("\nIn this process (`depth_of_field('auto', ...)` over the same scenes, best of 5):\n")
        print("| rows | 8 f-numbers (s) | continuous f-numbers (s) | ratio (budget 1.2x) |\n|---:|---:|---:|---:|")
        for rows in (2000, 10000):
            t_few, t_many = library_time(rows, False, 5), library_time(rows, True, 5)
            print(f"| {rows} | {t_few:.3f} | {t_many:.3f} | {t_many / t_few:.2f} |")
        print("\nThe effect estimates alone (`auto.estimate_effects`, aberration share included), best of 5:\n")
        print("| rows | 8 f-numbers (ms) | continuous f-numbers (ms) | ratio (budget 1.2x) |\n|---:|---:|---:|---:|")
        for rows in (2000, 10000):
            t_few, t_many = estimate_time(rows, False, 5), estimate_time(rows, True, 5)
            print(f"| {rows} | {t_few * 1e3:.2f} | {t_many * 1e3:.2f} | {t_many / t_few:.2f} |")


if __name__ == "__main__":
    main()
