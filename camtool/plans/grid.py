"""Combinations of option values: one row per combination, computed vectorised, chunk by chunk.

``-f 24,35 -N 2.8,4`` asks for four scenes. :func:`combine` turns the lists
into equally long columns (the first list varies slowest, like nested
loops), as plain floats when there is a single scene -- so a single command
never imports numpy -- and as numpy arrays otherwise.

A grid of more than :data:`CHUNK` combinations is not built whole: a
:class:`Grid` walks it in slices, and :func:`combine_slice` makes the
columns of one slice from the row numbers alone (index arithmetic, the same
order as :func:`combine`), so memory stays flat however many combinations
the lists ask for (docs/design.md §3.4).

A grid of a few combinations (at most :data:`SCALAR_ROWS`, a :class:`Grid`
made with ``scalar=True``) is computed one combination at a time with plain
floats instead: the command's formulas then run on Python's floats, and a
short list (``-N 2.8,4,5.6``) answers without importing numpy, whose import
costs more than the rows (docs/design.md §7); a grid whose combinations import
numpy anyway (a traced lens) is computed as a whole. JSON, CSV and ``--field`` rows
are written as they come; a table, whose footer and sharp-zone axis are drawn
from every row at once, is drawn from the combinations' plans merged (where
the command can, see :class:`camtool.cli.rows.Output`), else computed
vectorised. The output is the same either way (``tests/test_scalar_grid.py``).
"""

from __future__ import annotations

import itertools
import math
from collections.abc import Sequence
from typing import Any

from camtool.render.columnar import values_of

CHUNK = 20_000
"""Combinations computed and written at a time (the chunk of ``--batch`` too)."""

SCALAR_ROWS = 256
"""The most combinations computed one at a time with plain floats (no numpy)."""


def combine(*lists: Sequence[float]) -> tuple[int, tuple[Any, ...]]:
    """Return the number of combinations and one column (float or array) per list.

    >>> combine([50.0], [8.0])
    (1, (50.0, 8.0))
    >>> n, (f, N) = combine([24.0, 35.0], [2.8, 4.0])
    >>> n, f.tolist(), N.tolist()
    (4, [24.0, 24.0, 35.0, 35.0], [2.8, 4.0, 2.8, 4.0])
    """
    if all(len(values) == 1 for values in lists):
        return 1, tuple(float(values[0]) for values in lists)
    import numpy as np

    rows = list(itertools.product(*lists))
    table = np.array(rows, dtype=float).reshape(len(rows), len(lists))
    return len(rows), tuple(table[:, i].copy() for i in range(len(lists)))


def combine_slice(lists: Sequence[Sequence[float]], start: int, stop: int) -> tuple[int, tuple[Any, ...]]:
    """Combinations ``start`` to ``stop`` (0-based, ``stop`` excluded) of :func:`combine`'s order, as arrays.

    Row ``i`` takes, from each list, the item ``(i // stride) % len(list)``,
    the stride being the product of the lengths of the lists after it: the
    first list varies slowest, exactly as in :func:`itertools.product`.

    >>> n, (f, N) = combine_slice([[24.0, 35.0, 50.0], [2.8, 4.0]], 1, 4)
    >>> n, f.tolist(), N.tolist()
    (3, [24.0, 35.0, 35.0], [4.0, 2.8, 4.0])
    """
    import numpy as np

    index = np.arange(start, stop, dtype=np.int64)
    columns = []
    stride = math.prod(len(values) for values in lists)
    for values in lists:
        stride //= len(values)
        items = np.asarray(values, dtype=float)
        columns.append(items[(index // stride) % len(values)] if len(values) > 1
                       else np.full(len(index), items[0]))
    return len(index), tuple(columns)


def one_combination(lists: Sequence[Sequence[float]], index: int) -> list[list[float]]:
    """Combination ``index`` (0-based) of :func:`combine`'s order, one single-item list per list.

    >>> one_combination([[24.0, 35.0, 50.0], [2.8, 4.0]], 3)
    [[35.0], [4.0]]
    """
    stride = math.prod(len(values) for values in lists)
    chosen = []
    for values in lists:
        stride //= len(values)
        chosen.append([values[(index // stride) % len(values)]])
    return chosen


class Grid:
    """Which slice of the combinations the current call of a command computes.

    A command run with :attr:`whole` set computes every combination at once
    (a table, which needs every row anyway); otherwise it computes
    combinations :attr:`start` to :attr:`stop`, and the caller calls it again
    after :meth:`advance` until :attr:`done`. :attr:`count` is the number of
    combinations, known once the command has combined its lists.
    """

    def __init__(self, whole: bool = False, chunk: int | None = None, scalar: bool = False) -> None:
        self.whole = whole
        self.scalar_allowed = scalar
        self.chunk = max(2, chunk if chunk is not None else CHUNK)
        self.start = 0
        self.count: int | None = None
        self.scalar = False

    @property
    def stop(self) -> int:
        """The end of the current slice; a lone last combination joins the slice before it."""
        assert self.count is not None
        if self.scalar:
            return self.start + 1
        stop = min(self.start + self.chunk, self.count)
        return self.count if self.count - stop == 1 else stop

    @property
    def done(self) -> bool:
        """Whether the current slice is the last (or the command combined no lists)."""
        return self.whole or self.count is None or self.stop >= self.count

    def advance(self) -> None:
        """Move on to the next slice."""
        self.start = self.stop

    def columns(self, lists: Sequence[Sequence[float]]) -> tuple[int, tuple[Any, ...]]:
        """The current slice of the combinations of ``lists`` (all of them when they fit in one)."""
        count = math.prod(len(values) for values in lists)
        if self.count is None:
            self.count = count
            if self.scalar_allowed and 1 < count <= SCALAR_ROWS:  # one combination a call, as plain floats
                self.scalar, self.whole = True, False
        elif count != self.count:
            raise RuntimeError("the list options changed between the chunks of one grid")
        if count == 1:
            return combine(*lists)
        if self.scalar:
            return combine(*one_combination(lists, self.start))
        return combine_slice(lists, 0, count) if self.whole else combine_slice(lists, self.start, self.stop)


def column(values: Any, count: int) -> list[Any]:
    """The per-row Python values of a result column (a float repeated, or an array's items)."""
    return values_of(values, count)
