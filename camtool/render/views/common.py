"""Columns shared by several commands: the T-stop a cine user typed, beside the f-number used."""

from __future__ import annotations

T_STOP_COLUMN = "camtool.t_stop_column"  # ctx.meta: a --batch -N column holds T-stops (every row gets the keys)
