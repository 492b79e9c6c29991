"""What a preset is: the keys of each kind, their checks, and the frozen value classes.

Validation turns one raw YAML mapping into a *record*: a plain dict of checked
values (numbers in millimetres, strings, lists) that can be cached as JSON.
The value classes below (frozen :class:`camtool.core.record.Record` classes)
are built from records only when a preset is looked up,
so loading thousands of presets costs no object construction.

Every check reports ``(key, problem)`` pairs instead of raising, so that
``camtool presets validate FILE`` can list every problem of a file at once.
"""

from __future__ import annotations

import math
import re
from collections.abc import Callable, Iterable, Mapping
from typing import Any

from camtool.presets.kinds import (  # noqa: F401 - re-exported: the kinds and value classes are part of the schema
    FULL_FRAME_DIAGONAL_MM,
    KINDS,
    REFERENCES,
    SECTIONS,
    Camera,
    Film,
    Lens,
    Prescription,
    Preset,
    Scene,
    Sensor,
    kind_of,
    normalize,
    optics_mapping,
)

_ID = re.compile(r"^[a-z0-9]+(?:[.-][a-z0-9]+)*$")
_WORDS = re.compile(r"[a-z0-9]+(?:\.[a-z0-9]+)*")


def slugify(text: str) -> str:
    """A kebab-case id made from a free-form name (dots kept between digits and letters).

    >>> slugify("Canon EF 50mm f/1.8 STM")
    'canon-ef-50mm-f-1.8-stm'
    """
    return "-".join(_WORDS.findall(text.lower()))


# --- field checks -------------------------------------------------------------------------


class Bad(ValueError):
    """One field's value is wrong; the message says what was expected."""


def show(value: Any) -> str:
    """A short description of a bad value, safe for huge or nested values."""
    if isinstance(value, str):
        return repr(value if len(value) <= 40 else value[:37] + "...")
    if isinstance(value, (bool, int, float)) or value is None:
        return repr(value)
    if isinstance(value, Mapping):
        return "a mapping"
    if isinstance(value, (list, tuple)):
        return "a list"
    return type(value).__name__


def _real(value: Any, unit: str = "") -> float:
    if isinstance(value, bool) or not isinstance(value, (int, float)):
        if isinstance(value, str):
            hint = f" (write a plain number{' in ' + unit if unit else ''}; units are not allowed here)"
            raise Bad(f"expected a number, got the string {show(value)}{hint}")
        raise Bad(f"expected a number, got {show(value)}")
    number = float(value)
    if math.isnan(number):
        raise Bad("expected a number, got NaN")
    return number


def positive_mm(value: Any) -> float:
    """A length in mm: a plain positive finite number.

    >>> positive_mm(36)
    36.0
    >>> positive_mm("36mm")
    Traceback (most recent call last):
    ...
    camtool.presets.schema.Bad: expected a number, got the string '36mm' (write a plain number in mm; units are not allowed here)
    """
    number = _real(value, "mm")
    if not (number > 0 and math.isfinite(number)):
        raise Bad(f"must be > 0 mm, got {value!r}")
    return number


def positive(value: Any) -> float:
    """A positive finite number without unit (f-numbers, magnifications, ratios)."""
    number = _real(value)
    if not (number > 0 and math.isfinite(number)):
        raise Bad(f"must be > 0, got {value!r}")
    return number


def finite(value: Any) -> float:
    """Any finite number (a hiatus may be negative)."""
    number = _real(value, "mm")
    if not math.isfinite(number):
        raise Bad(f"must be finite, got {value!r}")
    return number


def pixel_count(value: Any) -> int:
    """A positive whole number of pixels."""
    number = _real(value)
    if not (number >= 1 and math.isfinite(number) and number == int(number)):
        raise Bad(f"must be a whole number >= 1, got {value!r}")
    return int(number)


def boolean(value: Any) -> bool:
    """true or false."""
    if not isinstance(value, bool):
        raise Bad(f"expected true or false, got {show(value)}")
    return value


def text(value: Any) -> str:
    """A non-empty string (a bare YAML number is accepted and kept as written)."""
    if isinstance(value, bool) or not isinstance(value, (str, int, float)):
        raise Bad(f"expected text, got {show(value)}")
    out = " ".join(str(value).split())
    if not out:
        raise Bad("must not be empty")
    return out


def ident(value: Any) -> str:
    """A kebab-case id: lower-case letters and digits in words joined by '-' (or '.').

    >>> ident("my-50mm-f1.8")
    'my-50mm-f1.8'
    >>> ident("My Lens")
    Traceback (most recent call last):
    ...
    camtool.presets.schema.Bad: 'My Lens' is not a kebab-case id (lower-case letters, digits and '-'); try 'my-lens'
    """
    if isinstance(value, int) and not isinstance(value, bool):
        value = str(value)
    if not isinstance(value, str):
        raise Bad(f"expected a kebab-case id, got {show(value)}")
    if not _ID.match(value):
        suggestion = slugify(value)
        hint = f"; try {suggestion!r}" if suggestion else ""
        raise Bad(f"{show(value)} is not a kebab-case id (lower-case letters, digits and '-'){hint}")
    return value


def name_list(value: Any) -> list[str]:
    """A list of alternative names (a single string is a list of one)."""
    if isinstance(value, (str, int)) and not isinstance(value, bool):
        value = [value]
    if not isinstance(value, list):
        raise Bad(f"expected a list of names, got {show(value)}")
    out = []
    for item in value:
        if isinstance(item, bool) or not isinstance(item, (str, int)):
            raise Bad(f"every alias must be text, got {show(item)} (quote numbers such as '1.5x')")
        if not normalize(str(item)):
            raise Bad(f"alias {show(item)} has no letters or digits")
        out.append(str(item))
    return out


def reference(value: Any) -> str:
    """The id or name of another preset."""
    if isinstance(value, bool) or not isinstance(value, (str, int)) or not normalize(str(value)):
        raise Bad(f"expected the name of a preset, got {show(value)}")
    return str(value)


def _length_with_default(unit: str, allow_inf: bool) -> Callable[[Any], float]:
    def check(value: Any) -> float:
        from camtool.core.units import UnitError, parse_length

        if isinstance(value, bool) or not isinstance(value, (str, int, float)):
            raise Bad(f"expected a length such as 3m or 50mm, got {show(value)}")
        try:
            number = parse_length(value, default_unit=unit)
        except UnitError as error:
            raise Bad(str(error)) from None
        if not (number > 0) or (math.isinf(number) and not allow_inf) or math.isnan(number):
            raise Bad(f"must be > 0{' (or inf)' if allow_inf else ''}, got {value!r}")
        return number

    check.__doc__ = f"A length with a unit (a bare number is in {unit})."
    return check


def f_number_text(value: Any) -> float:
    """An f-number written 8, f/8 or f8."""
    from camtool.core.units import UnitError, parse_f_number

    if isinstance(value, bool) or not isinstance(value, (str, int, float)):
        raise Bad(f"expected an f-number such as 8 or f/8, got {show(value)}")
    try:
        number = parse_f_number(value)
    except UnitError as error:
        raise Bad(str(error)) from None
    if not (number > 0 and math.isfinite(number)):
        raise Bad(f"must be > 0, got {value!r}")
    return number


CLOSE_FOCUS_FIELDS: dict[str, Callable[[Any], Any]] = {
    "focal_length_mm": positive_mm,
    "min_focus_mm": positive_mm,
    "max_magnification": positive,
}


def close_focus_rows(value: Any) -> list[dict[str, float]]:
    """A zoom's closest focus per focal length: ``[{focal_length_mm, min_focus_mm[, max_magnification]}]``.

    One row per focal length the maker publishes, in increasing focal length.

    >>> close_focus_rows([{"focal_length_mm": 24, "min_focus_mm": 210}, {"focal_length_mm": 70, "min_focus_mm": 380}])
    [{'focal_length_mm': 24.0, 'min_focus_mm': 210.0}, {'focal_length_mm': 70.0, 'min_focus_mm': 380.0}]
    >>> close_focus_rows([{"focal_length_mm": 70, "min_focus_mm": 380}, {"focal_length_mm": 24, "min_focus_mm": 210}])
    Traceback (most recent call last):
    ...
    camtool.presets.schema.Bad: row 2: focal_length_mm must be greater than the row before (70)
    """
    return _by_focal_length(value, CLOSE_FOCUS_FIELDS, ("focal_length_mm", "min_focus_mm"), "row",
                            "{focal_length_mm, min_focus_mm[, max_magnification]}")


def _by_focal_length(value: Any, fields: Mapping[str, Any], required: tuple[str, ...], word: str, shape: str,
                     also: Callable[[int, dict[str, float]], None] | None = None) -> list[dict[str, float]]:
    """A non-empty list of mappings of ``fields``, each checked (and by ``also``), in increasing
    ``focal_length_mm``; a problem names the ``word`` ("row", "member") and its number."""
    if not isinstance(value, list) or not value:
        raise Bad(f"expected a non-empty list of {shape}, got {show(value)}")
    out: list[dict[str, float]] = []
    for number, raw in enumerate(value, start=1):
        if not isinstance(raw, Mapping):
            raise Bad(f"{word} {number} must be a mapping, got {show(raw)}")
        record, problems = check_fields(raw, fields, required)
        if problems:
            key, problem = problems[0]
            raise Bad(f"{word} {number}, {key}: {problem}")
        if out and record["focal_length_mm"] <= out[-1]["focal_length_mm"]:
            raise Bad(f"{word} {number}: focal_length_mm must be greater than the {word} before "
                      f"({out[-1]['focal_length_mm']:g})")
        if also is not None:
            also(number, record)
        out.append(record)
    return out


def projection_name(value: Any) -> str:
    """A lens's mapping: rectilinear, equidistant, equisolid, orthographic or stereographic.

    >>> projection_name("equisolid")
    'equisolid'
    """
    from camtool.geometry.projection import PROJECTIONS

    if value not in PROJECTIONS:
        raise Bad(f"expected one of {', '.join(PROJECTIONS)}, got {show(value)}")
    return str(value)


def squeeze_factor(value: Any) -> float:
    """An anamorphic lens's squeeze, in the one range of ``--squeeze`` (:data:`camtool.core.ranges.SQUEEZE`).

    >>> squeeze_factor(2)
    2.0
    >>> squeeze_factor(0.5)
    Traceback (most recent call last):
    ...
    camtool.presets.schema.Bad: must be from 1 to 4, got 0.5
    """
    from camtool.core.ranges import SQUEEZE, describe

    number = _real(value)
    if not SQUEEZE[0] <= number <= SQUEEZE[1]:
        raise Bad(f"must be from {describe(SQUEEZE)}, got {value!r}")
    return number


def field_degrees(value: Any) -> float:
    """A lens's whole field in degrees, more than 0 and at most 360."""
    number = _real(value)
    if not 0.0 < number <= 360.0:
        raise Bad(f"must be more than 0 and at most 360 degrees, got {value!r}")
    return number


SET_FIELDS: dict[str, Callable[[Any], Any]] = {
    "focal_length_mm": positive_mm,
    "t_number_min": positive,
    "f_number_min": positive,
    "min_focus_mm": positive_mm,
    "max_magnification": positive,
}


def set_members(value: Any) -> list[dict[str, float]]:
    """A lens set's members, one per focal length: ``[{focal_length_mm[, t_number_min, f_number_min,
    min_focus_mm, max_magnification]}]`` in increasing focal length (a cine prime set).

    >>> set_members([{"focal_length_mm": 25, "t_number_min": 1.8, "min_focus_mm": 350}])
    [{'focal_length_mm': 25.0, 't_number_min': 1.8, 'min_focus_mm': 350.0}]
    >>> set_members([{"focal_length_mm": 50}, {"focal_length_mm": 35}])
    Traceback (most recent call last):
    ...
    camtool.presets.schema.Bad: member 2: focal_length_mm must be greater than the member before (50)
    """
    def t_stop_not_below_f_number(number: int, record: dict[str, float]) -> None:
        low, t_stop = record.get("f_number_min"), record.get("t_number_min")
        if low is not None and t_stop is not None and t_stop < low:
            raise Bad(f"member {number}: a T-stop cannot be below the f-number ({low:g})")

    return _by_focal_length(value, SET_FIELDS, ("focal_length_mm",), "member",
                            "{focal_length_mm[, t_number_min, min_focus_mm, ...]}", t_stop_not_below_f_number)


def sensor_ref(value: Any) -> str | dict[str, Any]:
    """A sensor: the name of a sensor preset, or an inline ``{width_mm, height_mm[, coc_mm]}``."""
    if isinstance(value, Mapping):
        record, problems = check_fields(value, INLINE_SENSOR_FIELDS, ("width_mm", "height_mm"))
        if problems:
            key, problem = problems[0]
            raise Bad(f"{key}: {problem}")
        return record
    return reference(value)


def _index(value: Any) -> float:
    number = finite(value)
    if number < 1.0:
        raise Bad(f"a refractive index must be >= 1, got {value!r}")
    return number


def surfaces(value: Any) -> list[Any]:
    """The surfaces of a prescription, from the object side: a non-empty list.

    What each surface holds (and the one stop) is checked with the rest of the
    prescription by :func:`camtool.optics.prescription.prescription_from_mapping`
    (:func:`_check_prescription`), the one validation of a prescription.
    """
    if not isinstance(value, list) or not value:
        raise Bad(f"expected a non-empty list of surfaces, got {show(value)}")
    return value


def reciprocity_exponent(value: Any) -> float:
    """A Schwarzschild exponent p for t_c = t_m^p: a plain number from 1 to 3.

    >>> reciprocity_exponent(1.31)
    1.31
    """
    number = _real(value)
    if not 1.0 <= number <= 3.0:
        raise Bad(f"must be from 1 to 3, got {value!r}")
    return number


def film_points(value: Any) -> tuple[tuple[float, Any], ...]:
    """A film's published reciprocity table: [metered s, adjusted s] or [metered s, "+1/3 stops"] pairs.

    Metered times increase; an adjusted time is at least the metered one; a
    correction is written ``+N stops`` (N a number or a fraction).

    >>> film_points([[1, 2], [10, "+2 stops"]])
    ((1.0, 2.0), (10.0, '+2 stops'))
    """
    if not isinstance(value, (list, tuple)) or not value:
        raise Bad(f"expected a list of [metered s, adjusted s or '+N stops'] pairs, got {show(value)}")
    out: list[tuple[float, Any]] = []
    for pair in value:
        if not isinstance(pair, (list, tuple)) or len(pair) != 2:
            raise Bad(f"each point is [metered s, adjusted s or '+N stops'], got {show(pair)}")
        metered = positive(pair[0])
        given = pair[1]
        if isinstance(given, str):
            if not re.fullmatch(r"\s*\+?\d+(?:\.\d+)?(?:\s*/\s*\d+)?\s*stops?\s*", given):
                raise Bad(f"a correction is written '+1/3 stops' or '+1 stops', got {show(given)}")
        elif positive(given) < metered:
            raise Bad(f"the adjusted time {given!r} s is shorter than the metered {metered:g} s")
        else:
            given = float(given)
        if out and metered <= out[-1][0]:
            raise Bad(f"metered times must increase ({metered:g} s after {out[-1][0]:g} s)")
        out.append((metered, given))
    return tuple(out)


# --- the keys of each kind ------------------------------------------------------------------

_COMMON: dict[str, Callable[[Any], Any]] = {
    "id": ident,
    "name": text,
    "aliases": name_list,
    "source": text,
    "notes": text,
}

INLINE_SENSOR_FIELDS: dict[str, Callable[[Any], Any]] = {
    "width_mm": positive_mm,
    "height_mm": positive_mm,
    "coc_mm": positive_mm,
    "name": text,
}

FIELDS: dict[str, dict[str, Callable[[Any], Any]]] = {
    "sensor": {
        **_COMMON,
        "width_mm": positive_mm,
        "height_mm": positive_mm,
        "coc_mm": positive_mm,
        "category": text,
        "approximate": boolean,
    },
    "camera": {
        **_COMMON,
        "sensor": sensor_ref,
        "lens": reference,
        "pixels_w": pixel_count,
        "pixels_h": pixel_count,
        "mount": text,
        "category": text,
        "approximate": boolean,
    },
    "lens": {
        **_COMMON,
        "focal_length_mm": positive_mm,
        "focal_min_mm": positive_mm,
        "focal_max_mm": positive_mm,
        "f_number_min": positive,
        "f_number_max": positive,
        "f_number_min_tele": positive,
        "f_number_max_tele": positive,
        "min_focus_mm": positive_mm,
        "max_magnification": positive,
        "min_magnification": positive,
        "focus_at_max_magnification_mm": positive_mm,
        "close_focus": close_focus_rows,
        "set": set_members,
        "t_number_min": positive,
        "equivalent_focal_length_mm": positive_mm,
        "pupil_magnification": positive,
        "hiatus_mm": finite,
        "tilt_max_deg": positive,
        "projection": projection_name,
        "field_max_deg": field_degrees,
        "squeeze": squeeze_factor,
        "prescription": reference,
        "sensor": reference,
        "mount": text,
        "category": text,
        "approximate": boolean,
    },
    # The same top-level keys camtool.optics.prescription accepts, so a record
    # can be handed to it unchanged.
    "prescription": {
        **_COMMON,
        "description": text,
        "kind": text,
        "focal_length_mm": positive_mm,
        "f_number": positive,
        "wavelength_nm": positive,
        "object_index": _index,
        "surfaces": surfaces,
    },
    "scene": {
        **_COMMON,
        "camera": reference,
        "sensor": reference,
        "lens": reference,
        "f_number": f_number_text,
        "focal_length": _length_with_default("mm", allow_inf=False),
        "focal_length_mm": positive_mm,
        "distance": _length_with_default("m", allow_inf=True),
        "distance_mm": positive_mm,
        "subject_size": _length_with_default("mm", allow_inf=False),
        "subject_size_mm": positive_mm,
        "background": _length_with_default("m", allow_inf=True),
        "background_mm": positive_mm,
        "coc": _length_with_default("mm", allow_inf=False),
        "coc_mm": positive_mm,
        "magnification": positive,
    },
    "film": {
        **_COMMON,
        "p": reciprocity_exponent,
        "threshold_s": positive,
        "points": film_points,
        "valid_to_s": positive,
    },
}

REQUIRED = {
    "sensor": ("id", "width_mm", "height_mm"),
    "camera": ("id", "sensor"),
    "lens": ("id",),
    "prescription": ("id", "surfaces"),
    "scene": ("id",),
    "film": ("id",),
}


# Scene keys written with a unit, and the millimetre key each one fills.
_SCENE_UNIT_KEYS = {"focal_length": "focal_length_mm", "distance": "distance_mm",
                    "subject_size": "subject_size_mm", "background": "background_mm", "coc": "coc_mm"}


def suggest(word: str, choices: Iterable[str]) -> str:
    """' (did you mean X?)' for the closest choice, or '' when none is close."""
    import difflib

    close = difflib.get_close_matches(word, sorted(choices), n=1, cutoff=0.6)
    return f" (did you mean {close[0]}?)" if close else ""


def check_fields(
    raw: Mapping[Any, Any], fields: Mapping[str, Callable[[Any], Any]], required: tuple[str, ...] = ()
) -> tuple[dict[str, Any], list[tuple[str, str]]]:
    """Check every key of ``raw`` against ``fields``; return the clean record and the problems."""
    record: dict[str, Any] = {}
    problems: list[tuple[str, str]] = []
    for key, value in raw.items():
        name = str(key)
        check = fields.get(name)
        if check is None:
            problems.append((name, "unknown key" + suggest(name, fields.keys())))
            continue
        if value is None:
            problems.append((name, "has no value"))
            continue
        try:
            record[name] = check(value)
        except Bad as error:
            problems.append((name, str(error)))
    for name in required:
        if name not in raw:
            problems.append((name, "is required"))
    return record, problems


def check_record(kind: str, raw: Mapping[Any, Any]) -> tuple[dict[str, Any], list[tuple[str, str]]]:
    """Validate one raw preset mapping of ``kind``; return its record and the ``(key, problem)`` list.

    >>> record, problems = check_record("sensor", {"id": "tiny", "width_mm": -3, "height": 2})
    >>> problems
    [('width_mm', 'must be > 0 mm, got -3'), ('height', 'unknown key (did you mean height_mm?)'), ('height_mm', 'is required')]
    """
    record, problems = check_fields(raw, FIELDS[kind], REQUIRED[kind])
    if not problems:
        problems.extend(_CROSS_CHECKS.get(kind, _no_cross_check)(record))
    return record, problems


def _no_cross_check(record: dict[str, Any]) -> list[tuple[str, str]]:
    return []


def _check_camera(record: dict[str, Any]) -> list[tuple[str, str]]:
    if ("pixels_w" in record) != ("pixels_h" in record):
        missing = "pixels_h" if "pixels_w" in record else "pixels_w"
        return [(missing, "give both pixels_w and pixels_h, or neither")]
    return []


_PER_MEMBER = ("focal_length_mm", "focal_min_mm", "focal_max_mm", "close_focus", "min_focus_mm",
               "max_magnification", "min_magnification", "t_number_min", "f_number_min", "f_number_min_tele",
               "f_number_max_tele", "focus_at_max_magnification_mm", "prescription")


def _check_lens(record: dict[str, Any]) -> list[tuple[str, str]]:
    if "set" in record:
        clash = [key for key in _PER_MEMBER if key in record]
        if clash:
            return [(clash[0], "a lens set gives its focal lengths, stops and close focus per member, in set")]
        return []
    has_prime = "focal_length_mm" in record
    has_zoom = "focal_min_mm" in record or "focal_max_mm" in record
    if has_prime and has_zoom:
        return [("focal_length_mm", "give focal_length_mm for a prime or focal_min_mm/focal_max_mm, not both")]
    if not has_prime and not has_zoom:
        return [("focal_length_mm", "is required (or focal_min_mm and focal_max_mm for a zoom)")]
    if has_zoom:
        for key in ("focal_min_mm", "focal_max_mm"):
            if key not in record:
                return [(key, "a zoom needs both focal_min_mm and focal_max_mm")]
        if record["focal_min_mm"] > record["focal_max_mm"]:
            return [("focal_max_mm", f"must be >= focal_min_mm ({record['focal_min_mm']:g})")]
    widest, smallest = record.get("f_number_min"), record.get("f_number_max")
    if widest is not None and smallest is not None and widest > smallest:
        return [("f_number_max", f"must be >= f_number_min ({widest:g}): f_number_min is the widest aperture")]
    for end, short in (("f_number_min_tele", "f_number_min"), ("f_number_max_tele", "f_number_max")):
        value = record.get(end)
        if value is None:
            continue
        if not has_zoom:
            return [(end, "applies only to a zoom (focal_min_mm/focal_max_mm)")]
        if record.get(short) is None or value < record[short]:
            return [(end, f"needs {short} and must be >= it")]
    tele, tele_smallest = record.get("f_number_min_tele"), record.get("f_number_max_tele")
    if tele is not None and tele_smallest is not None and tele_smallest < tele:
        return [("f_number_max_tele", f"must be >= f_number_min_tele ({tele:g})")]
    t_stop = record.get("t_number_min")
    if t_stop is not None and widest is not None and t_stop < widest:
        return [("t_number_min", f"a T-stop cannot be below the f-number ({widest:g})")]
    low, high = record.get("min_magnification"), record.get("max_magnification")
    if low is not None and high is not None and low > high:
        return [("min_magnification", f"must be <= max_magnification ({high:g})")]
    if "field_max_deg" in record and record.get("projection", "rectilinear") == "rectilinear":
        return [("field_max_deg", "applies only to a fisheye (projection other than rectilinear)")]
    far = record.get("focus_at_max_magnification_mm")
    if far is not None and (low is None or high is None or record.get("min_focus_mm") is None):
        return [("focus_at_max_magnification_mm",
                 "applies only to a lens without infinity focus (min_magnification, max_magnification, min_focus_mm)")]
    if far is not None and far < record["min_focus_mm"]:
        return [("focus_at_max_magnification_mm", f"must be >= min_focus_mm ({record['min_focus_mm']:g})")]
    if "close_focus" in record:
        return _check_close_focus(record)
    return []


def _check_close_focus(record: dict[str, Any]) -> list[tuple[str, str]]:
    """A zoom's per-focal-length rows lie in its range and agree with its lens-level figures."""
    rows = record["close_focus"]
    if "focal_min_mm" not in record:
        return [("close_focus", "applies only to a zoom (focal_min_mm/focal_max_mm); a prime has min_focus_mm")]
    low, high = record["focal_min_mm"], record["focal_max_mm"]
    outside = [r["focal_length_mm"] for r in rows if not low - 0.5 <= r["focal_length_mm"] <= high + 0.5]
    if outside:
        return [("close_focus", f"focal length {outside[0]:g} mm is outside {low:g}-{high:g} mm")]
    shortest = min(r["min_focus_mm"] for r in rows)
    if "min_focus_mm" in record and not math.isclose(record["min_focus_mm"], shortest, abs_tol=0.5):
        return [("min_focus_mm", f"must be the shortest closest focus of close_focus ({shortest:g} mm)")]
    largest = max((r["max_magnification"] for r in rows if "max_magnification" in r), default=None)
    if largest is not None and record.get("max_magnification", math.inf) < largest - 1e-9:
        return [("max_magnification", f"must be at least the largest of close_focus ({largest:g})")]
    return []


def _check_scene(record: dict[str, Any]) -> list[tuple[str, str]]:
    problems = []
    for written, mm in _SCENE_UNIT_KEYS.items():
        if written in record:
            if mm in record:
                problems.append((written, f"give {written} or {mm}, not both"))
            else:
                record[mm] = record.pop(written)
    return problems


def _check_prescription(record: dict[str, Any]) -> list[tuple[str, str]]:
    """The prescription as :mod:`camtool.optics.prescription` validates it; a surface's problem is on ``surfaces``."""
    from camtool.optics.prescription import PrescriptionError, prescription_from_mapping

    try:
        prescription_from_mapping(optics_mapping(record), source=record["id"])
    except PrescriptionError as error:
        if error.surface is not None:
            return [("surfaces", f"surface {error.surface}, {error.key}: {error.problem}")]
        return [("surfaces" if error.key == "stop" else error.key, error.problem)]
    return []


def _check_film(record: dict[str, Any]) -> list[tuple[str, str]]:
    if ("p" in record) == ("points" in record):
        return [("p", "give p (an exponent) or points (a published table), one of them")]
    if "points" in record and "threshold_s" in record:
        return [("threshold_s", "applies to p; a table starts where its first point does")]
    return []


_CROSS_CHECKS: dict[str, Callable[[dict[str, Any]], list[tuple[str, str]]]] = {
    "camera": _check_camera,
    "lens": _check_lens,
    "prescription": _check_prescription,
    "scene": _check_scene,
    "film": _check_film,
}


