"""Shipped films against their makers' published reciprocity figures (sources in films.yaml)."""

from __future__ import annotations

import itertools
import math

import pytest

from camtool.core.errors import DomainError
from camtool.exposure.reciprocity import film_time_s, find_film, load_films


@pytest.mark.parametrize(
    ("film", "metered", "corrected"),
    [
        # Foma, FOMAPAN 100 Classic data sheet, Schwarzschild effect: 1 s x2, 10 s x8, 100 s x16.
        ("fomapan100", 1.0, 2.0),
        ("fomapan100", 10.0, 80.0),
        ("fomapan100", 100.0, 1600.0),
        # Foma, FOMAPAN 200 Creative data sheet: 1 s x3, 10 s x9, 100 s x18.
        ("fomapan200", 1.0, 3.0),
        ("fomapan200", 10.0, 90.0),
        ("fomapan200", 100.0, 1800.0),
        # Foma, FOMAPAN 400 Action data sheet: 1 s x1.5, 10 s x6, 100 s x8.
        ("fomapan400", 1.0, 1.5),
        ("fomapan400", 10.0, 60.0),
        ("fomapan400", 100.0, 800.0),
        # Kodak F-4017, Tri-X: 100 s indicated -> 1200 s adjusted (1 s -> 2 s, 10 s -> 50 s too).
        ("tri-x", 100.0, 1200.0),
        ("tri-x", 10.0, 50.0),
        ("tri-x", 1.0, 2.0),
        # Kodak F-4017: no adjustment at 1/10 s.
        ("tri-x", 0.1, 0.1),
        # Foma data sheets: no lengthening from 1/1000 s to 1/2 s.
        ("fomapan100", 0.5, 0.5),
        ("fomapan400", 1 / 1000, 1 / 1000),
        # Kodak E-7022 (Gold) and E-4046 (Ektar 100): no adjustment from 1/10,000 s to 1 s.
        ("gold200", 1.0, 1.0),
        ("gold", 1 / 10000, 1 / 10000),
        ("ektar100", 1.0, 1.0),
        ("ektar", 0.25, 0.25),
    ],
)
def test_published_figures(film: str, metered: float, corrected: float) -> None:
    assert film_time_s(find_film(film), metered) == pytest.approx(corrected, rel=1e-12)


@pytest.mark.parametrize(
    ("film", "beyond", "last"),
    [
        ("fomapan100", 101.0, "100 s"),  # Foma's table ends at 100 s
        ("fomapan200", 120.0, "100 s"),
        ("fomapan400", 1000.0, "100 s"),
        ("tri-x", 100.5, "100 s"),  # Kodak F-4017 ends at 100 s
        ("gold200", 2.0, "1 s"),  # Kodak E-7022: beyond 1 s "make tests"
        ("ektar100", 1.5, "1 s"),  # Kodak E-4046: beyond 1 s "make tests"
    ],
)
def test_refused_beyond_the_published_range(film: str, beyond: float, last: str) -> None:
    with pytest.raises(DomainError, match=f"up to {last}"):
        film_time_s(find_film(film), beyond)


def test_between_points_interpolated_in_stops_against_log_time() -> None:
    # Fomapan 100: 1 s is +1 stop, 10 s is +3 stops (x8); the geometric mid-point sqrt(10) s is
    # half way in log time, so +2 stops: 4 x sqrt(10) s.
    got = film_time_s(find_film("fomapan100"), math.sqrt(10.0))
    assert got == pytest.approx(4.0 * math.sqrt(10.0), rel=1e-12)
    # Tri-X between 1/10 s (none) and 1 s (+1 stop): 0.1*sqrt(10) s gets +1/2 stop.
    got = film_time_s(find_film("tri-x"), 0.1 * math.sqrt(10.0))
    assert got == pytest.approx(0.1 * math.sqrt(10.0) * math.sqrt(2.0), rel=1e-12)


def test_corrections_never_shorten_and_grow_with_time() -> None:
    # A physical identity of reciprocity failure: the given time is at least the metered time and
    # rises with it, for every shipped film within its published range.
    for film in load_films().values():
        last = film.valid_to_s or (film.points[-1][0] if film.points else 1e4)
        times = [last * 2.0**-k for k in range(14)][::-1]  # down to 1/16384 of the last time
        given = [film_time_s(film, t) for t in times]
        assert all(g >= t * (1 - 1e-12) for g, t in zip(given, times, strict=True)), film.id
        assert all(b > a for a, b in itertools.pairwise(given)), film.id


def test_every_film_names_its_source() -> None:
    for film in load_films().values():
        assert len(film.source) > 20, film.id


@pytest.mark.parametrize("name", ["Fomapan 100 Classic", "foma 400", "FOMAPAN-200", "Ektar", "Gold 200"])
def test_new_films_found_by_name_or_alias(name: str) -> None:
    assert find_film(name).id in load_films()
