"""The close-up exposure factor (bellows factor) from magnification and pupil magnification."""

from __future__ import annotations

from typing import Any

from camtool.core.arrays import ops
from camtool.core.errors import require


def bellows_factor(magnification: Any, pupil_magnification: Any = 1.0) -> Any:
    """Exposure factor for close focus: (1 + m/P)², the square of working/marked f-number.

    Parameters
    ----------
    magnification : float or array, m ≥ 0 (0 at infinity focus, 1 at 1:1)
    pupil_magnification : float or array, P > 0
        Exit over entrance pupil diameter; 1 for a symmetric lens, below 1 for
        telephoto designs, above 1 for retrofocus ones.

    References
    ----------
    Ray, *Applied Photographic Optics* (2002), §12 (bellows factor and pupil
    magnification); Wikipedia, "f-number" (working f-number N(1 + m/P)).

    Examples
    --------
    >>> bellows_factor(1.0)
    4.0
    >>> round(bellows_factor(1.0, 0.5), 2)
    9.0
    """
    require("magnification", magnification, magnification >= 0, ">= 0")
    require("pupil_magnification", pupil_magnification, pupil_magnification > 0, "> 0")
    return (1.0 + magnification / pupil_magnification) ** 2


def bellows_stops(magnification: Any, pupil_magnification: Any = 1.0) -> Any:
    """Extra exposure in stops for close focus: log2 of the bellows factor, 2·log2(1 + m/P).

    >>> bellows_stops(1.0)
    2.0
    """
    factor = bellows_factor(magnification, pupil_magnification)
    return ops(factor).log2(factor)
