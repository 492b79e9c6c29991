"""Focus distances as the makers encode them in their maker notes, converted to millimetres.

Each function takes the raw number exiv2 decodes from the maker note and
returns the distance in mm (``inf`` for the makers' infinity code) or None
where the code means "not recorded". The encodings are those ExifTool
documents (Image::ExifTool tag tables, https://exiftool.org/TagNames/) and
exiv2 prints; tests/test_exif_makernotes.py checks each against exiv2's own
rendering of the same raw value.

Which plane the distance is measured from is not recorded by any maker:
the figures come from the lens's distance encoder, which is calibrated
against the lens's distance scale, and distance scales are measured from the
focal-plane mark (the sensor). camtool therefore reads them as distances from
the sensor by default (``--distance-from sensor``); ExifTool's Composite:DOF
takes them as distances from the lens (docs/exif.md).
"""

from __future__ import annotations

INFINITY = float("inf")


def canon_focus_distance_mm(raw: int) -> float | None:
    """Canon FocusDistanceUpper/FocusDistanceLower (CanonFi 0x14/0x15, CanonSi 0x13) in mm.

    Formula: d = raw / 100 m = 10·raw mm, an unsigned 16-bit count of
    centimetres; 65535 (655.35 m) is Canon's infinity and 0 "not recorded".

    Parameters
    ----------
    raw : int
        The tag's value as stored; a signed reading (exiv2 decodes CanonFi
        as signed shorts) is taken modulo 2¹⁶.

    References
    ----------
    ExifTool Canon tags, ShotInfo/FileInfo FocusDistanceUpper and
    FocusDistanceLower: ``ValueConv => '$val / 100'`` (metres), printed as
    "inf" above 655.345 m; exiv2 prints the same value as "3.50 m" for 350.

    Examples
    --------
    >>> canon_focus_distance_mm(350)
    3500.0
    >>> canon_focus_distance_mm(-1), canon_focus_distance_mm(0)
    (inf, None)
    """
    value = int(raw) & 0xFFFF
    if value == 0:
        return None
    if value == 0xFFFF:
        return INFINITY
    return 10.0 * value


def nikon_focus_distance_mm(raw: float) -> float:
    """Nikon lens-data FocusDistance (NikonLd2/NikonLd3 FocusDistance, one byte) in mm.

    Formula: d = 0.01 m · 10^(raw/40) = 10 mm · 10^(raw/40): a logarithmic
    scale, 40 steps per decade, from 1 cm at raw 0; raw 80 is 1 m, raw 120
    10 m, raw 255 (the largest byte) about 23.7 km, which is infinity for
    any lens.

    Parameters
    ----------
    raw : float
        The byte, 0 to 255 (taken modulo 256 if an integer); a fraction for
        the Z-mount code (its 16-bit value over 256, ExifTool LensData0800
        0x4e) or for the ends of a byte's quantisation step (raw ± 0.5).

    References
    ----------
    ExifTool Nikon tags, LensData01/LensData0204 FocusDistance:
    ``ValueConv => '0.01 * 10**($val/40)'`` (metres), with the note that it is
    approximate and inaccurate for some lenses; exiv2 prints 80 as "1.00 m".

    Examples
    --------
    >>> nikon_focus_distance_mm(80)
    1000.0
    >>> round(nikon_focus_distance_mm(100), 1)
    3162.3
    """
    value = float(int(raw) & 0xFF) if isinstance(raw, int) else min(max(float(raw), -1.0), 256.5)
    return 10.0 * 10.0 ** (value / 40.0)


def olympus_focus_distance_mm(numerator: int, denominator: int = 1) -> float | None:
    """Olympus FocusDistance (OlympusFi 0x0305, a rational) in mm.

    Formula: d = numerator mm, the denominator ignored: the rational looks
    like metres over 1000 but the cameras write the numerator in mm whatever
    the denominator (1 on the E-1, 10 on the E-300), so only the numerator is
    consistent. 0xFFFFFFFF is infinity; 0 is "not recorded".

    References
    ----------
    ExifTool Olympus tags, FocusInfo 0x0305 FocusDistance (read as two
    int32u, ``$a[0] / 1000`` metres: "if we ignore the denominator we are
    consistently in mm"); exiv2's print of the same tag takes the numerator
    as mm too.

    Examples
    --------
    >>> olympus_focus_distance_mm(2500, 10)
    2500.0
    >>> olympus_focus_distance_mm(0xFFFFFFFF, 1), olympus_focus_distance_mm(0, 1)
    (inf, None)
    """
    value = int(numerator) & 0xFFFFFFFF
    if value == 0:
        return None
    if value == 0xFFFFFFFF:
        return INFINITY
    return float(value)


def exif_subject_distance_mm(numerator: int, denominator: int) -> float | None:
    """Exif SubjectDistance (0x9206, a rational in metres) in mm.

    Per the Exif standard (CIPA DC-008, tag 0x9206) the value is in metres;
    0xFFFFFFFF/1 means infinity and 0/1 "unknown".

    Examples
    --------
    >>> exif_subject_distance_mm(35, 10)
    3500.0
    >>> exif_subject_distance_mm(0xFFFFFFFF, 1), exif_subject_distance_mm(0, 1)
    (inf, None)
    """
    num, den = int(numerator), int(denominator)
    if num == 0xFFFFFFFF:
        return INFINITY
    if num <= 0 or den <= 0:
        return None
    return 1000.0 * num / den


def minolta_focus_distance_mm(raw: int) -> float:
    """Minolta camera-settings FocusDistance (MinoltaCsNew/MinoltaCsOld, index 19) in mm.

    Formula: d = raw mm (ExifTool: ``$val / 1000`` metres); 0 is infinity
    (ExifTool prints 0 as "inf").

    Examples
    --------
    >>> minolta_focus_distance_mm(2500), minolta_focus_distance_mm(0)
    (2500.0, inf)
    """
    value = int(raw) & 0xFFFFFFFF
    return INFINITY if value == 0 else float(value)


def casio_object_distance_mm(raw: int, type2: bool) -> float | None:
    """Casio ObjectDistance (Casio 0x0006; Casio2 0x2022) in mm.

    Formula: d = raw mm (ExifTool: ``$val / 1000`` metres); in the type-2
    maker note a value of 0x20000000 or more is infinity. 0 is "not
    recorded".

    Examples
    --------
    >>> casio_object_distance_mm(1850, True), casio_object_distance_mm(0x20000000, True)
    (1850.0, inf)
    >>> casio_object_distance_mm(0, False) is None
    True
    """
    value = int(raw) & 0xFFFFFFFF
    if value == 0:
        return None
    if type2 and value >= 0x20000000:
        return INFINITY
    return float(value)


def minolta_iso(code: float) -> float:
    """Minolta camera-settings ISO (MinoltaCsNew/MinoltaCsOld, index 8): 2^((code − 48)/8) · 100.

    References
    ----------
    ExifTool Minolta tags, CameraSettings ISO: ``2 ** (($val-48)/8) * 100``.

    Examples
    --------
    >>> minolta_iso(48), minolta_iso(56)
    (100.0, 200.0)
    """
    return 2.0 ** ((max(min(float(code), 4096.0), -4096.0) - 48.0) / 8.0) * 100.0


CANON_CAMERA_ISO = {16: 50.0, 17: 100.0, 18: 200.0, 19: 400.0, 20: 800.0}
"""Canon CameraSettings CameraISO codes (ExifTool Canon ``CameraISO``; 15 is Auto, 0 n/a)."""


def canon_iso(camera_iso: int | None, base_iso: int | None, auto_iso: int | None) -> float | None:
    """The ISO of a Canon shot from its maker note, as ExifTool's Composite:ISO takes it.

    Formula: CameraISO (CanonCs 0x10) when it is a number: the codes 16 to
    20 (50 to 800), or the value's low 14 bits when bit 14 is set; else
    BaseISO × AutoISO / 100 with BaseISO = 2^(b/32)·100/32 and AutoISO =
    2^(a/32)·100 from ShotInfo (CanonSi ISOSpeed b and AutoISO a). 0x7FFF
    and b = 0 are "not recorded".

    References
    ----------
    ExifTool Canon tags: CameraSettings CameraISO, ShotInfo AutoISO and
    BaseISO (``exp($val/32*log(2))*100/32``), Composite ISO ("use CameraISO
    if numerical, otherwise calculate as BaseISO * AutoISO / 100").

    Examples
    --------
    >>> canon_iso(17, 160, 0), canon_iso(15, 128, 0), canon_iso(0x4000 | 3200, None, None)
    (100.0, 50.0, 3200.0)
    >>> canon_iso(15, 0, 0) is None
    True
    """
    if camera_iso is not None:
        code = int(camera_iso) & 0xFFFF
        if code != 0x7FFF:
            if code & 0x4000 and code & 0x3FFF:
                return float(code & 0x3FFF)
            if code in CANON_CAMERA_ISO:
                return CANON_CAMERA_ISO[code]
    if not base_iso or auto_iso is None:
        return None
    base = max(min(int(base_iso), 4096), -4096)  # a signed short; clamped so 2^(b/32) stays finite
    auto = max(min(int(auto_iso), 4096), -4096)
    return 2.0 ** (base / 32.0) * 100.0 / 32.0 * 2.0 ** (auto / 32.0)
