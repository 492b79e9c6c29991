"""Flash guide numbers: GN = distance × f-number at ISO 100, scaled by √(ISO/100).

A flash's guide number is the product of the flash-to-subject distance and
the f-number that exposes the subject correctly, quoted at ISO 100 and in
metres (or feet: the two differ by 3.28). Light falls off as the square of
the distance and the film's speed adds linearly, so at ISO S the guide
number is GN·√(S/100): four times the ISO doubles it. Any one of guide
number, distance, f-number and ISO follows from the other three.
"""

from __future__ import annotations

import math
from typing import Any

from camtool.core.arrays import is_scalar, ops
from camtool.core.errors import DomainError, require
from camtool.core.record import NamedTuple


class Flash(NamedTuple):
    """One flash exposure: GN at ISO 100 and at the ISO used (metres), distance (m), f-number, ISO."""

    guide_number_m: Any
    guide_number_at_iso_m: Any
    distance_m: Any
    f_number: Any
    iso: Any
    solved: str


def guide_number_at_iso(guide_number: Any, iso: Any, quoted_iso: Any = 100.0) -> Any:
    """A guide number quoted at ``quoted_iso`` moved to ISO S: GN·√(S/S_quoted).

    References
    ----------
    Kodak DCS 600 manual, flash section (multipliers: ISO 400 × 1.414, ISO 800 × 2
    relative to ISO 200; GN 51 at ISO 200 becomes 102 at ISO 800).

    Examples
    --------
    >>> guide_number_at_iso(51.0, 800.0, 200.0)
    102.0
    """
    require("iso", iso, iso > 0, "> 0")
    return guide_number * ops(guide_number, iso).sqrt(iso / quoted_iso)


def solve_flash(guide_number_m: Any = None, distance_m: Any = None, f_number: Any = None, iso: Any = None,
                quoted_iso: Any = 100.0) -> Flash:
    """Give three of guide number (m, quoted at ``quoted_iso``), distance (m), f-number and ISO; get the fourth.

    N = GN_S / d with GN_S = GN·√(S/S_quoted); d = GN_S / N; GN = N·d·√(S_quoted/S);
    S = S_quoted·(N·d/GN)².

    Parameters
    ----------
    guide_number_m : float or array, > 0 (metres)
    distance_m : float or array, > 0 m (flash to subject)
    f_number : float or array, > 0
    iso : float or array, > 0
    quoted_iso : the ISO the guide number is quoted at (100 unless the maker says otherwise)

    References
    ----------
    Contax RTS manual, "Flash exposure" (GN 20 at ISO 100, 5 m → f/4);
    idigitalphoto.com, "guide number" (GN 45, 5 m → f/9); Pentax K100D
    manual (GN 15.6 at ISO 200, f/4 → 3.9 m); everything2.com, "flash guide
    number" (multiply by √(ISO/100)).

    Examples
    --------
    >>> solve_flash(20.0, 5.0, iso=100.0).f_number
    4.0
    >>> round(solve_flash(15.6, f_number=4.0, iso=200.0, quoted_iso=200.0).distance_m, 1)
    3.9
    """
    names = ("guide_number", "distance", "f_number", "iso")
    given = (guide_number_m, distance_m, f_number, iso)
    missing = [name for name, value in zip(names, given) if value is None]
    if len(missing) != 1:
        raise DomainError("flash", ", ".join(missing) or "all four", "exactly one of guide number, distance, "
                          "f-number and ISO left out")
    for name, value in zip(names, given):
        if value is not None:
            require(name, value, value > 0, "> 0")
    xp = ops(*(v for v in given if v is not None))
    # a quotient past the largest float is infinite, refused below on the quantity it stands for
    values = _solved(xp, guide_number_m, distance_m, f_number, iso, quoted_iso)
    guide_number_m, distance_m, f_number, iso, at_iso = values
    for name, value in zip(names, (guide_number_m, distance_m, f_number, iso)):
        if given[names.index(name)] is None:
            require(name, value, (value > 0) & (value < math.inf) if not is_scalar(value) else 0 < value < math.inf,
                    "a finite answer (the others are too far apart)")
    return Flash(guide_number_m * xp.sqrt(100.0 / quoted_iso), at_iso, distance_m, f_number, iso, missing[0])


def _solved(xp: Any, guide_number_m: Any, distance_m: Any, f_number: Any, iso: Any, quoted_iso: Any) -> tuple[Any, ...]:
    """The four quantities and the guide number at the ISO, the missing one solved (overflow gives infinity)."""
    import warnings

    with warnings.catch_warnings():
        warnings.simplefilter("ignore", RuntimeWarning)
        if guide_number_m is None:
            guide_number_m = f_number * distance_m * xp.sqrt(quoted_iso / iso)
        elif iso is None:
            iso = quoted_iso * (f_number * distance_m / guide_number_m) ** 2
        at_iso = guide_number_at_iso(guide_number_m, iso, quoted_iso)
        if f_number is None:
            f_number = at_iso / distance_m
        elif distance_m is None:
            distance_m = at_iso / f_number
    return guide_number_m, distance_m, f_number, iso, at_iso
