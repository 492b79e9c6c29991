"""The wave rung with a prescription: the real lens's wavefront, its FFT MTF, and depth of field by contrast.

Checked against independent values: the analytic OTF of a perfect pupil in and out of focus
(camtool.optics.transfer, itself checked against mpmath in test_wave.py); optiland 0.6.3's FFT MTF of
the shipped prescriptions (tests/data/optiland-fft-mtf.csv, made by benchmarks/optiland_wave_reference.py;
a live comparison when optiland is installed); physical identities (the skew-ray trace at a vanishing
field angle against the meridional one, the limits' own contrast, far = ∞ from the hyperfocal distance).
"""

from __future__ import annotations

import csv
import math
from pathlib import Path

import numpy as np
import pytest

from camtool.core.errors import DomainError
from camtool.dof.ladder import LensData, depth_of_field
from camtool.dof.wave import Criterion, wave_dof
from camtool.dof.wavetrace import NothingSharpHere, prescription_wave_dof
from camtool.optics.prescription import EXAMPLE_SINGLET, prescription_from_mapping
from camtool.optics.tracer import RayTraceError
from camtool.optics.transfer import defocus_mtf
from camtool.optics.wavefront import RadialWave, grid, otf_at_lag, otf_grid, radial_mtf, wavefront_tracer

ROOT = Path(__file__).resolve().parent.parent
DATA = Path(__file__).resolve().parent / "data"


def shipped() -> dict[str, object]:
    """The shipped prescriptions by id (:func:`camtool.presets.shipped.prescriptions_by_id`)."""
    from camtool.presets.shipped import prescriptions_by_id

    return prescriptions_by_id()


LENSES = shipped()


# -- the FFT MTF of a perfect pupil against the analytic OTF ------------------------------------------


@pytest.mark.parametrize("defocus", [0.0, 0.25, 0.5, 1.0, 2.0, 4.0])
def test_fft_mtf_of_a_perfect_pupil_agrees_with_the_analytic_otf(defocus: float) -> None:
    """W = W₂₀·ρ² on the grid camtool uses: |OTF| within 0.005 of Hopkins' autocorrelation at every frequency."""
    # W₂₀·ρ² in Chebyshev terms of x = 2ρ² − 1: W₂₀/2·(1 + x)
    coef = np.zeros((1, 33))
    coef[0, :2] = defocus / 2.0
    worst = 0.0
    for s in np.linspace(0.01, 0.99, 99):
        wave = RadialWave(coef, np.array([1.0]))  # one stop radius of shift is 1 lp/mm: ν = 2s
        fft = float(radial_mtf(wave, 2.0 * s)[0])
        worst = max(worst, abs(fft - abs(defocus_mtf(float(s), defocus))))
    assert worst < 0.005


def test_the_row_transform_is_the_two_dimensional_otf() -> None:
    """otf_at_lag (one FFT per row) gives the 2-D FFT of the PSF along the axis, to rounding."""
    coords, _ = grid(2.0 / 40)
    x, y = np.meshgrid(coords, coords)
    rng = np.random.default_rng(3)
    phase = 0.7 * x * x + 0.3 * y ** 3 + 0.1 * rng.standard_normal(x.shape)
    pupil = np.where(x * x + y * y <= 1.0, np.exp(2j * np.pi * phase), 0.0)
    full = otf_grid(pupil)
    for lag in (1, 7, 20, 35):
        assert abs(otf_at_lag(pupil, float(lag)) - full[0, lag]) < 1e-12
        assert abs(otf_at_lag(pupil, float(lag), axis=-2) - full[lag, 0]) < 1e-12


# -- the wavefront itself ------------------------------------------------------------------------------


@pytest.mark.parametrize("name", sorted(LENSES))
def test_the_radial_interpolant_agrees_with_a_ray_per_radius(name: str) -> None:
    """On the axis W(ρ²) is interpolated from 33 rays: within 1e-4 waves of tracing each radius."""
    lens = LENSES[name]
    tracer = wavefront_tracer(lens)
    n = lens.f_number
    film = float(tracer.rays.summaries([0.0], n).z_best[0])
    v = np.array([0.0, 2e-4, 1e-3])
    radii = np.linspace(0.0, 1.0, 41)
    exact = tracer.radial(v, n, film, radii=radii).coef
    wave = tracer.radial(v, n, film)
    interpolated = np.polynomial.chebyshev.chebval(2.0 * radii * radii - 1.0, wave.coef.T[:, :, None])[:, 0, :]
    assert np.max(np.abs(interpolated - exact)) < 1e-4


@pytest.mark.parametrize("name", ["dgauss100", "canon-rf50-f1.2"])
def test_skew_rays_at_a_vanishing_field_give_the_axial_wavefront(name: str) -> None:
    """Every grid point traced as a skew ray at 1e-7° off the axis: the axial (meridional) wavefront and MTF."""
    lens = LENSES[name]
    tracer = wavefront_tracer(lens)
    n = 2.0 * lens.f_number
    film = float(tracer.rays.summaries([0.0], n).z_best[0])
    axial = tracer.wavefront([0.0, 5e-4], n, film, 0.0, 2.0 / 60)
    skew = tracer.wavefront([0.0, 5e-4], n, film, 1e-7, 2.0 / 60)
    assert np.array_equal(axial.inside, skew.inside)
    assert np.max(np.abs(axial.opd_waves - skew.opd_waves)) < 1e-4
    assert np.allclose(tracer.mtf([5e-4], n, film, 30.0), tracer.mtf([5e-4], n, film, 30.0, field_deg=1e-7),
                       atol=1e-6)


# -- against optiland ----------------------------------------------------------------------------------


def _reference_rows() -> list[dict[str, str]]:
    with open(DATA / "optiland-fft-mtf.csv", encoding="utf-8") as handle:
        return list(csv.DictReader(line for line in handle if not line.startswith("#")))


def _camtool_mtf(row: dict[str, str], same_lag: bool = False) -> tuple[float, float]:
    """camtool's (tangential, sagittal) MTF for a row: at its frequency, or at optiland's pupil lag (``same_lag``).

    optiland scales its frequency axis by the directions of the marginal rays themselves, camtool by the
    reference sphere centred on the film (docs/wave.md); on a defocused film the two differ by the ratio of
    the rays' convergence to the sphere's. ``same_lag`` converts optiland's frequency to camtool's scale by
    that ratio (on the axis), so both read the autocorrelation of the pupil function at the same shift.
    """
    lens = LENSES[row["lens"]]
    tracer = wavefront_tracer(lens)
    object_z, n, film = float(row["object_z_mm"]), float(row["f_number"]), float(row["film_z_mm"])
    v = 0.0 if math.isinf(object_z) else 1.0 / (tracer.first.z_e_mm - object_z)
    frequency = float(row["frequency_lpmm"])
    if same_lag and float(row["field_deg"]) == 0.0:
        aims = tracer.aim(np.array([[v]]), 0.0, 0.0, np.array([[0.0, 1.0]]), tracer._r_stop(n))[1]
        rays = tracer._to_image(np.array([[v]]), 0.0, 0.0, aims)
        canonical = abs(float(tracer._sphere(rays, 0.0, 0.0, np.array([[film]]))[2][0, 1]))
        frequency *= canonical / abs(float(rays[4][0, 1]))
    sagittal, tangential = tracer.mtf([v], n, film, frequency, float(row["field_deg"]))[0]
    return float(tangential), float(sagittal)


def _worst(rows: list[dict[str, str]], same_lag: bool) -> float:
    worst = 0.0
    for row in rows:
        tangential, sagittal = _camtool_mtf(row, same_lag)
        for key, value in (("mtf_tangential", tangential), ("mtf_sagittal", sagittal)):
            if row[key]:
                worst = max(worst, abs(value - float(row[key])))
    return worst


def test_fft_mtf_agrees_with_optiland_on_every_shipped_prescription() -> None:
    """Every stored optiland value (in focus and defocused, on the axis and off it) within 0.02 MTF.

    At optiland's own frequencies every scene within a quarter wave of focus agrees within 0.02 (in
    fact 0.005); three quarter waves out of focus the two frequency scales part (by 4 % on cellphone at
    f/7, where the MTF then differs by up to 0.024), and at the same pupil shift every row agrees
    within 0.005.
    """
    rows = _reference_rows()
    assert {row["lens"] for row in rows} == set(LENSES)
    near_focus = [row for row in rows if float(row["defocus_quarter_waves"]) <= 1.0]
    assert len(near_focus) > len(rows) / 2
    assert _worst(near_focus, False) < 0.02
    assert _worst(rows, True) < 0.005


def test_fft_mtf_agrees_with_optiland_live() -> None:
    """The same check computed now by optiland, when it is installed (it is never a dependency)."""
    pytest.importorskip("optiland")
    import importlib.util
    import sys
    import warnings

    spec = importlib.util.spec_from_file_location("optiland_wave_reference",
                                                  ROOT / "benchmarks" / "optiland_wave_reference.py")
    module = importlib.util.module_from_spec(spec)  # type: ignore[arg-type]
    sys.modules["optiland_wave_reference"] = module
    spec.loader.exec_module(module)  # type: ignore[union-attr]
    from optiland.mtf import FFTMTF

    lens = LENSES["telephoto127"]
    n, object_z, film_z, field, _ = module.scenes("telephoto127", lens)[1]
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        op = module.optiland_lens(lens, n, object_z, film_z, field)
        mtf = FFTMTF(op, fields=[(0.0, 0.0)], wavelength="primary", num_rays=129, grid_size=512)
    for lag in (4, 16):
        row = {"lens": "telephoto127", "f_number": str(n), "object_z_mm": str(object_z), "film_z_mm": str(film_z),
               "field_deg": "0", "frequency_lpmm": str(float(np.asarray(mtf.freq_tang[0])[lag]))}
        assert abs(_camtool_mtf(row)[0] - float(np.asarray(mtf.mtf[0][0])[lag])) < 0.02


# -- depth of field by contrast --------------------------------------------------------------------------


SCENES = [("dgauss100", 4.0, 0.03, 2500.0), ("telephoto127", 11.2, 0.03, 3000.0), ("cellphone", 3.5, 0.0048, 300.0),
          ("canon-rf50-f1.2", 2.5, 0.03, 1250.0), ("nikon-z50-f1.8", 3.7, 0.03, 1250.0)]


@pytest.mark.parametrize(("name", "n", "coc", "distance"), SCENES)
def test_the_limits_have_the_criterions_contrast(name: str, n: float, coc: float, distance: float) -> None:
    """At the near and far limits the MTF on the focused film is the level; between them above it."""
    from camtool.dof.realray import real_focus

    lens = LENSES[name]
    criterion = Criterion(0.3, 0.5 / coc)
    r = prescription_wave_dof(lens, n, coc, distance, "sensor", criterion)
    assert r.near_mm < distance < r.far_mm < math.inf
    tracer = wavefront_tracer(lens)
    focus = real_focus(lens, n, distance, "sensor")
    z_near, z_far = focus.film_z_mm - r.near_mm, focus.film_z_mm - r.far_mm
    z_mid = focus.object_z_mm
    v = [1.0 / (tracer.first.z_e_mm - z) for z in (z_near, z_far, z_mid)]
    values = tracer.mtf(v, n, focus.film_z_mm, criterion.frequency_lpmm)[:, 0]
    assert values[0] == pytest.approx(0.3, abs=1e-6)
    assert values[1] == pytest.approx(0.3, abs=1e-6)
    assert values[2] > 0.3


def test_a_nearly_perfect_lens_gives_the_perfect_lens_depth() -> None:
    """A slow singlet (a fiftieth of a wave of spherical aberration at f/16) against the analytic wave rung."""
    lens = prescription_from_mapping(EXAMPLE_SINGLET)
    f = wavefront_tracer(lens).first.efl_mm
    criterion = Criterion(0.3, 20.0)
    real = prescription_wave_dof(lens, 16.0, 0.03, 3000.0, "lens", criterion)
    perfect = wave_dof(f, 16.0, 0.03, 3000.0, "lens", criterion, lens.wavelength_nm)
    assert real.near_mm == pytest.approx(perfect.near_mm, rel=0.01)
    assert real.far_mm == pytest.approx(perfect.far_mm, rel=0.01)


def test_far_is_infinite_exactly_from_the_hyperfocal_distance() -> None:
    lens = LENSES["telephoto127"]
    criterion = Criterion(0.3, 20.0)
    h = prescription_wave_dof(lens, 11.2, 0.03, 5000.0, "sensor", criterion).hyperfocal_mm
    assert math.isfinite(h)
    at_h = prescription_wave_dof(lens, 11.2, 0.03, h * (1.0 + 1e-6), "sensor", criterion)
    assert at_h.far_mm == math.inf
    assert at_h.hyperfocal_mm == pytest.approx(h, rel=1e-9)
    short = prescription_wave_dof(lens, 11.2, 0.03, h * 0.98, "sensor", criterion)
    assert math.isfinite(short.far_mm) and short.far_mm > 10.0 * h


def test_arrays_give_the_scalar_answers() -> None:
    lens = LENSES["dgauss100"]
    n = np.array([4.0, 8.0])
    d = np.array([2000.0, 3000.0])
    many = prescription_wave_dof(lens, n, 0.03, d)
    for i in range(2):
        one = prescription_wave_dof(lens, float(n[i]), 0.03, float(d[i]))
        assert many.near_mm[i] == one.near_mm and many.far_mm[i] == one.far_mm


def test_the_ladder_runs_it_for_wave_and_for_auto_with_a_criterion() -> None:
    lens = LensData(prescription=LENSES["dgauss100"])
    direct = prescription_wave_dof(LENSES["dgauss100"], 4.0, 0.03, 2500.0)
    for model, criterion in (("wave", None), ("auto", Criterion(0.181191754987, None))):
        r = depth_of_field(model, None, 4.0, 0.03, 2500.0, lens=lens, criterion=criterion)
        assert r.model == "wave+prescription" and r.error_estimate == 0.0
        assert r.limits.near_mm == pytest.approx(direct.near_mm, rel=1e-9)
    assert depth_of_field("wave", 100.0, 4.0, 0.03, 2500.0).model == "wave"  # no prescription: the perfect lens


# -- untrusted inputs ----------------------------------------------------------------------------------------


def test_nothing_sharp_at_the_focus_is_one_domain_error() -> None:
    with pytest.raises(NothingSharpHere) as caught:
        prescription_wave_dof(LENSES["cellphone"], 14.0, 0.0048, 300.0)
    assert isinstance(caught.value, DomainError)
    assert "nothing is sharp enough" in str(caught.value) and "cellphone" in str(caught.value)


def test_a_beam_that_cannot_get_through_is_a_ray_trace_error() -> None:
    """A singlet at f/0.75: the marginal rays are totally internally reflected."""
    lens = prescription_from_mapping(EXAMPLE_SINGLET)
    with pytest.raises(RayTraceError):
        prescription_wave_dof(lens, 0.75, 0.03, 3000.0)


def test_a_field_angle_out_of_range_is_refused() -> None:
    with pytest.raises(DomainError):
        prescription_wave_dof(LENSES["dgauss100"], 4.0, 0.03, 2500.0, field_deg=95.0)


# -- the optimum aperture by contrast with a real lens (focus --optimum --criterion) -----------------------------------

OPTIMA = [("dgauss100", "sensor", 2000.0, 5000.0, 30.0), ("telephoto127", "lens", 4000.0, math.inf, 20.0),
          ("cellphone", "entrance_pupil", 300.0, 900.0, 100.0)]


@pytest.mark.parametrize(("name", "plane", "near", "far", "nu"), OPTIMA)
def test_the_contrast_optimum_is_the_range_the_wave_rung_gives_at_its_contrast(name: str, plane: str, near: float,
                                                                              far: float, nu: float) -> None:
    """Focused and stopped down as the optimum says, the wave rung's limits at the MTF it found are the range asked
    for (two searches, one answer), and no film gives both ends more contrast a tenth of a stop either side."""
    from camtool.dof.realray import real_focus
    from camtool.dof.wavetrace import prescription_contrast_optimum

    lens = LENSES[name]
    r = prescription_contrast_optimum(lens, near, far, nu, plane)
    limits = prescription_wave_dof(lens, r.f_number, 0.03, r.distance_mm, plane, Criterion(r.mtf * (1 - 1e-9), nu))
    assert limits.near_mm == pytest.approx(near, rel=1e-6)
    assert limits.far_mm == pytest.approx(far, rel=1e-6) if math.isfinite(far) else math.isinf(limits.far_mm)
    assert limits.magnification == pytest.approx(r.magnification, rel=1e-12)
    tracer = wavefront_tracer(lens)
    fo = tracer.first
    for n in (r.f_number * 2 ** -0.05, r.f_number * 2 ** 0.05):
        films = np.linspace(real_focus(lens, n, far, plane).film_z_mm, real_focus(lens, n, near, plane).film_z_mm,
                            41)
        z_ref = films if plane == "sensor" else np.full_like(films, fo.z_h_mm if plane == "lens" else fo.z_e_mm)
        v_near = 1.0 / (fo.z_e_mm - (z_ref - near))
        v_far = np.zeros_like(films) if math.isinf(far) else 1.0 / (fo.z_e_mm - (z_ref - far))
        both = tracer.axial_mtf(np.concatenate([v_near, v_far]), n, np.concatenate([films, films]), nu)
        assert np.max(np.minimum(both[:41], both[41:])) < r.mtf + 1e-6


def test_a_nearly_perfect_lens_gives_the_perfect_lens_contrast_optimum() -> None:
    """The slow singlet at about f/34 against the analytic optimum of a perfect lens of its focal length and
    wavelength (camtool.dof.wave.contrast_optimum)."""
    from camtool.dof.wave import contrast_optimum
    from camtool.dof.wavetrace import prescription_contrast_optimum

    lens = prescription_from_mapping(EXAMPLE_SINGLET)
    real = prescription_contrast_optimum(lens, 2000.0, 5000.0, 30.0)
    perfect = contrast_optimum(wavefront_tracer(lens).first.efl_mm, 2000.0, 5000.0, 30.0, "sensor", lens.wavelength_nm)
    assert real.f_number == pytest.approx(perfect.f_number, rel=0.02)
    assert real.mtf == pytest.approx(perfect.mtf, abs=0.003)
    assert real.distance_mm == pytest.approx(perfect.distance_mm, rel=0.002)
    assert real.defocus_waves == pytest.approx(perfect.defocus_waves, rel=0.03)


def test_the_contrast_optimum_refuses_a_range_out_of_order() -> None:
    from camtool.dof.wavetrace import prescription_contrast_optimum

    lens = LENSES["dgauss100"]
    with pytest.raises(DomainError):
        prescription_contrast_optimum(lens, 5000.0, 2000.0, 30.0)
    with pytest.raises(DomainError):
        prescription_contrast_optimum(lens, 2000.0, 5000.0, -1.0)
    with pytest.raises(DomainError):
        prescription_contrast_optimum(lens, 10.0, 5000.0, 30.0)  # nearer than the lens can focus
    with pytest.raises(DomainError) as error:  # beyond what the lens resolves at any f-number: on the criterion
        prescription_contrast_optimum(lens, 2000.0, 5000.0, 2000.0)
    assert error.value.param == "criterion"
