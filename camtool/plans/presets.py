"""Presets: which ones a listing holds, what a preset shows, and the film a name stands for.

Films are read from two places: the films camtool ships with their makers'
reciprocity data (``camtool/exposure/films.yaml``) come first, so a preset
file cannot replace one, then any ``films:`` preset of the user's own. A
listing holds one :class:`PresetRow` per preset; :func:`show_preset` gives
every field of one preset with its derived values and, for a prescription
(or a lens with one), its paraxial first-order data.
"""

from __future__ import annotations

import os
from collections.abc import Callable
from typing import Any

from camtool.core.record import NamedTuple, Record
from camtool.core.record import fields as fields_of
from camtool.presets import PresetNotFound
from camtool.presets.summary import summary

__all__ = ["FILMS_ORIGIN", "KINDS", "NoSuchPreset", "PresetRow", "PresetShown", "describe", "film",
           "first_order_fields", "list_presets", "show_preset", "summary"]

KINDS = ["sensor", "camera", "lens", "prescription", "scene", "film"]
FILMS_ORIGIN = "camtool/exposure/films.yaml"


class NoSuchPreset(PresetNotFound):
    """No preset of any kind is named ``name``; ``suggestions`` are the closest ids of every kind."""

    def __str__(self) -> str:
        hint = f"; did you mean {', '.join(self.suggestions)}?" if self.suggestions else ""
        return f"no preset is named {self.name!r}{hint}"


class PresetRow(NamedTuple):
    """One line of a listing: the preset's kind, id, name, one-line summary, tier and file."""

    kind: str
    id: str
    name: str
    summary: str
    tier: str | None
    origin: str | None


class PresetShown(NamedTuple):
    """One preset: its kind, id, the file it came from, and every field by name (derived values included)."""

    kind: str
    id: str
    origin: str | None
    fields: dict[str, Any]


def shipped_films() -> list[Any]:
    """The films camtool ships with their makers' reciprocity data (``camtool/exposure/films.yaml``)."""
    from camtool.exposure.reciprocity import load_films

    return list(load_films().values())


def list_presets(*, database: Any, kind: str | None = None, search: str | None = None) -> list[PresetRow]:
    """The presets of ``kind`` (every kind when None) whose id, name or aliases contain ``search``.

    Decides the order (by kind, as :data:`KINDS`, then as the database holds
    them) and that the shipped films come first and hide a preset of the same id.
    """
    needle = (search or "").lower()
    rows = []
    for each in [kind] if kind else KINDS:
        shipped = database.shipped_listing(each) if each != "film" else None
        if shipped is not None:  # the shipped files alone, as the build listed them (the same rows, not rebuilt)
            rows += _shipped_rows(each, shipped, needle)
            continue
        film_rows = _listed_films(database, needle) if each == "film" else None
        if film_rows is not None:  # the shipped films and the shipped files' films, as the build listed them
            rows += film_rows
            continue
        listed: list[tuple[Any, str | None, str | None]] = [(p, p.tier, p.origin) for p in database.all(each)]
        if each == "film":
            films = shipped_films()
            ids = {f.id for f in films}
            listed = [(f, "shipped", FILMS_ORIGIN) for f in films] + [x for x in listed if x[0].id not in ids]
        rows += [PresetRow(each, preset.id, preset.name, summary(preset), tier, origin) for preset, tier, origin in listed
                 if _matches(needle, preset.id, preset.name, preset.aliases)]
    return rows


def _matches(needle: str, preset_id: str, name: str, aliases: Any) -> bool:
    """Whether a listing's search text (lower case; empty: every preset) is in a preset's id, name or aliases."""
    return not needle or needle in " ".join([preset_id, name, *aliases]).lower()


def _shipped_rows(kind: str, listed: list[list[Any]], needle: str) -> list[PresetRow]:
    """The rows of ``kind`` the build listed (``[id, name, aliases, summary, file under lens_db/]``) that match."""
    from camtool.presets.paths import shipped_dir

    directory = shipped_dir()
    files: dict[str, str] = {}  # a file's path joined once, not once a row
    return [PresetRow(kind, preset_id, name, line, "shipped",
                      files.get(origin) or files.setdefault(origin, os.path.join(directory, *origin.split("/"))))
            for preset_id, name, aliases, line, origin in listed if _matches(needle, preset_id, name, aliases)]


def _listed_films(database: Any, needle: str) -> list[PresetRow] | None:
    """The film rows of :func:`list_presets` from the build's listings (see :mod:`camtool.presets.shipped`), when the
    database holds the shipped files alone and ``films.yaml`` has the bytes the build read (else None)."""
    from camtool.exposure import films_path
    from camtool.presets.shipped_records import shipped_films

    in_files = database.shipped_listing("film")
    if in_files is None:
        return None
    try:
        with open(films_path(), "rb") as handle:
            shipped = shipped_films(handle.read())
    except OSError:  # a package not on the file system: the films are read one by one
        return None
    if shipped is None:
        return None
    ids = {film[0] for film in shipped}
    return ([PresetRow("film", film_id, name, line, "shipped", FILMS_ORIGIN) for film_id, name, aliases, line in shipped
             if _matches(needle, film_id, name, aliases)]
            + [row for row in _shipped_rows("film", in_files, needle) if row.id not in ids])


def show_preset(*, database: Any, name: str, kind: str | None = None) -> PresetShown:
    """The preset ``name`` (of ``kind``, else the first kind that has it; a shipped film first) with every field.

    Raises :class:`~camtool.presets.PresetNotFound` (:class:`NoSuchPreset`
    when no kind has the name, with the closest ids of every kind).
    """
    shipped = _shipped_film(name) if kind in (None, "film") else None
    if shipped is not None:
        fields: dict[str, Any] = {"kind": "film", **shipped._asdict(), "tier": "shipped", "origin": FILMS_ORIGIN}
        fields["points"] = [list(point) for point in shipped.points] or None  # (metered s, extra stops)
        fields["aliases"] = list(shipped.aliases)
        return PresetShown("film", shipped.id, FILMS_ORIGIN, fields)
    if kind or "@" in name:  # NAME@FOCAL: a member of a lens set
        preset = database.get(kind or "lens", name)
    else:
        found = database.find(name)
        if not found:
            raise NoSuchPreset("preset", name, [c for k in KINDS for c in database.suggestions(k, name)][:3])
        preset = found[0]
    fields = describe(preset)
    return PresetShown(fields["kind"], preset.id, preset.origin, fields)


def describe(preset: Any) -> dict[str, Any]:
    """Every field of a preset, its derived values and, for a prescription, its first-order data."""
    fields: dict[str, Any] = {"kind": type(preset).__name__.lower()}
    for item in fields_of(preset):
        value = getattr(preset, item.name)
        if isinstance(value, Record):
            value = getattr(value, "id", value)  # a referenced preset (a camera's sensor, a scene's lens)
        elif isinstance(value, tuple):
            # a lens set's members are presets of their own (SET@FOCAL): named here, shown on their own
            value = [getattr(v, "id", v) if isinstance(v, Record) else v for v in value]
        if item.name not in ("data", "prescription", "optics"):
            fields[item.name] = value
    for derived in ("diagonal_mm", "crop_factor", "aspect_ratio", "pixel_pitch_mm", "megapixels"):
        if hasattr(preset, derived):
            fields[derived] = getattr(preset, derived)
    lens = getattr(preset, "optics", None) if fields["kind"] == "prescription" else getattr(preset, "prescription", None)
    if lens is not None:
        fields.update(first_order_fields(lens))
    return fields


def first_order_fields(lens: Any) -> dict[str, Any]:
    """The paraxial first-order data of a prescription, as preset fields (positions from the first vertex)."""
    from camtool.optics.paraxial import first_order

    data = first_order(lens)
    return {
        "efl_mm": data.efl_mm, "back_focal_distance_mm": data.bfd_mm,
        "front_principal_plane_mm": data.z_h_mm, "rear_principal_plane_mm": data.z_h_prime_mm,
        "entrance_pupil_mm": data.z_e_mm, "exit_pupil_mm": data.z_x_mm,
        "pupil_magnification_paraxial": data.pupil_magnification, "hiatus_paraxial_mm": data.hiatus_mm,
    }


def _shipped_film(name: str) -> Any:
    """The shipped film of this name (id, name or alias, as --film reads it), or None."""
    from camtool.core.errors import DomainError
    from camtool.exposure.reciprocity import find_film

    try:
        return find_film(name)
    except DomainError:
        return None


def film(name: str, *, database: Callable[[], Any]) -> Any:
    """The film ``name`` stands for: a shipped film, else a ``films`` preset of ``database()`` (opened only then).

    Raises the shipped films' :class:`~camtool.core.errors.DomainError` on
    ``film`` when neither has the name.
    """
    from camtool.core.errors import DomainError
    from camtool.exposure.reciprocity import find_film

    try:
        return find_film(name)
    except DomainError as error:
        unknown = error
    try:
        return database().film(name).reciprocity()
    except PresetNotFound:
        raise unknown from None
