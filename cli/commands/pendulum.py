"""`orbits pendulum`: the exact period of a pendulum at any amplitude, and motion on a vertical circle (XXV)."""

from typing import Annotated

import typer

from orbits_cli.options import Format, FormatOption, OnlyOption, PlotOption, save_plot


def command(
    length: Annotated[str, typer.Option("--length", help="string length (or circle radius), e.g. '1 m'")],
    amplitude: Annotated[str | None, typer.Option(
        "--amplitude", help="release angle from the lowest point, 0..180 ('170'; bare numbers: deg)")] = None,
    bottom_speed: Annotated[str | None, typer.Option(
        "--bottom-speed", help="instead of --amplitude: speed at the lowest point, e.g. '7 m/s' (vertical circle)")]
    = None,
    rod: Annotated[bool, typer.Option("--rod", help="held by a rigid rod (pushes too), not a string")] = False,
    mass: Annotated[str | None, typer.Option("--mass", help="bob mass, for the forces (vertical circle)")] = None,
    g: Annotated[str | None, typer.Option("--g", help="gravity (default 9.80665 m/s2)")] = None,
    only: OnlyOption = None,
    fmt: FormatOption = Format.table,
    plot: PlotOption = None,
) -> None:
    """Exact large-amplitude period 4 K(sin^2(theta0/2)) / omega0 (XXV.iv), or the vertical circle from the speed
    at the bottom: loops, leaves the circle or swings, with the turning and leaving angles (XXV.vi)."""
    from orbits import Pendulum, VerticalCircle
    from orbits._common import inputs
    from orbits_cli import render

    size = inputs.parse_quantity(length, "length", "--length")
    gravity = None if g is None else inputs.parse_quantity(g, "acceleration", "--g")
    if (amplitude is None) == (bottom_speed is None):
        raise typer.BadParameter("give exactly one of --amplitude and --bottom-speed")
    if amplitude is not None:
        if rod or mass is not None:
            raise typer.BadParameter("--rod and --mass go with --bottom-speed (the vertical circle)")
        result = Pendulum.simple(size, inputs.parse_angle(amplitude, "--amplitude"), gravity)
        if plot:
            from orbits.plot import pendulum_periods

            save_plot(lambda: pendulum_periods(result), plot)
        render.emit(f"Pendulum of length {length}", result.quantities(inputs.names(only)), fmt.value)
        return
    circle = VerticalCircle.of(size, inputs.parse_quantity(bottom_speed, "speed", "--bottom-speed"), gravity,
                               None if mass is None else inputs.parse_quantity(mass, "mass", "--mass"),
                               "rod" if rod else "string")
    if plot:
        if circle.mass is None:
            raise typer.BadParameter("--plot of a vertical circle draws the normal force: give --mass")
        from orbits.plot import vertical_circle_forces

        save_plot(lambda: vertical_circle_forces({f"u = {bottom_speed}": circle}), plot)
    render.emit(f"Vertical circle of radius {length}: {circle.regime}", circle.quantities(inputs.names(only)),
                fmt.value)
