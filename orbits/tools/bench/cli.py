"""`orbits bench cli`: cold start of the command line, as the median of repeated fresh processes, and the first
run on a fresh install (empty kernel cache) against the second.
"""

import os
import shutil
import statistics
import subprocess
import sys
import tempfile
import time
from collections.abc import Sequence
from dataclasses import dataclass

from orbits.tools.bench.harness import check_sizes
from orbits.tools.bench.table import plain_table

#: (arguments of `orbits`, target wall time in seconds or None) of bench_cli.
CLI_COMMANDS = [
    (["--help"], 0.2),
    (["orbit", "--primary", "Earth", "--a", "42164 km", "--only", "period,speed"], 0.6),
    (["kepler", "--e", "0.9", "--M", "0.1 rad"], 0.5),
]


@dataclass(frozen=True)
class CliRow:
    """Wall time of `runs` fresh processes running one command: median and fastest; the target (s) or None."""

    command: str
    runs: int
    median_seconds: float
    min_seconds: float
    target_seconds: float | None


def _orbits_command():
    """The installed `orbits` script, or the same entry point through this interpreter."""
    script = shutil.which("orbits")
    return [script] if script else [sys.executable, "-c", "from orbits_cli.main import app; app()"]


#: imports every command pays before orbits does anything, timed the same way (fresh processes of this Python):
#: the floor under the cold-start targets on this machine
FLOOR_IMPORTS = ["numpy", "astropy.units"]

#: (arguments of `orbits`, target seconds or None, largest ratio to the warm run or None) of the first runs
#: bench_cli times: once with an empty kernel cache, as on a fresh install, then once more with the cache that
#: run left
FIRST_RUN_COMMANDS = [
    (["kepler", "--e", "0.9", "--M", "0.1 rad"], 1.0, None),
    (["validate", "--format", "json"], None, 1.5),
]


def bench_cli(runs: int = 10, commands: Sequence[tuple[list[str], float | None]] | None = None,
              first_runs: Sequence[tuple[list[str], float | None, float | None]] | None = None) -> list[CliRow]:
    """Cold-start wall time of each command over `runs` fresh processes (one unmeasured warm-up run
    fills the OS file cache, as on any machine that has run orbits before), after the FLOOR_IMPORTS alone (by
    default, that is when no commands are given); then each of `first_runs`
    (FIRST_RUN_COMMANDS when neither list is given) timed once with NUMBA_CACHE_DIR a new empty folder (what a
    new user waits for: anything compiled on first use) and once more warm, the target of the first run being
    its own, or its ratio to the warm run times the warm time."""
    check_sizes(runs=runs)
    rows = []
    floors = [([sys.executable, "-c", f"import {name}"], f"floor: python -c 'import {name}'")
              for name in (FLOOR_IMPORTS if commands is None else [])]
    timed = [(_orbits_command() + args, "orbits " + " ".join(args), target)
             for args, target in (CLI_COMMANDS if commands is None else commands)]
    for argv, label, target in [(argv, label, None) for argv, label in floors] + timed:
        _process_times(argv, 1)  # the warm-up run
        times = _process_times(argv, runs)
        rows.append(CliRow(label, runs, statistics.median(times), min(times), target))
    for args, target, ratio in (FIRST_RUN_COMMANDS if commands is None and first_runs is None else first_runs or []):
        first, warm = _first_and_warm(_orbits_command() + args)
        command = "orbits " + " ".join(args)
        rows.append(CliRow(f"{command} (first ever: empty kernel cache)", 1, first, first,
                           target if ratio is None else ratio * warm))
        rows.append(CliRow(f"{command} (second run, warm cache)", 1, warm, warm, None))
    return rows


def _first_and_warm(argv: list[str]) -> tuple[float, float]:
    """Wall times (s) of argv run twice in fresh processes sharing a new, empty numba cache folder."""
    with tempfile.TemporaryDirectory(prefix="orbits-bench-cache-") as folder:
        first, warm = _process_times(argv, 2, {**os.environ, "NUMBA_CACHE_DIR": folder})
    return first, warm


def _process_times(argv: list[str], runs: int, environment: dict[str, str] | None = None) -> list[float]:
    """Wall time (s) of each of `runs` fresh processes running argv (which must exit 0)."""
    times = []
    for _ in range(runs):
        start = time.perf_counter()
        subprocess.run(argv, capture_output=True, check=True, env=environment)
        times.append(time.perf_counter() - start)
    return times


def format_cli(rows: Sequence[CliRow]) -> str:
    """Plain-text table of bench_cli, at most 80 columns (a long command wraps onto indented lines)."""
    table = [
        [r.command, str(r.runs), f"{r.median_seconds:.3f}", f"{r.min_seconds:.3f}",
         f"{r.target_seconds:.2f}" if r.target_seconds else "-"]
        for r in rows
    ]
    return "\n".join(plain_table(["command", "runs", "median s", "min s", "target s"], table))
