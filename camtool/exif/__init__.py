"""Photo metadata for the optics: reading Exif and maker notes, and the inputs a depth of field needs.

:mod:`camtool.exif.makernotes` converts the makers' focus-distance encodings
(pure functions, no dependency); :mod:`camtool.exif.reader` reads a file with
python-exiv2 (the optional ``exif`` extra, imported only there);
:mod:`camtool.exif.sensor` derives the sensor size and matches presets.
See docs/exif.md.
"""
