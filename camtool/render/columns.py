"""What a column of output holds: its key, its header and the kind of quantity."""

from __future__ import annotations

from camtool.core.record import NamedTuple

DISTANCE = "distance"  # a distance or depth in mm; the table picks m/mm or ft/in per column
SMALL = "small"  # a small length (focal length, CoC, extension, blur): always mm, as photographers give them
ANGLE = "angle"  # degrees
NUMBER = "number"  # a plain number (magnification, EV, ratios)
FNUMBER = "fnumber"  # an f-number
TEXT = "text"


class Column(NamedTuple):
    """One output column: JSON/CSV ``key``, table ``header`` (without unit), ``kind``, and a ``legend``.

    The legend (what a picture's symbols mean) joins the table's footer only
    when the column is shown.
    """

    key: str
    header: str
    kind: str = DISTANCE
    legend: str = ""


IDENTIFYING = frozenset({
    "file", "frame", "model", "focal_length_mm", "f_number", "aperture", "id", "key", "kind", "given",
    "distance_mm", "distance", "tier",
})
"""Output keys that say which row is which: kept in a table at any width (with :data:`ANSWERS`)."""

ANSWERS = frozenset({
    "near_mm", "far_mm", "hyperfocal_mm", "corrected", "time", "iso_text", "step_mm", "at_mm", "value", "summary",
    "horizontal_deg", "vertical_deg", "diagonal_deg", "tilt_deg", "f_number_needed", "f_number_optimum",
    "rule500", "npf", "equivalent_focal_length_mm", "equivalent_iso", "gn", "field_width_mm", "extension_mm",
})
"""Output keys that hold a row's answer: kept in a table at any width, and emphasised."""
