"""One implementation for scalars and arrays.

A single command on the shell works on a handful of plain floats; importing
numpy would cost more than the whole computation (about 140 ms here). So the
formula modules ask :func:`ops` for a namespace of elementary functions: the
:mod:`math` module (wrapped) when every argument is a plain number, numpy when
any argument is an array or a list. The formulas themselves are written once,
with ordinary operators plus ``xp.sqrt``, ``xp.where`` and friends.
"""

from __future__ import annotations

import contextlib
import math
from types import SimpleNamespace
from typing import Any

_NUMBER_TYPES = (int, float)


def is_scalar(value: Any) -> bool:
    """True for a plain Python (or numpy scalar) number, false for arrays and lists."""
    return isinstance(value, _NUMBER_TYPES) and not isinstance(value, bool)


def _where(cond: bool, a: float, b: float) -> float:
    return a if cond else b


SCALAR = SimpleNamespace(
    name="math",
    sqrt=math.sqrt,
    hypot=math.hypot,
    atan=math.atan,
    atan2=math.atan2,
    tan=math.tan,
    sin=math.sin,
    cos=math.cos,
    degrees=math.degrees,
    radians=math.radians,
    log2=math.log2,
    log10=math.log10,
    log1p=math.log1p,
    expm1=math.expm1,
    exp=math.exp,
    exp2=lambda x: 2.0**x,
    fabs=math.fabs,
    isinf=math.isinf,
    isfinite=math.isfinite,
    isnan=math.isnan,
    where=_where,
    minimum=min,
    maximum=max,
    asfloat=float,
    inf=math.inf,
    pi=math.pi,
    any=bool,
    all=bool,
)

_NUMPY: SimpleNamespace | None = None


def _numpy_ops() -> SimpleNamespace:
    global _NUMPY
    if _NUMPY is None:
        import numpy as np

        _NUMPY = SimpleNamespace(
            name="numpy",
            sqrt=np.sqrt,
            hypot=np.hypot,
            atan=np.arctan,
            atan2=np.arctan2,
            tan=np.tan,
            sin=np.sin,
            cos=np.cos,
            degrees=np.degrees,
            radians=np.radians,
            log2=np.log2,
            log10=np.log10,
            log1p=np.log1p,
            expm1=np.expm1,
            exp=np.exp,
            exp2=np.exp2,
            fabs=np.fabs,
            isinf=np.isinf,
            isfinite=np.isfinite,
            isnan=np.isnan,
            where=np.where,
            minimum=np.minimum,
            maximum=np.maximum,
            asfloat=lambda x: np.asarray(x, dtype=float),
            inf=np.inf,
            pi=np.pi,
            any=np.any,
            all=np.all,
        )
    return _NUMPY


def ops(*values: Any) -> SimpleNamespace:
    """Return the math namespace if every value is a plain number, else numpy's.

    >>> ops(1.0, 2).name
    'math'
    >>> ops(1.0, [2.0, 3.0]).name
    'numpy'
    """
    if all(is_scalar(v) for v in values):
        return SCALAR
    return _numpy_ops()


def as_float(*values: Any) -> tuple[Any, ...]:
    """Convert each value to ``float`` (scalar path) or a float array (array path)."""
    xp = ops(*values)
    return tuple(xp.asfloat(v) for v in values)


def quiet(xp: SimpleNamespace) -> Any:
    """Context manager silencing floating-point warnings on the array path.

    The formulas mask divisions by zero with ``where``; numpy still evaluates
    the masked branch, and its warning would be noise (or, under
    ``filterwarnings = error``, a failure).
    """
    if xp is SCALAR:
        return contextlib.nullcontext()
    import numpy as np

    return np.errstate(divide="ignore", invalid="ignore", over="ignore")


def broadcast(value: Any, *like: Any) -> Any:
    """Return ``value`` broadcast to the common shape of ``like`` (unchanged for scalars).

    Used for results that do not depend on every input (the hyperfocal
    distance does not depend on the focus distance) but must still have one
    entry per row. Multiplying by zero would turn an infinite input into NaN.
    """
    if all(is_scalar(v) for v in (value, *like)):
        return value
    import numpy as np

    return np.broadcast_arrays(np.asarray(value, dtype=float), *(np.asarray(v, dtype=float) for v in like))[0].copy()
