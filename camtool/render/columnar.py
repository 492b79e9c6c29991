"""Rows kept as columns: what the vectorised core computed, written without a dict per row.

:class:`ColumnRows` is a sequence of row dicts to whoever reads it row by
row (a table, a command adding a picture column); the writer instead turns
each column into text in one pass (:func:`texts`) and joins the lines,
which is what makes a long ``--batch`` fast. Once anyone has asked for the
dicts, those (and any change made to them) are what gets written.
"""

from __future__ import annotations

import json
from collections.abc import Iterator, Sequence
from typing import Any

from camtool.render.serial import ERROR, printable

_ENCODER = json.JSONEncoder(allow_nan=False, ensure_ascii=False)


class Masked:
    """A float column with a hole where a row has no value (null in JSON, an empty CSV cell).

    >>> import numpy as np
    >>> values_of(Masked(np.array([2.0, 0.5]), np.array([True, False])), 2)
    [2.0, None]
    """

    def __init__(self, values: Any, present: Any) -> None:
        self.values, self.present = values, present

    def __len__(self) -> int:
        return len(self.values)

    def __getitem__(self, index: slice) -> Masked:
        return Masked(self.values[index], self.present[index])

    def items(self) -> list[float | None]:
        """The per-row values, None where there is none."""
        return [v if ok else None for v, ok in zip(self.values.tolist(), self.present.tolist())]


def values_of(values: Any, count: int) -> list[Any]:
    """The per-row Python values of a result column (a float repeated, or an array's items)."""
    if isinstance(values, Masked):
        return values.items()
    if isinstance(values, (int, float)):
        return [float(values)] * count
    if isinstance(values, str) or values is None:
        return [values] * count
    if isinstance(values, list):
        return values
    flat = values.reshape(-1) if hasattr(values, "reshape") else values
    if getattr(values, "dtype", None) is not None and values.dtype.kind not in "fiub":
        return [str(v) for v in flat]  # names, e.g. the model each row ran
    if len(flat) == 1 and count > 1:
        return [float(flat[0])] * count
    return [float(v) for v in flat]


def placed(count: int, parts: Sequence[tuple[Any, Any]]) -> Any:
    """One column of ``count`` rows from the columns of groups of them: each part's values put in its rows' places
    (a part's rows a sequence of indices or an index array).

    Rows no part covers (skipped rows) get a value that is never written
    (0, or an empty name): no NaN to withhold.

    >>> import numpy as np
    >>> placed(3, [([0, 2], np.array([1.5, 2.5])), ([1], 4.0)]).tolist()
    [1.5, 4.0, 2.5]
    >>> placed(3, [([0, 2], "thin"), ([1], np.array(["approx"]))]).tolist()
    ['thin', 'approx', 'thin']
    """
    import numpy as np

    values = [value for _, value in parts]
    if (len(parts) == 1 and len(parts[0][0]) == count) or (
            all(isinstance(v, str) or v is None for v in values) and len(set(values)) == 1):
        return values[0]
    kinds = {"f" if isinstance(v, (int, float)) and not isinstance(v, bool) else "U" if isinstance(v, str)
             else "M" if isinstance(v, Masked) else getattr(getattr(v, "dtype", None), "kind", "O") for v in values}
    if kinds <= set("fiubM"):  # numbers, some with holes
        column = np.zeros(count)
        present = np.zeros(count, dtype=bool)
        for members, value in parts:
            if isinstance(value, Masked):
                column[members], present[members] = value.values, value.present
            else:
                column[members] = value if isinstance(value, (int, float)) else np.asarray(value, float).reshape(-1)
                present[members] = True
        return Masked(column, present) if "M" in kinds else column
    if kinds == {"U"}:  # names: a string array, written a distinct name at a time
        width = max(len(v) if isinstance(v, str) else v.dtype.itemsize // 4 for v in values)
        column = np.full(count, "", dtype=f"<U{max(width, 1)}")
        for members, value in parts:
            column[members] = value if isinstance(value, str) else np.asarray(value).reshape(-1)
        return column
    column = np.empty(count, dtype=object)
    for members, value in parts:
        column[members] = values_of(value, len(members)) if value is not None else None
    return column


class ColumnRows(Sequence[dict[str, Any]]):
    """``count`` rows held as named columns (a float, a string, an array or a list per key).

    ``errors``, if given, holds a message for each row that could not be
    computed (its values are then ignored, but for the ``kept`` keys, such as
    columns passed through from the input) and None for the others.

    >>> import numpy as np
    >>> rows = ColumnRows(2, {"f": 50.0, "N": np.array([2.8, 8.0])})
    >>> rows[1]
    {'f': 50.0, 'N': 8.0}
    """

    def __init__(self, count: int, columns: dict[str, Any], errors: list[str | None] | None = None,
                 kept: frozenset[str] = frozenset()) -> None:
        self.size, self.columns, self.errors, self.kept = count, columns, errors, kept
        self._rows: list[dict[str, Any]] | None = None

    @property
    def materialised(self) -> bool:
        """Whether the row dicts exist (and may have been changed): then they are the truth."""
        return self._rows is not None

    def rows(self) -> list[dict[str, Any]]:
        """The rows as dicts, made once."""
        if self._rows is None:
            expanded = {key: values_of(value, self.size) for key, value in self.columns.items()}
            rows = [{key: values[i] for key, values in expanded.items()} for i in range(self.size)]
            if self.errors is not None:
                for i, message in enumerate(self.errors):
                    if message is not None:
                        rows[i] = {**{key: rows[i][key] for key in self.kept}, ERROR: message}
            self._rows = rows
        return self._rows

    def slice(self, start: int, stop: int) -> ColumnRows:
        """Rows ``start`` to ``stop`` (unmade dicts stay unmade).

        >>> import numpy as np
        >>> ColumnRows(3, {"f": 50.0, "N": np.array([2.8, 4.0, 8.0])}).slice(1, 3)[0]
        {'f': 50.0, 'N': 4.0}
        """
        stop = min(stop, self.size)
        count = max(0, stop - start)

        def cut(values: Any) -> Any:
            if isinstance(values, (str, int, float)) or values is None:
                return values
            if hasattr(values, "reshape"):
                flat = values.reshape(-1)
                return flat if len(flat) == 1 else flat[start:stop]
            return values[start:stop]

        errors = self.errors[start:stop] if self.errors is not None else None
        return ColumnRows(count, {key: cut(value) for key, value in self.columns.items()}, errors, self.kept)

    def __len__(self) -> int:
        return self.size

    def __getitem__(self, index: Any) -> Any:
        return self.rows()[index]

    def __iter__(self) -> Iterator[dict[str, Any]]:
        return iter(self.rows())


INFINITY = {"csv": "", "json": "null"}
MISSING = {"csv": "", "json": "null", "field": ""}


def texts(values: Any, count: int, style: str, skipped: Sequence[int] = ()) -> list[str]:
    """One column as the text of each row's cell, for ``style`` csv, json or field.

    Floats print as Python prints them (the shortest repr, as the row writer
    does); infinity as null/empty/``inf``; a NaN is an error, never output.
    Rows listed in ``skipped`` get an empty (null) cell.

    >>> import numpy as np
    >>> texts(np.array([1.5, np.inf]), 2, "json")
    ['1.5', 'null']
    >>> texts("thin", 2, "csv", skipped=[0])
    ['', 'thin']
    """
    missing = MISSING[style]
    if values is None:
        return [missing] * count
    if isinstance(values, str):
        cell = _string(values, style)
        out = [cell] * count
    elif isinstance(values, (int, float)):
        out = [_float(float(values), style)] * count
    elif isinstance(values, Masked):
        out = texts(values.values, count, style, skipped)
        for index in (~values.present).nonzero()[0].tolist():
            out[index] = missing
    elif isinstance(values, list):
        distinct = _distinct(values)
        if distinct is not None and all(type(v) is str or v is None for v in distinct):
            # names (and the holes of rows with no answer): each written once, then looked up
            shown = {v: missing if v is None else _string(v, style) for v in distinct}
            out = list(map(shown.__getitem__, values))
        else:
            out = [missing if v is None else _string(v, style) if isinstance(v, str) else _other(v, style)
                   for v in values]
    else:
        import numpy as np

        array = np.asarray(values).reshape(-1)
        if array.dtype.kind not in "fiub":  # names, or a batch chunk's groups put together (floats, None, names)
            items = array.tolist()
            return texts(items if array.dtype.kind in "OU" else [str(item) for item in items], count, style, skipped)
        else:
            array = array.astype(float, copy=False)
            if len(array) == 1 and count > 1:
                return texts(float(array[0]), count, style, skipped)
            items = array.tolist()
            out = list(map(float.__repr__, items))
            bad = np.flatnonzero(~np.isfinite(array)).tolist()
            if bad:
                skip = set(skipped)
                for index in bad:  # Python floats: an infinity costs a list lookup, not a numpy scalar
                    if index not in skip:
                        out[index] = _float(items[index], style)
    if skipped:
        out = list(out)
        for index in skipped:
            out[index] = missing
    return out


def _distinct(values: list[Any]) -> set[Any] | None:
    """The distinct values of a column, or None when one cannot be hashed."""
    try:
        return set(values)
    except TypeError:
        return None


def _float(value: float, style: str) -> str:
    if value - value == 0.0:
        return float.__repr__(value)
    if value != value:
        raise ValueError("internal error: a NaN reached the output")
    return float.__repr__(value) if style == "field" else INFINITY[style]


def _string(value: str, style: str) -> str:
    value = printable(value)
    if style == "json":
        return _ENCODER.encode(value)
    if style == "csv" and any(char in value for char in ',"\r\n'):
        return '"' + value.replace('"', '""') + '"'
    return value


def _other(value: Any, style: str) -> str:
    if isinstance(value, float):
        return _float(value, style)
    if style == "json":
        return _ENCODER.encode(value)
    return _string(str(value), style)


SLICE = 10_000
"""Rows turned to text at a time by pyarrow (the text of one slice in memory)."""


def arrow() -> Any:
    """pyarrow's compute module when the ``batch`` extra is installed, else None (the text is then made in Python)."""
    try:
        import pyarrow
        import pyarrow.compute
    except ImportError:  # pragma: no cover - the test environment has the extra
        return None
    # malloc's pool: memory freed by a slice is reused by the next (pyarrow's own pool keeps more of it)
    pyarrow.set_memory_pool(pyarrow.system_memory_pool())
    return pyarrow.compute


def arrow_lines(rows: ColumnRows, keys: Sequence[str], style: str, errors: Sequence[str | None]) -> Any:
    """The rows as CSV lines (each ending in a newline) or JSON objects (each after ``,\\n``), made by pyarrow.

    Byte for byte what the row writer makes of the same rows: each float as
    :func:`repr` prints it (pyarrow's shortest round-trip digits, which are
    Python's, in the range where both print plain decimals; Python's own
    ``repr`` outside it), strings escaped as :func:`texts` does. ``errors``:
    a message for each row that is skipped (its computed cells empty, in JSON
    null with an ``error`` key), None for the others.
    """
    import numpy as np
    import pyarrow as pa
    import pyarrow.compute as pc

    count = rows.size
    skipped = np.array([e is not None for e in errors], dtype=bool) if any(errors) else None
    missing = pa.scalar(MISSING[style])
    cells: list[Any] = []
    for key in keys:
        values = rows.columns.get(key)
        skip = None if key in rows.kept else skipped
        cells.append(_arrow_texts(values, count, style, skip, missing))
    parts: list[Any] = []
    if style == "csv":
        parts = [part for cell in cells for part in (cell, ",")]
        parts[-1:] = ["\n"]
        line = pc.binary_join_element_wise(*parts, "") if cells else pa.scalar("\n")
    else:
        for index, key in enumerate(keys):
            parts += [("{" if index == 0 else ", ") + _ENCODER.encode(key) + ": ", cells[index]]
        if not keys:
            parts.append("{")
        if skipped is not None:
            tail = ["}"] * count
            for index in np.flatnonzero(skipped).tolist():
                tail[index] = (", " if keys else "") + f"{_ENCODER.encode(ERROR)}: {_ENCODER.encode(errors[index])}}}"
            parts.append(pa.array(tail, pa.string()))
        else:
            parts.append("}")
        line = pc.binary_join_element_wise(",\n", *parts, "")
    if isinstance(line, pa.Scalar):  # every cell the same: no array to join
        return (str(line.as_py()) * count).encode()
    return _joined(line)


def _joined(array: Any) -> memoryview:
    """The concatenated UTF-8 text of a string array (no nulls): its data buffer between the first and last offsets."""
    import numpy as np

    if not len(array):
        return memoryview(b"")
    offsets = np.frombuffer(array.buffers()[1], dtype=np.int32)[array.offset:array.offset + len(array) + 1]
    return memoryview(array.buffers()[2])[int(offsets[0]):int(offsets[-1])]


def _arrow_texts(values: Any, count: int, style: str, skipped: Any, missing: Any) -> Any:
    """One column as pyarrow strings (or one string scalar for every row), as :func:`texts` writes it."""
    import numpy as np
    import pyarrow as pa
    import pyarrow.compute as pc

    if values is None:
        return missing
    if isinstance(values, Masked):
        out = _arrow_texts(values.values, count, style, skipped, missing)
        return pc.if_else(pa.array(values.present), out, missing)
    if isinstance(values, (str, int, float)):
        cell = _string(values, style) if isinstance(values, str) else _float(float(values), style)
        return cell if skipped is None else pc.if_else(pa.array(skipped), missing, cell)
    if not isinstance(values, np.ndarray) or values.dtype.kind not in "fiubUS":
        skip = np.flatnonzero(skipped).tolist() if skipped is not None else ()
        return pa.array(texts(values, count, style, skip), pa.string())
    array = values.reshape(-1)
    if len(array) == 1 and count > 1:
        return _arrow_texts(array[0].item(), count, style, skipped, missing)
    if array.dtype.kind in "US":  # names, e.g. the model each row ran: each distinct one escaped once
        encoded = pc.dictionary_encode(pa.array(array.astype(str)))
        shown = pa.array([_string(str(name), style) for name in encoded.dictionary.to_pylist()], pa.string())
        out = pc.take(shown, encoded.indices)
    else:
        array = np.ascontiguousarray(array, dtype=float)
        out = pc.cast(pa.array(array), pa.string())
        size = np.abs(array)
        with np.errstate(invalid="ignore"):  # pyarrow writes 1e+10 where Python writes 10000000000.0
            plain = ((size >= 1e-4) & (size < 1e10)) | (array == 0.0)
            whole = plain & (array == np.trunc(array))  # 35.0: pyarrow writes 35
        if whole.all():
            out = pc.binary_join_element_wise(out, ".0", "")
        elif whole.any():
            out = pc.if_else(pa.array(whole), pc.binary_join_element_wise(out, ".0", ""), out)
        infinite = size == np.inf
        if infinite.any():
            out = pc.if_else(pa.array(infinite), INFINITY[style], out)
        other = ~(plain | infinite)
        if skipped is not None:
            other &= ~skipped
        if other.any():
            shown = [_float(value, style) for value in array[other].tolist()]
            out = pc.replace_with_mask(out, pa.array(other), pa.array(shown, pa.string()))
    return out if skipped is None else pc.if_else(pa.array(skipped), missing, out)


def write_block(writer: Any, rows: ColumnRows, columns: Sequence[Any], keys: Sequence[str],
                footers: Sequence[str]) -> None:
    """Hand a block of rows held as columns to ``writer`` (a :class:`camtool.render.output.RowWriter`).

    CSV and JSON text is made by :func:`arrow_lines` when pyarrow is
    installed (the same bytes as the writer's own, several times faster); a
    table, ``--field`` lines, rows already made into dicts and a block with a
    NaN to withhold go through the writer itself.
    """
    fast = not (writer.fields or writer.fmt not in ("csv", "json") or rows.materialised or arrow() is None
                or _has_nan(rows, writer.keys or keys))
    for index, footer in enumerate(footers or [""]):  # the first fixes the keys (and writes a CSV header)
        writer.write([] if fast or index else rows, columns, keys, footer)
    if not fast:
        return
    for start in range(0, rows.size, SLICE):  # a slice at a time: the text of one slice in memory
        part = rows.slice(start, start + SLICE) if rows.size > SLICE else rows
        text = arrow_lines(part, writer.keys, writer.fmt, list(part.errors or [None] * part.size))
        if writer.fmt == "json":
            writer.stream.write("[\n" if not writer.started else ",\n")
            text = text[2:]
            writer.started = True
        binary = getattr(writer.stream, "buffer", None)
        if binary is not None:  # the bytes as pyarrow made them, not copied into a str
            writer.stream.flush()
            binary.write(text)
        else:
            writer.stream.write(bytes(text).decode("utf-8"))


def _has_nan(rows: ColumnRows, keys: Sequence[str]) -> bool:
    """Whether a computed float column holds a NaN (the writer then withholds those rows, naming the keys)."""
    import numpy as np

    for key in keys:
        values: Any = rows.columns.get(key)
        if key in rows.kept:
            continue
        if isinstance(values, Masked):
            values = values.values[values.present]
        if isinstance(values, float):
            if values != values:
                return True
        elif getattr(values, "dtype", None) is not None and values.dtype.kind == "f" and np.isnan(values).any():
            return True
    return False
