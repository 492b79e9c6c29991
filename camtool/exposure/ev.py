"""Exposure value (EV and EV100) and the missing setting of an exposure.

Two conventions are named apart everywhere, because mixing them is the
commonest bug in light-meter software:

- ``ev`` — the exposure value of the camera settings alone, EV = log2(N²/t);
- ``ev100`` — the scene's light level as the EV that gives the right exposure
  at ISO 100: EV100 = EV − log2(S/100). A scene of EV100 15 needs settings of
  EV 16 at ISO 200.

The domain (a photographer's, a pinhole's and a star-trail camera's):
times 1/64000 s to 10⁶ s, f-numbers 0.7 to 1024, ISO 1 to 10⁷, EV −10 to +25
(for a given EV or EV100). Outside it the functions raise
:class:`camtool.core.errors.DomainError`. Scalars in, floats out; arrays in,
arrays out (no numpy import on the scalar path).
"""

from __future__ import annotations

from typing import Any

from camtool.core.arrays import ops
from camtool.core.domain import check
from camtool.core.errors import DomainError
from camtool.core.record import NamedTuple


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


def t_stop(f_number: Any, transmittance: Any) -> Any:
    """T-stop of a lens: T = N / √τ, the f-number of an ideal lens passing the same light.

    Exposure goes by the T-stop; depth of field and diffraction by the
    f-number (the geometric ratio f/D).

    Parameters
    ----------
    f_number : float or array, > 0
    transmittance : float or array, 0 < τ ≤ 1 (the fraction of light the lens passes)

    References
    ----------
    Wikipedia, "F-number", T-stop (an f/2.0 lens of 75 % transmittance is T2.3);
    idigitalphoto.com, "T-number" (f/4 at 50 % is T5.6).

    Examples
    --------
    >>> round(t_stop(2.0, 0.75), 3)
    2.309
    """
    from camtool.core.errors import require

    require("transmittance", transmittance, (transmittance > 0) & (transmittance <= 1), "0 to 1")
    return f_number / ops(f_number, transmittance).sqrt(transmittance)


def f_number_from_t_stop(t: Any, transmittance: Any) -> Any:
    """The f-number behind a T-stop: N = T·√τ (for depth of field, which the geometry sets).

    Without the lens's transmittance, taking the T-stop for the f-number
    overstates N by 1/√τ: the depth of field is computed for a slightly
    smaller aperture than the lens has.

    >>> round(f_number_from_t_stop(2.309401, 0.75), 4)
    2.0
    """
    from camtool.core.errors import require

    require("transmittance", transmittance, (transmittance > 0) & (transmittance <= 1), "0 to 1")
    return t * ops(t, transmittance).sqrt(transmittance)


def transmittance_from_stops(f_number: Any, t_stop: Any) -> Any:
    """Transmittance of a lens from its f-number and T-stop at the same aperture: τ = (N/T)².

    Parameters
    ----------
    f_number : float or array, > 0 (the geometric f-number, f/D)
    t_stop : float or array, ≥ ``f_number`` (a T-stop is never below the f-number)

    References
    ----------
    Wikipedia, "F-number", T-stop: T = N/√τ (an f/2.0 lens of 75 % transmittance is T2.3).

    Examples
    --------
    >>> round(transmittance_from_stops(2.0, 2.309401), 4)
    0.75
    """
    from camtool.core.errors import require

    require("t_stop", t_stop, t_stop >= f_number * (1 - 1e-9), "at least the f-number (a T-stop is never below it)")
    return (f_number / t_stop) ** 2


T_STOP_ERROR_LOW, T_STOP_ERROR_HIGH = 1 - 0.9 ** 0.5, 1 - 0.7 ** 0.5
"""How far the f-number lies below a T-stop for the transmittance typical of cine lenses, τ = 0.9 to 0.7:
N = T·√τ is 5.1 % to 16.3 % below T (docs/design.md §2)."""


class FNumberChoice(NamedTuple):
    """The f-number that depth of field uses for one typed aperture, and where it came from."""

    f_number: float
    """The f-number used (f/D)."""
    t_stop: float | None
    """The T-stop typed, or None for an f-number."""
    source: str
    """``"typed"`` (an f-number), ``"transmittance"`` (N = T·√τ), or ``"t-stop"`` (T stands in for N)."""
    transmittance: float | None
    """The lens's transmittance τ used, or None."""


def resolve_f_number(value: float, t_stop: bool, transmittance: float | None = None) -> FNumberChoice:
    """The f-number for depth of field and diffraction from a typed f-number or T-stop.

    A T-stop with the lens's transmittance τ gives N = T·√τ (τ taken as at full
    aperture: it is assumed not to change as the lens stops down). Without τ the
    T-stop stands in for the f-number: since T ≥ N, that overstates N (and the
    depth of field) by up to 1/√τ, 5 % to 16 % below T for τ = 0.9 to 0.7.

    Parameters
    ----------
    value : float, 0.7 to 1024 (the typed f-number or T-stop)
    t_stop : bool, whether ``value`` is a T-stop
    transmittance : float or None, 0 < τ ≤ 1

    References
    ----------
    Wikipedia, "F-number", T-stop: T = N/√τ.

    Examples
    --------
    >>> resolve_f_number(2.0, False)
    FNumberChoice(f_number=2.0, t_stop=None, source='typed', transmittance=None)
    >>> round(resolve_f_number(2.309401, True, 0.75).f_number, 4)
    2.0
    >>> resolve_f_number(2.0, True).source
    't-stop'
    """
    if not t_stop:
        return FNumberChoice(float(value), None, "typed", None)
    if transmittance is None:
        return FNumberChoice(float(value), float(value), "t-stop", None)
    return FNumberChoice(float(f_number_from_t_stop(float(value), transmittance)), float(value), "transmittance",
                         float(transmittance))
