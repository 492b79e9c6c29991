"""What ``camtool cocmap`` shows: table columns and output keys."""

from __future__ import annotations

from camtool.render.columns import NUMBER, SMALL, TEXT, Column

KEYS = ["frame", "depth_file", "map_file", "mode", "width_px", "height_px", "depth_unit_mm", "focus_mm", "focus_from",
        "f_number", "f_number_from", "focal_length_mm", "focal_length_from", "pupil_offset_mm", "pupil_magnification",
        "sensor_width_mm", "coc_mm", "sharp_fraction", "sharp_near_mm", "sharp_far_mm", "near_limit_mm",
        "far_limit_mm", "max_coc_mm", "max_radius_px"]

COLUMNS = [Column("depth_file", "depth", TEXT), Column("sharp_fraction", "sharp", NUMBER),
           Column("sharp_near_mm", "sharp from"), Column("sharp_far_mm", "sharp to"),
           Column("near_limit_mm", "near"), Column("far_limit_mm", "far"), Column("max_coc_mm", "max CoC", SMALL),
           Column("max_radius_px", "max radius (px)", NUMBER)]
