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
    short_maker,
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
    assert (result.cameras, result.lenses, result.files) == (3, 4, 2)
    assert [Path(p).name for p, _ in result.bad_files] == ["fixture-broken.xml"]
    assert result.skipped["camera: no model or crop factor"] == 1
    assert result.skipped["lens: focal length unknown"] == 1
    assert result.skipped["lens: listed more than once"] == 1
    assert result.imported == 7 and result.skipped_total == 4
    assert validate_file(out) == []
    text = out.read_text(encoding="utf-8")
    assert "CC BY-SA 3.0" in text
    assert "sensors:" not in text

    db = load_db()
    # An interchangeable body is a camera with its sensor (sized from the crop factor) and its mount.
    body = db.camera("Testmaker T100")
    assert (body.id, body.approximate, body.tier, body.mount) == ("testmaker-t100", True, "lensfun", "Test Mount")
    assert body.lens_id is None
    assert (round(body.sensor.width_mm, 2), round(body.sensor.height_mm, 2)) == (24.0, 16.0)
    assert db.sensor("Testmaker T100").width_mm == body.sensor.width_mm
    # lensfun's English model names the camera; the other spelling finds it too.
    english = db.camera("testmaker t200")
    assert english.id == "testmaker-t200-english" and english.sensor.width_mm == pytest.approx(36.0, abs=1e-3)
    kit = db.lens("Testmaker 18-55mm f/3.5-5.6 Kit")
    assert (kit.focal_min_mm, kit.focal_max_mm, kit.f_number_min, kit.f_number_min_tele) == (18, 55, 3.5, 5.6)
    prime = db.lens("testmaker-50mm-1-1.8")
    assert (prime.focal_length_mm, prime.f_number_min) == (50, 1.8)
    special = db.lens("Testmaker Zoom Special")
    assert (special.focal_min_mm, special.focal_max_mm, special.f_number_min, special.f_number_max) == (70, 200, 4, 32)
    # A compact is a camera with its own lens: range from the calibration data, made for its 4:3 sensor.
    compact = db.camera("Compactco Pocket 1")
    assert (compact.id, compact.mount, compact.lens_id) == ("compactco-pocket-1", "fixed lens", "compactco-pocket-1-lens")
    assert compact.sensor.aspect_ratio == pytest.approx(4 / 3, abs=1e-3)
    lens = db.lens(compact.lens_id)
    assert (lens.focal_min_mm, lens.focal_max_mm, lens.f_number_min, lens.mount) == (4.8, 20.1, 2.8, "fixed lens")
    assert lens.sensor_id == "compactco-pocket-1"


def test_imported_compact_brings_its_lens_to_the_command_line(isolated):
    from cli_helpers import run

    import_lensfun(dirs=[FIXTURES])
    # --camera brings the compact's own lens (a zoom: the focal length is asked for, the aperture is
    # the lens's widest) and its sensor.
    shown = run("dof", "--camera", "compactco-pocket-1", "-s", "2m")
    assert shown.exit_code == 2 and "compactco-pocket-1-lens is a zoom (4.8–20.1 mm)" in shown.output
    shown = run("dof", "--camera", "compactco-pocket-1", "-f", "10", "-s", "2m")
    assert shown.exit_code == 0, shown.output
    assert "f/2.8" in shown.output and "Compactco Pocket 1 (" in shown.output


@pytest.mark.parametrize(
    ("registered", "everyday"),
    [("Ricoh Imaging Company, Ltd.", "Ricoh"), ("Leica Camera AG", "Leica"), ("Casio Computer Co.,Ltd", "Casio"),
     ("Eastman Kodak Company", "Eastman Kodak"), ("Samsung Techwin Co.", "Samsung"), ("SIGMA", "Sigma"),
     ("Konica Minolta", "Konica Minolta"), ("DJI", "DJI"), ("Olympus Optical Co.,Ltd", "Olympus")],
)
def test_short_maker(registered, everyday):
    assert short_maker(registered) == everyday


def test_a_ricoh_compact_gets_a_readable_id_and_its_own_lens(tmp_path, isolated):
    # The shape of lensfun's compact-ricoh.xml: a registered maker name, the body's own mount, the
    # lens named "... & compatibles" with the English model "fixed lens", and a converter variant.
    xml = tmp_path / "xml"
    xml.mkdir()
    (xml / "compact-ricoh.xml").write_text(
        "<lensdatabase>"
        "<camera><maker>Ricoh Imaging Company, Ltd.</maker><model>Ricoh GR II</model>"
        "<mount>ricohGRII</mount><cropfactor>1.53</cropfactor></camera>"
        "<lens><maker>Ricoh imaging company, ltd.</maker><model>Ricoh GR II &amp; compatibles</model>"
        "<model lang=\"en\">fixed lens</model><mount>ricohGRII</mount><cropfactor>1.53</cropfactor>"
        "<calibration><vignetting model=\"pa\" focal=\"18.3\" aperture=\"2.8\" distance=\"10\" k1=\"0\" k2=\"0\" k3=\"0\"/>"
        "</calibration></lens>"
        "<lens><maker>Ricoh imaging company, ltd.</maker><model>Ricoh GR II &amp; compatibles, with GW-3</model>"
        "<model lang=\"en\">fixed lens, with GW-3</model><mount>ricohGRII</mount>"
        "<calibration><distortion model=\"ptlens\" focal=\"13.8\" a=\"0\" b=\"0\" c=\"0\"/></calibration></lens>"
        "</lensdatabase>", encoding="utf-8")
    result = import_lensfun(dirs=[xml])
    assert (result.cameras, result.lenses) == (1, 2)
    db = load_db()
    camera = db.camera("ricoh-gr-ii")
    assert (camera.name, camera.mount, camera.lens_id) == ("Ricoh GR II", "fixed lens", "ricoh-gr-ii-lens")
    assert db.lens("ricoh-gr-ii-lens").focal_length_mm == 18.3
    converter = db.lens("ricoh-gr-ii-lens-with-gw-3")
    assert (converter.focal_length_mm, converter.sensor_id) == (13.8, "ricoh-gr-ii")
    text = Path(result.path).read_text(encoding="utf-8")
    assert "ricoh-imaging-company" not in text and "compatibles" not in text


def test_a_fixed_lens_that_cannot_be_imported_leaves_its_camera_without_a_lens(tmp_path, isolated):
    xml = tmp_path / "xml"
    xml.mkdir()
    (xml / "compact.xml").write_text(
        "<lensdatabase><camera><maker>Compactco</maker><model>Compactco Blank</model><mount>blank</mount>"
        "<cropfactor>5</cropfactor></camera>"
        "<lens><maker>Compactco</maker><model>fixed lens</model><mount>blank</mount></lens></lensdatabase>",
        encoding="utf-8")
    result = import_lensfun(dirs=[xml])
    assert result.skipped["lens: focal length unknown"] == 1
    assert validate_file(result.path) == []
    camera = load_db().camera("compactco-blank")
    assert (camera.mount, camera.lens_id) == ("fixed lens", None)


def test_a_body_shipped_by_camtool_is_not_imported_again(tmp_path, isolated):
    # lensfun's Sony spells the a7 III "ILCE-7M3" ("Alpha 7 III" in English); the shipped preset has
    # the alias ilce-7m3, so the import leaves the body (and its camtool figures) alone.
    xml = tmp_path / "xml"
    xml.mkdir()
    (xml / "mil-sony.xml").write_text(
        "<lensdatabase><camera><maker>Sony</maker><model>ILCE-7M3</model><model lang=\"en\">Alpha 7 III</model>"
        "<mount>Sony E</mount><cropfactor>1</cropfactor></camera>"
        "<camera><maker>Sony</maker><model>ILCE-7</model><model lang=\"en\">Alpha 7</model>"
        "<mount>Sony E</mount><cropfactor>1</cropfactor></camera></lensdatabase>", encoding="utf-8")
    result = import_lensfun(dirs=[xml])
    assert result.skipped["camera: already in camtool's shipped presets"] == 1 and result.cameras == 1
    db = load_db()
    assert db.camera("ilce-7m3").tier == "shipped"
    imported = db.camera("Sony ILCE-7")
    assert (imported.id, imported.tier) == ("sony-alpha-7", "lensfun")


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
    assert result.path == str(out) and load_db(extra_files=(out,)).camera("testmaker-t100").approximate


def test_default_dirs_follow_xdg_data_home(isolated):
    user = isolated / "xdg_data_home" / "lensfun" / "version_1"
    user.mkdir(parents=True)
    shutil.copy(FIXTURES / "fixture-slr.xml", user)
    assert user in default_dirs()


@pytest.mark.skipif(not SYSTEM.is_dir(), reason="lensfun database not installed (liblensfun-data-v1)")
def test_system_lensfun_database(isolated):
    result = import_lensfun(dirs=[SYSTEM])
    assert result.cameras > 300 and result.lenses > 500 and not result.bad_files
    db = load_db()
    assert len(db.names("lens")) > 500
    assert db.camera("Canon EOS 5D Mark II").sensor.width_mm == pytest.approx(36.0, abs=0.2)
    assert validate_file(result.path) == []
    # No id keeps a registered maker name or lensfun's "& compatibles".
    ids = db.names("camera") + db.names("lens")
    assert not [i for i in ids if "company" in i or "compatibles" in i or "corporation" in i]
    # Every compact is a camera with its own lens (a body on a fixed-lens mount), except where the lens could not
    # be imported; each lens it names exists and is made for it.
    compacts = [db.camera(i) for i in db.names("camera") if db.camera(i).tier == "lensfun"
                and db.camera(i).mount == "fixed lens"]
    assert len(compacts) > 200
    with_lens = [c for c in compacts if c.lens_id]
    assert len(with_lens) > 0.9 * len(compacts)
    for camera in with_lens:
        assert db.lens(camera.lens_id).sensor_id == camera.id


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
