"""The lensfun import reads its XML through the guarded reader: a FIFO named *.xml is refused at once, not waited on."""

from __future__ import annotations

import os
from pathlib import Path

from cli_helpers import run, time_bound  # noqa: F401

from camtool.presets.lensfun import import_lensfun

FIXTURES = Path(__file__).parent / "data" / "lensfun"


def test_a_fifo_named_xml_is_a_bad_file_not_a_hang(tmp_path: Path) -> None:
    source = tmp_path / "lensfun"
    source.mkdir()
    for name in ("fixture-slr.xml", "fixture-compact.xml"):
        (source / name).write_bytes((FIXTURES / name).read_bytes())
    os.mkfifo(source / "zz-mil-nikon.xml")
    result = import_lensfun(dirs=[source], out=tmp_path / "out.yaml")
    assert result.files == 2
    assert [(Path(path).name, "FIFO" in why) for path, why in result.bad_files] == [("zz-mil-nikon.xml", True)]
    shown = run("presets", "import-lensfun", "--dir", os.fspath(source), "--out", os.fspath(tmp_path / "cli.yaml"))
    assert shown.exit_code == 0 and "zz-mil-nikon.xml" in shown.stdout + shown.stderr
