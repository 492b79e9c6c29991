"""Focusing: where the lens sits for a distance or a magnification, and where to focus for wanted limits.

One function per question ``camtool focus`` answers, each returning the rows'
values by key (scalars or arrays, one per scene) and the facts the table shows:

- :func:`forward`: the focus setting of a distance or a magnification (unit
  focusing, or the close-up planner for a lens preset that focuses internally,
  an extension or a teleconverter);
- :func:`inverse`: the focus and f-number that make a near and a far limit
  exactly sharp, or, for an f-number given, the focus that centres the range;
- :func:`optimum`: the f-number balancing defocus against diffraction (Hansma)
  for a near and far limit, or for a focus spread (:func:`spread_optimum`);
- :func:`depth`: the CoC or f-number that give a total depth at a magnification.
"""

from __future__ import annotations

from typing import Any

from camtool.core.record import NamedTuple

__all__ = ["FocusRows", "depth", "forward", "inverse", "optimum", "spread_optimum"]


class FocusRows(NamedTuple):
    """The values of every row by key (or row dicts in ``rows``), and what the table shows.

    ``values``: key → a scalar or an array (one per scene), None when ``rows``
    holds the row dicts; ``planned``: the close-up planner placed the focus;
    ``internal_focus``: a lens preset's focus model did; ``focus_column``: some
    row's focal length at the focus differs from its nominal one; ``lens_focus_setting``:
    a distance given is the lens's own focus setting (an extension or a teleconverter moves the subject).
    """

    values: dict[str, Any] | None
    rows: list[dict[str, Any]] | None = None
    planned: bool = False
    internal_focus: bool = False
    focus_column: bool = False
    lens_focus_setting: bool = False


def forward(*, focal_length_mm: Any, wanted: Any, by_magnification: bool, f_number: Any = None,
            distance_from: str = "sensor", pupil_magnification: float = 1.0, hiatus_mm: float = 0.0,
            lens_preset: Any = None, extension_mm: float | None = None, teleconverter: float | None = None) -> FocusRows:
    """The focus setting of every scene: image distance, extension, magnification, working f-number.

    Decides the path: a lens preset with a published closest focus, an
    extension or a teleconverter go through the close-up planner
    (:func:`camtool.plans.closeup.plan_focus`), anything else is unit focusing
    (:func:`camtool.geometry.thinlens.focus_setting`). A distance from the
    sensor that is also reached at m > 1 gets that other magnification
    (``other_magnification``; for unit focusing without a hiatus it is 1/m).
    Without ``f_number`` the rows have no f-numbers.

    >>> r = forward(focal_length_mm=100.0, wanted=0.5, by_magnification=True)
    >>> r.values["distance_mm"], r.values["extension_mm"]
    (450.0, 50.0)
    """
    from camtool.plans.closeup import has_focus_model

    if extension_mm or teleconverter or has_focus_model(lens_preset):
        return _planned(focal_length_mm, wanted, by_magnification, f_number, distance_from, pupil_magnification,
                        hiatus_mm, lens_preset, extension_mm, teleconverter)
    from camtool.geometry.thinlens import focus_setting

    f, by_m, delta = focal_length_mm, by_magnification, hiatus_mm
    setting = focus_setting(f, None if by_m else wanted, wanted if by_m else None, distance_from, delta, f_number,
                            pupil_magnification)
    values: dict[str, Any] = {
        "focal_length_mm": f, "distance_mm": setting.distance_mm, "image_distance_mm": setting.image_distance_mm,
        "extension_mm": setting.extension_mm, "magnification": setting.magnification,
        "closest_focus_mm": setting.closest_focus_mm, "distance_from": distance_from,
        "focal_length_at_focus_mm": f,
    }
    if f_number is not None:
        values.update({"f_number": f_number, "working_f_number": setting.working_f_number})
    # the other magnification at the same distance from the sensor (m and 1/m, without hiatus)
    values["other_magnification"] = [1.0 / m if not by_m and distance_from == "sensor" and 0.0 < m < 1.0 and not delta
                                     else None for m in _floats(setting.magnification)]
    return FocusRows(values)


def _floats(value: Any) -> list[float]:
    import numpy as np

    return [float(v) for v in np.ravel(np.asarray(value, dtype=float))]


def _planned(f: Any, wanted: Any, by_m: bool, f_number: Any, distance_from: str, p: float, delta: float,
             lens_preset: Any, extension: float | None, teleconverter: float | None) -> FocusRows:
    """Focusing through the close-up planner: a preset's internal focus, extension, teleconverter."""
    from camtool.plans.closeup import focus_models, plan_focus

    setting = plan_focus(lens=lens_preset, focal_length_mm=f, f_number=1.0 if f_number is None else f_number,
                         wanted=wanted, by_magnification=by_m, distance_from=distance_from, hiatus_mm=delta,
                         extension_mm=extension, teleconverter=teleconverter)
    k = teleconverter or 1.0
    models = focus_models(lens_preset)
    focal = [float(v) for v in (f if hasattr(f, "__len__") else [f])]
    rows = []
    for i in range(len(setting.magnification)):
        fe, m = setting.focal_length_mm[i], setting.magnification[i]
        model = models(focal[i])
        closest = model.min_focus_mm if model is not None else 4.0 * fe + delta
        if distance_from == "lens":
            closest = closest - delta - fe * (1.0 + (model.max_magnification if model is not None else 1.0))
        other = setting.other_magnification[i]
        row: dict[str, Any] = {
            "focal_length_mm": k * focal[i], "focal_length_at_focus_mm": fe,
            "distance_mm": setting.sensor_distance_mm[i] if distance_from == "sensor" else setting.lens_distance_mm[i],
            "image_distance_mm": fe * (1.0 + m), "extension_mm": fe * m, "magnification": m,
            "closest_focus_mm": closest, "distance_from": distance_from,
            "other_magnification": None if other != other else other,
        }
        if f_number is not None:
            row.update({"f_number": setting.f_number[i], "working_f_number": setting.f_number[i] * (1.0 + m / p)})
        rows.append(row)
    differs = any(abs(r["focal_length_at_focus_mm"] - r["focal_length_mm"]) > 1e-9 * r["focal_length_mm"]
                  for r in rows)
    return FocusRows(None, rows, True, models(focal[0]) is not None, differs,
                     bool(extension or teleconverter) and not by_m)


class InverseRows(NamedTuple):
    """The rows of the inverse question by key; ``fixed``: an f-number was given (the limits are its own)."""

    values: dict[str, Any]
    fixed: bool


def inverse(*, focal_length_mm: Any, near_mm: Any, far_mm: Any, coc_mm: Any, f_number: Any = None,
            distance_from: str = "sensor") -> InverseRows:
    """Where to focus for a wanted near and far limit (thin model).

    Without ``f_number``: the focus and the f-number that make exactly that
    range acceptably sharp (:func:`camtool.dof.inverse.focus_for_limits`);
    with it, the focus that centres the range at that f-number, the limits it
    gives there and the f-number the range needs
    (:func:`camtool.dof.inverse.focus_for_limits_at`).

    35 mm, c = 0.03 mm, 2 m to 10 m from the lens: the harmonic-mean focus 2ab/(a + b) = 3.333 m.

    >>> r = inverse(focal_length_mm=35.0, near_mm=2000.0, far_mm=10000.0, coc_mm=0.03, distance_from="lens")
    >>> round(r.values["distance_mm"], 3), r.fixed
    (3333.333, False)
    """
    from camtool.dof.inverse import focus_for_limits, focus_for_limits_at

    f, a, b, c = focal_length_mm, near_mm, far_mm, coc_mm
    if f_number is not None:  # a fixed f-number: the focus that best uses it, and the limits it gives
        fixed = focus_for_limits_at(f, f_number, c, a, b, distance_from)
        return InverseRows({
            "focal_length_mm": f, "near_mm": fixed.near_mm, "far_mm": fixed.far_mm, "distance_mm": fixed.distance_mm,
            "f_number": f_number, "coc_mm": c, "distance_from": distance_from, "wanted_near_mm": a,
            "wanted_far_mm": b, "needed_f_number": fixed.needed_f_number,
        }, True)
    solution = focus_for_limits(f, c, a, b, distance_from)
    return InverseRows({
        "focal_length_mm": f, "near_mm": a, "far_mm": b, "distance_mm": solution.distance_mm,
        "f_number": solution.f_number, "coc_mm": c, "distance_from": distance_from,
    }, False)


def optimum(*, focal_length_mm: Any, near_mm: Any, far_mm: Any, distance_from: str = "sensor",
            pupil_magnification: float = 1.0, hiatus_mm: float = 0.0, wavelength_nm: float = 550.0) -> dict[str, Any]:
    """The optimum f-number for a near and far limit (Hansma): focus, spread, f-number, blur, by key.

    :func:`camtool.dof.closeup.optimum_for_limits`; the blur is the defocus
    and diffraction added root-sum-square.
    """
    from camtool.dof.closeup import optimum_for_limits

    f, a, b = focal_length_mm, near_mm, far_mm
    r = optimum_for_limits(f, a, b, distance_from, hiatus_mm, pupil_magnification, wavelength_nm)
    return {
        "focal_length_mm": f, "near_mm": a, "far_mm": b, "distance_mm": r.distance_mm, "magnification": r.magnification,
        "focus_spread_mm": r.focus_spread_mm, "f_number": r.optimum.f_number,
        "working_f_number": r.optimum.working_f_number, "blur_mm": r.optimum.blur_mm,
        "blur_sum_mm": r.optimum.blur_sum_mm, "distance_from": distance_from,
    }


def contrast_optimum(*, focal_length_mm: Any, near_mm: Any, far_mm: Any, criterion: Any, coc_mm: Any = None,
                     distance_from: str = "sensor", wavelength_nm: float = 550.0, lens: Any = None) -> dict[str, Any]:
    """The optimum f-number for a near and far limit by contrast: the most MTF at the criterion's frequency, by key.

    :func:`camtool.dof.wave.contrast_optimum` row by row (scalars, or lists of
    one length); the frequency is the criterion's, or 1/c for ``@coc``.
    ``mtf_level`` is the criterion's level: the range is sharp by it where ``mtf`` reaches it.

    ``model`` says what answered: ``wave``, a perfect lens at ``wavelength_nm``; or, with a ``lens``
    (:class:`camtool.dof.ladder.LensData`) that has a prescription in air, ``wave+prescription``: the real
    lens's wavefront at the prescription's own wavelength (``wavelength_nm`` gives it), as the ``wave`` rung
    of ``dof`` takes it (:func:`camtool.dof.wavetrace.prescription_contrast_optimum`). Its near and far limits
    at that f-number and focus, with the criterion's level set to the ``mtf`` found, are the range asked for.

    >>> from camtool.dof.wave import Criterion
    >>> r = contrast_optimum(focal_length_mm=150.0, near_mm=2000.0, far_mm=float("inf"), distance_from="lens",
    ...                      criterion=Criterion(0.1, 20.0))
    >>> round(r["f_number"], 1), r["mtf"] >= r["mtf_level"]
    (60.2, True)
    """
    from camtool.core.steps import step
    from camtool.dof.ladder import WAVE_PRESCRIPTION
    from camtool.dof.rungs import traceable
    from camtool.dof.wave import contrast_optimum, criterion_frequency
    from camtool.dof.wavetrace import prescription_contrast_optimum

    real = lens.prescription if lens is not None and traceable(lens) else None

    columns = [focal_length_mm, near_mm, far_mm, coc_mm if coc_mm is not None else 0.0]
    count = max((len(v) for v in columns if hasattr(v, "__len__")), default=0)
    keys = ["focal_length_mm", "near_mm", "far_mm", "distance_mm", "magnification", "f_number", "working_f_number",
            "mtf", "frequency_lpmm", "defocus_waves", "mtf_level"]
    out: dict[str, list[Any]] = {key: [] for key in keys}
    for i in range(max(count, 1)):
        f, a, b, c = (v[i] if hasattr(v, "__len__") else v for v in columns)
        nu = float(criterion_frequency(criterion, c))
        if real is not None:
            r = prescription_contrast_optimum(real, float(a), float(b), nu, distance_from)
            step()  # half a second a row: a progress bar listens
        else:
            r = contrast_optimum(float(f), float(a), float(b), nu, distance_from, wavelength_nm)
        for key, value in zip(keys, (f, a, b, r.distance_mm, r.magnification, r.f_number, r.working_f_number, r.mtf,
                                     nu, r.defocus_waves, criterion.level)):
            out[key].append(float(value))  # plain floats to the writer
    values: dict[str, Any] = {key: (column if count else column[0]) for key, column in out.items()}
    values["distance_from"] = distance_from
    values["model"] = "wave" if real is None else WAVE_PRESCRIPTION
    values["wavelength_nm"] = wavelength_nm if real is None else real.wavelength_nm
    return values


def spread_optimum(*, focus_spread_mm: Any, magnification: Any = 0.0, pupil_magnification: float = 1.0,
                   wavelength_nm: float = 550.0) -> dict[str, Any]:
    """The optimum f-number for a focus spread (rail travel) at a magnification, by key.

    Hansma's rule in the working f-number (docs/closeup.md §4),
    :func:`camtool.dof.closeup.optimum_aperture`.
    """
    from camtool.dof.closeup import optimum_aperture

    d, m = focus_spread_mm, magnification
    r = optimum_aperture(d, m, pupil_magnification, wavelength_nm)
    return {"focus_spread_mm": d, "magnification": m, "f_number": r.f_number, "working_f_number": r.working_f_number,
            "blur_mm": r.blur_mm, "blur_sum_mm": r.blur_sum_mm}


def depth(*, magnification: Any, depth_mm: Any, f_number: Any = None, coc_mm: Any = None,
          pupil_magnification: float = 1.0) -> dict[str, Any]:
    """The CoC (for an f-number given) or the f-number (for a CoC given) giving a total depth at a magnification.

    depth = 2·N·c·(1 + m/P)/m² (docs/closeup.md §6), solved for the one not given.

    >>> r = depth(magnification=1.0, depth_mm=0.96, f_number=8.0)
    >>> round(r["coc_mm"], 12), r["working_f_number"]
    (0.03, 16.0)
    """
    from camtool.dof.closeup import coc_for_depth, f_number_for_depth

    m, d, p = magnification, depth_mm, pupil_magnification
    if f_number is not None:
        n, c = f_number, coc_for_depth(f_number, m, d, p)
    else:
        n, c = f_number_for_depth(coc_mm, m, d, p), coc_mm
    return {"magnification": m, "depth_mm": d, "f_number": n, "coc_mm": c, "working_f_number": n * (1.0 + m / p)}

