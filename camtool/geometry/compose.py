"""Perspective composition: keep the subject the same size in the frame while focal length and distance change.

A subject of size S that fills a fraction F of a frame dimension h is imaged
at magnification m = F·h/S. Every focal length f reaches that magnification
at its own distance (thin lens, from the lens)

    s = f(1 + 1/m),   image distance v = f(1 + m),   from the sensor D = s + v,

so the subject stays put in the frame while the background changes: its
objects grow with f (perspective), less of it is visible, and its blur disc
grows in proportion to f (for a distant background, b → f·m/N).

Offsets of a background or foreground plane are measured from the subject
(positive behind it, negative in front of it), so they do not depend on the
distance reference plane. Lengths in millimetres, angles in degrees;
scalars in, floats out; arrays in, arrays out (broadcast together).

The near and far limits of the sharp zone for a composition row come from
the depth-of-field models (:mod:`camtool.dof.closed`) at ``distance_mm``; they are
not repeated here.
"""

from __future__ import annotations

from typing import Any

from camtool.core.arrays import ops, quiet
from camtool.core.domain import check
from camtool.core.errors import require, require_positive
from camtool.core.record import NamedTuple
from camtool.geometry.fov import angle_of_view_deg, field_size_mm


class Composition(NamedTuple):
    """Where to stand with a focal length so the subject fills the frame as asked.

    ``distance_mm`` is measured from the sensor plane (thin lens: s + v),
    ``lens_distance_mm`` from the lens; angles of view are at that focus
    (image distance v = f(1 + m)); the field is the size of the subject plane
    the frame shows.
    """

    focal_length_mm: Any
    magnification: Any
    distance_mm: Any
    lens_distance_mm: Any
    image_distance_mm: Any
    horizontal_deg: Any
    vertical_deg: Any
    field_width_mm: Any
    field_height_mm: Any


class PlaneView(NamedTuple):
    """How a background (or foreground) plane looks from one composition.

    ``scale`` is the size of the plane's objects on the sensor relative to a
    reference focal length (1 for the reference itself); ``visible_width_mm``
    is how much of the plane the frame width shows; ``blur_mm`` is the blur
    disc diameter of a point on the plane on the sensor and ``blur_pct`` that
    disc as a percentage of the frame width.
    """

    scale: Any
    visible_width_mm: Any
    blur_mm: Any
    blur_pct: Any


def magnification_for_fill(subject_size_mm: Any, fill: Any, frame_mm: Any) -> Any:
    """Magnification at which a subject of size S spans a fraction F of a frame dimension h: m = F·h/S.

    Parameters
    ----------
    subject_size_mm : float or array, S > 0 mm
    fill : float or array, F > 0 (1 = the whole frame height or width)
    frame_mm : float or array, h > 0 mm (the sensor dimension along the same axis)

    Examples
    --------
    >>> magnification_for_fill(1800.0, 0.8, 24.0)
    0.010666666666666668
    """
    require_positive("subject_size_mm", subject_size_mm)
    require_positive("fill", fill, unit="")
    require_positive("sensor_mm", frame_mm)
    return fill * frame_mm / subject_size_mm


def _check_lens(focal_length_mm: Any, magnification: Any) -> None:
    require_positive("focal_length_mm", focal_length_mm)
    require_positive("magnification", magnification, unit="")


def lens_distance_mm(focal_length_mm: Any, magnification: Any) -> Any:
    """Subject distance from the lens in mm for magnification m: s = f(1 + 1/m) (exact thin lens).

    From 1/s + 1/v = 1/f and m = v/s.

    Parameters
    ----------
    focal_length_mm : float or array, f > 0 mm
    magnification : float or array, m > 0

    References
    ----------
    Hecht, *Optics*, §5.2 (Gaussian lens formula and lateral magnification).

    Examples
    --------
    >>> lens_distance_mm(50.0, 0.01)
    5050.0
    """
    _check_lens(focal_length_mm, magnification)
    return focal_length_mm * (1.0 + 1.0 / magnification)


def sensor_distance_mm(focal_length_mm: Any, magnification: Any, hiatus_mm: Any = 0.0) -> Any:
    """Subject distance from the sensor plane in mm for magnification m: D = f(1 + 1/m) + f(1 + m) + δ.

    The object distance u = f(1 + 1/m) plus the image distance v = f(1 + m)
    (plus the hiatus δ between the principal planes of a thick lens). At
    m = 1 this is the closest a unit-focusing lens gets, 4f + δ.

    Examples
    --------
    >>> sensor_distance_mm(50.0, 0.01)
    5100.5
    >>> sensor_distance_mm(50.0, 1.0)
    200.0
    """
    _check_lens(focal_length_mm, magnification)
    return focal_length_mm * (2.0 + magnification + 1.0 / magnification) + hiatus_mm


def composition(focal_length_mm: Any, magnification: Any, width_mm: Any, height_mm: Any) -> Composition:
    """Camera distance, angles of view and field for focal length f at magnification m on a w × h frame.

    Parameters
    ----------
    focal_length_mm : float or array, f > 0 mm
    magnification : float or array, m > 0
    width_mm, height_mm : float or array, the frame (sensor) size, > 0 mm

    References
    ----------
    Hecht, *Optics*, §5.2; Wikipedia, "Angle of view" (with image distance f(1 + m)).

    Examples
    --------
    >>> c = composition(85.0, 0.02, 36.0, 24.0)
    >>> round(c.distance_mm), round(c.horizontal_deg, 2), round(c.field_width_mm)
    (4422, 23.46, 1800)
    """
    _check_lens(focal_length_mm, magnification)
    return Composition(
        focal_length_mm,
        magnification,
        sensor_distance_mm(focal_length_mm, magnification),
        lens_distance_mm(focal_length_mm, magnification),
        focal_length_mm * (1.0 + magnification),
        angle_of_view_deg(width_mm, focal_length_mm, magnification),
        angle_of_view_deg(height_mm, focal_length_mm, magnification),
        field_size_mm(width_mm, magnification),
        field_size_mm(height_mm, magnification),
    )


def fisheye_composition(shot: Composition, width_mm: Any, height_mm: Any, projection: str,
                        field_max_deg: float | None = None) -> Composition:
    """``shot`` through a lens of mapping ``projection`` (at most ``field_max_deg``): the angles of
    :func:`camtool.geometry.projection.fisheye_field_of_view` at its magnification, and the fields 2u·tan(α/2) at its
    lens distance (unbounded from 180°); its distances and magnification stay the thin lens's, those at the centre.

    Examples
    --------
    A 15 mm equisolid fisheye at m = 0.0125 on full frame: 4·asin(18/(2·15·1.0125)) = 145.4° across, at
    u = 15·(1 + 1/0.0125) = 1215 mm a field of 2u·tan(72.7°) = 7.79 m:

    >>> c = fisheye_composition(composition(15.0, 0.0125, 36.0, 24.0), 36.0, 24.0, "equisolid")
    >>> round(c.horizontal_deg, 1), round(c.field_width_mm)
    (145.4, 7793)
    """
    from camtool.geometry.projection import fisheye_field_of_view, fisheye_field_size_mm

    angles = fisheye_field_of_view(width_mm, height_mm, shot.focal_length_mm, projection, shot.magnification, 1.0,
                                   field_max_deg)
    return shot._replace(horizontal_deg=angles.horizontal_deg, vertical_deg=angles.vertical_deg,
                         field_width_mm=fisheye_field_size_mm(angles.horizontal_deg, shot.lens_distance_mm),
                         field_height_mm=fisheye_field_size_mm(angles.vertical_deg, shot.lens_distance_mm))


def _check_offset(focal_length_mm: Any, magnification: Any, offset_mm: Any) -> Any:
    """Return s (from the lens) after checking that the plane lies in front of the lens."""
    s = lens_distance_mm(focal_length_mm, magnification)
    require("offset_mm", offset_mm, offset_mm + s > focal_length_mm,
            "behind the subject (> 0), or in front of it but farther from the lens than f",
            "a foreground plane cannot be at or behind the front focal point")
    return s


def plane_magnification(focal_length_mm: Any, magnification: Any, offset_mm: Any) -> Any:
    """Image scale on the sensor of a plane ``offset_mm`` behind the subject: v/(s + x).

    The chief ray through the lens centre meets the sensor (at v = f(1 + m))
    at this scale whether or not the plane is in focus. Zero for a plane at
    infinity.

    Examples
    --------
    >>> plane_magnification(50.0, 1.0, 0.0)
    1.0
    >>> round(plane_magnification(50.0, 0.01, 5050.0), 6)
    0.005
    """
    s = _check_offset(focal_length_mm, magnification, offset_mm)
    return focal_length_mm * (1.0 + magnification) / (s + offset_mm)


def defocus_blur_mm(focal_length_mm: Any, f_number: Any, magnification: Any, offset_mm: Any) -> Any:
    """Blur disc diameter in mm on the sensor of a point ``offset_mm`` behind (+) or in front of (−) the subject.

    b = (f·m/N) · x_d/(s + x_d) for a background x_d behind the subject and
    b = (f·m/N) · x_d/(s − x_d) for a foreground x_d in front of it, with s
    the subject distance from the lens; both are f·m·|x|/(N·(s + x)) for a
    signed offset x. A background at infinity gives b = f·m/N.

    Parameters
    ----------
    focal_length_mm : float or array, f > 0 mm
    f_number : float or array, 0.7 to 1024
    magnification : float or array, subject magnification m > 0
    offset_mm : float or array, x; −s + f < x ≤ ∞ mm

    References
    ----------
    Wikipedia, "Depth of field", section "Foreground and background blur".

    Examples
    --------
    >>> defocus_blur_mm(50.0, 2.0, 0.01, float("inf"))
    0.25
    >>> round(defocus_blur_mm(100.0, 2.0, 0.02, 5100.0), 6)
    0.5
    """
    check("f_number", f_number)
    s = _check_offset(focal_length_mm, magnification, offset_mm)
    xp = ops(focal_length_mm, f_number, magnification, offset_mm)
    with quiet(xp):
        # x/(s + x) written 1/(1 + s/x) would fail at x = 0; inf/inf is masked instead.
        ratio = xp.where(xp.isinf(offset_mm), 1.0, xp.fabs(offset_mm) / (s + offset_mm))
    return focal_length_mm * magnification / f_number * ratio


def plane_view(
    focal_length_mm: Any,
    f_number: Any,
    magnification: Any,
    width_mm: Any,
    offset_mm: Any,
    reference_focal_length_mm: Any = None,
) -> PlaneView:
    """Perspective, visible width and blur of a plane ``offset_mm`` from the subject, for one composition.

    ``scale`` compares the plane's image size with that from a reference focal
    length at the same magnification (default: ``focal_length_mm`` itself, so
    scale 1): v·(s_ref + x) / (v_ref·(s + x)), which tends to f/f_ref for a
    distant plane — the telephoto "compression".

    Parameters
    ----------
    focal_length_mm : float or array, f > 0 mm
    f_number : float or array, 0.7 to 1024
    magnification : float or array, subject magnification m > 0
    width_mm : float or array, frame width > 0 mm
    offset_mm : float or array, positive behind the subject, negative in front; ``inf`` allowed
    reference_focal_length_mm : float or None

    Examples
    --------
    >>> v = plane_view(100.0, 2.0, 0.02, 36.0, 5100.0, reference_focal_length_mm=50.0)
    >>> round(v.scale, 4), round(v.visible_width_mm), round(v.blur_mm, 3), round(v.blur_pct, 3)
    (1.5, 3600, 0.5, 1.389)
    """
    if reference_focal_length_mm is None:
        reference_focal_length_mm = focal_length_mm
    require_positive("sensor_mm", width_mm)
    s = _check_offset(focal_length_mm, magnification, offset_mm)
    s_ref = _check_offset(reference_focal_length_mm, magnification, offset_mm)
    v = focal_length_mm * (1.0 + magnification)
    v_ref = reference_focal_length_mm * (1.0 + magnification)
    xp = ops(s, s_ref, offset_mm)
    with quiet(xp):
        # Written without dividing by the plane magnification, which is 0 at infinity.
        farther = xp.where(xp.isinf(offset_mm), 1.0, (s_ref + offset_mm) / (s + offset_mm))
    scale = v / v_ref * farther
    visible = width_mm * (s + offset_mm) / v
    blur = defocus_blur_mm(focal_length_mm, f_number, magnification, offset_mm)
    return PlaneView(scale, visible, blur, 100.0 * blur / width_mm)
