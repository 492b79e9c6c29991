"""Running the CLI in-process for tests."""

from __future__ import annotations

import json
import signal
from collections.abc import Iterator
from typing import Any

import pytest
from click.testing import CliRunner, Result

from camtool.cli import cli


def run(*args: str, env: dict[str, str | None] | None = None) -> Result:
    """Invoke ``camtool ARGS`` with no COLUMNS/NO_COLOR/CAMTOOL_FORMAT from the caller's environment."""
    base: dict[str, str | None] = {"COLUMNS": None, "CAMTOOL_FORMAT": None, "NO_COLOR": None}
    base.update(env or {})
    return CliRunner().invoke(cli, list(args), env=base, catch_exceptions=False)


def run_json(*args: str) -> list[dict[str, Any]]:
    """Invoke with ``--format json``, assert success and return the parsed rows."""
    result = run(*args, "--format", "json")
    assert result.exit_code == 0, result.output
    rows = json.loads(result.stdout)
    assert isinstance(rows, list)
    return rows


def time_limit(seconds: int) -> Iterator[None]:
    """A fixture body: the test ends within ``seconds``, a hang fails instead of stalling the run."""

    def expire(signum: int, frame: object) -> None:
        raise TimeoutError(f"test took longer than {seconds} s")

    previous = signal.signal(signal.SIGALRM, expire)
    signal.alarm(seconds)
    try:
        yield
    finally:
        signal.alarm(0)
        signal.signal(signal.SIGALRM, previous)


@pytest.fixture(autouse=True)
def time_bound() -> Iterator[None]:
    """Every test here ends within 60 s: a hang fails instead of stalling the run."""
    yield from time_limit(60)


def exif_image_maker() -> Any:
    """The module tests/data/exif/make_images.py, which writes the tiny test images (it is a script, not a package)."""
    import importlib.util
    from pathlib import Path

    path = Path(__file__).resolve().parent / "data" / "exif" / "make_images.py"
    spec = importlib.util.spec_from_file_location("make_images", path)
    assert spec is not None and spec.loader is not None
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module
