"""`orbits ring`: n equal masses on a regular n-gon, optionally about a central mass (XXIII, Maxwell's ring)."""

from typing import TYPE_CHECKING, Annotated

import typer

from orbits_cli.options import MASS_HELP, Format, FormatOption, OnlyOption, PlotOption, mass_or_body, save_plot

if TYPE_CHECKING:
    from orbits import Ring


def command(
    n: Annotated[int, typer.Argument(help="number of bodies on the ring (2 or more)")],
    mass: Annotated[str, typer.Option("--mass", help=f"each body's mass: {MASS_HELP}")],
    radius: Annotated[str, typer.Option("--radius", help="ring radius, e.g. '100000 km'")],
    primary: Annotated[
        str | None, typer.Option("--primary", help=f"the body at the centre (Maxwell's ring): {MASS_HELP}")
    ] = None,
    only: OnlyOption = None,
    fmt: FormatOption = Format.table,
    plot: PlotOption = None,
) -> None:
    """Angular velocity, period, speed, U, K, E, L of a ring (XXIII) and its linear stability: growth rate,
    break-up time from float64 round-off, and the central mass that makes a ring of n >= 7 stable. --plot
    integrates the ring with heyoka (or rebound) to 1.5 break-up times (20 periods if it is stable) and draws
    its shape deviation, the 1e-3 break-up level and snapshots."""
    from orbits import OrbitsError, Ring
    from orbits._common import inputs
    from orbits_cli import render

    ring = Ring.from_masses(
        n,
        mass_or_body(mass, "--mass"),
        inputs.parse_quantity(radius, "length", "--radius"),
        central_mass=None if primary is None else mass_or_body(primary, "--primary"),
    )
    title = f"Ring of {n} bodies" + ("" if primary is None else f" about {primary}")
    quantities = ring.quantities(inputs.names(only))
    about = None
    if only is None and "growth_rate" not in quantities:  # left out for a reason, which is said
        try:
            ring.quantities(["growth_rate"])
        except OrbitsError as err:
            about = {"not computed": f"growth_rate and the break-up: {err}"}
            title += f"; growth_rate and the break-up are not computed: {err}"
    if plot:
        save_plot(lambda: breakup_picture(ring), plot)
    render.emit(title, quantities, fmt.value, about=about)


def breakup_picture(ring: "Ring") -> tuple:
    """The ring integrated from its exact state (code units: radius 1, omega = 1) and drawn breaking up."""
    import numpy as np

    from orbits.plot import ring_snapshots
    from orbits.validate import backends
    from orbits.validate.builders import ring_problem

    beta = float(ring.central_mass_ratio.value)
    _, probe = ring_problem(ring.n, [1.0], central_ratio=beta)
    end = 1.5 * probe.breakup_time if np.isfinite(probe.breakup_time) else 40 * np.pi
    problem, expected = ring_problem(ring.n, np.linspace(0, end, 400)[1:], central_ratio=beta)
    backend = "heyoka" if backends.available("heyoka") else "rebound"
    result = backends.integrate(backend, problem)
    fig, axes = ring_snapshots(result.times, result.positions, expected.growth_rate, expected.breakup_time,
                               expected.first_body, period=ring.period)
    fig.suptitle(f"{ring.title}; integrated by {backend}")
    return fig, axes
