"""Checks shared by the test modules of the shipped phones: each module against the pages its entry quotes, its
focal length against the 35 mm equivalent, and each phone as its main module."""

from __future__ import annotations

import math
from pathlib import Path

import pytest
import yaml
from cli_helpers import run_json

from camtool.presets import load_db

ROOT = Path(__file__).resolve().parent.parent
FULL_FRAME_DIAGONAL_MM = math.hypot(36.0, 24.0)


def phone_lens_records() -> dict[str, dict]:
    text = (ROOT / "lens_db" / "phone-lenses.yaml").read_text(encoding="utf-8")
    return {record["id"]: record for record in yaml.safe_load(text)["lenses"]}


def camera_records() -> dict[str, dict]:
    text = (ROOT / "lens_db" / "cameras.yaml").read_text(encoding="utf-8")
    return {record["id"]: record for record in yaml.safe_load(text)["cameras"]}


def check_module_against_its_pages(lens_id: str, widest: float | None, smallest: float | None, equivalent: float,
                                   stated: bool, sensor_id: str, quotes: list[str], pages: list[str],
                                   never: tuple[str, ...] = ()) -> None:
    """The module's apertures, sensor and equivalent as its pages print them, each quote and page in its source
    (and none of ``never``)."""
    lens = load_db().lens(lens_id)
    record = phone_lens_records()[lens_id]
    assert (lens.f_number_min, lens.f_number_max) == (widest, smallest)
    assert lens.sensor_id == sensor_id
    assert lens.mount == "fixed lens" and lens.category == "phone"
    # an equivalent is a key of the entry only where the maker's own figure is printed (lens_db/README.md)
    assert record.get("equivalent_focal_length_mm") == (equivalent if stated else None)
    source = " ".join(record["source"].split())
    for quote in quotes:
        assert quote in source, quote
    for page in pages:
        assert page in source, page
    for word in never:
        assert word not in source, word


def check_focal_length_gives_the_equivalent(lens_id: str, sensor_id: str, equivalent: float, rel: float,
                                            said: str) -> None:
    """focal length × crop factor (full-frame diagonal over the sensor's) is the printed equivalent, within ``rel``
    (the rounding of the stored focal length), and the notes say the focal length is derived (``said``)."""
    db = load_db()
    lens = db.lens(lens_id)
    diagonal = db.sensor(sensor_id).diagonal_mm
    assert lens.focal_min_mm * FULL_FRAME_DIAGONAL_MM / diagonal == pytest.approx(equivalent, rel=rel)
    notes = " ".join(lens.notes.split())
    assert lens.approximate and "focal_length_mm derived from" in notes and said in notes


def check_fov_gives_the_equivalent(phone: str, lens_id: str, equivalent: float, tolerance: float) -> dict:
    """``camtool fov`` on the phone (and the module, when not its main one) gives the module's focal length and,
    within ``tolerance`` mm, its equivalent; the row, for more checks."""
    db = load_db()
    args = ("fov", "--camera", phone) if db.camera(phone).lens_id == lens_id else (
        "fov", "--camera", phone, "--lens", lens_id)
    (row,) = run_json(*args)
    assert row["focal_length_mm"] == db.lens(lens_id).focal_min_mm
    assert row["equivalent_focal_length_mm"] == pytest.approx(equivalent, abs=tolerance)
    return row


def check_phone_is_its_main_module(phone: str) -> None:
    """The phone's body is its main module's: the same sensor, no image size no page gives, a cited page."""
    db = load_db()
    body = db.camera(phone)
    assert body.category == "phone" and body.mount == "fixed lens" and body.approximate
    assert body.lens_id == f"{phone}-main"
    main = db.sensor(db.lens(body.lens_id).sensor_id)
    assert (body.sensor.width_mm, body.sensor.height_mm) == (main.width_mm, main.height_mm)
    # the recorded image size no page gives is left out, and the notes say the size is derived
    assert body.pixels_w is None and body.pixels_h is None
    assert "derived, not published" in body.notes.lower()
    assert "https://" in camera_records()[phone]["source"]
