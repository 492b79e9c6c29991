"""Options shared by the commands, and the translation of library errors into click errors.

Each decorator adds one family of options with the same names, help and
defaults everywhere (the output options are in :mod:`camtool.cli.command`): the
lens (``-f``), the aperture (``-N``, ``--exact-stops``), the focus distance
(``-s``, ``--distance-from``), the sensor (``--sensor``, ``--crop``) and the
circle of confusion (``--coc``, ``--coc-rule``).
"""

from __future__ import annotations

import contextlib
import sys
from collections.abc import Callable, Iterable, Iterator
from typing import Any, TypeVar

import click

from camtool.cli.params import FNumberType, LengthType, NumberType, one_value
from camtool.core import ranges
from camtool.core.errors import DomainError, InputError
from camtool.core.planes import FOCUS_PLANES

F = TypeVar("F", bound=Callable[..., Any])

LENGTH_MM = LengthType("mm")
EXTENSION_MM = LengthType("mm", bounds=ranges.EXTENSION_MM)
FOCAL_MM = LengthType("mm", bounds=ranges.FOCAL_LENGTH_MM)
COC_MM = LengthType("mm", bounds=ranges.COC_MM)
DISTANCE_M = LengthType("m", allow_inf=True, bounds=ranges.DISTANCE_MM)
FINITE_M = LengthType("m", bounds=ranges.DISTANCE_MM)
PIXEL_PITCH_UM = LengthType("um", bounds=(ranges.PIXEL_PITCH_UM[0] / 1000, ranges.PIXEL_PITCH_UM[1] / 1000))

# Library parameter name -> click parameter name, for error messages.
PARAM_FOR = {
    "guide_number_m": "guide_number",
    "pupil_magnification": "pupil_mag",
    "hiatus_mm": "hiatus",
    "wavelength_nm": "wavelength",
    "focal_length_mm": "focal_length",
    "f_number": "f_number",
    "coc_mm": "coc",
    "distance_mm": "distance",
    "near_mm": "near",
    "far_mm": "far",
    "magnification": "magnification",
    "sensor_mm": "sensor",
    "nd_factor": "nd",
    "prescription": "prescription_file",
    "background_mm": "background",
    "foreground_mm": "foreground",
    "tilt_deg": "tilt",
    "swing_deg": "swing",
    "hinge_mm": "hinge",
    "focus_mm": "distance",
    "image_distance_mm": "image_distance",
    "film_mm": "image_distance",
    "at_mm": "at",
    "half_depth_mm": "half_depth",
}
SHOWN_IN_METRES = {"distance", "near", "far", "background", "foreground"}
ALWAYS_IN_METRES = {"at"}
"""Options whose out-of-range lengths are always shown in metres, with no detail."""
ON_THE_OPTION = {"tilt"}
"""Commands whose range errors always name the option the parameter stands for (no partner, no derived blame)."""
UNTYPED_STANDS_FOR = {("tilt", "coc"): "f_number"}
"""(command, option) -> the option blamed when the first was not typed (tilt: a CoC it chose from the f-number)."""
NEEDS = {"a lens prescription": "--prescription (or a --lens with one)"}
"""What a model needs, as options, when the library names no option that supplies it."""


def stack(*decorators: Callable[[F], F]) -> Callable[[F], F]:
    """One decorator applying ``decorators`` in the order written (the first is outermost)."""

    def apply(function: F) -> F:
        for decorator in reversed(decorators):
            function = decorator(function)
        return function

    return apply


focal_option = click.option("-f", "--focal-length", "focal_length", type=FOCAL_MM, multiple=True,
                            help="Focal length, e.g. 50 or 50mm (bare numbers are mm); a list 24,35,50 gives a row each.")

aperture_options = stack(
    click.option("-N", "--f-number", "f_number", type=FNumberType(t_stops=True), multiple=True,
                 help="f-number: 8, f/8 or f8, or a T-stop T2 (depth of field uses the f-number: from the --lens "
                      "transmittance, else the T-stop stands in); a list 2.8,4,5.6 gives a row each."),
    click.option("--exact-stops", is_flag=True,
                 help="Read nominal f-numbers as the exact 2^(k/6) stops they label (5.6 -> 5.657, 22 -> 22.627)."),
)

squeeze_option = click.option(
    "--squeeze", type=NumberType(*ranges.SQUEEZE), callback=one_value,
    help="Anamorphic squeeze (1.3, 1.5, 1.8, 2; default: an anamorphic --lens preset's own): the horizontal angle is "
    "that of the de-squeezed width; dof adds the horizontal limits, of f/squeeze (docs/cine.md).")

distance_plane_option = click.option(
    "--distance-from", "distance_from", type=click.Choice(FOCUS_PLANES), default="sensor", show_default=True,
    help="Reference plane of all distances: the sensor (focal-plane mark, as lens scales and specs) or the lens.")

Completer = Callable[[click.Context, click.Parameter, str], list[Any]]


def completion(names: Callable[[], Iterable[str]]) -> Completer:
    """Shell completion from a list of values, made only when completing (a failure completes nothing)."""

    def complete(ctx: click.Context, param: click.Parameter, incomplete: str) -> list[Any]:
        from click.shell_completion import CompletionItem

        try:
            values = list(names())
        except Exception:
            return []
        prefix = incomplete.lower()
        return [CompletionItem(value) for value in dict.fromkeys(values) if value.lower().startswith(prefix)]

    return complete


def preset_names(*kinds: str) -> list[str]:
    """The ids of the presets of ``kinds`` in effect."""
    from camtool.presets import load_db

    database = load_db()
    return [name for kind in kinds for name in database.names(kind)]


def preset_completion(*kinds: str) -> Completer:
    """Shell completion of the preset names of ``kinds`` (loads the preset database only when completing)."""
    return completion(lambda: preset_names(*kinds))


def _coc_rules() -> Iterable[str]:
    from camtool.geometry.coc import RULES_TO_COMPLETE

    return RULES_TO_COMPLETE


def file_completion(ctx: click.Context, param: click.Parameter, incomplete: str) -> list[Any]:
    """Shell completion of file paths (the shell's own)."""
    from click.shell_completion import CompletionItem

    return [CompletionItem(incomplete, type="file")]


sensor_options = stack(
    click.option("--sensor", metavar="NAME|WxH", shell_complete=preset_completion("sensor"),
                 help="Sensor preset (full-frame, aps-c, m43, ...) or size in mm (36x24). Default: full frame."),
    click.option("--crop", type=NumberType(*ranges.CROP_FACTOR), callback=one_value,
                 help="Crop factor relative to 36 x 24 mm, instead of --sensor."),
)

coc_options = stack(
    click.option("--coc", type=COC_MM, multiple=True,
                 help="Circle of confusion, e.g. 0.03 or 0.03mm (overrides --coc-rule)."),
    click.option("--coc-rule", default=None, metavar="RULE", shell_complete=completion(_coc_rules),
                 help="CoC from the sensor: d/1500 (default), cine (0.025 mm, the default for cine cameras), d/1730, "
                 "d/1442, px:2 (pixel pitches), print:8x10in@25cm."),
    click.option("--pixel-pitch", type=PIXEL_PITCH_UM,
                 help="Pixel pitch for --coc-rule px:K, e.g. 4.3 or 4.3um (bare numbers are µm, as spec sheets give it)."),
)


@contextlib.contextmanager
def library_errors(ctx: click.Context) -> Iterator[None]:
    """Turn a library error on an input into one click error on the option the user typed (:func:`bad_parameter`).

    Range errors, refused combinations, a model the inputs do not allow and a
    ray trace that fails; any other error passes through.
    """
    try:
        yield
    except ValueError as error:
        if not isinstance(error, DomainError | InputError) and not any(
                _is(error, module, name) for module, name in _TRANSLATED):
            raise
        raise bad_parameter(ctx, error) from None


_TRANSLATED = (("camtool.exposure.calculator", "SettingsError"), ("camtool.plans.tilt", "TiltError"),
               ("camtool.dof.ladder", "ModelUnavailable"), ("camtool.optics.tracer", "RayTraceError"))
"""Library errors the translator knows besides DomainError and InputError (each module loaded only where used)."""


def _is(error: Exception, module: str, name: str) -> bool:
    cls = getattr(sys.modules.get(module), name, None)
    return cls is not None and isinstance(error, cls)


def bad_parameter(ctx: click.Context, error: Exception) -> click.ClickException:
    """The one translation of a library error on an input into a click error naming an option the user typed
    (:func:`_translated`); it keeps a :class:`DomainError`'s ``scenes`` (which scenes of a row failed)."""
    translated = _translated(ctx, error)
    scenes = getattr(error, "scenes", None)
    if scenes is not None:
        translated.scenes = scenes  # type: ignore[attr-defined]
    return translated


def _translated(ctx: click.Context, error: Exception) -> click.ClickException:
    """A library error on an input as a click error naming an option the user typed.

    An :class:`InputError` or a ``SettingsError`` has its inputs spelled as
    this command's options (``{focal_length}`` as ``-f``); a
    :class:`DomainError` is placed on the option its parameter stands for
    (or the typed one it meets, or the one that drives a derived value); an
    unavailable model on ``--model``; a ray trace that fails on the
    ``--prescription`` typed (exit 2), else as a runtime failure (exit 1).
    """
    known: Any = error
    if _is(error, "camtool.exposure.calculator", "SettingsError"):
        shown = {n: p.opts[0] if (p := param_named(ctx, PARAM_FOR.get(n, n))) is not None and p.opts else n
                 for n in known.names}
        return click.UsageError(known.template.format(**shown), ctx)
    if _is(error, "camtool.plans.tilt", "TiltError"):
        param = param_named(ctx, PARAM_FOR.get(known.param, known.param))
        if _is(error, "camtool.plans.tilt", "BeyondLensRange"):
            return click.BadParameter(f"{known.tilt_deg:.3g}° is outside the valid range of --lens {known.lens_id}: "
                                      f"±{known.limit_deg:g}°", ctx=ctx, param=param)
        return click.BadParameter(known.reason, ctx=ctx, param=param)
    if _is(error, "camtool.dof.ladder", "ModelUnavailable"):
        return click.BadParameter(f"{known.model} is not available here: it needs {_needs(ctx, known)}", ctx=ctx,
                                  param=param_named(ctx, "model"))
    if not isinstance(error, DomainError | InputError):  # a ray trace that failed
        prescription = param_named(ctx, "prescription_file")
        if prescription is not None and _typed_by_user(ctx, prescription):
            return click.BadParameter(str(error), ctx=ctx, param=prescription)
        return click.ClickException(str(error))
    if isinstance(error, InputError):
        text = error.render(lambda name: _spelling(ctx, PARAM_FOR.get(str(name), str(name))))
        if error.usage:
            return click.UsageError(text, ctx)
        target = param_named(ctx, PARAM_FOR.get(error.param, error.param))
        if target is not None and not _typed_by_user(ctx, target):  # what stood in for it: a crop for a sensor
            target = next((p for p in (param_named(ctx, n) for n in _STANDS_IN.get(target.name or "", ()))
                           if p is not None and _typed_by_user(ctx, p)), target)
        return click.BadParameter(text, ctx=ctx, param=target)
    if ctx.command.name in ON_THE_OPTION:
        name = PARAM_FOR.get(error.param, error.param)
        name = name if param_named(ctx, name) is not None else error.param
        if not ctx.params.get(name):
            name = UNTYPED_STANDS_FOR.get((ctx.command.name, name), name)
        message = domain_message(error, name)
        if name in ALWAYS_IN_METRES:
            message = (f"{error.value / 1000:.4g} m is outside the valid range: "
                       + error.valid.replace("{limit}", f"{error.limit / 1000:.4g} m"))
        return click.BadParameter(message, ctx=ctx, param=param_named(ctx, name))
    name = PARAM_FOR.get(error.param, error.param)
    param = param_named(ctx, name) or param_named(ctx, error.param)
    if param is not None:
        name = param.name or name
    if param is not None and not _typed_by_user(ctx, param):
        # the value is the option's default, or came from a preset: name what the user typed that it meets
        partner = next((p for p in (param_named(ctx, n) for n in _PARTNERS.get(name, ()))
                        if p is not None and _typed_by_user(ctx, p)), None)
        if partner is not None:
            source = "its default" if _from_default(ctx, param) else "the preset's value"
            return click.BadParameter(f"{_typed(ctx, partner)} does not go with {'/'.join(param.opts)} at {source}: "
                                      + domain_message(error, name), ctx=ctx, param=partner)
    if param is not None and _typed_by_user(ctx, param):
        return click.BadParameter(domain_message(error, name), ctx=ctx, param=param)
    # A value the library derived (a hyperfocal distance, an object distance from a magnification, a solved
    # exposure setting) or one the user did not type (a default, a preset's):
    # blame the option the user typed that drives it, with the value typed.
    blamed = next((p for p in (param_named(ctx, n) for n in BLAME_ORDER) if p is not None and _typed_by_user(ctx, p)),
                  None)
    message = domain_message(error, name)
    listed = error.value.split(",") if isinstance(error.value, str) else []
    named = [p for p in (param_named(ctx, PARAM_FOR.get(n.strip(), n.strip())) for n in listed)
             if isinstance(p, click.Option)]
    if named:  # options left out together ("exactly one of f_number, shutter_s, iso left to solve")
        options = " and ".join("/".join(p.opts) for p in named)
        return click.UsageError(f"missing {options}: {error.valid}", ctx)
    if blamed is not None:
        message = (f"{_typed(ctx, blamed)} gives {_DERIVED.get(error.param, error.param)} of "
                   + message.replace(" is outside the valid range", ", outside the valid range", 1))
    return click.BadParameter(message, ctx=ctx, param=blamed)


BLAME_ORDER = ("illuminance", "luminance", "ev100", "light", "magnification", "fill", "subject_size", "f_number",
               "focal_length", "coc", "coc_rule", "distance", "near", "far", "distance_from", "model", "scene",
               "camera", "lens", "prescription_file")
"""Options blamed, in this order, for a value the library derived from several of them."""

_DERIVED = {"distance_mm": "a distance", "near_mm": "a near limit", "far_mm": "a far limit",
            "magnification": "a magnification", "coc_mm": "a CoC", "focal_length_mm": "a focal length",
            "f_number": "an f-number", "iso": "an ISO", "shutter_s": "a time"}


def _needs(ctx: click.Context, error: Any) -> str:
    """What an unavailable model needs, with only the options this command has."""
    from camtool.dof.ladder import either

    options = {opt for param in ctx.command.params for opt in (*param.opts, *param.secondary_opts)}
    sources = [text for text in error.supplied_by if any(word in options for word in text.split())]
    return f"{error.needs} ({either(sources)})" if sources else NEEDS.get(error.missing, error.missing)


_STANDS_IN = {"sensor": ("crop", "camera", "lens", "scene")}
"""Options that give a value in another's place (a crop factor gives the sensor), blamed when that one was not typed."""

_PARTNERS = {"hiatus": ("pupil_mag", "focal_length", "distance"), "pupil_mag": ("hiatus", "focal_length")}
"""Options whose values meet in one check: when the one the library names was not typed, these are blamed."""


def _typed_by_user(ctx: click.Context, param: click.Parameter) -> bool:
    """Whether the user gave ``param`` (on the command line or in its environment variable)."""
    if param.name in ctx.meta.get("camtool.batch_cells", ()):  # a --batch cell is typed, as an option is
        return True
    source = ctx.get_parameter_source(param.name or "")
    return source in (click.core.ParameterSource.COMMANDLINE, click.core.ParameterSource.ENVIRONMENT)


def _from_default(ctx: click.Context, param: click.Parameter) -> bool:
    return ctx.get_parameter_source(param.name or "") in (click.core.ParameterSource.DEFAULT, None)


def _typed(ctx: click.Context, param: click.Parameter) -> str:
    value = ctx.params.get(param.name or "")
    if isinstance(value, (list, tuple)):
        flat = [v for group in value for v in (group if isinstance(group, list) else [group])]
        return ",".join(f"{v:g}" if isinstance(v, float) else str(v) for v in flat)
    return f"{value:g}" if isinstance(value, float) else str(value)


class FileParameterError(click.BadParameter):
    """A file given to an option cannot be read or is invalid: a runtime failure, exit status 1."""

    exit_code = 1


def file_error(ctx: click.Context, name: str, error: Exception) -> click.BadParameter:
    """An unreadable or invalid file given to option ``name``: one line naming the option and the file, exit 1."""
    return FileParameterError(str(error), ctx=ctx, param=param_named(ctx, name))


def _spelling(ctx: click.Context, name: str) -> str:
    """How the user writes the input ``name`` on this command: its first spelling (``--lens``, ``-f``, ``-N``)."""
    param = param_named(ctx, name)
    if param is None:
        return "--" + name.replace("_", "-")
    return param.opts[0]


def param_named(ctx: click.Context, name: str) -> click.Parameter | None:
    """The command's parameter called ``name`` (its Python name), for errors that name the option."""
    return next((p for p in ctx.command.params if p.name == name), None)


def domain_message(error: DomainError, name: str) -> str:
    """'<value> is outside the valid range: <range>' with lengths shown in a sensible unit."""
    metres = name in SHOWN_IN_METRES
    if isinstance(error.value, (int, float)):
        value = show_length(error.value, metres) if error.param.endswith("_mm") else f"{error.value:g}"
    else:
        value = str(error.value)
    valid = error.valid
    if error.limit is not None:
        valid = valid.replace("{limit}", show_length(error.limit, metres))
    text = f"{value} is outside the valid range: {valid}"
    return text + (f" ({error.detail})" if error.detail else "")


def show_length(mm: float, metres: bool = False) -> str:
    """A length for an error message: metres for distances, millimetres otherwise."""
    if metres and abs(mm) >= 1000:
        return f"{mm / 1000:.4g} m"
    return f"{mm:.4g} mm"


def projection_option(function: Callable[..., Any]) -> Callable[..., Any]:
    """``--projection``: the lens's mapping, rectilinear or a fisheye's."""
    from camtool.geometry.projection import PROJECTIONS

    return click.option("--projection", type=click.Choice(PROJECTIONS), default=None,
                        help="The lens's mapping (default: the --lens preset's, else rectilinear); a fisheye covers "
                             "at most its field (the preset's, else 180°).")(function)
