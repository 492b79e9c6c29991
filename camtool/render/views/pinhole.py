"""What ``camtool pinhole`` shows: table columns and output keys."""

from __future__ import annotations

from camtool.render.columns import FNUMBER, NUMBER, SMALL, TEXT, Column

KEYS = ["method", "constant", "pinhole_mm", "f_number", "geometric_blur_mm", "airy_mm", "defocus_waves",
        "resolution_lpmm", "mtf_level", "best_at_level", "shutter_s", "film_distance_mm", "subject_distance_mm",
        "wavelength_nm", "horizontal_deg", "vertical_deg", "diagonal_deg"]

COLUMNS = [Column("method", "rule", TEXT), Column("constant", "k", NUMBER), Column("pinhole_mm", "pinhole", SMALL),
           Column("f_number", "N", FNUMBER), Column("geometric_blur_mm", "shadow", SMALL),
           Column("airy_mm", "Airy", SMALL), Column("defocus_waves", "W₂₀ (waves)", NUMBER),
           Column("resolution_lpmm", "lp/mm at level", NUMBER), Column("best_at_level", "best at", NUMBER),
           Column("shutter_s", "time (s)", NUMBER)]
