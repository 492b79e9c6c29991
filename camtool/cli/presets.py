"""``camtool presets``: list, show, validate and import presets."""

from __future__ import annotations

from typing import Any

import click

from camtool.cli.command import Output, emit, format_option, presets_option
from camtool.cli.options import preset_completion
from camtool.core import collector
from camtool.plans import presets as plan
from camtool.plans.presets import KINDS
from camtool.render.views.presets import LIST_COLUMNS, LIST_KEYS, SHOW_COLUMNS, show_rows

KIND_CHOICE = click.Choice(KINDS)


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
    collector.resume()  # the subcommand's work begins (camtool.cli.main)


def _database(ctx: click.Context, preset_files: tuple[str, ...]) -> Any:
    from camtool.cli.equipment import open_presets

    return open_presets(ctx, preset_files)


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
    rows = [row._asdict() for row in plan.list_presets(database=_database(ctx, preset_files), kind=kind, search=search)]
    emit(Output(rows, LIST_COLUMNS, LIST_KEYS, f"{len(rows)} preset{'' if len(rows) == 1 else 's'}"), fmt, "metric")


@presets.command("show")
@click.argument("name", shell_complete=preset_completion(*KINDS))
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

    try:
        shown = plan.show_preset(database=_database(ctx, preset_files), name=name, kind=kind)
    except PresetNotFound as error:
        raise click.BadParameter(str(error), ctx=ctx, param_hint="'NAME'") from None
    fields = shown.fields
    if fmt != "table":
        emit(Output([fields], SHOW_COLUMNS, list(fields)), fmt, "metric")
        return
    rows = show_rows(shown.kind, fields)
    emit(Output(rows, SHOW_COLUMNS, ["key", "value"], f"{shown.kind} {shown.id} from {shown.origin}"), fmt, "metric")


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
    """Import cameras (sensor sized from their crop factor, marked approximate) and lenses from lensfun.

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
    from camtool.render.progress import progress

    with progress("camtool presets import-lensfun: files") as bar:
        def on_files(done: int, total: int) -> None:
            bar.grow(total)
            bar.advance(done - bar.done)

        try:
            result = run_import(list(dirs) or None, out, on_files)
        except LensfunImportError as error:
            raise click.ClickException(str(error)) from None
    click.echo(f"imported {result.cameras} cameras and {result.lenses} lenses from {result.files} files "
               f"into {result.path}; skipped {result.skipped_total}")
    for reason, count in sorted(result.skipped.items()):
        click.echo(f"  skipped {count}: {reason}")
    for path, why in result.bad_files:
        click.echo(f"  bad file {path}: {why}", err=True)
