"""The wavefront of a prescription by real rays, and its point spread and transfer functions by FFT.

An object point sends rays through the lens (Snell's law in three dimensions,
skew rays included, spheres, conics and polynomial aspheres: the surfaces of
:mod:`camtool.optics.tracer`). The rays sample the aperture stop on a square
grid, uniformly: each grid point (ξ, η) in units of the stop radius, |(ξ, η)|
≤ 1, is the ray that meets the stop surface at (ξ, η)·r_stop (found by
Newton's method on the trace to the stop: real-ray aiming). The fixed stop is
that of the reference data, r_stop = f/(2·N·m_E).

**Wavefront.** The optical path from the object point (for an object at
infinity, from a plane wave) to the *reference sphere* centred on the point
where the chief ray (the ray through the centre of the stop) meets the film,
passing through the paraxial exit pupil on the axis, minus the chief ray's
own path: the optical path difference W(ξ, η) in waves at the prescription's
wavelength (W. J. Smith, *Modern Optical Engineering*, 4th ed., §11.4;
M. Born and E. Wolf, *Principles of Optics*, §9.1). A film moved from focus
adds the defocus the rays themselves carry to the new sphere: through focus
is the same trace with another film.

**PSF and OTF.** The pupil function P = exp(2πi·W) inside the stop (0
outside, uniform amplitude), zero-padded, gives the amplitude spread
function by a discrete Fourier transform, the point spread function as its
squared modulus, and the optical transfer function as the normalised Fourier
transform of the PSF — equivalently the autocorrelation of P (J. W. Goodman,
*Introduction to Fourier Optics*, 3rd ed., §6.3, eqs. 6-19 to 6-27; the
padding makes the discrete autocorrelation linear rather than circular). A
lag of k grid samples along ξ (sagittal) or η (tangential) is the spatial
frequency

    ν = k·δ·Δκ/(2·λ),

with δ the grid step (stop radii), Δκ the difference (along the lag) of the
*canonical coordinates* of the two opposite marginal rays — the direction
cosines, seen from the reference sphere's centre on the film, of the points
where they cross the sphere — and λ in mm: the Fraunhofer kernel from the
reference sphere to the film (Goodman §6.4 for the defocused pupil; H. H.
Hopkins, Proc. Phys. Soc. B 70, 1002, 1957, for canonical coordinates), with
the pupil mapped to them as an affine map (exact for a lens that obeys the
sine condition). In focus the sphere's centre is the rays' own image point
and Δκ/2 is the sine of the marginal ray's angle, which is how optiland
calibrates its FFT MTF; out of focus the sphere's geometry, not the rays'
convergence, sets the scale, as in the perfect lens's OTF
(:mod:`camtool.optics.transfer`: s = ν·λ·N_w with N_w fixed by the film).
On the axis ν = k·δ/(2·λ·N_w), N_w = 1/(2 sin U′).

**Sampling and error.** :data:`SAMPLES` grid points across the stop
diameter; for one frequency the step is chosen so the frequency falls on a
whole lag (no interpolation). Against the exact OTF of a perfect pupil with
up to four waves of defocus (:func:`camtool.optics.transfer.defocus_mtf`)
the largest error of the MTF on that grid is 0.0017 (the staircase of
the sampled circle; ``tests/test_wavefront.py``).

numpy is imported with this module: it serves the ``wave`` rung with a
prescription alone.
"""

from __future__ import annotations

import functools
import math
from dataclasses import dataclass
from typing import Any

import numpy as np
from numpy.polynomial import chebyshev as cheb

from camtool.optics.chebyshev import lobatto_matrix
from camtool.optics.prescription import Prescription
from camtool.optics.tracer import RayTraceError, RealRayTracer, _sag, _Surface, real_tracer

__all__ = [
    "SAMPLES",
    "PupilWave",
    "Vignetted",
    "WavefrontTracer",
    "otf_at_lag",
    "otf_grid",
    "wavefront_tracer",
]

SAMPLES = 101
"""Grid points across the stop diameter (about 8000 rays inside the stop off the axis)."""

RADIAL_NODES = 32
"""On the axis: the degree of the Chebyshev interpolant of W(ρ²) (33 traced rays per object)."""

_RADII = np.sqrt((1.0 - np.cos(np.pi * np.arange(RADIAL_NODES + 1) / RADIAL_NODES)) / 2.0)


@dataclass(frozen=True)
class RadialWave:
    """An axial wavefront W(ρ²) per object, and the frequency scale of its pupil.

    ``coef`` (B, D + 1): Chebyshev coefficients in 2ρ² − 1 (waves);
    ``unit_lpmm`` (B,): the spatial frequency of a pupil shift of one stop
    radius, sin U′/λ with U′ the angle at the film's axial point of the marginal ray's point on the reference
    sphere (the marginal ray's own angle when the object is in focus).
    """

    coef: np.ndarray
    unit_lpmm: np.ndarray


class Vignetted(RayTraceError):
    """Rays of the beam cannot get through the lens: no wavefront to sample."""


@dataclass(frozen=True)
class PupilWave:
    """The wavefront over the stop grid, per object (arrays; mm, waves).

    ``opd_waves`` (B, n, n), 0 outside the stop; ``inside`` (B, n, n) the
    grid points whose rays got through; ``step`` the grid step δ in stop
    radii; ``lag_lpmm`` (B, 2) the spatial frequency of one lag along ξ
    (sagittal) and η (tangential) in lp/mm; ``image_mm`` (B, 2) where the
    chief ray meets the film (x, y).
    """

    opd_waves: np.ndarray
    inside: np.ndarray
    step: float
    lag_lpmm: np.ndarray
    image_mm: np.ndarray

    def pupil(self) -> np.ndarray:
        """The pupil function exp(2πi·W) inside the stop, 0 outside."""
        return np.where(self.inside, np.exp(2j * np.pi * self.opd_waves), 0.0)


def grid(step: float) -> tuple[np.ndarray, int]:
    """Grid coordinates (stop radii) with step δ covering [−1, 1] symmetrically, and their count n."""
    half = math.floor(1.0 / step + 1e-9)
    n = 2 * half + 1
    return (np.arange(n) - half) * step, n


def otf_grid(pupil: np.ndarray, size: int | None = None) -> np.ndarray:
    """The normalised OTF on the lag grid: FFT of the PSF = |FFT(P)|², P zero-padded to ``size`` (≥ 2n).

    Returns the complex OTF with lag (0, 0) at index [0, 0] (numpy's FFT
    order; lag k along the last axis is ξ, along the one before η).
    """
    n = pupil.shape[-1]
    size = size or _fast_size(2 * n)
    amplitude = np.fft.fft2(pupil, s=(size, size))
    psf = (amplitude * amplitude.conj()).real
    otf = np.fft.ifft2(psf)
    return otf / otf[..., :1, :1]


def otf_at_lag(pupil: np.ndarray, lag: float, axis: int = -1, weights: Any = None) -> Any:
    """The OTF of pupils (…, n, n) at a lag of ``lag`` samples along ``axis`` (−1: ξ, −2: η), by FFT.

    The slice of the OTF along one axis is the Fourier transform of the line
    spread function: the squared moduli of the rows' Fourier transforms
    (each row zero-padded to at least n + lag + 2), summed over the rows
    (``weights``: a weight per row, for a pupil given by half its rows), and
    transformed back — the same numbers as :func:`otf_grid` along that axis,
    at a fraction of the cost. A lag between whole samples is interpolated
    linearly.
    """
    if axis == -2:
        pupil = np.swapaxes(pupil, -1, -2)
    n = pupil.shape[-1]
    low = math.floor(lag)
    size = _fast_size(n + low + 2)
    amplitude = np.fft.fft(pupil, n=size, axis=-1)
    power = amplitude.real ** 2 + amplitude.imag ** 2
    spectrum = power.sum(axis=-2) if weights is None else np.tensordot(weights, power, axes=([0], [-2]))
    line = np.fft.ifft(spectrum, axis=-1)
    zero = line[..., 0].real
    frac = lag - low
    value = line[..., low] if frac == 0.0 else (1.0 - frac) * line[..., low] + frac * line[..., low + 1]
    with np.errstate(all="ignore"):
        return value / zero


def _fast_size(n: int) -> int:
    """The smallest 2^a·3^b ≥ n (a fast FFT length)."""
    best = 1 << math.ceil(math.log2(max(n, 1)))
    three = 1
    while three < best:
        power = three
        while power < n:
            power *= 2
        best = min(best, power)
        three *= 3
    return best


def _trace3(surfaces: tuple[_Surface, ...], x: Any, y: Any, z0: Any, kx: Any, ky: Any, kz: Any,
            ) -> tuple[Any, ...]:
    """Skew rays through ``surfaces`` (z0 relative to the first vertex), with their optical path.

    Returns x, y, z (relative to the last vertex), the direction cosines after
    the last surface, the optical path from the start and the smallest kz met
    (≤ 0 or NaN: the ray turned back, missed a surface or was totally
    internally reflected). Spheres and planes by the closed form (Welford);
    conics from their quadratic, polynomial aspheres then by Newton's method
    on the sag, as :func:`camtool.optics.tracer._propagate` in the meridian.
    """
    path = np.zeros(np.broadcast(x, y, kz).shape)
    kmin = kz
    last = len(surfaces) - 1
    for i, s in enumerate(surfaces):
        c = s.c
        if s.spherical and c == 0.0:
            t = -z0 / kz
        elif s.spherical:
            f_term = c * (x * x + y * y + z0 * z0) - 2.0 * z0
            g_term = kz - c * (x * kx + y * ky + z0 * kz)
            t = f_term / (g_term + np.sqrt(g_term * g_term - c * f_term))
        else:
            t = _general_path(s, x, y, z0, kx, ky, kz)
        x, y, z0 = x + t * kx, y + t * ky, z0 + t * kz
        path = path + s.n_before * t
        if s.n_before != s.n_after:
            if s.spherical:
                nx, ny, nz = -c * x, -c * y, 1.0 - c * z0
            else:
                r = np.hypot(x, y)
                _, slope = _sag(s, r)
                safe = np.where(r > 0.0, r, 1.0)
                gx, gy = np.where(r > 0.0, slope * x / safe, 0.0), np.where(r > 0.0, slope * y / safe, 0.0)
                norm = np.sqrt(1.0 + gx * gx + gy * gy)
                nx, ny, nz = -gx / norm, -gy / norm, 1.0 / norm
            cos_i = nx * kx + ny * ky + nz * kz
            mu = s.n_before / s.n_after
            cos_r = np.sqrt(1.0 - mu * mu * (1.0 - cos_i * cos_i))
            g = np.where(cos_i > 0.0, cos_r - mu * cos_i, np.nan)
            kx, ky, kz = mu * kx + g * nx, mu * ky + g * ny, mu * kz + g * nz
        kmin = np.minimum(kmin, kz)
        if i < last:
            z0 = z0 - s.gap
    return x, y, z0, kx, ky, kz, path, kmin


def _general_path(s: _Surface, x: Any, y: Any, z0: Any, kx: Any, ky: Any, kz: Any) -> Any:
    """Distance along the ray to a conic or aspheric surface (z0 relative to its vertex)."""
    if s.c == 0.0:
        t = -z0 / kz
    else:
        ck = s.c * (1.0 + s.k)
        a = s.c * (kx * kx + ky * ky) + ck * kz * kz
        b = s.c * (x * kx + y * ky) - kz + ck * z0 * kz
        cc = s.c * (x * x + y * y) - 2.0 * z0 + ck * z0 * z0
        t = cc / (np.sqrt(b * b - a * cc) - b)
    for _ in range(30 if s.dense else 0):
        px, py = x + t * kx, y + t * ky
        r = np.hypot(px, py)
        sag, slope = _sag(s, r)
        safe = np.where(r > 0.0, r, 1.0)
        radial = np.where(r > 0.0, (px * kx + py * ky) / safe, 0.0)
        step = (z0 + t * kz - sag) / (kz - slope * radial)
        t = t - step
        if not np.fmax.reduce(np.abs(step), axis=None) > 1e-9:
            break
    return t


class WavefrontTracer:
    """Wavefronts of one prescription (use :func:`wavefront_tracer` for a cached one).

    Objects are named by their entrance-pupil vergence v = 1/(z_E − z_obj)
    (0 at infinity; :class:`camtool.optics.tracer.RealRayTracer`) and a field
    angle θ seen from the paraxial entrance pupil (the object point at height
    tan θ/v, in the meridian y). Rays start where they cross the first
    vertex plane.

    Examples
    --------
    >>> from camtool.optics.prescription import EXAMPLE_SINGLET, prescription_from_mapping
    >>> tracer = wavefront_tracer(prescription_from_mapping(EXAMPLE_SINGLET))
    >>> film = tracer.rays.summaries([0.0], 16.0).z_best[0]
    >>> wave = tracer.wavefront([0.0], 16.0, film)
    >>> round(float(np.abs(wave.opd_waves).max()), 3)  # spherical aberration at best focus, waves
    0.02
    >>> round(float(tracer.mtf([0.0], 16.0, film, 50.0)[0, 0]), 3)  # at 50 lp/mm; a perfect f/16 lens: 0.424
    0.424
    """

    def __init__(self, prescription: Prescription) -> None:
        self.rays: RealRayTracer = real_tracer(prescription)
        self.first = self.rays.first
        self.surfaces = self.rays.surfaces
        self.to_stop = self.surfaces[: self.rays.stop + 1]
        self.wavelength_mm = prescription.wavelength_nm * 1e-6
        self.n_object = prescription.object_index
        self.n_image = prescription.image_index
        self._aims: dict[float, np.ndarray] = {}

    # -- launching and aiming ----------------------------------------------------------

    def _launch(self, v: Any, tan: Any, ax: Any, ay: Any) -> tuple[Any, ...]:
        """Rays from the object (v, tan θ) through the points (ax, ay) of the entrance-pupil plane.

        Returns the start at z = 0 (x, y), the direction cosines and the
        optical path from the object to the start (less a constant per object).
        """
        z_e = self.first.z_e_mm
        dx, dy = v * ax, v * ay - tan
        q = dx * dx + dy * dy
        root = np.sqrt(1.0 + q)
        scale = 1.0 - v * z_e
        path = self.n_object * scale * (v * (ax * ax + ay * ay) - 2.0 * ay * tan) / (root + np.sqrt(1.0 + tan * tan))
        return ax * scale, ay * scale + z_e * tan, dx / root, dy / root, 1.0 / root, path

    def _at_stop(self, v: Any, tan: Any, ax: Any, ay: Any) -> tuple[Any, Any]:
        """Where rays through (ax, ay) of the entrance-pupil plane meet the stop surface (NaN: void)."""
        x, y, kx, ky, kz, _ = self._launch(v, tan, ax, ay)
        z0: Any = 0.0
        kmin = kz
        before = self.to_stop[:-1]
        if before:
            x, y, z0, kx, ky, kz, _, kmin = _trace3(before, x, y, 0.0, kx, ky, kz)
            z0 = z0 - before[-1].gap
        t = _distance_to(self.to_stop[-1], x, y, z0, kx, ky, kz)
        void = ~(kmin > 0.0)
        return np.where(void, np.nan, x + t * kx), np.where(void, np.nan, y + t * ky)

    def aim(self, v: Any, tan: Any, sx: Any, sy: Any, r_stop: float, guess: Any = None) -> tuple[Any, Any]:
        """Entrance-pupil-plane points of the rays that meet the stop at (sx, sy)·r_stop (Newton's method).

        Arrays broadcast; the Jacobian by finite differences (relative step
        1e-7 of the pupil); ``guess`` the starting η aims of meridional rays
        (default the paraxial m_E·(sx, sy)·r_stop). Stops once a step is below
        1e-10 of the pupil radius: the wavefront's error from the rest is far
        below 1e-6 waves. NaN where the ray cannot reach the stop.
        """
        m_e = self.first.m_e
        tx, ty = sx * r_stop, sy * r_stop
        start_y = ty * m_e if guess is None else guess
        ax, ay = np.broadcast_arrays(np.asarray(tx * m_e, float), np.asarray(start_y, float))
        ax, ay = ax.copy(), ay.copy()
        h = 1e-7 * abs(r_stop * m_e)
        meridian = not np.any(ax)
        with np.errstate(all="ignore"):
            for _ in range(30):
                if meridian:
                    both = self._at_stop(v, tan, 0.0, np.stack([ay, ay + h]))
                    y0, y1 = both[1][0], both[1][1]
                    step_y = (y0 - ty) * h / (y1 - y0)
                    ay = ay - step_y
                    moved = np.abs(step_y)
                else:
                    xs, ys = self._at_stop(v, tan, np.stack([ax, ax + h, ax]), np.stack([ay, ay, ay + h]))
                    fx, fy = xs[0] - tx, ys[0] - ty
                    jxx, jyx = (xs[1] - xs[0]) / h, (ys[1] - ys[0]) / h
                    jxy, jyy = (xs[2] - xs[0]) / h, (ys[2] - ys[0]) / h
                    det = jxx * jyy - jxy * jyx
                    step_x = (fx * jyy - fy * jxy) / det
                    step_y = (fy * jxx - fx * jyx) / det
                    ax, ay = ax - step_x, ay - step_y
                    moved = np.hypot(step_x, step_y)
                if not np.any(moved > 1e-10 * abs(r_stop * m_e) + 1e-13):
                    break
        return ax, ay

    # -- the wavefront -----------------------------------------------------------------

    def _to_image(self, v: Any, tan: Any, ax: Any, ay: Any) -> tuple[Any, ...]:
        """Rays traced through the whole lens: position (absolute z), direction, path; NaN where void."""
        x, y, kx, ky, kz, path0 = self._launch(v, tan, ax, ay)
        x, y, z, kx, ky, kz, path, kmin = _trace3(self.surfaces, x, y, 0.0, kx, ky, kz)
        void = ~(kmin > 0.0) | ~np.isfinite(path)
        out = [np.where(void, np.nan, a) for a in (x, y, z + self.surfaces[-1].z, kx, ky, kz, path + path0)]
        return tuple(out)

    def _sphere_path(self, rays: tuple[Any, ...], centre_x: Any, centre_y: Any, film_z: Any) -> Any:
        """Optical path of each ray to the reference sphere (:meth:`_sphere`)."""
        return self._sphere(rays, centre_x, centre_y, film_z)[0]

    def _sphere(self, rays: tuple[Any, ...], centre_x: Any, centre_y: Any, film_z: Any) -> tuple[Any, Any, Any]:
        """Rays to the reference sphere centred on (x, y, film) through the exit pupil's centre on the axis.

        Returns the optical path of each ray to the sphere and where it
        crosses it, as direction cosines of the line to the centre projected
        on the film (x, y): the canonical pupil coordinates whose differences
        over λ are spatial frequencies on the film. A sphere through an exit
        pupil at infinity (or beyond 1e6 mm) is replaced by one through the
        last vertex.
        """
        x, y, z, kx, ky, kz, path = rays
        axial = film_z - self.first.z_x_mm
        axial = np.where(np.isfinite(axial) & (np.abs(axial) < 1e6), axial, film_z - self.surfaces[-1].z)
        radius = np.sqrt(axial * axial + centre_x * centre_x + centre_y * centre_y)
        qx, qy, qz = x - centre_x, y - centre_y, z - film_z
        dot = qx * kx + qy * ky + qz * kz
        length = np.sqrt(qx * qx + qy * qy + qz * qz)
        excess = (length - radius) * (length + radius)
        sign = np.where(axial > 0.0, -1.0, 1.0)
        t = -dot + sign * np.sqrt(dot * dot - excess)
        return path + self.n_image * t, (qx + t * kx) / radius, (qy + t * ky) / radius

    def _r_stop(self, f_number: float) -> float:
        return self.first.efl_mm / (2.0 * f_number * self.first.m_e)

    def _axial_aims(self, f_number: float) -> np.ndarray:
        """The aims of the radial nodes for an object at infinity: the start of every object's search (one per N).

        The same start whatever was traced before, so an answer never depends on the order of the questions.
        """
        if f_number not in self._aims:
            if len(self._aims) >= 64:
                del self._aims[next(iter(self._aims))]
            with np.errstate(all="ignore"):
                _, ay = self.aim(np.zeros((1, 1)), 0.0, 0.0, _RADII[None, :], self._r_stop(f_number))
            self._aims[f_number] = np.where(np.isfinite(ay), ay, _RADII * self._r_stop(f_number) * self.first.m_e)
        return self._aims[f_number]

    def radial(self, v: Any, f_number: float, film_z: Any, radii: Any = None) -> RadialWave:
        """On the axis: W(ρ²) of objects at pupil vergences v on films ``film_z``, by meridional rays.

        The wavefront of an axial object point is a function of the radius
        alone. It is traced at the :data:`RADIAL_NODES` + 1 Chebyshev–Lobatto
        nodes in ρ² (the chief ray at ρ = 0 and the marginal ray at ρ = 1 among
        them) and kept as the Chebyshev interpolant; the wavefront of a lens
        is smooth in ρ², and against a trace of every radius of the grid the
        difference is below 1e-4 waves on the shipped prescriptions
        (``tests/test_wavefront.py``). ``radii``: trace these radii instead
        (their values in ``coef``, no interpolant).

        Raises
        ------
        Vignetted
            A ray of the beam cannot get through the lens.
        """
        v = np.atleast_1d(np.asarray(v, float))
        film = np.broadcast_to(np.asarray(film_z, float), v.shape)[:, None]
        nodes = _RADII if radii is None else np.asarray(radii, float)
        guess = self._axial_aims(f_number) if radii is None else None
        with np.errstate(all="ignore"):
            _, ay = self.aim(v[:, None], 0.0, 0.0, nodes[None, :], self._r_stop(f_number), guess)
        with np.errstate(all="ignore"):
            traced = self._to_image(v[:, None], 0.0, 0.0, ay)
            total, _, cos_y = self._sphere(traced, 0.0, 0.0, film)
        values = (total - total[:, :1]) / self.wavelength_mm
        if not np.all(np.isfinite(values)):
            raise Vignetted(f"{self.rays._name()}: rays of the f/{f_number:g} beam cannot get through the lens")
        unit = np.abs(cos_y[:, -1]) * self.n_image / self.wavelength_mm
        coef = values if radii is not None else values @ lobatto_matrix(RADIAL_NODES).T
        return RadialWave(coef, unit)

    def axial_mtf(self, v: Any, f_number: float, film_z: Any, frequency_lpmm: float,
                  samples: int = SAMPLES) -> np.ndarray:
        """MTF at ν (lp/mm) of axial objects at pupil vergences v on films ``film_z``, by FFT (one per object).

        :meth:`radial`, then :func:`radial_mtf`.
        """
        return radial_mtf(self.radial(v, f_number, film_z), frequency_lpmm, samples)

    def wavefront(self, v: Any, f_number: float, film_z: Any, field_deg: float = 0.0,
                  step: float | None = None) -> PupilWave:
        """The wavefront over the stop grid of objects at pupil vergences v on films ``film_z``.

        Parameters
        ----------
        v : array
            Entrance-pupil vergences (1/mm, 0 at infinity).
        f_number : float
            Nominal N; the stop radius f/(2·N·m_E).
        film_z : float or array
            Film positions in lens coordinates (mm), one or one per object.
        field_deg : float
            Field angle θ from the axis (degrees, 0 ≤ θ < 90). On the axis the
            grid is filled from :meth:`radial`; off it every grid point is a
            traced skew ray.
        step : float or None
            Grid step in stop radii (default 2/(SAMPLES − 1)).

        Raises
        ------
        Vignetted
            The chief or a marginal ray cannot get through the lens.
        """
        v = np.atleast_1d(np.asarray(v, float))
        film = np.broadcast_to(np.asarray(film_z, float), v.shape)
        step = step or 2.0 / (SAMPLES - 1)
        coords, n = grid(step)
        gx, gy = np.meshgrid(coords, coords)
        rho2 = gx * gx + gy * gy
        inside0 = rho2 <= 1.0 + 1e-12
        if field_deg == 0.0:
            wave = self.radial(v, f_number, film)
            opd = cheb.chebval(2.0 * np.minimum(rho2, 1.0) - 1.0, wave.coef.T)
            inside = np.broadcast_to(inside0, opd.shape)
            lag = np.stack([wave.unit_lpmm, wave.unit_lpmm], axis=1) * step
            return PupilWave(np.where(inside, opd, 0.0), inside, step, lag, np.zeros((v.size, 2)))
        r_stop = self._r_stop(f_number)
        tan = math.tan(math.radians(field_deg))
        vv = v[:, None]
        chief, cx, cy, unit = self._chief(v, f_number, film, field_deg)
        lag = unit * step
        sx, sy = gx[inside0], gy[inside0]
        with np.errstate(all="ignore"):
            ax, ay = self.aim(vv, tan, sx[None, :], sy[None, :], r_stop)
            traced = self._to_image(vv, tan, ax, ay)
            total = self._sphere_path(traced, cx[:, None], cy[:, None], film[:, None])
        values = (total - chief) / self.wavelength_mm
        opd = np.zeros((v.size, n, n))
        inside = np.zeros((v.size, n, n), dtype=bool)
        ok = np.isfinite(values)
        opd[:, inside0] = np.where(ok, values, 0.0)
        inside[:, inside0] = ok
        return PupilWave(opd, inside, step, lag, np.stack([cx, cy], axis=1))

    def _chief(self, v: np.ndarray, f_number: float, film: np.ndarray, field_deg: float) -> tuple[Any, ...]:
        """Off the axis: the chief ray's path to its sphere, where it meets the film, and the frequency units.

        The units (B, 2) are the spatial frequencies of a pupil shift of one
        stop radius along ξ and η: half the difference of the canonical
        coordinates (:meth:`_sphere`) of the opposite marginal rays, projected
        on the flat film, over λ.
        """
        r_stop = self._r_stop(f_number)
        tan = math.tan(math.radians(field_deg))
        vv = v[:, None]
        mx = np.array([0.0, 1.0, -1.0, 0.0, 0.0])  # the chief ray and the marginal rays (±1, 0), (0, ±1)
        my = np.array([0.0, 0.0, 0.0, 1.0, -1.0])
        with np.errstate(all="ignore"):
            ax, ay = self.aim(vv, tan, mx[None, :], my[None, :], r_stop)
            rays = self._to_image(vv, tan, ax, ay)
        x, y, z, kx, ky, kz, path = rays
        if not np.all(np.isfinite(path)):
            raise Vignetted(f"{self.rays._name()}: the chief or a marginal ray of the f/{f_number:g} beam "
                            f"cannot get through the lens {field_deg:g}° off the axis")
        with np.errstate(all="ignore"):
            t_film = (film - z[:, 0]) / kz[:, 0]
        cx, cy = x[:, 0] + t_film * kx[:, 0], y[:, 0] + t_film * ky[:, 0]
        paths, cos_x, cos_y = self._sphere(rays, cx[:, None], cy[:, None], film[:, None])
        unit = np.stack([np.abs(cos_x[:, 1] - cos_x[:, 2]), np.abs(cos_y[:, 3] - cos_y[:, 4])], axis=1)
        unit = unit * self.n_image / (2.0 * self.wavelength_mm)
        return paths[:, :1], cx, cy, unit

    def mtf(self, v: Any, f_number: float, film_z: Any, frequency_lpmm: float, field_deg: float = 0.0,
            samples: int = SAMPLES) -> np.ndarray:
        """MTF at ν (lp/mm) of objects at pupil vergences v on films ``film_z``: (B, 2), sagittal and tangential.

        On the axis both are :meth:`axial_mtf`. Off the axis each object and
        direction gets its own grid, whose step puts ν on a whole lag.
        """
        if field_deg == 0.0:
            value = self.axial_mtf(v, f_number, film_z, frequency_lpmm, samples)
            return np.stack([value, value], axis=1)
        v = np.atleast_1d(np.asarray(v, float))
        film = np.broadcast_to(np.asarray(film_z, float), v.shape)
        nominal = 2.0 / (samples - 1)
        out = np.zeros((v.size, 2))
        for i in range(v.size):
            unit = self._chief(v[i : i + 1], f_number, film[i : i + 1], field_deg)[3][0]
            for k, axis in enumerate((-1, -2)):
                shift = frequency_lpmm / unit[k]
                if not shift < 2.0:
                    continue
                lags = max(1, round(shift / nominal))
                wave = self.wavefront(v[i : i + 1], f_number, film[i : i + 1], field_deg, shift / lags)
                out[i, k] = abs(otf_at_lag(wave.pupil()[0], float(lags), axis))
        return out


def radial_mtf(wave: RadialWave, frequency_lpmm: float, samples: int = SAMPLES) -> np.ndarray:
    """MTF at ν (lp/mm) of axial wavefronts, by FFT of the pupil function on a grid (one value per object).

    For each object the grid step δ ≈ 2/(samples − 1) is adjusted so that
    ν falls on a whole lag K = ν/(δ·ν₁), ν₁ the frequency of a shift of one
    stop radius: the OTF is read at a grid lag, not interpolated. The pupil
    is symmetric about ξ = 0, so the rows η ≥ 0 are transformed, those with
    η > 0 counted twice. 0 at and beyond the cut-off.
    """
    out = np.zeros(wave.unit_lpmm.size)
    nominal = 2.0 / (samples - 1)
    for i in range(out.size):
        shift = frequency_lpmm / wave.unit_lpmm[i]  # the pupil shift in stop radii
        if not shift < 2.0:
            continue
        lags = max(1, round(shift / nominal))
        step = shift / lags
        _, n = grid(step)
        radii2, where, weights = _radii(n)
        rho2 = radii2 * step * step
        phase = cheb.chebval(2.0 * np.minimum(rho2, 1.0) - 1.0, wave.coef[i])
        values = np.where(rho2 <= 1.0 + 1e-12, np.exp(2j * np.pi * phase), 0.0)
        out[i] = abs(otf_at_lag(values[where], float(lags), weights=weights))
    return out


@functools.lru_cache(maxsize=64)
def _radii(n: int) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """An n × n grid about its centre, rows η ≥ 0: the distinct squared radii (grid steps²), each point's
    index among them, and the row weights (1 for η = 0, 2 for the rows that stand for ±η)."""
    index = np.arange(n) - n // 2
    rows = index[n // 2 :]
    key = rows[:, None] ** 2 + index[None, :] ** 2
    unique, inverse = np.unique(key, return_inverse=True)
    weights = np.where(rows == 0, 1.0, 2.0)
    return unique.astype(float), inverse.reshape(key.shape), weights


def _distance_to(s: _Surface, x: Any, y: Any, z0: Any, kx: Any, ky: Any, kz: Any) -> Any:
    """Distance along rays to surface ``s`` (z0 relative to its vertex), no refraction."""
    if s.spherical and s.c == 0.0:
        return -z0 / kz
    if s.spherical:
        c = s.c
        f_term = c * (x * x + y * y + z0 * z0) - 2.0 * z0
        g_term = kz - c * (x * kx + y * ky + z0 * kz)
        return f_term / (g_term + np.sqrt(g_term * g_term - c * f_term))
    return _general_path(s, x, y, z0, kx, ky, kz)


_CACHE: dict[Prescription, WavefrontTracer] = {}


def wavefront_tracer(prescription: Prescription) -> WavefrontTracer:
    """A cached :class:`WavefrontTracer` (the 16 most recent prescriptions)."""
    tracer = _CACHE.get(prescription)
    if tracer is None:
        if len(_CACHE) >= 16:
            del _CACHE[next(iter(_CACHE))]
        tracer = _CACHE[prescription] = WavefrontTracer(prescription)
    return tracer
