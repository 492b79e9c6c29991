"""Option grids stream in chunks: the same bytes in one piece or in many, in nested-loop order, any size.

The chunk size is made small here (monkeypatched) so that a grid of a few
dozen combinations goes through the same slicing as a million-row one, and
every grid is vectorised (a short grid is otherwise computed a combination
at a time: ``tests/test_scalar_grid.py``).
"""

from __future__ import annotations

import itertools
import json
import random

import pytest
from cli_helpers import run

from camtool.cli.command import MAX_TABLE_ROWS
from camtool.plans import grid
from camtool.plans.grid import Grid, combine, combine_slice

GRIDS = [
    ["dof", "-f", "24,50,85", "-N", "1.4,2.8,8,16", "-s", "0.5m,2m,10m,inf", "--coc", "0.03,0.02"],
    ["dof", "-f", "35,50", "-N", "2,8,11", "-s", "0.3,1,3,inf", "--model", "thin", "--distance-from", "lens"],
    ["dof", "-f", "50,85", "-N", "2.8,8", "-s", "1,3,30", "--diffraction"],
    ["dof", "--lens", "dgauss100-lens", "-N", "2,4,8", "-s", "0.8m,1.5m,10m", "--model", "raytrace"],
    ["hyperfocal", "-f", "14,24,35,50,85", "-N", "2,2.8,4,5.6,8,11,16", "--sensor", "aps-c"],
    ["fov", "-f", "14,24,35,50,85,135,200", "-s", "1m,2m,10m", "--sensor", "aps-c"],
    ["focus", "-f", "50,100", "-s", "0.5m,1m,3m", "-N", "2.8,8,16"],
    ["focus", "-f", "24,35,50", "--near", "1m,2m,3m", "--far", "10m,20m,inf"],
    ["equiv", "-f", "12,25,50", "-N", "1.4,2,2.8,4", "--iso", "100,200,400,800", "--sensor", "m43"],
    ["exposure", "-N", "2.8,4,5.6,8,11", "-t", "1/60,1/125,1/250", "--iso", "100,400", "--nd", "ND1000"],
    ["exposure", "--ev100", "10,12,14,15", "-N", "4,8,16", "--iso", "100,200,400"],
    ["flash", "--gn", "20,40,60", "-s", "2,5,9", "--iso", "100,400,800"],
    ["stars", "-f", "14,20,24,35", "-N", "1.4,2.8", "--pixel-pitch", "3.9um,4.3um,6um", "--declination", "30"],
    ["compose", "--subject-size", "1.8m", "--fill", "0.8", "-N", "1.4,2.8,5.6", "--background", "20m",
     "-f", "24,35,50,85,135,200"],
]
OUTPUTS = [["--format", "json"], ["--format", "csv"]]


@pytest.fixture(autouse=True)
def vectorised(monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setattr(grid, "SCALAR_ROWS", 1)


def _fields(args: list[str]) -> list[str]:
    """Every output key of the command as --field options (each column of the output, tab-separated)."""
    rows = json.loads(run(*args, "--format", "json").stdout)
    return [option for key in rows[0] if key != "time_per_evaluation_s" for option in ("--field", key)]


@pytest.mark.parametrize("chunk", [2, 7, 23])
@pytest.mark.parametrize("args", GRIDS, ids=lambda a: " ".join(a[:3]))
def test_a_grid_in_small_chunks_gives_the_same_bytes(args: list[str], chunk: int,
                                                     monkeypatch: pytest.MonkeyPatch) -> None:
    outputs = [*OUTPUTS, _fields(args)]
    whole = [run(*args, *output) for output in outputs]
    for result in whole:
        assert result.exit_code == 0, result.output
    monkeypatch.setattr(grid, "CHUNK", chunk)
    for output, expected in zip(outputs, whole):
        result = run(*args, *output)
        assert result.exit_code == 0, result.output
        assert result.stdout == expected.stdout
        assert result.stderr == expected.stderr


def test_the_chunks_are_really_small(monkeypatch: pytest.MonkeyPatch) -> None:
    # the streamed path is the one taken: each chunk is one call of the command with that many combinations
    sizes: list[int] = []
    original = combine_slice

    def spy(lists, start, stop):  # type: ignore[no-untyped-def]
        sizes.append(stop - start)
        return original(lists, start, stop)

    monkeypatch.setattr(grid, "CHUNK", 7)
    monkeypatch.setattr(grid, "combine_slice", spy)
    assert run(*GRIDS[0], "--format", "csv").exit_code == 0
    # 3 × 4 × 4 × 2 = 96 = 13 × 7 + 5
    assert sizes == [7] * 13 + [5]


def test_a_lone_last_combination_joins_the_chunk_before_it(monkeypatch: pytest.MonkeyPatch) -> None:
    # 3 × 3 = 9 combinations in chunks of 4: 4 + 5, never a chunk of one scene (which a command may treat as single)
    sizes: list[int] = []
    original = combine_slice

    def spy(lists, start, stop):  # type: ignore[no-untyped-def]
        sizes.append(stop - start)
        return original(lists, start, stop)

    monkeypatch.setattr(grid, "CHUNK", 4)
    monkeypatch.setattr(grid, "combine_slice", spy)
    result = run("hyperfocal", "-f", "24,35,50", "-N", "4,8,16", "--format", "csv")
    assert result.exit_code == 0 and len(result.stdout.splitlines()) == 1 + 9
    assert sizes == [4, 5]


def test_rows_come_in_nested_loop_order(monkeypatch: pytest.MonkeyPatch) -> None:
    focal, apertures, distances = [24.0, 35.0, 50.0], [1.4, 2.8, 5.6, 11.0], [500.0, 2000.0, 10000.0]
    monkeypatch.setattr(grid, "CHUNK", 5)
    result = run("dof", "-f", "24,35,50", "-N", "1.4,2.8,5.6,11", "-s", "0.5,2,10", "--format", "json")
    rows = json.loads(result.stdout)
    got = [(r["focal_length_mm"], r["f_number"], r["distance_mm"]) for r in rows]
    assert got == list(itertools.product(focal, apertures, distances))  # the first list varies slowest


def test_a_slice_of_the_combinations_is_that_slice_of_the_product() -> None:
    rng = random.Random(7)
    for _ in range(200):
        lists = [[rng.uniform(1, 100) for _ in range(rng.randint(1, 5))] for _ in range(rng.randint(1, 4))]
        product = list(itertools.product(*lists))
        if len(product) < 2:
            continue
        start = rng.randrange(len(product))
        stop = rng.randint(start + 1, len(product))
        count, columns = combine_slice(lists, start, stop)
        assert count == stop - start
        assert list(zip(*(c.tolist() for c in columns))) == product[start:stop]
        whole_count, whole = combine(*lists)
        assert whole_count == len(product)
        assert [c[start:stop].tolist() for c in whole] == [c.tolist() for c in columns]


def test_the_grid_walks_every_combination_once() -> None:
    for count in range(2, 60):
        for chunk in (1, 2, 3, 5, 8, 13):  # 1 works as 2
            walk = Grid(chunk=chunk)
            walk.count = count
            covered = []
            while True:
                covered.extend(range(walk.start, walk.stop))
                assert walk.stop - walk.start >= 2  # never a chunk of one scene
                if walk.done:
                    break
                walk.advance()
            assert covered == list(range(count))


def test_a_table_is_drawn_whole_and_unchanged(monkeypatch: pytest.MonkeyPatch) -> None:
    args = GRIDS[0]
    expected = run(*args)
    monkeypatch.setattr(grid, "CHUNK", 3)
    result = run(*args)
    assert result.exit_code == 0 and result.stdout == expected.stdout != ""


def test_only_a_table_has_a_limit() -> None:
    many = ",".join(str(1 + i / 100) for i in range(400))
    args = ["hyperfocal", "-f", "24", "-N", many, "--coc", ",".join(f"{0.01 + i / 10000:.4f}" for i in range(300))]
    result = run(*args)
    assert result.exit_code == 2 and result.stdout == ""
    assert result.stderr == (f"Error: the list options ask for 400 × 300 = 120,000 combinations; a table holds at "
                             f"most {MAX_TABLE_ROWS:,} rows (use --format csv or --format json, which stream any "
                             "number)\n")
    streamed = run(*args, "--field", "hyperfocal_mm")
    assert streamed.exit_code == 0 and len(streamed.stdout.splitlines()) == 120_000


def test_an_error_in_a_later_chunk_ends_the_run_after_the_rows_before_it(monkeypatch: pytest.MonkeyPatch) -> None:
    # 0.1 m from the sensor is closer than a 50 mm lens focuses (4f = 200 mm): with chunks of two rows the
    # first chunk, (f/2.8, 5 m) and (f/2.8, 3 m), is written before the second one fails
    args = ["dof", "-f", "50", "-N", "2.8,4", "-s", "5,3,0.1", "--coc", "0.03", "--format", "json"]
    whole = run(*args)
    assert whole.exit_code == 2 and whole.stdout == "" and "closest focus" in whole.stderr
    monkeypatch.setattr(grid, "CHUNK", 2)
    result = run(*args)
    assert result.exit_code == 2 and result.stderr == whole.stderr
    rows = json.loads(result.stdout)  # still a complete JSON array
    assert [(r["f_number"], r["distance_mm"]) for r in rows] == [(2.8, 5000.0), (2.8, 3000.0)]


def test_a_grid_beyond_64_bit_row_numbers_is_a_usage_error() -> None:
    # seven lists of 520 values: 520⁷ ≈ 1.03e19 > 2⁶³ − 1 ≈ 9.22e18 combinations
    def values(low: float) -> str:
        return ",".join(str(low + i / 1000) for i in range(520))

    result = run("exposure", "-N", values(2), "-t", values(1), "--iso", values(100), "--ev100", values(5),
                 "--ev", values(5), "--luminance", values(10), "--illuminance", values(100), "--format", "csv")
    assert result.exit_code == 2 and result.stdout == ""
    assert result.stderr == ("Error: the list options ask for 520 × 520 × 520 × 520 × 520 × 520 × 520 = "
                             f"{520**7:,} combinations; the most is {2**63 - 1:,}\n")
