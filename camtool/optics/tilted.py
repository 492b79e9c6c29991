"""Real rays through a tilted lens: where its plane of sharp focus really lies.

The lens axis is tilted by θ from the film normal; object points off the
axis (the line of sight is θ off it) send real meridional rays through the
prescription with :class:`camtool.optics.tracer.RealRayTracer`. For one
object point, the chief ray (through the centre of the stop, found by the
secant method) and two neighbours ±ε beside it in the entrance pupil give
the tangential image point (Coddington's, where the neighbours cross). The
point is in focus when that image lies on the film.

Along two chief-ray directions from the entrance pupil E (the lens axis and
the line of sight) the object vergence k (1/distance from E; 0 at infinity,
negative behind the lens, so a plane of focus beyond the horizon needs no
special case) whose image falls on the film is found by the secant method.
The line through the two points is the real plane of sharp focus; where it
crosses the plane through the front principal point H parallel to the film
is the real hinge line.

Camera coordinates as in :mod:`camtool.geometry.tilt` (x along the line of
sight, y parallel to the film towards the tilt, origin at H); lens
coordinates as in the tracer (z along the axis towards the image, first
vertex at z = 0, Y = the meridional height, positive towards the film's +y
side rotated with the lens). Lengths in mm.
"""

from __future__ import annotations

import math
from typing import Any

import numpy as np

from camtool.core.record import NamedTuple
from camtool.optics.prescription import Prescription
from camtool.optics.tracer import RayTraceError, RealRayTracer, real_tracer

__all__ = ["TracedPlane", "traced_axial_blur_mm", "traced_plane_of_focus"]

_FAN = 1e-3  # half-separation of the two neighbour rays in the entrance pupil, as a fraction of f
_ITERATIONS = 60


class TracedPlane(NamedTuple):
    """The real plane of sharp focus: hinge distance from H (mm, signed), 1/(crossing of the line of sight), angle.

    ``k_focus`` is 1/mm along the line of sight through H; ``focus_deg`` the
    angle from the film plane (as :func:`camtool.geometry.tilt.plane_angle_deg`).
    """

    hinge_mm: float
    k_focus: float
    focus_deg: float


class _Tilted:
    """One prescription tilted by θ, its film v behind H′ (perpendicular)."""

    def __init__(self, tracer: RealRayTracer, tilt_deg: float, film_mm: float) -> None:
        self.tracer = tracer
        first = tracer.first
        self.t = math.radians(tilt_deg)
        self.cos, self.sin = math.cos(self.t), math.sin(self.t)
        self.z_e, self.z_h, self.z_hp = first.z_e_mm, first.z_h_mm, first.z_h_prime_mm
        self.f = first.efl_mm
        self.film = film_mm
        e = self.z_h - self.z_e  # entrance pupil in front of H along the axis
        self.pupil = (e * self.cos, e * self.sin)  # camera coordinates of E

    def to_lens(self, dx: float, dy: float) -> tuple[float, float]:
        """A camera-frame direction as (Y, z) components in the lens frame."""
        return -dx * self.sin + dy * self.cos, -(dx * self.cos + dy * self.sin)

    def _rays(self, k: float, d: tuple[float, float], s: Any) -> tuple[Any, Any, Any]:
        """Rays from the object point E + d/k aimed at height s in the entrance-pupil plane: (y at z = 0, m, l)."""
        dy_, dz_ = d
        my = k * np.asarray(s, float) - dy_
        mz = -dz_
        norm = np.hypot(my, mz)
        m, l = my / norm, mz / norm
        return np.asarray(s, float) - self.z_e * m / l, m, l

    def image(self, k: float, d: tuple[float, float]) -> tuple[float, float]:
        """Tangential image point (Y, z) in lens coordinates of the object at vergence k along d from E."""
        tracer = self.tracer
        s0, s1 = 0.0, 1e-3 * self.f
        heights = []
        for s in (s0, s1):
            y, m, l = self._rays(k, d, s)
            heights.append(float(tracer.trace(y, m, l, 0, tracer.stop + 1)[0]))
        for _ in range(_ITERATIONS):  # secant on the stop height of the chief ray
            if not all(math.isfinite(h) for h in heights):
                raise RayTraceError("the chief ray of the tilted lens misses a surface")
            if heights[1] == heights[0]:
                break
            s2 = s1 - heights[1] * (s1 - s0) / (heights[1] - heights[0])
            y, m, l = self._rays(k, d, s2)
            s0, s1, heights = s1, s2, [heights[1], float(tracer.trace(y, m, l, 0, tracer.stop + 1)[0])]
            if abs(s1 - s0) < 1e-13 * self.f:
                break
        eps = _FAN * self.f
        y, m, l = self._rays(k, d, np.array([s1 - eps, s1 + eps]))
        yy, zz, mm, ll = tracer.trace(y, m, l)
        if not np.all(np.isfinite(yy)):
            raise RayTraceError("rays near the chief ray of the tilted lens miss a surface")
        slope = mm / ll
        z_img = (yy[1] - yy[0] - zz[1] * slope[1] + zz[0] * slope[0]) / (slope[0] - slope[1])
        return float(yy[0] + (z_img - zz[0]) * slope[0]), float(z_img)

    def film_residual(self, k: float, d: tuple[float, float]) -> float:
        """How far (mm, along x) the image of that object point lies from the film: positive behind it."""
        big_y, z = self.image(k, d)
        behind = z - self.z_hp  # behind H′ along the axis
        x = -behind * self.cos - big_y * self.sin  # camera x from H′
        return -(x + self.film)

    def solve(self, k_guess: float, d_camera: tuple[float, float]) -> float:
        """Vergence k along the camera direction d (from E) whose real image lies on the film."""
        d = self.to_lens(*d_camera)
        k0, k1 = k_guess, k_guess + 1e-6 / self.f + 1e-4 * abs(k_guess)
        r0, r1 = self.film_residual(k0, d), self.film_residual(k1, d)
        for _ in range(_ITERATIONS):
            if r1 == r0:
                break
            k2 = k1 - r1 * (k1 - k0) / (r1 - r0)
            k0, r0 = k1, r1
            k1, r1 = k2, self.film_residual(k2, d)
            if abs(k1 - k0) <= 1e-14 / self.f:
                break
        if not math.isfinite(k1):
            raise RayTraceError("no object distance along the tilted lens's chief ray is imaged on the film")
        return k1


def traced_plane_of_focus(prescription: Prescription, tilt_deg: float, film_mm: float,
                          predicted_k_focus: float, field_deg: float = 5.0, about: str = "sight") -> TracedPlane:
    """The real plane of sharp focus of a tilted prescription with its film v behind H′ (perpendicular), mm.

    The plane is laid through the two object points seen ``field_deg`` above
    and below the line of sight from the entrance pupil (the edges of the
    picture, where two points are furthest apart) whose real images lie on
    the film: a lens's field is curved, so this is the chord of its surface
    of sharp focus across the picture. ``predicted_k_focus`` (1/mm, along
    the line of sight through H, e.g. from the thick model) starts the
    search. With ``about="axis"`` the two points are seen ``field_deg``
    either side of the lens axis instead: the field curvature, even about
    the axis, then shifts the plane without turning it, which isolates the
    first-order geometry of the tilt.

    Raises
    ------
    RayTraceError
        Rays miss a surface, or no object point along a chief ray is imaged
        on the film.

    Examples
    --------
    The example singlet tilted 4°, its film 105 mm behind H′: about the lens
    axis the real plane of focus has the first-order hinge f/sin θ (to the
    aberrations of a ±0.25° field), across a ±3° picture about the line of
    sight the singlet's curved field moves it.

    >>> import math
    >>> from camtool.optics.prescription import EXAMPLE_SINGLET, prescription_from_mapping
    >>> from camtool.optics.paraxial import first_order
    >>> lens = prescription_from_mapping(EXAMPLE_SINGLET)
    >>> f = first_order(lens).efl_mm
    >>> k = math.cos(math.radians(4.0)) / f - 1 / 105.0
    >>> axis = traced_plane_of_focus(lens, 4.0, 105.0, k, field_deg=0.25, about="axis")
    >>> round(axis.hinge_mm / (f / math.sin(math.radians(4.0))), 3)
    1.0
    >>> picture = traced_plane_of_focus(lens, 4.0, 105.0, k, field_deg=3.0)
    >>> abs(picture.hinge_mm / axis.hinge_mm - 1) > 0.1
    True
    """
    tracer = real_tracer(prescription)
    lens = _Tilted(tracer, tilt_deg, film_mm)
    ex, ey = lens.pupil
    f, s = lens.f, lens.sin
    points = []
    centre = lens.t if about == "axis" else 0.0
    for a in (centre - math.radians(field_deg), centre + math.radians(field_deg)):  # the picture's two edges
        dx, dy = math.cos(a), math.sin(a)
        # the predicted plane y = J(1 − k·x), J = f/sin θ, met by E + λ·d: k_dir = 1/λ
        guess = (dy * s + f * predicted_k_focus * dx) / (f * (1.0 - predicted_k_focus * ex) - ey * s)
        k = lens.solve(guess, (dx, dy))
        points.append(np.array([ex * k + dx, ey * k + dy, k]))  # homogeneous camera point E + d/k
    line = np.cross(points[0], points[1])
    hinge = np.cross(line, [1.0, 0.0, 0.0])  # meets x = 0
    sight = np.cross(line, [0.0, 1.0, 0.0])  # meets y = 0
    hinge_mm = float(hinge[1] / hinge[2]) if hinge[2] != 0 else math.inf
    k_focus = float(sight[2] / sight[0]) if sight[0] != 0 else math.inf
    return TracedPlane(hinge_mm, k_focus, _from_film(float(line[0]), float(line[1]), tilt_deg))


def _from_film(a: float, b: float, tilt_deg: float) -> float:
    """Angle from the film plane of the line a·x + b·y + c = 0, signed as the tilt (see ``plane_angle_deg``)."""
    dx, dy = -b, a  # its direction, turned to point away from the camera
    if dx < 0 or (dx == 0 and dy > 0):
        dx, dy = -dx, -dy
    angle = math.degrees(math.atan2(dx, -dy))
    return angle - 180.0 if tilt_deg < 0 and angle > 0 else angle


def traced_axial_blur_mm(prescription: Prescription, tilt_deg: float, film_mm: float, axis_distance_mm: float,
                         f_number: float) -> float:
    """Blur width (mm) across the tilt, on the tilted film, of a point on the lens axis, by real rays.

    The point lies ``axis_distance_mm`` in front of H on the tilted lens axis
    (``inf`` allowed); the film is ``film_mm`` behind H′, perpendicular,
    so it crosses the axis film/cos θ behind H′. By the lens's symmetry the
    rays through the stop's edge in the plane across the tilt (sagittal)
    follow the meridional edge ray's heights, and that plane meets the film
    in a line parallel to the hinge at the axis crossing: the blur across the
    tilt is twice the edge ray's height there. This is the quantity the
    wedge's criterion (docs/tilt.md §3) sets to the CoC.

    Examples
    --------
    >>> from camtool.optics.prescription import EXAMPLE_SINGLET, prescription_from_mapping
    >>> lens = prescription_from_mapping(EXAMPLE_SINGLET)
    >>> traced_axial_blur_mm(lens, 5.0, 100.0, float("inf"), 8.0) > 0.0
    True
    """
    tracer = real_tracer(prescription)
    first = tracer.first
    cos = math.cos(math.radians(tilt_deg))
    w = 0.0 if math.isinf(axis_distance_mm) else 1.0 / (axis_distance_mm - first.z_h_mm)
    v = tracer.pupil_vergence([w])  # entrance-pupil vergence
    aim = tracer.aims(v, f_number)  # where the edge ray crosses the entrance-pupil plane
    slope = aim * v
    l_start = 1.0 / np.sqrt(1.0 + slope * slope)
    y, z, m, l = tracer.trace(aim * (1.0 - v * first.z_e_mm), slope * l_start, l_start)
    z_film = first.z_h_prime_mm + film_mm / cos
    height = float((y + (z_film - z) * m / l)[0])
    if not math.isfinite(height):
        raise RayTraceError("the edge ray of the tilted lens misses a surface")
    return 2.0 * abs(height)

