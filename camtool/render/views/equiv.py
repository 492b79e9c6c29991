"""What ``camtool equiv`` shows: table columns and output keys."""

from __future__ import annotations

from typing import Any

from camtool.render.columns import NUMBER, SMALL, TEXT, Column

KEYS = ["focal_length_mm", "f_number", "iso", "equivalent_focal_length_mm", "equivalent_f_number",
        "equivalent_iso", "ratio", "aperture_diameter_mm", "light_stops", "converter"]

COLUMNS = [
    Column("given", "given", TEXT),
    Column("equivalent_focal_length_mm", "f", SMALL),
    Column("aperture", "N", TEXT),
    Column("equivalent_iso", "ISO", NUMBER),
    Column("aperture_diameter_mm", "aperture", SMALL),
    Column("light_stops", "light", NUMBER),
]


def equiv_footer(rows: Any, *, source: Any, target: Any, converter: float) -> str:
    """The table's texts of each row (the settings given, the f-number to set) and the footer."""
    for row in rows:
        row["given"] = f"{row['focal_length_mm']:g} mm f/{row['f_number']:g} ISO {row['iso']:g}"
        row["aperture"] = f"f/{row['equivalent_f_number']:.3g}"
    conv = f" · converter ×{converter:g} on the lens" if converter != 1.0 else ""
    return (f"{source.label} → {target.label}, ratio {rows[0]['ratio']:.4g}{conv} · same angle of view f·r, "
            "same depth of field N·r, same total light ISO·r²")
