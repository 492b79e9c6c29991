"""Exposure: EV and EV100, light levels, equivalents, ND filters, bellows, plans, stops, metering, reciprocity, times."""

import os as _os


def films_path() -> str:
    """Where the films shipped with their makers' reciprocity data are: ``films.yaml`` in this package (read by
    :func:`camtool.exposure.reciprocity.load_films`; listed by ``presets list`` without importing it)."""
    return _os.path.join(_os.path.dirname(_os.path.abspath(__file__)), "films.yaml")
