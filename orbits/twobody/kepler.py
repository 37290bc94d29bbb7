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

from orbits._common import inputs, units
from orbits.core.errors import OrbitDomainError
from orbits.core.twobody import anomalies as core
from orbits.core.twobody import kepler as kepler_core


def anomalies(
    e: float | np.ndarray | u.Quantity,
    *,
    mean_anomaly: u.Quantity | float | np.ndarray | None = None,
    true_anomaly: u.Quantity | None = None,
) -> dict[str, u.Quantity]:
    """{name: Quantity} of the mean, eccentric / hyperbolic / parabolic and true anomalies of one kind of conic.

    Give exactly one of `mean_anomaly` (an angle; on the parabola Barker's W, a plain number) and `true_anomaly`
    (an angle). e >= 0 and the anomaly broadcast together; every e must be on the same kind of conic (all
    ellipses, all parabolas or all hyperbolas), since each kind has its own anomaly. The true anomaly, and the
    mean anomaly of an ellipse, count modulo a turn: they are reduced to (-pi, pi] as given, exactly
    (inputs.periodic_angle), so that E lies in [-pi, pi] too; a hyperbola's mean anomaly is not periodic.
    """
    e = inputs.eccentricity(e)
    conic = _conic(e)
    if (mean_anomaly is None) == (true_anomaly is None):
        raise TypeError("give exactly one of mean_anomaly and true_anomaly")
    if true_anomaly is not None:
        nu, e = np.broadcast_arrays(inputs.periodic_angle(true_anomaly, "true anomaly nu"), e)
        result = _from_true(nu, e, conic)
    else:
        m = (units.to_number(mean_anomaly, "Barker's mean anomaly W") if conic == "parabola"
             else inputs.periodic_angle(mean_anomaly, "mean anomaly M") if conic == "ellipse"
             else inputs.angle(mean_anomaly, "mean anomaly M"))
        m, e = np.broadcast_arrays(m, e)
        result = _from_mean(m, e, conic)
    return {"eccentricity": e << u.one, **result}


def _conic(e):
    """'ellipse', 'parabola' or 'hyperbola': the one kind of conic every e lies on (OrbitDomainError otherwise)."""
    kinds = [name for name, on in (("ellipse", e < 1.0), ("parabola", e == 1.0), ("hyperbola", e > 1.0)) if on.any()]
    if not kinds:  # no eccentricity at all: an empty answer, of any one kind
        return "ellipse"
    if len(kinds) != 1:
        spanned = " and ".join(f"{kind}s" for kind in kinds)
        raise OrbitDomainError(
            f"eccentricities from e = {float(e.min())!r} to {float(e.max())!r} span {spanned}; each kind of conic "
            f"has its own anomaly: convert them separately"
        )
    return kinds[0]


def _from_mean(m, e, conic):
    """Anomalies from M (rad) or W: Kepler's equation solved once, the true anomaly from its solution."""
    if conic == "ellipse":
        eccentric = kepler_core.eccentric_anomaly(m, e)
        return {"mean_anomaly": _reduced(m) << units.RAD, "eccentric_anomaly": eccentric << units.RAD,
                "true_anomaly": core.true_from_eccentric(eccentric, e) << units.RAD}
    if conic == "parabola":
        parabolic = kepler_core.parabolic_anomaly(m)
        return {"barker_mean_anomaly": m << u.one, "parabolic_anomaly": parabolic << u.one,
                "true_anomaly": core.true_from_parabolic(parabolic) << units.RAD}
    hyperbolic = kepler_core.hyperbolic_anomaly(m, e)
    return {"mean_anomaly": m << units.RAD, "hyperbolic_anomaly": hyperbolic << units.RAD,
            "true_anomaly": core.true_from_hyperbolic(hyperbolic, e) << units.RAD}


def _from_true(nu, e, conic):
    """Anomalies from nu (rad), each in closed form: E, H or D from nu, then M from Kepler's equation."""
    if conic == "ellipse":
        eccentric = core.eccentric_from_true(nu, e)
        return {"mean_anomaly": _reduced(core.mean_from_eccentric(eccentric, e)) << units.RAD,
                "eccentric_anomaly": eccentric << units.RAD, "true_anomaly": np.asarray(nu) << units.RAD}
    if conic == "parabola":
        parabolic = core.parabolic_from_true(nu)
        return {"barker_mean_anomaly": core.mean_from_true(nu, 1.0) << u.one, "parabolic_anomaly": parabolic << u.one,
                "true_anomaly": np.asarray(nu) << units.RAD}
    hyperbolic = core.hyperbolic_from_true(nu, e)
    return {"mean_anomaly": core.mean_from_hyperbolic(hyperbolic, e) << units.RAD,
            "hyperbolic_anomaly": hyperbolic << units.RAD, "true_anomaly": np.asarray(nu) << units.RAD}


def _reduced(m):
    """M reduced to [-pi, pi] (rad), rounded from the exact double-double reduction."""
    return kepler_core.reduce_mean_anomaly(m)[0]
