"""How a camtool command is put together: compute rows, then one writer for every mode.

A command module defines one function that turns its parameters into an
:class:`Output` (rows, the columns a table shows, the keys JSON/CSV carry,
and a footer) and decorates it with :func:`camtool_command`. The decorator
adds the shared output options (``--format``, ``--units``, ``--presets``,
``--field``) and, for commands that take one, ``--batch FILE`` with
``--on-error``; it writes the result with the one renderer. The function
never prints.

In a batch, rows of the input file are zipped into the list options instead
of combined: :func:`combine_params` does either, as the context says. A grid
of combinations larger than one chunk is streamed: the command is called once
per chunk of :data:`camtool.plans.grid.CHUNK` combinations, each chunk written
as it comes, as ``--batch`` does with its input rows.
"""

from __future__ import annotations

import functools
import math
import sys
from collections.abc import Callable, Sequence
from typing import Any

import click

from camtool.cli.options import file_completion, preset_completion, stack
from camtool.cli.rows import DYNAMIC_KEYS, ZIP, Output, check_fields, open_writer
from camtool.core import collector
from camtool.plans.grid import Grid
from camtool.render.output import FORMATS

MAX_TABLE_ROWS = 100_000
"""The most combinations list options may ask for in a table, which holds every row until it is drawn.

JSON, CSV and ``--field`` output stream any number, a chunk at a time.
"""
MAX_COMBINATIONS = 2**63 - 1
"""The most combinations of any grid: row numbers are 64-bit integers."""

GRID = "camtool.grid"
"""The ``ctx.meta`` key of the :class:`~camtool.plans.grid.Grid` a command run on the command line walks."""


def combine_params(ctx: click.Context, *lists: Sequence[float]) -> tuple[int, tuple[Any, ...]]:
    """Rows from list options: the combinations on the command line (a chunk of them), row by row in a batch.

    A table of more than :data:`MAX_TABLE_ROWS` combinations is a usage
    error that points to ``--format csv``/``json``, which stream.
    """
    if not ctx.meta.get(ZIP):
        grid = ctx.meta.get(GRID)
        if grid is None:
            grid = ctx.meta[GRID] = Grid(whole=True)
        count = math.prod(len(values) for values in lists)
        limit = MAX_TABLE_ROWS if grid.whole else MAX_COMBINATIONS
        if count > limit:
            sizes = " × ".join(str(len(values)) for values in lists if len(values) > 1)
            if grid.whole:
                raise click.UsageError(f"the list options ask for {sizes} = {count:,} combinations; a table holds "
                                       f"at most {MAX_TABLE_ROWS:,} rows (use --format csv or --format json, "
                                       "which stream any number)", ctx)
            raise click.UsageError(f"the list options ask for {sizes} = {count:,} combinations; the most is "
                                   f"{MAX_COMBINATIONS:,}", ctx)
        return grid.columns(lists)
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
                 help="Lens preset: focal length of a prime (a zoom needs -f in its range; a lens set, -f or "
                      "SET@FOCAL), f-number range, closest focus, and pupil magnification, hiatus, prescription and "
                      "projection where known."),
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
    return click.option("--batch", metavar="FILE", shell_complete=file_completion,
                        help="Read one scene per row from FILE (CSV with a header, or JSON lines; - for stdin; "
                             "UTF-8, a BOM is fine); columns are named like the long options, cells may carry "
                             "units; other columns are passed through to the output.")(function)


class Command(click.Command):
    """A click command whose parser reads a known short option (``-f 50``, ``-N8``) as short at once.

    click's parser tries every option as a long one first; a short one then
    fails that match, which looks for close matches (importing ``difflib``)
    and builds an error, before it is read as short: about a millisecond of
    every command's start-up (docs/design.md §7). The parse is the same
    (``tests/test_short_options.py``); a parser without the parts this relies
    on, or a context that normalises tokens, is used as click makes it.
    """

    def make_parser(self, ctx: click.Context) -> Any:
        parser: Any = super().make_parser(ctx)
        parts = ("_short_opt", "_long_opt", "_opt_prefixes", "_process_opts", "_match_short_opt")
        if not all(hasattr(parser, name) for name in parts) or ctx.token_normalize_func is not None:
            return parser
        shorts, longs, prefixes = parser._short_opt, parser._long_opt, parser._opt_prefixes
        process, short = parser._process_opts, parser._match_short_opt

        def process_opts(arg: str, state: Any) -> None:
            if "=" not in arg and arg[:2] in shorts and arg[:2] not in prefixes and arg not in longs:
                short(arg, state)
            else:
                process(arg, state)

        parser._process_opts = process_opts
        return parser


def camtool_command(
    name: str, keys: Sequence[str] = (), batch: bool = True
) -> Callable[[Callable[..., Output]], click.Command]:
    """Make a click command of a function that returns an :class:`Output`.

    ``keys`` are every key the command can output; a batch file may carry
    them as extra columns (camtool's own CSV fed back in) without error.
    """

    def decorate(compute: Callable[..., Output]) -> click.Command:
        def equipped(ctx: click.Context, /, **params: Any) -> Output:
            from camtool.cli.common import CHOICES, t_stop_output
            from camtool.cli.equipment import apply_equipment

            ctx.meta.pop(CHOICES, None)  # nothing left over from a batch group that failed
            params = apply_equipment(ctx, params)
            collector.resume()  # off while the command was found and read (camtool.cli.main): work makes cycles
            return t_stop_output(ctx, compute(ctx, **params))

        @functools.wraps(compute)
        def run(ctx: click.Context, /, **params: Any) -> None:
            fields = params.pop("fields")
            source = params.pop("batch", None)
            on_error = params.pop("on_error", "stop")
            if fields:  # --field prints JSON keys' values: nothing drawn for a table is needed
                params["fmt"] = "json"
                if source is None and keys:  # a name no row of this command has: refused before any work
                    check_fields([f for f in fields if f not in DYNAMIC_KEYS], list(keys))
            fmt, units = params["fmt"], params["units"]
            if source is not None:
                from camtool.cli.batch import run_batch

                run_batch(ctx, equipped, params, source, on_error, fields)
                return
            grid = ctx.meta[GRID] = Grid(whole=fmt == "table", scalar=True)
            out = equipped(ctx, **params)
            if grid.scalar:
                outs = one_at_a_time(grid, out, lambda: equipped(ctx, **params), fmt == "table")
                if outs is not None:
                    emit_all(outs, fmt, units, fields)
                    return
                # a row without an answer (the grid as a whole says how), or a table drawn only from every row
                grid = ctx.meta[GRID] = Grid(whole=fmt == "table")
                out = equipped(ctx, **params)
            if grid.done:
                emit(out, fmt, units, fields)
                return
            stream_grid(ctx, grid, out, lambda: equipped(ctx, **params), fmt, units, fields)

        wrapped: Callable[..., Any] = equipment_options(output_options(run))
        if batch:
            wrapped = batch_options(wrapped)
        command = click.command(name, cls=Command)(click.pass_context(wrapped))
        command.output_keys = frozenset(keys)  # type: ignore[attr-defined]
        command.output_key_list = list(keys)  # type: ignore[attr-defined]
        return command

    return decorate


def stream_grid(ctx: click.Context, grid: Grid, first: Output, compute: Callable[[], Output], fmt: str,
                units: str, fields: Sequence[str]) -> None:
    """Write a grid chunk by chunk through one writer: ``first``, then ``compute()`` for each next chunk.

    An error in a later chunk ends the run after the chunks before it are
    written (JSON still a complete array), as a bad row ends ``--batch``.
    """
    from camtool.render.progress import progress

    writer = open_writer(fmt, units, fields)
    out = first
    with progress(f"camtool {ctx.info_name}: rows", total=grid.count) as bar:
        try:
            while True:
                writer.write(out.rows, out.columns, out.keys, out.footer)
                bar.advance(grid.stop - grid.start)
                if grid.done:
                    break
                grid.advance()
                out = compute()
        except click.ClickException:
            writer.close()
            raise
    writer.close()


def one_at_a_time(grid: Grid, first: Output, compute: Callable[[], Output], table: bool) -> list[Output] | None:
    """Every combination of a short grid, one call each (a table: one output drawn from them all); None if one
    fails or a table cannot be drawn from their plans merged.

    The vectorised grid decides what a combination without an answer means
    (a row with its reason, or the command's error), so a failure hands the
    whole grid back to it and nothing has been written yet.
    """
    if (table and first.redraw is None) or "t_stop" in first.keys:  # a T-stop's row is told from all the rows
        return None
    outs = [first]
    try:
        while not grid.done:
            if "numpy" in sys.modules:  # a combination needed it anyway (a traced lens): the grid as a whole, at once
                return None
            grid.advance()
            outs.append(compute())
        if not table:
            return outs
        drawn = first.redraw(outs)  # every output of the command can say how (a T-stop's cannot: refused above)
    except click.ClickException:
        return None
    return None if drawn is None else [drawn]


def emit_all(outs: Sequence[Output], fmt: str, units: str, fields: Sequence[str] = ()) -> None:
    """Write the outputs of a grid computed one combination at a time through one writer."""
    writer = open_writer(fmt, units, fields)
    for out in outs:
        writer.write(out.rows, out.columns, out.keys, out.footer)
    writer.close()


def emit(out: Output, fmt: str, units: str, fields: Sequence[str] = ()) -> None:
    """Write one command's output: ``--field`` values, or the chosen format."""
    emit_all([out], fmt, units, fields)
