"""camtool presets and the equipment options (--camera, --lens, --scene) through click."""

from __future__ import annotations

import json
import math
from pathlib import Path

import pytest
from cli_helpers import run, run_json

from camtool.dof.closed import thin_dof

DATA = Path(__file__).parent / "data"


pytestmark = pytest.mark.usefixtures("no_user_presets")  # the shipped presets alone


def test_sensor_preset_by_name_and_alias() -> None:
    (row,) = run_json("dof", "-f", "25", "-N", "4", "-s", "3", "--sensor", "Micro Four Thirds")
    (alias,) = run_json("dof", "-f", "25", "-N", "4", "-s", "3", "--sensor", "m43")
    assert row == alias
    # Micro Four Thirds 17.3 x 13.0 mm (Wikipedia, Image sensor format); d/1500 of its 21.64 mm diagonal
    assert row["coc_mm"] == pytest.approx(math.hypot(17.3, 13.0) / 1500, rel=1e-3)


def test_unknown_sensor_suggests() -> None:
    result = run("dof", "-f", "50", "-N", "8", "-s", "3", "--sensor", "ful-frame")
    assert result.exit_code == 2
    assert result.stderr.startswith("Error: Invalid value for '--sensor': unknown sensor 'ful-frame'; did you mean full-frame")


def test_camera_gives_sensor_and_pixel_pitch() -> None:
    (row,) = run_json("dof", "-f", "50", "-N", "8", "-s", "3", "--camera", "nikon-z-8", "--coc-rule", "px:2")
    # Nikon Z 8: 8256 px across the 36 mm preset width -> 4.36 µm pitch; px:2 = 8.72 µm
    assert row["coc_mm"] == pytest.approx(2 * 36.0 / 8256)


def test_prime_lens_supplies_focal_length_and_checks_range() -> None:
    (row,) = run_json("dof", "--lens", "sony-fe-85mm-f1.8", "-N", "2", "-s", "3", "--coc", "0.03")
    assert row["focal_length_mm"] == 85.0
    # the preset publishes its closest focus, so it focuses internally (docs/closeup.md §2): the thin lens
    # of its focal length at this focus
    assert row["focal_length_at_focus_mm"] < 85.0
    assert row["near_mm"] == pytest.approx(thin_dof(row["focal_length_at_focus_mm"], 2.0, 0.03, 3000.0).near_mm)
    wide = run("dof", "--lens", "sony-fe-85mm-f1.8", "-N", "1.4", "-s", "3")
    assert wide.exit_code == 2
    assert wide.stderr == ("Error: Invalid value for '-N' / '--f-number': f/1.4 is outside the valid range of "
                           "--lens sony-fe-85mm-f1.8 at 85 mm: from f/1.8\n")  # its smallest aperture is unconfirmed: no upper bound
    close = run("dof", "--lens", "sony-fe-85mm-f1.8", "-N", "2", "-s", "0.5")
    assert close.exit_code == 2 and "at least its closest focus, 0.8 m from the sensor" in close.stderr


def test_zoom_needs_focal_length_in_range() -> None:
    assert run("dof", "--lens", "nikon-z-24-70mm-f4-s", "-N", "4", "-s", "3").stderr == (
        "Error: --lens nikon-z-24-70mm-f4-s is a zoom (24–70 mm): give the focal length with -f\n")
    out = run("dof", "--lens", "nikon-z-24-70mm-f4-s", "-f", "100", "-N", "4", "-s", "3")
    assert out.exit_code == 2 and "24–70 mm" in out.stderr
    assert run_json("dof", "--lens", "nikon-z-24-70mm-f4-s", "-f", "50", "-N", "4", "-s", "3")[0]["focal_length_mm"] == 50


def test_unknown_lens_did_you_mean() -> None:
    result = run("dof", "--lens", "sony-fe-85", "-N", "2", "-s", "3")
    assert result.exit_code == 2
    assert result.stderr.startswith("Error: Invalid value for '--lens': unknown lens 'sony-fe-85'; did you mean ")


def test_scene_fills_and_options_override() -> None:
    (scene,) = run_json("dof", "--scene", "landscape-24")
    assert (scene["focal_length_mm"], scene["f_number"], scene["distance_mm"]) == (24.0, 11.0, 3000.0)
    (override,) = run_json("dof", "--scene", "landscape-24", "-N", "16")
    assert (override["focal_length_mm"], override["f_number"]) == (24.0, 16.0)


def test_user_preset_file_and_broken_file(tmp_path: Path) -> None:
    good = tmp_path / "mine.yaml"
    good.write_text("sensors:\n  - id: my-sensor\n    width_mm: 20\n    height_mm: 10\n    source: test\n")
    (row,) = run_json("dof", "-f", "50", "-N", "8", "-s", "3", "--sensor", "my-sensor", "--presets", str(good))
    assert row["coc_mm"] == pytest.approx(math.hypot(20, 10) / 1500)
    broken = tmp_path / "broken.yaml"
    broken.write_text("sensors:\n  - id: x\n    width_mm: [1\n")
    result = run("dof", "-f", "50", "-N", "8", "-s", "3", "--sensor", "x", "--presets", str(broken))
    assert result.exit_code == 1
    assert result.stderr.startswith(f"Error: Invalid value for '--presets': {broken}:") and result.stderr.count("\n") == 1


def test_presets_list_show_validate(tmp_path: Path) -> None:
    rows = json.loads(run("presets", "list", "--kind", "scene", "--format", "json").stdout)
    assert {r["id"] for r in rows} >= {"landscape-24", "portrait-85"}
    (lens,) = json.loads(run("presets", "show", "dgauss100-lens", "--format", "json").stdout)
    # first-order data of the shared double Gauss (reference table of oracle-README: f = 100.003757028, P = 1.14640104669)
    assert lens["efl_mm"] == pytest.approx(100.003757028, rel=1e-9)
    assert lens["pupil_magnification_paraxial"] == pytest.approx(1.14640104669, rel=1e-9)
    assert lens["origin"].endswith("lenses.yaml")
    bad = tmp_path / "bad.yaml"
    bad.write_text("sensors:\n  - id: x\n    width_mm: -3\n")
    result = run("presets", "validate", str(bad))
    assert result.exit_code == 1
    assert "width_mm: must be > 0 mm, got -3" in result.stderr
    assert run("presets", "validate", str(Path(__file__).parent.parent / "lens_db" / "sensors.yaml")).exit_code == 0


def test_import_lensfun_from_fixtures(tmp_path: Path) -> None:
    fixtures = DATA / "lensfun"
    out = tmp_path / "lf.yaml"
    result = run("presets", "import-lensfun", "--dir", str(fixtures), "--out", str(out))
    assert result.exit_code == 0, result.stderr
    assert result.stdout.startswith("imported ") and out.exists()


def test_preset_names_complete() -> None:
    from click.shell_completion import ShellComplete

    from camtool.cli import cli

    completer = ShellComplete(cli, {}, "camtool", "_CAMTOOL_COMPLETE")
    names = [item.value for item in completer.get_completions(["dof", "--sensor"], "full")]
    assert "full-frame" in names
    lenses = [item.value for item in completer.get_completions(["dof", "--lens"], "sony-fe-8")]
    assert "sony-fe-85mm-f1.8" in lenses


def test_presets_list_and_show_films(tmp_path: Path) -> None:
    # the films `camtool exposure --film` knows, as camtool/exposure/films.yaml lists them (read here
    # with yaml, not through camtool), then a user's own films: section
    import yaml

    shipped = yaml.safe_load((Path(__file__).parents[1] / "camtool" / "exposure" / "films.yaml").read_text())["films"]
    own = tmp_path / "films.yaml"
    own.write_text("films:\n  - {id: my-film, name: My film, p: 1.4}\n"
                   "  - {id: ilford-hp5-plus, name: Not HP5, p: 2.0}\n")
    rows = run_json("presets", "list", "--kind", "film", "--presets", str(own))
    assert [r["id"] for r in rows] == [f["id"] for f in shipped] + ["my-film"]  # --film finds a shipped film first
    hp5 = rows[0]
    assert hp5["summary"] == "Ilford HP5 Plus, reciprocity p = 1.31 beyond 1 s"  # Ilford's sheet: t_c = t_m^1.31
    assert hp5["tier"] == "shipped" and hp5["origin"] == "camtool/exposure/films.yaml"
    assert rows[-1]["summary"] == "My film, reciprocity p = 1.4 beyond 1 s" and rows[-1]["tier"].startswith("--presets")
    assert [r["kind"] for r in run_json("presets", "list", "--search", "ektar")] == ["film"]
    (shown,) = run_json("presets", "show", "HP5+")
    assert shown["id"] == "ilford-hp5-plus" and shown["p"] == 1.31 and "hp5" in shown["aliases"]
    (tmax,) = run_json("presets", "show", "tmax100", "--kind", "film")
    # Kodak F-4016: 100 s metered -> +1 stop
    assert tmax["p"] is None and tmax["points"][-1] == [100.0, 1.0]
    table = run("presets", "show", "tmax100")
    assert table.exit_code == 0 and "100 s +1 EV" in table.stdout
    assert run("presets", "list", "--kind", "film").stdout.splitlines()[-1] == f"{len(shipped)} presets"
    assert run("presets", "list", "--search", "ektar").stdout.splitlines()[-1] == "1 preset"


def test_a_phone_module_brings_its_own_sensor() -> None:
    # A fixed (phone) lens is made for its own format: without --sensor it is used, even beside the
    # phone's --camera preset, whose sensor is the main module's. Angle of view from the module's
    # focal length and its sensor preset's diagonal, 2·atan(d / 2f), read here from the presets.
    import yaml

    root = Path(__file__).resolve().parents[1] / "lens_db"
    lenses = {e["id"]: e for e in yaml.safe_load((root / "lenses.yaml").read_text())["lenses"]}
    sensors = {e["id"]: e for e in yaml.safe_load((root / "sensors.yaml").read_text())["sensors"]}
    for module, camera in (("apple-iphone-16-pro-main", None), ("apple-iphone-16-pro-ultra-wide", "apple-iphone-16-pro")):
        lens = lenses[module]
        sensor = sensors[lens["sensor"]]
        diagonal = math.hypot(sensor["width_mm"], sensor["height_mm"])
        args = ["fov", "--lens", module, *(["--camera", camera] if camera else [])]
        (row,) = run_json(*args)
        assert row["diagonal_deg"] == pytest.approx(math.degrees(2 * math.atan(diagonal / (2 * lens["focal_length_mm"]))))
        assert "the lens's own format" in run(*args).stdout
    # --sensor still wins
    (full,) = run_json("fov", "--lens", "apple-iphone-16-pro-main", "--sensor", "full-frame")
    assert full["diagonal_deg"] == pytest.approx(math.degrees(2 * math.atan(math.hypot(36, 24) / (2 * 6.82))), rel=1e-3)
    # an interchangeable lens made for APS-C is on that format without a camera, on the body's with one
    (alone,) = run_json("dof", "--lens", "fujifilm-xf35mm-f1.4-r", "-N", "2", "-s", "3")
    assert alone["coc_mm"] == pytest.approx(math.hypot(sensors["aps-c"]["width_mm"], sensors["aps-c"]["height_mm"]) / 1500)
    (body,) = run_json("dof", "--lens", "fujifilm-xf35mm-f1.4-r", "--camera", "fujifilm-x-t5", "-N", "2", "-s", "3",
                       "--coc-rule", "px:1")
    assert body["coc_mm"] == pytest.approx(23.5 / 7728)  # X-T5: 7728 px across 23.5 mm (its preset)
    # the camera's pixel pitch is kept only when the module is the camera's own sensor (the main one)
    (main,) = run_json("dof", "--lens", "google-pixel-3-main", "--camera", "google-pixel-3", "-N", "1.8", "-s", "2m",
                       "--coc-rule", "px:2")
    assert main["coc_mm"] == pytest.approx(2 * 0.0014, rel=0.01)  # Google: 1.4 µm pixels
    wide = run("dof", "--lens", "apple-iphone-16-pro-ultra-wide", "--camera", "apple-iphone-16-pro", "-N", "2.2",
               "-s", "2m", "--coc-rule", "px:2")
    assert wide.exit_code == 2 and wide.stderr == (
        "Error: Invalid value for '--coc-rule': 'px:2' needs the pixel pitch: --camera's is its main sensor's, not "
        "this lens's; give --pixel-pitch\n")


def test_a_zoom_accepts_its_smallest_aperture_at_each_end() -> None:
    # Sony FE 200-600mm: f/32 at 200 mm, f/36 at 600 mm (Wikipedia's infobox)
    assert run("dof", "--lens", "sel200600g", "-f", "600", "-N", "36", "-s", "30m").exit_code == 0
    assert run("dof", "--lens", "sel200600g", "-f", "200", "-N", "36", "-s", "30m").stderr == (
        "Error: Invalid value for '-N' / '--f-number': f/36 is outside the valid range of --lens "
        "sony-fe-200-600mm-f5.6-6.3-g-oss at 200 mm: f/5.6 to f/32\n")
    assert "f/6.3 to f/36" in run("dof", "--lens", "sel200600g", "-f", "600", "-N", "40", "-s", "30m").stderr


def test_a_lens_without_a_published_smallest_aperture_is_bounded_from_below_only() -> None:
    # The NIKKOR Z 70-180mm f/2.8 preset has no f_number_max (no page read gives it): any f-number from
    # its widest, f/2.8, is accepted, and one below it names only the lower bound.
    assert run("dof", "--lens", "nikon-z-70-180mm-f2.8", "-f", "100", "-N", "22", "-s", "3m").exit_code == 0
    assert run("dof", "--lens", "nikon-z-70-180mm-f2.8", "-f", "100", "-N", "64", "-s", "3m").exit_code == 0
    result = run("dof", "--lens", "nikon-z-70-180mm-f2.8", "-f", "100", "-N", "2", "-s", "3m")
    assert result.exit_code == 2 and result.stderr == (
        "Error: Invalid value for '-N' / '--f-number': f/2 is outside the valid range of --lens "
        "nikon-z-70-180mm-f2.8 at 100 mm: from f/2.8\n")
