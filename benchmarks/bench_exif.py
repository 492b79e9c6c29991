"""``camtool exif``: files per second over 1,000 images, and ``camtool dof``'s start-up before and after.

1. Throughput: a temporary directory of 1,000 tiny JPEGs (the six readable
   test images of tests/data/exif, copied round-robin), read with
   ``camtool exif --recursive DIR --format json`` (one process, the whole
   directory; default options, so ``--model auto``) and, in-process, with
   :func:`camtool.exif.reader.read_file` alone (the reading share).
2. Against ExifTool (``--against-exiftool N``, default 10,000 files; skipped
   without ``exiftool``): the same tiny JPEGs, N of them, read in one process
   each by ``camtool exif -r DIR --format json`` (camtool's answers) and
   ``camtool exif --exiftool -r DIR --format json`` (ExifTool's composites),
   and by ExifTool itself computing the same composites,
   ``exiftool -j -n -Composite:all -r DIR`` and its fastest form with
   ``-fast2`` (no maker notes: an upper bound on ExifTool's speed), and the
   camtool of ``--before`` for the change. Runs are
   interleaved, best of ``--exiftool-repeat``; the ratios are to the fastest
   ExifTool run, wall-clock and CPU time (the machine may be shared).
3. Start-up: ``camtool dof -f 50 -N 8 -s 3m --format json`` of this tree
   against the same command of a git ref without the exif command (``--before``,
   default ``main``; exported with ``git archive`` to a temporary directory,
   nothing else touched), each as ``python -m camtool`` and interleaved with
   ``python -c "import click"``; the ratios to that baseline are compared.

Run: ``python benchmarks/bench_exif.py [--files 1000] [--repeat 20] [--before main] [--against-exiftool 10000]``
"""

from __future__ import annotations

import argparse
import io
import math
import os
import shutil
import statistics
import subprocess
import sys
import tarfile
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
DATA = ROOT / "tests" / "data" / "exif"
IMAGES = ["canon_bracket.jpg", "canon_infinity.jpg", "nikon.jpg", "olympus.jpg", "fujifilm_subject.jpg",
          "sony_apex_lens.jpg"]
PY = sys.executable
DOF = ["-m", "camtool", "dof", "-f", "50", "-N", "8", "-s", "3m", "--format", "json"]


def throughput(files: int) -> None:
    with tempfile.TemporaryDirectory() as tmp:
        for i in range(files):
            shutil.copyfile(DATA / IMAGES[i % len(IMAGES)], Path(tmp) / f"img{i:05d}.jpg")
        argv = [PY, "-m", "camtool", "exif", "--recursive", tmp, "--format", "json"]
        # warm-up (byte-code, caches); the files' one-line warnings on stderr are discarded
        subprocess.run(argv, check=True, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, cwd=ROOT)
        runs = []
        for _ in range(3):
            start = time.perf_counter()
            subprocess.run(argv, check=True, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, cwd=ROOT)
            runs.append(time.perf_counter() - start)
        best = min(runs)
        sys.path.insert(0, str(ROOT))
        from camtool.exif.reader import read_file

        paths = sorted(str(p) for p in Path(tmp).iterdir())
        start = time.perf_counter()
        for path in paths:
            read_file(path)
        reading = time.perf_counter() - start
    print(f"| `camtool exif -r` over {files} files (best of 3, whole process) | {best:.2f} s | {files / best:.0f} files/s |")
    print(f"| reading alone (`read_file`, in-process) | {reading:.2f} s | {files / reading:.0f} files/s |")


def _timed(argv: list[str], cwd: Path = ROOT) -> tuple[float, float]:
    """Wall-clock and CPU seconds (this child's user + system) of one run, output discarded."""
    before = os.times()
    start = time.perf_counter()
    subprocess.run(argv, check=False, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, cwd=cwd)
    wall = time.perf_counter() - start
    after = os.times()
    return wall, (after.children_user - before.children_user) + (after.children_system - before.children_system)


def against_exiftool(files: int, repeat: int, before: str | None) -> None:
    exiftool = shutil.which("exiftool")
    if exiftool is None:
        print("\nexiftool is not installed: the comparison with ExifTool is skipped")
        return
    version = subprocess.run([exiftool, "-ver"], capture_output=True, text=True, check=True).stdout.strip()
    with tempfile.TemporaryDirectory() as tmp, tempfile.TemporaryDirectory() as old:
        for i in range(files):
            shutil.copyfile(DATA / IMAGES[i % len(IMAGES)], Path(tmp) / f"img{i:05d}.jpg")
        cases: dict[str, tuple[list[str], Path]] = {}
        if before:
            export(before, Path(old))
            cases[f"camtool exif -r DIR --format json ({before})"] = (
                [PY, "-m", "camtool", "exif", "-r", tmp, "--format", "json"], Path(old))
        commands = {
            "camtool exif -r DIR --format json": [PY, "-m", "camtool", "exif", "-r", tmp, "--format", "json"],
            "camtool exif --exiftool -r DIR --format json": [PY, "-m", "camtool", "exif", "--exiftool", "-r", tmp,
                                                             "--format", "json"],
            f"exiftool {version} -j -n -Composite:all -r DIR": [exiftool, "-j", "-n", "-Composite:all", "-r", tmp],
            f"exiftool {version} -fast2 -j -n -Composite:all -r DIR": [exiftool, "-fast2", "-j", "-n",
                                                                       "-Composite:all", "-r", tmp],
        }
        cases.update({name: (argv, ROOT) for name, argv in commands.items()})
        for argv, cwd in cases.values():  # warm-up: byte-code, caches, the page cache
            _timed(argv, cwd)
        best: dict[str, tuple[float, float]] = dict.fromkeys(cases, (math.inf, math.inf))
        for _ in range(repeat):
            for name, (argv, cwd) in cases.items():
                wall, cpu = _timed(argv, cwd)
                best[name] = (min(best[name][0], wall), min(best[name][1], cpu))
    fastest = min((value for name, value in best.items() if name.startswith("exiftool")), key=lambda v: v[0])
    print(f"\n{files} files, best of {repeat} (interleaved)\n")
    print("| command | wall (s) | files/s | CPU (s) | ExifTool's fastest / this, wall | CPU |\n|---|---:|---:|---:|---:|---:|")
    for name, (wall, cpu) in best.items():
        print(f"| `{name}` | {wall:.2f} | {files / wall:.0f} | {cpu:.2f} | {fastest[0] / wall:.1f} | "
              f"{fastest[1] / cpu:.1f} |")


def export(ref: str, target: Path) -> None:
    archive = subprocess.run(["git", "archive", ref, "camtool", "lens_db"], cwd=ROOT, check=True,
                             capture_output=True).stdout
    with tarfile.open(fileobj=io.BytesIO(archive)) as tar:
        tar.extractall(target, filter="data")


def startup(repeat: int, before: str) -> None:
    env = {k: v for k, v in os.environ.items() if k not in {"PYTHONDONTWRITEBYTECODE", "PYTHONPATH"}}
    with tempfile.TemporaryDirectory() as tmp:
        export(before, Path(tmp))
        cases = {
            "python -c 'import click'": ([PY, "-c", "import click"], ROOT),
            f"camtool dof ... --format json ({before})": ([PY, *DOF], Path(tmp)),
            "camtool dof ... --format json (this tree)": ([PY, *DOF], ROOT),
        }
        for argv, cwd in cases.values():
            subprocess.run(argv, check=True, stdout=subprocess.DEVNULL, env=env, cwd=cwd)
        times: dict[str, list[float]] = {name: [] for name in cases}
        for _ in range(repeat):
            for name, (argv, cwd) in cases.items():
                start = time.perf_counter()
                subprocess.run(argv, check=True, stdout=subprocess.DEVNULL, env=env, cwd=cwd)
                times[name].append(time.perf_counter() - start)
    medians = {name: statistics.median(values) for name, values in times.items()}
    base = medians["python -c 'import click'"]
    print("\n| command | median (ms) | ratio to `import click` |\n|---|---:|---:|")
    for name, value in medians.items():
        print(f"| `{name}` | {value * 1000:.1f} | {value / base:.2f} |")
    names = list(medians)
    print(f"\nthis tree / {before}: {medians[names[2]] / medians[names[1]]:.3f}")


def main() -> None:
    parser = argparse.ArgumentParser(description=(__doc__ or "").splitlines()[0])
    parser.add_argument("--files", type=int, default=1000)
    parser.add_argument("--repeat", type=int, default=20)
    parser.add_argument("--before", default="main", help="git ref without the exif command")
    parser.add_argument("--against-exiftool", type=int, default=10000, metavar="N",
                        help="files for the comparison with exiftool (0: skip it)")
    parser.add_argument("--exiftool-repeat", type=int, default=2)
    parser.add_argument("--skip-startup", action="store_true")
    args = parser.parse_args()
    print("| run | time | rate |\n|---|---:|---:|")
    throughput(args.files)
    if args.against_exiftool:
        against_exiftool(args.against_exiftool, args.exiftool_repeat, args.before)
    if not args.skip_startup:
        startup(args.repeat, args.before)


if __name__ == "__main__":
    main()
