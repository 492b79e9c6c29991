"""Read what a photo's metadata says about the shot, with python-exiv2 (libexiv2).

python-exiv2 is the optional ``exif`` extra (``pip install 'camtool[exif]'``);
it is imported only here, on the ``camtool exif`` path. Every value comes with
the tag it came from (``sources``) so a reader of the output can check it;
values the file does not carry are None, never guessed.

The focus distance is read, most specific first: the maker note's recorded
bracket (Canon FocusDistanceUpper/Lower), the maker note's single distance
(Nikon lens data, Olympus focus info, Canon ShotInfo), then Exif
SubjectDistance. The conversions are in :mod:`camtool.exif.makernotes`.

References
----------
python-exiv2 (https://python-exiv2.readthedocs.io): ``ImageFactory.open``,
``Image.readMetadata``, ``Image.exifData``, ``Exifdatum.toFloat``/``toRational``/``toInt64``;
Exif 2.32 (CIPA DC-008-2019) for the standard tags.
"""

from __future__ import annotations

import math
from typing import Any, NamedTuple

from camtool.core.errors import CamtoolError
from camtool.exif import makernotes


class ExifUnavailable(CamtoolError, ImportError):
    """python-exiv2 is not installed; the message says what to install."""


class UnreadableFile(Exception):
    """The file could not be read as an image with metadata; the message says why (one line)."""


class Reading(NamedTuple):
    """What one file's metadata says, in mm, seconds and ISO; None where it says nothing.

    ``sources`` maps each field name to the tag (exiv2 key) it came from.
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
    sources: dict[str, str] = {}  # noqa: RUF012 - NamedTuple default, never mutated (a fresh dict per reading)


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
})


def _exiv2() -> Any:
    try:
        import exiv2
    except ImportError:
        raise ExifUnavailable("camtool exif needs python-exiv2: pip install 'camtool[exif]' (or pip install exiv2)") \
            from None
    # our own one-line messages replace libexiv2's warnings on stderr
    exiv2.LogMsg.setLevel(exiv2.LogMsg.Level.mute)
    return exiv2


def require_exiv2() -> None:
    """Raise :class:`ExifUnavailable` unless python-exiv2 can be imported."""
    _exiv2()


def read_file(path: str) -> Reading:
    """Read the shot's settings from the image at ``path``.

    Raises
    ------
    ExifUnavailable
        python-exiv2 is not installed.
    UnreadableFile
        Not a file, not an image libexiv2 knows, truncated, or without any
        Exif metadata (the message says which).
    """
    exiv2 = _exiv2()
    try:
        image = exiv2.ImageFactory.open(path)
        image.readMetadata()
    except exiv2.Exiv2Error as error:
        raise UnreadableFile(_reason(error)) from None
    except OSError as error:
        raise UnreadableFile(error.strerror or str(error)) from None
    data = {datum.key(): datum for datum in image.exifData() if datum.key() in _WANTED}
    if not data:
        raise UnreadableFile("no Exif metadata")
    sources: dict[str, str] = {}
    fields: dict[str, Any] = {"sources": sources}

    def text(name: str, *keys: str) -> None:
        for key in keys:
            if key in data:
                value = data[key].toString().strip().strip("\x00").strip()
                if value:
                    fields[name], sources[name] = value, _short(key)
                    return

    def number(name: str, *keys: str, convert: Any = None) -> None:
        for key in keys:
            if key in data:
                value = _float(data[key])
                if value is not None and convert is not None:
                    value = convert(value)
                if value is not None and math.isfinite(value) and value > 0:
                    fields[name], sources[name] = value, _short(key)
                    return

    text("make", "Exif.Image.Make")
    text("model", "Exif.Image.Model")
    text("lens", "Exif.Photo.LensModel", "Exif.Canon.LensModel")
    number("focal_length_mm", "Exif.Photo.FocalLength", "Exif.Image.FocalLength")
    number("focal_length_35mm", "Exif.Photo.FocalLengthIn35mmFilm")
    # FNumber; else the APEX aperture value Av, N = 2^(Av/2) (Exif 2.32 ApertureValue)
    number("f_number", "Exif.Photo.FNumber", "Exif.Image.FNumber")
    number("f_number", "Exif.Photo.ApertureValue", convert=lambda av: 2.0 ** (av / 2.0)) \
        if "f_number" not in fields else None
    # ExposureTime; else the APEX shutter speed value Tv, t = 2^(−Tv) (Exif 2.32 ShutterSpeedValue)
    number("shutter_s", "Exif.Photo.ExposureTime", "Exif.Image.ExposureTime")
    if "shutter_s" not in fields:
        number("shutter_s", "Exif.Photo.ShutterSpeedValue", convert=lambda tv: 2.0 ** (-tv))
    # ISOSpeedRatings is a 16-bit field: cameras write 65535 for ISO 65535 and above and put the value in
    # StandardOutputSensitivity or RecommendedExposureIndex (Exif 2.3, SensitivityType)
    number("iso", "Exif.Photo.ISOSpeedRatings", convert=lambda iso: iso if iso < 65535 else None)
    if "iso" not in fields:
        number("iso", "Exif.Photo.StandardOutputSensitivity", "Exif.Photo.RecommendedExposureIndex")
    _pixels(data, fields, image)
    _focal_plane(data, fields)
    _focus(data, fields)
    return Reading(**fields)


def _short(key: str) -> str:
    """``Exif.Photo.FNumber`` -> ``Photo.FNumber``: the group and tag, as exiv2 names them."""
    return key[5:] if key.startswith("Exif.") else key


def _reason(error: Exception) -> str:
    text = str(getattr(error, "message", "") or error).strip()
    message = text.splitlines()[0] if text else type(error).__name__
    lowered = message.lower()
    if "unknown image type" in lowered or "not an image" in lowered or "supported" in lowered:
        return "not an image libexiv2 can read"
    if "failed to open" in lowered or "no such file" in lowered:
        return "cannot be opened"
    if any(word in lowered for word in ("corrupt", "eof", "truncat", "exceeds", "failed to read")):
        return f"truncated or corrupt ({message[:1].lower() + message[1:]})"
    return message


def _float(datum: Any) -> float | None:
    try:
        if datum.count() < 1:
            return None
        num, den = datum.toRational(0)
        if den == 0:
            return None
        return float(num) / float(den)
    except Exception:  # a malformed value is treated as absent
        return None


def _int(datum: Any) -> int | None:
    try:
        return int(datum.toInt64(0)) if datum.count() >= 1 else None
    except Exception:
        return None


def _pixels(data: dict[str, Any], fields: dict[str, Any], image: Any) -> None:
    # The Exif image size (the one FocalPlaneXResolution refers to), else the image's own size
    for w_key, h_key in (("Exif.Photo.PixelXDimension", "Exif.Photo.PixelYDimension"),
                         ("Exif.Image.ImageWidth", "Exif.Image.ImageLength")):
        w = _int(data[w_key]) if w_key in data else None
        h = _int(data[h_key]) if h_key in data else None
        if w and h and w > 0 and h > 0:
            fields["pixels_w"], fields["pixels_h"] = w, h
            fields["sources"]["pixels"] = f"{_short(w_key)}/{_short(h_key).rsplit('.', 1)[1]}"
            return
    try:
        w, h = int(image.pixelWidth()), int(image.pixelHeight())
    except Exception:
        return
    if w > 0 and h > 0:
        fields["pixels_w"], fields["pixels_h"] = w, h
        fields["sources"]["pixels"] = "image size"


def _focal_plane(data: dict[str, Any], fields: dict[str, Any]) -> None:
    """Sensor size from FocalPlaneX/YResolution (pixels per unit on the sensor) and the image size."""
    w, h = fields.get("pixels_w"), fields.get("pixels_h")
    if not (w and h):
        return
    for group in ("Photo", "Image"):
        x_key, y_key = f"Exif.{group}.FocalPlaneXResolution", f"Exif.{group}.FocalPlaneYResolution"
        unit_key = f"Exif.{group}.FocalPlaneResolutionUnit"
        x = _float(data[x_key]) if x_key in data else None
        y = _float(data[y_key]) if y_key in data else x
        unit = _int(data[unit_key]) if unit_key in data else 2  # Exif default: inches
        if x and y and x > 0 and y > 0 and unit in _RESOLUTION_UNIT_MM:
            width, height = w / x * _RESOLUTION_UNIT_MM[unit], h / y * _RESOLUTION_UNIT_MM[unit]
            # a diagonal outside 1 to 100 mm is a resized image or a wrong unit, not a sensor (the same
            # sanity check as ExifTool's CalcScaleFactor35efl); the next source is used instead
            if 1.0 < math.hypot(width, height) < 100.0:
                fields["plane_width_mm"], fields["plane_height_mm"] = width, height
                fields["sources"]["sensor"] = f"{group}.FocalPlaneX/YResolution"
                return


def _focus(data: dict[str, Any], fields: dict[str, Any]) -> None:
    sources = fields["sources"]
    upper = _int(data["Exif.CanonFi.FocusDistanceUpper"]) if "Exif.CanonFi.FocusDistanceUpper" in data else None
    lower = _int(data["Exif.CanonFi.FocusDistanceLower"]) if "Exif.CanonFi.FocusDistanceLower" in data else None
    far = makernotes.canon_focus_distance_mm(upper) if upper is not None else None
    near = makernotes.canon_focus_distance_mm(lower) if lower is not None else None
    if far is not None and near is not None:
        near, far = min(near, far), max(near, far)
        fields["focus_distance_min_mm"], fields["focus_distance_max_mm"] = near, far
        # ExifTool's DOF takes the middle of the bracket (Composite.pm, DOF); the geometric mean would be
        # no better founded, and the bracket's ends are reported beside it.
        fields["focus_distance_mm"] = (near + far) / 2.0 if math.isfinite(far) else far
        sources["focus_distance"] = "CanonFi.FocusDistanceUpper/Lower (middle)"
        return
    if far is not None:
        fields["focus_distance_mm"], sources["focus_distance"] = far, "CanonFi.FocusDistanceUpper"
        return
    for key in ("Exif.NikonLd3.FocusDistance", "Exif.NikonLd4.FocusDistance", "Exif.NikonLd2.FocusDistance"):
        raw = _int(data[key]) if key in data else None
        if raw:  # 0 is written by lenses without a distance encoder
            fields["focus_distance_mm"], sources["focus_distance"] = makernotes.nikon_focus_distance_mm(raw), _short(key)
            return
    if "Exif.OlympusFi.FocusDistance" in data:
        try:
            num, den = data["Exif.OlympusFi.FocusDistance"].toRational(0)
        except Exception:
            num, den = 0, 1
        value = makernotes.olympus_focus_distance_mm(num, den)
        if value is not None:
            fields["focus_distance_mm"], sources["focus_distance"] = value, "OlympusFi.FocusDistance"
            return
    if "Exif.CanonSi.SubjectDistance" in data:
        raw = _int(data["Exif.CanonSi.SubjectDistance"])
        value = makernotes.canon_focus_distance_mm(raw) if raw is not None else None
        if value is not None:
            fields["focus_distance_mm"], sources["focus_distance"] = value, "CanonSi.SubjectDistance"
            return
    for key in ("Exif.Photo.SubjectDistance", "Exif.Image.SubjectDistance"):
        if key in data:
            try:
                num, den = data[key].toRational(0)
            except Exception:
                continue
            value = makernotes.exif_subject_distance_mm(num, den)
            if value is not None:
                fields["focus_distance_mm"], sources["focus_distance"] = value, _short(key)
                return
