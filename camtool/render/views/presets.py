"""What ``camtool presets`` shows: table columns and output keys."""

from __future__ import annotations

from camtool.render.columns import TEXT, Column

LIST_KEYS = ["kind", "id", "name", "summary", "tier", "origin"]

LIST_COLUMNS = [Column("kind", "kind", TEXT), Column("id", "id", TEXT), Column("summary", "summary", TEXT),
                Column("tier", "from", TEXT)]

SHOW_COLUMNS = [Column("key", "key", TEXT), Column("value", "value", TEXT)]
