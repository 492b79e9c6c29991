"""Angle of view and the field covered at a distance, with focus breathing and close-up focusing.

:func:`field_of_view` decides how the focus is set: at infinity, on a distance
given (unit focusing, the angles through f(1 + m/P)), or through the close-up
planner (:func:`camtool.plans.closeup.plan_focus`) for a magnification, an
extension, a teleconverter or a lens preset that focuses internally, whose
angles are then those of the focal length in effect at the focus.

The projection (docs/design.md §4, fisheyes) is the one asked for, else the lens
preset's ``projection``, else rectilinear. Under a fisheye mapping the angles
come from :mod:`camtool.geometry.projection` (at most the lens's field,
``field_max_deg``, 180° when the preset states none), and the field at the
subject spans 2u·tan(α/2) across each angle α, unbounded from 180°.
"""

from __future__ import annotations

from typing import Any

from camtool.core.record import NamedTuple

__all__ = ["FieldOfView", "field_of_view"]


class FieldOfView(NamedTuple):
    """The values of every row by key (scalars or arrays, one per scene); ``at_distance``: a focus was given."""

    values: dict[str, Any]
    at_distance: bool


def field_of_view(*, focal_length_mm: Any, sensor_width_mm: float, sensor_height_mm: float, crop_factor: float,
                  wanted: Any = None, by_magnification: bool = False, distance_from: str = "sensor",
                  pupil_magnification: float = 1.0, hiatus_mm: float = 0.0, lens_preset: Any = None,
                  extension_mm: float | None = None, teleconverter: float | None = None,
                  squeeze: float | None = None, projection: str | None = None) -> FieldOfView:
    """Angles of view, 35 mm equivalent focal length and, for a focus, the field covered at the subject.

    ``wanted`` is a focus distance in ``distance_from``'s plane (None: infinity)
    or, with ``by_magnification``, a magnification. The keys are those of
    ``camtool fov``; ``focal_length_mm`` is the lens's nominal one (× a
    teleconverter). An anamorphic ``squeeze`` S widens the horizontal angle to that of the de-squeezed width
    S·w (the diagonal angle and the 35 mm equivalent follow the de-squeezed frame); ``sensor_width_mm`` stays the
    sensor's.

    36 × 24 mm, 50 mm at infinity: horizontal 2·atan(18/50) = 39.598°:

    >>> v = field_of_view(focal_length_mm=50.0, sensor_width_mm=36.0, sensor_height_mm=24.0, crop_factor=1.0)
    >>> round(v.values["horizontal_deg"], 3), v.at_distance
    (39.598, False)

    An 8 mm equisolid-angle fisheye on full frame: a circle inside the frame, 180° every way:

    >>> v = field_of_view(focal_length_mm=8.0, sensor_width_mm=36.0, sensor_height_mm=24.0, crop_factor=1.0,
    ...                   projection="equisolid")
    >>> v.values["horizontal_deg"], v.values["projection"]
    (180.0, 'equisolid')
    """
    import math

    from camtool.geometry.fov import view
    from camtool.plans.cine import desqueezed_width_mm
    from camtool.plans.closeup import has_focus_model

    w, h = desqueezed_width_mm(sensor_width_mm, squeeze), sensor_height_mm
    crop = crop_factor * math.hypot(sensor_width_mm, h) / math.hypot(w, h)
    f, p, delta = focal_length_mm, pupil_magnification, hiatus_mm
    given = wanted is not None
    if by_magnification or extension_mm or teleconverter or (given and has_focus_model(lens_preset)):
        import numpy as np

        from camtool.plans.closeup import plan_focus

        count = np.broadcast(np.asarray(f, float), np.asarray(wanted if given else 0.0, float)).size
        ones = 1.0 if count == 1 else np.ones(count)  # no f-number here: one placeholder per row
        setting = plan_focus(lens=lens_preset, focal_length_mm=f, f_number=ones,
                             wanted=wanted if given else float("inf"), by_magnification=by_magnification,
                             distance_from=distance_from, hiatus_mm=delta, extension_mm=extension_mm,
                             teleconverter=teleconverter)
        pick = (lambda values: values[0]) if count == 1 else np.asarray
        # a lens preset with a published closest focus focuses internally: its focal length at m (docs/closeup.md §2)
        fe, m, u = pick(setting.focal_length_mm), pick(setting.magnification), pick(setting.lens_distance_mm)
        seen, f_used, lens_u = view(w, h, fe, u, "lens", p, delta, crop), fe, u
        s = pick(setting.sensor_distance_mm) if distance_from == "sensor" else u
        focal, given = f * (teleconverter or 1.0), True
    else:
        seen, f_used, lens_u = view(w, h, f, wanted, distance_from, p, delta, crop), f, None
        focal, s, m = f, wanted, seen.magnification
    angles = seen.angles
    mapping, field_max = lens_projection(projection, lens_preset)
    if mapping != "rectilinear":
        angles, width, height = _fisheye(w, h, f_used, seen.magnification, lens_u, p, mapping, field_max, given)
        seen = seen._replace(field_width_mm=width, field_height_mm=height)
    values = {"focal_length_mm": focal, "horizontal_deg": angles.horizontal_deg, "vertical_deg": angles.vertical_deg,
              "diagonal_deg": angles.diagonal_deg, "equivalent_focal_length_mm": seen.equivalent_focal_length_mm,
              "crop_factor": crop, "sensor_width_mm": sensor_width_mm, "sensor_height_mm": h, "projection": mapping}
    if squeeze is not None:
        values["squeeze"] = squeeze
    if given:
        values.update({"distance_mm": s, "magnification": m, "field_width_mm": seen.field_width_mm,
                       "field_height_mm": seen.field_height_mm, "distance_from": distance_from})
    return FieldOfView(values, given)


def lens_projection(projection: str | None, lens_preset: Any) -> tuple[str, float | None]:
    """(mapping, the lens's whole field or None): the one asked for, else the lens preset's, else rectilinear.

    >>> lens_projection(None, None)
    ('rectilinear', None)
    """
    from camtool.geometry.projection import check_projection

    preset = getattr(lens_preset, "projection", None)
    field = getattr(lens_preset, "field_max_deg", None)
    chosen = check_projection(projection or preset or "rectilinear")
    # a lens's stated field belongs to its own mapping; another asked for gets the default field
    return chosen, field if chosen == (preset or "rectilinear") else None


def _fisheye(w: float, h: float, f_in_effect: Any, m: Any, lens_u: Any, p: float, mapping: str,
             field_max: float | None, given: bool) -> tuple[Any, Any, Any]:
    """The angles under a fisheye mapping at the focal length in effect and magnification m, and the field at u."""
    from camtool.geometry.projection import fisheye_field_of_view, fisheye_field_size_mm

    # the image sits f(1 + m/P) behind the lens as for the rectilinear view
    angles = fisheye_field_of_view(w, h, f_in_effect, mapping, m, p, field_max)
    if not given:
        return angles, None, None
    import numpy as np

    if lens_u is None:  # focused on a distance: the thin lens's subject distance u = f(1 + 1/m)
        with np.errstate(divide="ignore", invalid="ignore"):
            lens_u = np.asarray(f_in_effect, float) * (1.0 + 1.0 / np.asarray(m, float))
    spans = np.asarray(lens_u, float)
    u: Any = spans if spans.ndim else float(spans)
    return (angles, fisheye_field_size_mm(angles.horizontal_deg, u),
            fisheye_field_size_mm(angles.vertical_deg, u))
