"""Output: one entry point, :func:`camtool.render.output.write_rows`, for table, JSON and CSV."""
