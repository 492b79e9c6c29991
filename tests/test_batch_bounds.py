"""One bound per quantity: every option a ``--batch`` column can give accepts exactly what the option accepts.

For each command with ``--batch`` and each of its numeric options, values on
both sides of the option's own range (read from its parameter type, not
written here) are given once as the option and once as a batch cell, with
the same other inputs; the two runs must both succeed or both fail.
"""

from __future__ import annotations

import math
import os

import click
import pytest
from cli_helpers import run, time_bound  # noqa: F401

from camtool.cli import cli
from camtool.cli.params import FNumberType, LengthType, NumberType, _ListType
from camtool.core.ranges import F_NUMBER

BASE = {
    "dof": ["-f", "50", "-N", "8", "-s", "3m"],
    "fov": ["-f", "50"],
    "focus": ["-f", "50", "-s", "3m"],
    "hyperfocal": ["-f", "50", "-N", "8"],
    "stars": ["-f", "24", "-N", "2.8"],
    "flash": ["--gn", "40", "-N", "8"],
    "equiv": ["-f", "25", "-N", "1.4"],
}


def _bounds(kind: click.ParamType) -> tuple[float, float] | None:
    """The option's range in its own bare-number unit (what a cell without a unit means)."""
    if isinstance(kind, LengthType):
        from camtool.core.units import MM_PER_UNIT

        scale = MM_PER_UNIT[kind.default_unit]
        return kind.bounds[0] / scale, kind.bounds[1] / scale
    if isinstance(kind, FNumberType):
        return F_NUMBER
    if isinstance(kind, NumberType):
        return kind.low, kind.high
    return None


def _cases() -> list[tuple[str, str, str]]:
    cases = []
    for name in BASE:
        command = cli.get_command(click.Context(cli), name)
        assert command is not None
        for param in command.params:
            if not isinstance(param, click.Option) or not isinstance(param.type, _ListType):
                continue
            option = max(param.opts, key=len)
            bounds = _bounds(param.type)
            values = ["0", "-1", "1e-320", "1e308", "inf", "1_0", "\u0661\u0660"]  # 1_0: no; Arabic-Indic 10: yes
            if bounds is not None:
                low, high = bounds
                values += [repr(low), repr(low * (1 - 1e-6) if low else -1e-9)]
                if math.isfinite(high):
                    values += [repr(high), repr(high * (1 + 1e-6))]
            cases += [(name, option, value) for value in values]
    return cases


@pytest.mark.parametrize(("command", "option", "value"), _cases())
def test_a_batch_cell_accepts_what_its_option_accepts(command: str, option: str, value: str, tmp_path) -> None:
    base = list(BASE[command])
    short = {"--focal-length": "-f", "--f-number": "-N", "--distance": "-s", "--magnification": "-s"}.get(option)
    if short in base or option in base:  # the option under test replaces the base's value (-m replaces -s)
        index = base.index(short if short in base else option)
        del base[index:index + 2]
    by_option = run(command, *base, option, value, "--format", "json")
    table = tmp_path / "scenes.csv"
    table.write_text(f"{option.lstrip('-')}\n{value}\n")
    by_cell = run(command, *base, "--batch", os.fspath(table), "--format", "json")
    assert (by_option.exit_code == 0) == (by_cell.exit_code == 0), (
        f"{command} {option} {value}: option exit {by_option.exit_code} ({by_option.stderr.strip()}), "
        f"batch exit {by_cell.exit_code} ({by_cell.stderr.strip()})")
    for result in (by_option, by_cell):
        assert result.exit_code in (0, 1, 2)
        if result.exit_code:
            assert result.stderr.count("\n") == 1, result.stderr
