"""`orbits projectile`: a launch under uniform gravity, without drag or with linear or quadratic drag (notes XX)."""

from enum import StrEnum
from typing import Annotated

import typer

from orbits_cli.options import Format, FormatOption, OnlyOption, PlotOption, save_plot


class Drag(StrEnum):
    none = "none"
    linear = "linear"
    quadratic = "quadratic"


def command(
    speed: Annotated[str, typer.Option("--speed", help="launch speed, e.g. '20 m/s'")],
    angle: Annotated[str, typer.Option("--angle", help="above the horizontal, -90..90 ('45'; bare numbers: deg)")],
    height: Annotated[str, typer.Option("--height", help="launch height above the ground")] = "0 m",
    g: Annotated[str | None, typer.Option("--g", help="gravity (default 9.80665 m/s2)")] = None,
    drag: Annotated[Drag, typer.Option("--drag", help="none, linear (-m b v) or quadratic (-C rho A |v| v / 2)")]
    = Drag.none,
    rate: Annotated[str | None, typer.Option("--rate", help="linear drag rate b, e.g. '0.1 1/s'")] = None,
    terminal_speed: Annotated[str | None, typer.Option(
        "--terminal-speed", help="quadratic drag: v_t = sqrt(2 m g / (C rho A)), e.g. '30 m/s'")] = None,
    only: OnlyOption = None,
    fmt: FormatOption = Format.table,
    plot: PlotOption = None,
) -> None:
    """Time of flight, range, apex and landing speed of a projectile (XX.iii-v)."""
    from orbits import inputs
    from orbits.mechanics import Projectile
    from orbits_cli import render

    shot = Projectile.launch(
        inputs.parse_quantity(speed, "speed", "--speed"), inputs.parse_angle(angle, "--angle"),
        inputs.parse_quantity(height, "length", "--height"),
        None if g is None else inputs.parse_quantity(g, "acceleration", "--g"))
    if drag == Drag.linear:
        if rate is None or terminal_speed is not None:
            raise typer.BadParameter("--drag linear takes --rate (b, e.g. '0.1 1/s') and no --terminal-speed")
        shot = shot.with_linear_drag(_rate(rate))
    elif drag == Drag.quadratic:
        if terminal_speed is None or rate is not None:
            raise typer.BadParameter("--drag quadratic takes --terminal-speed (e.g. '30 m/s') and no --rate")
        shot = shot.with_quadratic_drag(inputs.parse_quantity(terminal_speed, "speed", "--terminal-speed"))
    elif rate is not None or terminal_speed is not None:
        raise typer.BadParameter("--rate and --terminal-speed need --drag linear or --drag quadratic")
    if plot:
        from orbits.mechanics.plots import projectile_paths

        save_plot(lambda: projectile_paths({TITLES[drag]: shot}), plot)
    render.emit(f"Projectile, {TITLES[drag]}", shot.quantities(inputs.names(only)), fmt.value)


TITLES = {Drag.none: "no drag", Drag.linear: "linear drag", Drag.quadratic: "quadratic drag"}


def _rate(text):
    """A rate in 1/s from "0.1 1/s" (a bare number has no unit and is refused)."""
    from orbits import inputs

    return inputs.parse_quantity(text, "rate", "--rate")
