"""Close-up on the command line: ``-m/--magnification``, ``--extension``, ``--teleconverter``, per-row diffraction.

The options and the columns; :mod:`camtool.plans.closeup` makes every decision
(the focus setting of each row, the ladder on it, the one hyperfocal distance of
a lens with a focus model). :func:`unreachable_errors` names the option typed
when a focus derived from it is out of a model's reach.
"""

from __future__ import annotations

import contextlib
import math
from collections.abc import Iterator

import click

from camtool.cli.common import one_value
from camtool.cli.options import EXTENSION_MM, _typed, param_named, stack
from camtool.cli.params import NumberType
from camtool.core import ranges
from camtool.plans import closeup

MAGNIFICATION = NumberType(*ranges.MAGNIFICATION)
"""Any magnification above 0, to 1000:1 (the formulas hold far past the tested 20:1)."""

magnification_option = click.option(
    "-m", "--magnification", type=MAGNIFICATION, multiple=True,
    help="Magnification instead of -s: 0.5 (1:2), 1 (life size), 5 (5:1); a list 1,2,5 gives a row each.")

teleconverter_option = click.option(
    "--teleconverter", type=NumberType(1.0, 4.0), metavar="K", callback=one_value,
    help="Teleconverter factor, e.g. 1.4 or 2: focal length and f-number × K.")

closeup_options = stack(
    click.option("--extension", type=EXTENSION_MM, metavar="LENGTH", callback=one_value,
                 help="Extension tubes or bellows added behind the lens, e.g. 25mm: adds E/f to the magnification."),
    teleconverter_option,
)
"""``--extension`` and ``--teleconverter``."""


@contextlib.contextmanager
def unreachable_errors(ctx: click.Context) -> Iterator[None]:
    """A focus distance the user did not type (it came from -m or a focus model) is blamed on what they typed."""
    try:
        yield
    except closeup.UnreachableFocus as error:
        largest = error.largest_magnification
        where = f"the lens focuses no closer than {error.closest_mm:.4g} mm from the lens here" + (
            f", m ≤ {largest:.3g}" if math.isfinite(largest) else "")
        if not error.by_magnification or not ctx.params.get("magnification"):
            # the typed option that drives the focus: the extension, the converter, else the distance
            driver = next((param_named(ctx, name) for name in ("extension", "teleconverter", "distance")
                           if ctx.params.get(name) not in (None, (), [], 1.0)), None)
            if driver is None:
                raise click.UsageError(f"the focus this lens setting needs is outside the model's range: {where}",
                                       ctx) from None
            raise click.BadParameter(f"{_typed(ctx, driver)} needs a focus outside the model's range: {where} "
                                     "(another --model reaches further)", ctx=ctx, param=driver) from None
        shown = ", ".join(f"{m:g}" for m in error.magnifications)
        raise click.BadParameter(f"{shown} is outside the valid range: {where} (another --model reaches further)",
                                 ctx=ctx, param=param_named(ctx, "magnification")) from None

