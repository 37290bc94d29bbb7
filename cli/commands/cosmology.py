"""`orbits cosmology`: the expanding universe (XXIV) and the Friedmann models around it, at a redshift or a time."""

from typing import TYPE_CHECKING, Annotated

import typer

from orbits_cli.options import Format, FormatOption, OnlyOption, PlotOption, save_plot

if TYPE_CHECKING:

    import numpy
    from astropy.units import Quantity

    from orbits.cosmology.models import Cosmology

NOTES_HUBBLE = "0.5e-10 / yr"  # XXIV.iv's H, which gives the notes' age 1.33e10 yr
MODELS = ("notes", "planck18", "planck18-radiation")


def command(
    model: Annotated[
        str | None,
        typer.Option("--model", help="a named universe: notes (XXIV's Einstein-de Sitter, H0 = 0.5e-10 / yr), "
                     "planck18 (flat, H0 = 67.66 km/s/Mpc, Om = 0.30966), planck18-radiation (plus photons and "
                     "massless neutrinos)"),
    ] = None,
    h0: Annotated[
        str | None,
        typer.Option("--H0", help="Hubble constant with units: '70 km/s/Mpc', '0.5e-10 / yr', '2.3e-18 / s'"),
    ] = None,
    om: Annotated[float | None, typer.Option("--Om", help="matter density parameter today")] = None,
    ol: Annotated[float | None, typer.Option("--Ol", help="cosmological-constant density parameter today")] = None,
    orad: Annotated[float | None, typer.Option("--Or", help="radiation density parameter today (default 0)")] = None,
    ok: Annotated[
        float | None, typer.Option("--Ok", help="curvature parameter (default: from Om + Or + Ok + Ol = 1)")
    ] = None,
    z: Annotated[str | None, typer.Option("--z", help="redshift(s), comma-separated, e.g. '0.5,1,inf'")] = None,
    t: Annotated[str | None, typer.Option("--t", help="time since the big bang, e.g. '1 Gyr'")] = None,
    only: OnlyOption = None,
    fmt: FormatOption = Format.table,
    plot: PlotOption = None,
) -> None:
    """H(z), age, distances (comoving, luminosity, angular-diameter), distance modulus, comoving volume and a(t)
    of a Friedmann universe, today or at --z or --t.

    Einstein-de Sitter with the notes' H = 0.5e-10 / yr by default (XXIV.iv: age 1.33e10 yr); --model planck18
    for today's universe. Give --Om alone (or --Ol alone) for a flat universe; give two of --Om, --Ol, --Ok and
    the third follows from the sum 1. A closed universe (--Om 2 --Ok -1) runs through its turnaround to its big
    crunch. --plot draws a(t), the distances against z and the Hubble diagram.
    """
    from orbits._common import inputs
    from orbits_cli import render

    cosmology = build(h0, om, ol, orad, ok, model)
    table = cosmology.quantities(**epoch(z, t), only=inputs.names(only))
    course = model == "notes" or all(x is None for x in (model, h0, om, ol, orad, ok))
    heading = title(cosmology) + ("; the course's universe (--model planck18 for ours)" if course else "")
    if plot:
        from orbits.plot import cosmology_overview

        save_plot(lambda: cosmology_overview(cosmology, title(cosmology)), plot)
    render.emit(heading, table, fmt.value, index="redshift")


def build(
    h0: str | None, om: float | None, ol: float | None, orad: float | None, ok: float | None, model: str | None = None
) -> "Cosmology":
    """The Cosmology of the options: the named --model, else Einstein-de Sitter when no density is given."""
    from orbits import Cosmology

    if model is not None:
        if model not in MODELS:
            raise typer.BadParameter(f"--model {model!r} is not a model I know; choose from {', '.join(MODELS)}")
        if model != "notes":
            if any(x is not None for x in (h0, om, ol, orad, ok)):
                raise typer.BadParameter(f"--model {model} fixes H0 and the densities; leave out --H0, --Om, --Ol, "
                                         "--Or and --Ok (or give them without --model)")
            return Cosmology.planck18(radiation=model == "planck18-radiation")
    hubble = hubble_constant(h0 or NOTES_HUBBLE)
    if all(x is None for x in (om, ol, orad, ok)):
        return Cosmology.einstein_de_sitter(hubble)
    if om is None and ol is None:
        raise typer.BadParameter("give --Om or --Ol (or both) with --Or or --Ok; no density at all: Einstein-de Sitter")
    return Cosmology.from_densities(hubble, Om0=om, Ol0=ol, Or0=orad, Ok0=ok)


def hubble_constant(text: str) -> "Quantity":
    """H0 Quantity from "VALUE UNIT" with units of 1 / time ("70 km/s/Mpc", "0.07 / Gyr")."""
    from orbits._common import inputs

    return inputs.parse_quantity(text, "rate", "--H0")


def epoch(z: str | None, t: str | None) -> "dict[str, Quantity | numpy.ndarray | float]":
    """{"z": redshifts} or {"t": time} from the options (neither: today)."""
    import numpy as np

    from orbits._common import inputs

    if z is not None and t is not None:
        raise typer.BadParameter("give --z (a redshift) or --t (a time since the big bang), not both")
    if t is not None:
        return {"t": inputs.parse_quantity(t, "time", "--t")}
    if z is None:
        return {}
    try:
        values = np.array([float(x) for x in z.split(",")])
    except ValueError:
        raise typer.BadParameter(f"--z: cannot read {z!r}; write numbers such as '0.5' or '0.5,1,inf'") from None
    return {"z": values[0] if values.size == 1 else values}


def title(cosmology: "Cosmology") -> str:
    """E.g. "Einstein-de Sitter, H0 = 48.8896 km/s/Mpc, Om = 1" (Cosmology.description)."""
    return cosmology.description
