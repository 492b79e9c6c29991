"""The shipped lens_db and man pages reach an installed wheel; the source tree finds its own lens_db."""

from __future__ import annotations

import os
import subprocess
import sys
import zipfile
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parent.parent


@pytest.fixture(scope="module")
def wheel(tmp_path_factory: pytest.TempPathFactory) -> Path:
    pytest.importorskip("hatchling")
    out = tmp_path_factory.mktemp("wheel")
    subprocess.run([sys.executable, "-m", "pip", "wheel", "--no-deps", "--no-build-isolation", "-q", "-w", str(out),
                    str(ROOT)], check=True, capture_output=True)
    (built,) = out.glob("camtool-*.whl")
    return built


def test_wheel_holds_lens_db_and_man_pages(wheel: Path) -> None:
    names = zipfile.ZipFile(wheel).namelist()
    shipped = sorted(p.name for p in (ROOT / "lens_db").glob("*.yaml"))
    assert shipped and all(f"camtool/lens_db/{name}" in names for name in shipped)
    man = sorted(p.name for p in (ROOT / "man" / "man1").glob("*.1"))
    assert any(n.endswith("/data/share/man/man1/camtool.1") for n in names)
    assert all(any(n.endswith(f"/share/man/man1/{page}") for n in names) for page in man)


def test_installed_wheel_finds_its_lens_db(wheel: Path, tmp_path: Path) -> None:
    target = tmp_path / "site"
    subprocess.run([sys.executable, "-m", "pip", "install", "--no-deps", "-q", "--target", str(target), str(wheel)],
                   check=True, capture_output=True)
    code = ("import camtool, camtool.presets.paths as p; print(camtool.__file__); print(p.shipped_dir()); "
            "from camtool.presets import load_db; print(load_db().sensor('full-frame').width_mm)")
    env = {**os.environ, "PYTHONPATH": str(target)}
    result = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, env=env, cwd=tmp_path,
                            check=True)
    package, lens_db, width = result.stdout.split("\n")[:3]
    assert package.startswith(str(target))
    assert lens_db == str(target / "camtool" / "lens_db")
    assert float(width) == 36.0


def test_source_tree_finds_repository_lens_db() -> None:
    import camtool
    from camtool.presets.paths import shipped_dir

    if Path(camtool.__file__).resolve().parent.parent == ROOT:  # editable install or run from the checkout
        assert Path(shipped_dir()).resolve() == ROOT / "lens_db"
