"""What a column of output holds: its key, its header and the kind of quantity."""

from __future__ import annotations

from typing import NamedTuple

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
