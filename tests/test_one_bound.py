"""One bound per quantity: a Python API argument accepts what its command-line option accepts.

(The command-line options and their ``--batch`` columns are compared in tests/test_batch_bounds.py.)
For each numeric argument of each public function that stands for an option, the bounds its annotation
names are the option's own, read from the option's parameter type; and a value just outside them is
refused on both paths while the bounds themselves are accepted.
"""

from __future__ import annotations

import inspect
import math
import typing

import click
import pytest

import camtool
from camtool import api
from camtool.cli import cli
from camtool.cli.params import AngleType, FNumberType, LengthType, NumberType, Parsed
from camtool.core.errors import DomainError, InputError

# API argument -> (command, option parameter name)
STANDS_FOR = {
    "focal_length_mm": ("dof", "focal_length"),
    "f_number": ("dof", "f_number"),
    "coc_mm": ("dof", "coc"),
    "distance_mm": ("dof", "distance"),
    "magnification": ("dof", "magnification"),
    "pixel_pitch_mm": ("dof", "pixel_pitch"),
    "crop_factor": ("stars", "crop"),
    "declination_deg": ("stars", "declination"),
    "rule_constant": ("stars", "rule_constant"),
    "npf_k": ("stars", "npf_k"),
    "iso": ("exposure", "iso"),
    "pupil_magnification": ("dof", "pupil_mag"),
    "fps": ("exposure", "fps"),
    "shutter_angle_deg": ("exposure", "shutter_angle"),
    "film_distance_mm": ("pinhole", "film_distance"),
    "contrast_level": ("pinhole", "contrast"),
    "ev100": ("pinhole", "ev100"),
    "wavelength_nm": ("dof", "wavelength"),
    "tolerance": ("dof", "tolerance"),
    "tilt_deg": ("tilt", "tilt"),
    "swing_deg": ("tilt", "swing"),
    "overlap": ("stack", "overlap"),
}


def _option_bounds(command: str, name: str) -> tuple[float, float] | None:
    group = cli.get_command(click.Context(cli), command)
    assert group is not None
    param = next(p for p in group.params if p.name == name)
    kind = param.type
    if isinstance(kind, LengthType):
        return kind.bounds  # millimetres, as the API's arguments
    if isinstance(kind, FNumberType):
        from camtool.core.ranges import F_NUMBER

        return F_NUMBER
    if isinstance(kind, NumberType):
        return kind.low, kind.high
    if isinstance(kind, (Parsed, AngleType)) and kind.bounds is not None:
        return kind.bounds
    if isinstance(kind, click.FloatRange):
        return kind.min, kind.max
    return None


def _cases() -> list[tuple[str, str, tuple[float, float]]]:
    cases = []
    for fname in camtool.__all__:
        function = getattr(camtool, fname)
        if not inspect.isfunction(function):
            continue
        hints = typing.get_type_hints(inspect.unwrap(function), include_extras=True)
        for pname, hint in hints.items():
            kinds = [m for m in getattr(hint, "__metadata__", ()) if isinstance(m, api._Kind)]
            if pname in STANDS_FOR and kinds and kinds[0].bounds is not None:
                cases.append((fname, pname, kinds[0].bounds))
    return cases


CASES = _cases()


def test_every_argument_standing_for_an_option_is_checked() -> None:
    assert {p for _, p, _ in CASES} >= {"focal_length_mm", "f_number", "coc_mm", "distance_mm", "magnification",
                                         "crop_factor", "iso"}


@pytest.mark.parametrize(("function", "param", "bounds"), CASES, ids=[f"{f}.{p}" for f, p, _ in CASES])
def test_the_api_argument_has_the_option_s_bounds(function: str, param: str, bounds: tuple[float, float]) -> None:
    option = _option_bounds(*STANDS_FOR[param])
    assert option is not None
    low, high = option
    kind = next(m for m in typing.get_type_hints(inspect.unwrap(getattr(camtool, function)),
                                                   include_extras=True)[param].__metadata__ if isinstance(m, api._Kind))
    if kind.zero_ok:  # 0 also stands for "at infinity" (no magnification): the option's range above it
        low = bounds[0]
    assert math.isclose(bounds[0], low, rel_tol=1e-12, abs_tol=0.0) and (
        bounds[1] == high or math.isclose(bounds[1], high, rel_tol=1e-12)), (bounds, option)


@pytest.mark.parametrize("value", [0.999, 5000.5])
def test_a_focal_length_outside_the_option_s_range_is_refused_on_both_paths(value: float) -> None:
    from cli_helpers import run

    assert run("dof", "-f", repr(value), "-N", "8", "-s", "3m").exit_code == 2
    with pytest.raises(DomainError) as caught:
        camtool.depth_of_field(value, 8, 0.03, 3000)
    assert caught.value.param == "focal_length_mm"
    assert run("dof", "-f", "1", "-N", "8", "-s", "3m").exit_code == 0
    camtool.depth_of_field(1.0, 8, 0.03, 3000)


def test_every_pupil_magnification_option_takes_one_range() -> None:
    """--pupil-mag is one quantity on every command that takes it (exposure's bellows factor included)."""
    found = _every_option("--pupil-mag")
    assert len(found) >= 5 and set(found.values()) == {(0.05, 20.0)}, found


def _every_option(option: str) -> dict[str, tuple[float, float] | None]:
    """The bounds of ``option`` on every command and chart subcommand that takes it, by "command subcommand"."""
    found = {}
    ctx = click.Context(cli)
    for name in cli.list_commands(ctx):
        command = cli.get_command(ctx, name)
        for sub in list(getattr(command, "commands", {}).values()) or [command]:
            for param in sub.params:
                if option in getattr(param, "opts", ()):
                    found[f"{name} {sub.name}"] = _option_bounds_of(param)
    return found


def _option_bounds_of(param: click.Parameter) -> tuple[float, float] | None:
    kind = param.type
    if isinstance(kind, Parsed):
        return kind.bounds
    return (kind.low, kind.high) if isinstance(kind, NumberType) else None


def test_every_squeeze_takes_one_range_option_preset_and_plan() -> None:
    """--squeeze on every command, a lens preset's squeeze key and the plan that picks between them share
    camtool.core.ranges.SQUEEZE (a batch cell of --squeeze is compared with the option in test_batch_bounds)."""
    from camtool.core.ranges import SQUEEZE
    from camtool.plans.equipment import lens_squeeze
    from camtool.presets.schema import Bad, squeeze_factor

    found = _every_option("--squeeze")
    assert set(found) >= {"fov fov", "dof dof", "compose compose", "chart dof"} and set(found.values()) == {SQUEEZE}
    for value in SQUEEZE:
        assert squeeze_factor(value) == value == lens_squeeze(None, squeeze=value)
    for value in (SQUEEZE[0] * (1 - 1e-9), SQUEEZE[1] * (1 + 1e-9)):
        with pytest.raises(Bad):
            squeeze_factor(value)
        with pytest.raises(DomainError):
            lens_squeeze(None, squeeze=value)


@pytest.mark.parametrize(("command", "call", "given"), [
    (["hyperfocal", "--lens", "nikon-z-24mm-f1.8-s", "-N", "32"],
     lambda: camtool.hyperfocal_distance(focal_length_mm=24, f_number=32, coc_mm=0.03, lens="nikon-z-24mm-f1.8-s"),
     "f/32"),
    (["stack", "--lens", "nikon-z-24mm-f1.8-s", "-f", "1400", "-N", "8", "--near", "1m", "--far", "inf"],
     lambda: camtool.bracket_stack(1400, 8, 0.03, 1000, float("inf"), lens="nikon-z-24mm-f1.8-s"), "1400 mm"),
    (["stack", "--lens", "nikon-z-24mm-f1.8-s", "-N", "22", "--near", "1m", "--far", "inf"],
     lambda: camtool.bracket_stack(24, 22, 0.03, 1000, float("inf"), lens="nikon-z-24mm-f1.8-s"), "f/22"),
])
def test_a_lens_preset_bounds_the_api_as_it_bounds_the_command(command, call, given) -> None:
    # the lens's own focal length and apertures (NIKKOR Z 24mm f/1.8 S: 24 mm, f/1.8 to f/16), whichever way
    # it is asked; the API fuzz found bracket_stack taking 1400 mm on a 24 mm prime (and dividing by zero)
    from cli_helpers import run

    result = run(*command)
    assert result.exit_code == 2 and f"{given} is outside the valid range of --lens nikon-z-24mm-f1.8-s" in result.stderr
    with pytest.raises(InputError, match=f"{given} is outside the valid range of lens nikon-z-24mm-f1.8-s"):
        call()
