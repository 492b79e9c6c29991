"""The exposure calculator: from what the photographer knows to the settings to use.

One function, :func:`work_out`, takes everything ``camtool exposure`` reads
and makes every decision: which light level counts, whether the settings
given are *metered* settings to correct or settings to solve a scene from,
which setting is left to solve, when the answer is a list of equivalents,
and what to say when the question cannot be answered. The command only
parses, calls it and renders. Four kinds of answer (``mode``):

``metered``
    -N and -t (and --iso) are what the meter said, without filters; a change
    (ND filters, close-up bellows factor, a film's reciprocity failure, a new
    ISO with ``new_iso``, a new f-number with ``new_f_number``) gives the
    time to set (or, with ``solve``, the f-number or ISO to set), each
    correction in stops of its own. This is how long-exposure calculators
    read a metered exposure: 1/60 s at f/8 with an ND1000 is 16.7 s.
``scene``
    A light level (EV100, EV, a named light, a luminance or an illuminance)
    and two of the three settings: the third is solved; ND and bellows are
    between the scene and the film.
``equivalents``
    A light level with both f-number and time open (or ``equivalents``
    asked for): the f-number and time pairs over the stops.
``settings``
    -N and -t alone: their EV and the scene EV100 they expose for.

Errors are :class:`DomainError` on the parameter the photographer gave
(never on one derived inside), or :class:`SettingsError` saying which
settings to give.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from typing import TYPE_CHECKING, Any

from camtool.core.arrays import ops
from camtool.core.domain import EV_RANGE, SHUTTER_RANGE_S, check
from camtool.core.errors import CamtoolError, DomainError
from camtool.core.record import NamedTuple

if TYPE_CHECKING:
    from camtool.exposure.reciprocity import Film

LIGHT_PARAMS = ("ev100", "ev", "light", "luminance", "illuminance")
"""The parameters that each give the light level; at most one may be given."""
SLOWEST_DIAL_S = 30.0
"""The slowest marked shutter speed (30 s): longer times are bulb times, shown exactly, never snapped."""
KEYS = ["f_number", "shutter_s", "iso", "ev", "ev100", "solved", "f_number_nominal", "shutter_nominal_s",
        "iso_nominal", "nd_stops", "bellows_stops", "corrected_shutter_s", "reciprocity_stops",
        "metered_f_number", "metered_shutter_s", "metered_iso", "iso_change_stops", "aperture_change_stops",
        "aperture_kind", "av", "tv", "sv", "bv"]
"""Every key a row of :func:`work_out` carries (JSON and CSV), in order."""


class SettingsError(CamtoolError, ValueError):
    """The question cannot be answered as asked: ``template`` says which settings to give.

    ``template`` names parameters in braces (``{f_number}``); the caller
    replaces each with the option the user types for it.
    """

    def __init__(self, template: str, names: Sequence[str] = ()) -> None:
        self.template = template
        self.names = tuple(names)
        super().__init__(template.format(**{n: n for n in names}))


class Answer(NamedTuple):
    """What :func:`work_out` found: the kind of answer, the rows as named columns, and notes.

    ``values`` maps output keys to scalars or arrays (``rows`` rows);
    ``solved`` names the setting computed; ``film`` is the film used, if any.
    """

    mode: str
    rows: int
    values: dict[str, Any]
    solved: str
    film: Film | None
    notes: tuple[str, ...]


def _given(value: Any) -> bool:
    return value is not None and not (isinstance(value, (list, tuple)) and not value)


def light_ev100(ev100: Any = None, ev: Any = None, light: str | None = None, luminance: Any = None,
                illuminance: Any = None, iso: Any = None, meter_k: float = 12.5, meter_c: float = 250.0) -> Any:
    """The scene's EV100 from the one light level given (None when none is).

    ``ev`` is a meter's EV at the ISO in use (``iso``, default 100); a
    luminance (cd/m²) or illuminance (lx) goes through the meter equations
    with the calibration constants K and C (ISO 2720).

    >>> light_ev100(ev=12.0, iso=400.0)
    10.0
    >>> round(light_ev100(luminance=4096.0), 6)
    15.0
    """
    from camtool.exposure import metering
    from camtool.exposure.ev import ev100_from_ev
    from camtool.exposure.light import light_level

    given = [name for name, value in zip(LIGHT_PARAMS, (ev100, ev, light, luminance, illuminance)) if _given(value)]
    if len(given) > 1:
        raise SettingsError("Give only one light level: " + ", ".join("{" + n + "}" for n in given) + ".", given)
    if ev100 is not None:
        check("ev100", ev100)
        return ev100
    if ev is not None:
        check("ev", ev)
        return ev100_from_ev(ev, 100.0 if iso is None else iso)
    if light is not None:
        return light_level(light).ev100
    if luminance is not None:
        return metering.ev_from_luminance(luminance, 100.0, meter_k)
    if illuminance is not None:
        return metering.ev_from_illuminance(illuminance, 100.0, meter_c)
    return None


def shutter_setting_s(shutter_s: Any, step: str = "third") -> Any:
    """The time to set: the nearest marked speed up to 30 s, the exact time (to the second) beyond.

    Times longer than the slowest shutter-dial speed are bulb times: a
    photographer times them, so they are not snapped to a stop.

    >>> shutter_setting_s(1 / 128), shutter_setting_s(2185.3)
    (0.008, 2185.0)
    """
    from camtool.exposure.stops import snap_shutter_s

    nominal = snap_shutter_s(shutter_s, step).nominal
    xp = ops(shutter_s)
    return xp.where(shutter_s > SLOWEST_DIAL_S, (shutter_s + 0.5) // 1.0, nominal)


def _apex(f_number: Any, shutter_s: Any, iso: Any, ev100: Any) -> dict[str, Any]:
    """APEX values: Av = 2·log2 N, Tv = −log2 t, Sv = log2(S/3.125), Bv = EV100 − 5 (the scene)."""
    from camtool.exposure import metering

    return {"av": metering.aperture_value(f_number), "tv": metering.time_value(shutter_s),
            "sv": metering.speed_value(iso), "bv": ev100 - 5.0}


def _reciprocity(shutter_s: Any, film: Film | None, p: Any) -> Any:
    from camtool.exposure.reciprocity import corrected_time_s, film_time_s

    if film is not None:
        return film_time_s(film, shutter_s)
    if p is not None:
        return corrected_time_s(shutter_s, p)
    return shutter_s


def work_out(
    *,
    f_number: Any = None,
    shutter_s: Any = None,
    iso: Any = None,
    ev100: Any = None,
    ev: Any = None,
    light: str | None = None,
    luminance: Any = None,
    illuminance: Any = None,
    meter_k: float = 12.5,
    meter_c: float = 250.0,
    nd: Sequence[str] = (),
    magnification: Any = 0.0,
    pupil_magnification: Any = 1.0,
    film: Film | None = None,
    reciprocity_p: Any = None,
    new_iso: Any = None,
    new_f_number: Any = None,
    solve: str = "time",
    t_stop: bool = False,
    step: str = "third",
    equivalents: bool = False,
    count: int = 1,
) -> Answer:
    """Work out an exposure from what the photographer knows (see the module text for the four answers).

    Parameters
    ----------
    f_number, shutter_s, iso : float or array or None
        The settings (f/0.7 to f/1024, 1/64000 s to 10⁶ s, ISO 1 to 10⁷):
        the metered ones when no light level is given.
    ev100, ev, light, luminance, illuminance : the light level, at most one
        (EV −10 to +25; a name of :data:`camtool.exposure.light.LIGHT_LEVELS`;
        cd/m²; lx); ``meter_k`` and ``meter_c`` are the meter constants.
    nd : ND filter spellings (:func:`camtool.exposure.nd.parse_nd`), stacked.
    magnification, pupil_magnification : close-up, bellows factor (1 + m/P)².
    film, reciprocity_p : a film's reciprocity data, or a Schwarzschild p.
    new_iso, new_f_number : metered settings moved to another ISO or f-number.
    solve : "time", "f_number" or "iso": the setting a metered answer gives.
    t_stop : the aperture is a T-stop (transmission-corrected; used as is).
    step : "full", "half" or "third": stops of the nominal values and equivalents.
    equivalents : list the equivalent f-number and time pairs.
    count : the number of rows the array inputs hold.

    Returns
    -------
    Answer

    References
    ----------
    ISO 2720:1974 (meter equations); Wikipedia, "Exposure value" (EV100);
    Ilford and Kodak reciprocity data (see ``films.yaml``).

    Examples
    --------
    >>> a = work_out(f_number=8.0, shutter_s=1 / 60, nd=["ND1000"])
    >>> a.mode, round(a.values["corrected_shutter_s"], 1)
    ('metered', 16.7)
    >>> work_out(ev100=12.0, iso=100.0).mode
    'equivalents'
    """
    from camtool.exposure.bellows import bellows_stops
    from camtool.exposure.nd import parse_nd, stack_nd

    if film is not None and reciprocity_p is not None:
        raise SettingsError("Give {film} or {reciprocity_p}, not both.", ["film", "reciprocity_p"])
    level = light_ev100(ev100, ev, light, luminance, illuminance, iso, meter_k, meter_c)
    loss_nd = stack_nd([parse_nd(text) for text in nd]).stops
    loss_close = bellows_stops(magnification, pupil_magnification)
    if level is None:
        if f_number is None or shutter_s is None:
            raise SettingsError("Give a light level ({ev100}, {ev}, {light}, {luminance}, {illuminance}) "
                                "or the metered {f_number} and {shutter_s}.", [*LIGHT_PARAMS, "f_number", "shutter_s"])
        changes = bool(nd) or (_given(magnification) and magnification != 0.0)
        changes = changes or film is not None or reciprocity_p is not None
        changes = changes or new_iso is not None or new_f_number is not None
        if changes and not equivalents:
            return _metered(f_number, shutter_s, iso, loss_nd, loss_close, film, reciprocity_p, new_iso,
                            new_f_number, solve, t_stop, step, count)
        iso = 100.0 if iso is None else iso
        from camtool.exposure.ev import ev100_from_ev, exposure_value

        level = ev100_from_ev(exposure_value(f_number, shutter_s), iso)
        if not equivalents:
            return _settings(f_number, shutter_s, iso, level, t_stop, step, count)
        if count != 1:
            raise SettingsError("{equivalents} needs a single exposure (one value per option).", ["equivalents"])
        answer = _equivalents(level, iso if new_iso is None else new_iso, loss_nd, loss_close, step, "shutter_s",
                              shutter_s)
        if film is not None or reciprocity_p is not None:
            answer = answer._replace(notes=(answer.notes[0] + " · times before reciprocity failure",))
        return answer
    if new_iso is not None or new_f_number is not None:
        names = ["new_iso" if new_iso is not None else "new_f_number", *_light_names(ev100, ev, light, luminance,
                                                                                     illuminance)]
        raise SettingsError("{" + names[0] + "} moves metered settings: give -N and -t without {" + names[1] + "}.",
                            names)
    given = [name for name, value in (("f_number", f_number), ("shutter_s", shutter_s), ("iso", iso))
             if value is not None]
    light_name = _light_names(ev100, ev, light, luminance, illuminance)[0]
    if len(given) == 3:
        raise SettingsError("With a light level, give at most two of {f_number}, {shutter_s}, {iso}: "
                            "the third is solved.", ["f_number", "shutter_s", "iso"])
    if light_name == "ev" and {"f_number", "shutter_s"} <= set(given):
        raise SettingsError("{ev} is the meter's EV at the ISO in use (default 100), so with {f_number} and "
                            "{shutter_s} nothing is left to solve: leave out one of them, or give {ev100} to solve "
                            "the ISO.", ["ev", "f_number", "shutter_s", "ev100"])
    if f_number is None and shutter_s is None:
        return _equivalents(level, 100.0 if iso is None else iso, loss_nd, loss_close, step, light_name,
                            _typed(light_name, (ev100, ev, light, luminance, illuminance)))
    answer = _scene(level, f_number, shutter_s, iso, loss_nd, loss_close, film, reciprocity_p, t_stop, step,
                    count, light_name, (ev100, ev, light, luminance, illuminance))
    if equivalents:
        if count != 1:
            raise SettingsError("{equivalents} needs a single exposure (one value per option).", ["equivalents"])
        values = answer.values
        return _equivalents(values["ev100"], values["iso"], loss_nd, loss_close, step, light_name,
                            _typed(light_name, (ev100, ev, light, luminance, illuminance)))
    return answer


def _typed(name: str, levels: tuple[Any, ...]) -> Any:
    """The value the user gave for the light level ``name`` (its first, for a list)."""
    value = dict(zip(LIGHT_PARAMS, levels))[name]
    return value if isinstance(value, str) else _first(value)


def _light_names(*levels: Any) -> list[str]:
    return [name for name, value in zip(LIGHT_PARAMS, levels) if _given(value)]


def _settings(f_number: Any, shutter_s: Any, iso: Any, level: Any, t_stop: bool, step: str, count: int) -> Answer:
    from camtool.exposure.ev import exposure_value
    from camtool.exposure.stops import snap_f_number, snap_iso

    zero = 0.0 * level
    values = {"f_number": f_number, "shutter_s": shutter_s, "iso": iso, "ev": exposure_value(f_number, shutter_s),
              "ev100": level, "solved": "ev100", "f_number_nominal": snap_f_number(f_number, step).nominal,
              "shutter_nominal_s": shutter_setting_s(shutter_s, step), "iso_nominal": snap_iso(iso, step).nominal,
              "nd_stops": zero, "bellows_stops": zero, "corrected_shutter_s": shutter_s, "reciprocity_stops": zero,
              "metered_f_number": f_number, "metered_shutter_s": shutter_s, "metered_iso": iso,
              "iso_change_stops": zero, "aperture_change_stops": zero, "aperture_kind": "T" if t_stop else "f",
              **_apex(f_number, shutter_s, iso, level)}
    return Answer("settings", count, values, "ev100", None, ())


def _metered(f_number: Any, shutter_s: Any, iso: Any, loss_nd: Any, loss_close: Any, film: Film | None, p: Any,
             new_iso: Any, new_f_number: Any, solve: str, t_stop: bool, step: str, count: int) -> Answer:
    """Metered settings and the changes: the settings to use, each correction in stops."""
    from camtool.exposure.ev import ev100_from_ev, exposure_value
    from camtool.exposure.stops import snap_f_number, snap_iso

    iso = 100.0 if iso is None else iso
    check("f_number", f_number)
    check("shutter_s", shutter_s)
    check("iso", iso)
    scene = ev100_from_ev(exposure_value(f_number, shutter_s), iso)
    xp = ops(f_number, shutter_s, iso)
    to_iso = iso if new_iso is None else new_iso
    to_n = f_number if new_f_number is None else new_f_number
    iso_stops = xp.log2(iso / to_iso)
    aperture_stops = 2.0 * xp.log2(to_n / f_number)
    if solve == "time":
        target = shutter_s * xp.exp2(loss_nd + loss_close + iso_stops + aperture_stops)
        _check_derived("shutter_s", shutter_s, target, "the time to set after the corrections")
        corrected = _reciprocity(target, film, p)
        _check_derived("shutter_s", shutter_s, corrected, "the time to set after reciprocity failure")
        n_set, t_set, s_set = to_n, target, to_iso
    else:
        if (solve == "f_number" and new_f_number is not None) or (solve == "iso" and new_iso is not None):
            name = "new_f_number" if solve == "f_number" else "new_iso"
            raise SettingsError("{solve} " + solve.replace("_", "-") + " solves the setting {" + name + "} gives: "
                                "give one of them.", ["solve", name])
        failure = xp.log2(_reciprocity(shutter_s, film, p) / shutter_s)
        total = loss_nd + loss_close + iso_stops + aperture_stops + failure
        t_set = corrected = target = shutter_s
        if solve == "f_number":
            n_set, s_set = f_number * xp.exp2(-total / 2.0), to_iso
            _check_derived("f_number", f_number, n_set, "the f-number to set after the corrections")
        else:
            n_set, s_set = to_n, to_iso * xp.exp2(total)
            _check_derived("iso", iso, s_set, "the ISO to set after the corrections")
    values = {"f_number": n_set, "shutter_s": t_set, "iso": s_set, "ev": exposure_value(n_set, t_set),
              "ev100": scene, "solved": {"time": "shutter_s"}.get(solve, solve),
              "f_number_nominal": snap_f_number(n_set, step).nominal,
              "shutter_nominal_s": shutter_setting_s(corrected, step), "iso_nominal": snap_iso(s_set, step).nominal,
              "nd_stops": loss_nd + 0.0 * scene, "bellows_stops": loss_close + 0.0 * scene,
              "corrected_shutter_s": corrected, "reciprocity_stops": xp.log2(corrected / target),
              "metered_f_number": f_number, "metered_shutter_s": shutter_s, "metered_iso": iso,
              "iso_change_stops": iso_stops + 0.0 * scene, "aperture_change_stops": aperture_stops + 0.0 * scene,
              "aperture_kind": "T" if t_stop else "f", **_apex(n_set, t_set, s_set, scene)}
    return Answer("metered", count, values, values["solved"], film, ())


def _check_derived(param: str, given: Any, derived: Any, what: str) -> None:
    """Refuse a derived setting outside its domain, naming the setting the user gave."""
    try:
        check(param, derived)
    except DomainError as error:
        raise DomainError(param, _first(given), f"a metered value that keeps {what} within {error.valid}",
                          f"it would be {error.value:g}") from None


def _first(value: Any) -> Any:
    try:
        return float(value)
    except TypeError:
        import numpy as np

        return float(np.asarray(value).ravel()[0])


def _scene(level: Any, f_number: Any, shutter_s: Any, iso: Any, loss_nd: Any, loss_close: Any,
           film: Film | None, p: Any, t_stop: bool, step: str, count: int, light_name: str,
           levels: tuple[Any, ...]) -> Answer:
    """Light level and two settings: solve the third (behind ND and bellows)."""
    from camtool.exposure.ev import exposure_value
    from camtool.exposure.stops import snap_f_number, snap_iso

    effective = level - loss_nd - loss_close
    try:
        if iso is None and f_number is not None and shutter_s is not None:
            xp = ops(level, f_number, shutter_s)
            iso = 100.0 * xp.exp2(exposure_value(f_number, shutter_s) - effective)
            check("iso", iso)
            solved = "iso"
        elif shutter_s is None:
            iso = 100.0 if iso is None else iso
            check("iso", iso)
            check("f_number", f_number)
            xp = ops(level, f_number, iso)
            shutter_s = f_number**2 * xp.exp2(-(effective + xp.log2(iso / 100.0)))
            check("shutter_s", shutter_s)
            solved = "shutter_s"
        else:
            iso = 100.0 if iso is None else iso
            check("iso", iso)
            check("shutter_s", shutter_s)
            xp = ops(level, shutter_s, iso)
            f_number = xp.sqrt(shutter_s * xp.exp2(effective + xp.log2(iso / 100.0)))
            check("f_number", f_number)
            solved = "f_number"
    except DomainError as error:
        if error.param not in ("shutter_s", "f_number", "iso") or error.value is iso:
            raise
        shown = _typed(light_name, levels)
        what = {"shutter_s": "time", "f_number": "f-number", "iso": "ISO"}[error.param]
        raise DomainError(light_name, shown, f"a light level these settings can expose ({what} within "
                          f"{error.valid})", f"it needs a {what} of {error.value:g}") from None
    corrected = _reciprocity(shutter_s, film, p)
    xp = ops(level, f_number, shutter_s)
    values = {"f_number": f_number, "shutter_s": shutter_s, "iso": iso, "ev": exposure_value(f_number, shutter_s),
              "ev100": level, "solved": solved, "f_number_nominal": snap_f_number(f_number, step).nominal,
              "shutter_nominal_s": shutter_setting_s(corrected, step), "iso_nominal": snap_iso(iso, step).nominal,
              "nd_stops": loss_nd + 0.0 * level, "bellows_stops": loss_close + 0.0 * level,
              "corrected_shutter_s": corrected, "reciprocity_stops": xp.log2(corrected / shutter_s),
              "metered_f_number": None, "metered_shutter_s": None, "metered_iso": None,
              "iso_change_stops": 0.0 * level, "aperture_change_stops": 0.0 * level, "aperture_kind": "T" if t_stop else "f",
              **_apex(f_number, shutter_s, iso, level)}
    return Answer("scene", count, values, solved, film, ())


def _equivalents(level: Any, iso: Any, loss_nd: Any, loss_close: Any, step: str, light_name: str,
                 typed: Any) -> Answer:
    """The f-number and time pairs for a light level at one ISO, over the stops.

    ``light_name`` and ``typed`` are the option the light level came from and
    the value the user gave it, for errors.
    """
    from camtool.exposure.equivalents import equivalent_exposures

    level, iso = _first(level), _first(iso)
    check("iso", iso)
    ev = level + math.log2(iso / 100.0) - _first(loss_nd) - _first(loss_close)
    if not EV_RANGE[0] <= ev <= EV_RANGE[1]:
        raise DomainError(light_name, typed, "a value whose settings' EV at this ISO, behind the filters, "
                          "lies within -10 to +25", f"it is {ev:.3g}")
    table = equivalent_exposures(ev, step=step)
    if not table.f_number:
        raise DomainError(light_name, typed, f"a value with times within 1/64000 s to {SHUTTER_RANGE_S[1]:g} s "
                          "between f/1 and f/32")
    n = len(table.f_number)
    values: dict[str, Any] = {**table._asdict(), "iso": [iso] * n, "ev100": [level] * n}
    return Answer("equivalents", n, values, "equivalents", None, (f"EV {ev:.2f} at ISO {iso:g}",))
