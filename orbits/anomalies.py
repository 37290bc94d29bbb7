"""Every anomaly of a conic from the mean or the true anomaly, with units (section XXI.vii of the notes).

    >>> import astropy.units as u
    >>> from orbits import anomalies
    >>> result = anomalies(0.5, mean_anomaly=1.0 * u.rad)
    >>> round(float(result["eccentric_anomaly"].to_value(u.rad)), 12)
    1.498701133517

Ellipse (e < 1): M = E - e sin E; hyperbola (e > 1): M = e sinh H - H; parabola (e = 1): Barker's equation
W = D + D**3 / 3 with D = tan(nu / 2), where W is a plain number. Kepler's equation is solved once (orbits.core
.kepler, within 2 ulp: tests/core/test_kepler.py); the true anomaly then follows from E, H or D in closed form.
"""

import astropy.units as u
import numpy as np

from orbits import inputs, units
from orbits.core import anomalies as core
from orbits.core import kepler


def anomalies(e, *, mean_anomaly=None, true_anomaly=None) -> dict[str, u.Quantity]:
    """{name: Quantity} of the mean, eccentric / hyperbolic / parabolic and true anomalies of one conic.

    Give exactly one of `mean_anomaly` (an angle; for e = 1 Barker's W, a plain number) and `true_anomaly`
    (an angle). e is one eccentricity >= 0; the anomalies may be arrays. The mean anomaly of an ellipse is
    returned reduced to [-pi, pi].
    """
    e = inputs.eccentricity(e)
    if e.ndim:
        raise TypeError(f"eccentricity e has shape {e.shape}; give one eccentricity (the anomalies may be arrays)")
    e = float(e)
    if (mean_anomaly is None) == (true_anomaly is None):
        raise TypeError("give exactly one of mean_anomaly and true_anomaly")
    result = {"eccentricity": e * u.one}
    if true_anomaly is not None:
        nu = units.to_si(true_anomaly, units.RAD, "true anomaly nu")
        result.update(_from_true(nu, e))
    else:
        m = (units.to_number(mean_anomaly, "Barker's mean anomaly W") if e == 1.0
             else units.to_si(mean_anomaly, units.RAD, "mean anomaly M"))
        result.update(_from_mean(m, e))
    result["true_anomaly_deg"] = result["true_anomaly"].to(u.deg)
    return result


def _from_mean(m, e):
    """Anomalies from M (rad) or W: Kepler's equation solved once, the true anomaly from its solution."""
    if e < 1.0:
        eccentric = kepler.eccentric_anomaly(m, e)
        return {"mean_anomaly": _reduced(m) << units.RAD, "eccentric_anomaly": eccentric << units.RAD,
                "true_anomaly": core.true_from_eccentric(eccentric, e) << units.RAD}
    if e == 1.0:
        parabolic = kepler.parabolic_anomaly(m)
        return {"barker_mean_anomaly": m << u.one, "parabolic_anomaly": parabolic << u.one,
                "true_anomaly": core.true_from_parabolic(parabolic) << units.RAD}
    hyperbolic = kepler.hyperbolic_anomaly(m, e)
    return {"mean_anomaly": m << units.RAD, "hyperbolic_anomaly": hyperbolic << units.RAD,
            "true_anomaly": core.true_from_hyperbolic(hyperbolic, e) << units.RAD}


def _from_true(nu, e):
    """Anomalies from nu (rad), each in closed form: E, H or D from nu, then M from Kepler's equation."""
    if e < 1.0:
        eccentric = core.eccentric_from_true(nu, e)
        return {"mean_anomaly": _reduced(core.mean_from_eccentric(eccentric, e)) << units.RAD,
                "eccentric_anomaly": eccentric << units.RAD, "true_anomaly": np.asarray(nu) << units.RAD}
    if e == 1.0:
        parabolic = core.parabolic_from_true(nu)
        return {"barker_mean_anomaly": core.mean_from_true(nu, 1.0) << u.one, "parabolic_anomaly": parabolic << u.one,
                "true_anomaly": np.asarray(nu) << units.RAD}
    hyperbolic = core.hyperbolic_from_true(nu, e)
    return {"mean_anomaly": core.mean_from_hyperbolic(hyperbolic, e) << units.RAD,
            "hyperbolic_anomaly": hyperbolic << units.RAD, "true_anomaly": np.asarray(nu) << units.RAD}


def _reduced(m):
    """M reduced to [-pi, pi] (rad), rounded from the exact double-double reduction."""
    return kepler.reduce_mean_anomaly(m)[0]
