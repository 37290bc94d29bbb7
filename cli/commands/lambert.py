"""`orbits lambert`: the transfer orbit from r1 to r2 in a given time of flight (Lambert's problem), or from one
body to another between two dates (positions from the ephemeris, C3 and v_inf at both ends)."""

from typing import Annotated

import typer

from orbits_cli.options import MASS_HELP, Ephemeris, EphemerisOption, Format, FormatOption, OnlyOption


def command(
    r1: Annotated[str | None, typer.Option("--r1", help="departure position 'X,Y,Z UNIT', e.g. '1,0,0 AU'")] = None,
    r2: Annotated[str | None, typer.Option("--r2", help="arrival position, e.g. '0,1.5,0 AU'")] = None,
    tof: Annotated[str | None, typer.Option("--tof", help="time of flight, e.g. '200 d'")] = None,
    departure: Annotated[str | None, typer.Option(
        "--from", help="departure body instead of --r1, e.g. Earth (with --depart; positions from the ephemeris)")
    ] = None,
    target: Annotated[str | None, typer.Option("--to", help="arrival body instead of --r2, e.g. Mars")] = None,
    depart: Annotated[str | None, typer.Option(
        "--depart", help="departure date with --from, e.g. 2026-11-26 (UTC, or '... TDB')")] = None,
    arrive: Annotated[str | None, typer.Option("--arrive", help="arrival date with --to, e.g. 2027-08-15")] = None,
    ephemeris: EphemerisOption = Ephemeris.auto,
    primary: Annotated[str, typer.Option(help=f"the attracting body: {MASS_HELP}")] = "Sun",
    revolutions: Annotated[int, typer.Option(min=0, help="complete revolutions before arrival")] = 0,
    branch: Annotated[str | None, typer.Option(help="left or right: which of the two solutions when revolutions > 0 "
                                                    "(default right, lamberthub's low path)")] = None,
    retrograde: Annotated[bool, typer.Option(
        "--retrograde", help="clockwise about +z, or about the ecliptic pole between bodies (default: prograde; "
                             "not with --normal, which sets the sense)")
    ] = False,
    normal: Annotated[str | None, typer.Option(
        help="the orbit's angular momentum direction 'X,Y,Z' (any unit or none); needed when r1, r2 are opposite"
    )] = None,
    only: OnlyOption = None,
    fmt: FormatOption = Format.table,
) -> None:
    """Velocities, transfer angle and elements of the conic from r1 to r2 in the time of flight (Izzo's method);
    between bodies (--from, --to, --depart, --arrive: positions from the ephemeris, exactly as orbits porkchop
    computes a cell) also the launch energy C3 and v_inf at both ends."""
    from orbits import lambert
    from orbits._common import inputs
    from orbits_cli import render

    common = {"revolutions": revolutions, "branch": branch, "prograde": False if retrograde else None,
              "normal": None if normal is None else inputs.parse_direction(normal, "--normal")}
    shown = f", {revolutions} revolutions ({branch or 'right'} branch)" if revolutions else ""
    if departure is not None or target is not None:
        transfer = between_bodies(departure, target, depart, arrive, ephemeris.value, primary,
                                  {"--r1": r1, "--r2": r2, "--tof": tof}, common)
        start, end = transfer.departure, transfer.arrival
        from orbits.ephemeris.positions import provenance, tdb_iso

        source, stated = provenance(start, end)

        title = (f"Lambert transfer from {start.point} ({tdb_iso(start.epoch)} TDB) to {end.point} "
                 f"({tdb_iso(end.epoch)} TDB) about the Sun{shown}; vectors in the ICRF (equatorial), elements in "
                 f"the ecliptic of J2000; positions: {source}" + (f"; {stated}" if stated else ""))
        about = {"from": start.point, "to": end.point, "depart_tdb": tdb_iso(start.epoch),
                 "arrive_tdb": tdb_iso(end.epoch), "source": source,
                 "accuracy": stated or start.accuracy,
                 "frame": "ICRF vectors, elements in the ecliptic of J2000"}
        render.emit(title, transfer.quantities(inputs.names(only)), fmt.value, about=about)
        return
    if depart is not None or arrive is not None:
        raise typer.BadParameter("--depart and --arrive date a transfer between bodies: give --from and --to")
    named = [(option, text) for option, text in (("--r1", r1), ("--r2", r2)) if text and inputs.find_body(text)]
    if named:
        option, text = named[0]
        raise typer.BadParameter(f"{option} {text!r} is a body, not a position: for a transfer between bodies give "
                                 f"--from and --to with --depart and --arrive dates, e.g. --from Earth --to Mars "
                                 f"--depart 2026-11-26 --arrive 2027-08-15")
    missing = [name for name, value in (("--r1", r1), ("--r2", r2), ("--tof", tof)) if value is None]
    if missing:
        raise typer.BadParameter(f"give {', '.join(missing)} (or bodies: --from Earth --to Mars --depart DATE "
                                 f"--arrive DATE)")
    transfer = lambert(inputs.parse_vector(r1, "length", "--r1"), inputs.parse_vector(r2, "length", "--r2"),
                       inputs.parse_quantity(tof, "time", "--tof"), inputs.parse_primary(primary), **common)
    render.emit(f"Lambert transfer about {primary}{shown}", transfer.quantities(inputs.names(only)), fmt.value)


def between_bodies(departure, target, depart, arrive, source, primary, positions, common):
    """The LambertTransfer between two bodies on two dates; BadParameter for a missing or conflicting option."""
    from orbits import lambert

    given = [name for name, value in positions.items() if value is not None]
    if given:
        raise typer.BadParameter(f"{', '.join(given)}: with --from and --to the positions and the time of flight "
                                 f"come from the bodies and the dates")
    missing = [name for name, value in (("--from", departure), ("--to", target), ("--depart", depart),
                                        ("--arrive", arrive)) if value is None]
    if missing:
        raise typer.BadParameter(f"a transfer between bodies needs {', '.join(missing)} too")
    if primary.strip().lower() != "sun":
        raise typer.BadParameter("--primary: a transfer between bodies is about the Sun")
    return lambert(departure, target, depart=depart, arrive=arrive, source=source, **common)
