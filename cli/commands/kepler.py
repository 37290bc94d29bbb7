"""`orbits kepler`: anomaly conversions on any conic."""

import astropy.units as u
import numpy as np
import typer

from orbits.core import anomalies, kepler
from orbits_cli import params


def anomalies_from(e, mean, true):
    """{name: Quantity}: mean, eccentric / hyperbolic / parabolic and true anomalies for one e."""
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
