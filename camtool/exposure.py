"""Exposure value, the missing setting, sunny-16 light levels, equivalents, ND filters, bellows factor.

Two conventions are named apart everywhere, because mixing them is the
commonest bug in light-meter software:

- ``ev`` — the exposure value of the camera settings alone, EV = log2(N²/t);
- ``ev100`` — the scene's light level as the EV that gives the right exposure
  at ISO 100: EV100 = EV − log2(S/100). A scene of EV100 15 needs settings of
  EV 16 at ISO 200.

The domain (a photographer's, a pinhole's and a star-trail camera's):
times 1/64000 s to 10⁶ s, f-numbers 0.7 to 1024, ISO 1 to 10⁷, EV −10 to +25
(for a given EV or EV100). Outside it the functions raise
:class:`camtool.errors.DomainError`. Scalars in, floats out; arrays in,
arrays out (no numpy import on the scalar path).
"""

from __future__ import annotations

import re
from typing import Any, NamedTuple

from camtool.arrays import ops
from camtool.errors import DomainError, require
from camtool.stops import Snapped, f_number_series, snap_f_number, snap_iso, snap_shutter_s, steps_per_stop

SHUTTER_RANGE_S = (1.0 / 64000.0, 1.0e6)
F_NUMBER_RANGE = (0.7, 1024.0)
ISO_RANGE = (1.0, 1.0e7)
EV_RANGE = (-10.0, 25.0)

_VALID = {
    "shutter_s": "1/64000 s to 1000000 s",
    "f_number": "f/0.7 to f/1024",
    "iso": "ISO 1 to 10000000",
    "ev": "EV -10 to +25",
    "ev100": "EV -10 to +25",
}
_RANGES = {
    "shutter_s": SHUTTER_RANGE_S,
    "f_number": F_NUMBER_RANGE,
    "iso": ISO_RANGE,
    "ev": EV_RANGE,
    "ev100": EV_RANGE,
}


def check(param: str, value: Any, detail: str = "") -> None:
    """Raise :class:`DomainError` unless ``value`` of ``param`` lies in its domain.

    ``param`` is one of ``shutter_s``, ``f_number``, ``iso``, ``ev``, ``ev100``.
    NaN fails (every comparison with it is false).

    >>> check("f_number", 2048.0)
    Traceback (most recent call last):
    ...
    camtool.errors.DomainError: f_number=2048 is outside the valid range: f/0.7 to f/1024
    """
    low, high = _RANGES[param]
    # A relative slack of 1e-12 lets round-trips land on the ends of the range.
    low, high = low - abs(low) * 1e-12, high + abs(high) * 1e-12
    require(param, value, (value >= low) & (value <= high), _VALID[param], detail)


def exposure_value(f_number: Any, shutter_s: Any) -> Any:
    """Exposure value of camera settings, in stops: EV = log2(N²/t) (no ISO term).

    Written 2·log2(N) − log2(t), which neither overflows nor loses digits.

    Parameters
    ----------
    f_number : float or array, 0.7 to 1024
    shutter_s : float or array, 1/64000 s to 10⁶ s

    References
    ----------
    ISO 2720:1974, "General purpose photographic exposure meters"; Ray,
    *Applied Photographic Optics*, 3rd ed. (2002), ch. 33; Wikipedia,
    "Exposure value".

    Examples
    --------
    >>> round(exposure_value(16.0, 1 / 125), 2)
    14.97
    >>> exposure_value(4.0, 1 / 64)
    10.0
    """
    check("f_number", f_number)
    check("shutter_s", shutter_s)
    xp = ops(f_number, shutter_s)
    return 2.0 * xp.log2(f_number) - xp.log2(shutter_s)


def iso_stops(iso: Any) -> Any:
    """Stops of sensitivity above ISO 100: log2(S/100).

    >>> iso_stops(400.0)
    2.0
    """
    check("iso", iso)
    return ops(iso).log2(iso / 100.0)


def ev100_from_ev(ev: Any, iso: Any) -> Any:
    """Scene light level EV100 from settings' EV at ISO S: EV100 = EV − log2(S/100).

    >>> ev100_from_ev(8.0, 200.0)
    7.0
    """
    return ev - iso_stops(iso)


def ev_from_ev100(ev100: Any, iso: Any) -> Any:
    """Settings' EV that exposes a scene of EV100 correctly at ISO S: EV = EV100 + log2(S/100).

    >>> ev_from_ev100(15.0, 400.0)
    17.0
    """
    return ev100 + iso_stops(iso)


def ev100(f_number: Any, shutter_s: Any, iso: Any) -> Any:
    """Scene light level (EV at ISO 100) that settings N, t, S expose correctly: log2(N²/t) − log2(S/100).

    Parameters
    ----------
    f_number : float or array, 0.7 to 1024
    shutter_s : float or array, 1/64000 s to 10⁶ s
    iso : float or array, 1 to 10⁷

    References
    ----------
    Wikipedia, "Exposure value" (EV at ISO 100; "EV100").

    Examples
    --------
    >>> round(ev100(8.0, 0.004, 100.0), 8)
    13.96578428
    >>> ev100(4.0, 1 / 64, 200.0)
    9.0
    """
    return ev100_from_ev(exposure_value(f_number, shutter_s), iso)


def shutter_for_ev100(ev100: Any, f_number: Any, iso: Any) -> Any:
    """Shutter time in seconds for a scene of EV100 at N and ISO S: t = N²·2^−EV, EV = EV100 + log2(S/100).

    The result is checked against the shutter domain (1/64000 s to 10⁶ s).

    Examples
    --------
    >>> shutter_for_ev100(10.0, 4.0, 100.0)
    0.015625
    >>> shutter_for_ev100(14.0, 16.0, 100.0)
    0.015625
    """
    check("ev100", ev100)
    check("f_number", f_number)
    xp = ops(ev100, f_number, iso)
    t = f_number**2 * xp.exp2(-ev_from_ev100(ev100, iso))
    check("shutter_s", t, "the shutter time this light level needs")
    return t


def f_number_for_ev100(ev100: Any, shutter_s: Any, iso: Any) -> Any:
    """f-number for a scene of EV100 at time t and ISO S: N = √(t·2^EV), EV = EV100 + log2(S/100).

    Examples
    --------
    >>> f_number_for_ev100(10.0, 1 / 64, 100.0)
    4.0
    """
    check("ev100", ev100)
    check("shutter_s", shutter_s)
    xp = ops(ev100, shutter_s, iso)
    n = xp.sqrt(shutter_s * xp.exp2(ev_from_ev100(ev100, iso)))
    check("f_number", n, "the f-number this light level needs")
    return n


def iso_for_ev100(ev100: Any, f_number: Any, shutter_s: Any) -> Any:
    """ISO speed for a scene of EV100 at N and t: S = 100·2^(EV − EV100), EV = log2(N²/t).

    Examples
    --------
    >>> iso_for_ev100(9.0, 4.0, 1 / 64)
    200.0
    """
    check("ev100", ev100)
    xp = ops(ev100, f_number, shutter_s)
    s = 100.0 * xp.exp2(exposure_value(f_number, shutter_s) - ev100)
    check("iso", s, "the ISO speed this light level needs")
    return s


class Exposure(NamedTuple):
    """A complete exposure: the three settings, their EV and the scene's EV100; ``solved`` names the computed one."""

    f_number: Any
    shutter_s: Any
    iso: Any
    ev: Any
    ev100: Any
    solved: str


def solve_exposure(ev100: Any, f_number: Any = None, shutter_s: Any = None, iso: Any = None) -> Exposure:
    """Complete an exposure for a scene of EV100: give two of f-number, time and ISO, get the third.

    Parameters
    ----------
    ev100 : float or array, −10 to +25
    f_number, shutter_s, iso : float or array or None
        Exactly one must be ``None``.

    Examples
    --------
    >>> e = solve_exposure(15.0, f_number=16.0, iso=200.0)
    >>> e.shutter_s, e.ev, e.solved
    (0.00390625, 16.0, 'shutter_s')
    """
    missing = [name for name, v in (("f_number", f_number), ("shutter_s", shutter_s), ("iso", iso)) if v is None]
    if len(missing) != 1:
        raise DomainError("settings", ", ".join(missing) or "none missing",
                          "exactly one of f_number, shutter_s, iso left to solve")
    if f_number is None:
        f_number = f_number_for_ev100(ev100, shutter_s, iso)
    elif shutter_s is None:
        shutter_s = shutter_for_ev100(ev100, f_number, iso)
    else:
        iso = iso_for_ev100(ev100, f_number, shutter_s)
    return Exposure(f_number, shutter_s, iso, exposure_value(f_number, shutter_s), ev100, missing[0])


# --- light levels ----------------------------------------------------------


class LightLevel(NamedTuple):
    """A named light level: the scene's EV100, what it looks like, and where the value comes from."""

    ev100: float
    description: str
    source: str


_SUNNY16 = "sunny-16 rule: f/{} at 1/ISO s (Wikipedia, 'Sunny 16 rule', table of apertures)"
_ANSI = "ANSI PH2.7-1986 exposure guide, via Wikipedia 'Exposure value', Table 2{}"
# The sunny-16 rule: in bright sun, f/16 at a time of 1/ISO; each weaker light
# one stop more aperture. Its EV100 is log2(16²·100) = 14.64 (the ANSI table
# rounds this scene to 15); the family keeps the rule exact so that it gives
# exactly 1/ISO at f/16.
_EV100_SUNNY16 = 8.0 + 6.643856189774724  # log2(256) + log2(100)

LIGHT_LEVELS: dict[str, LightLevel] = {
    "snow": LightLevel(_EV100_SUNNY16 + 1, "snow or sand in sun, dark sharp shadows", _SUNNY16.format(22)),
    "sunny": LightLevel(_EV100_SUNNY16, "bright sun, distinct shadows", _SUNNY16.format(16)),
    "slight-overcast": LightLevel(_EV100_SUNNY16 - 1, "slight overcast, soft shadow edges", _SUNNY16.format(11)),
    "overcast": LightLevel(_EV100_SUNNY16 - 2, "overcast, shadows barely visible", _SUNNY16.format(8)),
    "heavy-overcast": LightLevel(_EV100_SUNNY16 - 3, "heavy overcast, no shadows", _SUNNY16.format("5.6")),
    "shade": LightLevel(_EV100_SUNNY16 - 4, "open shade or sunset", _SUNNY16.format(4)),
    "sunset": LightLevel(12.0, "typical scene at sunset", _ANSI.format("")),
    "after-sunset": LightLevel(10.0, "just after sunset", _ANSI.format(" (9 to 11; middle)")),
    "full-moon": LightLevel(15.0, "the full moon itself, altitude > 40°", _ANSI.format("")),
    "bright-street": LightLevel(8.0, "bright street scenes at night", _ANSI.format("")),
    "night-street": LightLevel(7.5, "night street scenes, window displays", _ANSI.format(" (7 to 8; middle)")),
    "office": LightLevel(7.5, "offices and work areas", _ANSI.format(" (7 to 8; middle)")),
    "home-interior": LightLevel(6.0, "home interiors", _ANSI.format(" (5 to 7; middle)")),
    "floodlit-buildings": LightLevel(4.0, "floodlit buildings, monuments, fountains", _ANSI.format(" (3 to 5; middle)")),
    "distant-city-lights": LightLevel(2.0, "distant views of lighted buildings", _ANSI.format("")),
    "moonlight": LightLevel(-2.5, "landscape by full moonlight, moon altitude > 40°", _ANSI.format(" (-3 to -2; middle)")),
}
"""Named light levels and their EV100, each with its source."""


def light_level(name: str) -> LightLevel:
    """Look up a named light level; ignores case, spaces and underscores.

    Examples
    --------
    >>> round(light_level("Sunny").ev100, 2)
    14.64
    >>> light_level("dusk")
    Traceback (most recent call last):
    ...
    camtool.errors.DomainError: light=dusk is outside the valid range: one of snow, sunny, slight-overcast, overcast, heavy-overcast, shade, sunset, after-sunset, full-moon, bright-street, night-street, office, home-interior, floodlit-buildings, distant-city-lights, moonlight
    """
    key = re.sub(r"[\s_]+", "-", name.strip().lower())
    try:
        return LIGHT_LEVELS[key]
    except KeyError:
        raise DomainError("light", name, "one of " + ", ".join(LIGHT_LEVELS)) from None


# --- equivalent exposures --------------------------------------------------


class Equivalents(NamedTuple):
    """Equivalent settings for one EV: one entry per f-number, lists of floats.

    ``f_number`` and ``shutter_s`` are exact standard stops (f-numbers 2^(k/2n),
    times 2^(−k/n) s); ``*_nominal`` are their marked labels; ``shutter_exact_s``
    is the unsnapped time N²/2^EV and ``ev`` the EV of each snapped pair
    (equal to the target within half a snapping step).
    """

    f_number: list[float]
    f_number_nominal: list[float]
    shutter_s: list[float]
    shutter_nominal_s: list[float]
    shutter_exact_s: list[float]
    ev: list[float]


def equivalent_exposures(ev: float, f_min: float = 1.0, f_max: float = 32.0, step: str = "full") -> Equivalents:
    """Equivalent f-number and time pairs for settings of EV ``ev``, over standard stops.

    For each standard f-number N from ``f_min`` to ``f_max`` (full, half or
    third stops) the time t = N²/2^EV is snapped to the same kind of stop.
    Rows whose time (exact or snapped) falls outside 1/64000 s to 10⁶ s are left out.

    Parameters
    ----------
    ev : float, −10 to +25 (the settings' EV at the ISO in use, not EV100)
    f_min, f_max : float, f-number range, within 0.7 to 1024
    step : "full", "half" or "third"

    Examples
    --------
    >>> from camtool.timefmt import format_time
    >>> eq = equivalent_exposures(15.0, 8.0, 22.0)
    >>> eq.f_number_nominal, [format_time(t) for t in eq.shutter_nominal_s]
    ([8.0, 11.0, 16.0, 22.0], ['1/500', '1/250', '1/125', '1/60'])
    """
    check("ev", ev)
    check("f_number", f_min)
    check("f_number", f_max)
    steps_per_stop(step)
    rows: list[tuple[float, ...]] = []
    for n in f_number_series(f_min, f_max, step):
        exact = n * n * 2.0**-ev
        if not (SHUTTER_RANGE_S[0] <= exact <= SHUTTER_RANGE_S[1]):
            continue
        f_snap: Snapped = snap_f_number(n, step)
        t_snap: Snapped = snap_shutter_s(exact, step)
        if not (SHUTTER_RANGE_S[0] <= t_snap.exact <= SHUTTER_RANGE_S[1]):
            continue  # 1/65536 s snaps out of the domain, although 1/64000 s is in it
        rows.append((f_snap.exact, f_snap.nominal, t_snap.exact, t_snap.nominal, exact,
                     exposure_value(f_snap.exact, t_snap.exact)))
    columns = list(zip(*rows)) if rows else [()] * 6
    return Equivalents(*(list(c) for c in columns))


def shift_time_s(shutter_s: Any, stops: Any) -> Any:
    """Time in seconds after adding ``stops`` of exposure: t·2^stops (negative stops shorten it).

    >>> shift_time_s(1 / 125, 10.0)
    8.192
    """
    return shutter_s * ops(shutter_s, stops).exp2(stops)


# --- neutral density filters ----------------------------------------------

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


# --- close-up -------------------------------------------------------------


def bellows_factor(magnification: Any, pupil_magnification: Any = 1.0) -> Any:
    """Exposure factor for close focus: (1 + m/P)², the square of working/marked f-number.

    Parameters
    ----------
    magnification : float or array, m ≥ 0 (0 at infinity focus, 1 at 1:1)
    pupil_magnification : float or array, P > 0
        Exit over entrance pupil diameter; 1 for a symmetric lens, below 1 for
        telephoto designs, above 1 for retrofocus ones.

    References
    ----------
    Ray, *Applied Photographic Optics* (2002), §12 (bellows factor and pupil
    magnification); Wikipedia, "f-number" (working f-number N(1 + m/P)).

    Examples
    --------
    >>> bellows_factor(1.0)
    4.0
    >>> round(bellows_factor(1.0, 0.5), 2)
    9.0
    """
    require("magnification", magnification, magnification >= 0, ">= 0")
    require("pupil_magnification", pupil_magnification, pupil_magnification > 0, "> 0")
    return (1.0 + magnification / pupil_magnification) ** 2


def bellows_stops(magnification: Any, pupil_magnification: Any = 1.0) -> Any:
    """Extra exposure in stops for close focus: log2 of the bellows factor, 2·log2(1 + m/P).

    >>> bellows_stops(1.0)
    2.0
    """
    factor = bellows_factor(magnification, pupil_magnification)
    return ops(factor).log2(factor)


# --- a whole exposure: light, settings, filters, close-up, reciprocity -------


class ExposurePlan(NamedTuple):
    """Everything the exposure calculator reports for one scene and set of settings.

    ``ev100`` is the scene's light level at ISO 100 *in front of the lens*;
    ``nd_stops`` and ``bellows_stops`` are lost on the way to the film, so
    the settings (``f_number``, ``shutter_s``, ``iso``; ``ev`` = log2(N²/t))
    expose for ``ev100 − nd_stops − bellows_stops``. ``shutter_s`` is the
    metered time; ``corrected_shutter_s`` adds the film's reciprocity
    failure (equal to it without a film). The ``*_nominal`` values are the
    settings snapped to standard stops (labels as marked on cameras);
    ``solved`` names the setting computed (``"ev100"`` when the light level
    was derived from the settings).
    """

    f_number: Any
    shutter_s: Any
    iso: Any
    ev: Any
    ev100: Any
    solved: str
    nd_stops: Any
    bellows_stops: Any
    corrected_shutter_s: Any
    reciprocity_stops: Any
    f_number_nominal: Any
    shutter_nominal_s: Any
    iso_nominal: Any


def plan_exposure(
    ev100: Any = None,
    f_number: Any = None,
    shutter_s: Any = None,
    iso: Any = None,
    nd_stops: Any = 0.0,
    magnification: Any = 0.0,
    pupil_magnification: Any = 1.0,
    reciprocity_p: Any = None,
    reciprocity_threshold_s: Any = 1.0,
    step: str = "third",
) -> ExposurePlan:
    """Work out a complete exposure, from the light or from the settings.

    With ``ev100`` (a light level): give two of f-number, time and ISO and
    the third is solved; when only one of f-number and time is given the ISO
    is taken as 100. Without it: f-number and time are required (ISO 100 if
    not given) and the scene's EV100 is what those settings expose for,
    ``ev100(N, t, S) + nd_stops + bellows_stops``.

    Parameters
    ----------
    ev100 : float or array or None, −10 to +25
    f_number, shutter_s, iso : float or array or None (domains as in :func:`check`)
    nd_stops : float or array, ≥ 0 (see :func:`parse_nd`, :func:`stack_nd`)
    magnification, pupil_magnification : close-up, see :func:`bellows_factor`
    reciprocity_p : float or array or None, Schwarzschild exponent (1 to 3)
    reciprocity_threshold_s : float, time below which the film needs no correction
    step : "full", "half" or "third" — the stops the nominal values snap to

    Examples
    --------
    >>> p = plan_exposure(light_level("sunny").ev100, f_number=16.0, iso=100.0, nd_stops=10.0)
    >>> round(p.shutter_s, 3), p.shutter_nominal_s, p.solved
    (10.24, 10.0, 'shutter_s')
    >>> p = plan_exposure(f_number=4.0, shutter_s=1 / 64, iso=200.0)
    >>> p.ev, p.ev100, p.solved
    (10.0, 9.0, 'ev100')
    """
    require("nd_stops", nd_stops, nd_stops >= 0, ">= 0 stops")
    close_up = bellows_stops(magnification, pupil_magnification)
    if ev100 is None:
        if f_number is None or shutter_s is None:
            raise DomainError("settings", "f_number and shutter_s", "both needed when no light level is given")
        iso = 100.0 if iso is None else iso
        scene = ev100_from_ev(exposure_value(f_number, shutter_s), iso) + nd_stops + close_up
        solved = "ev100"
    else:
        check("ev100", ev100)
        if iso is None and (f_number is None or shutter_s is None):
            iso = 100.0
        result = solve_exposure(ev100 - nd_stops - close_up, f_number, shutter_s, iso)
        f_number, shutter_s, iso, scene, solved = result.f_number, result.shutter_s, result.iso, ev100, result.solved
    if reciprocity_p is None:
        corrected, extra = shutter_s, 0.0 * shutter_s
    else:
        from camtool.reciprocity import corrected_time_s

        corrected = corrected_time_s(shutter_s, reciprocity_p, reciprocity_threshold_s)
        extra = ops(corrected).log2(corrected / shutter_s)
    return ExposurePlan(
        f_number, shutter_s, iso, exposure_value(f_number, shutter_s), scene, solved, nd_stops, close_up,
        corrected, extra, snap_f_number(f_number, step).nominal, snap_shutter_s(shutter_s, step).nominal,
        snap_iso(iso, step).nominal,
    )
