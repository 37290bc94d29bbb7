"""`orbits kepler`: anomaly conversions on any conic."""

from typing import TYPE_CHECKING, Annotated

import typer

from orbits_cli.options import Format, FormatOption

if TYPE_CHECKING:
    from astropy.units import Quantity


def command(
    e: Annotated[float, typer.Option("--e", help="eccentricity (any conic)")],
    mean: Annotated[
        str | None, typer.Option("--M", help="mean anomaly, e.g. '1.2 rad' (bare numbers are degrees); Barker's W, "
                                             "a plain number, when e = 1")
    ] = None,
    true: Annotated[
        str | None, typer.Option("--nu", help="true anomaly, e.g. '120 deg' (bare numbers are degrees)")
    ] = None,
    fmt: FormatOption = Format.table,
) -> None:
    """Anomaly conversions: from the mean anomaly (--M) or the true anomaly (--nu) to all the others."""
    from orbits_cli import render

    render.emit(f"Kepler's equation, e = {e}", anomalies_from(e, mean, true), fmt.value)


def anomalies_from(e: float, mean: str | None, true: str | None) -> "dict[str, Quantity]":
    """{name: Quantity}: mean, eccentric / hyperbolic / parabolic and true anomalies for one e."""

    from orbits import anomalies
    from orbits._common import inputs

    if (mean is None) == (true is None):
        raise typer.BadParameter("give exactly one of --M (mean anomaly) and --nu (true anomaly)")
    if true is not None:
        return anomalies(e, true_anomaly=inputs.parse_angle(true, "--nu"))
    if e == 1.0:
        return anomalies(e, mean_anomaly=inputs.parse_quantity(mean, "dimensionless", "--M (Barker's W)"))
    return anomalies(e, mean_anomaly=inputs.parse_angle(mean, "--M"))
