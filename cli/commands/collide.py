"""`orbits collide`: two bodies colliding with a coefficient of restitution, head-on or oblique (notes IX)."""

from typing import TYPE_CHECKING, Annotated

import typer

from orbits_cli.options import Format, FormatOption, OnlyOption, PlotOption, save_plot

if TYPE_CHECKING:
    from astropy.units import Quantity

VELOCITY_HELP = "a speed along the line ('3 m/s', negative to the left) or a vector ('3,4 m/s', '1,2,0 km/s')"


def command(
    m1: Annotated[str, typer.Option("--m1", help="mass of body 1, e.g. '2 kg'")],
    v1: Annotated[str, typer.Option("--v1", help=f"velocity of body 1: {VELOCITY_HELP}")],
    m2: Annotated[str, typer.Option("--m2", help="mass of body 2")],
    v2: Annotated[str, typer.Option("--v2", help="velocity of body 2 (same form as --v1)")],
    restitution: Annotated[float, typer.Option("--restitution", help="e in [0, 1]: 1 elastic, 0 sticks")] = 1.0,
    line_of_impact: Annotated[str | None, typer.Option(
        "--line-of-impact", help="line of impact for vectors, e.g. '1,1' (default: along v1 - v2, the notes' "
        "model)")] = None,
    only: OnlyOption = None,
    fmt: FormatOption = Format.table,
    plot: PlotOption = None,
) -> None:
    """Velocities after, centre-of-mass velocity and kinetic energies of a collision (IX.vii-xiii)."""
    from orbits import Collision
    from orbits._common import inputs
    from orbits_cli import render

    masses = inputs.parse_quantity(m1, "mass", "--m1"), inputs.parse_quantity(m2, "mass", "--m2")
    first, second = velocity(v1, "--v1"), velocity(v2, "--v2")
    if first.ndim != second.ndim or first.size != second.size:
        raise typer.BadParameter("--v1 and --v2 must both be speeds along a line or both vectors of one size")
    if first.ndim == 0:
        if line_of_impact is not None:
            raise typer.BadParameter("--line-of-impact needs vector velocities ('3,4 m/s')")
        result = Collision.head_on(masses[0], first, masses[1], second, restitution)
        title = "Head-on collision"
    else:
        line = None if line_of_impact is None else _direction(line_of_impact, first.size)
        result = Collision.oblique(masses[0], first, masses[1], second, restitution, normal=line)
        title = "Oblique collision"
    if plot:
        from orbits.plot import collision_velocities

        save_plot(lambda: collision_velocities(result), plot)
    render.emit(f"{title} (e = {restitution:g})", result.quantities(inputs.names(only)), fmt.value)


def velocity(text: str, option: str) -> "Quantity":
    """A signed speed "3 m/s" or a 2-D / 3-D vector "3,4 m/s" (orbits._common.inputs rules: finite, a speed)."""
    from orbits._common import inputs

    numbers, _, unit = text.strip().partition(" ")
    count = numbers.count(",") + 1
    if count == 1:
        return inputs.parse_quantity(text, "speed", option)
    if count == 2:
        return inputs.parse_vector(f"{numbers},0 {unit}", "speed", option)[:2]
    return inputs.parse_vector(text, "speed", option)


def _direction(text: str, size: int) -> list[float]:
    try:
        values = [float(x) for x in text.split(",")]
    except ValueError:
        raise typer.BadParameter(f"--line-of-impact {text!r}: write comma-separated numbers, e.g. '1,1'") from None
    if len(values) != size:
        raise typer.BadParameter(f"--line-of-impact {text!r} needs {size} components like the velocities")
    return values
