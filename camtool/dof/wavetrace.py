"""The ``wave`` rung with a prescription: depth of field by contrast from the real lens's wavefront.

The lens is focused as the ``raytrace`` rung focuses it (:func:`camtool.dof.realray.real_focus`:
the fixed stop of the nominal f-number, unit focusing, the film at the real
best focus of the focused object), and the film stays there. An object point
at another distance is imaged with the wavefront the real rays give it on
that film (:mod:`camtool.optics.wavefront`: the optical path difference over
the stop, relative to the sphere centred on the chief ray's point on the
film), and its MTF at the criterion's frequency comes from the pupil function
by FFT. The near and far limits are the object distances, either side of the
focus, at which that MTF first falls to the criterion's level: diffraction,
defocus and the lens's own aberrations together.

**Search.** In the object's entrance-pupil vergence v = 1/(z_E − z_obj)
(0 at infinity). The step is set by the perfect lens of the same aperture
(Δv = 8·λ·W*/A², :mod:`camtool.dof.wave`); one batch of objects at multiples
of it either side of the focus brackets the first crossing on each side, and
the Illinois variant of regula falsi, both sides in one batch per step,
narrows it to 1e-7 of the step. The hyperfocal distance is the focus whose far
limit is at infinity: the film position behind the infinity focus where an
object at infinity falls to the level (the same search along the film), and
the object focused on that film; far = ∞ exactly when the film of the focus
lies in front of it (the focus at or beyond H).

**Errors.** Nothing sharp at the focus (its own MTF below the level) is a
:class:`camtool.dof.wave.ContrastUnreachable`-like :class:`NothingSharpHere`
on ``f_number``; rays that cannot get through the lens a
:class:`camtool.optics.tracer.RayTraceError`.
"""

from __future__ import annotations

import math
from typing import Any

import numpy as np

from camtool.core.arrays import is_scalar
from camtool.core.errors import DomainError, require_positive
from camtool.dof.limits import DofLimits
from camtool.dof.wave import DEFAULT_CRITERION, ContrastOptimum, ContrastUnreachable, Criterion, criterion_frequency
from camtool.optics.roots import golden_section

__all__ = ["NothingSharpHere", "prescription_contrast_optimum", "prescription_wave_dof"]

_GROWTH = (0.5, 0.85, 1.2, 1.7, 2.5, 4.0, 7.0, 12.0, 25.0)
"""Multiples of the perfect lens's vergence step at which the first batch looks for the crossings."""

_ROUNDS = 40
_TOLERANCE = 1e-7


class NothingSharpHere(ContrastUnreachable):
    """Even the focused object's MTF at the criterion's frequency is below the level: nothing is sharp enough.

    A :class:`camtool.dof.wave.ContrastUnreachable` whose ``largest_f_number``
    is unknown (None): a real lens's contrast need not fall as it stops down.
    """

    def __init__(self, f_number: float, criterion: Criterion, frequency_lpmm: float, mtf: float, name: str) -> None:
        self.mtf = mtf
        self.largest_f_number = None  # type: ignore[assignment]
        self.criterion = criterion
        DomainError.__init__(
            self,
            "f_number", f_number, f"an f-number at which {name} in focus meets {criterion.label()}",
            detail=f"nothing is sharp enough: in focus the MTF of {name} at {frequency_lpmm:.3g} lp/mm is "
                   f"{mtf:.3g}, below {criterion.level:.3g}",
        )


def prescription_wave_dof(prescription: Any, f_number: Any, coc_mm: Any, distance_mm: Any,
                          distance_from: str = "sensor", criterion: Criterion | None = None,
                          field_deg: float = 0.0) -> DofLimits:
    """Near and far limits where a prescription's MTF at the criterion's frequency falls to its level (mm).

    Parameters
    ----------
    prescription : camtool.optics.prescription.Prescription
        Object and image space in air; computed at its ``wavelength_nm``.
    f_number : float or array
        Nominal N > 0 (the fixed stop f/(2·N·m_E)).
    coc_mm : float or array
        c > 0: sets the frequency of an ``@coc`` criterion (ν = 1/c).
    distance_mm : float or array
        Focus distance (``inf`` allowed) from ``distance_from`` (``"sensor"``,
        ``"lens"`` or ``"entrance_pupil"``), as for ``raytrace``.
    criterion : Criterion or None
        None: :data:`camtool.dof.wave.DEFAULT_CRITERION`.
    field_deg : float
        The object point's angle from the axis, seen from the entrance pupil
        (0: on the axis); off the axis the worse of the sagittal and the
        tangential MTF counts.

    Returns
    -------
    DofLimits
        In the plane of ``distance_mm``; arrays for array input.

    Raises
    ------
    NothingSharpHere
        The MTF at the focus is already below the level.
    DomainError
        N, c or the distance out of range; a focus closer than the lens can.
    RayTraceError
        Rays of the beam cannot get through the lens.

    Examples
    --------
    >>> from camtool.optics.prescription import EXAMPLE_SINGLET, prescription_from_mapping
    >>> lens = prescription_from_mapping(EXAMPLE_SINGLET)
    >>> r = prescription_wave_dof(lens, 8.0, 0.03, 3000.0)
    >>> round(r.near_mm), round(r.far_mm)
    (2854, 3349)
    """
    if not all(is_scalar(v) for v in (f_number, coc_mm, distance_mm)):
        ns, cs, ds = np.broadcast_arrays(*(np.asarray(v, float) for v in (f_number, coc_mm, distance_mm)))
        rows = [prescription_wave_dof(prescription, float(a), float(b), float(e), distance_from, criterion,
                                      field_deg) for a, b, e in zip(ns.flat, cs.flat, ds.flat)]
        return DofLimits(*(np.array(column, float).reshape(ns.shape) for column in zip(*rows)))
    from camtool.dof.realray import _check_scene, closest_focus_mm, focus_for_film, limits_from_vergences, real_focus
    from camtool.optics.transfer import defocus_at_level
    from camtool.optics.wavefront import radial_mtf, wavefront_tracer

    _check_scene(prescription, f_number, distance_mm, distance_from, "defocus")
    require_positive("coc_mm", coc_mm)
    if not 0.0 <= field_deg < 89.0:
        raise DomainError("field_deg", field_deg, "from 0 to 89°")
    criterion = criterion or DEFAULT_CRITERION
    n_f, nu = float(f_number), float(criterion_frequency(criterion, float(coc_mm)))
    level = criterion.level
    tracer = wavefront_tracer(prescription)
    fo = tracer.first
    name = tracer.rays._name()
    focus = real_focus(prescription, n_f, float(distance_mm), distance_from)
    film = focus.film_z_mm
    v_focus = 0.0 if math.isinf(focus.object_z_mm) else 1.0 / (fo.z_e_mm - focus.object_z_mm)
    v_max = 1.0 / closest_focus_mm(prescription, n_f, "entrance_pupil")
    key = (prescription, n_f, nu, field_deg, level)
    find_h = key not in _HYPERFOCAL_FILM
    film_inf = real_focus(prescription, n_f, math.inf, "lens").film_z_mm

    def mtf(vs: Any, films: Any) -> np.ndarray:
        """The criterion's MTF (the worse direction off the axis) of objects at vergences vs on films."""
        return np.min(tracer.mtf(np.asarray(vs, float), n_f, np.asarray(films, float), nu, field_deg), axis=1)

    # the focused object, and the object at infinity on its own film (for the hyperfocal distance)
    wave = tracer.radial([v_focus, 0.0], n_f, [film, film_inf])
    first = radial_mtf(wave, nu) if field_deg == 0.0 else mtf([v_focus, 0.0], [film, film_inf])
    at_focus = float(first[0])
    if not at_focus > level:
        raise NothingSharpHere(n_f, criterion, nu, at_focus, name)
    lam = tracer.wavelength_mm

    def steps(unit: float) -> tuple[float, float]:
        """The perfect lens's W* at s = ν·λ·N_w, and as a shift of the object's vergence and of the film.

        W₂₀ = A²·Δv/(8λ) in object space, Δz = 8·λ·W*·N_w² with N_w = 1/(2 sin U′) on the film."""
        w_star = defocus_at_level(min(nu / (2.0 * unit), 0.999), level)
        w_star = w_star if math.isfinite(w_star) and w_star > 0.0 else 0.25
        sin_u = min(unit * lam, 0.999)
        return 8.0 * lam * w_star / (fo.efl_mm / n_f) ** 2, 2.0 * lam * w_star / (sin_u * sin_u)

    dv, _ = steps(float(wave.unit_lpmm[0]))
    _, dz = steps(float(wave.unit_lpmm[1]))
    growth = np.array(_GROWTH)
    # searches: (start, value there, candidates, the (vergence, film) of a parameter x)
    searches: list[Any] = [
        (v_focus, at_focus, np.minimum(v_focus + dv * growth, v_max), lambda x: (x, film)),
        (v_focus, at_focus, np.maximum(v_focus - dv * growth, 0.0), lambda x: (x, film)),
    ]
    if find_h:
        searches.append((film_inf, float(first[1]), film_inf + dz * growth, lambda x: (0.0, x)))
        if not first[1] > level:
            searches[2] = None  # infinity is never sharp enough: no hyperfocal distance
    live = [i for i, search in enumerate(searches) if search is not None]

    def evaluate(which: list[int], xs: Any) -> np.ndarray:
        pairs = [searches[i][3](float(x)) for i, x in zip(which, np.ravel(xs).tolist())]
        return mtf([p[0] for p in pairs], [p[1] for p in pairs])

    which = [i for i in live for _ in searches[i][2]]
    values = evaluate(which, np.concatenate([searches[i][2] for i in live]))
    brackets: list[Any] = [None] * len(searches)
    taken = 0
    for i in live:
        start, at_start, points, _ = searches[i]
        part = values[taken : taken + points.size]
        taken += points.size
        brackets[i] = _bracket(start, at_start, points, part, level)
        if brackets[i] is None and i < 2 and points[-1] != (v_max if i == 0 else 0.0):
            # still sharp further on: the rest of the way to the closest object or to infinity
            more = np.linspace(points[-1], v_max if i == 0 else 0.0, 33)[1:]
            brackets[i] = _bracket(points[-1], float(part[-1]), more, evaluate([i] * more.size, more), level)
    roots = _refine(brackets, lambda which, xs: evaluate(which, xs) - level, [dv, dv, dz][: len(searches)])
    near_v, far_v = roots[0], roots[1]
    if find_h:
        _remember(key, roots[2] if len(roots) > 2 else None)
    hyper_film = _HYPERFOCAL_FILM[key]
    if near_v is None:
        near_v = v_max  # sharp to the closest object the lens can focus on
    if far_v is None or v_focus == 0.0 or (hyper_film is not None and film <= hyper_film):
        far_v = 0.0
    z_ref = {"sensor": film, "lens": fo.z_h_mm, "entrance_pupil": fo.z_e_mm}[distance_from]
    near, far, front, rear = limits_from_vergences(z_ref, fo.z_e_mm - 1.0 / near_v, focus.object_z_mm,
                                                   float(distance_mm), v_focus, far_v)
    hyperfocal = math.inf
    if hyper_film is not None:
        at_h = focus_for_film(prescription, n_f, hyper_film)
        if at_h is not None:
            z_ref_h = {"sensor": at_h.film_z_mm, "lens": fo.z_h_mm, "entrance_pupil": fo.z_e_mm}[distance_from]
            hyperfocal = z_ref_h - at_h.object_z_mm
        else:
            hyperfocal = closest_focus_mm(prescription, n_f, distance_from)  # every focus keeps infinity sharp
    return DofLimits(near, far, front, rear, front + rear, hyperfocal, focus.magnification)


_HYPERFOCAL_FILM: dict[tuple[Any, ...], float | None] = {}
"""The film behind the infinity focus where an object at infinity falls to the level (None: never sharp), per
lens, f-number and criterion: the same whatever the focus of a scene, so found once."""


def _remember(key: tuple[Any, ...], film: float | None) -> None:
    if len(_HYPERFOCAL_FILM) >= 256:
        del _HYPERFOCAL_FILM[next(iter(_HYPERFOCAL_FILM))]
    _HYPERFOCAL_FILM[key] = film


def _bracket(start: float, start_value: float, points: np.ndarray, values: np.ndarray,
             level: float) -> tuple[float, float, float, float] | None:
    """(a, f(a), b, f(b)) around the first fall below the level going from ``start`` through ``points``."""
    previous, previous_value = start, start_value
    for point, value in zip(points.tolist(), values.tolist()):
        if point == previous:
            continue
        if value <= level:
            return previous, previous_value - level, point, value - level
        previous, previous_value = point, value
    return None


def _refine(brackets: list[Any], excess: Any, scales: list[float]) -> list[float | None]:
    """The roots inside each bracket (None: no bracket), by the Illinois method, every bracket in one batch.

    ``excess(which, xs)`` evaluates the function of the brackets ``which`` at ``xs``; each stops when
    narrower than 1e-7 of its ``scales``."""
    state = [list(b) if b is not None else None for b in brackets]
    side = [0] * len(state)
    for _ in range(_ROUNDS):
        live = [i for i, b in enumerate(state) if b is not None and abs(b[2] - b[0]) > _TOLERANCE * scales[i]]
        if not live:
            break
        points = []
        for i in live:
            a, fa, b, fb = state[i]  # type: ignore[misc]
            x = b - fb * (b - a) / (fb - fa) if fb != fa else 0.5 * (a + b)
            low, high = min(a, b), max(a, b)
            if not low < x < high:
                x = 0.5 * (a + b)
            points.append(x)
        values = excess(live, np.array(points))
        for i, x, fx in zip(live, points, values.tolist()):
            a, fa, b, fb = state[i]  # type: ignore[misc]
            if fx == 0.0:
                state[i] = [x, 0.0, x, 0.0]
                continue
            if (fx > 0.0) == (fa > 0.0):  # x replaces a; halve fb if a was replaced last time too
                state[i] = [x, fx, b, fb * 0.5 if side[i] == 1 else fb]
                side[i] = 1
            else:
                state[i] = [a, fa * 0.5 if side[i] == -1 else fa, x, fx]
                side[i] = -1
    out: list[float | None] = []
    for b in state:
        if b is None:
            out.append(None)
        else:
            a, fa, c, fc = b
            out.append(c if fa == fc else c - fc * (c - a) / (fc - fa))
    return out


def prescription_contrast_optimum(prescription: Any, near_mm: float, far_mm: float, frequency_lpmm: float,
                                  distance_from: str = "sensor") -> ContrastOptimum:
    """The f-number and focus that make the worse end of a range sharpest by contrast, by the real lens's wavefront.

    The counterpart of :func:`camtool.dof.wave.contrast_optimum` for a
    prescription, at its own wavelength: for each f-number (the fixed stop
    f/(2·N·m_E), as the ``wave`` rung sets it) the film between the real best
    focus of the far end and that of the near end where the two ends' MTF at
    ν are equal (Illinois method; each end is sharpest on its own film, so the
    worse of the two is largest there), and the f-number where that MTF is
    largest (golden-section search in ln N about the best of nine f-numbers
    from the lens's widest to 1/(λν), where a perfect lens's contrast at ν
    vanishes). The focus is the object whose real
    best focus is that film (:func:`camtool.dof.realray.focus_for_film`).

    ``working_f_number`` is N·(1 + m/P), as ``dof`` gives it (P the prescription's
    pupil magnification, m its first-order magnification); ``defocus_waves``
    the defocus W₂₀ = A²·(v_near − v_far)/(16λ) of either end from the mean of
    their entrance-pupil vergences (A = f/N), as for a perfect lens.

    Raises
    ------
    DomainError
        ``near_mm``/``far_mm`` out of range (the near end closer than the lens
        can focus); on ``criterion``, no f-number and film give both ends any
        contrast at ν.
    RayTraceError
        Rays of the beam cannot get through the lens.

    Examples
    --------
    >>> from camtool.optics.prescription import EXAMPLE_SINGLET, prescription_from_mapping
    >>> lens = prescription_from_mapping(EXAMPLE_SINGLET)
    >>> r = prescription_contrast_optimum(lens, 2000.0, 5000.0, 30.0)
    >>> round(r.f_number, 1), round(r.mtf, 3), round(r.distance_mm)
    (33.9, 0.179, 2835)
    """
    from camtool.core.errors import require
    from camtool.dof.realray import _check_scene, focus_for_film, real_focus
    from camtool.optics.wavefront import Vignetted, wavefront_tracer

    _check_scene(prescription, 1.0, near_mm, distance_from, "defocus")
    require_positive("far_mm", far_mm, allow_inf=True)
    require("far_mm", far_mm, far_mm > near_mm, "beyond the near limit")
    require_positive("frequency_lpmm", frequency_lpmm, unit="lp/mm")
    tracer = wavefront_tracer(prescription)
    fo = tracer.first
    lam = tracer.wavelength_mm
    nu = float(frequency_lpmm)
    fixed = {"lens": fo.z_h_mm, "entrance_pupil": fo.z_e_mm}.get(distance_from)

    def vergence(distance: float, films: np.ndarray) -> np.ndarray:
        """The entrance-pupil vergence of the object ``distance`` from the plane asked, with the film at ``films``."""
        if math.isinf(distance):
            return np.zeros_like(films)
        return 1.0 / (fo.z_e_mm - ((films if fixed is None else np.full_like(films, fixed)) - distance))

    def ends(n: float, films: Any) -> tuple[np.ndarray, np.ndarray]:
        """The MTF at ν of the near and of the far end with the film at ``films``."""
        films = np.atleast_1d(np.asarray(films, float))
        both = tracer.axial_mtf(np.concatenate([vergence(near_mm, films), vergence(far_mm, films)]), n,
                                np.concatenate([films, films]), nu)
        return both[: films.size], both[films.size :]

    def best_film(n: float) -> tuple[float, float]:
        """The worse end's MTF on the film that makes the two ends equally sharp at ``n``, and that film."""
        try:
            films = [real_focus(prescription, n, far_mm, distance_from).film_z_mm,
                     real_focus(prescription, n, near_mm, distance_from).film_z_mm]
            near, far = ends(n, films)
        except Vignetted:
            return -1.0, math.nan  # wider than the lens lets through
        gap = near - far  # below 0 on the far end's film, above on the near end's
        if not (gap[0] < 0.0 < gap[1]):
            side = 0 if min(near[0], far[0]) >= min(near[1], far[1]) else 1
            return float(min(near[side], far[side])), films[side]
        root = _refine([[films[0], float(gap[0]), films[1], float(gap[1])]],
                       lambda _which, xs: np.subtract(*ends(n, xs)), [films[1] - films[0]])[0]
        assert root is not None
        near, far = ends(n, [root])
        return float(min(near[0], far[0])), root

    # from the lens's own widest f-number (f/1 when it states none) to where a perfect lens's MTF at ν vanishes
    low, high = math.log(prescription.f_number or 1.0), math.log(max(1.0 / (lam * nu), 2.0 * (prescription.f_number or 1.0)))
    memo: dict[float, tuple[float, float]] = {}

    def value(x: float) -> float:
        if x not in memo:
            memo[x] = best_film(math.exp(x))
        return memo[x][0]

    points = np.linspace(low, high, 9)
    i = int(np.argmax([value(float(x)) for x in points]))
    golden_section(value, float(points[max(i - 1, 0)]), float(points[min(i + 1, points.size - 1)]), steps=200,
                   tolerance=1e-4)  # ln N to 1e-4; every value is kept in memo
    x_best = max(memo, key=lambda x: memo[x][0])
    mtf, film = memo[x_best]
    n_best = math.exp(x_best)
    if not mtf > 0.0:
        raise DomainError("criterion", f"{nu:g} lp/mm", "a frequency at which the lens gives the range some contrast")
    focus = focus_for_film(prescription, n_best, film)
    if focus is None:  # pragma: no cover - the film lies between two reachable foci
        raise DomainError("near_mm", near_mm, "a range whose focus the lens can reach")
    z_ref = film if fixed is None else fixed
    v_near, v_far = (float(vergence(d, np.array([film]))[0]) for d in (near_mm, far_mm))
    defocus = (fo.efl_mm / n_best) ** 2 * (v_near - v_far) / (16.0 * lam)
    m = focus.magnification
    return ContrastOptimum(z_ref - focus.object_z_mm, m, n_best, n_best * (1.0 + m / fo.pupil_magnification), mtf,
                           defocus)
