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
- Where a zoom row gives a closest focus but no magnification, the row's
  magnification is modelled: the unit-focusing magnification at that
  distance, but never more than the lens's published maximum
  (``max_magnification``, the largest over the zoom range). A long zoom end
  focuses closer than a unit-focusing lens of its nominal focal length can
  (the FE 24-70 GM II at 70 mm: 0.30 m, where unit focusing would give
  0.59×, but Sony's maximum is 0.32×), so the cap is what keeps the model
  from more magnification, and so less depth of field, than the lens has.
  Where unit focusing cannot reach the published distance at all (D < 4f:
  the Z 70-180 at 85 mm, 0.33 m), the row takes the published maximum and
  the internal-focus model reaches it at that distance. Without a published
  maximum either, the lens is taken to focus as a unit, stopped at the
  published closest focus or at 1:1, whichever is farther.
"""

from __future__ import annotations

from typing import Any

from camtool.geometry.closeup import InternalFocus, internal_focus, internal_focus_between, magnification_branches

__all__ = ["focus_model", "row_magnification"]


def row_magnification(lens: Any, focal_length_mm: float, distance_mm: float, published: float | None,
                      hiatus_mm: float = 0.0) -> float | None:
    """The magnification a zoom row reaches at its closest focus: published, else modelled (None: neither).

    Modelled: the unit-focusing magnification at the row's distance, capped at the
    lens's published maximum; the published maximum where unit focusing cannot reach
    the distance (D < 4f + δ).

    Examples
    --------
    >>> from camtool.presets import load_db
    >>> lens = load_db().get("lens", "sel2470gm2")  # Sony: 0.30 m at 70 mm, at most 0.32x
    >>> row_magnification(lens, 70.0, 300.0, None)
    0.32
    """
    if published is not None:
        return float(published)
    cap = getattr(lens, "max_magnification", None)
    if distance_mm >= 4.0 * focal_length_mm + hiatus_mm:
        unit = float(magnification_branches(focal_length_mm, distance_mm, hiatus_mm).low)
        return unit if cap is None else min(unit, float(cap))
    return None if cap is None else float(cap)


def _row_at(lens: Any, focal_length_mm: float, delta: float) -> tuple[float, float | None] | None:
    rows = [(f, d, row_magnification(lens, f, d, m, delta)) for f, d, m in sorted(lens.close_focus)]
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
    if m1 is None or m2 is None:
        return d1 + t * (d2 - d1), None
    return d1 + t * (d2 - d1), m1 + t * (m2 - m1)


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
        row = _row_at(lens, focal_length_mm, delta)
        assert row is not None
        distance, m = row
    elif getattr(lens, "focus_at_max_magnification_mm", None) is not None and low > 0.0:
        # both ends of a lens without infinity focus are published (the MP-E 65: 0.24 m at 1x, 0.313 m at 5x)
        return internal_focus_between(float(focal_length_mm), low, float(lens.min_focus_mm),
                                      float(lens.max_magnification), float(lens.focus_at_max_magnification_mm))
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
