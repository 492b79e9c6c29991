"""Reciprocity-law failure of film in long exposures (Schwarzschild's power law).

Film grows less sensitive when the light is weak and the exposure long: a
metered time t_m beyond about a second has to be stretched to

    t_c = t_m^p        (t_m > 1 s; t_c = t_m otherwise)

with a film's Schwarzschild exponent p > 1. The exponents ship with camtool
in ``camtool/exposure/films.yaml`` (Ilford's published values, source in the
file); any other film works through :func:`corrected_time_s` with its own p.
"""

from __future__ import annotations

import difflib
import functools
import re
from typing import Any, NamedTuple

from camtool.core.arrays import ops
from camtool.core.domain import check
from camtool.core.errors import DomainError, require

P_RANGE = (1.0, 3.0)


class Film(NamedTuple):
    """A film's reciprocity data: ``p`` applies to metered times above ``threshold_s``."""

    id: str
    name: str
    p: float
    threshold_s: float
    aliases: tuple[str, ...]
    source: str


def corrected_time_s(metered_s: Any, p: Any, threshold_s: Any = 1.0) -> Any:
    """Exposure time in seconds corrected for reciprocity failure: t_c = t₀·(t_m/t₀)^p above t₀.

    With the usual t₀ = 1 s this is Ilford's t_c = t_m^p; shorter metered
    times are returned unchanged, and the curve is continuous at t₀.

    Parameters
    ----------
    metered_s : float or array, 1/64000 s to 10⁶ s
    p : float or array, Schwarzschild exponent, 1 to 3
    threshold_s : float or array, > 0 s (1 s for Ilford's films)

    References
    ----------
    Ilford Photo, "Reciprocity Law Failure Compensation" (technical
    information sheet); K. Schwarzschild, "On the deviations from the law of
    reciprocity for bromide of silver gelatine", *Astrophys. J.* 11 (1900) 89.

    Examples
    --------
    >>> round(corrected_time_s(10.0, 1.31), 1)
    20.4
    >>> corrected_time_s(0.5, 1.31)
    0.5
    """
    check("shutter_s", metered_s)
    require("reciprocity_p", p, (p >= P_RANGE[0]) & (p <= P_RANGE[1]), "1 to 3")
    require("threshold_s", threshold_s, threshold_s > 0, "> 0 s")
    xp = ops(metered_s, p, threshold_s)
    ratio = xp.maximum(metered_s / threshold_s, 1.0)
    return xp.where(metered_s > threshold_s, threshold_s * ratio**p, metered_s)


def reciprocity_stops(metered_s: Any, p: Any, threshold_s: Any = 1.0) -> Any:
    """Extra exposure in stops that reciprocity failure asks for: log2(t_c/t_m).

    >>> round(reciprocity_stops(10.0, 1.31), 2)
    1.03
    """
    corrected = corrected_time_s(metered_s, p, threshold_s)
    return ops(corrected).log2(corrected / metered_s)


def _key(name: str) -> str:
    """Lookup key: lower case, '+' read as 'plus', punctuation and spaces dropped."""
    return re.sub(r"[^a-z0-9]", "", name.lower().replace("+", "plus"))


@functools.lru_cache(maxsize=1)
def load_films() -> dict[str, Film]:
    """The shipped films, by id, read once from ``camtool/exposure/films.yaml``.

    >>> load_films()["ilford-hp5-plus"].p
    1.31
    """
    from importlib.resources import files

    import yaml

    data = yaml.safe_load(files("camtool.exposure").joinpath("films.yaml").read_text(encoding="utf-8"))
    return {
        entry["id"]: Film(entry["id"], entry["name"], float(entry["p"]), float(entry.get("threshold_s", 1.0)),
                          tuple(entry.get("aliases", ())), entry.get("source", data["source"]))
        for entry in data["films"]
    }


def find_film(name: str) -> Film:
    """Look a film up by id, name or alias, ignoring case and punctuation ("HP5+", "hp5 plus").

    Examples
    --------
    >>> find_film("HP5+").name
    'Ilford HP5 Plus'
    >>> find_film("delta 300")
    Traceback (most recent call last):
    ...
    camtool.core.errors.DomainError: film=delta 300 is outside the valid range: a known film (did you mean ilford-delta-100, ilford-delta-3200, ilford-delta-400?)
    """
    films = load_films()
    index: dict[str, Film] = {}
    for film in films.values():
        for label in (film.id, film.name, *film.aliases):
            index[_key(label)] = film
    found = index.get(_key(name))
    if found is not None:
        return found
    close = difflib.get_close_matches(_key(name), list(index), n=6, cutoff=0.6)
    ids = sorted({index[k].id for k in close})
    hint = f"did you mean {', '.join(ids)}?" if ids else "known: " + ", ".join(films)
    raise DomainError("film", name, "a known film", hint)
