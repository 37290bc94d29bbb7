"""`orbits orbit`: every section XXI quantity of an orbit from a named body, elements or a state vector."""

from typing import TYPE_CHECKING, Annotated

import typer

from orbits_cli.options import (
    Ephemeris,
    EphemerisOption,
    EpochOption,
    Format,
    FormatOption,
    OnlyOption,
    PlotOption,
    save_plot,
)

if TYPE_CHECKING:
    from astropy.units import Quantity

    from orbits.twobody.orbit import Orbit


def command(
    body_name: Annotated[
        str | None, typer.Argument(metavar="[BODY]", help="a named body (Mars, Moon, ...): its J2000 mean orbit, "
                                   "or with --epoch its osculating orbit from the ephemeris")
    ] = None,
    epoch: EpochOption = None,
    ephemeris: EphemerisOption = Ephemeris.auto,
    primary: Annotated[
        str | None, typer.Option(help="central body: name, mass ('5.97e24 kg') or GM ('3.986e14 m3/s2') [default: Sun]")
    ] = None,
    a: Annotated[str | None, typer.Option("--a", help="semi-major axis, e.g. '1 AU' (negative for hyperbolas)")] = None,
    p: Annotated[str | None, typer.Option("--p", help="semi-latus rectum")] = None,
    q: Annotated[str | None, typer.Option("--q", help="periapsis distance (use for e = 1)")] = None,
    e: Annotated[float | None, typer.Option("--e", help="eccentricity [default: 0]")] = None,
    inc: Annotated[str | None, typer.Option("--inc", help="inclination ('28.5 deg'; bare numbers are degrees)")] = None,
    raan: Annotated[str | None, typer.Option("--raan", help="longitude of the ascending node [default: 0]")] = None,
    argp: Annotated[str | None, typer.Option("--argp", help="argument of periapsis [default: 0]")] = None,
    nu: Annotated[str | None, typer.Option("--nu", help="true anomaly [default: 0]")] = None,
    r: Annotated[
        str | None, typer.Option("--r", help="position vector 'X,Y,Z UNIT' (with --v instead of elements)")
    ] = None,
    v: Annotated[str | None, typer.Option("--v", help="velocity vector 'X,Y,Z UNIT'")] = None,
    mass: Annotated[str | None, typer.Option(help="orbiting body's mass, for U, K, E, L")] = None,
    at_r: Annotated[str | None, typer.Option(
        "--at-r", help="also the speed (and, given --mass, U and K) at this distance from the centre, e.g. '8000 km'")
    ] = None,
    area_between: Annotated[str | None, typer.Option(
        "--area-between", help="also the area the radius vector sweeps between two times after now, 'T1,T2', e.g. "
        "'0 h,2 h'")] = None,
    only: OnlyOption = None,
    fmt: FormatOption = Format.table,
    plot: PlotOption = None,
) -> None:
    """Every section XXI quantity of an orbit, from elements, a state vector, or a named body; with --at-r the speed,
    U and K at a distance, with --area-between the area swept between two times. A body without an ephemeris
    (Ceres, Vesta, Pallas, Hygiea, Eris) is carried to --epoch from its published orbit by two-body propagation,
    and a note after the table says how well."""
    from orbits._common import inputs
    from orbits_cli import render

    if body_name is None and epoch is not None:
        raise typer.BadParameter("--epoch needs a BODY: the osculating orbit of a planet, Pluto or the Moon")
    about, notes = None, ""
    if body_name is not None and epoch is not None:
        result, title, about, notes = at_epoch(body_name, epoch, ephemeris.value,
                                               [mass, primary, a, p, q, e, inc, raan, argp, nu, r])
    else:
        result, title = build(body_name, primary, a, p, q, e, inc, raan, argp, nu, r, v, mass)
        if body_name is not None:
            title, about, notes = published_orbit(body_name)
    asked = inputs.names(only)
    extra = course_quantities(result, at_r, area_between)
    quantities = result.quantities(None if asked is None else [n for n in asked if n not in extra])
    quantities.update({name: q for name, q in extra.items() if asked is None or name in asked})
    if plot:
        from orbits.plot import orbit_plane

        when = None if about is None or "epoch_tdb" not in about else f"{about['epoch_tdb']} TDB"
        save_plot(lambda: orbit_plane(result, epoch=when), plot)
    render.emit(title, quantities, fmt.value, about=about, notes=notes)


def published_orbit(body_name: str) -> "tuple[str, dict[str, str], str]":
    """(title, JSON 'about') of a named body's published orbit: its source, epoch, frame and accuracy."""
    from astropy.time import Time

    from orbits import body
    from orbits.ephemeris.catalogue import mean_elements

    el = mean_elements(body_name)
    when = Time(el.epoch, format="jd", scale="tdb").iso[:16]
    frame = "ecliptic J2000"
    title = f"{body(body_name).name}'s orbit at {when} TDB, {frame}"
    about = {"body": body(body_name).name, "epoch_tdb": when, "source": el.source, "frame": frame}
    notes = f"Source: {el.source}."
    if el.accuracy:
        notes += f" {el.accuracy[0].upper()}{el.accuracy[1:]}."
        about["accuracy"] = el.accuracy
    return title, about, notes


def course_quantities(orbit: "Orbit", at_r: str | None, area_between: str | None) -> "dict[str, Quantity]":
    """{name: Quantity} of what --at-r and --area-between ask: speed_at_r, potential_energy_at_r and
    kinetic_energy_at_r (with the orbit's mass), area_swept."""
    from orbits._common.inputs import parse_quantity

    extra = {}
    if at_r is not None:
        r = parse_quantity(at_r, "length", "--at-r")
        extra["speed_at_r"] = orbit.speed_at(r)
        if orbit.mass is not None:
            extra["potential_energy_at_r"] = orbit.potential_energy_at(r)
            extra["kinetic_energy_at_r"] = orbit.kinetic_energy_at(r)
    if area_between is not None:
        times = area_between.split(",")
        if len(times) != 2:
            raise typer.BadParameter(f"--area-between {area_between!r}: write T1,T2, e.g. '0 h,2 h'")
        t1, t2 = (parse_quantity(t.strip(), "time", "--area-between") for t in times)
        extra["area_swept"] = orbit.area_swept(t1, t2)
    return extra


def at_epoch(body_name: str, epoch: str, source: str, others: list) -> "tuple[Orbit, str, dict[str, str], str]":
    """(the body's osculating orbit at `epoch`, its title, the JSON's "about", and the notes printed after the
    table: the ephemeris that answered and its accuracy)."""
    from orbits import Orbit, OrbitDomainError, body
    from orbits.ephemeris import positions as ephemeris

    if any(option is not None for option in others):
        raise typer.BadParameter(f"with --epoch, {body_name}'s orbit comes from the ephemeris: drop the elements")
    named = body(body_name)
    if named.parent is None:
        raise OrbitDomainError(f"{named.name} orbits nothing in the catalogue")
    when = ephemeris.epoch(epoch)
    seen = ephemeris.state(named.name, when, named.parent, source=source)
    orbit = Orbit.from_state(seen)
    title = (f"Osculating orbit of {seen.point} about the {seen.center_point}, {ephemeris.tdb_iso(when)} TDB, "
             f"ecliptic J2000")
    about = {"body": seen.point, "center": seen.center_point, "epoch_tdb": ephemeris.tdb_iso(when),
             "source": seen.source, "accuracy": seen.accuracy, "frame": "ecliptic J2000"}
    return orbit, title, about, f"Positions: {seen.provenance}."


def build(
    body_name: str | None,
    primary: str | None,
    a: str | None,
    p: str | None,
    q: str | None,
    e: float | None,
    inc: str | None,
    raan: str | None,
    argp: str | None,
    nu: str | None,
    r: str | None,
    v: str | None,
    mass: str | None,
) -> "tuple[Orbit, str]":
    """(Orbit, title) from the command's options; BadParameter for inconsistent combinations."""
    from orbits import Orbit, body
    from orbits._common.inputs import parse_primary, parse_quantity, parse_vector
    from orbits_cli import params

    mass_q = None if mass is None else parse_quantity(mass, "mass", "--mass")
    elements = {"--a": a, "--p": p, "--q": q, "--e": e, "--inc": inc, "--raan": raan, "--argp": argp, "--nu": nu}
    if body_name is not None:
        given = [flag for flag, option in {**elements, "--primary": primary, "--r": r, "--v": v, "--mass": mass}.items()
                 if option is not None]
        if given:
            verb = "does" if len(given) == 1 else "do"
            raise typer.BadParameter(f"{', '.join(given)} {verb} not apply to {body_name}: a named body's orbit "
                                     f"comes from the catalogue; drop BODY to give an orbit of your own")
        orbit = Orbit.from_body(body_name)
        return orbit, f"{body(body_name).name}'s mean orbit"
    center = parse_primary("Sun" if primary is None else primary)
    if (r is None) != (v is None):
        raise typer.BadParameter("give both --r and --v for a state vector")
    if r is not None:
        given = [flag for flag, option in elements.items() if option is not None]
        if given:
            raise typer.BadParameter(f"give either a state vector (--r, --v) or elements ({', '.join(given)}), "
                                     f"not both")
        orbit = Orbit.from_vectors(center, parse_vector(r, "length", "--r"), parse_vector(v, "speed", "--v"),
                                   mass=mass_q)
        return orbit, "Orbit from a state vector"
    if a is None and p is None and q is None:
        raise typer.BadParameter("give a size (--a, --p or --q), a state vector (--r and --v), or a BODY name")
    sizes = {key: None if text is None else parse_quantity(text, "length", f"--{key}")
             for key, text in zip("apq", (a, p, q))}
    angles = params.orientation(*(angle or "0" for angle in (inc, raan, argp, nu)))
    orbit = Orbit.from_elements(center, e=0.0 if e is None else e, **angles, mass=mass_q, **sizes)
    return orbit, "Orbit from elements"
