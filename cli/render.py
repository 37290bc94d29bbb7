"""Rendering of calculator results: a rich table, or JSON mapping each name to {"value", "unit"}."""

import json
from collections.abc import Mapping
from typing import TYPE_CHECKING, Any

import numpy as np
from rich.console import Console
from rich.markup import escape
from rich.table import Table

if TYPE_CHECKING:
    from astropy.units import Quantity


def to_json(quantities: "Mapping[str, Quantity]") -> str:
    """JSON text {name: {"value": number or nested list, "unit": str}}."""
    out = {}
    for name, q in quantities.items():
        value = np.asarray(q.value)
        out[name] = {"value": value.tolist(), "unit": q.unit.to_string()}
    return json.dumps(out, indent=2)


def _format(value):
    value = np.asarray(value)
    if value.ndim == 0:
        return f"{float(value):.16g}"
    return np.array2string(value, precision=16, max_line_width=100)


def table(title: str, quantities: "Mapping[str, Quantity]") -> None:
    """Print a two-column table of quantities with their units."""
    grid = Table(title=title)
    grid.add_column("quantity", style="cyan")
    grid.add_column("value", justify="right")
    grid.add_column("unit")
    for name, q in quantities.items():
        grid.add_row(name, _format(q.value), q.unit.to_string() or "")
    Console().print(grid)


def emit(title: str, quantities: "Mapping[str, Quantity]", fmt: str) -> None:
    """Print quantities in the chosen format ("table" or "json")."""
    if fmt == "json":
        print(to_json(quantities))
    else:
        table(title, quantities)


def _number(x):
    return "-" if x is None else f"{x:.3g}"


def _wide_console():
    """A console as wide as the terminal, or 140 columns when the output is piped to a file."""
    console = Console()
    return console if console.is_terminal else Console(width=140)


def validation_report(data: dict[str, Any]) -> None:
    """Print a validation report (the dict of ValidationReport.to_dict) as one table per scene."""
    console = _wide_console()
    for scene in data["scenes"]:
        backends = list(scene["wall_time_s"])[1:]
        grid = Table(title=f"{scene['name']}: {scene['description']}", title_justify="left")
        grid.add_column("check", style="cyan", no_wrap=True, min_width=30)
        grid.add_column("analytic", justify="right", no_wrap=True)
        for name in backends:
            grid.add_column(f"{name} error", justify="right", no_wrap=True)
        grid.add_column("ulps", justify="right", no_wrap=True)
        grid.add_column("tolerance", justify="right", no_wrap=True)
        grid.add_column("pass", no_wrap=True)
        for check in scene["checks"]:
            ulps = [check["ulps"][b] for b in backends if check["ulps"][b] is not None]
            grid.add_row(
                escape(check["quantity"] + (f" ({check['unit']})" if check["unit"] else "")),
                _number(check["analytic"]),
                *(_number(check["errors"][b]) for b in backends),
                " / ".join(f"{x:.3g}" for x in ulps) or "-",
                f"{check['tolerance']:.0e} {check['kind'].split()[0][:3]}",
                "[green]yes[/green]" if check["passed"] else "[red]NO[/red]",
            )
        console.print(grid)
        setup = scene["setup_time_s"]
        times = ", ".join(
            f"{k} {v * 1e3:.1f} ms" + (f" (+ setup {setup[k] * 1e3:.1f} ms)" if k in setup else "")
            for k, v in scene["wall_time_s"].items()
        )
        console.print(f"  wall time: {times}")
        for name in backends:
            settings = ", ".join(f"{k}={v}" for k, v in scene["settings"][name].items())
            console.print(escape(f"  {name} {scene['versions'][name]}: {settings}; {scene['time_modes'][name]}"))
    verdict = "[green]all checks passed[/green]" if data["passed"] else "[red]some checks FAILED[/red]"
    console.print(f"\n{verdict} ({len(data['scenes'])} scenes)")


def precision_tables(data: dict[str, Any]) -> None:
    """Print the work-precision summary: per problem, each method's best error and its fastest run at target."""
    console = _wide_console()
    grid = Table(title=f"work-precision: best error, and the fastest run reaching {data['target']:.0e}")
    for name in ("problem", "method", "best error", "at", "time", f"fastest <= {data['target']:.0e}", "time"):
        grid.add_column(name, no_wrap=True, justify="left" if name in ("problem", "method") else "right")
    for row in data["summary"]:
        fastest = row["fastest_at_target"] or "not reached"
        grid.add_row(row["problem"], row["method"], f"{row['best_error']:.2e}", row["best_setting"],
                     f"{row['best_seconds'] * 1e3:.2f} ms", fastest,
                     "-" if row["fastest_seconds"] is None else f"{row['fastest_seconds'] * 1e3:.2f} ms")
    console.print(grid)
    notes = {r["note"] for r in data["rows"] if r["note"]}
    for note in sorted(notes):
        console.print(escape(f"  note: {note}"))
