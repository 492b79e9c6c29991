"""The suite writes nothing outside its temporary directory (conftest.py sets HOME and the XDG variables)."""

from __future__ import annotations

import os
import subprocess
import sys
from pathlib import Path

import conftest

DOF_WITH_PRESCRIPTION = ["dof", "-f", "100", "-N", "8", "-s", "3", "--prescription", "dgauss100", "--model", "auto"]


def test_home_and_every_xdg_directory_are_inside_the_session_directory() -> None:
    for name in conftest.SANDBOX_ENV:
        assert Path(os.environ[name]).is_relative_to(conftest.SANDBOX), name
    assert not conftest.SANDBOX.is_relative_to(conftest.REAL_HOME)  # the temporary directory is not in the real home


def camtool(env: dict[str, str], *args: str) -> subprocess.CompletedProcess[str]:
    env = {k: v for k, v in env.items() if k != "CAMTOOL_NO_CACHE"}  # the caches are what is watched here
    return subprocess.run([sys.executable, "-m", "camtool", *args], env=env, capture_output=True, text=True,
                          timeout=120, check=True)


def test_a_subprocess_writes_its_caches_into_the_session_directory_not_the_real_home() -> None:
    before = {root: conftest.listing(Path(root)) for root in map(str, conftest.WATCHED)}
    camtool(dict(os.environ), *DOF_WITH_PRESCRIPTION)  # inherits the session's variables
    tables = list((Path(os.environ["XDG_CACHE_HOME"]) / "camtool" / "aberrations").glob("*.json"))
    assert tables, "the aberration table was not written where XDG_CACHE_HOME points"
    # with no XDG variable at all, camtool's defaults are below HOME, which is the session's too
    bare = {k: v for k, v in os.environ.items() if not k.startswith("XDG_")}
    camtool(bare, *DOF_WITH_PRESCRIPTION)
    assert list((Path(os.environ["HOME"]) / ".cache" / "camtool" / "aberrations").glob("*.json"))
    assert {root: conftest.listing(Path(root)) for root in map(str, conftest.WATCHED)} == before


def test_listing_sees_a_change() -> None:
    root = conftest.SANDBOX / "listing-probe"
    root.mkdir()
    empty = conftest.listing(root)
    (root / "entry").write_text("x")
    assert conftest.listing(root) != empty and empty == []
