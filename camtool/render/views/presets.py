"""What ``camtool presets`` shows: table columns and output keys."""

from __future__ import annotations

from typing import Any

from camtool.render.columns import TEXT, Column

LIST_KEYS = ["kind", "id", "name", "summary", "tier", "origin"]

LIST_COLUMNS = [Column("kind", "kind", TEXT), Column("id", "id", TEXT), Column("summary", "summary", TEXT),
                Column("tier", "from", TEXT)]

SHOW_COLUMNS = [Column("key", "key", TEXT), Column("value", "value", TEXT)]


def show_rows(kind: str, fields: dict[str, Any]) -> list[dict[str, str]]:
    """A preset's fields as key/value rows of a table (a film's reciprocity points as ``1 s +0.3 EV``)."""
    shown = dict(fields)
    if kind == "film" and shown.get("points"):
        shown["points"] = ", ".join(f"{t:g} s +{stops:.2g} EV" for t, stops in shown["points"])
    return [{"key": key, "value": _shown(value)} for key, value in shown.items() if value is not None]


def _shown(value: Any) -> str:
    if isinstance(value, float):
        return f"{value:.6g}"
    if isinstance(value, list):
        return ", ".join(map(str, value))
    return str(value)
