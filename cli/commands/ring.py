"""`orbits ring`: n equal masses on a regular n-gon, optionally about a central mass (XXIII, Maxwell's ring)."""

from typing import Annotated

import typer

from orbits_cli.commands.binary import MASS_HELP, mass_or_body
from orbits_cli.options import Format, FormatOption, OnlyOption


def command(
    n: Annotated[int, typer.Argument(help="number of bodies on the ring (2 or more)")],
    m: Annotated[str, typer.Option("--m", help=f"each body's mass: {MASS_HELP}")],
    r: Annotated[str, typer.Option("--r", help="ring radius, e.g. '100000 km'")],
    central_mass: Annotated[
        str | None, typer.Option("--central-mass", help=f"mass at the centre (Maxwell's ring): {MASS_HELP}")
    ] = None,
    only: OnlyOption = None,
    fmt: FormatOption = Format.table,
) -> None:
    """Angular velocity, period, speed, U, K, E, L of a ring (XXIII) and its linear stability: growth rate,
    break-up time from float64 round-off, and the central mass that makes a ring of n >= 7 stable."""
    from orbits import Ring, inputs
    from orbits_cli import render

    ring = Ring.from_masses(
        n,
        mass_or_body(m, "--m"),
        inputs.parse_quantity(r, "length", "--r"),
        central_mass=None if central_mass is None else mass_or_body(central_mass, "--central-mass"),
    )
    title = f"Ring of {n} bodies" + ("" if central_mass is None else f" about {central_mass}")
    render.emit(title, ring.quantities(inputs.names(only)), fmt.value)
