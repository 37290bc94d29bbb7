"""Rendering of calculator results: tables a person reads in 80 columns, or strict JSON with full precision.

Tables show each quantity in the unit orbits._common.display chooses (natural units by default, `--units si`, a
per-quantity `--unit NAME=UNIT`, `--digits N`). JSON carries every value exactly as the library returns it, the
float64 bit for bit with its unit ({name: {"value", "unit"}}, SI with angles in rad); a non-finite value, which
JSON (RFC 8259) cannot hold, is the string "inf", "-inf" or "nan", which float() reads back.
"""

import json
import math
from collections.abc import Mapping, Sequence
from dataclasses import dataclass, field
from typing import TYPE_CHECKING, Any

import numpy as np
from rich import box
from rich.console import Console
from rich.markup import escape
from rich.table import Table

if TYPE_CHECKING:
    from astropy.units import Quantity

#: the width every table is laid out for
WIDTH = 80


@dataclass(frozen=True)
class Display:
    """How tables show quantities: unit system, per-quantity unit overrides and significant digits."""

    system: str = "natural"
    overrides: Mapping[str, str] = field(default_factory=dict)
    digits: int = 7


#: set once per command by orbits_cli.options.displays, from --units, --unit and --digits
DISPLAY = Display()


def use(display: Display) -> None:
    """Make `display` the way the following tables are shown."""
    global DISPLAY
    DISPLAY = display


def console() -> Console:
    """A console no wider than WIDTH columns, without rich's highlighting of numbers and paths."""
    width = min(Console().width, WIDTH)
    return Console(width=width, highlight=False, soft_wrap=False)


# ---- JSON ------------------------------------------------------------------------------------------------


def json_value(x: Any) -> Any:
    """A float, a nested list of floats, or for a non-finite float its name as a string ("inf", "-inf", "nan")."""
    if isinstance(x, (list, tuple)):
        return [json_value(v) for v in x]
    if isinstance(x, float) and not math.isfinite(x):
        return "nan" if math.isnan(x) else ("inf" if x > 0 else "-inf")
    return x


def dumps(data: Any) -> str:
    """Strict JSON text (RFC 8259: no NaN or Infinity tokens) of `data`, non-finite floats named as strings."""
    def clean(obj):
        if isinstance(obj, dict):
            return {k: clean(v) for k, v in obj.items()}
        if isinstance(obj, (list, tuple)):
            return [clean(v) for v in obj]
        if isinstance(obj, (float, np.floating)):
            return json_value(float(obj))
        if isinstance(obj, np.integer):
            return int(obj)
        if isinstance(obj, np.ndarray):
            return clean(obj.tolist())
        return obj

    return json.dumps(clean(data), indent=2, allow_nan=False)


def to_json(quantities: "Mapping[str, Quantity]", about: "Mapping[str, str] | None" = None) -> str:
    """JSON text {name: {"value": float or nested list, "unit": str}}: the library's float64 values bit for bit,
    in the units the library returns them (SI, angles in rad); "" for a pure number. `about` (what answered, its
    accuracy, the epoch) goes first, under the key "about", as strings."""
    out = {} if about is None else {"about": dict(about)}
    for name, q in quantities.items():
        out[name] = {"value": np.asarray(q.value).tolist(), "unit": q.unit.to_string()}
    return dumps(out)


# ---- tables ----------------------------------------------------------------------------------------------


def _shown(q, name, unit=None):
    from orbits._common.display import shown

    return shown(q, name, DISPLAY.system, DISPLAY.overrides, DISPLAY.digits, unit)


def number(x: float) -> str:
    """x with the display's significant digits (orbits._common.display.number)."""
    from orbits._common.display import number as display_number

    return display_number(x, DISPLAY.digits)


def _label(name: str) -> str:
    """A column header: the quantity's name with spaces, so that it wraps."""
    return name.replace("_", " ")


def quantity_table(title: str, quantities: "Mapping[str, Quantity]", prefix: str = "") -> Table:
    """A table of rows quantity | value | unit; `prefix` is what the names lost in grouping (for --unit)."""
    grid = Table(title=escape(title) or None, title_justify="left", box=box.SIMPLE_HEAD, pad_edge=False)
    grid.add_column("quantity", overflow="fold")
    grid.add_column("value", justify="right", overflow="fold")
    grid.add_column("unit", overflow="fold")
    from orbits._common.display import table_units

    units = table_units({prefix + name: q for name, q in quantities.items()}, DISPLAY.system, DISPLAY.overrides)
    for name, q in quantities.items():
        value, unit = _shown(q, prefix + name, units[prefix + name])
        grid.add_row(escape(name), value, escape(unit))
    return grid


def _grid(columns):
    """A table whose headers are wrapped to the width of their numbers (10 columns at least), so that nothing
    in it wraps again and its measured width is the width it prints at."""
    from orbits._common.display import wrapped

    grid = Table(box=box.SIMPLE_HEAD, pad_edge=False)
    for header, cells in columns:
        lines = wrapped(header, max(10, *map(len, cells)))
        grid.add_column(escape("\n".join(lines)), justify="right", no_wrap=True)
    for row in zip(*(cells for _, cells in columns)):
        grid.add_row(*row)
    return grid


def _fits(grid, width):
    out = Console(width=10 * width)
    return grid.__rich_measure__(out, out.options).maximum <= width


def column_tables(index: tuple[str, list[str]], columns: list[tuple[str, list[str]]]) -> list[Table]:
    """Tables of one row per element, as many columns to a table as fit WIDTH (the numbers never wrap), each
    table repeating the index column. `index` and `columns` are (header, [cell texts]) pairs."""
    tables, current = [], []
    for column in columns:
        if current and not _fits(_grid([index, *current, column]), WIDTH):
            tables.append(_grid([index, *current]))
            current = []
        current.append(column)
    tables.append(_grid([index, *current]))
    return tables


def column(name: str, q: "Quantity", header: str | None = None, like: "Quantity | None" = None
           ) -> tuple[str, list[str]]:
    """(header "name [unit]", one cell per element) of a 1-D quantity, in the display unit of q (or of `like`,
    so that the components of one vector share a unit)."""
    from orbits._common.display import in_unit, number, unit_for, unit_text

    unit = unit_for(q if like is None else like, name, DISPLAY.system, DISPLAY.overrides)
    cells = [number(v, DISPLAY.digits) for v in np.ravel(in_unit(q, unit, name))]
    header = _label(name) if header is None else header
    return header + (f" [{unit_text(unit, compact=True)}]" if unit_text(unit) else ""), cells


def element_tables(index: str, quantities: "Mapping[str, Quantity]") -> list[Table]:
    """One row per element of the 1-D quantity `index` (e.g. one row per redshift), one column per quantity of
    the same length, packed into as many tables as 80 columns need; scalars go to a table of their own."""
    size = np.size(quantities[index])
    rows, scalars = {}, {}
    for name, q in quantities.items():
        (rows if np.ndim(q) == 1 and np.size(q) == size else scalars)[name] = q
    columns = []
    for name, q in rows.items():
        columns.append(column(name, q))
    tables = column_tables(columns[0], columns[1:])
    if scalars:
        tables.append(quantity_table("", scalars))
    return tables


def grouped_tables(quantities: "Mapping[str, Quantity]", groups: Sequence[tuple[str, str]]) -> list[Table | str]:
    """One table per group of quantities, each after its heading (a line print_tables wraps to the console's
    width, not the table's): `groups` lists (name prefix, heading); the prefix is dropped from the names;
    quantities matching no prefix come first."""
    title = ""
    sections: dict[str, tuple[str, dict]] = {title: ("", {})}
    for prefix, heading in groups:
        sections.setdefault(heading, (prefix, {}))
    for name, q in quantities.items():
        match = next(((p, h) for p, h in groups if name.startswith(p)), None)
        if match is None:
            sections[title][1][name] = q
        else:
            sections[match[1]][1][name.removeprefix(match[0])] = q
    shown: list[Table | str] = []
    for heading, (prefix, table) in sections.items():
        if table:
            shown += [heading, quantity_table("", table, prefix)] if heading else [quantity_table("", table, prefix)]
    return shown


def print_tables(tables: Sequence[Table | str], title: str = "") -> None:
    """Print the title wrapped to the console's width, then the tables (a string among them is a heading, wrapped
    the same way)."""
    from orbits._common.display import filled

    out = console()
    if title:
        out.print(escape(filled(title, out.width)))
    for grid in tables:
        out.print(escape(filled(grid, out.width)) if isinstance(grid, str) else grid)


def emit(title: str, quantities: "Mapping[str, Quantity]", fmt: str, *, index: str | None = None,
         groups: Sequence[tuple[str, str]] = (), about: "Mapping[str, str] | None" = None,
         notes: str = "") -> None:
    """Print quantities as JSON (with `about`, see to_json), or as tables under the title: one row per element of
    `index` when given, grouped by name prefix when `groups` are given, else one row per quantity; `notes` (where
    the numbers come from, how far to trust them) follow the tables, so that the answer comes first."""
    unknown = sorted(set(DISPLAY.overrides) - set(quantities))
    if unknown:
        raise ValueError(f"--unit {', '.join(unknown)}: no such quantity here; choose from {', '.join(quantities)}")
    if fmt == "json":
        print(to_json(quantities, about))
    elif index is not None and index in quantities and np.ndim(quantities[index]) == 1:
        print_tables(element_tables(index, quantities), title)
    elif groups:
        print_tables(grouped_tables(quantities, groups), title)
    else:
        print_tables([quantity_table("", quantities)], title)
    if notes and fmt != "json":
        print_tables([notes])


# ---- the validation report ---------------------------------------------------------------------------------


def _error(x):
    from orbits._common.display import number

    return "-" if x is None else number(x, 2)


def _analytic(check):
    """The analytic value in its display unit, for the check's label."""
    if check["analytic"] is None or check["kind"] != "relative error":
        return ""
    import astropy.units as u

    from orbits._common.display import number, quantity_text

    try:
        return " = " + quantity_text(u.Quantity(check["analytic"], check["unit"] or u.one))
    except ValueError:  # a code unit such as "1 / time unit": shown as it is
        return f" = {number(check['analytic'])} {check['unit']}".rstrip()


_KINDS = {"relative error": "rel", "relative drift": "rel drift", "absolute drift": "abs drift"}


def validation_report(data: dict[str, Any]) -> None:
    """Print a validation report (the dict of ValidationReport.to_dict): per scene its verdict, then one line
    per check led by its verdict, each backend's error and the tolerance; settings follow as plain lines."""
    from orbits._common.display import (
        filled,
        printable,
        # text from scene files: no control character reaches the terminal,
    )

    out = console()
    def line(text):
        return escape(filled(text, out.width, initial_indent="  ", subsequent_indent="    "))

    for scene in data["scenes"]:
        backends = list(scene["wall_time_s"])[1:]
        verdict = "[green]passed[/green]" if scene["passed"] else "[red]FAILED[/red]"
        out.print(f"[bold]{escape(printable(scene['name']))}[/bold]: {verdict}")
        out.print(escape(filled(printable(scene["description"]), out.width, initial_indent="  ",
                                       subsequent_indent="  ")))
        grid = Table(box=box.SIMPLE_HEAD, pad_edge=False, padding=(0, 1))
        grid.add_column("", no_wrap=True)
        grid.add_column("check", overflow="fold", ratio=1)
        for name in backends:
            grid.add_column(escape(name), justify="right", no_wrap=True)
        grid.add_column("tolerance", justify="right", no_wrap=True)
        for check in scene["checks"]:
            mark = "[green]pass[/green]" if check["passed"] else "[red]FAIL[/red]"
            grid.add_row(mark, escape(printable(check["quantity"]) + _analytic(check)),
                         *(_error(check["errors"].get(b)) for b in backends),
                         f"{_error(check['tolerance'])} {_KINDS.get(check['kind'], check['kind'])}")
        out.print(grid)
        setup = scene["setup_time_s"]
        times = ", ".join(
            f"{k} {v * 1e3:.1f} ms" + (f" (+ setup {setup[k] * 1e3:.1f} ms)" if k in setup else "")
            for k, v in scene["wall_time_s"].items()
        )
        out.print(line(f"wall time: {times}"))
        for name in backends:
            settings = ", ".join(f"{k}={v}" for k, v in scene["settings"][name].items())
            out.print(line(f"{name} {scene['versions'][name]}: {settings}; {scene['time_modes'][name]}"))
        out.print()
    validation_summary(data)


def validation_summary(data: dict[str, Any]) -> None:
    """One row per scene, one screen for the built-in set: each backend's worst check as a fraction of its
    tolerance (at most 1 passes; the check's kind and size are in the full report), the scene's run time, and a
    last line naming the scenes that failed."""
    from orbits._common.display import printable

    out = console()
    backends = list(dict.fromkeys(b for scene in data["scenes"] for b in list(scene["wall_time_s"])[1:]))
    out.print("worst error / tolerance per scene (at most 1 passes)")
    grid = Table(box=box.SIMPLE_HEAD, pad_edge=False, padding=(0, 1))
    grid.add_column("scene", no_wrap=True, overflow="ellipsis", max_width=34)
    grid.add_column("", no_wrap=True)
    for name in backends:
        grid.add_column(escape(name), justify="right", no_wrap=True)
    grid.add_column("time", justify="right", no_wrap=True)
    for scene in data["scenes"]:
        mark = "[green]pass[/green]" if scene["passed"] else "[red]FAIL[/red]"
        used = [_worst_share(scene, name) for name in backends]
        grid.add_row(escape(printable(scene["name"])), mark, *(_share(u) for u in used),
                     _seconds(sum(scene["wall_time_s"].values())))
    out.print(grid)
    failed = [scene["name"] for scene in data["scenes"] if not scene["passed"]]
    if failed:
        out.print(escape(f"{len(failed)} of {len(data['scenes'])} scenes FAILED: {', '.join(failed)}"),
                  style="red")
    else:
        checks = sum(len(scene["checks"]) for scene in data["scenes"])
        out.print(f"[green]all {checks} checks of {len(data['scenes'])} scenes passed[/green]")


def _worst_share(scene: dict[str, Any], backend: str) -> float | None:
    """max over the scene's checks of |error| / tolerance for `backend` (None where it ran no check)."""
    shares = [check["errors"][backend] / check["tolerance"] for check in scene["checks"]
              if check["errors"].get(backend) is not None and check["tolerance"]]
    return max(shares) if shares else None


def _share(share: float | None) -> str:
    if share is None:
        return "-"
    text = f"{share:.2g}"
    return text if share <= 1.0 else f"[red]{text}[/red]"


def _seconds(seconds: float | None) -> str:
    """A run time in us, ms or s, 3 significant digits ("-" for none); the unit is chosen after rounding, so
    999.96 us reads "1 ms", never "1e+03 us"."""
    if seconds is None:
        return "-"
    rounded = float(f"{seconds:.3g}")
    if rounded < 1e-3:
        return f"{rounded * 1e6:.3g} us"
    return f"{rounded * 1e3:.3g} ms" if rounded < 1 else f"{rounded:.3g} s"


def _setting(setting: Any) -> str:
    """A knob setting in few characters: "epsilon=1e-07" -> "eps 1e-07", "steps per period=300" -> "300 steps/P"."""
    text = str(setting)
    if text.startswith("steps per period="):
        return text.removeprefix("steps per period=") + " steps/P"
    return text.replace("epsilon=", "eps ").replace("rtol=", "rtol ").replace("tol=", "tol ")


def precision_tables(data: dict[str, Any]) -> None:
    """Print the work-precision summary, one table per problem: each method's best error with its setting and run
    time, and its fastest run reaching the target."""
    from orbits._common.display import filled

    out = console()
    target = _error(data["target"])
    out.print(f"work-precision: each method's best position error (relative to the orbit's size), and its fastest "
              f"run reaching {target}")
    problems = list(dict.fromkeys(row["problem"] for row in data["summary"]))
    for problem in problems:
        grid = Table(title=escape(problem), title_justify="left", box=box.SIMPLE_HEAD, pad_edge=False)
        for name in ("method", "error", "at", "time", f"to {target}", "time"):
            grid.add_column(escape(name), justify="left" if name == "method" else "right", no_wrap=True)
        for row in (r for r in data["summary"] if r["problem"] == problem):
            fastest = row["fastest_at_target"]
            method = row["method"].replace("high_accuracy", "high acc.")
            grid.add_row(escape(method), _error(row["best_error"]), escape(_setting(row["best_setting"])),
                         _seconds(row["best_seconds"]), "not reached" if fastest is None else escape(_setting(fastest)),
                         _seconds(row["fastest_seconds"]))
        out.print(grid)
    notes = {r["note"] for r in data["rows"] if r["note"]}
    for note in sorted(notes):
        out.print(escape(filled(f"note: {note}", out.width, initial_indent="  ", subsequent_indent="    ")))
