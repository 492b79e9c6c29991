"""Presets for real equipment: sensors, cameras, lenses, prescriptions and scenes.

>>> from camtool.presets import load_db
>>> db = load_db(use_cache=False, lensfun=False)
>>> db.camera("Nikon Z 8").sensor.id
'full-frame'

Modules: :mod:`~camtool.presets.kinds` (the kinds and their value classes),
:mod:`~camtool.presets.schema` (keys and checks),
:mod:`~camtool.presets.loader` (one file: safe YAML, line numbers, cache),
:mod:`~camtool.presets.shipped_records` (the shipped files' records, merged keys and listing, as the build
:mod:`~camtool.presets.shipped` wrote them),
:mod:`~camtool.presets.summary` (a listing's line),
:mod:`~camtool.presets.database` (tiers, index, lookup),
:mod:`~camtool.presets.paths` (search order) and
:mod:`~camtool.presets.lensfun` (import of the lensfun database). numpy is
never imported here.
"""

from __future__ import annotations

from camtool.presets.database import Database, load_db, validate_file
from camtool.presets.errors import PresetFileError, PresetNotFound
from camtool.presets.kinds import (
    KINDS,
    Camera,
    Lens,
    Prescription,
    Preset,
    Scene,
    Sensor,
    normalize,
)

__all__ = [
    "KINDS",
    "Camera",
    "Database",
    "Lens",
    "Prescription",
    "Preset",
    "PresetFileError",
    "PresetNotFound",
    "Scene",
    "Sensor",
    "load_db",
    "normalize",
    "validate_file",
]
