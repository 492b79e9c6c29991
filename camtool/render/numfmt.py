"""Numbers for people: significant figures that fit the magnitude, units per column.

A table column of distances is shown in one unit, chosen from its largest
finite value (metres from 1 m up, millimetres below; feet and inches for
``--units imperial``), each value to four significant figures: 30.00 m, not
30000.0 mm, and never a false millimetre at thirty metres.
"""

from __future__ import annotations

import math
from collections.abc import Sequence

SIGNIFICANT = 4
INFINITY = "∞"


def significant(value: float | None, digits: int = SIGNIFICANT) -> str:
    """Format ``value`` with ``digits`` significant figures, in plain notation up to 10⁷.

    >>> significant(4188.234)
    '4188'
    >>> significant(0.0288)
    '0.02880'
    >>> significant(float("inf"))
    '∞'
    >>> significant(3.2e12)
    '3.200e+12'
    """
    if value is None:
        return "–"
    if math.isinf(value):
        return INFINITY if value > 0 else "-" + INFINITY
    if value == 0:
        return "0"
    magnitude = math.floor(math.log10(abs(value)))
    if magnitude >= 7 or magnitude < -5:
        return f"{value:.{digits - 1}e}"
    decimals = max(0, digits - 1 - magnitude)
    return f"{value:.{decimals}f}"


METRIC_DISTANCE = (("m", 1000.0, 1000.0), ("mm", 1.0, 0.0))
IMPERIAL_DISTANCE = (("ft", 304.8, 914.4), ("in", 25.4, 0.0))


def distance_unit(values_mm: Sequence[float | None], units: str = "metric") -> tuple[str, float]:
    """Pick the display unit and its size in mm for a column of distances.

    >>> distance_unit([418.8, 30000.0])
    ('m', 1000.0)
    >>> distance_unit([0.5, 418.8])
    ('mm', 1.0)
    >>> distance_unit([3048.0], "imperial")
    ('ft', 304.8)
    """
    table = IMPERIAL_DISTANCE if units == "imperial" else METRIC_DISTANCE
    finite = [abs(v) for v in values_mm if v is not None and math.isfinite(v)]
    largest = max(finite, default=0.0)
    for name, size, threshold in table:
        if largest >= threshold:
            return name, size
    return table[-1][0], table[-1][1]


def feet_inches(value_mm: float | None) -> str:
    """A distance as photographers in feet write it: 9' 10.1", 378' 9", ∞.

    Inches get one decimal below 100 ft and none above, and below a foot
    four significant figures (as metric cells): one notation whatever the
    size, so a table of distances never mixes two.

    >>> print(feet_inches(3000.0), feet_inches(115_400.0), feet_inches(240.0), feet_inches(float("inf")))
    9' 10.1" 378' 7" 9.449" ∞
    >>> print(feet_inches(0.3))
    0.01181"
    """
    if value_mm is None:
        return "–"
    if math.isinf(value_mm):
        return INFINITY
    decimals = 1 if value_mm < 100 * 304.8 else 0
    total_inches = round(value_mm / 25.4, decimals)
    feet, inches = divmod(total_inches, 12.0)
    if abs(feet) >= 100_000:
        return significant(value_mm / 304.8) + "'"
    if feet == 0:
        return significant(value_mm / 25.4) + '"'
    return f"{int(feet)}' {inches:.{decimals}f}\""


def length(value_mm: float, units: str = "metric", metres: bool = True) -> str:
    """One length for a footer or a message, in the table's units: 0.6096 m, 0.4506 mm, 2' 0.0", 0.01774", ∞.

    ``metres``: a distance, in metres; else a small length (a step, a depth at the subject), in millimetres.

    >>> print(length(609.6), length(0.4506, metres=False), length(609.6, "imperial"), length(float("inf")))
    0.6096 m 0.4506 mm 2' 0.0" ∞
    """
    if math.isinf(value_mm):
        return INFINITY
    if units == "imperial":
        return feet_inches(value_mm)
    return f"{value_mm / 1000:.4g} m" if metres else f"{value_mm:.4g} mm"
