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
import math
import time
from typing import Any

from camtool.core.arrays import ops
from camtool.core.errors import CamtoolError, DomainError, first_bad
from camtool.core.planes import FOCUS_PLANES, check_plane
from camtool.core.record import NamedTuple
from camtool.core.steps import step
from camtool.dof import rungs
from camtool.dof.auto import Effects, depth_error, estimate_effects, left_out
from camtool.dof.closed import thin_hyperfocal_mm
from camtool.dof.limits import DofLimits
from camtool.dof.rungs import NO_LENS, LensData
from camtool.geometry.thinlens import FocusGeometry, focus_geometry

__all__ = [
    "CHOICES",
    "LADDER",
    "Hyperfocal",
    "LensData",
    "ModelComparison",
    "ModelResult",
    "ModelUnavailable",
    "available_models",
    "compare_models",
    "depth_of_field",
    "focal_lengths",
    "hyperfocal",
    "hyperfocal_choices",
    "hyperfocal_rung",
    "model_choices",
    "prescription_focal_length",
]

LADDER = rungs.names()
"""The rungs, cheapest (and least complete) first (the records are :data:`camtool.dof.rungs.RUNGS`)."""

CHOICES = (*LADDER, "auto", "all")
"""The ``--model`` choices (see :func:`model_choices`)."""

AUTO_HELP = "the cheapest that the scene needs within --tolerance"
ALL_HELP = "every model the inputs allow, side by side, with the time each took"


def model_choices() -> tuple[str, ...]:
    """The ``--model`` choices of ``camtool dof``: every rung, then ``auto`` and ``all``.

    Examples
    --------
    >>> model_choices()
    ('approx', 'thin', 'thick', 'paraxial', 'raytrace', 'wave', 'auto', 'all')
    """
    return (*rungs.names(), "auto", "all")


def model_help() -> str:
    """The ``--model`` help of ``camtool dof``: one clause per rung, then ``auto`` and ``all``."""
    clauses = [f"{rung.name}: {rung.help}" for rung in rungs.RUNGS]
    return "; ".join([*clauses, f"auto: {AUTO_HELP}", f"all: {ALL_HELP}."])

FOCAL_LENGTH_TOLERANCE = 0.01
"""A focal length given with a prescription may differ from its paraxial one by this fraction."""


class ModelUnavailable(CamtoolError, ValueError):
    """The inputs do not allow the model asked for; ``missing`` says what it needs.

    ``needs`` names the data alone and ``supplied_by`` the options that give
    them (the rung's record), for a command to name only the options it has.
    """

    def __init__(self, model: str, missing: str, needs: str = "", supplied_by: tuple[str, ...] = ()) -> None:
        self.model = model
        self.missing = missing
        self.needs = needs or missing
        self.supplied_by = supplied_by
        super().__init__(f"the {model} model needs {missing}")


def either(items: tuple[str, ...] | list[str]) -> str:
    """``a, b, or c``: alternatives as the messages list them.

    Examples
    --------
    >>> either(["--pupil-mag", "--hiatus", "a --lens that has them"])
    '--pupil-mag, --hiatus, or a --lens that has them'
    >>> either(["--hiatus"])
    '--hiatus'
    """
    return items[0] if len(items) == 1 else ", ".join(items[:-1]) + ", or " + items[-1]


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


def available_models(lens: LensData | None = None) -> tuple[str, ...]:
    """The geometric rungs the lens data allow, cheapest first (``wave`` stands apart: :func:`depth_of_field`).

    Examples
    --------
    >>> available_models()
    ('approx', 'thin')
    >>> available_models(LensData(pupil_magnification=0.7))
    ('approx', 'thin', 'thick')

    With a prescription and no P or δ by hand, ``thick`` would repeat
    ``paraxial`` (same f, P and δ) and is left out.
    """
    return _available(id(rungs.RUNGS), lens or NO_LENS)


@functools.lru_cache(maxsize=64)
def _available(ladder: int, lens: LensData) -> tuple[str, ...]:
    # cached: auto asks on every call, and the answer depends only on the ladder (its identity: a replaced
    # RUNGS is a new ladder) and on which data the lens carries
    by_hand = lens.pupil_magnification is not None or lens.hiatus_mm is not None
    # with a prescription and no values by hand, thick is paraxial by another name
    skip = "thick" if rungs.traceable(lens) and not by_hand else ""
    return tuple(rung.name for rung in rungs.geometric() if rung.name != skip and rung.can_run(lens))


def _unavailable(model: str, lens: LensData) -> ModelUnavailable | None:
    """The error for ``model`` when ``lens`` lacks what it needs (None when it can run)."""
    rung = rungs.by_name()[model]
    if rung.can_run(lens):
        return None
    if rung.can_run is rungs.traceable and lens.prescription is not None:  # one, but not in air
        return ModelUnavailable(model, rungs.in_air(lens.prescription))
    return ModelUnavailable(model, f"{rung.needs} ({either(rung.supplied_by)})", rung.needs, rung.supplied_by)


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


def focal_lengths(lens: LensData | None, given: list[Any]) -> list[Any]:
    """The focal lengths to compute with: with a prescription its paraxial one, else those ``given`` (mm).

    With a prescription each given focal length must agree with the paraxial
    one within 1 % (:func:`prescription_focal_length`); none given means the
    prescription's. Without a prescription ``given`` is returned unchanged
    (possibly empty: the caller says the focal length is missing).

    Examples
    --------
    >>> focal_lengths(None, [50.0, 85.0])
    [50.0, 85.0]
    >>> from camtool.optics.prescription import EXAMPLE_SINGLET, prescription_from_mapping
    >>> lens = LensData(prescription=prescription_from_mapping(EXAMPLE_SINGLET))
    >>> [round(f, 3) for f in focal_lengths(lens, [])] == [round(lens.focal_length_mm, 3)]
    True
    """
    if lens is None or lens.prescription is None:
        return given
    return [prescription_focal_length(lens, f) for f in (given or [None])]


class Hyperfocal(NamedTuple):
    """The hyperfocal distance and the near limit when focused there (mm, in the plane asked for), and the model."""

    hyperfocal_mm: Any
    near_mm: Any
    model: Any


def hyperfocal_choices() -> tuple[str, ...]:
    """The models of ``camtool hyperfocal``: the rungs with a hyperfocal help (closed forms), then ``auto``.

    Examples
    --------
    >>> hyperfocal_choices()
    ('approx', 'thin', 'thick', 'wave', 'auto')
    """
    return (*(rung.name for rung in rungs.RUNGS if rung.hyperfocal_help), "auto")


HYPERFOCAL_AUTO_HELP = ("thick when that lens data is known, else thin (the rung auto uses at and beyond H); wave with "
                        "--diffraction or --criterion.")


def hyperfocal_rung(lens: LensData | None = None) -> str:
    """The rung of the hyperfocal distance under ``auto``: the most complete closed form the lens data allow.

    ``thick`` when the lens's pupil magnification or hiatus is known and
    differs from 1 and 0, else ``thin``. It is the rung of
    :func:`hyperfocal` under ``auto``, and the one :func:`depth_of_field`
    runs under ``auto`` for a focus at or beyond that hyperfocal distance
    (where a cheaper rung would put the start of the infinite far limit
    elsewhere), so the two answer with one hyperfocal distance.

    Examples
    --------
    >>> hyperfocal_rung(), hyperfocal_rung(LensData(pupil_magnification=0.7)), hyperfocal_rung(LensData(hiatus_mm=0.0))
    ('thin', 'thick', 'thin')
    """
    known = None if lens is None else lens.thick_parameters()
    return "thick" if known is not None and (float(known[0]), float(known[1])) != (1.0, 0.0) else "thin"


def hyperfocal_help() -> str:
    """The ``--model`` help of ``camtool hyperfocal``, one clause per choice."""
    clauses = [f"{rung.name}: {rung.hyperfocal_help}" for rung in rungs.RUNGS if rung.hyperfocal_help]
    return "; ".join([*clauses, f"auto: {HYPERFOCAL_AUTO_HELP}"])


def hyperfocal(
    model: str,
    focal_length_mm: Any,
    f_number: Any,
    coc_mm: Any,
    distance_from: str = "sensor",
    lens: LensData | None = None,
    diffraction: bool = False,
    wavelength_nm: float = 550.0,
    criterion: Any = None,
) -> Hyperfocal:
    """Hyperfocal distance H in mm by a closed-form rung, and the near limit when focused at H.

    With ``diffraction`` or a ``criterion``, ``auto`` is ``wave``: the
    hyperfocal distance by contrast, diffraction and defocus together (a
    stopped-down lens gets the H it can reach, or
    :class:`camtool.dof.wave.ContrastUnreachable` with the largest f-number
    that has one); a geometric rung named with ``diffraction`` adds the Airy
    disc by root-sum-square instead.

    H in the chosen plane is where the far limit first reaches infinity: the
    limits of a focus at infinity carry it, and focusing there gives the near
    limit. ``auto`` is :func:`hyperfocal_rung` (``thick`` with a pupil
    magnification or hiatus other than 1 and 0, else ``thin``), the rung
    :func:`depth_of_field` runs under ``auto`` for a focus at H, so its
    limits there reach infinity and its ``hyperfocal_mm`` is this H. A lens
    that focuses internally changes its focal length as it focuses: its
    hyperfocal focus setting is :func:`camtool.plans.depth.hyperfocal_setting`.

    Parameters
    ----------
    model : str
        One of :func:`hyperfocal_choices`.
    focal_length_mm, f_number, coc_mm : float or array, all > 0
    distance_from : ``"sensor"`` or ``"lens"``
    lens : LensData or None
        Pupil magnification and hiatus; a prescription (in air) only by
        contrast, where ``wave`` traces its wavefront (``wave+prescription``,
        the H ``depth_of_field`` reports for it); the geometric rungs take its
        first-order data.

    References
    ----------
    Wikipedia, "Hyperfocal distance": H = f²/(N·c) + f; docs/design.md §4.

    Examples
    --------
    >>> h = hyperfocal("thin", 50.0, 8.0, 0.03, distance_from="lens")
    >>> round(h.hyperfocal_mm, 3), round(h.near_mm, 3), h.model
    (10466.667, 5233.333, 'thin')
    >>> hyperfocal("auto", 50.0, 8.0, 0.03, lens=LensData(pupil_magnification=1.0)).model
    'thin'
    """
    if model not in hyperfocal_choices():
        raise ValueError(f"unknown model {model!r}; choose one of {', '.join(hyperfocal_choices())}")
    known = None if lens is None else lens.thick_parameters()
    p, delta = known if known is not None else (1.0, 0.0)
    data = LensData(pupil_magnification=p, hiatus_mm=delta) if (p, delta) != (1.0, 0.0) else None
    by_contrast = model == "wave" or (model == "auto" and (diffraction or criterion is not None))
    if by_contrast and lens is not None and rungs.traceable(lens):
        data = lens  # by contrast the real lens's wavefront, as depth_of_field's wave rung takes it
    rung = "wave" if by_contrast else hyperfocal_rung(lens) if model == "auto" else model
    extra = {"diffraction": diffraction and not by_contrast, "wavelength_nm": wavelength_nm, "criterion": criterion}
    at_infinity = depth_of_field(rung, focal_length_mm, f_number, coc_mm, float("inf"), distance_from, lens=data,
                                 **extra)
    h = at_infinity.limits.hyperfocal_mm
    at_h = depth_of_field(rung, focal_length_mm, f_number, coc_mm, h, distance_from, lens=data, **extra)
    return Hyperfocal(h, at_h.limits.near_mm, at_h.model)


def _scene_lens(lens: LensData) -> tuple[Any, Any]:
    """(P, δ) the estimates and the working f-number use: known values, else 1 and 0."""
    params = lens.thick_parameters()
    return params if params is not None else (1.0, 0.0)


def _focus(f: Any, s: Any, plane: str, lens: LensData) -> rungs.Focus:
    """The one conversion of the focus distance for a call: checked reachable, with the thin model's messages.

    From the sensor with the lens's hiatus (0 when unknown; the m ≤ 1 branch,
    closest 1:1); from the lens any u > f (m > 1 between f and 2f), and the
    hiatus does not move u or v.
    """
    from camtool.core.errors import require, require_positive

    if check_plane(plane, FOCUS_PLANES) == "lens":
        require_positive("distance_mm", s, allow_inf=True)
        require("distance_mm", s, s > f,
                "more than {limit} from the lens (the focal length; between f and 2f the magnification is above 1)",
                limit=f)
        return rungs.Focus(focus_geometry(f, s, plane), 0.0)
    delta = _scene_lens(lens)[1]
    return rungs.Focus(focus_geometry(f, s, plane, delta), delta)


def _usable_coc(n: Any, c: Any, focus: rungs.Focus, lens: LensData, wavelength_nm: Any) -> tuple[Any, Any]:
    """(usable CoC √(c² − b_airy²), b_airy) with the working f-number at the focus distance."""
    from camtool.dof.diffraction import airy_diameter_mm, usable_coc_mm

    p = _scene_lens(lens)[0]
    m = focus.geometry.magnification
    usable = usable_coc_mm(c, n, m, p, wavelength_nm)
    return usable, airy_diameter_mm(n * (1.0 + m / p), wavelength_nm)


def _effects(f: Any, n: Any, c: Any, s: Any, plane: str, lens: LensData, airy: Any, focus: rungs.Focus) -> Effects:
    p = _scene_lens(lens)[0]
    return estimate_effects(f, n, c, s, plane, p, focus.hiatus_mm, airy, lens.prescription, focus.geometry)


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
         usable: Any, focus: rungs.Focus | None = None) -> DofLimits:
    return rungs.by_name()[name].run(f, n, usable if applied else c, s, plane, lens, focus)


WAVE_PRESCRIPTION = "wave+prescription"
"""The model a result names when the ``wave`` rung ran on a prescription's real wavefront (camtool.dof.wavetrace)."""

DOMINANCE = 0.5 ** 0.5
"""``auto`` with ``diffraction``: the ``wave`` rung runs where the Airy disc exceeds this fraction of the CoC.

There the Airy disc's square is more than half the CoC's in the root-sum-square: diffraction dominates the blur
at the depth-of-field limits, where the root-sum-square is least accurate (docs/wave.md)."""


def _wave_rows(model: str, criterion: Any, diffraction: bool, n: Any, c: Any, focus: rungs.Focus, lens: LensData,
               wavelength_nm: Any) -> Any:
    """Which scenes the ``wave`` rung answers: all for ``wave`` or a criterion under ``auto``; under ``auto`` with
    ``diffraction``, those whose Airy disc 2.44·λ·N(1 + m/P) exceeds c/√2; else none (False)."""
    if model == "wave" or (model == "auto" and criterion is not None):
        return True
    if model != "auto" or not diffraction:
        return False
    from camtool.dof.diffraction import airy_diameter_mm

    p = _scene_lens(lens)[0]
    return airy_diameter_mm(n * (1.0 + focus.geometry.magnification / p), wavelength_nm) > DOMINANCE * c


def _wave(f: Any, n: Any, c: Any, s: Any, plane: str, lens: LensData, focus: rungs.Focus, criterion: Any,
          wavelength_nm: Any) -> ModelResult:
    """The ``wave`` rung (diffraction built in), with its estimate: the lens data it leaves out."""
    limits = rungs.by_name()["wave"].run(f, n, c, s, plane, lens, focus, criterion=criterion,
                                         wavelength_nm=wavelength_nm)
    if rungs.traceable(lens):  # the real lens's wavefront: aberrations, pupils and hiatus included
        return ModelResult(limits, WAVE_PRESCRIPTION, 0.0)
    effects = _effects(f, n, c, s, plane, lens, 0.0, focus)
    return ModelResult(limits, "wave", left_out(effects, "wave", True))


def _split(wave: Any, inputs: tuple[Any, ...], plane: str, lens: LensData, diffraction: bool, wavelength_nm: Any,
           tolerance: float, criterion: Any) -> ModelResult:
    """``auto`` over arrays where some scenes go to ``wave``: each part in one call, the results back in place."""
    import numpy as np

    shape = np.broadcast_shapes(*(np.shape(v) for v in (*inputs, wave)))
    flat = [np.broadcast_to(np.asarray(v, dtype=float), shape).ravel() for v in inputs]
    mask = np.broadcast_to(wave, shape).ravel()
    parts = []
    for rows, model in ((np.nonzero(mask)[0], "wave"), (np.nonzero(~mask)[0], "auto")):
        if rows.size:
            f, n, c, s = (v[rows] for v in flat)
            parts.append((rows, depth_of_field(model, f, n, c, s, plane, lens, diffraction, wavelength_nm, tolerance,
                                               criterion)))
    count = mask.size
    fields = [np.empty(count) for _ in DofLimits._fields]
    names = np.empty(count, dtype=object)
    estimate = np.empty(count)
    for rows, result in parts:
        for out, value in zip(fields, result.limits):
            out[rows] = value
        names[rows] = result.model
        estimate[rows] = result.error_estimate
    return ModelResult(DofLimits(*(v.reshape(shape) for v in fields)), names.reshape(shape), estimate.reshape(shape))


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
    criterion: Any = None,
) -> ModelResult:
    """Depth of field by the named model, or by the cheapest one the scene needs (``auto``).

    ``wave`` (:mod:`camtool.dof.wave`) answers by a contrast ``criterion``
    (None: its default); ``auto`` runs it for every scene when a criterion is
    given, and with ``diffraction`` for the scenes where the Airy disc exceeds
    c/√2 (:data:`DOMINANCE`: diffraction dominates the blur); other scenes
    take the geometric ladder as below.

    ``auto`` (the one meaning every command and the API share): the cheapest
    rung whose estimated error (:func:`camtool.dof.auto.depth_error`) is
    within ``tolerance``; but a rung cheaper than :func:`hyperfocal_rung`
    qualifies only in front of the hyperfocal distance (where both give a
    finite far limit): at and beyond it the hyperfocal rung runs, so a focus
    at the distance :func:`hyperfocal` reports gets a far limit of infinity.
    ``hyperfocal_mm`` is always the hyperfocal rung's, whatever rung gave
    the limits, so it does not change with the focus of the scene.

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
    criterion : camtool.dof.wave.Criterion or None
        The contrast criterion of ``wave`` (given, ``auto`` runs ``wave``).

    Returns
    -------
    ModelResult
        ``model`` names the rung that ran (``+diffraction`` when the add-on
        did; ``wave+prescription`` for ``wave`` on a prescription's real
        wavefront, :mod:`camtool.dof.wavetrace`); ``error_estimate`` the estimated relative error of the answer
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
    ValueError: unknown model 'bogus'; choose one of approx, thin, thick, paraxial, raytrace, wave, auto
    """
    lens = lens or NO_LENS
    if model != "auto":
        if model not in rungs.by_name():
            raise ValueError(f"unknown model {model!r}; choose one of {', '.join((*rungs.names(), 'auto'))}")
        unavailable = _unavailable(model, lens)
        if unavailable is not None:
            raise unavailable
    elif (not (type(distance_mm) is float and type(f_number) is float  # a single scene asks no more
               and type(focal_length_mm) is float and type(coc_mm) is float)
          and not diffraction and criterion is None and lens.prescription is None
          and any(getattr(v, "size", 1) > _BLOCK for v in (focal_length_mm, f_number, coc_mm, distance_mm))):
        in_blocks = _auto_in_blocks(focal_length_mm, f_number, coc_mm, distance_mm, distance_from, lens, tolerance)
        if in_blocks is not None:
            return in_blocks
    f = prescription_focal_length(lens, focal_length_mm)
    from camtool.dof.closed import check_inputs

    check_inputs(f, f_number, coc_mm)
    focus = _focus(f, distance_mm, distance_from, lens)  # converted once, handed to the estimates and the model
    wave = _wave_rows(model, criterion, diffraction, f_number, coc_mm, focus, lens, wavelength_nm)
    if wave is True or (not isinstance(wave, bool) and bool(wave.all())):
        return _wave(f, f_number, coc_mm, distance_mm, distance_from, lens, focus, criterion, wavelength_nm)
    if wave is not False and bool(wave.any()):
        return _split(wave, (f, f_number, coc_mm, distance_mm), distance_from, lens, diffraction, wavelength_nm,
                      tolerance, criterion)
    usable, airy = _usable_coc(f_number, coc_mm, focus, lens, wavelength_nm) if diffraction else (coc_mm, 0.0)
    effects = _effects(f, f_number, coc_mm, distance_mm, distance_from, lens, airy, focus)
    if model != "auto":
        limits = _run(model, diffraction, f, f_number, coc_mm, distance_mm, distance_from, lens, usable, focus)
        return ModelResult(limits, _label(model, diffraction), left_out(effects, model, diffraction))
    number = (int, float)
    if (isinstance(f, number) and isinstance(f_number, number) and isinstance(coc_mm, number)
            and isinstance(distance_mm, number)
            and (not diffraction or (isinstance(usable, number) and isinstance(airy, number)))):
        models, rung_h, below_h, sums, h_data = _plan(lens)
        if diffraction:
            name, applied = choose(effects, models, diffraction, tolerance)
            estimate = left_out(effects, name, applied)
        else:  # the same sums as left_out, in the same order, without its look-ups
            name, applied, estimate = models[-1], False, None
            for candidate, fields in sums:
                total = 0.0
                for i in fields:
                    total += effects[i]
                if total <= tolerance:
                    name, estimate = candidate, total
                    break
            if estimate is None:
                estimate = total
        if below_h and name in below_h:
            # the hyperfocal rung's H alone (its closed form, not its limits): its far limit is ∞ exactly from H on
            h = _hyperfocal_only(rung_h, h_data, f, f_number, usable if applied else coc_mm, distance_from)
            cheap = None if distance_mm >= h else _run(name, applied, f, f_number, coc_mm, distance_mm,
                                                       distance_from, lens, usable, focus)
            if cheap is None or cheap[1] == _INF:
                # at or beyond the hyperfocal distance: its rung, whose far limit starts being infinite at H
                at_h = _run(rung_h, applied, f, f_number, coc_mm, distance_mm, distance_from, lens, usable, focus)
                if diffraction:  # diffraction asked for: its share is in the estimate unless it was added
                    return ModelResult(at_h, _label(rung_h, applied), left_out(effects, rung_h, applied))
                total = 0.0
                for i in dict(sums)[rung_h]:
                    total += effects[i]
                return ModelResult(at_h, rung_h, total)
            # the fields in order, hyperfocal_mm the sixth (tuple.__new__: a third of _replace's cost)
            limits = _TUPLE_NEW(DofLimits, (cheap[0], cheap[1], cheap[2], cheap[3], cheap[4], h, cheap[6]))
            return ModelResult(limits, _label(name, applied), estimate)
        limits = _run(name, applied, f, f_number, coc_mm, distance_mm, distance_from, lens, usable, focus)
        return ModelResult(limits, _label(name, applied), estimate)
    inputs = (f, f_number, coc_mm, distance_mm, usable)
    return _auto_each(effects, available_models(lens), diffraction, tolerance, inputs, airy, distance_from, lens,
                      focus)


_BLOCK = 16384
"""``auto`` over more scenes than this in one input (closed-form rungs only) runs a block of them at a time
(:func:`_auto_in_blocks`)."""


def _auto_in_blocks(f: Any, n: Any, c: Any, s: Any, plane: str, lens: LensData, tolerance: float) -> ModelResult | None:
    """``auto`` without diffraction or a prescription over many scenes, :data:`_BLOCK` scenes at a time.

    Each scene's answer is computed on its own by every step (the choice and
    the closed-form rungs work scene by scene), so a block gives the numbers
    the whole arrays would; but a block's arrays stay in the processor's
    cache and the allocator reuses their memory, where arrays of every
    scene at once are page-faulted in again on every step (at 200,000
    scenes about 40 % of the time: benchmarks/README.md). None when the
    inputs do not broadcast, or when a block raises: the whole arrays then
    run at once, so the error names the scene and the check a single call
    over them names.
    """
    import numpy as np

    inputs = (f, n, c, s)
    if any(v is None for v in inputs):
        return None
    try:
        shape = np.broadcast_shapes(*(np.shape(v) for v in inputs))
    except ValueError:
        return None
    count = math.prod(shape)
    flat = [v if np.ndim(v) == 0 else np.broadcast_to(v, shape).reshape(-1) for v in inputs]
    fields = [np.empty(count) for _ in DofLimits._fields]
    names = np.empty(count, dtype=object)
    estimate = np.empty(count)
    try:
        for start in range(0, count, _BLOCK):
            part = slice(start, start + _BLOCK)
            f, n, c, s = (v if np.ndim(v) == 0 else v[part] for v in flat)
            result = depth_of_field("auto", f, n, c, s, plane, lens, tolerance=tolerance)
            for out, value in zip(fields, result.limits):
                out[part] = value
            names[part] = result.model
            estimate[part] = result.error_estimate
    except CamtoolError:
        return None
    return ModelResult(DofLimits(*(v.reshape(shape) for v in fields)), names.reshape(shape), estimate.reshape(shape))


Plan = tuple[tuple[str, ...], str, frozenset[str], tuple[tuple[str, tuple[int, ...]], ...], tuple[float, ...]]
_PLANS: dict[int, tuple[LensData, Any, Plan]] = {}
_INF = float("inf")
_TUPLE_NEW = tuple.__new__


def _plan(lens: LensData) -> Plan:
    """(available rungs, the hyperfocal rung, the rungs cheaper than it, each rung's left-out effects as indices of
    :class:`Effects`, the hyperfocal rung's lens data: () for thin, (P, δ) for thick, (f, P, δ) for paraxial) of
    ``lens``, remembered by its identity.

    ``auto`` asks on every call; hashing a prescription's surfaces for the
    cached functions behind these costs more than a closed-form rung, so the
    answer is kept per LensData object (held, so its id is not reused) and
    per ladder (:data:`camtool.dof.rungs.RUNGS`, by identity).
    """
    entry = _PLANS.get(id(lens))
    if entry is None or entry[0] is not lens or entry[1] is not rungs.RUNGS:
        models, rung_h = available_models(lens), _hyperfocal_rung_of(lens)
        order = rungs.names()
        below = frozenset(m for m in models if rung_h in models and order.index(m) < order.index(rung_h))
        sums = tuple((m, tuple(Effects._fields.index(e) for e in rungs.by_name()[m].left_out)) for m in models)
        data: tuple[float, ...] = ()
        if rung_h == "paraxial":
            fo = lens.first_order
            data = (fo.efl_mm, fo.pupil_magnification, fo.hiatus_mm)
        elif rung_h == "thick":
            data = lens.thick_parameters()  # type: ignore[assignment]
        if len(_PLANS) >= 64:
            _PLANS.clear()
        entry = _PLANS[id(lens)] = (lens, rungs.RUNGS, (models, rung_h, below, sums, data))
    return entry[2]


@functools.cache
def _thick_hyperfocal() -> Any:
    """:func:`camtool.dof.thick.thick_hyperfocal_mm`, imported on first use (start-up) and then kept at hand."""
    from camtool.dof.thick import thick_hyperfocal_mm

    return thick_hyperfocal_mm


def _hyperfocal_only(rung_h: str, data: tuple[float, ...], f: Any, n: Any, c: Any, plane: str) -> Any:
    """The hyperfocal distance the rung ``rung_h`` (thin, thick or paraxial) reports, by its closed form alone.

    ``data`` is the rung's lens data from :func:`_plan`: () for thin, (P, δ) for thick, (f, P, δ) for paraxial.
    """
    if rung_h == "thin":
        return thin_hyperfocal_mm(f, n, c, plane)
    if rung_h == "paraxial":
        f, p, delta = data
    else:
        p, delta = data
    return _thick_hyperfocal()(f, n, c, p, delta, plane)


def _hyperfocal_rung_of(lens: LensData) -> str:
    """:func:`hyperfocal_rung` where the ladder offers it for ``lens`` (a prescription's thick is its paraxial)."""
    name = hyperfocal_rung(lens)
    models = available_models(lens)
    if name in models:
        return name
    return "paraxial" if "paraxial" in models else "thin"


_ANY_SCENE = frozenset({"approx", "thin"})
"""Rungs that check nothing beyond what the dispatcher's focus conversion has checked: ``auto`` over arrays may run
one over every scene, the rows other rungs answer included (no error, no warning there), and write those rows over."""

_SHARE = 0.5
"""The least share of the scenes for which a rung of :data:`_ANY_SCENE` runs over every scene rather than its own."""

_TAKES_H = frozenset({"thin", "thick"})
"""Rungs whose hyperfocal distance is :func:`_hyperfocal_only`'s closed form: ``auto`` hands them the H it has."""


def _auto_each(effects: Effects, models: tuple[str, ...], diffraction: bool, tolerance: float,
               inputs: tuple[Any, ...], airy: Any, plane: str, lens: LensData,
               focus: rungs.Focus | None = None) -> ModelResult:
    """``auto`` over arrays: each scene gets its own cheapest sufficient rung, as a single call would.

    The scenes are grouped by the rung chosen; each group runs in one
    vectorised call with the scenes' (u, v) and, for the hyperfocal rung, the
    H the choice took, and the results go back in place; ``model`` is then
    an array of names, one per scene. The largest group whose rung can run
    on any scene (:data:`_ANY_SCENE`), when it holds at least :data:`_SHARE`
    of them, or a rung every scene chose, runs over all the scenes instead: its results are the arrays the others'
    rows are written into, so its own scenes are neither gathered nor
    scattered. Every scene's numbers are those its rung gives it alone.
    """
    import numpy as np

    if focus is not None:  # the scenes' (u, v) go with them into each group
        inputs = (*inputs, focus.geometry.object_mm, focus.geometry.image_mm)
    shape = np.broadcast_shapes(*(np.shape(v) for v in (*inputs, airy, *effects)))

    def flatten(v: Any) -> Any:
        """One value per scene, flat (a view where it can be); a number stays a number (nothing to copy or index)."""
        if type(v) is np.ndarray and v.ndim and v.shape == shape and v.dtype == np.float64:
            return v.reshape(-1)  # read, never written
        return float(v) if np.ndim(v) == 0 else np.broadcast_to(np.asarray(v, dtype=float), shape).ravel()

    flat = [flatten(v) for v in inputs]
    each = Effects(*(flatten(v) for v in effects))
    count = math.prod(shape)
    # each rung's estimate (what it leaves out): over every scene, or one number where every term is a number
    applied = None
    totals = [left_out(each, name, True) for name in models]
    if diffraction:  # the add-on runs where diffraction alone exceeds the tolerance; elsewhere it is left out
        applied = np.broadcast_to(each.diffraction > tolerance, (count,))
        # each scene's sum in left_out's order (diffraction first where it is left out), as a single call adds it
        totals = [np.where(applied, total, left_out(each, name, False)) for name, total in zip(models, totals)]
    chosen = np.full(count, len(models) - 1)
    for index in reversed(range(len(models) - 1)):
        chosen = np.where(totals[index] <= tolerance, index, chosen)
    rung_h = _hyperfocal_rung_of(lens)
    h_index = models.index(rung_h) if rung_h in models else -1
    hyper = None
    if h_index > 0:
        # a rung cheaper than the hyperfocal rung only in front of that rung's H (its closed form): from H on, it runs
        f, n, c, s, usable = flat[:5]
        hyper = np.broadcast_to(_hyperfocal_only(rung_h, _plan(lens)[4], f, n,
                                                 c if applied is None else np.where(applied, usable, c), plane),
                                (count,))
        chosen = np.where((chosen < h_index) & (s >= hyper), h_index, chosen)
    hands_h = hyper is not None and rung_h in _TAKES_H
    hf = DofLimits._fields.index("hyperfocal_mm")

    def run(index: int, add: bool, rows: Any) -> DofLimits:
        """The rung ``index`` over the scenes ``rows`` (None: every scene), in one vectorised call."""
        f, n, c, s, usable, *uv = (v if rows is None or isinstance(v, float) else v[rows] for v in flat)
        part_focus = None
        if focus is not None:
            h = hyper if hands_h and index == h_index else None
            part_focus = rungs.Focus(FocusGeometry(uv[0], uv[1], None, None, None), focus.hiatus_mm,
                                     h if h is None or rows is None else h[rows])
        return _run(models[index], add, f, n, c, s, plane, lens, usable, part_focus)

    # (rung, add-on, scenes) of every rung chosen; the largest that may run over every scene does
    width = 1 if applied is None else 2
    codes = chosen if applied is None else 2 * chosen + applied
    sizes = np.bincount(codes, minlength=width * len(models))
    groups = [(int(k) // width, bool(k % width), int(size)) for k, size in enumerate(sizes) if size]
    whole = [group for group in groups
             if group[2] == count or (models[group[0]] in _ANY_SCENE and group[2] >= _SHARE * count)]
    base = max(whole, key=lambda group: group[2]) if whole else None
    if base is None:
        fields = [np.empty(count) for _ in DofLimits._fields]
        names = np.empty(count, dtype=object)
        estimate = np.empty(count)
    else:
        fields = _writable(run(base[0], base[1], None), count)
        names = np.empty(count, dtype=object)
        names.fill(_label(models[base[0]], base[1]))  # np.full of an object is 30 times slower
        estimate = np.array(np.broadcast_to(totals[base[0]], (count,)), dtype=float)

    pending: list[tuple[bool, Any]] = []  # cheaper rows whose far limit may be ∞ where the hyperfocal rung's is not

    def put(index: int, add: bool, rows: Any) -> None:
        """Run rung ``index`` over ``rows`` and put its limits (H too unless it is cheaper), name and estimate in place.

        A cheaper rung's own far limit can reach ∞ a little before the hyperfocal rung's H: where the
        hyperfocal rung ran over every scene, those rows keep its answer; else they run it afterwards.
        """
        part = list(run(index, add, rows))
        if index < h_index:
            if base is not None and base[:2] == (h_index, add):
                back = np.isinf(part[1])
                if back.any():
                    keep = ~back
                    rows, part = rows[keep], [value[keep] for value in part]
            else:
                pending.append((add, rows))
        for i, value in enumerate(part):
            if i != hf or index >= h_index:
                fields[i][rows] = value
        names[rows] = _label(models[index], add)
        total = totals[index]
        estimate[rows] = total if np.ndim(total) == 0 else total[rows]

    def rows_of(index: int, add: bool) -> Any:
        return np.nonzero(codes == (index if applied is None else 2 * index + add))[0]

    for index, add, size in groups:
        if (index, add, size) != base:
            put(index, add, rows_of(index, add))
    if hyper is not None:
        if not (hands_h and base is not None and base[0] == h_index):  # else the H handed is in place already
            cheaper = np.nonzero(chosen < h_index)[0]
            fields[hf][cheaper] = hyper[cheaper]
        if base is not None and base[0] < h_index:
            pending.append((base[1], rows_of(base[0], base[1])))
        for add, rows in pending:  # a cheaper rung's far limit at ∞ in front of H: the hyperfocal rung runs there
            again = rows[np.isinf(fields[1][rows])]
            if again.size:
                put(h_index, add, again)
    limits = DofLimits(*(field.reshape(shape) for field in fields))
    return ModelResult(limits, names.reshape(shape), estimate.reshape(shape))


def _writable(values: Any, count: int) -> list[Any]:
    """``values`` as separate, writable arrays of ``count`` entries each (copied only where they are not)."""
    import numpy as np

    out: list[Any] = []
    for value in values:
        array = np.asarray(value, dtype=float)
        if (array.shape != (count,) or not array.flags.writeable or array.base is not None
                or any(array is other for other in out)):
            array = np.array(np.broadcast_to(array, (count,)))
        out.append(array)
    return out


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
    criterion: Any = None,
) -> list[ModelComparison]:
    """Every rung the lens data allow, for the same scene, with its difference from the most complete one and its cost.

    The geometric rungs come first, then ``wave`` by ``criterion`` (left out
    when some scene's in-focus MTF is below the criterion's level).
    ``difference`` is :func:`camtool.dof.auto.depth_error` against the most
    complete geometric rung; ``time_per_evaluation_s`` the best of ``repeat``
    timed runs (``time.perf_counter``) divided by the number of scenes.

    Examples
    --------
    >>> rows = compare_models(50.0, 8.0, 0.03, 3000.0)
    >>> [(r.result.model, round(r.difference, 4)) for r in rows]
    [('approx', 0.0287), ('thin', 0.0), ('wave', 0.0702)]
    """
    lens = lens or NO_LENS
    f = prescription_focal_length(lens, focal_length_mm)
    from camtool.dof.closed import check_inputs

    check_inputs(f, f_number, coc_mm)
    count = 1
    for value in (f, f_number, coc_mm, distance_mm):
        count = max(count, getattr(value, "size", 1))
    from camtool.dof.wave import ContrastUnreachable

    results: list[tuple[ModelResult, float]] = []
    geometric = available_models(lens)
    for name in (*geometric, "wave"):
        best = float("inf")
        for _ in range(max(repeat, 1)):
            start = time.perf_counter()
            try:
                result = depth_of_field(name, f, f_number, coc_mm, distance_mm, distance_from, lens, diffraction,
                                        wavelength_nm, criterion=criterion)
            except ContrastUnreachable:
                break  # no answer by contrast for some scene: the geometric rungs stand alone
            best = min(best, time.perf_counter() - start)
        else:
            results.append((result, best / count))
        step()  # a timed, traced rung: a progress bar listens
    reference = results[len(geometric) - 1][0].limits
    return [ModelComparison(result, depth_error(result.limits, reference), seconds) for result, seconds in results]
