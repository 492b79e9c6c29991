"""``auto``: model only what the scene requires.

Before computing, :func:`estimate_effects` says cheaply how much each effect
that a cheaper rung of the ladder leaves out would change the depth of field
of this scene; :func:`choose` then runs the cheapest rung whose left-out
effects add up to no more than the tolerance. The same estimates give every
model's ``error_estimate``.

**Error measure.** The error of a result against a reference is measured in
vergence (1/distance, in the plane the distances are given in), relative to
the reference's depth of field in vergence:

    error = max(|1/near − 1/near_ref|, |1/far − 1/far_ref|) / (1/near_ref − 1/far_ref)

For a shallow depth of field this is the shift of the worse limit divided by
the total depth (Δd/d² over depth/d²); it stays finite when a far limit is
infinite (1/∞ = 0), so a far limit of 2 km against ∞ near the hyperfocal
distance counts as the small error it is. :func:`depth_error` computes it.

**Estimates** (u, v from the principal planes, D from the sensor, H₀ = f²/(N·c),
u_e = min(u, H₀ + f), m = f/(u_e − f), a = N·c·(u_e − f)/f²; a focus beyond the
hyperfocal distance behaves, for the near limit that is left, like one at it):

- approximation (``approx`` neglects f against s): m/2;
- distance plane (``approx`` takes a distance from the sensor as one from the
  lens): ((u_e + v + δ)/u_e)² − 1 ≈ 2(v + δ)/D;
- pupil magnification: |e|·(1 + a)/(2u_e)·(1 + 1.5|e|/u_e), e = f(1 − 1/P),
  ≈ |1 − 1/P|·m;
- hiatus (from the sensor): |δ|/(2a·u_e)·max(|(1 + m²)(1 ± a)² − 1|), ≈ |δ|/D;
- diffraction: 1 − √(1 − (b_airy/c)²) ≈ (b_airy/c)²/2;
- aberrations (real against paraxial rays, only with a prescription): half
  the relative change of the local depth of field in object vergence between
  real and paraxial rays (2√2·S·dz_best/dw against 2·u′·dz′/dw: each limit
  moves by about half the change of the depth), times a safety factor of
  1.7; and, for a distance from the sensor, the shift of the focused object
  that the real best focus causes (:func:`focus_shift_share`). Both are
  measured once per prescription over a grid of f-numbers (f/1 to f/64 in
  half stops) at a few magnifications and interpolated (linearly in m,
  log-log in N). The table is cached for the process and on disk, keyed by
  the prescription's content, so a command with a prescription traces no
  rays (and imports no numpy) unless its model is ``raytrace``.

These are first-order results of the closed forms (the first four are within a
few per cent of the exact differences over the whole domain); the aberration
estimate bounds the ray trace's actual difference from ``paraxial`` on every
scene of the grid of ``tests/test_auto_bound.py`` (every shipped prescription,
closest focus to beyond the hyperfocal distance, design aperture to f/32).
"""

from __future__ import annotations

import bisect
import functools
import itertools
import math
from typing import Any

from camtool.core.arrays import ops, quiet
from camtool.core.record import NamedTuple
from camtool.dof.rungs import RUNGS, by_name

__all__ = [
    "EFFECTS", "LEFT_OUT", "Effects", "aberration_share", "aberration_table", "depth_error", "estimate_effects",
    "focus_shift", "focus_shift_share", "left_out",
]

EFFECTS = ("approximation", "distance_plane", "pupil", "hiatus", "diffraction", "aberrations")

LEFT_OUT = {rung.name: rung.left_out for rung in RUNGS}
"""The geometric effects each rung leaves out (diffraction is left out unless the add-on runs); from the rung records."""

_ABERRATION_MAGNIFICATIONS = (0.0, 0.05, 0.15, 0.35, 0.7, 1.0)


class Effects(NamedTuple):
    """Estimated relative change of the depth of field by each effect (see the module docstring)."""

    approximation: Any
    distance_plane: Any
    pupil: Any
    hiatus: Any
    diffraction: Any
    aberrations: Any


def left_out(effects: Effects, model: str, diffraction_applied: bool) -> Any:
    """Estimated relative error of ``model``: the sum of the effects it leaves out.

    Examples
    --------
    >>> e = Effects(0.01, 0.02, 0.003, 0.001, 0.004, 0.0)
    >>> round(left_out(e, "thin", False), 6)
    0.008
    >>> round(left_out(e, "thin", True), 6)
    0.004
    """
    total: Any = 0.0 if diffraction_applied else effects.diffraction
    for name in by_name()[model].left_out:
        total = total + getattr(effects, name)
    return total


def estimate_effects(
    focal_length_mm: Any,
    f_number: Any,
    coc_mm: Any,
    distance_mm: Any,
    distance_from: str = "sensor",
    pupil_magnification: Any = 1.0,
    hiatus_mm: Any = 0.0,
    airy_mm: Any = 0.0,
    prescription: Any = None,
    geometry: Any = None,
) -> Effects:
    """Estimate, before computing, how much each effect changes this scene's depth of field.

    Parameters
    ----------
    focal_length_mm, f_number, coc_mm : float or array, all > 0
    distance_mm : float or array
        Focus distance from ``distance_from`` (``inf`` allowed).
    distance_from : ``"sensor"`` or ``"lens"``
    pupil_magnification, hiatus_mm : float or array
        The lens's P and δ (1 and 0 when unknown).
    airy_mm : float or array
        Airy diameter at the focus when diffraction is asked for, else 0.
    prescription : Prescription or None
        Enables the aberration estimate.
    geometry : FocusGeometry or None
        ``focus_geometry(f, distance_mm, distance_from, hiatus_mm)`` when the
        caller has it (the conversion is then not repeated).

    Returns
    -------
    Effects
        Relative errors in the measure of :func:`depth_error`; a term that is
        exactly 0 for every scene (P = 1, no hiatus, no Airy disc, no
        prescription, a distance from the lens) is the plain number 0.0.

    Examples
    --------
    50 mm f/8 at 3 m from the sensor: neglecting f costs about 1 %, the
    distance plane about 4 %:

    >>> e = estimate_effects(50.0, 8.0, 0.03, 3000.0)
    >>> round(e.approximation, 4), round(e.distance_plane, 4), e.pupil
    (0.0086, 0.0348, 0.0)
    """
    from camtool.dof.diffraction import diffraction_share
    from camtool.geometry.thinlens import focus_geometry

    f, nc, p, delta = focal_length_mm, f_number * coc_mm, pupil_magnification, hiatus_mm
    xp = ops(f, f_number, coc_mm, distance_mm, p, delta, airy_mm)
    if geometry is None:
        geometry = focus_geometry(f, distance_mm, distance_from, delta)
    # a symmetric lens (P = 1), no hiatus and no Airy disc leave their terms exactly 0: not computed
    symmetric, no_hiatus = _is(p, 1.0), _is(delta, 0.0)
    with quiet(xp):
        u_e = xp.minimum(geometry.object_mm, f * f / nc + f)
        w = u_e - f
        m = f / w
        a = nc * w / (f * f)
        approximation = 0.5 * m
        if symmetric:
            pupil: Any = 0.0
        else:
            e = xp.fabs(f - f / p)
            pupil = e * (1.0 + a) / (2.0 * u_e) * (1.0 + 1.5 * e / u_e)
        if distance_from == "sensor":
            ratio = (u_e + geometry.image_mm + delta) / u_e
            plane = ratio * ratio - 1.0
            if no_hiatus:
                hiatus: Any = 0.0
            else:
                grow = (1.0 + m * m) * (1.0 + a) * (1.0 + a) - 1.0
                shrink = xp.where(a < 1.0, xp.fabs((1.0 + m * m) * (1.0 - a) * (1.0 - a) - 1.0), 0.0)
                hiatus = xp.fabs(delta) / (2.0 * a * u_e) * xp.maximum(xp.fabs(grow), shrink)
        else:
            plane = hiatus = 0.0
        diffraction = 0.0 if _is(airy_mm, 0.0) else diffraction_share(coc_mm, airy_mm)
    if prescription is None:
        aberrations = 0.0
    else:
        aberrations = aberration_share(prescription, f_number, m)
        if distance_from == "sensor":
            aberrations = aberrations + focus_shift_share(prescription, f, f_number, coc_mm, geometry)
    return Effects(approximation, plane, pupil, hiatus, diffraction, aberrations)


def _is(value: Any, number: float) -> bool:
    """Whether ``value`` is the plain number ``number`` (an array is never taken for one)."""
    return isinstance(value, (int, float)) and value == number


def focus_shift_share(prescription: Any, focal_length_mm: Any, f_number: Any, coc_mm: Any, geometry: Any) -> Any:
    """Estimated error from where the real rays put the focused object, for a distance from the sensor.

    The paraxial rungs place the object at u with u + v(u) = L (L the
    distance from the sensor less the hiatus); the real rays focus it
    Δ = :func:`focus_shift` further back, so the focused object is the one
    with u′ + v(u′) = L − Δ. Both in closed form, 1/u = (1 − √(1 − 4f/L))/(2f),
    taken as 2/(L·(1 + √(1 − 4f/L))); the estimate is |1/u′ − 1/u| over the
    thin lens's depth of field in vergence, (1/u + A) − max(1/u − A, 0) with
    A = N·c·(1 − f/u)/f². Near 1:1, where L is least, a small Δ moves the
    object far (dL/du = 1 − m² → 0); where L − Δ < 4f the real rays cannot
    focus there and the estimate is 1 (everything uncertain).

    Examples
    --------
    >>> from camtool.optics.prescription import EXAMPLE_SINGLET, prescription_from_mapping
    >>> from camtool.optics.paraxial import first_order
    >>> from camtool.geometry.thinlens import focus_geometry
    >>> lens = prescription_from_mapping(EXAMPLE_SINGLET)
    >>> f = first_order(lens).efl_mm
    >>> near, far = (focus_shift_share(lens, f, 8.0, 0.03, focus_geometry(f, d * f)) for d in (4.2, 100.0))
    >>> near > far > 0.0
    True
    """
    f = focal_length_mm
    u, v = geometry.object_mm, geometry.image_mm
    xp = ops(f, f_number, coc_mm, u, v)
    with quiet(xp):
        shift = focus_shift(prescription, f_number, f / (u - f))
        g = 1.0 / u
        moved = u + v - shift
        reachable = moved >= 4.0 * f
        span = xp.maximum(moved, 4.0 * f)
        g_real = 2.0 / (span * (1.0 + xp.sqrt(1.0 - 4.0 * f / span)))
        a_g = f_number * coc_mm * (1.0 - f * g) / (f * f)
        depth = (g + a_g) - xp.maximum(g - a_g, 0.0)
        return xp.where(reachable, xp.fabs(g_real - g) / depth, 1.0)


def aberration_share(prescription: Any, f_number: Any, magnification: Any) -> Any:
    """Estimated relative difference between the real-ray and the paraxial local depth of field.

    Interpolates the calibration of :func:`aberration_table` (one per
    prescription, over a grid of f-numbers): linearly in magnification, and
    in f-number linearly in log N and log share (the share falls about as
    a power of N). Continuous f-numbers cost no more than a few.

    Examples
    --------
    >>> from camtool.optics.prescription import EXAMPLE_SINGLET, prescription_from_mapping
    >>> lens = prescription_from_mapping(EXAMPLE_SINGLET)
    >>> aberration_share(lens, 2.8, 0.0) > aberration_share(lens, 16.0, 0.0)
    True
    """
    return _interpolated(prescription, f_number, magnification, 1)


def focus_shift(prescription: Any, f_number: Any, magnification: Any) -> Any:
    """Estimated real best focus minus the paraxial image of the same object (mm, signed), from the table.

    Interpolated as :func:`aberration_share` (geometrically in N where the
    neighbours share a sign, else linearly).

    Examples
    --------
    >>> from camtool.optics.prescription import EXAMPLE_SINGLET, prescription_from_mapping
    >>> lens = prescription_from_mapping(EXAMPLE_SINGLET)
    >>> abs(focus_shift(lens, 4.0, 0.0)) > abs(focus_shift(lens, 16.0, 0.0)) > 0.0
    True
    """
    return _interpolated(prescription, f_number, magnification, 2)


def _interpolated(prescription: Any, f_number: Any, magnification: Any, column: int) -> Any:
    """Column ``column`` of the table (1 share, 2 focus shift) at (N, m): linear in m, log-log in N where it can."""
    grid_n, table = aberration_table(prescription)
    xp = ops(f_number, magnification)
    if xp.name == "math":
        i, t = _grid_position(grid_n, float(f_number))
        low = _interpolate(table[i], float(magnification), column)
        high = _interpolate(table[i + 1], float(magnification), column)
        return _between(low, high, t)
    import numpy as np

    n, mags = np.broadcast_arrays(np.asarray(f_number, float), np.asarray(magnification, float))
    rows = [np.interp(np.where(np.isfinite(mags), mags, row[-1][0]), [e[0] for e in row], [e[column] for e in row])
            for row in table]
    grid = np.array(rows)  # (f-numbers, scenes)
    logs_n = np.log(grid_n)
    with np.errstate(all="ignore"):
        log_n = np.clip(np.log(np.where(n > 0.0, n, grid_n[0])), logs_n[0], logs_n[-1])
    cell = np.clip(np.searchsorted(logs_n, log_n, side="right") - 1, 0, len(table) - 2)
    frac = (log_n - logs_n[cell]) / (logs_n[cell + 1] - logs_n[cell])
    flat = np.arange(n.size).reshape(n.shape)
    cells = grid.reshape(len(table), -1)
    below, above = cells[cell, flat], cells[cell + 1, flat]
    with np.errstate(all="ignore"):
        logs = np.sign(below) * np.exp((1.0 - frac) * np.log(np.fabs(below)) + frac * np.log(np.fabs(above)))
    return np.where(below * above > 0.0, logs, (1.0 - frac) * below + frac * above)


_GRID_F_NUMBERS = tuple(2.0 ** (k / 2.0) for k in range(13))
"""N = 2^(k/2), f/1 to f/64 in half stops; a prescription's own design f-number is added."""
_TABLE_VERSION = 3


def _grid_position(grid: tuple[float, ...], f_number: float) -> tuple[int, float]:
    """The cell of the f-number grid N falls in and its position there in log N (clamped to the ends)."""
    log_n = math.log(min(max(f_number, grid[0]), grid[-1])) if f_number > 0.0 else math.log(grid[0])
    i = min(bisect.bisect_right(grid, math.exp(log_n)) - 1, len(grid) - 2)
    i = max(i, 0)
    return i, (log_n - math.log(grid[i])) / (math.log(grid[i + 1]) - math.log(grid[i]))


def _between(low: float, high: float, t: float) -> float:
    """Interpolate two grid values: geometrically when they share a sign (and are not 0), else linearly."""
    if low * high > 0.0:
        return math.copysign(math.exp((1.0 - t) * math.log(abs(low)) + t * math.log(abs(high))), low)
    return (1.0 - t) * low + t * high


def _interpolate(row: tuple[tuple[float, float, float], ...], m: float, column: int = 1) -> float:
    """Piecewise-linear interpolation of a row's ``column`` in m; the last value beyond the table."""
    if not math.isfinite(m):
        return row[-1][column]
    for low, high in itertools.pairwise(row):
        if m <= high[0]:
            return low[column] + (high[column] - low[column]) * max(m - low[0], 0.0) / (high[0] - low[0])
    return row[-1][column]


Table = tuple[tuple[float, ...], tuple[tuple[tuple[float, float, float], ...], ...]]


@functools.lru_cache(maxsize=64)
def aberration_table(prescription: Any) -> Table:
    """The aberration calibration of a prescription: its f-number grid and (magnification, share, focus shift) per f-number.

    The f-numbers are N = 2^(k/2), f/1 to f/64 (k = 0…12), and the
    prescription's design f-number when it states one. Computing it
    traces rays (numpy, about 20 ms), except for the prescriptions shipped in
    ``lens_db/prescriptions/``, whose tables ship with the package
    (:data:`SHIPPED_TABLES`, checked as a cache entry's are); the result is
    cached for the process and on disk, in ``$XDG_CACHE_HOME/camtool/aberrations/`` (default
    ``~/.cache/camtool``), bound to the SHA-256 of the prescription's
    content, so a later command with the same prescription reads a small
    JSON file instead. An entry is used only when it passes the checks of
    :mod:`camtool.core.cache` (a regular file of at most 64 KiB, its MAC,
    the camtool version, the content digest) and of :func:`_valid_table`;
    otherwise it is computed afresh and written over the entry.
    ``CAMTOOL_NO_CACHE`` bypasses the disk and the shipped tables (every
    table computed, as every preset file is then parsed).

    Examples
    --------
    >>> from camtool.optics.prescription import EXAMPLE_SINGLET, prescription_from_mapping
    >>> grid, table = aberration_table(prescription_from_mapping(EXAMPLE_SINGLET))
    >>> len(grid), grid[0], grid[-1], table[0][0][0]
    (13, 1.0, 64.0, 0.0)
    """
    from camtool.core import cache

    if not cache.enabled():
        return _compute_table(prescription)
    source = _source(prescription)
    path = _cache_path(source)
    table = _read_table(path, source, prescription)
    if table is None:
        table = _shipped_table(source, prescription) or _compute_table(prescription)
        _write_table(path, source, table)
    return table


SHIPPED_TABLES = "aberrations.json"
"""The tables of the shipped prescriptions (``lens_db/prescriptions/``), beside this module.

Written by ``python -m camtool.presets.shipped`` (:mod:`camtool.presets.shipped`); each
table is keyed by the :func:`_source` digest of the prescription it was
computed for, so an edited prescription, another grid or another table
version finds no table there and is computed afresh. Each table is a JSON
text of its own, parsed only when its prescription is used.
"""


@functools.lru_cache(maxsize=1)
def _shipped() -> dict[str, Any]:
    """The shipped tables by source digest (empty when the file is missing or not the expected shape)."""
    import json
    import os

    path = os.path.join(os.path.dirname(os.path.abspath(__file__)), SHIPPED_TABLES)
    try:
        with open(path, "rb") as handle:
            data = json.loads(handle.read(1 << 20))
    except (OSError, ValueError, RecursionError):
        return {}
    tables = data.get("tables") if isinstance(data, dict) and data.get("version") == _TABLE_VERSION else None
    return tables if isinstance(tables, dict) else {}


def _shipped_table(source: str, prescription: Any) -> Table | None:
    """The shipped table of this prescription's content, when there is one and it passes :func:`_valid_table`.

    Shipped with the package rather than read from a cache, it is checked
    all the same: keyed by the content digest, and a table a fresh
    calibration could not give (another grid, other magnifications, a
    share that is not a finite number ≥ 0) is refused and computed afresh.
    """
    table = _shipped().get(source)
    if isinstance(table, str):  # each table is a JSON text of its own, parsed when its prescription is used
        import json

        try:
            table = json.loads(table)
        except (ValueError, RecursionError):
            return None
    return _valid_table(table, prescription)


def _content(prescription: Any) -> str:
    """What the table depends on: the surfaces, the object medium, the grids and the table version."""
    return repr((_TABLE_VERSION, _grid(prescription), _ABERRATION_MAGNIFICATIONS, prescription.surfaces,
                 prescription.object_index))


def _source(prescription: Any) -> str:
    """The SHA-256 of :func:`_content`: what a cache entry is bound to."""
    from camtool.core import cache

    return cache.source_digest(_content(prescription).encode("utf-8"))


_CACHE_KIND = "aberrations"
_CACHE_MAX_BYTES = 64 * 1024
"""Largest cache entry read (a table is about 2 KB)."""


def _cache_path(source: str) -> str:
    """Cache file of a prescription's table, named by the SHA-256 of :func:`_content`."""
    import os

    from camtool.core import cache

    return os.path.join(cache.root(), _CACHE_KIND, f"{source[:40]}.json")


def _read_table(path: str, source: str, prescription: Any) -> Table | None:
    """The cached table when its entry passes every check of :mod:`camtool.core.cache` and :func:`_valid_table`."""
    import json

    from camtool.core import cache

    payload = cache.read(path, _CACHE_KIND, source, _CACHE_MAX_BYTES)
    if payload is None:
        return None
    try:
        data = json.loads(payload)
    except (ValueError, RecursionError):
        return None
    return _valid_table(data, prescription)


def _valid_table(data: Any, prescription: Any) -> Table | None:
    """``data`` as a table when it is one a fresh calibration of ``prescription`` could give, else None.

    The f-number grid and the magnifications must be exactly the ones
    :func:`_compute_table` uses for this prescription (increasing, the same
    in every row), every share a finite number ≥ 0 and every focus shift finite.
    """
    if not isinstance(data, dict) or set(data) != {"f_numbers", "table"}:
        return None
    grid, rows = data["f_numbers"], data["table"]
    expected_grid = _grid(prescription)
    if not isinstance(grid, list) or not isinstance(rows, list) or len(grid) != len(expected_grid):
        return None
    if any(type(n) is not float or n != e for n, e in zip(grid, expected_grid, strict=True)):
        return None
    try:
        expected_ms = _table_magnifications(prescription)
    except (ValueError, ArithmeticError):
        return None
    if len(rows) != len(expected_grid):
        return None
    table = []
    for row in rows:
        if not isinstance(row, list) or len(row) != len(expected_ms):
            return None
        entries = []
        for entry, m_expected in zip(row, expected_ms, strict=True):
            if not isinstance(entry, list) or len(entry) != 3:
                return None
            m, share, shift = entry
            if type(m) is not float or m != m_expected or type(share) is not float or type(shift) is not float:
                return None
            if not (math.isfinite(share) and share >= 0.0 and math.isfinite(shift)):
                return None
            entries.append((m, share, shift))
        table.append(tuple(entries))
    return tuple(expected_grid), tuple(table)


def _write_table(path: str, source: str, table: Table) -> None:
    """Store the table (atomically; a table that cannot be written, or holds a non-finite number, is skipped)."""
    from camtool.core import cache

    try:
        payload = cache.dumps({"f_numbers": list(table[0]), "table": [[list(p) for p in row] for row in table[1]]})
    except ValueError:
        return
    cache.write(path, _CACHE_KIND, source, payload)


def _grid(prescription: Any) -> tuple[float, ...]:
    """The f-numbers of a prescription's table: the half-stop grid and its design f-number."""
    design = prescription.f_number
    extra = {float(design)} if design and _GRID_F_NUMBERS[0] < design < _GRID_F_NUMBERS[-1] else set()
    return tuple(sorted(set(_GRID_F_NUMBERS) | extra))


def _compute_table(prescription: Any) -> Table:
    """(magnification, 0.85·|real/paraxial − 1| of the local depth of field, focus shift), per grid f-number.

    At a few magnifications m (objects at vertex vergence w), with a
    neighbouring object at w + dw: the real rays' 2√2·S·dz_best/dw (S the RMS
    slope, z_best the minimum-RMS focus) against the paraxial marginal ray's
    2·|u′|·dz′/dw through the stop edge. Their ratio is the ratio of the
    depths of field in vergence (the limits are where the blur, proportional
    to these, reaches c). Magnifications the real rays cannot reach are left
    out; where the rays cannot be traced the estimate is 1 (everything
    uncertain). The focus shift is z_best minus the paraxial image of the
    same object (mm), which :func:`focus_shift_share` turns into the shift of
    the focused object when the distance is given from the sensor.
    """
    from camtool.optics.paraxial import first_order, paraxial_trace
    from camtool.optics.tracer import real_tracer

    fo = first_order(prescription)
    ws, ms = _object_points(fo)
    tracer = real_tracer(prescription)
    stop = prescription.stop_index
    a, _ = paraxial_trace(prescription, 1.0, 0.0, stop=stop)
    b, _ = paraxial_trace(prescription, 0.0, 1.0, stop=stop)
    ya, nua = paraxial_trace(prescription, 1.0, 0.0)
    yb, nub = paraxial_trace(prescription, 0.0, 1.0)
    z_k = prescription.vertices_mm[-1]
    v = tracer.pupil_vergence(ws)
    table = []
    grid = _grid(prescription)
    for f_number in grid:
        summary, ok = tracer.summarise(v, f_number)
        r_stop = fo.stop_radius_mm(f_number)

        def paraxial_image(w: float, r_stop: float = r_stop) -> tuple[float, float]:
            h = r_stop / (a + b * w)
            y_k, nu_k = h * (ya + w * yb), h * (nua + w * nub)
            return z_k - y_k / nu_k, abs(nu_k)

        row = []
        for i, m in enumerate(ms):
            w0, w1 = ws[2 * i], ws[2 * i + 1]
            z0, slope = paraxial_image(w0)
            z1, _ = paraxial_image(w1)
            real = _SQRT8 * float(summary.slope_rms[2 * i]) * float(summary.z_best[2 * i + 1] - summary.z_best[2 * i])
            # each limit moves by about half the relative change of the depth; the safety factor bounds the
            # measured ratio of actual to half-change on the shipped prescriptions (docs/design.md §4.10)
            share = 0.5 * _SHARE_SAFETY * abs(real / (2.0 * slope * (z1 - z0)) - 1.0)
            shift = float(summary.z_best[2 * i]) - z0
            good = bool(ok[2 * i] and ok[2 * i + 1]) and math.isfinite(share) and math.isfinite(shift)
            row.append((m, share, shift) if good else (m, 1.0, 0.0))
        if len(row) == 1:
            row.append((1.0, *row[0][1:]))
        table.append(tuple(row))
    return grid, tuple(table)


_SQRT8 = 2.0 * math.sqrt(2.0)
_SHARE_SAFETY = 1.7
"""Half the relative change of the local depth understates the actual error by up to 1.65x (shipped lenses)."""


def _object_points(fo: Any) -> tuple[list[float], list[float]]:
    """The object vergences traced (each magnification's w and a neighbour w + dw) and the magnifications kept.

    Magnifications the real rays cannot reach (w < 0) are left out.
    """
    f = fo.efl_mm
    ws, ms = [], []
    for m in _ABERRATION_MAGNIFICATIONS:
        w = 0.0 if m == 0.0 else 1.0 / (f * (1.0 + m) / m - fo.z_h_mm)
        if w < 0.0:
            continue
        dw = max(w, 1.0 / f) * 1e-4
        ws += [w, w + dw]
        ms.append(m)
    return ws, ms


def _table_magnifications(prescription: Any) -> list[float]:
    """The magnifications of every row of the table :func:`_compute_table` makes for ``prescription``."""
    from camtool.optics.paraxial import first_order

    ms = _object_points(first_order(prescription))[1]
    return [*ms, 1.0] if len(ms) == 1 else ms


def depth_error(limits: Any, reference: Any) -> Any:
    """Relative error of ``limits`` against ``reference`` in vergence (see the module docstring).

    Parameters
    ----------
    limits, reference : DofLimits
        In the same distance plane; far limits may be infinite.

    Examples
    --------
    >>> from camtool.dof.closed import approx_dof, thin_dof
    >>> round(depth_error(approx_dof(50.0, 8.0, 0.03, 3000.0), thin_dof(50.0, 8.0, 0.03, 3000.0, "lens")), 4)
    0.0085
    """
    xp = ops(limits.near_mm, limits.far_mm, reference.near_mm, reference.far_mm)
    with quiet(xp):
        near, far = 1.0 / limits.near_mm, 1.0 / limits.far_mm
        near_ref, far_ref = 1.0 / reference.near_mm, 1.0 / reference.far_mm
        return xp.maximum(xp.fabs(near - near_ref), xp.fabs(far - far_ref)) / (near_ref - far_ref)
