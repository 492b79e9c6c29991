"""Fisheye projections: the angle a sensor dimension covers, and the field at a distance, for each mapping.

A lens maps a ray at θ from the axis to an image height r from the centre:

- rectilinear (gnomonic): r = f·tan θ — every ordinary lens; below 90° either side;
- equidistant (f-θ): r = f·θ;
- equisolid angle (equal area): r = 2f·sin(θ/2);
- orthographic: r = f·sin θ — at most 90° either side (r = f);
- stereographic: r = 2f·tan(θ/2).

A fisheye's image circle is where its field ends (``field_max_deg`` of the
lens, 180° when the preset states none): a sensor dimension reaching beyond it
(a circular fisheye on full frame) covers that whole field. Focused closer, the
image sits f(1 + m/P) behind the lens's rear node, as for a rectilinear lens
(:func:`camtool.geometry.fov.angle_of_view_deg`), so f(1 + m/P) replaces f in
the mapping. The field at a subject u in front of the lens spans
2u·tan(α/2) across an angle α; it is unbounded from α = 180°. For the
rectilinear mapping this is the sensor size over m, the formula of
:func:`camtool.geometry.fov.field_size_mm`, which that projection keeps.

Lengths in millimetres, angles in degrees.

References
----------
Wikipedia, "Fisheye lens" (mapping functions); Kingslake, *A History of the
Photographic Lens* (1989), ch. 10; Nikon, Fisheye-Nikkor 6mm f/2.8 instruction
manual ("the equidistant projection formula (y = fθ)", 220°, 23 mm circle).
"""

from __future__ import annotations

import math
from typing import Any

from camtool.core.arrays import ops, quiet
from camtool.core.errors import DomainError, require, require_positive
from camtool.core.record import NamedTuple

__all__ = [
    "FISHEYE_FIELD_DEG",
    "PROJECTIONS",
    "fill_magnification",
    "fisheye_angle_of_view_deg",
    "fisheye_field_of_view",
    "fisheye_field_size_mm",
    "half_angle_deg",
    "image_height_mm",
]

PROJECTIONS = ("rectilinear", "equidistant", "equisolid", "orthographic", "stereographic")
"""The mappings camtool knows, by the name a lens preset's ``projection`` and ``--projection`` take."""

FISHEYE_FIELD_DEG = 180.0
"""The field of a fisheye whose preset states none (``field_max_deg``): a hemisphere."""


def check_projection(projection: Any) -> str:
    """The projection's name, or a :class:`DomainError` naming the valid ones.

    >>> check_projection("equisolid")
    'equisolid'
    """
    if projection not in PROJECTIONS:
        raise DomainError("projection", projection, "one of " + ", ".join(PROJECTIONS))
    return str(projection)


def image_height_mm(focal_length_mm: Any, angle_deg: Any, projection: str) -> Any:
    """Image height r (mm from the centre) of a ray at ``angle_deg`` from the axis, r(θ) of ``projection``.

    Examples
    --------
    The Fisheye-Nikkor 6mm f/2.8 (equidistant) at 110°, the edge of its 220° field:
    6 × 110π/180 = 11.52 mm, the radius of its 23 mm image circle (Nikon's manual).

    >>> round(image_height_mm(6.0, 110.0, "equidistant"), 2)
    11.52
    >>> round(image_height_mm(8.0, 90.0, "equisolid"), 3)  # 2·8·sin 45°
    11.314
    """
    check_projection(projection)
    require_positive("focal_length_mm", focal_length_mm)
    xp = ops(focal_length_mm, angle_deg)
    theta = xp.radians(angle_deg)
    if projection == "rectilinear":
        return focal_length_mm * xp.tan(theta)
    if projection == "equidistant":
        return focal_length_mm * theta
    if projection == "equisolid":
        return 2.0 * focal_length_mm * xp.sin(theta / 2.0)
    if projection == "orthographic":
        return focal_length_mm * xp.sin(theta)
    return 2.0 * focal_length_mm * xp.tan(theta / 2.0)


def half_angle_deg(height_mm: Any, focal_length_mm: Any, projection: str) -> Any:
    """The angle θ (degrees from the axis) imaged at height r: the inverse of :func:`image_height_mm`.

    Where the mapping cannot reach r (equisolid beyond 2f, orthographic beyond
    f) the answer is the angle at its edge, 180° and 90°: the whole field the
    mapping holds lies inside r.

    Examples
    --------
    >>> round(half_angle_deg(11.5, 6.0, "equidistant"), 2)  # the Fisheye-Nikkor 6 mm's 23 mm circle
    109.82
    >>> half_angle_deg(12.0, 10.0, "orthographic")  # beyond r = f: the hemisphere
    90.0
    """
    check_projection(projection)
    require_positive("focal_length_mm", focal_length_mm)
    require("image_height_mm", height_mm, height_mm >= 0, ">= 0")
    return _half_angle(height_mm, focal_length_mm, projection, ops(height_mm, focal_length_mm))


def _half_angle(height_mm: Any, focal_length_mm: Any, projection: str, xp: Any) -> Any:
    """:func:`half_angle_deg` on inputs already checked."""
    ratio = height_mm / focal_length_mm
    with quiet(xp):
        if projection == "rectilinear":
            theta = xp.atan(ratio)
        elif projection == "equidistant":
            theta = ratio
        elif projection == "equisolid":
            theta = 2.0 * _asin(xp, xp.minimum(ratio / 2.0, 1.0))
        elif projection == "orthographic":
            theta = _asin(xp, xp.minimum(ratio, 1.0))
        else:
            theta = 2.0 * xp.atan(ratio / 2.0)
    return xp.degrees(theta)


def _asin(xp: Any, x: Any) -> Any:
    """asin x for 0 ≤ x ≤ 1, on either path."""
    if xp.name == "numpy":
        import numpy as np

        return np.arcsin(x)
    return math.asin(x)


def fisheye_angle_of_view_deg(size_mm: Any, focal_length_mm: Any, projection: str, magnification: Any = 0.0,
                              pupil_magnification: Any = 1.0, field_max_deg: float | None = None) -> Any:
    """Angle of view across a sensor dimension h: 2·θ(h/2) of the mapping at f(1 + m/P), at most the lens's field.

    Parameters
    ----------
    size_mm : float or array, h > 0
    focal_length_mm : float or array, f > 0
    projection : one of :data:`PROJECTIONS`
    magnification, pupil_magnification : as :func:`camtool.geometry.fov.angle_of_view_deg`
    field_max_deg : float or None
        The lens's whole field (its image circle); None: 180° for a fisheye
        mapping (:data:`FISHEYE_FIELD_DEG`), none for the rectilinear one.

    Examples
    --------
    An 8 mm circular fisheye (equisolid) on full frame covers its 180° every way;
    a 15 mm one across the 36 mm side, 4·asin(18/30) = 147.48°:

    >>> fisheye_angle_of_view_deg(36.0, 8.0, "equisolid")
    180.0
    >>> round(fisheye_angle_of_view_deg(36.0, 15.0, "equisolid"), 2)
    147.48
    """
    require_positive("sensor_mm", size_mm)
    _check_view(focal_length_mm, projection, magnification, pupil_magnification, field_max_deg)
    xp = ops(size_mm, focal_length_mm, magnification, pupil_magnification)
    effective = focal_length_mm * (1.0 + magnification / pupil_magnification)
    return _angle(size_mm, effective, projection, field_max_deg, xp)


def _check_view(focal_length_mm: Any, projection: str, magnification: Any, pupil_magnification: Any,
                field_max_deg: float | None) -> None:
    require_positive("focal_length_mm", focal_length_mm)
    require("magnification", magnification, magnification >= 0, ">= 0")
    require_positive("pupil_magnification", pupil_magnification, unit="")
    if field_max_deg is not None:
        require("field_max_deg", field_max_deg, (field_max_deg > 0) & (field_max_deg <= 360), "in (0, 360]")
    check_projection(projection)


def _angle(size_mm: Any, effective_mm: Any, projection: str, field_max_deg: float | None, xp: Any) -> Any:
    """2·θ(h/2) at the effective focal length, at most the field (inputs already checked)."""
    angle = 2.0 * _half_angle(size_mm / 2.0, effective_mm, projection, xp)
    limit = field_max_deg if field_max_deg is not None else (
        None if projection == "rectilinear" else FISHEYE_FIELD_DEG)
    return angle if limit is None else xp.minimum(angle, float(limit))


class FisheyeAngles(NamedTuple):
    """Horizontal, vertical and diagonal angles of view in degrees."""

    horizontal_deg: Any
    vertical_deg: Any
    diagonal_deg: Any


def fisheye_field_of_view(width_mm: Any, height_mm: Any, focal_length_mm: Any, projection: str,
                          magnification: Any = 0.0, pupil_magnification: Any = 1.0,
                          field_max_deg: float | None = None) -> FisheyeAngles:
    """Horizontal, vertical and diagonal angles of a ``width_mm`` × ``height_mm`` sensor under ``projection``.

    Examples
    --------
    >>> [round(a, 2) for a in fisheye_field_of_view(36.0, 24.0, 15.0, "equisolid")]
    [147.48, 94.31, 180.0]
    """
    require_positive("sensor_mm", width_mm)
    require_positive("sensor_mm", height_mm)
    _check_view(focal_length_mm, projection, magnification, pupil_magnification, field_max_deg)
    xp = ops(width_mm, height_mm, focal_length_mm, magnification, pupil_magnification)
    effective = focal_length_mm * (1.0 + magnification / pupil_magnification)
    diagonal = ops(width_mm, height_mm).hypot(width_mm, height_mm)
    return FisheyeAngles(*(_angle(size, effective, projection, field_max_deg, xp)
                           for size in (width_mm, height_mm, diagonal)))


def fisheye_field_size_mm(angle_deg: Any, lens_distance_mm: Any) -> Any:
    """The field at a subject u in front of the lens across an angle α: 2u·tan(α/2); unbounded from α = 180°.

    Examples
    --------
    >>> round(fisheye_field_size_mm(90.0, 1000.0), 6)
    2000.0
    >>> fisheye_field_size_mm(180.0, 1000.0)
    inf
    """
    require("angle_deg", angle_deg, (angle_deg > 0) & (angle_deg <= 360), "in (0, 360]")
    require("distance_mm", lens_distance_mm, lens_distance_mm > 0, "> 0")
    xp = ops(angle_deg, lens_distance_mm)
    with quiet(xp):
        size = 2.0 * lens_distance_mm * xp.tan(xp.radians(xp.minimum(angle_deg, 179.0) / 2.0))
    return xp.where(angle_deg >= 180.0, xp.inf, size)


def fill_magnification(focal_length_mm: Any, subject_size_mm: Any, fill: Any, frame_mm: Any, projection: str) -> Any:
    """The magnification m at the centre of the frame at which a centred flat subject S fills F of a frame dimension h.

    The subject's edges image at r = F·h/2 from the centre. Under ``projection``
    they lie at the angle θ the mapping gives for r at the focal length in
    effect f(1 + m) (as :func:`fisheye_angle_of_view_deg` takes it), so the
    subject is u = (S/2)/tan θ in front of the lens and m = f/(u − f), the thin
    lens's magnification at u: the fixed point of these, from m = 0 (focus at
    infinity). Rectilinear gives m = F·h/S (the fixed point at once).

    A subject whose edges would lie at 90° or beyond (a flat subject cannot
    fill that much of a fisheye's frame) or closer than f is a
    :class:`DomainError` on ``fill``.

    Examples
    --------
    A 1.8 m subject filling 0.8 of a 24 mm frame height with a 15 mm equisolid
    fisheye: r = 9.6 mm, at infinity focus θ = 2·asin(9.6/30) = 37.3° and
    u = 0.9 m/tan θ = 1.18 m; the focal length in effect there, f(1 + m),
    takes θ to 36.8° and the subject to 1.20 m:

    >>> m = fill_magnification(15.0, 1800.0, 0.8, 24.0, "equisolid")
    >>> round(15.0 * (1.0 + 1.0 / m))
    1201
    """
    check_projection(projection)
    require_positive("focal_length_mm", focal_length_mm)
    require_positive("subject_size_mm", subject_size_mm)
    require("fill", fill, (fill > 0) & (fill <= 1), "in (0, 1]")
    require_positive("frame_mm", frame_mm)
    xp = ops(focal_length_mm, subject_size_mm, fill, frame_mm)
    r, half = fill * frame_mm / 2.0, subject_size_mm / 2.0
    m = 0.0 * (focal_length_mm * r)
    for _ in range(200):
        theta = xp.radians(_half_angle(r, focal_length_mm * (1.0 + m), projection, xp))
        if not bool(xp.all(theta < math.pi / 2.0)):
            raise DomainError("fill", fill, "less than the frame a flat subject can fill: its edges would lie at "
                                            "90° or beyond")
        u = half / xp.tan(theta)
        if not bool(xp.all(u > focal_length_mm)):
            raise DomainError("fill", fill, "a fill that puts the subject beyond the front focal point")
        following = focal_length_mm / (u - focal_length_mm)
        if bool(xp.all(xp.fabs(following - m) <= 1e-15 * following)):
            return following
        m = following
    raise DomainError("fill", fill, "a fill whose magnification converges")
