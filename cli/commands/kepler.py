"""`orbits kepler`: anomaly conversions on any conic."""

from typing import Annotated

import typer

from orbits_cli.options import Format, FormatOption


def command(
    e: Annotated[float, typer.Option("--e", help="eccentricity (any conic)")],
    mean: Annotated[
        str | None, typer.Option("--M", help="mean anomaly (Barker's W when e = 1), e.g. '1.2 rad'")
    ] = None,
    true: Annotated[str | None, typer.Option("--nu", help="true anomaly, e.g. '120 deg'")] = None,
    fmt: FormatOption = Format.table,
):
    """Anomaly conversions: from the mean anomaly (--M) or the true anomaly (--nu) to all the others."""
    from orbits_cli import render

    render.emit(f"Kepler's equation, e = {e}", anomalies_from(e, mean, true), fmt.value)


def anomalies_from(e, mean, true):
    """{name: Quantity}: mean, eccentric / hyperbolic / parabolic and true anomalies for one e."""
    import astropy.units as u
    import numpy as np

    from orbits.core import anomalies, kepler
    from orbits_cli import params

    if (mean is None) == (true is None):
        raise typer.BadParameter("give exactly one of --M (mean anomaly) and --nu (true anomaly)")
    if true is not None:
        nu = params.angle(true, "--nu").to_value(u.rad)
        m = float(anomalies.mean_from_true(nu, e))
    else:
        m = params.quantity(mean, "angle", "--M").to_value(u.rad) if not _is_number(mean) else float(mean)
        nu = float(anomalies.true_from_mean(m, e))
    result = {"eccentricity": e * u.one}
    if e < 1:
        result["mean_anomaly"] = float(kepler.reduce_mean_anomaly(m)[0]) * u.rad
        result["eccentric_anomaly"] = float(kepler.eccentric_anomaly(m, e)) * u.rad
    elif e == 1:
        result["barker_mean_anomaly"] = m * u.one
        result["parabolic_anomaly"] = float(kepler.parabolic_anomaly(m)) * u.one
    else:
        result["mean_anomaly"] = m * u.rad
        result["hyperbolic_anomaly"] = float(kepler.hyperbolic_anomaly(m, e)) * u.rad
    result["true_anomaly"] = nu * u.rad
    result["true_anomaly_deg"] = np.degrees(nu) * u.deg
    return result


def _is_number(text):
    try:
        float(text)
    except ValueError:
        return False
    return True
