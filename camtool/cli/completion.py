"""``camtool completion SHELL``: print the shell-completion script for bash, zsh or fish."""

from __future__ import annotations

import click


@click.command("completion")
@click.argument("shell", type=click.Choice(["bash", "zsh", "fish"]), metavar="SHELL")
@click.pass_context
def completion(ctx: click.Context, shell: str) -> None:
    """Print the completion script for SHELL; load it from your shell's start-up file.

    Completes subcommands, options, choices and preset names (--sensor,
    --camera, --lens, --scene). The same script comes from
    _CAMTOOL_COMPLETE=bash_source camtool (zsh_source, fish_source).

    \b
    Examples:
      eval "$(camtool completion bash)"      # in ~/.bashrc
      eval "$(camtool completion zsh)"       # in ~/.zshrc
      camtool completion fish > ~/.config/fish/completions/camtool.fish
    """
    from click.shell_completion import get_completion_class

    root = ctx.find_root().command
    cls = get_completion_class(shell)
    assert cls is not None  # the Choice above admits only shells click knows
    click.echo(cls(root, {}, "camtool", "_CAMTOOL_COMPLETE").source(), nl=False)
