"""How a camtool command is put together: compute rows, then one writer for every mode.

A command module defines one function that turns its parameters into an
:class:`Output` (rows, the columns a table shows, the keys JSON/CSV carry,
and a footer) and decorates it with :func:`camtool_command`. The decorator
adds the shared output options (``--format``, ``--units``, ``--presets``,
``--field``) and, for commands that take one, ``--batch FILE`` with
``--on-error``; it writes the result with the one renderer. The function
never prints.

In a batch, rows of the input file are zipped into the list options instead
of combined: :func:`combine_params` does either, as the context says.
"""

from __future__ import annotations

import functools
import math
from collections.abc import Callable, Sequence
from typing import Any

import click

from camtool.cli.grid import combine
from camtool.cli.options import preset_completion, stack
from camtool.cli.rows import ZIP, Output, open_writer
from camtool.render.output import FORMATS

MAX_COMBINATIONS = 100_000
"""The most rows list options may ask for on the command line; ``--batch`` streams any number."""


def combine_params(ctx: click.Context, *lists: Sequence[float]) -> tuple[int, tuple[Any, ...]]:
    """Rows from list options: every combination on the command line, row by row in a batch.

    More than :data:`MAX_COMBINATIONS` combinations is a usage error that
    points to ``--batch``, rather than gigabytes of rows held at once.
    """
    if not ctx.meta.get(ZIP):
        count = math.prod(len(values) for values in lists)
        if count > MAX_COMBINATIONS:
            sizes = " × ".join(str(len(values)) for values in lists if len(values) > 1)
            raise click.UsageError(f"the list options ask for {sizes} = {count:,} combinations; the limit is "
                                   f"{MAX_COMBINATIONS:,} (write the scenes to a file, one per row, and use --batch, "
                                   "which streams any number)", ctx)
        return combine(*lists)
    import numpy as np

    count = max(len(values) for values in lists)
    columns = tuple(np.broadcast_to(np.asarray(values, dtype=float), (count,)).copy() for values in lists)
    return count, columns


format_option = click.option(
    "--format", "fmt", type=click.Choice(FORMATS), default="table", show_default=True, envvar="CAMTOOL_FORMAT",
    help="Output: a table for people, JSON (an array of rows, one per line) or CSV for scripts.")
presets_option = click.option(
    "--presets", "preset_files", multiple=True, type=click.Path(dir_okay=False),
    help="Extra preset file (YAML); repeatable, later files win.")

output_options = stack(
    format_option,
    click.option("--units", type=click.Choice(["metric", "imperial"]), default="metric", show_default=True,
                 help="Units of the table (JSON and CSV are always in mm, degrees and seconds)."),
    click.option("--field", "fields", multiple=True, metavar="KEY",
                 help="Print only this JSON key's value, one row per line, tab-separated when "
                      "repeated; no header (for $(...)). Infinity prints as inf."),
    presets_option,
)
"""The output options every command shares."""


equipment_options = stack(
    click.option("--camera", metavar="NAME", shell_complete=preset_completion("camera"),
                 help="Camera preset: its sensor and pixel pitch (for --coc-rule px:K)."),
    click.option("--lens", metavar="NAME", shell_complete=preset_completion("lens"),
                 help="Lens preset: focal length of a prime (a zoom needs -f in its range), f-number range, "
                      "closest focus, and pupil magnification, hiatus and prescription where known."),
    click.option("--scene", metavar="NAME", shell_complete=preset_completion("scene"),
                 help="Scene preset: camera or sensor, lens, f-number, distance, subject size, background; "
                      "options given explicitly override it."),
)
"""``--camera``, ``--lens`` and ``--scene``: presets that supply sensor, lens data and settings."""


def batch_options(function: Callable[..., Any]) -> Callable[..., Any]:
    """``--batch FILE`` and ``--on-error``."""
    function = click.option("--on-error", type=click.Choice(["stop", "skip"]), default="stop", show_default=True,
                            help="With --batch: stop at the first bad row (exit 2), or skip it: it keeps its place "
                                 "(empty in CSV, null with an error key in JSON), is reported on stderr, and the "
                                 "run exits 1.")(function)
    return click.option("--batch", metavar="FILE",
                        help="Read one scene per row from FILE (CSV with a header, or JSON lines; - for stdin; "
                             "UTF-8, a BOM is fine); columns are named like the long options, cells may carry "
                             "units; other columns are passed through to the output.")(function)


def camtool_command(
    name: str, keys: Sequence[str] = (), batch: bool = True
) -> Callable[[Callable[..., Output]], click.Command]:
    """Make a click command of a function that returns an :class:`Output`.

    ``keys`` are every key the command can output; a batch file may carry
    them as extra columns (camtool's own CSV fed back in) without error.
    """

    def decorate(compute: Callable[..., Output]) -> click.Command:
        def equipped(ctx: click.Context, /, **params: Any) -> Output:
            from camtool.cli.equipment import apply_equipment

            return compute(ctx, **apply_equipment(ctx, params))

        @functools.wraps(compute)
        def run(ctx: click.Context, /, **params: Any) -> None:
            fields = params.pop("fields")
            source = params.pop("batch", None)
            on_error = params.pop("on_error", "stop")
            fmt, units = params["fmt"], params["units"]
            if source is not None:
                from camtool.cli.batch import run_batch

                run_batch(ctx, equipped, params, source, on_error, fields)
                return
            emit(equipped(ctx, **params), fmt, units, fields)

        wrapped: Callable[..., Any] = equipment_options(output_options(run))
        if batch:
            wrapped = batch_options(wrapped)
        command = click.command(name)(click.pass_context(wrapped))
        command.output_keys = frozenset(keys)  # type: ignore[attr-defined]
        command.output_key_list = list(keys)  # type: ignore[attr-defined]
        return command

    return decorate


def emit(out: Output, fmt: str, units: str, fields: Sequence[str] = ()) -> None:
    """Write one command's output: ``--field`` values, or the chosen format."""
    writer = open_writer(fmt, units, fields)
    writer.write(out.rows, out.columns, out.keys, out.footer)
    writer.close()
