"""`orbits escape`: escape speed, cosmic velocities, synchronous (GEO) orbits and maximum elongation (XXI.ix-xi).

A sub-application with one command per question; main.py mounts it with app.add_typer(escape.app).
"""

from typing import Annotated

import typer

from orbits_cli.options import MASS_HELP, Format, FormatOption, OnlyOption, displays, mass_or_body, reports_errors

app = typer.Typer(
    help="Escape speed, cosmic velocities, synchronous orbits and maximum elongation (notes XXI.ix-xi).",
    no_args_is_help=True,
)

PrimaryOption = Annotated[str, typer.Option("--primary", help=f"the body: {MASS_HELP}")]


def speed(
    primary: PrimaryOption = "Earth",
    at_r: Annotated[
        str | None, typer.Option("--at-r", help="distance from the centre (default: a named body's equatorial "
                                 "radius)")
    ] = None,
    fmt: FormatOption = Format.table,
) -> None:
    """Escape speed sqrt(2 G M / r) at a distance from a body's centre (at its surface by default)."""
    import astropy.units as u

    from orbits import body, escape_speed
    from orbits._common import inputs
    from orbits_cli import render

    center = mass_or_body(primary, "--primary")
    r = None if at_r is None else inputs.parse_quantity(at_r, "length", "--at-r")
    v = escape_speed(center, r)
    shown = r if r is not None else body(primary).radius * u.m
    result = {"distance": shown.to(u.km), "escape_speed": v.to(u.km / u.s)}
    render.emit(f"Escape speed from {primary}", result, fmt.value)


def cosmic(
    primary: Annotated[
        str | None, typer.Option("--primary", help="a named body; default: the notes' Earth (g0, 6371 km)")
    ] = None,
    g: Annotated[str | None, typer.Option("--g", help="surface gravity, e.g. '9.80665 m/s2'")] = None,
    body_radius: Annotated[str | None, typer.Option("--body-radius", help="surface radius, e.g. '6371 km'")] = None,
    orbital_speed: Annotated[
        str | None, typer.Option(help="the body's circular speed about the Sun (default: Earth's, 29.785 km/s)")
    ] = None,
    only: OnlyOption = None,
    fmt: FormatOption = Format.table,
) -> None:
    """First, second and third cosmic velocities (XXI.ix): sqrt(g R), sqrt(2 g R) and the patched-conic third."""
    from orbits import CosmicVelocities
    from orbits._common import inputs
    from orbits_cli import render

    if primary is not None:
        if any(x is not None for x in (g, body_radius, orbital_speed)):
            raise typer.BadParameter("give --primary or the model (--g, --body-radius, --orbital-speed), not both")
        result, title = CosmicVelocities.of(primary), f"Cosmic velocities of {primary}"
    else:
        result = CosmicVelocities.from_surface_gravity(
            None if g is None else _acceleration(g),
            None if body_radius is None else inputs.parse_quantity(body_radius, "length", "--body-radius"),
            None if orbital_speed is None else inputs.parse_quantity(orbital_speed, "speed", "--orbital-speed"),
        )
        title = "Cosmic velocities (the notes' model: v1 = sqrt(g R), v2 = sqrt(2 g R))"
    render.emit(title, result.quantities(inputs.names(only)), fmt.value)


def geo(
    primary: PrimaryOption = "Earth",
    rotation_period: Annotated[str | None, typer.Option(
        "--rotation-period", help="sidereal rotation period (default: the body's)")] = None,
    body_radius: Annotated[str | None, typer.Option(
        "--body-radius", help="body radius, for the altitude (default: the body's)")] = None,
    only: OnlyOption = None,
    fmt: FormatOption = Format.table,
) -> None:
    """Synchronous orbit of a rotating body (XXI.x): geosynchronous / geostationary radius and altitude for Earth."""
    from orbits import SynchronousOrbit
    from orbits._common import inputs
    from orbits_cli import render

    result = SynchronousOrbit.of(
        mass_or_body(primary, "--primary"),
        None if rotation_period is None else inputs.parse_quantity(rotation_period, "time", "--rotation-period"),
        None if body_radius is None else inputs.parse_quantity(body_radius, "length", "--body-radius"),
    )
    render.emit(f"Synchronous orbit of {primary}", result.quantities(inputs.names(only)), fmt.value)


def elongation(
    inner: Annotated[str, typer.Option(help="inner orbit radius ('0.723 AU') or a named body")],
    outer: Annotated[str, typer.Option(help="outer (observer's) orbit radius ('1 AU') or a named body")],
    fmt: FormatOption = Format.table,
) -> None:
    """Maximum elongation arcsin(r / R) of an inner planet seen from an outer one (XXI.xi), circular orbits."""
    import astropy.units as u

    from orbits import max_elongation
    from orbits_cli import render

    radii = [_radius_or_body(x, name) for x, name in ((inner, "--inner"), (outer, "--outer"))]
    angle = max_elongation(*radii)
    render.emit(f"Maximum elongation of {inner} seen from {outer}", {"max_elongation": angle.to(u.deg)}, fmt.value)


def _acceleration(text):
    """The --g option as an acceleration Quantity (a bare number has no unit and is refused)."""
    from orbits._common import inputs

    return inputs.parse_quantity(text, "acceleration", "--g")


def _radius_or_body(text, option):
    """A catalogued body's name, or a length parsed from `text`."""
    from orbits._common import inputs

    if inputs.find_body(text) is not None:
        return text
    return inputs.parse_quantity(text, "length", option)


app.command("speed")(reports_errors(displays(speed)))
app.command("cosmic")(reports_errors(displays(cosmic)))
app.command("geo")(reports_errors(displays(geo)))
app.command("elongation")(reports_errors(displays(elongation)))
