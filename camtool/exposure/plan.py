"""A whole exposure: light level, settings, ND filters, close-up and reciprocity together."""

from __future__ import annotations

from typing import Any

from camtool.core.arrays import ops
from camtool.core.domain import check
from camtool.core.errors import DomainError, require
from camtool.core.record import NamedTuple
from camtool.exposure.bellows import bellows_stops
from camtool.exposure.ev import (
    ev100_from_ev,
    exposure_value,
    solve_exposure,
)
from camtool.exposure.stops import (
    snap_f_number,
    snap_iso,
    snap_shutter_s,
)


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
    >>> from camtool.exposure.light import light_level
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
        from camtool.exposure.reciprocity import corrected_time_s

        corrected = corrected_time_s(shutter_s, reciprocity_p, reciprocity_threshold_s)
        extra = ops(corrected).log2(corrected / shutter_s)
    return ExposurePlan(
        f_number, shutter_s, iso, exposure_value(f_number, shutter_s), scene, solved, nd_stops, close_up,
        corrected, extra, snap_f_number(f_number, step).nominal, snap_shutter_s(shutter_s, step).nominal,
        snap_iso(iso, step).nominal,
    )
