"""Combinations of option values: one row per combination, computed in one vectorised call.

``-f 24,35 -N 2.8,4`` asks for four scenes. :func:`combine` turns the lists
into equally long columns (the first list varies slowest, like nested
loops), as plain floats when there is a single scene -- so a single command
never imports numpy -- and as numpy arrays otherwise.
"""

from __future__ import annotations

import itertools
from collections.abc import Sequence
from typing import Any

from camtool.render.columnar import values_of


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


def column(values: Any, count: int) -> list[Any]:
    """The per-row Python values of a result column (a float repeated, or an array's items)."""
    return values_of(values, count)
