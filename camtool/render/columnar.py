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

from camtool.render.serial import printable

_ENCODER = json.JSONEncoder(allow_nan=False, ensure_ascii=False)


def values_of(values: Any, count: int) -> list[Any]:
    """The per-row Python values of a result column (a float repeated, or an array's items)."""
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
                from camtool.render.serial import ERROR

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
    elif isinstance(values, list):
        out = [missing if v is None else _string(v, style) if isinstance(v, str) else _other(v, style)
               for v in values]
    else:
        import numpy as np

        array = np.asarray(values).reshape(-1)
        if array.dtype.kind not in "fiub":
            items = array.tolist()
            shown = {item: _string(str(item), style) for item in set(items)}
            out = list(map(shown.__getitem__, items))
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
