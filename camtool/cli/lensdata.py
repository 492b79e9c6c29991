"""Lens data for the model ladder from the command line: pupil magnification, hiatus, prescription.

The options (``--tolerance``, ``--wavelength``, ``--pupil-mag``, ``--hiatus``,
``--prescription``; their parameter types are :mod:`camtool.cli.params`) and
the one call of :func:`camtool.plans.equipment.lens_data`, which decides the
precedence (values given by hand win over the ``--lens`` preset's) and loads a
prescription.
"""

from __future__ import annotations

import sys
from collections.abc import Callable
from typing import Any

import click

from camtool.cli.equipment import LENS
from camtool.cli.options import F, stack
from camtool.cli.params import CriterionType, PupilMagnificationType, SignedLengthType, ToleranceType, WavelengthType
from camtool.dof.ladder import LensData as LensData
from camtool.plans import equipment


def lens_data(ctx: click.Context, pupil_mag: float | None = None, hiatus: float | None = None,
              prescription_file: str | None = None, preset_lens: Any = None) -> LensData | None:
    """:func:`camtool.plans.equipment.lens_data` with ``preset_lens``, by default the ``--lens`` in ``ctx.meta``,
    and the prescription file or preset named; a bad file exits 1 naming it, an invalid one or an unknown name is
    one line on ``--prescription``."""
    from camtool.cli.equipment import open_presets
    from camtool.cli.options import bad_parameter, file_error
    from camtool.core.errors import InputError

    try:
        return equipment.lens_data(pupil_magnification=pupil_mag, hiatus_mm=hiatus, prescription=prescription_file,
                                   lens_preset=ctx.meta.get(LENS) if preset_lens is None else preset_lens,
                                   database=lambda: open_presets(ctx, tuple(ctx.params.get("preset_files") or ())))
    except Exception as error:
        files = sys.modules.get("camtool.core.files")  # a file problem only once a file was read: not imported before
        if files is not None and isinstance(error, files.FileProblem):
            raise file_error(ctx, "prescription_file", error) from None
        if isinstance(error, InputError):
            raise bad_parameter(ctx, error) from None
        raise


def wavelength_option(use: str = "") -> Callable[[F], F]:
    """``--wavelength`` in nm (``use``: what it is for, e.g. "for --diffraction")."""
    return click.option("--wavelength", type=WavelengthType(), default="550", show_default=True, metavar="NM",
                        help=f"Wavelength{' ' + use if use else ''}: 550, 550nm or 0.55um.")


pupil_mag_option = click.option(
    "--pupil-mag", "pupil_mag", type=PupilMagnificationType(), metavar="P",
    help="Pupil magnification P of the lens (exit/entrance pupil diameter; 1 for a thin lens).")
hiatus_option = click.option(
    "--hiatus", type=SignedLengthType(), metavar="LENGTH",
    help="Separation of the lens's principal planes (rear minus front, mm, either sign).")

lens_geometry_options = stack(pupil_mag_option, hiatus_option)
"""``--pupil-mag`` and ``--hiatus`` alone, for commands that focus but compute no depth of field."""

diffraction_options = stack(
    click.option("--diffraction/--no-diffraction", default=False, show_default=True,
                 help="Add the Airy disc 2.44·λ·N·(1 + m/P) to the blur in quadrature (usable CoC "
                      "√(c² − airy²)); under auto the wave model where it exceeds c/√2; says so when nothing "
                      "can be sharp."),
    wavelength_option("for --diffraction"),
)
"""``--diffraction`` and ``--wavelength``."""

model_options = stack(
    click.option("--tolerance", type=ToleranceType(), default="1%", show_default=True,
                 help="auto: the largest estimated error accepted, relative to the depth of field (1% or 0.01)."),
    diffraction_options,
    pupil_mag_option,
    hiatus_option,
    click.option("--prescription", "prescription_file", type=click.Path(dir_okay=False), metavar="FILE",
                 help="Lens prescription (YAML: surfaces from the object side, one stop), or a prescription "
                      "preset's name, for the paraxial and raytrace models; its focal length is used (-f, if "
                      "given, must agree within 1%)."),
)
"""``--tolerance``, ``--diffraction``, ``--wavelength`` and the lens data ``--pupil-mag``, ``--hiatus``, ``--prescription``."""

criterion_option = click.option(
    "--criterion", "criterion", type=CriterionType(), metavar="mtf:LEVEL@FREQ",
    help="Sharp where the perfect lens's MTF at FREQ (lp/mm on the sensor, or coc: 1/c) is at least LEVEL; "
         "runs the wave model (default mtf:0.181@coc, docs/wave.md).")


def pupil_and_hiatus(ctx: click.Context, pupil_mag: float | None = None,
                     hiatus: float | None = None) -> tuple[float, float, str]:
    """(P, δ, footer note) for focusing and angle of view (:func:`camtool.plans.closeup.pupil_and_hiatus`)."""
    from camtool.plans.closeup import pupil_and_hiatus as known

    found = known(lens_data(ctx, pupil_mag, hiatus))
    return found.pupil_magnification, found.hiatus_mm, lens_note(found)


def lens_note(found: Any) -> str:
    """The footer's words for the pupil magnification and hiatus in use (none when they are 1 and 0 by default)."""
    return f"P = {found.pupil_magnification:.3g}, hiatus {found.hiatus_mm:+.3g} mm" if found.known else ""
