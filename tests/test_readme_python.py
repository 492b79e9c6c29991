"""The README's Python examples run, and the public API is what ``camtool.__all__`` says."""

from __future__ import annotations

import contextlib
import io
import re
import subprocess
import sys
from pathlib import Path

import pytest

import camtool

README = Path(__file__).resolve().parent.parent / "README.md"
BLOCKS = re.findall(r"^```python\n(.*?)^```$", README.read_text(encoding="utf-8"), flags=re.M | re.S)


def test_the_readme_has_a_python_section() -> None:
    assert "\n## Python\n" in README.read_text(encoding="utf-8")
    assert BLOCKS


@pytest.mark.parametrize("code", BLOCKS, ids=[f"block{i}" for i in range(len(BLOCKS))])
def test_readme_python_block_runs_and_prints_what_its_comments_say(code: str) -> None:
    out = io.StringIO()
    with contextlib.redirect_stdout(out):
        exec(compile(code, str(README), "exec"), {"__name__": "readme"})
    printed = out.getvalue().splitlines()
    # the comment after each print(...) is the line it prints
    expected = [line.split("#", 1)[1].strip() for line in code.splitlines() if line.startswith("print(") and "#" in line]
    assert printed == expected


def test_every_public_name_resolves_and_is_documented() -> None:
    for name in camtool.__all__:
        obj = getattr(camtool, name)
        assert obj.__doc__ and obj.__doc__.strip(), name
    assert sorted(camtool.__all__) == sorted(camtool.api.__all__)


def test_import_camtool_loads_no_numpy_and_no_formula_module() -> None:
    code = "import sys, camtool; print('numpy' in sys.modules, 'camtool.api' in sys.modules)"
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True).stdout
    assert out.split() == ["False", "False"]


def test_a_scalar_call_imports_no_numpy() -> None:
    code = ("import sys, camtool; camtool.depth_of_field(50, 8, 0.03, 3000, model='thin'); "
            "print('numpy' in sys.modules)")
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True).stdout
    assert out.strip() == "False"
