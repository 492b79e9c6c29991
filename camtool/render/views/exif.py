"""What ``camtool exif`` shows: table columns and output keys."""

from __future__ import annotations

from camtool.render.columns import ANGLE, FNUMBER, NUMBER, SMALL, TEXT, Column

COLUMNS = [Column("file", "file", TEXT), Column("focal_length_mm", "f", SMALL), Column("f_number", "N", FNUMBER),
           Column("focus_distance_mm", "focus"), Column("near_mm", "near"), Column("far_mm", "far"),
           Column("total_mm", "depth"), Column("hyperfocal_mm", "H"), Column("horizontal_deg", "h. angle", ANGLE),
           Column("ev100", "EV100", NUMBER)]


def exif_footer(*, coc_mm: float | None, coc_rule: str, distance_from: str, model: str) -> str:
    """The table's footer: the distance plane, the CoC (given, or the rule applied to each file's sensor), the model."""
    criterion = f"CoC {coc_mm:g} mm" if coc_mm is not None else f"CoC {coc_rule} of each sensor"
    return f"distances from the {distance_from} · {criterion} · model {model} · JSON/CSV carry every key and its *_source"
