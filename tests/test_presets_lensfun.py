"""Import of lensfun XML: small fixtures written for these tests, and the system database when present."""

from __future__ import annotations

import shutil
from pathlib import Path

import pytest
from conftest import point_xdg_at, presets_home

from camtool.presets import load_db, validate_file
from camtool.presets.lensfun import (
    LensfunImportError,
    default_dirs,
    import_lensfun,
    parse_aperture,
    parse_focal,
    sensor_size,
)

FIXTURES = Path(__file__).resolve().parent / "data" / "lensfun"
SYSTEM = Path("/usr/share/lensfun/version_1")


@pytest.fixture(autouse=True)
def isolated(request, monkeypatch, shared_presets_home):
    """Point every XDG directory away from the user's own files: into tmp_path for a test that asks for
    `isolated` or `tmp_path` (it writes presets or looks at the cache), else into directories shared by the
    tests that only read the shipped presets (parsed once per session)."""
    root = presets_home(request, shared_presets_home, "isolated", "tmp_path")
    point_xdg_at(root, monkeypatch)
    return root


@pytest.mark.parametrize(
    ("name", "focal", "aperture"),
    [
        ("Canon EF-S 18-55mm f/3.5-5.6 IS STM", (18.0, 55.0), 3.5),
        ("FE 16-35mm F2.8 GM", (16.0, 35.0), 2.8),
        ("XF18mmF2 R", (18.0, 18.0), 2.0),
        ("smc Pentax-M 35mm 1:2", (35.0, 35.0), 2.0),
        ("Touit 2.8/50M", (50.0, 50.0), 2.8),
        ("Leica X Vario 18.0-46.0 mm f/3.5-6.4", (18.0, 46.0), 3.5),
        ("AF-S DX Nikkor 35mm f/1.8G", (35.0, 35.0), 1.8),
        ("fixed lens", None, None),
    ],
)
def test_parse_model_names(name, focal, aperture):
    assert parse_focal(name) == focal
    assert parse_aperture(name) == aperture


def test_sensor_size_from_crop_factor():
    width, height = sensor_size(1.5)
    assert (round(width, 2), round(height, 2)) == (24.0, 16.0)
    width, height = sensor_size(5.6, 4 / 3)
    assert width / height == pytest.approx(4 / 3)


def test_import_fixtures(isolated):
    result = import_lensfun(dirs=[FIXTURES])
    out = isolated / "xdg_data_home" / "camtool" / "lensfun.yaml"
    assert result.path == str(out) and out.is_file()
    assert (result.sensors, result.lenses, result.files) == (3, 4, 2)
    assert [Path(p).name for p, _ in result.bad_files] == ["fixture-broken.xml"]
    assert result.skipped["camera: no model or crop factor"] == 1
    assert result.skipped["lens: focal length unknown"] == 1
    assert result.skipped["lens: listed more than once"] == 1
    assert result.imported == 7 and result.skipped_total == 4
    assert validate_file(out) == []
    text = out.read_text(encoding="utf-8")
    assert "CC BY-SA 3.0" in text

    db = load_db()
    body = db.sensor("Testmaker T100")
    assert body.approximate and body.tier == "lensfun"
    assert (round(body.width_mm, 2), round(body.height_mm, 2)) == (24.0, 16.0)
    assert db.sensor("testmaker t200").width_mm == pytest.approx(36.0, abs=1e-3)
    kit = db.lens("Testmaker 18-55mm f/3.5-5.6 Kit")
    assert (kit.focal_min_mm, kit.focal_max_mm, kit.f_number_min, kit.f_number_min_tele) == (18, 55, 3.5, 5.6)
    prime = db.lens("testmaker-50mm-1-1.8")
    assert (prime.focal_length_mm, prime.f_number_min) == (50, 1.8)
    special = db.lens("Testmaker Zoom Special")
    assert (special.focal_min_mm, special.focal_max_mm, special.f_number_min, special.f_number_max) == (70, 200, 4, 32)
    # A compact's "fixed lens": named after its only body, range from the calibration data, 4:3 sensor.
    compact = db.lens("Compactco Pocket 1 fixed lens")
    assert (compact.focal_min_mm, compact.focal_max_mm, compact.f_number_min) == (4.8, 20.1, 2.8)
    assert compact.sensor_id == "compactco-pocket-1"
    assert db.sensor("compactco pocket 1").aspect_ratio == pytest.approx(4 / 3, abs=1e-3)


def test_import_never_overrides_shipped_presets(tmp_path, isolated):
    xml = tmp_path / "xml"
    xml.mkdir()
    (xml / "clash.xml").write_text(
        "<lensdatabase><lens><maker>Canon</maker><model>Canon RF 50mm F1.8 STM</model>"
        "<mount>Canon RF</mount></lens><camera><maker>X</maker><model>X One</model>"
        "<cropfactor>2</cropfactor></camera></lensdatabase>", encoding="utf-8")
    result = import_lensfun(dirs=[xml])
    assert result.skipped["lens: already in camtool's shipped presets"] == 1
    assert load_db().lens("Canon RF 50mm F1.8 STM").tier == "shipped"


def test_failed_import_writes_nothing(tmp_path, isolated):
    empty = tmp_path / "empty"
    empty.mkdir()
    with pytest.raises(LensfunImportError, match="no lensfun XML files"):
        import_lensfun(dirs=[empty])
    only_broken = tmp_path / "broken"
    only_broken.mkdir()
    shutil.copy(FIXTURES / "fixture-broken.xml", only_broken)
    with pytest.raises(LensfunImportError, match="nothing imported"):
        import_lensfun(dirs=[only_broken])
    assert not (isolated / "xdg_data_home" / "camtool").exists() or not list(
        (isolated / "xdg_data_home" / "camtool").iterdir())


def test_explicit_output_path(tmp_path):
    out = tmp_path / "elsewhere" / "lf.yaml"
    result = import_lensfun(dirs=[FIXTURES], out=out)
    assert result.path == str(out) and load_db(extra_files=(out,)).sensor("testmaker-t100").approximate


def test_default_dirs_follow_xdg_data_home(isolated):
    user = isolated / "xdg_data_home" / "lensfun" / "version_1"
    user.mkdir(parents=True)
    shutil.copy(FIXTURES / "fixture-slr.xml", user)
    assert user in default_dirs()


@pytest.mark.skipif(not SYSTEM.is_dir(), reason="lensfun database not installed (liblensfun-data-v1)")
def test_system_lensfun_database(isolated):
    result = import_lensfun(dirs=[SYSTEM])
    assert result.sensors > 300 and result.lenses > 500 and not result.bad_files
    db = load_db()
    assert len(db.names("lens")) > 500
    assert db.sensor("Canon EOS 5D Mark II").width_mm == pytest.approx(36.0, abs=0.2)
    assert validate_file(result.path) == []


# --- hardening: aspect ratios, odd entries, the output file ---------------------------------

HARDENING = FIXTURES / "hardening"


def test_body_aspect_comes_from_the_body_not_lenses_shared_with_other_mounts(isolated):
    # A lens made for both a 3:2 mount and a 4:3 mount carries 4:3 (as lensfun's Sigma DC DN
    # lenses for Sony E and Micro Four Thirds do); the full-frame body must stay 36 x 24 mm.
    import_lensfun(dirs=[HARDENING])
    db = load_db()
    body = db.sensor("Testmaker E1")
    assert (round(body.width_mm, 2), round(body.height_mm, 2)) == (36.0, 24.0)
    assert "3:2" in body.source
    assert db.sensor("Testmaker F4").aspect_ratio == pytest.approx(4 / 3, abs=1e-3)
    # A body's own fixed lens still gives its ratio (a square compact, crop 1.53).
    square = db.sensor("Compactco Square 3")
    assert square.aspect_ratio == pytest.approx(1.0) and "fixed lens" in square.source


def test_an_odd_entry_is_skipped_and_reported_not_fatal(isolated):
    result = import_lensfun(dirs=[HARDENING])
    reasons = [reason for reason in result.skipped if "Body Cap 0mm" in reason]
    assert len(reasons) == 1 and "focal_length_mm" in reasons[0]
    assert load_db().lens("Testmaker 85mm f/1.8").focal_length_mm == 85


def test_lensfun_spelling_finds_the_shipped_lens(isolated):
    # lensfun writes "Nikon NIKKOR Z 50mm f/1.8 S"; the shipped preset is "NIKKOR Z 50mm f/1.8 S".
    result = import_lensfun(dirs=[HARDENING])
    assert result.skipped["lens: already in camtool's shipped presets"] == 1
    assert load_db().lens("Nikon NIKKOR Z 50mm f/1.8 S").tier == "shipped"


def test_new_output_file_is_0644(tmp_path):
    import os

    out = tmp_path / "new.yaml"
    old = os.umask(0o077)
    try:
        import_lensfun(dirs=[FIXTURES], out=out)
    finally:
        os.umask(old)
    assert out.stat().st_mode & 0o777 == 0o644


@pytest.mark.parametrize("mode", [0o600, 0o640, 0o664])
def test_output_keeps_the_permissions_of_the_file_it_replaces(tmp_path, mode):
    out = tmp_path / "lf.yaml"
    out.write_text("sensors: []\n", encoding="utf-8")
    out.chmod(mode)
    import_lensfun(dirs=[FIXTURES], out=out)
    assert out.stat().st_mode & 0o777 == mode and "Testmaker" in out.read_text(encoding="utf-8")


def test_output_through_a_symlink_replaces_the_file_it_names(tmp_path):
    real = tmp_path / "real.yaml"
    real.write_text("sensors: []\n", encoding="utf-8")
    link = tmp_path / "link.yaml"
    link.symlink_to(real)
    import_lensfun(dirs=[FIXTURES], out=link)
    assert link.is_symlink() and "Testmaker" in real.read_text(encoding="utf-8")


def test_output_that_is_not_a_regular_file_is_refused(tmp_path):
    import os

    with pytest.raises(LensfunImportError, match="it is a directory"):
        import_lensfun(dirs=[FIXTURES], out=tmp_path)
    fifo = tmp_path / "fifo"
    os.mkfifo(fifo)
    with pytest.raises(LensfunImportError, match="not a regular file"):
        import_lensfun(dirs=[FIXTURES], out=fifo)
    dangling = tmp_path / "dangling.yaml"
    dangling.symlink_to(tmp_path / "missing" / "x.yaml")
    with pytest.raises(LensfunImportError, match="missing file"):
        import_lensfun(dirs=[FIXTURES], out=dangling)


def test_cli_refuses_a_bad_out_with_one_line(tmp_path):
    import os

    from cli_helpers import run

    result = run("presets", "import-lensfun", "--dir", str(FIXTURES), "--out", str(tmp_path))
    assert result.exit_code == 2 and "is a directory" in result.output
    fifo = tmp_path / "fifo"
    os.mkfifo(fifo)
    result = run("presets", "import-lensfun", "--dir", str(FIXTURES), "--out", str(fifo))
    assert result.exit_code == 1
    assert result.output.strip().splitlines() == [f"Error: cannot write {fifo}: it is not a regular file"]
    readonly = tmp_path / "ro"
    readonly.mkdir()
    readonly.chmod(0o500)
    try:
        if os.access(readonly, os.W_OK):
            pytest.skip("running as a user who can write anywhere")
        result = run("presets", "import-lensfun", "--dir", str(FIXTURES), "--out", str(readonly / "x.yaml"))
        assert result.exit_code == 1 and len(result.output.strip().splitlines()) == 1
        assert "cannot write" in result.output
    finally:
        readonly.chmod(0o700)
