"""`orbits porkchop`: launch energy C3 and arrival v_inf of the transfers on a grid of launch and arrival dates."""

from typing import Annotated

import typer

from orbits_cli.options import Ephemeris, EphemerisOption, Format, FormatOption, OnlyOption, PlotOption, save_plot


def _window(text: str, option: str) -> tuple[str, str]:
    """'START:END' (ISO dates) as a pair of strings."""
    start, sep, end = text.partition(":")
    if not sep or not start.strip() or not end.strip():
        raise typer.BadParameter(f"{option} {text!r}: write START:END dates, e.g. 2026-09-01:2027-01-31")
    return start.strip(), end.strip()


def command(
    departure: Annotated[str, typer.Option(
        "--from", help="the departure body, e.g. Earth, or EMB (the Earth-Moon barycentre, whose C3 is "
                       "the one NASA's Earth-to-Mars handbook tabulates)")] = "Earth",
    target: Annotated[str, typer.Option("--to", help="the arrival body, e.g. Mars")] = "Mars",
    depart: Annotated[str, typer.Option("--depart", help="departure dates START:END, e.g. 2026-09-01:2027-01-31")
                      ] = "2026-09-01:2027-01-31",
    arrive: Annotated[str, typer.Option("--arrive", help="arrival dates START:END, e.g. 2027-06-01:2028-03-01")
                       ] = "2027-06-01:2028-03-01",
    step: Annotated[str, typer.Option("--step", help="spacing of both date axes, e.g. '1 d'")] = "1 d",
    ephemeris: EphemerisOption = Ephemeris.auto,
    only: OnlyOption = None,
    fmt: FormatOption = Format.table,
    plot: PlotOption = None,
) -> None:
    """The transfers of least departure C3, least arrival v_inf and least total v_inf among the zero-revolution
    prograde Lambert transfers about the Sun on a grid of launch and arrival dates (patched conics, DE421 states).
    JSON adds each minimum's dates as TDB Julian dates (*_jd_tdb); --plot draws the porkchop. A least value on
    the grid's edge is flagged (in JSON under "about", e.g. min_c3_edge): the true minimum may lie outside the
    windows."""
    from orbits import Porkchop
    from orbits._common import inputs
    from orbits._common.tables import check_names
    from orbits.manoeuvres.porkchop import QUANTITY_NAMES
    from orbits_cli import render

    asked = inputs.names(only)
    if asked is not None:
        check_names(asked, QUANTITY_NAMES)  # before the grid's work, not after it
    chart = Porkchop.between(departure, target, _window(depart, "--depart"), _window(arrive, "--arrive"),
                             inputs.parse_quantity(step, "time", "--step"), source=ephemeris.value)
    quantities = chart.quantities(asked)
    if fmt.value != "json":
        quantities = {k: v for k, v in quantities.items() if not k.endswith("_jd_tdb")}
    groups = [(prefix, f"least {best.kind}: {best.launch.tdb.iso[:10]} -> {best.arrival.tdb.iso[:10]}"
                       + (" (edge)" if best.edges else ""))
              for prefix, best in chart.minima().items()]
    about = {f"{prefix}edge": best.edge_note for prefix, best in chart.minima().items() if best.edges}
    if plot:
        from orbits.plot import porkchop

        save_plot(lambda: porkchop(chart), plot)
    title = (f"{chart.departure} to {chart.target}, launch -> arrival dates (TDB) on a grid of "
             f"{chart.launch_dates.size} x {chart.arrival_dates.size}")
    title += "".join(f"; {note}" for note in about.values())
    render.emit(title, quantities, fmt.value, groups=groups, about=about or None,
                notes=f"Positions: {chart.source}.")
