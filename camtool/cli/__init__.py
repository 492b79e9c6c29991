"""The ``camtool`` command group.

Subcommands live in their own modules and are imported only when run, so a
single ``camtool dof ... --format json`` pays for click and its own module,
not for rich, numpy or the other commands.
"""

from __future__ import annotations

import contextlib
import importlib
import importlib.util
import os
import sys
from typing import Any

import click

from camtool import __version__
from camtool.core import collector
from camtool.core.errors import FileError
from camtool.render import terminal

COMMANDS = {
    "fov": "camtool.cli.fov",
    "focus": "camtool.cli.focus",
    "dof": "camtool.cli.dof",
    "hyperfocal": "camtool.cli.hyperfocal",
    "tilt": "camtool.cli.tilt",
    "compose": "camtool.cli.compose",
    "exposure": "camtool.cli.exposure",
    "stars": "camtool.cli.stars",
    "flash": "camtool.cli.flash",
    "equiv": "camtool.cli.equiv",
    "presets": "camtool.cli.presets",
    "completion": "camtool.cli.completion",
    "exif": "camtool.cli.exif",
    "chart": "camtool.cli.chart",
    "stack": "camtool.cli.stack",
    "cocmap": "camtool.cli.cocmap",
    "pinhole": "camtool.cli.pinhole",
}

def summary(name: str) -> str:
    """The first paragraph of a command's help, read from its module's source: ``camtool --help`` imports none.

    The command's function is ``def NAME(`` at the top of its module, its docstring the help click shows.
    """
    from pathlib import Path

    spec = importlib.util.find_spec(COMMANDS[name])
    source = Path(spec.origin if spec is not None and spec.origin else "").read_text(encoding="utf-8")
    start = source.index('"""', source.index(f"\ndef {name}(")) + 3
    return " ".join(source[start:source.index('"""', start)].split("\n\n")[0].split())


def _available(name: str) -> bool:
    return importlib.util.find_spec(COMMANDS[name]) is not None


class CamtoolGroup(click.Group):
    """A group that imports its commands lazily and prints errors as one line."""

    def list_commands(self, ctx: click.Context) -> list[str]:
        return [name for name in COMMANDS if _available(name)]

    def get_command(self, ctx: click.Context, name: str) -> click.Command | None:
        if name not in COMMANDS or not _available(name):
            return None
        module = importlib.import_module(COMMANDS[name])
        command: click.Command = getattr(module, name)
        return command

    def format_commands(self, ctx: click.Context, formatter: click.HelpFormatter) -> None:
        """The list of commands, as click writes it, from each :func:`summary`: no command module is imported."""
        names = self.list_commands(ctx)
        if names:
            limit = formatter.width - 6 - max(len(name) for name in names)
            with formatter.section("Commands"):  # click shortens each summary as it would the command's help
                formatter.write_dl([(name, click.Command(name, help=summary(name)).get_short_help_str(limit))
                                    for name in names])

    def resolve_command(self, ctx: click.Context, args: list[str]) -> Any:
        name = args[0] if args else ""
        if name and not name.startswith("-") and self.get_command(ctx, name) is None:
            import difflib  # only on this error path: it costs 12 ms of start-up

            close = difflib.get_close_matches(name, self.list_commands(ctx), n=2)
            hint = f" Did you mean {' or '.join(repr(c) for c in close)}?" if close else ""
            raise click.UsageError(f"No such command {name!r}.{hint}", ctx)
        return super().resolve_command(ctx, args)

    def invoke(self, ctx: click.Context) -> Any:
        try:
            return super().invoke(ctx)
        except OSError as error:  # past click, which would make a closed pipe exit 1
            raise _WriteFailed(error) from None

    def main(self, args: Any = None, prog_name: str | None = None, **extra: Any) -> Any:  # type: ignore[override]
        """Run the group; expected errors become one line on stderr, never a traceback.

        A reader that goes away (``camtool ... | head -1``) is a normal end,
        exit 0; output that cannot be written (a full disk, a closed standard
        output) is a one-line error, exit 1.
        """
        extra.pop("standalone_mode", None)
        if sys.stdout is None:
            sys.stdout = terminal.ClosedOutput()
        terminal.degrade_to_ascii()
        try:
            code = super().main(args=args, prog_name=prog_name or "camtool", standalone_mode=False, **extra)
            sys.stdout.flush()
        except Interrupted:
            terminal.interrupted()
        except click.exceptions.Abort:
            click.echo("Aborted!", err=True)
            sys.exit(1)
        except click.ClickException as error:
            sys.stdout.flush()
            click.echo(f"Error: {_shown(_hinted(error, args))}", err=True)
            sys.exit(error.exit_code)
        except FileError as error:  # a file found wrong only when a preset is used
            click.echo(f"Error: {_shown(str(error))}", err=True)
            sys.exit(1)
        except _WriteFailed as failure:
            _output_failed(failure.error)
        except OSError as error:
            _output_failed(error)
        sys.exit(code if isinstance(code, int) else 0)


class Interrupted(BaseException):
    """SIGINT (Ctrl-C), raised by camtool's own handler so that no library catches it on the way out."""


def _on_sigint(signum: int, frame: Any) -> None:
    raise Interrupted()


def _shown(message: str) -> str:
    """An error message as printed: one line, control characters escaped (it may quote what a file held)."""
    from camtool.render.serial import printable

    return printable(" ".join(message.split("\n")))


_CHOICE_WORDS = {"feet": "imperial", "foot": "imperial", "ft": "imperial", "inches": "imperial", "us": "imperial",
                 "metres": "metric", "meters": "metric", "m": "metric", "si": "metric", "mm": "metric",
                 "text": "table", "tsv": "csv"}
"""Words people type for a choice that is spelled otherwise (``--units feet``)."""

_UNITS = {"m", "mm", "cm", "km", "ft", "in", "um", "µm", "s", "ms", "min", "h", "deg", "°", "stops", "ev"}


def _hinted(error: click.ClickException, args: Any) -> str:
    """click's message, with the hint a photographer needs: the unit apart from its number, a near-miss choice,
    a bad CAMTOOL_FORMAT that nobody typed as --format."""
    message = error.format_message()
    typed = list(args) if args is not None else sys.argv[1:]
    if isinstance(error, click.UsageError) and message.startswith("Got unexpected extra argument"):
        extra = message[message.find("(") + 1:message.rfind(")")].split()
        if extra and extra[0].lower() in _UNITS:
            return f"{message}: a value and its unit are one word, e.g. 3m or 50mm, not 3 m"
        if extra and extra[0][:1].isdigit():
            return f"{message}: a list is written with commas and no spaces, e.g. -N 2.8,4,5.6"
        return message
    param = getattr(error, "param", None)
    if isinstance(error, click.BadParameter) and param is not None and isinstance(param.type, click.Choice):
        envvar = getattr(param, "envvar", None)
        if isinstance(envvar, str) and os.environ.get(envvar) and not any(
                arg in param.opts or any(arg.startswith(opt + "=") for opt in param.opts) for arg in typed):
            choices = ", ".join(map(str, param.type.choices))
            return f"{envvar}={os.environ[envvar]!r} is not one of {choices} (unset it, or give {param.opts[-1]})"
        import difflib
        import re

        found = re.search(r"'([^']*)' is not one of", message)
        if found:
            names = [str(c) for c in param.type.choices]
            word = _CHOICE_WORDS.get(found.group(1).strip().lower(), "")
            close = [word] if word in names else difflib.get_close_matches(found.group(1), names, n=2, cutoff=0.5)
            if close:
                return f"{message} Did you mean {' or '.join(repr(c) for c in close)}?"
    return message


def _output_failed(error: OSError) -> None:
    """Exit after a write error: 0 for a reader that went away, else a one-line error and 1."""
    code, line = terminal.write_failure(error)
    if line is not None:
        click.echo(line, err=True)
    sys.exit(code)


class _WriteFailed(Exception):
    """An OSError from a command (a closed pipe, a full disk), carried past click's own handling."""

    def __init__(self, error: OSError) -> None:
        super().__init__(str(error))
        self.error = error


@click.group(cls=CamtoolGroup, context_settings={"help_option_names": ["-h", "--help"], "max_content_width": 100})
@click.version_option(__version__, "--version", prog_name="camtool")
def cli() -> None:
    """Depth of field, field of view, focusing and exposure for photographers and shell scripts.

    Every command prints a table, or JSON/CSV with --format (or
    CAMTOOL_FORMAT). Run camtool COMMAND --help for a command's options and
    examples; man camtool describes units, exit codes and the environment.

    \b
    Examples:
      camtool dof -f 50 -N 8 -s 3m
      camtool hyperfocal -f 24 -N 8,11,16
    """


def main(collecting: bool | None = None) -> None:
    """Run the command line (``camtool`` and ``python -m camtool`` call it through :func:`camtool.__main__.main`).

    The cyclic garbage collector is paused while the command is found and its options read, and resumed as its
    work begins (:mod:`camtool.core.collector`). ``collecting`` is given by the process's entry point, which paused
    the collector before the first import: whether it was on before; what start-up made is then frozen. An
    in-process caller (``collecting`` None) gets its collector back as it was, nothing frozen.
    """
    import signal

    with contextlib.suppress(ValueError, OSError):  # not the main thread, or no such signal here
        signal.signal(signal.SIGINT, _on_sigint)
    collector.pause(collecting, owned=collecting is not None)
    try:
        cli.main()
    except Interrupted:
        terminal.interrupted()
    except OSError as error:
        _output_failed(error)
    finally:
        collector.resume()

