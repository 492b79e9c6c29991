"""Write the test images of tests/test_exif*.py: tiny JPEGs whose metadata python-exiv2 writes.

Run from the repository root: ``python tests/data/exif/make_images.py``. No
camera file is copied from anywhere: every file is made here.

The image itself is a minimal baseline JPEG built byte by byte (ITU-T T.81):
SOI; a DQT with one table of 64 ones; an SOF0 for an 8-bit, 3 × 2 pixel,
one-component (grey) frame; two DHT segments, a DC and an AC table, each with
a single one-bit code (code 0) for symbol 0x00 (DC difference category 0, and
AC end-of-block); an SOS for the one component; the entropy-coded data, one
8 × 8 block coded as the DC bit 0 and the EOB bit 0, padded with 1-bits to a
byte (0x3F); EOI. Every decoder reads it as a flat grey 3 × 2 picture, and
libexiv2 accepts it as a JPEG to write Exif into.

The metadata are then written with python-exiv2: standard Exif tags, and
maker-note tags exiv2 can write (Canon FileInfo, Olympus FocusInfo, Nikon
LensData version 0101, which is not encrypted). The values are chosen for
the tests; the expected results are derived in the tests from the published
encodings and formulas, not from these files.
"""

from __future__ import annotations

import struct
import sys
from pathlib import Path

import exiv2

HERE = Path(__file__).resolve().parent


def _segment(marker: int, payload: bytes) -> bytes:
    return bytes([0xFF, marker]) + struct.pack(">H", len(payload) + 2) + payload


def tiny_jpeg(width: int = 3, height: int = 2) -> bytes:
    """A valid baseline JPEG of ``width`` × ``height`` grey pixels (at most 8 × 8: one block)."""
    one_code = bytes([1] + [0] * 15) + b"\x00"  # one code of length 1, for symbol 0
    return (b"\xff\xd8"
            + _segment(0xDB, b"\x00" + b"\x01" * 64)
            + _segment(0xC0, b"\x08" + struct.pack(">HH", height, width) + b"\x01" + b"\x01\x11\x00")
            + _segment(0xC4, b"\x00" + one_code)
            + _segment(0xC4, b"\x10" + one_code)
            + _segment(0xDA, b"\x01\x01\x00\x00\x3f\x00")
            + b"\x3f"
            + b"\xff\xd9")


def rational(num: int, den: int = 1) -> exiv2.URationalValue:
    return exiv2.URationalValue([(num, den)])


def ushort(value: int) -> exiv2.UShortValue:
    return exiv2.UShortValue([value])


def undefined(data: bytes) -> exiv2.Value:
    value = exiv2.Value.create(exiv2.TypeId.undefined)
    value.read(data)
    return value


def write(name: str, tags: list[tuple[str, object]]) -> None:
    path = HERE / name
    path.write_bytes(tiny_jpeg())
    if not tags:
        return
    image = exiv2.ImageFactory.open(str(path))
    image.readMetadata()
    data = image.exifData()
    for key, value in tags:
        data[key] = value
    image.writeMetadata()


def nikon_lens_data(focus_distance_raw: int) -> bytes:
    """Nikon LensData version 0101 (unencrypted): 18 bytes, FocusDistance at offset 9 (ExifTool LensData01)."""
    block = bytearray(b"0101" + bytes(14))
    block[9] = focus_distance_raw
    return bytes(block)


EXPOSURE = [("Exif.Photo.ExposureTime", rational(1, 125)), ("Exif.Photo.ISOSpeedRatings", ushort(400))]


def main() -> None:
    # Canon: FocalPlane resolution (5616 px across 36 mm: 5616 / (36/25.4) = 3962.4 px/in) and a bracket
    write("canon_bracket.jpg", [
        ("Exif.Image.Make", "Canon"), ("Exif.Image.Model", "Canon EOS 5D Mark II"),
        ("Exif.Photo.FocalLength", rational(50)), ("Exif.Photo.FNumber", rational(8)), *EXPOSURE,
        ("Exif.Photo.PixelXDimension", exiv2.ULongValue([5616])),
        ("Exif.Photo.PixelYDimension", exiv2.ULongValue([3744])),
        ("Exif.Photo.FocalPlaneXResolution", rational(5616 * 254, 360)),
        ("Exif.Photo.FocalPlaneYResolution", rational(3744 * 254, 240)),
        ("Exif.Photo.FocalPlaneResolutionUnit", ushort(2)),
        ("Exif.CanonFi.FocusDistanceUpper", ushort(350)), ("Exif.CanonFi.FocusDistanceLower", ushort(320)),
    ])
    # Canon, bracket open to infinity (upper 65535); sensor from the 35 mm equivalent (crop 1.6)
    write("canon_infinity.jpg", [
        ("Exif.Image.Make", "Canon"), ("Exif.Image.Model", "Canon EOS 7D"),
        ("Exif.Photo.FocalLength", rational(30)), ("Exif.Photo.FocalLengthIn35mmFilm", ushort(48)),
        ("Exif.Photo.FNumber", rational(11)), *EXPOSURE,
        ("Exif.Photo.PixelXDimension", exiv2.ULongValue([5184])),
        ("Exif.Photo.PixelYDimension", exiv2.ULongValue([3456])),
        ("Exif.CanonFi.FocusDistanceUpper", ushort(65535)), ("Exif.CanonFi.FocusDistanceLower", ushort(1000)),
    ])
    # Canon, older layout: ShotInfo 0x13 (exiv2's CanonSi.SubjectDistance, ExifTool's FocusDistanceUpper), 250 cm
    write("canon_shotinfo.jpg", [
        ("Exif.Image.Make", "Canon"), ("Exif.Image.Model", "Canon EOS 5D Mark II"),
        ("Exif.Photo.FocalLength", rational(85)), ("Exif.Photo.FNumber", rational(2)), *EXPOSURE,
        ("Exif.CanonSi.SubjectDistance", ushort(250)),
    ])
    # Nikon: lens data FocusDistance raw 100 (10^(100/40) cm); the sensor from the camera preset nikon-d850
    write("nikon.jpg", [
        ("Exif.Image.Make", "NIKON CORPORATION"), ("Exif.Image.Model", "NIKON D850"),
        ("Exif.Photo.FocalLength", rational(85)), ("Exif.Photo.FNumber", rational(28, 10)),
        ("Exif.Photo.ExposureTime", rational(1, 250)), ("Exif.Photo.ISOSpeedRatings", ushort(100)),
        ("Exif.Photo.LensModel", "AF-S Nikkor 85mm f/1.8G"),
        ("Exif.Nikon3.LensData", undefined(nikon_lens_data(100))),
    ])
    # Olympus: FocusInfo FocusDistance 2500/10 (numerator in mm), 35 mm equivalent 50 at 25 mm (crop 2), 4:3
    write("olympus.jpg", [
        ("Exif.Image.Make", "OLYMPUS IMAGING CORP."), ("Exif.Image.Model", "E-M5"),
        ("Exif.Photo.FocalLength", rational(25)), ("Exif.Photo.FocalLengthIn35mmFilm", ushort(50)),
        ("Exif.Photo.FNumber", rational(56, 10)), *EXPOSURE,
        ("Exif.Photo.PixelXDimension", exiv2.ULongValue([4608])),
        ("Exif.Photo.PixelYDimension", exiv2.ULongValue([3456])),
        ("Exif.OlympusFi.FocusDistance", rational(2500, 10)),
    ])
    # Fujifilm (exiv2 decodes no focus distance for it): Exif SubjectDistance 3.5 m; crop 1.5 from 35 mm eq
    write("fujifilm_subject.jpg", [
        ("Exif.Image.Make", "FUJIFILM"), ("Exif.Image.Model", "X-T3"),
        ("Exif.Photo.FocalLength", rational(35)), ("Exif.Photo.FocalLengthIn35mmFilm", ushort(52)),
        ("Exif.Photo.FNumber", rational(4)), *EXPOSURE,
        ("Exif.Photo.PixelXDimension", exiv2.ULongValue([6240])),
        ("Exif.Photo.PixelYDimension", exiv2.ULongValue([4160])),
        ("Exif.Photo.SubjectDistance", rational(35, 10)),
    ])
    # APEX only: ApertureValue Av = 6 (f/8), ShutterSpeedValue Tv = 7 (1/128 s); Sony preset; a lens preset
    # with a prescription matched by its alias
    write("sony_apex_lens.jpg", [
        ("Exif.Image.Make", "SONY"), ("Exif.Image.Model", "ILCE-7M4"),
        ("Exif.Photo.FocalLength", rational(100)), ("Exif.Photo.ApertureValue", rational(6)),
        ("Exif.Photo.ShutterSpeedValue", exiv2.RationalValue([(7, 1)])),
        ("Exif.Photo.ISOSpeedRatings", ushort(200)), ("Exif.Photo.LensModel", "Double Gauss 100"),
        ("Exif.Photo.SubjectDistance", rational(2)),
    ])
    # A resized copy: FocalPlane resolution of the full 5184 px frame (22.3 mm wide) kept on a 100 × 67 px image
    # (a 0.43 mm "sensor", rejected), the 35 mm equivalent 48 at 30 mm (crop 1.6) used instead; ISO 102400,
    # past ISOSpeedRatings' 16 bits (65535), in RecommendedExposureIndex
    write("resized_high_iso.jpg", [
        ("Exif.Image.Make", "Canon"), ("Exif.Image.Model", "Canon EOS 7D"),
        ("Exif.Photo.FocalLength", rational(30)), ("Exif.Photo.FocalLengthIn35mmFilm", ushort(48)),
        ("Exif.Photo.FNumber", rational(4)), ("Exif.Photo.ExposureTime", rational(1, 1000)),
        ("Exif.Photo.ISOSpeedRatings", ushort(65535)),
        ("Exif.Photo.RecommendedExposureIndex", exiv2.ULongValue([102400])),
        ("Exif.Photo.PixelXDimension", exiv2.ULongValue([100])),
        ("Exif.Photo.PixelYDimension", exiv2.ULongValue([67])),
        ("Exif.Photo.FocalPlaneXResolution", rational(5184 * 254, 223)),
        ("Exif.Photo.FocalPlaneYResolution", rational(5184 * 254, 223)),
        ("Exif.Photo.FocalPlaneResolutionUnit", ushort(2)),
        ("Exif.Photo.SubjectDistance", rational(5)),
    ])
    # Partial: a make and model no preset knows, a focal length, nothing else
    write("partial.jpg", [
        ("Exif.Image.Make", "Acme"), ("Exif.Image.Model", "Pinhole 1"), ("Exif.Photo.FocalLength", rational(50)),
    ])
    write("no_metadata.jpg", [])
    whole = (HERE / "canon_bracket.jpg").read_bytes()
    (HERE / "truncated.jpg").write_bytes(whole[: len(whole) // 3])
    (HERE / "not_an_image.jpg").write_text("This is a text file with a .jpg name.\n", encoding="utf-8")


if __name__ == "__main__":
    sys.exit(main())
