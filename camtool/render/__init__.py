"""Output: one writer, :class:`camtool.render.output.RowWriter`, for table, JSON, CSV and ``--field``."""
