"""Depth of field of a scene: which path it takes (the close-up planner or the ladder directly), which model.

:func:`dof_table` makes every decision of ``camtool dof``: whether the scene
goes through the close-up planner (:mod:`camtool.plans.closeup`) or straight
to the model ladder, one rung or all of them (``--model all``: each rung's
difference from the most complete and its time per evaluation), and the facts
the table's columns and footer are made from. :func:`lens_behind_converter`
is the rule for a prescription behind a teleconverter.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from typing import Any

from camtool.core.record import NamedTuple
from camtool.dof.ladder import LensData, depth_of_field, hyperfocal_rung

__all__ = ["DofTable", "dof_table", "lens_behind_converter"]


class DofTable(NamedTuple):
    """The rows of ``camtool dof`` and the facts its columns and footer are made from.

    ``rows`` are row dicts (a :class:`camtool.render.columnar.ColumnRows` on
    the direct path); every row has the keys of its path, ``--model all``
    rows ``difference_pct`` and ``time_per_evaluation_s`` as well. ``path``
    is ``"direct"`` (the ladder on the distances as given) or ``"closeup"``
    (through :mod:`camtool.plans.closeup`). ``close``: some row is close up
    (the magnification and working f-number are worth showing);
    ``focus_column``: some row's focal length at the focus differs from its
    nominal one; ``hyperfocal_model``: under ``auto``, the rung the H column
    is computed by when some row's limits came from another one (else
    None); ``dominated_by``: with diffraction, which depth (``wave`` or
    ``geometric``) the rows' depth of field is dominated by;
    ``lens_focus_setting``: a distance given is the lens's own focus setting
    (an extension or a teleconverter then moves the subject);
    ``reference_model``: under ``--model all``, the most complete rung.
    """

    rows: Any
    path: str
    close: bool
    focus_column: bool
    hyperfocal_model: str | None
    dominated_by: frozenset[str]
    by_magnification: bool
    lens_focus_setting: bool
    reference_model: str


def merge_tables(tables: Sequence[DofTable]) -> DofTable | None:
    """The table of several scenes computed one at a time, as one call over all of them gives it; None when the
    scenes took different paths (the close-up planner for some), or for ``--model all``.

    >>> one = dof_table(model="thin", focal_length_mm=50.0, f_number=8.0, wanted=3000.0, coc_mm=0.03)
    >>> two = dof_table(model="thin", focal_length_mm=50.0, f_number=16.0, wanted=3000.0, coc_mm=0.03)
    >>> merged = merge_tables([one, two])
    >>> [row["f_number"] for row in merged.rows], merged.path
    ([8.0, 16.0], 'direct')
    """
    first = tables[0]
    if any((t.path, t.by_magnification, t.lens_focus_setting, t.reference_model)
           != (first.path, first.by_magnification, first.lens_focus_setting, "") for t in tables):
        return None
    rungs = {t.hyperfocal_model for t in tables} - {None}  # the H rung, where some row's limits came from another
    if len(rungs) > 1:
        return None
    return DofTable([row for t in tables for row in t.rows], first.path, any(t.close for t in tables),
                    any(t.focus_column for t in tables), next(iter(rungs), None),
                    frozenset().union(*(t.dominated_by for t in tables)), first.by_magnification,
                    first.lens_focus_setting, "")


def lens_behind_converter(lens: LensData | None, *, teleconverter: float | None, model: str,
                          pupil_magnification: float | None = None, hiatus_mm: float | None = None) -> Any:
    """The lens data a teleconverter leaves: a prescription is the lens alone, so behind a converter it is dropped.

    The converter is not traced, so the rungs that trace the prescription
    cannot answer (an :class:`InputError` on ``teleconverter``), and the
    prescription's pupils and hiatus are not those of lens and converter
    together: only a pupil magnification and hiatus given are kept.

    >>> lens_behind_converter(LensData(pupil_magnification=0.5), teleconverter=1.4, model="thin").pupil_magnification
    0.5
    """
    if teleconverter in (None, 1.0) or lens is None or lens.prescription is None:
        return lens
    if model in ("paraxial", "raytrace"):
        from camtool.core.errors import InputError

        raise InputError("teleconverter", f"{teleconverter:g} is not part of the lens prescription, which {{model}} "
                         f"{model} traces; use {{model}} thin, thick or auto")
    if (pupil_magnification, hiatus_mm) == (None, None):
        return None
    return LensData(pupil_magnification=pupil_magnification, hiatus_mm=hiatus_mm)


def dof_table(*, model: str, focal_length_mm: Any, f_number: Any, wanted: Any, coc_mm: Any,
              by_magnification: bool = False, distance_from: str = "sensor", lens: LensData | None = None,
              pupil_magnification: float | None = None, hiatus_mm: float | None = None, lens_preset: Any = None,
              extension_mm: float | None = None, teleconverter: float | None = None, diffraction: bool = False,
              wavelength_nm: float = 550.0, tolerance: float = 0.01, criterion: Any = None) -> DofTable:
    """Every row of ``camtool dof``: which path a scene takes, the model (or all of them), the rows.

    ``wanted`` is the focus distance in ``distance_from``'s plane, or the
    magnification with ``by_magnification``; scalars or arrays of one length.
    ``lens`` is the lens data in use (:func:`camtool.plans.equipment.lens_data`,
    after :func:`lens_behind_converter`); ``pupil_magnification`` and
    ``hiatus_mm`` as given and ``lens_preset`` give the pupil magnification
    of the working f-number (and the close-up planner's hiatus when ``lens``
    has none).

    A scene goes through the close-up planner
    (:func:`camtool.plans.closeup.plan_focus` and
    :func:`camtool.plans.closeup.dof_rows`) when asked by magnification, with
    an extension, a teleconverter or diffraction, or when the lens preset
    focuses internally (unless a prescription is traced); otherwise the ladder
    runs on the distances as given. ``model="all"`` gives every rung the lens
    data allow, scene by scene, the most complete last, with each rung's
    difference from it and its time per evaluation (best of three); then
    ``wave``. ``criterion`` (a :class:`camtool.dof.wave.Criterion`) is the
    contrast criterion of ``wave``, which ``auto`` then runs; ``wave`` has
    diffraction built in, so ``diffraction`` alone does not send it through
    the close-up planner.

    Examples
    --------
    50 mm f/8, c = 0.03 mm, focused at 3 m from the lens: H = f²/(N·c) + f = 10,466.67 mm and the near
    limit s(H − f)/(H + s − 2f) (Wikipedia, "Depth of field"):

    >>> t = dof_table(model="thin", focal_length_mm=50.0, f_number=8.0, wanted=3000.0, coc_mm=0.03,
    ...               distance_from="lens")
    >>> h = 50.0 ** 2 / 0.24 + 50.0
    >>> t.path, round(t.rows[0]["near_mm"], 6) == round(3000.0 * (h - 50.0) / (h + 3000.0 - 100.0), 6)
    ('direct', True)
    """
    from camtool.plans.closeup import has_focus_model

    if criterion is not None and model not in ("wave", "auto", "all"):
        from camtool.core.errors import InputError

        raise InputError("criterion", f"{{criterion}} sets the wave model's contrast criterion; with {{model}} {model} "
                         "it has nothing to set (use {model} wave, auto or all)", usage=True)
    scene = _Scene(model, focal_length_mm, f_number, wanted, coc_mm, by_magnification, distance_from, lens,
                   pupil_magnification, hiatus_mm, lens_preset, extension_mm, teleconverter, diffraction,
                   wavelength_nm, tolerance, criterion)
    wave = model == "wave" or (model == "auto" and criterion is not None)
    asked = bool(by_magnification or extension_mm or teleconverter or (diffraction and not wave))
    by_rays = lens is not None and lens.prescription is not None
    if asked or (has_focus_model(lens_preset) and not by_rays):
        return _closeup_all(scene) if model == "all" else _closeup_table(scene, model)
    return _direct_all(scene) if model == "all" else _direct(scene)


class _Scene(NamedTuple):
    model: str
    f: Any
    n: Any
    wanted: Any
    c: Any
    by_m: bool
    plane: str
    lens: LensData | None
    pupil: float | None
    hiatus: float | None
    preset: Any
    extension: float | None
    teleconverter: float | None
    diffraction: bool
    wavelength: float
    tolerance: float
    criterion: Any

    def fallback(self) -> Any:
        """P and δ of the lens data given by hand and the preset (no prescription file), else 1 and 0."""
        from camtool.plans.closeup import pupil_and_hiatus
        from camtool.plans.equipment import lens_data

        return pupil_and_hiatus(lens_data(pupil_magnification=self.pupil, hiatus_mm=self.hiatus,
                                          lens_preset=self.preset))


def _size(*values: Any) -> int:
    """How many scenes the values broadcast to (1 for scalars: numpy is imported only when an array is given)."""
    from camtool.core.arrays import is_scalar

    if all(is_scalar(v) for v in values):
        return 1
    import numpy as np

    return int(np.broadcast(*(np.asarray(v, dtype=float) for v in values)).size)


def _direct(scene: _Scene) -> DofTable:
    from camtool.plans.closeup import CLOSE_UP
    from camtool.render.columnar import ColumnRows

    f, n, s, c, plane = scene.f, scene.n, scene.wanted, scene.c, scene.plane
    result = depth_of_field(scene.model, f, n, c, s, plane, scene.lens, scene.diffraction, scene.wavelength,
                            scene.tolerance, scene.criterion)
    limits = result.limits
    p = scene.fallback().pupil_magnification
    rows = ColumnRows(_size(f, n, s, c), {
        "focal_length_mm": f, "f_number": n, "distance_mm": s, "near_mm": limits.near_mm, "far_mm": limits.far_mm,
        "total_mm": limits.total_mm, "front_mm": limits.front_mm, "rear_mm": limits.rear_mm,
        "hyperfocal_mm": limits.hyperfocal_mm, "coc_mm": c, "magnification": limits.magnification,
        "model": result.model, "error_estimate": result.error_estimate, "distance_from": plane,
    })
    m = limits.magnification
    if isinstance(m, float):
        close = m >= CLOSE_UP
        rows.columns["working_f_number"] = n * (1.0 + m / p)
        rows.columns["other_magnification"] = 1.0 / m if plane == "sensor" and 0.0 < m < 1.0 else None
    else:  # JSON and CSV always carry the close-up keys (a batch and a single call agree), a column each
        import numpy as np

        from camtool.render.columnar import Masked

        m = np.broadcast_to(np.asarray(m, dtype=float), (rows.size,))
        close = bool((m >= CLOSE_UP).any())
        rows.columns["working_f_number"] = np.asarray(n, dtype=float) * (1.0 + m / p)
        other = (m > 0.0) & (m < 1.0) if plane == "sensor" else np.zeros(rows.size, dtype=bool)
        rows.columns["other_magnification"] = Masked(1.0 / np.where(other, m, 1.0), other)
    rows.columns["focal_length_at_focus_mm"] = f
    return DofTable(rows, "direct", close, False, _hyperfocal_model(scene.model, scene.lens, [result.model]),
                    frozenset(), False, False, "")


def _closeup_rows(scene: _Scene, model: str) -> tuple[list[dict[str, Any]], bool]:
    """The rows of one rung through the close-up planner, and whether the planner changed the focus."""
    from camtool.plans.closeup import dof_rows, plan_focus

    known = scene.lens.thick_parameters() if scene.lens is not None else None  # a prescription's own P and δ too
    if known is not None:
        p, delta = (float(v) for v in known)
    else:
        p, delta = scene.fallback()[:2]
    setting = plan_focus(lens=scene.preset, focal_length_mm=scene.f, f_number=scene.n, wanted=scene.wanted,
                         by_magnification=scene.by_m, distance_from=scene.plane, hiatus_mm=delta,
                         extension_mm=scene.extension, teleconverter=scene.teleconverter)
    k = scene.teleconverter or 1.0
    nominal = [k * float(v) for v in (scene.f if hasattr(scene.f, "__len__") else [scene.f])]
    rows = dof_rows(model=model, setting=setting, coc_mm=scene.c, distance_from=scene.plane, lens=scene.lens,
                    diffraction=scene.diffraction, wavelength_nm=scene.wavelength, tolerance=scene.tolerance,
                    pupil_magnification=p, direct=not scene.by_m and not setting.modelled, nominal_focal_mm=nominal,
                    lens_preset=scene.preset, criterion=scene.criterion)
    return rows, setting.modelled


def _focus_column(rows: list[dict[str, Any]]) -> bool:
    return any(abs(r["focal_length_at_focus_mm"] - r["focal_length_mm"]) > 1e-9 * r["focal_length_mm"] for r in rows)


def _closeup_table(scene: _Scene, model: str) -> DofTable:
    from camtool.plans.closeup import CLOSE_UP

    rows, modelled = _closeup_rows(scene, model)
    answered = [r for r in rows if r["near_mm"] is not None]
    close = scene.by_m or modelled or any(r["magnification"] >= CLOSE_UP for r in rows)
    dominated = frozenset(r["depth_dominated_by"] for r in rows if r.get("depth_dominated_by"))
    return DofTable(rows, "closeup", close, _focus_column(rows), _hyperfocal_model(model, scene.lens, answered),
                    dominated, scene.by_m, bool(scene.extension or scene.teleconverter) and not scene.by_m, "")


def _hyperfocal_model(model: str, lens: Any, rows: Any) -> str | None:
    """Under auto, when some row's limits came from a cheaper rung: the one rung the H column is computed by."""
    rung = hyperfocal_rung(lens)
    if model != "auto" or all(name.split("+")[0] in (rung, "wave") for name in _model_names(rows)):  # wave: its own H
        return None
    return rung


def _model_names(rows: Any) -> set[str]:
    """The names of the rungs the rows ran: from row dicts, or from the model columns (a name or an array of them)."""
    names: set[str] = set()
    for item in rows:
        if isinstance(item, dict):
            names.add(str(item["model"]))
        elif isinstance(item, str):
            names.add(item)
        else:
            names.update(str(name) for name in set(item.reshape(-1).tolist()))
    return names


def _direct_all(scene: _Scene) -> DofTable:
    """``--model all`` away from close-up: one row per scene and rung, the most complete rung last."""
    from camtool.dof.ladder import compare_models
    from camtool.render.columnar import ColumnRows

    f, n, s, c, plane = scene.f, scene.n, scene.wanted, scene.c, scene.plane
    count = _size(f, n, s, c)
    rungs = compare_models(f, n, c, s, plane, scene.lens, scene.diffraction, scene.wavelength,
                           criterion=scene.criterion)
    per_model = []
    for rung in rungs:
        limits = rung.result.limits
        per_model.append(ColumnRows(count, {
            "focal_length_mm": f, "f_number": n, "distance_mm": s, "near_mm": limits.near_mm,
            "far_mm": limits.far_mm, "total_mm": limits.total_mm, "front_mm": limits.front_mm,
            "rear_mm": limits.rear_mm, "hyperfocal_mm": limits.hyperfocal_mm, "coc_mm": c,
            "magnification": limits.magnification, "model": rung.result.model,
            "error_estimate": rung.result.error_estimate, "distance_from": plane,
            "difference_pct": rung.difference * 100.0, "time_per_evaluation_s": rung.time_per_evaluation_s,
        }))
    rows = [model_rows[i] for i in range(count) for model_rows in per_model]  # every model of one scene together
    reference = [rung.result.model for rung in rungs if str(rung.result.model).split("+")[0] != "wave"][-1]
    return DofTable(rows, "direct", False, False, None, frozenset(), False, False, reference)


def _closeup_all(scene: _Scene) -> DofTable:
    """``--model all`` for close-up scenes: every rung through the close-up planner, the most complete last.

    Each rung places the subject the same way (the planner's focus: a
    magnification, the lens's focusing model, extension, teleconverter) and
    differs only in the depth of field it computes there; the time per
    evaluation includes the planning, best of three runs.
    """
    import time
    from types import SimpleNamespace

    from camtool.dof.auto import depth_error
    from camtool.dof.ladder import NO_LENS, available_models

    per_model = []
    for rung in available_models(scene.lens or NO_LENS):
        best = math.inf
        for _ in range(3):
            start = time.perf_counter()
            rows = _closeup_rows(scene, rung)[0]
            best = min(best, time.perf_counter() - start)
        per_model.append((rows, best / max(len(rows), 1)))
    reference = per_model[-1][0]
    out: list[dict[str, Any]] = []
    for i, ref in enumerate(reference):  # scene by scene, every model of one scene together
        for model_rows, seconds in per_model:
            row = dict(model_rows[i])
            answered = row["near_mm"] is not None and ref["near_mm"] is not None
            row["difference_pct"] = (100.0 * float(depth_error(SimpleNamespace(**_limits(row)),
                                                                SimpleNamespace(**_limits(ref))))
                                     if answered else None)
            row["time_per_evaluation_s"] = seconds
            out.append(row)
    return DofTable(out, "closeup", True, _focus_column(out), None, frozenset(), scene.by_m, False,
                    reference[0]["model"] if reference else "")


def _limits(row: dict[str, Any]) -> dict[str, float]:
    far = row["far_mm"]
    return {"near_mm": float(row["near_mm"]), "far_mm": math.inf if far is None else float(far)}
