"""Reference FFT MTF values from optiland for camtool's wave rung with a prescription (tests/data/optiland-fft-mtf.csv).

Run with a Python that has optiland (never a dependency of camtool, at run time or in the tests):

    python3 -m venv /tmp/optics-wave && /tmp/optics-wave/bin/pip install optiland==0.6.3
    /tmp/optics-wave/bin/python benchmarks/optiland_wave_reference.py > tests/data/optiland-fft-mtf.csv

For every shipped prescription (lens_db/prescriptions/) the lens is built in optiland from the same
surfaces (spherical, conic and polynomial aspheric surfaces as optiland's ``odd_asphere``, whose sag
is the conic plus Σ C_i·r^i, the form of the YAML files; indices as ``IdealMaterial`` at the file's
wavelength), with the aperture stop where the file puts it and ray aiming ``iterative`` (rays aimed at
a square grid on the real stop, as camtool aims them). optiland sizes the stop by the entrance-pupil
diameter: the stop's edge is where the real ray through the pupil's edge meets it; camtool's stop is
the paraxial f/(2·N·m_E) of its reference data (about 1 % larger in radius on dgauss100 at f/2), so
optiland is given the entrance-pupil diameter whose real edge ray meets camtool's stop (camtool's
edge-ray aim for that object). With that, optiland's optical path differences agree with camtool's to
about 1e-7 waves (dgauss100, f/2, on the axis). The
scenes: the object at infinity and at 20 focal lengths, on the film camtool's ``real_focus`` puts at
that focus (the real best focus) and on a film moved from it by a stated defocus; one field point at
infinity for the longer lenses. optiland's ``FFTMTF`` (strategy ``chief_ray``: the reference sphere
centred on the chief ray's image point, through the exit pupil; num_rays 129 across the pupil,
grid 512) gives the tangential and sagittal MTF at its own frequency samples (lags of its pupil
grid); the rows keep a few of them. Columns: lens, f_number, object_z_mm (lens coordinates, the
first vertex at 0; ``-inf`` at infinity), film_z_mm, defocus_quarter_waves (how far the film was moved
behind the focus), field_deg, frequency_lpmm, mtf_tangential, mtf_sagittal.
"""

from __future__ import annotations

import math
import sys
import warnings
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT))

import numpy as np  # noqa: E402

from camtool.dof.realray import real_focus  # noqa: E402
from camtool.optics.paraxial import first_order  # noqa: E402
from camtool.optics.tracer import real_tracer  # noqa: E402

NUM_RAYS = 129
GRID = 512
LAGS = (4, 8, 16, 28)
"""The optiland frequency samples kept: these lags of its 129-point pupil grid (of 128 to the cut-off)."""


def shipped() -> dict[str, object]:
    """The shipped prescriptions by id (:func:`camtool.presets.shipped.prescriptions_by_id`)."""
    from camtool.presets.shipped import prescriptions_by_id

    return prescriptions_by_id()


def optiland_lens(lens, f_number: float, object_z: float, film_z: float, field_deg: float):
    """The optiland Optic of a prescription with its object and film placed (lens coordinates, mm)."""
    from optiland.materials import IdealMaterial
    from optiland.optic import Optic

    op = Optic()
    op.add_surface(index=0, thickness=np.inf if math.isinf(object_z) else -object_z)
    last = len(lens.surfaces) - 1
    for i, s in enumerate(lens.surfaces):
        material = IdealMaterial(n=s.n) if s.n != 1.0 else "air"
        thickness = film_z - lens.vertices_mm[-1] if i == last else s.thickness_mm
        extra = {}
        if s.aspheric:
            terms = dict(s.aspheric)
            extra = {"surface_type": "odd_asphere",
                     "coefficients": [terms.get(p, 0.0) for p in range(1, max(terms) + 1)]}
        op.add_surface(index=i + 1, radius=s.radius_mm, thickness=thickness, material=material, is_stop=s.stop,
                       conic=s.conic, **extra)
    op.add_surface(index=len(lens.surfaces) + 1)
    # optiland's EPD places the stop's edge where the real ray through the edge of the entrance pupil meets it;
    # camtool's stop is the paraxial f/(2·N·m_E): give optiland the pupil whose real edge ray meets that stop
    tracer = real_tracer(lens)
    vergence = 0.0 if math.isinf(object_z) else 1.0 / (tracer.first.z_e_mm - object_z)
    edge = float(tracer.aims([vergence], f_number)[0])
    op.set_aperture(aperture_type="EPD", value=2.0 * edge)
    op.set_field_type(field_type="angle")
    op.add_field(y=0.0)
    if field_deg:
        op.add_field(y=field_deg)
    op.add_wavelength(value=lens.wavelength_nm / 1000.0, is_primary=True)
    op.ray_tracer.set_aiming("iterative")
    return op


def scenes(name: str, lens) -> list[tuple[float, float, float, float, float]]:
    """(N, object z, film z, field, defocus) per scene: infinity and 20 f, in focus and moved by 1 or 3 quarter
    waves of defocus (2·λ·N² each, behind the focus); a field point in focus."""
    fo = first_order(lens)
    n_design = lens.f_number or 4.0
    out = []
    for n in (n_design, 2.0 * n_design):
        lam = lens.wavelength_nm * 1e-6
        quarter = 2.0 * lam * n * n  # the image-side shift of a quarter wave of defocus at f/N: 2λN²
        for distance in (math.inf, 20.0 * fo.efl_mm):
            focus = real_focus(lens, n, distance, "sensor")
            for quarters in (0.0, 1.0 if n == n_design else 3.0):
                out.append((n, focus.object_z_mm, focus.film_z_mm + quarters * quarter, 0.0, quarters))
    if fo.efl_mm > 20.0:
        focus = real_focus(lens, 2.0 * n_design, math.inf, "sensor")
        out.append((2.0 * n_design, focus.object_z_mm, focus.film_z_mm, 8.0, 0.0))
    return out


def main() -> None:
    from importlib.metadata import version as installed

    from optiland.mtf import FFTMTF  # fails clearly without optiland

    version = installed("optiland")

    print(f"# optiland {version} FFTMTF (num_rays {NUM_RAYS}, grid_size {GRID}, strategy chief_ray, ray aiming "
          "iterative); produced by: /tmp/optics-wave/bin/python benchmarks/optiland_wave_reference.py "
          "> tests/data/optiland-fft-mtf.csv")
    print("lens,f_number,object_z_mm,film_z_mm,defocus_quarter_waves,field_deg,frequency_lpmm,mtf_tangential,"
          "mtf_sagittal")
    for name, lens in shipped().items():
        for n, object_z, film_z, field, quarters in scenes(name, lens):
            op = optiland_lens(lens, n, object_z, film_z, field)
            with warnings.catch_warnings():
                warnings.simplefilter("ignore")
                mtf = FFTMTF(op, fields=[(0.0, 1.0 if field else 0.0)], wavelength="primary",
                             num_rays=NUM_RAYS, grid_size=GRID)
            tangential, sagittal = (np.asarray(m) for m in mtf.mtf[0])
            freq_t, freq_s = np.asarray(mtf.freq_tang[0]), np.asarray(mtf.freq_sag[0])
            for lag in LAGS:
                if field and abs(freq_t[lag] - freq_s[lag]) > 1e-9 * freq_t[lag]:
                    # the directions' frequency scales differ: a row for each
                    print(f"{name},{n:.12g},{object_z:.12g},{film_z:.12g},{quarters:g},{field:g},{freq_t[lag]:.12g},"
                          f"{tangential[lag]:.9f},")
                    print(f"{name},{n:.12g},{object_z:.12g},{film_z:.12g},{quarters:g},{field:g},{freq_s[lag]:.12g},,"
                          f"{sagittal[lag]:.9f}")
                else:
                    print(f"{name},{n:.12g},{object_z:.12g},{film_z:.12g},{quarters:g},{field:g},{freq_t[lag]:.12g},"
                          f"{tangential[lag]:.9f},{sagittal[lag]:.9f}")
            sys.stdout.flush()


if __name__ == "__main__":
    main()
