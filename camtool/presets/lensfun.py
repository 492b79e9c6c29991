"""Import the lensfun database installed on this system as a camtool preset file.

lensfun (used by darktable and RawTherapee; Debian package
``liblensfun-data-v1``) describes cameras and lenses in XML files under
``/usr/share/lensfun/version_1/``, with newer copies in
``/var/lib/lensfun-updates`` and ``~/.local/share/lensfun``. camtool ships no
copy of it (its licence is CC BY-SA 3.0); this module reads the user's own
copy at run time with :mod:`xml.etree.ElementTree` and writes
``$XDG_DATA_HOME/camtool/lensfun.yaml``, which :func:`camtool.presets.load_db`
reads as the "lensfun" tier.

What is kept:

- each ``<camera>`` becomes a *camera* preset named after its maker and model
  (``Ricoh GR III`` gives ``ricoh-gr-iii``: the maker's English name where
  lensfun gives one, else its name without "Imaging Company, Ltd." and the
  like; the model's English name where given, the other spelling kept as an
  alias). lensfun gives only a crop factor, so its sensor size is derived
  from it: diagonal 43.27 mm / crop, in the aspect ratio of the body itself.
  lensfun records an aspect ratio only on lenses, and on an interchangeable
  lens it is the ratio of whatever body the lens was calibrated on (a Sigma
  lens made for both Sony E and Micro Four Thirds says 4:3), so it is used
  only from the body's own fixed lens: a lens named "fixed lens" or
  "Standard", or one made for that mount alone when no lens on the mount
  serves another mount and the lenses on it agree. Otherwise 3:2 for crop
  factors 0.9 to 1.8 (35 mm and APS bodies) and 4:3 otherwise (medium
  format, Four Thirds, compacts); every such camera is marked
  ``approximate``;
- a camera whose mount carries a fixed lens (a compact) becomes a camera with
  ``mount: fixed lens`` and its own lens: ``<camera id>-lens`` (a converter
  variant such as lensfun's "fixed lens, with GW-4" becomes
  ``<camera id>-lens-with-gw-4``), made for that camera's sensor, so
  ``--camera`` brings the lens's focal length and f-number; an
  interchangeable body keeps its lensfun mount;
- each other ``<lens>`` becomes a lens preset with its focal length or range and
  widest f-number, taken from ``<focal>`` / ``<aperture>`` when present, else
  parsed from the model name (``18-55mm f/3.5-5.6``, ``1:2``, ``2.8/50``),
  else from the range of its calibration data, as lensfun itself does.

Entries that clash with camtool's shipped presets or with an earlier entry,
or whose focal length cannot be found, are skipped and counted; an entry
whose figures do not validate (a model named "0mm" gives a focal length of
0) is skipped and named in the reason; a file that cannot be parsed is
reported and skipped, never failing the import. A lensfun lens is taken to
be a shipped preset when its name, with or without the maker in front,
matches a shipped lens's id, name or alias (the shipped lenses carry
lensfun's spelling as an alias), so a body imported from lensfun finds the
shipped lens instead of a second, uncited copy of it.

The output file keeps the permission bits of the file it replaces (a new
file gets 0644); an output path that exists and is not a regular file (a
directory, a device, a FIFO) is refused before anything is read.
"""

from __future__ import annotations

import contextlib
import math
import os
import re
from collections import Counter
from collections.abc import Callable
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any
from xml.etree import ElementTree

from camtool.core.errors import CamtoolError
from camtool.core.files import FileProblem, read_bytes
from camtool.presets import paths
from camtool.presets.schema import FULL_FRAME_DIAGONAL_MM, check_record, normalize, slugify

_NUMBER = r"(\d+(?:[.,]\d+)?)"
_FOCAL_IN_NAME = re.compile(rf"(?<![\d.]){_NUMBER}(?:\s*-\s*{_NUMBER})?\s*mm", re.IGNORECASE)
_APERTURE_IN_NAME = re.compile(rf"(?:(?<![a-z])|(?<=mm))f\s*/?\s*{_NUMBER}(?:\s*-\s*{_NUMBER})?", re.IGNORECASE)
_RATIO_IN_NAME = re.compile(rf"(?<![\d.])1\s*:\s*{_NUMBER}(?:\s*-\s*{_NUMBER})?")
_ZEISS_STYLE = re.compile(rf"(?<![\d.]){_NUMBER}\s*/\s*(\d+)(?![\d.])")
_ASPECT = re.compile(r"^\s*(\d+(?:\.\d+)?)\s*:\s*(\d+(?:\.\d+)?)\s*$")
_GENERIC_LENS_NAMES = {"fixedlens", "standard"}


@dataclass
class ImportResult:
    """What an import did: counts, the reasons entries were skipped, files that failed."""

    cameras: int = 0
    lenses: int = 0
    files: int = 0
    skipped: Counter[str] = field(default_factory=Counter)
    bad_files: list[tuple[str, str]] = field(default_factory=list)
    path: str | None = None

    @property
    def imported(self) -> int:
        """Presets written (cameras plus lenses)."""
        return self.cameras + self.lenses

    @property
    def skipped_total(self) -> int:
        """Entries and files left out."""
        return sum(self.skipped.values()) + len(self.bad_files)


MAX_XML_BYTES = 16 * 1024 * 1024
"""Largest lensfun XML file read (the largest of lensfun's own is under 1 MiB)."""


class LensfunImportError(CamtoolError):
    """Nothing could be imported (no lensfun data found, or the output cannot be written)."""


def default_dirs() -> list[Path]:
    """The lensfun data directories on this system that hold XML files, least important first."""
    data_home = Path(os.environ.get("XDG_DATA_HOME", "") or Path.home() / ".local" / "share")
    bases = [Path("/usr/share/lensfun"), Path("/usr/local/share/lensfun"), Path("/var/lib/lensfun-updates"),
             data_home / "lensfun", data_home / "lensfun" / "updates"]
    found = []
    for base in bases:
        for candidate in (base / "version_1", base):
            if candidate.is_dir() and any(candidate.glob("*.xml")):
                found.append(candidate)
                break
    return found


def parse_focal(name: str) -> tuple[float, float] | None:
    """Focal length range in mm from a lens model name.

    >>> parse_focal("Canon EF-S 18-55mm f/3.5-5.6 IS STM")
    (18.0, 55.0)
    >>> parse_focal("XF18mmF2 R"), parse_focal("Touit 2.8/50M"), parse_focal("fixed lens")
    ((18.0, 18.0), (50.0, 50.0), None)
    """
    match = _FOCAL_IN_NAME.search(name)
    if match:
        low = _float(match.group(1))
        return low, _float(match.group(2)) if match.group(2) else low
    match = _ZEISS_STYLE.search(name)
    if match:
        focal = _float(match.group(2))
        return focal, focal
    return None


def parse_aperture(name: str) -> float | None:
    """The widest f-number from a lens model name (``f/2.8``, ``F4``, ``1:2``, ``2.8/50``).

    >>> parse_aperture("Nikon AF-S DX Zoom-Nikkor 16-85mm f/3.5-5.6G ED VR")
    3.5
    >>> parse_aperture("smc Pentax-M 35mm 1:2"), parse_aperture("XF18mmF2 R"), parse_aperture("FE 24mm")
    (2.0, 2.0, None)
    """
    for pattern in (_APERTURE_IN_NAME, _RATIO_IN_NAME):
        match = pattern.search(name)
        if match:
            return _float(match.group(1))
    match = _ZEISS_STYLE.search(name)
    return _float(match.group(1)) if match else None


def parse_aperture_tele(name: str) -> float | None:
    """The widest f-number at the long end of a variable-aperture zoom, from its name.

    >>> parse_aperture_tele("Canon EF-S 18-55mm f/3.5-5.6 IS STM"), parse_aperture_tele("FE 50mm F1.8")
    (5.6, None)
    """
    for pattern in (_APERTURE_IN_NAME, _RATIO_IN_NAME):
        match = pattern.search(name)
        if match:
            return _float(match.group(2)) if match.group(2) else None
    return None


def sensor_size(crop_factor: float, aspect: float | None = None) -> tuple[float, float]:
    """Width and height in mm of a format with this crop factor (aspect = width / height).

    >>> tuple(round(x, 2) for x in sensor_size(1.0))
    (36.0, 24.0)
    >>> tuple(round(x, 2) for x in sensor_size(2.0))
    (17.31, 12.98)
    """
    if aspect is None:
        aspect = 1.5 if 0.9 <= crop_factor <= 1.8 else 4.0 / 3.0
    diagonal = FULL_FRAME_DIAGONAL_MM / crop_factor
    height = diagonal / math.hypot(aspect, 1.0)
    return aspect * height, height


def _float(text: str) -> float:
    return float(text.replace(",", "."))


def _text(element: ElementTree.Element, tag: str) -> str | None:
    """The text of the first child ``tag`` without a ``lang`` attribute (lensfun's default language)."""
    fallback = None
    for child in element.findall(tag):
        value = " ".join((child.text or "").split())
        if not value:
            continue
        if "lang" not in child.attrib:
            return value
        fallback = fallback or value
    return fallback


def _positive(value: Any) -> float | None:
    try:
        number = _float(str(value))
    except (TypeError, ValueError):
        return None
    return number if number > 0 and math.isfinite(number) else None


def _aspect(text: str | None) -> float | None:
    match = _ASPECT.match(text or "")
    if not match:
        return None
    width, height = float(match.group(1)), float(match.group(2))
    return width / height if width > 0 and height > 0 else None


def _display_name(maker: str | None, model: str) -> str:
    if maker and not normalize(model).startswith(normalize(maker)):
        return f"{maker} {model}"
    return model


def _english(element: ElementTree.Element, tag: str) -> str | None:
    """The text of the child ``tag`` marked ``lang="en"``, if any."""
    for child in element.findall(tag):
        value = " ".join((child.text or "").split())
        if value and child.attrib.get("lang") == "en":
            return value
    return None


# Words after which a maker's registered name is only its legal form ("Ricoh Imaging Company,
# Ltd.", "Leica Camera AG", "Casio Computer Co.,Ltd"): the name a photographer uses ends before them.
_CORPORATE_WORDS = {"imaging", "company", "co", "corp", "corporation", "ltd", "limited", "inc", "camera", "ag",
                    "gmbh", "optical", "computer", "techwin"}


def short_maker(name: str | None) -> str | None:
    """A maker's everyday name from lensfun's registered one.

    >>> short_maker("Ricoh Imaging Company, Ltd."), short_maker("Casio Computer Co.,Ltd"), short_maker("SIGMA")
    ('Ricoh', 'Casio', 'Sigma')
    >>> short_maker("Konica Minolta"), short_maker("DJI"), short_maker(None)
    ('Konica Minolta', 'DJI', None)
    """
    if not name:
        return None
    kept: list[str] = []
    for word in name.replace(",", " ").split():
        if kept and word.lower().rstrip(".") in _CORPORATE_WORDS:
            break
        kept.append(word)
    short = " ".join(kept)
    return short.title() if short.isupper() and len(short) > 3 else short


def _maker(element: ElementTree.Element) -> str | None:
    return short_maker(_english(element, "maker") or _text(element, "maker"))


def camera_name(camera: ElementTree.Element) -> tuple[str, list[str]] | None:
    """A lensfun camera's display name (maker and model) and its other spellings, or None without a model.

    The model's English name wins where lensfun gives one (Nikon's "Z 6II" for "Nikon Z 6_2");
    the other spelling is kept as an alias.
    """
    default = _COMPATIBLES.sub("", _text(camera, "model") or "") or None
    english = _COMPATIBLES.sub("", _english(camera, "model") or "") or None
    model = english or default
    if not model:
        return None
    maker = _maker(camera)
    name = _display_name(maker, model)
    variant = _text(camera, "variant")
    if variant:
        name = f"{name} ({variant})"
    others = [_display_name(maker, default)] if default and english and normalize(default) != normalize(english) else []
    return name, others


_COMPATIBLES = re.compile(r"\s*&\s*compatibles\b", re.IGNORECASE)
_STANDARD_SUFFIX = re.compile(r"\s*\(standard\)\s*$", re.IGNORECASE)


def _fixed_lens(lens: ElementTree.Element) -> str | None:
    """None for an interchangeable lens; for a compact's own lens, the suffix of its variant ("" for the lens itself).

    lensfun names a body's built-in lens "fixed lens" (in English), "Standard", or "<body> &
    compatibles (Standard)"; "fixed lens, with GW-4" and "<body> & compatibles, with WCL-X100" are
    the same lens with a converter.

    >>> lens = ElementTree.fromstring("<lens><model>X100V &amp; compatibles, with WCL-X100</model></lens>")
    >>> _fixed_lens(lens), _fixed_lens(ElementTree.fromstring("<lens><model>XF 23mm F2</model></lens>"))
    (', with WCL-X100', None)
    """
    texts = [" ".join((child.text or "").split()) for child in lens.findall("model")]
    for text in texts:
        key = normalize(text)
        if key in _GENERIC_LENS_NAMES or key.startswith("standard") or "(standard)" in text.lower():
            return ""
    for text in texts:
        if text.lower().startswith("fixed lens"):
            return text[len("fixed lens"):]
    for text in texts:
        match = _COMPATIBLES.search(text)
        if match:
            return _STANDARD_SUFFIX.sub("", text[match.end():])
    return None


class _Collector:
    """Accumulates records from the XML files, skipping clashes."""

    def __init__(self, taken: dict[str, set[str]]) -> None:
        self.taken = taken
        self.cameras: list[dict[str, Any]] = []
        self.lenses: list[dict[str, Any]] = []
        self.keys: dict[str, set[str]] = {"camera": set(), "lens": set()}
        self.result = ImportResult()
        self.mount_cameras: dict[str, list[tuple[str, str]]] = {}
        self.mount_aspect: dict[str, float] = {}
        # Mounts that carry a body's own lens (a compact's "mount" names the body, not a system).
        self.fixed_mounts: set[str] = set()
        # Aspect ratios seen on each mount: from fixed lenses, from single-mount lenses; mounts
        # that a multi-mount lens also serves (interchangeable mounts shared with other systems).
        self.fixed_aspects: dict[str, set[float]] = {}
        self.single_mount_aspects: dict[str, set[float]] = {}
        self.shared_mounts: set[str] = set()

    def settle_aspects(self) -> None:
        """Decide each mount's aspect ratio once every file has been scanned (see the module notes)."""
        for mount in set(self.fixed_aspects) | set(self.single_mount_aspects):
            ratios = self.fixed_aspects.get(mount)
            if not ratios and mount not in self.shared_mounts:
                ratios = self.single_mount_aspects.get(mount)
            if ratios and len(ratios) == 1:
                self.mount_aspect[mount] = next(iter(ratios))

    def add(self, kind: str, record: dict[str, Any], model: str = "") -> bool:
        key = normalize(record["id"])
        if not key:
            self.result.skipped[f"{kind}: no usable name"] += 1
            return False
        if self._shipped(kind, record):
            self.result.skipped[f"{kind}: already in camtool's shipped presets"] += 1
            return False
        _, problems = check_record(kind, {k: v for k, v in record.items() if not k.startswith("_")})
        if problems:
            name, problem = problems[0]
            self.result.skipped[f"{kind}: {model or record['name']!r}: {name} {problem}"] += 1
            return False
        if key in self.keys[kind]:
            self.result.skipped[f"{kind}: listed more than once"] += 1
            return False
        self.keys[kind].add(key)
        # An alias another entry (or a shipped preset) already answers to is dropped, not fatal.
        aliases = [alias for alias in record.get("aliases", ())
                   if normalize(alias) not in self.keys[kind] and normalize(alias) not in self.taken.get(kind, set())]
        if aliases:
            record["aliases"] = aliases
            self.keys[kind].update(normalize(alias) for alias in aliases)
        else:
            record.pop("aliases", None)
        self.keys[kind].add(normalize(record["name"]))
        (self.cameras if kind == "camera" else self.lenses).append(record)
        return True

    def _shipped(self, kind: str, record: dict[str, Any]) -> bool:
        taken = self.taken.get(kind, set())
        keys = {normalize(record["id"])}
        for name in (record["name"], *record.get("aliases", ())):
            keys |= match_keys(name, record.get("_maker"))
        return any(key in taken for key in keys)


_MAKER_WORDS = {"canon": ("canon",), "nikon": ("nikon", "nikkor"), "sony": ("sony",),
                "fujifilm": ("fujifilm", "fujinon", "fuji"), "fuji": ("fujifilm", "fujinon", "fuji"),
                "olympus": ("olympus", "omsystem", "om", "mzuiko", "zuiko"), "omsystem": ("omsystem", "om", "olympus"),
                "panasonic": ("panasonic", "lumix"), "leica": ("leica",), "sigma": ("sigma",), "tamron": ("tamron",),
                "zeiss": ("zeiss", "carlzeiss"), "hasselblad": ("hasselblad",), "samyang": ("samyang",),
                "ricoh": ("ricoh",), "pentax": ("pentax", "smcpentax")}


def match_keys(name: str, maker: str | None = None) -> set[str]:
    """Lookup keys under which a lensfun lens name matches a shipped preset.

    The name as it is, and without its maker's words in front, so lensfun's
    "Nikon NIKKOR Z 50mm f/1.8 S" meets the shipped "NIKKOR Z 50mm f/1.8 S".

    >>> sorted(match_keys("Nikon NIKKOR Z 50mm f/1.8 S", "Nikon"))
    ['nikkorz50mmf18s', 'nikonnikkorz50mmf18s', 'z50mmf18s']
    """
    key = normalize(name)
    keys = {key}
    words = _MAKER_WORDS.get(normalize(maker or ""), (normalize(maker or ""),) if maker else ())
    changed = True
    while changed:
        changed = False
        for word in words:
            if word and key.startswith(word) and len(key) > len(word) + 2:
                key = key[len(word):]
                keys.add(key)
                changed = True
    return keys

def _scan(root: ElementTree.Element, collector: _Collector) -> None:
    """First pass over a file: the bodies on each mount, fixed-lens mounts and their aspect ratios."""
    for camera in root.iter("camera"):
        mount, named = _text(camera, "mount"), camera_name(camera)
        if mount and named:
            collector.mount_cameras.setdefault(mount, []).append((named[0], slugify(named[0])))
    for lens_element in root.iter("lens"):
        aspect = _aspect(_text(lens_element, "aspect-ratio"))
        mounts = [m.text.strip() for m in lens_element.findall("mount") if m.text and m.text.strip()]
        if len(mounts) > 1:
            collector.shared_mounts.update(mounts)
        fixed = _fixed_lens(lens_element) is not None
        if fixed:
            collector.fixed_mounts.update(mounts)
        if not aspect:
            continue
        plain = _fixed_lens(lens_element) == ""
        for mount in mounts:
            target = collector.fixed_aspects if plain else collector.single_mount_aspects
            if plain or len(mounts) == 1:
                target.setdefault(mount, set()).add(round(aspect, 4))


def _cameras(root: ElementTree.Element, source: str, collector: _Collector) -> None:
    for camera in root.iter("camera"):
        named = camera_name(camera)
        crop = _positive(_text(camera, "cropfactor"))
        if not named or crop is None:
            collector.result.skipped["camera: no model or crop factor"] += 1
            continue
        name, others = named
        mount = _text(camera, "mount")
        aspect = collector.mount_aspect.get(mount or "")
        width, height = sensor_size(crop, aspect)
        ratio = "its fixed lens" if aspect else ("3:2" if 0.9 <= crop <= 1.8 else "4:3")
        record: dict[str, Any] = {"id": slugify(name), "name": name}
        if others:
            record["aliases"] = others
        record["sensor"] = {"width_mm": round(width, 3), "height_mm": round(height, 3)}
        if mount in collector.fixed_mounts:
            record["mount"] = "fixed lens"
            record["lens"] = f"{record['id']}-lens"
        elif mount:
            record["mount"] = mount
        record["approximate"] = True
        record["source"] = f"lensfun {source}: crop factor {crop:g}, sensor size derived (aspect from {ratio})"
        if mount in collector.fixed_mounts:
            record["notes"] = f"lensfun mount {mount}"
        record["_maker"] = _maker(camera)
        added = collector.add("camera", record, _text(camera, "model") or name)
        del record["_maker"]
        if added:
            collector.result.cameras += 1


def _calibration_range(lens: ElementTree.Element, attribute: str) -> list[float]:
    values = []
    for element in lens.iter():
        value = _positive(element.attrib.get(attribute))
        if value is not None and element.tag in {"distortion", "tca", "vignetting"}:
            values.append(value)
    return values


def _lenses(root: ElementTree.Element, source: str, collector: _Collector) -> None:
    for lens in root.iter("lens"):
        model = _text(lens, "model")
        if not model:
            collector.result.skipped["lens: no model"] += 1
            continue
        mounts = [m.text.strip() for m in lens.findall("mount") if m.text and m.text.strip()]
        maker = _maker(lens)
        figures = _lens_figures(lens, model)
        if figures is None:
            collector.result.skipped["lens: focal length unknown"] += 1
            continue
        crop = _positive(_text(lens, "cropfactor"))
        origin = f"lensfun {source}" + (f" (calibrated at crop factor {crop:g})" if crop else "")
        suffix = _fixed_lens(lens)
        if suffix is not None:
            # A compact's own lens: one preset for each body on its mount, made for that body's sensor.
            bodies = [body for mount in mounts for body in collector.mount_cameras.get(mount, [])]
            if not bodies:
                collector.result.skipped["lens: a fixed lens without its camera"] += 1
            for body_name, body_id in bodies:
                name = f"{body_name} lens{suffix}"
                record = {"id": slugify(name), "name": name, **figures, "mount": "fixed lens", "sensor": body_id,
                          "source": origin}
                if collector.add("lens", record, model):
                    collector.result.lenses += 1
            continue
        name = _display_name(maker, model)
        record = {"id": slugify(name), "name": name, **figures}
        if mounts:
            record["mount"] = mounts[0]
        record["source"] = origin
        record["_maker"] = maker
        added = collector.add("lens", record, model)
        del record["_maker"]
        if added:
            collector.result.lenses += 1


def _lens_figures(lens: ElementTree.Element, model: str) -> dict[str, Any] | None:
    """Focal length or range and the apertures of a lensfun lens, or None when no focal length is found."""
    focal = _element_range(lens, "focal") or parse_focal(model)
    if focal is None:
        calibrated = _calibration_range(lens, "focal")
        focal = (min(calibrated), max(calibrated)) if calibrated else None
    if focal is None:
        return None
    aperture_range = _element_range(lens, "aperture")
    aperture = aperture_range[0] if aperture_range else parse_aperture(model)
    if aperture is None:
        calibrated = _calibration_range(lens, "aperture")
        aperture = min(calibrated) if calibrated else None
    figures: dict[str, Any] = {}
    low, high = sorted(focal)
    if high > low:
        figures.update(focal_min_mm=low, focal_max_mm=high)
    else:
        figures["focal_length_mm"] = low
    if aperture is not None:
        figures["f_number_min"] = aperture
        tele = parse_aperture_tele(model) if not aperture_range else None
        if tele is not None and tele > aperture and high > low:
            figures["f_number_min_tele"] = tele
        if aperture_range and aperture_range[1] > aperture:
            figures["f_number_max"] = aperture_range[1]
    return figures


def _element_range(lens: ElementTree.Element, tag: str) -> tuple[float, float] | None:
    element = lens.find(tag)
    if element is None:
        return None
    low = _positive(element.attrib.get("min") or element.attrib.get("value"))
    high = _positive(element.attrib.get("max")) or low
    if low is None or high is None:
        return None
    return (low, high) if high >= low else (high, low)


def read_lensfun(dirs: list[Path] | None = None, taken: dict[str, set[str]] | None = None,
                 on_files: Callable[[int, int], None] | None = None
                 ) -> tuple[list[dict[str, Any]], list[dict[str, Any]], ImportResult]:
    """Read every ``*.xml`` of ``dirs`` (default :func:`default_dirs`); return cameras, lenses, result.

    ``taken`` maps a kind to lookup keys that must not be reused (camtool's
    shipped presets); clashing entries are skipped and counted. ``on_files(done, total)`` is told after
    each file (a progress bar's hook).
    """
    directories = default_dirs() if dirs is None else [Path(d) for d in dirs]
    files = [f for d in directories for f in sorted(Path(d).glob("*.xml"))]
    collector = _Collector(taken or {})
    parsed = []
    for done, path in enumerate(files):
        if on_files is not None:
            on_files(done, len(files))
        try:  # through the guarded reader: a FIFO or device named *.xml is refused at once, not waited on
            root = ElementTree.fromstring(read_bytes(path, MAX_XML_BYTES))
        except FileProblem as problem:
            collector.result.bad_files.append((str(path), problem.problem))
            continue
        except (ElementTree.ParseError, OSError, ValueError) as error:
            collector.result.bad_files.append((str(path), " ".join(str(error).split())))
            continue
        collector.result.files += 1
        parsed.append((path, root))
        _scan(root, collector)
    collector.settle_aspects()
    # Later directories (updates, the user's own) come first so that they win the clashes.
    for path, root in reversed(parsed):
        try:
            _cameras(root, path.name, collector)
        except (ValueError, TypeError, AttributeError) as error:
            collector.result.bad_files.append((str(path), f"cameras: {error}"))
    for path, root in reversed(parsed):
        try:
            _lenses(root, path.name, collector)
        except (ValueError, TypeError, AttributeError) as error:
            collector.result.bad_files.append((str(path), f"lenses: {error}"))
    _settle_references(collector)
    return collector.cameras, collector.lenses, collector.result


def _settle_references(collector: _Collector) -> None:
    """Drop a camera's ``lens`` or a lens's ``sensor`` that names nothing imported or shipped.

    A compact's lens can be skipped (its focal length unknown, a clash) while its camera is kept,
    and the other way round; a reference to a missing preset would make the whole file invalid.
    """
    lenses = collector.keys["lens"] | collector.taken.get("lens", set())
    cameras = collector.keys["camera"] | collector.taken.get("camera", set())
    for camera in collector.cameras:
        if "lens" in camera and normalize(camera["lens"]) not in lenses:
            del camera["lens"]
    for lens in collector.lenses:
        if "sensor" in lens and normalize(lens["sensor"]) not in cameras:
            del lens["sensor"]


def _shipped_keys() -> dict[str, set[str]]:
    from camtool.presets.loader import read_file

    keys: dict[str, set[str]] = {"camera": set(), "sensor": set(), "lens": set()}
    for path in paths.shipped_files():
        records = read_file(path).records
        for kind in keys:
            for record in records.get(kind, ()):
                keys[kind].update(record["_keys"])
                for name in [record.get("name", ""), *record.get("aliases", ())]:
                    words = str(name).split()
                    keys[kind].update(match_keys(str(name), words[0] if words else None))
    return keys


def import_lensfun(dirs: list[Path] | list[str] | None = None, out: str | os.PathLike[str] | None = None,
                   on_files: Callable[[int, int], None] | None = None) -> ImportResult:
    """Read the system's lensfun database and write it as a camtool preset file, atomically.

    ``dirs`` defaults to :func:`default_dirs`, ``out`` to
    ``$XDG_DATA_HOME/camtool/lensfun.yaml``. The file is written to a
    temporary name, validated, then moved into place, so a failed import
    leaves the previous file untouched. Raises :class:`LensfunImportError`
    when no lensfun XML is found or nothing can be imported.
    """
    target = _output_path(Path(out if out is not None else paths.lensfun_file()))
    directories = default_dirs() if dirs is None else [Path(d) for d in dirs]
    if not any(any(Path(d).glob("*.xml")) for d in directories):
        where = ", ".join(map(str, directories)) or "the usual places"
        raise LensfunImportError(
            f"no lensfun XML files found in {where} (install liblensfun-data-v1 or give --dir)")
    cameras, lenses, result = read_lensfun(directories, _shipped_keys(), on_files)
    if not cameras and not lenses:
        raise LensfunImportError(f"nothing imported from {', '.join(map(str, directories))}")
    _write_atomically(target, _render(cameras, lenses, directories))
    result.path = str(target)
    return result


NEW_FILE_MODE = 0o644
"""Permission bits of a new output file (a replaced file keeps its own)."""


def _output_path(target: Path) -> Path:
    """The file to write: ``target``, or the regular file a symbolic link names; refuse anything else.

    Checked before any lensfun file is read, so a wrong ``--out`` fails at once.
    """
    import stat

    try:
        mode = target.stat().st_mode
    except FileNotFoundError:
        if target.is_symlink():
            raise LensfunImportError(f"cannot write {target}: it is a symbolic link to a missing file") from None
        return target
    except OSError as error:
        raise LensfunImportError(f"cannot write {target}: {error.strerror or error}") from None
    if not stat.S_ISREG(mode):
        what = "a directory" if stat.S_ISDIR(mode) else "not a regular file"
        raise LensfunImportError(f"cannot write {target}: it is {what}")
    return Path(os.path.realpath(target)) if target.is_symlink() else target


def _render(cameras: list[dict[str, Any]], lenses: list[dict[str, Any]], dirs: list[Path]) -> str:
    import yaml

    dumper = getattr(yaml, "CSafeDumper", yaml.SafeDumper)
    body = yaml.dump({"cameras": cameras, "lenses": lenses}, Dumper=dumper, sort_keys=False, allow_unicode=True,
                     width=120, default_flow_style=None)
    header = (
        "# camtool presets imported from the lensfun database on this system\n"
        f"# by `camtool presets import-lensfun` from: {', '.join(map(str, dirs))}\n"
        "# lensfun data is licensed CC BY-SA 3.0 (https://lensfun.github.io/). Cameras' sensor sizes are\n"
        "# derived from crop factors and marked approximate. Re-run the import to refresh; do not edit.\n"
    )
    return header + body


def _write_atomically(target: Path, text: str) -> None:
    import stat
    import tempfile

    from camtool.presets.errors import PresetFileError
    from camtool.presets.loader import parse_file, read_file

    try:
        target.parent.mkdir(parents=True, exist_ok=True)
        # closed by hand below, after the rename, so a failed write can remove it
        handle = tempfile.NamedTemporaryFile("w", encoding="utf-8", dir=target.parent, prefix=".lensfun-",  # noqa: SIM115
                                             suffix=".yaml.tmp", delete=False)
    except OSError as error:
        raise LensfunImportError(f"cannot write {target}: {error.strerror or error}") from None
    try:
        with handle:
            handle.write(text)
        try:
            mode = stat.S_IMODE(target.stat().st_mode)
        except FileNotFoundError:
            mode = NEW_FILE_MODE
        os.chmod(handle.name, mode)
        problems = parse_file(handle.name).problems
        if problems:
            raise LensfunImportError(f"the imported presets do not validate: {problems[0].error(str(target))}")
        os.replace(handle.name, target)
    except OSError as error:
        raise LensfunImportError(f"cannot write {target}: {error.strerror or error}") from None
    finally:
        if os.path.exists(handle.name):
            os.unlink(handle.name)
    with contextlib.suppress(PresetFileError):
        read_file(str(target), cache_dir=paths.cache_dir())
