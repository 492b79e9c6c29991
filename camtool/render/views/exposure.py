"""What ``camtool exposure`` shows: table columns and output keys."""

from __future__ import annotations

from collections.abc import Sequence
from typing import Any

from camtool.render.columns import ANGLE as ANGLE_KIND
from camtool.render.columns import NUMBER, TEXT, Column

EQUIVALENT_KEYS = ["f_number", "f_number_nominal", "shutter_s", "shutter_nominal_s", "shutter_exact_s", "ev",
                   "iso", "ev100"]

EQUIVALENT_COLUMNS = [
    Column("aperture", "N", TEXT),
    Column("time", "time", TEXT),
    Column("exact", "exact time", TEXT),
    Column("ev", "EV", NUMBER),
]

SETTINGS_COLUMNS = [
    Column("aperture", "N", TEXT),
    Column("time", "time", TEXT),
    Column("iso_text", "ISO", TEXT),
    Column("ev", "EV", NUMBER),
    Column("ev100", "EV100", NUMBER),
    Column("nominal", "nearest stops", TEXT),
]

METERED_COLUMNS = [
    Column("metered", "metered", TEXT),
    Column("nd_stops", "ND", NUMBER),
    Column("bellows_stops", "bellows", NUMBER),
    Column("iso_change_stops", "ISO change", NUMBER),
    Column("aperture_change_stops", "aperture change", NUMBER),
    Column("reciprocity_stops", "reciprocity", NUMBER),
    Column("aperture", "N", TEXT),
    Column("iso_text", "ISO", TEXT),
    Column("corrected", "time to set", TEXT),
]

LOSS_COLUMNS = [Column("nd_stops", "ND stops", NUMBER), Column("bellows_stops", "bellows stops", NUMBER)]

RECIPROCITY_COLUMNS = [Column("corrected", "with reciprocity", TEXT)]


ANGLE = [Column("shutter_angle_deg", "shutter angle", ANGLE_KIND)]
SOLVED_NAMES = {"f_number": "f-number", "shutter_s": "time", "iso": "ISO", "ev100": "scene EV100"}


def exposure_view(answer: Any, rows: Any, *, t_stop: bool, step: str, film: Any, angles: list[str]
                  ) -> tuple[list[Column], list[str], str]:
    """The rows' text cells (aperture, times, ISO), the table's columns, the keys and the footer of an exposure."""
    from camtool.exposure.calculator import KEYS as ROW_KEYS
    from camtool.exposure.timefmt import format_time

    mark = "T" if t_stop else "f/"
    angle = ANGLE[:len(angles)]
    if answer.mode == "equivalents":
        for row in rows:
            row["aperture"] = f"{mark}{row['f_number_nominal']:g}"
            row["time"], row["exact"] = format_time(row["shutter_nominal_s"]), format_time(row["shutter_exact_s"])
        return (EQUIVALENT_COLUMNS + angle, [*EQUIVALENT_KEYS, *angles],
                f"{answer.notes[0]} · {step} stops · exact time before snapping")
    for row in rows:
        row["aperture"] = f"{mark}{row['f_number']:.3g}"
        row["time"] = format_time(row["shutter_s"])
        row["iso_text"] = f"{row['iso']:.4g}"
        row["nominal"] = (f"{mark}{row['f_number_nominal']:g} {format_time(row['shutter_nominal_s'])} "
                          f"ISO {row['iso_nominal']:g}")
        row["corrected"] = format_time(row["corrected_shutter_s"])
        if answer.mode == "metered":
            row["metered"] = (f"{mark}{row['metered_f_number']:.3g} {format_time(row['metered_shutter_s'])} "
                              f"ISO {row['metered_iso']:.4g}")
    keys = [*ROW_KEYS, *(key for key in EQUIVALENT_KEYS if key not in ROW_KEYS), *angles]
    return _columns(answer, rows) + angle, keys, _footer(answer, step, film, t_stop)


def _columns(answer: Any, rows: Sequence[dict[str, Any]]) -> list[Column]:
    """The table's columns: the corrections that are not zero, then the answer."""
    if answer.mode == "metered":
        optional = {"nd_stops", "bellows_stops", "iso_change_stops", "aperture_change_stops", "reciprocity_stops"}
        return [c for c in METERED_COLUMNS
                if c.key not in optional or any(abs(float(r[c.key])) > 1e-12 for r in rows)]
    shown = list(SETTINGS_COLUMNS)
    if answer.mode == "scene" and any(float(r["nd_stops"]) or float(r["bellows_stops"]) for r in rows):
        shown += LOSS_COLUMNS
    if answer.film is not None or any(abs(float(r["reciprocity_stops"])) > 1e-12 for r in rows):
        shown += RECIPROCITY_COLUMNS
    return shown


def _footer(answer: Any, step: str, film: Any, t_stop: bool) -> str:
    if answer.mode == "metered":
        note = (f"metered settings without the filters · answer: {SOLVED_NAMES[answer.solved]} · "
                "corrections in stops · bulb times (> 30 s) exact")
    else:
        note = (f"EV = log2(N²/t) of the settings · EV100 = the scene at ISO 100 · "
                f"solved: {SOLVED_NAMES[answer.solved]} · nearest {step} stops")
    if t_stop:
        note += " · T-stops: exposure uses them as given"
    if film is not None:
        model = f"p = {film.p:g}" if film.p is not None else f"published table to {film.points[-1][0]:g} s"
        note += f" · {film.name}, {model}"
    return note
