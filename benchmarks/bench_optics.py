"""Time the prescription-based depth-of-field models: ``raytrace`` and ``paraxial``.

Run from the repository root:

    python benchmarks/bench_optics.py

For each reference lens (tests/data/prescriptions) it times, over the focus
distances and f-numbers of the reference table, one ``raytrace`` near/far pair
(a cold call: a fresh focus solve and limit search each time; the tracer for the
lens is built once) and one ``paraxial`` call, and prints the median and
maximum per call, the ray-trace budget ratio (docs/design.md §7: well under
50 ms) and the paraxial ratio (under 1 ms).
"""

from __future__ import annotations

import csv
import statistics
import time
from pathlib import Path

import yaml

from camtool.dof.paraxial import paraxial_dof
from camtool.dof.realray import raytrace_dof
from camtool.optics.prescription import prescription_from_mapping

DATA = Path(__file__).resolve().parent.parent / "tests" / "data"
RAYTRACE_BUDGET_S = 0.050
PARAXIAL_BUDGET_S = 0.001


def per_call(function, repeat: int = 1) -> float:
    """Best-of-three wall time per call of ``function`` in seconds."""
    best = float("inf")
    for _ in range(3):
        start = time.perf_counter()
        for _ in range(repeat):
            function()
        best = min(best, (time.perf_counter() - start) / repeat)
    return best


def main() -> None:
    with open(DATA / "oracle-dof.csv", newline="") as handle:
        rows = [r for r in csv.DictReader(handle) if r["method"] == "real_defocus"]
    print(f"{'lens':<14}{'model':<10}{'calls':>6}{'median ms':>11}{'max ms':>9}{'max/budget':>12}")
    for name in ("dgauss100", "telephoto127", "cellphone"):
        path = DATA / "prescriptions" / f"{name}.yaml"
        lens = prescription_from_mapping(yaml.safe_load(path.read_text()), source=path.name)
        scenes = [(float(r["f_number"]), float(r["coc_mm"]), float(r["focus_distance_mm"])) for r in rows if r["lens"] == name]
        raytrace_dof(lens, *scenes[0])  # build and cache the tracer (not part of a pair)
        for model, function, repeat, budget in (
            ("raytrace", raytrace_dof, 1, RAYTRACE_BUDGET_S),
            ("paraxial", paraxial_dof, 200, PARAXIAL_BUDGET_S),
        ):
            times = [per_call(lambda s=s: function(lens, *s), repeat) for s in scenes]
            median, worst = statistics.median(times), max(times)
            print(f"{name:<14}{model:<10}{len(times):>6}{median * 1e3:>11.3f}{worst * 1e3:>9.3f}{worst / budget:>12.2f}")


if __name__ == "__main__":
    main()
