"""``python -m camtool``: the same as the ``camtool`` command."""

from camtool.cli import main

main()
