"""The hyperfocal distance: one answer per lens, model and CoC, by the rung ``auto`` runs there.

:func:`hyperfocal_setting` decides which rung computes the hyperfocal distance
(the named one, or under ``auto`` :func:`camtool.dof.ladder.hyperfocal_rung`:
the most complete closed form the lens data allow, the rung
:func:`camtool.dof.ladder.depth_of_field` runs under ``auto`` at and beyond
that distance) and, for a lens preset that focuses internally (docs/closeup.md
§2, f(m) = f₀/(1 + κm)), solves for the focus setting whose far limit is
infinite with the focal length in effect there. For the thin model that is the
magnification m = N·c/(f₀ − κ·N·c); every rung is solved the same way, by the
fixed point m = f(m)/(H(f(m)) − f(m)) of the rung's own lens-plane hyperfocal
distance H(f).

``camtool hyperfocal``, the H column of ``camtool dof`` and
:func:`hyperfocal_plan` all call it, so focusing at the distance it returns
(the same float, from ``--field hyperfocal_mm`` or JSON) gives a far limit of
infinity in ``camtool dof`` for the same lens, model and CoC.
"""

from __future__ import annotations

import math
from typing import Any

from camtool.core.errors import DomainError
from camtool.core.record import NamedTuple
from camtool.dof.ladder import LensData, depth_of_field, hyperfocal, hyperfocal_choices, hyperfocal_rung
from camtool.geometry.closeup import internal_focus_at_magnification
from camtool.presets.focusing import focus_model

__all__ = ["HyperfocalPlan", "HyperfocalSetting", "hyperfocal_plan", "hyperfocal_setting"]


class HyperfocalSetting(NamedTuple):
    """One hyperfocal focus setting (mm, in the plane asked for) and the rung that computed it.

    ``focal_length_at_focus_mm`` and ``magnification`` are those in effect at
    that focus (× a teleconverter); ``focal_length_mm`` and ``f_number`` the
    lens's at infinity (× a teleconverter).
    """

    hyperfocal_mm: float
    near_mm: float
    model: str
    focal_length_mm: float
    f_number: float
    focal_length_at_focus_mm: float
    magnification: float


class HyperfocalPlan(NamedTuple):
    """The rows of ``camtool hyperfocal``: scalars for one scene, arrays (``model`` a list) for several."""

    focal_length_mm: Any
    f_number: Any
    hyperfocal_mm: Any
    near_mm: Any
    model: Any


def _thick_data(lens: LensData | None) -> LensData | None:
    """The pupil magnification and hiatus of ``lens`` alone (no prescription), None when they are 1 and 0."""
    known = None if lens is None else lens.thick_parameters()
    p, delta = known if known is not None else (1.0, 0.0)
    return LensData(pupil_magnification=p, hiatus_mm=delta) if (p, delta) != (1.0, 0.0) else None


def hyperfocal_setting(*, model: str, focal_length_mm: float, f_number: float, coc_mm: float,
                       distance_from: str = "sensor", lens: LensData | None = None, lens_preset: Any = None,
                       teleconverter: float = 1.0, diffraction: bool = False, wavelength_nm: float = 550.0,
                       criterion: Any = None) -> HyperfocalSetting:
    """The hyperfocal focus setting of one scene: where the far limit starts being infinite.

    Decides the rung (``model``, or :func:`camtool.dof.ladder.hyperfocal_rung`
    under ``auto``) and, when ``lens_preset`` publishes a closest focus, the
    focal length in effect at that focus (the self-consistent solution of its
    internal-focus model). Without a focus model this is
    :func:`camtool.dof.ladder.hyperfocal` at k·f and k·N.

    Raises
    ------
    DomainError
        On ``f_number`` when no focus of the lens reaches an infinite far
        limit (a macro lens that focuses no farther than a magnification
        above the hyperfocal one).

    Examples
    --------
    Canon EF 100 mm f/2.8L Macro (1:1 at 300 mm, κ = 1/3) at f/8, c = 0.03 mm, thin model: the
    hyperfocal magnification is N·c/(f₀ − κ·N·c) = 0.24/99.92 and the focal length there
    f₀ − κ·N·c = 99.92 mm, so from the lens H = 99.92²/0.24 + 99.92:

    >>> from camtool.presets import load_db
    >>> h = hyperfocal_setting(model="thin", focal_length_mm=100.0, f_number=8.0, coc_mm=0.03,
    ...                        distance_from="lens", lens_preset=load_db().get("lens", "ef-100-macro-l"))
    >>> round(h.hyperfocal_mm, 6) == round(99.92 ** 2 / 0.24 + 99.92, 6), round(h.focal_length_at_focus_mm, 9)
    (True, 99.92)
    """
    if model not in hyperfocal_choices():
        raise ValueError(f"unknown model {model!r}; choose one of {', '.join(hyperfocal_choices())}")
    by_contrast = model == "wave" or (model == "auto" and (diffraction or criterion is not None))
    rung = "wave" if by_contrast else hyperfocal_rung(lens) if model == "auto" else model
    extra = {"diffraction": diffraction and not by_contrast, "wavelength_nm": wavelength_nm, "criterion": criterion}
    k = teleconverter
    focal, kn = k * focal_length_mm, k * f_number
    focus = _focus_model(lens_preset, focal_length_mm)
    if focus is None:
        h = hyperfocal(rung, focal, kn, coc_mm, distance_from, lens, **extra)
        u_h = float(hyperfocal(rung, focal, kn, coc_mm, "lens", lens, **extra).hyperfocal_mm)
        return HyperfocalSetting(float(h.hyperfocal_mm), float(h.near_mm), str(h.model), focal, kn, focal,
                                 focal / (u_h - focal))
    data = _thick_data(lens)

    def lens_plane_h(f_in_effect: float) -> float:
        at_infinity = depth_of_field(rung, f_in_effect, kn, coc_mm, math.inf, "lens", lens=data, **extra)
        return float(at_infinity.limits.hyperfocal_mm)

    f0, kappa = focus.focal_length_mm, focus.kappa
    m_lens, seen = 0.0, set()
    for _ in range(200):  # a contraction by about κ·m per step: a few steps to the last bit
        f_here = k * (f0 / (1.0 + kappa * m_lens))
        h_lens = lens_plane_h(f_here)
        following = f_here / (h_lens - f_here) / k
        if following == m_lens or following in seen:
            m_lens = max(m_lens, following)  # an alternation in the last bit: the larger m, the nearer focus
            break
        seen.add(following)
        m_lens = following
    if m_lens < focus.min_magnification * 0.999:
        raise DomainError("f_number", f_number, f"a value whose hyperfocal focus this lens reaches (it focuses "
                          f"no farther than {focus.min_magnification:g}×)")
    m_lens = min(m_lens, focus.max_magnification)  # sharp to infinity even at its closest focus: that focus
    # the focus setting as the close-up planner places a magnification (camtool.plans.closeup.plan_focus)
    f_here = k * internal_focus_at_magnification(focus, m_lens)[0]
    m = k * m_lens
    u = f_here + f_here / m
    shift = f_here + f_here * m + focus.hiatus_mm if distance_from == "sensor" else 0.0
    at_h = depth_of_field(rung, f_here, kn, coc_mm, u, "lens", lens=data, **extra)
    return HyperfocalSetting(u + shift, float(at_h.limits.near_mm) + shift, str(at_h.model), focal, kn, f_here, m)


def _focus_model(lens_preset: Any, focal_length_mm: float) -> Any:
    """The internal-focus model of a lens preset without a prescription at this focal length (else None)."""
    if lens_preset is None or getattr(lens_preset, "prescription", None) is not None:
        return None
    return focus_model(lens_preset, float(focal_length_mm))


def hyperfocal_plan(*, model: str, focal_length_mm: Any, f_number: Any, coc_mm: Any, distance_from: str = "sensor",
                    lens: LensData | None = None, lens_preset: Any = None,
                    teleconverter: float | None = None, diffraction: bool = False, wavelength_nm: float = 550.0,
                    criterion: Any = None) -> HyperfocalPlan:
    """Every row of ``camtool hyperfocal``: the lens's focal length and f-number × the teleconverter, H, its near limit.

    With ``diffraction`` or a ``criterion`` under ``auto`` the hyperfocal
    distance is the ``wave`` rung's (by contrast; a geometric ``model`` named
    with ``diffraction`` takes the root-sum-square add-on instead): a lens
    stopped down past the criterion's reach is a :class:`DomainError` on
    ``f_number`` naming the largest f-number that has a hyperfocal distance.

    >>> p = hyperfocal_plan(model="auto", focal_length_mm=50.0, f_number=200.0, coc_mm=0.03, diffraction=True)
    Traceback (most recent call last):
    ...
    camtool.dof.wave.ContrastUnreachable: f_number=200 is outside the valid range: below f/38.6 for any depth of \
field by mtf:0.181@coc at 550 nm (nothing is sharp enough: even in focus the MTF at 33.3 lp/mm is below 0.181)

    Scalars or arrays of one length (a scalar stands for every row). Without
    a lens preset that focuses internally the arrays go through
    :func:`camtool.dof.ladder.hyperfocal` in one call; with one, each row is
    :func:`hyperfocal_setting`.

    Examples
    --------
    50 mm f/8, c = 0.03 mm, thin model, from the lens: H = f²/(N·c) + f (Wikipedia, "Hyperfocal distance"):

    >>> p = hyperfocal_plan(model="auto", focal_length_mm=50.0, f_number=8.0, coc_mm=0.03, distance_from="lens")
    >>> round(p.hyperfocal_mm, 4), p.model
    (10466.6667, 'thin')
    """
    k = teleconverter or 1.0
    focal = _scaled(focal_length_mm, k)
    kn = _scaled(f_number, k)
    if not any(_focus_model(lens_preset, v) for v in _values(focal_length_mm)):
        h = hyperfocal(model, focal, kn, coc_mm, distance_from, lens, diffraction, wavelength_nm, criterion)
        return HyperfocalPlan(focal, kn, h.hyperfocal_mm, h.near_mm, h.model)
    import numpy as np

    f0s, ns, cs = np.broadcast_arrays(np.asarray(focal_length_mm, float), np.asarray(f_number, float),
                                      np.asarray(coc_mm, float))
    settings = [hyperfocal_setting(model=model, focal_length_mm=float(fi), f_number=float(ni), coc_mm=float(ci),
                                   distance_from=distance_from, lens=lens, lens_preset=lens_preset, teleconverter=k,
                                   diffraction=diffraction, wavelength_nm=wavelength_nm, criterion=criterion)
                for fi, ni, ci in zip(f0s.ravel(), ns.ravel(), cs.ravel(), strict=True)]
    if np.ndim(f0s) == 0:
        (one,) = settings
        return HyperfocalPlan(one.focal_length_mm, one.f_number, one.hyperfocal_mm, one.near_mm, one.model)
    models = [s.model for s in settings]
    # the shape of the input, as the ladder gives it without a preset (one model name when every row has it)
    return HyperfocalPlan(focal, kn, np.array([s.hyperfocal_mm for s in settings]).reshape(f0s.shape),
                          np.array([s.near_mm for s in settings]).reshape(f0s.shape),
                          models[0] if len(set(models)) == 1 else np.array(models, dtype=object).reshape(f0s.shape)
                          .tolist())


def _values(value: Any) -> list[float]:
    """Every number of ``value``: a number, a list, or an array of any shape."""
    if hasattr(value, "ravel"):
        return [float(v) for v in value.ravel()]
    return [float(v) for v in value] if hasattr(value, "__len__") else [float(value)]


def _scaled(value: Any, k: float) -> Any:
    """k × value, as the rows show it (a list stays a list)."""
    if isinstance(value, list):
        return [k * v for v in value]
    return k * value if k != 1.0 else value

