"""lens_db/third-party-lenses.yaml: each entry's figures against the page its `source` quotes, and the figures
the model derives from them against what the pages say of the lens in use."""

from __future__ import annotations

import math

import pytest
from cli_helpers import run, run_json
from lens_checks import DB, check_cited_row, isolated, lens_records, record_of, taken_elsewhere  # noqa: F401

from camtool.geometry.closeup import internal_focus_at_distance
from camtool.geometry.projection import half_angle_deg, image_height_mm
from camtool.presets import load_db
from camtool.presets.focusing import focus_model

FILE = DB / "third-party-lenses.yaml"
RECORDS = lens_records(FILE)


# (lens, focal length mm, closest focus mm, magnification or None, f-number range) as the page each entry's
# source names gives them; ranges are (widest, smallest) at the short end and, for a zoom whose apertures
# change, at the long end (None: the page gives none).
CITED = [
    # DIY Photography: 33cm (wide) / 85cm (tele), f/2-2.8, minimum aperture f/16-22; Photography Life: 1:5.7, 1:5.9
    ("tamron-35-150mm-f2-2.8-di-iii-vxd", 35, 330, 1 / 5.7, (2, 16)),
    ("tamron-35-150mm-f2-2.8-di-iii-vxd", 150, 850, 1 / 5.9, (2.8, 22)),
    # The Phoblographer: 0.6 m / 1.8 m, 1:3.1 / 1:3.7, F5-6.7, F22-32
    ("tamron-150-500mm-f5-6.7-di-iii-vc-vxd", 150, 600, 1 / 3.1, (5, 22)),
    ("tamron-150-500mm-f5-6.7-di-iii-vc-vxd", 500, 1800, 1 / 3.7, (6.7, 32)),
    # 31.5 in at 70 mm, 59.1 in at 300 mm (0.8 m, 1.5 m); Photography Life 1:5 at 300 mm; f/4.5-22, f/6.3-32
    ("tamron-70-300mm-f4.5-6.3-di-iii-rxd", 70, 800, None, (4.5, 22)),
    ("tamron-70-300mm-f4.5-6.3-di-iii-rxd", 300, 1500, 1 / 5, (6.3, 32)),
    # Giggster / Amateur Photographer: 0.19 m and 1:3.1 at 28 mm, 0.8 m at 200 mm; f/2.8, f/5.6 from 150 mm
    ("tamron-28-200mm-f2.8-5.6-di-iii-rxd", 28, 190, 1 / 3.1, (2.8, None)),
    ("tamron-28-200mm-f2.8-5.6-di-iii-rxd", 200, 800, None, (5.6, None)),
    # Digital Camera World: 0.15-0.24 m, 0.25-0.13x, minimum aperture f/16
    ("tamron-11-20mm-f2.8-di-iii-a-rxd", 11, 150, 0.25, (2.8, 16)),
    ("tamron-11-20mm-f2.8-di-iii-a-rxd", 20, 240, 0.13, (2.8, 16)),
    # Lenstip: 11, 12 and 15 cm, 1:2; Paul Amyes: 0.15 m, 1:2, F/22
    ("tamron-20mm-f2.8-di-iii-osd-m1-2", 20, 110, 0.5, (2.8, None)),
    ("tamron-24mm-f2.8-di-iii-osd-m1-2", 24, 120, 0.5, (2.8, None)),
    ("tamron-35mm-f2.8-di-iii-osd-m1-2", 35, 150, 0.5, (2.8, 22)),
    # PCMag (gamebastion.com copy): 7.5 in at 17 mm, 11.8 in at 50 mm (0.19 m, 0.30 m)
    ("tamron-17-50mm-f4-di-iii-vxd", 17, 190, None, (4, None)),
    ("tamron-17-50mm-f4-di-iii-vxd", 50, 300, None, (4, None)),
    # ppa.com: 11.8 in (30 cm) throughout, 1:4 at 28 or 45 mm, F1.8
    ("sigma-28-45mm-f1.8-dg-dn-art", 28, 300, 0.25, (1.8, None)),
    ("sigma-28-45mm-f1.8-dg-dn-art", 45, 300, 0.25, (1.8, None)),
    # Phototrend: f/1.2 to f/16; isamu/lens-database (Sigma Japan's page, a024_50_12): 0.4 m, 0.161x
    ("sigma-50mm-f1.2-dg-dn-art", 50, 400, 0.161, (1.2, 16)),
    # Sigma Suisse: 15 mm f/1.4, 38.5 cm
    ("sigma-15mm-f1.4-dg-dn-diagonal-fisheye-art", 15, 385, None, (1.4, None)),
    # Webnews: f/1.4 to f/16, 28 cm; ronbuening/LensVisualizer src/lens-data/sigma/Sigma28mmf14DGHSMA.analysis.md
    # at 2dcf6ef8 (LENSVISUALIZER below): "Sigma's specification gives ... a 0.28 m minimum focusing distance, 1:5.4
    # maximum magnification"
    ("sigma-28mm-f1.4-dg-hsm-art", 28, 280, 1 / 5.4, (1.4, 16)),
    # No Film School: f/16, 40 cm, 1:5.6
    ("sigma-50mm-f1.4-dg-hsm-art", 50, 400, 1 / 5.6, (1.4, 16)),
    # Dennis Sassmannshausen's review: 0.875 m, F1.8
    ("sigma-135mm-f1.8-dg-hsm-art", 135, 875, None, (1.8, None)),
    # Fotografidigitali: 25.8 cm from the sensor; Digital Photographer: a 1.0x macro
    ("sigma-70mm-f2.8-dg-macro-art", 70, 258, 1.0, (2.8, None)),
    # Le Monde de la Photo: 20 cm
    ("samyang-af-14mm-f2.8-ef", 14, 200, None, (2.8, None)),
    # Fotocult: 12 cm from the focal plane, 0.11x
    ("laowa-7.5mm-f2-mft", 7.5, 120, 0.11, (2, None)),
    # a user's blog: 15 cm
    ("laowa-10-18mm-f4.5-5.6-fe-zoom", 10, 150, None, (4.5, None)),
    ("laowa-10-18mm-f4.5-5.6-fe-zoom", 18, 150, None, (5.6, None)),
    # Phototrend: 17 cm and 0.26x at 20 mm, 29 cm and 0.20x at 40 mm, f/2.8 to f/22
    ("tamron-20-40mm-f2.8-di-iii-vxd", 20, 170, 0.26, (2.8, 22)),
    ("tamron-20-40mm-f2.8-di-iii-vxd", 40, 290, 0.20, (2.8, 22)),
    # Samuel Colombo: F1.4 to F16, 27.6 cm, 1:7.1
    ("sigma-20mm-f1.4-dg-hsm-art", 20, 276, 1 / 7.1, (1.4, 16)),
    # siam-breeze (Sigma's page): F1.8, F22, 20 cm, 1:4
    ("sigma-20mm-f1.8-ex-dg-aspherical-rf", 20, 200, 1 / 4, (1.8, 22)),
    # Wetpixel: f/2.8, 19.7 in (50 cm), 1:7.2
    ("sigma-60mm-f2.8-dn-art", 60, 500, 1 / 7.2, (2.8, None)),
    # Sigma UK: f3.5-4, f22-27, 0.5 m; its 1:6.15 has no focal length and is kept at lens level (checked below)
    ("sigma-zoom-28-70mm-f3.5-4-uc", 28, 500, None, (3.5, 22)),
    ("sigma-zoom-28-70mm-f3.5-4-uc", 70, 500, None, (4, 27)),
    # Nikon Rumors / Light and Matter: f/16, 28 cm, 0.23x (kept at lens level)
    ("sigma-18-35mm-f1.8-dc-hsm-art", 18, 280, None, (1.8, 16)),
    ("sigma-18-35mm-f1.8-dc-hsm-art", 35, 280, None, (1.8, 16)),
    # Nikonmag (Sigma UK): 12.3 in (31.2 cm) at 1:1
    ("sigma-105mm-f2.8-ex-dg-os-hsm-macro", 105, 312, 1.0, (2.8, None)),
    # Bob Atkins: f2.8 - f32, 1:1, 0.3 m
    ("tamron-sp-90mm-f2.8-di-vc-usd-macro-f004", 90, 300, 1.0, (2.8, 32)),
    # The Phoblographer (Tamron's site): 0.29 m, f/2.8 to f/32; 1:1
    ("tamron-sp-af-90mm-f2.8-di-macro-272e", 90, 290, 1.0, (2.8, 32)),
    # Fotografidigitali: 23 cm for 1:1; SlashGear: f/2
    ("tamron-sp-af-60mm-f2-di-ii-ld-if-macro", 60, 230, 1.0, (2, None)),
    # erphotoreview: 0.14 m, 1:1
    ("tokina-at-x-m35-pro-dx-35mm-f2.8-macro", 35, 140, 1.0, (2.8, None)),
    # Les Numériques / Photography Blog: 0.49 m, f/3.5-6.3, f/22-40; 1:3.5 kept at lens level
    ("tamron-28-300mm-f3.5-6.3-di-vc-pzd", 28, 490, None, (3.5, 22)),
    ("tamron-28-300mm-f3.5-6.3-di-vc-pzd", 300, 490, None, (6.3, 40)),
    # DPReview / Photo Review: 0.39 m; 0.34x kept at lens level
    ("tamron-16-300mm-f3.5-6.3-di-ii-vc-pzd-macro", 16, 390, None, (3.5, None)),
    ("tamron-16-300mm-f3.5-6.3-di-ii-vc-pzd-macro", 300, 390, None, (6.3, None)),
    # Tamron Australia: 0.27 m throughout, 1:4.5 at 50 mm; SLR Lens Review: f/2.8-f/32
    ("tamron-sp-af-17-50mm-f2.8-xr-di-ii-ld-a16", 17, 270, None, (2.8, 32)),
    ("tamron-sp-af-17-50mm-f2.8-xr-di-ii-ld-a16", 50, 270, 1 / 4.5, (2.8, 32)),
    # Professional Photographer: 0.29 m over the range; 1:4.8 kept at lens level
    ("tamron-sp-af-17-50mm-f2.8-xr-di-ii-vc-b005", 17, 290, None, (2.8, None)),
    ("tamron-sp-af-17-50mm-f2.8-xr-di-ii-vc-b005", 50, 290, None, (2.8, None)),
    # Wikipedia: f/4.5/22 - f/5.6/29, 24 cm; 1:7.8 kept at lens level
    ("sigma-8-16mm-f4.5-5.6-dc-hsm", 8, 240, None, (4.5, 22)),
    ("sigma-8-16mm-f4.5-5.6-dc-hsm", 16, 240, None, (5.6, 29)),
    # dptnt.com: 0.24 m; 1:6.7 kept at lens level
    ("sigma-10-20mm-f4-5.6-ex-dc-hsm", 10, 240, None, (4, None)),
    ("sigma-10-20mm-f4-5.6-ex-dc-hsm", 20, 240, None, (5.6, None)),
    # SLR Lens Review: 30 cm, f/22, 1:8 at 24 mm
    ("tokina-at-x-124-pro-dx-12-24mm-f4", 12, 300, None, (4, 22)),
    ("tokina-at-x-124-pro-dx-12-24mm-f4", 24, 300, 1 / 8, (4, 22)),
    # DPReview: 95 cm (no magnification published)
    ("sigma-50-100mm-f1.8-dc-hsm-art", 50, 950, None, (1.8, None)),
    ("sigma-50-100mm-f1.8-dc-hsm-art", 100, 950, None, (1.8, None)),
    # Lennart Verhoeven: 5.6 to 22, 4.0 m, 1:9.5
    ("sigma-400mm-f5.6-apo", 400, 4000, 1 / 9.5, (5.6, 22)),
    # Photo Review: 1:1 at 188 mm; magazine test: f/2.8 to f/32
    ("sigma-50mm-f2.8-ex-dg-macro", 50, 188, 1.0, (2.8, 32)),
    # Shutterbug: 12.3 in (31.2 cm), 1:1
    ("sigma-af-105mm-f2.8-ex-macro", 105, 312, 1.0, (2.8, None)),
    # lens-db.com: F/2.5, 0.39 m, 1:2
    ("tamron-sp-af-90mm-f2.5-macro-52e", 90, 390, 0.5, (2.5, None)),
    # DPReview: 0.49 m (0.26x kept at lens level); Amateur Photographer: f/22-40
    ("tamron-18-270mm-f3.5-6.3-di-ii-vc-pzd", 18, 490, None, (3.5, 22)),
    ("tamron-18-270mm-f3.5-6.3-di-ii-vc-pzd", 270, 490, None, (6.3, 40)),
    # Adorama: 1.48 ft (45 cm), f/22-40 (1:3.4 kept at lens level)
    ("sigma-18-250mm-f3.5-6.3-dc-os-hsm", 18, 450, None, (3.5, 22)),
    ("sigma-18-250mm-f3.5-6.3-dc-os-hsm", 250, 450, None, (6.3, 40)),
    # LA Splash / Shutterbug: 17.7 in (45 cm) throughout, F/22 (1:3.5 kept at lens level)
    ("tamron-af-18-250mm-f3.5-6.3-di-ii-ld-macro-a18", 18, 450, None, (3.5, 22)),
    ("tamron-af-18-250mm-f3.5-6.3-di-ii-ld-macro-a18", 250, 450, None, (6.3, 22)),
    # Shutterbug: 59.1 in (1.5 m), 37.4 in (0.95 m) at 300 mm; Popular Photography: 1:2
    ("sigma-af-70-300mm-f4-5.6-dl-macro", 70, 1500, None, (4, None)),
    ("sigma-af-70-300mm-f4-5.6-dl-macro", 300, 950, 0.5, (5.6, None)),
    # alpha85.com: 0.9 m (1:2.8 kept at lens level)
    ("tamron-80-210mm-f3.8-4-cf-tele-macro-103a", 80, 900, None, (3.8, None)),
    ("tamron-80-210mm-f3.8-4-cf-tele-macro-103a", 210, 900, None, (4, None)),
    # Lens Shatter / The Manual Photographer: macro 30 cm at 60 mm (1:1.55), 1.9 m otherwise; f/3.8-5.4, f/32
    ("tamron-sp-60-300mm-f3.8-5.4-macro-23a", 60, 300, 1 / 1.55, (3.8, 32)),
    ("tamron-sp-60-300mm-f3.8-5.4-macro-23a", 300, 1900, None, (5.4, 32)),
    # akiophoto / joseramonmartinez: 18 cm, 1:2.7 (0.37x)
    ("sigma-24mm-f1.8-ex-dg-aspherical-macro", 24, 180, 0.37, (1.8, None)),
    # fisheyes: Nikon School Italia and Dante Stella (f/8 to f/22, no focusing); Nikon School Italia;
    # Nikon's manual (f/2.8); syaraku / pt4pano (f/3.5)
    ("nikon-fisheye-nikkor-8mm-f8", 8, None, None, (8, 22)),
    ("nikon-fisheye-nikkor-7.5mm-f5.6", 7.5, None, None, (5.6, None)),
    ("nikon-fisheye-nikkor-6mm-f5.6", 6, None, None, (5.6, None)),
    ("nikon-fisheye-nikkor-8mm-f2.8", 8, None, None, (2.8, None)),
    ("sigma-8mm-f3.5-ex-dg-circular-fisheye", 8, None, None, (3.5, None)),
    ("sigma-8mm-f4-ex-circular-fisheye", 8, None, None, (4, None)),  # Impress DC Watch: 8mm F4
]

# (lens, projection, field_max_deg) as the page each fisheye's source names them
FISHEYES = [
    ("sigma-15mm-f1.4-dg-dn-diagonal-fisheye-art", "equisolid", 180),
    ("nikon-fisheye-nikkor-8mm-f8", "equidistant", 180),  # Nikon School Italia: equidistant, 180°
    ("nikon-fisheye-nikkor-7.5mm-f5.6", "equidistant", 180),  # Nikon School Italia: equidistant, 180°
    ("nikon-fisheye-nikkor-6mm-f5.6", "equidistant", 220),  # Nikon School Italia: equidistant, 220°
    ("nikon-fisheye-nikkor-8mm-f2.8", "equidistant", 180),  # Nikon's manual: y = f·θ, 180°
    ("sigma-8mm-f3.5-ex-dg-circular-fisheye", "equisolid", 180),  # Wikipedia (ja): Sigma's are equisolid
    ("sigma-8mm-f4-ex-circular-fisheye", "equisolid", 180),  # Wikipedia (ja); Impress: 180° on Four Thirds
]


# the LensVisualizer lens-design analyses quoted in `source` beside the pages: lens, analysis path, commit
LENSVISUALIZER = [
    ("sigma-28mm-f1.4-dg-hsm-art", "src/lens-data/sigma/Sigma28mmf14DGHSMA.analysis.md",
     "2dcf6ef8b666ae7c04f463d51d84bc023776b169"),
]


@pytest.mark.parametrize(("lens_id", "path", "commit"), LENSVISUALIZER)
def test_the_lensvisualizer_analysis_is_cited_with_path_and_commit(lens_id, path, commit):
    record = record_of(RECORDS, lens_id)
    assert f"ronbuening/LensVisualizer {path} at {commit}" in " ".join(record["source"].split())
    # a magnification only one source gives keeps the entry approximate, its note naming the figure
    assert record["approximate"] is True and "1:5.4" in " ".join(record["notes"].split())


def test_every_entry_is_checked_against_its_page():
    assert {lens_id for lens_id, *_ in CITED} == {r["id"] for r in RECORDS}
    assert {lens_id for lens_id, *_ in FISHEYES} == {r["id"] for r in RECORDS if r["category"] == "fisheye"}


@pytest.mark.parametrize(("lens_id", "projection", "field"), FISHEYES, ids=[f[0] for f in FISHEYES])
def test_fisheye_mappings_against_the_cited_pages(lens_id, projection, field):
    record = record_of(RECORDS, lens_id)
    assert (record["projection"], record["field_max_deg"]) == (projection, field)
    lens = load_db().lens(lens_id)
    assert (lens.projection, lens.field_max_deg) == (projection, float(field))


@pytest.mark.parametrize(("lens_id", "focal", "distance", "magnification", "apertures"), CITED,
                         ids=[f"{c[0]}@{c[1]}" for c in CITED])
def test_figures_against_the_cited_pages(lens_id, focal, distance, magnification, apertures):
    record = record_of(RECORDS, lens_id)
    check_cited_row(record, focal, distance, magnification, apertures)
    # a closest focus left out is said to be "not found" too
    if distance is None:
        assert "min_focus_mm" in record["notes"] and "not found" in record["notes"]


def test_every_entry_names_its_mounts_and_is_a_new_id():
    # lens_db/README.md: within one tier an id or alias names one preset; the entries of lenses.yaml are kept
    taken, _names = taken_elsewhere(FILE)
    for record in RECORDS:
        assert not ({record["id"], *record.get("aliases", [])} & taken), record["id"]
        assert record["mount"] and record["mount"] != "various", record["id"]
        assert load_db().lens(record["id"]).tier == "shipped"


def test_unpublished_zoom_rows_stay_within_what_the_pages_say():
    # Photography Life: the 70-300 reaches less than 1:9 at 70 mm, where Tamron publishes no figure; the model
    # (unit focusing at 0.8 m) gives 0.107x
    lens = load_db().lens("tamron-70-300")
    model = focus_model(lens, 70.0)
    m, _f = internal_focus_at_distance(model, 800.0)
    assert m < 1 / 9
    assert m == pytest.approx((800 / 70 - 2 - math.sqrt((800 / 70 - 2) ** 2 - 4)) / 2, rel=1e-9)
    # and no focal length of any entry here magnifies more than its page's maximum
    for record in RECORDS:
        lens = load_db().lens(record["id"])
        if lens.max_magnification is None or lens.min_focus_mm is None:
            continue
        for f in {lens.focal_min_mm, lens.focal_max_mm, (lens.focal_min_mm + lens.focal_max_mm) / 2}:
            model = focus_model(lens, f)
            assert internal_focus_at_distance(model, model.min_focus_mm)[0] <= lens.max_magnification * 1.001


def test_laowa_7_5mm_covers_110_degrees_on_four_thirds():
    # Fotocult: about 110° on the diagonal, like a 15 mm on full frame (rectilinear); Four Thirds 17.3 × 13 mm
    (row,) = run_json("fov", "--lens", "laowa-7.5")
    assert row["diagonal_deg"] == pytest.approx(110, abs=1.5)
    assert row["diagonal_deg"] == pytest.approx(2 * math.degrees(math.atan(math.hypot(17.3, 13) / 15)), rel=1e-3)


def test_sigma_15mm_diagonal_fisheye_covers_180_degrees_across_full_frame():
    # Sigma Suisse: 180° diagonal on full frame. An equisolid 15 mm maps the 21.63 mm half-diagonal to 92.3°
    # (184.6° across, within 3 % of 180°; its 180° circle is 42.4 mm, 2 % inside the 43.3 mm diagonal); an
    # equidistant one would reach only 165°, 8 % short — why the entry takes equisolid (approximate, as its
    # notes say)
    half_diagonal = math.hypot(36, 24) / 2
    assert 2 * half_angle_deg(half_diagonal, 15.0, "equisolid") == pytest.approx(180, rel=0.03)
    assert 2 * half_angle_deg(half_diagonal, 15.0, "equidistant") < 180 * 0.93
    assert 2 * image_height_mm(15.0, 90.0, "equisolid") == pytest.approx(2 * half_diagonal, rel=0.03)
    lens = load_db().lens("sigma-15-fisheye")
    assert (lens.projection, lens.field_max_deg, lens.approximate) == ("equisolid", 180.0, True)
    (row,) = run_json("fov", "--lens", "sigma-15-fisheye")
    assert row["diagonal_deg"] == 180.0 and row["projection"] == "equisolid"


def test_dof_runs_with_a_third_party_zoom_and_refuses_closer_than_its_closest_focus():
    # Tamron 150-500: 1.8 m at 500 mm (The Phoblographer)
    (row,) = run_json("dof", "--lens", "tamron-150-500", "-f", "500", "-N", "8", "-s", "2m")
    assert row["near_mm"] < 2000.0 < row["far_mm"]
    assert row["magnification"] < 0.27  # 1:3.7 at its 1.8 m closest focus, less farther away
    result = run("dof", "--lens", "tamron-150-500", "-f", "500", "-N", "8", "-s", "1.5m")
    assert result.exit_code == 2
    assert "1.8 m" in result.output


@pytest.mark.parametrize(("lens_id", "focal", "published_deg", "rounding"), [
    # Phototrend: 94°30' at 20 mm, 56°49' at 40 mm (to the minute)
    ("tamron-20-40", 20, 94 + 30 / 60, 1 / 60),
    ("tamron-20-40", 40, 56 + 49 / 60, 1 / 60),
    # siam-breeze / bruno.cracco: 94.5° on 24 x 36
    ("sigma-20-1.8-ex", 20, 94.5, 0.05),
    # Bob Atkins (Tamron's table): 27°02' on full frame
    ("tamron-f004", 90, 27 + 2 / 60, 1 / 60),
    # Sigma UK: field of view 75-34° (whole degrees)
    ("sigma-28-70-uc", 28, 75, 0.5),
    ("sigma-28-70-uc", 70, 34, 0.5),
    # The Manual Photographer: angle of view 40-8° (whole degrees)
    ("tamron-23a", 60, 40, 0.5),
    ("tamron-23a", 300, 8, 0.5),
])
def test_diagonal_angle_of_view_against_the_cited_pages(lens_id, focal, published_deg, rounding):
    (row,) = run_json("fov", "--lens", lens_id, "-f", str(focal))
    assert row["projection"] == "rectilinear"
    assert abs(row["diagonal_deg"] - published_deg) <= rounding + 1e-9


def test_nikon_eight_mm_f8_draws_its_hemisphere_in_the_circle_its_user_measured():
    # Dante Stella: a 180° circle 24 mm across on film; Nikon School Italia: equidistant. An equidistant
    # 8 mm puts 90° at 8·π/2 = 12.57 mm (a 25.1 mm circle, 4.7 % more than the 24 mm read off the film);
    # on full frame the circle overfills the 24 mm height: 2·(12/8) rad = 171.9° vertically
    assert 2 * image_height_mm(8.0, 90.0, "equidistant") == pytest.approx(24.0, rel=0.05)
    (row,) = run_json("fov", "--lens", "fisheye-nikkor-8mm-f8")
    assert (row["horizontal_deg"], row["diagonal_deg"], row["projection"]) == (180.0, 180.0, "equidistant")
    assert row["vertical_deg"] == pytest.approx(2 * math.degrees(12 / 8), rel=1e-12)


def test_nikon_circular_fisheyes_fit_inside_the_full_frame():
    # 7.5 mm equidistant: a 7.5·π = 23.6 mm circle; 6 mm over 220°: 6·220·π/180 = 23.0 mm; both inside 24 mm
    for lens_id, field in (("fisheye-nikkor-7.5mm", 180.0), ("fisheye-nikkor-6mm-f5.6", 220.0)):
        lens = load_db().lens(lens_id)
        assert 2 * image_height_mm(lens.focal_length_mm, field / 2, "equidistant") < 24.0
        (row,) = run_json("fov", "--lens", lens_id)
        assert (row["horizontal_deg"], row["vertical_deg"], row["diagonal_deg"]) == (field, field, field)


def test_sigma_8mm_f4_on_four_thirds_is_near_diagonal_filling():
    # Impress: the full-frame circular 8mm F4 becomes a diagonal fisheye on the E-410 (Four Thirds)
    (row,) = run_json("fov", "--lens", "sigma-8-f4-fisheye")
    assert (row["horizontal_deg"], row["vertical_deg"], row["diagonal_deg"]) == (180.0, 180.0, 180.0)
    (row,) = run_json("fov", "--lens", "sigma-8-f4-fisheye", "--sensor", "four-thirds")
    assert 165.0 < row["diagonal_deg"] < 180.0
    assert 2 * image_height_mm(8.0, 90.0, "equisolid") == pytest.approx(math.hypot(17.3, 13), rel=0.05)


def test_sigma_8mm_circle_points_to_the_equisolid_mapping():
    # syaraku.org: a 22 mm circle on 35 mm film, about the Four Thirds diagonal. Equisolid 8 mm: 22.6 mm
    # (3 % more); equidistant: 25.1 mm (14 % more) — why the entry takes equisolid (approximate)
    assert 2 * image_height_mm(8.0, 90.0, "equisolid") == pytest.approx(22.0, rel=0.03)
    assert 2 * image_height_mm(8.0, 90.0, "equidistant") > 22.0 * 1.1
    (row,) = run_json("fov", "--lens", "sigma-8-fisheye")
    assert (row["horizontal_deg"], row["vertical_deg"], row["diagonal_deg"]) == (180.0, 180.0, 180.0)
    # on Four Thirds (17.3 x 13 mm) the circle nearly spans the diagonal: 4·asin(10.82/16) = 170°
    (row,) = run_json("fov", "--lens", "sigma-8-fisheye", "--sensor", "four-thirds")
    half_diagonal = math.hypot(17.3, 13) / 2
    assert row["diagonal_deg"] == pytest.approx(4 * math.degrees(math.asin(half_diagonal / 16)), rel=1e-9)
    assert 2 * half_diagonal == pytest.approx(22.0, rel=0.03)


@pytest.mark.parametrize(("lens_id", "magnification"), [
    ("sigma-zoom-28-70mm-f3.5-4-uc", 1 / 6.15),  # Sigma UK: 1:6.15
    ("sigma-18-35mm-f1.8-dc-hsm-art", 0.23),  # Nikon Rumors (Fotoradce): 0.23x
    ("tamron-28-300mm-f3.5-6.3-di-vc-pzd", 1 / 3.5),  # Photography Blog: 1:3.5 (Les Numériques: 0.29x)
    ("tamron-16-300mm-f3.5-6.3-di-ii-vc-pzd-macro", 0.34),  # DPReview: 0.34x
    ("tamron-sp-af-17-50mm-f2.8-xr-di-ii-vc-b005", 1 / 4.8),  # Professional Photographer: 1:4.8
    ("sigma-8-16mm-f4.5-5.6-dc-hsm", 1 / 7.8),  # Wikipedia: 1:7.8
    ("sigma-10-20mm-f4-5.6-ex-dc-hsm", 1 / 6.7),  # dptnt.com: 1:6.7
    ("tamron-18-270mm-f3.5-6.3-di-ii-vc-pzd", 0.26),  # DPReview: 0.26x
    ("sigma-18-250mm-f3.5-6.3-dc-os-hsm", 1 / 3.4),  # Adorama: 1:3.4 on the barrel
    ("tamron-af-18-250mm-f3.5-6.3-di-ii-ld-macro-a18", 1 / 3.5),  # LA Splash: 1:3.5
    ("tamron-80-210mm-f3.8-4-cf-tele-macro-103a", 1 / 2.8),  # alpha85.com: 1:2.8
])
def test_a_zooms_single_published_magnification_is_its_lens_level_maximum(lens_id, magnification):
    # a page giving one magnification without its focal length: it bounds every row, none claims it
    record = record_of(RECORDS, lens_id)
    assert record["max_magnification"] == pytest.approx(magnification, abs=0.0006)
    assert all("max_magnification" not in row for row in record["close_focus"])
    lens = load_db().lens(lens_id)
    for f in (lens.focal_min_mm, (lens.focal_min_mm + lens.focal_max_mm) / 2, lens.focal_max_mm):
        model = focus_model(lens, f)
        assert internal_focus_at_distance(model, model.min_focus_mm)[0] <= record["max_magnification"] * (1 + 1e-9)
