"""Timing helpers the benchmark scripts share (run them as ``python benchmarks/NAME.py``)."""

from __future__ import annotations

import statistics
import subprocess
import time
from collections.abc import Callable


def best(fn: Callable[[], object], repeat: int) -> float:
    """The shortest of ``repeat`` wall times of ``fn()``, in seconds."""
    times = []
    for _ in range(repeat):
        start = time.perf_counter()
        fn()
        times.append(time.perf_counter() - start)
    return min(times)


def interleaved_medians(cases: dict[str, list[str]], repeat: int, env: dict[str, str]) -> dict[str, float]:
    """Median wall time of each command, run ``repeat`` times in turn (A B C A B C ...) after one warm-up each.

    Interleaving lets machine noise hit every command alike; the warm-up writes byte-code and caches once.
    """
    for argv in cases.values():
        subprocess.run(argv, check=True, stdout=subprocess.DEVNULL, env=env)
    times: dict[str, list[float]] = {name: [] for name in cases}
    for _ in range(repeat):
        for name, argv in cases.items():
            start = time.perf_counter()
            subprocess.run(argv, check=True, stdout=subprocess.DEVNULL, env=env)
            times[name].append(time.perf_counter() - start)
    return {name: statistics.median(values) for name, values in times.items()}


def report(medians: dict[str, float], budgets: list[tuple[str, str, float]]) -> None:
    """Print the medians (ms) and each budget's ratio and verdict as Markdown tables."""
    print("| command | median wall time (ms) |\n|---|---:|")
    for name, value in medians.items():
        print(f"| `{name}` | {value * 1000:.1f} |")
    print("\n| budget | ratio | limit | verdict |\n|---|---:|---:|---|")
    for name, reference, limit in budgets:
        ratio = medians[name] / medians[reference]
        print(f"| `{name}` / `{reference}` | {ratio:.2f} | {limit:.1f} | {'ok' if ratio <= limit else 'OVER'} |")
