"""Named light levels (the sunny-16 family and the ANSI exposure guide) as EV100."""

from __future__ import annotations

import re

from camtool.core.errors import DomainError
from camtool.core.record import NamedTuple


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
    camtool.core.errors.DomainError: light=dusk is outside the valid range: one of snow, sunny, slight-overcast, overcast, heavy-overcast, shade, sunset, after-sunset, full-moon, bright-street, night-street, office, home-interior, floodlit-buildings, distant-city-lights, moonlight
    """
    key = re.sub(r"[\s_]+", "-", name.strip().lower())
    try:
        return LIGHT_LEVELS[key]
    except KeyError:
        raise DomainError("light", name, "one of " + ", ".join(LIGHT_LEVELS)) from None
