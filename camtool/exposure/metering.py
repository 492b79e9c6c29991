"""Light metering: exposure from scene luminance (reflected) and illuminance (incident), and back.

The exposure-meter equations of ISO 2720 tie camera settings to the light:

    N²/t = L·S/K        (reflected light, luminance L in cd/m²)
    N²/t = E·S/C        (incident light, illuminance E in lux)

with the calibration constants K (12.5 for Canon, Nikon and Sekonic; 14 for
Minolta and Kenko) and C (250 for a flat diffuser, 320–340 for a hemisphere).
Taking log2 of both sides gives the EV of the settings at ISO S; at S = 100
it is the scene's EV100. The APEX quantities (Av, Tv, Sv, Bv, Iv) are here too.

Scalars in, floats out; arrays in, arrays out.
"""

from __future__ import annotations

from typing import Any

from camtool.core.arrays import ops
from camtool.core.domain import check
from camtool.core.errors import require
from camtool.exposure.ev import exposure_value

K_REFLECTED = 12.5
"""Reflected-light meter calibration constant K in cd·s/m² (ISO 2720; Canon, Nikon, Sekonic)."""
C_INCIDENT = 250.0
"""Incident-light meter calibration constant C in lx·s (ISO 2720, flat receptor)."""
APEX_SPEED_ZERO_ISO = 3.125
"""ISO speed at which APEX Sv = 0 (Sv = log2(S/3.125), so ISO 100 is Sv 5)."""
APEX_N = 0.3
"""APEX constant relating Bv and Iv to luminance and illuminance (ASA PH2.5-1960)."""


def _positive(param: str, value: Any, unit: str) -> None:
    require(param, value, value > 0, f"> 0 {unit}")


def ev_from_luminance(luminance_cd_m2: Any, iso: Any = 100.0, k: Any = K_REFLECTED) -> Any:
    """EV of the settings that expose a surface of luminance L correctly at ISO S: log2(L·S/K).

    At S = 100 this is the scene's EV100.

    Parameters
    ----------
    luminance_cd_m2 : float or array, > 0 cd/m²
    iso : float or array, 1 to 10⁷
    k : float or array, meter calibration constant, > 0 (12.5 by default)

    References
    ----------
    ISO 2720:1974, "General purpose photographic exposure meters (photoelectric
    type) — Guide to product specification"; Wikipedia, "Light meter",
    "Exposure value" (EV vs. luminance table, K = 12.5).

    Examples
    --------
    >>> ev_from_luminance(0.125)
    0.0
    >>> ev_from_luminance(4096.0)
    15.0
    """
    _positive("luminance_cd_m2", luminance_cd_m2, "cd/m²")
    _positive("meter_k", k, "")
    check("iso", iso)
    return ops(luminance_cd_m2, iso, k).log2(luminance_cd_m2 * iso / k)


def ev_from_illuminance(illuminance_lux: Any, iso: Any = 100.0, c: Any = C_INCIDENT) -> Any:
    """EV of the settings that expose a subject lit by illuminance E correctly at ISO S: log2(E·S/C).

    Parameters
    ----------
    illuminance_lux : float or array, > 0 lx
    iso : float or array, 1 to 10⁷
    c : float or array, incident meter calibration constant, > 0 (250 by default)

    References
    ----------
    ISO 2720:1974; Wikipedia, "Light meter" (incident-light calibration constant C).

    Examples
    --------
    >>> ev_from_illuminance(160.0)
    6.0
    """
    _positive("illuminance_lux", illuminance_lux, "lx")
    _positive("meter_c", c, "")
    check("iso", iso)
    return ops(illuminance_lux, iso, c).log2(illuminance_lux * iso / c)


def luminance_from_ev100(ev100: Any, k: Any = K_REFLECTED) -> Any:
    """Luminance in cd/m² of a scene of EV100: L = K·2^EV100/100.

    >>> luminance_from_ev100(15.0)
    4096.0
    """
    check("ev100", ev100)
    _positive("meter_k", k, "")
    return k * ops(ev100, k).exp2(ev100) / 100.0


def illuminance_from_ev100(ev100: Any, c: Any = C_INCIDENT) -> Any:
    """Illuminance in lux on a subject of EV100 (incident reading): E = C·2^EV100/100.

    >>> illuminance_from_ev100(6.0)
    160.0
    """
    check("ev100", ev100)
    _positive("meter_c", c, "")
    return c * ops(ev100, c).exp2(ev100) / 100.0


def luminance_from_exposure(f_number: Any, shutter_s: Any, iso: Any, k: Any = K_REFLECTED) -> Any:
    """Scene luminance in cd/m² that settings N, t, S expose correctly: L = N²·K/(t·S).

    Examples
    --------
    >>> round(luminance_from_exposure(2.8, 0.125, 100.0), 10)
    7.84
    """
    check("iso", iso)
    _positive("meter_k", k, "")
    ev = exposure_value(f_number, shutter_s)
    return k * ops(ev, iso, k).exp2(ev) / iso


def illuminance_from_exposure(f_number: Any, shutter_s: Any, iso: Any, c: Any = C_INCIDENT) -> Any:
    """Illuminance in lux that settings N, t, S expose correctly (incident): E = N²·C/(t·S).

    Examples
    --------
    >>> round(illuminance_from_exposure(2.8, 0.125, 100.0), 10)
    156.8
    """
    check("iso", iso)
    _positive("meter_c", c, "")
    ev = exposure_value(f_number, shutter_s)
    return c * ops(ev, iso, c).exp2(ev) / iso


# --- APEX (Additive System of Photographic Exposure) ----------------------
#
# Av + Tv = Bv + Sv = Ev, each term in stops (ASA PH2.5-1960; Wikipedia, "APEX system").


def aperture_value(f_number: Any) -> Any:
    """APEX aperture value Av = log2(N²) = 2·log2(N), in stops.

    >>> aperture_value(22.0) > 8.9
    True
    """
    check("f_number", f_number)
    return 2.0 * ops(f_number).log2(f_number)


def time_value(shutter_s: Any) -> Any:
    """APEX time value Tv = log2(1/t), in stops (1/125 s is about 7).

    >>> time_value(0.125)
    3.0
    """
    check("shutter_s", shutter_s)
    return -ops(shutter_s).log2(shutter_s)


def speed_value(iso: Any, zero_iso: Any = APEX_SPEED_ZERO_ISO) -> Any:
    """APEX speed value Sv = log2(S/S₀), in stops; S₀ = 3.125 in APEX (ISO 100 → Sv 5).

    ``zero_iso=100`` gives stops above ISO 100, a common variant.

    >>> speed_value(100.0)
    5.0
    """
    check("iso", iso)
    return ops(iso, zero_iso).log2(iso / zero_iso)


def brightness_value(luminance_cd_m2: Any, k: Any = K_REFLECTED) -> Any:
    """APEX brightness value Bv = log2(L/(N·K)), N = 0.3, in stops.

    >>> round(brightness_value(3.75), 12)
    0.0
    """
    _positive("luminance_cd_m2", luminance_cd_m2, "cd/m²")
    return ops(luminance_cd_m2, k).log2(luminance_cd_m2 / (APEX_N * k))


def incident_value(illuminance_lux: Any, c: Any = C_INCIDENT) -> Any:
    """APEX incident-light value Iv = log2(E/(N·C)), N = 0.3, in stops.

    >>> round(incident_value(75.0), 12)
    0.0
    """
    _positive("illuminance_lux", illuminance_lux, "lx")
    return ops(illuminance_lux, c).log2(illuminance_lux / (APEX_N * c))
