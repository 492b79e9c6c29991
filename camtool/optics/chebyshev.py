"""Chebyshev interpolation at the Chebyshev–Lobatto nodes, shared by the ray trace's and the wavefront's interpolants.

A smooth function sampled at x_j = −cos(πj/n), j = 0…n, is interpolated by the Chebyshev series whose
coefficients are discrete cosine sums of the samples (Trefethen, *Approximation Theory and Approximation
Practice*, ch. 3); :func:`lobatto_matrix` is the matrix of those sums.
"""

from __future__ import annotations

import functools

import numpy as np

__all__ = ["lobatto_matrix"]


@functools.lru_cache(maxsize=4)
def lobatto_matrix(degree: int) -> np.ndarray:
    """The matrix taking values at x_j = −cos(πj/n) (j = 0…n) to Chebyshev coefficients (discrete cosine sums).

    >>> x = -np.cos(np.pi * np.arange(5) / 4)
    >>> [abs(round(c, 12)) for c in (lobatto_matrix(4) @ (2 * x**2 - 1)).tolist()]  # T₂ itself
    [0.0, 0.0, 1.0, 0.0, 0.0]
    """
    j = np.arange(degree + 1)
    matrix = 2.0 / degree * np.cos(np.pi * np.outer(j, j) / degree) * (-1.0) ** j[:, None]
    matrix[:, 0] *= 0.5
    matrix[:, -1] *= 0.5
    matrix[0] *= 0.5
    matrix[-1] *= 0.5
    return matrix
