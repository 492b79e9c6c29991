"""A photo's metadata turned into a scene and its answers: every decision ``camtool exif`` makes.

Which files a list of paths names (:func:`photo_files`, :func:`names_from_lines`),
and for each file's :class:`camtool.exif.reader.Reading` (:func:`photo_answer`):
which value wins (what the caller gives over what the file says), the lens
(the caller's preset, else a preset whose name matches the file's lens name),
the sensor (the caller's, else the focal-plane resolution, else the 35 mm
equivalent focal length, else a camera preset matching Make and Model), the CoC
(the caller's, else the rule applied to that sensor, the pixel pitch for a
``px:K`` rule from the image size), the focus distance (the caller's, else the
maker note or SubjectDistance, with the maker's bracket), and the depth of
field, angle of view and exposure value computed from them. A value the file
lacks is None and named as missing; a value it carries outside the range of
the option it stands for is None and named as unusable (the file's problem,
not the caller's error); the rest of the row is still computed.

The reader (:mod:`camtool.exif.reader`, python-exiv2) is the caller's: this
module never opens a photo, and imports the EXIF package only when a function
runs.
"""

from __future__ import annotations

import math
import os
from collections.abc import Callable, Iterable, Mapping, Sequence
from typing import TYPE_CHECKING, Any

from camtool.core.errors import braced
from camtool.core.record import NamedTuple
from camtool.core.text import printable

if TYPE_CHECKING:
    from camtool.dof.ladder import LensData
    from camtool.exif.reader import Reading
    from camtool.exif.sensor import SensorSize

__all__ = ["BRACKET_KEYS", "CONVENTIONS", "IMAGE_SUFFIXES", "KEYS", "PhotoAnswer", "PhotoFiles", "PresetIndex", "Problem",
           "check_coc_rule", "names_from_lines", "photo_answer", "photo_files", "unreadable_answer"]

BRACKET_KEYS = ["near_min_mm", "near_max_mm", "far_min_mm", "far_max_mm"]
KEYS = [
    "file", "camera", "lens", "focal_length_mm", "f_number", "shutter_s", "iso", "crop_factor",
    "sensor_width_mm", "sensor_height_mm", "coc_mm", "focus_distance_mm", "focus_distance_min_mm",
    "focus_distance_max_mm", "near_mm", "far_mm", "total_mm", "hyperfocal_mm", *BRACKET_KEYS,
    "horizontal_deg", "vertical_deg", "diagonal_deg", "field_width_mm", "ev", "ev100", "model", "distance_from",
    "convention", "focal_length_source", "f_number_source", "shutter_source", "iso_source", "sensor_source",
    "coc_source", "focus_distance_source", "lens_source", "warnings",
]
"""Every key of a photo's row (JSON and CSV), in order."""
IMAGE_SUFFIXES = frozenset({
    ".jpg", ".jpeg", ".jpe", ".tif", ".tiff", ".heic", ".heif", ".avif", ".png", ".webp", ".jxl", ".dng",
    ".cr2", ".cr3", ".crw", ".nef", ".nrw", ".arw", ".srf", ".sr2", ".orf", ".rw2", ".raf", ".pef", ".srw",
    ".x3f", ".mrw", ".3fr", ".erf", ".kdc", ".mef", ".mos", ".iiq", ".rwl", ".exv",
})
"""The file name suffixes (lower case) a directory walk reads: images and raw files."""
RAW_SUFFIXES = IMAGE_SUFFIXES - {".jpg", ".jpeg", ".jpe", ".tif", ".tiff", ".heic", ".heif", ".avif", ".png", ".webp",
                                 ".jxl", ".exv"}
"""The raw files among them (a DNG too): their pixel size as libexiv2 reports it may be a preview's."""


class PhotoFiles(NamedTuple):
    """The files to read, in the order given, and (path, reason) for each path that names none."""

    files: tuple[str, ...]
    failed: tuple[tuple[str, str], ...]


def names_from_lines(lines: Iterable[bytes]) -> list[str]:
    r"""Paths listed one a line (bytes, as from standard input), decoded as the file system does.

    A name that is not UTF-8 keeps its bytes (as surrogates); a CRLF line end
    is a line end; blank lines are skipped.

    >>> names_from_lines([b"a.jpg\r\n", b"\n", b"dir/b.jpg"])
    ['a.jpg', 'dir/b.jpg']
    """
    return [os.fsdecode(line.rstrip(b"\n").removesuffix(b"\r")) for line in lines if line.strip()]


def photo_files(names: Sequence[str], *, recursive: bool = False) -> PhotoFiles:
    """The files ``names`` stand for: a file as itself, a directory (with ``recursive``) its images.

    A directory is walked in sorted order (subdirectories too), keeping the
    files whose suffix is in :data:`IMAGE_SUFFIXES`; without ``recursive``
    it is a failed path, as is a directory the walk cannot read. Whether a
    file can be read is the reader's question.
    """
    files: list[str] = []
    failed: list[tuple[str, str]] = []
    for name in names:
        if not os.path.isdir(name):
            files.append(name)
            continue
        if not recursive:
            failed.append((name, "is a directory (give --recursive to read the images in it)"))
            continue

        def unreadable(error: OSError, top: str = name) -> None:
            failed.append((error.filename or top, f"cannot be read: {error.strerror or error}"))

        for root, dirs, entries in os.walk(name, onerror=unreadable):
            dirs.sort()
            files.extend(os.path.join(root, e) for e in sorted(entries)
                         if os.path.splitext(e)[1].lower() in IMAGE_SUFFIXES)
    return PhotoFiles(tuple(files), tuple(failed))


class Problem(NamedTuple):
    """One thing wrong with a file's answer: ``template`` names in braces the parameters that would supply it.

    :meth:`text` fills them in (with the caller's names for them, e.g. its
    options); a template without ``names`` is the text itself.
    """

    template: str
    names: tuple[str, ...] = ()

    def text(self, shown: Mapping[str, str] | None = None) -> str:
        if not self.names:
            return self.template
        return self.template.format(**{n: (shown or {}).get(n, n) for n in self.names})


class PhotoAnswer(NamedTuple):
    """One file's row (every key of :data:`KEYS`), its unusable values, what it lacks, and what was assumed.

    ``unusable`` come first on the file's one message line, then what is
    missing, then each warning (``warning: ...``); a file with an unusable
    value (or that cannot be read) is not ``ok``; warnings say where an
    answer rests on a guess (a resized file, an inferred sensor) and do not
    make it fail.
    """

    values: dict[str, Any]
    unusable: tuple[Problem, ...]
    missing: tuple[Problem, ...]
    warnings: tuple[str, ...] = ()

    @property
    def ok(self) -> bool:
        return not self.unusable

    def message(self, shown: Mapping[str, str] | None = None) -> str:
        """The file's problems on one line ("" when none), parameters shown as ``shown`` names them."""
        return "; ".join([*(p.text(shown) for p in (*self.unusable, *self.missing)),
                          *(f"warning: {w}" for w in self.warnings)])


def unreadable_answer(path: str, reason: str) -> PhotoAnswer:
    """The answer for a path that cannot be read: a row of nulls but its name, and why."""
    return PhotoAnswer(dict.fromkeys(KEYS) | {"file": printable(path)}, (Problem(reason),), ())


class PresetIndex:
    """Presets of a kind by normalised name, built on first use from the database ``load()`` returns, then kept."""

    def __init__(self, load: Callable[[], Any]) -> None:
        self._load = load
        self._kinds: dict[str, dict[str, list[Any]]] = {}

    def __call__(self, kind: str) -> dict[str, list[Any]]:
        if kind not in self._kinds:
            from camtool.exif.sensor import name_index

            self._kinds[kind] = name_index(self._load().all(kind))
        return self._kinds[kind]


def check_coc_rule(rule: str | None) -> None:
    """Refuse a CoC rule that does not parse (None is the default rule), whatever the sensor.

    Raises ``camtool.core.units.UnitError``. The rule is tried on a full-frame
    sensor with a 5 µm pitch, so a ``px:K`` rule is not refused for want of a
    pitch here: that is a file's problem.

    >>> check_coc_rule("d/1440"); check_coc_rule("px:2")
    """
    from camtool.geometry.coc import DEFAULT_RULE, coc_from_rule

    coc_from_rule(rule or DEFAULT_RULE, 36.0, 24.0, 0.005)


def photo_answer(reading: Reading, *, path: str, distance_mm: float | None = None,
                 sensor_mm: tuple[float, float] | None = None, coc_mm: float | None = None,
                 coc_rule: str | None = None, pixel_pitch_mm: float | None = None, distance_from: str = "sensor",
                 model: str = "auto", tolerance: float = 0.01, diffraction: bool = False,
                 wavelength_nm: float = 550.0, pupil_magnification: float | None = None,
                 hiatus_mm: float | None = None, prescription: Any = None, lens_preset: Any = None,
                 presets: PresetIndex | None = None, given_as: Mapping[str, str] | None = None,
                 convention: str = "camtool") -> PhotoAnswer:
    """The row of one photo: what its metadata and the caller's values say, and the answers they give.

    What the caller gives wins over what the file says: ``lens_preset`` (else
    a preset from ``presets`` matching the file's lens name; a prime's focal
    length stands in for a missing FocalLength), ``sensor_mm`` (width, height;
    else the file's focal plane, 35 mm equivalent, or a camera preset matching
    Make and Model), ``coc_mm`` (else ``coc_rule``, d/1500 by default, on that
    sensor, the pitch for ``px:K`` from ``pixel_pitch_mm`` else the sensor's
    width over the image's long side), ``distance_mm`` (else the recorded focus
    and the maker's bracket); ``pupil_magnification``, ``hiatus_mm`` and
    ``prescription`` over the lens preset's. A number outside the range of the
    option it stands for is unusable, as the reader's own problems are. Each
    ``*_source`` key names the tag a value came from, or ``given_as[name]``
    for a value given as parameter ``name`` (``lens_preset``, ``sensor_mm``,
    ``coc_mm``, ``distance_mm``; the name itself by default).

    ``convention="exiftool"`` answers as ExifTool 12.57's composite tags do
    (:func:`exiftool_answer`'s rules: its ScaleFactor35efl and the 3:2
    frame of that diagonal, CoC d/1440, H = f²/(N·c), the thin-lens DOF from
    the lens at its choice of distance, its FOV); ``model``,
    ``distance_from``, ``coc_rule`` and ``pixel_pitch_mm`` are then not
    used. Either way ``warnings`` say what had to be assumed.

    A file's CoC by ExifTool's rule d/1440 (its Composite:CircleOfConfusion)
    on a full-frame sensor is √(36² + 24²)/1440 = 0.03005 mm:

    >>> from camtool.exif.reader import Reading
    >>> scene = Reading(focal_length_mm=50.0, f_number=8.0, plane_width_mm=36.0, plane_height_mm=24.0,
    ...                 focus_distance_mm=3000.0, sources={"sensor": "focal plane"})
    >>> answer = photo_answer(scene, path="a.jpg", coc_rule="d/1440", model="thin")
    >>> round(answer.values["coc_mm"], 5), answer.values["sensor_source"], answer.ok
    (0.03005, 'focal plane', True)
    """
    from camtool.exif.sensor import match_preset, normalise

    given = dict(given_as or {})
    sources = reading.sources
    row: dict[str, Any] = dict.fromkeys(KEYS)
    row["file"] = printable(path)
    camera = " ".join(p for p in (reading.make, reading.model) if p) or None
    if reading.make and reading.model and reading.model.lower().startswith(reading.make.split()[0].lower()):
        camera = reading.model
    row["camera"] = camera
    named = {field for field, _ in reading.problems}  # a value named as unusable is not named again as missing
    unusable = [Problem(message) for _, message in reading.problems]
    missing: list[Problem] = []
    f, n = reading.focal_length_mm, reading.f_number
    row["focal_length_source"] = sources.get("focal_length_mm")
    row["f_number_source"] = sources.get("f_number")
    row["shutter_source"] = sources.get("shutter_s")
    row["iso_source"] = sources.get("iso")

    row["lens"], row["lens_source"] = reading.lens, sources.get("lens")
    if lens_preset is not None:
        row["lens"], row["lens_source"] = lens_preset.name, given.get("lens_preset", "lens_preset")
    elif reading.lens and presets is not None:
        found = match_preset(presets("lens"), [normalise(reading.lens)])
        if found is not None:
            lens_preset = found
            row["lens_source"] = f"{sources.get('lens')} = preset {found.id}"
    if f is None and lens_preset is not None and not lens_preset.is_zoom:
        f, row["focal_length_source"] = lens_preset.focal_min_mm, f"lens preset {lens_preset.id}"
    row["focal_length_mm"], row["f_number"] = f, n
    row["shutter_s"], row["iso"] = reading.shutter_s, reading.iso

    if convention not in CONVENTIONS:
        raise ValueError(f"unknown convention {convention!r}; choose one of {', '.join(CONVENTIONS)}")
    exiftool = convention == "exiftool"
    row["convention"] = convention
    warnings: list[str] = []
    given_sensor = given.get("sensor_mm", "sensor_mm")
    if exiftool:
        size = _exiftool_frame(reading, f, sensor_mm, given_sensor)
        coc_rule, pixel_pitch_mm, model, distance_from = "d/1440", None, "thin", "lens"
    else:
        size = _sensor(reading, f, sensor_mm, given_sensor, presets, unusable, named, warnings)
    if size is None:
        if "sensor" not in named:
            missing.append(Problem("no sensor size (FocalPlaneResolution, a maker note's sensor data, "
                                   "FocalLengthIn35mmFilm or a camera preset): give {sensor} or {crop}",
                                   ("sensor", "crop")))
    else:
        row["sensor_width_mm"], row["sensor_height_mm"] = size.width_mm, size.height_mm
        row["crop_factor"], row["sensor_source"] = size.crop_factor, size.source
    if sensor_mm is None:
        warnings.extend(_size_warnings(reading, size, os.path.splitext(path)[1].lower() in RAW_SUFFIXES))

    c = _coc(row, coc_mm, given.get("coc_mm", "coc_mm"), coc_rule, pixel_pitch_mm, size, reading, missing, unusable)
    if f is None and "focal_length_mm" not in named:
        missing.append(Problem("no focal length (FocalLength)"))
    if n is None and "f_number" not in named:
        missing.append(Problem("no f-number (FNumber, ApertureValue)"))

    s, s_min, s_max = reading.focus_distance_mm, reading.focus_distance_min_mm, reading.focus_distance_max_mm
    row["focus_distance_source"] = sources.get("focus_distance")
    s_view = s
    if exiftool:
        s, s_view, row["focus_distance_source"] = _exiftool_distances(reading)
        s_min = s_max = None
    if distance_mm is not None:
        s, s_min, s_max, row["focus_distance_source"] = distance_mm, None, None, given.get("distance_mm", "distance_mm")
        s_view = s
    if s is None and "focus_distance" not in named:
        missing.append(Problem("no focus distance (maker note or SubjectDistance): give {distance_mm}",
                               ("distance_mm",)))
    row["focus_distance_mm"], row["focus_distance_min_mm"], row["focus_distance_max_mm"] = s, s_min, s_max
    row["distance_from"] = distance_from

    lens = None if exiftool else _lens_data(pupil_magnification, hiatus_mm, prescription, lens_preset)
    if f is not None and n is not None and c is not None and s is not None:
        options = (model, distance_from, diffraction and not exiftool, wavelength_nm, tolerance)
        _depth(row, f, n, c, s, s_min, s_max, lens, options, missing)
    if f is not None and n is not None and c is not None:
        _hyperfocal(row, f, n, c, model, distance_from, lens, exiftool, missing)
    if f is not None and size is not None:
        _angles(row, f, s_view, size, lens, distance_from, missing, exiftool, lens_preset)
    iso = reading.iso
    if exiftool and reading.iso_speed_ratings is not None:  # ExifTool's ISO is the 16-bit tag, 65535 included
        iso, row["iso"], row["iso_source"] = reading.iso_speed_ratings, reading.iso_speed_ratings, \
            "Photo.ISOSpeedRatings (ExifTool's ISO)"
    _exposure(row, n, reading.shutter_s, iso, missing, named)
    row["warnings"] = "; ".join(warnings) or None
    return PhotoAnswer(row, tuple(unusable), tuple(missing), tuple(warnings))


CONVENTIONS = ("camtool", "exiftool")
"""The conventions of :func:`photo_answer`: camtool's own, and ExifTool 12.57's composite tags."""


def _exiftool_frame(reading: Reading, f: float | None, given: tuple[float, float] | None,
                    given_source: str) -> SensorSize | None:
    """ExifTool's frame: the 3:2 frame 36/k × 24/k of its ScaleFactor35efl k (the sensor given wins).

    ExifTool's CircleOfConfusion is that frame's diagonal over 1440 and its
    FOV the angle across its 36/k mm width, so the frame carries both.
    """
    from camtool.exif.reader import outside
    from camtool.exif.sensor import SensorSize, exiftool_scale_factor, from_plane

    if given is not None:
        return from_plane(given[0], given[1], given_source)
    scale = exiftool_scale_factor(
        focal_length_mm=f, focal_length_35mm=reading.focal_length_35mm, digital_zoom=reading.digital_zoom,
        diagonal_mm=reading.plane_diagonal_mm, canon_sensor_mm=reading.canon_sensor_mm,
        plane_size_mm=reading.maker_plane_mm, px_per_mm=reading.plane_px_per_mm, sizes=reading.sizes)
    if scale is None or outside("crop", scale.factor) is not None:
        return None
    return SensorSize(36.0 / scale.factor, 24.0 / scale.factor, scale.factor,
                      f"ExifTool ScaleFactor35efl: {scale.source}")


def _exiftool_distances(reading: Reading) -> tuple[float | None, float | None, str | None]:
    """The focus distance of ExifTool's DOF, that of its FOV, and where the first came from.

    DOF: a FocusDistance tag (Nikon, Olympus, Minolta; 0 is infinity), else
    SubjectDistance or ObjectDistance, else the middle of Canon's
    FocusDistanceUpper/Lower in ExifTool's metres (raw/100, so Canon's
    infinity counts as 655.35 m and an unrecorded lower end as 0). FOV: the
    FocusDistance tag only (ExifTool's Composite:DOF and FOV definitions).
    """
    tag = reading.focus_tag_mm
    if tag is not None:
        return tag, tag, "FocusDistance (ExifTool's DOF and FOV)"
    for value, name in ((reading.subject_distance_mm, "SubjectDistance"), (reading.object_distance_mm,
                                                                         "ObjectDistance")):
        if value:
            return value, None, f"{name} (ExifTool's DOF)"
    if reading.bracket_m is not None:
        upper, lower = reading.bracket_m
        return 1000.0 * (upper + lower) / 2.0, None, "Canon FocusDistanceUpper/Lower (ExifTool's mean, m = raw/100)"
    return None, None, None


def _size_warnings(reading: Reading, size: SensorSize | None, raw: bool) -> list[str]:
    """What a file's sizes say was assumed: a resized or cropped image, a sensor inferred rather than recorded.

    A raw file is not taken as resized: the pixel size libexiv2 reports for
    one may be that of an embedded preview.
    """
    from camtool.exif.reader import show

    warnings: list[str] = []
    w, h, stored_w, stored_h = reading.pixels_w, reading.pixels_h, reading.stored_w, reading.stored_h
    pixels_source = reading.sources.get("pixels", "")
    if not raw and w and h and stored_w and stored_h and pixels_source != "image size" and \
            max(stored_w, stored_h) < 0.95 * max(w, h):
        warnings.append(f"the file holds {stored_w}×{stored_h} px where its metadata ({pixels_source}) give {w}×{h}: "
                        f"a resized copy or a preview; the sensor, CoC and angles are for the camera's {w}×{h} frame")
    canon = reading.canon_sensor_mm
    if canon is not None and reading.plane_width_mm is not None and reading.plane_height_mm is not None:
        width, height = reading.plane_width_mm, reading.plane_height_mm
        if width < 0.95 * canon[0] or height < 0.95 * canon[1]:
            warnings.append(f"the image covers {show(round(width, 2))} × {show(round(height, 2))} mm of the "
                            f"{show(round(canon[0], 2))} × {show(round(canon[1], 2))} mm sensor Canon records "
                            "(a crop mode or an in-camera crop): the angles and CoC are for the image's part")
    inferred = {"Photo.FocalLengthIn35mmFilm": "the sensor is inferred from the 35 mm-equivalent focal length, "
                                                "which the camera rounds to whole millimetres",
                "Olympus": "the sensor is Olympus's focal-plane diagonal",
                "Nikon3.SensorPixelSize": "the sensor is Nikon's pixel size times the image size",
                "camera preset": "the sensor is that of the {} (matched on Make and Model)"}
    for prefix, what in ([] if size is None else inferred.items()):
        if size is not None and size.source.startswith(prefix):
            aspect = "" if prefix in ("camera preset", "Nikon3.SensorPixelSize") else \
                (f", with the image's aspect ratio {max(w, h) / min(w, h):.4g}:1" if w and h else
                 ", with a 3:2 aspect ratio assumed (the file gives no image size)")
            warnings.append(f"{what.format(size.source)}{aspect}: {show(round(size.width_mm, 2))} × "
                            f"{show(round(size.height_mm, 2))} mm")
    return warnings


def _lens_data(p: float | None, delta: float | None, prescription: Any, preset: Any) -> LensData | None:
    """The lens data: the values given over the lens preset's (:func:`camtool.plans.equipment.lens_data`)."""
    from camtool.plans.equipment import lens_data

    return lens_data(pupil_magnification=p, hiatus_mm=delta, prescription=prescription, lens_preset=preset)


def _sensor(reading: Reading, f: float | None, given: tuple[float, float] | None, given_source: str,
            presets: PresetIndex | None, unusable: list[Problem], named: set[str],
            warnings: list[str]) -> SensorSize | None:
    """The sensor: the one given, else the file's focal plane, maker-note sensor data, 35 mm equivalent, camera preset.

    The maker-note rung takes Canon's FocalPlaneX/YSize (when its aspect
    ratio is 4:3 or 3:2), else Olympus's focal-plane diagonal with the
    image's aspect ratio, else Nikon's pixel size times the image size. A
    crop factor from the 35 mm equivalent passes --crop's range and its
    sensor's sides --sensor's, or it is named in ``unusable`` and the camera
    preset is tried.
    """
    from camtool.exif.reader import outside, show
    from camtool.exif.sensor import camera_names, canon_plane_ok, from_crop, from_plane, match_preset

    if given is not None:
        return from_plane(given[0], given[1], given_source)
    if reading.plane_width_mm is not None and reading.plane_height_mm is not None:
        return from_plane(reading.plane_width_mm, reading.plane_height_mm, reading.sources["sensor"])
    w, h = reading.pixels_w, reading.pixels_h
    if reading.maker_plane_mm is not None and canon_plane_ok(*reading.maker_plane_mm):
        return from_plane(*reading.maker_plane_mm, "Canon.FocalLength (FocalPlaneX/YSize)")
    if reading.plane_diagonal_mm is not None:
        size = from_crop(math.hypot(36.0, 24.0) / reading.plane_diagonal_mm, w, h,
                         reading.sources.get("plane_diagonal", "Olympus.FocalPlaneDiagonal"))
        if outside("sensor_side", min(size.width_mm, size.height_mm)) is None:
            return size
    if reading.pixel_pitch_mm is not None and w and h:
        width, height = reading.pixel_pitch_mm * w, reading.pixel_pitch_mm * h
        if 1.0 < math.hypot(width, height) < 100.0 and outside("sensor_side", min(width, height)) is None:
            return from_plane(width, height, "Nikon3.SensorPixelSize × image size")
    if reading.focal_length_35mm is not None and f is not None:
        crop = reading.focal_length_35mm / f
        size = from_crop(crop, w, h, "Photo.FocalLengthIn35mmFilm / FocalLength")
        valid = outside("crop", crop)
        side = outside("sensor_side", min(size.width_mm, size.height_mm)) or \
            outside("sensor_side", max(size.width_mm, size.height_mm))
        if valid is None and side is None:
            return size
        named.add("sensor")
        unusable.append(Problem(
            f"Exif.Photo.FocalLengthIn35mmFilm {show(reading.focal_length_35mm)} over FocalLength {show(f)} mm: "
            + (f"a crop factor of {show(crop)} is outside the valid range: {valid}" if valid is not None else
               f"a sensor of {show(size.width_mm)} × {show(size.height_mm)} mm has a side outside the valid range: "
               f"{side}")))
    body = match_preset(presets("camera"), camera_names(reading.make, reading.model)) if presets is not None else None
    if body is not None:
        return from_plane(body.sensor.width_mm, body.sensor.height_mm, f"camera preset {body.id}")
    return None


def _coc(row: dict[str, Any], coc_mm: float | None, coc_source: str, rule: str | None, pitch: float | None,
         size: SensorSize | None, reading: Reading, missing: list[Problem], unusable: list[Problem]) -> float | None:
    """The CoC given, else the rule (d/1500 by default) applied to the sensor; the CoC passes --coc's range.

    The pixel pitch a ``px:K`` rule needs is the one given, else the sensor width over the image's long side
    if that lies in --pixel-pitch's range; a file without a usable pitch, or whose CoC falls outside --coc's
    range, has a problem; a rule that does not parse raises ``UnitError``.
    """
    from camtool.core.units import UnitError
    from camtool.exif.reader import outside, show
    from camtool.geometry.coc import DEFAULT_RULE, coc_from_rule

    if coc_mm is not None:
        row["coc_mm"], row["coc_source"] = coc_mm, coc_source
        return float(coc_mm)
    check_coc_rule(rule)  # a rule that does not parse is the caller's error, not the file's
    rule = rule or DEFAULT_RULE
    if size is None:
        return None
    if pitch is None and reading.pixels_w:
        derived = size.width_mm / max(reading.pixels_w, reading.pixels_h or 0)
        pitch = derived if outside("pixel_pitch", derived) is None else None
    try:
        choice = coc_from_rule(rule, size.width_mm, size.height_mm, pitch)
    except UnitError:
        shown = braced(rule)
        missing.append(Problem(f"no pixel pitch for {{coc_rule}} {shown} (the image size gives none in range): "
                               "give {pixel_pitch_mm}", ("coc_rule", "pixel_pitch_mm")))
        return None
    valid = outside("coc", choice.coc_mm)
    if valid is not None:
        unusable.append(Problem(f"a CoC of {show(choice.coc_mm)} mm ({choice.origin}, sensor from {size.source}) "
                                f"is outside the valid range: {valid}"))
        return None
    row["coc_mm"], row["coc_source"] = choice.coc_mm, choice.origin
    return float(choice.coc_mm)


def _depth(row: dict[str, Any], f: float, n: float, c: float, s: float, s_min: float | None, s_max: float | None,
           lens: LensData | None, options: tuple[str, str, bool, float, float], missing: list[Problem]) -> None:
    from camtool.core.errors import DomainError
    from camtool.dof.ladder import ModelUnavailable, depth_of_field, focal_lengths

    model, distance_from, diffraction, wavelength, tolerance = options

    def run(distance: float) -> Any:
        focal = focal_lengths(lens, [f])[0]
        return depth_of_field(model, focal, n, c, distance, distance_from, lens, diffraction, wavelength, tolerance)

    try:
        result = run(s)
    except (DomainError, ModelUnavailable, ValueError) as error:
        missing.append(Problem(f"no depth of field ({_one_line(error)})"))
        return
    limits = result.limits
    row.update(near_mm=limits.near_mm, far_mm=limits.far_mm, total_mm=limits.total_mm,
               hyperfocal_mm=limits.hyperfocal_mm, model=result.model)
    if s_min is not None and s_max is not None:
        try:
            low, high = run(s_min).limits, run(s_max).limits
        except (DomainError, ModelUnavailable, ValueError) as error:
            missing.append(Problem(f"no limits for the focus bracket ({_one_line(error)})"))
            return
        row.update(near_min_mm=low.near_mm, far_min_mm=low.far_mm, near_max_mm=high.near_mm, far_max_mm=high.far_mm)


def _hyperfocal(row: dict[str, Any], f: float, n: float, c: float, model: str, distance_from: str,
                lens: LensData | None, exiftool: bool, missing: list[Problem]) -> None:
    """The hyperfocal distance whatever the focus: ExifTool's f²/(N·c), or camtool's model's (when the DOF gave none).

    Under camtool's convention the depth of field's own H stands when there
    is one; else the model's closed form (``approx``, ``thin``, ``thick``),
    and for the other rungs the one ``auto`` uses for H
    (:func:`camtool.dof.ladder.hyperfocal_rung`).
    """
    from camtool.core.errors import DomainError
    from camtool.dof.closed import hyperfocal_mm
    from camtool.dof.ladder import LensData, ModelUnavailable, depth_of_field, hyperfocal_choices, hyperfocal_rung

    try:
        if exiftool:
            row["hyperfocal_mm"] = hyperfocal_mm(f, n, c, plus_f=False)
        elif row["hyperfocal_mm"] is None:
            # camtool.dof.ladder.hyperfocal's H: the limits of a focus at infinity by the closed-form rung, with
            # the lens's pupil magnification and hiatus only (its near limit at H is not needed here)
            rung = model if model in hyperfocal_choices() and model != "auto" else hyperfocal_rung(lens)
            known = None if lens is None else lens.thick_parameters()
            p, delta = known if known is not None else (1.0, 0.0)
            data = LensData(pupil_magnification=p, hiatus_mm=delta) if (p, delta) != (1.0, 0.0) else None
            row["hyperfocal_mm"] = depth_of_field(rung, f, n, c, math.inf, distance_from, lens=data).limits.hyperfocal_mm
    except (DomainError, ModelUnavailable, ValueError) as error:
        missing.append(Problem(f"no hyperfocal distance ({_one_line(error)})"))


def _angles(row: dict[str, Any], f: float, s: float | None, size: SensorSize, lens: LensData | None,
            distance_from: str, missing: list[Problem], exiftool: bool = False, lens_preset: Any = None) -> None:
    """The angles of view across the sensor, and the field width at a finite focus distance.

    ExifTool's FOV corrects the focal length for the focus only when the
    distance exceeds f and gives the field width only below 10 km; the same
    limits apply in its convention here. A fisheye lens preset's angles are
    those of its projection (docs/design.md §4.2), in camtool's convention
    (ExifTool's formula is rectilinear).
    """
    from camtool.core.errors import DomainError
    from camtool.geometry.fov import view

    p, delta = (lens.thick_parameters() if lens is not None else None) or (1.0, 0.0)
    distance = s if s is not None and math.isfinite(s) else None
    if exiftool and distance is not None and distance <= f:
        distance = None
    try:
        seen = view(size.width_mm, size.height_mm, f, distance, distance_from, p, delta)
        angles: Any = seen.angles
        mapping = getattr(lens_preset, "projection", None)
        if mapping not in (None, "rectilinear") and not exiftool:
            from camtool.geometry.projection import fisheye_field_of_view

            angles = fisheye_field_of_view(size.width_mm, size.height_mm, f, mapping, seen.magnification, p,
                                           getattr(lens_preset, "field_max_deg", None))
    except (DomainError, ValueError) as error:
        missing.append(Problem(f"no angle of view ({_one_line(error)})"))
        return
    row.update(horizontal_deg=angles.horizontal_deg, vertical_deg=angles.vertical_deg,
               diagonal_deg=angles.diagonal_deg)
    if seen.field_width_mm is not None and (not exiftool or (distance is not None and distance < 1e7)):
        row["field_width_mm"] = float(seen.field_width_mm)


def _exposure(row: dict[str, Any], n: float | None, t: float | None, iso: float | None, missing: list[Problem],
              named: set[str]) -> None:
    from camtool.core.errors import DomainError
    from camtool.exposure.ev import ev100, exposure_value

    if t is None and "shutter_s" not in named:
        missing.append(Problem("no shutter time (ExposureTime, ShutterSpeedValue)"))
    if iso is None and "iso" not in named:
        missing.append(Problem("no ISO (ISOSpeedRatings, ExposureIndex, maker note)"))
    if n is None or t is None:
        return
    try:
        row["ev"] = exposure_value(n, t)
        if iso is not None:
            row["ev100"] = ev100(n, t, iso)
    except DomainError as error:
        missing.append(Problem(f"no EV ({_one_line(error)})"))


def _one_line(error: Exception) -> str:
    return str(error).splitlines()[0] if str(error) else type(error).__name__
