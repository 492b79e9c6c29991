"""Batch throughput and memory: rows per second of ``camtool dof --batch``, and peak memory against row count.

A batch streams through the vectorised core in chunks, so its peak memory
must not grow with the number of rows: the benchmark runs 10⁵ and 10⁶ rows
and reports both the rate and the ratio of their peak resident memory.

Run: ``python benchmarks/bench_batch.py [--rows 1000000]``
"""

from __future__ import annotations

import argparse
import os
import random
import resource
import shutil
import subprocess
import tempfile
import time


def write_scenes(path: str, rows: int) -> None:
    rng = random.Random(1)
    with open(path, "w", encoding="utf-8") as out:
        out.write("focal-length,f-number,distance\n")
        for _ in range(rows):
            f = rng.choice((24, 35, 50, 85, 135))
            out.write(f"{f},{rng.choice((1.4, 2, 2.8, 4, 5.6, 8, 11, 16))},{rng.uniform(1, 50):.3f}m\n")


def run(path: str, fmt: str) -> tuple[float, float]:
    """Wall time in s and the peak resident memory in MiB of one batch run."""
    camtool = shutil.which("camtool")
    assert camtool, "install camtool first"
    before = resource.getrusage(resource.RUSAGE_CHILDREN).ru_maxrss
    start = time.perf_counter()
    with open(os.devnull, "w") as sink:
        subprocess.run([camtool, "dof", "--batch", path, "--format", fmt], check=True, stdout=sink)
    elapsed = time.perf_counter() - start
    peak = resource.getrusage(resource.RUSAGE_CHILDREN).ru_maxrss
    return elapsed, max(peak, before) / 1024


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--rows", type=int, default=1_000_000)
    args = parser.parse_args()
    with tempfile.TemporaryDirectory() as tmp:
        small, large = os.path.join(tmp, "small.csv"), os.path.join(tmp, "large.csv")
        write_scenes(small, args.rows // 10)
        write_scenes(large, args.rows)
        print("| rows | format | time (s) | rows/s | peak memory (MiB) |\n|---:|---|---:|---:|---:|")
        peaks = {}
        for rows, path in ((args.rows // 10, small), (args.rows, large)):
            for fmt in ("csv", "json"):
                elapsed, peak = run(path, fmt)
                peaks[rows] = peak
                print(f"| {rows:,} | {fmt} | {elapsed:.2f} | {rows / elapsed:,.0f} | {peak:.0f} |")
        print(f"\npeak memory of {args.rows:,} rows / {args.rows // 10:,} rows: "
              f"{peaks[args.rows] / peaks[args.rows // 10]:.2f} (bounded: close to 1)")


if __name__ == "__main__":
    main()
