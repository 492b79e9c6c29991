"""Real rays through a lens prescription by Snell's law: meridional fans, best focus, blur.

An on-axis object point sends a meridional fan of 65 rays through the lens,
spherical and aspheric surfaces alike, vectorised with numpy over the rays
and over several candidate object distances at once. From where the rays
leave the lens follow the best-focus plane (minimum RMS spot) and the blur on
any film plane. The definitions are those of the reference data
(``oracle-README.md``):

- **Fixed stop**: r_stop = f/(2·N·m_E) from the nominal f-number (paraxial f
  and stop-to-entrance-pupil magnification m_E); focusing moves the lens as
  a whole (unit focusing) and the stop does not change.
- **Edge ray**: the real ray from the object point that meets the stop
  surface at height r_stop, found by Newton's method to ~1e-13.
- **Fan**: θ_k = θ_max·k/64 (k = 0…64) with weights S_k·sin θ_k (Simpson
  S = 1, 4, 2, …, 4, 1), normalised; for an object at infinity parallel rays
  at h_k = h_max·k/64 with weights S_k·h_k. Rays start where they cross the
  first vertex's tangent plane (z = 0): starting them at a distant object
  point would lose precision with the square of the distance.
- Each ray leaves the lens on y(z) = a_k + t_k·z; the best focus is
  z_best = −Σ w·a·t / Σ w·t²; on a film at z_film the criteria are
  ``"defocus"`` (the default): 2√2·|z_film − z_best|·√(Σ w·t²), the blur
  added by defocus alone; ``"rms"``: 2√2·√(Σ w·(a + t·z_film)²), the total
  RMS-equivalent diameter, aberrations included.

Rays that miss a surface, meet it from behind or are totally internally
reflected are dropped (their weight is removed and the rest renormalised);
if the edge ray fails, or fewer than 9 of 65 rays survive, a
:class:`RayTraceError` says so.

Coordinates: z in mm along the axis, the first vertex at z = 0, light towards
+z; an object at z_obj < 0 has vertex vergence w = −1/z_obj (0 at infinity).
The depth-of-field solver built on these fans is :mod:`camtool.dof.realray`.
"""

from __future__ import annotations

import functools
import math
from dataclasses import dataclass
from typing import Any

import numpy as np

from camtool.core.errors import CamtoolError
from camtool.optics.paraxial import FirstOrder, first_order
from camtool.optics.prescription import Prescription

__all__ = ["CRITERIA", "FanSummary", "RayTraceError", "RealRayTracer", "real_tracer"]

CRITERIA = ("defocus", "rms")
"""Blur criteria: ``defocus`` (blur added by defocus, the default) and ``rms`` (total RMS blur)."""

_FAN_SIZE = 65
_MIN_RAYS = 9
_SQRT8 = 2.0 * math.sqrt(2.0)


class RayTraceError(CamtoolError, ValueError):
    """Real rays could not be traced (missed surfaces, total internal reflection, no focus found)."""


@dataclass(frozen=True)
class _Surface:
    """A surface prepared for tracing: vertex z, curvature, conic, polynomial, indices, gap to the next."""

    z: float
    c: float
    k: float
    dense: tuple[float, ...]
    n_before: float
    n_after: float
    gap: float

    @functools.cached_property
    def spherical(self) -> bool:
        """True for a sphere or a plane (no conic, no polynomial): the closed-form fast path."""
        return self.k == 0.0 and not self.dense

    @functools.cached_property
    def terms(self) -> tuple[np.ndarray, np.ndarray]:
        """Polynomial coefficients a_1…a_P and the slope coefficients 2·a_2…P·a_P."""
        values = np.array(self.dense)
        return values, values[1:] * np.arange(2, values.size + 1)

    @functools.cached_property
    def even(self) -> tuple[np.ndarray, np.ndarray, np.ndarray] | None:
        """A surface whose polynomial has even powers alone (a conic's sag is even too): the polynomial in q = r²
        as b_1…b_J (b_j = a_2j), and the coefficients of dsag/dy ÷ y, 2·b_1 and 4·b_2…2J·b_J; None otherwise.

        Its sag and slope are then taken in q = y², which needs neither |y| nor its sign and half the powers.
        """
        if any(a != 0.0 for a in self.dense[0::2]):  # a_1, a_3, …: an odd power
            return None
        b = np.array(self.dense[1::2])
        return b, np.array(2.0 * b[0] if b.size else 0.0), b[1:] * np.arange(4.0, 2.0 * b.size + 1.0, 2.0)

    @functools.cached_property
    def constants(self) -> tuple[np.ndarray, ...]:
        """c, μ = n/n′, μ², 1 − μ², the gap and 2 as 0-d arrays (numpy multiplies an array by them faster than by floats)."""
        mu = self.n_before / self.n_after
        return tuple(np.array(x) for x in (self.c, mu, mu * mu, 1.0 - mu * mu, self.gap, 2.0))

    @functools.cached_property
    def conic(self) -> tuple[np.ndarray, ...]:
        """c·(1 + k), c²·(1 + k) and 1 as 0-d arrays, for the general path (see :attr:`constants`)."""
        return tuple(np.array(x) for x in (self.c * (1.0 + self.k), self.c * self.c * (1.0 + self.k), 1.0))


@dataclass(frozen=True)
class FanSummary:
    """What one object point's ray fan says about focus, per candidate vergence (arrays, mm).

    ``z_best`` best-focus (minimum-RMS) film position; ``slope_rms`` √(Σ w·t²);
    ``best_blur`` 2√2 × RMS radius on the best-focus plane; ``edge_mm`` the
    edge ray's height at z = 0; ``aim_mm`` the edge ray's height where it
    crosses the plane of the paraxial entrance pupil (extended in object
    space), the parameter the edge-ray search solves for.
    """

    z_best: np.ndarray
    slope_rms: np.ndarray
    best_blur: np.ndarray
    edge_mm: np.ndarray
    aim_mm: np.ndarray


def _poly(values: np.ndarray, slopes: np.ndarray, r: Any, value: bool = True) -> tuple[Any, Any]:
    """Σ a_n rⁿ and its derivative Σ n·a_n rⁿ⁻¹ at r ≥ 0, from the powers r¹…r^P.

    ``values`` holds a_1…a_P (zeros included), ``slopes`` 2·a_2…P·a_P: the
    sums are two matrix products over the stacked powers. ``value`` false:
    the derivative alone (the first result is None). The same sums in q = r²
    serve a polynomial of even powers (:func:`_even_sag`).
    """
    flat = r.reshape(-1)
    size = max(values.size if value else values.size - 1, 1)
    powers = np.empty((size, flat.size))
    rows = list(powers)
    rows[0][...] = flat
    for k in range(1, size):
        np.multiply(rows[k - 1], flat, rows[k])
    slope = (slopes @ powers[: values.size - 1]).reshape(r.shape)
    return ((values @ powers).reshape(r.shape) if value else None), slope


def _propagate(
    surfaces: tuple[_Surface, ...], y: Any, z0: Any, m: Any, l: Any, refract_last: bool = True
) -> tuple[Any, Any, Any, Any, Any]:
    """Trace rays through ``surfaces`` (z0: position relative to the first one's vertex).

    Returns (y, z, m, l, l_min): height and position relative to the last
    surface's vertex at the last intersection, the direction cosines after
    it (before it when ``refract_last`` is false), and the smallest l met on
    the way (a ray that turns back has l ≤ 0 and is void). Spheres and planes
    take the closed form (Welford's intersection: with F = c(y² + z²) − 2z
    and G = l − c(y·m + z·l), the path is F/(G + √(G² − cF)) and the cosine
    of incidence is √(G² − cF), taken as F = y·cy + z·(cz − 2) and G = l − (cy·m + cz·l)
    with cy = c·y, cz = c·z; the cosine of refraction is √(μ²·(G² − cF) + 1 − μ²), the
    discriminant standing for the cosine of incidence squared); conics and aspheres the
    general path. NaN marks rays that miss a surface or are totally internally reflected.
    """
    lmin = l
    last = len(surfaces) - 1
    for i, s in enumerate(surfaces):
        refract = (refract_last or i < last) and s.n_before != s.n_after
        if not s.spherical:
            y, z0, m, l = _general_surface(s, y, z0, m, l, refract)
            lmin = np.minimum(lmin, l)
        elif s.c == 0.0:
            y = y - z0 / l * m
            z0 = 0.0
            if refract:
                m = s.constants[1] * m
                l = np.sqrt(1.0 - m * m)  # cos of refraction; NaN: total internal reflection
        else:
            c, mu0, mu2, rest, _, two = s.constants
            cy, cz = c * y, c * z0
            f_term = y * cy + z0 * (cz - two)
            g_term = l - (cy * m + cz * l)
            disc = g_term * g_term - c * f_term
            cos_i = np.sqrt(disc)  # NaN: the ray misses the sphere
            t = f_term / (g_term + cos_i)
            y = y + t * m
            z0 = z0 + t * l
            if refract:
                g = np.sqrt(mu2 * disc + rest) - mu0 * cos_i
                gc = g * c
                m, l = mu0 * m - gc * y, mu0 * l + g - gc * z0
                lmin = np.minimum(lmin, l)
        if i < last:
            z0 = z0 - s.constants[4]
    return y, z0, m, l, lmin


def _general_surface(s: _Surface, y: Any, z0: Any, m: Any, l: Any, refract: bool) -> tuple[Any, Any, Any, Any]:
    """Intersect (and refract at) a conic or aspheric surface; z0 relative to its vertex."""
    c, mu, mu2, _, _, two = s.constants
    ck, _, one = s.conic
    if s.c == 0.0:
        t = -z0 / l
    else:
        a = c * m * m + ck * l * l
        b = c * y * m - l + ck * z0 * l
        cc = c * y * y - two * z0 + ck * z0 * z0
        t = cc / (np.sqrt(b * b - a * cc) - b)
    even = s.even
    for _ in range(30 if s.dense else 0):
        height = y + t * m
        if even is not None:
            sag, dzdy = _even_sag(s, even, height)
        else:
            sag, dsag = _sag(s, np.abs(height))
            dzdy = dsag * np.sign(height)
        step = (z0 + t * l - sag) / (l - dzdy * m)
        t = t - step
        if not np.fmax.reduce(np.abs(step), axis=None) > 1e-6:
            break  # quadratic convergence: the error left is ~ K·step² with K ~ 0.01/mm on the shared lenses
    y = y + t * m
    z0 = z0 + t * l
    if not refract:
        return y, z0, m, l
    if even is not None:
        dzdy = _even_sag(s, even, y, value=False)[1]
    else:
        _, dsag = _sag(s, np.abs(y), value=False)
        dzdy = dsag * np.sign(y)
    norm = np.sqrt(one + dzdy * dzdy)
    ny, nz = -dzdy / norm, one / norm
    cos_i = ny * m + nz * l
    cos_r = np.sqrt(one - mu2 * (one - cos_i * cos_i))  # NaN: total internal reflection
    g = np.where(cos_i > 0.0, cos_r - mu * cos_i, np.nan)
    return y, z0, mu * m + g * ny, mu * l + g * nz


class RealRayTracer:
    """Real meridional ray trace of one prescription (use :func:`real_tracer` for a cached one).

    Object points are given by their entrance-pupil vergence v = 1/(z_E − z_obj)
    (z_E the paraxial entrance pupil; 0 at infinity), which stays finite for
    every object in front of the lens, the first vertex included, and in
    which focus and blur vary smoothly. The vertex vergence is
    w = −1/z_obj = v/(1 − v·z_E). A ray from the object is named by its aim
    height p where it crosses the plane z = z_E: it leaves at the angle
    tan θ = p·v and crosses z = 0 at the height p·(1 − v·z_E).

    Parameters
    ----------
    prescription : Prescription

    Examples
    --------
    >>> from camtool.optics.prescription import EXAMPLE_SINGLET, prescription_from_mapping
    >>> lens = prescription_from_mapping(EXAMPLE_SINGLET)
    >>> tracer = RealRayTracer(lens)
    >>> s = tracer.summaries([0.0], f_number=16.0)
    >>> round(float(s.z_best[0]) - tracer.first.z_f_prime_mm, 4)  # spherical aberration
    -0.0708
    """

    def __init__(self, prescription: Prescription) -> None:
        self.prescription = prescription
        self.first: FirstOrder = first_order(prescription)
        n_before = prescription.object_index
        prepared = []
        for surface, z in zip(prescription.surfaces, prescription.vertices_mm):
            terms = dict(surface.aspheric)
            dense = tuple(terms.get(p, 0.0) for p in range(1, max(terms, default=0) + 1))
            prepared.append(_Surface(z, surface.curvature, surface.conic, dense, n_before, surface.n, surface.thickness_mm))
            n_before = surface.n
        self.surfaces = tuple(prepared)
        self.stop = prescription.stop_index
        self._to_stop = self.surfaces[: self.stop + 1]
        weights = np.ones(_FAN_SIZE)
        weights[1:-1:2], weights[2:-1:2] = 4.0, 2.0
        self._simpson = weights
        self._fraction = np.arange(_FAN_SIZE) / (_FAN_SIZE - 1.0)

    # -- tracing ---------------------------------------------------------------------

    def trace(self, y: Any, m: Any, l: Any, start: int = 0, end: int | None = None) -> tuple[Any, Any, Any, Any]:
        """Trace rays from the plane z = 0 through surfaces ``start``…``end − 1``.

        Rays are given by their height y at z = 0 and direction cosines
        (m, l) = (sin θ, cos θ). Returns (y, z, m, l) at the last surface
        reached, after its refraction; failed rays are NaN.

        Parameters
        ----------
        y, m, l : array
            Broadcastable arrays.
        start, end : int
            Surfaces to trace (0-based, ``end`` exclusive, default all).
        """
        end = len(self.surfaces) if end is None else end
        y, m, l = np.broadcast_arrays(np.asarray(y, float), np.asarray(m, float), np.asarray(l, float))
        surfaces = self.surfaces[start:end]
        with np.errstate(all="ignore"):
            y, z, m, l, lmin = _propagate(surfaces, y, -surfaces[0].z, m, l)
            void = ~(lmin > 0.0)
            z = np.where(void, np.nan, z + surfaces[-1].z)
            return np.where(void, np.nan, y), z, np.where(void, np.nan, m), np.where(void, np.nan, l)

    def _start(self, aim: Any, v: Any) -> tuple[Any, Any, Any]:
        """Height at z = 0 and direction cosines of rays aimed at height ``aim`` on the plane z_E."""
        slope = aim * v
        l = 1.0 / np.sqrt(1.0 + slope * slope)
        return aim * (1.0 - v * self.first.z_e_mm), slope * l, l

    def _stop_height(self, aim: Any, v: Any) -> Any:
        """Height where rays aimed at ``aim`` (from objects at pupil vergence v) meet the stop surface."""
        y, m, l = self._start(aim, v)
        y, _, _, _, lmin = _propagate(self._to_stop, y, 0.0, m, l, refract_last=False)
        return np.where(lmin > 0.0, y, np.nan)

    def pupil_vergence(self, w: Any) -> np.ndarray:
        """Entrance-pupil vergence v = w/(1 + w·z_E) of objects at vertex vergence w (1/mm)."""
        w = np.atleast_1d(np.asarray(w, float))
        z_e = self.first.z_e_mm
        with np.errstate(all="ignore"):
            return np.where(np.isinf(w), 1.0 / z_e if z_e else np.inf, w / (1.0 + w * z_e))

    def aims(self, v: Any, f_number: Any, guess: Any = None) -> np.ndarray:
        """Aim height of the edge ray (meeting the stop at r_stop) for each pupil vergence v (mm).

        ``f_number`` is one N, or one per vergence.

        Starts from ``guess`` (default: the paraxial entrance-pupil radius
        f/(2N), exact in the paraxial limit) and refines by Halley's method,
        p − 2·e·e′/(2·e′² − e·e″) with e the stop height's miss, its slope and
        curvature by central differences (relative step 1e-5, one trace of the
        three rays of every vergence). The error after a step s (relative to
        the height) is about A·s³ + 1e-10·s (cubic convergence; the slope's
        truncation error ~1e-10), A measured by the last two steps as
        s_k/s_(k−1)³: the iteration stops once every ray's step is below 1e-6,
        or below 1e-4 with s_k⁴/s_(k−1)³ below 1e-15, the error left below
        ~1e-14 of the height either way (from the paraxial start two traces on
        every shipped prescription, where Newton's method took three or four).
        NaN where the edge ray cannot be traced.
        """
        v = np.atleast_1d(np.asarray(v, float))
        n = np.asarray(f_number, float)
        r_stop = self.first.efl_mm / (2.0 * n * self.first.m_e)  # f/(2·N·m_E), as FirstOrder.stop_radius_mm
        p = np.broadcast_to(self.first.efl_mm / (2.0 * n), v.shape).copy() if guess is None else np.array(guess, float)
        triple_v = np.concatenate([v, v, v])
        size = v.size
        before = None
        with np.errstate(all="ignore"):
            for _ in range(40):
                h = p * 1e-5
                heights = self._stop_height(np.concatenate([p, p + h, p - h]), triple_v)
                e, up, down = heights[:size] - r_stop, heights[size : 2 * size], heights[2 * size :]
                slope = (up - down) / (2.0 * h)
                curvature = (up - 2.0 * heights[:size] + down) / (h * h)
                step = 2.0 * e * slope / (2.0 * slope * slope - e * curvature)
                p = p - step
                moved = np.abs(step) / np.abs(p)  # NaN where the ray failed: it holds nothing up
                if not np.any(moved > 1e-6):
                    break
                if before is not None and not np.any((moved > 1e-4) | (moved**4 > 1e-15 * before**3)):
                    break
                before = moved
        return p

    def _fan(self, v: np.ndarray, aim: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """Image-space lines y = a + t·z and normalised weights of the 65-ray fans, per pupil vergence."""
        v2 = v[:, None]
        tan_max = (aim * v)[:, None]
        theta = np.arctan(tan_max) * self._fraction
        finite = tan_max != 0.0
        tan_k = np.tan(theta)
        ratio = np.where(finite, tan_k / np.where(finite, tan_max, 1.0), self._fraction)
        h0 = (aim * (1.0 - v * self.first.z_e_mm))[:, None] * ratio
        sin_k = np.sin(theta)
        weights = self._simpson * np.where(v2 == 0.0, self._fraction, sin_k)
        # the rays as one flat array: numpy's element-wise calls cost less on one dimension than on two
        y, z, m, l, lmin = _propagate(self.surfaces, h0.reshape(-1), 0.0, sin_k.reshape(-1), np.cos(theta).reshape(-1))
        t = m / l
        a = y - t * (z + self.surfaces[-1].z)
        ok = (np.isfinite(a) & np.isfinite(t) & (lmin > 0.0)).reshape(h0.shape)
        a, t = a.reshape(h0.shape), t.reshape(h0.shape)
        if ok.all():  # the usual case: no ray lost, nothing to mask
            self._survivors = np.full(v.size, _FAN_SIZE)
            return a, t, weights / weights.sum(axis=1, keepdims=True)
        weights = np.where(ok, weights, 0.0)
        weights = weights / weights.sum(axis=1, keepdims=True)
        self._survivors = ok.sum(axis=1)
        return np.where(ok, a, 0.0), np.where(ok, t, 0.0), weights

    def summarise(self, v: Any, f_number: Any, guess: Any = None) -> tuple[FanSummary, np.ndarray]:
        """Fan summaries per pupil vergence v, and a mask of those that could be traced.

        ``f_number`` is one N, or one per vergence (several f-numbers in one batch).

        Where the edge ray fails or fewer than 9 of 65 rays survive, the
        mask is False and the summary NaN; nothing is raised.
        """
        v = np.atleast_1d(np.asarray(v, float))
        with np.errstate(all="ignore"):
            aim = self.aims(v, f_number, guess)
            a, t, weights = self._fan(v, aim)
            wt2 = (weights * t * t).sum(axis=1)
            z_best = -(weights * a * t).sum(axis=1) / wt2
            residual = a + t * z_best[:, None]
            best = _SQRT8 * np.sqrt((weights * residual * residual).sum(axis=1))
            ok = np.isfinite(aim) & (self._survivors >= _MIN_RAYS) & np.isfinite(z_best) & np.isfinite(best)
            edge = aim * (1.0 - v * self.first.z_e_mm)
        return FanSummary(z_best, np.sqrt(wt2), best, edge, aim), ok

    def summaries(self, w: Any, f_number: float, guess: Any = None) -> FanSummary:
        """Best focus, RMS slope and best-focus RMS blur for each vertex vergence w (mm).

        z_best = −Σ w·a·t/Σ w·t²; slope_rms = √(Σ w·t²);
        best_blur = 2√2·√(Σ w·(a + t·z_best)²). ``guess``: starting aim
        heights for :meth:`aims`.

        Raises
        ------
        RayTraceError
            The edge ray cannot reach the stop, or fewer than 9 of 65 rays
            get through the lens.
        """
        v = self.pupil_vergence(w)
        summary, ok = self.summarise(v, f_number, guess)
        if not np.all(ok):
            raise self.failure(f_number, summary, ok)
        return summary

    def failure(self, f_number: float, summary: FanSummary, ok: np.ndarray) -> RayTraceError:
        """The error that says why some fans could not be traced."""
        if not np.all(np.isfinite(summary.aim_mm[~ok])):
            return RayTraceError(
                f"{self._name()}: the edge ray of the f/{f_number:g} beam cannot reach the stop "
                "(it misses a surface or is totally internally reflected)"
            )
        return RayTraceError(
            f"{self._name()}: fewer than {_MIN_RAYS} of {_FAN_SIZE} rays get through the lens "
            f"at f/{f_number:g} (rays miss surfaces or are totally internally reflected)"
        )

    def _name(self) -> str:
        return self.prescription.id or self.prescription.source or "prescription"


def _sag(s: _Surface, r: Any, value: bool = True) -> tuple[Any, Any]:
    """Sag and radial slope (sag, dsag/dr) of a prepared surface at r ≥ 0; NaN beyond a conic's rim.

    ``value`` false: the slope alone (the sag is None).
    """
    c = s.constants[0]
    _, c2k, one = s.conic
    r2 = r * r
    root = np.sqrt(one - c2k * r2)
    sag = c * r2 / (one + root) if value else None
    slope = c * r / root
    if s.dense:
        extra, extra_slope = _poly(*s.terms, r, value)
        if value:
            sag = sag + extra
        slope = slope + extra_slope
    return sag, slope


def _even_sag(s: _Surface, even: tuple[np.ndarray, np.ndarray, np.ndarray], y: Any,
              value: bool = True) -> tuple[Any, Any]:
    """Sag and dsag/dy at the signed height y of a surface whose sag is even in y (:attr:`_Surface.even`).

    In q = y²: the conic's c·q/(1 + √(1 − c²(1 + k)·q)) with slope y·c/√(…), and
    Σ b_j q^j with slope y·(2·b_1 + Σ 2j·b_j q^(j−1)), the sums by :func:`_poly`
    in q. The same sag and slope as :func:`_sag` at |y| with the sign of y, to
    round-off; NaN beyond a conic's rim.
    """
    c = s.constants[0]
    _, c2k, one = s.conic
    q = y * y
    root = np.sqrt(one - c2k * q)
    sag = c * q / (one + root) if value else None
    per_y = c / root
    b, first, rest = even
    if b.size:
        extra, extra_slope = _poly(b, rest, q, value)
        if value:
            sag = sag + extra
        per_y = per_y + first + extra_slope
    return sag, y * per_y


_BY_IDENTITY: dict[int, tuple[Prescription, RealRayTracer]] = {}


def real_tracer(prescription: Prescription) -> RealRayTracer:
    """A cached :class:`RealRayTracer` for a prescription.

    The same prescription object finds its tracer by identity (the object is
    held, so its id is not reused); an equal one by value, as a cache keyed
    by the prescription would (hashing every surface costs tens of µs).

    Examples
    --------
    >>> from camtool.optics.prescription import EXAMPLE_SINGLET, prescription_from_mapping
    >>> lens = prescription_from_mapping(EXAMPLE_SINGLET)
    >>> real_tracer(lens) is real_tracer(lens)
    True
    >>> real_tracer(prescription_from_mapping(EXAMPLE_SINGLET)) is real_tracer(lens)
    True
    """
    hit = _BY_IDENTITY.get(id(prescription))
    if hit is not None and hit[0] is prescription:
        return hit[1]
    tracer = _real_tracer(prescription)
    if len(_BY_IDENTITY) >= 16:
        _BY_IDENTITY.clear()
    _BY_IDENTITY[id(prescription)] = (prescription, tracer)
    return tracer


@functools.lru_cache(maxsize=16)
def _real_tracer(prescription: Prescription) -> RealRayTracer:
    """The tracer of a prescription, cached by value."""
    return RealRayTracer(prescription)


