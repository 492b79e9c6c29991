"""What ``camtool stars`` shows: table columns and output keys."""

from __future__ import annotations

from collections.abc import Sequence
from typing import Any

from camtool.render.columns import NUMBER, SMALL, TEXT, Column

KEYS = ["focal_length_mm", "f_number", "crop_factor", "pixel_pitch_um", "declination_deg", "rule500_s",
        "npf_simple_s", "npf_s"]

COLUMNS = [
    Column("focal_length_mm", "f", SMALL),
    Column("aperture", "N", TEXT),
    Column("declination_deg", "δ (°)", NUMBER),
    Column("rule500", "500 rule", TEXT),
    Column("npf_simple", "NPF simple", TEXT),
    Column("npf", "NPF", TEXT),
]


def stars_footer(rows: Any, *, apertures_given: bool, pitches_um: Sequence[float], sensor: Any,
                 rule_constant: float) -> str:
    """The table's texts of each row (the times as a photographer reads them) and the footer."""
    from camtool.exposure.timefmt import format_time

    for row in rows:
        row["aperture"] = f"f/{row['f_number']:g}" if apertures_given else "—"
        row["rule500"] = format_time(row["rule500_s"])
        row["npf_simple"] = format_time(row["npf_simple_s"]) if pitches_um else "—"
        row["npf"] = format_time(row["npf_s"]) if pitches_um else "—"
    pitch_note = (f"pixel pitch {', '.join(f'{v:.3g}' for v in pitches_um)} µm" if pitches_um else
                  "no pixel pitch (--pixel-pitch or --camera) for the NPF rule")
    return (f"{sensor.label}, crop {sensor.crop_factor:.3g} · {pitch_note} · declination in degrees · "
            f"{rule_constant:g} rule")
