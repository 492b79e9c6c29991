"""camtool.core.records: the file layer of --batch (opening, encodings, bounded lines, CSV and JSON-lines rows).

Expected texts are derived from what they describe (the C library's strerror, the json and
codecs modules' own reasons, the csv module's own field limit), not copied from the reader.
"""

from __future__ import annotations

import codecs
import csv
import errno
import io
import json
import os
import subprocess
import sys
import threading
from pathlib import Path

import pytest

from camtool.core import records as rec
from camtool.core.errors import CamtoolError, FileError
from camtool.core.files import FileProblem

HEADER = "focal-length,f-number,distance\n"


def _read(path: Path | str) -> list[rec.Record]:
    stream, name = rec.open_source(str(path))
    with stream:
        return list(rec.records(stream, name))


@pytest.mark.parametrize("encoding", ["utf-8", "utf-8-sig", "utf-16", "utf-16-le+bom", "utf-16-be+bom"])
def test_each_accepted_encoding_reads_the_same_rows(tmp_path: Path, encoding: str) -> None:
    text = HEADER + "50,8,3m\nkafé,2.8,∞\n"
    if encoding == "utf-16-le+bom":
        data = codecs.BOM_UTF16_LE + text.encode("utf-16-le")
    elif encoding == "utf-16-be+bom":
        data = codecs.BOM_UTF16_BE + text.encode("utf-16-be")
    else:
        data = text.encode(encoding)
    path = tmp_path / "scenes.csv"
    path.write_bytes(data)
    assert _read(path) == [(0, ["focal-length", "f-number", "distance"], None), (1, ["50", "8", "3m"], None),
                           (2, ["kafé", "2.8", "∞"], None)]


def test_utf16_without_a_byte_order_mark_is_refused_by_name(tmp_path: Path) -> None:
    path = tmp_path / "scenes.csv"
    path.write_bytes((HEADER + "50,8,3\n").encode("utf-16-le"))
    with pytest.raises(FileProblem) as caught:
        _read(path)
    assert caught.value.path == str(path) and "UTF-16" in caught.value.problem and "\n" not in str(caught.value)


def test_latin1_text_is_refused_with_the_codecs_reason_and_byte(tmp_path: Path) -> None:
    path = tmp_path / "scenes.csv"
    path.write_bytes((HEADER + "50,8,3\n# café\n").encode("latin-1"))
    try:
        "é\n".encode("latin-1").decode("utf-8")
    except UnicodeDecodeError as error:
        reason = error.reason
    with pytest.raises(FileProblem) as caught:
        _read(path)
    assert str(caught.value).startswith(f"{path}: not UTF-8 text ({reason}, byte 0xe9); save it as UTF-8")


def test_opening_refuses_what_is_not_a_file_or_a_pipe(tmp_path: Path) -> None:
    with pytest.raises(FileProblem) as missing:
        rec.open_source(str(tmp_path / "none.csv"))
    assert missing.value.problem == f"cannot read it ({os.strerror(errno.ENOENT)})"
    with pytest.raises(FileProblem) as directory:
        rec.open_source(str(tmp_path))
    assert directory.value.problem == "is a directory, not a file"
    with pytest.raises(FileProblem) as device:
        rec.open_source("/dev/zero")  # it never ends: refused before any read
    assert device.value.path == "/dev/zero" and "device" in device.value.problem
    assert isinstance(device.value, FileError) and isinstance(device.value, CamtoolError)


def test_a_fifo_nobody_writes_to_reads_as_empty_and_one_with_a_writer_as_it_comes(tmp_path: Path) -> None:
    fifo = tmp_path / "scenes"
    os.mkfifo(fifo)
    done: list[list[rec.Record]] = []
    reader = threading.Thread(target=lambda: done.append(_read(fifo)), daemon=True)
    reader.start()
    reader.join(10)
    assert done == [[]], "opening a FIFO with no writer must not wait"

    def write() -> None:
        with open(fifo, "w", encoding="utf-8") as out:
            out.write(HEADER + "50,8,3\n")

    # the writer opens first (it waits for a reader), then the reader finds it
    writer = threading.Thread(target=write, daemon=True)
    writer.start()
    found: list[list[rec.Record]] = []
    while writer.is_alive() and not found:
        rows = _read(fifo)
        if rows:
            found.append(rows)
    writer.join(10)
    if not found:  # the writer finished between two opens: nothing is lost, its rows are in no read
        pytest.skip("the writer ran before a reader opened the FIFO")
    assert found[0][-1] == (1, ["50", "8", "3"], None)


def test_standard_input_is_named_so(monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setattr(sys, "stdin", io.TextIOWrapper(io.BytesIO(b"\xef\xbb\xbf" + HEADER.encode() + b"50,8,3\n")))
    stream, name = rec.open_source("-")
    assert name == "standard input"
    assert list(rec.records(stream, name))[1] == (1, ["50", "8", "3"], None)


def test_csv_rows_carry_their_problems_in_place() -> None:
    text = HEADER + "50,8,3,4\n\n35,4,2\n"
    rows = list(rec.records(io.StringIO(text, newline=""), "x.csv"))
    assert rows[1] == (1, None, "4 cells, more than the 3 header columns")
    assert rows[2] == (2, ["35", "4", "2"], None)  # the blank line is no row


def test_a_cell_longer_than_the_csv_limit_is_a_bad_row_and_the_next_row_is_read() -> None:
    assert csv.field_size_limit() == rec.CELL_LIMIT  # the limit named is the one the csv module applies
    text = HEADER + "50,8," + "3" * (rec.CELL_LIMIT + 10) + "\n35,4,2\n"
    rows = list(rec.records(io.StringIO(text, newline=""), "x.csv"))
    assert rows[1] == (1, None, f"a cell longer than {rec.CELL_LIMIT // 1024} KiB")
    assert rows[2] == (2, ["35", "4", "2"], None)


def test_lines_are_bounded_and_a_stream_without_line_ends_stops(monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setattr(rec, "LINE_LIMIT", 16)
    lines = list(rec.lines(io.StringIO("a" * 40 + "\nshort\n"), "x"))
    assert lines == ["a" * 16 + "\n", "short\n"]  # the rest of the long line is dropped, the next line kept
    monkeypatch.setattr(rec, "DROP_LIMIT", 64)
    with pytest.raises(FileProblem) as caught:
        list(rec.lines(io.StringIO("a" * 1000), "endless"))
    assert caught.value.path == "endless" and caught.value.problem.startswith("a line longer than")


def test_a_bad_header_row_is_a_file_problem() -> None:
    with pytest.raises(FileProblem) as caught:
        list(rec.records(io.StringIO('"a' + "x" * (rec.CELL_LIMIT + 10) + '"\n1\n', newline=""), "x.csv"))
    assert str(caught.value) == f"x.csv: the header row is a cell longer than {rec.CELL_LIMIT // 1024} KiB"


def test_json_lines_are_numbered_without_blank_lines_and_their_problems_use_json_words() -> None:
    text = '{"f": 50}\n\n[1]\n{bad\n{"f": 35}\n'
    try:
        json.loads("{bad")
    except json.JSONDecodeError as error:
        reason = error.msg
    assert list(rec.records(io.StringIO(text), "x.jsonl")) == [
        (1, {"f": 50}, None), (2, None, "expected a JSON object"), (3, None, f"not valid JSON ({reason})"),
        (4, {"f": 35}, None)]


def test_blank_or_empty_input_has_no_rows() -> None:
    assert list(rec.records(io.StringIO(""), "x")) == []
    assert list(rec.records(io.StringIO("\n  \n\n"), "x")) == []


def test_the_record_layer_needs_no_click() -> None:
    code = "import sys, camtool.core.records, camtool.core.files; print('click' in sys.modules)"
    done = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, timeout=60)
    assert done.stdout.strip() == "False", done.stderr
