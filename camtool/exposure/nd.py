"""Neutral density filters as stops, factor or optical density, parsed and stacked."""

from __future__ import annotations

import re
from typing import Any, NamedTuple

from camtool.core.arrays import ops
from camtool.core.errors import DomainError, require

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
    (re.compile(r"^(\d+)$"), nd_from_stops),
    (re.compile(r"^nd\s*(\d+)$"), nd_from_factor),
    (re.compile(r"^(?:x\s*(\d+(?:\.\d+)?)|(\d+(?:\.\d+)?)\s*x)$"), nd_from_factor),
    (re.compile(r"^(?:nd|od)\s*(\d*\.\d+|\d+\.\d*)$"), nd_from_density),
    (re.compile(r"^od\s*(\d+)$"), nd_from_density),
    (re.compile(r"^(\d*\.\d+|\d+\.\d*)\s*(?:nd|od)?$"), nd_from_density),
)


def parse_nd(text: str) -> NdFilter:
    """Read an ND filter written as stops, a filter factor or an optical density.

    The three spellings are told apart by their form, as filters are sold:

    ========================  ===========  =====================================
    written                   read as      why
    ========================  ===========  =====================================
    ``3``, ``3stops``, ``3ev``  stops      a whole number alone counts stops;
    ``1.5stops``                           fractions of a stop need the suffix
    ``ND1000``, ``ND8``,      factor       "ND" + whole number is the filter
    ``1000x``, ``x8``                      factor (Hoya, B+W "ND 1000")
    ``3.0``, ``0.9``,         density      a number with a decimal point is an
    ``ND3.0``, ``0.9ND``,                  optical density (Lee, Kodak Wratten
    ``OD3``                                "0.9 ND")
    ========================  ===========  =====================================

    Case and spaces are ignored. Anything else raises :class:`DomainError`.

    Examples
    --------
    >>> [round(parse_nd(s).stops, 2) for s in ("3", "ND1000", "3.0", "0.9 ND", "x8", "1.5stops")]
    [3.0, 9.97, 9.97, 2.99, 3.0, 1.5]
    """
    key = text.strip().lower()
    for pattern, reader in _ND_SPELLINGS:
        match = pattern.match(key)
        if match:
            number = next(g for g in match.groups() if g is not None)
            return reader(float(number))
    raise DomainError("nd", text, "stops (3, 1.5stops), a factor (ND1000, 8x) or a density (3.0, ND0.9, OD3)")


def stack_nd(filters: list[NdFilter]) -> NdFilter:
    """Filters stacked in front of one another: stops and densities add, factors multiply.

    >>> round(stack_nd([parse_nd("ND8"), parse_nd("0.6")]).stops, 2)
    4.99
    """
    return nd_from_stops(sum((f.stops for f in filters), 0.0))
