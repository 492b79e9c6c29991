"""Diffraction as an add-on to every depth-of-field model: the Airy disc and the usable CoC.

A lens stopped down far enough blurs a point by diffraction alone. camtool
adds that blur to the geometric (defocus) blur in quadrature,

    b_total = √(b_geometric² + b_airy²),   b_airy = 2.44·λ·N_w,

with N_w = N·(1 + m/P) the working f-number at the focus (the image-side
cone is fixed by the lens-to-sensor spacing, which stays at its focus
setting for the near and far limits too). The limits are then those of the
geometric model with the usable circle of confusion c′ = √(c² − b_airy²).
When b_airy ≥ c nothing is acceptably sharp: :class:`NothingSharp` says so
and gives the largest f-number that still leaves depth of field.

Works on plain floats (no numpy import) and on numpy arrays alike.
"""

from __future__ import annotations

from typing import Any

from camtool.core.arrays import is_scalar, ops
from camtool.core.errors import DomainError, first_bad, require_positive

__all__ = [
    "AIRY_FACTOR",
    "NothingSharp",
    "airy_diameter_mm",
    "diffraction_share",
    "largest_sharp_f_number",
    "usable_coc_mm",
]

AIRY_FACTOR = 2.44
"""Diameter of the Airy disc's first dark ring in units of λ·N (2 × 1.22)."""

_MM_PER_NM = 1e-6


class NothingSharp(DomainError):
    """The Airy disc alone fills the circle of confusion: no distance is acceptably sharp.

    ``largest_f_number`` is the f-number at which the Airy disc just equals
    the CoC at this focus (any smaller f-number leaves some depth of field);
    ``airy_mm`` is the Airy diameter at the f-number asked for.
    """

    def __init__(self, f_number: float, largest_f_number: float, airy_mm: float, coc_mm: float,
                 wavelength_nm: float) -> None:
        self.largest_f_number = largest_f_number
        self.airy_mm = airy_mm
        self.coc_mm = coc_mm
        super().__init__(
            "f_number",
            f_number,
            f"below f/{largest_f_number:.3g} for any depth of field with diffraction at {wavelength_nm:g} nm",
            detail=f"nothing is acceptably sharp: the Airy disc, {airy_mm:.3g} mm, "
                   f"fills the {coc_mm:.3g} mm circle of confusion",
        )


def airy_diameter_mm(working_f_number: Any, wavelength_nm: Any = 550.0) -> Any:
    """Airy-disc diameter (to the first dark ring) in mm: b_airy = 2.44·λ·N_w.

    Parameters
    ----------
    working_f_number : float or array
        Working f-number N_w = N·(1 + m/P) > 0.
    wavelength_nm : float or array
        Wavelength λ in nm (550: the middle of the visible band).

    References
    ----------
    M. Born and E. Wolf, *Principles of Optics*, §8.5.2 (the Airy pattern);
    Wikipedia, "Airy disk".

    Examples
    --------
    >>> round(airy_diameter_mm(16.0), 5)
    0.02147
    """
    return AIRY_FACTOR * wavelength_nm * _MM_PER_NM * working_f_number


def largest_sharp_f_number(coc_mm: Any, magnification: Any = 0.0, pupil_magnification: Any = 1.0,
                           wavelength_nm: Any = 550.0) -> Any:
    """Largest nominal f-number whose Airy disc still fits the CoC at this focus: c/(2.44·λ·(1 + m/P)).

    At this f-number b_airy = c and the depth of field shrinks to nothing;
    any smaller f-number leaves some.

    Parameters
    ----------
    coc_mm : float or array, c > 0
    magnification : float or array, m ≥ 0 at the focus (0 at infinity)
    pupil_magnification : float or array, P > 0
    wavelength_nm : float or array, λ > 0

    Examples
    --------
    >>> round(largest_sharp_f_number(0.03), 2)
    22.35
    >>> round(largest_sharp_f_number(0.03, magnification=1.0), 2)
    11.18
    """
    return coc_mm / (AIRY_FACTOR * wavelength_nm * _MM_PER_NM * (1.0 + magnification / pupil_magnification))


def diffraction_share(coc_mm: Any, airy_mm: Any) -> Any:
    """Relative change of the depth of field when diffraction is included: 1 − √(1 − (b_airy/c)²).

    The geometric depth of field is proportional to the CoC, so shrinking c
    to √(c² − b_airy²) shortens it by this fraction (≈ (b_airy/c)²/2 for a
    small Airy disc; 1 when the Airy disc fills the CoC).

    Examples
    --------
    >>> round(diffraction_share(0.03, 0.003), 6)
    0.005013
    """
    xp = ops(coc_mm, airy_mm)
    ratio = xp.minimum(airy_mm / coc_mm, 1.0)
    return 1.0 - xp.sqrt(1.0 - ratio * ratio)


def usable_coc_mm(coc_mm: Any, f_number: Any, magnification: Any = 0.0, pupil_magnification: Any = 1.0,
                  wavelength_nm: Any = 550.0) -> Any:
    """The CoC left for the geometric blur once the Airy disc is added in quadrature: √(c² − b_airy²), mm.

    Parameters
    ----------
    coc_mm : float or array
        Circle of confusion c > 0 (total blur allowed on the sensor).
    f_number : float or array
        Nominal N > 0.
    magnification : float or array
        Magnification m ≥ 0 at the focus distance (0 at infinity).
    pupil_magnification : float or array
        P > 0 (1 without lens data).
    wavelength_nm : float or array
        λ > 0 in nm.

    Raises
    ------
    NothingSharp
        b_airy ≥ c: nothing is acceptably sharp (a :class:`DomainError` on
        ``f_number`` that gives the largest f-number still leaving depth of
        field).

    References
    ----------
    docs/design.md §4 (diffraction as an add-on: root-sum-square blur).

    Examples
    --------
    >>> round(usable_coc_mm(0.03, 8.0), 5)
    0.02801
    >>> usable_coc_mm(0.03, 32.0)
    Traceback (most recent call last):
    ...
    camtool.dof.diffraction.NothingSharp: f_number=32 is outside the valid range: below f/22.4 for any depth of field \
with diffraction at 550 nm (nothing is acceptably sharp: the Airy disc, 0.0429 mm, fills the 0.03 mm circle of confusion)
    """
    require_positive("wavelength_nm", wavelength_nm, unit="nm")
    xp = ops(coc_mm, f_number, magnification, pupil_magnification, wavelength_nm)
    working = f_number * (1.0 + magnification / pupil_magnification)
    airy = airy_diameter_mm(working, wavelength_nm)
    sharp = airy < coc_mm
    if not (sharp if isinstance(sharp, bool) else bool(xp.all(sharp))):
        largest = largest_sharp_f_number(coc_mm, magnification, pupil_magnification, wavelength_nm)
        if is_scalar(sharp) or isinstance(sharp, bool):
            raise NothingSharp(f_number, largest, airy, coc_mm, float(wavelength_nm))
        import numpy as np

        shape = np.shape(sharp)
        pick = [first_bad(np.broadcast_to(v, shape), sharp) for v in (f_number, largest, airy, coc_mm, wavelength_nm)]
        raise NothingSharp(*pick)
    return xp.sqrt((coc_mm - airy) * (coc_mm + airy))
