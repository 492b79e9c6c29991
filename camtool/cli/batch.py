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

Rows are read in chunks of at most :data:`CHUNK` rows (plain CSV split
into columns a block at a time: :func:`camtool.core.records.chunks`) and
parsed a column at a time: plain numbers (and cells that all share one unit,
``3.2m``) at once, other cells one by one; a validity mask finds the bad
cells, which alone are parsed again for their messages. Within a chunk, rows sharing the same
non-numeric settings (sensor, model, ...) are computed in one vectorised
call (a failing call is bisected to find its bad rows), and the output
keeps the input order, written column by column (by pyarrow when the batch
extra is installed: :func:`camtool.render.columnar.write_block`). Output goes
through the one :class:`~camtool.render.output.RowWriter`: memory stays bounded for JSON, CSV
and ``--field`` output; a table is drawn once at the end from every row.

A bad row stops the run (exit 2) after the rows before it are written (JSON
still a complete array); with ``--on-error skip`` it keeps its place in the
output, is reported on standard error in row order, and the run exits 1.
"""

from __future__ import annotations

import math
from collections.abc import Callable, Sequence
from typing import Any

import click

from camtool.cli.params import FNumberType, LengthType, NumberType, _ListType, flatten
from camtool.cli.rows import CELLS, ZIP, Output, open_writer
from camtool.core.files import FileProblem
from camtool.core.ranges import F_NUMBER
from camtool.core.records import CAMERA_DATA_COLUMNS, Chunk, camera_cells, chunks, floats, group_rows, open_source, unit_column
from camtool.core.units import plain_number
from camtool.plans.grid import CHUNK as GRID_CHUNK
from camtool.render.columnar import ColumnRows, placed, write_block
from camtool.render.columns import TEXT, Column
from camtool.render.output import RowWriter

SKIPS_SHOWN = 5
"""Skipped rows named on stderr one by one; the rest are counted in the run's last line."""
CHUNK = GRID_CHUNK  # one chunk size for batch files and option grids
CONTROL = {"fmt", "units", "preset_files", "fields", "batch", "on_error"}
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
        for key, target in {**_KEY_ALIASES, **EXIFTOOL_COLUMNS, **CAMERA_DATA_COLUMNS}.items():
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
        import difflib

        near = difflib.get_close_matches(key, list(self.aliases), n=1, cutoff=0.85)
        if near and key:
            option = self.params[self.aliases[near[0]][0]].opts[-1]
            raise BatchRowError(f"--batch: column {column!r} names no option; did you mean {option}? (a column "
                                "that names no option is passed through to the output: rename it to keep it)")
        return PASS


# Output keys that feed back in as inputs (camtool's CSV is a valid batch file).
_KEY_ALIASES = {"focal_length_mm": ("focal_length", "mm"), "distance_mm": ("distance", "mm"),
                "near_mm": ("near", "mm"), "far_mm": ("far", "mm"), "coc_mm": ("coc", "mm")}
# exiftool's own column names (`exiftool -n -csv`: distances in metres, the CoC in mm); FocalLength and FNumber
# already name options, SourceFile and the others pass through (docs/exif.md, "exiftool's CSV as a batch file").
EXIFTOOL_COLUMNS = {"FocusDistance": ("distance", None), "SubjectDistance": ("distance", None),
                    "ObjectDistance": ("distance", None), "ApproximateFocusDistance": ("distance", None),
                    "ScaleFactor35efl": ("crop", None), "Aperture": ("f_number", None),
                    "CircleOfConfusion": ("coc", "mm")}


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


def run_batch(ctx: click.Context, compute: Callable[..., Output], params: dict[str, Any], source: str,
              on_error: str, fields: tuple[str, ...]) -> None:
    """Compute and write one output row per input row, chunk by chunk; exit 1 if a row was skipped."""
    columns = _Columns(ctx.command)
    defaults = {name: _single(params.get(name), name) for name, param in columns.params.items() if _vector(param)}
    writer = open_writer(params["fmt"], params["units"], fields)
    batch = _Batch(ctx, compute, params, defaults, columns, writer, on_error)
    batch.fields = fields
    try:
        stream, name = open_source(source)
    except FileProblem as unreadable:
        raise BatchFileError(f"--batch {unreadable}") from None
    from contextlib import ExitStack

    from camtool.render.progress import progress

    try:
        with stream, ExitStack() as shown:
            bar = None
            for chunk in chunks(stream, name, CHUNK, stop=on_error == "stop"):
                if bar is None and batch.total:  # a second chunk: long work, shown on a terminal
                    bar = shown.enter_context(progress(f"camtool {ctx.info_name} --batch: rows"))
                    bar.advance(batch.total)
                batch.run(chunk)
                if bar is not None:
                    bar.advance(len(chunk.numbers))
    except FileProblem as unreadable:
        batch.end(failed=True)
        raise BatchFileError(f"--batch {unreadable}") from None
    except click.ClickException:
        batch.end(failed=True)
        raise
    batch.end()
    if batch.skipped:
        more = f" (the first {SKIPS_SHOWN} above; --format json gives each row's error in its place)" \
            if batch.skipped > SKIPS_SHOWN else ""
        click.echo(f"camtool: {batch.skipped:,} of {batch.total:,} rows skipped{more}", err=True)
        ctx.exit(1)


class _Batch:
    """Parses chunks of rows column by column, computes them in groups, and writes them in input order."""

    def __init__(self, ctx: click.Context, compute: Callable[..., Output], params: dict[str, Any],
                 defaults: dict[str, Any], columns: _Columns, writer: RowWriter, on_error: str) -> None:
        self.ctx, self.compute, self.params, self.defaults = ctx, compute, params, defaults
        self.columns, self.writer, self.on_error = columns, writer, on_error
        self.fields: tuple[str, ...] = ()
        self.skipped = self.total = 0
        self.shape: tuple[list[Column], list[str]] | None = None
        self.fallback: list[str] = []
        self.factors: dict[tuple[str, str | None], float] = {}

    # -- parsing: a column at a time ------------------------------------------------------------

    def _parse(self, chunk: Chunk, errors: list[str | None]) -> tuple[dict[str, Any], dict[str, list[Any]]]:
        """Parameter values by name (float arrays, NaN where a cell is empty; lists for the others) and
        the passed-through cells by column; a bad cell's message goes to ``errors`` (the first per row)."""
        header, numbers, records = chunk.header, chunk.numbers, chunk.rows or []
        if chunk.columns is not None:
            data: dict[str, Sequence[Any]] = dict(zip(header or [], chunk.columns))
        elif header is not None:
            width = len(header)
            rows = [cells if cells is not None and len(cells) == width
                    else [*(cells or []), *[""] * (width - len(cells or []))] for cells in records]
            data = dict(zip(header, zip(*rows))) if width else {}
        else:
            keys = dict.fromkeys(key for record in records if record for key in record)
            data = {key: [record.get(key) if record else None for record in records] for key in keys}
        values: dict[str, Any] = {}
        passed: dict[str, list[Any]] = {}
        for column, cells in data.items():
            target = self.columns.resolve(column)
            if target is None:
                continue
            if target == PASS:
                # JSON's NaN and Infinity have no place in JSON output: null
                passed[column] = list(cells) if header is not None else [
                    None if isinstance(cell, float) and not math.isfinite(cell) else cell for cell in cells]
                continue
            name, unit = target
            param = self.columns.params[name]
            cells, unit = camera_cells(cells, unit)  # a camera's t_stop column: a bare 2.8 is T2.8
            if _vector(param) and not _t_stops(self.ctx, param, cells):
                parsed: Any = self._numbers(param, unit, column, cells, numbers, errors)
            else:
                parsed = self._settings(param, unit, column, cells, numbers, errors)
            if name in values:  # two columns for one option (JSON lines: distance_mm in one row, distance in another)
                parsed = self._merge(param, values[name], parsed, numbers, errors)
            values[name] = parsed
        return values, passed

    def _merge(self, param: click.Parameter, first: Any, second: Any, numbers: Sequence[int],
               errors: list[str | None]) -> Any:
        """One option given by two columns: each row takes the one it fills; a row that fills both is bad."""
        import numpy as np

        if isinstance(first, list) or isinstance(second, list):
            firsts = first if isinstance(first, list) else [None if v != v else v for v in first.tolist()]
            seconds = second if isinstance(second, list) else [None if v != v else v for v in second.tolist()]
            both = [a is not None and b is not None for a, b in zip(firsts, seconds)]
            merged: Any = [b if a is None else a for a, b in zip(firsts, seconds)]
        else:
            both = (~np.isnan(first) & ~np.isnan(second)).tolist()
            merged = np.where(np.isnan(first), second, first)
        for index, twice in enumerate(both):
            if twice and errors[index] is None:
                errors[index] = f"--batch row {numbers[index]}: two columns give {param.opts[-1]}; keep one"
        return merged

    def _numbers(self, param: click.Parameter, unit: str | None, column: str, cells: Sequence[Any],
                 numbers: Sequence[int], errors: list[str | None]) -> Any:
        """One list-option column as floats: plain numbers parsed at once, cells with units one by one."""
        import numpy as np

        key = (str(param.name), unit)
        if key not in self.factors:
            self.factors[key] = float(param.type.parse("1" + (unit or "")))  # type: ignore[attr-defined]
        factor = self.factors[key]
        array, suffix = None, ""
        first = cells[0] if cells else None  # 3.2m: a unit column (no float ends in a unit)
        if isinstance(first, str) and first.rstrip()[-1:].isalpha() and "inf" not in first.lower():
            array, suffix = unit_column(cells) or (None, "")
        try:
            if array is None:
                array = floats(cells)
                if np.isnan(array).any():
                    array = None  # "nan" typed in a cell: an error, found below
        except (ValueError, TypeError):
            array, suffix = unit_column(cells) or (None, "")
        if suffix:
            try:
                factor = float(param.type.parse("1" + suffix))  # type: ignore[attr-defined]
            except (ValueError, TypeError):  # not a unit of this option (a UnitError): each cell says why
                array = None
        overflow = None
        if array is not None:
            if factor != 1.0:
                with np.errstate(over="ignore"):
                    scaled = array * factor
                overflow = np.isinf(scaled) & np.isfinite(array)  # 1e308 m: no finite length, as on the command line
                array = scaled
        else:
            array = np.empty(len(cells))
            for index, cell in enumerate(cells):
                text = "" if cell is None else cell if isinstance(cell, str) else str(cell)
                if not text.strip():
                    array[index] = np.nan
                    continue
                try:
                    number = plain_number(text)  # not 1_000, as no option takes it
                except ValueError:
                    number = math.nan
                array[index] = number * factor if number == number else self._one(
                    param, text, unit, column, numbers[index], errors, index)
        invalid = ~_valid(param.type, array) & ~np.isnan(array)
        bad = np.flatnonzero(invalid if overflow is None else invalid | overflow)
        for index in bad.tolist():
            cell = cells[index]
            array[index] = self._one(param, cell if isinstance(cell, str) else str(cell), unit, column,
                                     numbers[index], errors, index)
        return array

    def _one(self, param: click.Parameter, text: str, unit: str | None, column: str, number: int,
             errors: list[str | None], index: int) -> float:
        """One cell parsed as on the command line; NaN, and its message in ``errors``, if it is bad."""
        try:
            return float(_convert(self.ctx, param, text, unit, number, column))
        except BatchRowError as error:
            if errors[index] is None:
                errors[index] = error.format_message()
            return math.nan

    def _settings(self, param: click.Parameter, unit: str | None, column: str, cells: Sequence[Any],
                  numbers: Sequence[int], errors: list[str | None]) -> list[Any]:
        """A column of other options (sensor, model, ...): each distinct cell converted once."""
        known: dict[str, Any] = {}
        out: list[Any] = [None] * len(cells)
        for index, cell in enumerate(cells):
            text = "" if cell is None else cell if isinstance(cell, str) else str(cell)
            if not text.strip():
                continue
            if text not in known:
                try:
                    known[text] = _convert(self.ctx, param, text, unit, numbers[index], column)
                except BatchRowError:
                    known[text] = _BAD
            if known[text] is _BAD:
                try:
                    _convert(self.ctx, param, text, unit, numbers[index], column)
                except BatchRowError as error:
                    if errors[index] is None:
                        errors[index] = error.format_message()
                continue
            out[index] = known[text]
        return out

    # -- computing: one call per group of rows sharing their settings ------------------------------

    def run(self, chunk: Chunk) -> None:
        """Compute one chunk and write its rows; in stop mode, the rows before the first bad one, then raise."""
        numbers = chunk.numbers
        if not numbers:
            return
        import numpy as np

        errors: list[str | None] = [None if problem is None else f"--batch row {number}: {problem}"
                                    for number, problem in zip(numbers, chunk.problems)] if chunk.problems \
            else [None] * len(numbers)
        values, passed = self._parse(chunk, errors)
        if self.fields and not self.total:  # a --field no row can have: refused before any row's message
            from camtool.cli.rows import DYNAMIC_KEYS, check_fields

            declared = list(getattr(self.ctx.command, "output_key_list", []))
            if declared:
                check_fields([f for f in self.fields if f not in DYNAMIC_KEYS and f not in self.columns.passed],
                             declared)
        for name, column in values.items():
            param = self.columns.params[name]
            if _vector(param) and self.defaults[name] is None and not isinstance(column, list):
                missing = np.isnan(column)
                if missing.all():
                    continue  # not this chunk's column at all: the command says what it needs
                for index in np.flatnonzero(missing).tolist():
                    if errors[index] is None:
                        errors[index] = f"--batch row {numbers[index]}: no value for {param.opts[-1]}"
        groups = group_rows([column for column in values.values() if isinstance(column, list)], errors)
        results: list[tuple[list[int], Output]] = []
        for members in groups.values():
            self._solve(members, values, numbers, errors, results)
        self.total += len(numbers)
        bad = [index for index, error in enumerate(errors) if error is not None] if any(errors) else []
        if bad and self.on_error == "stop":
            self._write_rows(results, passed, errors, bad[0])
            raise BatchRowError(str(errors[bad[0]]))
        for index in bad[:max(0, SKIPS_SHOWN - self.skipped)]:  # the first few; the end of the run counts them all
            click.echo(f"Error: {errors[index]} (skipped)", err=True)
        self.skipped += len(bad)
        if bad:
            self._start_shape(passed)
        if results and all(isinstance(out.rows, ColumnRows) and not out.rows.materialised for _, out in results):
            self._write_columns(results, passed, errors)
        else:
            self._write_rows(results, passed, errors, len(numbers))

    def _solve(self, members: list[int], values: dict[str, Any], numbers: Sequence[int], errors: list[str | None],
               results: list[tuple[list[int], Output]]) -> None:
        """Compute a group in one call; if it fails, find the bad rows: those the error names, or by halving.

        A range check over the group's scenes names the ones that failed
        (``scenes`` of :class:`camtool.core.errors.DomainError`): each is
        computed alone (its own message, as halving would give it) and, when
        every one of them fails alone, the rest goes on in one call. Otherwise,
        or if a row named computes alone (the names did not match the rows),
        the group is halved until the bad rows are found.
        """
        while True:
            try:
                out = self._compute_group(members, values)
                if len(out.rows) != len(members):  # one row a member, or the group is split until it is
                    raise click.ClickException(f"{len(out.rows)} results for {len(members)} rows")
            except click.ClickException as error:
                if len(members) == 1:
                    message = error.format_message()
                    number = numbers[members[0]]
                    errors[members[0]] = (message if isinstance(error, BatchRowError)
                                          else f"--batch row {number}: {message}")
                    return
                named = _named_rows(error, len(members))
                if named:
                    aside = [members[i] for i in named]
                    for member in aside:
                        self._solve([member], values, numbers, errors, results)
                    set_aside = set(named)
                    members = [m for i, m in enumerate(members) if i not in set_aside]
                    if not members:
                        return
                    if all(errors[member] is not None for member in aside):
                        continue  # the rest, in one call
                half = len(members) // 2
                if half:
                    self._solve(members[:half], values, numbers, errors, results)
                self._solve(members[half:], values, numbers, errors, results)
                return
            results.append((members, out))
            return

    def _compute_group(self, members: list[int], values: dict[str, Any]) -> Output:
        import numpy as np

        merged = dict(self.params)
        zipped = False
        chunk = len(next(iter(values.values()), []))
        every: Any = slice(None) if len(members) == chunk else members  # one group of the whole chunk: no gather
        for name, column in values.items():
            param = self.columns.params[name]
            if isinstance(column, list):  # settings, and an -N column holding T-stops (one value a group)
                if column[members[0]] is not None:
                    merged[name] = [[column[members[0]]]] if _vector(param) else column[members[0]]
            elif isinstance(param.type, _ListType):
                chosen = column[every]
                missing = np.isnan(chosen)
                if missing.all():
                    continue
                if missing.any():
                    chosen = np.where(missing, self.defaults[name], chosen)
                merged[name] = [chosen.tolist()]
                zipped = True
        if not zipped and len(members) > 1:  # no row gives a value: one row per member from the options alone
            for name, param in self.columns.params.items():
                given = flatten(merged.get(name)) if isinstance(param.type, _ListType) else []
                if len(given) == 1:
                    merged[name] = [given * len(members)]
                    break
        self.ctx.meta[ZIP] = True
        self.ctx.meta[CELLS] = frozenset(name for name, column in values.items()
                                         if (column[members[0]] is not None if isinstance(column, list)
                                             else not np.isnan(column[every]).all()))
        try:
            return self.compute(self.ctx, **merged)
        finally:
            self.ctx.meta[ZIP] = False
            self.ctx.meta[CELLS] = frozenset()

    # -- writing, in input order ---------------------------------------------------------------------

    def _shape(self, out: Output) -> tuple[list[Column], list[str]]:
        if self.shape is None:
            passed = self.columns.passed
            self.shape = ([*(Column(k, k, TEXT) for k in passed), *out.columns], [*passed, *out.keys])
        return self.shape

    def _write_columns(self, results: list[tuple[list[int], Output]], passed: dict[str, list[Any]],
                       errors: list[str | None]) -> None:
        """The chunk as one block of columns: each group's columns put in its rows' places."""
        import numpy as np

        count = len(errors)
        columns, keys = self._shape(results[0][1])
        # each group's rows as an index array once, not a list numpy converts again for every column
        places = [np.asarray(members, dtype=np.intp) if len(members) != count else members for members, _ in results]
        data = {key: passed[key] if key in passed else placed(
            count, [(where, out.rows.columns.get(key))  # type: ignore[attr-defined]
                    for where, (_, out) in zip(places, results)])
            for key in keys}
        skipped = errors if any(error is not None for error in errors) else None
        rows = ColumnRows(count, data, skipped, kept=frozenset(passed))
        write_block(self.writer, rows, columns, keys, [out.footer for _, out in results])

    def _write_rows(self, results: list[tuple[list[int], Output]], passed: dict[str, list[Any]],
                    errors: list[str | None], end: int) -> None:
        """Rows before index ``end`` one by one (row dicts): skipped rows in place, runs of one output together."""
        found: dict[int, tuple[dict[str, Any], Output]] = {}
        for members, out in results:
            for index, row in zip(members, out.rows):
                if index < end:
                    found[index] = ({**{k: v[index] for k, v in passed.items()}, **row} if passed else row, out)
        run: list[dict[str, Any]] = []
        current: Output | None = None
        for index in range(end):
            if errors[index] is not None:
                self._flush(run, current)
                run = []
                self.writer.skip(str(errors[index]), {k: v[index] for k, v in passed.items()})
                continue
            row, out = found[index]
            if out is not current:
                self._flush(run, current)
                run, current = [], out
            run.append(row)
        self._flush(run, current)

    def _flush(self, rows: list[dict[str, Any]], out: Output | None) -> None:
        if out is None or not rows:
            return
        columns, keys = self._shape(out)
        self.writer.write(rows, columns, keys, out.footer)

    def _start_shape(self, passed: dict[str, list[Any]]) -> None:
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
        if failed:  # the run's one line is its error: no note on columns left out of the partial table
            self.writer.errors = None
        self.writer.close(self.fallback, [Column(k, k, TEXT) for k in self.fallback])


_BAD = object()


def _t_stops(ctx: click.Context, param: click.Parameter, cells: Sequence[Any]) -> bool:
    """Whether an -N column holds T-stops (T2): then each cell is parsed alone, keeping what it is."""
    if not getattr(param.type, "t_stops", False):
        return False
    from camtool.cli.common import T_STOP_COLUMN
    from camtool.core.units import parse_t_stop

    try:  # a CSV column: one look at its text finds that no cell holds a T
        if "t" not in "".join(cells).lower():
            return False
    except TypeError:  # JSON values: numbers among the strings
        pass
    found = any(isinstance(cell, str) and parse_t_stop(cell) is not None for cell in cells)
    if found:
        ctx.meta[T_STOP_COLUMN] = True
    return found


def _named_rows(error: click.ClickException, size: int) -> list[int] | None:
    """The rows of a group of ``size`` that a failed range check names (their places in the group), if it names any."""
    scenes = getattr(error, "scenes", None)
    if scenes is None or scenes[0] != size or not scenes[1]:
        return None
    return list(scenes[1])


def _vector(param: click.Parameter) -> bool:
    """Whether a column of this option goes to the command as one list a chunk (-f, -N, -s ...).

    An option that takes a single value (``--teleconverter``, ``--extension``:
    a callback makes the list one number) is a setting instead: each
    distinct cell is one group, converted and checked as the option is.
    """
    return isinstance(param.type, _ListType) and getattr(param, "callback", None) is None


def _valid(kind: click.ParamType, array: Any) -> Any:
    """Which values pass the option's range check (the check of :mod:`camtool.cli.params`, on arrays)."""
    import numpy as np

    check = type(kind).check  # type: ignore[attr-defined]
    with np.errstate(invalid="ignore"):
        if check is LengthType.check:  # the option's own bounds, as LengthType.check applies them
            low, high = kind.bounds  # type: ignore[attr-defined]
            ok = (array > 0 if low == 0 else array >= low * (1 - 1e-12)) & (array <= high * (1 + 1e-12))
            return ok | (array == np.inf) if kind.allow_inf else ok & np.isfinite(array)  # type: ignore[attr-defined]
        if check is FNumberType.check:
            return (array >= F_NUMBER[0]) & (array <= F_NUMBER[1])
        if check is NumberType.check:
            return (array >= kind.low) & (array <= kind.high)  # type: ignore[attr-defined]
        if check is _ListType.check:
            return (array > 0) & np.isfinite(array)
    return np.array([value != value or kind.check(value) for value in array.tolist()], dtype=bool)  # type: ignore[attr-defined]


def _single(value: Any, name: str) -> Any:
    groups = value if isinstance(value, (list, tuple)) else [] if value is None else [value]
    flat = [v for group in groups for v in (group if isinstance(group, list) else [group])]
    if len(flat) > 1:
        raise click.UsageError(f"with --batch, --{name.replace('_', '-')} takes one value on the command line")
    return flat[0] if flat else None
