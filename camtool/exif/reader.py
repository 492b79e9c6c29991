"""Read what a photo's metadata says about the shot, with python-exiv2 (libexiv2).

python-exiv2 is the optional ``exif`` extra (``pip install 'camtool[exif]'``);
it is imported only here, on the ``camtool exif`` path. Every value comes with
the tag it came from (``sources``) so a reader of the output can check it;
values the file does not carry are None, never guessed.

Nothing in a file is trusted. Only a regular file is handed to libexiv2 (a
FIFO, a device or a directory is refused before it is opened, so nothing
blocks); every number read from a tag passes the range of the option it
stands for (the f-number that of ``-N``, the focal length that of ``-f``, the
focus distance that of ``-s``) or is left out and named in ``problems``
(``Exif.Photo.FNumber 65288 is outside the valid range: f/0.7 to f/1024``);
every string read from a tag has its control characters escaped
(:func:`camtool.core.text.printable`).

The focus distance is read, most specific first: the maker note's recorded
bracket (Canon FocusDistanceUpper/Lower), the maker note's single distance
(Nikon lens data, Olympus focus info, Canon ShotInfo), then Exif
SubjectDistance. The conversions are in :mod:`camtool.exif.makernotes`.

References
----------
python-exiv2 (https://python-exiv2.readthedocs.io): ``ImageFactory.open``,
``Image.readMetadata``, ``Image.exifData``, ``Exifdatum.toRational``/``toInt64``;
Exif 2.32 (CIPA DC-008-2019) for the standard tags.
"""

from __future__ import annotations

import contextlib
import errno
import math
import os
import re
import stat
import warnings
from collections.abc import Callable
from typing import Any

from camtool.core import domain, ranges
from camtool.core.errors import CamtoolError, DomainError
from camtool.core.files import file_kind
from camtool.core.record import NamedTuple
from camtool.core.text import printable
from camtool.exif import makernotes


class ExifUnavailable(CamtoolError, ImportError):
    """python-exiv2 is not installed; the message says what to install."""


class UnreadableFile(Exception):
    """The file could not be read as an image with metadata; the message says why (one line)."""


class Reading(NamedTuple):
    """What one file's metadata says, in mm, seconds and ISO; None where it says nothing usable.

    ``sources`` maps each field name to the tag (exiv2 key) it came from;
    ``problems`` holds (field, message) for each tag whose value was present
    but unusable (outside its range, a zero denominator, unreadable), the
    message naming the tag; the field is ``sensor`` or ``focus_distance`` for
    the tags behind those, else the name of the field left None.

    The fields after ``focus_distance_max_mm`` are the raw inputs of the
    other conventions (ExifTool's composites, the warnings): ``stored_w`` and
    ``stored_h`` the pixels the file itself holds (a preview or a resized
    copy holds fewer than the camera's frame); ``sizes`` the image sizes the
    metadata give, (width, height, tag) in ExifTool's order (Exif, Canon's
    maker note, the file's own); ``plane_px_per_mm`` the focal-plane
    resolution in pixels per mm; ``canon_sensor_mm`` the sensor Canon encodes
    in that resolution's denominators; ``maker_plane_mm`` Canon's maker-note
    FocalPlaneX/YSize; ``plane_diagonal_mm`` Olympus's FocalPlaneDiagonal;
    ``pixel_pitch_mm`` Nikon's SensorPixelSize; ``digital_zoom`` Canon's
    digital zoom ratio; ``focus_tag_mm`` a maker-note distance ExifTool names
    FocusDistance (Nikon, Olympus, Minolta), ``subject_distance_mm`` Exif
    SubjectDistance, ``object_distance_mm`` Casio's ObjectDistance, and
    ``bracket_m`` Canon's (upper, lower) in ExifTool's metres (raw/100, so
    Canon's infinity is 655.35 m and an unrecorded lower end 0);
    ``iso_speed_ratings`` Exif ISOSpeedRatings as written, 65535 included
    (ExifTool's ISO).
    """

    make: str | None = None
    model: str | None = None
    lens: str | None = None
    focal_length_mm: float | None = None
    focal_length_35mm: float | None = None
    f_number: float | None = None
    shutter_s: float | None = None
    iso: float | None = None
    pixels_w: int | None = None
    pixels_h: int | None = None
    plane_width_mm: float | None = None
    plane_height_mm: float | None = None
    focus_distance_mm: float | None = None
    focus_distance_min_mm: float | None = None
    focus_distance_max_mm: float | None = None
    stored_w: int | None = None
    stored_h: int | None = None
    sizes: tuple[tuple[int, int, str], ...] = ()
    plane_px_per_mm: tuple[float, float] | None = None
    canon_sensor_mm: tuple[float, float] | None = None
    maker_plane_mm: tuple[float, float] | None = None
    plane_diagonal_mm: float | None = None
    pixel_pitch_mm: float | None = None
    digital_zoom: float | None = None
    focus_tag_mm: float | None = None
    subject_distance_mm: float | None = None
    object_distance_mm: float | None = None
    bracket_m: tuple[float, float] | None = None
    iso_speed_ratings: float | None = None
    sources: dict[str, str] = {}  # noqa: RUF012 - NamedTuple default, never mutated (a fresh dict per reading)
    problems: tuple[tuple[str, str], ...] = ()


# -- numbers: the range of the option each one stands for ---------------------------------------------------

def _bounds(bounds: tuple[float, float], unit: str, allow_inf: bool = False) -> Callable[[float], str | None]:
    def outside(value: float) -> str | None:
        ok = ranges.in_range(value, bounds, allow_inf) and (bounds[0] > 0 or value > 0)
        return None if ok else ranges.describe(bounds, unit, allow_inf)

    return outside


def _domain(param: str) -> Callable[[float], str | None]:
    def outside(value: float) -> str | None:
        try:
            domain.check(param, value)
        except DomainError as error:
            return error.valid
        return None

    return outside


OUTSIDE: dict[str, Callable[[float], str | None]] = {
    "focal_length": _bounds(ranges.FOCAL_LENGTH_MM, "mm"),  # -f
    "f_number": _domain("f_number"),  # -N
    "shutter_s": _domain("shutter_s"),  # -t
    "iso": _domain("iso"),  # --iso
    "distance": _bounds(ranges.DISTANCE_MM, "mm", allow_inf=True),  # -s
    "sensor_side": _bounds(ranges.SENSOR_SIDE_MM, "mm"),  # --sensor WxH
    "crop": _bounds(ranges.CROP_FACTOR, ""),  # --crop
    "coc": _bounds(ranges.COC_MM, "mm"),  # --coc
    "pixel_pitch": _bounds((ranges.PIXEL_PITCH_UM[0] / 1000, ranges.PIXEL_PITCH_UM[1] / 1000), "mm"),  # --pixel-pitch
}
"""For each kind of value, a function giving the valid range in words if the value lies outside it, else None.

The ranges are the command-line options' own (:mod:`camtool.core.ranges`,
:mod:`camtool.core.domain`): a number from a file passes the check a typed
number passes. NaN lies outside every range.
"""


def outside(kind: str, value: float) -> str | None:
    """The valid range of ``kind`` in words if ``value`` lies outside it (NaN always does), else None.

    >>> outside("f_number", 8.0) is None, outside("f_number", 65288.0)
    (True, 'f/0.7 to f/1024')
    >>> outside("focal_length", float("nan"))
    '1 to 5000 mm'
    """
    return OUTSIDE[kind](value)


def show(value: float) -> str:
    """A number for a message: ``65288``, ``1.5e-08``, ``inf``."""
    return f"{value:.6g}"


def _pow2(exponent: float) -> float:
    """2^exponent without OverflowError: inf above the largest float, 0 below the smallest."""
    if not math.isfinite(exponent):
        return math.inf if exponent > 0 else 0.0
    return math.inf if exponent >= 1024 else 2.0 ** max(exponent, -1100.0)


# Exif FocalPlaneResolutionUnit: 2 inch, 3 cm (Exif 2.32 tag 0xA210); 4 mm and 5 µm are used by some cameras
# and understood by ExifTool (Exif.pm, FocalPlaneResolutionUnit).
_RESOLUTION_UNIT_MM = {1: 25.4, 2: 25.4, 3: 10.0, 4: 1.0, 5: 0.001}

_WANTED = frozenset({
    "Exif.Image.Make", "Exif.Image.Model", "Exif.Photo.LensModel", "Exif.Photo.LensMake",
    "Exif.Photo.FocalLength", "Exif.Image.FocalLength", "Exif.Photo.FocalLengthIn35mmFilm",
    "Exif.Photo.FNumber", "Exif.Image.FNumber", "Exif.Photo.ApertureValue",
    "Exif.Photo.ExposureTime", "Exif.Image.ExposureTime", "Exif.Photo.ShutterSpeedValue",
    "Exif.Photo.ISOSpeedRatings", "Exif.Photo.RecommendedExposureIndex", "Exif.Photo.StandardOutputSensitivity",
    "Exif.Photo.PixelXDimension", "Exif.Photo.PixelYDimension", "Exif.Image.ImageWidth", "Exif.Image.ImageLength",
    "Exif.Photo.FocalPlaneXResolution", "Exif.Photo.FocalPlaneYResolution", "Exif.Photo.FocalPlaneResolutionUnit",
    "Exif.Image.FocalPlaneXResolution", "Exif.Image.FocalPlaneYResolution", "Exif.Image.FocalPlaneResolutionUnit",
    "Exif.Photo.SubjectDistance", "Exif.Image.SubjectDistance",
    "Exif.CanonFi.FocusDistanceUpper", "Exif.CanonFi.FocusDistanceLower", "Exif.CanonSi.SubjectDistance",
    "Exif.NikonLd2.FocusDistance", "Exif.NikonLd3.FocusDistance", "Exif.NikonLd4.FocusDistance",
    "Exif.OlympusFi.FocusDistance", "Exif.CanonCs.Lens", "Exif.Canon.LensModel", "Exif.Nikon3.Lens",
    "Exif.Photo.ExposureIndex", "Exif.CanonCs.ISOSpeed", "Exif.CanonSi.ISOSpeed", "Exif.CanonSi.AutoISO",
    "Exif.Nikon3.ISOSpeed", "Exif.Casio2.ISO", "Exif.Samsung2.ISO",
    "Exif.MinoltaCsNew.ISO", "Exif.MinoltaCsOld.ISO", "Exif.CanonSi.0x0014",
    "Exif.CanonPi.ImageWidth", "Exif.CanonPi.ImageHeight", "Exif.Canon.FocalLength", "Exif.CanonCs.FocalUnits",
    "Exif.CanonCs.DigitalZoom", "Exif.CanonCs.ZoomSourceWidth", "Exif.CanonCs.ZoomTargetWidth",
    "Exif.Olympus.FocalPlaneDiagonal", "Exif.OlympusEq.FocalPlaneDiagonal", "Exif.Nikon3.SensorPixelSize",
    "Exif.NikonLd4.FocusDistance2", "Exif.MinoltaCsNew.FocusDistance", "Exif.MinoltaCsOld.FocusDistance",
    "Exif.Casio.ObjectDistance", "Exif.Casio2.ObjectDistance",
})
_SUBIMAGE = re.compile(r"Exif\.SubImage\d+\.(ImageWidth|ImageLength|NewSubfileType)|Exif\.Image\.NewSubfileType")


def _wanted(key: str) -> bool:
    return key in _WANTED or (key.startswith("Exif.SubImage") and _SUBIMAGE.fullmatch(key) is not None)

MAX_BUFFER_BYTES = 1 << 30
"""Largest file read into memory (only for a name libexiv2 cannot be given: one that is not UTF-8)."""


def _exiv2() -> Any:
    try:
        import exiv2
    except ImportError:
        raise ExifUnavailable("camtool exif needs python-exiv2: pip install 'camtool[exif]' (or pip install exiv2)") \
            from None
    if id(exiv2) not in _READY:
        _setup(exiv2)
        _READY.add(id(exiv2))
    return exiv2


_READY: set[int] = set()
"""The python-exiv2 modules already set up (once per process: the setup costs more than reading a small file)."""


def _setup(exiv2: Any) -> None:
    # our own one-line messages replace libexiv2's warnings on stderr
    exiv2.LogMsg.setLevel(exiv2.LogMsg.Level.mute)
    # CR3, HEIF and AVIF are ISO BMFF files, which libexiv2 0.27.4 to 0.27.x reads only once told to; from
    # 0.28 a build with BMFF support reads them anyway (python-exiv2 then warns that the call is not needed)
    enable = getattr(exiv2, "enableBMFF", None)
    if enable is not None:
        with warnings.catch_warnings(), contextlib.suppress(Exception):
            warnings.simplefilter("ignore")
            enable(True)


def require_exiv2() -> None:
    """Raise :class:`ExifUnavailable` unless python-exiv2 can be imported."""
    _exiv2()


def check_regular(path: str) -> None:
    """Raise :class:`UnreadableFile` unless ``path`` (symbolic links followed) is a regular file.

    A FIFO would block the reader until a writer came, a device could be
    endless: both are refused here, before anything opens them.
    """
    try:
        info = os.stat(path)
    except OSError as error:
        if error.errno in (errno.ENOENT, errno.ENOTDIR):
            raise UnreadableFile("cannot be opened") from None
        if error.errno == errno.ELOOP:
            raise UnreadableFile("cannot be opened: a loop of symbolic links") from None
        raise UnreadableFile(f"cannot be opened: {error.strerror or error}") from None
    if not stat.S_ISREG(info.st_mode):
        raise UnreadableFile(f"is {file_kind(info.st_mode)}, not a regular file")


def _open(exiv2: Any, path: str) -> tuple[Any, bytes | None]:
    """The libexiv2 image of ``path`` with its metadata read, and the buffer it reads from (kept alive)."""
    check_regular(path)
    try:
        path.encode("utf-8")
    except UnicodeEncodeError:  # a name that is not UTF-8 (os.fsdecode's surrogates): give libexiv2 the bytes
        from camtool.core.files import FileProblem, read_bytes

        try:
            buffer: bytes | None = read_bytes(path, MAX_BUFFER_BYTES)
        except FileProblem as problem:
            raise UnreadableFile(problem.problem) from None
        image = exiv2.ImageFactory.open(buffer)
    else:
        buffer = None
        image = exiv2.ImageFactory.open(path)
    image.readMetadata()
    return image, buffer


def read_file(path: str) -> Reading:
    """Read the shot's settings from the image at ``path``.

    Raises
    ------
    ExifUnavailable
        python-exiv2 is not installed.
    UnreadableFile
        Not a regular file, not an image libexiv2 knows, truncated, or
        without any Exif metadata (the message, one line, says which).
    """
    exiv2 = _exiv2()
    try:
        image, _buffer = _open(exiv2, path)
        data = {key: datum for datum in image.exifData() if _wanted(key := datum.key())}
    except UnreadableFile:
        raise
    except exiv2.Exiv2Error as error:
        reason = _reason(error)
        suffix = os.path.splitext(path)[1].lower()
        if reason == NOT_READ or suffix == ".x3f":
            reason += _FORMAT_NOTES.get(suffix, "")
        raise UnreadableFile(reason) from None
    except OSError as error:
        raise UnreadableFile(error.strerror or str(error)) from None
    except (ValueError, OverflowError, MemoryError, RuntimeError, UnicodeError) as error:
        # libexiv2 on a structure it cannot follow: one line, never a traceback
        raise UnreadableFile(f"truncated or corrupt ({_reason(error)})") from None
    if not data:
        raise UnreadableFile("no Exif metadata")
    return _Tags(data, image).reading()


class _Tags:
    """The wanted tags of one file, turned into a :class:`Reading` with the problems found on the way."""

    def __init__(self, data: dict[str, Any], image: Any) -> None:
        self.data, self.image = data, image
        self.sources: dict[str, str] = {}
        self.fields: dict[str, Any] = {"sources": self.sources}
        self.problems: list[tuple[str, str]] = []

    def reading(self) -> Reading:
        self.text("make", "Exif.Image.Make")
        self.text("model", "Exif.Image.Model")
        self.text("lens", "Exif.Photo.LensModel", "Exif.Canon.LensModel")
        self.number("focal_length_mm", "focal_length", "Exif.Photo.FocalLength", "Exif.Image.FocalLength")
        self.number("focal_length_35mm", "focal_length", "Exif.Photo.FocalLengthIn35mmFilm")
        # FNumber; else the APEX aperture value Av, N = 2^(Av/2) (Exif 2.32 ApertureValue); Av 0 is f/1
        self.number("f_number", "f_number", "Exif.Photo.FNumber", "Exif.Image.FNumber")
        self.number("f_number", "f_number", "Exif.Photo.ApertureValue", apex=lambda av: _pow2(av / 2.0))
        # ExposureTime; else the APEX shutter speed value Tv, t = 2^(−Tv) (Exif 2.32 ShutterSpeedValue); Tv 0 is 1 s
        self.number("shutter_s", "shutter_s", "Exif.Photo.ExposureTime", "Exif.Image.ExposureTime")
        self.number("shutter_s", "shutter_s", "Exif.Photo.ShutterSpeedValue", apex=lambda tv: _pow2(-tv))
        # ISOSpeedRatings is a 16-bit field: cameras write 65535 for ISO 65535 and above and put the value in
        # StandardOutputSensitivity or RecommendedExposureIndex (Exif 2.3, SensitivityType)
        self.number("iso", "iso", "Exif.Photo.ISOSpeedRatings", skip=lambda iso: iso >= 65535)
        self.number("iso", "iso", "Exif.Photo.StandardOutputSensitivity", "Exif.Photo.RecommendedExposureIndex")
        self.maker_iso()
        self.number("iso", "iso", "Exif.Photo.ExposureIndex")
        iso_tag = self.integer("iso", "Exif.Photo.ISOSpeedRatings")
        if iso_tag and outside("iso", iso_tag) is None:
            self.fields["iso_speed_ratings"] = float(iso_tag)
        self.canon_focal_length()
        self.pixels()
        self.focal_plane()
        self.maker_sensor()
        self.focus()
        self.exiftool_distances()
        return Reading(**self.fields, problems=tuple(self.problems))

    def unusable(self, field: str, key: str, shown: str, why: str) -> None:
        self.problems.append((field, f"{key} {shown} {why}"))

    def text(self, name: str, *keys: str) -> None:
        for key in keys:
            if key not in self.data:
                continue
            try:
                raw = self.data[key].toString()
            except Exception:  # a value libexiv2 cannot render is unusable, named below
                self.problems.append((name, f"{key} cannot be read as text"))
                continue
            value = printable(str(raw).strip().strip("\x00").strip())
            if value:
                self.fields[name], self.sources[name] = value, _short(key)
                return

    def rational(self, field: str, key: str) -> tuple[int, int] | None:
        """The tag's first value as (numerator, denominator); None (and a problem) if it has none."""
        try:
            datum = self.data[key]
            if datum.count() < 1:  # an empty value: nothing recorded
                return None
            num, den = datum.toRational(0)
            return int(num), int(den)
        except Exception:  # a malformed value is unusable, named
            self.problems.append((field, f"{key} cannot be read as a number"))
            return None

    def number(self, name: str, kind: str, *keys: str, apex: Callable[[float], float] | None = None,
               skip: Callable[[float], bool] | None = None) -> None:
        """The first of ``keys`` whose value passes ``kind``'s range; the others present are named as problems.

        0 means "not recorded" for a plain value (Exif's convention for
        unknown), but is a real value for an APEX one (Av 0 is f/1).
        """
        if name in self.fields:
            return
        for key in keys:
            if key not in self.data:
                continue
            raw = self.rational(name, key)
            if raw is None:
                continue
            num, den = raw
            if num == 0 and apex is None:
                continue
            shown = f"{num}/{den}" if den != 1 else str(num)
            if den == 0:
                self.unusable(name, key, shown, "has a zero denominator")
                continue
            value = num / den
            if skip is not None and skip(value):
                continue
            if apex is not None:
                converted = apex(value)
                shown, value = f"{shown} (= {show(converted)})", converted
            valid = outside(kind, value)
            if valid is not None:
                self.unusable(name, key, shown, f"is outside the valid range: {valid}")
                continue
            self.fields[name], self.sources[name] = value, _short(key)
            return

    def integer(self, field: str, key: str) -> int | None:
        if key not in self.data:
            return None
        try:
            datum = self.data[key]
            return int(datum.toInt64(0)) if datum.count() >= 1 else None
        except Exception:  # a malformed value is unusable, named
            self.problems.append((field, f"{key} cannot be read as a number"))
            return None

    def value(self, field: str, key: str, index: int = 0) -> float | None:
        """The tag's ``index``-th value as a number (a rational divided out); None if absent, empty or 0/0."""
        if key not in self.data:
            return None
        try:
            datum = self.data[key]
            if datum.count() <= index:
                return None
            num, den = datum.toRational(index)
        except Exception:  # a malformed value is unusable, named
            self.problems.append((field, f"{key} cannot be read as a number"))
            return None
        return float(num) / float(den) if den else None

    def accept(self, name: str, kind: str, key: str, value: float | None) -> bool:
        """Take ``value`` for ``name`` if it passes ``kind``'s range (else name it as unusable); True if taken."""
        if value is None or name in self.fields:
            return False
        valid = outside(kind, value)
        if valid is not None:
            self.unusable(name, key, show(value), f"is outside the valid range: {valid}")
            return False
        self.fields[name], self.sources[name] = value, _short(key)
        return True

    def maker_iso(self) -> None:
        """ISO from the maker note when Exif records none: Canon, Nikon, Casio, Samsung, Minolta (ExifTool's ISO tags)."""
        if "iso" in self.fields:
            return
        camera = self.integer("iso", "Exif.CanonCs.ISOSpeed")
        base = self.integer("iso", "Exif.CanonSi.ISOSpeed")
        auto = self.integer("iso", "Exif.CanonSi.AutoISO")
        if camera is not None or base is not None:
            iso = makernotes.canon_iso(camera, base, auto)
            key = "Exif.CanonCs.ISOSpeed" if makernotes.canon_iso(camera, None, None) else "Exif.CanonSi.ISOSpeed"
            if self.accept("iso", "iso", key, iso):
                return
        # Nikon's ISO is (0, value) or (value): the last number is the ISO (ExifTool Nikon ISO: "ISO used")
        for key in ("Exif.Nikon3.ISOSpeed",):
            if key in self.data:
                count = self.data[key].count()
                iso = self.value("iso", key, max(count - 1, 0)) if count else None
                if iso and self.accept("iso", "iso", key, iso):
                    return
        for key in ("Exif.Casio2.ISO", "Exif.Samsung2.ISO"):
            iso = self.value("iso", key)
            if iso and self.accept("iso", "iso", key, iso):
                return
        for key in ("Exif.MinoltaCsNew.ISO", "Exif.MinoltaCsOld.ISO"):
            code = self.integer("iso", key)
            if code and self.accept("iso", "iso", key, makernotes.minolta_iso(code)):
                return

    def canon_focal_length(self) -> None:
        """Canon's maker-note FocalLength record: (type, focal length / FocalUnits, plane x, y size in 1/1000 in).

        The focal length stands in for a missing Exif FocalLength (Canon CRW
        files carry it only here); the focal-plane size is ExifTool's
        FocalPlaneXSize/YSize (``$val * 25.4 / 1000`` mm).
        """
        key = "Exif.Canon.FocalLength"
        if key not in self.data:
            return
        raw = self.value("focal_length_mm", key, 1)
        # FocalUnits (CanonCs 0x19) is decoded by exiv2 as the third value of CanonCs.Lens (0x17 to 0x19)
        units = self.value("focal_length_mm", "Exif.CanonCs.FocalUnits") or \
            self.value("focal_length_mm", "Exif.CanonCs.Lens", 2) or 1.0
        if raw and self.accept("focal_length_mm", "focal_length", key, raw / units):
            self.sources["focal_length_mm"] = "Canon.FocalLength / FocalUnits"
        x, y = self.value("sensor", key, 2), self.value("sensor", key, 3)
        if x and y and x > 0 and y > 0:
            self.fields["maker_plane_mm"] = (x * 0.0254, y * 0.0254)

    def pixels(self) -> None:
        """The image size the focal-plane resolution refers to: Exif, Canon's maker note, the full-size IFD, the file.

        Never a thumbnail or a preview: of the TIFF directories (IFD0 and the
        SubIFDs of a raw file or DNG) the largest is taken, and the file's own
        size only when the metadata give none.
        """
        sizes: list[tuple[int, int, str]] = []
        for w_key, h_key in (("Exif.Photo.PixelXDimension", "Exif.Photo.PixelYDimension"),
                             ("Exif.CanonPi.ImageWidth", "Exif.CanonPi.ImageHeight")):
            w, h = self.integer("sensor", w_key), self.integer("sensor", h_key)
            if w and h and w > 0 and h > 0:
                sizes.append((w, h, f"{_short(w_key)}/{_short(h_key).rsplit('.', 1)[1]}"))
        stored = None
        with contextlib.suppress(Exception):  # no usable image size: the rungs that need one are passed over
            stored = int(self.image.pixelWidth()), int(self.image.pixelHeight())
        if stored is not None and stored[0] > 0 and stored[1] > 0:
            self.fields["stored_w"], self.fields["stored_h"] = stored
        directories = []
        for key in self.data:
            if key.endswith(".ImageWidth") and (key.startswith("Exif.SubImage") or key == "Exif.Image.ImageWidth"):
                w, h = self.integer("sensor", key), self.integer("sensor", key[:-5] + "Length")
                if w and h and w > 0 and h > 0:
                    directories.append((w * h, w, h, key))
        ifd = max(directories) if directories else None
        chosen = sizes[0] if sizes else None
        if chosen is None and ifd is not None:
            chosen = (ifd[1], ifd[2], f"{_short(ifd[3])}/ImageLength (largest of the file's images)")
        if chosen is None and "stored_w" in self.fields:
            chosen = (self.fields["stored_w"], self.fields["stored_h"], "image size")
        if chosen is not None:
            self.fields["pixels_w"], self.fields["pixels_h"] = chosen[0], chosen[1]
            self.sources["pixels"] = chosen[2]
        # ExifTool's order of image sizes for the focal-plane resolution: ExifImage, CanonImage, ImageWidth
        if "stored_w" in self.fields:
            sizes.append((self.fields["stored_w"], self.fields["stored_h"], "image size"))
        self.fields["sizes"] = tuple(sizes)

    def focal_plane(self) -> None:
        """Sensor size from FocalPlaneX/YResolution (pixels per unit on the sensor) and the image size."""
        w, h = self.fields.get("pixels_w"), self.fields.get("pixels_h")
        for group in ("Photo", "Image"):
            x_key, y_key = f"Exif.{group}.FocalPlaneXResolution", f"Exif.{group}.FocalPlaneYResolution"
            if x_key not in self.data:
                continue
            x_raw = self.rational("sensor", x_key)
            y_raw = self.rational("sensor", y_key) if y_key in self.data else x_raw
            unit = self.integer("sensor", f"Exif.{group}.FocalPlaneResolutionUnit")
            unit = 2 if unit is None else unit  # Exif default: inches
            if x_raw is None or y_raw is None or unit not in _RESOLUTION_UNIT_MM:
                continue
            (xn, xd), (yn, yd) = x_raw, y_raw
            if xn <= 0 or xd <= 0 or yn <= 0 or yd <= 0:
                continue
            self.fields["plane_px_per_mm"] = (xn / xd / _RESOLUTION_UNIT_MM[unit], yn / yd / _RESOLUTION_UNIT_MM[unit])
            self.canon_sensor(xn, xd, yn, yd)
            if not (w and h):
                return
            width = w * xd / xn * _RESOLUTION_UNIT_MM[unit]
            height = h * yd / yn * _RESOLUTION_UNIT_MM[unit]
            # a diagonal outside 1 to 100 mm is a resized image or a wrong unit, not a sensor (the same
            # sanity check as ExifTool's CalcScaleFactor35efl); the next source is used instead
            if not 1.0 < math.hypot(width, height) < 100.0:
                return
            valid = outside("sensor_side", min(width, height))
            if valid is not None:
                self.unusable("sensor", f"Exif.{group}.FocalPlaneX/YResolution", f"{xn}/{xd}, {yn}/{yd}",
                              f"give a sensor of {show(width)} × {show(height)} mm, a side outside {valid}")
                return
            self.fields["plane_width_mm"], self.fields["plane_height_mm"] = width, height
            self.sources["sensor"] = f"{group}.FocalPlaneX/YResolution"
            return

    def canon_sensor(self, xn: int, xd: int, yn: int, yd: int) -> None:
        """Canon's sensor size, from the focal-plane resolution as Canon writes it (ExifTool Canon CalcSensorDiag).

        Canon writes the resolution as (full image width × 1000) / (sensor
        width in 1/1000 inch), likewise for the height; ExifTool takes the
        denominators as the sensor size when the numerators are multiples of
        1000 from 640 000 to 10⁷ (480 000 for the height), the denominators
        from 61 to 1500 (1000 for the height), and differ (a reduced rational
        is not Canon's encoding).
        """
        if not (self.fields.get("make") or "").lower().startswith("canon"):
            return
        if (xn % 1000 == 0 and yn % 1000 == 0 and 640000 <= xn < 10**7 and 480000 <= yn < 10**7
                and 61 <= xd < 1500 and 61 <= yd < 1000 and xd != yd):
            self.fields["canon_sensor_mm"] = (xd * 0.0254, yd * 0.0254)

    def maker_sensor(self) -> None:
        """Sensor data the maker notes carry: Olympus's focal-plane diagonal, Nikon's pixel size."""
        for key in ("Exif.OlympusEq.FocalPlaneDiagonal", "Exif.Olympus.FocalPlaneDiagonal"):
            diagonal = self.value("sensor", key)
            if diagonal:
                valid = outside("sensor_side", diagonal)
                if valid is None and 1.0 < diagonal < 100.0:
                    self.fields["plane_diagonal_mm"], self.sources["plane_diagonal"] = diagonal, _short(key)
                    break
                self.unusable("sensor", key, show(diagonal), "mm is not a sensor diagonal (1 to 100 mm)")
        pitch = self.value("sensor", "Exif.Nikon3.SensorPixelSize")
        if pitch and outside("pixel_pitch", pitch / 1000.0) is None:
            self.fields["pixel_pitch_mm"] = pitch / 1000.0
        if self.integer("sensor", "Exif.CanonCs.DigitalZoom") == 3:  # Canon: zoom ratio = target / source width
            source = self.integer("sensor", "Exif.CanonCs.ZoomSourceWidth")
            target = self.integer("sensor", "Exif.CanonCs.ZoomTargetWidth")
            if source and target and source > 0 and target > 0 and 0.01 < target / source < 100:
                self.fields["digital_zoom"] = target / source

    def distance(self, key: str, value: float | None) -> float | None:
        """``value`` (mm) if it is a focus distance ``-s`` would take; else None, named as a problem."""
        if value is None:
            return None
        valid = outside("distance", value)
        if valid is not None:
            self.unusable("focus_distance", key, f"(= {show(value)} mm)", f"is outside the valid range: {valid}")
            return None
        return value

    def set_focus(self, value: float, source: str, bracket: tuple[float, float] | None = None) -> None:
        self.fields["focus_distance_mm"], self.sources["focus_distance"] = value, source
        if bracket is not None:
            self.fields["focus_distance_min_mm"], self.fields["focus_distance_max_mm"] = bracket

    def canon_bracket(self, upper_key: str, lower_key: str) -> bool:
        """Canon's FocusDistanceUpper/Lower pair: a bracket, or the upper end alone; True if a distance was set."""
        upper = self.integer("focus_distance", upper_key)
        lower = self.integer("focus_distance", lower_key)
        far = makernotes.canon_focus_distance_mm(upper) if upper is not None else None
        near = makernotes.canon_focus_distance_mm(lower) if lower is not None else None
        if far is not None and near is not None:
            near, far = min(near, far), max(near, far)
            # ExifTool's DOF takes the middle of the bracket (Composite.pm, DOF); the geometric mean would be
            # no better founded, and the bracket's ends are reported beside it.
            middle = (near + far) / 2.0 if math.isfinite(far) else far
            self.set_focus(middle, f"{_short(upper_key)}/{lower_key.rsplit('.', 1)[1]} (middle)", (near, far))
            return True
        if far is not None:
            self.set_focus(far, _short(upper_key))
            return True
        return False

    def focus(self) -> None:
        data = self.data
        if self.canon_bracket("Exif.CanonFi.FocusDistanceUpper", "Exif.CanonFi.FocusDistanceLower"):
            return
        # Canon's ShotInfo pair (exiv2's CanonSi.SubjectDistance and 0x0014; ExifTool's ShotInfo
        # FocusDistanceUpper and FocusDistanceLower): a bracket where the lower end is recorded
        upper = self.integer("focus_distance", "Exif.CanonSi.SubjectDistance")
        lower = self.integer("focus_distance", "Exif.CanonSi.0x0014")
        if upper and lower and self.canon_bracket("Exif.CanonSi.SubjectDistance", "Exif.CanonSi.0x0014"):
            return
        # Nikon Z lenses: a 16-bit code, 1/256 of the F-mount step (ExifTool LensData0800 0x4e)
        raw = self.integer("focus_distance", "Exif.NikonLd4.FocusDistance2")
        if raw:
            value = self.distance("Exif.NikonLd4.FocusDistance2", makernotes.nikon_focus_distance_mm((raw & 0xFFFF) / 256.0))
            if value is not None:
                self.set_focus(value, "NikonLd4.FocusDistance2")
                return
        for key in ("Exif.NikonLd3.FocusDistance", "Exif.NikonLd4.FocusDistance", "Exif.NikonLd2.FocusDistance"):
            raw = self.integer("focus_distance", key)
            if raw:  # 0 is written by lenses without a distance encoder
                value = self.distance(key, makernotes.nikon_focus_distance_mm(raw))
                if value is not None:
                    # one byte, 40 codes a decade: the distance lies within half a code of the recorded one
                    code = float(raw & 0xFF)
                    bracket = (makernotes.nikon_focus_distance_mm(code - 0.5),
                               makernotes.nikon_focus_distance_mm(code + 0.5))
                    self.set_focus(value, _short(key), bracket)
                    return
        if "Exif.OlympusFi.FocusDistance" in data:
            raw_pair = self.rational("focus_distance", "Exif.OlympusFi.FocusDistance")
            value = makernotes.olympus_focus_distance_mm(*raw_pair) if raw_pair is not None else None
            value = self.distance("Exif.OlympusFi.FocusDistance", value)
            if value is not None:
                self.set_focus(value, "OlympusFi.FocusDistance")
                return
        for key in ("Exif.MinoltaCsNew.FocusDistance", "Exif.MinoltaCsOld.FocusDistance"):
            raw = self.integer("focus_distance", key)
            value = self.distance(key, makernotes.minolta_focus_distance_mm(raw) if raw is not None else None)
            if value is not None:
                self.set_focus(value, _short(key))
                return
        for key in ("Exif.Casio2.ObjectDistance", "Exif.Casio.ObjectDistance"):
            raw = self.integer("focus_distance", key)
            converted = makernotes.casio_object_distance_mm(raw, key.endswith("2.ObjectDistance")) \
                if raw is not None else None
            value = self.distance(key, converted)
            if value is not None:
                self.set_focus(value, _short(key))
                return
        raw = self.integer("focus_distance", "Exif.CanonSi.SubjectDistance")
        value = makernotes.canon_focus_distance_mm(raw) if raw is not None else None
        value = self.distance("Exif.CanonSi.SubjectDistance", value)
        if value is not None:
            self.set_focus(value, "CanonSi.SubjectDistance")
            return
        for key in ("Exif.Photo.SubjectDistance", "Exif.Image.SubjectDistance"):
            if key in data:
                raw_pair = self.rational("focus_distance", key)
                if raw_pair is None:
                    continue
                value = self.distance(key, makernotes.exif_subject_distance_mm(*raw_pair))
                if value is not None:
                    self.set_focus(value, _short(key))
                    return

    def quiet_distance(self, value: float | None) -> float | None:
        """``value`` if ``-s`` would take it, else None (already named by :meth:`focus` if it was used there)."""
        return value if value is not None and outside("distance", value) is None else None

    def exiftool_distances(self) -> None:
        """The distances ExifTool's DOF and FOV choose among, each as ExifTool names and scales it."""
        fields = self.fields
        for key in ("Exif.NikonLd4.FocusDistance2",):
            raw = self.integer("focus_distance", key)
            if raw:
                fields["focus_tag_mm"] = self.quiet_distance(makernotes.nikon_focus_distance_mm((raw & 0xFFFF) / 256.0))
        for key in ("Exif.NikonLd3.FocusDistance", "Exif.NikonLd4.FocusDistance", "Exif.NikonLd2.FocusDistance"):
            raw = self.integer("focus_distance", key)
            if raw and fields.get("focus_tag_mm") is None:
                fields["focus_tag_mm"] = self.quiet_distance(makernotes.nikon_focus_distance_mm(raw))
        if fields.get("focus_tag_mm") is None and "Exif.OlympusFi.FocusDistance" in self.data:
            pair = self.rational("focus_distance", "Exif.OlympusFi.FocusDistance")
            fields["focus_tag_mm"] = self.quiet_distance(makernotes.olympus_focus_distance_mm(*pair) if pair else None)
        for key in ("Exif.MinoltaCsNew.FocusDistance", "Exif.MinoltaCsOld.FocusDistance"):
            raw = self.integer("focus_distance", key)
            if raw is not None and fields.get("focus_tag_mm") is None:
                fields["focus_tag_mm"] = self.quiet_distance(makernotes.minolta_focus_distance_mm(raw))
        for key in ("Exif.Photo.SubjectDistance", "Exif.Image.SubjectDistance"):
            pair = self.rational("focus_distance", key) if key in self.data else None
            if pair is not None and fields.get("subject_distance_mm") is None:
                fields["subject_distance_mm"] = self.quiet_distance(makernotes.exif_subject_distance_mm(*pair))
        for key in ("Exif.Casio2.ObjectDistance", "Exif.Casio.ObjectDistance"):
            raw = self.integer("focus_distance", key)
            if raw and fields.get("object_distance_mm") is None:
                fields["object_distance_mm"] = self.quiet_distance(
                    makernotes.casio_object_distance_mm(raw, key.endswith("2.ObjectDistance")))
        for upper_key, lower_key in (("Exif.CanonFi.FocusDistanceUpper", "Exif.CanonFi.FocusDistanceLower"),
                                     ("Exif.CanonSi.SubjectDistance", "Exif.CanonSi.0x0014")):
            upper = self.integer("focus_distance", upper_key)
            if upper and upper & 0xFFFF:  # ExifTool reads the pair only when the upper end is recorded
                lower = self.integer("focus_distance", lower_key) or 0
                fields["bracket_m"] = ((upper & 0xFFFF) / 100.0, (lower & 0xFFFF) / 100.0)
                return


def _short(key: str) -> str:
    """``Exif.Photo.FNumber`` -> ``Photo.FNumber``: the group and tag, as exiv2 names them."""
    return key[5:] if key.startswith("Exif.") else key


NOT_READ = "not an image libexiv2 can read"
_BMFF = ": an ISO BMFF file, which libexiv2 reads only when built with BMFF support"
_FORMAT_NOTES = {".x3f": " (Sigma X3F is not among libexiv2's formats)", ".cr3": f" (Canon CR3{_BMFF})",
                 ".heic": f" (HEIF{_BMFF})", ".heif": f" (HEIF{_BMFF})", ".avif": f" (AVIF{_BMFF})",
                 ".jxl": f" (JPEG XL{_BMFF})"}
"""Why a file of a known photo format may not be read, added to :data:`NOT_READ` by its suffix."""


def _reason(error: Exception) -> str:
    text = printable(str(getattr(error, "message", "") or error).strip())
    message = text.split("\\n")[0] if text else type(error).__name__
    lowered = message.lower()
    if "unknown image type" in lowered or "not an image" in lowered or "supported" in lowered:
        return NOT_READ
    if "failed to open" in lowered or "no such file" in lowered:
        return "cannot be opened"
    if any(word in lowered for word in ("corrupt", "eof", "truncat", "exceeds", "failed to read")):
        return f"truncated or corrupt ({message[:1].lower() + message[1:]})"
    return message
