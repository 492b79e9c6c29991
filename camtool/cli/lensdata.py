"""Lens data for the model ladder from the command line: pupil magnification, hiatus, prescription.

The options and their parameter types (``--tolerance``, ``--wavelength``,
``--pupil-mag``, ``--hiatus``, ``--prescription``) and the glue to
:func:`camtool.plans.equipment.lens_data`, which decides the precedence (values
given by hand win over the ``--lens`` preset's) and loads a prescription.
"""

from __future__ import annotations

import math
from typing import Any

import click

from camtool.cli.equipment import LENS
from camtool.cli.options import library_errors, stack
from camtool.core.units import UnitError, parse_length
from camtool.dof.ladder import LensData
from camtool.plans import equipment


class ToleranceType(click.ParamType):
    """A relative tolerance written ``1%`` or ``0.01``; valid above 0 and below 1 (100 %)."""

    name = "tolerance"

    def convert(self, value: Any, param: click.Parameter | None, ctx: click.Context | None) -> float:
        if isinstance(value, float):
            return value
        text = str(value).strip()
        try:
            number = float(text[:-1]) / 100.0 if text.endswith("%") else float(text)
        except ValueError:
            self.fail(f"{value!r} is not a tolerance (examples: 1%, 0.5%, 0.01)", param, ctx)
        if not 0.0 < number < 1.0:
            self.fail(f"{text} is outside the valid range: above 0 and below 100 % (1 % = 0.01)", param, ctx)
        return number


class WavelengthType(click.ParamType):
    """A wavelength in nm: ``550``, ``550nm`` or ``0.55um``; valid 200 to 2000 nm."""

    name = "wavelength"

    def convert(self, value: Any, param: click.Parameter | None, ctx: click.Context | None) -> float:
        if isinstance(value, float):
            return value
        text = str(value).strip().lower()
        try:
            nm = float(text[:-2]) if text.endswith("nm") else parse_length(text, "mm") * 1e6 \
                if any(text.endswith(u) for u in ("um", "µm", "mm")) else float(text)
        except (ValueError, UnitError):
            self.fail(f"{value!r} is not a wavelength (examples: 550, 550nm, 0.55um)", param, ctx)
        if not (200.0 <= nm <= 2000.0 and math.isfinite(nm)):
            self.fail(f"{value} is outside the valid range: 200 to 2000 nm", param, ctx)
        return nm


def load_prescription(ctx: click.Context, path: str) -> Any:
    """:func:`camtool.plans.equipment.load_prescription` (a file, or a prescription preset's name); a bad file
    exits 1 naming it, an invalid one or an unknown name is one line on ``--prescription``."""
    from camtool.cli.equipment import open_presets
    from camtool.cli.options import bad_parameter, file_error
    from camtool.core.errors import InputError
    from camtool.core.files import FileProblem

    try:
        return equipment.load_prescription(
            path, database=lambda: open_presets(ctx, tuple(ctx.params.get("preset_files") or ())))
    except FileProblem as problem:
        raise file_error(ctx, "prescription_file", problem) from None
    except InputError as error:
        raise bad_parameter(ctx, error) from None


def lens_data(ctx: click.Context, pupil_mag: float | None, hiatus: float | None, prescription_file: str | None,
              preset_lens: Any = None) -> LensData | None:
    """:func:`camtool.plans.equipment.lens_data` with ``preset_lens``, by default the ``--lens`` in ``ctx.meta``."""
    prescription = load_prescription(ctx, prescription_file) if prescription_file is not None else None
    return equipment.lens_data(pupil_magnification=pupil_mag, hiatus_mm=hiatus, prescription=prescription,
                               lens_preset=ctx.meta.get(LENS) if preset_lens is None else preset_lens)


class SignedLengthType(click.ParamType):
    """A length of either sign in mm (``-12``, ``3.5mm``, ``-1cm``), e.g. a hiatus."""

    name = "length"

    def convert(self, value: Any, param: click.Parameter | None, ctx: click.Context | None) -> float:
        if isinstance(value, float):
            return value
        text = str(value).strip()
        sign = -1.0 if text.startswith("-") else 1.0
        try:
            mm = sign * parse_length(text.lstrip("+-"), "mm")
        except UnitError as error:
            self.fail(str(error), param, ctx)
        if not math.isfinite(mm):
            self.fail(f"{text} is outside the valid range: a finite length in mm, either sign", param, ctx)
        return mm


class PupilMagnificationType(click.ParamType):
    """Pupil magnification P = exit/entrance pupil diameter; valid 0.05 to 20."""

    name = "ratio"

    def convert(self, value: Any, param: click.Parameter | None, ctx: click.Context | None) -> float:
        if isinstance(value, float):
            return value
        try:
            number = float(str(value).strip())
        except ValueError:
            self.fail(f"{value!r} is not a number (examples: 0.6, 1, 2.5)", param, ctx)
        if not 0.05 <= number <= 20.0:
            self.fail(f"{value} is outside the valid range: 0.05 to 20 (exit over entrance pupil diameter)",
                      param, ctx)
        return number


pupil_mag_option = click.option(
    "--pupil-mag", "pupil_mag", type=PupilMagnificationType(), metavar="P",
    help="Pupil magnification P of the lens (exit/entrance pupil diameter; 1 for a thin lens).")
hiatus_option = click.option(
    "--hiatus", type=SignedLengthType(), metavar="LENGTH",
    help="Separation of the lens's principal planes (rear minus front, mm, either sign).")

lens_geometry_options = stack(pupil_mag_option, hiatus_option)
"""``--pupil-mag`` and ``--hiatus`` alone, for commands that focus but compute no depth of field."""

model_options = stack(
    click.option("--tolerance", type=ToleranceType(), default="1%", show_default=True,
                 help="auto: the largest estimated error accepted, relative to the depth of field (1% or 0.01)."),
    click.option("--diffraction/--no-diffraction", default=False, show_default=True,
                 help="Add the Airy disc 2.44·λ·N·(1 + m/P) to the blur in quadrature (usable CoC "
                      "√(c² − airy²)); says so when nothing can be sharp."),
    click.option("--wavelength", type=WavelengthType(), default="550", show_default=True, metavar="NM",
                 help="Wavelength for --diffraction: 550, 550nm or 0.55um."),
    pupil_mag_option,
    hiatus_option,
    click.option("--prescription", "prescription_file", type=click.Path(dir_okay=False), metavar="FILE",
                 help="Lens prescription (YAML: surfaces from the object side, one stop), or a prescription "
                      "preset's name, for the paraxial and raytrace models; its focal length is used (-f, if "
                      "given, must agree within 1%)."),
)
"""``--tolerance``, ``--diffraction``, ``--wavelength`` and the lens data ``--pupil-mag``, ``--hiatus``, ``--prescription``."""


ladder_errors = library_errors
"""The ladder's errors (an unavailable model, a ray trace that fails) have the one translator."""


def pupil_and_hiatus(ctx: click.Context, pupil_mag: float | None = None,
                     hiatus: float | None = None) -> tuple[float, float, str]:
    """(P, δ, footer note) for focusing and angle of view (:func:`camtool.plans.closeup.pupil_and_hiatus`)."""
    from camtool.plans.closeup import pupil_and_hiatus as known

    found = known(lens_data(ctx, pupil_mag, hiatus, None))
    return found.pupil_magnification, found.hiatus_mm, lens_note(found)


def lens_note(found: Any) -> str:
    """The footer's words for the pupil magnification and hiatus in use (none when they are 1 and 0 by default)."""
    return f"P = {found.pupil_magnification:.3g}, hiatus {found.hiatus_mm:+.3g} mm" if found.known else ""
