"""``camtool stack`` on the command line: table snapshots, JSON keys, the rail/bracketing identities, errors."""

from __future__ import annotations

import itertools
import math

import pytest
from cli_helpers import run, run_json

BRACKET_TABLE = """\
         focus    near     far              step
frame      (m)    (mm)     (m)         m     (m)
────────────────────────────────────────────────
1       0.6687   500.0   1.023   0.03873       0
2        1.794   909.1       ∞   0.01375   1.125
2 frames · 0.5 m to ∞ · classic depth · thin model · overlap 0.2 · CoC 0.03 mm (--coc) · full frame 36 × 24 mm · from the sensor plane
"""

RAIL_TABLE = """\
         focus     near      far             step
frame     (mm)     (mm)     (mm)       m     (mm)
─────────────────────────────────────────────────
1       0.2816        0   0.5632   1.000        0
2       0.8448   0.5632    1.126   1.000   0.5632
3        1.408    1.126    1.690   1.000   0.5632
4        1.971    1.690    2.253   1.000   0.5632
4 frames · step 0.5632 mm at the subject (0.5632 mm of lens extension) · total depth 2 mm · wave depth λ/NA² · frame depth 0.5632 mm, overlap 0 · positions along the subject from its nearest point
"""


def test_bracketing_table_snapshot() -> None:
    assert run("stack", "-f", "24", "-N", "11", "--near", "0.5", "--far", "inf", "--coc", "0.03").stdout == BRACKET_TABLE


def test_rail_table_snapshot() -> None:
    assert run("stack", "-m", "1", "-N", "8", "--depth", "2mm", "--overlap", "0").stdout == RAIL_TABLE


KEYS = ["frame", "distance_mm", "near_mm", "far_mm", "magnification", "step_mm", "extension_step_mm",
        "criterion", "mode", "distance_from"]


def test_json_keys_and_bracketing_rows() -> None:
    rows = run_json("stack", "-f", "50", "-N", "8", "--near", "1m", "--far", "inf", "--overlap", "0.5")
    assert [list(r) for r in rows] == [KEYS] * len(rows)
    assert [r["frame"] for r in rows] == list(range(1, len(rows) + 1))
    assert rows[0]["near_mm"] == pytest.approx(1000.0, rel=1e-12)
    assert rows[-1]["far_mm"] is None or math.isinf(rows[-1]["far_mm"]) or rows[-1]["far_mm"] == "inf"
    assert {r["criterion"] for r in rows} == {"classic"} and {r["mode"] for r in rows} == {"bracket"}
    for a, b in itertools.pairwise(rows[:-1]):  # the last frame may be clamped at H (more overlap)
        assert a["far_mm"] - b["near_mm"] == pytest.approx(0.5 * (a["far_mm"] - a["near_mm"]), rel=1e-9)
        assert b["step_mm"] == pytest.approx(b["distance_mm"] - a["distance_mm"], rel=1e-12)


def test_rail_json_frames_times_step_covers_the_depth() -> None:
    rows = run_json("stack", "-m", "2", "-N", "5.6", "--depth", "3mm")
    step = rows[1]["step_mm"]
    assert len(rows) * step >= 3.0 > (len(rows) - 1) * step
    assert rows[0]["near_mm"] == 0.0 and rows[-1]["far_mm"] >= 3.0
    assert rows[0]["criterion"] == "wave"  # the default from 1:1 up
    assert rows[1]["extension_step_mm"] == pytest.approx(4.0 * step, rel=1e-12)


def test_criterion_default_and_choice_are_reported() -> None:
    assert run_json("stack", "-m", "0.5", "-N", "8", "--depth", "5mm")[0]["criterion"] == "classic"
    assert run_json("stack", "-m", "0.5", "-N", "8", "--depth", "5mm", "--criterion", "wave")[0]["criterion"] == "wave"
    out = run("stack", "-f", "24", "-N", "11", "--near", "1", "--far", "inf", "--criterion", "wave").stdout
    assert "wave depth" in out.splitlines()[-1]


def test_field_gives_the_focus_distances() -> None:
    out = run("stack", "-f", "24", "-N", "11", "--near", "0.5", "--far", "inf", "--field", "distance_mm").stdout
    values = [float(x) for x in out.split()]
    assert len(values) >= 2 and values == sorted(values)


@pytest.mark.parametrize(
    ("args", "message"),
    [
        (["-f", "100", "-N", "1.4", "--near", "0.5", "--far", "inf", "--coc", "0.001"],
         "Error: Invalid value for '--near': 500 mm is outside the valid range: far enough that at most 10000 frames "
         "reach --far (more than 10000 frames: a larger f-number, CoC or --near needs fewer)"),
        (["-f", "100", "-N", "8", "--near", "0.2", "--far", "inf"],
         "Error: Invalid value for '--near': 200 mm is outside the valid range: more than 400 mm from the sensor "
         "(4f + hiatus: the closest a lens focuses at m ≤ 1)"),
        (["-f", "100", "-N", "8", "--near", "2", "--far", "1"],
         "Error: Invalid value for '--far': 1 m is outside the valid range: beyond --near"),
        (["-f", "100", "-N", "64", "--near", "0.5", "--far", "1", "--diffraction", "--coc", "0.01"],
         "Error: Invalid value for '-N' / '--f-number': f/64 is outside the valid range: below f/7.45 (the Airy "
         "disc, 0.0859 mm, fills the CoC 0.01 mm: nothing is sharp)"),
        (["-m", "1", "-N", "8", "--depth", "1mm", "--overlap", "1"],
         "Error: Invalid value for '--overlap': 1 is outside the valid range: 0 to 0.99"),
        (["--lens", "mp-e-65", "-N", "2.8", "-m", "6", "--depth", "1mm"],
         "Error: Invalid value for '-m' / '--magnification': 6 is outside the valid range: 0 to 5 (the lens's "
         "largest magnification)"),
        (["--lens", "rf-50-1.8", "-N", "8", "--near", "0.25", "--far", "inf"],
         "Error: Invalid value for '--near': 250 mm is outside the valid range: at least 295.5 mm from the sensor "
         "(the near limit with the lens at its closest focus)"),
        (["--lens", "mp-e-65", "-N", "8", "--near", "0.25", "--far", "0.3"],
         "Error: Invalid value for '--lens': mp-e-65 is outside the valid range: a lens that focuses to infinity "
         "(this one works from 1× to 5×: stack it on a rail with -m and --depth)"),
        (["-m", "1", "-N", "8", "--depth", "1mm", "--model", "raytrace"],
         "Error: Invalid value for '--model': raytrace is not available in rail mode: the frames use the close-up "
         "closed form (thin, or thick with the pupil magnification); it applies to --near/--far"),
        (["-m", "1", "-N", "8,11", "--depth", "1mm"],
         "Error: Invalid value for '-N' / '--f-number': takes one value here"),
        (["-f", "50", "-N", "8", "--near", "1", "--far", "2", "-m", "1"],
         "Error: give -m and --depth (rail) or --near and --far (bracketing), not both"),
    ],
)
def test_errors_are_one_line_exit_2(args: list[str], message: str) -> None:
    result = run("stack", *args)
    assert result.exit_code == 2
    assert result.stdout == ""
    assert result.stderr.strip() == message


def test_a_thick_lens_moves_the_frames_and_keeps_the_chain() -> None:
    # through the ladder's thick rung (P = 0.6): the frames differ from the thin lens's, and each frame's
    # near limit still sits on the previous far limit less the overlap
    thin = run_json("stack", "-f", "50", "-N", "8", "--near", "1", "--far", "inf")
    thick = run_json("stack", "-f", "50", "-N", "8", "--near", "1", "--far", "inf", "--model", "thick",
                     "--pupil-mag", "0.6")
    assert abs(thick[1]["distance_mm"] / thin[1]["distance_mm"] - 1) > 1e-3
    for a, b in itertools.pairwise(thick[:-1]):
        assert a["far_mm"] - b["near_mm"] == pytest.approx(0.2 * (a["far_mm"] - a["near_mm"]), rel=1e-6)
    assert thick[0]["near_mm"] == pytest.approx(1000.0, rel=1e-9)


@pytest.mark.parametrize(("lens", "extra", "plane"), [
    ("sony-fe-85mm-f1.8", ["--far", "2.5"], "sensor"),
    ("ef-100-macro-l", [], "sensor"),
    ("ef-100-macro-l", [], "lens"),
    ("nikon-z-24-70mm-f4-s", ["-f", "50"], "sensor"),
    ("ef-100-macro-l", ["--model", "thick", "--pupil-mag", "0.6"], "sensor"),
])
def test_an_internally_focusing_lens_brackets_as_dof_sees_it(lens: str, extra: list[str], plane: str) -> None:
    # A lens preset with a published closest focus shortens its focal length as it focuses (docs/closeup.md §2).
    # Each frame's limits must be the ones `camtool dof` gives for that lens focused where the frame is
    # (dof places the subject through its own close-up planner), and the frames must still chain.
    common = ["--lens", lens, "-N", "8", "--coc", "0.03", "--distance-from", plane, *extra]
    near, far = (1.0, 2.5) if "--far" in extra else (0.5, 0.8)
    if "--far" in extra:
        common = common[:-2]
    frames = run_json("stack", *common, "--near", str(near), "--far", str(far))
    assert frames[0]["near_mm"] == pytest.approx(near * 1000, rel=1e-9) and frames[-1]["far_mm"] >= far * 1000
    for a, b in itertools.pairwise(frames):
        assert a["far_mm"] - b["near_mm"] == pytest.approx(0.2 * (a["far_mm"] - a["near_mm"]), rel=1e-6)
    focus = ",".join(repr(frame["distance_mm"] / 1000.0) for frame in frames)
    rows = run_json("dof", *common, "-s", focus)
    for frame, row in zip(frames, rows, strict=True):
        assert frame["near_mm"] == pytest.approx(row["near_mm"], rel=1e-9)
        assert frame["far_mm"] == pytest.approx(row["far_mm"], rel=1e-9)
        assert frame["magnification"] == pytest.approx(row["magnification"], rel=1e-9)


def test_internal_focus_is_named_and_reaches_the_hyperfocal_distance() -> None:
    result = run("stack", "--lens", "ef-100-macro-l", "-N", "8", "--coc", "0.03", "--near", "0.3", "--far", "inf")
    assert result.exit_code == 0 and "the lens focuses internally: f 75.12 to 99.92 mm" in result.stdout
    frames = run_json("stack", "--lens", "ef-100-macro-l", "-N", "8", "--coc", "0.03", "--near", "0.3", "--far", "inf")
    last = frames[-1]
    assert last["far_mm"] is None and frames[-2]["far_mm"] is not None  # JSON writes infinity as null
    # the thin-lens hyperfocal focus of the lens at that setting: m = N·c/f(m), f(m) = f0/(1 + κm), κ = 1/3
    # (EF 100 mm f/2.8L Macro: 1:1 at 0.3 m), so m = Nc/(f0 − κNc)
    m = 8 * 0.03 / (100.0 - 8 * 0.03 / 3)
    assert last["magnification"] == pytest.approx(m, rel=1e-9)
