"""`orbits bench all`: every benchmark in one run, one table each under its name, one JSON object {name: rows}."""

from collections.abc import Iterable, Mapping, Sequence
from typing import Any

from orbits.tools.bench.api import bench_api, format_api
from orbits.tools.bench.call import bench_call, format_call
from orbits.tools.bench.cli import bench_cli, format_cli
from orbits.tools.bench.ephemeris import bench_ephemeris, format_ephemeris
from orbits.tools.bench.kepler import bench_kepler, format_rows
from orbits.tools.bench.lambert import bench_lambert, format_lambert
from orbits.tools.bench.periodic import bench_periodic, format_periodic
from orbits.tools.bench.propagate import bench_propagate, format_propagate
from orbits.tools.bench.stm import bench_stm, format_stm
from orbits.tools.bench.table import rows_to_json
from orbits.tools.bench.validate import bench_validate, format_validate

#: every benchmark: name -> (run with default sizes, format), in the order `orbits bench all` runs them
BENCHMARKS = {
    "kepler": (bench_kepler, format_rows),
    "propagate": (bench_propagate, format_propagate),
    "stm": (bench_stm, format_stm),
    "lambert": (bench_lambert, format_lambert),
    "periodic": (bench_periodic, format_periodic),
    "ephemeris": (bench_ephemeris, format_ephemeris),
    "api": (bench_api, format_api),
    "call": (bench_call, format_call),
    "cli": (bench_cli, format_cli),
    "validate": (bench_validate, format_validate),
}


def bench_all(names: Sequence[str] | None = None, **options: dict[str, Any]) -> dict[str, list[Any]]:
    """{name: rows} of every benchmark (or those in `names`, in the suite's order); options maps a benchmark name
    to its keyword arguments."""
    return {name: run(**options.get(name, {})) for name, (run, _) in BENCHMARKS.items()
            if names is None or name in names}


def format_report(report: Mapping[str, Sequence[Any]]) -> str:
    """Every benchmark's table under its name."""
    return "\n\n".join(f"== {name} ==\n{BENCHMARKS[name][1](rows)}" for name, rows in report.items())


def report_to_json(report: Mapping[str, Iterable[object]]) -> dict[str, list[dict[str, object]]]:
    """{name: rows as JSON-ready dicts} (NaN and infinity become None)."""
    return {name: rows_to_json(rows) for name, rows in report.items()}
