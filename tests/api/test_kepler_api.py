"""orbits.anomalies: every anomaly of a conic, with units, against the 60-digit roots of orbits.tools.reference."""

import astropy.units as u
import numpy as np
import pytest

from orbits import OrbitDomainError, anomalies
from orbits.tools import reference

ELLIPSES = [(0.5, 1.0), (0.9, -2.5), (1 - 1e-12, 1e-9), (0.0, 3.0), (0.3, 7.0)]
HYPERBOLAS = [(2.0, 3.0), (1.5, 1e6), (1 + 1e-9, -1e-3)]


@pytest.mark.parametrize("e, m", ELLIPSES)
def test_ellipse_from_the_mean_anomaly_within_2_ulp(e, m):
    result = anomalies(e, mean_anomaly=m * u.rad)
    E = result["eccentric_anomaly"].to_value(u.rad)
    assert float(reference.kepler_E_ulps(float(E), m, e)) <= 2  # measured <= 0.37 ulp on these cases
    nu_exact = reference.true_from_E(reference.kepler_E(m, e), e)
    nu = float(result["true_anomaly"].to_value(u.rad))
    assert float(reference.rel_error(nu, nu_exact)) <= 5e-16  # measured 5e-17


@pytest.mark.parametrize("e, m", HYPERBOLAS)
def test_hyperbola_from_the_mean_anomaly_within_2_ulp(e, m):
    result = anomalies(e, mean_anomaly=m * u.rad)
    H = float(result["hyperbolic_anomaly"].to_value(u.rad))
    assert float(reference.kepler_H_ulps(H, m, e)) <= 2  # measured <= 0.31 ulp
    nu_exact = reference.true_from_H(reference.kepler_H(m, e), e)
    nu = float(result["true_anomaly"].to_value(u.rad))
    assert float(reference.rel_error(nu, nu_exact)) <= 1e-15  # measured 1.3e-16


def test_parabola_uses_barkers_plain_number():
    result = anomalies(1.0, mean_anomaly=2.0)
    D = float(result["parabolic_anomaly"].value)
    assert abs(D - float(reference.barker_D(2.0))) <= np.spacing(D)
    assert result["barker_mean_anomaly"].unit == u.one and result["true_anomaly"].unit == u.rad


@pytest.mark.parametrize("e, nu_deg", [(0.5, 120.0), (0.999, -170.0), (3.0, 100.0), (1.0, 150.0)])
def test_from_the_true_anomaly_and_back(e, nu_deg):
    """The closed-form path from nu, then Kepler's equation solved from the M it gives, returns nu."""
    forward = anomalies(e, true_anomaly=nu_deg * u.deg)
    key = "barker_mean_anomaly" if e == 1.0 else "mean_anomaly"
    back = anomalies(e, mean_anomaly=forward[key])
    assert back["true_anomaly"].to_value(u.deg) == pytest.approx(nu_deg, rel=1e-15)  # measured 1.1e-16


def test_arrays_of_one_kind_of_conic_broadcast():
    result = anomalies(np.array([0.1, 0.5, 0.9]), mean_anomaly=np.array([1.0, 2.0, 3.0]) * u.rad)
    assert result["eccentric_anomaly"].shape == (3,) and result["eccentricity"].shape == (3,)
    for k, (e, m) in enumerate([(0.1, 1.0), (0.5, 2.0), (0.9, 3.0)]):
        assert float(reference.kepler_E_ulps(float(result["eccentric_anomaly"][k].value), m, e)) <= 2


@pytest.mark.parametrize(
    "kwargs, error, fragment",
    [
        (dict(e=[0.5, 2.0], mean_anomaly=1 * u.rad), OrbitDomainError, "span ellipses and hyperbolas"),
        (dict(e=0.5), TypeError, "exactly one of"),
        (dict(e=0.5, mean_anomaly=1 * u.rad, true_anomaly=1 * u.rad), TypeError, "exactly one of"),
        (dict(e=0.5, mean_anomaly=1.0), TypeError, "has no unit"),
        (dict(e=-0.1, mean_anomaly=1 * u.rad), OrbitDomainError, "outside [0, inf)"),
        (dict(e=2.0, true_anomaly=150 * u.deg), OrbitDomainError, "asymptote"),
    ],
)
def test_bad_input_is_a_clear_error(kwargs, error, fragment):
    with pytest.raises(error, match=None) as info:
        anomalies(**kwargs)
    assert fragment in str(info.value)
