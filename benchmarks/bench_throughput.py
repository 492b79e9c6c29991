"""Throughput: 10⁶ evaluations of each closed-form model against the same formula as one numpy expression.

docs/design.md §7: a grid or batch of 10⁶ evaluations runs at numpy speed, within 1.5×
of the formula hand-written as one numpy expression. Both sides get the same
inputs (focus distances from the lens, so no plane conversion is timed on one
side only); figures are the best of ``--repeat`` runs, and the verdict is the
ratio.

Run: ``python benchmarks/bench_throughput.py [--n 1000000] [--repeat 7]``
"""

from __future__ import annotations

import argparse

import numpy as np
from timing import best

from camtool.dof.closed import approx_dof, thin_dof


def scenes(n: int) -> tuple[np.ndarray, ...]:
    rng = np.random.default_rng(7)
    f = rng.uniform(14, 200, n)
    big_n = rng.choice([1.4, 2, 2.8, 4, 5.6, 8, 11, 16, 22], n)
    c = np.full(n, 0.03)
    s = f * 2.0 * np.exp(rng.uniform(0.01, 8, n))
    return f, big_n, c, s


# The references are the models' own formulas (as their docstrings write them: the same
# arrangement, the same seven outputs, infinity where the far limit is beyond infinity) typed
# straight into numpy, without camtool's input checks and scalar/array dispatch: the ratio is
# what the library's structure costs over bare numpy.


def hand_thin(f: np.ndarray, n: np.ndarray, c: np.ndarray, s: np.ndarray) -> tuple[np.ndarray, ...]:
    h0 = f * f / (n * c)
    h, u_minus_f = h0 + f, s - f
    denominator = 1.0 + (h0 - f) / s
    near, front = h0 / denominator, u_minus_f / denominator
    beyond, gap = s >= h, h - s
    with np.errstate(divide="ignore", invalid="ignore"):
        far = np.where(beyond, np.inf, s * h0 / gap)
        rear = np.where(beyond, np.inf, s * u_minus_f / gap)
    return near, far, front, rear, front + rear, h, f / u_minus_f


def hand_approx(f: np.ndarray, n: np.ndarray, c: np.ndarray, s: np.ndarray) -> tuple[np.ndarray, ...]:
    h0 = f * f / (n * c)
    ratio = h0 / s
    denominator = 1.0 + ratio
    beyond = s >= h0
    with np.errstate(divide="ignore", invalid="ignore"):
        far = np.where(beyond, np.inf, h0 / (ratio - 1.0))
        rear = np.where(beyond, np.inf, s / (ratio - 1.0))
    front = s / denominator
    return h0 / denominator, far, front, rear, front + rear, h0, f / (s - f)


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
    print("| model | camtool (ms) | same formula in bare numpy (ms) | ratio | budget |\n|---|---:|---:|---:|---|")
    for name, ours, reference in cases:
        t_ours, t_ref = best(ours, args.repeat), best(reference, args.repeat)
        ratio = t_ours / t_ref
        print(f"| {name} | {t_ours * 1e3:.1f} | {t_ref * 1e3:.1f} | {ratio:.2f} | {'ok' if ratio <= 1.5 else 'OVER'} (≤ 1.5) |")
    t_sensor = best(lambda: thin_dof(f, n, c, s + 4 * f, "sensor"), args.repeat)
    print(f"\nthin from the sensor plane (exact conversion included): {t_sensor * 1e3:.1f} ms")


if __name__ == "__main__":
    main()
