"""The ``raytrace`` rung: depth of field solved on real rays through a prescription.

- **Focus**: the object whose best-focus film plane lies at the focus
  distance behind it; the film then stays put. Near and far limits are the
  object distances where the blur on that film reaches c.
- **How it is solved**: the fan summaries (best focus z_best, RMS slope S,
  best-focus blur B; :mod:`camtool.optics.tracer`) are smooth functions of
  the object's entrance-pupil vergence v = 1/(z_E − z_obj), which runs from
  0 (infinity) to the closest object without a singularity, even to the first
  vertex of a retrofocus lens (w = ∞ there). One batched trace at 17
  Chebyshev–Lobatto nodes on [0, v_closest] gives interpolants of them that
  agree with direct traces to ~1e-13 mm on the shared lenses (z_best after
  the paraxial term z_F′ + f²·v/(1 + v·(z_F − z_E)) is taken out). Focus,
  hyperfocal, near and far limits are roots of these interpolants (a scan,
  then Brent's method). When the interpolants' last Chebyshev coefficients say
  they may be less accurate than 1e-11 f (rays dropped from a fan at a wide
  aperture, say), the roots are polished by Newton steps on direct traces.
  The interpolants are cached per lens and f-number, so every further scene
  at the same f-number costs no ray trace at all.
- **Closest focus**: the object at 1:1 (2f in front of H), or, for a lens
  whose 1:1 object would lie inside it (a retrofocus lens with H far behind
  its first vertex), the object at the first vertex. A near limit that would
  lie closer than the first vertex is reported at the first vertex: nothing
  can be put nearer.
"""


from __future__ import annotations

import itertools
import math
from dataclasses import dataclass
from typing import Any

import numpy as np
from numpy.polynomial import chebyshev as cheb

from camtool.core.arrays import is_scalar
from camtool.core.errors import DomainError, require_positive
from camtool.core.planes import check_plane
from camtool.dof.limits import DofLimits
from camtool.optics.chebyshev import lobatto_matrix
from camtool.optics.prescription import Prescription
from camtool.optics.roots import brent
from camtool.optics.tracer import _SQRT8, CRITERIA, RayTraceError, RealRayTracer, real_tracer

__all__ = ["NoDepthOfField", "RealFocus", "closest_focus_mm", "focus_for_film", "raytrace_dof", "real_focus"]

_DEGREE = 16
_TRUST = 1e-10
"""Largest trusted interpolation error, relative to f (z_best) or to the largest value (S, B²)."""


class NoDepthOfField(DomainError):
    """The blur at focus already reaches the circle of confusion: nothing is acceptably sharp.

    Only the total-blur criterion ``rms`` can raise it; ``blur_at_focus_mm``
    holds the lens's own blur at the focus distance.
    """

    def __init__(self, coc_mm: float, blur_at_focus_mm: float) -> None:
        self.blur_at_focus_mm = blur_at_focus_mm
        super().__init__(
            "coc_mm",
            coc_mm,
            f"> {blur_at_focus_mm:.4g} mm, the lens's own RMS blur at this focus",
            detail="no depth of field: the aberrations alone exceed the circle of confusion",
        )


@dataclass(frozen=True)
class RealFocus:
    """Where a lens focused on a distance puts its object and film, by real rays (mm).

    ``object_z_mm`` the focused object (−inf at infinity) and ``film_z_mm``
    the film (its best focus) in lens coordinates; ``distance_mm`` film →
    object; ``blur_mm`` the criterion's blur of the focused object on its own
    film (0 for ``defocus``); ``magnification`` f/(u − f) with u = z_H − z_obj
    (first order, as in the reference data); ``film_to_entrance_pupil_mm``
    and ``film_to_front_principal_mm`` the offsets to distances from E and H.
    """

    object_z_mm: float
    film_z_mm: float
    distance_mm: float
    blur_mm: float
    magnification: float
    film_to_entrance_pupil_mm: float
    film_to_front_principal_mm: float


class _Curves:
    """z_best, S and B of one lens at one f-number as Chebyshev interpolants in pupil vergence v."""

    def __init__(self, tracer: RealRayTracer, f_number: float, traced: Any = None) -> None:
        self.tracer, self.f_number = tracer, f_number
        self.trusted = self.rms_trusted = False
        self.tails: tuple[float, float, float] = (math.inf, math.inf, math.inf)
        fo = self.fo = tracer.first
        f, z_e = fo.efl_mm, fo.z_e_mm
        z_close = min(fo.z_h_mm - 2.0 * f, 0.0)
        if not z_e - z_close > 0.0:
            raise RayTraceError(f"{tracer._name()}: the entrance pupil lies in front of the closest object")
        self.at_vertex = z_close == 0.0
        self.v_front = 1.0 / z_e if z_e > 0.0 else math.inf  # the object at the first vertex
        v_cap = 1.0 / (z_e - z_close)
        for attempt in range(4):
            nodes = _nodes(v_cap)
            summary, ok = traced if attempt == 0 and traced is not None else tracer.summarise(nodes, f_number)
            if np.all(ok):
                break
            if not ok[0]:
                raise tracer.failure(f_number, summary, ok)
            v_cap = float(nodes[int(np.argmin(ok))]) * 0.5  # rays fail at close range: keep to where they pass
            self.at_vertex = False
        else:
            raise tracer.failure(f_number, summary, ok)
        self.v_cap = v_cap
        self._pole = fo.z_f_mm - z_e
        self._full = v_cap == 1.0 / (z_e - z_close)  # the whole range traced (no rays failed at close range)
        self._nodes, self._summary = nodes, summary
        self._fit(nodes, summary)
        if not self.trusted:
            self.refine()

    def refine(self) -> None:
        """Double the degree once (the 2n-point nodes are the n-point ones and their midpoints).

        The new nodes' edge rays start from the first interpolant's aim heights: one Newton step
        then meets the edge-ray search's tolerance, where the paraxial start takes three.
        """
        nodes, summary = self._nodes, self._summary
        degree = nodes.size - 1
        if degree != _DEGREE or not self._full:
            return
        odd = self.v_cap * (1.0 - np.cos(np.pi * np.arange(1, 2 * degree, 2) / (2 * degree))) / 2.0
        guess = cheb.chebval(2.0 * odd / self.v_cap - 1.0, self.coef_aim)  # the edge rays' aims, to ~1e-10
        more, ok = self.tracer.summarise(odd, self.f_number, guess)
        if not np.all(ok):
            return
        merged = np.empty(2 * degree + 1)
        merged[0::2], merged[1::2] = nodes, odd
        both = {name: np.empty(2 * degree + 1) for name in ("z_best", "slope_rms", "best_blur", "edge_mm", "aim_mm")}
        for name, array in both.items():
            array[0::2], array[1::2] = getattr(summary, name), getattr(more, name)
        self._nodes, self._summary = merged, type(summary)(**both)
        self._fit(self._nodes, self._summary)

    def trusts(self, criterion: str) -> bool:
        """Whether the interpolants are good enough for ``criterion`` (refining them once if not)."""
        if not self.trusted or (criterion == "rms" and not self.rms_trusted):
            self.refine()
        return self._full and self.trusted and (criterion != "rms" or self.rms_trusted)

    def _fit(self, nodes: np.ndarray, summary: Any) -> None:
        """Chebyshev interpolants through the traced nodes, and whether to trust them."""
        matrix = lobatto_matrix(nodes.size - 1)
        values = np.stack([summary.z_best - self._base(nodes), summary.slope_rms, summary.best_blur**2, summary.aim_mm])
        self.coef_z, self.coef_s, self.coef_b2, self.coef_aim = values @ matrix.T
        self._stacked = np.stack([self.coef_z, self.coef_s, self.coef_b2])
        self._scans: dict[tuple[float, float], tuple[np.ndarray, ...]] = {}
        self._lists = [c.tolist() for c in (self.coef_z, self.coef_s, self.coef_b2)]
        self._reversed = list(zip(*(reversed(c[1:]) for c in self._lists)))
        self._reversed_z = self._lists[0][:0:-1]
        self._reversed_zs = list(zip(self._reversed_z, self._lists[1][:0:-1]))
        self._first = (self._lists[0][0], self._lists[1][0], self._lists[2][0])
        self.at_zero = (float(summary.z_best[0]), float(summary.slope_rms[0]), float(summary.best_blur[0]))

        def tail(c: np.ndarray) -> float:
            # error of the interpolant ≈ twice the coefficients left out; they fall geometrically by
            # about ρ = |c_n/c_(n−1)| (analytic functions), so ≈ 2·|c_n|·ρ/(1 − ρ); no clear decay: 8·|c_n|
            last, before = abs(float(c[-1])), abs(float(c[-2]))
            ratio = last / before if before > 0.0 else 1.0
            return 2.0 * last * min(ratio / (1.0 - ratio), 4.0) if ratio < 0.8 else 8.0 * last

        f = self.fo.efl_mm
        self.tails = (tail(self.coef_z) / f, tail(self.coef_s) / float(np.max(summary.slope_rms)),
                      tail(self.coef_b2) / float(np.max(summary.best_blur**2) + 1e-30))
        self.trusted = max(self.tails[:2]) <= _TRUST  # z_best and S: every criterion
        self.rms_trusted = self.tails[2] <= _TRUST  # B², for the total-blur criterion only

    def _base(self, v: Any) -> Any:
        """Paraxial image position z_F′ + f²·v/(1 + v·(z_F − z_E)) (Newton's x·x′ = −f²)."""
        f = self.fo.efl_mm
        return self.fo.z_f_prime_mm + f * f * v / (1.0 + v * self._pole)

    def curves(self, v: Any) -> tuple[Any, Any, Any]:
        """Interpolated (z_best, S, B) at pupil vergences v (array).

        The polynomials T_k(x) by their recurrence T_(k+1) = 2x·T_k − T_(k−1), then one matrix product
        for the three curves: a quarter of the time of numpy's ``chebval`` on the stacked coefficients
        (whose Clenshaw steps broadcast each coefficient over the points); the values agree to round-off
        (~1e-14 mm here, where they only locate sign changes).
        """
        x = 2.0 * np.asarray(v, float) / self.v_cap - 1.0
        powers = np.empty((self._stacked.shape[1], x.size))
        rows = list(powers)
        rows[0][...] = 1.0
        rows[1][...] = x
        x2 = 2.0 * x
        for k in range(2, len(rows)):
            np.multiply(x2, rows[k - 1], rows[k])
            np.subtract(rows[k], rows[k - 2], rows[k])
        z, s, b2 = self._stacked @ powers
        return z + self._base(v), s, np.sqrt(np.maximum(b2, 0.0))

    def scan(self, v_from: float, v_to: float, also: tuple[float, float] | None = None) -> tuple[np.ndarray, ...]:
        """(v, z_best, S, B) on the scan grid from v_from towards v_to (see :func:`_first_crossing`).

        ``also``: the ends of another grid to evaluate in the same pass and keep for a later call (the
        near and far searches start from the same focus; the focus and hyperfocal searches share a grid).
        """
        found = self._scans.get((v_from, v_to))
        if found is not None:
            return found
        if len(self._scans) >= 8:
            self._scans.clear()
        pairs = [(v_from, v_to)] + ([also] if also is not None and also not in self._scans else [])
        vs = np.concatenate([a + (b - a) * _SCAN_STEPS for a, b in pairs])
        z, s, b = self.curves(vs)
        size = _SCAN_STEPS.size
        for k, pair in enumerate(pairs):
            part = slice(k * size, (k + 1) * size)
            self._scans[pair] = (vs[part], z[part], s[part], b[part])
        return self._scans[(v_from, v_to)]

    def curve(self, v: float) -> tuple[float, float, float]:
        """Interpolated (z_best, S, B) at one pupil vergence (plain floats).

        Σ c_k T_k(x) by Clenshaw's recurrence (b_k = 2x·b_{k+1} − b_{k+2} + c_k, the sum x·b_1 − b_2 + c_0),
        the three curves' recurrences side by side in one loop (a third of three loops' overhead).
        """
        x = 2.0 * v / self.v_cap - 1.0
        x2 = 2.0 * x
        z1 = z2 = s1 = s2 = b1 = b2 = 0.0
        for cz, cs, cb in self._reversed:
            z1, z2 = x2 * z1 - z2 + cz, z1
            s1, s2 = x2 * s1 - s2 + cs, s1
            b1, b2 = x2 * b1 - b2 + cb, b1
        z0, s0, b0 = self._first
        z = x * z1 - z2 + z0
        s = x * s1 - s2 + s0
        b2_value = x * b1 - b2 + b0
        return z + self._base(v), s, math.sqrt(max(b2_value, 0.0))

    def curve_z(self, v: float) -> float:
        """Interpolated z_best at one pupil vergence (the first value of :meth:`curve`, alone)."""
        x = 2.0 * v / self.v_cap - 1.0
        x2 = 2.0 * x
        z1 = z2 = 0.0
        for cz in self._reversed_z:
            z1, z2 = x2 * z1 - z2 + cz, z1
        return x * z1 - z2 + self._first[0] + self._base(v)

    def curve_zs(self, v: float) -> tuple[float, float]:
        """Interpolated (z_best, S) at one pupil vergence (the first two values of :meth:`curve`)."""
        x = 2.0 * v / self.v_cap - 1.0
        x2 = 2.0 * x
        z1 = z2 = s1 = s2 = 0.0
        for cz, cs in self._reversed_zs:
            z1, z2 = x2 * z1 - z2 + cz, z1
            s1, s2 = x2 * s1 - s2 + cs, s1
        return x * z1 - z2 + self._first[0] + self._base(v), x * s1 - s2 + self._first[1]

    def exact(self, v: list[float]) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """(z_best, S, B) by direct traces at pupil vergences v (aims started from the interpolant)."""
        vs = np.asarray(v, float)
        guess = cheb.chebval(2.0 * vs / self.v_cap - 1.0, self.coef_aim)
        guess = np.where(vs <= self.v_cap, guess, self.fo.efl_mm / (2.0 * self.f_number))  # no extrapolation
        summary, ok = self.tracer.summarise(vs, self.f_number, guess)
        if not np.all(ok):
            raise self.tracer.failure(self.f_number, summary, ok)
        return summary.z_best, summary.slope_rms, summary.best_blur


def _nodes(v_cap: float) -> np.ndarray:
    """The Chebyshev–Lobatto nodes of degree _DEGREE on [0, v_cap]."""
    return v_cap * (1.0 - np.cos(np.pi * np.arange(_DEGREE + 1) / _DEGREE)) / 2.0


class _CurvesCache:
    """Interpolants per (prescription, f-number), the most recent 256; several f-numbers are built in one trace."""

    def __init__(self) -> None:
        # keyed by the prescription's identity (held in the entry, so its id is not reused while stored):
        # hashing a prescription, its every surface, costs about as much as a Brent search
        self._store: dict[tuple[int, float], tuple[Prescription, _Curves]] = {}

    def _get(self, prescription: Prescription, f_number: float) -> _Curves | None:
        entry = self._store.get((id(prescription), f_number))
        return entry[1] if entry is not None and entry[0] is prescription else None

    def __call__(self, prescription: Prescription, f_number: float) -> _Curves:
        curves = self._get(prescription, f_number)
        if curves is None:
            curves = _Curves(real_tracer(prescription), f_number)
            self._keep(prescription, f_number, curves)
        return curves

    def prepare(self, prescription: Prescription, f_numbers: Any) -> None:
        """Build the missing interpolants of many f-numbers, up to 16 per batched trace (a batch or grid)."""
        missing = sorted({float(n) for n in f_numbers if self._get(prescription, float(n)) is None})
        if len(missing) < 2:
            return
        tracer = real_tracer(prescription)
        fo = tracer.first
        z_close = min(fo.z_h_mm - 2.0 * fo.efl_mm, 0.0)
        if not fo.z_e_mm - z_close > 0.0:
            return
        nodes = _nodes(1.0 / (fo.z_e_mm - z_close))
        for start in range(0, len(missing), 16):
            chunk = missing[start : start + 16]
            summary, ok = tracer.summarise(np.tile(nodes, len(chunk)), np.repeat(chunk, nodes.size))
            for i, n in enumerate(chunk):
                part = slice(i * nodes.size, (i + 1) * nodes.size)
                fields = (summary.z_best, summary.slope_rms, summary.best_blur, summary.edge_mm, summary.aim_mm)
                traced = (type(summary)(*(field[part] for field in fields)), ok[part])
                self._keep(prescription, n, _Curves(tracer, n, traced))

    def _keep(self, prescription: Prescription, f_number: float, curves: _Curves) -> None:
        if len(self._store) >= 256:
            del self._store[next(iter(self._store))]
        self._store[(id(prescription), f_number)] = (prescription, curves)

    def cache_clear(self) -> None:
        """Forget every interpolant."""
        self._store.clear()


_curves = _CurvesCache()


_SCAN_STEPS = np.concatenate([[0.0], np.geomspace(1e-12, 1.0, 240)])
"""Where :func:`_first_crossing` looks between its ends (fractions of the way; made once, not per call)."""
_SCAN_STEPS.flags.writeable = False
_BRACKET_STEPS = np.concatenate([[0.0], np.geomspace(1e-10, 1.0, 48)])
_BRACKET_STEPS.flags.writeable = False


def _first_crossing(
    curves: _Curves,
    value: Any,
    v_from: float,
    v_to: float,
    scalar: Any = None,
    also: tuple[float, float] | None = None,
) -> float | None:
    """First root of ``value(z, S, B, v)`` going from v_from towards v_to on the interpolants (None: none).

    ``scalar(v)``: the same value at one vergence as a float, computed from only the curves it needs
    (default: ``value`` on :meth:`_Curves.curve`); ``also``: another scan's ends, see :meth:`_Curves.scan`.
    """
    vs, z, s, b = curves.scan(v_from, v_to, also)
    values = value(z, s, b, vs)
    positive = values > 0.0
    change = np.nonzero(positive[1:] != positive[:-1])[0]
    if change.size == 0:
        return None
    i = int(change[0])
    if values[i] == 0.0:
        return float(vs[i])
    if scalar is None:
        scalar = lambda v: float(value(*curves.curve(v), v))  # noqa: E731
    low, high = float(vs[i]), float(vs[i + 1])
    f_low, f_high = scalar(low), scalar(high)
    if (f_low > 0.0) == (f_high > 0.0) and f_low != 0.0 and f_high != 0.0:
        # the scan's sums and the scalar ones differ by round-off: the root lies on a grid point (a focus
        # at the closest distance, say), the end where the value is nearer zero
        return low if abs(f_low) <= abs(f_high) else high
    return brent(scalar, low, high, fa=f_low, fb=f_high)


def _check_scene(
    prescription: Prescription, f_number: float, distance_mm: float, distance_from: str, criterion: str
) -> None:
    """Validate the scalar inputs of the real-ray functions."""
    check_plane(distance_from)
    if criterion not in CRITERIA:
        raise ValueError(f"criterion must be one of {', '.join(CRITERIA)}, not {criterion!r}")
    require_positive("f_number", f_number, unit="")
    require_positive("distance_mm", distance_mm, allow_inf=True)
    if prescription.object_index != 1.0 or prescription.image_index != 1.0:
        raise ValueError("the real-ray depth of field needs object and image space in air (n = 1)")


def _closest(curves: _Curves, distance_from: str) -> float:
    """Closest focus distance in mm from ``distance_from`` (the object at v_cap)."""
    fo, v = curves.fo, curves.v_cap
    z_obj = fo.z_e_mm - 1.0 / v
    z_ref = {"sensor": curves.curve(v)[0], "lens": fo.z_h_mm, "entrance_pupil": fo.z_e_mm}[distance_from]
    return z_ref - z_obj


def closest_focus_mm(prescription: Prescription, f_number: float, distance_from: str = "sensor") -> float:
    """Closest focus distance of a prescription by real rays, in mm from ``distance_from``.

    The object at 1:1 (2f in front of the front principal plane H), or at the
    first vertex when the 1:1 object would lie inside the lens (a retrofocus
    lens whose H lies more than 2f behind its front vertex), with the film at
    its real best focus.

    Parameters
    ----------
    prescription : Prescription
    f_number : float
        Nominal N > 0.
    distance_from : ``"sensor"``, ``"lens"`` or ``"entrance_pupil"``

    Examples
    --------
    >>> from camtool.optics.prescription import EXAMPLE_SINGLET, prescription_from_mapping
    >>> lens = prescription_from_mapping(EXAMPLE_SINGLET)
    >>> round(closest_focus_mm(lens, 8.0, "lens"), 6)  # 2f
    200.0
    """
    _check_scene(prescription, f_number, 1.0, distance_from, "defocus")
    return _closest(_curves(prescription, float(f_number)), distance_from)


def _focus_vergence(curves: _Curves, distance_mm: float, distance_from: str) -> float:
    """Pupil vergence of the focused object."""
    fo = curves.fo
    if math.isinf(distance_mm):
        return 0.0
    closest = _closest(curves, distance_from)
    if distance_mm < closest * (1.0 - 1e-12):
        where = {"sensor": "the sensor", "lens": "the lens", "entrance_pupil": "the entrance pupil"}[distance_from]
        raise DomainError("distance_mm", distance_mm, f"at least {{limit}} from {where} (the closest focus)", limit=closest)
    if distance_from == "sensor":

        def mismatch(z: Any, s: Any, b: Any, v: Any) -> Any:
            return v * (z - fo.z_e_mm - distance_mm) + 1.0  # zero where z_best − z_obj = D

        found = _first_crossing(curves, mismatch, 0.0, curves.v_cap, lambda v: mismatch(curves.curve_z(v), 0.0, 0.0, v))
        return curves.v_cap if found is None else found
    z_ref = fo.z_h_mm if distance_from == "lens" else fo.z_e_mm
    return min(1.0 / (fo.z_e_mm - (z_ref - distance_mm)), curves.v_cap)


class _Problem:
    """One scene on the interpolants: focus, hyperfocal, near and far pupil vergences."""

    def __init__(self, curves: _Curves, coc_mm: float, criterion: str, v_focus: float, distance_mm: float) -> None:
        self.curves, self.coc, self.criterion = curves, coc_mm, criterion
        self.distance_mm = distance_mm
        self.v_focus = v_focus
        self.free_focus = False  # the focus is a root of the sensor-plane distance (polished too)

    def blur(self, z: Any, s: Any, b: Any, z_film: float) -> Any:
        """The criterion's blur diameter (mm) on a film at z_film."""
        defocus = _SQRT8 * np.abs(z_film - z) * s
        return defocus if self.criterion == "defocus" else np.hypot(defocus, b)

    def hyperfocal_film(self) -> float | None:
        """Film position that puts an object at infinity exactly at c (None: never within c)."""
        z0, s0, b0 = self.curves.at_zero
        allowance = self.coc if self.criterion == "defocus" else self.coc * self.coc - b0 * b0
        if allowance <= 0.0:
            return None
        if self.criterion == "rms":
            allowance = math.sqrt(allowance)
        return z0 + allowance / (_SQRT8 * s0)

    def hyperfocal(self) -> float | None:
        """Pupil vergence of the hyperfocal object (None: no focus keeps infinity sharp; v_cap: all do)."""
        z_film = self.hyperfocal_film()
        if z_film is None:
            return None
        curves = self.curves
        found = _first_crossing(curves, lambda z, s, b, v: z - z_film, 0.0, curves.v_cap, lambda v: curves.curve_z(v) - z_film)
        return self.curves.v_cap if found is None else found

    def limits(self, z_film: float) -> tuple[float, float]:
        """Near and far pupil vergences on a film at z_film (far 0: infinity is within c)."""
        coc = self.coc

        def excess(z: Any, s: Any, b: Any, v: Any) -> Any:
            return self.blur(z, s, b, z_film) - coc

        def scalar(v: float) -> float:
            if self.criterion != "defocus":
                return float(excess(*curves.curve(v), v))
            z, s = curves.curve_zs(v)
            return _SQRT8 * abs(z_film - z) * s - coc  # as blur(), on floats

        curves = self.curves
        near = _first_crossing(curves, excess, self.v_focus, curves.v_cap, scalar, also=(self.v_focus, 0.0))
        if near is None:
            # at the first vertex nothing can be put closer; short of the front focal point, trace on
            near = curves.v_cap if curves.at_vertex else self._near_beyond(z_film)
        far = 0.0
        if excess(*curves.curve(0.0), 0.0) > 0.0:
            found = _first_crossing(curves, excess, self.v_focus, 0.0, scalar)
            far = 0.0 if found is None else found
        return near, far

    def _near_beyond(self, z_film: float) -> float:
        """Near limit closer than the 1:1 object, by direct traces towards the front focal point.

        Objects stay in front of the first vertex: when the blur there is
        still below c, the near limit is the first vertex.
        """
        curves = self.curves
        fo = curves.fo
        gap = fo.z_e_mm - fo.z_f_mm  # 1/v of an object at the front focal point F
        v_pole = 1.0 / gap if gap > 0.0 else 4.0 * curves.v_cap
        v_front = curves.v_front
        end = min(v_pole, v_front)
        factors = (0.05, 0.15, 0.3, 0.5, 0.7, 0.85, 0.95) + ((1.0,) if end == v_front else ())
        candidates = [curves.v_cap + (end - curves.v_cap) * q for q in factors]

        def excess(v: float) -> float:
            z, s, b = curves.exact([v])
            return float(self.blur(z[0], s[0], b[0], z_film)) - self.coc

        z, s, b = curves.exact(candidates)
        values = [float(self.blur(*point, z_film)) - self.coc for point in zip(z, s, b)]
        low = curves.v_cap
        for v, value in zip(candidates, values):
            if value > 0.0:
                return brent(excess, low, v, 1e-14 * v)
            low = v
        if end == v_front:
            return v_front  # nothing can be put closer than the first vertex
        raise RayTraceError(f"{curves.tracer._name()}: no near limit in front of the front focal point")


def _polish(problem: _Problem, roots: list[float]) -> tuple[float, float, list[float]]:
    """Newton steps on direct traces (slopes from the interpolants) until the roots stop moving.

    ``roots`` are [hyperfocal, near, far] pupil vergences (NaN: none; 0 or
    v_cap and beyond: nothing to polish); returns the focus vergence, its
    film position and the polished roots.
    """
    curves = problem.curves
    fo = curves.fo
    v_focus = problem.v_focus
    z_film_h = problem.hyperfocal_film()
    h = 1e-7 * curves.v_cap

    def slope(function: Any, v: float) -> float:
        return (function(*curves.curve(v + h), v + h) - function(*curves.curve(v - h), v - h)) / (2.0 * h)

    def mismatch(z: float, s: float, b: float, v: float) -> float:
        return v * (z - fo.z_e_mm - problem.distance_mm) + 1.0  # zero where z_best − z_obj = D

    for _ in range(12):
        inside = [i for i, r in enumerate(roots) if 0.0 < r < curves.v_cap]
        z, s, b = curves.exact([v_focus] + [roots[i] for i in inside])
        z_film = float(z[0])
        moved = 0.0
        if problem.free_focus:
            step = mismatch(z_film, 0.0, 0.0, v_focus) / slope(mismatch, v_focus)
            z_film -= step * slope(lambda z, s, b, v: z, v_focus)
            v_focus -= step
            moved = abs(step)
        def excess(z: float, s: float, b: float, v: float, film: float = z_film) -> float:
            return float(problem.blur(z, s, b, film)) - problem.coc

        def behind(z: float, s: float, b: float, v: float) -> float:
            return z - (z_film_h if z_film_h is not None else 0.0)

        roots = list(roots)
        for k, i in enumerate(inside, start=1):
            function = behind if i == 0 else excess
            step = function(float(z[k]), float(s[k]), float(b[k]), roots[i]) / slope(function, roots[i])
            roots[i] -= step
            moved = max(moved, abs(step))
        if moved <= 1e-14 * curves.v_cap:
            return v_focus, z_film, roots
    return _bracketed(problem, roots)


def _bracketed(problem: _Problem, roots: list[float]) -> tuple[float, float, list[float]]:
    """Every root from direct traces alone: a batched scan for the first sign change, then Brent's method.

    The slow, safe path (when Newton steps from the interpolants do not
    settle) for fans whose summaries are not smooth: rays dropped at an
    aperture wider than the lens was designed for make z_best jump.
    ``roots`` only says which roots exist.
    """
    curves = problem.curves
    fo = curves.fo
    steps = _BRACKET_STEPS

    def exact(v: float) -> tuple[float, float, float]:
        z, s, b = curves.exact([v])
        return float(z[0]), float(s[0]), float(b[0])

    def first_root(value: Any, v_from: float, v_to: float) -> float | None:
        vs = v_from + (v_to - v_from) * steps
        z, s, b = curves.exact(vs.tolist())
        values = [value(*point) for point in zip(z.tolist(), s.tolist(), b.tolist(), vs.tolist())]
        for (va, fa), (vb, fb) in itertools.pairwise(zip(vs.tolist(), values)):
            if fa == 0.0:
                return va
            if (fa > 0.0) != (fb > 0.0):
                low, high = min(va, vb), max(va, vb)
                return brent(lambda v: value(*exact(v), v), low, high, 1e-15 * high)
        return None

    v_focus = problem.v_focus
    if problem.free_focus:
        d = problem.distance_mm
        found = first_root(lambda z, s, b, v: v * (z - fo.z_e_mm - d) + 1.0, 0.0, curves.v_cap)
        v_focus = curves.v_cap if found is None else found
    z_film = exact(v_focus)[0]
    roots = list(roots)
    z_film_h = problem.hyperfocal_film()
    if roots and math.isfinite(roots[0]) and z_film_h is not None:
        found = first_root(lambda z, s, b, v: z - z_film_h, 0.0, curves.v_cap)
        roots[0] = curves.v_cap if found is None else found

    def excess(z: float, s: float, b: float, v: float) -> float:
        return float(problem.blur(z, s, b, z_film)) - problem.coc

    if len(roots) > 1:
        found = first_root(excess, v_focus, curves.v_cap)
        if found is None:
            found = curves.v_cap if curves.at_vertex else problem._near_beyond(z_film)
        roots[1] = found
    if len(roots) > 2:
        found = first_root(excess, v_focus, 0.0) if excess(*exact(0.0), 0.0) > 0.0 else None
        roots[2] = 0.0 if found is None else found
    return v_focus, z_film, roots


def _object_z(curves: _Curves, v: float) -> float:
    """Lens coordinate of the object at pupil vergence v (−inf at infinity, 0 at the first vertex)."""
    if v == 0.0:
        return -math.inf
    if v == curves.v_front:
        return 0.0
    return curves.fo.z_e_mm - 1.0 / v


def _solve(curves: _Curves, distance_mm: float, distance_from: str, coc_mm: float, criterion: str) -> Any:
    """Focus, film, hyperfocal, near and far of one scene (pupil vergences; film z in mm)."""
    trusted = curves.trusts(criterion)
    v_focus = _focus_vergence(curves, distance_mm, distance_from)
    problem = _Problem(curves, coc_mm, criterion, v_focus, distance_mm)
    problem.free_focus = distance_from == "sensor" and v_focus > 0.0
    z_film, _, own = curves.curve(v_focus)
    if criterion == "rms":
        own = own if trusted else float(curves.exact([v_focus])[2][0])
        if own >= coc_mm:
            raise NoDepthOfField(coc_mm, own)
    hyper = problem.hyperfocal()
    near, far = problem.limits(z_film)
    if not trusted:
        roots = [math.nan if hyper is None else hyper, near, far]
        v_focus, z_film, roots = _polish(problem, roots)
        problem.v_focus = v_focus
        hyper = None if hyper is None else roots[0]
        near, far = roots[1], roots[2]
    return problem, v_focus, z_film, hyper, near, far


def real_focus(
    prescription: Prescription,
    f_number: float,
    distance_mm: float,
    distance_from: str = "sensor",
    criterion: str = "defocus",
) -> RealFocus:
    """Focused object and film position of a prescription by real rays, in mm.

    From the sensor, the object is the one whose best-focus (minimum-RMS)
    plane lies ``distance_mm`` behind it; from the lens (front principal
    plane H) or the entrance pupil the object position is given directly.

    Parameters
    ----------
    prescription : Prescription
        Object and image space in air.
    f_number : float
        Nominal N > 0; fixes the stop radius r_stop = f/(2·N·m_E).
    distance_mm : float
        Focus distance > 0 (``inf`` allowed) from ``distance_from``
        (``"sensor"``, ``"lens"`` or ``"entrance_pupil"``), no closer than
        :func:`closest_focus_mm`.
    distance_from : str
    criterion : ``"defocus"`` or ``"rms"``
        Which blur ``blur_mm`` reports (the focus is the same).

    Returns
    -------
    RealFocus

    Raises
    ------
    DomainError
        N ≤ 0, a distance ≤ 0, NaN, or closer than the lens can focus.
    RayTraceError
        The rays do not get through the lens.

    References
    ----------
    Focus definition of the reference data (oracle-README.md, "Limits").

    Examples
    --------
    >>> from camtool.optics.prescription import EXAMPLE_SINGLET, prescription_from_mapping
    >>> lens = prescription_from_mapping(EXAMPLE_SINGLET)
    >>> focus = real_focus(lens, 8.0, 1000.0)
    >>> round(focus.film_z_mm, 3), round(focus.magnification, 4)
    (114.016, 0.1272)
    """
    _check_scene(prescription, f_number, distance_mm, distance_from, criterion)
    curves = _curves(prescription, float(f_number))
    trusted = curves.trusts("defocus")  # the focus needs z_best alone
    v = _focus_vergence(curves, float(distance_mm), distance_from)
    if not trusted and distance_from == "sensor" and v > 0.0:
        problem = _Problem(curves, 1.0, criterion, v, float(distance_mm))
        problem.free_focus = True
        v, _, _ = _polish(problem, [])
    z, _, b = curves.exact([v])
    return _real_focus(curves, v, float(z[0]), float(b[0]) if criterion == "rms" else 0.0)


def focus_for_film(prescription: Prescription, f_number: float, film_z_mm: float) -> RealFocus | None:
    """The focus that puts the film at ``film_z_mm`` (lens coordinates): the object whose real best focus lies there.

    None when no object between infinity and the closest focus has its best
    focus there. The inverse of :func:`real_focus` (same definitions).

    Examples
    --------
    >>> from camtool.optics.prescription import EXAMPLE_SINGLET, prescription_from_mapping
    >>> lens = prescription_from_mapping(EXAMPLE_SINGLET)
    >>> focus = real_focus(lens, 8.0, 1000.0)
    >>> round(focus_for_film(lens, 8.0, focus.film_z_mm).distance_mm, 6)
    1000.0
    """
    curves = _curves(prescription, float(f_number))

    def behind(z: Any, s: Any, b: Any, v: Any) -> Any:
        return z - film_z_mm

    found = _first_crossing(curves, behind, 0.0, curves.v_cap)
    if found is None:
        return None
    if not curves.trusts("defocus"):
        found = brent(lambda v: float(curves.exact([v])[0][0]) - film_z_mm, 0.0, curves.v_cap)
    z, _, _ = curves.exact([found])
    return _real_focus(curves, found, float(z[0]), 0.0)


def _real_focus(curves: _Curves, v: float, z_film: float, blur: float) -> RealFocus:
    """Assemble the RealFocus of the object at pupil vergence v."""
    fo = curves.fo
    z_obj = _object_z(curves, v)
    f = fo.efl_mm
    magnification = 0.0 if v == 0.0 else f / (fo.z_h_mm - z_obj - f)  # f/(u − f), u = z_H − z_obj
    return RealFocus(
        object_z_mm=z_obj,
        film_z_mm=z_film,
        distance_mm=z_film - z_obj,
        blur_mm=blur,
        magnification=magnification,
        film_to_entrance_pupil_mm=z_film - fo.z_e_mm,
        film_to_front_principal_mm=z_film - fo.z_h_mm,
    )


def raytrace_dof(
    prescription: Prescription,
    f_number: Any,
    coc_mm: Any,
    distance_mm: Any,
    distance_from: str = "sensor",
    criterion: str = "defocus",
) -> DofLimits:
    """Depth of field of a prescription by real rays, in mm (the ``raytrace`` model).

    The lens (fixed stop for the nominal N, unit focusing) is focused on
    ``distance_mm`` with the film at the focused object's best focus; the
    near and far limits are the object distances where the blur on that film
    reaches c:

        defocus:  2√2·|z_film − z_best(z_obj)|·√(Σ w·t²) = c
        rms:      2√2·√(Σ w·(a + t·z_film)²) = c

    found on interpolants of the fan summaries in entrance-pupil vergence
    (see the module docstring). far = ∞ when an object at infinity is still
    within c. The hyperfocal distance is the focus whose far limit is at
    infinity (the closest focus when every focus keeps infinity sharp).

    Parameters
    ----------
    prescription : Prescription
        Object and image space in air; spherical, conic and polynomial
        aspheric surfaces.
    f_number : float or array
        Nominal N > 0.
    coc_mm : float or array
        Circle of confusion c > 0 (blur diameter on the film).
    distance_mm : float or array
        Focus distance > 0 (``inf`` allowed) from ``distance_from``:
        ``"sensor"`` (the film plane), ``"lens"`` (the paraxial front
        principal plane H) or ``"entrance_pupil"`` (the paraxial E); no
        closer than :func:`closest_focus_mm`.
    distance_from : str
    criterion : ``"defocus"`` (default) or ``"rms"``

    Returns
    -------
    DofLimits
        In the plane of ``distance_mm``; arrays for array input. A near
        limit that would lie inside a retrofocus lens is its first vertex.

    Raises
    ------
    NoDepthOfField
        ``rms`` only: the lens's own blur at the focus already reaches c.
    DomainError
        N, c or the distance ≤ 0 or NaN; a focus closer than possible.
    RayTraceError
        The rays do not get through the lens.

    References
    ----------
    Snell's law in vector form: W. J. Smith, *Modern Optical Engineering*,
    4th ed., §10.5; the definitions of the reference data
    (oracle-README.md); R. P. Brent, *Algorithms for Minimization without
    Derivatives* (1973); L. N. Trefethen, *Approximation Theory and
    Approximation Practice* (SIAM, 2013), ch. 2–8 (Chebyshev interpolation).

    Examples
    --------
    >>> from camtool.optics.prescription import EXAMPLE_SINGLET, prescription_from_mapping
    >>> lens = prescription_from_mapping(EXAMPLE_SINGLET)
    >>> r = raytrace_dof(lens, 8.0, 0.03, 3000.0)
    >>> round(r.near_mm, 1), round(r.far_mm, 1)
    (2817.2, 3209.2)
    """
    if not all(is_scalar(v) for v in (f_number, coc_mm, distance_mm)):
        return _raytrace_many(prescription, f_number, coc_mm, distance_mm, distance_from, criterion)
    _check_scene(prescription, f_number, distance_mm, distance_from, criterion)
    require_positive("coc_mm", coc_mm)
    curves = _curves(prescription, float(f_number))
    fo = curves.fo
    coc, focus_mm = float(coc_mm), float(distance_mm)
    _, v_focus, z_film, hyper, v_near, v_far = _solve(curves, focus_mm, distance_from, coc, criterion)
    focus = _real_focus(curves, v_focus, z_film, 0.0)
    z_ref = {"sensor": z_film, "lens": fo.z_h_mm, "entrance_pupil": fo.z_e_mm}[distance_from]
    near, far, front, rear = limits_from_vergences(z_ref, _object_z(curves, v_near), focus.object_z_mm, focus_mm,
                                                   v_focus, v_far)
    hyperfocal = _hyperfocal_distance(curves, hyper, distance_from)
    return DofLimits(near, far, front, rear, front + rear, hyperfocal, focus.magnification)


def limits_from_vergences(z_ref: float, z_near: float, object_z: float, distance_mm: float, v_focus: float,
                          v_far: float) -> tuple[float, float, float, float]:
    """(near, far, front, rear) in mm of a focus ``distance_mm`` from the plane at ``z_ref``, its object at
    ``object_z``: the near limit's object at ``z_near``, the far limit at the vergence ``v_far`` and the focus at
    ``v_focus`` (vergences from the entrance pupil, 1/mm; 0 is infinity)."""
    if v_focus == 0.0:
        front = math.inf
        near = z_ref - z_near
    else:
        front = z_near - object_z
        near = distance_mm - front
    rear = math.inf if v_far == 0.0 else (1.0 / v_far - 1.0 / v_focus)
    return near, distance_mm + rear, front, rear


def _hyperfocal_distance(curves: _Curves, hyper: float | None, distance_from: str) -> float:
    """Hyperfocal distance in the requested plane from the hyperfocal object's pupil vergence."""
    if hyper is None:
        return math.inf  # infinity is never within c
    fo = curves.fo
    z_obj = _object_z(curves, hyper)
    z_ref = {"sensor": curves.curve(hyper)[0], "lens": fo.z_h_mm, "entrance_pupil": fo.z_e_mm}[distance_from]
    return z_ref - z_obj


def _raytrace_many(
    prescription: Prescription, f_number: Any, coc_mm: Any, distance_mm: Any, distance_from: str, criterion: str
) -> DofLimits:
    """Element-wise :func:`raytrace_dof` over broadcast arrays (the interpolants are shared per f-number)."""
    n, c, d = np.broadcast_arrays(*(np.asarray(v, float) for v in (f_number, coc_mm, distance_mm)))
    valid = n[np.isfinite(n) & (n > 0.0)]
    if valid.size and prescription.object_index == 1.0 and prescription.image_index == 1.0:
        _curves.prepare(prescription, np.unique(valid))
    rows = [
        raytrace_dof(prescription, float(a), float(b), float(e), distance_from, criterion)
        for a, b, e in zip(n.flat, c.flat, d.flat)
    ]
    return DofLimits(*(np.array(column, float).reshape(n.shape) for column in zip(*rows)))



