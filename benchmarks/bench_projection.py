"""Throughput of ``fov --projection``: 10⁶ fisheye angles through camtool against bare numpy.

A fisheye's angle of view across a sensor dimension is 2·θ(h/2) of its
mapping at f(1 + m/P), at most its field (docs/design.md §4.2);
:func:`camtool.geometry.projection.fisheye_field_of_view` computes the three
angles of each scene with its input checks and scalar/array dispatch. The
reference is the equisolid-angle formula typed as one numpy expression per
angle. Best of ``--repeat`` runs, interleaved; the verdict is the ratio.

Run: ``python benchmarks/bench_projection.py [--n 1000000] [--repeat 15]``
"""

from __future__ import annotations

import argparse

import numpy as np
from timing import best

from camtool.geometry.projection import fisheye_field_of_view


def scenes(n: int) -> tuple[np.ndarray, np.ndarray]:
    rng = np.random.default_rng(28)
    return rng.uniform(4.0, 16.0, n), np.exp(rng.uniform(np.log(1e-3), np.log(0.2), n))


def hand(f: np.ndarray, m: np.ndarray, w: float = 36.0, h: float = 24.0) -> tuple[np.ndarray, ...]:
    effective = f * (1.0 + m)
    out = []
    for size in (w, h, float(np.hypot(w, h))):
        ratio = np.minimum(size / (4.0 * effective), 1.0)
        out.append(np.minimum(4.0 * np.degrees(np.arcsin(ratio)), 180.0))
    return tuple(out)


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--n", type=int, default=1_000_000)
    parser.add_argument("--repeat", type=int, default=15)
    args = parser.parse_args()
    f, m = scenes(args.n)
    ours = fisheye_field_of_view(36.0, 24.0, f, "equisolid", m)
    for a, b in zip(ours, hand(f, m), strict=True):
        np.testing.assert_allclose(a, b, rtol=1e-12)
    t_ours = t_ref = float("inf")
    for _ in range(args.repeat):
        t_ours = min(t_ours, best(lambda: fisheye_field_of_view(36.0, 24.0, f, "equisolid", m), 1))
        t_ref = min(t_ref, best(lambda: hand(f, m), 1))
    print(f"{args.n} fisheye scenes (three angles each): camtool {t_ours * 1e3:.1f} ms, "
          f"bare numpy {t_ref * 1e3:.1f} ms, ratio {t_ours / t_ref:.2f}")


if __name__ == "__main__":
    main()
