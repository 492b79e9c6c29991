"""Neutral density filters as stops, factor or optical density, parsed and stacked."""

from __future__ import annotations

import re
from typing import Any

from camtool.core.arrays import ops
from camtool.core.errors import DomainError, require
from camtool.core.record import NamedTuple

LOG10_2 = 0.30102999566398120
"""log10(2): one stop of exposure in optical density."""


class NdFilter(NamedTuple):
    """A neutral density filter in its three usual descriptions.

    ``stops`` of light it takes away, its filter ``factor`` 2^stops (ND1000
    passes 1/1000) and its optical ``density`` log10(factor) = stops·log10 2.
    """

    stops: Any
    factor: Any
    density: Any


def nd_from_stops(stops: Any) -> NdFilter:
    """An ND filter of ``stops`` stops: factor 2^stops, density stops·log10(2).

    >>> nd_from_stops(3.0).factor
    8.0
    """
    require("nd_stops", stops, stops >= 0, ">= 0 stops")
    return NdFilter(stops, ops(stops).exp2(stops), stops * LOG10_2)


def nd_from_factor(factor: Any) -> NdFilter:
    """An ND filter of filter factor F (ND1000: F = 1000): stops = log2 F.

    References
    ----------
    Wikipedia, "Neutral-density filter" (ND number, optical density, f-stop
    reduction table: ND1000 = 3.0 = 10 stops nominal, 9.97 exactly).

    Examples
    --------
    >>> round(nd_from_factor(1000.0).stops, 2)
    9.97
    """
    require("nd_factor", factor, factor >= 1, ">= 1")
    return NdFilter(ops(factor).log2(factor), factor, ops(factor).log10(factor))


def nd_from_density(density: Any) -> NdFilter:
    """An ND filter of optical density d: stops = d/log10(2), factor 10^d.

    Examples
    --------
    >>> round(nd_from_density(3.0).stops, 2)
    9.97
    >>> round(nd_from_density(0.9).stops, 3)
    2.99
    """
    require("nd_density", density, density >= 0, ">= 0")
    stops = density / LOG10_2
    return NdFilter(stops, ops(density).exp2(stops), density)


_ND_NUMBER = r"(\d+(?:\.\d*)?|\.\d+)"
_ND_SPELLINGS = (
    (re.compile(rf"^{_ND_NUMBER}\s*(?:stops?|ev)$"), nd_from_stops),
    (re.compile(r"^nd\s*(\d+)$"), nd_from_factor),
    (re.compile(r"^(?:x\s*(\d+(?:\.\d+)?)|(\d+(?:\.\d+)?)\s*x)$"), nd_from_factor),
    (re.compile(rf"^{_ND_NUMBER}\s*d$"), nd_from_density),
    (re.compile(rf"^od\s*{_ND_NUMBER}$"), nd_from_density),
    (re.compile(r"^nd\s*(\d*\.\d+)$"), nd_from_density),
)
ND_SPELLINGS = "a factor (ND1000, 1000x), stops (10stops, 10ev) or an optical density (3.0D, OD3, ND.6, ND0.9)"
"""The three spellings :func:`parse_nd` reads, for messages."""


def parse_nd(text: str) -> NdFilter:
    """Read an ND filter written as a filter factor, stops or an optical density.

    Each description has its own spelling, so that no reader can take one for
    another and no decimal point changes the meaning:

    ========================  ===========  =====================================
    written                   read as      notes
    ========================  ===========  =====================================
    ``ND1000``, ``ND8``,      factor       "ND" + a whole number is the filter
    ``1000x``, ``x8``                      factor (Hoya, B+W "ND 1000")
    ``10stops``, ``3stop``,   stops        fractions allowed (``1.5stops``)
    ``10ev``
    ``3.0D``, ``0.9d``,       optical      D after the number or OD before it
    ``OD3``, ``OD0.9``        density      (Lee, Kodak Wratten "0.9 ND")
    ``ND.3``, ``ND.6``,       optical      the cinema's notation: ND and a number
    ``ND0.9``, ``ND1.2``      density      with a decimal point (Tiffen, Kodak
                                           Wratten 2 #96 "ND .30 = 1 stop",
                                           "ND 3.0 = 10 stops")
    ========================  ===========  =====================================

    ``ND`` and a whole number is a factor (``ND8``), ``ND`` and a number with a
    decimal point a density (``ND.9``, ``ND3.0``), so the decimal point is what
    tells them apart. A bare number (``3``, ``3.0``, ``1000``) is refused with
    the spellings. Case and spaces are ignored.

    Examples
    --------
    >>> [round(parse_nd(s).stops, 2) for s in ("ND1000", "1000x", "10stops", "3.0D", "OD3", "x8", "1.5stops")]
    [9.97, 9.97, 10.0, 9.97, 9.97, 3.0, 1.5]
    >>> [round(parse_nd(s).stops, 2) for s in ("ND.3", "ND.6", "ND0.9", "ND1.2")]
    [1.0, 1.99, 2.99, 3.99]
    >>> parse_nd("1000")  # doctest: +ELLIPSIS
    Traceback (most recent call last):
    ...
    camtool.core.errors.DomainError: nd=1000 is outside the valid range: a factor (ND1000, 1000x), ...
    """
    key = re.sub(r"\s+", "", text.strip().lower())
    for pattern, reader in _ND_SPELLINGS:
        match = pattern.match(key)
        if match:
            number = next(g for g in match.groups() if g is not None)
            return reader(float(number))
    detail = ""
    if re.match(rf"^{_ND_NUMBER}$", key):
        detail = "a bare number could be any of the three"
    raise DomainError("nd", text, ND_SPELLINGS, detail)


def stack_nd(filters: list[NdFilter]) -> NdFilter:
    """Filters stacked in front of one another: stops and densities add, factors multiply.

    >>> round(stack_nd([parse_nd("ND8"), parse_nd("0.6D")]).stops, 2)
    4.99
    """
    return nd_from_stops(sum((f.stops for f in filters), 0.0))
