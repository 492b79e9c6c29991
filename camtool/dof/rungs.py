"""The rungs of the model ladder, one record each: where a model rung lives.

A :class:`Rung` holds everything the rest of the package knows about one
model: the function that computes it, the lens data it needs (and where a
user supplies them), the effects it leaves out (which ``auto`` weighs) and
its one-line help. :data:`RUNGS` lists them cheapest (and least complete)
first; the dispatcher (:mod:`camtool.dof.ladder`), ``auto``'s estimates
(:mod:`camtool.dof.auto`) and the ``--model`` choices and help of the
commands are derived from it. Adding a rung means adding one record here
and one function. docs/design.md §4.
"""

from __future__ import annotations

from collections.abc import Callable
from typing import Any

from camtool.core.record import NamedTuple, Record
from camtool.dof.closed import approx_dof, thin_dof
from camtool.dof.limits import DofLimits
from camtool.geometry.thinlens import FocusGeometry, LensPlaneDistances, focus_geometry

__all__ = ["NO_LENS", "RUNGS", "Focus", "LensData", "Rung", "by_name", "geometric", "in_air", "names", "traceable"]


class LensData(Record):
    """What is known about the lens beyond its focal length.

    ``pupil_magnification`` P (exit/entrance pupil diameter) and
    ``hiatus_mm`` δ (separation of the principal planes) for ``thick``;
    ``prescription`` (a :class:`camtool.optics.prescription.Prescription`)
    for ``paraxial`` and ``raytrace``, which also supplies f, P and δ where
    they are not given by hand.
    """

    pupil_magnification: float | None = None
    hiatus_mm: float | None = None
    prescription: Any = None

    @property
    def first_order(self) -> Any:
        """First-order data of the prescription (None without one)."""
        if self.prescription is None:
            return None
        from camtool.optics.paraxial import first_order

        return first_order(self.prescription)

    @property
    def focal_length_mm(self) -> float | None:
        """The prescription's paraxial focal length (None without a prescription)."""
        fo = self.first_order
        return None if fo is None else fo.efl_mm

    def thick_parameters(self) -> tuple[float, float] | None:
        """(P, δ) for ``thick``: given by hand, else the prescription's, else P = 1, δ = 0 for the missing one.

        None when neither is known.
        """
        fo = self.first_order
        if self.pupil_magnification is None and self.hiatus_mm is None and fo is None:
            return None
        p = self.pupil_magnification if self.pupil_magnification is not None else (fo.pupil_magnification if fo else 1.0)
        delta = self.hiatus_mm if self.hiatus_mm is not None else (fo.hiatus_mm if fo else 0.0)
        return p, delta


NO_LENS = LensData()


class Rung(NamedTuple):
    """One model of the ladder.

    ``run(f, N, c, s, plane, lens, focus)`` returns :class:`camtool.dof.limits.DofLimits`
    (lengths in mm); ``focus`` (a :class:`Focus`, or None) is the dispatcher's
    one conversion of the focus distance, for the rung to reuse. ``can_run(lens)`` says whether the lens data allow it;
    when not, ``needs`` names the missing data and ``supplied_by`` the options
    that supply them (a command names those it has). ``left_out`` lists the
    geometric effects of :class:`camtool.dof.auto.Effects` the model neglects
    (diffraction is left out unless the add-on runs). ``help`` is the one-line
    ``--model`` help; ``hyperfocal_help``, when set, makes the rung a choice of
    ``camtool hyperfocal`` (a closed form whose focus at infinity gives H).
    ``contrast`` marks a rung that defines sharpness by a contrast criterion
    (``wave``): it takes ``criterion`` and ``wavelength_nm`` as keywords, has
    diffraction built in, and stands beside the geometric ladder rather than on
    it (``auto`` picks it by its own rule, :func:`camtool.dof.ladder.depth_of_field`).
    """

    name: str
    run: Callable[..., DofLimits]
    left_out: tuple[str, ...]
    help: str
    can_run: Callable[[LensData], bool] = lambda lens: True
    needs: str = ""
    supplied_by: tuple[str, ...] = ()
    hyperfocal_help: str | None = None
    contrast: bool = False


class Focus(NamedTuple):
    """The focus distance converted once by the dispatcher: the geometry, with the hiatus it used (mm).

    ``hyperfocal_mm``, when set, is the hyperfocal distance in the focus plane of the rung the focus is handed to,
    by that rung's own closed form (``auto`` over arrays has it before the rung runs); None: the rung computes it.
    """

    geometry: FocusGeometry
    hiatus_mm: float
    hyperfocal_mm: Any = None


def _distances(focus: Focus | None, plane: str, hiatus_mm: float) -> LensPlaneDistances | None:
    """(u, v) of the dispatcher's conversion when it used this plane's hiatus (a rung then converts nothing)."""
    if focus is None or plane != "sensor" or focus.hiatus_mm != hiatus_mm:
        return None
    return LensPlaneDistances(focus.geometry.object_mm, focus.geometry.image_mm)


def _approx(f: Any, n: Any, c: Any, s: Any, plane: str, lens: LensData, focus: Focus | None = None) -> DofLimits:
    # The approximation has no notion of the closest focus; the scene still must be reachable
    # (the dispatcher's conversion has checked it).
    if focus is None:
        focus_geometry(f, s, plane)
    return approx_dof(f, n, c, s)


def _thin(f: Any, n: Any, c: Any, s: Any, plane: str, lens: LensData, focus: Focus | None = None) -> DofLimits:
    return thin_dof(f, n, c, s, plane, _distances(focus, plane, 0.0), None if focus is None else focus.hyperfocal_mm)


def _thick(f: Any, n: Any, c: Any, s: Any, plane: str, lens: LensData, focus: Focus | None = None) -> DofLimits:
    from camtool.dof.thick import thick_dof

    p, delta = lens.thick_parameters()  # type: ignore[misc]
    return thick_dof(f, n, c, s, pupil_magnification=p, hiatus_mm=delta, distance_from=plane,
                     focus=_distances(focus, plane, delta), hyperfocal=None if focus is None else focus.hyperfocal_mm)


def _paraxial(f: Any, n: Any, c: Any, s: Any, plane: str, lens: LensData, focus: Focus | None = None) -> DofLimits:
    from camtool.dof.paraxial import paraxial_dof

    return paraxial_dof(lens.prescription, n, c, s, plane)


def _raytrace(f: Any, n: Any, c: Any, s: Any, plane: str, lens: LensData, focus: Focus | None = None) -> DofLimits:
    from camtool.dof.realray import raytrace_dof

    return raytrace_dof(lens.prescription, n, c, s, plane)


def _wave(f: Any, n: Any, c: Any, s: Any, plane: str, lens: LensData, focus: Focus | None = None,
          criterion: Any = None, wavelength_nm: float = 550.0) -> DofLimits:
    if traceable(lens):  # the real lens's wavefront, at the prescription's own wavelength
        from camtool.dof.wavetrace import prescription_wave_dof

        return prescription_wave_dof(lens.prescription, n, c, s, plane, criterion)
    from camtool.dof.wave import wave_dof

    return wave_dof(f, n, c, s, plane, criterion, wavelength_nm, _distances(focus, plane, 0.0))


def _has_thick_data(lens: LensData) -> bool:
    return lens.thick_parameters() is not None


def in_air(prescription: Any) -> str:
    """What a prescription the traced paths cannot use needs: "" when it is in air (n = 1 before and after it)."""
    if prescription.object_index == 1.0 and prescription.image_index == 1.0:
        return ""
    return (f"a lens prescription in air (object and image space of index 1; this one has {prescription.object_index:g} "
            f"and {prescription.image_index:g})")


def traceable(lens: LensData) -> bool:
    """Whether the lens has a prescription the paraxial, real-ray and wavefront paths can use: in air (n = 1 before
    and after it); another one still gives its first-order data to ``thick``."""
    return lens.prescription is not None and not in_air(lens.prescription)


_PRESCRIPTION = "a lens prescription"
_PRESCRIPTION_SOURCES = ("--prescription FILE", "a --lens that has one")

RUNGS: tuple[Rung, ...] = (
    Rung("approx", _approx, ("approximation", "distance_plane", "pupil", "hiatus", "aberrations"),
         "H·s/(H±s)", hyperfocal_help="H = f²/(N·c)"),
    Rung("thin", _thin, ("pupil", "hiatus", "aberrations"),
         "exact thin lens", hyperfocal_help="H = f²/(N·c) + f, exact"),
    Rung("thick", _thick, ("aberrations",),
         "+ pupil magnification and hiatus", _has_thick_data, "the lens's pupil magnification or hiatus",
         ("--pupil-mag", "--hiatus", "a --lens that has them", "--prescription"),
         hyperfocal_help="with the lens's pupil magnification and hiatus (--lens, --pupil-mag, --hiatus)"),
    Rung("paraxial", _paraxial, ("aberrations",),
         "first-order trace of --prescription", traceable, _PRESCRIPTION, _PRESCRIPTION_SOURCES),
    Rung("raytrace", _raytrace, (),
         "real rays", traceable, _PRESCRIPTION, _PRESCRIPTION_SOURCES),
    Rung("wave", _wave, ("pupil", "hiatus", "aberrations"),
         "sharp where the MTF meets --criterion (diffraction and defocus together): a perfect thin lens, or "
         "with a prescription its real wavefront's FFT MTF",
         hyperfocal_help="by contrast: where the far limit's MTF meets --criterion (auto with --diffraction or "
                         "--criterion)", contrast=True),
)
"""The rungs, cheapest (and least complete) first."""

_INDEX: tuple[tuple[Rung, ...], dict[str, Rung]] = ((), {})


def by_name() -> dict[str, Rung]:
    """The rungs of :data:`RUNGS` by name (rebuilt only when RUNGS is replaced).

    Examples
    --------
    >>> by_name()["thick"].left_out
    ('aberrations',)
    """
    global _INDEX
    if _INDEX[0] is not RUNGS:
        _INDEX = (RUNGS, {rung.name: rung for rung in RUNGS})
    return _INDEX[1]


def names() -> tuple[str, ...]:
    """The rung names, cheapest first.

    Examples
    --------
    >>> names()
    ('approx', 'thin', 'thick', 'paraxial', 'raytrace', 'wave')
    """
    return tuple(by_name())


def geometric() -> tuple[Rung, ...]:
    """The rungs of the geometric ladder (blur against the CoC), cheapest first: every rung but the contrast ones.

    >>> [rung.name for rung in geometric()]
    ['approx', 'thin', 'thick', 'paraxial', 'raytrace']
    """
    return tuple(rung for rung in RUNGS if not rung.contrast)
