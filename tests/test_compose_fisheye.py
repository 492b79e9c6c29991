"""compose with a fisheye: the subject's edges where the mapping puts them, and the angles and fields fov gives."""

from __future__ import annotations

import math

import pytest
from cli_helpers import run, run_json
from conftest import point_xdg_at, presets_home
from hypothesis import given, settings
from hypothesis import strategies as st

from camtool.core.errors import DomainError
from camtool.geometry.projection import PROJECTIONS, fill_magnification, image_height_mm

FISHEYES = [p for p in PROJECTIONS if p != "rectilinear"]


@pytest.fixture(autouse=True)
def isolated(request, monkeypatch, shared_presets_home):
    root = presets_home(request, shared_presets_home, "tmp_path")
    point_xdg_at(root, monkeypatch)
    return root


@settings(max_examples=300, deadline=None)
@given(projection=st.sampled_from(FISHEYES), f=st.floats(4.0, 20.0), size=st.floats(50.0, 20000.0),
       fill=st.floats(0.05, 1.0), frame=st.floats(10.0, 40.0))
def test_the_subjects_edges_image_where_the_fill_puts_them(projection: str, f: float, size: float, fill: float,
                                                           frame: float) -> None:
    try:
        m = fill_magnification(f, size, fill, frame, projection)
    except DomainError as error:  # a subject whose edges would lie at 90° or beyond, or within f
        assert error.param == "fill"
        return
    u = f * (1.0 + 1.0 / m)  # the thin lens at magnification m
    edge = math.degrees(math.atan(size / 2.0 / u))
    assert image_height_mm(f * (1.0 + m), edge, projection) == pytest.approx(fill * frame / 2.0, rel=1e-12)


def test_rectilinear_gives_the_fill_over_the_subject() -> None:
    assert fill_magnification(50.0, 1800.0, 0.8, 24.0, "rectilinear") == pytest.approx(0.8 * 24.0 / 1800.0, rel=1e-14)


@pytest.mark.parametrize("projection", FISHEYES)
def test_compose_gives_the_angles_and_fields_fov_gives_at_its_distance(projection: str) -> None:
    lens = ["-f", "10,15", "--projection", projection]
    rows = run_json("compose", "--subject-size", "1.8m", "--fill", "0.6", *lens)
    for row in rows:
        (seen,) = run_json("fov", "-f", str(row["focal_length_mm"]), "--projection", projection,
                           "-s", f"{row['distance_mm']!r}mm")
        for key in ("horizontal_deg", "vertical_deg", "field_width_mm", "field_height_mm", "magnification"):
            assert row[key] == (None if seen[key] is None else pytest.approx(seen[key], rel=1e-9)), key  # None: ∞
    assert rows[0]["vertical_deg"] > rows[1]["vertical_deg"]  # the shorter fisheye sees more


def test_a_fisheye_presets_projection_is_used_and_named() -> None:
    lens = "sigma-15mm-f1.4-dg-dn-diagonal-fisheye-art"
    (row,) = run_json("compose", "--subject-size", "1.8m", "--fill", "0.8", "--lens", lens)
    (typed,) = run_json("compose", "--subject-size", "1.8m", "--fill", "0.8", "-f", "15", "--projection", "equisolid")
    assert row == typed
    (rectilinear,) = run_json("compose", "--subject-size", "1.8m", "--fill", "0.8", "-f", "15")
    assert row["distance_mm"] < rectilinear["distance_mm"] and row["horizontal_deg"] > rectilinear["horizontal_deg"]
    table = run("compose", "--subject-size", "1.8m", "--fill", "0.8", "--lens", lens, env={"COLUMNS": "200"})
    assert table.exit_code == 0 and "equisolid projection" in table.stdout


def test_a_fill_no_flat_subject_reaches_is_one_line() -> None:
    # an 8 mm orthographic fisheye holds r ≤ f: a subject filling the 36 mm width would need its edges at 90°
    result = run("compose", "--subject-size", "1m", "--fill", "1", "--fill-axis", "width", "-f", "8",
                 "--projection", "orthographic")
    assert result.exit_code == 2 and result.stderr.count("\n") == 1 and "--fill" in result.stderr


@pytest.mark.parametrize("projection", FISHEYES)
def test_the_api_composition_is_the_commands_at_a_magnification(projection: str) -> None:
    import camtool

    (row,) = run_json("compose", "-m", "0.02", "-f", "12", "--projection", projection)
    api = camtool.composition(12, 0.02, 36, 24, projection=projection)
    for key in ("distance_mm", "magnification", "horizontal_deg", "vertical_deg", "field_width_mm", "field_height_mm"):
        value = getattr(api, key)
        assert row[key] == (None if math.isinf(value) else value), key  # None: ∞ in JSON
