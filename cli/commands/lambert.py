"""`orbits lambert`: the transfer orbit from r1 to r2 in a given time of flight (Lambert's problem)."""

from typing import Annotated

import typer

from orbits_cli.commands.binary import MASS_HELP
from orbits_cli.options import Format, FormatOption, OnlyOption


def command(
    r1: Annotated[str, typer.Option("--r1", help="departure position 'X,Y,Z UNIT', e.g. '1,0,0 AU'")],
    r2: Annotated[str, typer.Option("--r2", help="arrival position, e.g. '0,1.5,0 AU'")],
    tof: Annotated[str, typer.Option("--tof", help="time of flight, e.g. '200 d'")],
    primary: Annotated[str, typer.Option(help=f"the attracting body: {MASS_HELP}")] = "Sun",
    revolutions: Annotated[int, typer.Option(min=0, help="complete revolutions before arrival")] = 0,
    branch: Annotated[str | None, typer.Option(help="left or right: which of the two solutions when revolutions > 0 "
                                                    "(default right, lamberthub's low path)")] = None,
    retrograde: Annotated[bool, typer.Option("--retrograde", help="clockwise about +z (default: prograde; not "
                                                                  "with --normal, which sets the sense)")] = False,
    normal: Annotated[str | None, typer.Option(
        help="the orbit's angular momentum direction 'X,Y,Z' (any unit or none); needed when r1, r2 are opposite"
    )] = None,
    only: OnlyOption = None,
    fmt: FormatOption = Format.table,
) -> None:
    """Velocities, transfer angle, a and e of the conic from r1 to r2 in the time of flight (Izzo's method)."""
    from orbits import inputs, lambert
    from orbits_cli import render

    transfer = lambert(
        inputs.parse_vector(r1, "length", "--r1"),
        inputs.parse_vector(r2, "length", "--r2"),
        inputs.parse_quantity(tof, "time", "--tof"),
        inputs.parse_primary(primary),
        revolutions=revolutions,
        branch=branch,
        prograde=False if retrograde else None,
        normal=None if normal is None else inputs.parse_direction(normal, "--normal"),
    )
    shown = f", {revolutions} revolutions ({transfer.branch} branch)" if revolutions else ""
    render.emit(f"Lambert transfer about {primary}{shown}", transfer.quantities(inputs.names(only)), fmt.value)

