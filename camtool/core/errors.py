"""Errors raised by the formula core, and the shared domain check."""

from __future__ import annotations

import math
from typing import Any

from camtool.core.arrays import is_scalar


class CamtoolError(Exception):
    """The root of every error camtool's library raises on purpose.

    A caller of the Python API catches this one type; each subclass keeps the
    built-in base it had (``ValueError``, ``LookupError``, ...), so existing
    ``except ValueError`` clauses go on working.
    """


class DomainError(CamtoolError, ValueError):
    """A value lies outside the physical domain of a formula.

    ``param`` names the parameter (as the library spells it), ``value`` is the
    offending value and ``valid`` describes the valid range in words, so the
    CLI can map the parameter to its option and print one line. ``scenes``,
    when a check over a row of scenes failed (:func:`require`), is how many
    scenes it checked and which of them failed: a batch sets those rows aside
    rather than halving its group until it finds them.
    """

    scenes: tuple[int, list[int]] | None = None

    def __init__(self, param: str, value: Any, valid: str, detail: str = "", limit: Any = None) -> None:
        self.param = param
        self.value = value
        self.valid = valid
        self.detail = detail
        self.limit = limit
        shown_valid = valid.replace("{limit}", f"{_show(limit)} mm") if limit is not None else valid
        text = f"{param}={_show(value)} is outside the valid range: {shown_valid}"
        if detail:
            text += f" ({detail})"
        super().__init__(text)


class InputError(CamtoolError, ValueError):
    """An input that cannot be used, in words: ``param`` names it, ``template`` says why.

    Inputs are named in the template by placeholder, ``{focal_length}``, so
    each caller spells them its own way: the command line as the option
    (``-f``), the Python API as the argument; ``str()`` shows the bare
    names. ``usage`` marks a combination of inputs rather than one bad value.

    >>> error = InputError("crop", "give {sensor} or {crop}, not both", usage=True)
    >>> str(error), error.render(lambda name: "--" + name)
    ('give sensor or crop, not both', 'give --sensor or --crop, not both')
    """

    def __init__(self, param: str, template: str, usage: bool = False) -> None:
        self.param = param
        self.template = template
        self.usage = usage
        super().__init__(self.render(lambda name: name))

    def render(self, spell: Any) -> str:
        """The message with each ``{name}`` spelled by ``spell(name)``."""

        class Spelled(dict[str, str]):
            def __missing__(self, key: str) -> str:
                return str(spell(key))

        return self.template.format_map(Spelled())


def braced(text: str) -> str:
    """``text`` safe inside an :class:`InputError` template (or any ``str.format`` template): braces doubled.

    >>> braced("rule {x}")
    'rule {{x}}'
    """
    return text.replace("{", "{{").replace("}", "}}")


class FileError(CamtoolError):
    """A file camtool was asked to read cannot be read or is invalid: exit status 1, one line naming the file.

    The guarded reader's ``FileProblem`` and the preset database's
    ``PresetFileError`` derive from it, so the command line reports either
    the same way wherever it surfaces.
    """


def _show(value: Any) -> str:
    if isinstance(value, float) and value.is_integer() and abs(value) < 1e15:
        return str(int(value))
    return f"{value:g}" if isinstance(value, float) else str(value)


def first_bad(value: Any, ok: Any) -> Any:
    """Return the first element of ``value`` where ``ok`` is false (scalar or array)."""
    if (is_scalar(value) and isinstance(ok, bool)) or isinstance(value, str):  # a name (a film's) names itself
        return value
    import numpy as np

    value, ok = np.broadcast_arrays(np.asarray(value, dtype=float), np.asarray(ok))
    return float(value[~ok].flat[0])


def require(param: str, value: Any, ok: Any, valid: str, detail: str = "", limit: Any = None) -> None:
    """Raise :class:`DomainError` unless ``ok`` holds everywhere.

    ``ok`` is a bool (scalar path) or a boolean array (array path); a NaN in
    ``value`` must make ``ok`` false, which comparisons such as ``value > 0``
    already do.
    """
    if isinstance(ok, bool):
        if not ok:
            raise DomainError(param, value, valid, detail, limit)
        return
    import numpy as np

    if not bool(np.all(ok)):
        bad_limit = None if limit is None else first_bad(np.broadcast_to(limit, np.shape(ok)), ok)
        error = DomainError(param, first_bad(value, ok), valid, detail, bad_limit)
        failed = ~np.broadcast_to(np.asarray(ok, dtype=bool), np.broadcast_shapes(np.shape(value), np.shape(ok)))
        if failed.ndim == 1:  # one row of scenes: which of them failed
            error.scenes = (failed.size, np.flatnonzero(failed).tolist())
        raise error


def require_positive(param: str, value: Any, unit: str = "mm", allow_inf: bool = False) -> None:
    """Raise unless ``value`` is a positive finite number (or +inf if allowed)."""
    if is_scalar(value):
        ok = value > 0 and (allow_inf or math.isfinite(value))
    else:
        import numpy as np

        v = np.asarray(value, dtype=float)
        # two reductions instead of elementwise masks: NaN makes min() NaN, failing the test
        if v.size and float(v.min()) > 0 and (allow_inf or float(v.max()) < math.inf):
            return
        ok = (v > 0) & (np.isfinite(v) | allow_inf)
    valid = f"> 0 {unit}".rstrip() + (" (inf allowed)" if allow_inf else "")
    require(param, value, ok, valid)
