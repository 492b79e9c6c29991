"""Lens prescriptions: the surfaces of a real lens, validated into frozen value classes.

A prescription lists the refracting surfaces from the object side. Each surface
has a vertex radius (``inf`` for a flat surface), the axial thickness to the
next surface (for the last surface: the back focal distance at infinity
focus), the index of the medium after it, a clear semi-diameter, and
optionally a conic constant and polynomial aspheric terms. Exactly one surface
is the aperture stop.

Sag convention (vertex at z = 0, r ≥ 0, c = 1/radius, k = conic)::

    z(r) = c r² / (1 + √(1 − (1 + k) c² r²)) + Σ a_n rⁿ

with odd powers taken of |r| so the surface stays rotationally symmetric
(rayoptics' ``RadialPolynomial``; k = 0 is a sphere, k = −1 a paraboloid).

This module does no file I/O: :func:`prescription_from_mapping` takes the
mapping a YAML loader produced and names the source in its error messages.
"""

from __future__ import annotations

import itertools
import math
from collections.abc import Mapping
from typing import Any

from camtool.core.errors import CamtoolError
from camtool.core.record import Record

__all__ = [
    "Prescription",
    "PrescriptionError",
    "Surface",
    "prescription_from_mapping",
]

_SURFACE_KEYS = frozenset(
    {"radius_mm", "thickness_mm", "n", "semi_diameter_mm", "stop", "conic", "aspheric", "name", "glass", "note"}
)
_TOP_KEYS = frozenset(
    {
        "id",
        "name",
        "source",
        "aliases",
        "notes",
        "description",
        "kind",
        "focal_length_mm",
        "f_number",
        "wavelength_nm",
        "object_index",
        "surfaces",
    }
)
_INFINITY_WORDS = {"inf", ".inf", "+inf", "infinity", "flat"}


EXAMPLE_SINGLET = {"surfaces": [
    {"radius_mm": "inf", "thickness_mm": 0.0, "n": 1.0, "stop": True},
    {"radius_mm": 51.68, "thickness_mm": 5.0, "n": 1.5168},
    {"radius_mm": "inf", "thickness_mm": 96.7, "n": 1.0},
]}
"""A 100 mm plano-convex N-BK7 singlet with its stop in front, the lens of the optics modules' examples."""


class PrescriptionError(CamtoolError, ValueError):
    """A prescription mapping is invalid; the message names the source, the surface and the key.

    ``source`` is where the mapping came from (a file name or preset id),
    ``surface`` the 1-based surface number (``None`` for a top-level key) and
    ``key`` the offending key.
    """

    def __init__(self, source: str, key: str, problem: str, surface: int | None = None) -> None:
        self.source = source
        self.key = key
        self.surface = surface
        self.problem = problem
        where = f"surface {surface}, " if surface is not None else ""
        super().__init__(f"{source}: {where}{key}: {problem}")


class Surface(Record):
    """One refracting surface of a prescription; lengths in mm.

    ``aspheric`` holds ``(power, coefficient)`` pairs of the polynomial sag
    terms, sorted by power; ``semi_diameter_mm`` is informative (``None`` when
    not given); ``stop`` marks the aperture stop.
    """

    radius_mm: float
    thickness_mm: float
    n: float
    semi_diameter_mm: float | None = None
    stop: bool = False
    conic: float = 0.0
    aspheric: tuple[tuple[int, float], ...] = ()

    @property
    def curvature(self) -> float:
        """Vertex curvature c = 1/radius in 1/mm (0 for a flat surface)."""
        return 0.0 if math.isinf(self.radius_mm) else 1.0 / self.radius_mm

    @property
    def paraxial_curvature(self) -> float:
        """Curvature seen by paraxial rays in 1/mm: c + 2·a₂ (the r² term bends like a curvature)."""
        return self.curvature + 2.0 * dict(self.aspheric).get(2, 0.0)

    @property
    def is_aspheric(self) -> bool:
        """True when the surface has a conic constant or polynomial terms."""
        return self.conic != 0.0 or bool(self.aspheric)

    def sag_mm(self, r_mm: float) -> float:
        """Sag z(r) in mm at radial height r (see the module docstring for the formula).

        Examples
        --------
        >>> round(Surface(radius_mm=50.0, thickness_mm=5.0, n=1.5).sag_mm(10.0), 6)
        1.010205
        >>> Surface(radius_mm=math.inf, thickness_mm=5.0, n=1.5, aspheric=((4, 1e-3),)).sag_mm(2.0)
        0.016
        """
        c, r = self.curvature, abs(r_mm)
        base = c * r * r / (1.0 + math.sqrt(1.0 - (1.0 + self.conic) * c * c * r * r))
        return base + sum(a * r**power for power, a in self.aspheric)


class Prescription(Record):
    """A validated lens prescription: surfaces from the object side plus the light it was designed for.

    ``focal_length_mm`` and ``f_number`` are the values the source states
    (informative; :func:`camtool.optics.paraxial.first_order` computes the
    focal length from the surfaces). Hashable, so results derived from it can
    be cached.
    """

    surfaces: tuple[Surface, ...]
    object_index: float = 1.0
    wavelength_nm: float = 587.6
    focal_length_mm: float | None = None
    f_number: float | None = None
    id: str = ""
    name: str = ""
    source: str = ""

    @property
    def stop_index(self) -> int:
        """0-based index of the aperture-stop surface."""
        return next(i for i, s in enumerate(self.surfaces) if s.stop)

    @property
    def vertices_mm(self) -> tuple[float, ...]:
        """Axial position z of every surface vertex in mm, the first at z = 0."""
        z, out = 0.0, []
        for surface in self.surfaces:
            out.append(z)
            z += surface.thickness_mm
        return tuple(out)

    @property
    def image_index(self) -> float:
        """Refractive index of image space (after the last surface)."""
        return self.surfaces[-1].n

    @property
    def is_aspheric(self) -> bool:
        """True when any surface is aspheric or conic."""
        return any(s.is_aspheric for s in self.surfaces)


def _number(value: Any, source: str, key: str, surface: int | None, allow_inf: bool = False) -> float:
    """Read one real number (``inf`` words allowed for radii), or raise naming the key."""
    if isinstance(value, str) and allow_inf and value.strip().lower() in _INFINITY_WORDS:
        return math.inf
    if isinstance(value, bool) or not isinstance(value, (int, float)):
        raise PrescriptionError(source, key, f"expected a number, got {value!r}", surface)
    number = float(value)
    if math.isnan(number) or (math.isinf(number) and not allow_inf):
        raise PrescriptionError(source, key, f"expected a finite number, got {value!r}", surface)
    return number


def _aspheric_terms(value: Any, source: str, surface: int) -> tuple[tuple[int, float], ...]:
    """Parse ``{a3: ..., a4: ...}`` into sorted (power, coefficient) pairs, dropping zeros."""
    if not isinstance(value, Mapping):
        raise PrescriptionError(source, "aspheric", "expected a mapping such as {a4: 1.2e-5, a6: ...}", surface)
    terms = {}
    for name, coefficient in value.items():
        text = str(name).strip().lower()
        if not (text.startswith("a") and text[1:].isdigit()):
            raise PrescriptionError(source, f"aspheric.{name}", "term names are a2, a3, a4, ... (aN: power of r)", surface)
        power = int(text[1:])
        if power < 2 or power > 30:
            raise PrescriptionError(
                source, f"aspheric.{name}", "powers 2 to 30 are supported (an r¹ term has a kink on the axis)", surface
            )
        a = _number(coefficient, source, f"aspheric.{name}", surface)
        if a != 0.0:
            terms[power] = a
    return tuple(sorted(terms.items()))


def _surface(data: Any, number: int, last: bool, source: str) -> Surface:
    """Validate one surface mapping (``number`` is 1-based, for messages)."""
    if not isinstance(data, Mapping):
        raise PrescriptionError(source, "surfaces", f"surface {number} must be a mapping, got {data!r}")
    unknown = sorted(set(map(str, data)) - _SURFACE_KEYS)
    if unknown:
        raise PrescriptionError(source, unknown[0], f"unknown key (known: {', '.join(sorted(_SURFACE_KEYS))})", number)
    for key in ("radius_mm", "thickness_mm", "n"):
        if key not in data:
            raise PrescriptionError(source, key, "missing", number)
    radius = _number(data["radius_mm"], source, "radius_mm", number, allow_inf=True)
    if radius == 0.0:
        raise PrescriptionError(source, "radius_mm", "must not be 0 (write inf for a flat surface)", number)
    thickness = _number(data["thickness_mm"], source, "thickness_mm", number)
    if thickness < 0.0 or (last and thickness == 0.0):
        what = "the back focal distance must be > 0" if last else "must be ≥ 0"
        raise PrescriptionError(source, "thickness_mm", f"{what}, got {thickness:g}", number)
    index = _number(data["n"], source, "n", number)
    if index < 1.0:
        raise PrescriptionError(source, "n", f"refractive index must be ≥ 1, got {index:g}", number)
    semi = None
    if data.get("semi_diameter_mm") is not None:
        semi = _number(data["semi_diameter_mm"], source, "semi_diameter_mm", number)
        if semi <= 0.0:
            raise PrescriptionError(source, "semi_diameter_mm", f"must be > 0, got {semi:g}", number)
    stop = data.get("stop", False)
    if not isinstance(stop, bool):
        raise PrescriptionError(source, "stop", f"expected true or false, got {stop!r}", number)
    conic = _number(data.get("conic", 0.0), source, "conic", number)
    terms = _aspheric_terms(data["aspheric"], source, number) if data.get("aspheric") is not None else ()
    return Surface(radius, thickness, index, semi, stop, conic, terms)


def _check_contacts(surfaces: tuple[Surface, ...], source: str) -> None:
    """Zero thickness is allowed only where one of the two surfaces is flat (a stop on a vertex)."""
    for i, (here, after) in enumerate(itertools.pairwise(surfaces), start=1):
        if here.thickness_mm == 0.0 and here.curvature != 0.0 and after.curvature != 0.0:
            raise PrescriptionError(
                source, "thickness_mm", f"is 0 between two curved surfaces ({i} and {i + 1}): they would intersect", i
            )


def prescription_from_mapping(data: Mapping[str, Any], source: str = "<prescription>") -> Prescription:
    """Validate a parsed prescription mapping (e.g. from ``yaml.safe_load``) into a :class:`Prescription`.

    Checks: ``surfaces`` is a non-empty list; every surface has ``radius_mm``
    (≠ 0, ``inf`` = flat), ``thickness_mm`` (≥ 0; 0 only next to a flat
    surface; the last, the back focal distance, > 0) and ``n`` ≥ 1; exactly
    one surface has ``stop: true``; ``object_index`` ≥ 1; ``wavelength_nm``,
    ``focal_length_mm`` and ``f_number`` > 0 when given; no unknown keys.

    Parameters
    ----------
    data : mapping
        The prescription: ``surfaces`` (list of mappings) and the optional
        top-level keys ``id``, ``name``, ``source``, ``focal_length_mm``,
        ``f_number``, ``wavelength_nm`` (default 587.6), ``object_index``
        (default 1.0).
    source : str
        Where the mapping came from; every error message starts with it.

    Returns
    -------
    Prescription

    Raises
    ------
    PrescriptionError
        A ``ValueError`` whose message names the source, the 1-based surface
        number and the key.

    References
    ----------
    docs/design.md §5 (prescription presets); the reference data's
    ``prescriptions/*.yaml`` headers for the sag convention.

    Examples
    --------
    >>> lens = prescription_from_mapping({"surfaces": [
    ...     {"radius_mm": "inf", "thickness_mm": 0.0, "n": 1.0, "stop": True},
    ...     {"radius_mm": 51.68, "thickness_mm": 5.0, "n": 1.5168},
    ...     {"radius_mm": "inf", "thickness_mm": 96.7, "n": 1.0}]}, source="singlet")
    >>> lens.stop_index, lens.vertices_mm
    (0, (0.0, 0.0, 5.0))
    >>> prescription_from_mapping({"surfaces": [{"radius_mm": 0, "thickness_mm": 1, "n": 1}]}, "x.yaml")
    Traceback (most recent call last):
    ...
    camtool.optics.prescription.PrescriptionError: x.yaml: surface 1, radius_mm: must not be 0 (write inf for a flat surface)
    """
    if not isinstance(data, Mapping):
        raise PrescriptionError(source, "surfaces", f"a prescription must be a mapping, got {type(data).__name__}")
    unknown = sorted(set(map(str, data)) - _TOP_KEYS)
    if unknown:
        raise PrescriptionError(source, unknown[0], f"unknown key (known: {', '.join(sorted(_TOP_KEYS))})")
    raw = data.get("surfaces")
    if not isinstance(raw, (list, tuple)) or not raw:
        raise PrescriptionError(source, "surfaces", "expected a non-empty list of surfaces")
    surfaces = tuple(_surface(s, i, i == len(raw), source) for i, s in enumerate(raw, start=1))
    stops = [i for i, s in enumerate(surfaces, start=1) if s.stop]
    if len(stops) != 1:
        found = f"surfaces {stops}" if stops else "none"
        raise PrescriptionError(source, "stop", f"exactly one surface must have stop: true (found {found})")
    _check_contacts(surfaces, source)
    object_index = _number(data.get("object_index", 1.0), source, "object_index", None)
    if object_index < 1.0:
        raise PrescriptionError(source, "object_index", f"refractive index must be ≥ 1, got {object_index:g}")
    optional = {}
    for key in ("wavelength_nm", "focal_length_mm", "f_number"):
        if data.get(key) is not None:
            optional[key] = _number(data[key], source, key, None)
            if optional[key] <= 0.0:
                raise PrescriptionError(source, key, f"must be > 0, got {optional[key]:g}")
    return Prescription(
        surfaces=surfaces,
        object_index=object_index,
        wavelength_nm=optional.get("wavelength_nm", 587.6),
        focal_length_mm=optional.get("focal_length_mm"),
        f_number=optional.get("f_number"),
        id=str(data.get("id", "")),
        name=str(data.get("name", "")),
        source=source,
    )
