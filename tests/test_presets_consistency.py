"""Internal consistency of every shipped preset: pixel pitch, phone equivalents, close focus, crop factors.

Each check runs over the whole shipped database, so a new entry is checked the day it is added.
Known exceptions are listed next to each check with the reason.
"""

from __future__ import annotations

import copy
import functools
import math
from pathlib import Path

import pytest
import yaml
from conftest import point_xdg_at, presets_home
from test_cameras_fifth_pass import PHONES_FIFTH_PASS
from test_phones_2026 import PHONES_2026
from test_phones_vivo_huawei import PHONES_VIVO_HUAWEI

from camtool.geometry.closeup import internal_focus_at_distance
from camtool.presets import load_db, paths
from camtool.presets.focusing import focus_model
from camtool.presets.loader import read_file

FULL_FRAME_DIAGONAL_MM = math.hypot(36.0, 24.0)


@pytest.fixture(autouse=True)
def isolated(request, monkeypatch, shared_presets_home):
    """Point every XDG directory away from the user's own files: into tmp_path for a test that asks for
    `isolated` or `tmp_path` (it writes presets or looks at the cache), else into directories shared by the
    tests that only read the shipped presets (parsed once per session)."""
    root = presets_home(request, shared_presets_home, "isolated", "tmp_path")
    point_xdg_at(root, monkeypatch)
    return root


def lens_records() -> list[dict]:
    """The validated lens records of the shipped files (they carry the keys the Lens class has no field for).

    Parsed once per session; each call hands out deep copies, so no test sees another's changes."""
    return copy.deepcopy(_shipped_lens_records())


@functools.lru_cache(maxsize=1)
def _shipped_lens_records() -> list[dict]:
    return [r for path in paths.shipped_files() for r in read_file(path).records.get("lens", ())]


# --- pixel pitch from pixels and size ---------------------------------------------------------


def test_pixels_are_square_and_of_a_plausible_size():
    # The pitch across (width / pixels_w) and down (height / pixels_h) must agree: a body whose
    # pixel counts and sensor size disagree has one of them wrong (or the wrong aspect ratio).
    for camera in load_db().all("camera"):
        if not camera.pixels_w:
            continue
        across = camera.sensor.width_mm / camera.pixels_w
        down = camera.sensor.height_mm / camera.pixels_h
        assert across == pytest.approx(down, rel=0.015), camera.id
        assert 0.5e-3 <= across <= 10e-3, camera.id


@pytest.mark.parametrize(
    ("camera", "pitch_um"),
    [
        # Google Pixel 8/9/10 Pro tech specs: main camera "1.2 um pixel width".
        ("google-pixel-8-pro", 1.2),
        ("google-pixel-9-pro", 1.2),
        ("google-pixel-10-pro", 1.2),
        # Apple iPhone 15/16/17 Pro: "2.44 um quad pixel" (four 1.22 um pixels).
        ("apple-iphone-15-pro", 1.22),
        ("apple-iphone-16-pro", 1.22),
        ("apple-iphone-17-pro", 1.22),
        # Samsung ISOCELL HP2 (Galaxy S23/S24/S25 Ultra main): 0.6 um.
        # Samsung's HP2 release as printed by Devdiscourse (2023-01-17): "0.6-micrometer (um) pixels".
        ("samsung-galaxy-s23-ultra", 0.6),
        ("samsung-galaxy-s24-ultra", 0.6),
        ("samsung-galaxy-s25-ultra", 0.6),
        # Wikipedia, Pixel 4: rear camera "Sony Exmor IMX363 12.2MP (1.4um)".
        ("google-pixel-4", 1.4),
        # Nothing Phone (1): Sony IMX766, 1.0 um (GSMArena's spec list in the LineageOS device tree
        # README; Sparrows News: IMX766 "1/1.56-inch ... 1.0um").
        ("nothing-phone-1", 1.0),
        # ARRI ALEV III (ALEXA Mini, Mini LF, LF, 265) photosites are 8.25 um.
        ("arri-alexa-mini", 8.25),
        ("arri-alexa-mini-lf", 8.25),
        ("arri-alexa-265", 8.25),
        # slashcam.de, "Der Sensor der Sony FX3 - Rolling Shutter und Debayering": 8.40 um sensels.
        ("sony-fx3", 8.40),
        # NiYien/telemetry-parser src/blackmagic/mod.rs: Pocket Cinema Camera 6K pixel pitch 3.759 um.
        ("blackmagic-pocket-6k", 3.759),
    ],
)
def test_pixel_pitch_against_published_values(camera, pitch_um):
    body = load_db().camera(camera)
    assert body.pixel_pitch_mm * 1000 == pytest.approx(pitch_um, rel=0.01)


# --- a phone module's stated equivalent against its size --------------------------------------


def test_phone_equivalent_focal_length_matches_its_sensor():
    db = load_db()
    checked = 0
    for record in lens_records():
        equivalent = record.get("equivalent_focal_length_mm")
        if equivalent is None or "sensor" not in record:
            continue
        sensor = db.sensor(record["sensor"])
        computed = record["focal_length_mm"] * FULL_FRAME_DIAGONAL_MM / sensor.diagonal_mm
        assert computed == pytest.approx(equivalent, rel=0.03), record["id"]
        checked += 1
    assert checked >= 7


def test_every_phone_has_every_rear_module():
    names = {record["id"] for record in lens_records()}
    rear_modules = {
        "google-pixel-3": ("main",),
        "google-pixel-4": ("main", "telephoto"),
        "apple-iphone-15-pro": ("main", "ultra-wide", "telephoto"),
        "nothing-phone-1": ("main", "ultra-wide"),
        "apple-iphone-16-pro": ("main", "ultra-wide", "telephoto"),
        "apple-iphone-17-pro": ("main", "ultra-wide", "telephoto"),
        "google-pixel-8-pro": ("main", "ultrawide", "telephoto"),
        "google-pixel-9-pro": ("main", "ultrawide", "telephoto"),
        "google-pixel-10-pro": ("main", "ultrawide", "telephoto"),
        "samsung-galaxy-s23-ultra": ("main", "ultra-wide", "3x", "10x"),
        "samsung-galaxy-s24-ultra": ("main", "ultra-wide", "3x", "5x"),
        "samsung-galaxy-s25-ultra": ("main", "ultra-wide", "3x", "5x"),
        # phone-lenses.yaml
        "xiaomi-15-ultra": ("main", "ultra-wide", "telephoto", "periscope"),
        "apple-iphone-air": ("main",),
        # the phones of tests/test_phones_2026.py and tests/test_cameras_fifth_pass.py, each with all its rear modules
        **PHONES_2026,
        **PHONES_FIFTH_PASS,
        # the phones of tests/test_phones_vivo_huawei.py, each with every rear module a launch page gives (the modules
        # no launch page sizes are named in the phone's notes and checked there)
        **PHONES_VIVO_HUAWEI,
    }
    # Every shipped phone is listed, so a new phone cannot ship without its modules.
    phones = {camera.id for camera in load_db().all("camera") if camera.category == "phone"}
    assert phones == set(rear_modules)
    for phone, modules in rear_modules.items():
        for module in modules:
            assert f"{phone}-{module}" in names, (phone, module)


@pytest.mark.parametrize(
    ("lens_id", "fov_deg", "rel"),
    [
        # Diagonal fields of view the makers state. A module whose focal length is derived from it
        # must give it back exactly; one whose focal length has another origin (image files, a
        # stated equivalent) is held to the tolerance given.
        # Google Pixel 3 tech specs: 76 deg (focal length from its image files).
        ("google-pixel-3-main", 76.0, 0.02),
        # Google Pixel 4 tech specs (MySmartPrice): 12 MP 77 deg, 16 MP telephoto 52 deg.
        ("google-pixel-4-main", 77.0, 0.005),
        ("google-pixel-4-telephoto", 52.0, 0.005),
        # Google's Pixel 9 Pro list as printed by Livemint: wide 82 deg, ultrawide 123 deg
        # (1/2.55" sensor), telephoto 22 deg.
        ("google-pixel-9-pro-main", 82.0, 0.005),
        ("google-pixel-9-pro-ultrawide", 123.0, 0.005),
        ("google-pixel-9-pro-telephoto", 22.0, 0.005),
        # Google Pixel 8 Pro tech specs: wide 82 deg, ultrawide 125.5 deg (also in Neowin's print of
        # the spec sheet), telephoto 21.8 deg.
        ("google-pixel-8-pro-main", 82.0, 0.005),
        ("google-pixel-8-pro-ultrawide", 125.5, 0.005),
        ("google-pixel-8-pro-telephoto", 21.8, 0.005),
        # Samsung Galaxy S23 Ultra specifications: 85, 120, 36 and 11 deg.
        ("samsung-galaxy-s23-ultra-main", 85.0, 0.005),
        ("samsung-galaxy-s23-ultra-ultra-wide", 120.0, 0.005),
        ("samsung-galaxy-s23-ultra-3x", 36.0, 0.005),
        ("samsung-galaxy-s23-ultra-10x", 11.0, 0.005),
        # Apple iPhone 15 Pro technical specifications: ultra wide "13 mm ... 120 deg field of view"
        # (focal length from the 13 mm equivalent).
        ("apple-iphone-15-pro-ultra-wide", 120.0, 0.02),
        # Apple iPhone 16 Pro list: ultra wide 13 mm and 120 deg, telephoto 120 mm and 20 deg; iPhone
        # 17 Pro: ultra wide 13 mm and 120 deg (focal lengths from the stated equivalents).
        ("apple-iphone-16-pro-ultra-wide", 120.0, 0.02),
        ("apple-iphone-16-pro-telephoto", 20.0, 0.03),
        ("apple-iphone-17-pro-ultra-wide", 120.0, 0.02),
        # Phonesaaz's Galaxy S24 Ultra list: ultra wide 120 deg.
        ("samsung-galaxy-s24-ultra-ultra-wide", 120.0, 0.005),
        # GSMArena's Nothing Phone (1) spec list: ultra wide 114 deg.
        ("nothing-phone-1-ultra-wide", 114.0, 0.005),
    ],
)
def test_phone_field_of_view_against_the_stated_figure(lens_id, fov_deg, rel):
    record = next(r for r in lens_records() if r["id"] == lens_id)
    diagonal = load_db().sensor(record["sensor"]).diagonal_mm
    computed = math.degrees(2.0 * math.atan(diagonal / (2.0 * record["focal_length_mm"])))
    assert computed == pytest.approx(fov_deg, rel=rel)


# --- closest focus against maximum magnification --------------------------------------------


def thin_lens_magnification(focal_mm: float, distance_mm: float) -> float | None:
    """The magnification (< 1 root) of a unit-focusing thin lens at object-to-image distance D.

    D = f (2 + m + 1/m); no real solution when D < 4 f (no thin lens of that focal length
    focuses there, so the published figure comes from a lens that is not one).
    """
    k = distance_mm / focal_mm - 2.0
    if k < 2.0:
        return None
    return (k - math.sqrt(k * k - 4.0)) / 2.0


# Lenses whose published magnification is below what a unit-focusing thin lens of their nominal
# focal length gives at their closest focus. For these the combination is real, not a data error:
# they focus by moving an inner group, and their focal length at close focus is shorter than the
# nominal one (the EF 70-200 III is about 172 mm at 1.2 m: 1.2 m and 0.21x give f = D / (2 + m + 1/m)).
# Contrary to the expectation that internal focusing reaches *more* magnification than the thin-lens
# figure, nearly every modern telephoto, zoom at its long end and fast standard prime reaches less,
# so the list is long; the internal-focus model will replace it. A lens missing from it whose figures
# come out low is either a new internal-focus lens (add it, with the check below still true) or has
# its closest focus and magnification from different focal lengths or focus modes (a data error:
# the RF 24-70's 0.30x at 32 mm paired with 0.38 m at 70 mm, the Leica Q3's 0.3 m paired with its
# macro-mode magnification).
SHORTER_AT_CLOSE_FOCUS = {
    # primes
    ("canon-rf-50mm-f1.8-stm", 50.0), ("canon-rf-85mm-f1.2l-usm", 85.0), ("canon-ts-e-90mm-f2.8l-macro", 90.0),
    ("nikon-z-50mm-f1.8-s", 50.0), ("nikon-z-85mm-f1.8-s", 85.0), ("sony-fe-50mm-f1.8", 50.0),
    ("sony-fe-85mm-f1.8", 85.0), ("fujifilm-xf23mm-f2-r-wr", 23.0), ("fujifilm-xf56mm-f1.2-r-wr", 56.0),
    # (the Hasselblad XCD 3,5/45 left this list when its unsourced 1:7 became the datasheet's 1:6.4, more than a
    # unit-focusing 45 mm lens reaches at 0.40 m: tests/test_lens_confirmations.py)
    ("fujifilm-gf110mm-f2-r-lm-wr", 110.0),
    ("canon-rf-85mm-f2-macro-is-stm", 85.0),
    ("nikon-z-28mm-f2.8", 28.0), ("nikon-z-40mm-f2", 40.0), ("sony-fe-50mm-f2.5-g", 50.0),
    # super-telephotos
    ("canon-rf-600mm-f4l-is-usm", 600.0), ("canon-rf-800mm-f11-is-stm", 800.0), ("nikon-z-600mm-f6.3-vr-s", 600.0),
    ("nikon-z-400mm-f2.8-tc-vr-s", 400.0), ("sony-fe-600mm-f4-gm-oss", 600.0), ("sony-fe-400mm-f2.8-gm-oss", 400.0),
    # zooms at the focal length of the published magnification
    ("canon-ef-70-200mm-f2.8l-is-iii-usm", 200.0), ("canon-ef-s-18-55mm-f3.5-5.6-is-stm", 55.0),
    ("nikon-z-24-70mm-f4-s", 70.0), ("nikon-z-70-200mm-f2.8-vr-s", 200.0), ("fujifilm-xf18-55mm-f2.8-4-r-lm-ois", 55.0),
    ("olympus-m-zuiko-12-40mm-f2.8-pro", 40.0), ("tamron-28-75mm-f2.8-di-iii-rxd", 75.0),
    ("nikon-z-24-70mm-f2.8-s", 70.0),
    ("nikon-z-180-600mm-f5.6-6.3-vr", 600.0),
    ("sony-fe-200-600mm-f5.6-6.3-g-oss", 600.0),
    ("canon-rf-24-105mm-f2.8l-is-usm-z", 105.0), ("sigma-18-50mm-f2.8-dc-dn-contemporary", 50.0),
    ("sony-fe-28-70mm-f2-gm", 70.0), ("tamron-70-180mm-f2.8-di-iii-vxd", 180.0),
    # 0.38 m with 1:4.5 and 1:4.6 imply about 57 mm and 56 mm at the 70 mm end.
    ("sigma-24-70mm-f2.8-dg-dn-art", 70.0), ("sigma-28-70mm-f2.8-dg-dn-contemporary", 70.0),
    # 0.3 m with 1:2.6 and 0.85 m with 1:4.7 imply about 60 mm at 70 mm and 123 mm at 180 mm.
    ("tamron-70-180mm-f2.8-di-iii-vc-vxd-g2", 70.0), ("tamron-70-180mm-f2.8-di-iii-vc-vxd-g2", 180.0),
    # one closest focus for the zoom with the magnification at the long end: about 158 mm and 169 mm there
    ("nikon-af-s-70-200mm-f2.8e-fl-ed-vr", 200.0), ("nikon-af-s-70-200mm-f4g-ed-vr", 200.0),
    # internal focusing: about 52 mm and 254 mm at the closest focus
    ("sigma-56mm-f1.4-dc-dn-contemporary", 56.0), ("hasselblad-hc-300mm-f4.5", 292.0),
    # 0.9 m with 0.14x at the long end: about 97 mm there
    ("olympus-zuiko-digital-ed-40-150mm-f4-5.6", 150.0),
    # 0.29 m with 1:5.2 at the long end: about 39 mm there
    ("olympus-zuiko-digital-14-42mm-f3.5-5.6-ed", 42.0),
    # internal focusing: 0.82 m with 0.2x and 0.22 m with 0.24x imply about 114 mm and 34 mm
    ("nikon-z-135mm-f1.8-s-plena", 135.0), ("sony-fe-35mm-f1.8", 35.0),
    # 0.35 m with 1:5.8 at the long end: about 44 mm there
    ("nikon-z-24-50mm-f4-6.3", 50.0),
    # third-party-lenses.yaml: 0.85 m with 1:5.9, 0.6 m with 1:3.1, 1.5 m with 1:5 imply about 105, 111 and
    # 208 mm at those ends; 0.15 m with 1:2 about 33 mm for the 35 mm prime
    ("tamron-35-150mm-f2-2.8-di-iii-vxd", 150.0), ("tamron-150-500mm-f5-6.7-di-iii-vc-vxd", 150.0),
    ("tamron-70-300mm-f4.5-6.3-di-iii-rxd", 300.0), ("tamron-35mm-f2.8-di-iii-osd-m1-2", 35.0),
    # maker-lenses.yaml: 2 m with 0.16x and 0.7 m with 0.08x imply about 238 mm and 48 mm (internal focusing)
    ("sony-fe-300mm-f2.8-gm-oss", 300.0), ("fujifilm-xf50mm-f1-r-wr", 50.0),
    # 0.8 m with 0.25x and 3.3 m with 0.2x imply about 128 mm and 458 mm at the ends of the RF 200-800
    ("canon-rf-200-800mm-f6.3-9-is-usm", 200.0), ("canon-rf-200-800mm-f6.3-9-is-usm", 800.0),
    # third-party-lenses.yaml, the later additions: 0.5 m with 1:7.2 implies about 54 mm for the Sigma 60mm DN
    ("sigma-60mm-f2.8-dn-art", 60.0),
    # 0.27 m with 1:4.5 at 50 mm and 4.0 m with 1:9.5 imply about 40 mm and 345 mm (Tamron 17-50mm A16,
    # Sigma APO 400mm)
    ("tamron-sp-af-17-50mm-f2.8-xr-di-ii-ld-a16", 50.0), ("sigma-400mm-f5.6-apo", 400.0),
    # 0.4 m with 0.161x imply about 48 mm at the closest focus (Sigma 50mm F1.2 DG DN Art, internal focusing)
    ("sigma-50mm-f1.2-dg-dn-art", 50.0),
    # 0.39 m with 1:2 implies about 87 mm (Tamron SP AF 90mm F/2.5 52E)
    ("tamron-sp-af-90mm-f2.5-macro-52e", 90.0),
    # current-lenses.yaml: 0.39 m with 0.18x at the 70 mm end implies about 50 mm there (RF 28-70 F2 L)
    ("canon-rf-28-70mm-f2l-usm", 70.0),
    # internal focusing: 4.5 m with 0.14x, 0.35 m with 0.19x and 0.49 m with 0.2x imply about 485 mm, 47 mm
    # and 68 mm (RF 600mm F11, RF 24-50mm at 50 mm, RF 70-200mm F2.8 Z at 70 mm)
    ("canon-rf-600mm-f11-is-stm", 600.0), ("canon-rf-24-50mm-f4.5-6.3-is-stm", 50.0),
    ("canon-rf-70-200mm-f2.8l-is-usm-z", 70.0),
    # internal focusing: 0.4 m with 0.15x, 0.85 m with 0.12x and 0.7 m with 0.26x imply about 45, 81 and
    # 115 mm (RF 50mm F1.4 L VCM, RF 85mm F1.2 L DS, RF 135mm F1.8 L)
    ("canon-rf-50mm-f1.4l-vcm", 50.0), ("canon-rf-85mm-f1.2l-usm-ds", 85.0), ("canon-rf-135mm-f1.8l-is-usm", 135.0),
    # 2.5 m with 0.17x implies about 311 mm (RF 400mm F2.8 L, internal focusing)
    ("canon-rf-400mm-f2.8l-is-usm", 400.0),
    # 2.4 m with 0.24x at the long end implies about 375 mm there (Fujifilm XF150-600mm)
    ("fujifilm-xf150-600mm-f5.6-8-r-lm-ois-wr", 600.0),
    # sony-lenses.yaml, internal focusing: 0.35 m with 0.12x, 0.28 m with 0.2x, 0.41 m with 0.16x, 0.85 m with
    # 0.12x and 0.11x, 0.57 m with 0.25x, 0.7 m with 0.25x imply about 34, 39, 49, 81, 76, 91 and 112 mm (FE 35mm
    # F2.8 ZA, 40mm F2.5 G, 50mm F1.4 GM, 85mm F1.4 GM and GM II, 100mm STF in its macro range, 135mm F1.8 GM);
    # 0.2 m with 0.12x, 0.3 m with 0.15x and 0.39 m with 0.16x about 19, 34 and 46 mm (E 20mm, 35mm and 50mm)
    ("sony-fe-35mm-f2.8-za", 35.0), ("sony-fe-40mm-f2.5-g", 40.0), ("sony-fe-50mm-f1.4-gm", 50.0),
    ("sony-fe-85mm-f1.4-gm", 85.0), ("sony-fe-85mm-f1.4-gm-ii", 85.0), ("sony-fe-100mm-f2.8-stf-gm-oss", 100.0),
    ("sony-fe-135mm-f1.8-gm", 135.0), ("sony-e-20mm-f2.8", 20.0), ("sony-e-35mm-f1.8-oss", 35.0),
    ("sony-e-50mm-f1.8-oss", 50.0),
    # independent-lenses.yaml, internal focusing: 0.85 m with 0.119x, 1.1 m with 0.145x, 1.7 m with 0.132x and
    # 3.2 m with 0.167x imply about 81, 122, 175 and 392 mm (Sigma 85mm F1.4 DG DN, 135mm F1.4 DG, 200mm F2 DG OS,
    # 500mm F5.6 DG DN); 0.27 m with 0.175x, 0.24 m with 0.25x, 0.55 m with 0.147x and 0.5 m with 0.2x imply
    # about 34, 38, 62 and 69 mm (Sigma 35mm F2, 45mm F2.8, 65mm F2 and 90mm F2.8 DG DN); 0.22 m with 1:2 at
    # 50 mm about 49 mm (Tamron 50-300mm A069)
    ("sigma-85mm-f1.4-dg-dn-art", 85.0), ("sigma-135mm-f1.4-dg-art", 135.0),
    ("sigma-200mm-f2-dg-os-sports", 200.0), ("sigma-500mm-f5.6-dg-dn-os-sports", 500.0),
    ("sigma-35mm-f2-dg-dn-contemporary", 35.0), ("sigma-45mm-f2.8-dg-dn-contemporary", 45.0),
    ("sigma-65mm-f2-dg-dn-contemporary", 65.0), ("sigma-90mm-f2.8-dg-dn-contemporary", 90.0),
    ("tamron-50-300mm-f4.5-6.3-di-iii-vc-vxd", 50.0),
    # more-maker-lenses.yaml, internal focusing: 0.33 m with 0.22x at 60 mm (Lumix S 24-60mm), 0.8 m with
    # 0.16x at 100 mm (S 100-500mm), 1.4 m with 0.24x (M.Zuiko 300mm F4) and 2.8 m with 0.20x at 600 mm
    # (M.Zuiko 150-600mm) imply about 49, 95, 219 and 389 mm; the primes' two-figure magnifications imply
    # 37-81 mm for the S 40, 50 and 85mm, 41 mm for the Nocticron 42.5mm and the M.Zuiko 45mm F1.2, 69 mm for
    # the M.Zuiko 75mm and 24 mm for the M.Zuiko 25mm F1.8 II
    ("panasonic-lumix-s-24-60mm-f2.8", 60.0), ("panasonic-lumix-s-100-500mm-f5-7.1-ois", 100.0),
    ("om-m-zuiko-300mm-f4-is-pro", 300.0), ("om-m-zuiko-150-600mm-f5-6.3-is", 600.0),
    ("panasonic-lumix-s-40mm-f2", 40.0), ("panasonic-lumix-s-50mm-f1.8", 50.0), ("panasonic-lumix-s-85mm-f1.8", 85.0),
    ("panasonic-leica-dg-nocticron-42.5mm-f1.2", 42.5), ("om-m-zuiko-45mm-f1.2-pro", 45.0),
    ("om-m-zuiko-75mm-f1.8", 75.0), ("om-m-zuiko-25mm-f1.8-ii", 25.0),
    # 1:5 at 0.35, 0.5 and 0.6 m imply about 49, 69 and 83 mm (APO-Summicron-SL 50, 75, 90, internal focusing)
    ("leica-apo-summicron-sl-50mm-f2-asph", 50.0), ("leica-apo-summicron-sl-75mm-f2-asph", 75.0),
    ("leica-apo-summicron-sl-90mm-f2-asph", 90.0),
    # nikon-fujifilm-lenses.yaml, internal focusing: 0.33 m with 0.32x at 70 mm, 0.85 m with 0.11x, 0.267 m with
    # 0.5x, 0.39 m with 0.15x, 2.75 m with 0.2x and 1.75 m with 0.19x at 400 mm imply about 61, 76, 59, 44, 382
    # and 235 mm (NIKKOR Z 24-70mm f/2.8 S II, Z 85mm f/1.2 S; XF60mm Macro, XF50mm F2, XF500mm, XF100-400mm)
    ("nikon-z-24-70mm-f2.8-s-ii", 70.0), ("nikon-z-85mm-f1.2-s", 85.0), ("fujifilm-xf60mm-f2.4-r-macro", 60.0),
    ("fujifilm-xf50mm-f2-r-wr", 50.0), ("fujifilm-xf500mm-f5.6-r-lm-ois-wr", 500.0),
    ("fujifilm-xf100-400mm-f4.5-5.6-r-lm-ois-wr", 400.0),
    # 0.38 m with 0.3x at 70 mm and 0.8 m with 0.25x at 200 mm imply about 67 and 128 mm (NIKKOR Z 70-200mm f/2.8
    # VR S II); 0.6 m with 0.2x at 120 mm, 0.6 m with 0.2x at 100 mm, 0.35 m with 0.28x at 70 mm and 2.75 m with 0.2x
    # imply about 83, 83, 60 and 382 mm (XF18-120mm, GF100-200mm, GF35-70mm, GF500mm)
    ("nikon-z-70-200mm-f2.8-vr-s-ii", 70.0), ("nikon-z-70-200mm-f2.8-vr-s-ii", 200.0),
    ("fujifilm-xf18-120mm-f4-lm-pz-wr", 120.0),
    ("fujifilm-gf100-200mm-f5.6-r-lm-ois-wr", 100.0), ("fujifilm-gf35-70mm-f4.5-5.6-wr", 70.0),
    ("fujifilm-gf500mm-f5.6-r-lm-ois-wr", 500.0),
    # 1.1 m with 0.18x at the long end implies about 142 mm there (XF55-200mm, internal focusing)
    ("fujifilm-xf55-200mm-f3.5-4.8-r-lm-ois", 200.0),
    # medium-format-pentax-leica-lenses.yaml, internal focusing: 0.7 m with 0.12x, 0.85 m with 0.12x and 1.4 m with
    # 0.24x imply about 67, 81 and 219 mm (HD PENTAX-DA 70mm Limited, D FA★85mm, smc DA★300mm [IF])
    ("pentax-hd-da-70mm-f2.4-limited", 70.0), ("pentax-hd-d-fa-star-85mm-f1.4-ed-sdm-aw", 85.0),
    ("pentax-smc-da-star-300mm-f4-ed-if-sdm", 300.0),
    # viltrox-samyang-lenses.yaml, internal focusing: 0.35 m with 0.12x implies about 33 mm (Samyang AF 35mm F2.8 FE)
    ("samyang-af-35mm-f2.8-fe", 35.0),
    # viltrox-samyang-lenses.yaml, internal focusing by one negative inner element: 0.6 m with 0.1x implies about
    # 50 mm (Viltrox AF 56mm F1.4; its design analysis traces the patent's 0.63 m state to 0.088x)
    ("viltrox-af-56mm-f1.4", 56.0),
    # more-current-lenses.yaml, internal focusing: 0.37 m with 0.17x implies about 46 mm (NIKKOR Z 50mm f/1.4)
    ("nikon-z-50mm-f1.4", 50.0),
}


def close_focus_pairs():
    """(lens id, focal length, closest focus, magnification) wherever a source pairs the two figures."""
    for record in lens_records():
        # The design lenses (with a prescription) publish no closest focus; a retail lens with a
        # prescription keeps its maker's figures and is checked like any other.
        if record.get("category") == "phone":
            continue
        if "close_focus" in record:
            for row in record["close_focus"]:
                if "max_magnification" in row:
                    yield record["id"], row["focal_length_mm"], row["min_focus_mm"], row["max_magnification"]
        elif "focal_length_mm" in record and "min_focus_mm" in record and "max_magnification" in record:
            yield record["id"], record["focal_length_mm"], record["min_focus_mm"], record["max_magnification"]


def test_closest_focus_and_magnification_are_physically_possible():
    impossible = []
    for lens_id, focal, distance, magnification in close_focus_pairs():
        thin = thin_lens_magnification(focal, distance)
        if thin is not None and magnification < thin * 0.97 and (lens_id, focal) not in SHORTER_AT_CLOSE_FOCUS:
            impossible.append(f"{lens_id} at {focal:g} mm: {magnification:g}x at {distance:g} mm, "
                              f"a unit-focusing {focal:g} mm lens gives {thin:.3f}x")
    assert impossible == []


def test_listed_exceptions_are_still_exceptions():
    pairs = {(lens_id, focal): (distance, m) for lens_id, focal, distance, m in close_focus_pairs()}
    for key in SHORTER_AT_CLOSE_FOCUS:
        distance, magnification = pairs[key]
        thin = thin_lens_magnification(key[1], distance)
        assert thin is not None and magnification < thin * 0.97, key
        # The focal length that the published pair implies is shorter than the nominal one, never
        # absurdly so (a closest focus from the other end of a zoom would give a tiny one).
        implied = distance / (2 + magnification + 1 / magnification)
        assert 0.3 * key[1] < implied < key[1], key


def test_zoom_rows_agree_with_the_lens_level_figures():
    for record in lens_records():
        rows = record.get("close_focus")
        if rows is None:
            continue
        assert record["min_focus_mm"] == min(r["min_focus_mm"] for r in rows), record["id"]
        published = [r["max_magnification"] for r in rows if "max_magnification" in r]
        assert not published or record["max_magnification"] >= max(published), record["id"]
        assert rows[0]["focal_length_mm"] == record["focal_min_mm"], record["id"]
        assert rows[-1]["focal_length_mm"] == record["focal_max_mm"], record["id"]


def test_every_shipped_zoom_has_per_focal_length_rows():
    for record in lens_records():
        if "focal_min_mm" in record and record.get("category") not in ("cine", "phone"):
            assert "close_focus" in record, record["id"]


# --- closest focus and magnification against the cited pages ----------------------------------

# (lens, focal length, closest focus mm, magnification or None) as the page cited in each entry's
# source gives them; each row must be in the entry (its close_focus row, or the prime's own figures).
CITED_CLOSE_FOCUS = [
    # Photography Life, Nikon Z 24-70mm f/2.8 S review p. 2: 0.38 m, 0.22x.
    ("nikon-z-24-70mm-f2.8-s", 70, 380, 0.22),
    # Nikon's Z 24-120mm f/4 S page as quoted in Photography Stack Exchange q. 132297: 0.35 m, 0.39x.
    ("nikon-z-24-120mm-f4-s", 24, 350, None), ("nikon-z-24-120mm-f4-s", 120, 350, 0.39),
    # Photo Review / desnoulez.fr: 0.16 m, 1:1.
    ("nikon-z-mc-50mm-f2.8", 50, 160, 1.0),
    # OpticalLimits: 0.17 m, 1:2.
    ("canon-rf-35mm-f1.8-macro-is-stm", 35, 170, 0.5),
    # DPReview hands-on / Digital Camera World: 0.9 m at 100 mm, 1.2 m and 0.33x at 500 mm.
    ("canon-rf-100-500mm-f4.5-7.1l-is-usm", 100, 900, None), ("canon-rf-100-500mm-f4.5-7.1l-is-usm", 500, 1200, 0.33),
    # Digital Camera World / Photo Review: 6 m, 0.14x.
    ("canon-rf-800mm-f11-is-stm", 800, 6000, 0.14),
    # Wikipedia infobox / Photography Life: 2.4 m, 0.2x.
    ("sony-fe-200-600mm-f5.6-6.3-g-oss", 200, 2400, None), ("sony-fe-200-600mm-f5.6-6.3-g-oss", 600, 2400, 0.2),
    # savazzi.net and Eric Svendsen's blog: 1.3 m at 180 mm, 2.4 m at 600 mm, 0.25x.
    ("nikon-z-180-600mm-f5.6-6.3-vr", 180, 1300, None), ("nikon-z-180-600mm-f5.6-6.3-vr", 600, 2400, 0.25),
    # Le Monde de la Photo: 0.3 m at every focal length, 0.5x.
    ("panasonic-lumix-s-24-105mm-f4-macro-ois", 24, 300, None),
    ("panasonic-lumix-s-24-105mm-f4-macro-ois", 105, 300, 0.5),
    # Photography Life announcement: 0.28 m, 0.21x.
    ("canon-rf-15-35mm-f2.8l-is-usm", 15, 280, None), ("canon-rf-15-35mm-f2.8l-is-usm", 35, 280, 0.21),
    # The Phoblographer (Canon's table): 0.25 m and 0.11x at 16 mm, 0.2 m and 0.26x at 28 mm.
    ("canon-rf-16-28mm-f2.8-is-stm", 16, 250, 0.11), ("canon-rf-16-28mm-f2.8-is-stm", 28, 200, 0.26),
    # Photography Life announcement: 45 cm; 0.08x at 24 mm, 0.29x at 105 mm.
    ("canon-rf-24-105mm-f2.8l-is-usm-z", 24, 450, 0.08), ("canon-rf-24-105mm-f2.8l-is-usm-z", 105, 450, 0.29),
    # Camera Jabber: 0.88 m, 0.41x.
    ("canon-rf-100-400mm-f5.6-8-is-usm", 100, 880, None), ("canon-rf-100-400mm-f5.6-8-is-usm", 400, 880, 0.41),
    # Photography Life announcement: 0.25 m, 0.15x.
    ("nikon-z-24mm-f1.8-s", 24, 250, 0.15),
    # PetaPixel: 0.19 m, 0.2x.
    ("nikon-z-28mm-f2.8", 28, 190, 0.2),
    # Photography Life announcement: 0.29 m, 0.17x (1:5.9).
    ("nikon-z-40mm-f2", 40, 290, 0.17),
    # Digital Camera World / Photography Life reviews: 0.45 m, 0.15x.
    ("nikon-z-50mm-f1.2-s", 50, 450, 0.15),
    # Bright Publishing 'First test': 19 cm at 28 mm (0.34x), 22 cm at 50 mm, 39 cm at 75 mm.
    ("nikon-z-28-75mm-f2.8", 28, 190, 0.34), ("nikon-z-28-75mm-f2.8", 50, 220, None),
    ("nikon-z-28-75mm-f2.8", 75, 390, None),
    # PetaPixel via todayschronic.com / PRONEWS: 0.18 m at 24 mm, 0.29 m at 50 mm (manual focus).
    ("sony-fe-24-50mm-f2.8-g", 24, 180, None), ("sony-fe-24-50mm-f2.8-g", 50, 290, None),
    # Alpha Shooters: 350 mm, 0.18x (autofocus).
    ("sony-fe-50mm-f2.5-g", 50, 350, 0.18),
    # DPReview field review: 0.83 m over the range, 0.33x at the tele end.
    ("fujifilm-xf70-300mm-f4-5.6-r-lm-ois-wr", 70, 830, None),
    ("fujifilm-xf70-300mm-f4-5.6-r-lm-ois-wr", 300, 830, 0.33),
    # Phototrend: 12.1 cm and 0.36x at 18 mm, 30 cm and 0.2x at 50 mm.
    ("sigma-18-50mm-f2.8-dc-dn-contemporary", 18, 121, 0.36),
    ("sigma-18-50mm-f2.8-dc-dn-contemporary", 50, 300, 0.2),
    # Shutterbug News / Galaxus: 38 cm, 0.23x.
    ("sony-fe-28-70mm-f2-gm", 28, 380, None), ("sony-fe-28-70mm-f2-gm", 70, 380, 0.23),
    # Fstoppers / Photozone: 27 cm and 1:2 at 70 mm (manual focus), 0.85 m and 1:4.6 at 180 mm.
    ("tamron-70-180mm-f2.8-di-iii-vxd", 70, 270, 0.5), ("tamron-70-180mm-f2.8-di-iii-vxd", 180, 850, 0.217),
    # Test Materiel (testmateriel.com) review: 0,45 m, 0,29x (one closest focus for the zoom).
    ("sony-e-18-135mm-f3.5-5.6-oss", 18, 450, None), ("sony-e-18-135mm-f3.5-5.6-oss", 135, 450, 0.29),
    # Canon Asia SNAPSHOT, Centre Focus Macro article: 20 cm and 0.21x at 24 mm (AF), 34 cm and 0.40x at 105 mm.
    ("canon-rf-24-105mm-f4-7.1-is-stm", 24, 200, 0.21), ("canon-rf-24-105mm-f4-7.1-is-stm", 105, 340, 0.4),
    # Nikon's catalogue figures on the tessue-photo blog: 0.27/0.33/0.42/0.58/0.85 m at 70/85/105/135/180 mm,
    # 0.48x (digitalkamera.de: 27 cm at 70 mm, 85 cm at 180 mm).
    ("nikon-z-70-180mm-f2.8", 70, 270, 0.48), ("nikon-z-70-180mm-f2.8", 85, 330, None),
    ("nikon-z-70-180mm-f2.8", 105, 420, None), ("nikon-z-70-180mm-f2.8", 135, 580, None),
    ("nikon-z-70-180mm-f2.8", 180, 850, None),
    # ora.it.com (Nikon's table): 0.5 m at 24 mm, 0.7 m at 200 mm, 0.28x.
    ("nikon-z-24-200mm-f4-6.3-vr", 24, 500, None), ("nikon-z-24-200mm-f4-6.3-vr", 200, 700, 0.28),
    # Japanese four-zoom comparison (prod-news.global.ssl.fastly.net 20180629-656222/3): 0.38 m, 0.31x.
    ("sony-fe-24-105mm-f4-g-oss", 24, 380, None), ("sony-fe-24-105mm-f4-g-oss", 105, 380, 0.31),
    # Le Monde de la Photo: 15 cm and 0.43x at 20 mm, 40 cm at 60 mm.
    ("panasonic-lumix-s-20-60mm-f3.5-5.6", 20, 150, 0.43), ("panasonic-lumix-s-20-60mm-f3.5-5.6", 60, 400, None),
    # Le Monde de la Photo: 18 cm and 1:2.9 at the wide end, 38 cm and 1:4.5 at the long end.
    ("sigma-24-70mm-f2.8-dg-dn-art", 24, 180, 0.345), ("sigma-24-70mm-f2.8-dg-dn-art", 70, 380, 0.222),
    # lens-db.com: 0.19 m at 28 mm, 0.38 m and 1:4.6 at 70 mm.
    ("sigma-28-70mm-f2.8-dg-dn-contemporary", 28, 190, None),
    ("sigma-28-70mm-f2.8-dg-dn-contemporary", 70, 380, 0.217),
    # ScubaPortal (Tamron's figures): 19 cm and 1:5.2 at 17 mm, 26 cm and 1:6 at 28 mm.
    ("tamron-17-28mm-f2.8-di-iii-rxd", 17, 190, 0.192), ("tamron-17-28mm-f2.8-di-iii-rxd", 28, 260, 0.167),
    # Amateur Photographer: 29 cm, 0.13x.
    ("sony-fe-28mm-f2", 28, 290, 0.13),
    # ora.it.com (Nikon's table): 1.1 m, 0.21x; Nikon School Italia: 1 m, 0.274x.
    ("nikon-af-s-70-200mm-f2.8e-fl-ed-vr", 200, 1100, 0.21), ("nikon-af-s-70-200mm-f4g-ed-vr", 200, 1000, 0.274),
    # Sigma's page quoted on Canon Rumors: 50 cm, 1:7.4.
    ("sigma-56mm-f1.4-dc-dn-contemporary", 56, 500, 0.135),
    # Hasselblad's data sheets: 0.60 m and 1:8,8 (50,7 mm); 2.45 m and 1:7.5 (292 mm).
    ("hasselblad-hc-50mm-f3.5-ii", 50.7, 600, 0.114), ("hasselblad-hc-300mm-f4.5", 292, 2450, 0.133),
    # Olympus's specification pages: 0.2 m and 0.08x; 0.9 m and 0.14x (one closest focus for the zoom).
    ("olympus-m-zuiko-digital-12mm-f2", 12, 200, 0.08), ("olympus-zuiko-digital-ed-40-150mm-f4-5.6", 40, 900, None),
    ("olympus-zuiko-digital-ed-40-150mm-f4-5.6", 150, 900, 0.14),
    # Digital Camera World: 0.093 m and 1.2x; Sony's SAL20F28 service manual: 0.25 m and 0.13x.
    ("canon-ef-m-28mm-f3.5-macro-is-stm", 28, 93, 1.2), ("sony-20mm-f2.8-sal20f28", 20, 250, 0.13),
    # photozone.de's specification table: 0.29 m, 1:5.2 (one closest focus for the zoom).
    ("olympus-zuiko-digital-14-42mm-f3.5-5.6-ed", 14, 290, None),
    ("olympus-zuiko-digital-14-42mm-f3.5-5.6-ed", 42, 290, 0.192),
    # Photofocus (Tamron's list): 0.3 m and 1:2.6 at 70 mm, 0.85 m and 1:4.7 at 180 mm.
    ("tamron-70-180mm-f2.8-di-iii-vc-vxd-g2", 70, 300, 0.385),
    ("tamron-70-180mm-f2.8-di-iii-vc-vxd-g2", 180, 850, 0.213),
    # utopia-photography.ch (Nikon's table): 0.2 m from the sensor, 0.19x.
    ("nikon-z-20mm-f1.8-s", 20, 200, 0.19),
    # Digital Camera World review (inkl.com copy): 0.2 m, 0.19x.
    ("nikon-z-26mm-f2.8", 26, 200, 0.19),
    # Photography Life announcement: 0.82 m, 0.2x.
    ("nikon-z-135mm-f1.8-s-plena", 135, 820, 0.2),
    # Photography Life announcement: 34 cm at 28 mm, 57 cm at 135 mm (the 0.25x on no row).
    ("nikon-z-28-135mm-f4-pz", 28, 340, None), ("nikon-z-28-135mm-f4-pz", 135, 570, None),
    # Photography Life review / Canon Singapore: 14 cm, 0.5x.
    ("canon-rf-24mm-f1.8-macro-is-stm", 24, 140, 0.5),
    # anotherlounge.jp: 22 cm, 0.24x.
    ("sony-fe-35mm-f1.8", 35, 220, 0.24),
    # Photo Review: 35 cm at all settings, 1:5.8 at 50 mm.
    ("nikon-z-24-50mm-f4-6.3", 24, 350, None), ("nikon-z-24-50mm-f4-6.3", 50, 350, 0.172),
    # Neocamera: 50 cm at 50 mm, 1 m at 250 mm (the 0.23x on no row).
    ("nikon-z-dx-50-250mm-f4.5-6.3-vr", 50, 500, None), ("nikon-z-dx-50-250mm-f4.5-6.3-vr", 250, 1000, None),
    # Fujifilm's 'XF16mm' story: 15 cm from the sensor; 1:0.21.
    ("fujifilm-xf16mm-f1.4-r-wr", 16, 150, 0.21),
    # isamu/lens-database sony/e/fe-zoom.js (Sony Japan's page): 最短撮影距離0.4m(ワイド端)/望遠端0.82m, 0.3;
    # LensVisualizer: 0.40 m at 70 mm and 0.82 m at 200 mm, 0.30x (on no row).
    ("sony-fe-70-200mm-f2.8-gm-oss-ii", 70, 400, None), ("sony-fe-70-200mm-f2.8-gm-oss-ii", 200, 820, None),
    # polynomial/camera's transcriptions of Canon Japan's pages: 最短撮影距離 0.45m, 0.24倍 (on no row); 0.7m,
    # 0.23倍（200mm時）; 0.35m, 0.5倍.
    ("canon-rf-24-105mm-f4l-is-usm", 24, 450, None), ("canon-rf-24-105mm-f4l-is-usm", 105, 450, None),
    ("canon-rf-70-200mm-f2.8l-is-usm", 70, 700, None), ("canon-rf-70-200mm-f2.8l-is-usm", 200, 700, 0.23),
    ("canon-rf-85mm-f2-macro-is-stm", 85, 350, 0.5),
    # LensVisualizer (Sony's figures) and isamu/lens-database sony/e/fe-prime.js: 0.24 m, 0.17x.
    ("sony-fe-24mm-f1.4-gm", 24, 240, 0.17),
    # LensVisualizer (Fujifilm's specifications): GF63mm 0.50 m and 0.17x; GF110mm MFD = 0.9 m, 0.16x.
    ("fujifilm-gf63mm-f2.8-r-wr", 63, 500, 0.17), ("fujifilm-gf110mm-f2-r-lm-wr", 110, 900, 0.16),
    # LensVisualizer (FUJIFILM's specifications): 0.30 m from the sensor plane, 0.15x.
    ("fujifilm-xf33mm-f1.4-r-lm-wr", 33, 300, 0.15),
    # LensVisualizer (FUJIFILM's published figures) and photosanpo.com: 0.50 m from the focal plane; 0.14x.
    ("fujifilm-xf56mm-f1.2-r-wr", 56, 500, 0.14),
]


@pytest.mark.parametrize(("lens_id", "focal", "distance", "magnification"), CITED_CLOSE_FOCUS)
def test_close_focus_against_the_cited_pages(lens_id, focal, distance, magnification):
    record = next(r for r in lens_records() if r["id"] == lens_id)
    assert not record.get("approximate"), lens_id
    rows = record.get("close_focus") or [
        {"focal_length_mm": record["focal_length_mm"], "min_focus_mm": record["min_focus_mm"],
         "max_magnification": record["max_magnification"]}]
    row = next(r for r in rows if r["focal_length_mm"] == focal)
    assert row["min_focus_mm"] == distance
    assert row.get("max_magnification") == magnification


# (lens, smallest aperture) as the page named in each entry's source or notes gives it, checked whether
# or not the entry's other figures are confirmed; for a variable-aperture zoom the figure at the short
# end, like f_number_min.
CITED_F_NUMBER_MAX = [
    # Amateur Photographer's RF 50mm F1.8 STM review (pressreader.com copy): minimum aperture of f/22.
    ("canon-rf-50mm-f1.8-stm", 22),
    # Digital Camera World, RF 800mm f/11 IS STM review: fixed f/11 aperture.
    ("canon-rf-800mm-f11-is-stm", 11),
    # theartofphotography.tv, NIKKOR Z 50mm f/1.8 S spec list: f/1.8 to f/16 aperture range.
    ("nikon-z-50mm-f1.8-s", 16),
    # Photography Life's Z 24-70mm f/2.8 S / S II table (onlinenews24-7.com copy): aperture range f/2.8-22.
    ("nikon-z-24-70mm-f2.8-s", 22),
    # desnoulez.fr field test of the Z MC 50mm f/2.8: f/2.8-f/22 at infinity.
    ("nikon-z-mc-50mm-f2.8", 22),
    # Wikipedia infobox, Sony FE 200-600mm F5.6-6.3 G OSS: aperture 5.6 (32.0) - 6.3 (36.0).
    ("sony-fe-200-600mm-f5.6-6.3-g-oss", 32),
    # Wikipedia infobox, Canon MP-E 65mm f/2.8 1-5x Macro: aperture f/2.8-f/16.
    ("canon-mp-e-65mm-f2.8-1-5x-macro", 16),
    # Amateur Photographer's FE 28mm F2 review: down to f/22; Hasselblad's HC 50-II and HC 300 data sheets.
    ("sony-fe-28mm-f2", 22), ("hasselblad-hc-50mm-f3.5-ii", 32), ("hasselblad-hc-300mm-f4.5", 45),
    # Olympus's 12mm F2.0 and 40-150mm specification pages: F22; Digital Camera World (EF-M 28mm Macro): f/22;
    # Sony's SAL20F28 service manual: f/22.
    ("olympus-m-zuiko-digital-12mm-f2", 22), ("olympus-zuiko-digital-ed-40-150mm-f4-5.6", 22),
    ("canon-ef-m-28mm-f3.5-macro-is-stm", 22), ("sony-20mm-f2.8-sal20f28", 22),
    # Photo Review, AF-S Nikkor 50mm f/1.8G: the minimum aperture is f/16.
    ("nikon-af-s-50mm-f1.8g", 16),
    # PConline's Z 70-200mm f/2.8 VR S review: f/22, the smallest aperture (tested at 70 and 200 mm).
    ("nikon-z-70-200mm-f2.8-vr-s", 22),
    # zsystemuser.com's Z MC 105mm review: the minimum aperture is f/32 (digitalkamera.de: f/2.8 to f/32).
    ("nikon-z-mc-105mm-f2.8-vr-s", 32),
    # Photography Life's Z 24-70mm f/4 S review (French copy at photo-secret.net): f/4 to f/22.
    ("nikon-z-24-70mm-f4-s", 22),
    # Digital Camera World, RF 100-500mm review: minimum aperture f/32-54 (f/32 at 100 mm).
    ("canon-rf-100-500mm-f4.5-7.1l-is-usm", 32),
    # Smart Photography review of the Tamron A036 (pressreader.com, April 2020): f/2.8-22 throughout.
    ("tamron-28-75mm-f2.8-di-iii-rxd", 22),
    # Leica's description as reproduced by lavidaleica.com: aperture range 1.4 - 16 (1/2 steps).
    ("leica-summilux-m-50mm-f1.4-asph", 16),
    # zakkeys.com, Tamron 17-28mm F/2.8 Di III RXD basic specifications: smallest aperture f/22 throughout.
    ("tamron-17-28mm-f2.8-di-iii-rxd", 22),
    # DPReview's Ricoh GR III page (open-product-data/digital-cameras, database/ricoh_griii.yaml):
    # MaximumAperture F2.8-16; tekgenius.pt's announcement: 18.3mm f/2.8-f/16.
    ("ricoh-gr-iii-lens", 16),
    # Digital Camera World (Z 26mm): f/16; Photography Life (Z 135mm Plena): f/16; (Z 28-135mm PZ): f/22;
    # Photography Life (RF 24mm F1.8 Macro): f/22; sonyalphalab.com (FE 20mm G: f/22, FE 24mm GM: f/16).
    ("nikon-z-26mm-f2.8", 16), ("nikon-z-135mm-f1.8-s-plena", 16), ("nikon-z-28-135mm-f4-pz", 22),
    ("canon-rf-24mm-f1.8-macro-is-stm", 22), ("sony-fe-20mm-f1.8-g", 22), ("sony-fe-24mm-f1.4-gm", 16),
    # polynomial/camera's transcriptions of Canon Japan's pages: 最小絞り 22, 32 and 29.
    ("canon-rf-24-105mm-f4l-is-usm", 22), ("canon-rf-70-200mm-f2.8l-is-usm", 32), ("canon-rf-85mm-f2-macro-is-stm", 29),
]


@pytest.mark.parametrize(("lens_id", "f_number_max"), CITED_F_NUMBER_MAX)
def test_smallest_aperture_against_the_cited_pages(lens_id, f_number_max):
    record = next(r for r in lens_records() if r["id"] == lens_id)
    assert record["f_number_max"] == f_number_max
    assert load_db().lens(lens_id).f_number_max == f_number_max


# --- crop factor against lensfun's ----------------------------------------------------------

# lensfun's <cropfactor> for shipped bodies, from lensfun's data/db/*.xml (lensfun/lensfun on
# GitHub), recorded with the file, commit and camera model string in tests/data/lensfun-crops.yaml.
# camtool's crop factor comes from the maker's own sensor size; the two must agree within 1.5 %.
LENSFUN_DATA = yaml.safe_load((Path(__file__).resolve().parent / "data" / "lensfun-crops.yaml").read_text())
LENSFUN_CROP = {camera: float(entry["cropfactor"]) for camera, entry in LENSFUN_DATA["cameras"].items()}

# Bodies whose crop factor differs from lensfun's by more than 1.5 %, and why. None of the
# shipped bodies listed in tests/data/lensfun-crops.yaml does (the largest difference, 1.0 %, is
# Sony's 35.6 x 23.8 mm against lensfun's 1); the 4x5 format (no lensfun entry) differs from the research
# table's nominal sheet for the reason given in lens_db/sensors.yaml.
CROP_EXCEPTIONS: dict[str, str] = {}


def test_lensfun_crop_data_has_provenance():
    sources = LENSFUN_DATA["sources"]
    for source in sources.values():
        assert source["repository"] == "lensfun/lensfun"
        assert source["path"].startswith("data/db/") and source["path"].endswith(".xml")
        assert len(source["commit"]) == 40
    makers = set()
    for camera, entry in LENSFUN_DATA["cameras"].items():
        assert entry["source"] in sources, camera
        assert entry["model"], camera
        makers.add(camera.split("-")[0])
    # Every maker whose lensfun file lists a shipped body is compared, not only Sony.
    assert {"sony", "canon", "nikon", "leica", "om", "fujifilm", "hasselblad", "olympus", "ricoh"} <= makers


@pytest.mark.parametrize(("camera", "crop"), sorted(LENSFUN_CROP.items()))
def test_crop_factor_against_lensfun(camera, crop):
    body = load_db().camera(camera)
    if camera in CROP_EXCEPTIONS:
        pytest.skip(CROP_EXCEPTIONS[camera])
    assert body.sensor.crop_factor == pytest.approx(crop, rel=0.015)


def test_thin_lens_magnification_known_values():
    # 50 mm at 4f = 200 mm gives 1:1; at 2.5 m (D/f = 50) m = 0.0208 (1/m + m = 48).
    assert thin_lens_magnification(50, 200) == pytest.approx(1.0)
    assert thin_lens_magnification(50, 2500) == pytest.approx(0.020842, rel=1e-4)
    assert thin_lens_magnification(100, 300) is None


# (lens, largest magnification) where the cited sources give the zoom's maximum without placing it at a focal
# length, so no close_focus row above carries it: the entry's max_magnification is that figure.
CITED_LARGEST_MAGNIFICATION = [
    # isamu/lens-database sony/e/fe-zoom.js (Sony Japan's page): maxMagnification 0.3; LensVisualizer: 0.30x.
    ("sony-fe-70-200mm-f2.8-gm-oss-ii", 0.3),
    # polynomial/camera's transcription of Canon Japan's page: 最大撮影倍率 0.24倍.
    ("canon-rf-24-105mm-f4l-is-usm", 0.24),
]


@pytest.mark.parametrize(("lens_id", "largest"), CITED_LARGEST_MAGNIFICATION)
def test_largest_magnification_against_the_cited_pages(lens_id, largest):
    record = next(r for r in lens_records() if r["id"] == lens_id)
    assert not record.get("approximate"), lens_id
    assert record["max_magnification"] == largest
    assert all("max_magnification" not in row for row in record["close_focus"])
    lens = load_db().lens(lens_id)
    for focal in (lens.focal_min_mm, lens.focal_max_mm):
        model = focus_model(lens, focal)
        assert internal_focus_at_distance(model, model.min_focus_mm)[0] <= largest * (1 + 1e-9)
