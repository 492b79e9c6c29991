"""Batch throughput, memory and the cost of bad rows and of tables, each as a ratio measured in one run.

* **Against a pyarrow pipeline.** ``camtool dof --batch FILE --model thin``
  on N rows, to CSV and to JSON, against the fastest pipeline a user would
  write with a columnar library: pyarrow reads the same CSV
  (``pyarrow.csv.read_csv``, the distances' ``m`` cut off by a compute
  kernel), numpy computes the same thin-lens limits from the sensor plane
  as camtool's ``thin`` model, and ``pyarrow.csv.write_csv`` writes the same
  17 columns, each float with its shortest round-trip digits (the digits
  camtool writes). The two outputs are checked to hold the same numbers.
  Runs are paired and interleaved (A B A B ...), the medians compared.
  Targets: CSV within 2×, JSON within 2.5×.
* **auto** (the default ``--model``) against ``--model thin`` on the same N
  rows to CSV: what choosing each row's rung costs, with the per-row model
  and error estimate it writes (thin writes one model and one estimate).
* **Memory** is flat in N: peak resident memory at N against N/10; at most 100 MiB at 10⁶ rows.
* **Bad rows** (one in 20,000, a focus distance inside the closest focus)
  against the clean file, in both ``--on-error`` modes. Target: at most 1.2×
  (stop mode ends at the bad row, so it costs less).
* **Tables**: ``--format table`` at 10⁴ rows against ``--format csv``. Target: within 3×.

Run: ``python benchmarks/bench_batch.py [--rows 1000000] [--repeat 3]`` (needs pyarrow: ``pip install -e '.[batch]'``)
"""

from __future__ import annotations

import argparse
import csv
import math
import os
import random
import shutil
import statistics
import subprocess
import sys
import tempfile
import time

KEYS = ["focal_length_mm", "f_number", "distance_mm", "near_mm", "far_mm", "total_mm", "front_mm", "rear_mm",
        "hyperfocal_mm", "coc_mm", "magnification", "model", "error_estimate", "distance_from", "working_f_number",
        "other_magnification", "focal_length_at_focus_mm"]


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


def arrow_pipeline(path: str) -> None:
    """The pyarrow pipeline: read the CSV, the thin-lens limits from the sensor plane with numpy, write 17 columns."""
    import numpy as np
    import pyarrow as pa
    import pyarrow.compute as pc
    import pyarrow.csv as pcsv

    table = pcsv.read_csv(path, convert_options=pcsv.ConvertOptions(column_types={"distance": pa.string()}))
    f = table["focal-length"].to_numpy().astype(float)
    n = table["f-number"].to_numpy().astype(float)
    d = pc.cast(pc.utf8_slice_codeunits(table["distance"], 0, -1), pa.float64()).to_numpy() * 1000.0
    c = math.hypot(36.0, 24.0) / 1500  # the full-frame CoC, d/1500
    h0 = f * f / (n * c)
    h = h0 + f
    root = np.sqrt(np.maximum(1.0 - 4.0 * f / d, 0.0))
    v = 2.0 * f / (1.0 + root)
    u = d * 0.5 * (1.0 + root)
    hyperfocal = np.where(h >= 2.0 * f, h + f + n * c, 4.0 * f)
    denominator = 1.0 + (h0 - f) / u
    gap = np.maximum(h - u, h * 2.0**-53)
    beyond = d >= hyperfocal
    with np.errstate(divide="ignore"):
        near = h0 / denominator + v
        far = np.where(beyond, np.inf, u * h0 / gap) + v
        front = (u - f) / denominator
        rear = np.where(beyond, np.inf, u * (u - f) / gap)
    m = f / (u - f)
    other = (m > 0.0) & (m < 1.0)
    count = len(f)

    def column(values: np.ndarray, hide: np.ndarray | None = None) -> pa.Array:
        return pa.array(values, mask=np.isinf(values) if hide is None else hide)

    out = pa.table({
        "focal_length_mm": f, "f_number": n, "distance_mm": d, "near_mm": column(near), "far_mm": column(far),
        "total_mm": column(front + rear), "front_mm": front, "rear_mm": column(rear), "hyperfocal_mm": hyperfocal,
        "coc_mm": np.full(count, c), "magnification": m, "model": pa.array(["thin"] * count),
        "error_estimate": np.zeros(count), "distance_from": pa.array(["sensor"] * count),
        "working_f_number": n * (1.0 + m), "other_magnification": column(1.0 / np.where(other, m, 1.0), ~other),
        "focal_length_at_focus_mm": f,
    })
    pcsv.write_csv(out, sys.stdout.buffer, pcsv.WriteOptions(quoting_style="none", quoting_header="none"))


def same_numbers(camtool_csv: str, arrow_csv: str, rows: int = 20_000) -> bool:
    """Whether the first ``rows`` rows of both outputs hold the same keys and numbers (pyarrow writes 35 for 35.0)."""
    with open(camtool_csv, encoding="utf-8") as a, open(arrow_csv, encoding="utf-8") as b:
        first, second = csv.reader(a), csv.reader(b)
        if next(first) != next(second):
            return False
        for _, x, y in zip(range(rows), first, second):
            for p, q in zip(x, y):
                if p != q and not (p and q and float(p) == float(q)):
                    return False
    return True


def run(args: list[str]) -> tuple[float, float]:
    """Wall time in s and the peak resident memory in MiB of one process (its output thrown away)."""
    start = time.perf_counter()
    with open(os.devnull, "w") as sink:
        process = subprocess.Popen(args, stdout=sink, stderr=subprocess.DEVNULL)
        _, _, usage = os.wait4(process.pid, 0)  # this child's own peak, not the largest child's so far
        process.returncode = 0
    elapsed = time.perf_counter() - start
    return elapsed, usage.ru_maxrss / 1024


def paired(commands: dict[str, list[str]], repeat: int) -> dict[str, float]:
    """Median wall time of each command, run in interleaved rounds (A B A B ...) so load affects each alike."""
    times: dict[str, list[float]] = {name: [] for name in commands}
    for _ in range(repeat):
        for name, args in commands.items():
            times[name].append(run(args)[0])
    return {name: statistics.median(found) for name, found in times.items()}


def main() -> None:
    parser = argparse.ArgumentParser(description=(__doc__ or "").splitlines()[0])
    parser.add_argument("--rows", type=int, default=1_000_000)
    parser.add_argument("--repeat", type=int, default=3)
    parser.add_argument("--arrow", metavar="FILE", help=argparse.SUPPRESS)
    args = parser.parse_args()
    if args.arrow:
        arrow_pipeline(args.arrow)
        return
    camtool = shutil.which("camtool")
    assert camtool, "install camtool first"
    rows = args.rows
    with tempfile.TemporaryDirectory() as tmp:
        small, large = os.path.join(tmp, "small.csv"), os.path.join(tmp, "large.csv")
        write_scenes(small, rows // 10)
        write_scenes(large, rows)
        mine, theirs = os.path.join(tmp, "camtool.csv"), os.path.join(tmp, "arrow.csv")
        with open(mine, "w") as out:
            subprocess.run([camtool, "dof", "--batch", large, "--format", "csv", "--model", "thin"], stdout=out, check=True)
        with open(theirs, "w") as out:
            subprocess.run([sys.executable, __file__, "--arrow", large], stdout=out, check=True)
        print(f"same numbers in both outputs: {same_numbers(mine, theirs)}\n")
        print("| measurement | time (s) | against | ratio |\n|---|---:|---|---:|")
        _, small_peak = run([camtool, "dof", "--batch", small, "--format", "csv"])
        _, large_peak = run([camtool, "dof", "--batch", large, "--format", "csv"])
        _, json_peak = run([camtool, "dof", "--batch", large, "--format", "json"])
        times = paired({"arrow": [sys.executable, __file__, "--arrow", large],
                        "csv": [camtool, "dof", "--batch", large, "--format", "csv", "--model", "thin"],
                        "json": [camtool, "dof", "--batch", large, "--format", "json", "--model", "thin"],
                        "auto": [camtool, "dof", "--batch", large, "--format", "csv"]},
                       args.repeat)
        for fmt in ("csv", "json"):
            print(f"| camtool dof --batch, {rows:,} rows, {fmt.upper()} | {times[fmt]:.2f} | pyarrow pipeline "
                  f"{times['arrow']:.2f} s | {times[fmt] / times['arrow']:.2f} |")
        print(f"| camtool dof --batch, {rows:,} rows, CSV, --model auto (the default: each row's rung, model and "
              f"estimate) | {times['auto']:.2f} | --model thin {times['csv']:.2f} s | {times['auto'] / times['csv']:.2f} |")
        print(f"| rows per second, CSV | {rows / times['csv']:,.0f} | | |")
        print(f"| peak memory, {rows:,} rows, CSV | {large_peak:.0f} MiB | {rows // 10:,} rows {small_peak:.0f} MiB | "
              f"{large_peak / small_peak:.2f} |")
        print(f"| peak memory, {rows:,} rows, JSON | {json_peak:.0f} MiB | | |")
        bad = os.path.join(tmp, "bad.csv")
        write_scenes(bad, rows // 10, bad_every=20_000)
        for mode in ("stop", "skip"):
            found = paired({"clean": [camtool, "dof", "--batch", small, "--format", "csv", "--on-error", mode],
                            "bad": [camtool, "dof", "--batch", bad, "--format", "csv", "--on-error", mode]}, args.repeat)
            print(f"| one bad row in 20,000, --on-error {mode}, {rows // 10:,} rows | {found['bad']:.2f} | clean file "
                  f"{found['clean']:.2f} s | {found['bad'] / found['clean']:.2f} |")
        table_rows = os.path.join(tmp, "table.csv")
        write_scenes(table_rows, 10_000)
        found = paired({"csv": [camtool, "dof", "--batch", table_rows, "--format", "csv"],
                        "table": [camtool, "dof", "--batch", table_rows, "--format", "table"]}, args.repeat)
        print(f"| table, 10,000 rows | {found['table']:.2f} | CSV {found['csv']:.2f} s | "
              f"{found['table'] / found['csv']:.2f} |")


if __name__ == "__main__":
    main()
