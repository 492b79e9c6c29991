"""What ``camtool tilt`` shows: table columns and output keys."""

from __future__ import annotations

from camtool.render.columns import ANGLE, FNUMBER, SMALL, TEXT, Column

COLUMNS = [Column("focal_length_mm", "f", SMALL), Column("f_number", "N", FNUMBER), Column("tilt_deg", "tilt", ANGLE),
           Column("hinge_mm", "hinge J"), Column("focus_mm", "focus"), Column("near_mm", "near"), Column("far_mm", "far"),
           Column("focus_plane_deg", "focus plane", ANGLE), Column("near_plane_deg", "near plane", ANGLE),
           Column("far_plane_deg", "far plane", ANGLE), Column("hyperfocal_mm", "hyperfocal")]

AT_COLUMNS = [Column("at_mm", "at"), Column("above_mm", "above"), Column("below_mm", "below")]

NEED_COLUMNS = [Column("half_depth_mm", "± wanted"), Column("f_number_needed", "needs", FNUMBER)]

OPTIMUM_COLUMNS = [Column("f_number_optimum", "optimum", FNUMBER), Column("blur_optimum_mm", "blur there", SMALL)]

MODEL_COLUMN = Column("model", "model", TEXT)
