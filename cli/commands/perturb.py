"""`orbits perturb`: secular rates about an oblate body, orbit designs (sun-synchronous, frozen, repeat ground
track), drag decay, the Kozai-Lidov oscillation and general relativity's periapsis advance.

A sub-application with one command per question; main.py mounts it with app.add_typer(perturb.app). Tables show
rates in deg/day, lengths in km, times in days or years (any --unit NAME=UNIT still wins); JSON is exact SI."""

from typing import Annotated

import typer

from orbits_cli.options import (
    MASS_HELP,
    Format,
    FormatOption,
    OnlyOption,
    PlotOption,
    displays,
    mass_or_body,
    reports_errors,
    save_plot,
)

app = typer.Typer(
    help="Perturbed orbits: J2 secular rates and designs, drag decay, Kozai-Lidov, the relativistic advance.",
    no_args_is_help=True,
)

PrimaryOption = Annotated[str, typer.Option("--primary", help="a catalogue body with J2")]
SizeOption = Annotated[str | None, typer.Option("--a", help="semi-major axis, e.g. '7078 km'")]
AltitudeOption = Annotated[str | None, typer.Option("--altitude", help="a - R_eq, e.g. '700 km'")]
InclinationOption = Annotated[str | None, typer.Option("--inc", help="inclination ('98 deg'; bare numbers are "
                                                                     "degrees)")]
RevolutionsOption = Annotated[int | None, typer.Option("--plot-revolutions", min=1, max=2000,
                                                       help="revolutions the --plot integrates (default 30)")]


def _plot_only(plot, **given) -> None:
    """Refuse an option that only --plot reads, given without --plot (it would be ignored)."""
    for option, value in given.items():
        if value is not None and not plot:
            raise typer.BadParameter(f"--{option.replace('_', '-')} sets what --plot integrates; give --plot FILE "
                                     f"with it")

#: the units tables use for these quantities unless --units si or --unit NAME=UNIT says otherwise
NATURAL = {
    "node_rate": "deg / d", "periapsis_rate": "deg / d", "mean_anomaly_rate": "deg / d", "node_rate_target": "deg / d",
    "nodal_period": "min", "semi_major_axis": "km", "osculating_semi_major_axis_at_node": "km", "altitude": "km",
    "base_altitude": "km", "scale_height": "km",
    "decay_rate": "km / d", "decay_per_revolution": "km", "lifetime": "d", "breakdown_altitude": "km",
    "timescale": "yr", "period": "yr", "advance_per_orbit": "arcsec", "advance_per_century": "arcsec",
    "density_at_base": "kg / m3",
}


def emit(title: str, quantities: dict, fmt: Format) -> None:
    """render.emit with this verb's natural units (for the quantities shown) under the user's own choices."""
    from orbits_cli import render

    shown = render.DISPLAY
    if shown.system == "natural":
        defaults = {name: unit for name, unit in NATURAL.items() if name in quantities}
        render.use(render.Display(shown.system, {**defaults, **shown.overrides}, shown.digits))
    try:
        render.emit(title, quantities, fmt.value)
    finally:
        render.use(shown)


def _length(text, option):
    from orbits._common import inputs

    return None if text is None else inputs.parse_quantity(text, "length", option)


def _angle(text, option):
    from orbits._common import inputs

    return None if text is None else inputs.parse_angle(text, option)


def rates(
    primary: PrimaryOption = "Earth",
    a: SizeOption = None,
    altitude: AltitudeOption = None,
    e: Annotated[float, typer.Option("--e", help="eccentricity")] = 0.0,
    inc: InclinationOption = "0",
    argp: Annotated[str, typer.Option("--argp", help="argument of periapsis")] = "0",
    only: OnlyOption = None,
    fmt: FormatOption = Format.table,
    plot: PlotOption = None,
    plot_revolutions: RevolutionsOption = None,
) -> None:
    """J2's secular rates of the node, periapsis and mean anomaly (first order: good to J2 (R/p)**2 relative).

    --plot integrates the orbit under the body's J2 and J4 with rebound and heyoka for --plot-revolutions and draws
    its node (and, for an eccentric orbit, its argument of periapsis) over the secular lines of these rates.
    """
    from orbits import SecularOrbit
    from orbits._common import inputs
    from orbits.perturb.secular import oblate_body

    _plot_only(plot, plot_revolutions=plot_revolutions)
    secular = SecularOrbit.about(primary, a=_length(a, "--a"), altitude=_length(altitude, "--altitude"), e=e,
                                 inc=_angle(inc, "--inc"), argp=_angle(argp, "--argp"))
    emit(f"J2 secular rates about {oblate_body(primary).name} (first order; accuracy J2 (R/p)^2)",
         secular.quantities(inputs.names(only)), fmt)
    if plot:
        _plot_secular(secular.orbit, plot_revolutions, plot)


def _plot_secular(orbit, revolutions: int | None, path):
    """The orbit integrated under J2 and J4 (orbits.validate.histories.secular_history), drawn to `path`."""
    from orbits.plot import secular_elements
    from orbits.validate.histories import secular_history

    history = secular_history(orbit, 30 if revolutions is None else revolutions)
    save_plot(lambda: secular_elements(history), path)


def sun_synchronous(
    primary: PrimaryOption = "Earth",
    a: SizeOption = None,
    altitude: AltitudeOption = None,
    e: Annotated[float, typer.Option("--e", help="eccentricity")] = 0.0,
    inc: Annotated[str | None, typer.Option("--inc", help="solve for the size at this inclination instead")] = None,
    only: OnlyOption = None,
    fmt: FormatOption = Format.table,
    plot: PlotOption = None,
    plot_revolutions: RevolutionsOption = None,
) -> None:
    """The sun-synchronous orbit: its inclination for a size (or its size for an inclination).

    --plot integrates the orbit under the body's J2 and J4 with rebound and heyoka for --plot-revolutions and draws
    its node turning with the mean Sun over the secular line.
    """
    from orbits import sun_synchronous as design
    from orbits._common import inputs

    _plot_only(plot, plot_revolutions=plot_revolutions)
    result = design(primary, a=_length(a, "--a"), altitude=_length(altitude, "--altitude"), e=e,
                    inc=_angle(inc, "--inc"))
    emit(f"Sun-synchronous orbit about {result.primary.name} (node follows the mean Sun)",
         result.quantities(inputs.names(only)), fmt)
    if plot:
        _plot_secular(result.secular.orbit, plot_revolutions, plot)


def frozen(
    primary: PrimaryOption = "Earth",
    a: SizeOption = None,
    altitude: AltitudeOption = None,
    inc: Annotated[str, typer.Option("--inc", help="inclination")] = "98",
    argp: Annotated[str, typer.Option("--argp", help="argument of periapsis: 90 or 270 deg")] = "90",
    only: OnlyOption = None,
    fmt: FormatOption = Format.table,
    plot: PlotOption = None,
    plot_revolutions: Annotated[int | None, typer.Option(
        "--plot-revolutions", min=1, max=4000, help="revolutions the --plot integrates (default: one apsidal "
        "period)")] = None,
) -> None:
    """The frozen orbit (J2 with J3): the eccentricity that keeps e and omega fixed.

    --plot integrates the design and a circular orbit of its size and inclination under the body's J2, J3 and J4
    with rebound and heyoka and draws their mean eccentricity vectors circling the frozen point (one apsidal period
    by default: about 1,700 revolutions, 15 s, at 700 km)."""
    from orbits import frozen as design
    from orbits._common import inputs

    _plot_only(plot, plot_revolutions=plot_revolutions)
    result = design(primary, a=_length(a, "--a"), altitude=_length(altitude, "--altitude"), inc=_angle(inc, "--inc"),
                    argp=_angle(argp, "--argp"))
    if plot:  # integrated first: a run too long for a picture is refused before anything is printed
        from orbits.validate.histories import frozen_history

        history = frozen_history(result, plot_revolutions)
    emit(f"Frozen orbit about {result.primary.name} (J2 with J3, first order)", result.quantities(inputs.names(only)),
         fmt)
    if plot:
        from orbits.plot import frozen_eccentricity

        save_plot(lambda: frozen_eccentricity(history), plot)


def repeat(
    primary: PrimaryOption = "Earth",
    revolutions: Annotated[int, typer.Option("--revolutions", help="revolutions (nodal periods) per cycle")] = 15,
    days: Annotated[int, typer.Option("--days", help="days (turns of the body under the node) per cycle")] = 1,
    inc: Annotated[str, typer.Option("--inc", help="inclination")] = "98",
    e: Annotated[float, typer.Option("--e", help="eccentricity")] = 0.0,
    only: OnlyOption = None,
    fmt: FormatOption = Format.table,
    plot: PlotOption = None,
) -> None:
    """The repeat-ground-track orbit: k revolutions in d days, J2 included.

    --plot integrates one cycle under the body's J2 and J4 with rebound and heyoka and draws the track over the
    turning body, with each ascending node against the closed form's place for it (at most 2000 revolutions)."""
    from orbits._common import inputs
    from orbits.perturb.secular import repeat_ground_track

    result = repeat_ground_track(primary, revolutions=revolutions, days=days, inc=_angle(inc, "--inc"), e=e)
    if plot:  # integrated first: a run too long for a picture is refused before anything is printed
        from orbits.validate.histories import ground_track

        track = ground_track(result)
    emit(f"Repeat ground track about {result.primary.name}: {revolutions} revolutions in {days} days",
         result.quantities(inputs.names(only)), fmt)
    if plot:
        from orbits.plot import ground_track as draw

        save_plot(lambda: draw(track), plot)


def decay(
    primary: PrimaryOption = "Earth",
    altitude: Annotated[str, typer.Option("--altitude", help="altitude of the circular orbit")] = "400 km",
    ballistic: Annotated[str, typer.Option("--ballistic", help="C_D A / m, e.g. '0.01 m2/kg'")] = "0.01 m2/kg",
    density: Annotated[str | None, typer.Option("--density", help="the band's density at its base")] = None,
    scale_height: Annotated[str | None, typer.Option("--scale-height", help="the band's scale height H")] = None,
    base: Annotated[str | None, typer.Option("--base-altitude", help="the band's base altitude")] = None,
    only: OnlyOption = None,
    fmt: FormatOption = Format.table,
    plot: PlotOption = None,
) -> None:
    """Drag decay of a circular orbit in an exponential atmosphere band (the Earth's standard table by default).

    --plot draws the closed form's altitude against time to the end of the lifetime, where it stops holding.
    """
    from orbits._common import inputs
    from orbits.perturb.secular import DragDecay

    mass = None if density is None else inputs.parse_quantity(density, "density", "--density")
    result = DragDecay.of(primary, altitude=_length(altitude, "--altitude"),
                          ballistic=inputs.parse_quantity(ballistic, "area per mass", "--ballistic"),
                          density=mass, scale_height=_length(scale_height, "--scale-height"),
                          base_altitude=_length(base, "--base-altitude"))
    emit(f"Drag decay about {primary} (circular orbit, exponential band; accuracy (da_rev / H)^2)",
         result.quantities(inputs.names(only)), fmt)
    if plot:
        from orbits.plot import drag_decay

        save_plot(lambda: drag_decay(result), plot)


def kozai(
    primary: Annotated[str, typer.Option("--primary", help=f"the central body: {MASS_HELP}")] = "Sun",
    perturber: Annotated[str, typer.Option("--perturber", help=f"the distant perturber: {MASS_HELP}")] = "Jupiter",
    a: Annotated[str, typer.Option("--a", help="inner semi-major axis")] = "1 AU",
    a_out: Annotated[str, typer.Option("--a-out", help="the perturber's semi-major axis")] = "5.2 AU",
    inc: Annotated[str, typer.Option("--inc", help="inclination to the perturber's orbit")] = "65",
    e: Annotated[float, typer.Option("--e", help="initial eccentricity (> 0)")] = 0.001,
    argp: Annotated[str, typer.Option("--argp", help="initial argument of periapsis")] = "90",
    e_out: Annotated[float, typer.Option("--e-out", help="the perturber's eccentricity")] = 0.0,
    cycles: Annotated[float | None, typer.Option("--cycles", min=0.1, max=4.0,
                                                 help="oscillations of e the --plot integrates (default 2)")] = None,
    only: OnlyOption = None,
    fmt: FormatOption = Format.table,
    plot: PlotOption = None,
) -> None:
    """The quadrupole Kozai-Lidov oscillation of a test particle (e and i range, period, validity).

    --plot integrates the triple with rebound and heyoka for --cycles oscillations and draws e, i and the conserved
    sqrt(1 - e^2) cos i over the theory's marks; a triple whose cycles last more than 20,000 inner revolutions is
    refused (a nearer or heavier perturber, or fewer cycles)."""
    from orbits._common import inputs
    from orbits.perturb.secular import KozaiLidov

    _plot_only(plot, cycles=cycles)
    result = KozaiLidov.of(mass_or_body(primary, "--primary"), mass_or_body(perturber, "--perturber"),
                           a=_length(a, "--a"),
                           a_out=_length(a_out, "--a-out"), inc=_angle(inc, "--inc"), e=e, argp=_angle(argp, "--argp"),
                           e_out=e_out)
    if plot:  # integrated first: a run too long for a picture is refused before anything is printed
        from orbits.validate.histories import kozai_history

        history = kozai_history(cycles=2.0 if cycles is None else cycles, triple=result)
    emit("Kozai-Lidov oscillation (quadrupole, test particle; octupole and averaging parameters give its error)",
         result.quantities(inputs.names(only)), fmt)
    if plot:
        from orbits.plot import kozai_cycles

        save_plot(lambda: kozai_cycles(history), plot)


def relativity(
    name: Annotated[str, typer.Argument(metavar="BODY", help="a catalogue body with a mean orbit")] = "Mercury",
    only: OnlyOption = None,
    fmt: FormatOption = Format.table,
) -> None:
    """General relativity's periapsis advance 6 pi G M / (c^2 a (1 - e^2)) of a body's mean orbit."""
    import astropy.units as u

    from orbits import Orbit
    from orbits._common import inputs
    from orbits._common.tables import check_names
    from orbits.perturb.secular import relativistic_periapsis_advance

    per_orbit, rate = relativistic_periapsis_advance(Orbit.from_body(name))
    table = {"advance_per_orbit": per_orbit, "advance_per_century": (rate * 36525 * u.day).to(u.rad),
             "periapsis_rate": rate}
    names = inputs.names(only) or list(table)
    check_names(names, list(table))
    emit(f"Relativistic periapsis advance of {name} (1PN; relative error G M / (c^2 p))",
         {n: table[n] for n in names}, fmt)


app.command("rates")(reports_errors(displays(rates)))
app.command("sun-synchronous")(reports_errors(displays(sun_synchronous)))
app.command("frozen")(reports_errors(displays(frozen)))
app.command("repeat")(reports_errors(displays(repeat)))
app.command("decay")(reports_errors(displays(decay)))
app.command("kozai")(reports_errors(displays(kozai)))
app.command("relativity")(reports_errors(displays(relativity)))
