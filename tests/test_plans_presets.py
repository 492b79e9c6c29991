"""camtool.plans.presets called directly: keyword arguments, named results, checked against published values."""

from __future__ import annotations

import math

import pytest

from camtool.core.errors import DomainError
from camtool.plans import presets as plan
from camtool.presets import PresetNotFound, load_db


@pytest.fixture(scope="module")
def db():  # type: ignore[no-untyped-def]
    return load_db(lensfun=False)


def test_listing_rows_are_named(db) -> None:  # type: ignore[no-untyped-def]
    rows = plan.list_presets(database=db, kind="sensor", search="full-frame")
    row = next(r for r in rows if r.id == "full-frame")
    assert row.kind == "sensor" and row.summary == "36 × 24 mm"  # the 135 film frame, 36 × 24 mm
    assert all(r.kind == "sensor" for r in rows)
    assert plan.list_presets(database=db, search="no-preset-has-this-text") == []


def test_shipped_films_come_first_and_are_listed_once(db) -> None:  # type: ignore[no-untyped-def]
    rows = plan.list_presets(database=db, kind="film")
    hp5 = next(r for r in rows if r.id == "ilford-hp5-plus")
    assert hp5.tier == "shipped" and hp5.origin == plan.FILMS_ORIGIN
    assert hp5.summary == "Ilford HP5 Plus, reciprocity p = 1.31 beyond 1 s"  # Ilford's sheet: t_c = t_m^1.31
    assert len({r.id for r in rows}) == len(rows)


def test_show_derived_values_obey_their_identities(db) -> None:  # type: ignore[no-untyped-def]
    shown = plan.show_preset(database=db, name="full-frame")
    assert shown.kind == "sensor" and shown.id == "full-frame" and shown.origin
    assert shown.fields["diagonal_mm"] == pytest.approx(math.hypot(36.0, 24.0), rel=1e-15)
    assert shown.fields["crop_factor"] == pytest.approx(1.0, rel=1e-15)


def test_show_prescription_first_order_data(db) -> None:  # type: ignore[no-untyped-def]
    fields = plan.show_preset(database=db, name="dgauss100", kind="prescription").fields
    # the design's published focal length is 100 mm; the hiatus is the rear minus the front principal plane
    assert fields["efl_mm"] == pytest.approx(100.0, rel=1e-3)
    assert fields["hiatus_paraxial_mm"] == pytest.approx(
        fields["rear_principal_plane_mm"] - fields["front_principal_plane_mm"], abs=1e-9)


def test_unknown_names(db) -> None:  # type: ignore[no-untyped-def]
    with pytest.raises(plan.NoSuchPreset, match="no preset is named 'full-fram'; did you mean full-frame"):
        plan.show_preset(database=db, name="full-fram")
    with pytest.raises(PresetNotFound):
        plan.show_preset(database=db, name="full-frame", kind="lens")


def test_film_shipped_first_database_only_when_needed() -> None:
    def unused():  # type: ignore[no-untyped-def]
        raise AssertionError("the database is opened only for a name the shipped films do not know")

    assert plan.film("hp5", database=unused).p == 1.31  # Ilford HP5 Plus data sheet
    with pytest.raises(DomainError) as error:
        plan.film("no-such-film", database=lambda: load_db(lensfun=False))
    assert error.value.param == "film"
