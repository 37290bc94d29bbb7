"""Rendering of calculator results: a rich table, or JSON mapping each name to {"value", "unit"}."""

import json

import numpy as np
from rich.console import Console
from rich.table import Table


def to_json(quantities):
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


def table(title, quantities):
    """Print a two-column table of quantities with their units."""
    grid = Table(title=title)
    grid.add_column("quantity", style="cyan")
    grid.add_column("value", justify="right")
    grid.add_column("unit")
    for name, q in quantities.items():
        grid.add_row(name, _format(q.value), q.unit.to_string() or "")
    Console().print(grid)


def emit(title, quantities, fmt):
    """Print quantities in the chosen format ("table" or "json")."""
    if fmt == "json":
        print(to_json(quantities))
    else:
        table(title, quantities)
