"""``python -m camtool`` and the ``camtool`` command: :func:`main`."""

from __future__ import annotations

import gc


def main() -> None:
    """The command line, with the cyclic garbage collector paused from its first import.

    Starting camtool imports click and camtool's modules: objects that live as
    long as the process, which the collector would walk about thirty times
    over (about 4 ms of a command's start-up) for no garbage.
    :func:`camtool.cli.main` keeps it paused until the command's work begins,
    then freezes what exists and turns it back on (docs/design.md §7).
    """
    collecting = gc.isenabled()
    gc.disable()
    from camtool.cli import main as run

    run(collecting)


if __name__ == "__main__":
    main()
