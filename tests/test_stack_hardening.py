"""``camtool stack`` under generated command lines: every line a right plan or one clear error.

A seeded generator draws ``camtool stack`` command lines over every option of
``camtool stack --help`` (rail and bracketing mode, every model, criterion,
plane, preset, every output format including the table, ``--field``), good
values and hostile ones (zero, negatives, NaN, 1e-300, 1e300, units, lists).
Each runs in-process, its output going to a sink that keeps only the first
megabyte (a plan streams: a long one must not need its text held), under a
time bound (a hang is a defect), and must:

- raise nothing but ``SystemExit``, exit 0 or 2 (1 only for an unreadable file);
- on failure print one line ``Error: ...`` naming an option typed;
- print no ``nan``; in JSON no NaN/Infinity, no negative ``*_mm``, near ≤ focus ≤ far,
  frames numbered 1, 2, ... and focus distances strictly increasing.

The default run tries ``CAMTOOL_FUZZ_EXAMPLES`` lines (default 400, some
seconds); for a deeper search::

    CAMTOOL_FUZZ_EXAMPLES=20000 CAMTOOL_FUZZ_SEED=7 python -m pytest tests/test_stack_hardening.py -q

The other tests check the fixes against independent values: the thin-lens
bracketing identities, the hyperfocal identity H = f²/(N·c) + f, the rail
step and frame count, bounded memory of a long rail plan.
"""

from __future__ import annotations

import contextlib
import io
import itertools
import json
import math
import os
import random
import re
import signal
import sys
from typing import Any

import click
import pytest

from camtool.cli import cli

EXAMPLES = int(os.environ.get("CAMTOOL_FUZZ_EXAMPLES", "400"))
SEED = int(os.environ.get("CAMTOOL_FUZZ_SEED", "20260523"))
TIME_LIMIT_S = int(os.environ.get("CAMTOOL_FUZZ_TIME_LIMIT", "30"))
KEEP = 1 << 20
"""Characters of standard output kept for the checks (the rest is counted, not held)."""

# --- values ------------------------------------------------------------------------------------

HOSTILE = ["0", "-0", "-1", "1e-320", "1e-300", "1e-20", "1e-9", "1e-6", "9e-6", "1e-5", "1e15", "1e300", "1e308",
           "1e309", "nan", "inf", "-inf", "", "abc", "1,", ",", "0x10", "1_0"]
UNITS = ["", "", "", "mm", "cm", "m", "in", "ft", "um", "km"]
LENSES = ["ef-100-macro-l", "mp-e-65", "rf-50-1.8", "sony-fe-85mm-f1.8", "nikon-z-24-70mm-f4-s",
          "nikon-z-24mm-f1.8-s", "sony-fe-24-70mm-f2.8-gm-ii", "apple-iphone-15-pro-main", "no-such-lens"]
CAMERAS = ["sony-a7-iv", "apple-iphone-15-pro", "arri-alexa-35", "no-such-camera"]
SCENES = ["landscape-24", "macro-1to1", "phone-snapshot", "portrait-85", "street-35-zone"]
SENSORS = ["full-frame", "aps-c", "m43", "36x24", "1x1", "0x0", "1e300x1", "1-1.7-inch"]
PRESCRIPTIONS = ["dgauss100", "cellphone", "telephoto127", "canon-rf50-f1.2", "no-such-prescription"]
KEYS = ["frame", "distance_mm", "near_mm", "far_mm", "magnification", "step_mm", "extension_step_mm",
        "criterion", "mode", "distance_from", "nope"]


def _log_number(rng: random.Random, low: float, high: float) -> str:
    return f"{10.0 ** rng.uniform(low, high):.6g}"


def _value(rng: random.Random, low: float, high: float, units: bool = False) -> str:
    """A number drawn mostly log-uniformly in [10^low, 10^high], sometimes hostile, sometimes with a unit."""
    roll = rng.random()
    text = rng.choice(HOSTILE) if roll < 0.12 else _log_number(rng, low - 3, high + 3) if roll < 0.25 else \
        _log_number(rng, low, high)
    if units and rng.random() < 0.3:
        text += rng.choice(UNITS)
    if rng.random() < 0.04:
        text += "," + _log_number(rng, low, high)
    return text


def stack_line(rng: random.Random) -> list[str]:
    """One ``camtool stack`` command line."""
    argv = ["stack"]

    def maybe(p: float, *words: str) -> None:
        if rng.random() < p:
            argv.extend(words)

    rail = rng.random() < 0.5
    maybe(0.1, "--lens", rng.choice(LENSES))
    maybe(0.05, "--camera", rng.choice(CAMERAS))
    maybe(0.03, "--scene", rng.choice(SCENES))
    maybe(0.4 if rail else 0.9, "-f", _value(rng, 0.5, 3.0, units=True))
    maybe(0.97, "-N", _value(rng, 0.0, 1.6) if rng.random() < 0.8 else rng.choice(["f/8", "f8", "0.7", "1024"]))
    maybe(0.05, "--exact-stops")
    if rail or rng.random() < 0.05:
        maybe(0.95, "-m", _value(rng, -1.5, 1.0))
        maybe(0.95, "--depth", _value(rng, -1.0, 2.5, units=True))
    if not rail or rng.random() < 0.05:
        near = _value(rng, -0.7, 1.0, units=True)
        far = "inf" if rng.random() < 0.4 else _value(rng, -0.3, 2.0, units=True)
        maybe(0.95, "--near", near)
        maybe(0.95, "--far", far)
    maybe(0.5, "--overlap", rng.choice(["0", "0.2", "0.5", "0.9", "0.99", "1", "-0.1", "nan", "abc",
                                        f"{rng.random():.3f}"]))
    maybe(0.4, "--criterion", rng.choice(["classic", "wave", "other"]))
    maybe(0.4, "--model", rng.choice(["approx", "thin", "thick", "paraxial", "raytrace", "auto", "all"]))
    maybe(0.3, "--distance-from", rng.choice(["sensor", "lens"]))
    maybe(0.3, "--coc", _value(rng, -3.0, -0.5, units=True))
    maybe(0.08, "--coc-rule", rng.choice(["d/1500", "d/1730", "px:2", "print:8x10in@25cm", "d/0", "px:-1", "junk"]))
    maybe(0.08, "--pixel-pitch", _value(rng, -0.5, 1.5, units=True))
    maybe(0.1, "--sensor", rng.choice(SENSORS))
    maybe(0.05, "--crop", _value(rng, -0.5, 1.0))
    maybe(0.2, rng.choice(["--diffraction", "--no-diffraction"]))
    maybe(0.1, "--wavelength", rng.choice(["550", "550nm", "0.55um", "400", "700", "0", "1e9", "nan"]))
    maybe(0.15, "--pupil-mag", _value(rng, -1.0, 0.7))
    maybe(0.1, "--hiatus", rng.choice(["0", "-10", "10", "1e9", "-1e9", _log_number(rng, -2, 2)]))
    maybe(0.05, "--prescription", rng.choice(PRESCRIPTIONS))
    maybe(0.05, "--tolerance", rng.choice(["1%", "0.01", "0", "50%", "1e-9"]))
    maybe(0.1, "--units", rng.choice(["metric", "imperial"]))
    argv.extend(["--format", rng.choice(["table", "table", "json", "json", "csv"])])
    maybe(0.1, "--field", rng.choice(KEYS))
    if rng.random() < 0.05:  # an option given twice
        starts = [i for i, word in enumerate(argv[:-1]) if word in ("-f", "-N", "-m", "--depth", "--near", "--coc")]
        if starts:
            i = rng.choice(starts)
            argv.extend([argv[i], _value(rng, 0.0, 1.0)])
    return argv


# --- running and checking ----------------------------------------------------------------------


class Sink(io.TextIOBase):
    """A text stream that keeps the first ``keep`` characters and counts the rest."""

    encoding = "utf-8"

    def __init__(self, keep: int = KEEP) -> None:
        self.kept: list[str] = []
        self.size = 0
        self.keep = keep

    def write(self, text: Any) -> int:
        if isinstance(text, bytes):
            text = text.decode("utf-8", "replace")
        if self.size < self.keep:
            self.kept.append(text[:self.keep - self.size])
        self.size += len(text)
        return len(text)

    def writable(self) -> bool:
        return True

    def isatty(self) -> bool:
        return False

    def text(self) -> str:
        return "".join(self.kept)


class Hang(Exception):
    """No answer within the time bound."""


class LongStream(Exception):
    """Still writing a long plan at the time bound: streaming, not hanging (more than :data:`KEEP` written)."""


def invoke(argv: list[str], keep: int = KEEP) -> tuple[int, str, str, int, BaseException | None]:
    """Run ``camtool ARGV``: (exit status, stdout kept, stderr, stdout size, unexpected exception)."""
    out, err = Sink(keep), Sink()

    def expire(signum: int, frame: object) -> None:
        if out.size > out.keep:
            raise LongStream(f"{out.size:,} characters written in {TIME_LIMIT_S} s")
        raise Hang(f"no answer within {TIME_LIMIT_S} s")

    previous = signal.signal(signal.SIGALRM, expire)
    signal.alarm(TIME_LIMIT_S)
    status, exception = 0, None
    try:
        with contextlib.redirect_stdout(out), contextlib.redirect_stderr(err):
            try:
                cli.main(argv, prog_name="camtool", standalone_mode=True)
            except SystemExit as done:
                status = done.code if isinstance(done.code, int) else 1
    except BaseException as error:
        if isinstance(error, KeyboardInterrupt):
            raise
        exception, status = error, -1
    finally:
        signal.alarm(0)
        signal.signal(signal.SIGALRM, previous)
    return status, out.text(), err.text(), out.size, exception


OPTION = re.compile(r"'-{1,2}[\w-]+'|(?<![\w-])--?[A-Za-z][\w-]*")


def defect(argv: list[str], status: int, stdout: str, stderr: str, size: int,
           exception: BaseException | None) -> str:
    """The defect class of one run ('' when it kept every promise)."""
    if isinstance(exception, Hang):
        return "hang"
    if isinstance(exception, LongStream):
        return ""  # a plan of up to 10⁶ frames, still streaming (its first megabyte was checked below)
    if exception is not None:
        return f"traceback: {type(exception).__name__}: {str(exception)[:120]}"
    if status not in (0, 1, 2):
        return f"exit status {status}"
    if status:
        lines = stderr.splitlines()
        if len(lines) != 1 or not lines[0].startswith("Error: "):
            return f"error not one line: {stderr[:300]!r}"
        typed = any(len(word) > 2 and not word.startswith("-") and f"{word}:" in lines[0] for word in argv[1:])
        if not OPTION.search(lines[0]) and not typed:  # an option, or a preset or file typed, named
            return f"error names no option: {lines[0]}"
        if stdout:
            return "output before the error"
        return ""
    if stderr:
        return f"stderr on success: {stderr[:200]!r}"
    if re.search(r"\bnan\b", stdout, flags=re.I):
        return "nan printed"
    fmt = argv[argv.index("--format") + 1]
    if fmt != "json" or "--field" in argv or size > KEEP or exception is not None:
        return ""
    try:
        rows = json.loads(stdout, parse_constant=lambda c: (_ for _ in ()).throw(ValueError(c)))
    except ValueError as error:
        return f"JSON not parseable or holds NaN/Infinity: {error}"
    return plan_defect(rows)


def plan_defect(rows: list[dict[str, Any]]) -> str:
    """What is wrong with a plan's JSON rows ('' if nothing)."""
    if not rows:
        return "empty plan"
    previous = None
    for index, row in enumerate(rows, 1):
        if row.get("frame") != index:
            return f"frame {row.get('frame')} in place {index}"
        for key, value in row.items():
            if value is None and key not in ("far_mm", "extension_step_mm"):
                return f"null {key}"
            if isinstance(value, float) and not math.isfinite(value):
                return f"non-finite {key}"
            if key.endswith("_mm") and isinstance(value, (int, float)) and value < 0:
                return f"negative {key}"
        near, focus = row["near_mm"], row["distance_mm"]
        far = math.inf if row["far_mm"] is None else row["far_mm"]
        if not near <= focus * (1 + 1e-9) or not focus <= far * (1 + 1e-9):
            return "not near ≤ focus ≤ far"
        if previous is not None and not focus > previous["distance_mm"]:
            return "focus distances not increasing"
        if previous is not None and not near >= previous["near_mm"]:
            return "near limits not increasing"
        previous = row
    return ""


def fuzz(examples: int, seed: int) -> tuple[int, dict[str, list[str]]]:
    """Run ``examples`` generated lines: (lines run, defect class -> example lines)."""
    rng = random.Random(seed)
    failures: dict[str, list[str]] = {}
    for _ in range(examples):
        argv = stack_line(rng)
        found = defect(argv, *invoke(argv))
        if found:
            failures.setdefault(found.split(":")[0], []).append(f"camtool {' '.join(argv)}  ->  {found}")
    return examples, failures


@pytest.fixture()
def sandbox(tmp_path: Any, monkeypatch: pytest.MonkeyPatch) -> None:
    for name in ("XDG_CONFIG_HOME", "XDG_DATA_HOME", "XDG_CACHE_HOME"):
        monkeypatch.setenv(name, str(tmp_path / name.lower()))
    for name in ("COLUMNS", "CAMTOOL_FORMAT", "NO_COLOR"):
        monkeypatch.delenv(name, raising=False)


def test_generated_stack_lines_give_a_plan_or_one_clear_error(sandbox: None) -> None:
    tried, failures = fuzz(EXAMPLES, SEED)
    report = "\n".join(f"{kind} ({len(lines)}):\n  " + "\n  ".join(lines[:5]) for kind, lines in failures.items())
    assert not failures, f"{sum(map(len, failures.values()))} of {tried} command lines failed:\n{report}"


if __name__ == "__main__":  # python tests/test_stack_hardening.py [EXAMPLES [SEED]]: a report of every class
    count = int(sys.argv[1]) if len(sys.argv) > 1 else EXAMPLES
    tried, found = fuzz(count, int(sys.argv[2]) if len(sys.argv) > 2 else SEED)
    print(f"{tried} lines, {sum(map(len, found.values()))} defective")
    for kind, lines in sorted(found.items(), key=lambda item: -len(item[1])):
        print(f"{kind} ({len(lines)}):\n  " + "\n  ".join(lines[:6]))
    click.echo("done")


# --- the fixes, against independent values -------------------------------------------------------


def _run(*args: str, keep: int = KEEP) -> tuple[int, str, str]:
    status, out, err, size, exception = invoke(["stack", *args], keep)
    assert exception is None, exception
    assert size <= keep
    return status, out, err


def _plan(*args: str) -> list[dict[str, Any]]:
    status, out, err = _run(*args, "--format", "json")
    assert status == 0, err
    rows = json.loads(out)
    assert plan_defect(rows) == "", plan_defect(rows)
    return rows


def _error(*args: str) -> str:
    status, out, err = _run(*args)
    assert status == 2 and out == "" and len(err.splitlines()) == 1, (status, out, err)
    return err.strip()


def _thin_limits(f: float, n: float, c: float, u: float) -> tuple[float, float]:
    """The thin-lens limits from the lens, u·K/(K ± (u − f)), K = f²/(N·c) (Wikipedia, "Depth of field")."""
    k = f * f / (n * c)
    return u * k / (k + u - f), (u * k / (k - (u - f)) if u - f < k else math.inf)


def test_stack_f_has_the_focal_length_bound_of_every_command(sandbox: None) -> None:
    # the same option type as `dof -f`: the same bound, worded the same
    for value in ("1e-5", "1e-320", "0.5", "5001", "nan"):
        stack = _error("-f", value, "-N", "8", "--near", "1", "--far", "2")
        status, _, err, _, _ = invoke(["dof", "-f", value, "-N", "8", "-s", "1"])
        assert status == 2 and stack == err.strip(), (stack, err)
        assert "'-f' / '--focal-length'" in stack and ("1 to 5000 mm" in stack or value == "nan")
    assert "takes one value here" in _error("-f", "50,60", "-N", "8", "-m", "0.5", "--depth", "5mm")


@pytest.mark.parametrize(("f", "n", "c", "m"), [(48.0, 1024.0, 0.03, 0.32), (50.0, 22.0, 0.03, 0.01),
                                                 (24.0, 64.0, 0.02, 0.05)])
def test_rail_beyond_the_hyperfocal_distance_is_one_frame_sharp_to_infinity(sandbox: None, f: float, n: float,
                                                                           c: float, m: float) -> None:
    u = f * (1.0 + 1.0 / m)  # the subject's distance from the lens at magnification m
    assert u - f >= f * f / (n * c)  # at or beyond the hyperfocal distance H = f²/(N·c) + f
    rows = _plan("-f", str(f), "-N", str(n), "--coc", str(c), "-m", str(m), "--depth", "50mm", "--criterion",
                 "classic")
    near, far = _thin_limits(f, n, c, u)
    assert far == math.inf and len(rows) == 1
    (row,) = rows
    assert row["near_mm"] == 0.0 and row["far_mm"] is None and row["step_mm"] == 0.0
    assert row["distance_mm"] == pytest.approx(u - near, rel=1e-9)  # focus: the front depth past the nearest point
    status, table, _ = _run("-f", str(f), "-N", str(n), "--coc", str(c), "-m", str(m), "--depth", "50mm",
                            "--criterion", "classic")
    assert status == 0 and "1 frame · sharp from" in table and not re.search(r"\b(inf|nan)\b", table)


@pytest.mark.parametrize(("n", "m", "p", "overlap", "depth"), [(8.0, 1.0, 1.0, 0.0, 10.0), (5.6, 2.0, 1.0, 0.2, 3.0),
                                                               (4.0, 5.0, 0.5, 0.5, 1.0)])
def test_rail_step_and_count_from_the_wave_depth(sandbox: None, n: float, m: float, p: float, overlap: float,
                                                 depth: float) -> None:
    # the quarter-wave depth λ/NA², NA = m/(2·N_w) at the subject... written out: 4·λ·N_w²/m², N_w = N·(1 + m/P)
    wave = 4.0 * 550e-6 * (n * (1.0 + m / p)) ** 2 / (m * m)
    step = wave * (1.0 - overlap)
    frames = math.ceil(depth / step)
    rows = _plan("-N", str(n), "-m", str(m), "--pupil-mag", str(p), "--overlap", str(overlap), "--depth",
                 f"{depth}mm", "--criterion", "wave")
    assert len(rows) == frames and frames * step >= depth > (frames - 1) * step
    for k, row in enumerate(rows):
        assert row["near_mm"] == pytest.approx(k * step, rel=1e-12, abs=1e-15)
        assert row["far_mm"] - row["near_mm"] == pytest.approx(wave, rel=1e-12)
        assert row["step_mm"] == (0.0 if k == 0 else pytest.approx(step, rel=1e-12))
        assert row["extension_step_mm"] == (0.0 if k == 0 else pytest.approx(m * m * step, rel=1e-12))
    if len(rows) > 1:  # rail step = covered span / (frames − 1) between the first and last focus
        assert (rows[-1]["distance_mm"] - rows[0]["distance_mm"]) / (len(rows) - 1) == pytest.approx(step, rel=1e-9)


def test_a_long_rail_plan_streams_the_same_frames(sandbox: None) -> None:
    # 3 chunks and a bit: frame k's near limit is (k − 1)·step exactly, numbered without a gap or a repeat,
    # in CSV and JSON alike; the frame count is ⌈depth/step⌉ of the wave depth
    wave = 4.0 * 550e-6 * (8.0 * 2.0) ** 2  # m = 1, N = 8
    depth = 65_000.5 * wave
    status, out, err = _run("-m", "1", "-N", "8", "--overlap", "0", "--depth", f"{depth!r}mm", "--format", "csv",
                            keep=1 << 26)
    assert status == 0, err
    lines = out.splitlines()
    assert len(lines) == 1 + math.ceil(depth / wave) == 65_002
    for k in (1, 2, 20_000, 20_001, 40_001, 65_001):
        cells = lines[k].split(",")
        assert int(cells[0]) == k and float(cells[2]) == pytest.approx((k - 1) * wave, rel=1e-12, abs=0)
    assert [int(line.split(",")[0]) for line in lines[1:]] == list(range(1, 65_002))


def test_a_long_rail_plan_is_written_in_bounded_memory(sandbox: None) -> None:
    # the peak of Python allocations while a plan goes out is that of a chunk (20,000 frames), not of the
    # plan: three times the frames (40,000 and 120,000, two and six chunks) may not raise it by a third
    # (holding the rows would triple it: about a kilobyte a frame as dicts and text, some 120 MB)
    import tracemalloc

    invoke(["stack", "-m", "1", "-N", "8", "--depth", "5mm", "--format", "json"])  # modules imported first
    peaks = []
    for frames in (40_000, 120_000):
        tracemalloc.start()
        try:
            status, _, err, size, exception = invoke(["stack", "-m", "1", "-N", "8", "--overlap", "0", "--depth",
                                                       f"{frames * 0.5632 - 0.1}mm", "--format", "json"])
            peaks.append(tracemalloc.get_traced_memory()[1])
        finally:
            tracemalloc.stop()
        assert exception is None and status == 0, err
        assert size > frames * 150  # every frame was written
    assert peaks[1] < 1.33 * peaks[0] and peaks[1] < 60e6, [f"{p / 1e6:.0f} MB" for p in peaks]


def test_frame_limits_are_one_line_errors_on_depth(sandbox: None) -> None:
    table = _error("-m", "1", "-N", "8", "--depth", "100m")  # 222,000 frames: more than a table holds
    assert table.startswith("Error: Invalid value for '--depth':") and "--format csv" in table
    for fmt in ("json", "csv", "table"):
        huge = _error("-m", "1", "-N", "8", "--depth", "1e300", "--format", fmt)
        assert huge.startswith("Error: Invalid value for '--depth': 1e+300 mm") and "1,000,000 frames" in huge


def test_approx_wave_bracketing_never_plans_a_negative_distance(sandbox: None) -> None:
    # the approx rule's hyperfocal distance H₀ = f²/(N·c) with the wave CoC c = 2λN: f = 1.4 mm at f/439
    # gives H₀ = 0.0093 mm, inside the focal length: no frame can be focused there
    f, n = 1.4021, 439.1
    h0 = f * f / (n * 2 * 550e-6 * n)
    assert h0 < f
    for plane in ("sensor", "lens"):
        err = _error("-f", str(f), "-N", str(n), "--near", "0.1545", "--far", "0.17", "--criterion", "wave",
                     "--model", "approx", "--distance-from", plane)
        assert err.startswith("Error: Invalid value for '-N' / '--f-number': 439.1 gives a distance of")


@pytest.mark.parametrize(("f", "n", "near"), [(24.0, 8.0, 300.0), (50.0, 4.0, 1000.0), (100.0, 2.8, 2500.0)])
def test_approx_wave_bracketing_steps_the_vergence_by_two_over_h0(sandbox: None, f: float, n: float,
                                                                   near: float) -> None:
    # from the lens at overlap 0 the approx rule makes 1/u step by exactly 2/H₀, H₀ = f²/(N·c), c = 2λN
    h0 = f * f / (n * 2 * 550e-6 * n)
    rows = _plan("-f", str(f), "-N", str(n), "--near", f"{near}mm", "--far", "inf", "--criterion", "wave",
                 "--model", "approx", "--distance-from", "lens", "--overlap", "0")
    assert rows[-1]["far_mm"] is None and rows[-1]["distance_mm"] == pytest.approx(h0, rel=1e-12)
    assert rows[0]["near_mm"] == pytest.approx(near, rel=1e-12)
    for a, b in itertools.pairwise(rows[:-1]):  # the last is clamped at H₀
        assert 1.0 / a["distance_mm"] - 1.0 / b["distance_mm"] == pytest.approx(2.0 / h0, rel=1e-7)
        assert a["far_mm"] == pytest.approx(b["near_mm"], rel=1e-9)


@pytest.mark.parametrize("plane", ["lens", "sensor"])
def test_thin_bracketing_chains_to_the_hyperfocal_distance(sandbox: None, plane: str) -> None:
    # overlap 0: each far limit is the next near limit; the last frame is focused at H = f²/(N·c) + f
    f, n, c = 35.0, 11.0, 0.03
    h = f * f / (n * c) + f
    rows = _plan("-f", "35", "-N", "11", "--coc", "0.03", "--near", "0.4", "--far", "inf", "--overlap", "0",
                 "--model", "thin", "--distance-from", plane)
    for a, b in itertools.pairwise(rows[:-1]):
        assert a["far_mm"] == pytest.approx(b["near_mm"], rel=1e-9)
    shift = f * h / (h - f) if plane == "sensor" else 0.0  # the image distance, from lens to sensor
    assert rows[-1]["distance_mm"] == pytest.approx(h + shift, rel=1e-12) and rows[-1]["far_mm"] is None
    for row in rows[:-1]:  # each frame's limits are the thin lens's at its focus u (from the lens)
        u = row["distance_mm"] if plane == "lens" else _lens_focus(f, row["distance_mm"])
        near, far = _thin_limits(f, n, c, u)
        assert row["near_mm"] - shift_of(f, u, plane) == pytest.approx(near, rel=1e-9)
        assert row["far_mm"] - shift_of(f, u, plane) == pytest.approx(far, rel=1e-9)


def shift_of(f: float, u: float, plane: str) -> float:
    """From the lens to the sensor plane: the image distance v = f·u/(u − f) (no hiatus)."""
    return f * u / (u - f) if plane == "sensor" else 0.0


def _lens_focus(f: float, s: float) -> float:
    """The focus u from the lens whose subject is s = u + f·u/(u − f) from the sensor (the far root, m < 1)."""
    return (s + math.sqrt(s * s - 4.0 * f * s)) / 2.0


def test_a_numerically_solved_plan_is_bounded_in_frames_and_time(sandbox: None) -> None:
    import time

    start = time.monotonic()
    err = _error("-f", "376", "-N", "1.4", "--near", "2.2", "--far", "58", "--criterion", "wave", "--model", "thick",
                 "--pupil-mag", "1.12", "--overlap", "0.9")
    assert err.startswith("Error: Invalid value for '--near': 2.2 m") and "2000 frames" in err and "thick" in err
    assert time.monotonic() - start < 10.0
