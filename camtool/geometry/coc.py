"""Circle of confusion: an explicit value, or a rule applied to the sensor.

Rules (the text after ``--coc-rule``):

``d/1500`` (default), ``d/1730``, ``d/1442``, any ``d/K``
    the sensor diagonal divided by K. d/1442 gives the classic 0.030 mm on a
    36 × 24 mm frame, d/1500 0.0288 mm, d/1730 (Zeiss) 0.025 mm.
``cine``
    0.025 mm (0.001 in) whatever the sensor, the convention of 35 mm motion
    picture depth-of-field tables (Wikipedia, "Depth of field", circle of
    confusion criterion: "generally 35 mm productions set it at 0.025 mm
    (0.001 in)", after Ray 2000). The default for a camera preset of the
    ``cine`` category.
``px:K``
    K pixel pitches (needs the pixel pitch, from a camera preset or
    ``--pixel-pitch``): for pixel-level sharpness.
``print:WxH@V``
    a print W × H viewed from V, judged by an eye that resolves 0.25 mm at
    25 cm (so 0.25 mm × V/250 mm on the print), divided by the enlargement
    from sensor to print. The sensor is enlarged to *fill* the print (the
    larger of the two side ratios), as prints are made; e.g.
    ``print:8x10in@25cm`` on 36 × 24 mm gives 0.0295 mm.
"""

from __future__ import annotations

import math
import re

from camtool.core.record import NamedTuple
from camtool.core.units import UnitError, parse_length

DEFAULT_RULE = "d/1500"
RULES_TO_COMPLETE = ("d/1500", "cine", "d/1730", "d/1442", "px:1", "px:2", "print:8x10in@25cm")
"""The rules a shell completes for ``--coc-rule`` (any ``d/K``, ``px:K`` or ``print:WxH@DIST`` is accepted)."""
CINE_RULE = "cine"
CINE_COC_MM = 0.025
"""The cinema convention, 0.001 in (Wikipedia, "Depth of field": 35 mm productions set it at 0.025 mm)."""
EYE_ACUITY_MM_AT_250 = 0.25
"""Blur diameter an eye just resolves on a print viewed from 25 cm (the traditional figure)."""


class CocChoice(NamedTuple):
    """The circle of confusion used, in mm, and where it came from (for the output footer)."""

    coc_mm: float
    origin: str


_DIAGONAL = r"^\s*d\s*/\s*(\d+(?:\.\d*)?)\s*$"  # compiled on first use (re's cache)
_PIXELS = r"^\s*px\s*:\s*(\d+(?:\.\d*)?)\s*$"  # compiled on first use (re's cache)
_PRINT = r"^\s*print\s*:\s*([^x×@]+)\s*[x×]\s*([^@]+)@(.+)$"  # compiled on first use (re's cache)


def coc_from_rule(
    rule: str, width_mm: float, height_mm: float, pixel_pitch_mm: float | None = None
) -> CocChoice:
    """Circle of confusion in mm from a rule applied to a sensor of ``width_mm`` × ``height_mm``.

    Parameters
    ----------
    rule : str
        ``d/K``, ``px:K`` or ``print:WxH@V`` (see the module docstring).
    width_mm, height_mm : float
        Sensor size, > 0.
    pixel_pitch_mm : float, optional
        Needed by ``px:K``.

    References
    ----------
    Wikipedia, "Circle of confusion" (d/1500, d/1730 and the 8×10 print at
    25 cm); Zeiss's d/1730 criterion; Wikipedia, "Depth of field" (cine, 0.025 mm).

    Examples
    --------
    >>> coc_from_rule("d/1442", 36, 24).coc_mm.__round__(4)
    0.03
    >>> coc_from_rule("px:2", 36, 24, pixel_pitch_mm=0.0045).coc_mm
    0.009
    >>> round(coc_from_rule("print:8x10in@25cm", 36, 24).coc_mm, 4)
    0.0295
    >>> coc_from_rule("cine", 27.99, 19.22)
    CocChoice(coc_mm=0.025, origin='cine: 0.001 in')
    """
    if rule.strip().lower() == CINE_RULE:
        return CocChoice(CINE_COC_MM, "cine: 0.001 in")
    diagonal = math.hypot(width_mm, height_mm)
    match = re.match(_DIAGONAL, rule, re.IGNORECASE)
    if match:
        divisor = float(match.group(1))
        if divisor <= 0:
            raise UnitError(f"{rule!r}: the divisor must be > 0")
        return CocChoice(diagonal / divisor, f"{rule.strip()} of {diagonal:.1f} mm")
    match = re.match(_PIXELS, rule, re.IGNORECASE)
    if match:
        if pixel_pitch_mm is None:
            raise UnitError(f"{rule!r} needs the pixel pitch: give --camera or --pixel-pitch")
        factor = float(match.group(1))
        return CocChoice(factor * pixel_pitch_mm, f"{rule.strip()} × {pixel_pitch_mm * 1000:.2f} µm")
    match = re.match(_PRINT, rule, re.IGNORECASE)
    if match:
        return _print_coc(rule, match.groups(), width_mm, height_mm)
    raise UnitError(f"{rule!r} is not a CoC rule (d/1500, cine, d/1730, d/1442, d/K, px:K, print:WxH@DIST)")


def _print_coc(rule: str, parts: tuple[str, ...], width_mm: float, height_mm: float) -> CocChoice:
    side_a, side_b, viewing = (p.strip() for p in parts)
    unit = re.search(r"[a-z\"']+$", side_b, re.IGNORECASE)
    if unit and not re.search(r"[a-z\"']+$", side_a, re.IGNORECASE):
        side_a += unit.group(0)  # "8x10in" -> both sides in inches
    a, b, view = parse_length(side_a), parse_length(side_b), parse_length(viewing)
    if min(a, b, view) <= 0 or math.isinf(max(a, b, view)):
        raise UnitError(f"{rule!r}: print sides and viewing distance must be positive and finite")
    enlargement = max(max(a, b) / max(width_mm, height_mm), min(a, b) / min(width_mm, height_mm))
    coc = EYE_ACUITY_MM_AT_250 * (view / 250.0) / enlargement
    return CocChoice(coc, f"{rule.strip()}, ×{enlargement:.2f}")
