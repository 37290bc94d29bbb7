"""`orbits lagrange`: the five Lagrange points of a circular binary, their Jacobi constants and stability."""

from typing import TYPE_CHECKING, Annotated

import typer

from orbits_cli.options import MASS_HELP, Format, FormatOption, OnlyOption, PlotOption, save_plot, three_body

if TYPE_CHECKING:
    from orbits.threebody.lagrange import RestrictedThreeBody


def command(
    primary: Annotated[str, typer.Option("--primary", help=f"the heavier body M: {MASS_HELP}")],
    secondary: Annotated[str, typer.Option("--secondary", help=f"the lighter body m: {MASS_HELP}")],
    separation: Annotated[str | None, typer.Option(
        "--separation", help="distance between the bodies, e.g. '384399 km' (default: the secondary's catalogued "
        "mean distance)")] = None,
    points: Annotated[str, typer.Option("--points", help="comma-separated points, e.g. L1,L4")] = "L1,L2,L3,L4,L5",
    only: OnlyOption = None,
    fmt: FormatOption = Format.table,
    plot: PlotOption = None,
) -> None:
    """Lagrange points L1..L5 (rotating frame, x from M to m), Jacobi constants and linear stability (XXII.viii).

    growth_rate is 0 for a linearly stable point; eigenvalues are (re, im) pairs in 1/s. --plot draws the
    rotating frame: the points, the zero-velocity curves through L1..L3 and the regions they forbid.
    """
    from orbits._common import inputs
    from orbits_cli import render

    system = three_body(primary, secondary, separation)
    mu = float(system.mass_ratio.value)
    title = f"Lagrange points of {primary} and {secondary}, mu = {mu:.10g} (rotating frame, origin at the barycentre)"
    asked, listed = inputs.names(only), inputs.names(points)
    quantities = system.quantities(asked, points=listed)
    if plot:
        from orbits.plot import lagrange_plane

        save_plot(lambda: lagrange_plane(system), plot)
    if fmt == Format.json:
        render.emit(title, quantities, fmt.value)
    else:
        folding = [p for p in listed if asked is None or {"e_folding_time", f"{p}_e_folding_time"} & set(asked)]
        if asked is None:  # the eigenvalues, (re, im) pairs, are in the JSON unless asked for by name
            quantities = {name: q for name, q in quantities.items() if not name.endswith("_eigenvalues")}
        render.print_tables(point_tables(system, quantities, folding), title)


def point_tables(system: "RestrictedThreeBody", quantities: dict, folding: list[str] = ()) -> list:
    """The binary's own quantities, then one row per point: position (in units of r and in length units),
    distances, Jacobi constant, stability and e-folding time (for the points in `folding`; a stable point has none,
    its row says inf), a point without the asked value showing "-". Whatever has no column (eigenvalues asked for)
    follows as rows of its own."""
    import astropy.units as u
    import numpy as np

    from orbits_cli import render

    points = [p for p in ("L1", "L2", "L3", "L4", "L5")
              if p in folding or any(name.startswith(f"{p}_") for name in quantities)]
    binary = {name: q for name, q in quantities.items() if not name.startswith(tuple(f"{p}_" for p in points))}
    shown = set(binary)

    def stack(suffix, fill=np.nan):
        names = [f"{p}_{suffix}" for p in points]
        given = [name for name in names if name in quantities]
        if not given:
            return None, []
        shown.update(given)
        like = quantities[given[0]]
        values = u.Quantity([quantities.get(name, np.full(np.shape(like), fill) << like.unit) for name in names])
        return values, [name not in quantities for name in names]

    def dashed(column, missing):
        header, cells = column
        return header, ["-" if gap else cell for cell, gap in zip(cells, missing)]

    columns = []
    position, missing = stack("position")
    if position is not None:
        scaled = (position / system.separation).to_value(u.one)
        columns += [dashed(("x / r", [render.number(v) for v in scaled[:, 0]]), missing),
                    dashed(("y / r", [render.number(v) for v in scaled[:, 1]]), missing),
                    dashed(render.column("position", position[:, 0], "x", position), missing),
                    dashed(render.column("position", position[:, 1], "y", position), missing)]
    for suffix, header in (("distance_to_primary", "to M"), ("distance_to_secondary", "to m"),
                           ("jacobi_constant", "Jacobi C")):
        values, missing = stack(suffix)
        if values is not None:
            columns.append(dashed(render.column(suffix, values, header), missing))
    rates, missing = stack("growth_rate")
    if rates is not None:
        columns.append(dashed(("stable", ["yes" if rate == 0 else "no" for rate in rates.value]), missing))
    times, missing = stack("e_folding_time", fill=np.inf)
    if folding:
        times = times if times is not None else np.full(len(points), np.inf) << u.s
        unasked = [p not in folding for p in points]
        columns.append(dashed(render.column("e_folding_time", times, "e-folding"), unasked))
    tables = [render.quantity_table("", binary)] if binary else []
    if columns:
        tables += render.column_tables(("point", points), columns)
    rest = {name: q for name, q in quantities.items() if name not in shown}
    if rest:
        tables.append(render.quantity_table("", rest))
    return tables
