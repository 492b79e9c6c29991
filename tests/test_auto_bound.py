"""auto's error estimate bounds its actual error against the ray trace, over every shipped prescription.

The grid: every prescription in lens_db/prescriptions/, every f-number from its design value
down to f/32, focus distances from just beyond the closest real-ray focus (×1.001, ×1.01,
×1.05) to three times the hyperfocal distance, measured from the sensor and from the lens.
For each scene ``auto``'s answer is compared with ``raytrace`` (camtool.dof.auto.depth_error);
its ``error_estimate`` must be at least the actual error in at least 97 % of the scenes where
it ran a rung below the ray trace (a scene where it traced rays is exact by definition and is
not counted). The same is asked of ``paraxial``'s estimate on every scene (the aberration
estimate alone). The fractions and the worst scenes are printed (pytest -s).
"""

from __future__ import annotations

import functools
import math
from pathlib import Path
from typing import Any

import numpy as np
import pytest
import yaml

from camtool.core.errors import DomainError
from camtool.dof import auto
from camtool.dof.ladder import LensData, depth_of_field
from camtool.dof.realray import closest_focus_mm
from camtool.optics.prescription import prescription_from_mapping

SHIPPED = Path(__file__).resolve().parent.parent / "lens_db" / "prescriptions"
BOUND = 0.97
TOLERANCE = 0.01
F_NUMBERS = (2.8, 4.0, 5.6, 8.0, 11.0, 16.0, 22.0, 32.0)


@functools.cache
def shipped() -> tuple[tuple[str, LensData], ...]:
    out = []
    for path in sorted(SHIPPED.glob("*.yaml")):
        lens = prescription_from_mapping(yaml.safe_load(path.read_text()), source=path.name)
        out.append((path.stem, LensData(prescription=lens)))
    return tuple(out)


@functools.cache
def scenes() -> tuple[tuple[str, LensData, float, float, float, str], ...]:
    """(name, lens, N, c, distance, plane): the grid of the module docstring."""
    out = []
    for name, lens in shipped():
        f, design = lens.focal_length_mm, lens.prescription.f_number
        coc = 0.03 if f > 20.0 else 0.005  # full frame; a phone's small sensor
        for n in sorted({design, *(n for n in F_NUMBERS if n > design)}):
            hyperfocal = f * f / (n * coc) + 2.0 * f
            for plane in ("sensor", "lens"):
                closest = closest_focus_mm(lens.prescription, n, plane)
                near = [closest * k for k in (1.001, 1.01, 1.05)]
                for d in (*near, *np.geomspace(closest * 1.2, 3 * hyperfocal, 6)):
                    out.append((name, lens, n, coc, float(d), plane))
    return tuple(out)


@functools.cache
def reference(index: int) -> Any:
    _name, lens, n, c, d, plane = scenes()[index]
    return depth_of_field("raytrace", None, n, c, d, plane, lens=lens).limits


def audit(model: str) -> tuple[int, list[tuple[float, float, float, str]]]:
    """(scenes counted, [(actual/estimate, actual, estimate, scene)] where the estimate falls short, worst first)."""
    counted, short = 0, []
    for index, (name, lens, n, c, d, plane) in enumerate(scenes()):
        try:
            result = depth_of_field(model, None, n, c, d, plane, lens=lens, tolerance=TOLERANCE)
        except DomainError:  # the paraxial lens cannot focus this close (its closest focus differs by the shift)
            continue
        if result.model == "raytrace":
            continue
        counted += 1
        actual, estimate = float(auto.depth_error(result.limits, reference(index))), float(result.error_estimate)
        if not actual <= estimate:
            short.append((actual / estimate if estimate else math.inf, actual, estimate,
                          f"{name} f/{n:g} c {c} {d:.1f} mm from the {plane}: {result.model}"))
    return counted, sorted(short, reverse=True)


def report(label: str, counted: int, short: list[Any]) -> float:
    fraction = 1.0 - len(short) / counted
    print(f"\n{label}: {counted} scenes, estimate >= actual in {fraction:.1%}")
    for ratio, actual, estimate, scene in short[:5]:
        print(f"  {scene}: actual {actual:.3%}, estimated {estimate:.3%} ({ratio:.2f}x)")
    return fraction


def test_the_grid_covers_every_shipped_prescription_close_focus_and_small_apertures() -> None:
    names = {s[0] for s in scenes()}
    assert names == {p.stem for p in SHIPPED.glob("*.yaml")} and len(names) >= 5
    assert any(s[2] == 32.0 for s in scenes())
    # close focus: the first distance is within 0.1 % of the closest real-ray focus
    assert all(any(s[4] <= closest_focus_mm(lens.prescription, 32.0, s[5]) * 1.001 for s in scenes() if s[0] == name)
               for name, lens in shipped())


def test_auto_estimate_bounds_the_actual_error_against_the_ray_trace() -> None:
    counted, short = audit("auto")
    assert counted >= 400
    assert report("auto against raytrace", counted, short) >= BOUND, short[:5]


def test_paraxial_estimate_bounds_the_actual_error_on_every_scene() -> None:
    counted, short = audit("paraxial")
    assert report("paraxial against raytrace", counted, short) >= BOUND, short[:5]


def test_the_grid_fails_an_estimate_without_the_focus_shift(monkeypatch: pytest.MonkeyPatch) -> None:
    # The test can fail: leaving out where the real rays put the focused object (the error near
    # the closest focus, measured from the sensor) makes paraxial's estimate fall short.
    monkeypatch.setattr(auto, "focus_shift_share", lambda *args: 0.0)
    counted, short = audit("paraxial")
    assert report("paraxial without the focus shift", counted, short) < BOUND
