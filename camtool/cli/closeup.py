"""Close-up on the command line: ``-m/--magnification``, ``--extension``, ``--teleconverter``, per-row diffraction.

:func:`plan_focus` turns what was typed (a distance or a magnification, a
lens preset's internal-focus model, extension, teleconverter) into one
focus setting per row: the focal length and f-number in effect, the
magnification, the distances from the lens and from the sensor and, for a
sensor-plane distance, the other magnification that reaches it
(docs/closeup.md §1, §2, §7). :func:`dof_rows` runs the model ladder on
those settings, row by row where diffraction leaves some rows nothing
sharp (§3), and adds the close-up columns.
"""

from __future__ import annotations

import contextlib
import math
from collections.abc import Iterator, Sequence
from typing import Any, NamedTuple

import click

from camtool.cli.common import one_value
from camtool.cli.equipment import LENS
from camtool.cli.options import EXTENSION_MM, library_errors, param_named, stack
from camtool.cli.params import NumberType
from camtool.core.errors import DomainError, require
from camtool.render.columns import FNUMBER, NUMBER, SMALL, TEXT, Column

MAGNIFICATION = NumberType(1e-6, 1000.0)
"""Any magnification above 0, to 1000:1 (the formulas hold far past the tested 20:1)."""

magnification_option = click.option(
    "-m", "--magnification", type=MAGNIFICATION, multiple=True,
    help="Magnification instead of -s: 0.5 (1:2), 1 (life size), 5 (5:1); a list 1,2,5 gives a row each.")

teleconverter_option = click.option(
    "--teleconverter", type=NumberType(1.0, 4.0), metavar="K", callback=one_value,
    help="Teleconverter factor, e.g. 1.4 or 2: focal length and f-number × K.")

closeup_options = stack(
    click.option("--extension", type=EXTENSION_MM, metavar="LENGTH", callback=one_value,
                 help="Extension tubes or bellows added behind the lens, e.g. 25mm: adds E/f to the magnification."),
    teleconverter_option,
)
"""``--extension`` and ``--teleconverter``."""

CLOSEUP_KEYS = ["working_f_number", "other_magnification", "focal_length_at_focus_mm"]
DIFFRACTION_KEYS = ["airy_mm", "diffraction_limit_f_number", "wave_dof_mm", "depth_dominated_by", "reason"]
CLOSEUP_COLUMNS = [Column("magnification", "m", NUMBER), Column("working_f_number", "working N", FNUMBER)]
FOCUS_COLUMN = Column("focal_length_at_focus_mm", "f at focus", SMALL)
DIFFRACTION_COLUMNS = [
    Column("airy_mm", "Airy", SMALL),
    Column("diffraction_limit_f_number", "diffr. limit", FNUMBER),
    Column("wave_dof_mm", "wave depth"),
]
CLOSE_UP = 0.1
"""From this magnification on, the table shows the magnification and the working f-number."""


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


def has_focus_model(ctx: click.Context) -> bool:
    """True when ``--lens`` publishes a closest focus (and so focuses by the internal-focus model)."""
    lens = ctx.meta.get(LENS)
    return lens is not None and getattr(lens, "prescription", None) is None and bool(
        getattr(lens, "close_focus", ()) or (getattr(lens, "min_focus_mm", None) and not lens.is_zoom))


def focus_models(ctx: click.Context) -> Any:
    """A function focal length -> the ``--lens`` preset's internal-focus model (None without one)."""
    from camtool.presets.focusing import focus_model

    lens = ctx.meta.get(LENS)
    if lens is None or getattr(lens, "prescription", None) is not None:
        return lambda f: None
    return lambda f: focus_model(lens, float(f))


def plan_focus(ctx: click.Context, f: Any, n: Any, wanted: Any, by_magnification: bool, distance_from: str,
               hiatus_mm: float, extension_mm: float | None, teleconverter: float | None) -> Setting:
    """The focus setting of every row (see the module docstring); errors name the option typed."""
    models = focus_models(ctx)
    columns_in = [_list(f), _list(n), _list(wanted)]
    count = max(map(len, columns_in))  # a scalar (one f-number for every row, say) stands for every row
    rows = [_row(models(fi), float(fi), float(ni), float(wi), by_magnification, distance_from, hiatus_mm,
                 extension_mm or 0.0, teleconverter or 1.0)
            for fi, ni, wi in zip(*(c * count if len(c) == 1 else c for c in columns_in), strict=True)]
    columns: list[list[float]] = [list(c) for c in zip(*rows)] if rows else [[] for _ in range(7)]
    modelled = bool(extension_mm) or (teleconverter or 1.0) != 1.0 or any(models(fi) for fi in set(_list(f)))
    return Setting(columns[0], columns[1], columns[2], columns[3], columns[4], columns[5], columns[6], modelled)


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


@contextlib.contextmanager
def _derived_distance_errors(ctx: click.Context, direct: bool, setting: Setting, rows: list[int]) -> Iterator[None]:
    """A focus distance the user did not type (it came from -m or a focus model) is blamed on what they typed.

    The ray trace, for one, focuses a prescription only down to its closest
    focus (1:1 by unit focusing): a larger -m is out of that model's range.
    """
    try:
        yield
    except DomainError as error:
        if direct or error.param != "distance_mm" or error.limit is None:
            raise
        f = min(setting.focal_length_mm[i] for i in rows)
        largest = f / (float(error.limit) - f) if float(error.limit) > f else math.inf
        typed = "magnification" if ctx.params.get("magnification") else None
        where = f"the lens focuses no closer than {float(error.limit):.4g} mm from the lens here" + (
            f", m ≤ {largest:.3g}" if math.isfinite(largest) else "")
        if typed is None:
            raise click.UsageError(f"the focus this lens setting needs is outside the model's range: {where}", ctx) from None
        beyond = [setting.magnification[i] for i in rows if setting.magnification[i] > largest * (1 + 1e-9)]
        shown = ", ".join(f"{m:g}" for m in beyond or [setting.magnification[i] for i in rows])
        raise click.BadParameter(f"{shown} is outside the valid range: {where} (another --model reaches further)",
                                 ctx=ctx, param=param_named(ctx, typed)) from None


def dof_rows(ctx: click.Context, model: str, setting: Setting, c: Any, distance_from: str, lens: Any,
             diffraction: bool, wavelength: float, tolerance: float, pupil: float, delta: float,
             direct: bool = False, nominal_focal: Any = None) -> list[dict[str, Any]]:
    """Depth of field of every planned row (from the lens plane, shifted to the sensor plane when asked).

    With ``diffraction`` each row gets its Airy disc, diffraction-limit
    f-number and wave-optics depth; rows where the Airy disc fills the CoC
    get null limits and a ``reason``, the others their limits. ``direct``:
    the distances were typed and nothing changed them (no ``-m``, focus
    model, extension or teleconverter), so the ladder gets them as typed, in
    their own plane; otherwise it gets the lens-plane distance
    u = f(1 + 1/m) and the limits are moved to the sensor plane by v + δ.
    ``focal_length_mm`` is the lens's nominal focal length (× the
    teleconverter); ``focal_length_at_focus_mm`` the one in effect.
    """
    from camtool.cli.lensdata import ladder_errors
    from camtool.dof.closeup import diffraction_row, wave_depth_mm
    from camtool.dof.ladder import depth_of_field

    count = len(setting.focal_length_mm)
    cs = _list(c) if hasattr(c, "__len__") else [float(c)] * count
    rows: list[dict[str, Any]] = [{} for _ in range(count)]
    sharp = list(range(count))
    if diffraction:
        sharp = []
        for i in range(count):
            n, m, ci = setting.f_number[i], setting.magnification[i], cs[i]
            d = diffraction_row(n, ci, m, pupil, wavelength)
            rows[i].update({"airy_mm": d.airy_mm, "diffraction_limit_f_number": d.limit_f_number,
                            "wave_dof_mm": wave_depth_mm(n, m, pupil, wavelength) if m > 0 else math.inf,
                            "reason": None})
            if d.sharp:
                sharp.append(i)
            else:
                rows[i]["reason"] = (f"nothing sharp: the Airy disc ({d.airy_mm:.3g} mm) fills the CoC "
                                     f"({ci:.3g} mm); below f/{d.limit_f_number:.3g} leaves depth")
    if diffraction and not sharp:
        from camtool.dof.diffraction import usable_coc_mm

        with library_errors(ctx):  # the library's own one-line message, on -N
            usable_coc_mm(cs[0], setting.f_number[0], setting.magnification[0], pupil, wavelength)
    if sharp:
        pick = lambda values: _array([values[i] for i in sharp])  # noqa: E731
        f, n = pick(setting.focal_length_mm), pick(setting.f_number)
        plane = distance_from if direct else "lens"
        s = pick(setting.sensor_distance_mm if plane == "sensor" else setting.lens_distance_mm)
        with library_errors(ctx), ladder_errors(ctx), _derived_distance_errors(ctx, direct, setting, sharp):
            result = depth_of_field(model, f, n, pick(cs), s, plane, lens, diffraction, wavelength, tolerance)
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
    for i in range(count):
        m = setting.magnification[i]
        distance = setting.sensor_distance_mm[i] if distance_from == "sensor" else setting.lens_distance_mm[i]
        rows[i].update({
            "focal_length_mm": setting.focal_length_mm[i] if nominal_focal is None else nominal_focal[i],
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


def branch_note(rows: Sequence[dict[str, Any]]) -> str:
    """Footer text naming the other magnification of a sensor-plane distance (close-up rows only)."""
    others = [(r["distance_mm"], r["other_magnification"]) for r in rows
              if r.get("other_magnification") is not None and r["magnification"] >= CLOSE_UP
              and r["other_magnification"] > r["magnification"] * 1.0001]
    if not others:
        return ""
    shown = ", ".join(list(dict.fromkeys(f"{m:.3g}" for _, m in others))[:3])
    return f"the same distance is also reached at m = {shown} (give -m for that branch)"


def check_depth_inputs(ctx: click.Context, value: Any, name: str) -> None:
    """A one-line error on ``name`` for a non-positive depth or spread."""
    try:
        require(name, value, value > 0, "> 0 mm")
    except DomainError:
        with library_errors(ctx):
            raise


__all__ = [
    "CLOSEUP_COLUMNS",
    "CLOSEUP_KEYS",
    "DIFFRACTION_COLUMNS",
    "DIFFRACTION_KEYS",
    "TEXT",
    "Setting",
    "branch_note",
    "closeup_options",
    "dof_rows",
    "focus_models",
    "has_focus_model",
    "magnification_option",
    "plan_focus",
]
