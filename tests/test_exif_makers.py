"""``camtool exif`` on the makers' own tags: sensor, focus distance and ISO from maker notes, and the warnings.

Each file is made here (a tiny JPEG, tags written by python-exiv2 as in
tests/data/exif/make_images.py); the expected values come from the makers'
encodings as ExifTool documents them (https://exiftool.org/TagNames/, quoted
beside each test) and, where exiftool is installed, from ExifTool itself on
the same files (tests/test_exif_exiftool.py runs it on :func:`maker_files`).
"""

from __future__ import annotations

import json
import math
from pathlib import Path
from typing import Any

import pytest

from tests.cli_helpers import exif_image_maker, run

exiv2 = pytest.importorskip("exiv2")

DATA = Path(__file__).resolve().parent / "data" / "exif"
SAMPLES = Path(__file__).resolve().parent.parent.parent / "shared" / "reference" / "exif-samples"


IMAGES = exif_image_maker()
R, U = IMAGES.rational, IMAGES.ushort
SHOT = [("Exif.Photo.FNumber", R(56, 10)), ("Exif.Photo.ExposureTime", R(1, 250))]
FILES: dict[str, list[tuple[str, Any]]] = {
    # Canon ShotInfo: FocusDistanceUpper 350 cm, Lower 320 cm; CameraISO 15 (auto) with BaseISO code 128 and
    # AutoISO 0: 2^(128/32)·100/32 · 2^0 = 50; FocalLength record (2, 227, 286, 215) with FocalUnits 32
    "canon_shotinfo_pair.jpg": [
        ("Exif.Image.Make", "Canon"), ("Exif.Image.Model", "Canon PowerShot S40"), *SHOT,
        ("Exif.CanonSi.SubjectDistance", U(350)), ("Exif.CanonSi.0x0014", U(320)),
        ("Exif.CanonSi.ISOSpeed", U(128)), ("Exif.CanonSi.AutoISO", U(0)), ("Exif.CanonCs.ISOSpeed", U(15)),
        ("Exif.Canon.FocalLength", exiv2.UShortValue([2, 227, 286, 215])),
        ("Exif.CanonCs.Lens", exiv2.UShortValue([682, 227, 32])),
        ("Exif.Photo.PixelXDimension", exiv2.ULongValue([2272])), ("Exif.Photo.PixelYDimension", exiv2.ULongValue([1704]))],
    # Nikon: ISO (0, 200) in the maker note only, SensorPixelSize 7.8 µm, 35 mm equivalent 75 at 50 mm
    "nikon_iso.jpg": [
        ("Exif.Image.Make", "NIKON CORPORATION"), ("Exif.Image.Model", "NIKON D70"), *SHOT,
        ("Exif.Photo.FocalLength", R(50)), ("Exif.Photo.FocalLengthIn35mmFilm", U(75)),
        ("Exif.Nikon3.ISOSpeed", exiv2.UShortValue([0, 200])),
        ("Exif.Nikon3.SensorPixelSize", exiv2.URationalValue([(78, 10), (78, 10)])),
        ("Exif.Photo.PixelXDimension", exiv2.ULongValue([3008])), ("Exif.Photo.PixelYDimension", exiv2.ULongValue([2000]))],
    # Olympus: FocalPlaneDiagonal 9.04 mm, 4:3 image; Exif ExposureIndex 50 the only ISO
    "olympus_diagonal.jpg": [
        ("Exif.Image.Make", "OLYMPUS CORPORATION"), ("Exif.Image.Model", "C8080WZ"), *SHOT,
        ("Exif.Photo.FocalLength", R(234, 10)), ("Exif.Photo.ExposureIndex", R(50)),
        ("Exif.Olympus.FocalPlaneDiagonal", R(904, 100)),
        ("Exif.Photo.PixelXDimension", exiv2.ULongValue([3264])), ("Exif.Photo.PixelYDimension", exiv2.ULongValue([2448]))],
    # Minolta: camera settings FocusDistance 2500 (mm) and ISO code 56 (2^((56−48)/8)·100 = 200); crop 1.5
    "minolta_focus.jpg": [
        ("Exif.Image.Make", "Minolta Co., Ltd."), ("Exif.Image.Model", "DiMAGE A1"), *SHOT,
        ("Exif.Photo.FocalLength", R(28)), ("Exif.Photo.FocalLengthIn35mmFilm", U(42)),
        ("Exif.MinoltaCsNew.ISO", exiv2.ULongValue([56])),
        ("Exif.MinoltaCsNew.FocusDistance", exiv2.ULongValue([2500]))],
    # Casio type 2: ObjectDistance 1850 (mm), ISO 100 in the maker note (0x3014); crop 6
    "casio_object.jpg": [
        ("Exif.Image.Make", "CASIO COMPUTER CO.,LTD."), ("Exif.Image.Model", "EX-Z750"), *SHOT,
        ("Exif.Photo.FocalLength", R(79, 10)), ("Exif.Photo.FocalLengthIn35mmFilm", U(38)),
        ("Exif.Casio2.ObjectDistance", exiv2.ULongValue([1850])), ("Exif.Casio2.ISO", U(100))],
}


def maker_files(folder: Path) -> list[Path]:
    """The files of :data:`FILES`, written into ``folder``."""
    paths = []
    for name, tags in FILES.items():
        path = folder / name
        path.write_bytes(IMAGES.tiny_jpeg())
        handle = exiv2.ImageFactory.open(str(path))
        handle.readMetadata()
        data = handle.exifData()
        for key, value in tags:
            data[key] = value
        handle.writeMetadata()
        paths.append(path)
    return paths


@pytest.fixture(scope="module")
def rows(tmp_path_factory: pytest.TempPathFactory) -> dict[str, dict[str, Any]]:
    folder = tmp_path_factory.mktemp("makers")
    result = run("exif", "--format", "json", *map(str, maker_files(folder)))
    assert result.exit_code == 0, result.output
    return {Path(row["file"]).name: row for row in json.loads(result.stdout)}


def test_canon_shotinfo_pair_is_a_bracket_and_iso_and_focal_length_come_from_the_maker_note(rows: dict) -> None:
    row = rows["canon_shotinfo_pair.jpg"]
    # ExifTool Canon ShotInfo 19/20 FocusDistanceUpper/Lower: $val / 100 metres
    assert (row["focus_distance_min_mm"], row["focus_distance_max_mm"]) == (3200.0, 3500.0)
    assert row["near_min_mm"] < row["near_mm"] < row["near_max_mm"]  # beyond H: the far limits are infinite
    # Composite ISO: BaseISO exp(128/32·ln 2)·100/32 = 50, times AutoISO exp(0)·100 / 100
    assert row["iso"] == pytest.approx(50.0, rel=1e-12) and row["iso_source"] == "CanonSi.ISOSpeed"
    # Canon FocalLength: 227 / FocalUnits 32; FocalPlaneXSize, YSize = 286, 215 × 25.4/1000 mm
    assert row["focal_length_mm"] == pytest.approx(227 / 32, rel=1e-12)
    assert (row["sensor_width_mm"], row["sensor_height_mm"]) == pytest.approx((286 * 0.0254, 215 * 0.0254))
    assert row["warnings"] is not None and "resized" in row["warnings"]  # a 3 × 2 JPEG of a 2272 × 1704 frame


def test_nikon_maker_iso_and_pixel_size(rows: dict) -> None:
    row = rows["nikon_iso.jpg"]
    assert row["iso"] == 200.0 and row["iso_source"] == "Nikon3.ISOSpeed"
    # the pixel size times the image size: 7.8 µm × 3008 = 23.46 mm; ranked before the rounded 35 mm equivalent
    assert row["sensor_width_mm"] == pytest.approx(0.0078 * 3008, rel=1e-12)
    assert row["sensor_source"] == "Nikon3.SensorPixelSize × image size"
    assert "Nikon's pixel size" in row["warnings"]


def test_olympus_diagonal_with_the_image_aspect_ratio(rows: dict) -> None:
    row = rows["olympus_diagonal.jpg"]
    assert math.hypot(row["sensor_width_mm"], row["sensor_height_mm"]) == pytest.approx(9.04, rel=1e-12)
    assert row["sensor_width_mm"] / row["sensor_height_mm"] == pytest.approx(3264 / 2448, rel=1e-12)
    assert row["sensor_source"] == "Olympus.FocalPlaneDiagonal" and "Olympus" in row["warnings"]


def test_minolta_focus_distance_and_iso(rows: dict) -> None:
    row = rows["minolta_focus.jpg"]
    assert row["focus_distance_mm"] == 2500.0 and row["focus_distance_source"] == "MinoltaCsNew.FocusDistance"
    assert row["iso"] == 200.0 and row["iso_source"] == "MinoltaCsNew.ISO"
    assert rows["olympus_diagonal.jpg"]["iso"] == 50.0
    assert rows["olympus_diagonal.jpg"]["iso_source"] == "Photo.ExposureIndex"
    assert "35 mm-equivalent" in row["warnings"]


def test_casio_object_distance(rows: dict) -> None:
    row = rows["casio_object.jpg"]
    assert row["focus_distance_mm"] == 1850.0 and row["focus_distance_source"] == "Casio2.ObjectDistance"
    assert row["iso"] == 100.0


def test_nikon_byte_quantisation_is_an_error_bar() -> None:
    # nikon.jpg: lens data FocusDistance raw 100; 40 codes a decade, so the distance is within half a code:
    # 10 mm · 10^((100 ± 0.5)/40)
    (row,) = json.loads(run("exif", str(DATA / "nikon.jpg"), "--format", "json").stdout)
    assert row["focus_distance_min_mm"] == pytest.approx(10 * 10 ** (99.5 / 40), rel=1e-12)
    assert row["focus_distance_max_mm"] == pytest.approx(10 * 10 ** (100.5 / 40), rel=1e-12)
    assert row["near_min_mm"] < row["near_mm"] < row["near_max_mm"]


def test_hyperfocal_and_field_without_a_focus_distance_match_the_commands(tmp_path: Path) -> None:
    # fujifilm_subject.jpg with -s: the field width is the sensor width over the magnification (camtool fov)
    (row,) = json.loads(run("exif", str(DATA / "fujifilm_subject.jpg"), "--format", "json").stdout)
    fov = json.loads(run("fov", "-f", "35", "--sensor", f"{row['sensor_width_mm']}x{row['sensor_height_mm']}",
                         "-s", "3.5m", "--format", "json").stdout)[0]
    assert row["field_width_mm"] == pytest.approx(fov["field_width_mm"], rel=1e-9)
    # the Olympus file records no distance: H is still given, the same as camtool hyperfocal's
    path = maker_files(tmp_path)[2]
    (row,) = json.loads(run("exif", str(path), "--format", "json").stdout)
    assert row["focus_distance_mm"] is None and row["near_mm"] is None
    hyper = json.loads(run("hyperfocal", "-f", "23.4", "-N", "5.6", "--coc", str(row["coc_mm"]),
                           "--format", "json").stdout)[0]
    assert row["hyperfocal_mm"] == pytest.approx(hyper["hyperfocal_mm"], rel=1e-12)


def test_a_canon_crop_is_named(tmp_path: Path) -> None:
    # Canon writes FocalPlaneXResolution as (full width × 1000)/(sensor width in 1/1000 in): 5472000/1413 is a
    # 35.89 mm wide sensor; an image of 3408 px at that pitch covers 22.35 mm of it
    path = tmp_path / "crop.jpg"
    path.write_bytes(IMAGES.tiny_jpeg())
    handle = exiv2.ImageFactory.open(str(path))
    handle.readMetadata()
    data = handle.exifData()
    for key, value in [("Exif.Image.Make", "Canon"), ("Exif.Image.Model", "Canon EOS R6"), *SHOT,
                       ("Exif.Photo.FocalLength", R(200)), ("Exif.Photo.PixelXDimension", exiv2.ULongValue([3408])),
                       ("Exif.Photo.PixelYDimension", exiv2.ULongValue([2272])),
                       ("Exif.Photo.FocalPlaneXResolution", R(5472000, 1413)),
                       ("Exif.Photo.FocalPlaneYResolution", R(3648000, 942)),
                       ("Exif.Photo.FocalPlaneResolutionUnit", U(2))]:
        data[key] = value
    handle.writeMetadata()
    result = run("exif", str(path), "--format", "json")
    (row,) = json.loads(result.stdout)
    assert row["sensor_width_mm"] == pytest.approx(3408 * 1413 / 5472000 * 25.4, rel=1e-12)
    assert "of the 35.89 × 23.93 mm sensor Canon records" in row["warnings"]
    assert "warning: the image covers 22.35 × 14.9 mm" in result.stderr
    # ExifTool's convention takes Canon's whole sensor: sqrt(1413² + 942²) · 0.0254 mm (Canon CalcSensorDiag)
    (et,) = json.loads(run("exif", "--exiftool", str(path), "--format", "json").stdout)
    assert et["crop_factor"] == pytest.approx(math.hypot(36, 24) / (math.hypot(1413, 942) * 0.0254), rel=1e-12)


def test_exiftool_mode_refuses_the_options_it_fixes() -> None:
    for option in (("--model", "thin"), ("--distance-from", "lens"), ("--coc-rule", "d/1440")):
        result = run("exif", "--exiftool", *option, str(DATA / "nikon.jpg"))
        assert result.exit_code == 2 and f"--exiftool fixes what {option[0]} sets" in result.stderr


def test_a_format_libexiv2_does_not_read_says_so(tmp_path: Path) -> None:
    path = tmp_path / "a.x3f"
    path.write_bytes(b"FOVb" + bytes(60))
    result = run("exif", str(path))
    assert result.exit_code == 1 and "Sigma X3F is not among libexiv2's formats" in result.stderr
    assert len(result.stderr.splitlines()) == 1


@pytest.mark.skipif(not (SAMPLES / "camera").is_dir(), reason="../shared/reference/exif-samples is absent")
def test_real_cr3_and_canon_shotinfo_bracket() -> None:
    cr3 = SAMPLES / "camera" / "Canon-R6-pruned.CR3"
    (row,) = json.loads(run("exif", str(cr3), "--format", "json").stdout)
    assert row["camera"] == "Canon EOS R6" and row["focal_length_mm"] == 200.0  # read through BMFF
    # the 300D's ShotInfo: upper 65535 (infinity), lower 546 cm
    (row,) = json.loads(run("exif", str(SAMPLES / "camera" / "exiv2-canon-eos-300d.jpg"), "--format", "json").stdout)
    assert row["focus_distance_min_mm"] == 5460.0 and row["focus_distance_max_mm"] is None  # null: infinity


def test_exiftool_csv_columns_as_batch_aliases(tmp_path: Path) -> None:
    # the header and cells as `exiftool -n -csv -FocalLength -FNumber -FocusDistance -ScaleFactor35efl
    # -FocalLengthIn35mmFormat` writes them (metres, a bare crop factor)
    batch = tmp_path / "et.csv"
    batch.write_text("SourceFile,FocalLength,FNumber,FocusDistance,ScaleFactor35efl,FocalLengthIn35mmFormat\n"
                     "a/DSC_0001.jpg,50,9,5.30884444230989,1.5,75\n")
    result = run("dof", "--batch", str(batch), "--format", "json")
    assert result.exit_code == 0, result.output
    (row,) = json.loads(result.stdout)
    (direct,) = json.loads(run("dof", "-f", "50", "-N", "9", "-s", "5.30884444230989", "--crop", "1.5",
                               "--format", "json").stdout)
    assert row["SourceFile"] == "a/DSC_0001.jpg" and row["FocalLengthIn35mmFormat"] == "75"
    assert (row["near_mm"], row["far_mm"]) == (direct["near_mm"], direct["far_mm"])
    # an alias column has the option's own bound
    batch.write_text("SourceFile,FocalLength,FNumber,SubjectDistance,ScaleFactor35efl\na.jpg,50,9,3,1000\n")
    bad = run("dof", "--batch", str(batch))
    crop = run("dof", "-f", "50", "-N", "9", "-s", "3", "--crop", "1000")
    assert bad.exit_code == crop.exit_code == 2
    assert crop.stderr.rsplit(":", 1)[-1].strip() in bad.stderr
