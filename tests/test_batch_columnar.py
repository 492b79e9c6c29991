"""--batch a column at a time: pyarrow's text against Python's, block reading against the row reader.

The column path must give the bytes the row path gives: each float as Python's ``repr`` writes it
(checked against ``repr`` itself over random doubles of every magnitude), the rows and problems of
:func:`camtool.core.records.records` (checked on generated files, blocks cut anywhere), and the same
output with pyarrow as without it.
"""

from __future__ import annotations

import io
import math
import random
import struct
from pathlib import Path

import pytest
from cli_helpers import time_bound  # noqa: F401 - an autouse fixture
from click.testing import CliRunner
from hypothesis import given, settings
from hypothesis import strategies as st

from camtool.cli import cli
from camtool.core import records as rec
from camtool.render import columnar

pytest.importorskip("pyarrow")
np = pytest.importorskip("numpy")


def _doubles(count: int, seed: int) -> list[float]:
    """Finite doubles: random bit patterns (every exponent), log-uniform 1e-6..1e12, whole numbers, the edges."""
    rng = random.Random(seed)
    found: list[float] = []
    while len(found) < count // 3:
        value = struct.unpack("<d", rng.getrandbits(64).to_bytes(8, "little"))[0]
        if math.isfinite(value):
            found.append(value)
    found += [rng.choice((1, -1)) * 10 ** rng.uniform(-6, 12) for _ in range(count // 3)]
    found += [float(rng.randint(-10**12, 10**12)) for _ in range(count // 6)]
    found += [round(rng.uniform(0, 1e5), rng.randint(0, 6)) for _ in range(count // 6)]
    for edge in (1e-4, 1e10, 1e16, 0.1, 5e-324, 1.7976931348623157e308, 2.0**53, 123456789.0):
        found += [v for v in (edge, -edge, math.nextafter(edge, 0.0), math.nextafter(edge, math.inf)) if math.isfinite(v)]
    return [*found, 0.0, -0.0]


@pytest.mark.parametrize("style", ["csv", "json"])
def test_pyarrow_writes_every_float_as_python_repr(style: str) -> None:
    values = _doubles(120_000, seed=7)
    array = np.array([*values, math.inf, -math.inf])
    made = columnar._arrow_texts(array, len(array), style, None, None).to_pylist()
    infinity = "" if style == "csv" else "null"
    assert made == [repr(v) for v in values] + [infinity, infinity]


def test_pyarrow_and_python_texts_agree_on_holes_skips_and_names() -> None:
    import pyarrow as pa

    count = 6
    skipped = np.array([False, True, False, False, True, False])
    columns = {
        "x": np.array([1.5, math.nan, math.inf, 2.0, 3.0, 1e-7]),
        "m": columnar.Masked(np.array([2.0, 0.5, 4.0, 1.0, 8.0, 3.25]), np.array([True, True, False, True, True, False])),
        "name": np.array(["thin", "approx", 'a "quoted", name', "thin", "é", "thin"]),
        "one": 35.0,
        "text": "sensor",
        "none": None,
        "mixed": np.array([1.0, None, "a,b", 2.5, None, "x"], dtype=object),
    }
    for style in ("csv", "json"):
        missing = pa.scalar(columnar.MISSING[style])
        for key, values in columns.items():
            made = columnar._arrow_texts(values, count, style, skipped, missing)
            made = made.to_pylist() if hasattr(made, "to_pylist") else [made.as_py() if hasattr(made, "as_py")
                                                                         else made] * count
            assert made == columnar.texts(values, count, style, np.flatnonzero(skipped).tolist()), (style, key)


def _rows_by_chunks(text: str, size: int, stop: bool = False) -> list[rec.Record]:
    found: list[rec.Record] = []
    for chunk in rec.chunks(io.StringIO(text), "scenes.csv", size, stop):
        if chunk.header is not None and not found:
            found.append((0, chunk.header, None))
        if chunk.columns is not None:
            found += [(n, list(cells), None) for n, cells in zip(chunk.numbers, zip(*chunk.columns))]
        else:
            assert chunk.rows is not None and chunk.problems is not None
            found += list(zip(chunk.numbers, chunk.rows, chunk.problems))
    return found


CELL = st.sampled_from(["50", "8", "3m", "", " ", "f/2.8", '"a,b"', '"x""y"', '"line\nbreak"', "é", "x" * 40])
LINE = st.lists(CELL, min_size=1, max_size=4).map(",".join)
ENDING = st.sampled_from(["\n", "\n", "\n", "\r\n", "\n\n"])


@settings(max_examples=300, deadline=None)
@given(header=st.sampled_from(["f,N,s", "f", "a,b,c,d", '"f",N']), lines=st.lists(st.tuples(LINE, ENDING), max_size=30),
       block=st.integers(1, 64), size=st.integers(1, 7), last=st.booleans())
def test_chunks_read_the_rows_and_problems_records_reads(header: str, lines: list[tuple[str, str]], block: int,
                                                         size: int, last: bool) -> None:
    text = header + "\n" + "".join(line + ending for line, ending in lines)
    if not last and text.endswith("\n"):
        text = text[:-1]  # no line end after the last row
    expected = list(rec.records(io.StringIO(text), "scenes.csv"))
    if len(expected) == 1:
        expected = []  # a header and no rows: no chunk (and nothing to compute)
    with pytest.MonkeyPatch.context() as patch:
        patch.setattr(rec, "BLOCK", block)
        assert _rows_by_chunks(text, size) == expected
        stopped = _rows_by_chunks(text, size, stop=True)
    bad = [index for index, (_, _, problem) in enumerate(expected) if problem is not None]
    assert stopped == (expected[:bad[0] + 1] if bad else expected)


def test_plain_csv_is_read_a_column_at_a_time_in_chunks_of_at_most_size() -> None:
    text = "f,N,s\n" + "".join(f"{50 + i},8,{i}m\n" for i in range(25))
    found = list(rec.chunks(io.StringIO(text), "scenes.csv", 10))
    assert [len(c.numbers) for c in found] == [10, 10, 5]
    assert all(c.columns is not None and c.rows is None for c in found)
    assert found[2].columns is not None and list(found[2].columns[0]) == ["70", "71", "72", "73", "74"]
    assert list(found[2].numbers) == [21, 22, 23, 24, 25]


def _batch(text: str, *args: str) -> tuple[int, str, str]:
    result = CliRunner().invoke(cli, ["dof", *args, "--batch", "-"], input=text,
                                env={"COLUMNS": None, "CAMTOOL_FORMAT": None})
    return result.exit_code, result.stdout, result.stderr


SCENES = ("file,focal-length,f-number,distance,sensor\n"
          + "".join(f"r{i},{(24, 35, 50, 85)[i % 4]},{(1.4, 2.8, 8, 16)[i % 3]},{1 + i * 0.37:.2f}m,"
                    f"{'36x24' if i % 5 else 'aps-c'}\n" for i in range(300))
          + 'q,50,x,3m,36x24\n"a, ""quoted"" name",50,8,0.01m,36x24\nz,24,8,inf,36x24\n')


@pytest.mark.parametrize("output", [["--format", "csv"], ["--format", "json"], ["--field", "near_mm", "--field", "file"]])
@pytest.mark.parametrize("on_error", ["skip", "stop"])
def test_batch_output_is_the_same_with_pyarrow_and_without(output: list[str], on_error: str,
                                                           monkeypatch: pytest.MonkeyPatch) -> None:
    with_arrow = _batch(SCENES, *output, "--on-error", on_error)
    monkeypatch.setattr(columnar, "arrow", lambda: None)
    assert _batch(SCENES, *output, "--on-error", on_error) == with_arrow
    monkeypatch.setattr("camtool.render.columnar.ColumnRows.materialised", property(lambda self: True))
    assert _batch(SCENES, *output, "--on-error", on_error) == with_arrow
    assert with_arrow[0] == (1 if on_error == "skip" else 2)


def test_a_block_cut_anywhere_gives_the_same_output(monkeypatch: pytest.MonkeyPatch, tmp_path: Path) -> None:
    whole = _batch(SCENES, "--format", "csv", "--on-error", "skip")
    for block in (1, 17, 4096):
        monkeypatch.setattr(rec, "BLOCK", block)
        assert _batch(SCENES, "--format", "csv", "--on-error", "skip") == whole


@given(st.lists(st.one_of(st.sampled_from(["thin", "approx", "thick+diffraction", 'a "quoted", name', "é\n"]),
                          st.none(), st.floats(allow_nan=False)), max_size=30))
def test_a_column_of_names_is_written_as_each_name_alone(values: list) -> None:
    """A column of names (a batch's per-row ``model``) is written by looking each distinct name up once: the
    same cells as writing every value on its own, in both styles, with holes and other values mixed in."""
    for style in ("csv", "json"):
        expected = [columnar.MISSING[style] if v is None else columnar._string(v, style) if isinstance(v, str)
                    else columnar._other(v, style) for v in values]
        assert columnar.texts(values, len(values), style) == expected
