"""A frame sequence through ``camtool cocmap`` on 1, 2, ... cores: does it scale with the cores given?

The budget (issue "Cinema and visual effects"): a sequence scales with the cores given. The frames are the
smooth scene of ``bench_cocmap.py`` (a ground plane to the horizon, a sky at infinity), written
ZIP-compressed as renderers write them, into memory (``/dev/shm``) so that the disk is not what is measured.
Each ``--jobs J`` run is the whole command (start-up, reading, computing, writing every map), interleaved
with the others and repeated; the figure is the median wall time, the speed-up that of ``--jobs 1`` over
it, and the efficiency the speed-up over J. A machine with other work on it shows less than its cores.

Run: ``python benchmarks/bench_cocmap_sequence.py [--frames 16] [--width 2048] [--height 1080] [--repeat 3]``
"""

from __future__ import annotations

import argparse
import os
import statistics
import subprocess
import sys
import tempfile
import time

import OpenEXR
from bench_cocmap import scene


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--frames", type=int, default=16)
    parser.add_argument("--width", type=int, default=2048)
    parser.add_argument("--height", type=int, default=1080)
    parser.add_argument("--repeat", type=int, default=3)
    parser.add_argument("--cores", type=int, default=os.cpu_count() or 1)
    args = parser.parse_args()
    folder_root = "/dev/shm" if os.path.isdir("/dev/shm") else None
    camtool = [sys.executable, "-m", "camtool", "cocmap"]
    jobs = list(range(1, args.cores + 1))
    with tempfile.TemporaryDirectory(dir=folder_root) as folder:
        depth = scene(args.width, args.height)
        header = {"compression": OpenEXR.ZIP_COMPRESSION, "type": OpenEXR.scanlineimage}
        for number in range(1, args.frames + 1):
            OpenEXR.File(header, {"Z": depth}).write(os.path.join(folder, f"shot.{number:04d}.exr"))
        times: dict[int, list[float]] = {j: [] for j in jobs}
        for run in range(args.repeat + 1):  # the first round warms the byte-code and the caches
            for j in jobs:
                out = os.path.join(folder, f"out{j}")
                os.makedirs(out, exist_ok=True)
                argv = [*camtool, os.path.join(folder, "shot.%04d.exr"), "-o", out, "-f", "50", "-N", "2.8",
                        "-s", "3m", "--jobs", str(j), "--format", "csv"]
                start = time.perf_counter()
                subprocess.run(argv, check=True, stdout=subprocess.DEVNULL)
                if run:
                    times[j].append(time.perf_counter() - start)
    print(f"{args.frames} frames of {args.width} x {args.height} (ZIP EXR) through camtool cocmap, "
          f"median of {args.repeat} interleaved runs, {os.cpu_count()} cores on this machine")
    base = statistics.median(times[1])
    for j in jobs:
        wall = statistics.median(times[j])
        print(f"  --jobs {j}: {wall:6.2f} s, {wall / args.frames * 1000:6.1f} ms a frame, speed-up {base / wall:.2f}, "
              f"efficiency {base / wall / j:.0%}")


if __name__ == "__main__":
    main()
