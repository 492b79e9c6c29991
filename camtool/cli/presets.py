"""``camtool presets``: list, show, validate and import presets."""

from __future__ import annotations

import dataclasses
from typing import Any

import click

from camtool.cli.command import Output, emit, format_option, presets_option
from camtool.cli.options import preset_completion
from camtool.render.columns import TEXT, Column

KINDS = ["sensor", "camera", "lens", "prescription", "scene", "film"]
KIND_CHOICE = click.Choice(KINDS)
LIST_KEYS = ["kind", "id", "name", "summary", "tier", "origin"]
LIST_COLUMNS = [Column("kind", "kind", TEXT), Column("id", "id", TEXT), Column("summary", "summary", TEXT),
                Column("tier", "from", TEXT)]
SHOW_COLUMNS = [Column("key", "key", TEXT), Column("value", "value", TEXT)]


@click.group("presets")
def presets() -> None:
    """List, show, validate and import presets of sensors, cameras, lenses, prescriptions, scenes and films.

    Presets are read from the shipped database, a lensfun import, then
    $XDG_CONFIG_DIRS/camtool and $XDG_CONFIG_HOME/camtool (~/.config/camtool),
    then each --presets FILE; a later file wins by id.

    \b
    Examples:
      camtool presets list --kind lens --search macro
      camtool presets show full-frame
      camtool presets show dgauss100-lens
      camtool presets list --kind film
      camtool presets validate my-lenses.yaml
      camtool presets import-lensfun
    """


def _database(ctx: click.Context, preset_files: tuple[str, ...]) -> Any:
    from camtool.cli.equipment import open_presets

    return open_presets(ctx, preset_files)


def summary(preset: Any) -> str:
    """One line describing a preset, e.g. '36 × 24 mm' or '24–70 mm f/4–22'."""
    kind = type(preset).__name__.lower()
    if kind == "sensor":
        return f"{preset.width_mm:g} × {preset.height_mm:g} mm" + (" (approximate)" if preset.approximate else "")
    if kind == "camera":
        pixels = f", {preset.pixels_w} × {preset.pixels_h} px" if preset.pixels_w else ""
        return f"{preset.sensor.id} {preset.sensor.width_mm:g} × {preset.sensor.height_mm:g} mm{pixels}"
    if kind == "lens":
        focal = (f"{preset.focal_min_mm:g}–{preset.focal_max_mm:g} mm" if preset.is_zoom
                 else f"{preset.focal_min_mm:g} mm")
        stops = f" f/{preset.f_number_min:g}" if preset.f_number_min else ""
        return focal + stops + (" (prescription)" if preset.prescription is not None else "")
    if kind == "prescription":
        return f"{len(preset.surfaces)} surfaces, f = {preset.focal_length_mm or 0:g} mm"
    if kind == "film":
        film = preset.reciprocity() if hasattr(preset, "reciprocity") else preset
        model = (f"p = {film.p:g} beyond {film.threshold_s:g} s" if film.p is not None
                 else f"published table to {film.points[-1][0]:g} s")
        return f"{film.name}, reciprocity {model}"
    return preset.name


def shipped_films() -> list[Any]:
    """The films camtool ships with their makers' reciprocity data (``camtool/exposure/films.yaml``)."""
    from camtool.exposure.reciprocity import load_films

    return list(load_films().values())


FILMS_ORIGIN = "camtool/exposure/films.yaml"


@presets.command("list")
@click.option("--kind", type=KIND_CHOICE, help="Only presets of this kind.")
@click.option("--search", metavar="TEXT", help="Only presets whose id, name or aliases contain TEXT.")
@format_option
@presets_option
@click.pass_context
def list_presets(ctx: click.Context, kind: str | None, search: str | None, fmt: str,
                 preset_files: tuple[str, ...]) -> None:
    """List presets, optionally of one kind or matching a text.

    Films are the ones whose makers publish reciprocity data (what
    `camtool exposure --film` knows), then any `films:` preset of your own.

    \b
    Examples:
      camtool presets list --kind sensor
      camtool presets list --search 50mm --format json
      camtool presets list --kind film --search ilford
    """
    db = _database(ctx, preset_files)
    kinds = [kind] if kind else KINDS
    needle = (search or "").lower()
    rows = []
    for each in kinds:
        listed: list[tuple[Any, str | None, str | None]] = [(p, p.tier, p.origin) for p in db.all(each)]
        if each == "film":  # --film looks a shipped film up first, so a preset file cannot replace one
            films = shipped_films()
            ids = {f.id for f in films}
            listed = [(f, "shipped", FILMS_ORIGIN) for f in films] + [x for x in listed if x[0].id not in ids]
        for preset, tier, origin in listed:
            text = " ".join([preset.id, preset.name, *preset.aliases]).lower()
            if needle and needle not in text:
                continue
            rows.append({"kind": each, "id": preset.id, "name": preset.name, "summary": summary(preset),
                         "tier": tier, "origin": origin})
    emit(Output(rows, LIST_COLUMNS, LIST_KEYS, f"{len(rows)} preset{'' if len(rows) == 1 else 's'}"), fmt, "metric")


def describe(db: Any, preset: Any) -> dict[str, Any]:
    """Every field of a preset, its derived values and, for a prescription, its first-order data."""
    fields: dict[str, Any] = {"kind": type(preset).__name__.lower()}
    for item in dataclasses.fields(preset):
        value = getattr(preset, item.name)
        if dataclasses.is_dataclass(value):
            value = getattr(value, "id", value)  # a referenced preset (a camera's sensor, a scene's lens)
        elif isinstance(value, tuple):
            value = list(value)
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


@presets.command("show")
@click.argument("name", shell_complete=preset_completion("lens"))
@click.option("--kind", type=KIND_CHOICE, help="The kind, when a name is used by several kinds.")
@format_option
@presets_option
@click.pass_context
def show(ctx: click.Context, name: str, kind: str | None, fmt: str, preset_files: tuple[str, ...]) -> None:
    """Show every field of a preset, its derived values and the file it came from.

    For a lens with a prescription (or a prescription) it also prints the
    first-order data of a paraxial trace: focal length, back focal distance,
    principal planes, pupils, pupil magnification and hiatus (positions in mm
    from the first surface).

    \b
    Examples:
      camtool presets show nikon-z-8
      camtool presets show dgauss100-lens --format json
      camtool presets show hp5
    """
    from camtool.presets import PresetNotFound

    db = _database(ctx, preset_files)
    film = _shipped_film(name) if kind in (None, "film") else None
    try:
        if film is not None:
            preset = film
        elif kind:
            preset = db.get(kind, name)
        else:
            found = db.find(name)
            if not found:
                close = [c for k in KINDS for c in db.suggestions(k, name)][:3]
                hint = f"; did you mean {', '.join(close)}?" if close else ""
                raise click.BadParameter(f"no preset is named {name!r}{hint}", ctx=ctx, param_hint="'NAME'")
            preset = found[0]
    except PresetNotFound as error:
        raise click.BadParameter(str(error), ctx=ctx, param_hint="'NAME'") from None
    if film is not None:
        fields: dict[str, Any] = {"kind": "film", **film._asdict(), "tier": "shipped", "origin": FILMS_ORIGIN}
        fields["points"] = [list(point) for point in film.points] or None  # (metered s, extra stops)
        fields["aliases"] = list(film.aliases)
        origin = FILMS_ORIGIN
    else:
        fields = describe(db, preset)
        origin = preset.origin
    if fmt == "table":
        if fields["kind"] == "film" and fields.get("points"):
            fields["points"] = ", ".join(f"{t:g} s +{stops:.2g} EV" for t, stops in fields["points"])
        rows = [{"key": key, "value": _show_value(value)} for key, value in fields.items() if value is not None]
        emit(Output(rows, SHOW_COLUMNS, ["key", "value"], f"{fields['kind']} {preset.id} from {origin}"),
             fmt, "metric")
    else:
        emit(Output([fields], SHOW_COLUMNS, list(fields)), fmt, "metric")


def _shipped_film(name: str) -> Any:
    """The shipped film of this name (id, name or alias, as --film reads it), or None."""
    from camtool.core.errors import DomainError
    from camtool.exposure.reciprocity import find_film

    try:
        return find_film(name)
    except DomainError:
        return None


def _show_value(value: Any) -> str:
    if isinstance(value, float):
        return f"{value:.6g}"
    if isinstance(value, list):
        return ", ".join(map(str, value))
    return str(value)


@presets.command("validate")
@click.argument("file", type=click.Path(dir_okay=False))
def validate(file: str) -> None:
    """Check a preset file and list every problem (exit 1 if there is any).

    \b
    Examples:
      camtool presets validate ~/.config/camtool/lenses.yaml
    """
    from camtool.presets import validate_file

    problems = validate_file(file)
    if problems:
        for problem in problems:
            click.echo(problem, err=True)
        raise click.ClickException(f"{file}: {len(problems)} problem{'s' if len(problems) != 1 else ''}")
    click.echo(f"{file}: ok")


@presets.command("import-lensfun")
@click.option("--dir", "dirs", multiple=True, type=click.Path(file_okay=False),
              help="lensfun XML directory (repeatable); default: the system's lensfun database and its updates.")
@click.option("--out", type=click.Path(dir_okay=False),
              help="Output preset file; default $XDG_DATA_HOME/camtool/lensfun.yaml, read as the lensfun tier.")
def import_lensfun(dirs: tuple[str, ...], out: str | None) -> None:
    """Import cameras (as sensors from their crop factor, marked approximate) and lenses from lensfun.

    lensfun is the lens database of darktable and RawTherapee (Debian
    package liblensfun-data-v1, under /usr/share/lensfun/version_1/); camtool
    reads the copy on your system and ships none of it. A bad file is skipped,
    never fatal; the output is written atomically.

    \b
    Examples:
      camtool presets import-lensfun
      camtool presets import-lensfun --dir ./lensfun-db --out lensfun.yaml
    """
    from camtool.presets.lensfun import LensfunImportError
    from camtool.presets.lensfun import import_lensfun as run_import

    try:
        result = run_import(list(dirs) or None, out)
    except LensfunImportError as error:
        raise click.ClickException(str(error)) from None
    click.echo(f"imported {result.sensors} sensors and {result.lenses} lenses from {result.files} files "
               f"into {result.path}; skipped {result.skipped_total}")
    for reason, count in sorted(result.skipped.items()):
        click.echo(f"  skipped {count}: {reason}")
    for path, why in result.bad_files:
        click.echo(f"  bad file {path}: {why}", err=True)
