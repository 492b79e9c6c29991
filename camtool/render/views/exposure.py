"""What ``camtool exposure`` shows: table columns and output keys."""

from __future__ import annotations

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
