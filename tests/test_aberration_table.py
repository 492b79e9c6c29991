"""The aberration estimate of a prescription: one table over a grid of f-numbers, cached on disk.

A single-scene command with a prescription imports numpy and traces rays only when its model is
``raytrace`` (or the prescription's table is not yet cached); continuous f-numbers are
interpolated in the table, so they cost no more than a few.
"""

from __future__ import annotations

import json
import math
import os
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest
import yaml

from camtool.dof import auto
from camtool.optics.prescription import prescription_from_mapping

DATA = Path(__file__).parent / "data" / "prescriptions"


def load(name):
    return prescription_from_mapping(yaml.safe_load((DATA / f"{name}.yaml").read_text()), name)


def numpy_imported(model: str, env: dict[str, str]) -> bool:
    code = (
        "import sys\n"
        f"sys.argv = ['camtool', 'dof', '--lens', 'dgauss100-lens', '-N', '5.6', '-s', '3m', '--format', 'json',"
        f" '--model', '{model}']\n"
        "from camtool.cli import main\n"
        "try:\n    main()\nexcept SystemExit as done:\n    assert not done.code, done.code\n"
        "print('numpy' in sys.modules, file=sys.stderr)\n"
    )
    run = subprocess.run([sys.executable, "-c", code], env=env, capture_output=True, text=True, check=True)
    return run.stderr.strip().splitlines()[-1] == "True"


def test_a_single_scene_with_a_prescription_imports_numpy_only_for_the_ray_trace(tmp_path):
    env = {**os.environ, "XDG_CACHE_HOME": str(tmp_path)}
    numpy_imported("auto", env)  # the first command with this prescription calibrates and caches it
    assert list((tmp_path / "camtool" / "aberrations").glob("*.json"))
    for model in ("auto", "paraxial", "thin", "thick"):
        assert not numpy_imported(model, env), model
    assert numpy_imported("raytrace", env)


def test_the_disk_cache_holds_what_a_fresh_calibration_computes(tmp_path, monkeypatch):
    monkeypatch.setenv("XDG_CACHE_HOME", str(tmp_path))
    monkeypatch.delenv("CAMTOOL_NO_CACHE", raising=False)
    lens = load("telecentric36")
    computed = auto._compute_table(lens)
    source = auto._source(lens)
    path = auto._cache_path(source)
    auto._write_table(path, source, computed)
    assert auto._read_table(path, source, lens) == computed  # floats survive JSON exactly (shortest repr)
    payload = Path(path).read_bytes().split(b"\n", 1)[1]
    assert json.loads(payload)["f_numbers"][0] == 1.0
    assert auto._read_table(path, auto._source(load("dgauss100")), lens) is None  # a file of other content is not used
    Path(path).write_text("{not json")
    assert auto._read_table(path, source, lens) is None  # a damaged file is recomputed, not trusted


def test_the_cache_key_follows_the_prescription_content(tmp_path, monkeypatch):
    monkeypatch.setenv("XDG_CACHE_HOME", str(tmp_path))
    lens = load("dgauss100")
    data = yaml.safe_load((DATA / "dgauss100.yaml").read_text())
    data["surfaces"][0]["radius_mm"] *= 1.0000001
    changed = prescription_from_mapping(data, "dgauss100")
    assert auto._cache_path(auto._source(lens)) != auto._cache_path(auto._source(changed))
    renamed = prescription_from_mapping({**yaml.safe_load((DATA / "dgauss100.yaml").read_text()), "name": "other"})
    assert auto._cache_path(auto._source(lens)) == auto._cache_path(auto._source(renamed))


@pytest.mark.parametrize("name", ["dgauss100", "telephoto127", "cellphone", "telecentric36", "wideangle17"])
def test_interpolated_f_numbers_track_a_direct_calibration(name):
    # the share at an f-number between grid points against the same calibration run at exactly that
    # f-number: within 25 % of the share or 0.002 absolute (the estimate itself is good to about 2x)
    lens = load(name)
    auto.aberration_table(lens)  # the grid table (cached)
    design = lens.f_number
    for n in (design * 1.19, design * 1.6, 9.5, 18.0):
        direct_grid = auto._GRID_F_NUMBERS
        try:
            auto._GRID_F_NUMBERS = (n, n * 1.0001)
            exact = auto._compute_table(lens)[1][0]
        finally:
            auto._GRID_F_NUMBERS = direct_grid
        for m, share, _shift in exact:
            estimate = auto.aberration_share(lens, n, m)
            assert estimate == pytest.approx(share, rel=0.25, abs=0.002), (n, m)


def test_scalar_and_array_shares_agree():
    lens = load("dgauss100")
    n = np.array([2.0, 2.2, 3.3, 5.6, 7.77, 16.0, 100.0])[:, None]
    m = np.array([0.0, 0.02, 0.2, 0.9, math.inf])[None, :]
    many = auto.aberration_share(lens, n, m)
    for i, j in np.ndindex(many.shape):
        assert many[i, j] == pytest.approx(auto.aberration_share(lens, float(n[i, 0]), float(m[0, j])), rel=1e-12)


# --- the tables shipped with the package (camtool/dof/aberrations.json, python -m camtool.presets.shipped) ---------


def _shipped_file() -> dict:
    document = json.loads((Path(auto.__file__).parent / auto.SHIPPED_TABLES).read_text(encoding="utf-8"))
    assert all(isinstance(text, str) for text in document["tables"].values())  # each table a JSON text of its own
    return {**document, "tables": {source: json.loads(text) for source, text in document["tables"].items()}}


def test_the_shipped_tables_are_those_of_the_shipped_prescriptions_computed_afresh():
    from camtool.presets import shipped as tables

    shipped = _shipped_file()
    lenses = tables.shipped_prescriptions()
    assert len(lenses) >= 5
    # one table per shipped prescription, keyed by its content digest: an edited prescription is not current
    assert sorted(shipped["tables"]) == sorted(auto._source(lens) for _name, lens in lenses), \
        "camtool/dof/aberrations.json is out of date: run python -m camtool.presets.shipped"
    assert shipped["version"] == auto._TABLE_VERSION
    for name, lens in lenses:
        grid, rows = auto._compute_table(lens)  # a fresh ray-traced calibration, not read from anywhere
        table = shipped["tables"][auto._source(lens)]
        assert shipped["prescriptions"][auto._source(lens)] == name
        assert table["f_numbers"] == list(grid)
        for shipped_row, row in zip(table["table"], rows, strict=True):
            assert [entry[0] for entry in shipped_row] == [entry[0] for entry in row]  # the magnifications
            for shipped_entry, entry in zip(shipped_row, row, strict=True):  # the shares the table keeps
                assert list(shipped_entry[1:]) == pytest.approx(list(entry[1:]), rel=1e-9, abs=1e-15), name
        assert auto._shipped_table(auto._source(lens), lens) is not None  # passes the same checks as a cache entry


def _fresh(monkeypatch, tmp_path, shipped: dict) -> None:
    monkeypatch.setenv("XDG_CACHE_HOME", str(tmp_path))
    monkeypatch.delenv("CAMTOOL_NO_CACHE", raising=False)
    monkeypatch.setattr(auto, "_shipped", lambda: shipped)
    auto.aberration_table.cache_clear()


@pytest.mark.parametrize("poison", ["a negative share", "NaN", "another grid", "other magnifications", "not a table",
                                    "a string share", "rows missing", "a JSON text cut short"])
def test_a_shipped_table_that_fails_a_check_is_computed_afresh(poison, monkeypatch, tmp_path):
    from camtool.presets import shipped as tables

    _name, lens = next((n, p) for n, p in tables.shipped_prescriptions() if n == "dgauss100.yaml")
    source = auto._source(lens)
    table = json.loads(json.dumps(_shipped_file()["tables"][source]))
    if poison == "a negative share":
        table["table"][3][0][1] = -0.5
    elif poison == "NaN":
        table["table"][3][0][1] = math.nan
    elif poison == "another grid":
        table["f_numbers"][2] *= 1.01
    elif poison == "other magnifications":
        table["table"][0][1][0] += 0.01
    elif poison == "not a table":
        table = [1, 2, 3]
    elif poison == "a string share":
        table["table"][0][0][1] = "0.1"
    elif poison == "a JSON text cut short":  # as the file holds each table: a text, parsed when it is used
        table = json.dumps(table)[:-7]
    else:
        table["table"] = table["table"][:-1]
    _fresh(monkeypatch, tmp_path, {source: table})
    try:
        assert auto._shipped_table(source, lens) is None
        assert auto.aberration_table(lens) == auto._compute_table(lens)
    finally:
        auto.aberration_table.cache_clear()


def test_a_sound_shipped_table_is_used_without_tracing_and_cached(monkeypatch, tmp_path):
    from camtool.presets import shipped as tables

    _name, lens = next((n, p) for n, p in tables.shipped_prescriptions() if n == "telephoto127.yaml")
    source = auto._source(lens)
    shipped = _shipped_file()["tables"]
    _fresh(monkeypatch, tmp_path, shipped)

    def refuse(_lens):
        raise AssertionError("traced rays for a shipped prescription")

    monkeypatch.setattr(auto, "_compute_table", refuse)
    try:
        grid, rows = auto.aberration_table(lens)
        assert list(grid) == shipped[source]["f_numbers"]
        # written to the disk cache as a computed table is, bound to the same content digest
        assert auto._read_table(auto._cache_path(source), source, lens) == (grid, rows)
    finally:
        auto.aberration_table.cache_clear()


def test_a_first_command_with_a_shipped_prescription_imports_no_numpy(tmp_path):
    env = {**os.environ, "XDG_CACHE_HOME": str(tmp_path)}
    assert not numpy_imported("auto", env)  # every cache empty: the shipped table, no ray trace
    assert list((tmp_path / "camtool" / "aberrations").glob("*.json"))
