"""Cost of the preset database on a command's start-up, with and without a lensfun import.

Run: ``python benchmarks/bench_presets.py [--runs 21]``

Each figure is the median wall time of a fresh ``python -c ...`` process (what a
shell script pays per call), measured in one run on this machine:

- ``import click`` -- the docs/design.md §7 start-up reference;
- ``load_db() + lens lookup`` with the shipped presets only;
- the same with a generated lensfun import of 2,000 presets (1,000 cameras with
  their sensors, 1,000 lenses) in ``$XDG_DATA_HOME/camtool/lensfun.yaml``, shaped
  like the import's output;
- both again with a cold cache (``CAMTOOL_NO_CACHE=1``: every file parsed as YAML).

It prints the ratios the budgets are stated in: load+lookup with the import
over without it (budget 1.2), and ``import click`` + load+lookup over
``import click`` alone (the presets' share of the 2x start-up budget).
Byte-code is written to a temporary ``PYTHONPYCACHEPREFIX`` and warmed first,
so the figures are those of an installed camtool.
"""

from __future__ import annotations

import argparse
import os
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

REPO = Path(__file__).resolve().parent.parent
LOOKUP = "import click; from camtool.presets import load_db; load_db().lens('canon-rf-50mm-f1.8-stm')"


def write_lensfun_like(path: Path, count: int = 2000) -> None:
    """A preset file shaped like an import of the lensfun database, ``count`` entries."""
    half = count // 2
    lines = ["cameras:"]
    for i in range(half):
        crop = 1.0 + (i % 50) / 10
        lines.append(f"- {{id: bench-camera-{i}, name: Bench Camera {i}, aliases: [Bench BC-{i}], "
                     f"sensor: {{width_mm: {36 / crop:.3f}, height_mm: {24 / crop:.3f}}}, mount: Bench, "
                     f"approximate: true, source: 'lensfun bench.xml: crop factor {crop:g}, sensor size derived'}}")
    lines.append("lenses:")
    for i in range(count - half):
        low = 10 + i % 90
        lines.append(f"- {{id: bench-lens-{i}-{low}-{low * 3}mm, name: Bench {low}-{low * 3}mm f/3.5-5.6 No. {i}, "
                     f"focal_min_mm: {low}, focal_max_mm: {low * 3}, f_number_min: 3.5, f_number_min_tele: 5.6, "
                     f"mount: Bench, source: lensfun bench.xml (calibrated at crop factor 1.5)}}")
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_text("\n".join(lines) + "\n", encoding="utf-8")


def wall(code: str, env: dict[str, str], runs: int) -> float:
    """Median wall time in seconds of ``python -c code``."""
    times = []
    for _ in range(runs):
        start = time.perf_counter()
        subprocess.run([sys.executable, "-c", code], env=env, check=True, cwd=REPO)
        times.append(time.perf_counter() - start)
    return statistics.median(times)


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--runs", type=int, default=21)
    args = parser.parse_args()
    with tempfile.TemporaryDirectory() as tmp:
        root = Path(tmp)
        base = {k: v for k, v in os.environ.items() if k not in {"PYTHONDONTWRITEBYTECODE", "CAMTOOL_NO_CACHE"}}
        base.update(PYTHONPATH=str(REPO), PYTHONPYCACHEPREFIX=str(root / "pyc"), XDG_CONFIG_HOME=str(root / "config"),
                    XDG_CONFIG_DIRS=str(root / "etc"), XDG_CACHE_HOME=str(root / "cache"))
        without = {**base, "XDG_DATA_HOME": str(root / "data-empty")}
        with_import = {**base, "XDG_DATA_HOME": str(root / "data")}
        write_lensfun_like(root / "data" / "camtool" / "lensfun.yaml")
        for env in (without, with_import):  # warm byte-code and the preset cache
            wall(LOOKUP, env, 2)
        click_s = wall("import click", base, args.runs)
        plain_s = wall(LOOKUP, without, args.runs)
        imported_s = wall(LOOKUP, with_import, args.runs)
        cold_plain_s = wall(LOOKUP, {**without, "CAMTOOL_NO_CACHE": "1"}, max(5, args.runs // 3))
        cold_imported_s = wall(LOOKUP, {**with_import, "CAMTOOL_NO_CACHE": "1"}, max(5, args.runs // 3))
    print(f"median wall time of a fresh process, {args.runs} runs each")
    print(f"  import click                                   {click_s * 1e3:7.1f} ms")
    print(f"  click + load_db + lens lookup, shipped only    {plain_s * 1e3:7.1f} ms  ({plain_s / click_s:.2f}x click)")
    print(f"  ... with a 2,000-preset lensfun import         {imported_s * 1e3:7.1f} ms  "
          f"({imported_s / click_s:.2f}x click)")
    print(f"  ... shipped only, no cache (YAML parsed)       {cold_plain_s * 1e3:7.1f} ms")
    print(f"  ... with the import, no cache (YAML parsed)    {cold_imported_s * 1e3:7.1f} ms")
    print(f"ratio with import / without (budget 1.2):        {imported_s / plain_s:.3f}")


if __name__ == "__main__":
    main()
