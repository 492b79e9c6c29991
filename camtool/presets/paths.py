"""Where preset files live: the shipped database, the lensfun import and the user's directories.

Search order (docs/design.md §5), later tiers win by id:

1. ``shipped`` -- ``lens_db/`` inside the installed package (``camtool/lens_db``
   in a wheel) or, from a source tree or editable install, the repository's
   ``lens_db/`` next to the package;
2. ``lensfun`` -- ``$XDG_DATA_HOME/camtool/lensfun.yaml`` written by
   ``camtool presets import-lensfun`` (default ``~/.local/share/camtool``);
3. ``system`` -- ``camtool/`` in each of ``$XDG_CONFIG_DIRS`` (default
   ``/etc/xdg``; the first directory listed is the most important);
4. ``user`` -- ``$XDG_CONFIG_HOME/camtool`` (default ``~/.config/camtool``);
5. each ``--presets FILE``, in order.

In a configuration directory every ``*.yaml`` and ``*.yml`` file directly in
it and in its ``presets/`` subdirectory is read, in name order. Entries that
are not regular files (a FIFO, a dangling symbolic link, a loop of symbolic
links) are skipped, so that one stray entry cannot break every lookup; a
configuration directory that is itself a loop counts as empty.
"""

from __future__ import annotations

import os

import camtool
from camtool.core.record import NamedTuple

_SUFFIXES = (".yaml", ".yml")

# Plain strings rather than pathlib: this module is on the start-up path of every
# command that names a preset, and pathlib costs a few milliseconds to import.


class Tier(NamedTuple):
    """One level of the search order: a name for messages and its files in load order."""

    name: str
    files: tuple[str, ...]


def _xdg(variable: str, default: str) -> str:
    """An XDG base directory; relative values are ignored, as the specification says."""
    value = os.environ.get(variable, "")
    return value if value and os.path.isabs(value) else os.path.join(os.path.expanduser("~"), default)


def shipped_dir() -> str:
    """The shipped ``lens_db`` directory.

    In a wheel it is ``camtool/lens_db`` (the location
    ``importlib.resources.files("camtool") / "lens_db"`` names for a package on
    the file system, computed here without importing importlib.resources); from
    a source tree it is the repository's ``lens_db/``.
    """
    found = _shipped.get(camtool.__file__)
    if found is None:
        package = os.path.dirname(os.path.realpath(camtool.__file__))
        found = os.path.join(package, "lens_db")
        for candidate in (found, os.path.join(os.path.dirname(package), "lens_db")):
            if os.path.isdir(candidate):
                found = candidate
                break
        _shipped[camtool.__file__] = found
    return found


_shipped: dict[str, str] = {}
"""The shipped directory found for the package file (found once a process: it is a lookup's most frequent path)."""


def data_dir() -> str:
    """camtool's data directory: ``$XDG_DATA_HOME/camtool`` (default ``~/.local/share/camtool``)."""
    return os.path.join(_xdg("XDG_DATA_HOME", ".local/share"), "camtool")


def lensfun_file() -> str:
    """Where ``import-lensfun`` writes its presets and where :func:`load_db` reads them."""
    return os.path.join(data_dir(), "lensfun.yaml")


def cache_dir() -> str:
    """The cache of parsed preset files: ``$XDG_CACHE_HOME/camtool/presets`` (see :mod:`camtool.core.cache`)."""
    from camtool.core import cache

    return os.path.join(cache.root(), "presets")


def config_home() -> str:
    """The user's configuration directory: ``$XDG_CONFIG_HOME/camtool`` (default ``~/.config/camtool``)."""
    return os.path.join(_xdg("XDG_CONFIG_HOME", ".config"), "camtool")


def config_dirs() -> list[str]:
    """``camtool`` in each of ``$XDG_CONFIG_DIRS``, least important first (the reverse of the variable)."""
    value = os.environ.get("XDG_CONFIG_DIRS", "") or "/etc/xdg"
    dirs = [os.path.join(d, "camtool") for d in value.split(os.pathsep) if d and os.path.isabs(d)]
    return list(reversed(dirs))


def yaml_files(directory: str, recurse_into: tuple[str, ...] = ("presets",)) -> list[str]:
    """The preset files of a configuration directory, in name order (none if it does not exist)."""
    out: list[str] = []
    try:
        entries = sorted(os.scandir(directory), key=lambda e: e.name)
    except OSError:
        return out
    for entry in entries:
        try:
            regular = entry.is_file()
        except OSError:  # a loop of symbolic links: skipped, like a dangling link
            regular = False
        if entry.name.endswith(_SUFFIXES) and regular:
            out.append(entry.path)
    for sub in recurse_into:
        out.extend(yaml_files(os.path.join(directory, sub), ()))
    return out


def shipped_files() -> list[str]:
    """The shipped preset files: ``lens_db/*.yaml`` then ``lens_db/prescriptions/*.yaml``."""
    return yaml_files(shipped_dir(), ("prescriptions",))


def tiers(extra_files: tuple[str, ...] | list[str] = (), *, lensfun: bool = True) -> list[Tier]:
    """The search order as :class:`Tier` objects, least important first."""
    out = [Tier("shipped", tuple(shipped_files()))]
    imported = lensfun_file()
    if lensfun and os.path.isfile(imported):
        out.append(Tier("lensfun", (imported,)))
    for directory in config_dirs():
        files = yaml_files(directory)
        if files:
            out.append(Tier(f"system {directory}", tuple(files)))
    user = yaml_files(config_home())
    if user:
        out.append(Tier("user", tuple(user)))
    for path in extra_files:
        out.append(Tier(f"--presets {os.fspath(path)}", (os.fspath(path),)))
    return out
