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
    mass: Annotated[str | None, typer.Option("--mass", help="quadratic drag, instead of v_t: mass m, e.g. '0.145 kg'")]
    = None,
    drag_coefficient: Annotated[float | None, typer.Option(
        "--drag-coefficient", help="quadratic drag: C, e.g. 0.47 (a sphere)")] = None,
    density: Annotated[str | None, typer.Option("--density", help="quadratic drag: air density rho, e.g. '1.2 kg/m3'")]
    = None,
    area: Annotated[str | None, typer.Option("--area", help="quadratic drag: cross-section A, e.g. '4.2e-3 m2'")]
    = None,
    only: OnlyOption = None,
    fmt: FormatOption = Format.table,
    plot: PlotOption = None,
) -> None:
    """Time of flight, range, apex and landing speed of a projectile (XX.iii-v). --plot draws its path, beside
    the same launch without drag when there is drag."""
    from orbits import Projectile
    from orbits._common import inputs
    from orbits_cli import render

    shot = vacuum = Projectile.launch(
        inputs.parse_quantity(speed, "speed", "--speed"), inputs.parse_angle(angle, "--angle"),
        inputs.parse_quantity(height, "length", "--height"),
        None if g is None else inputs.parse_quantity(g, "acceleration", "--g"))
    body = {"--mass": mass, "--drag-coefficient": drag_coefficient, "--density": density, "--area": area}
    given = [name for name, value in body.items() if value is not None]
    if drag == Drag.linear:
        if rate is None or terminal_speed is not None or given:
            raise typer.BadParameter("--drag linear takes --rate (b, e.g. '0.1 1/s') and no --terminal-speed, "
                                     "--mass, --drag-coefficient, --density or --area")
        shot = shot.with_linear_drag(_rate(rate))
    elif drag == Drag.quadratic:
        one_way = (terminal_speed is not None and not given) or (terminal_speed is None and len(given) == len(body))
        if rate is not None or not one_way:
            raise typer.BadParameter("--drag quadratic takes --terminal-speed (e.g. '30 m/s'), or all of --mass, "
                                     "--drag-coefficient, --density and --area; no --rate")
        shot = shot.with_quadratic_drag(**_quadratic(terminal_speed, mass, drag_coefficient, density, area))
    elif rate is not None or terminal_speed is not None or given:
        raise typer.BadParameter(f"{', '.join(given) or '--rate and --terminal-speed'}: need --drag linear (--rate) "
                                 f"or --drag quadratic")
    if plot:
        from orbits.plot import projectile_paths

        compared = {TITLES[drag]: shot} if drag == Drag.none else {TITLES[drag]: shot, TITLES[Drag.none]: vacuum}
        save_plot(lambda: projectile_paths(compared), plot)  # with drag, beside the same launch without it
    render.emit(f"Projectile, {TITLES[drag]}", shot.quantities(inputs.names(only)), fmt.value)


TITLES = {Drag.none: "no drag", Drag.linear: "linear drag", Drag.quadratic: "quadratic drag"}


def _quadratic(terminal_speed, mass, drag_coefficient, density, area):
    """Keyword arguments of Projectile.with_quadratic_drag from the options."""
    from orbits._common import inputs

    if terminal_speed is not None:
        return {"terminal_speed": inputs.parse_quantity(terminal_speed, "speed", "--terminal-speed")}
    return {"mass": inputs.parse_quantity(mass, "mass", "--mass"), "drag_coefficient": drag_coefficient,
            "density": inputs.parse_quantity(density, "density", "--density"),
            "area": inputs.parse_quantity(area, "area", "--area")}


def _rate(text):
    """A rate in 1/s from "0.1 1/s" (a bare number has no unit and is refused)."""
    from orbits._common import inputs

    return inputs.parse_quantity(text, "rate", "--rate")
