"""A one-line picture of the sharp zone on a logarithmic distance axis.

::

    ·····━━━━━━━┃━━━━━━━━━━━━━━━━━━━━━━━━━━━H━━━▶

``━`` is the sharp zone from the near to the far limit, ``┃`` the focus
distance, ``H`` the hyperfocal distance and ``▶`` a far limit at infinity.
The axis runs from ``low_mm`` to ``high_mm``; several rows drawn on the same
axis can be compared by eye.
"""

from __future__ import annotations

import math

SHARP, BLUR, FOCUS, HYPERFOCAL, TO_INFINITY = "━", "·", "┃", "H", "▶"


def axis_range(values_mm: list[float]) -> tuple[float, float]:
    """Axis limits in mm that hold every finite value with a little room on each side."""
    finite = [v for v in values_mm if v is not None and math.isfinite(v) and v > 0]
    if not finite:
        return 1.0, 10.0
    low, high = min(finite) / 1.5, max(finite) * 1.5
    return low, max(high, low * 10.0)


def sharp_zone_bar(
    near_mm: float, focus_mm: float, far_mm: float, hyperfocal_mm: float | None,
    low_mm: float, high_mm: float, width: int = 32,
) -> str:
    """The bar for one scene, ``width`` characters long.

    >>> sharp_zone_bar(2000, 3000, 4000, 10000, 1000, 20000, 20)
    '····━━━┃━━·····H····'
    >>> sharp_zone_bar(5000, 10000, float("inf"), 10000, 1000, 20000, 10)
    '·····━━┃━▶'
    """
    span = math.log(high_mm / low_mm)

    def cell(distance: float) -> int:
        if math.isinf(distance):
            return width - 1
        position = math.log(max(distance, low_mm) / low_mm) / span
        return min(width - 1, max(0, int(position * width)))

    last = width - 1 if math.isinf(far_mm) else cell(far_mm)
    chars = [SHARP if cell(near_mm) <= i <= last else BLUR for i in range(width)]
    if hyperfocal_mm is not None and math.isfinite(hyperfocal_mm):
        chars[cell(hyperfocal_mm)] = HYPERFOCAL
    chars[cell(focus_mm)] = FOCUS
    if math.isinf(far_mm):
        chars[-1] = TO_INFINITY
    return "".join(chars)
