"""The kinds of preset and their frozen value classes: what a lookup builds, without the checks.

A preset is looked up by any spelling (:func:`normalize`) and built as one of
the :class:`camtool.core.record.Record` classes below from a record that
:mod:`camtool.presets.schema` checked (when its file was parsed, or when the
package was built, for the shipped presets). A lookup imports this module
only; the checks of every key, which only parsing a file needs, stay in
:mod:`camtool.presets.schema` (which re-exports these names).
"""

from __future__ import annotations

import math
import re
from collections.abc import Mapping
from typing import Any

from camtool.core.record import Record, field

KINDS = ("sensor", "camera", "lens", "prescription", "scene", "film")
"""The kinds of preset, in the order they are listed."""

SECTIONS = {"sensors": "sensor", "cameras": "camera", "lenses": "lens", "prescriptions": "prescription",
            "scenes": "scene", "films": "film"}
"""Top-level keys of a preset file and the kind of the entries under each."""

FULL_FRAME_DIAGONAL_MM = math.hypot(36.0, 24.0)

_PUNCTUATION = r"[^0-9a-z]+"  # compiled on first use (re's cache)


def normalize(name: str) -> str:
    """The lookup key of a name: lower case, punctuation and spaces dropped.

    >>> normalize("Full Frame"), normalize("full_frame"), normalize("FULL-FRAME")
    ('fullframe', 'fullframe', 'fullframe')
    >>> normalize('1/2.3"')
    '123'
    """
    return re.sub(_PUNCTUATION, "", name.casefold())


def kind_of(name: str) -> str:
    """The kind a user typed, singular or plural (``lenses`` → ``lens``); ValueError if unknown.

    >>> kind_of("Lenses"), kind_of("sensor")
    ('lens', 'sensor')
    """
    text = name.strip().lower()
    kind = SECTIONS.get(text, text)
    if kind not in KINDS:
        raise ValueError(f"unknown kind {name!r}; choose one of {', '.join(KINDS)}")
    return kind

REFERENCES = {
    "camera": {"sensor": "sensor", "lens": "lens"},
    "lens": {"prescription": "prescription", "sensor": "sensor"},
    "scene": {"camera": "camera", "sensor": "sensor", "lens": "lens"},
}
"""Keys whose value names another preset, and that preset's kind."""


# --- the value classes ----------------------------------------------------------------------


class Sensor(Record):
    """A sensor or film format; sizes in mm, width the long side.

    ``approximate`` marks a size that was derived (e.g. from a crop factor)
    rather than published; ``origin`` is the file the preset came from.

    >>> s = Sensor("full-frame", "Full frame", 36.0, 24.0)
    >>> round(s.diagonal_mm, 3), round(s.crop_factor, 3)
    (43.267, 1.0)
    """

    id: str
    name: str
    width_mm: float
    height_mm: float
    coc_mm: float | None = None
    aliases: tuple[str, ...] = ()
    category: str | None = None
    approximate: bool = False
    source: str | None = None
    notes: str | None = None
    origin: str | None = None
    tier: str | None = None

    kind = "sensor"

    @property
    def diagonal_mm(self) -> float:
        """Diagonal of the format in mm."""
        return math.hypot(self.width_mm, self.height_mm)

    @property
    def crop_factor(self) -> float:
        """Ratio of the 36 x 24 mm diagonal to this diagonal."""
        return FULL_FRAME_DIAGONAL_MM / self.diagonal_mm

    @property
    def aspect_ratio(self) -> float:
        """Width over height."""
        return self.width_mm / self.height_mm


class Camera(Record):
    """A camera body: its sensor (resolved to a :class:`Sensor`), pixel counts, mount and built-in lens.

    ``lens_id`` is the id of the lens preset of a camera whose lens is part of
    it (a compact's or a phone's main module), or None; the lens is looked up
    by id when it is used, so a lens whose own ``sensor`` names this camera
    does not make the two presets build each other.

    >>> body = Camera("x", "X", Sensor("s", "S", 36.0, 24.0), 6000, 4000)
    >>> round(body.pixel_pitch_mm * 1000, 3), body.megapixels
    (6.0, 24.0)
    """

    id: str
    name: str
    sensor: Sensor
    pixels_w: int | None = None
    pixels_h: int | None = None
    mount: str | None = None
    aliases: tuple[str, ...] = ()
    category: str | None = None
    approximate: bool = False
    source: str | None = None
    notes: str | None = None
    origin: str | None = None
    tier: str | None = None
    lens_id: str | None = None

    kind = "camera"

    @property
    def pixel_pitch_mm(self) -> float | None:
        """Sensor width over the pixel count across, in mm (None without pixel counts)."""
        return None if not self.pixels_w else self.sensor.width_mm / self.pixels_w

    @property
    def megapixels(self) -> float | None:
        """Pixel count in millions (None without pixel counts)."""
        return None if not (self.pixels_w and self.pixels_h) else self.pixels_w * self.pixels_h / 1e6


def optics_mapping(record: Mapping[str, Any]) -> dict[str, Any]:
    """The keys of a prescription record that :func:`camtool.optics.prescription.prescription_from_mapping` reads."""
    return {key: value for key, value in record.items() if not str(key).startswith("_")}


class Prescription(Record):
    """A lens prescription preset: its names and ``optics``, the validated lens.

    ``optics`` is the :class:`camtool.optics.prescription.Prescription` that
    :func:`camtool.optics.prescription.prescription_from_mapping` built from
    ``data`` (the mapping as written), the one validation of a prescription.
    """

    id: str
    name: str
    data: dict[str, Any] = field(compare=False, hash=False, repr=False)
    focal_length_mm: float | None = None
    f_number: float | None = None
    wavelength_nm: float | None = None
    aliases: tuple[str, ...] = ()
    source: str | None = None
    notes: str | None = None
    origin: str | None = None
    tier: str | None = None
    optics: Any = field(default=None, compare=False, hash=False, repr=False)

    kind = "prescription"

    @property
    def surfaces(self) -> list[dict[str, Any]]:
        """The surface mappings as written, from the object side."""
        return list(self.data["surfaces"])

    @property
    def stop_index(self) -> int:
        """0-based index of the aperture stop."""
        return int(self.optics.stop_index)


class Lens(Record):
    """A lens: focal length or range (mm), f-number range and close-focus data.

    ``f_number_min`` is the widest aperture (smallest f-number), at the short
    end for a variable-aperture zoom, whose widest f-number at the long end is
    ``f_number_min_tele``. ``min_focus_mm`` is measured from the sensor plane.
    ``prescription`` is the resolved, validated
    :class:`camtool.optics.prescription.Prescription` (or None).

    >>> zoom = Lens("z", "Z", 24.0, 70.0, 4.0, 22.0, f_number_min_tele=5.6)
    >>> zoom.is_zoom, zoom.widest_f_number(24.0), zoom.widest_f_number(70.0)
    (True, 4.0, 5.6)
    """

    id: str
    name: str
    focal_min_mm: float
    focal_max_mm: float
    f_number_min: float | None = None
    f_number_max: float | None = None
    f_number_min_tele: float | None = None
    min_focus_mm: float | None = None
    max_magnification: float | None = None
    pupil_magnification: float | None = None
    hiatus_mm: float | None = None
    prescription_id: str | None = None
    prescription: Any = field(default=None, compare=False, hash=False, repr=False)
    sensor_id: str | None = None
    mount: str | None = None
    aliases: tuple[str, ...] = ()
    category: str | None = None
    approximate: bool = False
    source: str | None = None
    notes: str | None = None
    origin: str | None = None
    tier: str | None = None
    min_magnification: float | None = None
    close_focus: tuple[tuple[float, float, float | None], ...] = ()  # (focal length, closest focus, magnification)
    t_number_min: float | None = None  # widest T-stop (cinema lenses)
    tilt_max_deg: float | None = None  # tilt range, ± degrees (tilt-shift lenses)
    f_number_max_tele: float | None = None  # smallest aperture at the long end, where it differs
    focus_at_max_magnification_mm: float | None = None  # a lens focusing farther at max than at min magnification
    projection: str | None = None  # a fisheye's mapping (camtool.geometry.projection); None: rectilinear
    members: tuple[Lens, ...] = field(default=(), compare=False, repr=False)  # a lens set's lenses
    field_max_deg: float | None = None  # a fisheye's whole field (its image circle), degrees
    squeeze: float | None = None  # an anamorphic lens's squeeze factor (docs/cine.md §5a); None: spherical

    kind = "lens"

    @property
    def transmittance(self) -> float | None:
        """τ = (N/T)² from the widest f-number and widest T-stop, when the preset has both (else None)."""
        if self.t_number_min is None or self.f_number_min is None or (self.is_zoom and self.f_number_min_tele):
            return None
        return (self.f_number_min / self.t_number_min) ** 2

    @property
    def is_zoom(self) -> bool:
        """True when the focal length can change (a lens set's members are primes: not a zoom)."""
        return self.focal_max_mm > self.focal_min_mm and not self.members

    def member(self, focal_length_mm: float) -> Lens | None:
        """The member of a lens set at ``focal_length_mm`` (None: no such member, or not a set).

        >>> one = Lens("s@25", "S 25mm", 25.0, 25.0, t_number_min=1.8)
        >>> Lens("s", "S", 25.0, 50.0, members=(one,)).member(25.0) is one
        True
        """
        return next((m for m in self.members if abs(m.focal_min_mm - focal_length_mm) <= 1e-6 * focal_length_mm),
                    None)

    @property
    def focal_length_mm(self) -> float | None:
        """The focal length of a prime; None for a zoom."""
        return None if self.is_zoom else self.focal_min_mm

    def smallest_f_number(self, focal_length_mm: float) -> float | None:
        """The largest f-number (smallest aperture) at a focal length within the range.

        A zoom whose smallest aperture closes down towards the long end
        (``f_number_max_tele``, Sony's 200-600: f/32 at 200 mm, f/36 at 600 mm)
        is interpolated linearly between the ends like :meth:`widest_f_number`.

        >>> Lens("z", "Z", 200.0, 600.0, 5.6, 32.0, 6.3, f_number_max_tele=36.0).smallest_f_number(600.0)
        36.0
        """
        return self._along_zoom(self.f_number_max, self.f_number_max_tele, focal_length_mm)

    def widest_f_number(self, focal_length_mm: float) -> float | None:
        """The smallest f-number at a focal length within the range.

        For a variable-aperture zoom the value is interpolated linearly between
        the two ends; real lenses step in thirds, so treat the middle as
        approximate.
        """
        return self._along_zoom(self.f_number_min, self.f_number_min_tele, focal_length_mm)

    def _along_zoom(self, short: float | None, long: float | None, focal_length_mm: float) -> float | None:
        """A figure given at both ends of a zoom, linear in focal length between them (clamped to the range)."""
        if short is None or long is None or not self.is_zoom:
            return short
        t = (focal_length_mm - self.focal_min_mm) / (self.focal_max_mm - self.focal_min_mm)
        t = min(1.0, max(0.0, t))
        return short + t * (long - short)


class Scene(Record):
    """A named shot: equipment references resolved to presets, distances in mm.

    Any field may be None; options given on the command line override a scene.
    ``sensor`` is the scene's own sensor, else the camera's.
    """

    id: str
    name: str
    camera: Camera | None = None
    sensor: Sensor | None = None
    lens: Lens | None = None
    focal_length_mm: float | None = None
    f_number: float | None = None
    distance_mm: float | None = None
    subject_size_mm: float | None = None
    background_mm: float | None = None
    coc_mm: float | None = None
    aliases: tuple[str, ...] = ()
    source: str | None = None
    notes: str | None = None
    origin: str | None = None
    tier: str | None = None
    magnification: float | None = None

    kind = "scene"


Preset = Sensor | Camera | Lens | Prescription | Scene


class Film(Record):
    """A film's reciprocity data from a preset file: an exponent ``p`` or a table ``points``.

    :meth:`reciprocity` gives the :class:`camtool.exposure.reciprocity.Film`
    the exposure calculator uses.

    >>> Film("my-film", "My film", p=1.4).reciprocity().p
    1.4
    """

    id: str
    name: str
    p: float | None = None
    threshold_s: float | None = None
    points: tuple[tuple[float, Any], ...] = ()
    valid_to_s: float | None = None
    aliases: tuple[str, ...] = ()
    source: str | None = None
    notes: str | None = None
    origin: str | None = None
    tier: str | None = None

    kind = "film"

    def reciprocity(self) -> Any:
        """This film as the exposure calculator's film (exponent or interpolated table)."""
        from camtool.exposure.reciprocity import film_from_entry

        entry: dict[str, Any] = {"id": self.id, "name": self.name, "aliases": list(self.aliases),
                                 "source": self.source or f"preset file {self.origin}"}
        if self.p is not None:
            entry["p"] = self.p
            entry["threshold_s"] = 1.0 if self.threshold_s is None else self.threshold_s
        if self.points:
            entry["points"] = [list(point) for point in self.points]
        if self.valid_to_s is not None:
            entry["valid_to_s"] = self.valid_to_s
        return film_from_entry(entry)
