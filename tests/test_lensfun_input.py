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


def test_clashing_spellings_and_unusable_names_are_dropped_not_fatal(tmp_path: Path) -> None:
    # Two bodies share a default model name (lensfun's spelling) under different English names, and a third
    # has a model of punctuation only: the import keeps both bodies, drops the alias the second would share,
    # skips the third, and the file it writes validates.
    from camtool.presets import validate_file

    source = tmp_path / "lensfun"
    source.mkdir()
    (source / "odd.xml").write_text(
        "<lensdatabase>"
        "<camera><maker>Oddco</maker><model>OC-1</model><model lang='en'>Odd One</model>"
        "<mount>Odd</mount><cropfactor>1.5</cropfactor></camera>"
        "<camera><maker>Oddco</maker><model>OC-1</model><model lang='en'>Odd One Mark II</model>"
        "<mount>Odd</mount><cropfactor>1.5</cropfactor></camera>"
        "<camera><maker></maker><model>!!!</model><mount>Odd</mount><cropfactor>2</cropfactor></camera>"
        "</lensdatabase>", encoding="utf-8")
    out = tmp_path / "out.yaml"
    result = import_lensfun(dirs=[source], out=out)
    assert result.cameras == 2 and result.skipped["camera: no usable name"] == 1
    assert validate_file(out) == []
    text = out.read_text(encoding="utf-8")
    assert text.count("Oddco OC-1") == 1 and "oddco-odd-one-mark-ii" in text
