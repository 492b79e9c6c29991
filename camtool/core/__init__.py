"""Foundations every layer uses: scalar-or-array arithmetic, domain errors and ranges, unit parsing."""
