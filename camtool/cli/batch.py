"""``--batch FILE``: one scene per input row, streamed in chunks through the vectorised core.

The input is CSV with a header row, or JSON lines (one object per line); the
format is told by the first non-blank character (``{`` means JSON lines).
Columns are named like the command's long options (``focal-length``,
``f_number``, ``--distance``: dashes, underscores and leading dashes are all
accepted), or like the output keys with a unit suffix (``distance_mm``), which
makes camtool's own CSV a valid batch file (its other output keys are passed
over). Cells may carry units (``3m``);
bare numbers mean what they mean on the command line, except in ``*_mm``
columns, which are millimetres. Options given on the command line apply to
every row; a column overrides them.

Rows are read in chunks of :data:`CHUNK` rows; within a chunk, rows sharing
the same non-numeric settings (sensor, model, ...) are computed in one
vectorised call, and the output keeps the input order. Memory stays bounded
for JSON, CSV and ``--field`` output; a table gets one table per chunk.
"""

from __future__ import annotations

import csv
import json
import sys
from collections.abc import Callable, Iterator
from typing import IO, Any

import click

from camtool.cli.params import _ListType
from camtool.cli.rows import ZIP, Output, check_fields, field_line
from camtool.render.serial import plain

CHUNK = 20_000
CONTROL = {"fmt", "units", "preset_files"}


class BatchRowError(click.ClickException):
    """A bad input row: its number (1 = first data row) and column are in the message; exit 2."""

    exit_code = 2


def _normalise(name: str) -> str:
    return name.strip().lstrip("-").replace("-", "_").lower()


def _records(source: IO[str]) -> Iterator[tuple[int, dict[str, str]]]:
    """(row number, {column: cell}) for each input row; row 1 is the first data row."""
    first = ""
    for line in source:
        if line.strip():
            first = line
            break
    if not first:
        return
    if first.lstrip().startswith("{"):
        number = 0
        for line in _chain(first, source):
            if not line.strip():
                continue
            number += 1
            try:
                record = json.loads(line)
            except json.JSONDecodeError as error:
                raise BatchRowError(f"--batch row {number}: not valid JSON ({error.msg})") from None
            if not isinstance(record, dict):
                raise BatchRowError(f"--batch row {number}: expected a JSON object")
            yield number, {k: ("" if v is None else str(v)) for k, v in record.items()}
    else:
        reader = csv.DictReader(_chain(first, source))
        for number, record in enumerate(reader, start=1):
            if None in record:
                raise BatchRowError(f"--batch row {number}: more cells than header columns")
            yield number, {k: (v or "") for k, v in record.items()}


def _chain(first: str, rest: IO[str]) -> Iterator[str]:
    yield first
    yield from rest


class _Columns:
    """Maps input column names to the command's parameters (and unit suffixes)."""

    def __init__(self, command: click.Command) -> None:
        self.params = {p.name: p for p in command.params if isinstance(p, click.Option) and p.name not in CONTROL}
        self.aliases: dict[str, tuple[str, str | None]] = {}
        for param in self.params.values():
            for opt in param.opts:
                self.aliases[_normalise(opt)] = (param.name, None)
            self.aliases[_normalise(param.name)] = (param.name, None)
        for key, target in _KEY_ALIASES.items():
            if target[0] in self.params:
                self.aliases.setdefault(key, target)

        self.ignored: frozenset[str] = getattr(command, "output_keys", frozenset())
        self.known: dict[str, tuple[str, str | None] | None] = {}

    def resolve(self, column: str) -> tuple[str, str | None] | None:
        """(parameter name, unit of bare numbers) for a column; None for an output key to pass over."""
        if column not in self.known:
            self.known[column] = self._resolve(column)
        return self.known[column]

    def _resolve(self, column: str) -> tuple[str, str | None] | None:
        key = _normalise(column)
        if key in self.aliases:
            return self.aliases[key]
        if key.endswith("_mm") and key[:-3] in self.aliases:
            return self.aliases[key[:-3]][0], "mm"
        if key in self.ignored:
            return None
        raise BatchRowError(f"--batch: column {column!r} names no option of this command")


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


def run_batch(ctx: click.Context, compute: Callable[..., Output], params: dict[str, Any], source: IO[str],
              on_error: str, fields: tuple[str, ...]) -> None:
    """Compute and write one output row per input row, chunk by chunk."""
    columns = _Columns(ctx.command)
    writer = _Writer(params["fmt"], params["units"], fields)
    chunk: list[tuple[int, dict[str, Any]]] = []
    for number, record in _decoded(ctx, source):
        try:
            chunk.append((number, _parse(ctx, columns, record, number)))
        except BatchRowError as error:
            if on_error == "stop":
                raise
            click.echo(f"Error: {error.format_message()} (skipped)", err=True)
        if len(chunk) >= CHUNK:
            writer.write(_compute_chunk(ctx, compute, params, chunk, columns, on_error))
            chunk = []
    if chunk:
        writer.write(_compute_chunk(ctx, compute, params, chunk, columns, on_error))
    writer.close()


def _decoded(ctx: click.Context, source: IO[str]) -> Iterator[tuple[int, dict[str, str]]]:
    """The records of ``source``; a file that is not UTF-8 is one line naming --batch and the file, exit 1."""
    from camtool.cli.options import FileParameterError, param_named

    try:
        yield from _records(source)
    except UnicodeDecodeError as error:
        raise FileParameterError(f"{getattr(source, 'name', '-')}: not UTF-8 text (byte {error.start}); save it as "
                                 "UTF-8", ctx=ctx, param=param_named(ctx, "batch")) from None


def _parse(ctx: click.Context, columns: _Columns, record: dict[str, str], number: int) -> dict[str, Any]:
    values: dict[str, Any] = {}
    for column, cell in record.items():
        if column is None or not cell.strip():
            continue
        target = columns.resolve(column)
        if target is None:
            continue
        name, unit = target
        values[name] = _convert(ctx, columns.params[name], cell, unit, number, column)
    return values


def _compute_chunk(ctx: click.Context, compute: Callable[..., Output], params: dict[str, Any],
                   chunk: list[tuple[int, dict[str, Any]]], columns: _Columns, on_error: str) -> Output | None:
    """Group the chunk's rows by their non-numeric settings and compute each group in one call."""
    groups: dict[tuple[Any, ...], list[tuple[int, dict[str, Any]]]] = {}
    for number, values in chunk:
        settings = tuple(sorted((k, _hashable(v)) for k, v in values.items()
                                if not isinstance(columns.params[k].type, _ListType)))
        groups.setdefault(settings, []).append((number, values))
    results: list[tuple[int, dict[str, Any]]] = []
    last: Output | None = None
    bad: list[tuple[int, str]] = []
    for members in groups.values():
        try:
            out = _compute_group(ctx, compute, params, members, columns)
        except click.ClickException:
            # find the bad rows one by one; the good ones still count
            for member in members:
                try:
                    out = _compute_group(ctx, compute, params, [member], columns)
                except click.ClickException as row_error:
                    bad.append((member[0], row_error.format_message()))
                    continue
                results.append((member[0], out.rows[0]))
                last = out
            continue
        results.extend(zip((number for number, _ in members), out.rows))
        last = out
    bad.sort()
    if bad and on_error == "stop":
        raise BatchRowError(f"--batch row {bad[0][0]}: {bad[0][1]}")
    for number, message in bad:
        click.echo(f"Error: --batch row {number}: {message} (skipped)", err=True)
    if last is None:
        return None
    results.sort(key=lambda item: item[0])
    return last._replace(rows=[row for _, row in results])


def _hashable(value: Any) -> Any:
    return tuple(value) if isinstance(value, list) else value


def _compute_group(ctx: click.Context, compute: Callable[..., Output], params: dict[str, Any],
                   members: list[tuple[int, dict[str, Any]]], columns: _Columns) -> Output:
    merged = dict(params)
    first = members[0][1]
    for name, param in columns.params.items():
        if isinstance(param.type, _ListType):
            present = [values.get(name) for _, values in members]
            if any(v is not None for v in present):
                default = _single(params.get(name), name)
                if default is None and any(v is None for v in present):
                    missing = next(n for n, v in zip((n for n, _ in members), present) if v is None)
                    raise BatchRowError(f"--batch row {missing}: no value for {param.opts[-1]}")
                merged[name] = [[v if v is not None else default for v in present]]
        elif name in first:
            merged[name] = first[name]
    ctx.meta[ZIP] = True
    try:
        return compute(ctx, **merged)
    finally:
        ctx.meta[ZIP] = False


def _single(value: Any, name: str) -> Any:
    flat = [v for group in value or () for v in (group if isinstance(group, list) else [group])]
    if len(flat) > 1:
        raise click.UsageError(f"with --batch, --{name.replace('_', '-')} takes one value on the command line")
    return flat[0] if flat else None


class _Writer:
    """Streams chunks of rows as one JSON array, one CSV table, field lines, or a table per chunk."""

    def __init__(self, fmt: str, units: str, fields: tuple[str, ...]) -> None:
        self.fmt, self.units, self.fields = fmt, units, fields
        self.started = False
        self.stream = sys.stdout

    def write(self, out: Output | None) -> None:
        if out is None:
            return
        if self.fields:
            check_fields(self.fields, out.keys)
            self.stream.write("".join(field_line(row, self.fields) + "\n" for row in out.rows))
        elif self.fmt == "json":
            for row in out.rows:
                self.stream.write("[\n" if not self.started else ",\n")
                self.stream.write(json.dumps({k: plain(row.get(k)) for k in out.keys}, allow_nan=False,
                                             ensure_ascii=False))
                self.started = True
        elif self.fmt == "csv":
            writer = csv.writer(self.stream, lineterminator="\n")
            if not self.started:
                writer.writerow(out.keys)
                self.started = True
            for row in out.rows:
                writer.writerow(["" if plain(row.get(k)) is None else plain(row.get(k)) for k in out.keys])
        else:
            from camtool.render.output import write_rows

            write_rows(out.rows, out.columns, "table", self.units, out.footer, keys=out.keys)

    def close(self) -> None:
        if self.fmt == "json" and not self.fields:
            self.stream.write("\n]\n" if self.started else "[]\n")
