"""``camtool exif``: files per second over 1,000 images, and ``camtool dof``'s start-up before and after.

1. Throughput: a temporary directory of 1,000 tiny JPEGs (the six readable
   test images of tests/data/exif, copied round-robin), read with
   ``camtool exif --recursive DIR --format json`` (one process, the whole
   directory; default options, so ``--model auto``) and, in-process, with
   :func:`camtool.exif.reader.read_file` alone (the reading share).
2. Start-up: ``camtool dof -f 50 -N 8 -s 3m --format json`` of this tree
   against the same command of a git ref without the exif command (``--before``,
   default ``main``; exported with ``git archive`` to a temporary directory,
   nothing else touched), each as ``python -m camtool`` and interleaved with
   ``python -c "import click"``; the ratios to that baseline are compared.

Run: ``python benchmarks/bench_exif.py [--files 1000] [--repeat 20] [--before main]``
"""

from __future__ import annotations

import argparse
import io
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
        subprocess.run(argv, check=True, stdout=subprocess.DEVNULL, cwd=ROOT)  # warm-up (byte-code, caches)
        runs = []
        for _ in range(3):
            start = time.perf_counter()
            subprocess.run(argv, check=True, stdout=subprocess.DEVNULL, cwd=ROOT)
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
    args = parser.parse_args()
    print("| run | time | rate |\n|---|---:|---:|")
    throughput(args.files)
    startup(args.repeat, args.before)


if __name__ == "__main__":
    main()
