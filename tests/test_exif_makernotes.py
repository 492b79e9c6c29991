"""The makers' focus-distance encodings, against their published definitions and exiv2's own reading.

Each conversion is checked twice: against the formula ExifTool documents
for the tag (https://exiftool.org/TagNames/Canon.html, Nikon.html,
Olympus.html; quoted beside each test), and against libexiv2's rendering of
the same raw value written into a maker note (a second, independent
implementation), where exiv2 can write that maker note.
"""

from __future__ import annotations

import math
import warnings
from pathlib import Path

import pytest

from camtool.exif import makernotes
from tests.cli_helpers import exif_image_maker

exiv2 = pytest.importorskip("exiv2")

DATA = Path(__file__).resolve().parent / "data" / "exif"


def _printed(tags: list[tuple[str, object]], key: str, tmp_path: Path) -> str:
    """exiv2's print() of ``key`` after writing ``tags`` into a fresh tiny JPEG."""
    module = exif_image_maker()
    path = tmp_path / "x.jpg"
    path.write_bytes(module.tiny_jpeg())
    image = exiv2.ImageFactory.open(str(path))
    image.readMetadata()
    data = image.exifData()
    for k, v in tags:
        data[k] = v
    image.writeMetadata()
    image = exiv2.ImageFactory.open(str(path))
    image.readMetadata()
    return next(d.print() for d in image.exifData() if d.key() == key)


# ExifTool Canon FileInfo/ShotInfo FocusDistanceUpper: ValueConv '$val / 100' (m); > 655.345 m prints "inf".
@pytest.mark.parametrize(("raw", "metres"), [(1, 0.01), (350, 3.5), (1000, 10.0), (65534, 655.34)])
def test_canon_is_centimetres(raw: int, metres: float) -> None:
    assert makernotes.canon_focus_distance_mm(raw) == pytest.approx(metres * 1000.0, rel=1e-12)


def test_canon_codes() -> None:
    assert makernotes.canon_focus_distance_mm(65535) == math.inf
    assert makernotes.canon_focus_distance_mm(-1) == math.inf  # exiv2 decodes CanonFi as signed shorts
    assert makernotes.canon_focus_distance_mm(0) is None


@pytest.mark.parametrize("raw", [320, 350, 1234])
def test_canon_agrees_with_exiv2(raw: int, tmp_path: Path) -> None:
    printed = _printed([("Exif.Image.Make", "Canon"), ("Exif.CanonFi.FocusDistanceUpper", exiv2.UShortValue([raw]))],
                       "Exif.CanonFi.FocusDistanceUpper", tmp_path)
    assert printed == f"{makernotes.canon_focus_distance_mm(raw) / 1000:.2f} m"


# ExifTool Nikon LensData FocusDistance: ValueConv '0.01 * 10**($val/40)' (m): 40 steps a decade from 1 cm.
@pytest.mark.parametrize(("raw", "metres"), [(0, 0.01), (40, 0.1), (80, 1.0), (120, 10.0), (160, 100.0)])
def test_nikon_decades(raw: int, metres: float) -> None:
    assert makernotes.nikon_focus_distance_mm(raw) == pytest.approx(metres * 1000.0, rel=1e-12)


def test_nikon_step_is_a_fortieth_of_a_decade() -> None:
    ratio = makernotes.nikon_focus_distance_mm(101) / makernotes.nikon_focus_distance_mm(100)
    assert ratio == pytest.approx(10 ** (1 / 40), rel=1e-12)


def test_nikon_inverts_exiftools_inverse() -> None:
    # ExifTool's ValueConvInv for the same tag: raw = 40·log10(100·d), d in metres
    for raw in range(256):
        metres = makernotes.nikon_focus_distance_mm(raw) / 1000
        assert 40 * math.log10(100 * metres) == pytest.approx(raw, abs=1e-9)


@pytest.mark.parametrize("raw", [60, 80, 100, 137])
def test_nikon_agrees_with_exiv2(raw: int, tmp_path: Path) -> None:
    block = bytearray(b"0101" + bytes(14))  # LensData version 0101: not encrypted, FocusDistance at byte 9
    block[9] = raw
    value = exiv2.Value.create(exiv2.TypeId.undefined)
    with warnings.catch_warnings():  # some python-exiv2 releases deprecate read(bytes), which they document
        warnings.simplefilter("ignore", DeprecationWarning)
        value.read(bytes(block))
    printed = _printed([("Exif.Image.Make", "NIKON CORPORATION"), ("Exif.Nikon3.LensData", value)],
                       "Exif.NikonLd2.FocusDistance", tmp_path)
    assert printed == f"{makernotes.nikon_focus_distance_mm(raw) / 1000:.2f} m"


# ExifTool Olympus FocusInfo 0x0305 FocusDistance: the numerator in mm whatever the denominator.
@pytest.mark.parametrize(("num", "den", "mm"), [(2500, 10, 2500.0), (2500, 1, 2500.0), (830, 1000, 830.0)])
def test_olympus_numerator_is_mm(num: int, den: int, mm: float) -> None:
    assert makernotes.olympus_focus_distance_mm(num, den) == mm


def test_olympus_codes_and_exiv2(tmp_path: Path) -> None:
    assert makernotes.olympus_focus_distance_mm(0xFFFFFFFF, 1) == math.inf
    assert makernotes.olympus_focus_distance_mm(0, 1) is None
    printed = _printed([("Exif.Image.Make", "OLYMPUS IMAGING CORP."),
                        ("Exif.OlympusFi.FocusDistance", exiv2.URationalValue([(2500, 10)]))],
                       "Exif.OlympusFi.FocusDistance", tmp_path)
    assert printed == "2.50 m"


# Exif 2.32 (CIPA DC-008) SubjectDistance 0x9206: metres; 0xFFFFFFFF infinity, 0 unknown.
def test_exif_subject_distance() -> None:
    assert makernotes.exif_subject_distance_mm(35, 10) == 3500.0
    assert makernotes.exif_subject_distance_mm(0xFFFFFFFF, 1) == math.inf
    assert makernotes.exif_subject_distance_mm(0, 1) is None


# ExifTool Casio ObjectDistance (0x0006; type 2 0x2022): ValueConv '$val / 1000' (m); type 2 >= 0x20000000: inf
@pytest.mark.parametrize(("key", "raw"), [("Exif.Casio.ObjectDistance", 1850), ("Exif.Casio2.ObjectDistance", 1850),
                                          ("Exif.Casio2.ObjectDistance", 12345)])
def test_casio_agrees_with_exiv2(key: str, raw: int, tmp_path: Path) -> None:
    make = "CASIO COMPUTER CO.,LTD." if "Casio2" in key else "CASIO"
    printed = _printed([("Exif.Image.Make", make), (key, exiv2.ULongValue([raw]))], key, tmp_path)
    value = makernotes.casio_object_distance_mm(raw, "Casio2" in key)
    assert printed == f"{value / 1000:.2f} m"
    assert makernotes.casio_object_distance_mm(0x20000000, True) == math.inf
    assert makernotes.casio_object_distance_mm(0x20000000, False) == 0x20000000


# ExifTool Canon CameraISO: 16..20 are 50..800, bit 14 set carries the ISO in the low 14 bits; ShotInfo BaseISO
# exp(val/32·ln 2)·100/32 (and AutoISO exp(val/32·ln 2)·100, so 0 is ×1)
@pytest.mark.parametrize(("key", "raw", "camera", "base"),
                         [("Exif.CanonCs.ISOSpeed", 17, 17, None), ("Exif.CanonCs.ISOSpeed", 0x4000 | 3200, 0x4000 | 3200,
                                                                      None),
                          ("Exif.CanonSi.ISOSpeed", 128, None, 128), ("Exif.CanonSi.ISOSpeed", 160, None, 160)])
def test_canon_iso_agrees_with_exiv2(key: str, raw: int, camera: int | None, base: int | None, tmp_path: Path) -> None:
    printed = _printed([("Exif.Image.Make", "Canon"), (key, exiv2.UShortValue([raw]))], key, tmp_path)
    assert makernotes.canon_iso(camera, base, 0) == pytest.approx(float(printed), rel=1e-12)


def test_canon_auto_iso_and_minolta_iso_by_exiftools_formulas() -> None:
    # BaseISO 160 -> 2^5·100/32 = 100; AutoISO 32 -> 2^1·100 = 200 %: ISO 200
    assert makernotes.canon_iso(15, 160, 32) == pytest.approx(200.0, rel=1e-15)
    # Minolta CameraSettings ISO: 2^((val − 48)/8)·100; 72 is 800
    assert makernotes.minolta_iso(72) == pytest.approx(800.0, rel=1e-15)


def test_nikon_z_code_is_the_f_mount_code_times_256() -> None:
    # ExifTool LensData0800 0x4e FocusDistance: int16u, RawConv $val/256, then 0.01·10^(val/40) m
    assert makernotes.nikon_focus_distance_mm(100 * 256 / 256) == makernotes.nikon_focus_distance_mm(100)
    assert makernotes.nikon_focus_distance_mm(20480 / 256) == pytest.approx(1000.0, rel=1e-12)  # 80: 1 m
