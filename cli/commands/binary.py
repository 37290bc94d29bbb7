"""`orbits binary`: every section XXII quantity of two finite masses about their centre of mass."""

from typing import TYPE_CHECKING, Annotated

import typer

from orbits_cli.options import (
    EccentricityOption,
    Format,
    FormatOption,
    InclinationOption,
    NodeOption,
    OnlyOption,
    PeriapsisArgumentOption,
    PlotOption,
    TrueAnomalyOption,
    save_plot,
)

if TYPE_CHECKING:
    from astropy.units import Quantity

    from orbits.binary import Binary
    from orbits.constants import Body

MASS_HELP = "body name (Earth, Moon, Sun, Jupiter), mass ('1.989e30 kg', '1 solMass') or GM ('3.986e14 m3/s2')"


def command(
    m1: Annotated[str, typer.Option("--m1", help=f"star 1 (the notes' M): {MASS_HELP}")],
    m2: Annotated[str, typer.Option("--m2", help=f"star 2 (the notes' m): {MASS_HELP}")],
    a: Annotated[str | None, typer.Option("--a", help="relative semi-major axis a1 + a2, e.g. '384399 km'")] = None,
    p: Annotated[str | None, typer.Option("--p", help="relative semi-latus rectum")] = None,
    q: Annotated[str | None, typer.Option("--q", help="periapsis separation")] = None,
    period: Annotated[str | None, typer.Option("--period", help="orbital period, e.g. '27.32 d' (sets a)")] = None,
    e: EccentricityOption = 0.0,
    inc: InclinationOption = "0",
    raan: NodeOption = "0",
    argp: PeriapsisArgumentOption = "0",
    nu: TrueAnomalyOption = "0",
    only: OnlyOption = None,
    fmt: FormatOption = Format.table,
    plot: PlotOption = None,
) -> None:
    """Masses, relative orbit, each star's orbit about the centre of mass, energy and angular momentum (XXII)."""
    from orbits import inputs
    from orbits_cli import render

    result = build(m1, m2, a, p, q, period, e, inc, raan, argp, nu)
    if plot:
        from orbits.plot import binary_plane

        save_plot(lambda: binary_plane(result), plot)
    groups = [("relative_", "relative orbit (star 2 about star 1)"), ("star1_", "star 1 about the centre of mass"),
              ("star2_", "star 2 about the centre of mass")]
    render.emit(f"Binary of {m1} and {m2}", result.quantities(inputs.names(only)), fmt.value, groups=groups)


def build(
    m1: str,
    m2: str,
    a: str | None,
    p: str | None,
    q: str | None,
    period: str | None,
    e: float,
    inc: str,
    raan: str,
    argp: str,
    nu: str,
) -> "Binary":
    """The Binary described by the options; BadParameter when no size (or more than one) is given."""
    from orbits import Binary, inputs
    from orbits_cli import params

    sizes = {"a": a, "p": p, "q": q, "period": period}
    given = [k for k, x in sizes.items() if x is not None]
    if len(given) != 1:
        raise typer.BadParameter(f"give exactly one size of --a, --p, --q, --period; got {given or 'none'}")
    kind = "time" if given[0] == "period" else "length"
    size = {given[0]: inputs.parse_quantity(sizes[given[0]], kind, f"--{given[0]}")}
    return Binary.from_elements(
        mass_or_body(m1, "--m1"),
        mass_or_body(m2, "--m2"),
        e=e,
        **params.orientation(inc, raan, argp, nu),
        **size,
    )


def mass_or_body(text: str, option: str) -> "Body | Quantity":
    """A body (name), mass or GM parsed from `text`; BadParameter naming `option` otherwise."""
    from orbits import OrbitDomainError, inputs

    try:
        return inputs.parse_primary(text)
    except OrbitDomainError as err:
        raise OrbitDomainError(f"{option}: {str(err).removeprefix('primary: ')}") from None
