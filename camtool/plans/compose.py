"""Perspective composition: where to stand with each focal length to frame a subject the same.

:func:`lenses` decides the lenses compared (the focal lengths given, else a
standard set; a teleconverter takes each lens as k·f at k·N) and
:func:`compose` every row: the magnification (given, or the subject's size
over the frame it fills), the camera distance, angles and field, the near and
far limits with an f-number, and how a background or foreground plane looks.
"""

from __future__ import annotations

from typing import Any

from camtool.core.errors import DomainError
from camtool.core.record import NamedTuple

__all__ = ["DEFAULT_FOCAL_LENGTHS_MM", "Lenses", "compose", "lenses"]

DEFAULT_FOCAL_LENGTHS_MM = [24.0, 35.0, 50.0, 85.0, 135.0, 200.0]


class Lenses(NamedTuple):
    """The focal lengths and f-numbers in effect (× a teleconverter), in mm."""

    focal_lengths_mm: list[float]
    f_numbers: list[float]


def lenses(*, focal_lengths_mm: list[float], f_numbers: list[float], teleconverter: float | None = None) -> Lenses:
    """The lenses compared: each as k·f at k·N with a teleconverter (docs/closeup.md §7), else the standard set.

    >>> lenses(focal_lengths_mm=[50.0], f_numbers=[4.0], teleconverter=2.0)
    Lenses(focal_lengths_mm=[100.0], f_numbers=[8.0])
    >>> lenses(focal_lengths_mm=[], f_numbers=[]).focal_lengths_mm[0]
    24.0
    """
    k = teleconverter or 1.0
    return Lenses([k * v for v in focal_lengths_mm] or list(DEFAULT_FOCAL_LENGTHS_MM), [k * v for v in f_numbers])


def compose(*, focal_length_mm: Any, sensor_width_mm: float, sensor_height_mm: float, reference_focal_length_mm: float,
            magnification: Any = None, subject_size_mm: float | None = None, fill: float | None = None,
            frame_mm: float | None = None, f_number: Any = None, coc_mm: Any = None, distance_from: str = "sensor",
            background_mm: float | None = None, foreground_mm: float | None = None, projection: str = "rectilinear",
            field_max_deg: float | None = None) -> dict[str, Any]:
    """Every row of ``camtool compose`` by key (scalars or arrays, one per scene).

    The magnification is ``magnification``, or ``subject_size_mm`` filling
    ``fill`` of ``frame_mm``. With ``f_number`` and ``coc_mm`` the near and
    far limits (``auto``): up to 1:1 from the plane asked, above it from the
    lens plane (where every magnification has its one distance) moved to the
    sensor plane by v = f(1 + m). A background ``background_mm`` behind or a
    foreground ``foreground_mm`` in front of the subject gets its scale
    against ``reference_focal_length_mm``, visible width and blur disc; a
    foreground beyond the front focal point is a :class:`DomainError` on
    ``foreground_mm``.

    Under a fisheye ``projection`` (at most ``field_max_deg``) the subject's
    edges lie where the mapping puts them
    (:func:`camtool.geometry.projection.fill_magnification`), the angles are
    the mapping's at that focus and the fields 2u·tan(α/2), as ``camtool fov``
    gives them; ``magnification`` and the blur are those at the centre of the
    frame (the thin lens at u), a plane's visible width is its field.

    50 mm at 1:10 from the lens: u = f(1 + 1/m) = 550 mm.

    >>> row = compose(focal_length_mm=50.0, magnification=0.1, sensor_width_mm=36.0, sensor_height_mm=24.0,
    ...               reference_focal_length_mm=50.0, distance_from="lens")
    >>> round(row["distance_mm"], 9)
    550.0
    """
    import numpy as np

    from camtool.dof.ladder import depth_of_field
    from camtool.geometry.compose import composition, fisheye_composition, magnification_for_fill, plane_view

    f, n, c = focal_length_mm, f_number, coc_mm
    values: dict[str, Any] = {"f_number": n, "coc_mm": c, "distance_from": distance_from,
                              "background_mm": background_mm, "foreground_mm": foreground_mm}
    fisheye = projection != "rectilinear"
    if magnification is not None:
        m = magnification
    elif fisheye:
        from camtool.geometry.projection import fill_magnification

        m = fill_magnification(f, subject_size_mm, fill, frame_mm, projection)
    else:
        m = magnification_for_fill(subject_size_mm, fill, frame_mm)
    shot = composition(f, m, sensor_width_mm, sensor_height_mm)
    if fisheye:
        shot = fisheye_composition(shot, sensor_width_mm, sensor_height_mm, projection, field_max_deg)
    distance = shot.distance_mm if distance_from == "sensor" else shot.lens_distance_mm
    values.update({key: getattr(shot, key) for key in ("focal_length_mm", "magnification", "horizontal_deg",
                                                        "vertical_deg", "field_width_mm", "field_height_mm")})
    values["distance_mm"] = distance
    if n is not None and float(np.max(m)) <= 1.0:
        limits = depth_of_field("auto", f, n, c, distance, distance_from).limits
        values.update({"near_mm": limits.near_mm, "far_mm": limits.far_mm})
    elif n is not None:
        limits = depth_of_field("auto", f, n, c, shot.lens_distance_mm, "lens").limits
        shift = 0.0 if distance_from == "lens" else distance - shot.lens_distance_mm
        values.update({"near_mm": limits.near_mm + shift, "far_mm": limits.far_mm + shift})
    for name, given, offset in (("background", background_mm, background_mm),
                                ("foreground", foreground_mm, None if foreground_mm is None else -foreground_mm)):
        if offset is None:
            continue
        try:
            view = plane_view(f, n, m, sensor_width_mm, offset, reference_focal_length_mm=reference_focal_length_mm)
        except DomainError as error:
            if error.param != "offset_mm":
                raise
            raise DomainError(f"{name}_mm", given, "less than the distance from the subject to the lens's front "
                              "focal point") from None
        visible = view.visible_width_mm
        if fisheye:  # a fisheye's visible width at the plane is its field there
            from camtool.geometry.projection import fisheye_field_size_mm

            visible = fisheye_field_size_mm(shot.horizontal_deg, shot.lens_distance_mm + offset)
        values.update({f"{name}_scale": view.scale, f"{name}_width_mm": visible,
                       f"{name}_blur_mm": view.blur_mm, f"{name}_blur_pct": view.blur_pct})
    return values
