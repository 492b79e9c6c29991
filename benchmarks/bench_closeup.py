"""Throughput of ``dof -m``: 10⁶ magnifications through the close-up closed form against bare numpy.

docs/design.md §7: a batch of 10⁶ evaluations runs within 1.5× of the same
formula typed as one numpy expression. ``camtool dof -m`` computes the thin
(or thick, with P) limits at a magnification with
:func:`camtool.dof.closeup.closeup_dof` (docs/closeup.md §1); the reference
below is that formula, with the same seven outputs and the same infinity
handling, without camtool's input checks and scalar/array dispatch. Best of
``--repeat`` runs; the verdict is the ratio.

Run: ``python benchmarks/bench_closeup.py [--n 1000000] [--repeat 15]``
"""

from __future__ import annotations

import argparse

import numpy as np
from timing import best

from camtool.dof.closeup import closeup_dof


def scenes(n: int) -> tuple[np.ndarray, ...]:
    rng = np.random.default_rng(12)
    f = rng.uniform(35, 200, n)
    big_n = rng.choice([2.8, 4, 5.6, 8, 11, 16, 22], n)
    c = np.full(n, 0.03)
    m = np.exp(rng.uniform(np.log(0.01), np.log(20.0), n))
    return f, big_n, c, m


def hand(f: np.ndarray, n: np.ndarray, c: np.ndarray, m: np.ndarray, p: float = 1.0) -> tuple[np.ndarray, ...]:
    nc = n * c
    k = nc / f
    spread = nc * (1.0 + m / p)
    u = f + f / m
    front = spread / (m * (m + k))
    beyond = m <= k
    with np.errstate(divide="ignore", invalid="ignore"):
        rear = np.where(beyond, np.inf, spread / (m * (m - k)))
    offset = u + f + f * m
    return offset - front, offset + rear, front, rear, front + rear, f * f / nc + f + f + nc, m


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--n", type=int, default=1_000_000)
    parser.add_argument("--repeat", type=int, default=15)
    args = parser.parse_args()
    f, n, c, m = scenes(args.n)
    ours = closeup_dof(f, n, c, m)
    reference = hand(f, n, c, m)
    for a, b in zip(ours, reference):
        np.testing.assert_allclose(a, b, rtol=1e-15)
    # interleaved, so that load from elsewhere on a shared machine falls on both sides alike
    t_ours = t_ref = float("inf")
    for _ in range(args.repeat):
        t_ours = min(t_ours, best(lambda: closeup_dof(f, n, c, m), 1))
        t_ref = min(t_ref, best(lambda: hand(f, n, c, m), 1))
    ratio = t_ours / t_ref
    print(f"{args.n:,} magnifications (0.01 to 20), best of {args.repeat}\n")
    print("| model | camtool (ms) | same formula in bare numpy (ms) | ratio | budget |\n|---|---:|---:|---:|---|")
    print(f"| dof -m (thin, sensor plane) | {t_ours * 1e3:.1f} | {t_ref * 1e3:.1f} | {ratio:.2f} | "
          f"{'ok' if ratio <= 1.5 else 'OVER'} (≤ 1.5) |")


if __name__ == "__main__":
    main()
