"""`orbits binary`: every section XXII quantity of two finite masses about their centre of mass, what an observer
sees of them (the apparent orbit, the radial-velocity curves), and back from a measured radial-velocity curve
(--K) to the mass function and the companion's mass."""

from typing import TYPE_CHECKING, Annotated

import typer

from orbits_cli.options import (
    MASS_HELP,
    EccentricityOption,
    Format,
    FormatOption,
    InclinationOption,
    NodeOption,
    OnlyOption,
    PeriapsisArgumentOption,
    PlotOption,
    TrueAnomalyOption,
    _writable,
    mass_or_body,
    save_plot,
)

if TYPE_CHECKING:

    from orbits.encounters.binary import Binary, SpectroscopicBinary

SkyOption = Annotated[str | None, typer.Option(
    "--sky", callback=_writable("--plot"), help="draw the apparent orbit on the sky (north up, east left) to this "
    ".png, .svg or .pdf file; the elements are read in the sky frame (x north, y east, z away from us)")]
RvOption = Annotated[str | None, typer.Option(
    "--rv", callback=_writable("--plot"), help="draw both stars' radial-velocity curves to this .png, .svg or .pdf")]
#: what the output says when --inc is not given
UNKNOWN_INCLINATION = ("inclination not given: the radial-velocity semi-amplitudes K1, K2 and the mass function "
                       "need sin i and are left out; give --inc (90: edge-on)")

#: the quantities of `orbits binary` that need the inclination to the sky
NEEDS_INCLINATION = ("rv_semi_amplitude1", "rv_semi_amplitude2", "mass_function", "relative_inclination")


def command(
    m1: Annotated[str | None, typer.Option("--m1", help=f"star 1 (the notes' M): {MASS_HELP}")] = None,
    m2: Annotated[str | None, typer.Option("--m2", help=f"star 2 (the notes' m): {MASS_HELP}")] = None,
    a: Annotated[str | None, typer.Option("--a", help="relative semi-major axis a1 + a2, e.g. '384399 km'")] = None,
    p: Annotated[str | None, typer.Option("--p", help="relative semi-latus rectum")] = None,
    q: Annotated[str | None, typer.Option("--q", help="periapsis separation")] = None,
    period: Annotated[str | None, typer.Option("--period", help="orbital period, e.g. '27.32 d' (sets a)")] = None,
    e: EccentricityOption = 0.0,
    inc: InclinationOption = None,
    raan: NodeOption = None,
    argp: PeriapsisArgumentOption = None,
    nu: TrueAnomalyOption = None,
    k: Annotated[str | None, typer.Option(
        "--K", help="star 1's measured radial-velocity semi-amplitude ('59 m/s'), with --period and --e: the mass "
        "function; with --m1 the companion's minimum mass (and its mass, given --inc)")] = None,
    gamma: Annotated[str | None, typer.Option(
        "--gamma", help="systemic (centre-of-mass) radial velocity, e.g. '12 km/s' [default: 0]")] = None,
    distance: Annotated[str | None, typer.Option(
        "--distance", help="distance of the binary, e.g. '10 pc': --sky in arcsec instead of a length")] = None,
    only: OnlyOption = None,
    fmt: FormatOption = Format.table,
    plot: PlotOption = None,
    sky: SkyOption = None,
    rv: RvOption = None,
) -> None:
    """Masses, relative orbit, each star's orbit about the centre of mass, energy and angular momentum (XXII), and,
    given --inc (the tilt to the sky), the radial-velocity semi-amplitudes and mass function. With --K: from a
    measured radial-velocity curve to the mass function and the companion's (minimum) mass."""
    from orbits._common import inputs
    from orbits_cli import render

    if k is not None:
        result = spectroscopic(k, period, e, m1, inc, {"--m2": m2, "--a": a, "--p": p, "--q": q, "--raan": raan,
                                                       "--argp": argp, "--nu": nu, "--gamma": gamma,
                                                       "--distance": distance, "--plot": plot, "--sky": sky,
                                                       "--rv": rv})
        render.emit(result.title, result.quantities(inputs.names(only)), fmt.value)
        return
    if m1 is None or m2 is None:
        raise typer.BadParameter("give both masses --m1 and --m2 (or --K and --period for a measured "
                                 "radial-velocity curve)")
    if gamma is not None and rv is None:
        raise typer.BadParameter("--gamma, the systemic velocity, shows only in the radial-velocity curves: give "
                                 "--rv FILE too (the table's quantities do not depend on it)")
    result = build(m1, m2, a, p, q, period, e, inc, raan, argp, nu, gamma)
    if inc is None and (sky or rv):
        raise typer.BadParameter(f"{'--sky' if sky else '--rv'} needs the inclination to the sky: give --inc "
                                 f"(90: edge-on, 0: face-on)")
    draw(result, plot, sky, rv, distance, with_velocities=inc is not None)
    groups = [("relative_", "relative orbit (star 2 about star 1)"), ("star1_", "star 1 about the centre of mass"),
              ("star2_", "star 2 about the centre of mass")]
    title, about = f"Binary of {m1} and {m2}", None
    asked = inputs.names(only) or []
    if inc is None and set(asked) & set(NEEDS_INCLINATION):
        raise typer.BadParameter(f"{', '.join(n for n in asked if n in NEEDS_INCLINATION)}: needs the inclination "
                                 f"to the sky (sin i): give --inc (90: edge-on, 0: face-on)")
    if inc is None and only is None:
        about = {"inclination": UNKNOWN_INCLINATION}
        title += f"; {UNKNOWN_INCLINATION}"
    render.emit(title, result.quantities(inputs.names(only)), fmt.value, groups=groups, about=about)


def draw(result: "Binary", plot: str | None, sky: str | None, rv: str | None, distance: str | None,
         with_velocities: bool) -> None:
    """The pictures asked for: the orbits about the centre of mass (beside the radial velocities when the
    inclination is known), the sky, the radial velocities."""
    from orbits._common.inputs import parse_quantity

    if distance is not None and sky is None:
        raise typer.BadParameter("--distance sets the scale of --sky: give --sky FILE too")
    if plot:
        save_plot(lambda: _plane_and_velocities(result, with_velocities), plot)
    if sky:
        from orbits.plot import binary_sky

        far = None if distance is None else parse_quantity(distance, "length", "--distance")
        save_plot(lambda: binary_sky(result, distance=far), sky)
    if rv:
        from orbits.plot import radial_velocity_curves

        save_plot(lambda: radial_velocity_curves(result), rv)


def _plane_and_velocities(result: "Binary", with_velocities: bool) -> tuple:
    """The orbits about the centre of mass; with a known inclination, the radial-velocity curves beside them."""
    from orbits.plot import binary_plane, radial_velocity_curves

    if not with_velocities:
        return binary_plane(result)
    import matplotlib.pyplot as plt

    fig, (plane, velocities) = plt.subplots(1, 2, figsize=(16.0, 6.4), layout="constrained",
                                            gridspec_kw={"width_ratios": (1.0, 1.25)})
    binary_plane(result, ax=plane)
    radial_velocity_curves(result, ax=velocities)
    return fig, (plane, velocities)


def spectroscopic(k: str, period: str | None, e: float, m1: str | None, inc: str | None,
                  others: dict[str, str | None]) -> "SpectroscopicBinary":
    """The SpectroscopicBinary of --K, --period, --e and, if given, --m1 and --inc; BadParameter for options that
    belong to a binary of known masses."""
    from orbits._common.inputs import parse_angle, parse_quantity
    from orbits.encounters.binary import SpectroscopicBinary

    given = [name for name, value in others.items() if value is not None]
    if given:
        verb = "does" if len(given) == 1 else "do"
        raise typer.BadParameter(f"{', '.join(given)} {verb} not apply with --K: a radial-velocity curve gives "
                                 f"the mass function; drop --K to describe a binary of known masses")
    if period is None:
        raise typer.BadParameter("--K needs the period of the radial-velocity curve: --period '4.23 d'")
    return SpectroscopicBinary.from_curve(
        parse_quantity(period, "time", "--period"),
        parse_quantity(k, "speed", "--K"),
        e,
        primary_mass=None if m1 is None else mass_or_body(m1, "--m1"),
        inc=None if inc is None else parse_angle(inc, "--inc"),
    )


def build(
    m1: str,
    m2: str,
    a: str | None,
    p: str | None,
    q: str | None,
    period: str | None,
    e: float,
    inc: str | None,
    raan: str | None,
    argp: str | None,
    nu: str | None,
    gamma: str | None = None,
) -> "Binary":
    """The Binary described by the options; BadParameter when no size (or more than one) is given."""
    import astropy.units as u
    import numpy as np

    from orbits import Binary
    from orbits._common import inputs
    from orbits_cli import params

    sizes = {"a": a, "p": p, "q": q, "period": period}
    given = [k for k, x in sizes.items() if x is not None]
    if len(given) != 1:
        raise typer.BadParameter(f"give exactly one size of --a, --p, --q, --period; got {given or 'none'}")
    kind = "time" if given[0] == "period" else "length"
    size = {given[0]: inputs.parse_quantity(sizes[given[0]], kind, f"--{given[0]}")}
    com_v = None
    if gamma is not None:
        along_sight = inputs.parse_quantity(gamma, "speed", "--gamma").to_value(u.m / u.s)
        com_v = np.array([0.0, 0.0, along_sight]) << u.m / u.s  # z: the line of sight, away from us
    angles = params.orientation(*(x or "0" for x in (inc, raan, argp, nu)))
    if inc is None:
        angles.pop("inc")  # not given: the tilt to the sky is unknown, and what needs sin i is left out
    return Binary.from_elements(mass_or_body(m1, "--m1"), mass_or_body(m2, "--m2"), e=e, com_v=com_v, **angles,
                                **size)
