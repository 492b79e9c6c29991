"""Focus stacking: every decision of ``camtool stack`` (docs/stack.md).

:func:`stack_mode` chooses rail or bracketing from what was given;
:func:`rail_stack` plans a rail stack (the criterion by magnification, the
usable CoC under diffraction, the lens's largest magnification) and
:func:`rail_rows` / :func:`rail_chunks` give its frames a chunk at a time, so a
plan of any length streams; :func:`bracket_stack` plans focus bracketing (the
rung, the frame and evaluation limits, a lens preset's internal-focus model,
its closest focus, the hyperfocal setting of the farthest frame, which is
:func:`camtool.plans.depth.hyperfocal_setting`'s) and returns the frames with
the facts of the footer.

All lengths in millimetres.
"""

from __future__ import annotations

import math
from collections.abc import Iterator
from typing import Any

from camtool.core.errors import DomainError, InputError
from camtool.core.record import NamedTuple
from camtool.dof.ladder import LensData, depth_of_field, focal_lengths, hyperfocal_choices
from camtool.dof.stack import (
    MAX_RAIL_FRAMES,
    BracketFrame,
    RailPlan,
    bracket_plan,
    internal_bracket_plan,
    rail_plan,
    wave_coc_mm,
)
from camtool.plans.closeup import focus_models, has_focus_model
from camtool.plans.depth import hyperfocal_setting
from camtool.render.columnar import ColumnRows

__all__ = [
    "DEFAULT_OVERLAP",
    "EVALUATIONS",
    "MAX_FRAMES",
    "WAVE_FROM",
    "BracketStack",
    "RailStack",
    "bracket_rows",
    "bracket_stack",
    "most_frames",
    "rail_chunks",
    "rail_rows",
    "rail_stack",
    "stack_mode",
]

DEFAULT_OVERLAP = 0.2
"""A fifth of each frame's depth shared with the next: margin for rail and focus-ring error."""
MAX_FRAMES = 10_000
"""The most frames a bracketing plan may have (thin and approx models, in closed form)."""
EVALUATIONS = {"thick": 20_000, "paraxial": 20_000, "raytrace": 250}
"""The most evaluations of the model one bracketing plan may make, for the rungs solved numerically.

A frame costs about ten evaluations (two for a bracket around the thin
lens's answer, a few of regula falsi): 159 for the 17 frames of
``camtool stack -N 1 --near 4.56 --far 9.66 --overlap 0.684 --prescription
canon-rf50-f1.2``. A ray-traced evaluation takes some 60 ms, so a raytrace
plan is bounded at about fifteen seconds on one core; thick and paraxial
evaluations are closed forms or a paraxial trace, far cheaper."""
EVALUATIONS_PER_FRAME = 10
"""The evaluations a numerically solved frame is budgeted: the frame limit of a rung is its cap over this."""
WAVE_FROM = 1.0
"""From this magnification on (life size), the default criterion is the wave-optics depth."""


def stack_mode(*, magnification: list[float], depth_mm: float | None, near_mm: float | None,
               far_mm: float | None) -> str:
    """``"rail"`` (a magnification and a depth) or ``"bracket"`` (a near and a far limit), from what was given.

    >>> stack_mode(magnification=[1.0], depth_mm=10.0, near_mm=None, far_mm=None)
    'rail'
    """
    rail = bool(magnification) or depth_mm is not None
    if rail and (near_mm is not None or far_mm is not None):
        raise InputError("near", "give {magnification} and {depth} (rail) or {near} and {far} (bracketing), not both",
                         usage=True)
    if rail:
        if depth_mm is None:
            raise InputError("depth", "Missing option '{depth}' (the subject depth for rail mode).", usage=True)
        if not magnification:
            raise InputError("magnification", "Missing option '{magnification}' (the magnification for rail mode).",
                             usage=True)
        return "rail"
    if near_mm is None or far_mm is None:
        raise InputError("near", "give {magnification} and {depth} (rail mode) or {near} and {far} (bracketing "
                         "mode)", usage=True)
    return "bracket"


def most_frames(model: str) -> int:
    """The most frames of a bracketing plan by this rung: its evaluation cap over a frame's budget, else 10,000.

    >>> most_frames("thin"), most_frames("raytrace")
    (10000, 25)
    """
    return EVALUATIONS[model] // EVALUATIONS_PER_FRAME if model in EVALUATIONS else MAX_FRAMES


def _usable(n: float, c: float, m: float, p: float, wavelength_nm: float) -> float:
    """The CoC left for defocus by the Airy disc; a DomainError on ``f_number`` when nothing is sharp."""
    from camtool.dof.closeup import diffraction_row

    d = diffraction_row(n, c, m, p, wavelength_nm)
    if not d.sharp:
        raise DomainError("f_number", f"f/{n:g}", f"below f/{d.limit_f_number:.3g}",
                          detail=f"the Airy disc, {d.airy_mm:.3g} mm, fills the CoC {c:.3g} mm: nothing is sharp")
    return float(d.usable_coc_mm)


class RailStack(NamedTuple):
    """A rail plan and what decided it: the criterion, the CoC used (after diffraction), the magnification."""

    plan: RailPlan
    magnification: float
    criterion: str
    coc_mm: float
    depth_mm: float
    overlap: float

    @property
    def frames(self) -> int:
        return self.plan.frames


def rail_stack(*, depth_mm: float, f_number: float, magnification: float, coc_mm: float,
               criterion: Any = None, overlap: float = DEFAULT_OVERLAP, pupil_magnification: float = 1.0,
               wavelength_nm: float = 550.0, focal_length_mm: float | None = None, diffraction: bool = False,
               model: str = "auto", lens_preset: Any = None, max_frames: int = MAX_RAIL_FRAMES) -> RailStack:
    """A rail stack: the criterion (wave from 1:1 up unless named), the CoC and :func:`camtool.dof.stack.rail_plan`.

    ``criterion`` is ``classic``, ``wave`` or a contrast criterion
    (:class:`camtool.dof.wave.Criterion`: each frame's depth is where the
    perfect lens's MTF meets it, docs/wave.md).

    Refuses a magnification beyond the lens preset's published largest, and
    the paraxial and raytrace models (the frames are the close-up closed form).

    Examples
    --------
    1:1 at f/8, 10 mm: the wave depth λ/NA² = 4·λ·N²·(1 + m)² = 4 × 550 nm × 256 = 0.5632 mm a frame
    (Zerene Stacker, "DOF Estimates For Macro/Micro"), so 18 frames at overlap 0:

    >>> r = rail_stack(depth_mm=10.0, f_number=8.0, magnification=1.0, coc_mm=0.03, overlap=0.0)
    >>> r.criterion, r.frames, round(r.plan.step_mm, 4)
    ('wave', 18, 0.5632)
    """
    largest = getattr(lens_preset, "max_magnification", None)
    if largest and magnification > largest * (1.0 + 1e-9):
        raise DomainError("magnification", magnification, f"0 to {largest:g} (the lens's largest magnification)")
    if model in ("paraxial", "raytrace"):
        raise InputError("model", f"{model} is not available in rail mode: the frames use the close-up closed form "
                         "(thin, or thick with the pupil magnification); it applies to {near}/{far}")
    chosen = criterion or ("wave" if magnification >= WAVE_FROM else "classic")
    c = coc_mm
    if diffraction and chosen == "classic":
        c = _usable(f_number, c, magnification, pupil_magnification, wavelength_nm)
    plan = rail_plan(depth_mm, f_number, magnification, chosen, c, overlap, pupil_magnification, wavelength_nm,
                     focal_length_mm, max_frames)
    return RailStack(plan, float(magnification), plan.criterion, c, float(depth_mm), float(overlap))


def rail_rows(stack: RailStack, *, start: int = 0, stop: int | None = None) -> ColumnRows:
    """Frames ``start + 1`` to ``stop`` of a rail plan, as columns: frame k's near limit is (k − 1)·step.

    A plan of more than one chunk is computed as arrays (the writer turns a
    float array into text in one pass); the values are the same products
    k·step either way.

    >>> rows = rail_rows(rail_stack(depth_mm=10.0, f_number=8.0, magnification=1.0, coc_mm=0.03, overlap=0.0))
    >>> rows.size, rows.columns["near_mm"][1] == rows.columns["step_mm"][1]
    (18, True)
    """
    plan = stack.plan
    stop = plan.frames if stop is None else stop
    count = max(0, stop - start)
    front, depth = plan.front_mm, plan.front_mm + plan.rear_mm
    step: Any
    extension: Any
    if math.isinf(plan.step_mm):  # one frame, sharp to infinity behind its focus: no step
        near: Any = [0.0] * count
        step = extension = [0.0] * count
        focus: Any = [front] * count
        far: Any = [math.inf] * count
    elif plan.frames <= _CHUNK:
        near = [k * plan.step_mm for k in range(start, stop)]
        step, extension = [plan.step_mm] * count, [plan.extension_step_mm] * count
        if start == 0 and count:
            step[0] = extension[0] = 0.0
        focus, far = [x + front for x in near], [x + depth for x in near]
    else:
        import numpy as np

        near = np.arange(start, stop, dtype=np.float64) * plan.step_mm
        step, extension = np.full(count, plan.step_mm), np.full(count, plan.extension_step_mm)
        if start == 0:
            step[0] = extension[0] = 0.0
        focus, far = near + front, near + depth
    columns = {"frame": list(range(start + 1, stop + 1)), "distance_mm": focus, "near_mm": near, "far_mm": far,
               "magnification": stack.magnification, "step_mm": step, "extension_step_mm": extension,
               "criterion": plan.criterion, "mode": "rail", "distance_from": "subject"}
    return ColumnRows(count, columns)


_CHUNK = 20_000
"""Rail plans up to this many frames are built as lists; longer ones as arrays (the command line's chunk)."""


def rail_chunks(stack: RailStack, *, size: int = _CHUNK) -> Iterator[ColumnRows]:
    """The frames of a rail plan, ``size`` at a time: constant memory for a plan of any length.

    >>> [c.size for c in rail_chunks(rail_stack(depth_mm=10.0, f_number=8.0, magnification=1.0, coc_mm=0.03,
    ...                                          overlap=0.0), size=8)]
    [8, 8, 2]
    """
    for start in range(0, stack.frames, size):
        yield rail_rows(stack, start=start, stop=min(start + size, stack.frames))


class BracketStack(NamedTuple):
    """A focus-bracketing plan and the facts of its footer.

    ``model`` is the rung that solved the frames, ``coc_mm`` the CoC used (the
    wave criterion's 2λN, or the usable CoC under diffraction), and
    ``focal_range_mm`` the focal lengths the frames are at when the lens
    focuses internally (None otherwise).
    """

    frames: list[BracketFrame]
    hyperfocal_mm: float
    model: str
    criterion: str
    coc_mm: float
    focal_range_mm: tuple[float, float] | None
    distance_from: str


def _rung(model: str, lens: LensData | None, f: float, n: float, c: float, near_mm: float, plane: str) -> str:
    """The rung of a bracketing plan. ``auto`` means what it means everywhere (:func:`camtool.dof.ladder.depth_of_field`):
    the cheapest rung within the tolerance, here for the plan's most demanding scene, the nearest frame; and never
    cheaper than :func:`camtool.dof.ladder.hyperfocal_rung`, so a bracket to infinity ends at the hyperfocal distance
    ``camtool hyperfocal`` gives."""
    if model != "auto":
        return model
    from camtool.core.errors import CamtoolError
    from camtool.dof import rungs
    from camtool.dof.ladder import depth_of_field, hyperfocal_rung

    floor = hyperfocal_rung(lens)
    try:
        picked = str(depth_of_field("auto", f, n, c, near_mm, plane, lens).model).split("+")[0]
    except CamtoolError:  # the near limit is out of this focus's reach: the plan's own checks say why
        return floor
    order = rungs.names()
    return max(picked, floor, key=order.index) if picked in order else floor


def bracket_stack(*, focal_length_mm: float | None, f_number: float, coc_mm: float, near_mm: float, far_mm: float,
                  overlap: float = DEFAULT_OVERLAP, criterion: Any = None, model: str = "auto",
                  lens: LensData | None = None, lens_preset: Any = None, pupil_magnification: float = 1.0,
                  wavelength_nm: float = 550.0, diffraction: bool = False, tolerance: float = 0.01,
                  distance_from: str = "sensor", lens_name: str | None = None) -> BracketStack:
    """A focus-bracketing plan: the focal length, the rung, the lens's own focusing, the limits, and every frame.

    The focal length is the one given, else the prescription's.
    ``auto`` is the cheapest rung within the tolerance for the nearest frame,
    never cheaper than the hyperfocal distance's (see :func:`_rung`). A lens
    preset with a published closest focus focuses internally
    (:func:`camtool.dof.stack.internal_bracket_plan`); otherwise the frames are
    :func:`camtool.dof.stack.bracket_plan`'s, refused when frame 1 would
    focus closer than the preset's closest focus. With the approx, thin and
    thick rungs (no prescription) the farthest frame is focused at
    :func:`camtool.plans.depth.hyperfocal_setting`'s distance, the same float
    ``camtool hyperfocal`` prints. A rung solved numerically is refused at once
    (a DomainError on ``near_mm``) when the thin lens's plan already has more
    frames than :func:`most_frames` allows it. ``lens_name`` is the preset as the caller named it (in errors).

    Examples
    --------
    24 mm f/11, c = 0.03 mm, 0.5 m to infinity from the lens: the last frame is at H = f²/(N·c) + f
    (Wikipedia, "Hyperfocal distance"):

    >>> s = bracket_stack(focal_length_mm=24.0, f_number=11.0, coc_mm=0.03, near_mm=500.0, far_mm=math.inf,
    ...                   overlap=0.0, distance_from="lens")
    >>> len(s.frames), s.model, s.frames[-1].distance_mm == 24.0 ** 2 / (11.0 * 0.03) + 24.0
    (2, 'thin', True)
    """
    if criterion is not None and not isinstance(criterion, str):
        raise InputError("criterion", "a contrast criterion sets the depth of each frame of a rail stack "
                         "({magnification} and {depth}); bracketing takes classic or wave", usage=True)
    focal = focal_lengths(lens, [] if focal_length_mm is None else [focal_length_mm])
    if not focal:
        raise InputError("focal_length", "Missing option '{focal_length}'.", usage=True)
    f, n = float(focal[0]), float(f_number)
    chosen = criterion or "classic"
    c = coc_mm
    if chosen == "wave":
        c = float(wave_coc_mm(f_number, 0.0, pupil_magnification, wavelength_nm))
    elif diffraction:
        c = _usable(f_number, c, 0.0, pupil_magnification, wavelength_nm)
    rung = _rung(model, lens, f, n, c, near_mm, distance_from)
    numeric = rung not in ("thin", "approx")
    one_h = rung in hyperfocal_choices() and (lens is None or lens.prescription is None)
    focusing = focus_models(lens_preset)(f) if has_focus_model(lens_preset) else None
    if focusing is not None:  # the lens focuses internally: each frame at its own focal length, as dof has it
        if focusing.min_magnification > 0.0:
            raise DomainError("lens", lens_name or getattr(lens_preset, "id", lens_preset), "a lens that focuses to infinity",
                              detail=f"this one works from {focusing.min_magnification:g}× to "
                                     f"{focusing.max_magnification:g}×: stack it on a rail with -m and --depth")
        m_hyper = hyperfocal_setting(model=rung, focal_length_mm=f, f_number=n, coc_mm=c, distance_from=distance_from,
                                     lens=lens, lens_preset=lens_preset).magnification if one_h else None
        by_rung = _limits_at(rung, n, c, lens, tolerance) if numeric else None
        if numeric:
            _bounded(rung, near_mm, lambda most: internal_bracket_plan(focusing, n, c, near_mm, far_mm, overlap,
                                                                       "thin", most, None, distance_from))
        plan = internal_bracket_plan(focusing, n, c, near_mm, far_mm, overlap, rung, most_frames(rung), by_rung,
                                     distance_from, m_hyper)
        focal = [focusing.focal_length_mm / (1.0 + focusing.kappa * frame.magnification) for frame in plan.frames]
        return BracketStack(plan.frames, plan.hyperfocal_mm, rung, chosen, c, (min(focal), max(focal)), distance_from)
    delta = float(lens.hiatus_mm) if lens is not None and lens.hiatus_mm is not None else 0.0
    limits = hyper = shown = None
    if one_h:  # a closed form keeps its own H for the chain (the same up to the last bit), the shown one ends it
        if numeric:
            hyper = hyperfocal_setting(model=rung, focal_length_mm=f, f_number=n, coc_mm=c, distance_from="lens",
                                       lens=lens).hyperfocal_mm
        shown = hyperfocal_setting(model=rung, focal_length_mm=f, f_number=n, coc_mm=c, distance_from=distance_from,
                                   lens=lens).hyperfocal_mm
    if numeric:
        _bounded(rung, near_mm, lambda most: bracket_plan(f, n, c, near_mm, far_mm, overlap, "thin", most, None, None,
                                                          distance_from, delta))
        limits, ladder_h = _limits(rung, f, n, c, lens, tolerance)
        hyper = ladder_h if hyper is None else hyper
    plan = bracket_plan(f, n, c, near_mm, far_mm, overlap, rung, most_frames(rung), limits, hyper, distance_from,
                        delta, shown, EVALUATIONS.get(rung) if numeric else None)
    _check_closest_focus(plan.frames[0].distance_mm, near_mm, f, distance_from, delta, lens_preset)
    return BracketStack(plan.frames, plan.hyperfocal_mm, rung, chosen, c, None, distance_from)


def bracket_rows(stack: BracketStack) -> list[dict[str, Any]]:
    """The rows of a bracketing plan: each frame, and its step from the previous focus (0 for frame 1)."""
    rows = []
    previous = None
    for k, frame in enumerate(stack.frames, 1):
        rows.append({"frame": k, "distance_mm": frame.distance_mm, "near_mm": frame.near_mm,
                     "far_mm": frame.far_mm, "magnification": frame.magnification,
                     "step_mm": 0.0 if previous is None else frame.distance_mm - previous, "extension_step_mm": None,
                     "criterion": stack.criterion, "mode": "bracket", "distance_from": stack.distance_from})
        previous = frame.distance_mm
    return rows


def _bounded(rung: str, near_mm: float, thin_plan: Any) -> None:
    """Refuse at once a plan the thin lens puts past the ``rung``'s frame limit, before solving any frame by it.

    The thin lens's frames (closed form, a few µs each) stand in for the
    count: a plan whose every frame is solved through a numerical rung costs
    evaluations of the model a frame, so one beyond the limit is refused
    without spending seconds to find out. A count near the limit is settled
    by the rung's own plan, which stops at the same limit and evaluation cap.
    """
    most = most_frames(rung)
    try:
        thin_plan(most + most // 10)  # a margin: the rung's own count may be a little lower
    except DomainError as error:
        if error.param == "near_mm" and "frames" in error.detail:
            raise DomainError("near_mm", f"{near_mm / 1000:.4g} m", f"far enough that at most {most} frames reach "
                              f"--far with the {rung} model (it solves each frame numerically; the thin and approx "
                              f"models plan up to {MAX_FRAMES})") from None
        # any other error is the rung's own to report


def _check_closest_focus(first: float, near_mm: float, f: float, plane: str, delta: float, preset: Any) -> None:
    """A DomainError on ``near_mm`` when frame 1 would focus closer than the lens preset's closest focus."""
    closest = getattr(preset, "min_focus_mm", None)
    if not closest or getattr(preset, "is_zoom", False):
        return
    sensor = first if plane == "sensor" else first + f * first / (first - f) + delta
    if sensor < closest * (1.0 - 1e-9):
        raise DomainError("near_mm", f"{near_mm / 1000:.4g} m", f"frame 1 would focus at {sensor / 1000:.4g} m from "
                          f"the sensor, closer than the lens's closest focus ({closest / 1000:.4g} m); give a "
                          "farther --near")


def _limits_at(rung: str, n: float, c: float, lens: LensData | None, tolerance: float) -> Any:
    """(f, u) -> (near, far) from the lens by one rung of the ladder, for a lens whose focal length changes."""

    def limits(f: float, u: float) -> tuple[float, float]:
        r = depth_of_field(rung, f, n, c, u, "lens", lens, False, 550.0, tolerance).limits
        return float(r.near_mm), float(r.far_mm)

    return limits


def _limits(rung: str, f: float, n: float, c: float, lens: LensData | None, tolerance: float) -> tuple[Any, float]:
    """u -> (near, far) from the lens by one rung of the ladder, and that rung's hyperfocal distance."""

    def limits(u: float) -> tuple[float, float]:
        r = depth_of_field(rung, f, n, c, u, "lens", lens, False, 550.0, tolerance).limits
        return float(r.near_mm), float(r.far_mm)

    first = depth_of_field(rung, f, n, c, 10.0 * f, "lens", lens, False, 550.0, tolerance).limits
    return limits, float(first.hyperfocal_mm)
