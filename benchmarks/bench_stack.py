"""Cost of a focus-bracketing plan of 10⁴ frames against one ``dof`` evaluation per frame.

``camtool stack`` (bracketing mode, thin model) chains each frame's near
limit to the previous far limit and solves the focus in closed form, with a
short fixed-point iteration for sensor-plane distances (docs/stack.md). The
reference is what a user without the planner would pay at the least: one
call of :func:`camtool.dof.ladder.depth_of_field` (``thin``, scalar) per
frame, at the plan's own focus distances. Best of ``--repeat`` runs; the
verdict is the ratio (plan time / reference time).

Run: ``python benchmarks/bench_stack.py [--repeat 5] [--plane sensor]``
"""

from __future__ import annotations

import argparse
import math

from timing import best

from camtool.dof.ladder import depth_of_field
from camtool.dof.stack import bracket_plan

# 100 mm at f/1.4 with a 1 µm CoC from 0.38 m (lens plane) or 0.53 m (sensor plane) to infinity: about 10⁴ frames
SCENE = {"focal_length_mm": 100.0, "f_number": 1.4, "coc_mm": 0.001}


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--repeat", type=int, default=5)
    parser.add_argument("--plane", choices=["lens", "sensor"], default="lens")
    args = parser.parse_args()
    f, n, c = SCENE["focal_length_mm"], SCENE["f_number"], SCENE["coc_mm"]
    near = 380.0 if args.plane == "lens" else 530.0

    def plan() -> object:
        return bracket_plan(f, n, c, near, math.inf, 0.0, "thin", 10**6, distance_from=args.plane)

    frames = bracket_plan(f, n, c, near, math.inf, 0.0, "thin", 10**6, distance_from=args.plane).frames
    focus = [f + f / fr.magnification for fr in frames]  # lens-plane focus of every frame

    def reference() -> None:
        for u in focus:
            depth_of_field("thin", f, n, c, u, "lens")

    t_plan, t_ref = best(plan, args.repeat), best(reference, args.repeat)
    print(f"{len(frames)} frames ({args.plane} plane): plan {t_plan * 1e3:.1f} ms, "
          f"{len(frames)} dof evaluations {t_ref * 1e3:.1f} ms, ratio {t_plan / t_ref:.3f}")


if __name__ == "__main__":
    main()
