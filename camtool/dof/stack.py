"""Focus-stacking plans: the frames that cover a depth, on a rail or by the focus ring (docs/stack.md).

Two ways to stack:

* **Rail** (constant magnification m): every frame has the same depth D, so
  the step between frames at the subject is ``s = D·(1 − o)`` for an overlap
  o, and ``n = ⌈depth/s⌉`` frames cover the depth (n·s ≥ depth). The same
  step made by the lens focusing instead of the rail moving is m²·s on the
  image side (Newton's longitudinal magnification, first order).
* **Focus bracketing** (the focus ring moves, distances from the lens): each
  frame's near limit is set at the previous frame's far limit minus o times
  that frame's depth, and the focus distance giving that near limit is solved
  for. In the exact thin lens, with K = f²/(N·c) (the hyperfocal distance
  from the lens is H = K + f) and w = u − f,

      near = u·K/(K + w),   far = u·K/(K − w)   (∞ for w ≥ K),
      u = near·(K − f)/(K − near)   (the focus with a given near limit).

  With overlap 0 the image distances v = f·u/(u − f) of consecutive frames
  are in the constant ratio (1 − a)/(1 + a), a = N·c/f: 1/u is evenly spaced
  only to first order in a. The ``approx`` rule (near = u·H₀/(H₀ + u),
  far = u·H₀/(H₀ − u), H₀ = f²/(N·c)) makes 1/u step by exactly 2/H₀.

Other rungs of the model ladder (thick, paraxial, raytrace) are planned by
solving each frame's focus numerically from the ladder's near limit.

A lens that focuses internally (a lens preset with a published closest focus,
docs/closeup.md §2) has a focal length f(m) = f₀/(1 + κ·m) that shortens as it
focuses closer; :func:`internal_bracket_plan` solves each frame for its
magnification m instead, with that frame's own f(m), u = f(m)·(1 + 1/m) and
the sensor at u + f(m)·(1 + m) + δ, as ``camtool dof`` places it.

All lengths in millimetres.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from typing import Any

from camtool.core.errors import DomainError, require, require_positive
from camtool.core.record import NamedTuple
from camtool.core.steps import step
from camtool.geometry.closeup import InternalFocus
from camtool.optics.roots import golden_section

__all__ = [
    "CRITERIA",
    "MAX_RAIL_FRAMES",
    "BracketFrame",
    "BracketPlan",
    "RailPlan",
    "bracket_plan",
    "frame_depth_mm",
    "internal_bracket_plan",
    "rail_plan",
    "wave_coc_mm",
]

CRITERIA = ("classic", "wave")
"""``classic``: the circle-of-confusion depth; ``wave``: the quarter-wave depth λ/NA²."""

_MM_PER_NM = 1e-6
MAX_RAIL_FRAMES = 1_000_000
"""The most frames of a rail plan: 10⁶, some 12 days of shooting at one frame a second (written in a few seconds)."""


def wave_coc_mm(f_number: Any, magnification: Any = 0.0, pupil_magnification: Any = 1.0,
                wavelength_nm: Any = 550.0) -> Any:
    """The CoC in mm whose classic depth equals the wave-optics depth λ/NA²: c = 2·λ·N_w.

    The close-up rule 2·N_w·c/m² equals 4·λ·N_w²/m² exactly when c = 2·λ·N_w,
    N_w = N·(1 + m/P) the working f-number.

    Examples
    --------
    >>> round(wave_coc_mm(8.0), 6)
    0.0088
    """
    return 2.0 * wavelength_nm * _MM_PER_NM * f_number * (1.0 + magnification / pupil_magnification)


def frame_depth_mm(f_number: float, magnification: float, criterion: Any, coc_mm: float = 0.03,
                   pupil_magnification: float = 1.0, wavelength_nm: float = 550.0,
                   focal_length_mm: float | None = None) -> tuple[float, float]:
    """(front, rear) depth in mm of one frame at magnification m, by the criterion named.

    ``wave``: λ/NA² split evenly; a :class:`camtool.dof.wave.Criterion`: the
    depth by contrast (:func:`camtool.dof.wave.contrast_depth_mm`) split
    evenly. ``classic``: the exact close-up depth of
    :func:`camtool.dof.closeup.closeup_dof` when the focal length is known,
    else the rule N·c·(1 + m/P)/m² each side.

    Examples
    --------
    >>> [round(x, 4) for x in frame_depth_mm(16.0, 1.0, "classic")]
    [0.96, 0.96]
    """
    from camtool.dof.closeup import closeup_dof, macro_depth_mm, wave_depth_mm

    if not isinstance(criterion, str):  # a contrast criterion: camtool.dof.wave.Criterion (docs/wave.md)
        from camtool.dof.wave import contrast_depth_mm

        half = 0.5 * contrast_depth_mm(f_number, magnification, criterion, coc_mm, pupil_magnification, wavelength_nm)
        return half, half
    require("criterion", criterion, criterion in CRITERIA, " or ".join(CRITERIA))
    if criterion == "wave":
        half = 0.5 * float(wave_depth_mm(f_number, magnification, pupil_magnification, wavelength_nm))
        return half, half
    if focal_length_mm is None:
        half = 0.5 * float(macro_depth_mm(f_number, coc_mm, magnification, pupil_magnification))
        return half, half
    r = closeup_dof(focal_length_mm, f_number, coc_mm, magnification, pupil_magnification, "lens")
    return float(r.front_mm), float(r.rear_mm)


class RailPlan(NamedTuple):
    """A constant-magnification (rail) plan; lengths in mm at the subject unless named otherwise."""

    frames: int
    step_mm: float  # rail step between frames at the subject
    extension_step_mm: float  # the same step made by the lens focusing: m²·step, image side
    front_mm: float  # each frame's depth in front of its focus
    rear_mm: float  # and behind it
    covered_mm: float  # (frames − 1)·step + frame depth
    criterion: str


def rail_plan(depth_mm: float, f_number: float, magnification: float, criterion: Any = "wave",
              coc_mm: float = 0.03, overlap: float = 0.2, pupil_magnification: float = 1.0,
              wavelength_nm: float = 550.0, focal_length_mm: float | None = None,
              max_frames: int = MAX_RAIL_FRAMES) -> RailPlan:
    """Frames and rail step in mm that cover a subject depth at constant magnification.

    step = D·(1 − o), D the frame depth (:func:`frame_depth_mm`), and
    frames = ⌈depth/step⌉, so that frames·step ≥ depth: frame k (1-based)
    has its sharp zone centred on [(k − 1)·s, k·s] along the subject.

    A frame sharp to infinity behind its focus (classic criterion with a focal
    length, the subject u = f·(1 + 1/m) at or beyond the hyperfocal distance)
    covers any depth: the plan is one frame, with step and covered depth ∞.
    Only the plan's figures are returned, never a list of frames: frame k's
    near limit is (k − 1)·step, so a plan of any length is written frame by
    frame in constant memory. More than ``max_frames`` frames is a
    :class:`DomainError` on ``depth_mm``.

    Parameters
    ----------
    depth_mm : float, subject depth > 0
    f_number : float, nominal N > 0
    magnification : float, m > 0
    criterion : ``"wave"``, ``"classic"`` or a :class:`camtool.dof.wave.Criterion`
    coc_mm : float, c > 0 (classic only)
    overlap : float, 0 ≤ o < 1, the fraction of each frame's depth shared with the next
    pupil_magnification : float, P > 0
    wavelength_nm : float, λ > 0
    focal_length_mm : float or None (classic: exact close-up depth when given)
    max_frames : int, the most frames a plan may have

    References
    ----------
    Zerene Stacker, "DOF Estimates For Macro/Micro" (step size = λ/NA² at overlap 0);
    docs/stack.md.

    Examples
    --------
    >>> p = rail_plan(10.0, 8.0, 1.0, "wave", overlap=0.0)
    >>> p.frames, round(p.step_mm, 4)
    (18, 0.5632)
    """
    require_positive("depth_mm", depth_mm)
    require("overlap", overlap, 0.0 <= overlap < 1.0, "0 to below 1")
    label = criterion if isinstance(criterion, str) else criterion.label()
    front, rear = frame_depth_mm(f_number, magnification, criterion, coc_mm, pupil_magnification, wavelength_nm,
                                 focal_length_mm)
    require("magnification", magnification, math.isfinite(front) and front > 0.0 and rear > 0.0,
            "one whose frame has a depth (no finite depth in front of the focus)")
    depth = front + rear
    step = depth * (1.0 - overlap)
    if math.isinf(rear):  # sharp to infinity behind the focus: one frame covers any depth
        return RailPlan(1, math.inf, math.inf, front, rear, math.inf, label)
    ratio = depth_mm / step * (1.0 - 1e-12)
    require("depth_mm", depth_mm, ratio <= max_frames, "at most {limit} ({frames:,} frames of "
            "{step:.4g} mm each)".format(limit="{limit}", frames=max_frames, step=step),
            detail=f"more than {max_frames:,} frames: a smaller magnification, a larger f-number or more "
                   "depth per frame needs fewer", limit=max_frames * step / (1.0 - 1e-12))
    frames = max(1, math.ceil(ratio))
    return RailPlan(frames, step, magnification * magnification * step, front, rear, (frames - 1) * step + depth,
                    label)


class BracketFrame(NamedTuple):
    """One frame of a bracketing plan (mm from the lens)."""

    distance_mm: float
    near_mm: float
    far_mm: float
    magnification: float


class BracketPlan(NamedTuple):
    """A focus-bracketing plan: the frames, nearest first (mm from the lens)."""

    frames: list[BracketFrame]
    hyperfocal_mm: float


Limits = Callable[[float], tuple[float, float]]
"""focus distance u from the lens -> (near, far) from the lens."""


def bracket_plan(focal_length_mm: float, f_number: float, coc_mm: float, near_mm: float, far_mm: float,
                 overlap: float = 0.0, model: str = "thin", max_frames: int = 10_000,
                 limits: Limits | None = None, hyperfocal_mm: float | None = None,
                 distance_from: str = "lens", hiatus_mm: float = 0.0, hyperfocal_shown_mm: float | None = None,
                 max_evaluations: int | None = None) -> BracketPlan:
    """Focus distances in mm whose depths of field chain from a near to a far limit.

    Frame 1 has its near limit at ``near_mm``; each next frame's near limit is
    the previous far limit minus ``overlap`` times the previous frame's depth;
    the plan ends at the first frame whose far limit reaches ``far_mm`` (∞:
    the last frame is focused at or beyond the hyperfocal distance, and a
    frame that would focus beyond it is focused at H instead).

    From the lens the chain is solved in closed form (module docstring). From
    the sensor, which stays put while a unit-focusing lens moves, a distance
    S is u + v + δ with v = f·u/(u − f) the image distance of the frame's
    focus u, so frame k's limits are its lens-plane limits plus v_k + δ, and
    the focus that puts a near limit at S is the fixed point of
    u = u_near(S − v(u) − δ) (a contraction with factor about m²). With
    ``limits`` of another model each frame's focus is one root of
    near(u) + v(u) + δ − S on 1/u, solved from a bracket around the thin
    lens's answer (widened only when it does not hold the root), so a frame
    costs a few evaluations of the model, not a fresh search of [1/H, 1/near].

    Parameters
    ----------
    focal_length_mm : float, f > 0
    f_number : float, N > 0
    coc_mm : float, c > 0
    near_mm : float, nearest point to cover: > f from the lens, > 4f + δ from the sensor
    far_mm : float, farthest point (may be ∞), > near
    overlap : float, 0 ≤ o < 1
    model : ``"thin"`` (exact thin lens) or ``"approx"`` (the H₀ = f²/(N·c) rule), in closed form
    max_frames : int, more frames than this is a DomainError on ``near_mm``
    limits : optional function u -> (near, far) from the lens of another model; the focus of
        each frame is then found by bisection on 1/u
    hyperfocal_mm : the model's hyperfocal distance from the lens (default: the closed form's)
    distance_from : ``"lens"`` or ``"sensor"``, the plane of ``near_mm``, ``far_mm`` and the results
    hiatus_mm : δ, the separation of the principal planes (sensor plane only)
    hyperfocal_shown_mm : that hyperfocal distance in the ``distance_from`` plane, as
        :func:`camtool.plans.depth.hyperfocal_setting` gives it: the focus of a frame at H (default:
        H + v(H) + δ from the sensor)
    max_evaluations : the most evaluations of ``limits`` one plan may make (None: no bound); more is a
        DomainError on ``near_mm``

    References
    ----------
    Wikipedia, "Depth of field", §"Derivation of the DOF formulae" (D_N = s(H − f)/(H + s − 2f),
    D_F = s(H − f)/(H − s)); docs/stack.md.

    Examples
    --------
    >>> p = bracket_plan(24.0, 11.0, 0.03, 500.0, float("inf"))
    >>> len(p.frames), round(p.frames[0].distance_mm, 1), p.frames[-1].far_mm
    (2, 691.1, inf)
    """
    require_positive("focal_length_mm", focal_length_mm)
    require_positive("f_number", f_number, unit="")
    require_positive("coc_mm", coc_mm)
    require("overlap", overlap, 0.0 <= overlap < 1.0, "0 to below 1")
    require("distance_from", distance_from, distance_from in ("lens", "sensor"), "lens or sensor")
    f = float(focal_length_mm)
    k = f * f / (f_number * coc_mm)
    hyper = k if model == "approx" else k + f
    if hyperfocal_mm is not None:
        hyper = float(hyperfocal_mm)
    sensor = distance_from == "sensor"
    closest = 4.0 * f + hiatus_mm if sensor else f
    where = "from the sensor (4f + hiatus: the closest a lens focuses at m ≤ 1)" if sensor else \
        "from the lens (the focal length)"
    require("near_mm", near_mm, near_mm > closest, "more than {limit} " + where, limit=closest)
    require("far_mm", far_mm, far_mm > near_mm, "beyond --near")
    numeric = limits is not None
    closed_limits = _closed_limits(f, k, "thin" if numeric else model)
    closed_focus = _closed_inverse(f, k, "thin" if numeric else model)
    if limits is not None:
        limits = _counted(limits, max_evaluations, near_mm)

    def offset(u: float) -> float:
        return f * u / (u - f) + hiatus_mm if sensor else 0.0

    def closed_focus_for_near(wanted: float, guess: float) -> float:
        """The closed form's focus for a near limit ``wanted`` in the plane asked for (a fixed point from the sensor)."""
        u = guess
        for _ in range(100):
            target = wanted - offset(u)
            require("near_mm", near_mm, target > f, "more than {limit} " + where, limit=closest)
            new = closed_focus(target)
            if abs(new - u) <= 1e-13 * u:
                return new
            u = new
        return u

    def focus_for_near(wanted: float, guess: float) -> float:
        solved = limits
        if not numeric or solved is None:
            return closed_focus_for_near(wanted, guess)
        try:  # the thin lens's answer, the centre of the first bracket
            start = closed_focus_for_near(wanted, min(guess, k))
        except DomainError:
            start = guess
        closest_focus = 2.0 * f if sensor else wanted * (1.0 + 1e-12)  # its near limit lies short of ``wanted``
        return _numeric_focus(lambda u: solved(u)[0] + offset(u) - wanted, start, 1.0 / hyper, 1.0 / closest_focus, f)

    # the farthest frame is focused at H: a focus the lens reaches (beyond f from the lens; at most 1:1 from
    # the sensor, as --near is). Only the approx rule's H = f²/(N·c) can fall closer (the thin lens's
    # H = f²/(N·c) + f never does): the rule has no frame there.
    nearest_focus = 2.0 * f if sensor else f
    require("distance_mm", hyper + offset(hyper) if hyper > f else hyper, hyper > nearest_focus,
            "more than {limit} " + ("from the sensor (4f + hiatus, 1:1)" if sensor else "from the lens (f)"),
            detail=f"the {model} model's hyperfocal distance, where the farthest frame is focused",
            limit=nearest_focus + offset(nearest_focus) if sensor else f)
    if limits is None:
        limits = closed_limits
    shown_hyper = float(hyperfocal_shown_mm) if hyperfocal_shown_mm is not None else hyper + offset(hyper)
    # the near limit when focused at H: any wanted near limit beyond it is met by focusing at H
    near_at_hyper = limits(hyper)[0] + offset(hyper)
    u = hyper

    def frame_for(wanted: float) -> BracketFrame:
        nonlocal u  # each frame's focus starts the next one's iteration
        u = hyper if wanted >= near_at_hyper * (1.0 - 1e-12) else focus_for_near(wanted, u)
        lo, hi = limits(u)
        shift = offset(u)
        if u >= hyper:  # focused at the hyperfocal distance: sharp to infinity
            return BracketFrame(shown_hyper, lo + shift, math.inf, f / (u - f))
        return BracketFrame(u + shift, lo + shift, hi + shift, f / (u - f))

    return BracketPlan(_chain(frame_for, near_mm, far_mm, overlap, max_frames), shown_hyper)


def _chain(frame_for: Callable[[float], BracketFrame], near_mm: float, far_mm: float, overlap: float,
           max_frames: int) -> list[BracketFrame]:
    """The frames, nearest first: each the frame whose near limit is the one wanted, chained to ``far_mm``.

    Frame 1's near limit is ``near_mm``; each next one's is the previous far
    limit less ``overlap`` times the previous depth. More than ``max_frames``
    frames is a :class:`DomainError` on ``near_mm``.
    """
    frames: list[BracketFrame] = []
    wanted = float(near_mm)
    while True:
        each = frame_for(wanted)
        _check_frame(each, frames[-1] if frames else None)
        frames.append(each)
        step()  # a traced frame takes a tenth of a second: a progress bar listens
        if each.far_mm >= far_mm:
            return frames
        if len(frames) >= max_frames:
            require("near_mm", near_mm, False, f"far enough that at most {max_frames} frames reach --far",
                    detail=f"more than {max_frames} frames: a larger f-number, CoC or --near needs fewer")
        wanted = each.far_mm - overlap * (each.far_mm - each.near_mm)


def _check_frame(frame: BracketFrame, previous: BracketFrame | None) -> None:
    """A :class:`DomainError` unless the frame is finite, 0 < near ≤ focus ≤ far, and beyond the previous one.

    The frames of a model evaluated far outside the range it was made for
    (a rung of the ladder at an extreme aperture, say) are refused rather than
    printed: a plan never holds a NaN, a negative distance or a focus that
    steps back.
    """
    focus, near, far = frame.distance_mm, frame.near_mm, frame.far_mm
    ordered = 0.0 < near <= focus * (1.0 + 1e-12) and focus <= far * (1.0 + 1e-12) and math.isfinite(focus) \
        and not math.isnan(far) and math.isfinite(frame.magnification) and frame.magnification > 0.0
    require("distance_mm", focus, ordered, "a focus with 0 < near ≤ focus ≤ far",
            detail="a frame the model has no answer for")
    if previous is not None:
        require("distance_mm", focus, focus > previous.distance_mm and near >= previous.near_mm,
                "beyond the previous frame's focus, {limit}", limit=previous.distance_mm,
                detail="the model's frames step back: no plan")


FocusLimits = Callable[[float, float], tuple[float, float]]
"""(focal length f, focus distance u from the lens) -> (near, far) from the lens."""


def internal_bracket_plan(lens: InternalFocus, f_number: float, coc_mm: float, near_mm: float, far_mm: float,
                          overlap: float = 0.0, model: str = "thin", max_frames: int = 10_000,
                          limits: FocusLimits | None = None, distance_from: str = "sensor",
                          hyperfocal_magnification: float | None = None) -> BracketPlan:
    """Focus bracketing with an internally focusing lens: frames chained as in :func:`bracket_plan`, solved for m.

    A frame at magnification m has the focal length f(m) = f₀/(1 + κm), its
    subject u = f(m)·(1 + 1/m) from the lens and f(m)·(1 + m)²/m + δ from the
    sensor; its limits are the chosen model's at f(m) and u (from the lens,
    moved to the sensor by f(m)·(1 + m) + δ). A frame's near limit falls as m
    grows, so each frame's m is found by regula falsi (Illinois) between the
    hyperfocal magnification m_H (the largest m whose far limit is infinite:
    m_H = N·c/f(m_H) in the thin lens) and the lens's largest magnification.

    Parameters
    ----------
    lens : :class:`camtool.geometry.closeup.InternalFocus`, the lens's focusing model
    f_number, coc_mm, near_mm, far_mm, overlap, max_frames : as :func:`bracket_plan`
    model : ``"thin"`` or ``"approx"`` in closed form (with ``limits`` None)
    limits : optional function (f, u) -> (near, far) from the lens of another rung
    distance_from : ``"sensor"`` (default) or ``"lens"`` (the lens's front principal plane at each frame's focus)
    hyperfocal_magnification : the magnification of the lens's hyperfocal focus setting, as
        :func:`camtool.plans.depth.hyperfocal_setting` solves it (default: found here by bisection); the
        farthest frame is focused there, sharp to infinity

    Examples
    --------
    Canon EF 100 mm f/2.8L Macro (1:1 at 300 mm from the sensor, κ = 1/3), f/8, c = 0.03 mm,
    from 0.5 m to 0.6 m from the sensor:

    >>> from camtool.geometry.closeup import internal_focus
    >>> p = internal_bracket_plan(internal_focus(100.0, 300.0, 1.0), 8.0, 0.03, 500.0, 600.0)
    >>> len(p.frames), round(p.frames[0].near_mm, 9), round(p.frames[0].magnification, 4)
    (13, 500.0, 0.3085)
    """
    require_positive("f_number", f_number, unit="")
    require_positive("coc_mm", coc_mm)
    require("overlap", overlap, 0.0 <= overlap < 1.0, "0 to below 1")
    require("distance_from", distance_from, distance_from in ("lens", "sensor"), "lens or sensor")
    require("far_mm", far_mm, far_mm > near_mm, "beyond --near")
    sensor = distance_from == "sensor"
    f0, kappa, delta = lens.focal_length_mm, lens.kappa, lens.hiatus_mm

    def frame(m: float) -> BracketFrame:
        f = f0 / (1.0 + kappa * m)
        u = f + f / m
        if limits is None:
            lo, hi = _closed_limits(f, f * f / (f_number * coc_mm), model)(u)
        else:
            lo, hi = limits(f, u)
        shift = f + f * m + delta if sensor else 0.0
        return BracketFrame(u + shift, lo + shift, hi + shift, m)

    require("min_magnification", lens.min_magnification, lens.min_magnification == 0.0,
            "0: a lens that focuses to infinity (one that works only above a magnification is stacked on a rail)")
    m_min = 1e-9 * lens.max_magnification
    m_max = _nearest_limit_magnification(lambda m: frame(m).near_mm, m_min, lens.max_magnification)
    closest = frame(m_max)
    plane = "from the sensor" if sensor else "from the lens"
    why = ("the near limit with the lens at its closest focus" if m_max == lens.max_magnification else
           f"the nearest limit it reaches, at {m_max:.3g}×: a closer setting moves the subject away again")
    require("near_mm", near_mm, near_mm >= closest.near_mm * (1.0 - 1e-12),
            "at least {limit} " + plane + f" ({why})", limit=closest.near_mm)
    # the hyperfocal magnification: the largest m whose far limit is infinite (bisection in log m)
    if hyperfocal_magnification is not None:
        m_hyper = min(max(float(hyperfocal_magnification), m_min), m_max)
    elif math.isinf(frame(m_min).far_mm):
        low, high = m_min, m_max
        if math.isinf(closest.far_mm):
            low = m_max
        for _ in range(200):  # bisection in log m: about 50 halvings of log(m_max/m_min) reach 1e-13
            if high - low <= 1e-13 * high:
                break
            mid = math.sqrt(low * high)
            if math.isinf(frame(mid).far_mm):
                low = mid
            else:
                high = mid
        m_hyper = low
    else:  # an aperture so wide and a CoC so small that even m = 1e-9·m_max is closer than the hyperfocal focus
        m_hyper = m_min
    at_hyper = frame(m_hyper)
    if hyperfocal_magnification is not None:  # sharp to infinity there by the definition of that setting
        at_hyper = at_hyper._replace(far_mm=math.inf)
    require("far_mm", far_mm, far_mm <= at_hyper.far_mm,
            "at most {limit} " + plane + " (the far limit with the lens at its farthest focus)", limit=at_hyper.far_mm)

    def solve(wanted: float) -> float:
        """The m whose near limit is ``wanted`` (≤ the near limit at m_hyper): the near limit falls as m grows."""
        return _outer_root(lambda m: frame(m).near_mm - wanted, m_hyper, m_max,
                           at_hyper.near_mm - wanted, closest.near_mm - wanted, 1e-14)

    def frame_for(wanted: float) -> BracketFrame:
        return at_hyper if wanted >= at_hyper.near_mm * (1.0 - 1e-12) else frame(solve(wanted))

    return BracketPlan(_chain(frame_for, near_mm, far_mm, overlap, max_frames), at_hyper.distance_mm)


def _nearest_limit_magnification(near: Callable[[float], float], low: float, high: float) -> float:
    """The m in [low, high] with the nearest near limit (``high`` unless the lens turns back past about 1:1).

    Up to 1:1 a closer focus setting always brings the subject nearer; beyond
    it the subject-to-sensor distance f(m)·(1 + m)²/m grows again, so a lens
    reaching past 1:1 is bracketed only up to the magnification where the near
    limit is nearest (golden-section search, the near limit being unimodal in m).
    """
    if near(high) <= near(high * (1.0 - 1e-6)):
        return high
    a, b = golden_section(lambda m: -near(m), low, high, steps=200, relative=1e-12)
    return 0.5 * (a + b)


def _closed_limits(f: float, k: float, model: str) -> Limits:
    if model == "approx":
        def approx(u: float) -> tuple[float, float]:
            return u * k / (k + u), (u * k / (k - u) if u < k else math.inf)
        return approx

    def thin(u: float) -> tuple[float, float]:
        w = u - f
        return u * k / (k + w), (u * k / (k - w) if w < k else math.inf)
    return thin


def _closed_inverse(f: float, k: float, model: str) -> Callable[[float], float]:
    if model == "approx":
        return lambda near: near * k / (k - near)
    return lambda near: near * (k - f) / (k - near)


def _outer_root(g: Callable[[float], float], a: float, b: float, ga: float, gb: float, tol: float) -> float:
    """The root of a falling g on [a, b] (g(a) ≥ 0 ≥ g(b)) by Illinois regula falsi, from its ``a`` side.

    Returns the bracket end where g ≥ 0 once the bracket is within ``tol``
    (relative): a near limit at least the one wanted, so frames never leave a gap.
    """
    side = 0
    for _ in range(200):
        x = b - gb * (b - a) / (gb - ga) if gb != ga else 0.5 * (a + b)
        if not a < x < b:
            x = 0.5 * (a + b)
        gx = g(x)
        if gx >= 0.0:  # at or beyond the value wanted: x is the new outer end
            a, ga = x, gx
            if side == 1:
                gb *= 0.5
            side = 1
        else:
            b, gb = x, gx
            if side == -1:
                ga *= 0.5
            side = -1
        if b - a <= tol * b or ga == 0.0:
            break
    return a


def _numeric_focus(g: Callable[[float], float], start: float, x_far: float, x_near: float, f: float) -> float:
    """The focus u whose ``g(u)`` (rising with u) is 0, solved on x = 1/u in [``x_far``, ``x_near``].

    The first bracket is 1/``start`` ± 1 %, widened fourfold on a side only
    while that side does not hold the root: a start within a few per cent of
    the answer (the thin lens's, for another rung) costs two evaluations of g
    for the bracket and a handful for Illinois regula falsi. Returns the
    bracket end where g ≥ 0 (a near limit at least the one wanted: no gap).
    """

    def of_x(x: float) -> float:
        return g(1.0 / x)

    x0 = min(max(1.0 / start, x_far), x_near) if math.isfinite(start) and start > 0.0 else x_far
    width = 0.01
    a = max(x_far, x0 * (1.0 - width))
    ga = of_x(a)
    while ga < 0.0 and a > x_far:
        width *= 4.0
        a = max(x_far, x0 * (1.0 - width))
        ga = of_x(a)
    width = 0.01
    b = min(x_near, x0 * (1.0 + width))
    gb = of_x(b)
    while gb > 0.0 and b < x_near:
        a, ga = b, gb  # b is on the outer side: the root lies nearer still
        width *= 4.0
        b = min(x_near, x0 * (1.0 + width))
        gb = of_x(b)
    if gb >= 0.0:
        x = b
    elif ga <= 0.0:
        x = a
    else:
        x = _outer_root(of_x, a, b, ga, gb, 1e-12)
    return max(1.0 / x, f * (1.0 + 1e-12))


def _counted(limits: Limits, most: int | None, near_mm: float) -> Limits:
    """``limits``, refusing (a :class:`DomainError` on ``near_mm``) its evaluation number ``most`` + 1."""
    if most is None:
        return limits
    used = 0

    def counted(u: float) -> tuple[float, float]:
        nonlocal used
        used += 1
        require("near_mm", near_mm, used <= most, f"far enough that the plan takes at most {most} evaluations of "
                "the model", detail="a plan solved numerically frame by frame: a larger f-number, CoC or --near "
                "needs fewer")
        return limits(u)

    return counted
