"""One 4096 × 2160 OpenEXR depth frame to a CoC map, on one core, reading and writing included.

The budget (issue "Cinema and visual effects"): at most 0.25 s a frame. The reference is what a user would
write by hand with the same libraries: OpenEXR's Python bindings to read the Z channel, the CoC formula as one
numpy expression, and OpenEXR to write the two float32 channels, with none of camtool's checks (NaN and
non-positive depths, header attributes, the summary row). The depth is a smooth scene (a ground plane receding
to the horizon, a sky at infinity), written ZIP-compressed as renderers write it. Best of ``--repeat`` runs.

One core: the OpenEXR library's own thread pool is set to one thread, and the script is meant to be run as
``taskset -c 0 python benchmarks/bench_cocmap.py`` (numpy's element-wise work is single-threaded already).

Run: ``python benchmarks/bench_cocmap.py [--repeat 7] [--width 4096] [--height 2160]``
"""

from __future__ import annotations

import argparse
import os
import tempfile
import tracemalloc

import numpy as np
import OpenEXR
from timing import best

from camtool.plans.cocmap import Settings, compute_frame


def scene(width: int, height: int) -> np.ndarray:
    """A ground plane seen from 1.6 m above it, level camera: Z = 1.6 m / (row offset below the horizon · pitch/f);
    above the horizon the sky, at infinity."""
    rows = (np.arange(height, dtype=np.float32) - height / 2 + 0.5)[:, None] * (24.0 / height) / 50.0
    with np.errstate(divide="ignore"):
        z = np.where(rows > 0, 1.6 / np.maximum(rows, 1e-9), np.inf).astype(np.float32)
    return np.broadcast_to(z, (height, width)).copy()


def by_hand(path: str, out: str) -> None:
    z = OpenEXR.File(path).channels()["Z"].pixels
    f, n, xf = 50.0, 2.8, 3000.0
    coc = (f * f / (n * (xf - f))) * np.abs(1.0 - (xf / 1000.0) / z)
    radius = coc * (0.5 * z.shape[1] / 36.0)
    header = {"compression": OpenEXR.NO_COMPRESSION, "type": OpenEXR.scanlineimage}
    OpenEXR.File(header, {"coc_mm": coc.astype(np.float32), "radius_px": radius.astype(np.float32)}).write(out)


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--repeat", type=int, default=7)
    parser.add_argument("--width", type=int, default=4096)
    parser.add_argument("--height", type=int, default=2160)
    args = parser.parse_args()
    OpenEXR.set_global_thread_count(1)  # one core: the library's own thread pool too
    folder_root = "/dev/shm" if os.path.isdir("/dev/shm") else None  # memory, not the disk: the CPU's share
    settings = Settings("physical", 3000.0, 2.8, 50.0, None, 1.0, 36.0, 0.025, None, None, 0.0, None,
                        "depth", 10.0, 100.0, None)
    frame_bytes = args.width * args.height * 4
    print(f"{args.width} x {args.height} EXR depth frame -> CoC map (read + compute + write), best of {args.repeat}, "
          f"files in {folder_root or 'the temporary folder'}")
    for label, compression in (("uncompressed", OpenEXR.NO_COMPRESSION), ("ZIP", OpenEXR.ZIP_COMPRESSION)):
        with tempfile.TemporaryDirectory(dir=folder_root) as folder:
            path, out, ref = (os.path.join(folder, name) for name in ("depth.exr", "coc.exr", "ref.exr"))
            header = {"compression": compression, "type": OpenEXR.scanlineimage}
            OpenEXR.File(header, {"Z": scene(args.width, args.height)}).write(path)
            mine = best(lambda: compute_frame(path, out, settings), args.repeat)
            hand = best(lambda: by_hand(path, ref), args.repeat)
            tracemalloc.start()
            compute_frame(path, out, settings)
            peak = tracemalloc.get_traced_memory()[1]
            tracemalloc.stop()
        verdict = "OK" if mine <= 0.25 else "OVER"
        print(f"  {label} input: camtool {mine * 1000:6.1f} ms (budget 250 ms: {verdict}); hand-written "
              f"{hand * 1000:6.1f} ms, ratio {mine / hand:.2f}; peak numpy memory {peak / frame_bytes:.2f} frames")


if __name__ == "__main__":
    main()
