"""camtool's ray-traced depth of field against the optical design packages, at equal answers.

Run with a Python that has the packages (they are never a dependency of camtool, at run time or
in the tests); without them this prints what is missing and exits:

    python -m venv /tmp/optics && /tmp/optics/bin/pip install rayoptics optiland pyyaml click numpy
    /tmp/optics/bin/python benchmarks/bench_optics_packages.py [--rows 4]

Every shipped prescription (lens_db/prescriptions/*.yaml) is modelled in both packages: spheres
and planes as such, conic and polynomial aspheres (every power of r, odd ones included) as
rayoptics' ``RadialPolynomial`` and optiland's ``odd_asphere``, each surface's sag checked
against camtool's before anything is timed; a lens a package cannot model is named with the
reason. On each package the definitions of tests/data/oracle-README.md run on the package's own
ray trace: the edge ray by Newton's method on the package's trace to the stop, the 65-ray fan
traced by the package, the best focus, the focused object and the near and far limits by
Brent's method (scipy), one fan per evaluation, rays started on the first vertex plane. Brent's
method stops at 1e-9 of the depth of field in vergence: as tightly as an answer equal to 1e-7
needs, no tighter. Each package is warmed (one fan traced) before it is timed. The scenes per
lens: ``--rows`` spread from the closest focus to half the hyperfocal distance, at the design
f-number and at f/8 (CoC 0.03 mm; 0.005 mm for the phone lens). Every package answer is
checked against camtool's for the same scene (front and rear depth equal to 1e-7), and only
then is the package's time per near/far pair divided by camtool's ``raytrace_dof`` for the
same scene, cold (its interpolants rebuilt for every call; the tracer of the lens built once,
as the package's model is; best of 5). Times are CPU time of this process (``time.process_time``),
so other jobs on a shared machine do not count against either side.
"""

from __future__ import annotations

import argparse
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

SHIPPED = ROOT / "lens_db" / "prescriptions"
PACKAGES = ("rayoptics", "optiland")
SQRT8 = 2.0 * math.sqrt(2.0)
DEPTH_TOLERANCE = 1e-7


def dense_terms(surface):
    """The polynomial coefficients a_1…a_P of a surface (zeros included), as camtool's tracer uses them."""
    terms = dict(surface.aspheric)
    return [terms.get(p, 0.0) for p in range(1, max(terms, default=0) + 1)]


def optiland_tracer(lens):
    """trace(h0, m, l, upto) through the first ``upto`` lens surfaces with optiland (vectorised over rays)."""
    from optiland.materials import IdealMaterial
    from optiland.optic import Optic
    from optiland.rays import RealRays

    op = Optic()
    op.add_surface(index=0, thickness=np.inf)
    for i, s in enumerate(lens.surfaces):
        material = IdealMaterial(n=s.n) if s.n != 1.0 else "air"
        extra = {"surface_type": "odd_asphere", "coefficients": dense_terms(s)} if s.aspheric else {}
        op.add_surface(index=i + 1, radius=s.radius_mm, thickness=s.thickness_mm, material=material,
                       is_stop=s.stop, conic=s.conic, **extra)
    op.add_surface(index=len(lens.surfaces) + 1)
    op.set_aperture(aperture_type="EPD", value=1.0)
    op.set_field_type(field_type="angle")
    op.add_field(y=0.0)
    op.add_wavelength(value=lens.wavelength_nm / 1000.0, is_primary=True)
    surfaces = op.surface_group.surfaces
    for surface in surfaces:
        if hasattr(surface.geometry, "tol"):  # aspheres: Newton's residual to round-off, as camtool's
            surface.geometry.tol = 1e-13
    wavelength = lens.wavelength_nm / 1000.0

    def sag(i, r):
        return float(np.asarray(surfaces[i + 1].geometry.sag(np.zeros(1), np.array([r])))[0])

    def trace(h0, m, l, upto):
        n = h0.size
        rays = RealRays(np.zeros(n), h0.copy(), np.zeros(n), np.zeros(n), m.copy(), l.copy(), np.ones(n),
                        np.full(n, wavelength))
        for surface in surfaces[1 : upto + 1]:
            surface.trace(rays, record=False)
        return np.asarray(rays.y), np.asarray(rays.z), np.asarray(rays.M), np.asarray(rays.N)

    return trace, sag


def rayoptics_tracer(lens):
    """trace(h0, m, l, upto) with rayoptics (one ray at a time, as its trace function works)."""
    from opticalglass.opticalmedium import ConstantIndex
    from rayoptics.elem.profiles import Conic, RadialPolynomial
    from rayoptics.optical.opticalmodel import OpticalModel
    from rayoptics.raytr import raytrace
    from rayoptics.raytr.opticalspec import WvlSpec

    opm = OpticalModel()
    opm.radius_mode = True
    sm = opm.seq_model
    sm.gaps[0].thi = 1e10  # a distant object for the model's own first-order set-up
    for i, s in enumerate(lens.surfaces):
        sm.add_surface([0.0 if math.isinf(s.radius_mm) else s.radius_mm, s.thickness_mm])
        if s.aspheric:
            sm.ifcs[sm.cur_surface].profile = RadialPolynomial(r=0.0 if math.isinf(s.radius_mm) else s.radius_mm, cc=s.conic,
                                                   coefs=dense_terms(s))
        elif s.conic:
            sm.ifcs[sm.cur_surface].profile = Conic(r=s.radius_mm, cc=s.conic)
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
    first = len(sm.ifcs) - 2 - len(lens.surfaces)  # the object interface comes first, the image last

    def sag(i, r):
        return float(sm.ifcs[first + i + 1].profile.sag(0.0, r))

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

    return trace, sag


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

        depth = n * c / (f * f) * (1.0 + w0 * f)  # paraxial spacing of the limits in vergence
        xtol = 1e-9 * depth  # an answer equal to 1e-7 of the depth, with a margin; no tighter
        w_focus = brentq(mismatch, *self._bracket(mismatch, w0, 0.02 * w0), xtol=xtol, rtol=1e-15)
        z_film = self.summary(w_focus, n)[0]

        def excess(w):
            z, s = self.summary(w, n)
            return SQRT8 * abs(z_film - z) * s - c

        w_near = brentq(excess, *self._bracket(excess, w_focus, depth, upward=True), xtol=xtol, rtol=1e-15)
        far = math.inf
        if excess(0.0) > 0.0:
            w_far = brentq(excess, *self._bracket(excess, w_focus, depth, upward=False), xtol=xtol, rtol=1e-15)
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
        start = time.process_time()
        result = realray.raytrace_dof(lens, n, c, distance)
        best = min(best, time.process_time() - start)
    return result, best


def sag_mismatch(lens, sag) -> float:
    """The largest difference (mm) between the package's sag and camtool's over each aspheric surface's aperture."""
    from camtool.optics.tracer import real_tracer

    worst = 0.0
    fo = first_order(lens)
    reach = fo.efl_mm / 2.0  # beyond any beam the scenes trace
    for i, (mine, surface) in enumerate(zip(real_tracer(lens).surfaces, lens.surfaces)):
        if mine.spherical:
            continue
        limit = surface.semi_diameter_mm or reach
        for r in np.linspace(0.0, limit, 9)[1:]:
            from camtool.optics.tracer import _sag

            ours = float(_sag(mine, np.array([r]))[0][0])
            if math.isfinite(ours):
                worst = max(worst, abs(sag(i, float(r)) - ours))
    return worst


def scenes(lens, count):
    """(N, c, distance from the sensor): ``count`` distances from near the closest focus to H/2, two f-numbers."""
    fo = first_order(lens)
    f = fo.efl_mm
    c = 0.005 if f < 10.0 else 0.03
    out = []
    for n in sorted({float(lens.f_number), 8.0}):
        closest = realray.closest_focus_mm(lens, n)
        far = 0.5 * (f * f / (n * c) + 2.0 * f)
        for d in np.geomspace(closest * 1.3, far, max(count // 2, 1)):
            out.append((n, c, float(d)))
    return out[:count] if count > 1 else out[:1]


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--rows", type=int, default=4, help="scenes per lens (half at the design f-number, half at f/8)")
    args = parser.parse_args()
    warnings.filterwarnings("ignore")  # the packages' deprecation and numba notices
    available = {}
    for package in PACKAGES:
        try:
            __import__(package)
            available[package] = __import__("importlib.metadata").metadata.version(package)
        except ImportError:
            print(f"skipped {package}: not installed (pip install {package} in a throwaway environment)")
    if not available:
        return
    import platform

    print(f"packages: {', '.join(f'{k} {v}' for k, v in available.items())}; numpy {np.__version__}; "
          f"Python {platform.python_version()}; {platform.machine()}")
    print("| lens | package | pairs | package ms (median) | camtool ms (median, cold) | ratio (median) | ratio (min) "
          "| largest depth difference, package against camtool |")
    print("|---|---|---:|---:|---:|---:|---:|---:|")
    ratios_all, cannot = {}, []
    for path in sorted(SHIPPED.glob("*.yaml")):
        name = path.stem
        lens = prescription_from_mapping(yaml.safe_load(path.read_text()), name)
        picked = scenes(lens, args.rows)
        camtool = [camtool_pair(lens, n, c, d) for n, c, d in picked]  # builds the tracer once, then timed cold
        for package in available:
            try:
                trace, sag = optiland_tracer(lens) if package == "optiland" else rayoptics_tracer(lens)
                mismatch = sag_mismatch(lens, sag)
            except Exception as error:  # the package cannot model a surface of the lens
                cannot.append((name, package, f"{type(error).__name__}: {error}"))
                continue
            if not mismatch < 1e-9:
                cannot.append((name, package, f"its aspheric sag differs from the prescription's by {mismatch:.2g} mm"))
                continue
            reference = Reference(lens, trace)
            reference.summary(0.0, picked[0][0])  # warm: the package's lazy imports and caches
            times, differences = [], []
            for (n, c, d), (result, _seconds) in zip(picked, camtool):
                start = time.process_time()
                near, far = reference.dof(n, c, d)
                times.append(time.process_time() - start)
                front, rear = d - near, far - d
                rear_diff = 0.0 if math.isinf(far) and math.isinf(result.rear_mm) else abs(rear / result.rear_mm - 1.0)
                differences.append(max(abs(front / result.front_mm - 1.0), rear_diff))
            assert max(differences) < DEPTH_TOLERANCE, (name, package, differences)  # equal answers, or no figure
            ratios = [p / q for p, q in zip(times, (seconds for _, seconds in camtool))]
            ratios_all.setdefault(package, []).extend(ratios)
            print(f"| {name} | {package} | {len(picked)} | {statistics.median(times) * 1e3:.1f} "
                  f"| {statistics.median(seconds for _, seconds in camtool) * 1e3:.2f} "
                  f"| {statistics.median(ratios):.0f}x | {min(ratios):.0f}x | {max(differences):.1e} |")
    for name, package, why in cannot:
        print(f"\n{name} is not run on {package}: {why}")
    for package, ratios in ratios_all.items():
        print(f"\n{package}, all pairs: median ratio {statistics.median(ratios):.0f}x, smallest {min(ratios):.0f}x "
              "(goal: 100x)")


if __name__ == "__main__":
    main()
