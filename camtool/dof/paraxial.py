"""The ``paraxial`` rung: depth of field from a prescription's first-order data."""

from __future__ import annotations

from typing import Any

from camtool.dof.limits import DofLimits
from camtool.dof.thick import thick_dof
from camtool.optics.paraxial import first_order
from camtool.optics.prescription import Prescription


def paraxial_dof(
    prescription: Prescription, f_number: Any, coc_mm: Any, distance_mm: Any, distance_from: str = "sensor"
) -> DofLimits:
    """Depth of field of a prescription in first-order optics, in mm (the ``paraxial`` model).

    The lens's paraxial f, pupil magnification P and hiatus δ go into the
    closed form of :func:`camtool.dof.thick.thick_dof`; with a fixed stop
    (r_stop from the nominal N) and unit focusing this is exactly the blur
    2·|y_K + (z_film − z_K)·u_K| of the paraxial marginal ray through the stop
    edge reaching c.

    Parameters
    ----------
    prescription : Prescription
        Object and image space in air (n = 1).
    f_number : float or array
        Nominal N > 0 (N = f/EPD for an object at infinity).
    coc_mm : float or array
        Circle of confusion c > 0 (blur diameter on the sensor).
    distance_mm : float or array
        Focus distance from the plane ``distance_from``: ``"sensor"`` (the
        image plane, ≥ 4f + δ), ``"lens"`` (the front principal plane H,
        ≥ 2f) or ``"entrance_pupil"``; ``inf`` allowed.
    distance_from : str

    Returns
    -------
    DofLimits
        Distances from the same plane as ``distance_mm``.

    References
    ----------
    The ``paraxial`` method of the reference data (oracle-README.md);
    docs/design.md §4.

    Examples
    --------
    >>> from camtool.optics.prescription import EXAMPLE_SINGLET, prescription_from_mapping
    >>> lens = prescription_from_mapping(EXAMPLE_SINGLET)
    >>> r = paraxial_dof(lens, 8.0, 0.03, 3000.0)
    >>> round(r.near_mm, 1), round(r.far_mm, 1)
    (2818.0, 3208.1)
    """
    if prescription.object_index != 1.0 or prescription.image_index != 1.0:
        raise ValueError("paraxial_dof needs object and image space in air (n = 1)")
    fo = first_order(prescription)
    return thick_dof(
        fo.efl_mm,
        f_number,
        coc_mm,
        distance_mm,
        pupil_magnification=fo.pupil_magnification,
        hiatus_mm=fo.hiatus_mm,
        distance_from=distance_from,
    )
