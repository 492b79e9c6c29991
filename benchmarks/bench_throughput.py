"""Throughput: 10⁶ evaluations of each closed-form model against the same formula as one numpy expression.

DESIGN §7: a grid or batch of 10⁶ evaluations runs at numpy speed, within 1.5×
of the formula hand-written as one numpy expression. Both sides get the same
inputs (focus distances from the lens, so no plane conversion is timed on one
side only); figures are the best of ``--repeat`` runs, and the verdict is the
ratio.

Run: ``python benchmarks/bench_throughput.py [--n 1000000] [--repeat 7]``
"""

from __future__ import annotations

import argparse
import time
from collections.abc import Callable

import numpy as np

from camtool.dof import approx_dof, thin_dof


def best(fn: Callable[[], object], repeat: int) -> float:
    times = []
    for _ in range(repeat):
        start = time.perf_counter()
        fn()
        times.append(time.perf_counter() - start)
    return min(times)


def scenes(n: int) -> tuple[np.ndarray, ...]:
    rng = np.random.default_rng(7)
    f = rng.uniform(14, 200, n)
    big_n = rng.choice([1.4, 2, 2.8, 4, 5.6, 8, 11, 16, 22], n)
    c = np.full(n, 0.03)
    s = f * 2.0 * np.exp(rng.uniform(0.01, 8, n))
    return f, big_n, c, s


# The references compute what the models return -- near, far, front, rear, total,
# hyperfocal and magnification -- written the obvious way, without camtool's
# input checks and cancellation-free arrangement.


def hand_thin(f: np.ndarray, n: np.ndarray, c: np.ndarray, s: np.ndarray) -> tuple[np.ndarray, ...]:
    f2, k = f * f, n * c * (s - f)
    near = s * f2 / (f2 + k)
    with np.errstate(divide="ignore"):
        far = np.where(f2 > k, s * f2 / (f2 - k), np.inf)
    return near, far, s - near, far - s, far - near, f2 / (n * c) + f, f / (s - f)


def hand_approx(f: np.ndarray, n: np.ndarray, c: np.ndarray, s: np.ndarray) -> tuple[np.ndarray, ...]:
    h = f * f / (n * c)
    near = h * s / (h + s)
    with np.errstate(divide="ignore"):
        far = np.where(s < h, h * s / (h - s), np.inf)
    return near, far, s - near, far - s, far - near, h, f / (s - f)


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--n", type=int, default=1_000_000)
    parser.add_argument("--repeat", type=int, default=7)
    args = parser.parse_args()
    f, n, c, s = scenes(args.n)
    cases = [
        ("approx", lambda: approx_dof(f, n, c, s), lambda: hand_approx(f, n, c, s)),
        ("thin (from the lens)", lambda: thin_dof(f, n, c, s, "lens"), lambda: hand_thin(f, n, c, s)),
    ]
    print(f"{args.n:,} scenes, best of {args.repeat}\n")
    print("| model | camtool (ms) | one numpy expression (ms) | ratio | budget |\n|---|---:|---:|---:|---|")
    for name, ours, reference in cases:
        t_ours, t_ref = best(ours, args.repeat), best(reference, args.repeat)
        ratio = t_ours / t_ref
        print(f"| {name} | {t_ours * 1e3:.1f} | {t_ref * 1e3:.1f} | {ratio:.2f} | {'ok' if ratio <= 1.5 else 'OVER'} (≤ 1.5) |")
    t_sensor = best(lambda: thin_dof(f, n, c, s + 4 * f, "sensor"), args.repeat)
    print(f"\nthin from the sensor plane (exact conversion included): {t_sensor * 1e3:.1f} ms")


if __name__ == "__main__":
    main()
