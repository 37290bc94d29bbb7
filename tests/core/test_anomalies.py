"""Anomaly conversions against mpmath, the orbit's area integral, and round trips."""

import math

import mpmath
import mpref
import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st

from orbits.core.errors import OrbitDomainError
from orbits.core.twobody import anomalies


@given(E=st.floats(min_value=-math.pi, max_value=math.pi), e=st.floats(min_value=0, max_value=1 - 2**-53))
def test_true_from_eccentric_against_mpmath(E, e):
    nu = anomalies.true_from_eccentric(E, e)
    ref = mpref.true_from_E(E, e)
    # 4 ulp of nu plus the conditioning of the map (d nu / d E times half an ulp of E)
    with mpmath.workdps(60):
        slope = mpmath.sqrt(1 - mpmath.mpf(e) ** 2) / (1 - e * mpmath.cos(mpmath.mpf(E)))
        bound = 4 * math.ulp(abs(float(ref))) + float(slope) * math.ulp(abs(E)) + 1e-300
        assert abs(mpmath.mpf(float(nu)) - ref) <= bound


@given(H=st.floats(min_value=-50, max_value=50), e=st.floats(min_value=1 + 2**-40, max_value=1e6))
def test_true_from_hyperbolic_against_mpmath(H, e):
    nu = anomalies.true_from_hyperbolic(H, e)
    assert float(mpref.rel_error(float(nu), mpref.true_from_H(H, e))) <= 4e-15 or abs(H) < 1e-300


@given(nu=st.floats(min_value=-3.1, max_value=3.1), e=st.floats(min_value=0, max_value=0.999999))
def test_elliptic_round_trip_true_mean_true(nu, e):
    back = anomalies.true_from_mean(anomalies.mean_from_true(nu, e), e)
    assert abs(back - nu) <= 1e-12 * (1 + abs(nu)) / (1 - e) ** 0.5


@given(frac=st.floats(min_value=-0.99, max_value=0.99), e=st.floats(min_value=1.000001, max_value=1e3))
def test_hyperbolic_round_trip(frac, e):
    nu = frac * math.acos(-1 / e)
    back = anomalies.true_from_mean(anomalies.mean_from_true(nu, e), e)
    assert abs(back - nu) <= 1e-10 * abs(nu) + 1e-15


def test_parabolic_round_trip_and_barker_form():
    nu = np.linspace(-3.0, 3.0, 101)
    W = anomalies.mean_from_true(nu, 1.0)
    D = np.tan(nu / 2)
    np.testing.assert_allclose(W, D + D**3 / 3, rtol=1e-15, atol=1e-15)
    np.testing.assert_allclose(anomalies.true_from_mean(W, 1.0), nu, rtol=1e-14, atol=1e-15)


@pytest.mark.parametrize("e", [0.0, 0.3, 0.9, 0.999, 1.0, 1.001, 2.5])
def test_time_since_periapsis_matches_the_area_integral(e):
    """t = integral of r**2 / h d nu (Kepler's second law), evaluated by mpmath quadrature."""
    p, mu = 2.0, 3.0
    nu = 1.2 if e <= 1 else 0.9 * math.acos(-1 / e)
    t = anomalies.time_since_periapsis(nu, p, e, mu)
    with mpmath.workdps(40):
        h = mpmath.sqrt(mu * p)
        ref = mpmath.quad(lambda f: (p / (1 + e * mpmath.cos(f))) ** 2 / h, [0, nu])
    assert abs(t - ref) <= 1e-14 * abs(ref)


def test_mixed_conics_in_one_array():
    e = np.array([0.0, 0.5, 1.0, 3.0])
    nu = np.array([0.4, -2.0, 2.5, 1.0])
    np.testing.assert_allclose(anomalies.true_from_mean(anomalies.mean_from_true(nu, e), e), nu, rtol=1e-14)


@pytest.mark.parametrize(
    "call, fragment",
    [
        (lambda: anomalies.mean_from_true(math.pi, 1.0), "infinite distance on a parabola"),  # EDGE 23
        (lambda: anomalies.mean_from_true(2.5, 2.0), "beyond the asymptote"),  # EDGE 22
        (lambda: anomalies.mean_from_true(math.acos(-1 / 2.0), 2.0), "beyond the asymptote"),
        (lambda: anomalies.true_from_mean(1.0, -0.5), "negative"),
    ],
)
def test_bad_input(call, fragment):
    with pytest.raises(OrbitDomainError, match=fragment):
        call()
