"""Every example in the README, in every --help text and in every man page runs, and succeeds.

An example that shows an error is marked so in its text: in the README a
``console`` block whose output starts with ``Error:`` (the error must then be
the one shown), in a help text a trailing ``# error`` comment. Examples run
with bash in a scratch directory that holds the files they name
(``scenes.csv``, ``my-lenses.yaml``, ``dgauss100.yaml``) and with every XDG
directory pointed into it; the ``camtool`` on the PATH is this checkout's
(``python -m camtool``).
"""

from __future__ import annotations

import os
import re
import shlex
import shutil
import subprocess
import sys
from pathlib import Path

import click
import pytest

from camtool.cli import cli

REPO = Path(__file__).resolve().parent.parent
README = REPO / "README.md"
MAN_DIR = REPO / "man" / "man1"
SETUP = ("python3 -m venv", "pip install")


def readme_examples() -> list[tuple[str, str | None]]:
    """(shell line, expected error line or None) from the README's sh and console blocks."""
    text = README.read_text(encoding="utf-8")
    out: list[tuple[str, str | None]] = []
    for lang, body in re.findall(r"```(sh|console)\n(.*?)```", text, flags=re.S):
        lines = [line.strip() for line in body.splitlines()]
        if lang == "sh":
            for line in lines:
                if "camtool" not in line or line.startswith("#"):
                    continue
                if any(s in line for s in SETUP):  # installation: run only the camtool command it ends with
                    line = line.rsplit("&&", 1)[-1].strip()
                    if "camtool" not in line or "make check" in line:
                        continue
                out.append((line, None))
        else:
            for i, line in enumerate(lines):
                if line.startswith("$ camtool"):
                    following = lines[i + 1] if i + 1 < len(lines) else ""
                    out.append((line[2:], following if following.startswith("Error:") else None))
    return out


def help_examples() -> list[tuple[str, str]]:
    """(command, example line) from every command's --help text, as click prints it."""
    out = []

    def visit(command: click.Command, path: list[str], parent: click.Context | None) -> None:
        ctx = click.Context(command, info_name=path[-1], parent=parent, help_option_names=["-h", "--help"])
        text = command.get_help(ctx)
        _, _, examples = text.partition("Examples:")
        for line in examples.splitlines():
            line = line.strip()
            if not line:
                if out and out[-1][0] == " ".join(path):
                    break
                continue
            if "camtool" in line and not line.startswith(("Options:", "-")):
                out.append((" ".join(path), line))
            elif line.endswith(":"):
                break
        if isinstance(command, click.Group):
            for name in command.list_commands(ctx):
                sub = command.get_command(ctx, name)
                if sub is not None:
                    visit(sub, [*path, name], ctx)

    visit(cli, ["camtool"], None)
    return out


def man_examples() -> list[tuple[str, str]]:
    """(page, example line) from the EXAMPLES section of every committed man page."""
    out = []
    for page in sorted(MAN_DIR.glob("*.1")):
        text = page.read_text(encoding="utf-8")
        match = re.search(r"^\.SH EXAMPLES\n\.nf\n(.*?)^\.fi$", text, flags=re.S | re.M)
        if not match:
            continue
        for line in match.group(1).splitlines():
            plain = line.replace("\\-", "-").replace("\\e", "\\").replace("\\&", "")
            plain = re.sub(r"\\\[u([0-9A-F]{4})\]", lambda m: chr(int(m.group(1), 16)), plain)
            out.append((page.name, plain))
    return out


@pytest.fixture(scope="module")
def scratch(tmp_path_factory: pytest.TempPathFactory) -> tuple[Path, dict[str, str]]:
    root = tmp_path_factory.mktemp("examples")
    home = root / "home"
    bin_dir = root / "bin"
    for d in (home / ".config" / "camtool", home / ".config" / "fish" / "completions", bin_dir,
              root / "xdg-data", root / "xdg-cache"):
        d.mkdir(parents=True, exist_ok=True)
    launcher = bin_dir / "camtool"
    launcher.write_text(f'#!/bin/sh\nexec "{sys.executable}" -m camtool "$@"\n')
    launcher.chmod(0o755)
    (root / "scenes.csv").write_text("focal-length,f-number,distance\n50,8,3m\n35,f/2.8,10ft\n")
    lenses = "lenses:\n  - id: my-lens\n    focal_length_mm: 50\n    f_number_min: 1.8\n    source: example\n"
    (root / "my-lenses.yaml").write_text(lenses)
    (home / ".config" / "camtool" / "lenses.yaml").write_text(lenses)
    shutil.copy(REPO / "lens_db" / "prescriptions" / "dgauss100.yaml", root / "dgauss100.yaml")
    # photos: the README names them from the repository root, the help of `exif` from a folder of photos
    shutil.copytree(REPO / "tests" / "data" / "exif", root / "tests" / "data" / "exif")
    shutil.copytree(REPO / "tests" / "data" / "depth", root / "tests" / "data" / "depth")
    shutil.copy(REPO / "tests" / "data" / "shot.csv", root / "tests" / "data" / "shot.csv")
    (root / "docs" / "charts").mkdir(parents=True)  # where the README's chart examples write
    photos = root / "photos"
    photos.mkdir()
    for name in ("canon_bracket.jpg", "canon_infinity.jpg", "nikon.jpg", "olympus.jpg", "fujifilm_subject.jpg"):
        shutil.copy(REPO / "tests" / "data" / "exif" / name, photos / name)
    # a lensfun database for `presets import-lensfun` (found in $XDG_DATA_HOME/lensfun, and named with --dir),
    # from the test data (copied there with its provenance)
    for lensfun in (root / "xdg-data" / "lensfun" / "version_1", root / "lensfun-db"):
        lensfun.mkdir(parents=True)
        for xml in (REPO / "tests" / "data" / "lensfun").glob("fixture-[cs]*.xml"):
            shutil.copy(xml, lensfun / xml.name)
    env = {
        "PATH": f"{bin_dir}{os.pathsep}{os.environ.get('PATH', '')}", "HOME": str(home),
        "XDG_CONFIG_HOME": str(home / ".config"), "XDG_DATA_HOME": str(root / "xdg-data"),
        "XDG_CACHE_HOME": str(root / "xdg-cache"), "XDG_CONFIG_DIRS": str(root / "etc-xdg"),
        "LANG": "C.UTF-8", "PYTHONPATH": str(REPO),
        "OPENBLAS_NUM_THREADS": "1",
    }
    return root, env


def run_line(line: str, scratch: tuple[Path, dict[str, str]]) -> subprocess.CompletedProcess[str]:
    root, env = scratch
    if line.startswith("camtool exif") and "tests/data" not in line:
        root = root / "photos"
    other_shell = re.match(r'eval "\$\((camtool completion (?:zsh|fish))\)"', line)
    if other_shell:  # a script for another shell: bash can print it but not load it
        line = other_shell.group(1)
    command = line.split("  #", 1)[0].split(" # ", 1)[0].strip()
    if not re.search(r"[|<>$();&`'\"\\*?~]", command) and command.startswith("camtool "):
        # a plain command: run in-process (a subprocess per example costs half a second of start-up)
        from click.testing import CliRunner

        cwd = os.getcwd()
        os.chdir(root)
        try:
            result = CliRunner().invoke(cli, shlex.split(command)[1:], env=env, catch_exceptions=True)
        finally:
            os.chdir(cwd)
        if result.exception is not None and not isinstance(result.exception, SystemExit):
            raise result.exception
        return subprocess.CompletedProcess(command, result.exit_code, result.stdout, result.stderr)
    return subprocess.run(["bash", "-c", f"set -o pipefail; {line}"], capture_output=True, text=True, cwd=root,
                          env=env, timeout=120)


def is_error_example(line: str) -> bool:
    return bool(re.search(r"#\s*(error\b|exit [12]\b)", line, flags=re.I))


README_EXAMPLES = readme_examples()
HELP_EXAMPLES = help_examples()
MAN_EXAMPLES = man_examples()


def test_examples_are_found() -> None:
    assert len(README_EXAMPLES) >= 25 and len(HELP_EXAMPLES) >= 20 and len(MAN_EXAMPLES) >= 20
    commands = {command for command, _ in HELP_EXAMPLES}
    assert {"camtool dof", "camtool fov", "camtool focus", "camtool hyperfocal", "camtool compose",
            "camtool exposure", "camtool presets"} <= commands


@pytest.mark.parametrize(("line", "error"), README_EXAMPLES, ids=[line[:60] for line, _ in README_EXAMPLES])
def test_readme_example(line: str, error: str | None, scratch: tuple[Path, dict[str, str]]) -> None:
    done = run_line(line, scratch)
    if error is None and is_error_example(line):
        assert done.returncode in (1, 2) and "Traceback" not in done.stderr
    elif error is None:
        assert done.returncode == 0, done.stderr
        assert "Traceback" not in done.stderr
    else:
        assert done.returncode in (1, 2) and done.stderr.strip() == error


@pytest.mark.parametrize(("command", "line"), HELP_EXAMPLES, ids=[line[:60] for _, line in HELP_EXAMPLES])
def test_help_example(command: str, line: str, scratch: tuple[Path, dict[str, str]]) -> None:
    done = run_line(line, scratch)
    if is_error_example(line):
        assert done.returncode in (1, 2) and done.stderr.count("\n") == 1, done.stderr
    else:
        assert done.returncode == 0, f"{line}\n{done.stderr}"


@pytest.mark.parametrize(("page", "line"), MAN_EXAMPLES, ids=[f"{p}:{line[:50]}" for p, line in MAN_EXAMPLES])
def test_man_example(page: str, line: str) -> None:
    # The man pages are generated from the help texts (tests/test_manpages.py keeps them in step), so each
    # of their examples is also a help example of the same command.
    # So an example is run once, as a help example; here it must read back from the roff unchanged.
    assert (page.removesuffix(".1").replace("-", " "), line) in HELP_EXAMPLES, line
