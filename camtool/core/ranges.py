"""The physical domain of the optical inputs, in one place (docs/design.md §6.1).

The command line checks every value against these ranges at the edge, with
the range in the message; the click parameter types read their bounds from
here. The exposure quantities have their own ranges in
:mod:`camtool.core.domain`.

>>> FOCAL_LENGTH_MM
(1.0, 5000.0)
>>> in_range(0.03, COC_MM), in_range(2.0, COC_MM)
(True, False)
"""

from __future__ import annotations

import math

FOCAL_LENGTH_MM = (1.0, 5000.0)
"""Focal length: a phone's wide camera (about 1.5 mm) to a long telescope (docs/design.md §6.1)."""

F_NUMBER = (0.7, 1024.0)
"""f-number: the fastest lenses made (f/0.7) to pinholes (f/1024)."""

COC_MM = (0.0005, 1.0)
"""Circle of confusion: a microscope's sensor pixel to an 8 × 10 in contact print viewed close."""

DISTANCE_MM = (0.0, 1.0e15)
"""Distances: positive, up to 10¹⁵ mm (a million km), or infinity where a distance may be infinite."""

PIXEL_PITCH_UM = (0.2, 100.0)
"""Pixel pitch in micrometres (the unit of spec sheets): sub-micron phone pixels to large scientific CCDs."""

SENSOR_SIDE_MM = (0.5, 2000.0)
"""A side of the sensor or film: a tiny endoscope chip to a 20 × 24 in (508 × 610 mm) view camera plate."""

CROP_FACTOR = (0.1, 100.0)
"""Crop factor relative to 36 × 24 mm (the sensor sides then lie within :data:`SENSOR_SIDE_MM` or near it)."""

HIATUS_FOCAL_LENGTHS = 10.0
"""Largest |hiatus| in focal lengths: real retrofocus and telephoto lenses reach several focal lengths."""

MAGNIFICATION = (1.0e-9, 1000.0)
"""Magnification for close-up work."""

CHART_SIDE_IN = (1.0, 40.0)
"""A chart's width or height in inches."""

CHART_DPI = (20.0, 1200.0)
"""A raster chart's resolution in dots per inch."""

PUPIL_MAGNIFICATION = (0.05, 20.0)
"""The pupil magnification P (exit over entrance pupil diameter): retrofocus wide angles to long telephotos."""

EXTENSION_MM = (0.0, 10_000.0)
"""Extension tubes or bellows behind a lens: up to 10 m, beyond any bellows made (and any magnification above)."""

SHUTTER_ANGLE_DEG = (0.1, 360.0)
"""A rotary (or electronic) shutter's open angle in degrees: up to the whole turn, 360°."""

FRAME_RATE_FPS = (0.01, 100_000.0)
"""Frames per second: from time-lapse to high-speed cameras."""

SQUEEZE = (1.0, 4.0)
"""An anamorphic lens's horizontal squeeze factor (1.3, 1.5, 1.8 and 2 are the usual ones; 1 is spherical)."""
WAVELENGTH_NM = (200.0, 2000.0)
"""A wavelength of light in nm, as ``--wavelength`` takes it: near ultraviolet to near infrared."""

TILT_DEG = (-89.0, 89.0)
"""A lens tilt or swing in degrees from the film plane (at 90° the plane of focus would be the axis)."""

TOLERANCE = (0.0, math.nextafter(1.0, 0.0))
"""A relative tolerance of ``--model auto``: above 0 and below 1 (100 %), both ends open."""

MTF_LEVEL = (0.05, 0.95)
"""A contrast level of a criterion ``mtf:LEVEL@FREQ``: below 5 % the first crossing of a defocused MTF is ill-defined."""

FREQUENCY_LPMM = (0.1, 5000.0)
"""A spatial frequency on the sensor in line pairs per mm: a large plate seen far off to past a phone sensor's cut-off."""


def in_range(value: float, bounds: tuple[float, float], allow_inf: bool = False) -> bool:
    """Whether ``value`` lies in the closed interval ``bounds`` (infinity only if ``allow_inf``; NaN never)."""
    if allow_inf and value == math.inf:
        return True
    return bounds[0] <= value <= bounds[1]


def describe(bounds: tuple[float, float], unit: str = "", allow_inf: bool = False) -> str:
    """The range in words for an error message, e.g. ``1 to 5000 mm`` or ``> 0 to 1e+15 mm, or inf``.

    >>> describe(FOCAL_LENGTH_MM, "mm")
    '1 to 5000 mm'
    >>> describe(DISTANCE_MM, "mm", allow_inf=True)
    '> 0 to 1e+15 mm, or inf'
    """
    low = f"> {bounds[0]:g}" if bounds[0] == 0 else f"{bounds[0]:g}"
    text = f"{low} to {bounds[1]:g} {unit}".rstrip()
    return text + (", or inf" if allow_inf else "")
