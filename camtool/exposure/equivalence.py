"""Equivalent settings across formats, teleconverters and focal reducers.

Two cameras take the *same picture* when they see the same angle of view
from the same place through the same entrance-pupil diameter for the same
time. With r the ratio of the formats' diagonals (target over source; the
ratio of crop factors, source over target):

- same angle of view: f' = f·r;
- same depth of field and background blur (the same aperture diameter
  f/N): N' = N·r;
- same total light on the sensor, hence the same shot noise for sensors of
  equal efficiency: at the same time, ISO' = ISO·r² (the larger sensor
  spreads the same light over r² the area).

A teleconverter of factor k makes a lens of focal length f·k at f-number
N·k (k² less light); a focal reducer ("speed booster") of factor s < 1 makes
f·s at N·s (1/s² more light).
"""

from __future__ import annotations

from typing import Any

from camtool.core.arrays import ops
from camtool.core.errors import require
from camtool.core.record import NamedTuple


class Equivalent(NamedTuple):
    """The settings on the target format that give the same picture, and the ratio used."""

    focal_length_mm: Any
    f_number: Any
    iso: Any
    ratio: Any
    aperture_diameter_mm: Any
    light_stops: Any


def equivalent_settings(focal_length_mm: Any, f_number: Any, iso: Any, source_diagonal_mm: Any,
                        target_diagonal_mm: Any, converter: Any = 1.0) -> Equivalent:
    """Focal length, f-number and ISO on the target format for the same picture: f·r, N·r, ISO·r².

    ``converter`` (a teleconverter k > 1 or a focal reducer s < 1) acts on the
    source lens first: f·c at N·c.

    Parameters
    ----------
    focal_length_mm : float or array, > 0 mm
    f_number : float or array, > 0
    iso : float or array, > 0
    source_diagonal_mm, target_diagonal_mm : float or array, > 0 mm
    converter : float or array, > 0 (1: none)

    Returns
    -------
    Equivalent
        ``aperture_diameter_mm`` f/N (the same on both), ``light_stops`` the
        exposure difference at the same time and ISO, 2·log2(r) (the target
        needs r² the ISO for the same brightness).

    References
    ----------
    J. James, "Equivalence" (josephjamesphotography.com): 25 mm f/1.4 on
    Four Thirds is equivalent to 31 mm f/1.8 on 1.6× APS-C, 33 mm f/1.9 on
    1.5× APS-C and 50 mm f/2.8 on full frame, all with an 18 mm aperture.

    Examples
    --------
    >>> e = equivalent_settings(25.0, 1.4, 200.0, 21.6, 43.2)
    >>> e.focal_length_mm, e.f_number, e.iso
    (50.0, 2.8, 800.0)
    """
    for name, value in (("focal_length_mm", focal_length_mm), ("f_number", f_number), ("iso", iso),
                        ("sensor", source_diagonal_mm), ("to_sensor", target_diagonal_mm), ("converter", converter)):
        require(name, value, value > 0, "> 0")
    r = target_diagonal_mm / source_diagonal_mm
    f, n = focal_length_mm * converter, f_number * converter
    xp = ops(r, f, n)
    return Equivalent(f * r, n * r, iso * r * r, r, f / n, 2.0 * xp.log2(r))
