"""``--batch FILE``: one scene per input row, streamed in chunks through the vectorised core.

The input is CSV with a header row, or JSON lines (one object per line); the
format is told by the first non-blank character (``{`` means JSON lines). The
file is UTF-8, with or without a byte-order mark (Excel's "CSV UTF-8"); a
UTF-16 file with its byte-order mark is read too. Columns are named like the
command's long options (``focal-length``, ``f_number``, ``--distance``,
``FNumber``: case, dashes, underscores and leading dashes do not matter), or
like the output keys with a unit suffix (``distance_mm``), which makes
camtool's own CSV a valid batch file (its other output keys are passed
over). Any other column (``SourceFile``, ``file``, a note) is passed through:
it leads each output row unchanged, so results join back to their inputs; a
column whose name is a near miss of an option's is an error instead. Cells
may carry units (``3m``); bare numbers mean what they mean on the command
line, except in ``*_mm`` columns, which are millimetres. Options given on the
command line apply to every row; a column overrides them.

Rows are read in chunks of :data:`CHUNK` rows; within a chunk, rows sharing
the same non-numeric settings (sensor, model, ...) are computed in one
vectorised call (a failing call is bisected to find its bad rows), and the
output keeps the input order. Output goes through the one
:class:`~camtool.render.output.RowWriter`: memory stays bounded for JSON, CSV
and ``--field`` output; a table is drawn once at the end from every row.

A bad row stops the run (exit 2) after the rows before it are written (JSON
still a complete array); with ``--on-error skip`` it keeps its place in the
output, is reported on standard error in row order, and the run exits 1.
"""

from __future__ import annotations

import codecs
import csv
import difflib
import io
import json
import os
import sys
from collections.abc import Callable, Iterator
from typing import IO, Any

import click

from camtool.cli.params import _ListType
from camtool.cli.rows import ZIP, Output, open_writer
from camtool.render.columns import TEXT, Column
from camtool.render.output import RowWriter

CHUNK = 20_000
CONTROL = {"fmt", "units", "preset_files", "fields", "batch", "on_error"}
CELL_LIMIT = 128 * 1024
"""Longest cell, in characters (the csv module's limit); a longer one is a bad row."""
LINE_LIMIT = 1024 * 1024
"""Longest line read whole; the rest of a longer one is dropped and the row is bad."""

PASS = ("", None)
"""What :meth:`_Columns.resolve` returns for a column passed through to the output."""


class BatchRowError(click.ClickException):
    """A bad input row: its number (1 = first data row) and column are in the message; exit 2."""

    exit_code = 2


class BatchFileError(click.ClickException):
    """A batch file that cannot be read (missing, a directory, not text): exit 1."""

    exit_code = 1


def _normalise(name: str) -> str:
    return name.strip().lstrip("-").replace("-", "_").lower()


def _loose(name: str) -> str:
    return _normalise(name).replace("_", "")


def open_source(source: str) -> tuple[IO[str], str]:
    """The batch text stream (``-`` is standard input) and the name errors call it.

    UTF-8 with or without a byte-order mark, or UTF-16 with one; a FIFO
    reads like a pipe; a directory or unreadable file is a :class:`BatchFileError`.
    """
    if source == "-":
        binary: Any = sys.stdin.buffer
        name = "standard input"
    else:
        name = source
        if os.path.isdir(source):
            raise BatchFileError(f"--batch {source}: is a directory, not a file")
        try:
            binary = open(source, "rb")  # noqa: SIM115 - closed by the caller through the text wrapper
        except OSError as error:
            raise BatchFileError(f"--batch {source}: cannot read it ({error.strerror})") from None
    if not hasattr(binary, "peek"):
        binary = io.BufferedReader(binary)
    try:
        head = binary.peek(4)[:4]
    except OSError as error:
        raise BatchFileError(f"--batch {name}: cannot read it ({error.strerror})") from None
    if head.startswith(codecs.BOM_UTF8):
        encoding = "utf-8-sig"
    elif head.startswith((codecs.BOM_UTF16_LE, codecs.BOM_UTF16_BE)):
        encoding = "utf-16"
    else:
        encoding = "utf-8"
    return io.TextIOWrapper(binary, encoding=encoding, newline=""), name


def _lines(source: IO[str]) -> Iterator[str]:
    """The lines of ``source``, none longer than :data:`LINE_LIMIT` (memory stays bounded)."""
    while True:
        line = source.readline(LINE_LIMIT)
        if not line:
            return
        if len(line) >= LINE_LIMIT and not line.endswith("\n"):
            while True:  # drop the rest of the over-long line; what is left fails as a too-long cell
                rest = source.readline(LINE_LIMIT)
                if not rest or rest.endswith("\n"):
                    break
            line += "\n"
        yield line


Record = tuple[int, "dict[str, Any] | None", "str | None"]


def _records(source: IO[str], name: str) -> Iterator[Record]:
    """(row number, {column: cell}, None) per input row, or (row number, None, error) for a bad one."""
    lines = _lines(source)
    first = ""
    for line in lines:
        if line.strip():
            first = line
            break
    if not first:
        return
    if "\x00" in first:
        raise BatchFileError(f"--batch {name}: looks like UTF-16 text without a byte-order mark; "
                             "save it as UTF-8 (in Excel: CSV UTF-8)")
    if first.lstrip().startswith("{"):
        number = 0
        for line in _chain(first, lines):
            if not line.strip():
                continue
            number += 1
            try:
                record = json.loads(line)
            except json.JSONDecodeError as error:
                yield number, None, f"--batch row {number}: not valid JSON ({error.msg})"
                continue
            if not isinstance(record, dict):
                yield number, None, f"--batch row {number}: expected a JSON object"
                continue
            yield number, record, None
    else:
        reader = csv.reader(_chain(first, lines))
        header = next(reader)
        number = 0
        while True:
            try:
                cells = next(reader)
            except StopIteration:
                return
            except csv.Error as error:
                number += 1
                yield number, None, f"--batch row {number}: {_csv_message(error)}"
                continue
            if not cells:
                continue
            number += 1
            if len(cells) > len(header):
                yield number, None, (f"--batch row {number}: {len(cells)} cells, more than the "
                                     f"{len(header)} header columns")
                continue
            yield number, dict(zip(header, cells)), None


def _csv_message(error: csv.Error) -> str:
    text = str(error)
    if "field limit" in text:
        return f"a cell longer than {CELL_LIMIT // 1024} KiB"
    return f"not valid CSV ({text})"


def _chain(first: str, rest: Iterator[str]) -> Iterator[str]:
    yield first
    yield from rest


class _Columns:
    """Maps input column names to the command's parameters (and unit suffixes)."""

    def __init__(self, command: click.Command) -> None:
        self.params = {p.name: p for p in command.params
                       if isinstance(p, click.Option) and p.name and p.name not in CONTROL}
        self.aliases: dict[str, tuple[str, str | None]] = {}
        for param in self.params.values():
            assert param.name is not None
            for opt in param.opts:
                self.aliases[_loose(opt)] = (param.name, None)
            self.aliases[_loose(param.name)] = (param.name, None)
        for key, target in _KEY_ALIASES.items():
            if target[0] in self.params:
                self.aliases.setdefault(_loose(key), target)
        self.ignored = {_loose(key) for key in getattr(command, "output_keys", frozenset())}
        self.known: dict[str, tuple[str, str | None] | None] = {}
        self.passed: list[str] = []

    def resolve(self, column: str) -> tuple[str, str | None] | None:
        """(parameter name, unit of bare numbers) for a column; None for an output key; PASS to pass through."""
        if column not in self.known:
            target = self._resolve(column)
            self.known[column] = target
            if target == PASS:
                self.passed.append(column)
        return self.known[column]

    def _resolve(self, column: str) -> tuple[str, str | None] | None:
        key = _loose(column)
        if key in self.aliases:
            return self.aliases[key]
        if key.endswith("mm") and key[:-2] in self.aliases:
            return self.aliases[key[:-2]][0], "mm"
        if key in self.ignored:
            return None
        near = difflib.get_close_matches(key, list(self.aliases), n=1, cutoff=0.85)
        if near and key:
            option = self.params[self.aliases[near[0]][0]].opts[-1]
            raise BatchRowError(f"--batch: column {column!r} names no option; did you mean {option}? (a column "
                                "that names no option is passed through to the output: rename it to keep it)")
        return PASS


# Output keys that feed back in as inputs (camtool's CSV is a valid batch file).
_KEY_ALIASES = {"focal_length_mm": ("focal_length", "mm"), "distance_mm": ("distance", "mm"),
                "near_mm": ("near", "mm"), "far_mm": ("far", "mm"), "coc_mm": ("coc", "mm")}


def _convert(ctx: click.Context, param: click.Parameter, cell: str, unit: str | None, number: int,
             column: str) -> Any:
    text = cell.strip()
    if unit and text and text[-1].isdigit():
        text += unit
    try:
        value = param.type.convert(text, param, ctx)
    except click.BadParameter as error:
        raise BatchRowError(f"--batch row {number}, column {column!r}: {error.format_message()}") from None
    if isinstance(param.type, _ListType):
        if len(value) != 1:
            raise BatchRowError(f"--batch row {number}, column {column!r}: one value per cell, not {cell!r}")
        return value[0]
    return value


Parsed = tuple[int, dict[str, Any], dict[str, Any]]
"""(row number, parameter values, passed-through cells) of a good input row."""


def run_batch(ctx: click.Context, compute: Callable[..., Output], params: dict[str, Any], source: str,
              on_error: str, fields: tuple[str, ...]) -> None:
    """Compute and write one output row per input row, chunk by chunk; exit 1 if a row was skipped."""
    columns = _Columns(ctx.command)
    defaults = {name: _single(params.get(name), name) for name, param in columns.params.items()
                if isinstance(param.type, _ListType)}
    writer = open_writer(params["fmt"], params["units"], fields)
    batch = _Batch(ctx, compute, params, defaults, columns, writer, on_error)
    stream, name = open_source(source)
    try:
        with stream:
            chunk: list[Parsed] = []
            bad: dict[int, tuple[str, dict[str, Any]]] = {}
            for number, record, error in _records(stream, name):
                passed: dict[str, Any] = {}
                if error is None:
                    assert record is not None
                    values, passed, error = _parse(ctx, columns, record, number)
                    if error is None:
                        chunk.append((number, values, passed))
                if error is not None:
                    bad[number] = (error, passed)
                    if on_error == "stop":
                        break
                if len(chunk) + len(bad) >= CHUNK:
                    batch.run(chunk, bad)
                    chunk, bad = [], {}
            batch.run(chunk, bad)
    except UnicodeDecodeError as error:
        batch.end(failed=True)
        raise BatchFileError(f"--batch {name}: not UTF-8 text ({error.reason}, byte 0x{error.object[error.start]:02x}); "
                             "save it as UTF-8 (in Excel: CSV UTF-8)") from None
    except click.ClickException:
        batch.end(failed=True)
        raise
    batch.end()
    if batch.skipped:
        click.echo(f"camtool: {batch.skipped} of {batch.total} rows skipped", err=True)
        ctx.exit(1)


def _parse(ctx: click.Context, columns: _Columns, record: dict[str, Any], number: int) -> tuple[
        dict[str, Any], dict[str, Any], str | None]:
    """A row's parameter values, its passed-through cells, and the error of its first bad cell."""
    values: dict[str, Any] = {}
    passed: dict[str, Any] = {}
    error = None
    for column, cell in record.items():
        target = columns.resolve(column)
        if target is None:
            continue
        if target == PASS:
            passed[column] = cell
            continue
        text = "" if cell is None else cell if isinstance(cell, str) else str(cell)
        if not text.strip() or error is not None:
            continue
        name, unit = target
        try:
            values[name] = _convert(ctx, columns.params[name], text, unit, number, column)
        except BatchRowError as row_error:
            error = row_error.format_message()
    return values, passed, error


class _Batch:
    """Computes chunks of parsed rows and writes them in input order."""

    def __init__(self, ctx: click.Context, compute: Callable[..., Output], params: dict[str, Any],
                 defaults: dict[str, Any], columns: _Columns, writer: RowWriter, on_error: str) -> None:
        self.ctx, self.compute, self.params, self.defaults = ctx, compute, params, defaults
        self.columns, self.writer, self.on_error = columns, writer, on_error
        self.skipped = self.total = 0
        self.shape: tuple[list[Column], list[str]] | None = None
        self.fallback: list[str] = []

    def run(self, chunk: list[Parsed], bad: dict[int, tuple[str, dict[str, Any]]]) -> None:
        """Compute one chunk and write its rows; in stop mode, the rows before the first bad one, then raise."""
        results: dict[int, tuple[dict[str, Any], Output]] = {}
        bad = dict(bad)
        groups: dict[tuple[Any, ...], list[Parsed]] = {}
        for member in chunk:
            settings = tuple(sorted((k, _hashable(v)) for k, v in member[1].items()
                                    if not isinstance(self.columns.params[k].type, _ListType)))
            groups.setdefault(settings, []).append(member)
        for members in groups.values():
            self._solve(members, results, bad)
        order = sorted([*results, *bad])
        self.total += len(order)
        run: list[dict[str, Any]] = []
        current: Output | None = None
        for number in order:
            if number in bad:
                self._flush(run, current)
                run = []
                message, passed = bad[number]
                if self.on_error == "stop":
                    raise BatchRowError(message)
                click.echo(f"Error: {message} (skipped)", err=True)
                self.skipped += 1
                self._start_shape()
                self.writer.skip(message, passed)
                continue
            row, out = results[number]
            if out is not current:
                self._flush(run, current)
                run, current = [], out
            run.append(row)
        self._flush(run, current)

    def _solve(self, members: list[Parsed], results: dict[int, tuple[dict[str, Any], Output]],
               bad: dict[int, tuple[str, dict[str, Any]]]) -> None:
        """Compute a group in one call; if it fails, halve it until the bad rows are found."""
        try:
            out = self._compute_group(members)
        except click.ClickException as error:
            if len(members) > 1:
                half = len(members) // 2
                self._solve(members[:half], results, bad)
                self._solve(members[half:], results, bad)
                return
            number, _, passed = members[0]
            message = error.format_message()
            bad[number] = (message if isinstance(error, BatchRowError) else f"--batch row {number}: {message}",
                           passed)
            return
        for (number, _, passed), row in zip(members, out.rows):
            if passed:
                row = {**passed, **row}
            results[number] = (row, out)

    def _compute_group(self, members: list[Parsed]) -> Output:
        merged = dict(self.params)
        first = members[0][1]
        for name, param in self.columns.params.items():
            if isinstance(param.type, _ListType):
                present = [values.get(name) for _, values, _ in members]
                if any(v is not None for v in present):
                    default = self.defaults[name]
                    if default is None and any(v is None for v in present):
                        missing = next(n for n, v in zip((n for n, _, _ in members), present) if v is None)
                        raise BatchRowError(f"--batch row {missing}: no value for {param.opts[-1]}")
                    merged[name] = [[v if v is not None else default for v in present]]
            elif name in first:
                merged[name] = first[name]
        self.ctx.meta[ZIP] = True
        try:
            return self.compute(self.ctx, **merged)
        finally:
            self.ctx.meta[ZIP] = False

    def _flush(self, rows: list[dict[str, Any]], out: Output | None) -> None:
        if out is None or not rows:
            return
        if self.shape is None:
            passed = self.columns.passed
            self.shape = ([*(Column(k, k, TEXT) for k in passed), *out.columns], [*passed, *out.keys])
        self.writer.write(rows, self.shape[0], self.shape[1], out.footer)

    def _start_shape(self) -> None:
        """Keys for skipped rows before any row was computed: the passed-through columns and the command's."""
        if self.writer.keys is None and not self.writer.pending:
            keys = getattr(self.ctx.command, "output_key_list", [])
            self.fallback = [*self.columns.passed, *keys]

    def end(self, failed: bool = False) -> None:
        """Close the output: a complete JSON document, the table of every row written.

        After an error, output that never started stays empty.
        """
        if failed and self.writer.keys is None:
            return
        self.writer.close(self.fallback, [Column(k, k, TEXT) for k in self.fallback])


def _hashable(value: Any) -> Any:
    return tuple(value) if isinstance(value, list) else value


def _single(value: Any, name: str) -> Any:
    flat = [v for group in value or () for v in (group if isinstance(group, list) else [group])]
    if len(flat) > 1:
        raise click.UsageError(f"with --batch, --{name.replace('_', '-')} takes one value on the command line")
    return flat[0] if flat else None
