"""films.yaml is parsed once per version: later runs read the checked cache entry, never a stale or forged one."""

from __future__ import annotations

import json
import os
from pathlib import Path

import pytest

from camtool.core import cache
from camtool.exposure import reciprocity


@pytest.fixture
def fresh_cache(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> Path:
    monkeypatch.setenv("XDG_CACHE_HOME", str(tmp_path))
    monkeypatch.delenv("CAMTOOL_NO_CACHE", raising=False)
    reciprocity.load_films.cache_clear()
    yield tmp_path / "camtool" / "films.json"
    reciprocity.load_films.cache_clear()


def _parsed_by_yaml() -> dict[str, reciprocity.Film]:
    from importlib.resources import files

    import yaml

    data = yaml.safe_load(files("camtool.exposure").joinpath("films.yaml").read_text(encoding="utf-8"))
    return {e["id"]: reciprocity.film_from_entry(e, data["source"]) for e in data["films"]}


def test_the_cached_table_gives_the_films_the_yaml_gives(fresh_cache: Path) -> None:
    first = reciprocity.load_films()
    assert fresh_cache.is_file()
    reciprocity.load_films.cache_clear()
    assert reciprocity.load_films() == first == _parsed_by_yaml()


def test_an_edited_entry_is_ignored_and_written_afresh(fresh_cache: Path) -> None:
    reciprocity.load_films()
    data = fresh_cache.read_bytes()
    fresh_cache.write_bytes(data.replace(b'"p":1.31', b'"p":1.99'))  # HP5 Plus's exponent, edited
    reciprocity.load_films.cache_clear()
    assert reciprocity.load_films()["ilford-hp5-plus"].p == 1.31
    assert fresh_cache.read_bytes() == data


def test_a_signed_entry_with_values_out_of_range_is_not_used(fresh_cache: Path) -> None:
    reciprocity.load_films()
    header, payload = fresh_cache.read_bytes().split(b"\n", 1)
    table = json.loads(payload)
    table["films"][0]["p"] = 40.0  # outside the exponent's range: film_from_entry refuses it
    source = json.loads(header)["source"]
    assert cache.write(os.fspath(fresh_cache), "films", source, cache.dumps(table))
    reciprocity.load_films.cache_clear()
    assert reciprocity.load_films() == _parsed_by_yaml()


def test_no_cache_is_written_when_caches_are_off(fresh_cache: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setenv("CAMTOOL_NO_CACHE", "1")
    assert reciprocity.load_films() == _parsed_by_yaml()
    assert not fresh_cache.exists()
