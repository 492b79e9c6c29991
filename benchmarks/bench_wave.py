"""The wave rung: time per scene over 10⁵ scenes, against the thin rung on the same scenes.

docs/wave.md: the perfect-lens ``wave`` rung costs at most 50 µs per scene vectorised over 10⁵
scenes. The baseline is the ``thin`` rung (the cheapest exact geometric answer a user would
reach for) on the same inputs, timed in the same run; the cold figure includes building the
level's table of (s·W*)² (once per contrast level and process). Also shown: one scene at a time
(a Python loop over 200 scalar calls), the cost a single command pays.

Run: ``python benchmarks/bench_wave.py [--n 100000] [--repeat 5]``
"""

from __future__ import annotations

import argparse
import time

import numpy as np
from timing import best

from camtool.dof.closed import thin_dof
from camtool.dof.wave import Criterion, wave_dof
from camtool.optics import transfer


def scenes(n: int) -> tuple[np.ndarray, ...]:
    rng = np.random.default_rng(7)
    f = rng.uniform(14, 200, n)
    big_n = rng.choice([1.4, 2, 2.8, 4, 5.6, 8, 11, 16], n)
    c = np.full(n, 0.03)
    s = f * 4.0 * np.exp(rng.uniform(0.01, 8, n))
    return f, big_n, c, s


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--n", type=int, default=100_000)
    parser.add_argument("--repeat", type=int, default=5)
    args = parser.parse_args()
    f, n, c, s = scenes(args.n)
    criterion = Criterion(0.3, 30.0)
    transfer._table.cache_clear()
    start = time.perf_counter()
    wave_dof(f, n, c, s, "lens", criterion)
    cold = time.perf_counter() - start
    warm = best(lambda: wave_dof(f, n, c, s, "lens", criterion), args.repeat)
    default = best(lambda: wave_dof(f, n, c, s, "lens"), args.repeat)
    thin = best(lambda: thin_dof(f, n, c, s, "lens"), args.repeat)
    loop = best(lambda: [wave_dof(float(f[i]), float(n[i]), 0.03, float(s[i]), "lens") for i in range(200)], 3)
    per = 1e6 / args.n
    print(f"{args.n} scenes, best of {args.repeat}")
    print(f"wave, mtf:0.3@30, cold (table built)  {cold * per:8.2f} µs/scene")
    print(f"wave, mtf:0.3@30, warm                {warm * per:8.2f} µs/scene")
    print(f"wave, default mtf:0.181@coc, warm     {default * per:8.2f} µs/scene")
    print(f"thin, same scenes                     {thin * per:8.3f} µs/scene")
    print(f"wave / thin                           {warm / thin:8.1f}")
    print(f"wave, one scalar scene at a time      {loop / 200 * 1e6:8.1f} µs/scene")
    verdict = "within" if max(cold, warm, default) * per <= 50.0 else "OVER"
    print(f"budget 50 µs/scene (cold and warm): {verdict}")


if __name__ == "__main__":
    main()
