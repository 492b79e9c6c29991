"""Property-based fuzzing of the whole command line: every input a right answer or a clear error.

Command lines are generated from the click definitions themselves (every
command, every option, every argument), with values that mix units, lists,
``inf``, absurd magnitudes, preset names and files, good and hostile. Each
runs in-process through click's CliRunner and must:

- raise nothing but ``SystemExit`` (no traceback), with exit status 0, 1 or 2;
- on failure print one line on standard error, ``Error: ...``, naming an option
  (or the argument) the user typed;
- never print ``nan``; with ``--format json``, print JSON without NaN or
  Infinity, no negative ``*_mm`` length, and near ≤ focus ≤ far in every row.

The run is derandomized (the same command lines every time). In CI it tries
``CAMTOOL_FUZZ_EXAMPLES`` command lines (default 2,000, under a minute on two
cores); locally, for a deeper search::

    CAMTOOL_FUZZ_EXAMPLES=50000 python -m pytest tests/test_cli_fuzz.py -q

(``CAMTOOL_FUZZ_SEED=<n>`` draws a different, still reproducible, set.)
"""

from __future__ import annotations

import json
import math
import os
import re
import shutil
from pathlib import Path
from typing import Any

import click
import pytest
from click.testing import CliRunner
from hypothesis import HealthCheck, Phase, given, seed, settings
from hypothesis import strategies as st

from camtool.cli import cli
from camtool.cli.params import FNumberType, LengthType, NumberType, TimeType

EXAMPLES = int(os.environ.get("CAMTOOL_FUZZ_EXAMPLES", "2000"))
SEED = int(os.environ.get("CAMTOOL_FUZZ_SEED", "20261123"))
REPO = Path(__file__).resolve().parent.parent

# --- values -----------------------------------------------------------------------------------

MAGNITUDES = ["0", "-0", "-1", "-300", "1e-20", "1e-9", "0.0004", "0.03", "0.5", "1", "2", "3", "8", "24", "50",
              "100", "150", "1000", "5000", "5001", "1e15", "1e16", "1e17", "1e300", "1e308", "1e309", "nan", "inf",
              "-inf", "∞", "+inf", "1_000", "0x10", "", " ", "abc", "1/0", "3.", ".5", "5000" * 1250]
UNITS = ["", "", "", "mm", "cm", "m", "km", "in", "ft", "um", "µm", "'", '"', "parsecs", "MM", "M"]


def number() -> st.SearchStrategy[str]:
    log_uniform = st.floats(-25, 25).map(lambda e: f"{10.0 ** e:.6g}")
    return st.one_of(st.sampled_from(MAGNITUDES), log_uniform, st.integers(-10, 10**6).map(str))


def length() -> st.SearchStrategy[str]:
    single = st.one_of(st.tuples(number(), st.sampled_from(UNITS)).map("".join),
                       st.sampled_from(["5ft6in", "5'6\"", "10ft", "inf", "3m", "50mm", "0.5m", "1m", "2m"]))
    return st.lists(single, min_size=1, max_size=3).map(",".join)


def f_number() -> st.SearchStrategy[str]:
    single = st.one_of(st.sampled_from(["8", "f/8", "f8", "F/2.8", "0.7", "0.69", "1024", "1025", "2048", "1.4",
                                        "22", "f/", "f/nan", "11", "16"]), number())
    return st.lists(single, min_size=1, max_size=3).map(",".join)


def time() -> st.SearchStrategy[str]:
    single = st.one_of(st.sampled_from(["1/125", "1/0", "0.004", "2s", "30", "1m30s", "2h30", "2h", "1'30\"",
                                        "1/64000", "1e6", "1e7", "0"]), number())
    return st.lists(single, min_size=1, max_size=2).map(",".join)


def plain_number() -> st.SearchStrategy[str]:
    return st.lists(number(), min_size=1, max_size=2).map(",".join)


SENSORS = ["full-frame", "aps-c", "m43", "4x5", "5x4", "6x6", "6x7", "6x9", "8x10", "36x24", "36x24mm", "5x4in",
           "6x7cm", "0x24", "1e9x3", "nan x 3", "36×24", "unknown-sensor", "FF", "nikon-z-8", "3x2ft"]
CAMERAS = ["nikon-z-8", "canon-eos-5d-mark-iv", "apple-iphone-15-pro", "apple-iphone-16-pro", "fujifilm-x-t5",
           "no-such-camera"]
LENSES = ["sony-fe-85mm-f1.8", "canon-ef-50mm-f1.8-stm", "canon-ef-70-200mm-f2.8l-is-iii-usm",
          "canon-mp-e-65mm-f2.8-1-5x-macro", "apple-iphone-15-pro-main", "dgauss100-lens", "no-such-lens",
          # an internally focusing macro, a zoom whose smallest aperture closes down, one with no smallest
          # aperture, a lens made for APS-C, a phone module off the main sensor, a patent design
          "canon-ef-100mm-f2.8l-macro-is-usm", "sony-fe-200-600mm-f5.6-6.3-g-oss", "nikon-z-70-180mm-f2.8",
          "fujifilm-xf35mm-f1.4-r", "apple-iphone-16-pro-ultra-wide", "nikon-z-50mm-f1.8-s-patent"]
PRESCRIPTIONS = ["dgauss100", "nikon-z50-f1.8", "dgaus100"]  # --prescription by preset name (the last unknown)
SCENES = ["landscape-24", "macro-1to1", "phone-snapshot", "portrait-85", "street-35-zone", "no-such-scene"]
NAMES = SENSORS + CAMERAS + LENSES + SCENES + ["dgauss100", "cellphone", "telephoto127", ""]
COC_RULES = ["d/1500", "d/1730", "d/1442", "d/0", "d/-3", "d/1e300", "px:2", "px:0", "px:1e9", "px:nan",
             "print:8x10in@25cm", "print:0x10in@25cm", "print:8x10in@0cm", "bogus", ""]
KEYS = ["near_mm", "far_mm", "distance_mm", "hyperfocal_mm", "f_number", "nope", "shutter_s", "horizontal_deg"]
CHOICE_GARBAGE = ["", "bogus", "ALL"]


def files(root: Path) -> dict[str, str]:
    """Preset, prescription and batch files, good and hostile, in ``root``."""
    made = {
        "good.yaml": "sensors:\n  - id: fuzz-sensor\n    width_mm: 20\n    height_mm: 10\n    source: test\n",
        "broken.yaml": "sensors:\n  - id: x\n    width_mm: [1\n",
        "dupkey.yaml": "sensors:\n  - id: d\n    width_mm: 20\n    width_mm: 21\n    height_mm: 10\n",
        "dupid.yaml": "sensors:\n  - {id: a, width_mm: 20, height_mm: 10}\n  - {id: a, width_mm: 21, height_mm: 10}\n",
        "bigint.yaml": "sensors:\n  - id: big\n    width_mm: " + "9" * 5000 + "\n    height_mm: 10\n",
        "bomb.yaml": "a: &a [x, x, x, x, x, x, x, x, x]\n" + "".join(
            f"{chr(98 + i)}: &{chr(98 + i)} [*{chr(97 + i)}, *{chr(97 + i)}, *{chr(97 + i)}, *{chr(97 + i)}, "
            f"*{chr(97 + i)}, *{chr(97 + i)}, *{chr(97 + i)}, *{chr(97 + i)}, *{chr(97 + i)}]\n" for i in range(9)),
        "deep.yaml": "[" * 5000 + "]" * 5000 + "\n",
        "empty.yaml": "",
        "batch.csv": "focal-length,f-number,distance\n50,8,3m\n35,f/2.8,10ft\n0,8,3\n",
        "batch.jsonl": '{"focal-length": 50, "f-number": 8, "distance": "inf"}\n{"focal-length": "nan"}\n',
    }
    out = {}
    for name, text in made.items():
        (root / name).write_text(text, encoding="utf-8")
        out[name] = str(root / name)
    (root / "latin1.yaml").write_bytes(b"sensors:\n  - id: caf\xe9\n")
    (root / "utf16.yaml").write_bytes("sensors: []\n".encode("utf-16"))
    (root / "a-dir.yaml").mkdir()
    shutil.copy(REPO / "lens_db" / "prescriptions" / "dgauss100.yaml", root / "dgauss100.yaml")
    for name in ("latin1.yaml", "utf16.yaml", "a-dir.yaml", "dgauss100.yaml"):
        out[name] = str(root / name)
    out["missing"] = str(root / "missing.yaml")
    return out


# --- command lines from the click definitions ------------------------------------------------------


def commands() -> list[tuple[list[str], click.Command]]:
    """(argv prefix, command) for every leaf command."""
    ctx = click.Context(cli, help_option_names=["-h", "--help"])  # as the command line makes it (click caches it)
    out = []
    for name in cli.list_commands(ctx):
        command = cli.get_command(ctx, name)
        assert command is not None
        if isinstance(command, click.Group):
            sub_ctx = click.Context(command, parent=ctx, help_option_names=["-h", "--help"])
            for sub in command.list_commands(sub_ctx):
                leaf = command.get_command(sub_ctx, sub)
                assert leaf is not None
                out.append(([name, sub], leaf))
        else:
            out.append(([name], command))
    return out


def values_for(param: click.Parameter, paths: dict[str, str]) -> st.SearchStrategy[str]:
    name = param.name or ""
    kind = param.type
    file_values = st.sampled_from(sorted(paths.values()))
    if name in ("sensor",):
        return st.sampled_from(SENSORS)
    if name == "camera":
        return st.sampled_from(CAMERAS)
    if name == "lens":
        return st.sampled_from(LENSES)
    if name == "scene":
        return st.sampled_from(SCENES)
    if name == "coc_rule":
        return st.sampled_from(COC_RULES)
    if name == "fields":
        return st.sampled_from(KEYS)
    if name == "prescription_file":
        return st.one_of(file_values, st.sampled_from(PRESCRIPTIONS))
    if name in ("preset_files", "batch", "file", "out"):
        return file_values
    if name == "dirs":
        return st.sampled_from([str(Path(paths["good.yaml"]).parent), paths["missing"]])
    if name == "name":
        return st.sampled_from(NAMES)
    if isinstance(kind, click.Choice):
        return st.one_of(st.sampled_from(list(kind.choices)), st.sampled_from(CHOICE_GARBAGE))
    if isinstance(kind, FNumberType):
        return f_number()
    if isinstance(kind, TimeType):
        return time()
    if isinstance(kind, LengthType):
        return length()
    if isinstance(kind, NumberType):
        return plain_number()
    if name in ("hiatus",):
        return length()
    if name in ("nd",):
        return st.sampled_from(["ND1000", "ND8", "3", "nd0", "ND-2", "10 stops", "x", "1e9"])
    if name in ("film",):
        return st.sampled_from(["hp5", "tri-x", "portra-400", "no-film"])
    if name in ("light",):
        return st.sampled_from(["sunny", "overcast", "night", "no-light"])
    if name in ("shell",):
        return st.sampled_from(["bash", "zsh", "fish", "tcsh"])
    return st.one_of(number(), length(), st.sampled_from(NAMES))


BASE = {  # a mostly valid core, so that the other options are exercised past the first error
    "dof": ["-f", "50", "-N", "8", "-s", "3"],
    "hyperfocal": ["-f", "24", "-N", "8"],
    "fov": ["-f", "50"],
    "focus": ["-f", "100", "-s", "0.5m"],
    "compose": ["--subject-size", "1.8m", "--fill", "0.8"],
    "exposure": ["-N", "16", "-t", "1/125"],
}


@st.composite
def command_line(draw: Any, paths: dict[str, str]) -> list[str]:
    prefix, command = draw(st.sampled_from(COMMANDS))
    argv = list(prefix)
    if draw(st.booleans()) or draw(st.booleans()):
        argv += BASE.get(prefix[0], [])
    options = [p for p in command.params if isinstance(p, click.Option) and p.name != "help"]
    chosen = draw(st.lists(st.sampled_from(options), max_size=5)) if options else []
    for param in chosen:
        if param.is_flag:
            argv.append(draw(st.sampled_from(param.opts + param.secondary_opts)))
        else:
            argv += [draw(st.sampled_from(param.opts)), draw(values_for(param, paths))]
    for param in command.params:
        if isinstance(param, click.Argument):
            argv.append(draw(values_for(param, paths)))
    if "--format" not in argv and "fmt" in {p.name for p in command.params} and draw(st.integers(0, 3)):
        argv += ["--format", "json"]
    return argv


COMMANDS = commands()
OPTION = re.compile(r"'-{1,2}[\w-]+'|'[A-Z]+'|(?<![\w-])--?[A-Za-z][\w-]*")


def check(argv: list[str], result: Any) -> str:
    """The defect class of one run ('' when it kept every promise)."""
    if result.exception is not None and not isinstance(result.exception, SystemExit):
        return f"traceback: {type(result.exception).__name__}: {result.exception}"
    if result.exit_code not in (0, 1, 2):
        return f"exit status {result.exit_code}"
    if result.exit_code:
        lines = result.stderr.splitlines()
        if argv[:2] == ["presets", "validate"] and result.exit_code == 1:
            lines = lines[-1:]  # validate lists every problem of the file, then one summary line
        if result.exit_code == 1 and (len(lines) > 1 or result.stderr.startswith("camtool")):
            # a run that goes on past bad items (--on-error skip, exif's files) reports each on its own line,
            # then maybe a count: each must name what was typed
            for line in lines:
                if re.match(r"camtool( \w+)?: \d+ of \d+ \w+ skipped$", line):
                    continue
                if line.startswith("camtool") and any(a in line for a in argv[1:]):  # "" is named as ""
                    continue
                if line.startswith("Error: ") and OPTION.search(line):
                    continue
                return f"error not one line: {line!r} in {result.stderr!r}"
            return ""
        if len(lines) != 1 or not lines[0].startswith("Error: "):
            return f"error not one line: {result.stderr!r}"
        typed_path = any(a.startswith("/") and a in lines[0] for a in argv)  # a FILE argument, named as typed
        if not OPTION.search(lines[0]) and not typed_path:
            return f"error names no option: {lines[0]}"
        return ""
    if re.search(r"\bnan\b", result.stdout, flags=re.I):
        return "nan printed"
    formats = [argv[i + 1] for i, a in enumerate(argv[:-1]) if a == "--format"]
    if not formats or formats[-1] != "json" or "--field" in argv:
        return ""
    try:
        rows = json.loads(result.stdout, parse_constant=lambda c: (_ for _ in ()).throw(ValueError(c)))
    except ValueError as error:
        return f"JSON not parseable or holds NaN/Infinity: {error}"
    for row in rows if isinstance(rows, list) else [rows]:
        if not isinstance(row, dict):
            continue
        for key, value in row.items():
            if isinstance(value, float) and not math.isfinite(value):
                return f"non-finite {key}"
            signed = argv[:2] == ["presets", "show"]  # positions of cardinal points from the first surface
            if key.endswith("_mm") and isinstance(value, (int, float)) and value < 0 and not signed:
                return f"negative {key} = {value}"
        near, focus, far = row.get("near_mm"), row.get("distance_mm"), row.get("far_mm")
        far = math.inf if far is None and "far_mm" in row else far
        if "wanted_near_mm" not in row and all(isinstance(v, (int, float)) for v in (near, focus, far)):
            assert isinstance(near, (int, float)) and isinstance(focus, (int, float)) and isinstance(far, (int, float))
            if not near <= focus * (1 + 1e-9) or not focus <= far * (1 + 1e-9):
                return f"not near ≤ focus ≤ far: {near}, {focus}, {far}"
    return ""


@pytest.fixture()
def sandbox(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> dict[str, str]:
    for name in ("XDG_CONFIG_HOME", "XDG_DATA_HOME", "XDG_CACHE_HOME"):
        monkeypatch.setenv(name, str(tmp_path / name.lower()))
    monkeypatch.setenv("XDG_CONFIG_DIRS", str(tmp_path / "etc-xdg"))
    for name in ("COLUMNS", "CAMTOOL_FORMAT", "NO_COLOR"):
        monkeypatch.delenv(name, raising=False)
    (tmp_path / "files").mkdir()
    return files(tmp_path / "files")


# click opens a --batch FILE while parsing and does not close it when a later option fails to parse
# (its context is not entered yet); the leak is harmless in a process that exits, so it is not a defect here.
@pytest.mark.filterwarnings("ignore::pytest.PytestUnraisableExceptionWarning")
def test_cli_fuzz(sandbox: dict[str, str]) -> None:
    tried: list[int] = [0]
    failures: dict[str, list[str]] = {}
    runner = CliRunner()

    @seed(SEED)
    @settings(max_examples=EXAMPLES, derandomize=False, database=None, deadline=None,
              phases=[Phase.explicit, Phase.generate], suppress_health_check=list(HealthCheck))
    @given(argv=command_line(sandbox))
    def run(argv: list[str]) -> None:
        tried[0] += 1
        result = runner.invoke(cli, argv, catch_exceptions=True)
        defect = check(argv, result)
        if defect:
            failures.setdefault(defect.split(":")[0], []).append(f"camtool {' '.join(argv)}  ->  {defect}")

    run()
    report = "\n".join(f"{kind} ({len(lines)}):\n  " + "\n  ".join(lines[:5]) for kind, lines in failures.items())
    assert not failures, f"{sum(map(len, failures.values()))} of {tried[0]} command lines failed:\n{report}"
    assert tried[0] >= min(EXAMPLES, 2000) * 0.9, tried[0]
