"""Close-up planning: a distance or a magnification, a lens preset's internal focus, extension, teleconverter.

:func:`plan_focus` turns what was asked (a distance or a magnification, the
lens preset's internal-focus model, extension, teleconverter) into one
focus setting per row: the focal length and f-number in effect, the
magnification, the distances from the lens and from the sensor and, for a
sensor-plane distance, the other magnification that reaches it
(docs/closeup.md §1, §2, §7). :func:`dof_rows` runs the model ladder on
those settings, row by row where diffraction leaves some rows nothing
sharp (§3), adds the close-up keys and gives every row of a lens with a
focus model its one hyperfocal distance (:func:`camtool.plans.depth.hyperfocal_setting`).
"""

from __future__ import annotations

import math
from typing import Any

from camtool.core.errors import DomainError, require
from camtool.core.record import NamedTuple

__all__ = [
    "CLOSE_UP",
    "Setting",
    "UnreachableFocus",
    "dof_rows",
    "focus_models",
    "has_focus_model",
    "plan_focus",
    "pupil_and_hiatus",
]

CLOSE_UP = 0.1
"""From this magnification on, a table shows the magnification and the working f-number."""


class UnreachableFocus(DomainError):
    """A focus distance derived from a magnification or a focus model (not typed) is outside the model's range.

    ``closest_mm`` is the closest focus the model reaches from the lens,
    ``largest_magnification`` the magnification there (inf when none),
    ``magnifications`` those of the rows beyond it (all the rows' when none is),
    ``by_magnification`` whether the rows were asked by magnification.
    """

    def __init__(self, error: DomainError, closest_mm: float, largest_magnification: float,
                 magnifications: list[float], by_magnification: bool) -> None:
        super().__init__(error.param, error.value, error.valid, limit=error.limit)
        self.closest_mm = closest_mm
        self.largest_magnification = largest_magnification
        self.magnifications = magnifications
        self.by_magnification = by_magnification


class Setting(NamedTuple):
    """One focus setting per row (lists of floats; ``other_magnification`` NaN where there is none)."""

    focal_length_mm: list[float]
    f_number: list[float]
    magnification: list[float]
    lens_distance_mm: list[float]
    sensor_distance_mm: list[float]
    other_magnification: list[float]
    hiatus_mm: list[float]  # the hiatus that placed the subject (a focus model's own), for the sensor-plane shift
    modelled: bool  # a lens preset's focus model, an extension or a teleconverter was applied
    lens_focal_length_mm: list[float]  # the lens's focal length at infinity (before a teleconverter)
    lens_f_number: list[float]  # the f-number set on the lens (before a teleconverter)
    wanted: list[float]  # the distance (in its plane) or magnification asked for, per row
    by_magnification: bool
    extension_mm: float
    teleconverter: float


class PupilHiatus(NamedTuple):
    """The pupil magnification and hiatus for focusing; ``known``: from the lens data, not the defaults 1 and 0."""

    pupil_magnification: float
    hiatus_mm: float
    known: bool


def pupil_and_hiatus(lens: Any) -> PupilHiatus:
    """P and δ of lens data (:func:`camtool.plans.equipment.lens_data`): its own, else 1 and 0 (a thin lens).

    >>> pupil_and_hiatus(None)
    PupilHiatus(pupil_magnification=1.0, hiatus_mm=0.0, known=False)
    """
    known = lens.thick_parameters() if lens is not None else None
    if known is None:
        return PupilHiatus(1.0, 0.0, False)
    p, delta = (float(v) for v in known)
    return PupilHiatus(p, delta, True)


def has_focus_model(lens: Any) -> bool:
    """True when the lens preset publishes a closest focus (and so focuses by the internal-focus model)."""
    return lens is not None and getattr(lens, "prescription", None) is None and bool(
        getattr(lens, "close_focus", ()) or (getattr(lens, "min_focus_mm", None) and not lens.is_zoom))


def focus_models(lens: Any) -> Any:
    """A function focal length -> the lens preset's internal-focus model (None without one or without a preset)."""
    from camtool.presets.focusing import focus_model

    if lens is None or getattr(lens, "prescription", None) is not None:
        return lambda f: None
    return lambda f: focus_model(lens, float(f))


def plan_focus(*, lens: Any, focal_length_mm: Any, f_number: Any, wanted: Any, by_magnification: bool,
               distance_from: str, hiatus_mm: float, extension_mm: float | None = None,
               teleconverter: float | None = None) -> Setting:
    """The focus setting of every row: ``wanted`` is a distance in ``distance_from``'s plane, or a magnification.

    ``lens`` is the lens preset (its internal-focus model is used when it
    publishes a closest focus) or None. A scalar stands for every row.
    Errors are :class:`DomainError` on ``distance_mm`` or ``magnification``.

    Examples
    --------
    A 100 mm lens at 1:2 sits 300 mm from the subject (u = f(1 + 1/m)):

    >>> s = plan_focus(lens=None, focal_length_mm=100.0, f_number=8.0, wanted=0.5, by_magnification=True,
    ...                distance_from="sensor", hiatus_mm=0.0)
    >>> s.lens_distance_mm, s.sensor_distance_mm, s.modelled
    ([300.0], [450.0], False)
    """
    f, n, by_m = focal_length_mm, f_number, by_magnification
    models = focus_models(lens)
    columns_in = [_list(f), _list(n), _list(wanted)]
    count = max(map(len, columns_in))  # a scalar (one f-number for every row, say) stands for every row
    rows = [_row(models(fi), float(fi), float(ni), float(wi), by_m, distance_from, hiatus_mm,
                 extension_mm or 0.0, teleconverter or 1.0)
            for fi, ni, wi in zip(*(c * count if len(c) == 1 else c for c in columns_in), strict=True)]
    columns: list[list[float]] = [list(c) for c in zip(*rows)] if rows else [[] for _ in range(7)]
    modelled = bool(extension_mm) or (teleconverter or 1.0) != 1.0 or any(models(fi) for fi in set(_list(f)))
    scenes = list(zip(*(c * count if len(c) == 1 else c for c in columns_in), strict=True))
    return Setting(columns[0], columns[1], columns[2], columns[3], columns[4], columns[5], columns[6], modelled,
                   [s[0] for s in scenes], [s[1] for s in scenes], [s[2] for s in scenes], by_m,
                   extension_mm or 0.0, teleconverter or 1.0)


def _list(value: Any) -> list[float]:
    return [float(v) for v in value] if hasattr(value, "__len__") else [float(value)]


def _row(model: Any, f0: float, n: float, wanted: float, by_m: bool, plane: str, delta: float, extension: float,
         k: float) -> tuple[float, ...]:
    from camtool.geometry.closeup import (
        internal_focus_at_distance,
        internal_focus_at_magnification,
        magnification_branches,
    )

    other = math.nan
    if by_m:
        lens_m = wanted / k  # what the lens and the extension must give
        if model is None:
            m_lens = lens_m - extension / f0
            f_lens = f0
        else:
            m_lens = (lens_m - extension / f0) / (1.0 + extension * model.kappa / f0)
        if extension:
            require("magnification", wanted, m_lens >= 0.0,
                    f"at least {extension * k / f0:.4g} with {extension:g} mm of extension (the lens at infinity)")
        if model is not None:
            f_lens = internal_focus_at_magnification(model, m_lens)[0] if m_lens > 0 else f0
    elif model is not None and plane == "sensor":
        m_lens, f_lens = internal_focus_at_distance(model, wanted)
    elif model is not None:
        # from the front principal plane: κ·u·m² + (u − f₀)·m − f₀ = 0
        require("distance_mm", wanted, wanted > f0, "more than {limit} from the lens", limit=f0)
        a, b = model.kappa * wanted, wanted - f0
        m_lens = 2.0 * f0 / (b + math.sqrt(max(b * b + 4.0 * a * f0, 0.0))) if not math.isinf(wanted) else 0.0
        f_lens = internal_focus_at_magnification(model, m_lens)[0] if m_lens > 0 else f0
    elif plane == "sensor":
        f_lens = f0
        if math.isinf(wanted):
            m_lens = 0.0
        else:
            low, high = magnification_branches(f0, wanted, delta)
            m_lens = float(low)
            other = float(high) if high > low * (1.0 + 1e-9) else math.nan  # at 1:1 the two branches meet
    else:
        f_lens = f0
        require("distance_mm", wanted, wanted > f0,
                "more than {limit} from the lens (the focal length; between f and 2f the magnification is above 1)",
                limit=f0)
        m_lens = 0.0 if math.isinf(wanted) else f0 / (wanted - f0)
    m = k * (m_lens + extension / f_lens)
    focal = k * f_lens
    if extension or k != 1.0:
        other = math.nan
    if model is not None:
        delta = model.hiatus_mm  # the preset's, or the effective hiatus of its focus model
    if m == 0.0:
        return focal, k * n, 0.0, math.inf, math.inf, other, delta
    u = focal + focal / m
    sensor = u + focal + focal * m + delta
    if not by_m and not extension and k == 1.0 and (model is None or plane == "sensor"):
        # a typed distance that the lens was focused on: keep it to the last digit in its own plane
        sensor, u = (wanted, u) if plane == "sensor" else (sensor, wanted)
        delta = sensor - u - focal - focal * m
    return focal, k * n, m, u, sensor, other, delta


def _array(values: list[float]) -> Any:
    if len(values) == 1:
        return values[0]
    import numpy as np

    return np.asarray(values, dtype=float)


def _contrast_reached(f_number: float, coc_mm: float, magnification: float, criterion: Any,
                      wavelength_nm: float) -> bool:
    """Whether the wave rung's in-focus MTF reaches its criterion (a row the Airy disc fills may still be sharp)."""
    return f_number < _contrast_limit(coc_mm, magnification, criterion, wavelength_nm)


def _contrast_limit(coc_mm: float, magnification: float, criterion: Any, wavelength_nm: float) -> float:
    from camtool.dof.wave import DEFAULT_CRITERION, largest_contrast_f_number

    return float(largest_contrast_f_number(criterion or DEFAULT_CRITERION, coc_mm, magnification, wavelength_nm))


def dof_rows(*, model: str, setting: Setting, coc_mm: Any, distance_from: str, lens: Any, diffraction: bool,
             wavelength_nm: float, tolerance: float, pupil_magnification: float, direct: bool = False,
             nominal_focal_mm: Any = None, lens_preset: Any = None, criterion: Any = None) -> list[dict[str, Any]]:
    """Depth of field of every planned row (from the lens plane, shifted to the sensor plane when asked).

    With ``diffraction`` each row gets its Airy disc, diffraction-limit
    f-number and wave-optics depth; rows where the Airy disc fills the CoC
    get null limits and a ``reason``, the others their limits. ``direct``:
    the distances were typed and nothing changed them (no magnification,
    focus model, extension or teleconverter), so the ladder gets them as
    typed, in their own plane; otherwise it gets the lens-plane distance
    u = f(1 + 1/m) and the limits are moved to the sensor plane by v + δ.
    ``focal_length_mm`` is the lens's nominal focal length (× the
    teleconverter); ``focal_length_at_focus_mm`` the one in effect.

    A lens preset with a focus model (``lens_preset``) has one hyperfocal
    distance per f-number and CoC, the focus setting at which the far limit
    reaches infinity with the focal length in effect there
    (:func:`camtool.plans.depth.hyperfocal_setting`): every row's
    ``hyperfocal_mm`` is that one, whatever the row's focus, and a typed
    distance at or beyond it has a far limit of infinity.
    """
    from camtool.dof.ladder import depth_of_field

    pupil = pupil_magnification
    count = len(setting.focal_length_mm)
    cs = _list(coc_mm) if hasattr(coc_mm, "__len__") else [float(coc_mm)] * count
    rows: list[dict[str, Any]] = [{} for _ in range(count)]
    sharp = list(range(count))
    if diffraction:
        from camtool.dof.closeup import diffraction_row, wave_depth_mm

        sharp = []
        for i in range(count):
            n, m, ci = setting.f_number[i], setting.magnification[i], cs[i]
            d = diffraction_row(n, ci, m, pupil, wavelength_nm)
            rows[i].update({"airy_mm": d.airy_mm, "diffraction_limit_f_number": d.limit_f_number,
                            "wave_dof_mm": wave_depth_mm(n, m, pupil, wavelength_nm) if m > 0 else math.inf,
                            "reason": None})
            by_contrast = model in ("auto", "wave") and not d.sharp and _contrast_reached(n, ci, m, criterion,
                                                                                          wavelength_nm)
            if d.sharp or by_contrast:  # auto runs wave where the Airy disc dominates (camtool.dof.ladder)
                sharp.append(i)
            elif model in ("auto", "wave"):
                rows[i]["reason"] = (f"nothing sharp: even in focus the MTF misses the contrast criterion; below "
                                     f"f/{_contrast_limit(ci, m, criterion, wavelength_nm):.3g} leaves depth")
            else:
                rows[i]["reason"] = (f"nothing sharp: the Airy disc ({d.airy_mm:.3g} mm) fills the CoC "
                                     f"({ci:.3g} mm); below f/{d.limit_f_number:.3g} leaves depth")
    if diffraction and not sharp and model in ("auto", "wave"):  # no row sharp even by contrast: say by how much
        from camtool.dof.wave import DEFAULT_CRITERION, ContrastUnreachable, criterion_frequency

        chosen = criterion or DEFAULT_CRITERION
        raise ContrastUnreachable(setting.f_number[0], _contrast_limit(cs[0], setting.magnification[0], criterion,
                                                                       wavelength_nm), chosen,
                                  float(criterion_frequency(chosen, cs[0])), wavelength_nm)
    if diffraction and not sharp:
        from camtool.dof.diffraction import usable_coc_mm

        usable_coc_mm(cs[0], setting.f_number[0], setting.magnification[0], pupil, wavelength_nm)
    if sharp:
        pick = lambda values: _array([values[i] for i in sharp])  # noqa: E731
        f, n = pick(setting.focal_length_mm), pick(setting.f_number)
        plane = distance_from if direct else "lens"
        s = pick(setting.sensor_distance_mm if plane == "sensor" else setting.lens_distance_mm)
        try:
            result = depth_of_field(model, f, n, pick(cs), s, plane, lens, diffraction, wavelength_nm, tolerance,
                                    criterion)
        except DomainError as error:
            raise _unreachable(error, direct, setting, sharp) from None
        limits = result.limits
        for j, i in enumerate(sharp):
            def take(v: Any, j: int = j) -> Any:
                return v if not hasattr(v, "__len__") or isinstance(v, str) else v[j]

            shift = 0.0
            hyper_shift = 0.0
            if distance_from == "sensor" and not direct:
                fi, mi = setting.focal_length_mm[i], setting.magnification[i]
                # v + δ, with the δ that placed the subject (a focus model's own); at infinity too
                row_delta = setting.hiatus_mm[i]
                shift = fi + fi * mi + row_delta
                hyper_shift = fi + setting.f_number[i] * cs[i] + row_delta  # image distance at the hyperfocal focus
            rows[i].update({
                "near_mm": float(take(limits.near_mm)) + shift, "far_mm": float(take(limits.far_mm)) + shift,
                "total_mm": float(take(limits.total_mm)), "front_mm": float(take(limits.front_mm)),
                "rear_mm": float(take(limits.rear_mm)),
                "hyperfocal_mm": float(take(limits.hyperfocal_mm)) + hyper_shift,
                "model": str(take(result.model)), "error_estimate": float(take(result.error_estimate)),
            })
        if lens_preset is not None and not diffraction:
            _one_hyperfocal(rows, sharp, setting, cs, model, distance_from, lens, lens_preset, tolerance)
    for i in range(count):
        m = setting.magnification[i]
        distance = setting.sensor_distance_mm[i] if distance_from == "sensor" else setting.lens_distance_mm[i]
        rows[i].update({
            "focal_length_mm": setting.focal_length_mm[i] if nominal_focal_mm is None else nominal_focal_mm[i],
            "focal_length_at_focus_mm": setting.focal_length_mm[i],
            "f_number": setting.f_number[i], "distance_mm": distance,
            "coc_mm": cs[i], "magnification": m, "distance_from": distance_from,
            "working_f_number": setting.f_number[i] * (1.0 + m / pupil),
            "other_magnification": None if math.isnan(setting.other_magnification[i])
            else setting.other_magnification[i],
        })
        if diffraction:
            total = rows[i].get("total_mm")
            if total is None:
                rows[i].update(dict.fromkeys(("near_mm", "far_mm", "total_mm", "front_mm", "rear_mm",
                                              "hyperfocal_mm", "error_estimate")))
                rows[i]["model"] = None
                rows[i]["depth_dominated_by"] = "wave"
            else:
                rows[i]["depth_dominated_by"] = "wave" if rows[i]["wave_dof_mm"] > total else "geometric"
    return rows


def _one_hyperfocal(rows: list[dict[str, Any]], sharp: list[int], setting: Setting, cs: list[float], model: str,
                    plane: str, lens: Any, lens_preset: Any, tolerance: float) -> None:
    """Give the rows of a lens with a focus model its one hyperfocal distance; a focus at or beyond it, far = ∞.

    The rung of the hyperfocal distance is the row's model when it is a
    closed form with one, and :func:`camtool.dof.ladder.hyperfocal_rung`
    under ``auto`` (the rung ``auto`` runs at and beyond H). A row focused
    at or beyond H (the distance typed, compared in its own plane, so the
    float ``hyperfocal`` reports gives ∞) that a cheaper rung computed is
    computed again by the hyperfocal rung. Rows with an extension tube
    keep the ladder's values (their lens reaches no infinity focus).
    """
    from camtool.dof.ladder import depth_of_field, hyperfocal_choices, hyperfocal_rung
    from camtool.dof.rungs import names
    from camtool.plans.depth import hyperfocal_setting

    if setting.extension_mm or not setting.lens_focal_length_mm:
        return
    closed = [name for name in hyperfocal_choices() if name != "auto"]
    for i in sharp:
        row = rows[i]
        rung = row["model"].split("+")[0]
        if model == "auto":
            rung_h = hyperfocal_rung(lens)
        elif model in closed:
            rung_h = model
        else:
            continue
        try:
            h = hyperfocal_setting(model=rung_h, focal_length_mm=setting.lens_focal_length_mm[i],
                                   f_number=setting.lens_f_number[i], coc_mm=cs[i], distance_from=plane, lens=lens,
                                   lens_preset=lens_preset, teleconverter=setting.teleconverter)
        except DomainError:
            continue  # no focus of this lens reaches an infinite far limit (a macro-only lens): the ladder's value
        row["hyperfocal_mm"] = h.hyperfocal_mm
        typed = setting.wanted[i] if not setting.by_magnification else (
            setting.sensor_distance_mm[i] if plane == "sensor" else setting.lens_distance_mm[i])
        if typed < h.hyperfocal_mm:
            continue
        if rung != rung_h and rung in names() and names().index(rung) < names().index(rung_h):
            again = depth_of_field(rung_h, setting.focal_length_mm[i], setting.f_number[i], cs[i],
                                   setting.lens_distance_mm[i], "lens", lens, False, 550.0, tolerance)
            shift = (setting.focal_length_mm[i] * (1.0 + setting.magnification[i]) + setting.hiatus_mm[i]
                     if plane == "sensor" else 0.0)
            row.update({"near_mm": float(again.limits.near_mm) + shift, "front_mm": float(again.limits.front_mm),
                        "model": str(again.model), "error_estimate": float(again.error_estimate)})
        row.update({"far_mm": math.inf, "rear_mm": math.inf, "total_mm": math.inf})


def _unreachable(error: DomainError, direct: bool, setting: Setting, rows: list[int]) -> DomainError:
    """A focus distance not typed (it came from a magnification or a focus model) out of the model's range.

    The ray trace, for one, focuses a prescription only down to its closest
    focus (1:1 by unit focusing): a larger magnification is out of that
    model's range. Other errors are returned as they are.
    """
    if direct or error.param != "distance_mm" or error.limit is None:
        return error
    f = min(setting.focal_length_mm[i] for i in rows)
    closest = float(error.limit)
    largest = f / (closest - f) if closest > f else math.inf
    beyond = [setting.magnification[i] for i in rows if setting.magnification[i] > largest * (1 + 1e-9)]
    return UnreachableFocus(error, closest, largest, beyond or [setting.magnification[i] for i in rows],
                            setting.by_magnification)
