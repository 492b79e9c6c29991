"""Output keys a command adds only as it runs (a batch's passed-through columns aside)."""

from __future__ import annotations

DYNAMIC_KEYS = ("t_stop", "f_number_from")
"""Keys a row gains from what was typed (a T-stop), beyond those the command declares."""
