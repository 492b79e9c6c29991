"""Prescriptions and first-order (paraxial) optics against the reference data.

Reference: tests/data/oracle-README.md (first-order table, computed from the YAML files by
an independent y-nu trace) and tests/data/oracle-dof.csv (`paraxial` rows, rayoptics 0.9.8 /
optiland 0.6.3); see tests/data/README.md.
"""

from __future__ import annotations

import csv
import math
from pathlib import Path

import pytest
import yaml

from camtool.dof.paraxial import paraxial_dof
from camtool.optics.paraxial import first_order, paraxial_trace
from camtool.optics.prescription import PrescriptionError, prescription_from_mapping

DATA = Path(__file__).parent / "data"


def load(name: str):
    path = DATA / "prescriptions" / f"{name}.yaml"
    return prescription_from_mapping(yaml.safe_load(path.read_text()), source=path.name)


def oracle_rows(method: str) -> list[dict[str, str]]:
    with open(DATA / "oracle-dof.csv", newline="") as handle:
        return [row for row in csv.DictReader(handle) if row["method"] == method]


def singlet(stop_first: bool = True, thickness: float = 5.0, radius: float = 51.68, n: float = 1.5168) -> dict:
    """Plano-convex singlet, curved side first; the stop in contact in front (or 90 mm behind)."""
    stop = {"radius_mm": "inf", "thickness_mm": 0.0, "n": 1.0, "stop": True}
    lens = [
        {"radius_mm": radius, "thickness_mm": thickness, "n": n},
        {"radius_mm": "inf", "thickness_mm": 90.0, "n": 1.0},
    ]
    if stop_first:
        return {"surfaces": [stop, *lens]}
    lens[1] = {"radius_mm": "inf", "thickness_mm": 90.0, "n": 1.0}
    return {"surfaces": [*lens, {**stop, "thickness_mm": 10.0}]}


# oracle-README.md, "Reproducing the first-order data from the YAML" (12-digit table)
FIRST_ORDER = {
    "dgauss100": {
        "efl_mm": 100.003757028, "bfd_mm": 61.4875364180, "z_k_mm": 77.9674018904, "z_h_mm": 70.6829745795,
        "z_h_prime_mm": 39.4511812805, "z_e_mm": 57.9120034224, "z_x_mm": 24.8105265787, "m_e": 1.57703562027,
        "m_x": 1.80791528575, "pupil_magnification": 1.14640104669,
    },
    "telephoto127": {
        "efl_mm": 127.016601138, "bfd_mm": 63.4060594396, "z_k_mm": 43.1114200000, "z_h_mm": -38.1087203396,
        "z_h_prime_mm": -20.4991216982, "z_e_mm": 7.78381237089, "z_x_mm": 13.2128829412, "m_e": 1.16553097813,
        "m_x": 0.856182551310, "pupil_magnification": 0.734585838879,
    },
}
# oracle-README.md, same table: EPD at the design N and the stop radius
STOP = {"dgauss100": (2.0, 50.0018785140, 15.8531227422), "telephoto127": (5.6, 22.6815359175, 9.73013001930)}


@pytest.mark.parametrize("lens", sorted(FIRST_ORDER))
def test_first_order_matches_reference_table(lens):
    fo = first_order(load(lens))
    for key, expected in FIRST_ORDER[lens].items():
        assert getattr(fo, key) == pytest.approx(expected, rel=1e-6, abs=1e-9), key
    n, epd, r_stop = STOP[lens]
    assert fo.epd_mm(n) == pytest.approx(epd, rel=1e-9)
    assert fo.stop_radius_mm(n) == pytest.approx(r_stop, rel=1e-9)
    assert fo.hiatus_mm == pytest.approx(FIRST_ORDER[lens]["z_h_prime_mm"] - FIRST_ORDER[lens]["z_h_mm"], rel=1e-9)


@pytest.mark.parametrize("lens", ["dgauss100", "telephoto127", "cellphone"])
def test_focal_length_and_pupil_magnification_match_oracle_columns(lens):
    # oracle-dof.csv columns efl_mm and pupil_mag (12 significant digits)
    row = next(r for r in oracle_rows("paraxial") if r["lens"] == lens)
    fo = first_order(load(lens))
    assert fo.efl_mm == pytest.approx(float(row["efl_mm"]), rel=1e-10)
    assert fo.pupil_magnification == pytest.approx(float(row["pupil_mag"]), rel=1e-10)
    # the YAML's stated focal length (same source)
    assert fo.efl_mm == pytest.approx(load(lens).focal_length_mm, rel=1e-12)


@pytest.mark.parametrize("row", oracle_rows("paraxial"), ids=lambda r: f"{r['lens']}-f{r['f_number']}-{r['focus_distance_mm']}")
def test_paraxial_rows_of_oracle(row):
    # oracle-dof.csv, method = paraxial: film-plane near/far to 1e-6, depths to 1e-6 relative
    lens = load(row["lens"])
    focus = float(row["focus_distance_mm"])
    near, far = float(row["near_mm"]), float(row["far_mm"])
    result = paraxial_dof(lens, float(row["f_number"]), float(row["coc_mm"]), focus)
    assert result.near_mm == pytest.approx(near, rel=1e-6)
    assert result.far_mm == pytest.approx(far, rel=1e-6)
    assert result.front_mm == pytest.approx(focus - near, rel=1e-6)
    assert result.rear_mm == pytest.approx(far - focus, rel=1e-6)
    assert result.magnification == pytest.approx(float(row["magnification"]), rel=1e-9)


def test_paraxial_dof_in_other_planes_matches_film_plane():
    # oracle-dof.csv first dgauss100 paraxial row, re-measured from E and from H with its offsets
    row = oracle_rows("paraxial")[0]
    lens, n, c = load(row["lens"]), float(row["f_number"]), float(row["coc_mm"])
    focus = float(row["focus_distance_mm"])
    for plane, offset in (("entrance_pupil", "film_to_entrance_pupil_mm"), ("lens", "film_to_front_principal_mm")):
        shift = float(row[offset])
        result = paraxial_dof(lens, n, c, focus - shift, distance_from=plane)
        assert result.near_mm + shift == pytest.approx(float(row["near_mm"]), rel=1e-9)
        assert result.far_mm + shift == pytest.approx(float(row["far_mm"]), rel=1e-9)


def test_singlet_with_stop_first_matches_lensmaker():
    # thick-lens formulas (Hecht, Optics, §6.2): plano-convex, curved side first, f = R/(n − 1),
    # BFD = f − t/n, front principal point at the curved vertex; stop at the first vertex
    radius, n, t = 51.68, 1.5168, 5.0
    fo = first_order(prescription_from_mapping(singlet(thickness=t, radius=radius, n=n)))
    f = radius / (n - 1.0)
    assert fo.efl_mm == pytest.approx(f, rel=1e-13)
    assert fo.bfd_mm == pytest.approx(f - t / n, rel=1e-13)
    assert fo.z_h_mm == pytest.approx(0.0, abs=1e-12)  # curved side first: H at its vertex
    assert fo.z_e_mm == 0.0 and fo.m_e == 1.0  # stop in contact with the first vertex
    # exit pupil: the stop (at H, z = 0) imaged by the lens: u = 0 from H gives m = 1, so P = 1
    assert fo.pupil_magnification == pytest.approx(1.0, rel=1e-12)


def test_stop_behind_lens_entrance_pupil_is_image_of_stop():
    # stop 90 mm behind a thin-ish singlet (f = 100): the entrance pupil is the stop's image
    # through the lens seen from the front, magnification 1/(1 − d/f) = 10 (Smith, §6.2)
    fo = first_order(prescription_from_mapping(singlet(stop_first=False, thickness=1e-9)))
    assert fo.m_e == pytest.approx(10.0, rel=1e-6)
    assert fo.z_e_mm == pytest.approx(900.0, rel=1e-6)


def test_r2_aspheric_term_acts_as_curvature_paraxially():
    # sag c r²/2 + a2 r²: paraxial curvature c + 2 a2 (a flat surface with a2 = 1/(2R) is a sphere of R)
    sphere = singlet()
    flat = singlet()
    flat["surfaces"][1] = {"radius_mm": "inf", "thickness_mm": 5.0, "n": 1.5168, "aspheric": {"a2": 1.0 / (2 * 51.68)}}
    a, b = first_order(prescription_from_mapping(sphere)), first_order(prescription_from_mapping(flat))
    assert a.efl_mm == pytest.approx(b.efl_mm, rel=1e-14)


def test_paraxial_trace_of_flat_plate_only_shifts():
    # a plane-parallel plate has no power: a parallel ray stays parallel (nu = 0)
    plate = prescription_from_mapping(
        {"surfaces": [{"radius_mm": "inf", "thickness_mm": 3.0, "n": 1.5, "stop": True},
                      {"radius_mm": "inf", "thickness_mm": 10.0, "n": 1.0}]}
    )
    assert paraxial_trace(plate, 2.0, 0.0) == (2.0, 0.0)
    with pytest.raises(ValueError, match="no positive focal length"):
        first_order(plate)


GOOD = {"radius_mm": 50.0, "thickness_mm": 5.0, "n": 1.5}
LAST = {"radius_mm": "inf", "thickness_mm": 95.0, "n": 1.0, "stop": True}


@pytest.mark.parametrize(
    "surfaces, message",
    [
        ([{**GOOD, "radius_mm": 0}, LAST], "surface 1, radius_mm: must not be 0"),
        ([{**GOOD, "thickness_mm": -1}, LAST], "surface 1, thickness_mm: must be ≥ 0"),
        ([GOOD, {**LAST, "thickness_mm": 0.0}], "surface 2, thickness_mm: the back focal distance must be > 0"),
        ([{**GOOD, "n": 0.9}, LAST], "surface 1, n: refractive index must be ≥ 1"),
        ([{**GOOD, "n": "glass"}, LAST], "surface 1, n: expected a number"),
        ([GOOD, {**LAST, "stop": False}], "stop: exactly one surface must have stop: true \\(found none\\)"),
        ([{**GOOD, "stop": True}, LAST], "found surfaces \\[1, 2\\]"),
        ([{**GOOD, "thicknes_mm": 5.0}, LAST], "surface 1, thicknes_mm: unknown key"),
        ([{k: v for k, v in GOOD.items() if k != "n"}, LAST], "surface 1, n: missing"),
        ([{**GOOD, "aspheric": {"b4": 1.0}}, LAST], "surface 1, aspheric.b4: term names are"),
        ([{**GOOD, "aspheric": {"a1": 1.0}}, LAST], "surface 1, aspheric.a1: powers 2 to 30"),
        ([{**GOOD, "thickness_mm": 0.0}, {**GOOD, "radius_mm": -50.0}, LAST], "surface 1, thickness_mm: is 0 between two curved"),
        ([{**GOOD, "semi_diameter_mm": -2}, LAST], "surface 1, semi_diameter_mm: must be > 0"),
    ],
)
def test_invalid_prescriptions_name_surface_and_key(surfaces, message):
    with pytest.raises(PrescriptionError, match=message) as caught:
        prescription_from_mapping({"surfaces": surfaces}, source="bad.yaml")
    assert str(caught.value).startswith("bad.yaml: ")
    assert isinstance(caught.value, ValueError)


def test_invalid_top_level_keys():
    with pytest.raises(PrescriptionError, match="object_index: refractive index"):
        prescription_from_mapping({"surfaces": [GOOD, LAST], "object_index": 0.5})
    with pytest.raises(PrescriptionError, match="surfaces: expected a non-empty list"):
        prescription_from_mapping({"surfaces": []})
    with pytest.raises(PrescriptionError, match="f_number: must be > 0"):
        prescription_from_mapping({"surfaces": [GOOD, LAST], "f_number": 0})
    with pytest.raises(PrescriptionError, match="focal_lenght_mm: unknown key"):
        prescription_from_mapping({"surfaces": [GOOD, LAST], "focal_lenght_mm": 100})


def test_prescription_reads_shared_files_faithfully():
    # prescriptions/cellphone.yaml: stop first, 8 aspheric surfaces, a flat filter plate
    lens = load("cellphone")
    assert lens.stop_index == 0 and lens.is_aspheric
    assert sum(s.is_aspheric for s in lens.surfaces) == 8
    assert lens.surfaces[1].aspheric[0] == (3, -0.01895) and lens.surfaces[1].conic == 1.153
    assert math.isinf(lens.surfaces[9].radius_mm) and lens.surfaces[9].curvature == 0.0
    assert lens.vertices_mm[-1] == pytest.approx(5.97, abs=1e-12)
    assert hash(lens) == hash(load("cellphone"))  # frozen and hashable (cached traces)
