"""Option grids: time and peak memory of a 10⁶-combination grid, against the same scenes through ``--batch``.

``camtool dof -f 50 -N <1000 values> -s <1000 values> --format csv`` streams
its combinations in chunks; the same million scenes written to a CSV file
and read back with ``--batch`` is the reference (ratios grid / batch; the
grid should cost no more, having no file to parse). For scale, the grid is
also run with the chunk made larger than the grid, i.e. built whole, as it
was before it streamed. Each process's own peak resident memory comes from
``os.wait4``.

Run: ``python benchmarks/bench_grid.py [--side 1000]`` (side² combinations)
"""

from __future__ import annotations

import argparse
import os
import shutil
import subprocess
import sys
import tempfile
import time

WHOLE = ("import sys; from camtool.plans import grid; from camtool.cli import main; grid.CHUNK = 10**9; "
         "sys.argv[0] = 'camtool'; main()")


def measure(args: list[str]) -> tuple[float, float, int]:
    """Wall time in s, peak resident memory in MiB and the number of output lines of one process."""
    start = time.perf_counter()
    with tempfile.TemporaryFile() as sink:
        process = subprocess.Popen(args, stdout=sink, stderr=subprocess.DEVNULL)
        _, status, usage = os.wait4(process.pid, 0)
        elapsed = time.perf_counter() - start
        process.returncode = os.waitstatus_to_exitcode(status)
        assert process.returncode == 0, args[:3]
        sink.seek(0)
        lines = sum(chunk.count(b"\n") for chunk in iter(lambda: sink.read(1 << 20), b""))
    return elapsed, usage.ru_maxrss / 1024, lines


def main() -> None:
    parser = argparse.ArgumentParser(description=(__doc__ or "").splitlines()[0])
    parser.add_argument("--side", type=int, default=1000, help="values per list (the grid is side × side)")
    args = parser.parse_args()
    camtool = shutil.which("camtool")
    assert camtool, "install camtool first"
    side = args.side
    apertures = [f"{1 + i / 100:g}" for i in range(side)]
    distances = [f"{1 + i / 100:g}" for i in range(side)]
    grid = ["dof", "-f", "50", "-N", ",".join(apertures), "-s", ",".join(distances)]
    with tempfile.TemporaryDirectory() as tmp:
        scenes = os.path.join(tmp, "scenes.csv")
        with open(scenes, "w", encoding="utf-8") as out:
            out.write("focal-length,f-number,distance\n")
            for n in apertures:
                out.write("".join(f"50,{n},{s}\n" for s in distances))
        print(f"{side * side:,} scenes\n\n| output | grid (s, MiB) | --batch (s, MiB) | time ratio | memory ratio |"
              "\n|---|---:|---:|---:|---:|")
        for name, output in (("CSV", ["--format", "csv"]), ("--field near_mm far_mm",
                                                           ["--field", "near_mm", "--field", "far_mm"])):
            grid_time, grid_peak, grid_lines = measure([camtool, *grid, *output])
            batch_time, batch_peak, batch_lines = measure([camtool, "dof", "--batch", scenes, *output])
            assert grid_lines == batch_lines, (grid_lines, batch_lines)
            print(f"| {name} | {grid_time:.2f}, {grid_peak:.0f} | {batch_time:.2f}, {batch_peak:.0f} | "
                  f"{grid_time / batch_time:.2f} | {grid_peak / batch_peak:.2f} |")
        whole_time, whole_peak, _ = measure([sys.executable, "-c", WHOLE, *grid, "--format", "csv"])
        print(f"\nbuilt whole (one chunk), CSV: {whole_time:.2f} s, {whole_peak:.0f} MiB")


if __name__ == "__main__":
    main()
