"""camtool's ray-traced depth of field against the optical design packages, at equal answers.

Run with a Python that has the packages (they are never a dependency of camtool, at run time or
in the tests); without them this prints what is missing and exits:

    python -m venv /tmp/optics && /tmp/optics/bin/pip install rayoptics optiland pyyaml click
    /tmp/optics/bin/python benchmarks/bench_optics_packages.py [--rows 6]

The reference data (tests/data/oracle-dof.csv) were computed with rayoptics 0.9.8 (dgauss100,
cellphone) and optiland 0.6.3 (telephoto127, telecentric36, wideangle17). For each lens this
runs the definitions of tests/data/oracle-README.md on the package that traced it: the edge ray
by Newton's method on the package's trace to the stop, the 65-ray fan traced by the package,
the best focus, the focused object and the near and far limits by Brent's method (scipy), one
fan per evaluation, rays started on the first vertex plane. Every answer is checked against the
table (the same 1e-7 of each depth camtool's tests ask), and only then timed against
camtool's ``raytrace_dof`` for the same scene, cold (its interpolants rebuilt for every call;
the tracer of the lens built once, as the package's model is). The ratio is the package's time
per near/far pair over camtool's. cellphone's aspheric surfaces are left to rayoptics' own
profile classes and are not run here.
"""

from __future__ import annotations

import argparse
import csv
import math
import statistics
import sys
import time
import warnings
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT))

import numpy as np  # noqa: E402
import yaml  # noqa: E402

from camtool.dof import realray  # noqa: E402
from camtool.optics.paraxial import first_order  # noqa: E402
from camtool.optics.prescription import prescription_from_mapping  # noqa: E402

DATA = ROOT / "tests" / "data"
BACKENDS = {"dgauss100": "rayoptics", "telephoto127": "optiland", "telecentric36": "optiland", "wideangle17": "optiland"}
SQRT8 = 2.0 * math.sqrt(2.0)


def optiland_tracer(lens):
    """trace(h0, m, l, upto) through the first ``upto`` lens surfaces with optiland (vectorised over rays)."""
    from optiland.materials import IdealMaterial
    from optiland.optic import Optic
    from optiland.rays import RealRays

    op = Optic()
    op.add_surface(index=0, thickness=np.inf)
    for i, s in enumerate(lens.surfaces):
        material = IdealMaterial(n=s.n) if s.n != 1.0 else "air"
        op.add_surface(index=i + 1, radius=s.radius_mm, thickness=s.thickness_mm, material=material,
                       is_stop=s.stop, conic=s.conic)
    op.add_surface(index=len(lens.surfaces) + 1)
    op.set_aperture(aperture_type="EPD", value=1.0)
    op.set_field_type(field_type="angle")
    op.add_field(y=0.0)
    op.add_wavelength(value=lens.wavelength_nm / 1000.0, is_primary=True)
    surfaces = op.surface_group.surfaces
    wavelength = lens.wavelength_nm / 1000.0

    def trace(h0, m, l, upto):
        n = h0.size
        rays = RealRays(np.zeros(n), h0.copy(), np.zeros(n), np.zeros(n), m.copy(), l.copy(), np.ones(n),
                        np.full(n, wavelength))
        for surface in surfaces[1 : upto + 1]:
            surface.trace(rays, record=False)
        return np.asarray(rays.y), np.asarray(rays.z), np.asarray(rays.M), np.asarray(rays.N)

    return trace


def rayoptics_tracer(lens):
    """trace(h0, m, l, upto) with rayoptics (one ray at a time, as its trace function works)."""
    from opticalglass.opticalmedium import ConstantIndex
    from rayoptics.optical.opticalmodel import OpticalModel
    from rayoptics.raytr import raytrace
    from rayoptics.raytr.opticalspec import WvlSpec

    opm = OpticalModel()
    opm.radius_mode = True
    sm = opm.seq_model
    sm.gaps[0].thi = 1e10  # a distant object for the model's own first-order set-up
    for i, s in enumerate(lens.surfaces):
        sm.add_surface([0.0 if math.isinf(s.radius_mm) else s.radius_mm, s.thickness_mm])
        if s.n != 1.0:
            sm.gaps[-1].medium = ConstantIndex(s.n, f"n{i}")
        if s.stop:
            sm.set_stop()
    opm.optical_spec.spectral_region = WvlSpec([(lens.wavelength_nm, 1.0)], ref_wl=0)
    opm.update_model()
    sm.gaps[0].thi = 0.0  # rays start on the first vertex plane
    sm.gbl_tfrms = sm.compute_global_coords()
    sm.lcl_tfrms = sm.compute_local_transforms()
    vertices = lens.vertices_mm

    def trace(h0, m, l, upto):
        out = np.full((4, h0.size), np.nan)
        for k in range(h0.size):
            try:
                ray, _, _ = raytrace.trace(sm, np.array([0.0, h0[k], 0.0]), np.array([0.0, m[k], l[k]]),
                                           lens.wavelength_nm)
            except Exception:  # a missed surface or total internal reflection: the ray is void
                continue
            point, direction = ray[upto][0], ray[upto][1]
            out[:, k] = point[1], point[2] + vertices[upto - 1], direction[1], direction[2]
        return out[0], out[1], out[2], out[3]

    return trace


class Reference:
    """The reference data's definitions (oracle-README.md) on a package's ray trace."""

    def __init__(self, lens, trace):
        self.lens, self.trace = lens, trace
        self.fo = first_order(lens)
        self.stop = lens.stop_index
        self.count = len(lens.surfaces)
        simpson = np.ones(65)
        simpson[1:-1:2], simpson[2:-1:2] = 4.0, 2.0
        self.simpson, self.fraction = simpson, np.arange(65) / 64.0

    def edge(self, w, n):
        r_stop = self.fo.stop_radius_mm(n)
        h = self.fo.efl_mm / (2.0 * n) / (1.0 + w * self.fo.z_e_mm)
        for _ in range(40):
            pair = np.array([h, h * (1.0 + 1e-7)])
            theta = np.arctan(pair * w)
            y, _, _, _ = self.trace(pair, np.sin(theta), np.cos(theta), self.stop + 1)
            step = (y[0] - r_stop) * (h * 1e-7) / (y[1] - y[0])
            h -= step
            if abs(step) <= 1e-8 * abs(h):
                break
        return h

    def summary(self, w, n):
        h_edge = self.edge(w, n)
        if w == 0.0:
            theta, h0, weights = np.zeros(65), h_edge * self.fraction, self.simpson * self.fraction
        else:
            theta = np.arctan(h_edge * w) * self.fraction
            h0, weights = np.tan(theta) / w, self.simpson * np.sin(theta)
        y, z, m, l = self.trace(h0, np.sin(theta), np.cos(theta), self.count)
        t = m / l
        a = y - t * z
        weights = weights / weights.sum()
        wt2 = float((weights * t * t).sum())
        return -float((weights * a * t).sum()) / wt2, math.sqrt(wt2)

    def dof(self, n, c, distance):
        from scipy.optimize import brentq

        fo, f = self.fo, self.fo.efl_mm
        span = distance - fo.hiatus_mm
        u = 0.5 * span * (1.0 + math.sqrt(1.0 - 4.0 * f / span))
        w0 = 1.0 / (u - fo.z_h_mm)

        def mismatch(w):
            return w * (self.summary(w, n)[0] - distance) + 1.0

        w_focus = brentq(mismatch, *self._bracket(mismatch, w0, 0.02 * w0), xtol=1e-20, rtol=1e-14)
        z_film = self.summary(w_focus, n)[0]

        def excess(w):
            z, s = self.summary(w, n)
            return SQRT8 * abs(z_film - z) * s - c

        depth = n * c / (f * f) * (1.0 + w_focus * f)  # paraxial spacing of the limits in vergence
        w_near = brentq(excess, *self._bracket(excess, w_focus, depth, upward=True), xtol=1e-20, rtol=1e-14)
        far = math.inf
        if excess(0.0) > 0.0:
            w_far = brentq(excess, *self._bracket(excess, w_focus, depth, upward=False), xtol=1e-20, rtol=1e-14)
            far = z_film + 1.0 / w_far
        return z_film + 1.0 / w_near, far

    @staticmethod
    def _bracket(function, start, step, upward=None):
        """A sign change of ``function`` next to ``start`` (both sides, or only up or down), by widening steps.

        A side where the rays fail (NaN) stops widening.
        """
        f_start = function(start)
        sides = {"down": upward in (None, False), "up": upward in (None, True)}
        for k in range(60):
            d = step * 1.6**k
            for side in [s for s, open_ in sides.items() if open_]:
                other = start + d if side == "up" else max(start - d, 0.0)
                value = function(other)
                if not math.isfinite(value):
                    sides[side] = False
                elif (value > 0.0) != (f_start > 0.0):
                    return (start, other) if side == "up" else (other, start)
        raise RuntimeError("no bracket")


def camtool_pair(lens, n, c, distance, repeat=5):
    """camtool's limits and its best time for a cold near/far pair (interpolants rebuilt)."""
    best = math.inf
    for _ in range(repeat):
        realray._curves.cache_clear()
        start = time.perf_counter()
        result = realray.raytrace_dof(lens, n, c, distance)
        best = min(best, time.perf_counter() - start)
    return result, best


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--rows", type=int, default=6, help="reference rows per lens (spread over the table)")
    args = parser.parse_args()
    warnings.filterwarnings("ignore")  # the packages' deprecation and numba notices
    available = {}
    for package in ("rayoptics", "optiland"):
        try:
            __import__(package)
            available[package] = __import__("importlib.metadata").metadata.version(package)
        except ImportError:
            print(f"skipped {package}: not installed (pip install {package} in a throwaway environment)")
    if not available:
        return
    with open(DATA / "oracle-dof.csv", newline="") as handle:
        rows = [r for r in csv.DictReader(handle) if r["method"] == "real_defocus"]
    print(f"packages: {', '.join(f'{k} {v}' for k, v in available.items())}")
    print("| lens | package | pairs | package ms (median) | camtool ms (median, cold) | ratio (median) | ratio (min) "
          "| worst depth error, package / camtool |")
    print("|---|---|---:|---:|---:|---:|---:|---|")
    ratios_all = []
    for name, package in BACKENDS.items():
        if package not in available:
            continue
        lens = prescription_from_mapping(yaml.safe_load((DATA / "prescriptions" / f"{name}.yaml").read_text()), name)
        trace = optiland_tracer(lens) if package == "optiland" else rayoptics_tracer(lens)
        reference = Reference(lens, trace)
        mine = [r for r in rows if r["lens"] == name]
        pick = [mine[round(i * (len(mine) - 1) / max(args.rows - 1, 1))] for i in range(min(args.rows, len(mine)))]
        realray.raytrace_dof(lens, 8.0, 0.03, 5000.0)  # the tracer of the lens, built once
        package_times, camtool_times, errors_p, errors_c = [], [], [], []
        for r in pick:
            n, c, d = float(r["f_number"]), float(r["coc_mm"]), float(r["focus_distance_mm"])
            front, rear = d - float(r["near_mm"]), float(r["far_mm"]) - d
            start = time.perf_counter()
            near, far = reference.dof(n, c, d)
            package_times.append(time.perf_counter() - start)
            errors_p.append(max(abs((d - near) / front - 1.0), abs((far - d) / rear - 1.0)))
            result, seconds = camtool_pair(lens, n, c, d)
            camtool_times.append(seconds)
            errors_c.append(max(abs(result.front_mm / front - 1.0), abs(result.rear_mm / rear - 1.0)))
        assert max(errors_p) < 1e-7 and max(errors_c) < 1e-7, (name, max(errors_p), max(errors_c))  # equal answers
        ratios = [p / q for p, q in zip(package_times, camtool_times)]
        ratios_all += ratios
        print(f"| {name} | {package} | {len(pick)} | {statistics.median(package_times) * 1e3:.1f} "
              f"| {statistics.median(camtool_times) * 1e3:.2f} | {statistics.median(ratios):.0f}x | {min(ratios):.0f}x "
              f"| {max(errors_p):.1e} / {max(errors_c):.1e} |")
    print(f"\nall pairs: median ratio {statistics.median(ratios_all):.0f}x, smallest {min(ratios_all):.0f}x (goal: 100x)")


if __name__ == "__main__":
    main()
