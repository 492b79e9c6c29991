"""The sensor size and the lens of a shot, from its metadata and the preset database.

Order of trust for the sensor (docs/exif.md):

1. FocalPlaneX/YResolution with the image size: the camera's own statement
   of how many pixels it puts on a unit of the focal plane;
2. (the crop factor form: a diagonal 43.27 mm over the factor, with the
   aspect ratio of the image, 3:2 when the file gives no size);
3. the maker note's sensor data libexiv2 decodes: Canon's focal-plane
   size (FocalPlaneX/YSize), Olympus's focal-plane diagonal with the image's
   aspect ratio, Nikon's pixel size times the image size;
4. the 35 mm-equivalent focal length (FocalLengthIn35mmFilm) over the focal
   length, as in 2;
5. a camera preset whose name (or alias) matches the file's Make and Model.

:func:`exiftool_scale_factor` is ExifTool's own order (its
Composite:ScaleFactor35efl), for the ExifTool-compatible mode.
"""

from __future__ import annotations

import math
import re
from typing import Any

from camtool.core.record import NamedTuple

FULL_FRAME_DIAGONAL_MM = math.hypot(36.0, 24.0)


class SensorSize(NamedTuple):
    """Sensor width and height in mm (width the long side), its crop factor, and where it came from."""

    width_mm: float
    height_mm: float
    crop_factor: float
    source: str


def from_crop(crop: float, pixels_w: int | None, pixels_h: int | None, source: str) -> SensorSize:
    """A sensor of diagonal 43.27 mm / ``crop`` with the image's aspect ratio (3:2 without one).

    Formula: d = √(36² + 24²)/k; w = d·cos(atan(r⁻¹)), h = w/r for the aspect
    ratio r = long/short side (the ExifTool ScaleFactor35efl convention:
    the crop factor is the ratio of the diagonals).

    Examples
    --------
    >>> s = from_crop(1.5, 6000, 4000, "x")
    >>> round(s.width_mm, 3), round(s.height_mm, 3)
    (24.0, 16.0)
    >>> round(from_crop(2.0, 4000, 3000, "x").width_mm, 3)
    17.307
    """
    diagonal = FULL_FRAME_DIAGONAL_MM / crop
    ratio = max(pixels_w, pixels_h) / min(pixels_w, pixels_h) if pixels_w and pixels_h else 1.5
    height = diagonal / math.hypot(ratio, 1.0)
    return SensorSize(height * ratio, height, crop, source)


def from_plane(width_mm: float, height_mm: float, source: str) -> SensorSize:
    """A sensor of the given size (long side first), with its crop factor 43.27 mm / diagonal.

    Examples
    --------
    >>> s = from_plane(15.6, 23.5, "x")
    >>> s.width_mm, s.height_mm, round(s.crop_factor, 3)
    (23.5, 15.6, 1.534)
    """
    w, h = max(width_mm, height_mm), min(width_mm, height_mm)
    return SensorSize(w, h, FULL_FRAME_DIAGONAL_MM / math.hypot(w, h), source)


def normalise(name: str) -> str:
    """A name for matching: lower case, letters and digits only, ``f/1.8`` and ``F1.8`` alike.

    Examples
    --------
    >>> normalise("Canon EF 50mm f/1.8 STM") == normalise("CANON EF50MM F1.8 STM")
    True
    """
    return re.sub(r"[^a-z0-9.]", "", name.lower().replace("f/", "f"))


def camera_names(make: str | None, model: str | None) -> list[str]:
    """The strings a camera preset may be called by for this Make and Model (normalised).

    Makers repeat the make in the model ("Canon" + "Canon EOS R5") or not
    ("NIKON CORPORATION" + "NIKON Z 6"; "SONY" + "ILCE-7M3"); both the model
    alone and the make's first word followed by the model are tried.

    Examples
    --------
    >>> camera_names("NIKON CORPORATION", "NIKON Z 6")
    ['nikonz6']
    >>> camera_names("SONY", "ILCE-7M3")
    ['ilce7m3', 'sonyilce7m3']
    """
    if not model:
        return []
    names = [normalise(model)]
    if make:
        first = make.split()[0]
        if not model.lower().startswith(first.lower()):
            names.append(normalise(f"{first} {model}"))
    return names


def name_index(presets: Any) -> dict[str, list[Any]]:
    """Presets by every normalised id, name and alias (built once per run, then looked up per file)."""
    index: dict[str, list[Any]] = {}
    for preset in presets:
        for name in {normalise(preset.id), normalise(preset.name), *(normalise(a) for a in preset.aliases)}:
            index.setdefault(name, []).append(preset)
    return index


def match_preset(index: dict[str, list[Any]], names: list[str]) -> Any:
    """The one preset an index holds under any of ``names``; None if none, or several different ones.

    Examples
    --------
    >>> from types import SimpleNamespace as P
    >>> index = name_index([P(id="nikon-d850", name="Nikon D850", aliases=("d850",))])
    >>> match_preset(index, camera_names("NIKON CORPORATION", "NIKON D850")).id
    'nikon-d850'
    >>> match_preset(index, ["d85"]) is None
    True
    """
    found = {id(p): p for name in names for p in index.get(name, ())}
    return next(iter(found.values())) if len(found) == 1 else None


def canon_plane_ok(width_mm: float, height_mm: float) -> bool:
    """Whether Canon's FocalPlaneX/YSize pair is a sensor: a 4:3 or 3:2 aspect ratio within 0.1 (ExifTool's check).

    >>> canon_plane_ok(23.2156, 15.494), canon_plane_ok(770.7, 1046.3)
    (True, False)
    """
    ratio = width_mm / height_mm
    return abs(ratio - 1.3333) < 0.1 or abs(ratio - 1.5) < 0.1


class ScaleFactor(NamedTuple):
    """ExifTool's ScaleFactor35efl and the rule that gave it (named as in ExifTool's tags)."""

    factor: float
    source: str


def exiftool_scale_factor(*, focal_length_mm: float | None, focal_length_35mm: float | None,
                          digital_zoom: float | None = None, diagonal_mm: float | None = None,
                          canon_sensor_mm: tuple[float, float] | None = None,
                          plane_size_mm: tuple[float, float] | None = None,
                          px_per_mm: tuple[float, float] | None = None,
                          sizes: tuple[tuple[int, int, str], ...] = ()) -> ScaleFactor | None:
    """ExifTool's Composite:ScaleFactor35efl: the 35 mm equivalent over the focal length, else 43.27 mm · zoom / diagonal.

    The order is ExifTool 12.57's (``Image::ExifTool::Exif::CalcScaleFactor35efl``):
    FocalLengthIn35mmFormat / FocalLength when both are known; else the
    diagonal of the focal plane times Canon's digital zoom ratio, the
    diagonal being Canon's sensor (from the focal-plane resolution's
    denominators), else Olympus's FocalPlaneDiagonal, else Canon's
    FocalPlaneX/YSize when their aspect ratio is 4:3 or 3:2, else the first
    image size (Exif, Canon's maker note, the file's own) with an aspect
    ratio between 1:2 and 2:1 over the focal-plane resolution, kept only for
    a diagonal between 1 and 100 mm.

    Examples
    --------
    >>> exiftool_scale_factor(focal_length_mm=28.0, focal_length_35mm=42.0).factor
    1.5
    >>> round(exiftool_scale_factor(focal_length_mm=23.4, focal_length_35mm=None, diagonal_mm=9.04).factor, 5)
    4.78613
    """
    if focal_length_mm and focal_length_35mm:
        return ScaleFactor(focal_length_35mm / focal_length_mm, "FocalLengthIn35mmFilm / FocalLength")
    zoom = digital_zoom or 1.0
    diagonal, source = None, ""
    if canon_sensor_mm is not None:
        diagonal, source = math.hypot(*canon_sensor_mm), "Canon sensor (FocalPlaneX/YResolution denominators)"
    elif diagonal_mm:
        diagonal, source = diagonal_mm, "Olympus FocalPlaneDiagonal"
    elif plane_size_mm is not None and canon_plane_ok(*plane_size_mm):
        diagonal, source = math.hypot(*plane_size_mm), "Canon FocalPlaneX/YSize"
    if diagonal is None and px_per_mm is not None:
        for w, h, tag in sizes:
            if w and h and 0.5 < w / h < 2:
                candidate = math.hypot(w / px_per_mm[0], h / px_per_mm[1])
                if not 1.0 < candidate < 100.0:
                    return None
                diagonal, source = candidate, f"FocalPlaneX/YResolution with {tag}"
                break
    if not diagonal:
        return None
    if zoom != 1.0:
        source += f" × Canon digital zoom {zoom:g}"
    return ScaleFactor(FULL_FRAME_DIAGONAL_MM * zoom / diagonal, source)
