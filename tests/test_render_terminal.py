"""camtool.render.terminal: what a write error, a closed output and an ASCII-only stream come to."""

from __future__ import annotations

import errno
import sys

import pytest

from camtool.render import terminal


@pytest.fixture(autouse=True)
def keep_stdout(monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setattr(sys, "stdout", terminal.ClosedOutput())  # discard_stdout leaves this one alone


def test_a_reader_that_went_away_is_a_normal_end() -> None:
    assert terminal.write_failure(BrokenPipeError(errno.EPIPE, "Broken pipe")) == (0, None)


def test_output_that_cannot_be_written_is_one_line_and_exit_1() -> None:
    assert terminal.write_failure(OSError(errno.ENOSPC, "No space left on device")) == (
        1, "Error: cannot write the output: no space left on device")
    assert terminal.write_failure(OSError(errno.EACCES, "Permission denied", "out.csv")) == (
        1, "Error: out.csv: Permission denied")


def test_a_closed_output_refuses_text_only() -> None:
    closed = terminal.ClosedOutput()
    assert closed.write("") == 0
    with pytest.raises(OSError) as error:
        closed.write("x")
    assert error.value.errno == errno.EBADF


def test_ascii_stand_ins_are_ascii() -> None:
    assert all(key.encode("utf-8") != key.encode("ascii", "replace") for key in terminal.ASCII)
    assert all(value.isascii() for value in terminal.ASCII.values())
    text = "f/8 · 3 m → ∞"
    encoded = text.encode("ascii", errors="strict" if text.isascii() else "backslashreplace")
    assert b"\\u" in encoded  # the text needs the stand-ins
    import codecs

    codecs.register_error("camtool-ascii-test", terminal._ascii_fallback)
    assert text.encode("ascii", errors="camtool-ascii-test") == b"f/8 - 3 m -> inf"
