"""`orbits lagrange`: the five Lagrange points of a circular binary, their Jacobi constants and stability."""

from typing import TYPE_CHECKING, Annotated

import typer

from orbits_cli.commands.binary import MASS_HELP, mass_or_body
from orbits_cli.options import Format, FormatOption, OnlyOption

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
) -> None:
    """Lagrange points L1..L5 (rotating frame, x from M to m), Jacobi constants and linear stability (XXII.viii).

    growth_rate is 0 for a linearly stable point; eigenvalues are (re, im) pairs in 1/s.
    """
    from orbits import inputs
    from orbits_cli import render

    system = build(primary, secondary, r)
    mu = float(system.mass_ratio.value)
    title = f"Lagrange points of {primary} and {secondary}, mu = {mu:.10g} (rotating frame, origin at the barycentre)"
    render.emit(title, system.quantities(inputs.names(only), points=inputs.names(points)), fmt.value)


def build(primary: str, secondary: str, r: str | None) -> "RestrictedThreeBody":
    """The RestrictedThreeBody of the two bodies at separation r (None: the catalogued mean distance)."""
    from orbits import RestrictedThreeBody, inputs

    separation = None if r is None else inputs.parse_quantity(r, "length", "--r")
    return RestrictedThreeBody.from_primaries(
        mass_or_body(primary, "PRIMARY"), mass_or_body(secondary, "SECONDARY"), separation
    )
