"""Time the prescription-based depth-of-field models: ``raytrace`` and ``paraxial``.

Run from the repository root:

    python benchmarks/bench_optics.py

For each reference lens (tests/data/prescriptions: the five lenses of oracle-dof.csv) it
times, over the focus distances and f-numbers of the reference table:

- ``raytrace`` cold: one near/far pair with the lens's interpolants rebuilt for the call
  (a batched trace of the fan at the Chebyshev nodes, then the focus, hyperfocal and limit
  searches); the tracer of the lens is built once, as a command builds it once;
- ``raytrace`` warm: the same pair once the interpolants of that f-number exist (what every
  further scene at that f-number costs, in a list, a grid or a batch);
- ``paraxial``: one call.

It prints the median and maximum per call (best of three) and the verdicts against the
budgets: ray trace median ≤ 10 ms and maximum ≤ 50 ms per pair (cold) on every lens,
paraxial under 1 ms.
"""

from __future__ import annotations

import csv
import statistics
import time
from pathlib import Path

import yaml

from camtool.dof import realray
from camtool.dof.paraxial import paraxial_dof
from camtool.optics.prescription import prescription_from_mapping

DATA = Path(__file__).resolve().parent.parent / "tests" / "data"
LENSES = ("dgauss100", "telephoto127", "cellphone", "telecentric36", "wideangle17")
BUDGETS = {"raytrace cold": (0.010, 0.050), "raytrace warm": (0.010, 0.050), "paraxial": (0.001, 0.001)}


def per_call(function, repeat: int = 1, cold: bool = False) -> float:
    """Best-of-three wall time per call of ``function`` in seconds (interpolants dropped first when cold)."""
    best = float("inf")
    for _ in range(3):
        if cold:
            realray._curves.cache_clear()
        start = time.perf_counter()
        for _ in range(repeat):
            function()
        best = min(best, (time.perf_counter() - start) / repeat)
    return best


def main() -> None:
    with open(DATA / "oracle-dof.csv", newline="") as handle:
        rows = [r for r in csv.DictReader(handle) if r["method"] == "real_defocus"]
    print("| lens | model | calls | median ms | max ms | median / budget | max / budget |")
    print("|---|---|---:|---:|---:|---:|---:|")
    for name in LENSES:
        path = DATA / "prescriptions" / f"{name}.yaml"
        lens = prescription_from_mapping(yaml.safe_load(path.read_text()), source=path.name)
        scenes = [(float(r["f_number"]), float(r["coc_mm"]), float(r["focus_distance_mm"])) for r in rows if r["lens"] == name]
        realray.raytrace_dof(lens, *scenes[0])  # build and cache the tracer (not part of a pair)
        for model, function, repeat, cold in (
            ("raytrace cold", realray.raytrace_dof, 1, True),
            ("raytrace warm", realray.raytrace_dof, 1, False),
            ("paraxial", paraxial_dof, 200, False),
        ):
            times = [per_call(lambda s=s: function(lens, *s), repeat, cold) for s in scenes]
            median, worst = statistics.median(times), max(times)
            budget_median, budget_max = BUDGETS[model]
            print(f"| {name} | {model} | {len(times)} | {median * 1e3:.2f} | {worst * 1e3:.2f} "
                  f"| {median / budget_median:.2f} | {worst / budget_max:.2f} |")


if __name__ == "__main__":
    main()
