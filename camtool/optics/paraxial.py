"""First-order (paraxial) optics of a lens prescription by a y–nu ray trace.

Two paraxial rays through the surfaces give every first-order property of the
lens: focal length, focal and principal points, pupils and the pupil
magnification. Fed into the closed-form :func:`camtool.dof.thick.thick_dof`
they give the ``paraxial`` rung of the model ladder: the depth of field of the
real lens in first-order optics, with a fixed stop and unit focusing.

Coordinates: z along the axis in mm, the first vertex at z = 0, light towards
+z (the reference data's lens coordinates). Plain floats only: a prescription
has a dozen surfaces, and numpy would cost more to import than the trace.
"""

from __future__ import annotations

import functools

from camtool.core.errors import require_positive
from camtool.core.record import Record
from camtool.optics.prescription import Prescription

__all__ = ["FirstOrder", "first_order", "paraxial_trace"]


class FirstOrder(Record):
    """First-order data of a lens, in mm (positions are z in lens coordinates).

    ``efl_mm`` f; ``bfd_mm`` last vertex → rear focal point; ``z_k_mm`` last
    vertex; ``z_h_mm``/``z_h_prime_mm`` front/rear principal points;
    ``z_f_mm``/``z_f_prime_mm`` front/rear focal points; ``z_e_mm``/``z_x_mm``
    entrance/exit pupils; ``m_e``/``m_x`` magnification from the stop to the
    entrance/exit pupil; ``pupil_magnification`` P = m_X/m_E (exit over
    entrance pupil diameter); ``hiatus_mm`` δ = z_H′ − z_H, so that a subject
    at u in front of H imaged at v behind H′ lies u + δ + v from the image
    plane (negative for the crossed principal planes of a double Gauss,
    positive for a telephoto).
    """

    efl_mm: float
    bfd_mm: float
    z_k_mm: float
    z_h_mm: float
    z_h_prime_mm: float
    z_f_mm: float
    z_f_prime_mm: float
    z_e_mm: float
    z_x_mm: float
    m_e: float
    m_x: float
    pupil_magnification: float
    hiatus_mm: float

    def epd_mm(self, f_number: float) -> float:
        """Entrance-pupil diameter in mm at the nominal f-number: EPD = f/N.

        Examples
        --------
        >>> round(FirstOrder(100, 60, 78, 70, 40, -30, 138, 58, 25, 1.5, 1.8, 1.2, -30).epd_mm(2.0), 3)
        50.0
        """
        require_positive("f_number", f_number, unit="")
        return self.efl_mm / f_number

    def stop_radius_mm(self, f_number: float) -> float:
        """Aperture-stop radius in mm for the nominal f-number: r_stop = f/(2·N·m_E).

        The stop is fixed: focusing does not change it, so the working
        f-number rises by itself at close range.

        Examples
        --------
        >>> round(FirstOrder(100, 60, 78, 70, 40, -30, 138, 58, 25, 2.0, 1.8, 0.9, -30).stop_radius_mm(2.0), 3)
        12.5
        """
        return self.epd_mm(f_number) / (2.0 * self.m_e)


def paraxial_trace(
    prescription: Prescription, y: float, nu: float, start: int = 0, stop: int | None = None
) -> tuple[float, float]:
    """Trace one paraxial ray (height y in mm, reduced slope nu = n·u) and return (y, nu) at the end.

    At each surface i: refract nu′ = nu − y·(n_i − n_(i−1))·c_i, then transfer
    y′ = y + t_i·nu′/n_i. The ray enters at the vertex plane of surface
    ``start`` (before its refraction) and leaves at the vertex plane of
    surface ``stop`` (before its refraction), or after the last refraction
    (at the last vertex, before its transfer) when ``stop`` is ``None``.

    Parameters
    ----------
    prescription : Prescription
    y : float
        Ray height in mm at the vertex plane of surface ``start``.
    nu : float
        Reduced slope n·u entering that surface.
    start, stop : int
        0-based surface indices.

    References
    ----------
    W. J. Smith, *Modern Optical Engineering*, 4th ed., §2.6 (the y–nu trace).

    Examples
    --------
    A single plano-convex lens (R = 51.68 mm, n = 1.5168) in contact with its
    stop has power (n − 1)/R, so a unit-height ray leaves at nu = −1/f:

    >>> from camtool.optics.prescription import prescription_from_mapping
    >>> lens = prescription_from_mapping({"surfaces": [
    ...     {"radius_mm": "inf", "thickness_mm": 0.0, "n": 1.0, "stop": True},
    ...     {"radius_mm": 51.68, "thickness_mm": 0.0, "n": 1.5168},
    ...     {"radius_mm": "inf", "thickness_mm": 100.0, "n": 1.0}]})
    >>> y, nu = paraxial_trace(lens, 1.0, 0.0)
    >>> round(-1.0 / nu, 3)
    100.0
    """
    surfaces = prescription.surfaces
    end = len(surfaces) if stop is None else stop
    n_before = prescription.object_index if start == 0 else surfaces[start - 1].n
    for i in range(start, end):
        surface = surfaces[i]
        nu = nu - y * (surface.n - n_before) * surface.paraxial_curvature
        if stop is not None or i < end - 1:
            y = y + surface.thickness_mm * nu / surface.n
        n_before = surface.n
    return y, nu


@functools.lru_cache(maxsize=64)
def first_order(prescription: Prescription) -> FirstOrder:
    """First-order data of a prescription (focal length, cardinal points, pupils) in mm.

    Ray A (y = 1, nu = 0) and ray B (y = 0, nu = 1) enter at the first
    vertex. With n₀ the object-space and n_K the image-space index:
    f = −1/nu_A,K; BFD = −n_K·y_A,K/nu_A,K; z_F′ = z_K + BFD; z_H′ = z_F′ − n_K·f;
    z_F = n₀·nu_B,K/nu_A,K; z_H = z_F + n₀·f. With a, b the heights of A and B
    at the stop vertex: z_E = n₀·b/a and m_E = 1/a. Rays C (y = 0, nu = 1) and
    D (y = 1, nu = 0) from the stop vertex give z_X = z_K − n_K·y_C/nu_C,
    m_X = y_D + (z_X − z_K)·nu_D/n_K and P = m_X/m_E.

    Parameters
    ----------
    prescription : Prescription
        Any prescription with a positive focal length.

    Returns
    -------
    FirstOrder

    Raises
    ------
    ValueError
        The lens is afocal or has a negative focal length (no real image of
        a distant subject).

    References
    ----------
    W. J. Smith, *Modern Optical Engineering*, 4th ed., ch. 2 and 6; the
    recipe of the reference data's ``oracle-README.md``.

    Examples
    --------
    >>> from camtool.optics.prescription import EXAMPLE_SINGLET, prescription_from_mapping
    >>> lens = prescription_from_mapping(EXAMPLE_SINGLET)
    >>> fo = first_order(lens)
    >>> round(fo.efl_mm, 4), round(fo.bfd_mm, 4), round(fo.z_h_prime_mm, 4), fo.z_e_mm
    (100.0, 96.7036, 1.7036, 0.0)
    """
    n0, nk = prescription.object_index, prescription.image_index
    z_k = prescription.vertices_mm[-1]
    ya, nua = paraxial_trace(prescription, 1.0, 0.0)
    _, nub = paraxial_trace(prescription, 0.0, 1.0)
    if not nua < 0.0:
        raise ValueError(f"{prescription.source or 'prescription'}: the lens has no positive focal length (afocal or diverging)")
    efl = -1.0 / nua
    bfd = -nk * ya / nua
    z_f_prime = z_k + bfd
    z_f = n0 * nub / nua
    s = prescription.stop_index
    a, _ = paraxial_trace(prescription, 1.0, 0.0, stop=s)
    b, _ = paraxial_trace(prescription, 0.0, 1.0, stop=s)
    z_e = n0 * b / a
    yc, nuc = paraxial_trace(prescription, 0.0, 1.0, start=s)
    yd, nud = paraxial_trace(prescription, 1.0, 0.0, start=s)
    z_x = z_k - nk * yc / nuc
    m_x = yd + (z_x - z_k) * nud / nk
    m_e = 1.0 / a
    z_h = z_f + n0 * efl
    z_h_prime = z_f_prime - nk * efl
    return FirstOrder(
        efl_mm=efl,
        bfd_mm=bfd,
        z_k_mm=z_k,
        z_h_mm=z_h,
        z_h_prime_mm=z_h_prime,
        z_f_mm=z_f,
        z_f_prime_mm=z_f_prime,
        z_e_mm=z_e,
        z_x_mm=z_x,
        m_e=m_e,
        m_x=m_x,
        pupil_magnification=m_x / m_e,
        hiatus_mm=z_h_prime - z_h,
    )
