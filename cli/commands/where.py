"""`orbits where`: where a planet, Pluto or the Moon is at a date, seen from the Earth (or another body)."""

from typing import Annotated

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


def command(
    body_name: Annotated[str, typer.Argument(metavar="BODY", help="a planet, Pluto, the Moon or a barycentre")],
    epoch: EpochOption = None,
    observer: Annotated[str, typer.Option(help="where it is seen from: a planet, Pluto, the Moon or a barycentre "
                                               "(not the Sun: elongation and phase are measured from it)")] = "Earth",
    ephemeris: EphemerisOption = Ephemeris.auto,
    only: OnlyOption = None,
    fmt: FormatOption = Format.table,
    plot: PlotOption = None,
) -> None:
    """Distance from the Sun and the observer, elongation from the Sun (XXI.xi), phase angle, light time and
    geometric ICRF right ascension and declination of a body at a date (default: now). --plot draws the sky
    seen from the observer: the body among the Sun and the planets (the inner ones, or all of them for
    Jupiter-Pluto) on a chart of right ascension and declination, with the ecliptic."""
    from astropy.time import Time

    from orbits._common import inputs
    from orbits.ephemeris import positions as eph
    from orbits_cli import render

    when = eph.epoch(Time.now() if epoch is None else epoch)
    drawn = {}
    if plot:
        from orbits import plot as pictures

        drawn = dict(which=pictures.solar_system_part(body_name), highlight=body_name, observer=observer,
                     source=ephemeris.value)
        points = pictures.solar_system_points(**drawn)
    else:
        points = []
    heliocentric = eph.states([body_name, observer, *points], when, "Sun", source=ephemeris.value)  # read once
    sighting = eph.sighting(heliocentric, body_name, observer)
    seen = sighting.from_observer
    title = f"{seen.point} seen from {seen.center_point}, {eph.tdb_iso(when)} TDB (geometric)"
    about = {"body": seen.point, "observer": seen.center_point, "epoch_tdb": eph.tdb_iso(when), "source": seen.source,
             "accuracy": seen.accuracy}
    quantities = sighting.quantities(inputs.names(only))
    if plot:
        save_plot(lambda: pictures.sky_chart(when, body_name, observer, which=drawn["which"],
                                             source=ephemeris.value, states=heliocentric), plot)
    render.emit(title, quantities, fmt.value, about=about, notes=f"Positions: {seen.provenance}.")
