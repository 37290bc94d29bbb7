"""`orbits periodic`: a periodic orbit of the restricted three-body problem, or a table of its family."""

import contextlib
from enum import StrEnum
from typing import TYPE_CHECKING, Annotated

import typer

from orbits_cli.options import MASS_HELP, Format, FormatOption, OnlyOption, PlotOption, save_plot, three_body

if TYPE_CHECKING:
    from orbits.periodic.family import PeriodicFamily


class Family(StrEnum):
    lyapunov = "lyapunov"
    halo = "halo"
    vertical = "vertical"
    dro = "dro"
    nrho = "nrho"


class Branch(StrEnum):
    northern = "northern"
    southern = "southern"


class Spacing(StrEnum):
    arclength = "arclength"
    period = "period"
    jacobi = "jacobi"


def command(
    primary: Annotated[str, typer.Option("--primary", help=f"the heavier body M: {MASS_HELP}")],
    secondary: Annotated[str, typer.Option("--secondary", help=f"the lighter body m: {MASS_HELP}")],
    family: Annotated[Family, typer.Option("--family", help="lyapunov (planar), halo, vertical, dro (distant "
                                           "retrograde) or nrho (the halo family near the secondary)")],
    point: Annotated[str | None, typer.Option("--point", help="L1, L2 or L3 (default: L1 for lyapunov and vertical, "
                                              "L2 for halo and nrho; none for dro)")] = None,
    branch: Annotated[Branch | None, typer.Option("--branch", help="halo and nrho: northern (reaching farther to "
                                                  "+z, the binary's spin) or southern (default: northern halo, "
                                                  "southern nrho)")] = None,
    ax: Annotated[str | None, typer.Option("--ax", help="x amplitude (half the extent in x), e.g. '20000 km'")] = None,
    ay: Annotated[str | None, typer.Option("--ay", help="y amplitude (half the extent in y)")] = None,
    az: Annotated[str | None, typer.Option("--az", help="z amplitude (the largest distance from the binary's "
                                           "plane)")] = None,
    period: Annotated[str | None, typer.Option("--period", help="period, e.g. '12 d'")] = None,
    jacobi: Annotated[str | None, typer.Option("--jacobi", help="Jacobi constant: a plain number in units of "
                                               "(n r)**2, or in m2/s2 / km2/s2")] = None,
    closest_approach: Annotated[str | None, typer.Option("--closest-approach", help="least distance from the "
                                                         "secondary's centre (an NRHO's perilune radius)")] = None,
    resonance: Annotated[str | None, typer.Option("--resonance", help="nrho: p:q synodic resonance, period q/p "
                                                  "synodic periods (the Gateway's: 9:2)")] = None,
    separation: Annotated[str | None, typer.Option(
        "--separation", help="distance between the bodies, e.g. '384399 km' (default: the secondary's catalogued "
        "mean distance)")] = None,
    members: Annotated[int | None, typer.Option("--members", min=2, max=1000, help="a table of this many members "
                                                "of the family, from its first to the requested one (or to its "
                                                "end)")] = None,
    spacing: Annotated[Spacing | None, typer.Option(
        "--spacing", help="with --members: the members evenly in arclength along the family (the default), in "
        "period or in Jacobi constant")] = None,
    only: OnlyOption = None,
    fmt: FormatOption = Format.table,
    plot: PlotOption = None,
) -> None:
    """A periodic orbit of the restricted three-body problem about a Lagrange point or the secondary: corrected by
    differential correction, continued along its family to the requested amplitude, period, Jacobi constant,
    closest approach or resonance. With --members, a table of the family with its stability indices
    nu = lambda + 1/lambda (stable when both are real and |nu| <= 2) and its bifurcations.
    """
    from orbits._common import inputs
    from orbits.periodic.family import PeriodicFamily, PeriodicOrbit
    from orbits_cli import render
    if spacing is not None and members is None:
        raise typer.BadParameter("--spacing spreads the members of a family table: give --members N with it")
    system = three_body(primary, secondary, separation)
    targets = _targets(ax=ax, ay=ay, az=az, period=period, jacobi=jacobi, closest_approach=closest_approach,
                       resonance=resonance)
    chosen_branch = None if branch is None else branch.value
    if members is not None:
        result = PeriodicFamily.of(system, family.value, point, branch=chosen_branch, members=members,
                                   spacing=(spacing or Spacing.arclength).value, **targets)
        quantities = result.quantities(inputs.names(only))
        title = f"{result.members[0].describe()} family: {len(result)} members to {result.end}"
        if plot:
            from orbits.plot import periodic_family

            save_plot(lambda: periodic_family(result), plot)
        if fmt == Format.json:
            render.emit(title, quantities, fmt.value, about=_about(result))
        else:
            render.print_tables(family_tables(result, quantities), title)
        return
    orbit = PeriodicOrbit.of(system, family.value, point, branch=chosen_branch, **targets)
    quantities = orbit.quantities(inputs.names(only))
    if plot:
        from orbits.plot import periodic_orbit

        save_plot(lambda: periodic_orbit(orbit), plot)
    if fmt == Format.json:
        render.emit(orbit.title, quantities, fmt.value)
    else:
        render.print_tables(orbit_tables(quantities), f"{orbit.title} (rotating frame, origin at the barycentre)")


def _targets(**given) -> dict:
    """The targets given on the command line as Quantities (a resonance as its text); which of them picks a member
    of the family is the library's rule (orbits.periodic.family.FAMILY_TARGETS)."""
    from orbits._common import inputs

    kinds = {"ax": "length", "ay": "length", "az": "length", "closest_approach": "length", "period": "time"}
    targets = {}
    for name, text in given.items():
        if text is None:
            continue
        option = "--" + name.replace("_", "-")
        if name == "resonance":
            targets[name] = text
        elif name == "jacobi":
            targets[name] = _jacobi(text, option)
        else:
            targets[name] = inputs.parse_quantity(text, kinds[name], option)
    return targets


def _jacobi(text: str, option: str):
    """A Jacobi constant: a plain number (units of (n r)**2) or a speed squared ('3.3 km2 / s2')."""
    import astropy.units as u

    from orbits import OrbitDomainError

    with contextlib.suppress(ValueError):  # a plain number, in units of (n r)**2
        return float(text) * u.one
    try:
        value = u.Quantity(text)
    except (TypeError, ValueError):
        raise OrbitDomainError(f"{option}: cannot read {text!r}; write a plain number such as 3.05 or a speed "
                               f"squared such as '3.3 km2 / s2'") from None
    if not value.unit.is_equivalent(u.m**2 / u.s**2):
        raise OrbitDomainError(f"{option}: {text!r} is not a speed squared (m2/s2) nor a plain number")
    return value


def orbit_tables(quantities: dict) -> list:
    """One table of the orbit's quantities; the stability indices as nu_1, nu_2 (real, or re and im), the
    eigenvalues left to the JSON output."""
    import astropy.units as u
    import numpy as np

    from orbits_cli import render

    rows = {}
    for name, q in quantities.items():
        if name == "eigenvalues":
            continue
        if name == "stability_indices":
            for k, (re, im) in enumerate(np.asarray(q.value)):
                rows[f"nu_{k + 1}"] = (re if im == 0.0 else np.array([re, im])) << u.one
            continue
        rows[name] = q
    return [render.quantity_table("", rows)]


def family_tables(result: "PeriodicFamily", quantities: dict) -> list:
    """One row per member: period, Jacobi constant, amplitudes, closest approaches, stability indices; then the
    bifurcations found along the family."""
    import astropy.units as u
    import numpy as np

    from orbits_cli import render

    columns = []
    headers = {"period": "T", "dimensionless_jacobi_constant": "C", "ax": "Ax", "ay": "Ay", "az": "Az",
               "closest_approach_primary": "to M", "closest_approach_secondary": "to m"}
    for name, header in headers.items():
        if name in quantities:
            columns.append(render.column(name, quantities[name], header))
    if "stability_indices" in quantities:
        nu = np.asarray(quantities["stability_indices"].value)
        for k in range(2):
            columns.append((f"nu_{k + 1}", [render.number(re) if im == 0.0 else f"{render.number(re)}"
                                            f"{'+' if im > 0 else '-'}{render.number(abs(im))}i"
                                            for re, im in nu[:, k]]))
        columns.append(("stable", ["yes" if m.stable else "no" for m in result.members]))
    tables = render.column_tables(("#", [str(k + 1) for k in range(len(result))]), columns) if columns else []
    if "stability_indices" in quantities and result.bifurcations:
        rows = {}
        for k, (kind, orbit) in enumerate(result.bifurcations):
            rows[f"{kind} bifurcation {k + 1}: C"] = orbit.dimensionless_jacobi_constant << u.one
            rows[f"{kind} bifurcation {k + 1}: T"] = orbit.period
        tables.append(render.quantity_table("bifurcations (a stability index crosses 2 or -2)", rows))
    return tables


def _about(result: "PeriodicFamily") -> dict:
    return {"family": result.members[0].describe(), "end": result.end, "members": str(len(result))}
