"""The committed man pages are exactly what the click definitions generate (pinned date)."""

from __future__ import annotations

import subprocess
from pathlib import Path

from camtool.cli.manpage import pages

MAN_DIR = Path(__file__).resolve().parent.parent / "man" / "man1"


def test_no_drift() -> None:
    generated = pages()
    committed = {p.name: p.read_text(encoding="utf-8") for p in MAN_DIR.glob("*.1")}
    assert sorted(committed) == sorted(generated), "run: python -m camtool.cli.manpage man/man1"
    for name, text in generated.items():
        assert committed[name] == text, f"{name} drifted; run: python -m camtool.cli.manpage man/man1"


def test_every_command_has_a_page_with_examples_and_exit_status() -> None:
    generated = pages()
    from camtool.cli import COMMANDS

    for command in COMMANDS:
        name = f"camtool-{command}.1"
        if name in generated:
            assert ".SH EXIT STATUS" in generated[name] and ".SH ENVIRONMENT" in generated[name]
    assert "camtool\\-dof" in generated["camtool.1"]


def test_pages_render_without_warnings(tmp_path: Path) -> None:
    import shutil

    groff = shutil.which("groff")
    if groff is None:
        return  # rendering is checked where groff exists; the drift test still holds
    for path in MAN_DIR.glob("*.1"):
        result = subprocess.run([groff, "-man", "-Tutf8", "-ww", "-z", str(path)], capture_output=True, text=True)
        assert result.stderr == "", f"{path.name}: {result.stderr}"
