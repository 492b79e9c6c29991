"""Retail lenses with a patent prescription: the transcriptions against the patents' own figures.

Each prescription in lens_db/prescriptions/ that belongs to a retail lens is a numerical
example of a patent. The patent states its focal length, back focus, total length and a
close-focus state (gaps and magnification) next to the surface table; a paraxial trace of
the transcribed surfaces must reproduce them. That is an independent check of the
transcription: a wrong radius, thickness or index moves the focal length or the back
focus, a wrong focusing gap the close-focus magnification.
"""

from __future__ import annotations

from typing import Any

import pytest
from cli_helpers import run, run_json

from camtool.core.record import replace
from camtool.dof.realray import real_focus
from camtool.optics.paraxial import first_order, paraxial_trace
from camtool.presets import load_db

# The patents' stated values, as both transcriptions named in each prescription's `source`
# print them (each a copy of the patent's table of various data).
PATENTS: dict[str, dict[str, Any]] = {
    # US 2019/0265441 A1, numerical example 2: f 51.10, Fno 1.25, Bf 14.60, total length 111.01;
    # close-focus state: d19 16.11, object 274.83 mm in front of surface 1 (400 mm from the
    # image), magnification -0.19. Printed to 0.01 mm and 0.01.
    "canon-rf50-f1.2": {
        "lens": "canon-rf-50mm-f1.2l-usm", "design": "canon-rf-50mm-f1.2l-usm-patent", "efl": 51.10, "f_number": 1.25, "total": 111.01,
        "back_focus": 14.60, "last_lens_surface": 25, "tol": 0.005,
        "close_gaps": {19: 16.11}, "close_object": 274.83, "close_m": -0.19, "close_m_tol": 0.005,
        "close_image": 14.60, "nominal_mm": 50.0,
    },
    # WO 2019/220618 A1, Table 9: f 51.60, FNO 1.85, BF 13.100 (surface 24 to the image, the
    # 1.6 mm filter plate included), BFa 12.554, TL 92.330; close-focus state: D12 2.409,
    # D19 14.267, D0 307.67 (400 mm from the image), beta -0.1565, D26 1.000.
    "nikon-z50-f1.8": {
        "lens": "nikon-z-50mm-f1.8-s", "design": "nikon-z-50mm-f1.8-s-patent", "efl": 51.60, "f_number": 1.85, "total": 92.330,
        "back_focus": 13.100, "back_focus_air": 12.554, "last_lens_surface": 24, "tol": 0.0005,
        "close_gaps": {12: 2.409, 19: 14.267}, "close_object": 307.67, "close_m": -0.1565,
        "close_m_tol": 0.00005, "close_image": 1.000, "nominal_mm": 50.0,
    },
}


def optics(prescription_id: str) -> Any:
    return load_db().prescription(prescription_id).optics


@pytest.mark.parametrize("pid", sorted(PATENTS))
def test_focal_length_back_focus_and_length_reproduce_the_patent(pid):
    patent, lens = PATENTS[pid], optics(pid)
    fo = first_order(lens)
    # EFL printed to 0.01 mm in both patents: half a unit of the last digit.
    assert fo.efl_mm == pytest.approx(patent["efl"], abs=0.005)
    # Back focus from the last lens surface: through the filter plate where there is one.
    last = patent["last_lens_surface"]
    to_image = fo.z_f_prime_mm - lens.vertices_mm[last - 1]
    assert to_image == pytest.approx(patent["back_focus"], abs=patent["tol"])
    if "back_focus_air" in patent:
        # Air-equivalent: the plate counts t/n. The patent's 12.554 is its figure for
        # 10.5 + 1.6/1.5168 + 1.000 = 12.5549, truncated, hence 0.001.
        air = sum(s.thickness_mm / s.n for s in lens.surfaces[last - 1:-1]) + fo.bfd_mm
        assert air == pytest.approx(patent["back_focus_air"], abs=0.001)
    # Total length: first vertex to the image.
    assert fo.z_f_prime_mm == pytest.approx(patent["total"], abs=patent["tol"])
    # The file's last thickness is the paraxial back focus (the header's convention).
    assert lens.surfaces[-1].thickness_mm == pytest.approx(fo.bfd_mm, abs=1e-9)
    assert lens.f_number == patent["f_number"]


def close_state(pid: str) -> tuple[float, float, float]:
    """Paraxial magnification, image distance after the last vertex and lens length of the patent's close-focus state."""
    patent, lens = PATENTS[pid], optics(pid)
    surfaces = list(lens.surfaces)
    for number, gap in patent["close_gaps"].items():
        surfaces[number - 1] = replace(surfaces[number - 1], thickness_mm=gap)
    moved = replace(lens, surfaces=tuple(surfaces))
    # A ray from the axial object point at unit slope reaches surface 1 at height d0.
    y, nu = paraxial_trace(moved, patent["close_object"], 1.0)
    return 1.0 / nu, -y / nu, moved.vertices_mm[-1]  # m = n0·u0 / (nK·uK); image where the ray meets the axis


@pytest.mark.parametrize("pid", sorted(PATENTS))
def test_close_focus_state_reproduces_the_patent(pid):
    patent = PATENTS[pid]
    m, image, length = close_state(pid)
    assert m == pytest.approx(patent["close_m"], abs=patent["close_m_tol"])
    # The image stays on the sensor: the focusing gaps alone move the focus.
    assert image == pytest.approx(patent["close_image"], abs=patent["tol"])
    # The close-focus state lies at the maker's closest focus (0.4 m from the sensor for both,
    # as the presets' sources give it): the patents' examples are the production focusing range.
    closest = load_db().lens(patent["lens"]).min_focus_mm
    assert closest == 400.0
    assert patent["close_object"] + length + image == pytest.approx(closest, abs=0.01)


@pytest.mark.parametrize("pid", sorted(PATENTS))
def test_focal_length_matches_the_makers_nominal_one(pid):
    patent = PATENTS[pid]
    preset = load_db().lens(patent["lens"])
    assert preset.focal_length_mm == patent["nominal_mm"]
    # Makers name a lens by a rounded focal length (the examples are 2.2 % and 3.2 % longer);
    # 5 % would still catch an example read at the wrong scale or from the wrong table.
    assert abs(first_order(optics(pid)).efl_mm / patent["nominal_mm"] - 1.0) < 0.05


@pytest.mark.parametrize("pid", sorted(PATENTS))
def test_preset_pupil_magnification_and_hiatus_are_the_prescriptions(pid):
    # The lens as sold carries the patent design's P and δ (at infinity focus) for the thick model,
    # and keeps its own focal length and internal-focus model; the design preset carries the prescription.
    patent = PATENTS[pid]
    preset, design = load_db().lens(patent["lens"]), load_db().lens(patent["design"])
    assert preset.prescription is None and design.prescription_id == pid
    fo = first_order(design.prescription)
    assert preset.pupil_magnification == pytest.approx(fo.pupil_magnification, abs=0.0005)
    assert preset.hiatus_mm == pytest.approx(fo.hiatus_mm, abs=0.005)
    assert design.focal_length_mm == pytest.approx(fo.efl_mm, rel=1e-12)
    assert design.f_number_min == patent["f_number"]


def test_the_canon_close_focus_magnification_is_the_patents():
    # US 2019/0265441 A1 example 2 states -0.19 at its close-focus state, 400 mm from the image.
    assert load_db().lens("canon-rf-50mm-f1.2l-usm").max_magnification == pytest.approx(-close_state("canon-rf50-f1.2")[0],
                                                                                         abs=0.005)


# Unit extension against the patent's own focusing, at the closest focus (0.4 m from the
# sensor): the relative differences the design presets' notes state (-4 % and +23 %).
@pytest.mark.parametrize(("pid", "stated"), [("canon-rf50-f1.2", -0.04), ("nikon-z50-f1.8", 0.23)])
def test_unit_extension_close_focus_difference_is_the_one_the_notes_state(pid, stated):
    patent = PATENTS[pid]
    lens = optics(pid)
    unit = real_focus(lens, patent["f_number"], 400.0).magnification
    patent_m = -close_state(pid)[0]
    assert (unit / patent_m - 1.0) == pytest.approx(stated, abs=0.005)
    notes = load_db().lens(patent["design"]).notes
    assert f"{round(abs(stated) * 100):d} %" in notes and f"{unit:.3f}x" in notes


@pytest.mark.parametrize("pid", sorted(PATENTS))
@pytest.mark.parametrize("model", ["raytrace", "paraxial", "auto"])
def test_dof_runs_with_the_patent_design(pid, model):
    design = PATENTS[pid]["design"]
    efl = first_order(optics(pid)).efl_mm
    rows = run_json("dof", "--lens", design, "-N", "2", "-s", "3m", "--model", model)
    assert len(rows) == 1
    row = rows[0]
    assert model == "auto" or row["model"] == model
    # The design computes with the patent example's focal length.
    assert row["focal_length_mm"] == pytest.approx(efl, rel=1e-12)
    assert 2000.0 < row["near_mm"] < 3000.0 < row["far_mm"] < 4000.0


@pytest.mark.parametrize("pid", sorted(PATENTS))
def test_the_lens_as_sold_uses_the_patents_pupils_in_the_thick_model(pid):
    # thick with the preset's P and δ equals thick with the same values typed by hand, and differs
    # from the thin lens (P = 1, δ = 0) by the pupil terms
    lens = PATENTS[pid]["lens"]
    preset = load_db().lens(lens)
    (row,) = run_json("dof", "--lens", lens, "-N", "2", "-s", "3m", "--model", "thick", "--coc", "0.03")
    (typed,) = run_json("dof", "-f", "50", "-N", "2", "-s", "3m", "--model", "thick", "--coc", "0.03",
                        "--pupil-mag", str(preset.pupil_magnification), "--hiatus", str(preset.hiatus_mm),
                        "--lens", lens)
    assert row == typed
    (thin,) = run_json("dof", "--lens", lens, "-N", "2", "-s", "3m", "--model", "thin", "--coc", "0.03")
    assert row["near_mm"] != pytest.approx(thin["near_mm"], rel=1e-6)


def test_a_focal_length_the_retail_lens_does_not_have_is_still_refused():
    result = run("dof", "--lens", "canon-rf-50mm-f1.2l-usm", "-f", "85", "-N", "2", "-s", "3m")
    assert result.exit_code == 2
    assert "85 mm is outside the valid range of --lens canon-rf-50mm-f1.2l-usm: 50 mm" in result.output


def test_prescription_option_takes_a_preset_name():
    # --prescription NAME with no such file gives the prescription preset: the same rows as the file itself
    by_name = run_json("dof", "-N", "2", "-s", "3m", "--prescription", "dgauss100", "--model", "paraxial")
    by_file = run_json("dof", "-N", "2", "-s", "3m", "--prescription", "tests/data/prescriptions/dgauss100.yaml",
                       "--model", "paraxial")
    assert by_name == by_file
    (design,) = run_json("dof", "-N", "2", "-s", "3m", "--prescription", "nikon-z50-f1.8", "--model", "raytrace")
    assert design["focal_length_mm"] == pytest.approx(first_order(optics("nikon-z50-f1.8")).efl_mm, rel=1e-12)
    wrong = run("dof", "-N", "2", "-s", "3m", "--prescription", "dgaus100")
    assert wrong.exit_code == 2 and wrong.stderr == (
        "Error: Invalid value for '--prescription': no file or prescription preset is named 'dgaus100'; "
        "did you mean dgauss100?\n")
    assert run("dof", "-N", "2", "-s", "3m", "--prescription", "missing.yaml").exit_code == 1  # a file: exit 1
