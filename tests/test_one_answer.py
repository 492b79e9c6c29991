"""One hyperfocal distance per lens, model and CoC: ``hyperfocal``, ``dof`` and the library give the same float.

Over random scenes and every lens preset without a prescription (primes,
zooms, lenses that focus internally, lenses with pupil data): the hyperfocal
distance of ``camtool hyperfocal`` (JSON and ``--field``), the H column of
``camtool dof``, :func:`camtool.plans.depth.hyperfocal_setting` and the Python
API's :func:`camtool.hyperfocal_distance` are the same float, and ``dof`` focused at that distance (typed as ``--field`` prints
it) has a far limit of infinity. Independent checks: the thin model's closed
form of an internally focusing lens's hyperfocal focus, f(m) = f₀/(1 + κm) at
m = N·c/(f₀ − κ·N·c) (so f = f₀ − κ·N·c and H = f²/(N·c) + f from the lens),
and Wikipedia's H = f²/(N·c) + f for a plain lens.
"""

from __future__ import annotations

import math

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from camtool.dof.rungs import LensData
from camtool.plans.depth import hyperfocal_setting
from camtool.presets import load_db
from camtool.presets.focusing import focus_model
from tests.cli_helpers import run, run_json

LENSES = sorted((lens for lens in load_db().all("lens") if lens.prescription is None), key=lambda lens: lens.id)
FOCUSING = [lens for lens in LENSES if focus_model(lens, lens.focal_min_mm) is not None and not lens.min_magnification]


def _focal(lens, t: float) -> list[str]:
    if not lens.is_zoom:
        return []
    return ["-f", repr(lens.focal_min_mm + t * (lens.focal_max_mm - lens.focal_min_mm))]


def _f_number(lens, t: float) -> float:
    """An f-number the lens has at every focal length: from its slowest widest aperture to f/22 or its smallest."""
    low = max(lens.f_number_min or 1.4, getattr(lens, "f_number_min_tele", None) or 0.0, 1.0)
    high = min(lens.f_number_max or 22.0, getattr(lens, "f_number_max_tele", None) or math.inf, 22.0)
    return round(low * (high / low) ** t, 1) if high > low * 1.1 else low


@settings(max_examples=80, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(lens=st.sampled_from(LENSES), t=st.floats(0, 1), u=st.floats(0, 1),
       plane=st.sampled_from(["sensor", "lens"]), model=st.sampled_from(["auto", "thin", "approx", "thick"]),
       coc=st.sampled_from([[], ["--coc", "0.02"], ["--coc-rule", "d/3000"]]))
def test_hyperfocal_dof_and_the_plan_give_one_h_and_focusing_there_gives_infinity(lens, t, u, plane, model, coc):
    if model == "thick" and lens.pupil_magnification is None and lens.hiatus_mm is None:
        model = "thin"
    args = ["--lens", lens.id, *_focal(lens, t), "-N", repr(_f_number(lens, u)), *coc, "--distance-from", plane,
            "--model", model]
    result = run("hyperfocal", *args, "--format", "json")
    if result.exit_code != 0:  # a macro-only lens has no infinity focus: one line, exit 2
        assert result.exit_code == 2 and result.stderr.count("\n") == 1, result.output
        return
    (row,) = run_json("hyperfocal", *args)
    h = row["hyperfocal_mm"]
    printed = run("hyperfocal", *args, "--field", "hyperfocal_mm").stdout.strip()
    assert float(printed) == h  # --field prints the float that round-trips
    (at_h,) = run_json("dof", *args, "-s", printed + "mm")
    assert at_h["far_mm"] is None, (at_h, h)  # ∞
    assert at_h["hyperfocal_mm"] == h
    (at_inf,) = run_json("dof", *args, "-s", "inf")
    assert at_inf["hyperfocal_mm"] == h  # the H column does not move with the focus
    data = LensData(pupil_magnification=lens.pupil_magnification, hiatus_mm=lens.hiatus_mm)
    plan = hyperfocal_setting(model=model, focal_length_mm=row["focal_length_mm"], f_number=row["f_number"],
                              coc_mm=row["coc_mm"], distance_from=plane,
                              lens=None if data == LensData() else data, lens_preset=lens)
    assert plan.hyperfocal_mm == h and plan.model == row["model"]
    import camtool

    through_api = camtool.hyperfocal_distance(row["focal_length_mm"], row["f_number"], row["coc_mm"],
                                              distance_from=plane, model=model, lens=lens.id,
                                              pupil_magnification=lens.pupil_magnification, hiatus_mm=lens.hiatus_mm)
    assert through_api.hyperfocal_mm == h and through_api.model == row["model"]  # the Python API, the same float
    # named alone, as --lens names it: the preset's pupil magnification and hiatus come with it
    bare = camtool.hyperfocal_distance(row["focal_length_mm"], row["f_number"], row["coc_mm"], distance_from=plane,
                                       model=model, lens=lens.id)
    assert (bare.hyperfocal_mm, bare.near_mm, bare.model) == (h, row["near_mm"], row["model"])


PUPILS = [lens for lens in LENSES if (lens.pupil_magnification, lens.hiatus_mm) != (None, None) and not lens.is_zoom]


@pytest.mark.parametrize("lens", PUPILS, ids=lambda lens: lens.id)
def test_a_focus_bracket_through_the_api_is_the_command_s(lens) -> None:
    """``bracket_stack(..., lens=NAME)`` takes the preset's pupil magnification and hiatus as ``stack --lens`` does."""
    import camtool

    n = _f_number(lens, 0.5)
    closest = (lens.min_focus_mm or 300.0) * 2
    rows = run_json("stack", "--lens", lens.id, "-N", repr(n), "--coc", "0.03", "--near", f"{closest!r}mm",
                    "--far", "inf")
    plan = camtool.bracket_stack(lens.focal_min_mm, n, 0.03, closest, math.inf, lens=lens.id)
    assert [(f.distance_mm, f.near_mm) for f in plan.frames] == [(r["distance_mm"], r["near_mm"]) for r in rows]


@pytest.mark.parametrize("lens", FOCUSING[::5], ids=lambda lens: lens.id)
def test_the_thin_hyperfocal_focus_of_an_internally_focusing_lens_is_the_closed_form(lens) -> None:
    f0 = lens.focal_min_mm
    model = focus_model(lens, f0)
    n, c = 11.0, 0.03
    h = hyperfocal_setting(model="thin", focal_length_mm=f0, f_number=n, coc_mm=c, distance_from="lens",
                           lens_preset=lens)
    if n * c / (f0 - model.kappa * n * c) > model.max_magnification:
        # H nearer than the closest focus (Sigma 8-16mm at 8 mm: 202 mm inside its 240 mm): the plan focuses there
        assert h.magnification == pytest.approx(model.max_magnification, rel=1e-12)
        return
    f = f0 - model.kappa * n * c  # f₀/(1 + κm) at m = N·c/(f₀ − κ·N·c)
    assert h.focal_length_at_focus_mm == pytest.approx(f, rel=1e-12)
    assert h.hyperfocal_mm == pytest.approx(f * f / (n * c) + f, rel=1e-12)
    assert h.near_mm == pytest.approx(h.hyperfocal_mm / 2, rel=1e-12)  # thin lens: sharp from H/2


def test_the_issue_examples_give_one_answer() -> None:
    lens = ["--lens", "nikon-z-24mm-f1.8-s", "-N", "11"]
    for model in ("thin", "auto"):
        (h,) = run_json("hyperfocal", *lens, "--model", model)
        (row,) = run_json("dof", *lens, "-s", repr(h["hyperfocal_mm"]) + "mm", "--model", model)
        assert row["far_mm"] is None and row["hyperfocal_mm"] == h["hyperfocal_mm"]
        # a distance typed in front of H (the table's rounded 1.864 m was the old answer) stays finite
        (front,) = run_json("dof", *lens, "-s", repr(h["hyperfocal_mm"] * (1 - 1e-3)) + "mm", "--model", model)
        assert front["far_mm"] is not None and front["far_mm"] > 10 * h["hyperfocal_mm"]
    z8 = ["--camera", "nikon-z-8", "-f", "14", "-N", "2.8", "--coc-rule", "px:2"]
    (h,) = run_json("hyperfocal", *z8)
    rows = run_json("dof", *z8, "-s", "0.5,1,3,8,inf")
    assert {r["hyperfocal_mm"] for r in rows} == {h["hyperfocal_mm"]}
    # Wikipedia, "Hyperfocal distance": H = f²/(Nc) + f from the lens; from the sensor + f + Nc more
    c = h["coc_mm"]
    assert h["hyperfocal_mm"] == pytest.approx(14**2 / (2.8 * c) + 2 * 14 + 2.8 * c, rel=1e-12)
    assert rows[-1]["far_mm"] is None and rows[-1]["model"] == h["model"]
    listed = run_json("dof", *lens, "-s", "0.5,1,1.5,2,5,inf")
    assert len({r["hyperfocal_mm"] for r in listed}) == 1  # no drift with the row's rung or focus
    assert "H by the thin model" in run("dof", *lens, "-s", "0.5,1,1.864,5").stdout  # 1.864 m by approx


def test_a_typed_distance_beyond_h_is_infinite_and_every_row_names_its_model() -> None:
    lens = ["--lens", "ef-100-macro-l", "-N", "8", "--coc", "0.03"]
    (h,) = run_json("hyperfocal", *lens)
    rows = run_json("dof", *lens, "-s", ",".join(repr(h["hyperfocal_mm"] * k) + "mm" for k in (1, 1.5, 3)))
    assert all(r["far_mm"] is None and r["model"] == h["model"] for r in rows)
    assert not math.isnan(h["near_mm"])


def test_the_last_frame_of_a_bracket_to_infinity_lies_at_h() -> None:
    lens = ["--lens", "nikon-z-24mm-f1.8-s", "-N", "11"]
    (h,) = run_json("hyperfocal", *lens, "--model", "thin")
    frames = run_json("stack", *lens, "--near", "0.3", "--far", "inf", "--model", "thin")
    assert frames[-1]["distance_mm"] == h["hyperfocal_mm"]
    assert frames[-1]["far_mm"] is None
    import camtool  # the Python API asks the same plan: the same last frame

    plan = camtool.bracket_stack(h["focal_length_mm"], 11, h["coc_mm"], 300, float("inf"), model="thin",
                                 lens="nikon-z-24mm-f1.8-s")
    assert [f.distance_mm for f in plan.frames] == [f["distance_mm"] for f in frames]


@pytest.mark.parametrize("plane", ["sensor", "lens"])
@pytest.mark.parametrize("model", ["thin", "approx", "thick", "auto"])
def test_a_plain_lens_bracketed_to_infinity_ends_at_hyperfocal_h(plane: str, model: str) -> None:
    lens = ["-f", "50", "-N", "8", "--coc", "0.03", "--pupil-mag", "0.7", "--hiatus", "5", "--distance-from", plane]
    (h,) = run_json("hyperfocal", *lens, "--model", model)
    frames = run_json("stack", *lens, "--near", "1", "--far", "inf", "--model", model)
    assert frames[-1]["distance_mm"] == h["hyperfocal_mm"] and frames[-1]["far_mm"] is None
    import camtool  # the Python API: the same frames, the same H

    plan = camtool.bracket_stack(50, 8, 0.03, 1000, float("inf"), model=model, distance_from=plane,
                                 pupil_magnification=0.7, hiatus_mm=5)
    assert [f.distance_mm for f in plan.frames] == [f["distance_mm"] for f in frames]
    assert camtool.hyperfocal_distance(50, 8, 0.03, model=model, distance_from=plane, pupil_magnification=0.7,
                                       hiatus_mm=5).hyperfocal_mm == h["hyperfocal_mm"]
    assert all(f["distance_mm"] < h["hyperfocal_mm"] for f in frames[:-1])
    if model == "thin" and plane == "lens":  # Wikipedia, "Hyperfocal distance": H = f²/(N·c) + f
        assert h["hyperfocal_mm"] == pytest.approx(50**2 / (8 * 0.03) + 50, rel=1e-12)


@pytest.mark.parametrize("model", ["thin", "auto"])
def test_the_chart_api_gives_the_card_and_curves_the_command_draws(model: str, tmp_path) -> None:
    """``camtool.chart`` and ``camtool chart … --data`` are one path: the same numbers, float for float."""
    import json

    import camtool

    data = tmp_path / "card.json"
    result = run("chart", "card", "-f", "50", "-N", "4,8", "-s", "2m,5m", "--coc", "0.03", "--model", model,
                 "-o", str(tmp_path / "card.svg"), "--data", str(data))
    assert result.exit_code == 0, result.output
    card = camtool.chart("card", coc_mm=0.03, focal_length_mm=50, f_number=[4, 8], distance_mm=[2000, 5000],
                         model=model)
    shown = json.loads(data.read_text())
    assert shown["extra"]["near_mm"] == card.to_json()["extra"]["near_mm"]
    assert shown["extra"]["far_mm"] == card.to_json()["extra"]["far_mm"]
    dof = run("chart", "dof", "-f", "50", "-N", "8", "--coc", "0.03", "--model", model, "-o",
              str(tmp_path / "dof.svg"), "--data", str(data))
    assert dof.exit_code == 0, dof.output
    curves = camtool.chart("dof", coc_mm=0.03, focal_length_mm=50, f_number=8, model=model).to_json()["curves"]
    assert json.loads(data.read_text())["curves"] == curves
@settings(max_examples=30, deadline=None)
@given(angle=st.floats(1.0, 360.0), fps=st.sampled_from([23.976, 24.0, 25.0, 48.0, 120.0]))
def test_one_shutter_time_per_angle_command_line_and_api(angle, fps):
    import camtool

    by_angle = run_json("exposure", "--ev100", "12", "-N", "4", "--shutter-angle", repr(angle), "--fps", repr(fps))[0]
    api = camtool.rotary_shutter(fps=fps, shutter_angle_deg=angle)
    assert by_angle["shutter_s"] == api.shutter_s == angle / (360.0 * fps)
    assert by_angle["shutter_angle_deg"] == pytest.approx(angle, rel=1e-14)


def test_one_coc_map_command_line_and_api(tmp_path):
    import json

    import numpy as np

    import camtool

    openexr = pytest.importorskip("OpenEXR")
    z = np.geomspace(0.5, 50.0, 32, dtype=np.float32)[None, :].repeat(2, axis=0)
    depth = str(tmp_path / "d.exr")
    openexr.File({"compression": openexr.NO_COMPRESSION, "type": openexr.scanlineimage}, {"Z": z}).write(depth)
    out = tmp_path / "m.npy"
    row = json.loads(run("cocmap", depth, "-o", str(out), "-f", "50", "-N", "2.8", "-s", "3m", "--pupil-offset",
                         "90mm", "--coc", "0.03", "--format", "json").stdout)[0]
    api = camtool.coc_map(z.astype(float) * 1000.0, focus_mm=3000.0 - 90.0, focal_length_mm=50, f_number=2.8,
                          coc_mm=0.03)
    assert (row["near_limit_mm"], row["far_limit_mm"]) == (api.near_limit_mm, api.far_limit_mm)
    assert row["sharp_fraction"] == api.sharp_fraction
    assert np.allclose(np.load(out)[0], api.coc_mm, rtol=1e-6, atol=1e-6 * float(api.coc_mm.max()))
@pytest.mark.parametrize("criterion", ["mtf:0.3@coc", "mtf:0.5@20"])
def test_a_contrast_criterion_gives_one_answer_by_option_batch_and_api(criterion: str, tmp_path) -> None:
    """dof --criterion, a batch row's criterion cell, the Python API and hyperfocal: one wave rung, one H."""
    import camtool

    (option,) = run_json("dof", "-f", "50", "-N", "8", "-s", "3", "--criterion", criterion)
    batch_file = tmp_path / "rows.csv"
    batch_file.write_text(f"focal-length,f-number,distance,criterion\n50,8,3,{criterion}\n", encoding="utf-8")
    (batch,) = run_json("dof", "--batch", str(batch_file))
    api = camtool.depth_of_field(50, 8, option["coc_mm"], 3000, contrast_criterion=criterion)
    assert option["model"] == batch["model"] == api.model == "wave"
    for key in ("near_mm", "far_mm", "hyperfocal_mm"):
        assert option[key] == batch[key] == getattr(api, key)
    (h,) = run_json("hyperfocal", "-f", "50", "-N", "8", "--criterion", criterion)
    assert h["hyperfocal_mm"] == option["hyperfocal_mm"]
    (at_h,) = run_json("dof", "-f", "50", "-N", "8", "-s", f"{h['hyperfocal_mm']}mm", "--criterion", criterion)
    assert at_h["far_mm"] is None  # infinity


ANAMORPHIC = sorted((m for lens in load_db().all("lens") if getattr(lens, "squeeze", None) for m in lens.members
                     or [lens]), key=lambda m: m.id)
CHARTED = {(lens.members or (lens,))[0].id for lens in load_db().all("lens") if getattr(lens, "squeeze", None)}
"""The members whose chart is compared too: the first of each anamorphic set, and each single anamorphic lens."""


@pytest.mark.parametrize("member", ANAMORPHIC, ids=lambda m: m.id)
def test_an_anamorphic_preset_and_its_squeeze_typed_on_a_spherical_lens_give_one_answer(member, tmp_path) -> None:
    """The same scene via --lens ANAMORPHIC and via --squeeze S on a spherical lens preset with the member's own
    focal length, T-stop and closest focus: fov, dof and compose give the same numbers, and so does chart dof on the
    first member of each set."""
    own = {"focal_length_mm": member.focal_min_mm, "t_number_min": member.t_number_min,
           "min_focus_mm": member.min_focus_mm}
    spherical = tmp_path / "spherical.yaml"
    spherical.write_text("lenses:\n  - id: spherical\n    source: the anamorphic member's data without its squeeze\n"
                         + "".join(f"    {k}: {v!r}\n" for k, v in own.items() if v is not None))
    ways = {"preset": ["--lens", member.id],
            "typed": ["--presets", str(spherical), "--lens", "spherical", "--squeeze", repr(member.squeeze)]}
    common = ["--camera", "arri-alexa-35"]
    stop = f"T{max(2.8, member.t_number_min or 0):g}"  # T2.8, or the member's own widest stop where it is slower
    answers = {}
    for way, args in ways.items():
        answers[way] = [
            run_json("fov", *args, *common),
            run_json("dof", *args, *common, "-N", stop, "-s", "3m,10ft"),
            run_json("compose", *args, *common, "--subject-size", "4m", "--fill", "0.9", "--fill-axis", "width",
                     "-N", stop),
        ]
    assert answers["preset"] == answers["typed"]
    assert answers["preset"][1][0]["horizontal_focal_length_mm"] == member.focal_min_mm / member.squeeze
    if member.id not in CHARTED:
        return
    pytest.importorskip("matplotlib")
    import json

    curves = {}
    for way, args in ways.items():
        data = tmp_path / f"{way}.json"
        result = run("chart", "dof", *args, *common, "-N", stop, "-o", str(tmp_path / f"{way}.svg"), "--data",
                     str(data))
        assert result.exit_code == 0, result.output
        curves[way] = json.loads(data.read_text())["curves"]
    assert curves["preset"] == curves["typed"]


def test_a_contrast_criterion_on_a_prescription_gives_one_answer_by_option_and_api() -> None:
    """dof --prescription --criterion and the Python API: the one wave rung on the real wavefront, one answer."""
    import camtool

    (option,) = run_json("dof", "--prescription", "telephoto127", "-N", "11", "-s", "3", "--criterion", "mtf:0.3@20")
    lens = load_db().prescription("telephoto127").optics
    api = camtool.depth_of_field(None, 11, option["coc_mm"], 3000, prescription=lens, contrast_criterion="mtf:0.3@20")
    assert option["model"] == api.model == "wave+prescription"
    for key in ("near_mm", "far_mm", "hyperfocal_mm"):
        assert option[key] == getattr(api, key)
    (wave,) = run_json("dof", "--prescription", "telephoto127", "-N", "11", "-s", "3", "--model", "wave",
                       "--criterion", "mtf:0.3@20")
    assert wave["near_mm"] == option["near_mm"] and wave["far_mm"] == option["far_mm"]


@pytest.mark.parametrize("lens", [["--lens", "telephoto127-lens"], ["--lens", "dgauss100-lens"]])
def test_hyperfocal_by_contrast_on_a_prescription_is_the_wavefronts_h_dof_reports(lens: list[str]) -> None:
    """hyperfocal and dof's H column by a contrast criterion on a real lens: the one wave+prescription H."""
    (h,) = run_json("hyperfocal", *lens, "-N", "8", "--criterion", "mtf:0.3@coc")
    assert h["model"] == "wave+prescription"
    for distance in ("3", "20", f"{h['hyperfocal_mm']!r}mm"):
        (row,) = run_json("dof", *lens, "-N", "8", "-s", distance, "--criterion", "mtf:0.3@coc")
        assert row["model"] == h["model"]
        # the far limit's search ends within 1e-7 of its step, so H agrees to that search's tolerance
        assert row["hyperfocal_mm"] == pytest.approx(h["hyperfocal_mm"], rel=1e-9)
    assert row["far_mm"] is None and row["near_mm"] == pytest.approx(h["near_mm"], rel=1e-9)  # focused at H
    (thin,) = run_json("hyperfocal", *lens, "-N", "8", "--criterion", "mtf:0.3@coc", "--model", "thin")
    assert thin["model"] == "thin"  # a geometric rung named keeps its closed form


def test_the_api_s_hyperfocal_distance_takes_arrays_of_any_shape() -> None:
    # a 2-D array of focal lengths (the API fuzz found it raising a TypeError) gives each scene's own distance,
    # the float a call for that scene gives
    import numpy as np

    import camtool

    focal = np.array([[250.0, 50.0], [24.0, 85.0]])
    many = camtool.hyperfocal_distance(focal, 8, 0.03)
    assert np.shape(many.hyperfocal_mm) == focal.shape
    for index in np.ndindex(focal.shape):
        one = camtool.hyperfocal_distance(float(focal[index]), 8, 0.03)
        assert many.hyperfocal_mm[index] == one.hyperfocal_mm and many.near_mm[index] == one.near_mm
    # the same with a lens preset that focuses internally (each scene through its own plan): the input's shape kept
    apertures = np.array([[4.0, 8.0, 11.0], [16.0, 5.6, 2.8]])
    many = camtool.hyperfocal_distance(np.full(apertures.shape, 50.0), apertures, 0.03, lens="nikon-z-50mm-f1.8-s")
    assert np.shape(many.hyperfocal_mm) == np.shape(many.near_mm) == apertures.shape
    for index in np.ndindex(apertures.shape):
        one = camtool.hyperfocal_distance(50.0, float(apertures[index]), 0.03, lens="nikon-z-50mm-f1.8-s")
        assert (many.hyperfocal_mm[index], many.near_mm[index]) == (one.hyperfocal_mm, one.near_mm)
        assert many.model == one.model


@settings(max_examples=40, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(lens=st.sampled_from([lens for lens in LENSES if not getattr(lens, "members", ())]), t=st.floats(0, 1),
       u=st.floats(0, 1), plane=st.sampled_from(["sensor", "lens"]), model=st.sampled_from(["auto", "thin"]))
def test_the_api_s_depth_of_field_of_a_lens_preset_is_the_command_s(lens, t, u, plane, model) -> None:
    """``depth_of_field(..., lens=NAME)`` is ``camtool dof --lens NAME``: the focal length in effect at each focus of
    a lens that focuses internally, its one hyperfocal distance, the rung; a prime's focal length left out."""
    import camtool

    n = _f_number(lens, u)
    closest = (lens.min_focus_mm or 300.0) * 1.2
    distance = round(closest * (20_000.0 / closest) ** t, 3)
    focal = _focal(lens, t)
    row = run_json("dof", "--lens", lens.id, *focal, "-N", repr(n), "-s", f"{distance!r}mm", "--coc", "0.03",
                   "--distance-from", plane, "--model", model)[0]
    answer = camtool.depth_of_field(float(focal[1]) if focal else None, n, 0.03, distance, distance_from=plane,
                                    model=model, lens=lens.id)
    assert (answer.near_mm, answer.far_mm, answer.hyperfocal_mm, answer.magnification, answer.model) == (
        row["near_mm"], math.inf if row["far_mm"] is None else row["far_mm"], row["hyperfocal_mm"],
        row["magnification"], row["model"])


def test_the_api_s_depth_of_field_of_a_lens_preset_over_arrays_is_each_scene_s() -> None:
    import numpy as np

    import camtool

    apertures, distances = np.array([1.8, 4.0, 11.0]), np.array([[400.0], [3000.0]])
    many = camtool.depth_of_field(None, apertures, 0.03, distances, lens="nikon-z-50mm-f1.8-s")
    assert many.near_mm.shape == many.model.shape == (2, 3)
    for (i, j), near in np.ndenumerate(many.near_mm):
        one = camtool.depth_of_field(None, float(apertures[j]), 0.03, float(distances[i, 0]),
                                     lens="nikon-z-50mm-f1.8-s")
        assert (near, many.hyperfocal_mm[i, j], many.model[i, j]) == (one.near_mm, one.hyperfocal_mm, one.model)
    prescription = camtool.depth_of_field(None, 4.0, 0.03, 3000.0, lens="dgauss100-lens")
    row = run_json("dof", "--lens", "dgauss100-lens", "-N", "4", "-s", "3m", "--coc", "0.03")[0]
    assert (prescription.near_mm, prescription.model) == (row["near_mm"], row["model"])


@pytest.mark.parametrize("name", ["nikon-z-50mm-f1.8-s", "nikon-z-24mm-f1.8-s", "arri-signature-prime@47"])
def test_a_prime_s_focal_length_left_out_of_the_api_is_the_preset_s_as_on_the_command_line(name: str) -> None:
    """``hyperfocal_distance(None, ..., lens=NAME)`` takes the prime's (or the set member's) focal length, as
    ``camtool hyperfocal --lens NAME`` without ``-f`` does."""
    import camtool

    row = run_json("hyperfocal", "--lens", name, "-N", "8", "--coc", "0.03")[0]
    answer = camtool.hyperfocal_distance(None, 8.0, 0.03, lens=name)
    assert (answer.hyperfocal_mm, answer.near_mm, answer.model) == (row["hyperfocal_mm"], row["near_mm"], row["model"])
