"""Flash guide numbers: which of the four quantities is solved, and the answer.

GN = distance × f-number at the ISO the guide number is quoted at; at ISO S
it is GN·√(S/S_quoted). ``camtool flash`` and :func:`camtool.flash_exposure`
both ask :func:`solve`, so both refuse the same questions the same way.
"""

from __future__ import annotations

from typing import Any

from camtool.core.errors import InputError
from camtool.exposure.flash import Flash

INPUTS = ("guide_number_m", "distance_mm", "f_number", "iso")
"""The four quantities, by the names of the plan's parameters."""


def solve(*, guide_number_m: Any = None, distance_mm: Any = None, f_number: Any = None, iso: Any = None,
          quoted_iso: float = 100.0) -> Flash:
    """Give exactly three of guide number (metres, at ``quoted_iso``), distance (mm), f-number and ISO; get the fourth.

    An input left out is None; more or fewer than one left out is an :class:`InputError` naming them
    (``{guide_number_m}``, ...), which each caller spells its own way.

    >>> round(solve(guide_number_m=40.0, f_number=8.0, iso=400.0).distance_m, 6)  # 40·√(400/100)/8
    10.0
    """
    from camtool.exposure.flash import solve_flash

    given = dict(zip(INPUTS, (guide_number_m, distance_mm, f_number, iso)))
    left = [name for name, value in given.items() if value is None]
    if len(left) != 1:
        shown = ", ".join("{" + name + "}" for name in left) or "none"
        raise InputError(left[0] if left else "guide_number_m",
                         "Give three of {guide_number_m}, {distance_mm}, {f_number}, {iso} and get the fourth "
                         f"(left out: {shown}).", usage=True)
    return solve_flash(guide_number_m=guide_number_m, distance_m=None if distance_mm is None else distance_mm / 1000.0,
                       f_number=f_number, iso=iso, quoted_iso=quoted_iso)
