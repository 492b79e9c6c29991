"""The measured trade of the model ladder: speed against accuracy.

Run from the repository root:

    python benchmarks/bench_trade.py

For every model it prints a markdown table with

- the time per evaluation vectorised over 10⁶ scenes through the dispatcher
  ``camtool.dof.ladder.depth_of_field`` (which also computes every error
  estimate) and, for the closed forms, of the model function alone; the ray
  trace runs one scene at a time, so its vectorised figure is its scalar one,
- the time per scalar call (best of several repetitions),
- the median and maximum error against ``raytrace`` (camtool.dof.auto.depth_error:
  the worse limit's shift in vergence relative to the depth of field) over a
  fixed grid of scenes on the shared lenses (tests/data/prescriptions), and
- ``auto``'s cost against the rung it picks, over a few hundred scenes on every
  kind of lens (none, pupil magnification and hiatus by hand, every shipped
  prescription): each scene's auto call and the same dispatcher call of the
  rung auto picked (``--model RUNG``, which computes the same error estimate)
  timed in turn (A B A B …, best of each), summed over the scenes, overall and
  per rung (budget 1.05×); over arrays, auto against each rung it picked run
  on its own scenes; and auto with a cold aberration cache.

Other jobs may share the two cores: compare ratios, not absolute times.
"""

from __future__ import annotations

import statistics
import time
from pathlib import Path

import numpy as np
import yaml

from camtool.core.errors import DomainError
from camtool.dof import auto as auto_module
from camtool.dof.auto import depth_error
from camtool.dof.ladder import LensData, depth_of_field
from camtool.optics.prescription import prescription_from_mapping

DATA = Path(__file__).resolve().parent.parent / "tests" / "data" / "prescriptions"
SHARED = {"dgauss100": ((2.0, 2.8, 5.6, 11.0, 22.0), 0.03), "telephoto127": ((5.6, 8.0, 11.0, 22.0), 0.03),
          "cellphone": ((3.5, 5.6, 8.0, 16.0), 0.0048)}
MODELS = ("approx", "thin", "thick", "paraxial", "raytrace", "auto")


def lens(name: str) -> LensData:
    path = DATA / f"{name}.yaml"
    return LensData(prescription=prescription_from_mapping(yaml.safe_load(path.read_text()), source=path.name))


def best_time(function, repeat: int = 5, number: int = 1) -> float:
    """Best of ``repeat`` runs of ``number`` calls, per call, in seconds."""
    best = float("inf")
    for _ in range(repeat):
        start = time.perf_counter()
        for _ in range(number):
            function()
        best = min(best, (time.perf_counter() - start) / number)
    return best


def scene_grid():
    for name, (f_numbers, coc) in SHARED.items():
        data = lens(name)
        fo = data.first_order
        for n in f_numbers:
            h = fo.efl_mm**2 / (n * coc) + 2 * fo.efl_mm
            for s in np.geomspace((4 * fo.efl_mm + fo.hiatus_mm) * 1.02, 3 * h, 6):
                yield data, n, coc, float(s)


def errors() -> dict[str, list[float]]:
    out: dict[str, list[float]] = {m: [] for m in MODELS}
    for data, n, c, s in scene_grid():
        # thick with the prescription's paraxial P and hiatus (the same numbers as paraxial)
        reference = depth_of_field("raytrace", None, n, c, s, lens=data).limits
        for model in MODELS:
            try:
                result = depth_of_field(model, None, n, c, s, lens=data)
            except DomainError:  # closer than a thin lens of this focal length can focus (negative hiatus)
                continue
            out[model].append(float(depth_error(result.limits, reference)))
    return out


def vector_times() -> dict[str, float]:
    rng = np.random.default_rng(5)
    count = 1_000_000
    f = rng.uniform(14, 200, count)
    n = rng.choice([1.4, 2.8, 5.6, 11.0, 22.0], count)
    s = f * 4.5 + 10.0 + f * np.exp(rng.uniform(0, 8, count))
    hand = LensData(pupil_magnification=0.8, hiatus_mm=10.0)
    out = {}
    for model in ("approx", "thin", "thick", "auto"):
        out[model] = best_time(lambda: depth_of_field(model, f, n, 0.03, s, lens=hand), repeat=3) / count
    dg = lens("dgauss100")
    # dgauss100: f = 100 mm
    out["paraxial"] = best_time(lambda: depth_of_field("paraxial", None, n, 0.03, 500.0 + s * 4, lens=dg), repeat=3) / count

    from camtool.dof.closed import approx_dof, thin_dof
    from camtool.dof.thick import thick_dof

    out["approx (function)"] = best_time(lambda: approx_dof(f, n, 0.03, s), repeat=3) / count
    out["thin (function)"] = best_time(lambda: thin_dof(f, n, 0.03, s), repeat=3) / count
    out["thick (function)"] = best_time(lambda: thick_dof(f, n, 0.03, s, 0.8, 10.0), repeat=3) / count
    # one hand-written numpy expression of the thin-lens limits from the lens (the §7 comparison)
    h0 = f * f / (n * 0.03)
    out["numpy thin (hand-written)"] = best_time(
        lambda: (s * h0 / (h0 + s - f), np.where(s < h0 + f, s * h0 / (h0 + f - s), np.inf)), repeat=3) / count
    return out


def scalar_times() -> dict[str, float]:
    dg = lens("dgauss100")
    hand = LensData(pupil_magnification=1.146, hiatus_mm=-27.0)
    out = {}
    for model in MODELS:
        data = dg if model in ("paraxial", "raytrace", "auto") else hand
        number = 5 if model == "raytrace" else 2000
        out[model] = best_time(lambda: depth_of_field(model, None if data is dg else 100.0, 5.6, 0.03, 4000.0,
                                                      lens=data), number=number)
    return out


def auto_overhead() -> list[tuple[str, str, float, float]]:
    """(scene, model auto picks, auto time / the picked model's time, cold/warm auto) on one scalar scene."""
    rows = []
    scenes = [("50 mm f/8 3 m, no lens data", 50.0, 8.0, 3000.0, LensData(), 0.01),
              ("dgauss100 f/5.6 4 m", None, 5.6, 4000.0, lens("dgauss100"), 0.01),
              ("dgauss100 f/2 4 m, 0.1 %", None, 2.0, 4000.0, lens("dgauss100"), 0.001)]
    for label, f, n, s, data, tol in scenes:
        picked = depth_of_field("auto", f, n, 0.03, s, lens=data, tolerance=tol).model
        number = 5 if picked == "raytrace" else 2000
        auto = best_time(lambda: depth_of_field("auto", f, n, 0.03, s, lens=data, tolerance=tol), number=number)
        model = best_time(lambda: depth_of_field(picked, f, n, 0.03, s, lens=data), number=number)
        auto_module.aberration_table.cache_clear()
        start = time.perf_counter()
        depth_of_field("auto", f, n, 0.03, s, lens=data, tolerance=tol)
        cold = time.perf_counter() - start
        rows.append((label, picked, auto / model, cold / auto))
    return rows


SHIPPED = Path(__file__).resolve().parent.parent / "lens_db" / "prescriptions"


def overhead_scenes(per_lens: int = 40) -> list[tuple[str, object, float, float, LensData]]:
    """(lens label, focal length or None, N, distance from the sensor, lens data): random scenes, fixed seed."""
    lenses = [("no lens data", LensData()), ("P 0.8, hiatus 10 mm", LensData(pupil_magnification=0.8, hiatus_mm=10.0))]
    for path in sorted(SHIPPED.glob("*.yaml")):
        lenses.append((path.stem, LensData(prescription=prescription_from_mapping(yaml.safe_load(path.read_text()),
                                                                                   source=path.name))))
    rng = np.random.default_rng(7)
    out = []
    for label, data in lenses:
        for _ in range(per_lens):
            f = data.focal_length_mm or float(rng.uniform(14.0, 200.0))
            n = float(rng.choice([1.4, 2.0, 2.8, 4.0, 5.6, 8.0, 11.0, 16.0, 22.0]))
            if data.prescription is not None:
                n = max(n, data.prescription.f_number)
            s = float(4.6 * f + 20.0 + f * np.exp(rng.uniform(0.0, 7.0)))
            out.append((label, None if data.prescription is not None else f, n, s, data))
    return out


def cpu_time(function, number: int) -> float:
    """CPU time of this process per call over ``number`` calls (time.process_time: other jobs on the cores do not count)."""
    start = time.process_time()
    for _ in range(number):
        function()
    return (time.process_time() - start) / number


def auto_against_picked(per_lens: int = 40, rounds: int = 9) -> dict[str, tuple[int, float, float]]:
    """Per rung auto picked (and "all"): (scenes, summed auto time, summed time of that rung's dispatcher call).

    Each scene's two calls are timed in turn, ``rounds`` times, by CPU time; the least of each is kept.
    """
    totals: dict[str, list[float]] = {}
    for _label, f, n, s, data in overhead_scenes(per_lens):
        c = 0.005 if (data.focal_length_mm or 50.0) < 10.0 else 0.03
        picked = depth_of_field("auto", f, n, c, s, lens=data).model
        number = 20 if picked == "raytrace" else 200
        best_auto = best_rung = float("inf")
        for _ in range(rounds):  # interleaved: machine noise hits both alike
            best_auto = min(best_auto, cpu_time(lambda: depth_of_field("auto", f, n, c, s, lens=data), number))
            best_rung = min(best_rung, cpu_time(lambda: depth_of_field(picked, f, n, c, s, lens=data), number))
        for key in (picked, "all"):
            entry = totals.setdefault(key, [0, 0.0, 0.0])
            entry[0] += 1
            entry[1] += best_auto
            entry[2] += best_rung
    return {k: (int(v[0]), v[1], v[2]) for k, v in totals.items()}


def auto_vector(count: int = 200_000, rounds: int = 7) -> list[tuple[str, str, float, float]]:
    """Arrays: (lens, rungs picked, auto's CPU time, the picked rungs' over their own scenes), least of ``rounds``."""
    rng = np.random.default_rng(11)
    f = rng.uniform(14, 200, count)
    n = rng.choice([1.4, 2.8, 5.6, 11.0, 22.0], count)
    s = f * 4.6 + 20.0 + f * np.exp(rng.uniform(0, 7, count))
    out = []
    for label, data in (("no lens data", LensData()), ("P 0.8, hiatus 10 mm", LensData(pupil_magnification=0.8,
                                                                                          hiatus_mm=10.0))):
        for plane in ("sensor", "lens"):
            picked = depth_of_field("auto", f, n, 0.03, s, plane, lens=data).model
            groups = {str(name): np.nonzero(picked == name)[0] for name in sorted(set(picked))}

            def direct(groups=groups, data=data, plane=plane):
                for name, rows in groups.items():
                    depth_of_field(name, f[rows], n[rows], 0.03, s[rows], plane, lens=data)

            best_auto = best_rungs = float("inf")
            for _ in range(rounds):
                best_auto = min(best_auto, cpu_time(lambda data=data, plane=plane: depth_of_field(
                    "auto", f, n, 0.03, s, plane, lens=data), 1))
                best_rungs = min(best_rungs, cpu_time(direct, 1))
            mix = ", ".join(f"{name} {rows.size / count:.0%}" for name, rows in groups.items())
            out.append((f"{label}, from the {plane}", mix, best_auto, best_rungs))
    return out


def main() -> None:
    errs = errors()
    vec = vector_times()
    one = scalar_times()
    print("| model | time per evaluation, 10⁶ scenes | time per scalar call | median error vs raytrace "
          "| max error vs raytrace |")
    print("|---|---:|---:|---:|---:|")
    for model in MODELS:
        v = vec.get(model)
        shown = f"{v * 1e9:.0f} ns" if v is not None else f"{one[model] * 1e3:.1f} ms (one scene at a time)"
        print(f"| {model} | {shown} | {one[model] * 1e6:.1f} µs | {statistics.median(errs[model]):.3%} "
              f"| {max(errs[model]):.3%} |")
    for name in ("approx (function)", "thin (function)", "thick (function)", "numpy thin (hand-written)"):
        print(f"| {name} | {vec[name] * 1e9:.0f} ns | | | |")
    print(f"\n{len(errs['thin'])} scenes on dgauss100, telephoto127 and cellphone "
          "(closest focus to 3× hyperfocal, f-numbers from the design aperture to f/22).")
    print("thin_dof (sensor plane, all seven outputs) / near and far hand-written in numpy from the lens: "
          f"{vec['thin (function)'] / vec['numpy thin (hand-written)']:.2f}×; through the dispatcher "
          f"(estimates included): {vec['thin'] / vec['numpy thin (hand-written)']:.2f}× "
          "(benchmarks/bench_throughput.py makes the like-for-like §7 comparison)")
    print("\n| auto picked | scenes | auto, summed | that rung's call, summed | auto / that rung (budget 1.05×) |")
    print("|---|---:|---:|---:|---:|")
    for key, (count, mine, theirs) in sorted(auto_against_picked().items(), key=lambda kv: kv[0] == "all"):
        print(f"| {key} | {count} | {mine * 1e3:.2f} ms | {theirs * 1e3:.2f} ms | {mine / theirs:.3f}× |")
    print("\n| 200,000 scenes as arrays | rungs auto picks | auto | those rungs on their own scenes | ratio (budget 1.05×) |")
    print("|---|---|---:|---:|---:|")
    for label, mix, mine, theirs in auto_vector():
        print(f"| {label} | {mix} | {mine * 1e3:.1f} ms | {theirs * 1e3:.1f} ms | {mine / theirs:.3f}× |")
    print("\n| scene | auto picks | auto / that model (budget 1.05×) | first call / later calls |")
    print("|---|---|---:|---:|")
    for label, picked, ratio, cold in auto_overhead():
        print(f"| {label} | {picked} | {ratio:.2f}× | {cold:.1f}× |")


if __name__ == "__main__":
    main()
