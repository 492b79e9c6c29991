"""The rung table drives the ladder; one distance-plane check; a preset's prescription is the optics class."""

from __future__ import annotations

import pytest
from cli_helpers import run

from camtool.core.planes import FOCUS_PLANES, PLANES, check_plane
from camtool.dof import auto, ladder, rungs
from camtool.dof.closed import thin_dof
from camtool.dof.ladder import LensData, available_models, depth_of_field, model_choices
from camtool.dof.rungs import RUNGS, Rung


def test_the_cli_choices_and_help_come_from_the_table() -> None:
    from camtool.cli.dof import dof
    from camtool.cli.hyperfocal import hyperfocal

    model = next(p for p in dof.params if p.name == "model")
    assert tuple(model.type.choices) == (*(r.name for r in RUNGS), "auto", "all")
    for rung in RUNGS:
        assert f"{rung.name}: {rung.help}" in model.help
    h_model = next(p for p in hyperfocal.params if p.name == "model")
    assert tuple(h_model.type.choices) == (*(r.name for r in RUNGS if r.hyperfocal_help), "auto")
    assert {r.name: r.left_out for r in RUNGS} == auto.LEFT_OUT


def test_a_new_record_is_a_choice_and_an_auto_candidate(monkeypatch: pytest.MonkeyPatch) -> None:
    # A rung between thin and thick that leaves out only the hiatus; it runs the thin lens (same limits).
    calls = []

    def run(f, n, c, s, plane, lens, focus=None):
        calls.append(s)
        return thin_dof(f, n, c, s, plane)

    extra = Rung("halfway", run, ("hiatus", "aberrations"), "a test rung")
    monkeypatch.setattr(rungs, "RUNGS", (*RUNGS[:2], extra, *RUNGS[2:]))
    assert "halfway" in model_choices() and model_choices().index("halfway") == 2
    assert "halfway: a test rung" in ladder.model_help()
    assert available_models() == ("approx", "thin", "halfway")
    # With a pupil magnification far from 1 thin leaves out too much; the new rung leaves out only
    # the hiatus (0 here), so auto picks it before thick.
    lens = LensData(pupil_magnification=0.5)
    result = depth_of_field("auto", 100.0, 4.0, 0.03, 500.0, lens=lens)
    assert result.model == "halfway" and calls == [500.0]
    assert auto.left_out(auto.Effects(0.1, 0.2, 0.3, 0.4, 0.0, 0.5), "halfway", True) == pytest.approx(0.9)


def test_removed_records_leave_the_ladder(monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setattr(rungs, "RUNGS", RUNGS[:2])
    assert model_choices() == ("approx", "thin", "auto", "all")
    with pytest.raises(ValueError, match="unknown model 'raytrace'"):
        depth_of_field("raytrace", 50.0, 8.0, 0.03, 3000.0)


def test_records_are_complete() -> None:
    effects = set(auto.EFFECTS)
    for rung in RUNGS:
        assert set(rung.left_out) <= effects and rung.help
        assert rung.can_run(LensData()) == (not rung.needs)
        assert rung.name and callable(rung.run) and callable(rung.can_run)


@pytest.mark.parametrize("plane, allowed", [("pupil", PLANES), ("entrance_pupil", FOCUS_PLANES), ("", PLANES)])
def test_one_plane_check_one_message(plane: str, allowed: tuple[str, ...]) -> None:
    with pytest.raises(ValueError) as error:
        check_plane(plane, allowed)
    assert str(error.value) == f"distance_from must be one of {', '.join(allowed)}, not {plane!r}"


def test_every_model_rejects_an_unknown_plane_in_the_same_words() -> None:
    from camtool.dof.inverse import focus_for_limits
    from camtool.dof.thick import thick_dof
    from camtool.geometry.thinlens import focus_geometry

    calls = [
        lambda: thin_dof(50.0, 8.0, 0.03, 3000.0, "film"),
        lambda: thick_dof(50.0, 8.0, 0.03, 3000.0, distance_from="film"),
        lambda: focus_geometry(50.0, 3000.0, "film"),
        lambda: focus_for_limits(50.0, 0.03, 2000.0, 4000.0, "film"),
        lambda: depth_of_field("auto", 50.0, 8.0, 0.03, 3000.0, "film"),
    ]
    for call in calls:
        with pytest.raises(ValueError, match=r"^distance_from must be one of sensor, lens(, entrance_pupil)?, not 'film'$"):
            call()


def test_hyperfocal_names_only_its_own_options() -> None:
    result = run("hyperfocal", "-f", "50", "-N", "8", "--model", "thick")
    assert result.exit_code == 2
    assert "(--pupil-mag, --hiatus, or a --lens that has them)" in result.output
    assert "--prescription" not in result.output


def test_a_lens_preset_hands_over_the_optics_prescription() -> None:
    from camtool.optics.prescription import Prescription
    from camtool.presets import load_db

    db = load_db()
    lens = db.lens("dgauss100-lens")
    assert isinstance(lens.prescription, Prescription)
    assert lens.prescription is db.prescription("dgauss100").optics
    assert isinstance(db.prescription("dgauss100").optics, Prescription)


@pytest.mark.parametrize("model", ["approx", "thin", "thick", "auto"])
@pytest.mark.parametrize("diffraction", [False, True])
def test_the_focus_distance_is_converted_once(monkeypatch: pytest.MonkeyPatch, model: str, diffraction: bool) -> None:
    import camtool.dof.closed
    import camtool.dof.thick
    import camtool.geometry.thinlens as thinlens

    calls = []
    original = thinlens.lens_distances

    def counted(*args):
        calls.append(args)
        return original(*args)

    for module in (thinlens, camtool.dof.closed, camtool.dof.thick):
        monkeypatch.setattr(module, "lens_distances", counted)
    # (with a hiatus the thin model, which has none, converts with its own: that is a second, different geometry)
    lens = LensData(pupil_magnification=0.8)
    once = depth_of_field(model, 50.0, 8.0, 0.03, 3000.0, lens=lens, diffraction=diffraction)
    assert len(calls) == 1
    monkeypatch.undo()
    # the same answer as each piece converting on its own
    assert once.limits == thin_or_thick(model, lens, diffraction)


def thin_or_thick(model: str, lens: LensData, diffraction: bool):
    from camtool.dof.rungs import by_name

    result = depth_of_field(model, 50.0, 8.0, 0.03, 3000.0, lens=lens, diffraction=diffraction)
    name = str(result.model).split("+")[0]
    c = 0.03
    if diffraction:
        from camtool.dof.diffraction import usable_coc_mm
        from camtool.geometry.thinlens import focus_geometry

        m = focus_geometry(50.0, 3000.0, "sensor").magnification
        c = usable_coc_mm(0.03, 8.0, m, 0.8, 550.0) if "+diffraction" in str(result.model) else 0.03
    return by_name()[name].run(50.0, 8.0, c, 3000.0, "sensor", lens)


def test_auto_over_arrays_reuses_the_conversion(monkeypatch: pytest.MonkeyPatch) -> None:
    import numpy as np

    import camtool.dof.closed
    import camtool.dof.thick
    import camtool.geometry.thinlens as thinlens
    from camtool.dof.rungs import by_name

    distances = np.array([300.0, 3000.0, 30000.0, np.inf])
    lens = LensData(pupil_magnification=0.8)
    calls = []
    original = thinlens.lens_distances

    def counted(*args):
        calls.append(args)
        return original(*args)

    for module in (thinlens, camtool.dof.closed, camtool.dof.thick):
        monkeypatch.setattr(module, "lens_distances", counted)
    result = depth_of_field("auto", 50.0, 8.0, 0.03, distances, lens=lens)
    assert len(calls) == 1
    monkeypatch.undo()
    assert len(set(result.model)) > 1  # several rungs ran, each on its own scenes
    for i, s in enumerate(distances):  # each as its rung computes it alone, converting by itself
        alone = by_name()[result.model[i]].run(50.0, 8.0, 0.03, float(s), "sensor", lens)
        assert (result.limits.near_mm[i], result.limits.far_mm[i]) == pytest.approx((alone.near_mm, alone.far_mm),
                                                                                     rel=1e-12)
