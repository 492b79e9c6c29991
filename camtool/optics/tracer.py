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

from camtool.optics.paraxial import FirstOrder, first_order
from camtool.optics.prescription import Prescription

__all__ = ["CRITERIA", "FanSummary", "RayTraceError", "RealRayTracer", "real_tracer"]

CRITERIA = ("defocus", "rms")
"""Blur criteria: ``defocus`` (blur added by defocus, the default) and ``rms`` (total RMS blur)."""

_FAN_SIZE = 65
_MIN_RAYS = 9
_SQRT8 = 2.0 * math.sqrt(2.0)


class RayTraceError(ValueError):
    """Real rays could not be traced (missed surfaces, total internal reflection, no focus found)."""


@dataclass(frozen=True)
class _Surface:
    """A surface prepared for tracing: vertex z, curvature, conic, polynomial, indices."""

    z: float
    c: float
    k: float
    lowest: int
    dense: tuple[float, ...]
    n_before: float
    n_after: float


@dataclass(frozen=True)
class FanSummary:
    """What one object point's ray fan says about focus, per candidate vergence (arrays, mm).

    ``z_best`` best-focus (minimum-RMS) film position; ``slope_rms`` √(Σ w·t²);
    ``best_blur`` 2√2 × RMS radius on the best-focus plane; ``edge_mm`` the
    edge ray's height at z = 0.
    """

    z_best: np.ndarray
    slope_rms: np.ndarray
    best_blur: np.ndarray
    edge_mm: np.ndarray


def _poly(lowest: int, dense: tuple[float, ...], r: np.ndarray) -> tuple[Any, Any]:
    """Σ a_n rⁿ and its derivative Σ n·a_n rⁿ⁻¹ at r ≥ 0, by Horner's rule.

    ``dense`` holds a_lowest, a_lowest+1, … (zeros included), so no array
    is raised to a power.
    """
    value: Any = 0.0
    slope: Any = 0.0
    for offset in range(len(dense) - 1, -1, -1):
        value = value * r + dense[offset]
        slope = slope * r + (lowest + offset) * dense[offset]
    r_low = r ** (lowest - 1) if lowest != 2 else r
    return value * r_low * r, slope * r_low


class RealRayTracer:
    """Real meridional ray trace of one prescription (use :func:`real_tracer` for a cached one).

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
            lowest = min(terms, default=2)
            dense = tuple(terms.get(p, 0.0) for p in range(lowest, max(terms, default=1) + 1))
            prepared.append(_Surface(z, surface.curvature, surface.conic, lowest, dense, n_before, surface.n))
            n_before = surface.n
        self.surfaces = tuple(prepared)
        self.stop = prescription.stop_index
        weights = np.ones(_FAN_SIZE)
        weights[1:-1:2], weights[2:-1:2] = 4.0, 2.0
        self._simpson = weights
        self._fraction = np.arange(_FAN_SIZE) / (_FAN_SIZE - 1.0)

    # -- tracing ---------------------------------------------------------------------

    @staticmethod
    def _intersect(s: _Surface, y: np.ndarray, z: np.ndarray, m: np.ndarray, l: np.ndarray) -> Any:
        """Path length t from (y, z) along (m, l) to the surface (NaN where the ray misses)."""
        z0 = z - s.z
        if s.c == 0.0:
            t = -z0 / l
        else:
            ck = s.c * (1.0 + s.k)
            a = s.c * m * m + ck * l * l
            b = s.c * y * m - l + ck * z0 * l
            cc = s.c * y * y - 2.0 * z0 + ck * z0 * z0
            t = cc / (np.sqrt(b * b - a * cc) - b)
        for _ in range(30 if s.dense else 0):
            r = np.abs(y + t * m)
            sag, dsag = _sag(s, r)
            dzdy = dsag * np.sign(y + t * m)
            step = (z0 + t * l - sag) / (l - dzdy * m)
            t = t - step
            if not np.any(np.abs(step) > 1e-8):
                break  # quadratic convergence: the error left is ~ step² ≪ 1e-13 mm
        return t

    @staticmethod
    def _refract(s: _Surface, y: np.ndarray, m: np.ndarray, l: np.ndarray) -> tuple[Any, Any]:
        """New direction cosines after Snell's law at the surface point of height y."""
        r = np.abs(y)
        _, dsag = _sag(s, r)
        dzdy = dsag * np.sign(y)
        norm = np.sqrt(1.0 + dzdy * dzdy)
        ny, nz = -dzdy / norm, 1.0 / norm
        cos_i = ny * m + nz * l
        mu = s.n_before / s.n_after
        cos_r = np.sqrt(1.0 - mu * mu * (1.0 - cos_i * cos_i))  # NaN: total internal reflection
        g = cos_r - mu * cos_i
        g = np.where(cos_i > 0.0, g, np.nan)
        return mu * m + g * ny, mu * l + g * nz

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
        z = np.zeros_like(y)
        with np.errstate(all="ignore"):
            for s in self.surfaces[start:end]:
                t = self._intersect(s, y, z, m, l)
                y = y + t * m
                z = z + t * l
                if s.n_before != s.n_after:
                    m, l = self._refract(s, y, m, l)
                l = np.where(l > 0.0, l, np.nan)
        return y, z, m, l

    def _stop_height(self, h0: np.ndarray, w: np.ndarray) -> np.ndarray:
        """Height where rays leaving z = 0 at h0 (from an object of vergence w) meet the stop."""
        theta = np.arctan(h0 * w)
        y, _, _, _ = self.trace(h0, np.sin(theta), np.cos(theta), 0, self.stop + 1)
        return y

    def paraxial_edge_heights(self, w: Any, f_number: float) -> np.ndarray:
        """Height at z = 0 of the paraxial ray through the entrance-pupil edge: r_E/(1 + w·z_E) (mm)."""
        w = np.atleast_1d(np.asarray(w, float))
        return self.first.efl_mm / (2.0 * f_number) / (1.0 + w * self.first.z_e_mm)

    def edge_heights(self, w: Any, f_number: float, guess: Any = None) -> np.ndarray:
        """Height at z = 0 of the edge ray (meeting the stop at r_stop) for each vertex vergence w (mm).

        Starts from ``guess`` (default: the paraxial ray through the
        entrance-pupil edge, :meth:`paraxial_edge_heights`) and refines by
        Newton's method with a finite-difference slope (relative step 1e-7).
        Once a step is below 1e-8 of the height, the error left is below
        ~1e-15 of it (quadratic convergence, slope error ~1e-7), and the
        iteration stops.
        """
        w = np.atleast_1d(np.asarray(w, float))
        r_stop = self.first.stop_radius_mm(f_number)
        h = self.paraxial_edge_heights(w, f_number) if guess is None else np.asarray(guess, float)
        with np.errstate(all="ignore"):
            for _ in range(40):
                pair = self._stop_height(np.stack([h, h * (1.0 + 1e-7)]), w)
                slope = (pair[1] - pair[0]) / (h * 1e-7)
                step = (pair[0] - r_stop) / slope
                h = h - step
                if not np.any(np.abs(step) > 1e-8 * np.abs(h)):
                    break
        if not np.all(np.isfinite(h)):
            raise RayTraceError(
                f"{self._name()}: the edge ray of the f/{f_number:g} beam cannot reach the stop "
                "(it misses a surface or is totally internally reflected)"
            )
        return h

    def fan(self, w: Any, f_number: float, h_edge: Any = None) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """Image-space lines y = a + t·z and normalised weights of the 65-ray fan, per vergence.

        ``h_edge`` are the edge-ray heights (default: :meth:`edge_heights`).
        Returns arrays (a, t, weights) of shape (len(w), 65); dropped rays
        have weight 0.
        """
        w = np.atleast_1d(np.asarray(w, float))
        h_edge = self.edge_heights(w, f_number) if h_edge is None else h_edge
        theta = np.arctan(h_edge * w)[:, None] * self._fraction
        at_infinity = (w == 0.0)[:, None]
        with np.errstate(all="ignore"):
            h0 = np.where(at_infinity, h_edge[:, None] * self._fraction, np.tan(theta) / w[:, None])
            weights = self._simpson * np.where(at_infinity, self._fraction, np.sin(theta))
            y, z, m, l = self.trace(h0, np.sin(theta), np.cos(theta))
            t = m / l
            a = y - t * z
        ok = np.isfinite(a) & np.isfinite(t)
        if np.any(ok.sum(axis=1) < _MIN_RAYS):
            raise RayTraceError(
                f"{self._name()}: fewer than {_MIN_RAYS} of {_FAN_SIZE} rays get through the lens "
                f"at f/{f_number:g} (rays miss surfaces or are totally internally reflected)"
            )
        weights = np.where(ok, weights, 0.0)
        weights /= weights.sum(axis=1, keepdims=True)
        return np.where(ok, a, 0.0), np.where(ok, t, 0.0), weights

    def summaries(self, w: Any, f_number: float, guess: Any = None) -> FanSummary:
        """Best focus, RMS slope and best-focus RMS blur for each vertex vergence w (mm).

        z_best = −Σ w·a·t/Σ w·t²; slope_rms = √(Σ w·t²);
        best_blur = 2√2·√(Σ w·(a + t·z_best)²). ``guess``: starting edge-ray
        heights for :meth:`edge_heights`.
        """
        h_edge = self.edge_heights(w, f_number, guess)
        a, t, weights = self.fan(w, f_number, h_edge)
        wt2 = (weights * t * t).sum(axis=1)
        z_best = -(weights * a * t).sum(axis=1) / wt2
        residual = a + t * z_best[:, None]
        best = _SQRT8 * np.sqrt((weights * residual * residual).sum(axis=1))
        return FanSummary(z_best, np.sqrt(wt2), best, h_edge)

    def _name(self) -> str:
        return self.prescription.id or self.prescription.source or "prescription"


def _sag(s: _Surface, r: Any) -> tuple[Any, Any]:
    """Sag and radial slope (sag, dsag/dr) of a prepared surface at r ≥ 0; NaN beyond a conic's rim."""
    root = np.sqrt(1.0 - s.c * s.c * (1.0 + s.k) * r * r)
    sag = s.c * r * r / (1.0 + root)
    slope = s.c * r / root
    if s.dense:
        extra, extra_slope = _poly(s.lowest, s.dense, r)
        sag, slope = sag + extra, slope + extra_slope
    return sag, slope


@functools.lru_cache(maxsize=16)
def real_tracer(prescription: Prescription) -> RealRayTracer:
    """A cached :class:`RealRayTracer` for a prescription.

    Examples
    --------
    >>> from camtool.optics.prescription import EXAMPLE_SINGLET, prescription_from_mapping
    >>> lens = prescription_from_mapping(EXAMPLE_SINGLET)
    >>> real_tracer(lens) is real_tracer(lens)
    True
    """
    return RealRayTracer(prescription)


