"""`orbits where`: where a planet, Pluto or the Moon is at a date, seen from the Earth (or another body)."""

from typing import Annotated

import typer

from orbits_cli.options import Ephemeris, EphemerisOption, EpochOption, Format, FormatOption, OnlyOption


def command(
    body_name: Annotated[str, typer.Argument(metavar="BODY", help="a planet, Pluto, the Moon or a barycentre")],
    epoch: EpochOption = None,
    observer: Annotated[str, typer.Option(help="where it is seen from (a planet, the Moon, the Sun)")] = "Earth",
    ephemeris: EphemerisOption = Ephemeris.auto,
    only: OnlyOption = None,
    fmt: FormatOption = Format.table,
) -> None:
    """Distance from the Sun and the observer, elongation from the Sun (XXI.xi), phase angle, light time and
    geometric ICRF right ascension and declination of a body at a date (default: now)."""
    from astropy.time import Time

    from orbits import ephemeris as eph
    from orbits import inputs
    from orbits_cli import render

    when = Time.now() if epoch is None else eph.epoch(epoch)
    sighting = eph.where(body_name, when, observer, source=ephemeris.value)
    seen = sighting.from_observer
    title = (f"{seen.point} seen from {seen.center}, {when.tdb.iso[:19]} TDB (geometric, no light-time "
             f"correction); source: {seen.source}")
    render.emit(title, sighting.quantities(inputs.names(only)), fmt.value)
