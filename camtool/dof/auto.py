"""``auto``: model only what the scene requires.

Before computing, :func:`estimate_effects` says cheaply how much each effect
that a cheaper rung of the ladder leaves out would change the depth of field
of this scene; :func:`choose` then runs the cheapest rung whose left-out
effects add up to no more than the tolerance. The same estimates give every
model's ``error_estimate``.

**Error measure.** The error of a result against a reference is measured in
vergence (1/distance, in the plane the distances are given in), relative to
the reference's depth of field in vergence:

    error = max(|1/near − 1/near_ref|, |1/far − 1/far_ref|) / (1/near_ref − 1/far_ref)

For a shallow depth of field this is the shift of the worse limit divided by
the total depth (Δd/d² over depth/d²); it stays finite when a far limit is
infinite (1/∞ = 0), so a far limit of 2 km against ∞ near the hyperfocal
distance counts as the small error it is. :func:`depth_error` computes it.

**Estimates** (u, v from the principal planes, D from the sensor, H₀ = f²/(N·c),
u_e = min(u, H₀ + f), m = f/(u_e − f), a = N·c·(u_e − f)/f²; a focus beyond the
hyperfocal distance behaves, for the near limit that is left, like one at it):

- approximation (``approx`` neglects f against s): m/2;
- distance plane (``approx`` takes a distance from the sensor as one from the
  lens): ((u_e + v + δ)/u_e)² − 1 ≈ 2(v + δ)/D;
- pupil magnification: |e|·(1 + a)/(2u_e)·(1 + 1.5|e|/u_e), e = f(1 − 1/P),
  ≈ |1 − 1/P|·m;
- hiatus (from the sensor): |δ|/(2a·u_e)·max(|(1 + m²)(1 ± a)² − 1|), ≈ |δ|/D;
- diffraction: 1 − √(1 − (b_airy/c)²) ≈ (b_airy/c)²/2;
- aberrations (real against paraxial rays, only with a prescription): the
  relative change of the local depth of field in object vergence between
  real and paraxial rays, 2√2·S·dz_best/dw against 2·u′·dz′/dw, measured
  once per prescription and f-number (one batched fan trace, cached) at a few
  magnifications, times (1 + m), and interpolated.

These are first-order results of the closed forms (the first four are within a
few per cent of the exact differences over the whole domain); the aberration
estimate is about twice the actual difference on the shared lenses.
"""

from __future__ import annotations

import functools
import itertools
import math
from typing import Any, NamedTuple

from camtool.core.arrays import ops, quiet
from camtool.dof.rungs import RUNGS, by_name

__all__ = ["EFFECTS", "LEFT_OUT", "Effects", "aberration_share", "depth_error", "estimate_effects", "left_out"]

EFFECTS = ("approximation", "distance_plane", "pupil", "hiatus", "diffraction", "aberrations")

LEFT_OUT = {rung.name: rung.left_out for rung in RUNGS}
"""The geometric effects each rung leaves out (diffraction is left out unless the add-on runs); from the rung records."""

_ABERRATION_MAGNIFICATIONS = (0.0, 0.05, 0.15, 0.35, 0.7, 1.0)


class Effects(NamedTuple):
    """Estimated relative change of the depth of field by each effect (see the module docstring)."""

    approximation: Any
    distance_plane: Any
    pupil: Any
    hiatus: Any
    diffraction: Any
    aberrations: Any


def left_out(effects: Effects, model: str, diffraction_applied: bool) -> Any:
    """Estimated relative error of ``model``: the sum of the effects it leaves out.

    Examples
    --------
    >>> e = Effects(0.01, 0.02, 0.003, 0.001, 0.004, 0.0)
    >>> round(left_out(e, "thin", False), 6)
    0.008
    >>> round(left_out(e, "thin", True), 6)
    0.004
    """
    total: Any = 0.0 if diffraction_applied else effects.diffraction
    for name in by_name()[model].left_out:
        total = total + getattr(effects, name)
    return total


def estimate_effects(
    focal_length_mm: Any,
    f_number: Any,
    coc_mm: Any,
    distance_mm: Any,
    distance_from: str = "sensor",
    pupil_magnification: Any = 1.0,
    hiatus_mm: Any = 0.0,
    airy_mm: Any = 0.0,
    prescription: Any = None,
    geometry: Any = None,
) -> Effects:
    """Estimate, before computing, how much each effect changes this scene's depth of field.

    Parameters
    ----------
    focal_length_mm, f_number, coc_mm : float or array, all > 0
    distance_mm : float or array
        Focus distance from ``distance_from`` (``inf`` allowed).
    distance_from : ``"sensor"`` or ``"lens"``
    pupil_magnification, hiatus_mm : float or array
        The lens's P and δ (1 and 0 when unknown).
    airy_mm : float or array
        Airy diameter at the focus when diffraction is asked for, else 0.
    prescription : Prescription or None
        Enables the aberration estimate.
    geometry : FocusGeometry or None
        ``focus_geometry(f, distance_mm, distance_from, hiatus_mm)`` when the
        caller has it (the conversion is then not repeated).

    Returns
    -------
    Effects
        Relative errors in the measure of :func:`depth_error`.

    Examples
    --------
    50 mm f/8 at 3 m from the sensor: neglecting f costs about 1 %, the
    distance plane about 4 %:

    >>> e = estimate_effects(50.0, 8.0, 0.03, 3000.0)
    >>> round(e.approximation, 4), round(e.distance_plane, 4), e.pupil
    (0.0086, 0.0348, 0.0)
    """
    from camtool.dof.diffraction import diffraction_share
    from camtool.geometry.thinlens import focus_geometry

    f, nc, p, delta = focal_length_mm, f_number * coc_mm, pupil_magnification, hiatus_mm
    xp = ops(f, f_number, coc_mm, distance_mm, p, delta, airy_mm)
    if geometry is None:
        geometry = focus_geometry(f, distance_mm, distance_from, delta)
    with quiet(xp):
        u_e = xp.minimum(geometry.object_mm, f * f / nc + f)
        w = u_e - f
        m = f / w
        a = nc * w / (f * f)
        approximation = 0.5 * m
        e = xp.fabs(f - f / p)
        pupil = e * (1.0 + a) / (2.0 * u_e) * (1.0 + 1.5 * e / u_e)
        if distance_from == "sensor":
            ratio = (u_e + geometry.image_mm + delta) / u_e
            plane = ratio * ratio - 1.0
            grow = (1.0 + m * m) * (1.0 + a) * (1.0 + a) - 1.0
            shrink = xp.where(a < 1.0, xp.fabs((1.0 + m * m) * (1.0 - a) * (1.0 - a) - 1.0), 0.0)
            hiatus = xp.fabs(delta) / (2.0 * a * u_e) * xp.maximum(xp.fabs(grow), shrink)
        else:
            plane = hiatus = 0.0 * m
        diffraction = diffraction_share(coc_mm, airy_mm)
    aberrations = 0.0 * m if prescription is None else aberration_share(prescription, f_number, m)
    return Effects(approximation, plane, pupil, hiatus, diffraction, aberrations)


def aberration_share(prescription: Any, f_number: Any, magnification: Any) -> Any:
    """Estimated relative difference between the real-ray and the paraxial depth of field.

    Interpolates, in magnification, the calibration of
    :func:`_aberration_table` (cached per prescription and f-number).

    Examples
    --------
    >>> from camtool.optics.prescription import EXAMPLE_SINGLET, prescription_from_mapping
    >>> lens = prescription_from_mapping(EXAMPLE_SINGLET)
    >>> aberration_share(lens, 2.8, 0.0) > aberration_share(lens, 16.0, 0.0)
    True
    """
    xp = ops(f_number, magnification)
    if xp.name == "math":
        return _interpolate(_aberration_table(prescription, float(f_number)), float(magnification))
    import numpy as np

    n, m = np.broadcast_arrays(np.asarray(f_number, float), np.asarray(magnification, float))
    out = np.empty(n.shape)
    for value in np.unique(n):
        table = _aberration_table(prescription, float(value))
        mask = n == value
        ms, shares = zip(*table)
        out[mask] = np.interp(np.where(np.isfinite(m[mask]), m[mask], ms[-1]), ms, shares)
    return out


def _interpolate(table: tuple[tuple[float, float], ...], m: float) -> float:
    """Piecewise-linear interpolation in m; the last value beyond the table."""
    if not math.isfinite(m):
        return table[-1][1]
    for (m0, s0), (m1, s1) in itertools.pairwise(table):
        if m <= m1:
            return s0 + (s1 - s0) * max(m - m0, 0.0) / (m1 - m0)
    return table[-1][1]


@functools.lru_cache(maxsize=256)
def _aberration_table(prescription: Any, f_number: float) -> tuple[tuple[float, float], ...]:
    """(magnification, |real/paraxial − 1|) of the local depth of field in object vergence.

    At a few magnifications m (objects at vertex vergence w), with a
    neighbouring object at w + dw: the real rays' 2√2·S·dz_best/dw (S the RMS
    slope, z_best the minimum-RMS focus) against the paraxial marginal ray's
    2·|u′|·dz′/dw through the stop edge. Their ratio is the ratio of the
    depths of field in vergence (the limits are where the blur, proportional
    to these, reaches c). Magnifications the real rays cannot reach are left
    out; if none can be traced the estimate is 1 (everything uncertain).
    """
    from camtool.optics.paraxial import first_order, paraxial_trace
    from camtool.optics.tracer import RayTraceError, real_tracer

    fo = first_order(prescription)
    f = fo.efl_mm
    ws, ms = [], []
    for m in _ABERRATION_MAGNIFICATIONS:
        w = 0.0 if m == 0.0 else 1.0 / (f * (1.0 + m) / m - fo.z_h_mm)
        if w < 0.0:
            continue
        dw = max(w, 1.0 / f) * 1e-4
        ws += [w, w + dw]
        ms.append(m)
    try:
        summary = real_tracer(prescription).summaries(ws, f_number)
    except RayTraceError:
        return ((0.0, 1.0), (1.0, 1.0))
    stop = prescription.stop_index
    a, _ = paraxial_trace(prescription, 1.0, 0.0, stop=stop)
    b, _ = paraxial_trace(prescription, 0.0, 1.0, stop=stop)
    ya, nua = paraxial_trace(prescription, 1.0, 0.0)
    yb, nub = paraxial_trace(prescription, 0.0, 1.0)
    z_k, r_stop = prescription.vertices_mm[-1], fo.stop_radius_mm(f_number)

    def paraxial_image(w: float) -> tuple[float, float]:
        h = r_stop / (a + b * w)
        y_k, nu_k = h * (ya + w * yb), h * (nua + w * nub)
        return z_k - y_k / nu_k, abs(nu_k)

    table = []
    for i, m in enumerate(ms):
        w0, w1 = ws[2 * i], ws[2 * i + 1]
        z0, slope = paraxial_image(w0)
        z1, _ = paraxial_image(w1)
        real = 2.0 * math.sqrt(2.0) * float(summary.slope_rms[2 * i]) * float(summary.z_best[2 * i + 1] - summary.z_best[2 * i])
        first = 2.0 * slope * (z1 - z0)
        share = abs(real / first - 1.0)
        # (1 + m): at close range the real focus shift adds about as much again (shared lenses)
        table.append((m, share * (1.0 + m) if math.isfinite(share) else 1.0))
    if len(table) == 1:
        table.append((1.0, table[0][1]))
    return tuple(table)


def depth_error(limits: Any, reference: Any) -> Any:
    """Relative error of ``limits`` against ``reference`` in vergence (see the module docstring).

    Parameters
    ----------
    limits, reference : DofLimits
        In the same distance plane; far limits may be infinite.

    Examples
    --------
    >>> from camtool.dof.closed import approx_dof, thin_dof
    >>> round(depth_error(approx_dof(50.0, 8.0, 0.03, 3000.0), thin_dof(50.0, 8.0, 0.03, 3000.0, "lens")), 4)
    0.0085
    """
    xp = ops(limits.near_mm, limits.far_mm, reference.near_mm, reference.far_mm)
    with quiet(xp):
        near, far = 1.0 / limits.near_mm, 1.0 / limits.far_mm
        near_ref, far_ref = 1.0 / reference.near_mm, 1.0 / reference.far_mm
        return xp.maximum(xp.fabs(near - near_ref), xp.fabs(far - far_ref)) / (near_ref - far_ref)
