"""The wave rung with a prescription: time per near/far pair on every shipped prescription.

docs/wave.md: at most 200 ms per near/far pair (the focus by real rays, the wavefront of every object
the search tries, its FFT MTF, the limits and the hyperfocal distance). Two figures per scene:
**cold** — every cache emptied first (the ray tracer and its interpolants, the wavefront tracer, the
hyperfocal film), what a single ``camtool dof --model wave --prescription`` pays; **warm** — a new focus
distance with the same lens and f-number (the hyperfocal film and the interpolants kept), what each
further row of a list or batch pays. The baseline, timed in the same run, is the ``raytrace`` rung for
the same scene, cold (the cheapest answer from the same prescription a user would reach for).

Run: ``python benchmarks/bench_wave_prescription.py [--repeat 3]``
"""

from __future__ import annotations

import argparse
from pathlib import Path

from timing import best

from camtool.dof import realray, wavetrace
from camtool.dof.wave import DEFAULT_CRITERION, Criterion
from camtool.optics import tracer, wavefront
from camtool.optics.paraxial import first_order

ROOT = Path(__file__).resolve().parent.parent
BUDGET_S = 0.200
WIDE_OPEN = Criterion(0.1, None)
"""Wide open at 60 f the default criterion is out of reach of dgauss100 (its in-focus MTF at 1/c is 0.13)."""


def shipped() -> dict[str, object]:
    """The shipped prescriptions by id (:func:`camtool.presets.shipped.prescriptions_by_id`)."""
    from camtool.presets.shipped import prescriptions_by_id

    return prescriptions_by_id()


def forget() -> None:
    """Empty every cache the prescription path keeps."""
    realray._curves.cache_clear()
    tracer._BY_IDENTITY.clear()
    tracer._real_tracer.cache_clear()
    wavefront._CACHE.clear()
    wavetrace._HYPERFOCAL_FILM.clear()


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--repeat", type=int, default=3)
    args = parser.parse_args()
    worst = 0.0
    print(f"{'lens':<17}{'N':>6}{'focus':>9}  {'criterion':<14}{'cold ms':>8}{'warm ms':>9}{'raytrace ms':>13}{'ratio':>7}")
    for name, lens in shipped().items():
        f = first_order(lens).efl_mm
        coc = 0.0048 if name == "cellphone" else 0.03
        design = lens.f_number or 4.0
        stopped = 2.0 * design if name != "cellphone" else 1.2 * design
        for n, distance, criterion in ((design, 60.0 * f, WIDE_OPEN), (stopped, 25.0 * f, DEFAULT_CRITERION)):

            def cold(n: float = n, distance: float = distance, criterion: Criterion = criterion) -> None:
                forget()
                wavetrace.prescription_wave_dof(lens, n, coc, distance, criterion=criterion)

            def ray(n: float = n, distance: float = distance) -> None:
                forget()
                realray.raytrace_dof(lens, n, coc, distance)

            cold_s = best(cold, args.repeat)
            wavetrace.prescription_wave_dof(lens, n, coc, distance, criterion=criterion)
            steps = iter(range(1, 1000))
            warm_s = best(lambda n=n, distance=distance, criterion=criterion: wavetrace.prescription_wave_dof(
                lens, n, coc, distance * (1.0 + 0.01 * next(steps)), criterion=criterion), args.repeat)
            ray_s = best(ray, args.repeat)
            worst = max(worst, cold_s)
            print(f"{name:<17}{n:>6.3g}{distance / 1000:>8.2f}m  {criterion.label():<14}{cold_s * 1e3:>8.1f}"
                  f"{warm_s * 1e3:>9.1f}{ray_s * 1e3:>13.2f}{cold_s / ray_s:>7.0f}")
    verdict = "within" if worst <= BUDGET_S else "OVER"
    print(f"budget {BUDGET_S * 1e3:.0f} ms per near/far pair, cold, on every shipped prescription: {verdict} "
          f"(worst {worst * 1e3:.0f} ms)")


if __name__ == "__main__":
    main()
