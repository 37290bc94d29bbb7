"""`orbits lagrange`: the five Lagrange points of a circular binary, their Jacobi constants and stability."""

from typing import TYPE_CHECKING, Annotated

import typer

from orbits_cli.commands.binary import MASS_HELP, mass_or_body
from orbits_cli.options import Format, FormatOption, OnlyOption, PlotOption, save_plot

if TYPE_CHECKING:
    from orbits.lagrange import RestrictedThreeBody


def command(
    primary: Annotated[str, typer.Argument(help=f"the heavier body M: {MASS_HELP}")],
    secondary: Annotated[str, typer.Argument(help=f"the lighter body m: {MASS_HELP}")],
    r: Annotated[
        str | None,
        typer.Option("--r", help="separation, e.g. '384399 km' (default: the secondary's catalogued mean distance)"),
    ] = None,
    points: Annotated[str, typer.Option("--points", help="comma-separated points, e.g. L1,L4")] = "L1,L2,L3,L4,L5",
    only: OnlyOption = None,
    fmt: FormatOption = Format.table,
    plot: PlotOption = None,
) -> None:
    """Lagrange points L1..L5 (rotating frame, x from M to m), Jacobi constants and linear stability (XXII.viii).

    growth_rate is 0 for a linearly stable point; eigenvalues are (re, im) pairs in 1/s. --plot draws the
    rotating frame: the points, the zero-velocity curves through L1..L3 and the regions they forbid.
    """
    from orbits import inputs
    from orbits_cli import render

    system = build(primary, secondary, r)
    mu = float(system.mass_ratio.value)
    title = f"Lagrange points of {primary} and {secondary}, mu = {mu:.10g} (rotating frame, origin at the barycentre)"
    quantities = system.quantities(inputs.names(only), points=inputs.names(points))
    if plot:
        from orbits.plot import lagrange_plane

        save_plot(lambda: lagrange_plane(system), plot)
    if fmt == Format.json:
        render.emit(title, quantities, fmt.value)
    else:
        render.print_tables(point_tables(system, quantities), title)


def point_tables(system: "RestrictedThreeBody", quantities: dict) -> list:
    """The binary's own quantities, then one row per point: position (in units of r and in length units),
    distances, Jacobi constant, stability and e-folding time. The eigenvalues are in the JSON output."""
    import astropy.units as u
    import numpy as np

    from orbits_cli import render

    points = [p for p in ("L1", "L2", "L3", "L4", "L5") if any(name.startswith(f"{p}_") for name in quantities)]
    binary = {name: q for name, q in quantities.items() if not name.startswith(tuple(f"{p}_" for p in points))}

    def stack(suffix):
        return u.Quantity([quantities[f"{p}_{suffix}"] for p in points]) if points and all(
            f"{p}_{suffix}" in quantities for p in points) else None

    columns = []
    position = stack("position")
    if position is not None:
        scaled = (position / system.separation).to_value(u.one)
        columns += [("x / r", [render.number(v) for v in scaled[:, 0]]),
                    ("y / r", [render.number(v) for v in scaled[:, 1]]),
                    render.column("position", position[:, 0], "x", position),
                    render.column("position", position[:, 1], "y", position)]
    for suffix, header in (("distance_to_primary", "to M"), ("distance_to_secondary", "to m"),
                           ("jacobi_constant", "Jacobi C")):
        values = stack(suffix)
        if values is not None:
            columns.append(render.column(suffix, values, header))
    rates = stack("growth_rate")
    if rates is not None:
        columns.append(("stable", ["yes" if rate == 0 else "no" for rate in rates.value]))
        times = u.Quantity([quantities.get(f"{p}_e_folding_time", np.inf * u.s) for p in points])
        columns.append(render.column("e_folding_time", times, "e-folding"))
    tables = [render.quantity_table("", binary)] if binary else []
    if columns:
        tables += render.column_tables(("point", points), columns)
    return tables


def build(primary: str, secondary: str, r: str | None) -> "RestrictedThreeBody":
    """The RestrictedThreeBody of the two bodies at separation r (None: the catalogued mean distance)."""
    from orbits import RestrictedThreeBody, inputs

    separation = None if r is None else inputs.parse_quantity(r, "length", "--r")
    return RestrictedThreeBody.from_primaries(
        mass_or_body(primary, "PRIMARY"), mass_or_body(secondary, "SECONDARY"), separation
    )
