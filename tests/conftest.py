"""Suite-wide setup: a private home for the whole run, one Hypothesis profile, the `slow` mark.

Everything camtool writes by default (the aberration table and preset caches under
``$XDG_CACHE_HOME/camtool`` or ``~/.cache/camtool``, the lensfun import under ``$XDG_DATA_HOME``, user
presets under ``$XDG_CONFIG_HOME``) and what its dependencies write (matplotlib's font cache) goes into
one temporary directory per test session. The variables are set here, when pytest loads this file and
before any test module imports camtool, so every subprocess a test starts inherits them too; the
directory is removed when the run ends. At the end of the run the real ``~/.cache/camtool``,
``~/.config/camtool`` and ``~/.local/share/camtool`` are compared with their state at the start, and a
difference fails the run.
"""

from __future__ import annotations

import atexit
import inspect
import os
import pwd
import shutil
import sys
import tempfile
from pathlib import Path

import pytest
from hypothesis import settings

sys.path.insert(0, str(Path(__file__).parent))

SANDBOX = Path(tempfile.mkdtemp(prefix="camtool-tests-"))
atexit.register(shutil.rmtree, SANDBOX, ignore_errors=True)

REAL_HOME = Path(pwd.getpwuid(os.getuid()).pw_dir)
WATCHED = [REAL_HOME / ".cache" / "camtool", REAL_HOME / ".config" / "camtool", REAL_HOME / ".local" / "share" / "camtool"]

SANDBOX_ENV = {
    "HOME": SANDBOX / "home",
    "XDG_CACHE_HOME": SANDBOX / "xdg-cache",
    "XDG_CONFIG_HOME": SANDBOX / "xdg-config",
    "XDG_DATA_HOME": SANDBOX / "xdg-data",
    "XDG_CONFIG_DIRS": SANDBOX / "etc-xdg",
    "MPLCONFIGDIR": SANDBOX / "matplotlib",
}
for _name, _path in SANDBOX_ENV.items():
    _path.mkdir(parents=True, exist_ok=True)
    os.environ[_name] = str(_path)


def listing(root: Path) -> list[tuple[str, int, int]]:
    """(relative path, size, mtime in ns) of every entry below ``root``, symbolic links not followed."""
    if not root.is_dir() or root.is_symlink():
        return [(".", -1, root.lstat().st_mtime_ns)] if os.path.lexists(root) else []
    out = []
    for directory, dirs, names in os.walk(root):
        for name in sorted(dirs + names):
            path = Path(directory) / name
            stat = path.lstat()
            out.append((str(path.relative_to(root)), stat.st_size, stat.st_mtime_ns))
    return sorted(out)


BEFORE = {str(root): listing(root) for root in WATCHED}


# The same examples on every run (a property that fails, fails every time, in CI as here), and no
# per-example deadline: the machine is shared, and time is measured in benchmarks/, not in tests.
settings.register_profile("camtool", derandomize=True, deadline=None, print_blob=True, database=None)
settings.load_profile("camtool")


def pytest_sessionfinish(session: pytest.Session, exitstatus: int) -> None:
    changed = [root for root, before in BEFORE.items() if listing(Path(root)) != before]
    if changed:
        print(f"\nthe test run wrote outside its temporary directory: {', '.join(changed)} changed", file=sys.stderr)
        session.exitstatus = pytest.ExitCode.TESTS_FAILED


@pytest.fixture(scope="session")
def shared_presets_home(tmp_path_factory: pytest.TempPathFactory) -> Path:
    """XDG directories with no preset file of their own, shared by the tests that only read the shipped presets.

    Its preset cache is filled by the first such test, so the shipped files are parsed once per session
    rather than once per test.
    """
    return tmp_path_factory.mktemp("shipped-presets")


def presets_home(request: pytest.FixtureRequest, shared: Path, *own_if: str) -> Path:
    """The XDG root for one test: its own ``tmp_path`` when the test asks for any of ``own_if`` by name
    (it writes presets there or looks at the cache), else the shared one."""
    asked = inspect.signature(request.function).parameters if request.function is not None else {}
    if any(name in asked for name in own_if):
        return Path(request.getfixturevalue("tmp_path"))
    return shared


def point_xdg_at(root: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    for name in ("XDG_CONFIG_HOME", "XDG_DATA_HOME", "XDG_CACHE_HOME"):
        monkeypatch.setenv(name, str(root / name.lower()))
    monkeypatch.setenv("XDG_CONFIG_DIRS", str(root / "etc-xdg"))


@pytest.fixture
def no_user_presets(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    """Every XDG directory in the test's own empty folder: the shipped presets alone, and a cache of the test's own."""
    for var, sub in (("XDG_CONFIG_HOME", "config"), ("XDG_DATA_HOME", "data"), ("XDG_CACHE_HOME", "cache")):
        monkeypatch.setenv(var, str(tmp_path / sub))
    monkeypatch.setenv("XDG_CONFIG_DIRS", str(tmp_path / "etc"))
