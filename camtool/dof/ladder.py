"""The model ladder: one dispatcher over the depth-of-field models, cheapest first.

Rungs (docs/design.md §4): ``approx`` (the common rule), ``thin`` (exact thin
lens), ``thick`` (pupil magnification and hiatus), ``paraxial`` (first-order
trace of a prescription, fed into ``thick``) and ``raytrace`` (real rays).
Every model takes (f, N, c, focus distance, distance plane) in mm plus the
lens data it needs, and returns :class:`camtool.dof.limits.DofLimits`.
Diffraction is an add-on to every rung (:mod:`camtool.dof.diffraction`); ``auto``
picks the cheapest rung the scene needs (:func:`choose`, :mod:`camtool.dof.auto`) and ``all``
runs every rung the inputs allow (:func:`compare_models`).
"""

from __future__ import annotations

import functools
import time
from collections.abc import Callable
from dataclasses import dataclass
from typing import Any, NamedTuple

from camtool.core.arrays import ops
from camtool.core.errors import DomainError, first_bad
from camtool.dof.auto import Effects, depth_error, estimate_effects, left_out
from camtool.dof.closed import approx_dof, thin_dof
from camtool.dof.limits import DofLimits
from camtool.geometry.thinlens import focus_geometry

__all__ = [
    "CHOICES",
    "LADDER",
    "LensData",
    "ModelComparison",
    "ModelResult",
    "ModelUnavailable",
    "available_models",
    "compare_models",
    "depth_of_field",
    "prescription_focal_length",
]

LADDER = ("approx", "thin", "thick", "paraxial", "raytrace")
"""The rungs, cheapest (and least complete) first."""

CHOICES = (*LADDER, "auto", "all")

FOCAL_LENGTH_TOLERANCE = 0.01
"""A focal length given with a prescription may differ from its paraxial one by this fraction."""


@dataclass(frozen=True)
class LensData:
    """What is known about the lens beyond its focal length.

    ``pupil_magnification`` P (exit/entrance pupil diameter) and
    ``hiatus_mm`` δ (separation of the principal planes) for ``thick``;
    ``prescription`` (a :class:`camtool.optics.prescription.Prescription`)
    for ``paraxial`` and ``raytrace``, which also supplies f, P and δ where
    they are not given by hand.
    """

    pupil_magnification: float | None = None
    hiatus_mm: float | None = None
    prescription: Any = None

    @property
    def first_order(self) -> Any:
        """First-order data of the prescription (None without one)."""
        if self.prescription is None:
            return None
        from camtool.optics.paraxial import first_order

        return first_order(self.prescription)

    @property
    def focal_length_mm(self) -> float | None:
        """The prescription's paraxial focal length (None without a prescription)."""
        fo = self.first_order
        return None if fo is None else fo.efl_mm

    def thick_parameters(self) -> tuple[float, float] | None:
        """(P, δ) for ``thick``: given by hand, else the prescription's, else P = 1, δ = 0 for the missing one.

        None when neither is known.
        """
        fo = self.first_order
        if self.pupil_magnification is None and self.hiatus_mm is None and fo is None:
            return None
        p = self.pupil_magnification if self.pupil_magnification is not None else (fo.pupil_magnification if fo else 1.0)
        delta = self.hiatus_mm if self.hiatus_mm is not None else (fo.hiatus_mm if fo else 0.0)
        return p, delta


NO_LENS = LensData()


class ModelUnavailable(ValueError):
    """The inputs do not allow the model asked for; ``missing`` says what it needs."""

    def __init__(self, model: str, missing: str) -> None:
        self.model = model
        self.missing = missing
        super().__init__(f"the {model} model needs {missing}")


class ModelResult(NamedTuple):
    """The limits, the model that produced them (``+diffraction`` when the add-on ran) and its estimated relative error.

    ``error_estimate`` is the estimated relative error of the limits
    (:func:`camtool.dof.auto.depth_error`) from the effects the model leaves out.
    """

    limits: DofLimits
    model: Any  # str, or an array of str for array input
    error_estimate: Any


class ModelComparison(NamedTuple):
    """One rung of ``--model all``: its result, the difference from the most accurate rung and its cost."""

    result: ModelResult
    difference: Any
    time_per_evaluation_s: float


def _approx(f: Any, n: Any, c: Any, s: Any, plane: str, lens: LensData) -> DofLimits:
    # The approximation has no notion of the closest focus; the scene still must be reachable.
    focus_geometry(f, s, plane)
    return approx_dof(f, n, c, s)


def _thin(f: Any, n: Any, c: Any, s: Any, plane: str, lens: LensData) -> DofLimits:
    return thin_dof(f, n, c, s, plane)


def _thick(f: Any, n: Any, c: Any, s: Any, plane: str, lens: LensData) -> DofLimits:
    from camtool.dof.thick import thick_dof

    p, delta = lens.thick_parameters()  # type: ignore[misc]
    return thick_dof(f, n, c, s, pupil_magnification=p, hiatus_mm=delta, distance_from=plane)


def _paraxial(f: Any, n: Any, c: Any, s: Any, plane: str, lens: LensData) -> DofLimits:
    from camtool.dof.paraxial import paraxial_dof

    return paraxial_dof(lens.prescription, n, c, s, plane)


def _raytrace(f: Any, n: Any, c: Any, s: Any, plane: str, lens: LensData) -> DofLimits:
    from camtool.dof.realray import raytrace_dof

    return raytrace_dof(lens.prescription, n, c, s, plane)


MODELS: dict[str, Callable[..., DofLimits]] = {
    "approx": _approx, "thin": _thin, "thick": _thick, "paraxial": _paraxial, "raytrace": _raytrace,
}


def available_models(lens: LensData | None = None) -> tuple[str, ...]:
    """The rungs the lens data allow, cheapest first.

    Examples
    --------
    >>> available_models()
    ('approx', 'thin')
    >>> available_models(LensData(pupil_magnification=0.7))
    ('approx', 'thin', 'thick')

    With a prescription and no P or δ by hand, ``thick`` would repeat
    ``paraxial`` (same f, P and δ) and is left out.
    """
    return _available(lens or NO_LENS)


@functools.lru_cache(maxsize=64)
def _available(lens: LensData) -> tuple[str, ...]:
    # cached: auto asks on every call, and the answer depends only on which data the lens carries
    by_hand = lens.pupil_magnification is not None or lens.hiatus_mm is not None
    # with a prescription and no values by hand, thick is paraxial by another name
    skip = "thick" if lens.prescription is not None and not by_hand else ""
    return tuple(name for name in LADDER if name != skip and _missing(name, lens) is None)


def _missing(model: str, lens: LensData) -> str | None:
    """What ``model`` lacks in ``lens`` (None when it can run)."""
    if model == "thick" and lens.thick_parameters() is None:
        return ("the lens's pupil magnification or hiatus "
                "(--pupil-mag, --hiatus, a --lens that has them, or --prescription)")
    if model in ("paraxial", "raytrace") and lens.prescription is None:
        return "a lens prescription (--prescription FILE, or a --lens that has one)"
    return None


def prescription_focal_length(lens: LensData, focal_length_mm: Any = None) -> Any:
    """The focal length to use with ``lens``: the prescription's when it has one, else ``focal_length_mm``.

    Raises
    ------
    DomainError
        A focal length given with a prescription differs from the
        prescription's paraxial focal length by more than 1 %.
    """
    efl = lens.focal_length_mm
    if efl is None or focal_length_mm is None:
        return focal_length_mm if efl is None else efl
    xp = ops(focal_length_mm)
    close = xp.fabs(focal_length_mm / efl - 1.0) <= FOCAL_LENGTH_TOLERANCE
    if not (close if isinstance(close, bool) else bool(xp.all(close))):
        name = lens.prescription.id or lens.prescription.source or "the prescription"
        raise DomainError("focal_length_mm", first_bad(focal_length_mm, close),
                          f"within 1 % of {efl:.6g} mm, the paraxial focal length of {name}")
    return efl


def _scene_lens(lens: LensData) -> tuple[Any, Any]:
    """(P, δ) the estimates and the working f-number use: known values, else 1 and 0."""
    params = lens.thick_parameters()
    return params if params is not None else (1.0, 0.0)


def _usable_coc(f: Any, n: Any, c: Any, s: Any, plane: str, lens: LensData, wavelength_nm: Any) -> tuple[Any, Any]:
    """(usable CoC √(c² − b_airy²), b_airy) with the working f-number at the focus distance."""
    from camtool.dof.diffraction import airy_diameter_mm, usable_coc_mm

    p, delta = _scene_lens(lens)
    m = focus_geometry(f, s, plane, delta if plane == "sensor" else 0.0).magnification
    usable = usable_coc_mm(c, n, m, p, wavelength_nm)
    return usable, airy_diameter_mm(n * (1.0 + m / p), wavelength_nm)


def _check_focus(f: Any, s: Any, plane: str, lens: LensData) -> None:
    """The focus distance must be reachable (1:1 at the closest), with the thin model's messages."""
    from camtool.core.errors import require, require_positive
    from camtool.geometry.thinlens import lens_distances

    if plane == "lens":
        require_positive("distance_mm", s, allow_inf=True)
        require("distance_mm", s, s > f,
                "more than {limit} from the lens (the focal length; between f and 2f the magnification is above 1)",
                limit=f)
    elif plane == "sensor":
        lens_distances(f, s, _scene_lens(lens)[1])
    else:
        raise ValueError(f"distance_from must be 'sensor' or 'lens', not {plane!r}")


def _effects(f: Any, n: Any, c: Any, s: Any, plane: str, lens: LensData, airy: Any) -> Effects:
    p, delta = _scene_lens(lens)
    return estimate_effects(f, n, c, s, plane, p, delta if plane == "sensor" else 0.0, airy, lens.prescription)


def _worst(value: Any) -> float:
    """The largest entry of a scalar or array estimate."""
    if isinstance(value, (int, float)):
        return float(value)
    import numpy as np

    return float(np.max(value)) if np.size(value) else 0.0


def choose(effects: Effects, models: tuple[str, ...], diffraction: bool, tolerance: float) -> tuple[str, bool]:
    """The cheapest rung, and whether to add diffraction, that leaves out no more than the tolerance.

    ``models`` run cheapest first. Diffraction (when asked for) is added only
    when its own share exceeds the tolerance; a rung qualifies when the
    effects it leaves out, with diffraction if it is not added, stay within
    the tolerance in every scene of the call. With no rung within the
    tolerance the most complete one runs.
    """
    applied = diffraction and _worst(effects.diffraction) > tolerance
    for name in models:
        if _worst(left_out(effects, name, applied or not diffraction)) <= tolerance:
            return name, applied
    return models[-1], diffraction


def _run(name: str, applied: bool, f: Any, n: Any, c: Any, s: Any, plane: str, lens: LensData,
         usable: Any) -> DofLimits:
    return MODELS[name](f, n, usable if applied else c, s, plane, lens)


def _label(name: str, applied: bool) -> str:
    return f"{name}+diffraction" if applied else name


def depth_of_field(
    model: str,
    focal_length_mm: Any,
    f_number: Any,
    coc_mm: Any,
    distance_mm: Any,
    distance_from: str = "sensor",
    lens: LensData | None = None,
    diffraction: bool = False,
    wavelength_nm: float = 550.0,
    tolerance: float = 0.01,
) -> ModelResult:
    """Depth of field by the named model, or by the cheapest one the scene needs (``auto``).

    Parameters
    ----------
    model : str
        ``approx``, ``thin``, ``thick``, ``paraxial``, ``raytrace`` or ``auto``.
    focal_length_mm : float, array or None
        f > 0; with a prescription it must agree with the prescription's
        paraxial focal length within 1 % (None: take the prescription's).
    f_number, coc_mm, distance_mm : float or array
        N > 0, c > 0, focus distance (``inf`` allowed) from ``distance_from``.
    distance_from : ``"sensor"`` or ``"lens"``
    lens : LensData or None
        Pupil magnification, hiatus, prescription.
    diffraction : bool
        Add the Airy disc 2.44·λ·N(1 + m/P) in quadrature (the usable CoC
        becomes √(c² − b_airy²)).
    wavelength_nm : float
        λ for diffraction.
    tolerance : float
        ``auto``: the largest estimated relative error accepted (0.01 = 1 %
        of the depth of field, :func:`camtool.dof.auto.depth_error`).

    Returns
    -------
    ModelResult
        ``model`` names the rung that ran (``+diffraction`` when the add-on
        did); ``error_estimate`` the estimated relative error of the answer
        (what the rung leaves out; for ``raytrace`` 0).

    Raises
    ------
    ModelUnavailable
        The lens data do not allow the model (``thick`` without P or δ,
        ``paraxial``/``raytrace`` without a prescription).
    DomainError
        Inputs outside the physical domain; a focal length that disagrees
        with the prescription; :class:`camtool.dof.diffraction.NothingSharp` when
        the Airy disc fills the CoC.

    Examples
    --------
    >>> r = depth_of_field("auto", 50.0, 8.0, 0.03, 3000.0)
    >>> r.model, round(r.error_estimate, 4)
    ('thin', 0.0)
    >>> round(depth_of_field("approx", 50.0, 8.0, 0.03, 3000.0).error_estimate, 4)
    0.0434
    >>> depth_of_field("thick", 50.0, 8.0, 0.03, 3000.0)
    Traceback (most recent call last):
    ...
    camtool.dof.ladder.ModelUnavailable: the thick model needs the lens's pupil magnification or hiatus \
(--pupil-mag, --hiatus, a --lens that has them, or --prescription)
    >>> depth_of_field("bogus", 50.0, 8.0, 0.03, 3000.0)
    Traceback (most recent call last):
    ...
    ValueError: unknown model 'bogus'; choose one of approx, thin, thick, paraxial, raytrace, auto
    """
    lens = lens or NO_LENS
    if model not in (*LADDER, "auto"):
        raise ValueError(f"unknown model {model!r}; choose one of {', '.join((*LADDER, 'auto'))}")
    if model != "auto":
        missing = _missing(model, lens)
        if missing is not None:
            raise ModelUnavailable(model, missing)
    f = prescription_focal_length(lens, focal_length_mm)
    from camtool.dof.closed import check_inputs

    check_inputs(f, f_number, coc_mm)
    _check_focus(f, distance_mm, distance_from, lens)
    usable, airy = _usable_coc(f, f_number, coc_mm, distance_mm, distance_from, lens, wavelength_nm) \
        if diffraction else (coc_mm, 0.0)
    effects = _effects(f, f_number, coc_mm, distance_mm, distance_from, lens, airy)
    if model != "auto":
        limits = _run(model, diffraction, f, f_number, coc_mm, distance_mm, distance_from, lens, usable)
        return ModelResult(limits, _label(model, diffraction), left_out(effects, model, diffraction))
    inputs = (f, f_number, coc_mm, distance_mm, usable)
    if all(isinstance(v, (int, float)) for v in (*inputs, airy)):
        name, applied = choose(effects, available_models(lens), diffraction, tolerance)
        limits = _run(name, applied, f, f_number, coc_mm, distance_mm, distance_from, lens, usable)
        return ModelResult(limits, _label(name, applied), left_out(effects, name, applied))
    return _auto_each(effects, available_models(lens), diffraction, tolerance, inputs, airy, distance_from, lens)


def _auto_each(effects: Effects, models: tuple[str, ...], diffraction: bool, tolerance: float,
               inputs: tuple[Any, ...], airy: Any, plane: str, lens: LensData) -> ModelResult:
    """``auto`` over arrays: each scene gets its own cheapest sufficient rung, as a single call would.

    The scenes are grouped by the rung chosen, each group runs in one
    vectorised call, and the results go back in place; ``model`` is then an
    array of names, one per scene.
    """
    import numpy as np

    shape = np.broadcast_shapes(*(np.shape(v) for v in (*inputs, airy, *effects)))
    flat = [np.broadcast_to(np.asarray(v, dtype=float), shape).ravel() for v in inputs]
    each = Effects(*(np.broadcast_to(np.asarray(v, dtype=float), shape).ravel() for v in effects))
    count = flat[0].size
    applied = np.full(count, False) if not diffraction else each.diffraction > tolerance
    chosen = np.full(count, len(models) - 1)
    for index in reversed(range(len(models))):
        fits = left_out(each, models[index], True) + np.where(applied | (not diffraction), 0.0, each.diffraction)
        chosen = np.where(fits <= tolerance, index, chosen)
    fields = [np.empty(count) for _ in DofLimits._fields]
    names = np.empty(count, dtype=object)
    estimate = np.empty(count)
    for index, name in enumerate(models):
        for add in (False, True):
            rows = np.nonzero((chosen == index) & (applied == add))[0]
            if rows.size == 0:
                continue
            f, n, c, s, usable = (v[rows] for v in flat)
            limits = _run(name, add, f, n, c, s, plane, lens, usable)
            for out, value in zip(fields, limits):
                out[rows] = value
            names[rows] = _label(name, add)
            part = Effects(*(v[rows] for v in each))
            estimate[rows] = left_out(part, name, True) + (0.0 if add or not diffraction else part.diffraction)
    limits = DofLimits(*(field.reshape(shape) for field in fields))
    return ModelResult(limits, names.reshape(shape), estimate.reshape(shape))


def compare_models(
    focal_length_mm: Any,
    f_number: Any,
    coc_mm: Any,
    distance_mm: Any,
    distance_from: str = "sensor",
    lens: LensData | None = None,
    diffraction: bool = False,
    wavelength_nm: float = 550.0,
    repeat: int = 3,
) -> list[ModelComparison]:
    """Every rung the lens data allow, for the same scene, with its difference from the most complete one and its cost.

    ``difference`` is :func:`camtool.dof.auto.depth_error` against the last
    (most complete) rung; ``time_per_evaluation_s`` the best of ``repeat``
    timed runs (``time.perf_counter``) divided by the number of scenes.

    Examples
    --------
    >>> rows = compare_models(50.0, 8.0, 0.03, 3000.0)
    >>> [(r.result.model, round(r.difference, 4)) for r in rows]
    [('approx', 0.0287), ('thin', 0.0)]
    """
    lens = lens or NO_LENS
    f = prescription_focal_length(lens, focal_length_mm)
    from camtool.dof.closed import check_inputs

    check_inputs(f, f_number, coc_mm)
    count = 1
    for value in (f, f_number, coc_mm, distance_mm):
        count = max(count, getattr(value, "size", 1))
    results: list[tuple[ModelResult, float]] = []
    for name in available_models(lens):
        best = float("inf")
        for _ in range(max(repeat, 1)):
            start = time.perf_counter()
            result = depth_of_field(name, f, f_number, coc_mm, distance_mm, distance_from, lens, diffraction,
                                    wavelength_nm)
            best = min(best, time.perf_counter() - start)
        results.append((result, best / count))
    reference = results[-1][0].limits
    return [ModelComparison(result, depth_error(result.limits, reference), seconds) for result, seconds in results]
