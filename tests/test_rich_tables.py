"""Tables for people: rich draws them, colour means one thing everywhere, and no width loses an answer.

Snapshots (``tests/data/tables/``) hold representative tables at fixed widths,
with and without colour; ``CAMTOOL_UPDATE_SNAPSHOTS=1`` rewrites them after a
deliberate change (and the diff is then read in review).
"""

from __future__ import annotations

import io
import os
import re
import subprocess
import sys
from pathlib import Path

import pytest
from cli_helpers import run
from test_shell import _in_terminal

from camtool.render import table as table_module
from camtool.render.columns import ANGLE, DISTANCE, FNUMBER, NUMBER, SMALL, TEXT, Column
from camtool.render.table import render_table

SNAPSHOTS = Path(__file__).parent / "data" / "tables"
ESCAPE = re.compile(r"\x1b\[[0-9;]*m")
COLUMNS = [Column("file", "file", TEXT), Column("focal_length_mm", "f", SMALL), Column("f_number", "N", FNUMBER),
           Column("near_mm", "near"), Column("far_mm", "far"), Column("total_mm", "depth", DISTANCE),
           Column("horizontal_deg", "h. angle", ANGLE), Column("magnification", "m", NUMBER),
           Column("model", "model", TEXT), Column("sharp_zone", "sharp zone", TEXT, legend="┃ focus")]


def _rows(count: int) -> list[dict]:
    rows = []
    for i in range(count):
        row = {"file": f"IMG_{i:04d}.jpg", "focal_length_mm": 24.0 + i % 7, "f_number": 2.8 * (1 + i % 3),
               "near_mm": 1000.0 + 13.7 * i, "far_mm": float("inf") if i % 5 == 0 else 2000.0 + i,
               "total_mm": float("inf") if i % 5 == 0 else 1000.0 + i, "horizontal_deg": 40.0 + i / 7,
               "magnification": 0.01 * (i + 1), "model": "thin" if i % 2 else "thick", "sharp_zone": "··━━┃━━··"}
        if i % 11 == 3:
            row.update(near_mm=None, far_mm=None, total_mm=None, reason="nothing sharp: the Airy disc fills the CoC")
        rows.append(row)
    return rows


@pytest.mark.parametrize("colour", [None, "standard", "256", "truecolor"])
@pytest.mark.parametrize("width", [None, 200, 70])
def test_long_tables_are_drawn_with_the_same_bytes_rich_draws(colour, width, monkeypatch) -> None:
    rows = _rows(40)
    by_rich = render_table(rows, COLUMNS, width=width, colour=colour)
    monkeypatch.setattr(table_module, "RICH_ROWS", 10)
    by_lines = render_table(rows, COLUMNS, width=width, colour=colour)
    assert by_lines == by_rich
    assert ("\x1b[" in by_rich.text) == (colour is not None)


WORDS = ["Canon", "RF", "50mm", "f/1.2L", "USM", "(approximate)", "—", "9.84 × 7.38 mm", "an-extremely-long-hyphenated"
         "-identifier-that-must-fold", "x", "", "·", "IMG_0001.jpg", "published", "by", "the", "maker"]
TEXT_COLUMNS = [Column("kind", "kind", TEXT), Column("id", "id", TEXT), Column("summary", "summary", TEXT),
                Column("near_mm", "near"), Column("tier", "from", TEXT)]


def _text_rows(count: int, seed: int) -> list[dict]:
    import random

    draw = random.Random(seed)
    rows = []
    for i in range(count):
        summary = " ".join(draw.choice(WORDS) for _ in range(draw.randint(0, 14)))
        if i % 9 == 4:
            summary = "  " + summary + "   " + draw.choice(WORDS) + "  "  # spaces at the ends and doubled
        rows.append({"kind": draw.choice(["sensor", "lens", "prescription"]), "id": f"preset-{i}-{draw.random():.4f}",
                     "summary": summary, "near_mm": 1000.0 + 37.1 * i, "tier": draw.choice(["shipped", "user"]),
                     "reason": None})
    return rows


@pytest.mark.parametrize("colour", [None, "truecolor"])
@pytest.mark.parametrize("width", [120, 100, 80, 72])
@pytest.mark.parametrize("seed", [1, 2, 3])
def test_long_tables_whose_text_wraps_are_drawn_with_the_same_bytes_rich_draws(colour, width, seed,
                                                                              monkeypatch) -> None:
    rows = _text_rows(70, seed)
    by_rich = render_table(rows, TEXT_COLUMNS, width=width, colour=colour)
    monkeypatch.setattr(table_module, "RICH_ROWS", 10)
    by_lines = render_table(rows, TEXT_COLUMNS, width=width, colour=colour)
    assert by_lines == by_rich
    assert not by_rich.vertical
    assert width >= 120 or len(by_rich.text.splitlines()) > 80  # the summaries took more than a line each


def test_every_cell_is_whole_and_no_line_is_wider_than_the_screen() -> None:
    rows = _rows(12)
    wide = render_table(rows, COLUMNS).text
    for width in (120, 80, 60, 40, 20):
        narrow = render_table(rows, COLUMNS, width=width).text
        assert max(len(line) for line in narrow.splitlines()) <= width or width < 30
        numbers = set(re.findall(r"\d+\.\d+|∞", wide))
        assert set(re.findall(r"\d+\.\d+|∞", narrow)) <= numbers
        # the answers (near and far) and what identifies a row (file, f, N, model) are always there
        for cell in ("IMG_0000.jpg", "1.014", "f/5.6", "thick"):
            assert cell in narrow


def test_user_text_is_never_read_as_markup() -> None:
    rows = [{"file": "[bold red]x[/bold red] :smile: [link=http://e]y[/link]", "near_mm": 1.0, "far_mm": 2.0}]
    text = render_table(rows, COLUMNS[:1] + COLUMNS[3:5], colour="truecolor").text
    assert "[bold red]x[/bold red] :smile: [link=http://e]y[/link]" in ESCAPE.sub("", text)
    assert "\x1b]8" not in text  # no hyperlink escape


def test_rows_with_no_answer_give_their_reason_in_the_footer_and_many_are_summarised() -> None:
    rows = _rows(100)
    text = render_table(rows, COLUMNS, width=80).text
    reasons = [line for line in text.splitlines() if "nothing sharp" in line]
    assert len(reasons) == table_module.ROW_NOTES
    assert reasons[0].startswith("row 4 (IMG_0003.jpg")
    assert "… and 4 more rows with no answer (--format json or csv gives every row's error)" in text


def _snapshot(name: str, text: str) -> None:
    path = SNAPSHOTS / f"{name}.txt"
    if os.environ.get("CAMTOOL_UPDATE_SNAPSHOTS"):
        path.write_text(text, encoding="utf-8")
    assert text == path.read_text(encoding="utf-8"), f"{name}: the table changed (CAMTOOL_UPDATE_SNAPSHOTS=1)"


TABLES = {
    "dof-list": ["dof", "-f", "50", "-N", "2.8,8,22", "-s", "3m", "--model", "thin"],
    "dof-diffraction": ["dof", "-f", "50", "-N", "8,22,32", "-s", "3m", "--diffraction", "--model", "thin"],
    "exposure-nd-film": ["exposure", "--ev", "12", "-N", "8", "--nd", "10stops", "--nd", "6stops", "--film", "fp4"],
    "presets-list": ["presets", "list", "--kind", "sensor", "--search", "aps"],
    "stack-imperial": ["stack", "-f", "100", "-N", "8", "--near", "1m", "--far", "3m", "--units", "imperial"],
}


@pytest.mark.parametrize("name", sorted(TABLES))
@pytest.mark.parametrize("width", ["60", "80", "120"])
def test_representative_tables_at_fixed_widths(name: str, width: str) -> None:
    result = run(*TABLES[name], env={"COLUMNS": width})
    assert result.exit_code == 0, result.output
    text = result.stdout.replace(str(Path(__file__).parents[1]), "<root>")
    _snapshot(f"{name}-{width}", text)
    assert max(len(line) for line in text.splitlines()) <= int(width)


@pytest.mark.parametrize("name", ["dof-list", "exposure-nd-film"])
def test_representative_tables_in_colour(name: str) -> None:
    drawn = _in_terminal(TABLES[name], {"COLUMNS": "100", "TERM": "xterm-256color"}).replace("\r\n", "\n")
    assert "\x1b[1m" in drawn  # the header and the answers are bold
    _snapshot(f"{name}-colour", drawn)


def test_narrow_terminals_keep_the_answers() -> None:
    exposure = run(*TABLES["exposure-nd-film"], env={"COLUMNS": "60"}).stdout
    assert "time to set" in exposure or "with reciprocity" in exposure
    assert "1h 43m 28s" in exposure
    show = run("presets", "show", "nikon-z-8", env={"COLUMNS": "80"}).stdout
    assert "value" in show and "8256" in show and "Nikon Z 8" in show
    diffraction = run(*TABLES["dof-diffraction"], env={"COLUMNS": "60"}).stdout
    assert "row 2 (f/22): nothing sharp" in diffraction


@pytest.mark.parametrize(("env", "coloured"), [({}, True), ({"NO_COLOR": "1"}, False), ({"TERM": "dumb"}, False)])
def test_colour_on_a_terminal_only(env: dict[str, str], coloured: bool) -> None:
    drawn = _in_terminal(["dof", "-f", "50", "-N", "8", "-s", "3m,inf"], env)
    assert "3.000" in drawn
    assert ("\x1b[" in drawn) == coloured
    if coloured:
        assert "\x1b[36m" in drawn  # ∞ is cyan


def test_a_pipe_gets_no_escape_codes_and_force_color_gives_them() -> None:
    command = [sys.executable, "-m", "camtool", "dof", "-f", "50", "-N", "8", "-s", "3m"]
    env = {k: v for k, v in os.environ.items() if k not in ("NO_COLOR", "FORCE_COLOR")}
    plain = subprocess.run(command, capture_output=True, text=True, env=env).stdout
    forced = subprocess.run(command, capture_output=True, text=True, env={**env, "FORCE_COLOR": "1"}).stdout
    assert "\x1b" not in plain and "\x1b[1m" in forced
    assert ESCAPE.sub("", forced).replace(" \n", "\n") == plain.replace(" \n", "\n")


@pytest.mark.parametrize("fmt", [["--format", "json"], ["--format", "csv"], ["--field", "near_mm"]])
def test_scripts_output_imports_no_rich(fmt: list[str]) -> None:
    result = subprocess.run([sys.executable, "-X", "importtime", "-m", "camtool", "dof", "-f", "50", "-N", "8",
                             "-s", "3m", *fmt], capture_output=True, text=True)
    assert result.returncode == 0
    imported = [line.rsplit("|", 1)[-1].strip() for line in result.stderr.splitlines() if "|" in line]
    assert "camtool.render.output" in imported or "camtool" in imported
    assert not [name for name in imported if name == "rich" or name.startswith("rich.")]


def test_the_theme_is_the_one_source_of_escape_codes() -> None:
    from camtool.render.theme import THEME, codes

    for name in THEME:
        start, end = codes(name, "truecolor")
        assert start.startswith("\x1b[") and end == "\x1b[0m"
    out = io.StringIO()
    assert table_module.colour_system(out) is None


GRID = ["dof", "-f", "50", "-N", ",".join(f"{1 + i / 100:g}" for i in range(1000)), "-s",
        ",".join(f"{1 + i / 10:g}m" for i in range(100)), "--model", "thin", "--format", "csv"]


def _stderr_on_a_terminal(args: list[str], out: Path, interrupt_after: bytes | None = None) -> tuple[str, int]:
    """Run camtool with stdout to ``out`` and stderr on a pseudo-terminal: what the terminal got, and the status."""
    import pty
    import signal

    from test_shell import CAMTOOL, ENV, drain

    pid, fd = pty.fork()
    if pid == 0:  # child: stdout to the file, stderr stays on the terminal
        target = os.open(out, os.O_WRONLY | os.O_CREAT | os.O_TRUNC)
        os.dup2(target, 1)
        os.execve(CAMTOOL, [CAMTOOL, *args], {**ENV, "TERM": "xterm-256color", "COLUMNS": "100"})
    sent = []

    def interrupt(drawn: bytes) -> None:
        if interrupt_after is not None and not sent and interrupt_after in drawn:
            os.kill(pid, signal.SIGINT)
            sent.append(True)

    drawn, status = drain(pid, fd, interrupt)
    return drawn.decode(errors="replace"), status


def test_progress_shows_on_a_terminal_only_on_stderr(tmp_path) -> None:
    drawn, status = _stderr_on_a_terminal(GRID, tmp_path / "out.csv")
    assert status == 0
    assert "camtool dof: rows" in drawn and "100000" in drawn.replace(",", "")
    lines = (tmp_path / "out.csv").read_text().splitlines()
    assert len(lines) == 100_001 and "\x1b" not in lines[0] + lines[-1]  # stdout untouched


def test_no_progress_into_a_pipe() -> None:
    result = subprocess.run([sys.executable, "-m", "camtool", *GRID], capture_output=True, text=True)
    assert result.returncode == 0 and result.stderr == ""


def test_ctrl_c_during_progress_ends_in_one_line_and_restores_the_cursor(tmp_path) -> None:
    many = [*GRID[:4], ",".join(f"{1 + i / 1000:g}" for i in range(10_000)), *GRID[5:]]
    drawn, status = _stderr_on_a_terminal(many, tmp_path / "out.csv", interrupt_after=b"camtool dof: rows")
    assert status == 130
    assert drawn.rstrip().endswith("camtool: interrupted")
    assert "\x1b[?25h" in drawn.split("camtool: interrupted")[0][-40:]


def test_footers_of_many_chunks_are_said_once(monkeypatch) -> None:
    from camtool.render.output import LATER_NOTES, RowWriter

    monkeypatch.delenv("COLUMNS", raising=False)

    out = io.StringIO()
    writer = RowWriter("table", stream=out)
    columns = [Column("near_mm", "near")]
    for chunk in range(87):
        writer.write([{"near_mm": 1000.0 + chunk}], columns, ["near_mm"],
                     f"thin model · CoC 0.03 mm · the branch at m = {chunk}")
    writer.close()
    footer = out.getvalue().split("\n")[3 + 87:]
    assert footer[0] == "thin model · CoC 0.03 mm · the branch at m = 0"
    assert footer[1].startswith("later rows: the branch at m = 1 · ") and f"… and {86 - LATER_NOTES} more" in footer[1]
    assert footer[2:] == [""]


def test_a_skipping_batch_names_the_first_rows_and_counts_the_rest(tmp_path) -> None:
    rows = "".join(f"50,{'x' if i % 3 == 0 else 8},3\n" for i in range(30_000))
    source = tmp_path / "scenes.csv"
    source.write_text("focal-length,f-number,distance\n" + rows)
    result = subprocess.run([sys.executable, "-m", "camtool", "dof", "--batch", str(source), "--on-error", "skip",
                             "--format", "csv"], capture_output=True, text=True)
    lines = result.stderr.splitlines()
    assert result.returncode == 1 and len(lines) == 6
    assert lines[0].startswith("Error: --batch row 1, column 'f-number'")
    assert lines[-1] == ("camtool: 10,000 of 30,000 rows skipped (the first 5 above; --format json gives each "
                         "row's error in its place)")
    assert len(result.stdout.splitlines()) == 30_001  # every row keeps its place


def test_a_long_batch_shows_progress_on_a_terminal(tmp_path) -> None:
    source = tmp_path / "scenes.csv"
    source.write_text("focal-length,f-number,distance\n" + "".join(f"50,8,{1 + i % 50}\n" for i in range(60_000)))
    drawn, status = _stderr_on_a_terminal(["dof", "--batch", str(source), "--format", "csv"], tmp_path / "out.csv")
    assert status == 0 and "camtool dof --batch: rows" in drawn
    assert len((tmp_path / "out.csv").read_text().splitlines()) == 60_001


def test_a_traced_stack_plan_shows_its_frames_on_a_terminal(tmp_path) -> None:
    args = ["stack", "--lens", "canon-rf-50mm-f1.2l-usm-patent", "-N", "8", "--near", "0.5m", "--far", "inf",
            "--model", "raytrace", "--format", "csv"]
    drawn, status = _stderr_on_a_terminal(args, tmp_path / "out.csv")
    assert status == 0 and "camtool stack: frames" in drawn
    assert len((tmp_path / "out.csv").read_text().splitlines()) > 5


def test_a_real_lens_contrast_optimum_shows_its_ranges_on_a_terminal(tmp_path) -> None:
    args = ["focus", "--lens", "dgauss100-lens", "--near", "2m,3m", "--far", "5m,inf", "--optimum", "--criterion",
            "mtf:0.3@30", "--format", "csv"]
    drawn, status = _stderr_on_a_terminal(args, tmp_path / "out.csv")
    assert status == 0 and "camtool focus: ranges" in drawn
    assert len((tmp_path / "out.csv").read_text().splitlines()) == 5  # each near with each far


def test_text_folds_where_rich_folds_it() -> None:
    # the line-at-a-time drawing breaks a long text cell itself (rich's wrapping module costs 7 ms to import);
    # rich's public Text.wrap is the reference, over random words, runs of spaces and over-long words
    import random

    from rich.console import Console
    from rich.text import Text

    console = Console(width=200, color_system=None, legacy_windows=False)
    draw = random.Random(7)
    pieces = ["a", "bb", "ccc", "d" * 24, " ", "  ", "   ", "x" * 40, "é", "—", "·", "f/1.8"]
    checked = 0
    for _ in range(3000):
        text = "".join(draw.choice(pieces) for _ in range(draw.randint(1, 20)))
        width = draw.randint(1, 30)
        if len(text) <= width:
            continue
        lines = Text(text).wrap(console, width, justify="left", overflow="fold")
        assert [line.plain.ljust(width) for line in lines] == [line.ljust(width) for line in
                                                               table_module._folded(text, width)], (text, width)
        checked += 1
    assert checked > 2000
