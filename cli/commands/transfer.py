"""`orbits transfer`: impulsive manoeuvres between circular orbits (Hohmann, bi-elliptic, plane change, phasing)
a hyperbolic departure and a gravity assist. A sub-application with one command per manoeuvre; main.py mounts it with
app.add_typer(transfer.app)."""

from typing import Annotated

import typer

from orbits_cli.options import MASS_HELP, Format, FormatOption, OnlyOption, displays, mass_or_body, reports_errors

app = typer.Typer(
    help="Impulsive manoeuvres: Hohmann, bi-elliptic, plane change, phasing, departure (delta-v budgets, times).",
    no_args_is_help=True,
)

PrimaryOption = Annotated[str, typer.Option("--primary", help=f"the central body: {MASS_HELP}")]
R1Option = Annotated[str, typer.Option(
    "--radius1", help="initial circular orbit radius from the centre, e.g. '6678 km'")]
R2Option = Annotated[str, typer.Option("--radius2", help="final circular orbit radius, e.g. '42164 km'")]
OptionalR1 = Annotated[str | None, typer.Option(
    "--radius1", help="initial circular orbit radius from the centre, e.g. '6678 km'")]
OptionalR2 = Annotated[str | None, typer.Option("--radius2", help="final circular orbit radius, e.g. '42164 km'")]
ROption = Annotated[str, typer.Option("--radius", help="circular orbit radius from the centre, e.g. '7000 km'")]


def _length(text, option):
    from orbits._common import inputs

    return inputs.parse_quantity(text, "length", option)


def _emit(title, manoeuvre, only, fmt):
    from orbits._common import inputs
    from orbits_cli import render

    render.emit(title, manoeuvre.quantities(inputs.names(only)), fmt.value)


def hohmann(
    r1: OptionalR1 = None,
    r2: OptionalR2 = None,
    departure: Annotated[str | None, typer.Option(
        "--from", help="instead of --radius1: a body whose mean orbit (about the same primary as --to's) is the start")
    ] = None,
    target: Annotated[str | None, typer.Option("--to", help="instead of --radius2: the body whose orbit is the goal")
                      ] = None,
    primary: Annotated[str | None, typer.Option(
        "--primary", help=f"the central body: {MASS_HELP} [default: Earth; with --from/--to their common primary]")
    ] = None,
    inc: Annotated[str, typer.Option(
        "--inc", help="plane change combined with the burn at the larger radius ('28.5 deg'; bare numbers are degrees)")
    ] = "0",
    only: OnlyOption = None,
    fmt: FormatOption = Format.table,
) -> None:
    """Hohmann transfer: two tangential burns and half an ellipse, optionally turning the plane; the synodic period
    and the phase angle the target must lead by at departure. With --from and --to: between two bodies' mean
    orbits about their common primary, each taken as the circle of radius its semi-major axis."""
    from orbits import Hohmann, body
    from orbits._common import inputs

    turn = inputs.parse_angle(inc, "--inc")
    if departure is not None or target is not None:
        given = [name for name, value in (("--radius1", r1), ("--radius2", r2), ("--primary", primary))
                 if value is not None]
        if given or departure is None or target is None:
            raise typer.BadParameter("give both --from and --to (bodies), without --radius1, --radius2 or "
                                     "--primary: the radii and the primary come from the bodies' mean orbits")
        result = Hohmann.between_bodies(departure, target, inclination_change=turn)
        from orbits.ephemeris.catalogue import mean_elements

        about = mean_elements(departure).primary
        _emit(f"Hohmann transfer from {body(departure).name}'s to {body(target).name}'s mean orbit about "
              f"{'the Sun' if about == 'Sun' else about}, each taken as the circle of radius its semi-major axis",
              result, only, fmt)
        return
    for option, text in (("--radius1", r1), ("--radius2", r2)):
        if text is not None and inputs.find_body(text) is not None:
            raise typer.BadParameter(f"{option} {text!r} is a body, not a radius: for the transfer between the orbits "
                                     f"of two bodies give --from and --to, e.g. --from Earth --to Mars")
    if r1 is None or r2 is None:
        raise typer.BadParameter("give --radius1 and --radius2 (radii, e.g. '6678 km'), or --from and --to (bodies)")
    result = Hohmann.between(mass_or_body(primary or "Earth", "--primary"), _length(r1, "--radius1"),
                             _length(r2, "--radius2"), inclination_change=turn)
    _emit(f"Hohmann transfer about {primary or 'Earth'}", result, only, fmt)


def bi_elliptic(
    r1: R1Option,
    r2: R2Option,
    apoapsis: Annotated[str, typer.Option("--apoapsis", help="common apoapsis of the two ellipses, above both "
                                          "orbits")],
    primary: PrimaryOption = "Earth",
    only: OnlyOption = None,
    fmt: FormatOption = Format.table,
) -> None:
    """Bi-elliptic transfer: out to the common apoapsis rb, periapsis moved to r2, circularised; compared with
    Hohmann."""
    from orbits import BiElliptic

    result = BiElliptic.between(mass_or_body(primary, "--primary"), _length(r1, "--radius1"),
                                _length(r2, "--radius2"), _length(apoapsis, "--apoapsis"))
    _emit(f"Bi-elliptic transfer about {primary}", result, only, fmt)


def plane_change(
    r: ROption,
    inc: Annotated[str, typer.Option(
        "--inc", help="turn of the orbit plane ('28.5 deg'; bare numbers are degrees)")],
    primary: PrimaryOption = "Earth",
    only: OnlyOption = None,
    fmt: FormatOption = Format.table,
) -> None:
    """Plane change on a circular orbit: one burn 2 v sin(di / 2) at a node."""
    from orbits import PlaneChange
    from orbits._common import inputs

    result = PlaneChange.at(mass_or_body(primary, "--primary"), _length(r, "--radius"),
                            inputs.parse_angle(inc, "--inc"))
    _emit(f"Plane change about {primary}", result, only, fmt)


def phasing(
    r: ROption,
    phase: Annotated[str, typer.Option(
        "--phase", help="how far the target leads ('30 deg'; negative: it trails; bare numbers are degrees)")],
    revolutions: Annotated[int, typer.Option("--revolutions", min=1, help="revolutions on the phasing orbit")] = 1,
    primary: PrimaryOption = "Earth",
    only: OnlyOption = None,
    fmt: FormatOption = Format.table,
) -> None:
    """Phasing: a burn onto a faster or slower orbit, k revolutions, a burn back, meeting the target."""
    from orbits import Phasing
    from orbits._common import inputs

    result = Phasing.to(mass_or_body(primary, "--primary"), _length(r, "--radius"),
                        inputs.parse_angle(phase, "--phase"), revolutions)
    _emit(f"Phasing on a circular orbit about {primary}", result, only, fmt)


def departure(
    r: ROption,
    v_inf: Annotated[str, typer.Option("--v-inf", help="speed left far away, e.g. '3 km/s'")],
    primary: PrimaryOption = "Earth",
    only: OnlyOption = None,
    fmt: FormatOption = Format.table,
) -> None:
    """Departure from a circular parking orbit onto the hyperbola with the given speed at infinity."""
    from orbits import Departure
    from orbits._common import inputs

    result = Departure.to_excess_speed(mass_or_body(primary, "--primary"), _length(r, "--radius"),
                                       inputs.parse_quantity(v_inf, "speed", "--v-inf"))
    _emit(f"Departure from {primary}", result, only, fmt)


def assist(
    primary: Annotated[str, typer.Option("--primary", help=f"the planet flown past: {MASS_HELP}")],
    v_in: Annotated[str, typer.Option("--v-in", help="the probe's heliocentric velocity before, 'X,Y,Z km/s'")],
    v_planet: Annotated[str, typer.Option("--v-planet", help="the planet's heliocentric velocity, 'X,Y,Z km/s'")],
    periapsis: Annotated[str, typer.Option(help="closest approach to the planet's centre, e.g. '200000 km'")],
    normal: Annotated[str | None, typer.Option(
        help="axis the excess velocity turns about (right hand), 'X,Y,Z' [default: +z]")] = None,
    only: OnlyOption = None,
    fmt: FormatOption = Format.table,
) -> None:
    """Gravity assist by patched conics (IX's elastic collision in the planet's frame): the excess velocity turns
    by the flyby's deflection; the heliocentric velocity after, its change and the energy gained."""
    from orbits import GravityAssist
    from orbits._common import inputs

    result = GravityAssist.past(
        mass_or_body(primary, "--primary"), inputs.parse_vector(v_in, "speed", "--v-in"),
        inputs.parse_vector(v_planet, "speed", "--v-planet"), _length(periapsis, "--periapsis"),
        normal=None if normal is None else inputs.parse_direction(normal, "--normal"),
    )
    _emit(f"Gravity assist past {primary}", result, only, fmt)


app.command("hohmann")(reports_errors(displays(hohmann)))
app.command("bi-elliptic")(reports_errors(displays(bi_elliptic)))
app.command("plane-change")(reports_errors(displays(plane_change)))
app.command("phasing")(reports_errors(displays(phasing)))
app.command("departure")(reports_errors(displays(departure)))
app.command("assist")(reports_errors(displays(assist)))
