"""The longest exposure before stars trail, on a fixed tripod: the 500 rule and the NPF rule.

The sky turns 360° in a sidereal day, so a star at declination δ moves
across the sensor at f·ω·cos δ; a star stays a point while that motion is
below what the eye (500 rule) or the pixels and the lens's Airy disc (NPF
rule) can resolve.

- **500 rule** (from film days): t = 500 / (f · crop), the focal length in
  full-frame equivalent millimetres; 600 and 450 are variants
  (``constant``). It has no declination term.
- **NPF rule** (Frédéric Michaud, Société Astronomique du Havre, 2016),
  with N the f-number, p the pixel pitch in µm, f the focal length in mm:

  - full form: t = k · (16.856·N + 0.0997·f + 13.713·p) / (f · cos δ)
  - simple form (PhotoPills' "default" accuracy): t = (35·N + 30·p) / f,
    divided by cos δ for a star at declination δ as calculators apply it.

  Both use the real focal length: the pixel pitch carries the sensor size.
"""

from __future__ import annotations

import math
from typing import Any

from camtool.core.arrays import ops
from camtool.core.errors import require
from camtool.core.record import NamedTuple


class StarLimits(NamedTuple):
    """Longest untrailed exposures in seconds: the 500 rule, and the NPF rule (simple, full) when p is known."""

    rule500_s: Any
    npf_simple_s: Any
    npf_s: Any


def rule_500_s(focal_length_mm: Any, crop_factor: Any = 1.0, constant: Any = 500.0) -> Any:
    """Longest exposure by the 500 rule, in seconds: t = constant / (f · crop).

    Parameters
    ----------
    focal_length_mm : float or array, > 0 mm (the real focal length)
    crop_factor : float or array, > 0 (full frame 1, APS-C 1.5 or 1.6, Four Thirds 2)
    constant : 500 (or the 600 and 450 variants)

    References
    ----------
    F. Michaud, "'4-crop' rule instead of rule of 500", Cloudy Nights forum,
    2020 ("the 500 rule: t = 500/(crop·f)"); cag-creations.com, "NPF Rule"
    (500 ÷ 50 mm = 10 s).

    Examples
    --------
    >>> rule_500_s(50.0)
    10.0
    >>> round(rule_500_s(14.0, 1.5), 1)
    23.8
    """
    require("focal_length_mm", focal_length_mm, focal_length_mm > 0, "> 0 mm")
    require("crop", crop_factor, crop_factor > 0, "> 0")
    return constant / (focal_length_mm * crop_factor)


def npf_simple_s(f_number: Any, pixel_pitch_um: Any, focal_length_mm: Any, declination_deg: Any = 0.0) -> Any:
    """Longest exposure by the simple NPF rule, in seconds: t = (35·N + 30·p) / (f · cos δ).

    Parameters
    ----------
    f_number : float or array, > 0
    pixel_pitch_um : float or array, > 0 µm
    focal_length_mm : float or array, > 0 mm (real, not equivalent)
    declination_deg : float or array, −89° to 89° (0: the celestial equator, fastest)

    References
    ----------
    PhotoPills, "Spot Stars" (NPF rule, default accuracy); theprimecalculator.com,
    "Exposure time for stars" (worked example: 200 mm f/4, 3.75 µm, δ = 0 → 1.26 s).

    Examples
    --------
    >>> round(npf_simple_s(4.0, 3.75, 200.0), 2)
    1.26
    """
    _check_npf(f_number, pixel_pitch_um, focal_length_mm, declination_deg)
    xp = ops(f_number, pixel_pitch_um, focal_length_mm, declination_deg)
    return (35.0 * f_number + 30.0 * pixel_pitch_um) / (focal_length_mm * xp.cos(declination_deg * math.pi / 180.0))


def npf_s(f_number: Any, pixel_pitch_um: Any, focal_length_mm: Any, declination_deg: Any = 0.0, k: Any = 1.0) -> Any:
    """Longest exposure by the full NPF rule, in seconds: t = k·(16.856·N + 0.0997·f + 13.713·p) / (f·cos δ).

    Parameters
    ----------
    f_number, pixel_pitch_um, focal_length_mm, declination_deg : as :func:`npf_simple_s`
    k : float, > 0, the tolerance factor (1 in Michaud's rule)

    References
    ----------
    F. Michaud, "NPF rule to avoid star trails", Cloudy Nights forum (2016)
    and Société Astronomique du Havre; the coefficients as quoted on
    dpreview.com ("Major confusion NPF rule vs 500 rule": 16.856, 0.0997,
    13.713) and rounded (16.9, 0.1, 13.7) on celestialprogramming.com.

    Examples
    --------
    >>> round(npf_s(2.8, 4.3, 24.0), 2)
    4.52
    """
    _check_npf(f_number, pixel_pitch_um, focal_length_mm, declination_deg)
    require("k", k, k > 0, "> 0")
    xp = ops(f_number, pixel_pitch_um, focal_length_mm, declination_deg)
    top = 16.856 * f_number + 0.0997 * focal_length_mm + 13.713 * pixel_pitch_um
    return k * top / (focal_length_mm * xp.cos(declination_deg * math.pi / 180.0))


def _check_npf(f_number: Any, pixel_pitch_um: Any, focal_length_mm: Any, declination_deg: Any) -> None:
    require("f_number", f_number, f_number > 0, "> 0")
    require("pixel_pitch", pixel_pitch_um, pixel_pitch_um > 0, "> 0 µm")
    require("focal_length_mm", focal_length_mm, focal_length_mm > 0, "> 0 mm")
    require("declination", declination_deg, abs(declination_deg) <= 89.0, "-89 to 89 degrees")


def star_limits(focal_length_mm: Any, f_number: Any, crop_factor: Any = 1.0, pixel_pitch_um: Any = None,
                declination_deg: Any = 0.0, constant: Any = 500.0, k: Any = 1.0) -> StarLimits:
    """All three limits for one setup; the NPF ones are ``None`` without a pixel pitch.

    >>> s = star_limits(24.0, 2.8, 1.0, 4.3)
    >>> round(s.rule500_s, 1), round(s.npf_simple_s, 2), round(s.npf_s, 2)
    (20.8, 9.46, 4.52)
    """
    simple = full = None
    if pixel_pitch_um is not None:
        simple = npf_simple_s(f_number, pixel_pitch_um, focal_length_mm, declination_deg)
        full = npf_s(f_number, pixel_pitch_um, focal_length_mm, declination_deg, k)
    return StarLimits(rule_500_s(focal_length_mm, crop_factor, constant), simple, full)
