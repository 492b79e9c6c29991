"""T-stops on the depth-of-field commands: the f-number from the lens's transmittance, or the T-stop standing in."""

from __future__ import annotations

import math

import pytest
from cli_helpers import run, run_json

from camtool.exposure.ev import (
    T_STOP_ERROR_HIGH,
    T_STOP_ERROR_LOW,
    resolve_f_number,
    t_stop,
    transmittance_from_stops,
)

# Wikipedia, "F-number", section T-stop: "an f/2.0 lens with transmittance of 75 % has a T-stop of 2.3"
# (T = N/√τ = 2.0/√0.75 = 2.309...). The preset below is that worked example written as a lens.
WIKI_T = 2.0 / math.sqrt(0.75)
LENS_YAML = f"""lenses:
  - id: wiki-t-lens
    name: f/2.0 lens of 75 % transmittance (Wikipedia, F-number, T-stop)
    focal_length_mm: 50
    f_number_min: 2.0
    f_number_max: 22
    t_number_min: {WIKI_T!r}
"""


@pytest.fixture
def lens_file(tmp_path):
    path = tmp_path / "lens.yaml"
    path.write_text(LENS_YAML, encoding="utf-8")
    return str(path)


def test_transmittance_conversion_matches_the_published_example() -> None:
    assert round(t_stop(2.0, 0.75), 1) == 2.3  # Wikipedia, F-number: f/2.0 at 75 % is T2.3
    assert transmittance_from_stops(2.0, WIKI_T) == pytest.approx(0.75, rel=1e-12)
    choice = resolve_f_number(WIKI_T, True, 0.75)
    assert (choice.source, choice.t_stop) == ("transmittance", WIKI_T)
    assert choice.f_number == pytest.approx(2.0, rel=1e-12)
    # idigitalphoto.com, "T-number": f/4 at 50 % transmittance is T5.6 (4·√2 = 5.657)
    assert resolve_f_number(4 * math.sqrt(2), True, 0.5).f_number == pytest.approx(4.0, rel=1e-12)


def test_stand_in_error_bound_is_one_minus_root_tau() -> None:
    # N = T·√τ: for τ 0.9 and 0.7 the f-number is 1 − √τ below T
    assert abs(T_STOP_ERROR_LOW - 0.0513) < 5e-5 and abs(T_STOP_ERROR_HIGH - 0.1633) < 5e-5
    assert resolve_f_number(2.0, True).f_number == 2.0  # no τ: T stands in
    assert resolve_f_number(2.0, False) == (2.0, None, "typed", None)


def test_dof_with_the_lens_transmittance_uses_the_f_number(lens_file) -> None:
    (t_row,) = run_json("dof", "--lens", "wiki-t-lens", "--presets", lens_file, "-N", f"T{WIKI_T!r}", "-s", "3m")
    (f_row,) = run_json("dof", "--lens", "wiki-t-lens", "--presets", lens_file, "-N", "2", "-s", "3m")
    assert t_row["f_number"] == pytest.approx(2.0, rel=1e-12)
    assert (t_row["f_number_from"], t_row["t_stop"]) == ("transmittance", WIKI_T)
    for key in ("near_mm", "far_mm", "hyperfocal_mm"):  # the same f-number: the same depth of field
        assert t_row[key] == pytest.approx(f_row[key], rel=1e-9)
    assert "t_stop" not in f_row and "f_number_from" not in f_row  # f-numbers alone: the keys as before
    table = run("dof", "--lens", "wiki-t-lens", "--presets", lens_file, "-N", "T2.8", "-s", "3m")
    assert table.exit_code == 0 and "τ = 0.75" in table.output and "constant when stopped down" in table.output


def test_t_stop_stands_in_without_a_transmittance() -> None:
    (row,) = run_json("hyperfocal", "-f", "50", "-N", "T2.8")
    (plain,) = run_json("hyperfocal", "-f", "50", "-N", "2.8")
    assert (row["f_number"], row["t_stop"], row["f_number_from"]) == (2.8, 2.8, "t-stop")
    assert row["hyperfocal_mm"] == plain["hyperfocal_mm"]
    table = run("dof", "-f", "50", "-N", "T2", "-s", "3m")
    assert table.exit_code == 0
    assert "T-stops stand in for the f-number" in table.output and "5%–16% below T" in table.output
    # a cine preset with only its T-stop: still the stand-in
    (row,) = run_json("focus", "--lens", "cooke-s4i-50mm-t2", "-N", "T2", "-s", "3m")
    assert (row["f_number"], row["f_number_from"]) == (2.0, "t-stop")


def test_mixed_list_and_exact_stops() -> None:
    rows = run_json("dof", "-f", "50", "-N", "T2,4", "-s", "3m")
    assert [(r["f_number"], r["t_stop"], r["f_number_from"]) for r in rows] == [(2.0, 2.0, "t-stop"),
                                                                                 (4.0, None, "typed")]
    (row,) = run_json("dof", "-f", "50", "-N", "T5.6", "-s", "3m", "--exact-stops")
    assert row["f_number"] == pytest.approx(2 ** 2.5, rel=1e-12) and row["f_number_from"] == "t-stop"


def test_batch_cells_with_t_stops(tmp_path, lens_file) -> None:
    path = tmp_path / "rows.csv"
    path.write_text(f"f_number,distance\nT{WIKI_T!r},3m\n2,3m\n", encoding="utf-8")
    rows = run_json("dof", "--lens", "wiki-t-lens", "--presets", lens_file, "--batch", str(path))
    assert rows[0]["f_number"] == pytest.approx(2.0, rel=1e-12) and rows[0]["f_number_from"] == "transmittance"
    assert rows[0]["far_mm"] == pytest.approx(rows[1]["far_mm"], rel=1e-9)
    path.write_text("f_number,distance\nT2,3m\nT4,5m\nf/2.8,3m\n", encoding="utf-8")
    rows = run_json("dof", "-f", "50", "--batch", str(path))
    assert [(r["f_number"], r["t_stop"], r["f_number_from"]) for r in rows] == [
        (2.0, 2.0, "t-stop"), (4.0, 4.0, "t-stop"), (2.8, None, "typed")]
    first = rows[0]
    (plain,) = run_json("dof", "-f", "50", "-N", "2", "-s", "3m")
    assert first["far_mm"] == plain["far_mm"]  # the stand-in: T2 computed as f/2


def test_t_stop_below_the_lens_is_refused() -> None:
    result = run("dof", "--lens", "cooke-s4i-50mm-t2", "-N", "T1.4", "-s", "3m")
    assert result.exit_code == 2
    (line,) = [x for x in result.output.splitlines() if x.startswith("Error")]
    assert "'-N'" in line and "T1.4" in line and "from T2" in line
    result = run("exposure", "--lens", "cooke-s4i-50mm-t2", "-N", "T1.4", "--ev100", "12")
    assert result.exit_code == 2 and "from T2" in result.output
    result = run("dof", "-f", "50", "-N", "Tx", "-s", "3m")
    assert result.exit_code == 2 and "'-N'" in result.output


def test_exposure_uses_the_lens_widest_t_stop() -> None:
    (row,) = run_json("exposure", "--lens", "cooke-s4i-50mm-t2", "--ev100", "12")
    assert (row["f_number"], row["aperture_kind"]) == (2.0, "T")
    assert row["shutter_s"] == pytest.approx(2.0 ** 2 / 2 ** 12, rel=1e-12)  # t = N²/2^EV at ISO 100
    table = run("exposure", "--lens", "cooke-s4i-50mm-t2", "--ev100", "12")
    assert "T2: the widest T-stop of --lens cooke-s4i-50mm-t2" in table.output
    (row,) = run_json("exposure", "--lens", "cooke-s4i-50mm-t2", "--ev100", "12", "-t", "1/50", "--iso", "800")
    assert row["solved"] == "f_number"  # -N solved, not filled


def test_compose_with_a_teleconverter_keeps_the_t_stop_of_each_row() -> None:
    rows = run_json("compose", "--subject-size", "1.8m", "--fill", "0.8", "-N", "T2,4", "-f", "50,85",
                    "--teleconverter", "1.4")
    # the converter makes the lens k·f at k·N (k = 1.4): f/2.8 behind the T2 row
    assert {(round(r["f_number"], 9), r["t_stop"], r["f_number_from"]) for r in rows} == {
        (2.8, 2.0, "t-stop"), (5.6, None, "typed")}


# CinemaTechnic, "Lens Profiles – Carl Zeiss Standard Primes T2.1" (Jorge Diaz-Amador, updated 8 April 2020,
# http://cinematechnic.com/optics/arri_zeiss_standard_prime_f2_t21/): "35mm format f2.0 lenses", marked T2.1;
# the same page names the Zeiss High Speed (Super Speed) series f1.2 and T1.3.
STANDARD_PRIME = """lenses:
  - id: zeiss-standard-prime-50
    name: Zeiss Standard Prime 50mm (f/2.0, T2.1)
    focal_length_mm: 50
    f_number_min: 2.0
    t_number_min: 2.1
"""


def test_published_cine_lens_f_and_t_give_its_transmittance(tmp_path) -> None:
    assert transmittance_from_stops(2.0, 2.1) == pytest.approx(0.907, abs=5e-4)  # Standard Prime
    assert transmittance_from_stops(1.2, 1.3) == pytest.approx(0.852, abs=5e-4)  # High Speed
    path = tmp_path / "lens.yaml"
    path.write_text(STANDARD_PRIME, encoding="utf-8")
    (row,) = run_json("dof", "--lens", "zeiss-standard-prime-50", "--presets", str(path), "-N", "T2.8", "-s", "3m")
    assert row["f_number"] == pytest.approx(2.8 * 2.0 / 2.1, rel=1e-12)  # N = T·√τ = T·(N₀/T₀): f/2.667
    assert row["f_number_from"] == "transmittance"
    (wide,) = run_json("dof", "--lens", "zeiss-standard-prime-50", "--presets", str(path), "-N", "T2.1", "-s", "3m")
    assert wide["f_number"] == pytest.approx(2.0, rel=1e-12)  # wide open: the published f-number


def test_t_stop_cells_of_a_batch_give_the_rows_the_options_give(tmp_path) -> None:
    """Per-frame camera data (T-stop cells) stays a column at a time and answers as the options do, row for row."""
    import json

    from tests.cli_helpers import run

    source = tmp_path / "frames.csv"
    source.write_text("frame,distance,focal_length,f_number\n1,3m,50,T2\n2,4.5m,75,T2.8\n3,10m,50,f/4\n")
    batch = json.loads(run("dof", "--batch", str(source), "--camera", "arri-alexa-35", "--format", "json").stdout)
    for row, (s, f, n) in zip(batch, [("3m", "50", "T2"), ("4.5m", "75", "T2.8"), ("10m", "50", "f/4")]):
        alone = json.loads(run("dof", "-s", s, "-f", f, "-N", n, "--camera", "arri-alexa-35", "--format",
                               "json").stdout)[0]
        # the batch's keys are every row's: an f-number row among T-stop rows has t_stop null, "typed"
        assert {k: row[k] for k in alone} == alone
        assert row["t_stop"] == alone.get("t_stop") and row["f_number_from"] == alone.get("f_number_from", "typed")
