"""Reciprocity-law failure of film in long exposures (Schwarzschild's power law).

Film grows less sensitive when the light is weak and the exposure long: a
metered time t_m beyond about a second has to be stretched to

    t_c = t_m^p        (t_m > 1 s; t_c = t_m otherwise)

with a film's Schwarzschild exponent p > 1. The films ship with camtool
in ``camtool/exposure/films.yaml``, each as its maker publishes it: an
exponent (Ilford, Kentmere, CineStill's guide) or a table of metered and
adjusted times (Kodak, Fujifilm), with the source per film; any other film
works through :func:`corrected_time_s` with its own p.
"""

from __future__ import annotations

import contextlib
import functools
import itertools
import math
import re
from typing import Any

from camtool.core.arrays import is_scalar, ops
from camtool.core.domain import check
from camtool.core.errors import CamtoolError, DomainError, require
from camtool.core.record import NamedTuple
from camtool.exposure import films_path

P_RANGE = (1.0, 3.0)


class Film(NamedTuple):
    """A film's reciprocity data, as its maker publishes it.

    Either a Schwarzschild exponent ``p`` applying to metered times above
    ``threshold_s`` (Ilford, CineStill), or a table ``points`` of
    (metered time in s, extra exposure in stops) (Kodak, Fujifilm), valid up
    to ``valid_to_s``, its last metered time.
    """

    id: str
    name: str
    p: float | None
    threshold_s: float
    aliases: tuple[str, ...]
    source: str
    points: tuple[tuple[float, float], ...] = ()
    valid_to_s: float | None = None

    def corrected_time_s(self, metered_s: Any) -> Any:
        """The time to give for a metered time, by this film's exponent or table (see :func:`film_time_s`)."""
        return film_time_s(self, metered_s)


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


def _stops(value: Any) -> float:
    """A table entry's correction: '+1/3 stops' or '+1 stops' (a string), in stops."""
    text = str(value).replace("stops", "").replace("stop", "").strip().lstrip("+")
    if "/" in text:
        numerator, denominator = text.split("/")
        return float(numerator) / float(denominator)
    return float(text)


def table_stops(points: tuple[tuple[float, float], ...], metered_s: float) -> float:
    """Extra stops from a published table at a metered time: linear in log2(time) between points.

    No correction below the first point (every data sheet treats short times
    as needing none); beyond the last point the caller must refuse.

    >>> pts = ((0.1, 0.0), (1.0, 1 / 3), (10.0, math.log2(1.5)), (100.0, 1.0))
    >>> round(table_stops(pts, 10.0), 4), round(table_stops(pts, math.sqrt(10.0)), 4)
    (0.585, 0.4591)
    """
    if metered_s <= points[0][0]:
        return 0.0 if metered_s < points[0][0] else points[0][1]
    for (t0, s0), (t1, s1) in itertools.pairwise(points):
        if metered_s <= t1:
            w = math.log2(metered_s / t0) / math.log2(t1 / t0)
            return s0 + w * (s1 - s0)
    return points[-1][1]


def film_time_s(film: Film, metered_s: Any) -> Any:
    """Time in seconds to give ``film`` for a metered time: its exponent, or its table interpolated.

    Raises :class:`DomainError` on ``film`` when the metered time is beyond
    the film's published data.

    Examples
    --------
    >>> round(film_time_s(find_film("hp5"), 10.0), 1)  # Ilford's worked example
    20.4
    >>> film_time_s(find_film("tmax100"), 100.0)  # Kodak F-4016: 100 s -> 200 s
    200.0
    """
    if film.p is not None:
        return corrected_time_s(metered_s, film.p, film.threshold_s)
    check("shutter_s", metered_s)
    valid = film.valid_to_s or film.points[-1][0]
    require("film", film.id, metered_s <= valid * (1 + 1e-9),
            f"{film.name} has published data for metered times up to {valid:g} s")
    if is_scalar(metered_s):
        return metered_s * 2.0 ** table_stops(film.points, float(metered_s))
    import numpy as np

    flat = [t * 2.0 ** table_stops(film.points, float(t)) for t in np.asarray(metered_s).ravel()]
    return np.asarray(flat).reshape(np.shape(metered_s))


def _key(name: str) -> str:
    """Lookup key: lower case, '+' read as 'plus', punctuation and spaces dropped."""
    return re.sub(r"[^a-z0-9]", "", name.lower().replace("+", "plus"))


@functools.lru_cache(maxsize=1)
def load_films() -> dict[str, Film]:
    """The shipped films, by id, read once from ``camtool/exposure/films.yaml``.

    >>> load_films()["ilford-hp5-plus"].p
    1.31
    """
    data = _film_table()
    return {entry["id"]: film_from_entry(entry, data["source"]) for entry in data["films"]}


def _film_table() -> dict[str, Any]:
    """``films.yaml`` parsed: from the cache (:mod:`camtool.core.cache`) when its entry is bound to these bytes,
    else by PyYAML (and the entry written). Every entry is checked by :func:`film_from_entry` either way."""
    import json
    import os

    from camtool.core import cache

    try:  # the file beside this module (importlib.resources costs a few ms of start-up to say the same)
        with open(films_path(), "rb") as handle:
            raw = handle.read()
    except OSError:  # a package not on the file system (a zip)
        from importlib.resources import files

        raw = files("camtool.exposure").joinpath("films.yaml").read_bytes()
    path = os.path.join(cache.root(), "films.json")
    source = cache.source_digest(raw) if cache.enabled() else ""
    payload = cache.read(path, "films", source, 8 * len(raw) + 4096) if source else None
    if payload is not None:
        try:
            data = json.loads(payload)
        except ValueError:
            data = None
        try:  # checked as the fresh table is: an entry that fails is parsed again from the YAML
            if isinstance(data, dict) and isinstance(data["source"], str):
                for entry in data["films"]:
                    film_from_entry(entry, data["source"])
                return data
        except (CamtoolError, ValueError, TypeError, KeyError, AttributeError):
            pass
    import yaml

    data = yaml.safe_load(raw.decode("utf-8"))
    if source:
        with contextlib.suppress(ValueError, TypeError):  # a value JSON cannot hold: not cached
            cache.write(path, "films", source, cache.dumps(data))
    return data


def film_from_entry(entry: dict[str, Any], default_source: str = "") -> Film:
    """A :class:`Film` from one entry of ``films.yaml`` (or a ``films`` preset): ``p`` or ``points``.

    >>> film_from_entry({"id": "x", "name": "X", "points": [[1, 2], [10, "+2 stops"]]}).points
    ((1.0, 1.0), (10.0, 2.0))
    """
    points: tuple[tuple[float, float], ...] = ()
    for metered, given in entry.get("points", ()):
        t = float(metered)
        stops = _stops(given) if isinstance(given, str) else math.log2(float(given) / t)
        points += ((t, stops),)
    p = entry.get("p")
    if p is None and not points:
        raise DomainError("film", entry.get("id", "?"), "an exponent p or a table of points")
    if p is not None:
        require("reciprocity_p", float(p), P_RANGE[0] <= float(p) <= P_RANGE[1], "1 to 3")
    if any(b[0] <= a[0] for a, b in itertools.pairwise(points)):
        raise DomainError("film", entry.get("id", "?"), "points in increasing metered time")
    return Film(str(entry["id"]), str(entry.get("name", entry["id"])), None if p is None else float(p),
                float(entry.get("threshold_s", 1.0)), tuple(str(a) for a in entry.get("aliases", ())),
                str(entry.get("source", default_source)), points,
                float(entry["valid_to_s"]) if "valid_to_s" in entry else None)


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
    import difflib  # only on this error path

    close = difflib.get_close_matches(_key(name), list(index), n=6, cutoff=0.65)
    ids = sorted({index[k].id for k in close})
    hint = (f"did you mean {', '.join(ids)}?" if ids else
            "films with published data: " + ", ".join(films) + "; for another, give --reciprocity-p or a films preset")
    raise DomainError("film", name, "a known film", hint)
