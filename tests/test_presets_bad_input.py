"""Bad preset files: each problem is one line naming the file, the line, the preset and the key."""

from __future__ import annotations

import time

import pytest
from conftest import point_xdg_at, presets_home

from camtool.presets import PresetFileError, load_db, validate_file


@pytest.fixture(autouse=True)
def isolated(request, monkeypatch, shared_presets_home):
    """Point every XDG directory away from the user's own files: into tmp_path for a test that asks for
    `isolated` (it looks at the cache), else into directories shared by the tests that only read the shipped
    presets (parsed once per session); the bad files the others write in tmp_path are given as --presets."""
    root = presets_home(request, shared_presets_home, "isolated")
    point_xdg_at(root, monkeypatch)
    return root


def load_error(tmp_path, text: str) -> tuple[str, PresetFileError]:
    path = tmp_path / "bad.yaml"
    path.write_text(text, encoding="utf-8")
    with pytest.raises(PresetFileError) as caught:
        load_db(extra_files=(path,))
    message = str(caught.value)
    assert "\n" not in message and message.startswith(str(path))
    assert validate_file(path), "validate_file must list the same problem"
    return str(path), caught.value


def test_yaml_syntax_error_names_file_and_line(tmp_path):
    path, error = load_error(tmp_path, "sensors:\n  - id: a\n    width_mm: [1, 2\n    height_mm: 3\n")
    assert error.line == 4
    assert str(error).startswith(f"{path}:4: YAML error:")


def test_python_object_tag_is_refused(tmp_path):
    _path, error = load_error(tmp_path, "sensors:\n  - !!python/object/apply:os.system ['echo pwned']\n")
    assert error.line == 2 and "YAML error" in str(error) and "python/object" in str(error)


def test_alias_bomb_is_refused_quickly(tmp_path):
    lines = ['a: &a ["x","x","x","x","x","x","x","x","x"]']
    for level in range(1, 12):
        prev = chr(ord("a") + level - 1)
        name = chr(ord("a") + level)
        lines.append(f"{name}: &{name} [{', '.join([f'*{prev}'] * 9)}]")
    lines.append("sensors: *l")
    start = time.perf_counter()
    _path, error = load_error(tmp_path, "\n".join(lines) + "\n")
    assert time.perf_counter() - start < 5
    assert "too many nested aliases" in str(error)


def test_recursive_alias_is_refused(tmp_path):
    _path, error = load_error(tmp_path, "sensors: &s\n  - *s\n")
    assert "refers to the node that contains it" in str(error)


def test_unknown_key_says_did_you_mean(tmp_path):
    path, error = load_error(tmp_path, "sensors:\n  - id: tiny\n    width_mm: 5\n    hieght_mm: 4\n")
    assert str(error).startswith(f"{path}:4: sensor 'tiny': hieght_mm: unknown key (did you mean height_mm?)")
    assert (error.line, error.preset_id, error.key, error.kind) == (4, "tiny", "hieght_mm", "sensor")


def test_unknown_section_says_did_you_mean(tmp_path):
    _path, error = load_error(tmp_path, "lens:\n  - id: x\n    focal_length_mm: 50\n")
    assert "unknown section (did you mean lenses?)" in str(error) and error.line == 1


def test_string_where_a_number_belongs(tmp_path):
    path, error = load_error(tmp_path, "lenses:\n  - id: l\n    focal_length_mm: 50mm\n")
    assert str(error) == (f"{path}:3: lens 'l': focal_length_mm: expected a number, got the string '50mm' "
                          "(write a plain number in mm; units are not allowed here)")


def test_negative_width(tmp_path):
    path, error = load_error(tmp_path, "sensors:\n  - id: neg\n    width_mm: -36\n    height_mm: 24\n")
    assert str(error) == f"{path}:3: sensor 'neg': width_mm: must be > 0 mm, got -36"


@pytest.mark.parametrize(
    ("entry", "key", "words"),
    [
        ("  - id: s\n    width_mm: 0\n    height_mm: 1\n", "width_mm", "must be > 0"),
        ("  - id: s\n    width_mm: .nan\n    height_mm: 1\n", "width_mm", "NaN"),
        ("  - id: s\n    width_mm: .inf\n    height_mm: 1\n", "width_mm", "must be > 0"),
        ("  - id: s\n    width_mm: true\n    height_mm: 1\n", "width_mm", "expected a number"),
        ("  - id: Big Sensor\n    width_mm: 1\n    height_mm: 1\n", "id", "try 'big-sensor'"),
        ("  - id: s\n    width_mm: 1\n", "height_mm", "is required"),
        ("  - id: s\n    aliases: [[x]]\n    width_mm: 1\n    height_mm: 1\n", "aliases", "every alias must be text"),
    ],
)
def test_sensor_field_errors(tmp_path, entry, key, words):
    _path, error = load_error(tmp_path, "sensors:\n" + entry)
    assert error.key == key and words in str(error)


@pytest.mark.parametrize(
    ("entry", "key", "words"),
    [
        ("focal_min_mm: 70\n    focal_max_mm: 24", "focal_max_mm", "must be >= focal_min_mm"),
        ("focal_length_mm: 50\n    focal_min_mm: 24", "focal_length_mm", "not both"),
        ("f_number_min: 1.8", "focal_length_mm", "is required"),
        ("focal_length_mm: 50\n    f_number_min: 8\n    f_number_max: 2", "f_number_max", "widest aperture"),
        ("focal_length_mm: 50\n    hiatus_mm: x", "hiatus_mm", "expected a number"),
    ],
)
def test_lens_field_errors(tmp_path, entry, key, words):
    _path, error = load_error(tmp_path, f"lenses:\n  - id: l\n    {entry}\n")
    assert error.key == key and words in str(error)


def test_prescription_needs_exactly_one_stop(tmp_path):
    text = ("prescriptions:\n  - id: p\n    surfaces:\n"
            "      - {radius_mm: 50, thickness_mm: 5, n: 1.5}\n"
            "      - {radius_mm: inf, thickness_mm: 90, n: 1.0}\n")
    _path, error = load_error(tmp_path, text)
    assert error.key == "surfaces" and "exactly one surface must have stop: true (found none)" in str(error)


def test_prescription_surface_errors_name_the_surface(tmp_path):
    text = ("prescriptions:\n  - id: p\n    surfaces:\n"
            "      - {radius_mm: 0, thickness_mm: 5, n: 1.5, stop: true}\n")
    _path, error = load_error(tmp_path, text)
    assert "surface 1, radius_mm: must not be 0" in str(error)


def test_scene_distance_needs_a_length(tmp_path):
    _path, error = load_error(tmp_path, "scenes:\n  - id: s\n    distance: three metres\n")
    assert error.key == "distance" and "is not a length" in str(error)


def test_every_problem_is_listed(tmp_path):
    path = tmp_path / "many.yaml"
    path.write_text("sensors:\n  - id: a\n    width_mm: -1\n    height_mm: x\n  - id: b\n    wide: 3\n",
                    encoding="utf-8")
    problems = validate_file(path)
    assert len(problems) == 5
    assert all(p.startswith(f"{path}:") for p in problems)
    with pytest.raises(PresetFileError, match=r"and 4 more problems; camtool presets validate"):
        load_db(extra_files=(path,))


def test_missing_and_empty_files(tmp_path):
    missing = tmp_path / "nope.yaml"
    with pytest.raises(PresetFileError, match="cannot read the file"):
        load_db(extra_files=(missing,))
    assert len(validate_file(missing)) == 1
    empty = tmp_path / "empty.yaml"
    empty.write_text("# nothing\n", encoding="utf-8")
    with pytest.raises(PresetFileError, match="the file is empty"):
        load_db(extra_files=(empty,))


def test_nothing_is_cached_for_a_bad_file(tmp_path, isolated):
    load_error(tmp_path, "sensors:\n  - id: neg\n    width_mm: -36\n    height_mm: 24\n")
    cache = isolated / "xdg_cache_home" / "camtool" / "presets"
    assert not list(cache.glob("bad.yaml-*"))
