"""Presets: which ones a listing holds, what a preset shows, and the film a name stands for.

Films are read from two places: the films camtool ships with their makers'
reciprocity data (``camtool/exposure/films.yaml``) come first, so a preset
file cannot replace one, then any ``films:`` preset of the user's own. A
listing holds one :class:`PresetRow` per preset; :func:`show_preset` gives
every field of one preset with its derived values and, for a prescription
(or a lens with one), its paraxial first-order data.
"""

from __future__ import annotations

from collections.abc import Callable
from typing import Any, NamedTuple

from camtool.core.record import Record
from camtool.core.record import fields as fields_of
from camtool.presets import PresetNotFound

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


def summary(preset: Any) -> str:
    """One line describing a preset, e.g. '36 × 24 mm' or '24–70 mm f/4–22'.

    >>> from camtool.presets import Sensor
    >>> summary(Sensor("full-frame", "Full frame", 36.0, 24.0))
    '36 × 24 mm'
    """
    kind = type(preset).__name__.lower()
    if kind == "sensor":
        return f"{preset.width_mm:g} × {preset.height_mm:g} mm" + (" (approximate)" if preset.approximate else "")
    if kind == "camera":
        pixels = f", {preset.pixels_w} × {preset.pixels_h} px" if preset.pixels_w else ""
        return f"{preset.sensor.id} {preset.sensor.width_mm:g} × {preset.sensor.height_mm:g} mm{pixels}"
    if kind == "lens":
        focal = (f"{preset.focal_min_mm:g}–{preset.focal_max_mm:g} mm" if preset.is_zoom
                 else f"{preset.focal_min_mm:g} mm")
        if preset.members:
            return "set: " + ", ".join(f"{m.focal_min_mm:g}" for m in preset.members) + " mm"
        stops = f" f/{preset.f_number_min:g}" if preset.f_number_min else ""
        return focal + stops + (" (prescription)" if preset.prescription is not None else "")
    if kind == "prescription":
        return f"{len(preset.surfaces)} surfaces, f = {preset.focal_length_mm or 0:g} mm"
    if kind == "film":
        film = preset.reciprocity() if hasattr(preset, "reciprocity") else preset
        model = (f"p = {film.p:g} beyond {film.threshold_s:g} s" if film.p is not None
                 else f"published table to {film.points[-1][0]:g} s")
        return f"{film.name}, reciprocity {model}"
    return str(preset.name)


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
        listed: list[tuple[Any, str | None, str | None]] = [(p, p.tier, p.origin) for p in database.all(each)]
        if each == "film":
            films = shipped_films()
            ids = {f.id for f in films}
            listed = [(f, "shipped", FILMS_ORIGIN) for f in films] + [x for x in listed if x[0].id not in ids]
        for preset, tier, origin in listed:
            if needle and needle not in " ".join([preset.id, preset.name, *preset.aliases]).lower():
                continue
            rows.append(PresetRow(each, preset.id, preset.name, summary(preset), tier, origin))
    return rows


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
