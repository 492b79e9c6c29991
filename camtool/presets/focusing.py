"""How a lens preset focuses: the internal-focus model from its published closest focus and magnification.

:func:`focus_model` turns a :class:`camtool.presets.schema.Lens` and the focal
length in use into a :class:`camtool.geometry.closeup.InternalFocus`
(docs/closeup.md §2), or None when the preset publishes no closest focus.

- A prime with ``min_focus_mm`` and ``max_magnification`` (and, for a lens
  that cannot focus to infinity, ``min_magnification``) gives the model
  directly: at its closest focus it reaches its published magnification.
- A zoom uses its ``close_focus`` row at that focal length, or interpolates
  linearly in focal length between the two rows around it (the
  magnification only where both rows publish one).
- Where a closest focus is known but no magnification at that focal length,
  the lens is taken to focus as a unit (κ = 0), refusing distances closer
  than the published closest focus.
"""

from __future__ import annotations

from typing import Any

from camtool.geometry.closeup import InternalFocus, internal_focus, magnification_branches

__all__ = ["focus_model"]


def _row_at(lens: Any, focal_length_mm: float) -> tuple[float, float | None] | None:
    rows = sorted(lens.close_focus)
    if not rows:
        return None
    for f, distance, m in rows:
        if abs(f - focal_length_mm) <= 1e-6 * f:
            return distance, m
    below = [r for r in rows if r[0] < focal_length_mm]
    above = [r for r in rows if r[0] > focal_length_mm]
    if not below or not above:  # outside the published rows: the nearest one
        f, distance, m = (below or above)[-1 if below else 0]
        return distance, m
    (f1, d1, m1), (f2, d2, m2) = below[-1], above[0]
    t = (focal_length_mm - f1) / (f2 - f1)
    m = None if m1 is None or m2 is None else m1 + t * (m2 - m1)
    return d1 + t * (d2 - d1), m


def focus_model(lens: Any, focal_length_mm: float) -> InternalFocus | None:
    """The internal-focus model of a lens preset at one focal length (None without a published closest focus).

    Examples
    --------
    >>> from camtool.presets import load_db
    >>> model = focus_model(load_db().get("lens", "ef-100-macro-l"), 100.0)
    >>> round(model.kappa, 4), model.min_focus_mm, model.max_magnification
    (0.3333, 300.0, 1.0)
    """
    if lens is None:
        return None
    delta = float(getattr(lens, "hiatus_mm", None) or 0.0)
    low = float(getattr(lens, "min_magnification", None) or 0.0)
    if getattr(lens, "close_focus", ()):
        row = _row_at(lens, focal_length_mm)
        assert row is not None
        distance, m = row
    elif getattr(lens, "min_focus_mm", None) is not None and not lens.is_zoom:
        distance, m = lens.min_focus_mm, lens.max_magnification
    else:
        return None
    distance = float(distance)
    if m is None:
        # unit focusing, stopped at the published closest focus (or at 1:1 where that is nearer)
        span = max(distance, 4.0 * focal_length_mm + delta)
        m = float(magnification_branches(focal_length_mm, span, delta).low)
        return InternalFocus(float(focal_length_mm), 0.0, low, m, delta, span)
    return internal_focus(float(focal_length_mm), distance, float(m), delta, low)
