"""The ``camtool`` command group.

Subcommands live in their own modules and are imported only when run, so a
single ``camtool dof ... --format json`` pays for click and its own module,
not for rich, numpy or the other commands.
"""

from __future__ import annotations

import importlib
import importlib.util
import os
import sys
from typing import Any

import click

from camtool import __version__
from camtool.core.errors import FileError

COMMANDS = {
    "fov": "camtool.cli.fov",
    "focus": "camtool.cli.focus",
    "dof": "camtool.cli.dof",
    "hyperfocal": "camtool.cli.hyperfocal",
    "compose": "camtool.cli.compose",
    "exposure": "camtool.cli.exposure",
    "stars": "camtool.cli.stars",
    "flash": "camtool.cli.flash",
    "equiv": "camtool.cli.equiv",
    "presets": "camtool.cli.presets",
    "completion": "camtool.cli.completion",
}


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

    def resolve_command(self, ctx: click.Context, args: list[str]) -> Any:
        name = args[0] if args else ""
        if name and not name.startswith("-") and self.get_command(ctx, name) is None:
            import difflib  # only on this error path: it costs 12 ms of start-up

            close = difflib.get_close_matches(name, self.list_commands(ctx), n=2)
            hint = f" Did you mean {' or '.join(repr(c) for c in close)}?" if close else ""
            raise click.UsageError(f"No such command {name!r}.{hint}", ctx)
        return super().resolve_command(ctx, args)

    def main(self, args: Any = None, prog_name: str | None = None, **extra: Any) -> Any:  # type: ignore[override]
        """Run the group; expected errors become one line on stderr, never a traceback."""
        extra.pop("standalone_mode", None)
        try:
            code = super().main(args=args, prog_name=prog_name or "camtool", standalone_mode=False, **extra)
            sys.stdout.flush()
        except click.exceptions.Abort:
            click.echo("Aborted!", err=True)
            sys.exit(1)
        except click.ClickException as error:
            click.echo(f"Error: {error.format_message()}", err=True)
            sys.exit(error.exit_code)
        except FileError as error:  # a file found wrong only when a preset is used
            click.echo(f"Error: {error}", err=True)
            sys.exit(1)
        except BrokenPipeError:
            _quiet_broken_pipe()
            sys.exit(0)
        sys.exit(code if isinstance(code, int) else 0)


def _quiet_broken_pipe() -> None:
    # The reader (head -1) has gone: send the rest of our output nowhere so the
    # interpreter's final flush does not raise again.
    devnull = os.open(os.devnull, os.O_WRONLY)
    os.dup2(devnull, sys.stdout.fileno())


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


def main() -> None:
    """Console-script entry point."""
    try:
        cli.main()
    except BrokenPipeError:
        _quiet_broken_pipe()
        sys.exit(0)
