"""A camera's per-frame columns in ``dof --batch``: ``focus`` and a ``t_stop`` column of bare numbers against the
same frames written with ``distance`` and ``f_number`` cells ``T2.8`` and against bare f-numbers, as ratios of
interleaved medians measured in one run.

The three files hold the same N frames (a focus pull from 1.5 m, 50 mm, one stop for the shot). Target: the
``focus``/``t_stop`` spelling within 1.1x of the ``T2.8`` cells it stands for (the names resolve once per file,
and a bare number there is read as ``T`` + number a column at a time).

Run: ``python benchmarks/bench_camera_columns.py [--frames 100000] [--repeat 5]``
"""

from __future__ import annotations

import argparse
import os
import sys
import tempfile

from timing import interleaved_medians, report


def write(path: str, header: str, frames: int, stop: str) -> None:
    with open(path, "w", encoding="utf-8") as out:
        out.write(header + "\n")
        for index in range(frames):
            out.write(f"{index + 1},{1.5 + index * 1e-4:.4f},50,{stop}\n")


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--frames", type=int, default=100_000)
    parser.add_argument("--repeat", type=int, default=5)
    args = parser.parse_args()
    with tempfile.TemporaryDirectory() as tmp:
        files = {"focus,t_stop (bare 2.8)": ("frame,focus,focal_length,t_stop", "2.8"),
                 "distance,f_number (T2.8)": ("frame,distance,focal_length,f_number", "T2.8"),
                 "distance,f_number (bare 2.8)": ("frame,distance,focal_length,f_number", "2.8")}
        cases = {}
        for name, (header, stop) in files.items():
            path = os.path.join(tmp, f"{len(cases)}.csv")
            write(path, header, args.frames, stop)
            cases[name] = [sys.executable, "-m", "camtool", "dof", "--batch", path, "--camera", "arri-alexa-35",
                           "--model", "thin", "--format", "csv"]
        env = {**os.environ, "XDG_CACHE_HOME": os.path.join(tmp, "cache")}
        medians = interleaved_medians(cases, args.repeat, env)
        report(medians, [("focus,t_stop (bare 2.8)", "distance,f_number (T2.8)", 1.1),
                         ("focus,t_stop (bare 2.8)", "distance,f_number (bare 2.8)", 1.1)])


if __name__ == "__main__":
    main()
