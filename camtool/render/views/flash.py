"""What ``camtool flash`` shows: table columns and output keys."""

from __future__ import annotations

from typing import Any

from camtool.render.columns import TEXT, Column

KEYS = ["guide_number_m", "guide_number_at_iso_m", "distance_mm", "f_number", "iso", "solved"]

COLUMNS = [
    Column("gn", "GN (ISO 100)", TEXT),
    Column("gn_iso", "GN at ISO", TEXT),
    Column("distance", "distance", TEXT),
    Column("aperture", "N", TEXT),
    Column("iso_text", "ISO", TEXT),
]

FEET_PER_METRE = 1 / 0.3048
SOLVED = {"guide_number": "guide number", "distance": "distance", "f_number": "f-number", "iso": "ISO"}


def flash_footer(rows: Any, *, solved: str, imperial: bool) -> str:
    """The table's texts of each row (guide numbers and distance in metres, or feet) and the footer."""
    def gn(metres: float) -> str:
        return f"{metres * FEET_PER_METRE:.3g}" if imperial else f"{metres:.3g}"

    for row in rows:
        row["gn"], row["gn_iso"] = gn(row["guide_number_m"]), gn(row["guide_number_at_iso_m"])
        d = row["distance_mm"] / 1000.0
        row["distance"] = f"{d * FEET_PER_METRE:.3g} ft" if imperial else f"{d:.3g} m"
        row["aperture"] = f"f/{row['f_number']:.3g}"
        row["iso_text"] = f"{row['iso']:.4g}"
    return (f"solved: {SOLVED[solved]} · GN = distance × N at ISO 100, × √(ISO/100) · guide numbers in "
            f"{'feet' if imperial else 'metres'}")
