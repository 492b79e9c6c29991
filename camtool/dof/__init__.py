"""Depth of field: closed forms, the thick, paraxial and ray-traced rungs, the ladder and auto."""
