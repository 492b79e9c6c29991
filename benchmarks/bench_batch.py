"""Batch throughput, memory and the cost of bad rows and of tables, each as a ratio measured in one run.

* **Against a bare columnar pipeline.** ``camtool dof --batch FILE --format csv``
  on N rows, against the least a script could do for the same file: read the
  CSV a column at a time, compute the thin-lens limits with numpy, write the
  same 14 columns as CSV (floats as Python prints them). Target: within 2×.
* **Memory** is flat in N: peak resident memory at N against N/10.
* **Bad rows** (one in 20,000, a focus distance inside the closest focus)
  against the clean file, in both ``--on-error`` modes. Target: at most 1.2×
  (stop mode ends at the bad row, so it costs less).
* **Tables**: ``--format table`` at 10⁴ rows against ``--format csv``. Target: within 3×.

Run: ``python benchmarks/bench_batch.py [--rows 1000000]``
"""

from __future__ import annotations

import argparse
import os
import random
import resource
import shutil
import subprocess
import sys
import tempfile
import time


def write_scenes(path: str, rows: int, bad_every: int = 0) -> None:
    rng = random.Random(1)
    with open(path, "w", encoding="utf-8") as out:
        out.write("focal-length,f-number,distance\n")
        for index in range(rows):
            f = rng.choice((24, 35, 50, 85, 135))
            n = rng.choice((1.4, 2, 2.8, 4, 5.6, 8, 11, 16))
            distance = rng.uniform(1, 50)
            if bad_every and index % bad_every == bad_every // 2:
                distance = 0.01  # closer than the closest focus: a bad row
            out.write(f"{f},{n},{distance:.3f}m\n")


def bare(path: str) -> None:
    """The bare columnar pipeline: CSV columns in, the thin-lens formula on arrays, the same CSV columns out."""
    import csv

    import numpy as np

    coc = (36.0**2 + 24.0**2) ** 0.5 / 1500
    keys = ["focal_length_mm", "f_number", "distance_mm", "near_mm", "far_mm", "total_mm", "front_mm", "rear_mm",
            "hyperfocal_mm", "coc_mm", "magnification", "model", "error_estimate", "distance_from"]
    out = sys.stdout
    out.write(",".join(keys) + "\n")
    with open(path, encoding="utf-8", newline="") as source:
        reader = csv.reader(source)
        next(reader)
        while True:
            rows = [row for _, row in zip(range(20_000), reader)]
            if not rows:
                break
            fs, ns, ss = zip(*rows)
            f, n = np.array(fs, dtype=float), np.array(ns, dtype=float)
            s = np.array([cell[:-1] for cell in ss], dtype=float) * 1000.0
            h = f * f / (n * coc) + f
            u = s - f  # from the lens, roughly: the pipeline need only be of the same size
            near = u * (h - f) / (h + u - 2 * f) + f
            with np.errstate(divide="ignore"):
                far = np.where(u < h, u * (h - f) / (h - u) + f, np.inf)
            columns = [f, n, s, near, far, far - near, s - near, far - s, h, np.full(len(f), coc), f / u]

            def text(array: np.ndarray) -> list[str]:
                cells = list(map(float.__repr__, array.tolist()))
                for index in np.flatnonzero(np.isinf(array)).tolist():
                    cells[index] = ""
                return cells

            cells = [text(c) for c in columns] + [["thin"] * len(f), ["0.0"] * len(f), ["sensor"] * len(f)]
            out.write("\n".join(map(",".join, zip(*cells))) + "\n")


def run(args: list[str]) -> tuple[float, float]:
    """Wall time in s and the peak resident memory in MiB of one process (its output thrown away)."""
    start = time.perf_counter()
    with open(os.devnull, "w") as sink:
        subprocess.run(args, stdout=sink, stderr=subprocess.DEVNULL, check=False)
    elapsed = time.perf_counter() - start
    return elapsed, resource.getrusage(resource.RUSAGE_CHILDREN).ru_maxrss / 1024


def main() -> None:
    parser = argparse.ArgumentParser(description=(__doc__ or "").splitlines()[0])
    parser.add_argument("--rows", type=int, default=1_000_000)
    parser.add_argument("--bare", metavar="FILE", help=argparse.SUPPRESS)
    args = parser.parse_args()
    if args.bare:
        bare(args.bare)
        return
    camtool = shutil.which("camtool")
    assert camtool, "install camtool first"
    rows = args.rows
    with tempfile.TemporaryDirectory() as tmp:
        small, large = os.path.join(tmp, "small.csv"), os.path.join(tmp, "large.csv")
        write_scenes(small, rows // 10)
        write_scenes(large, rows)
        print("| measurement | time (s) | against | ratio |\n|---|---:|---|---:|")
        # peak memory first, before larger children raise RUSAGE_CHILDREN's maximum
        _, small_peak = run([camtool, "dof", "--batch", small, "--format", "csv"])
        large_time, large_peak = run([camtool, "dof", "--batch", large, "--format", "csv"])
        bare_time, _ = run([sys.executable, __file__, "--bare", large])
        print(f"| camtool dof --batch, {rows:,} rows, CSV | {large_time:.2f} | bare columnar pipeline "
              f"{bare_time:.2f} s | {large_time / bare_time:.2f} |")
        print(f"| rows per second | {rows / large_time:,.0f} | | |")
        print(f"| peak memory, {rows:,} rows | {large_peak:.0f} MiB | {rows // 10:,} rows {small_peak:.0f} MiB | "
              f"{large_peak / small_peak:.2f} |")
        bad = os.path.join(tmp, "bad.csv")
        write_scenes(bad, rows // 10, bad_every=20_000)
        for mode in ("stop", "skip"):
            clean_time, _ = run([camtool, "dof", "--batch", small, "--format", "csv", "--on-error", mode])
            bad_time, _ = run([camtool, "dof", "--batch", bad, "--format", "csv", "--on-error", mode])
            print(f"| one bad row in 20,000, --on-error {mode}, {rows // 10:,} rows | {bad_time:.2f} | clean file "
                  f"{clean_time:.2f} s | {bad_time / clean_time:.2f} |")
        table_rows = os.path.join(tmp, "table.csv")
        write_scenes(table_rows, 10_000)
        csv_time, _ = run([camtool, "dof", "--batch", table_rows, "--format", "csv"])
        table_time, _ = run([camtool, "dof", "--batch", table_rows, "--format", "table"])
        print(f"| table, 10,000 rows | {table_time:.2f} | CSV {csv_time:.2f} s | {table_time / csv_time:.2f} |")


if __name__ == "__main__":
    main()
