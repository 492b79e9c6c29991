"""The ``raytrace`` rung: depth of field solved on real rays through a prescription.

- **Focus**: the object whose best-focus film plane lies at the focus
  distance behind it; the film then stays put. Near and far limits are the
  object distances where the blur on that film reaches c, found by
  bracketing in object vergence and Brent's method.

The rays themselves are traced by :mod:`camtool.optics.tracer`.
"""


from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any

import numpy as np

from camtool.core.arrays import is_scalar
from camtool.core.errors import DomainError, require_positive
from camtool.core.planes import check_plane
from camtool.dof.limits import DofLimits
from camtool.optics.paraxial import FirstOrder
from camtool.optics.prescription import Prescription
from camtool.optics.roots import brent_steps, solve_lockstep
from camtool.optics.tracer import (
    _SQRT8,
    CRITERIA,
    RayTraceError,
    RealRayTracer,
    real_tracer,
)

__all__ = ["NoDepthOfField", "RealFocus", "raytrace_dof", "real_focus"]

_ROOT_RTOL = 1e-12


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


_Result = tuple[float, float, float]  # (z_best, slope_rms, best_blur) of one object point
_Bracket = tuple[float, float, float, float]


class _Scene:
    """One lens at one f-number: batched, cached fan evaluations per vertex vergence."""

    def __init__(self, tracer: RealRayTracer, f_number: float, criterion: str) -> None:
        self.tracer, self.f_number, self.criterion = tracer, f_number, criterion
        self._cache: dict[float, _Result] = {}
        self._planned: set[float] = set()
        self._edge_ratio: dict[float, float] = {}  # w → real/paraxial edge height (warm starts)

    def plan(self, ws: list[float]) -> None:
        """Have the next :meth:`evaluate` trace these vergences too (one batch instead of two)."""
        self._planned.update(ws)

    def evaluate(self, ws: list[float]) -> list[_Result]:
        """Results for each vergence, tracing all new (and planned) ones in one batch."""
        new = sorted({w for w in (*ws, *self._planned) if w not in self._cache})
        self._planned.clear()
        if new:
            s = self.tracer.summaries(new, self.f_number, self._edge_guess(new))
            paraxial = self.tracer.paraxial_edge_heights(new, self.f_number)
            self._edge_ratio.update(zip(new, (s.edge_mm / paraxial).tolist()))
            for i, w in enumerate(new):
                self._cache[w] = (float(s.z_best[i]), float(s.slope_rms[i]), float(s.best_blur[i]))
        return [self._cache[w] for w in ws]

    def _edge_guess(self, ws: list[float]) -> np.ndarray | None:
        """Edge-ray heights interpolated from the ones already solved (None before the first)."""
        if not self._edge_ratio:
            return None
        known = sorted(self._edge_ratio)
        ratio = np.interp(ws, known, [self._edge_ratio[w] for w in known])
        return ratio * self.tracer.paraxial_edge_heights(ws, self.f_number)

    def blur(self, result: _Result, z_film: float) -> float:
        """The criterion's blur diameter in mm on a film at z_film."""
        z_best, slope, best = result
        defocus = _SQRT8 * abs(z_film - z_best) * slope
        return defocus if self.criterion == "defocus" else math.hypot(defocus, best)

    def own_blur(self, result: _Result) -> float:
        """The criterion's blur in mm on the object's own best-focus plane."""
        return 0.0 if self.criterion == "defocus" else result[2]

    def bracket(self, candidates: list[float], value: Any) -> _Bracket | None:
        """First sign change of ``value(result, w)`` along ``candidates`` (already evaluated or not)."""
        values = [value(r, w) for r, w in zip(self.evaluate(candidates), candidates)]
        for (wa, fa), (wb, fb) in zip(zip(candidates, values), zip(candidates[1:], values[1:])):
            if math.isfinite(fa) and math.isfinite(fb) and (fa > 0.0) != (fb > 0.0):
                return wa, fa, wb, fb
        return None

    def refine(self, jobs: list[tuple[_Bracket, Any]]) -> list[float]:
        """Brent's method in each bracket, all roots advancing in lockstep (one batch per round)."""
        problems = [
            (brent_steps(wa, fa, wb, fb, _ROOT_RTOL * max(abs(wa), abs(wb))), _pair(value))
            for (wa, fa, wb, fb), value in jobs
        ]
        return solve_lockstep(lambda ws: list(zip(self.evaluate(list(ws)), ws)), problems)


def _pair(value: Any) -> Any:
    """Adapt ``value(result, w)`` to the (result, w) pairs :meth:`_Scene.refine` evaluates."""
    return lambda pair: value(pair[0], pair[1])


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


def _vergence(z_obj: float) -> float:
    """Vertex vergence w = −1/z_obj of an object at z_obj < 0 (0 at infinity)."""
    return 0.0 if math.isinf(z_obj) else -1.0 / z_obj


def _pupil_steps(fo: FirstOrder, w_from: float, delta: float, factors: tuple[float, ...]) -> list[float]:
    """Vertex vergences of objects whose entrance-pupil vergence is V(w_from) + delta·q, q in factors.

    Candidates behind the first vertex (or beyond infinity) are left out.
    """
    v_from = w_from / (1.0 + w_from * fo.z_e_mm)  # vergence seen from the entrance pupil
    out = []
    for q in factors:
        v = max(v_from + delta * q, 0.0)
        denominator = 1.0 - v * fo.z_e_mm
        if denominator > 0.0:
            out.append(v / denominator)
    return out


_NEAR_FACTORS = (0.5, 0.8, 0.9, 0.97, 1.03, 1.1, 1.25, 1.6, 2.5, 4.0)


def _focus_candidates(fo: FirstOrder, distance_mm: float, spread: float) -> list[float]:
    """Vertex vergences around the paraxial focused object (relative spread), with infinity first."""
    f = fo.efl_mm
    span = distance_mm - fo.hiatus_mm
    u = 0.5 * span * (1.0 + math.sqrt(1.0 - 4.0 * f / span))
    w0 = 1.0 / (u - fo.z_h_mm)
    return [0.0] + [w0 * (1.0 + spread * q) for q in (-1.0, -0.5, 0.0, 0.5, 1.0)]


_FOCUS_SPREADS = (0.01, 0.05, 0.2, 0.5)


def _focus_problem(scene: _Scene, fo: FirstOrder, distance_mm: float) -> tuple[_Bracket, Any]:
    """Bracket and function for the object whose best focus lies distance_mm behind it (sensor plane)."""
    f = fo.efl_mm
    span = distance_mm - fo.hiatus_mm
    if not span >= 4.0 * f:
        raise DomainError(
            "distance_mm", distance_mm, f"at least {4.0 * f + fo.hiatus_mm:.6g} mm from the sensor (1:1, the closest focus)"
        )

    def mismatch(result: _Result, w: float) -> float:
        return w * (result[0] - distance_mm) + 1.0  # zero where z_best − z_obj = D

    for spread in _FOCUS_SPREADS:
        found = scene.bracket(_focus_candidates(fo, distance_mm, spread), mismatch)
        if found is not None:
            return found, mismatch
    raise DomainError("distance_mm", distance_mm, "a distance this lens can focus on by real rays (too close)")


def _hyperfocal_candidates(fo: FirstOrder, f_number: float, coc_mm: float) -> list[float]:
    """Vertex vergences around the paraxial hyperfocal object, from infinity to at most 1:1."""
    f = fo.efl_mm
    u_hyp = f * f / (f_number * coc_mm) + f
    w_closest = 1.0 / (2.0 * f - fo.z_h_mm)
    w_hyp = 1.0 / (u_hyp - fo.z_h_mm) if u_hyp > 2.0 * f else w_closest
    return [0.0, *sorted({min(w_hyp * q, w_closest) for q in (0.5, 0.8, 0.95, 1.0, 1.05, 1.25, 2.0, 4.0)})]


def _hyperfocal_problem(scene: _Scene, fo: FirstOrder, coc_mm: float) -> tuple[_Bracket, Any] | float:
    """Bracket and function for the hyperfocal object, or its vergence when no root search is needed.

    The hyperfocal film plane z_H,film is where the object at infinity blurs
    by exactly c (on the far side of its best focus); the hyperfocal object
    is the one focused there. Returns ``-1.0`` when no focus makes infinity
    sharp (rms: the lens's own blur at infinity reaches c) and ``inf`` when
    every focus down to 1:1 does.
    """
    z_best, slope, best = scene.evaluate([0.0])[0]
    allowance = coc_mm if scene.criterion == "defocus" else coc_mm * coc_mm - best * best
    if allowance <= 0.0:
        return -1.0
    if scene.criterion == "rms":
        allowance = math.sqrt(allowance)
    z_film = z_best + allowance / (_SQRT8 * slope)

    def behind(result: _Result, w: float) -> float:
        return result[0] - z_film

    found = scene.bracket(_hyperfocal_candidates(fo, scene.f_number, coc_mm), behind)
    return (found, behind) if found is not None else math.inf


def _limit_problems(
    scene: _Scene, fo: FirstOrder, coc_mm: float, w_focus: float, z_film: float
) -> tuple[tuple[_Bracket, Any], tuple[_Bracket, Any] | None]:
    """Brackets for the near and far limits (far: ``None`` when infinity is within c)."""

    def excess(result: _Result, w: float) -> float:
        return scene.blur(result, z_film) - coc_mm

    # paraxial spacing of the limits in entrance-pupil vergence: Δ = N·c·(u − f)/(x·f²)
    f = fo.efl_mm
    ratio = 1.0 if w_focus == 0.0 else (1.0 + w_focus * (fo.z_h_mm - f)) / (1.0 + w_focus * fo.z_e_mm)
    delta = scene.f_number * coc_mm * ratio / (f * f)
    far = None
    near_candidates = [w_focus, *_pupil_steps(fo, w_focus, delta, _NEAR_FACTORS)]
    if excess(scene.evaluate([0.0])[0], 0.0) > 0.0:
        candidates = [w_focus, *_pupil_steps(fo, w_focus, -delta, _NEAR_FACTORS), 0.0]
        scene.plan(near_candidates)
        found = scene.bracket(candidates, excess)
        assert found is not None  # excess < 0 at the focus, > 0 at infinity
        far = (found, excess)
    factors: tuple[float, ...] = _NEAR_FACTORS
    for _ in range(60):
        found = scene.bracket(near_candidates, excess)
        if found is not None:
            return (found, excess), far
        factors = tuple(q * 4.0 for q in factors[-3:])
        near_candidates = [w_focus, *_pupil_steps(fo, w_focus, delta, factors)]
    raise RayTraceError(f"{scene.tracer._name()}: no near limit in front of the lens")


def real_focus(
    prescription: Prescription,
    f_number: float,
    distance_mm: float,
    distance_from: str = "sensor",
    criterion: str = "defocus",
) -> RealFocus:
    """Focused object and film position of a prescription by real rays, in mm.

    From the sensor, the object is the one whose best-focus (minimum-RMS)
    plane lies ``distance_mm`` behind it, solved by Brent's method in object
    vergence from the paraxial solution; from the lens (front principal
    plane H) or the entrance pupil the object position is given directly.

    Parameters
    ----------
    prescription : Prescription
        Object and image space in air.
    f_number : float
        Nominal N > 0; fixes the stop radius r_stop = f/(2·N·m_E).
    distance_mm : float
        Focus distance > 0 (``inf`` allowed) from ``distance_from``
        (``"sensor"``, ``"lens"`` or ``"entrance_pupil"``).
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
    scene = _Scene(real_tracer(prescription), float(f_number), criterion)
    fo = scene.tracer.first
    w = _solve_focus(scene, fo, float(distance_mm), distance_from)
    return _real_focus(scene, fo, w)


def _solve_focus(scene: _Scene, fo: FirstOrder, distance_mm: float, distance_from: str, extra: Any = None) -> Any:
    """Vertex vergence of the focused object (and the roots of ``extra`` jobs, solved alongside)."""
    jobs = list(extra or [])
    if math.isinf(distance_mm):
        w = 0.0
    elif distance_from == "sensor":
        jobs.insert(0, _focus_problem(scene, fo, distance_mm))
        w = None
    else:
        z_ref = fo.z_h_mm if distance_from == "lens" else fo.z_e_mm
        z_obj = z_ref - distance_mm
        if not z_obj < 0.0 or not (distance_from != "lens" or distance_mm >= 2.0 * fo.efl_mm):
            raise DomainError("distance_mm", distance_mm, "an object in front of the lens, at least 1:1 away")
        w = _vergence(z_obj)
    roots = scene.refine(jobs) if jobs else []
    if w is None:
        w = roots.pop(0)
    return (w, roots) if extra is not None else w


def _real_focus(scene: _Scene, fo: FirstOrder, w: float) -> RealFocus:
    """Assemble the RealFocus of the object at vertex vergence w."""
    result = scene.evaluate([w])[0]
    z_film = result[0]
    z_obj = -math.inf if w == 0.0 else -1.0 / w
    f = fo.efl_mm
    magnification = f * w / (1.0 + w * (fo.z_h_mm - f))  # f/(u − f), u = z_H − z_obj
    return RealFocus(
        object_z_mm=z_obj,
        film_z_mm=z_film,
        distance_mm=z_film - z_obj,
        blur_mm=scene.own_blur(result),
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

    found by bracketing in object vergence and Brent's method (near and far
    in lockstep). far = ∞ when an object at infinity is still within c. The
    hyperfocal distance is the focus whose far limit is at infinity.

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
        principal plane H) or ``"entrance_pupil"`` (the paraxial E).
    distance_from : str
    criterion : ``"defocus"`` (default) or ``"rms"``

    Returns
    -------
    DofLimits
        In the plane of ``distance_mm``; arrays (one trace per element) for
        array input.

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
    Derivatives* (1973).

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
    scene = _Scene(real_tracer(prescription), float(f_number), criterion)
    fo = scene.tracer.first
    coc = float(coc_mm)
    scene.plan(_hyperfocal_candidates(fo, scene.f_number, coc))
    if distance_from == "sensor" and math.isfinite(distance_mm) and distance_mm - fo.hiatus_mm >= 4.0 * fo.efl_mm:
        scene.plan(_focus_candidates(fo, float(distance_mm), _FOCUS_SPREADS[0]))
    hyper = _hyperfocal_problem(scene, fo, coc)
    extra = [hyper] if isinstance(hyper, tuple) else []
    w_focus, roots = _solve_focus(scene, fo, float(distance_mm), distance_from, extra)
    focus = _real_focus(scene, fo, w_focus)
    if focus.blur_mm >= coc:
        raise NoDepthOfField(coc, focus.blur_mm)
    near_job, far_job = _limit_problems(scene, fo, coc, w_focus, focus.film_z_mm)
    limits = scene.refine([near_job] + ([far_job] if far_job else []))
    w_near, w_far = limits[0], (limits[1] if far_job else 0.0)
    z_ref = {"sensor": focus.film_z_mm, "lens": fo.z_h_mm, "entrance_pupil": fo.z_e_mm}[distance_from]
    focus_mm = float(distance_mm)
    front = math.inf if w_focus == 0.0 else (w_near - w_focus) / (w_near * w_focus)
    near = z_ref + 1.0 / w_near if w_focus == 0.0 else focus_mm - front
    rear = math.inf if w_far == 0.0 else (w_focus - w_far) / (w_focus * w_far)
    far = focus_mm + rear
    hyperfocal = _hyperfocal_distance(scene, fo, hyper, roots, distance_from)
    return DofLimits(near, far, front, rear, front + rear, hyperfocal, focus.magnification)


def _hyperfocal_distance(scene: _Scene, fo: FirstOrder, hyper: Any, roots: list[float], distance_from: str) -> float:
    """Hyperfocal distance in the requested plane from the solved hyperfocal object."""
    if not isinstance(hyper, tuple):
        if hyper < 0.0:
            return math.inf  # infinity is never within c
        f = fo.efl_mm  # every focus down to 1:1 keeps infinity sharp: the closest focus
        return {"sensor": 4.0 * f + fo.hiatus_mm, "lens": 2.0 * f, "entrance_pupil": 2.0 * f - fo.z_h_mm + fo.z_e_mm}[
            distance_from
        ]
    w = roots[0]
    z_film = scene.evaluate([w])[0][0]
    z_ref = {"sensor": z_film, "lens": fo.z_h_mm, "entrance_pupil": fo.z_e_mm}[distance_from]
    return z_ref + 1.0 / w


def _raytrace_many(
    prescription: Prescription, f_number: Any, coc_mm: Any, distance_mm: Any, distance_from: str, criterion: str
) -> DofLimits:
    """Element-wise :func:`raytrace_dof` over broadcast arrays."""
    n, c, d = np.broadcast_arrays(*(np.asarray(v, float) for v in (f_number, coc_mm, distance_mm)))
    rows = [
        raytrace_dof(prescription, float(a), float(b), float(e), distance_from, criterion)
        for a, b, e in zip(n.flat, c.flat, d.flat)
    ]
    return DofLimits(*(np.array(column, float).reshape(n.shape) for column in zip(*rows)))
