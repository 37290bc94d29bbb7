"""`orbits flyby`: a hyperbolic encounter from the speed at infinity and the impact parameter (XXI.vi, XXII.vi)."""

from typing import TYPE_CHECKING, Annotated

import typer

from orbits_cli.options import MASS_HELP, Format, FormatOption, OnlyOption, PlotOption, mass_or_body, save_plot

if TYPE_CHECKING:
    from orbits.encounters.flyby import Flyby


def command(
    primary: Annotated[str, typer.Option(help=f"the attracting body: {MASS_HELP}")],
    v_inf: Annotated[str, typer.Option("--v-inf", help="speed at infinity, e.g. '5.6 km/s'")],
    b: Annotated[str | None, typer.Option("--b", help="impact parameter, e.g. '1e6 km'")] = None,
    periapsis: Annotated[
        str | None, typer.Option("--periapsis", help="wanted closest approach instead of --b (b is solved for)")
    ] = None,
    mass: Annotated[
        str | None, typer.Option(help="moving body's mass: energies about a fixed primary (XXI.vi)")
    ] = None,
    secondary: Annotated[
        str | None, typer.Option(help="second finite mass: both bodies move, with each star's speeds (XXII.vi)")
    ] = None,
    only: OnlyOption = None,
    fmt: FormatOption = Format.table,
    plot: PlotOption = None,
) -> None:
    """Closest approach, speed there, eccentricity, semi-major axis and deflection of a flyby (XXI.vi, XXII.vi)."""
    from orbits._common import inputs
    from orbits_cli import render

    result, title = build(primary, v_inf, b, periapsis, mass, secondary)  # a collision is said, once, by Flyby
    if plot:
        import warnings

        from orbits.plot import InsideBodyWarning, flyby_plane

        with warnings.catch_warnings():
            warnings.simplefilter("ignore", InsideBodyWarning)  # said once, above
            save_plot(lambda: flyby_plane(result), plot)
    groups = [("star1_", "the primary, in the centre-of-mass frame"), ("star2_", "the moving body, in that frame")]
    render.emit(title, result.quantities(inputs.names(only)), fmt.value, groups=groups)


def build(
    primary: str, v_inf: str, b: str | None, periapsis: str | None, mass: str | None, secondary: str | None
) -> "tuple[Flyby, str]":
    """(Flyby, title) from the options; BadParameter for inconsistent combinations."""
    from orbits import Flyby
    from orbits._common import inputs

    if (b is None) == (periapsis is None):
        raise typer.BadParameter("give exactly one of --b (impact parameter) and --periapsis (closest approach)")
    if mass is not None and secondary is not None:
        raise typer.BadParameter("give --mass (fixed primary, XXI.vi) or --secondary (two moving masses), not both")
    size = (
        {"b": inputs.parse_quantity(b, "length", "--b")}
        if b is not None
        else {"periapsis": inputs.parse_quantity(periapsis, "length", "--periapsis")}
    )
    speed = inputs.parse_quantity(v_inf, "speed", "--v-inf")
    center = mass_or_body(primary, "--primary")
    if secondary is not None:
        return Flyby.between(center, mass_or_body(secondary, "--secondary"), speed, **size), "Flyby of two masses"
    moving = None if mass is None else mass_or_body(mass, "--mass")
    return Flyby.past(center, speed, mass=moving, **size), f"Flyby past {primary}"
