"""Kepler solvers against mpmath at >= 60 digits (tests/mpref.py), in ulps of the exact root."""

import math

import mpmath
import mpref
import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st

from orbits.core.errors import OrbitDomainError
from orbits.core.twobody import kepler
from orbits.core.twobody._kepler_shared import TWO_PI_1, TWO_PI_2, TWO_PI_3

ELLIPTIC_ULPS = 4
HYPERBOLIC_ULPS = 4
BARKER_ULPS = 2


def worst_ulps(computed, reference):
    return max(float(mpref.ulp_error(float(x), ref)) for x, ref in zip(np.ravel(computed), reference))


def elliptic_cases(rng, n):
    generic = [(rng.uniform(-20, 20), rng.uniform(0, 1)) for _ in range(n)]
    corner = [(10 ** rng.uniform(-16, -3), 1 - 10 ** rng.uniform(-16, -12)) for _ in range(n)]
    near_one = [(10 ** rng.uniform(-12, 0.49), 1 - 10 ** rng.uniform(-16, -1)) for _ in range(n)]
    near_pi = [(math.pi - 10 ** rng.uniform(-15, 0), 1 - 10 ** rng.uniform(-16, -1)) for _ in range(n)]
    huge = [(10 ** rng.uniform(3, 15.8), rng.uniform(0, 1)) for _ in range(n)]
    return generic + corner + near_one + near_pi + huge


@pytest.mark.parametrize("seed", [1, 2])
def test_elliptic_within_4_ulp_of_the_true_root(seed):
    cases = elliptic_cases(np.random.default_rng(seed), 60)
    M, e = np.array(cases).T
    E = kepler.eccentric_anomaly(M, e)
    assert worst_ulps(E, [mpref.kepler_E(m, ee) for m, ee in cases]) <= ELLIPTIC_ULPS


@pytest.mark.parametrize(
    "M, e",
    [
        (1e-10, 1 - 2**-53),  # EDGE 3: largest double below 1
        (1e-15, 1 - 1e-12),  # EDGE 12: singular corner
        (1e-20, 0.5),
        (1e-300, 0.9),
        (5e-324, 0.9),
        (5e-324, 1 - 2**-53),  # EDGE 11: tiny and subnormal M
        (1e12, 0.3),
        (1e12, 1 - 2**-53),  # EDGE 15: exact reduction
        (2 * math.pi - 1e-14, 0.3),  # EDGE 14: continuous across the wrap
        (math.pi, 0.999999),  # EDGE 13
        (kepler.MAX_MEAN_ANOMALY, 0.7),
    ],
)
def test_elliptic_hard_corners(M, e):
    assert worst_ulps(kepler.eccentric_anomaly(M, e), [mpref.kepler_E(M, e)]) <= ELLIPTIC_ULPS


@given(
    M=st.floats(min_value=-1e6, max_value=1e6, allow_subnormal=True),
    e=st.one_of(st.floats(min_value=0, max_value=0.999), st.floats(min_value=0.999, max_value=1 - 2**-53)),
)
def test_elliptic_property_against_mpmath(M, e):
    assert worst_ulps(kepler.eccentric_anomaly(M, e), [mpref.kepler_E(M, e)]) <= ELLIPTIC_ULPS


@given(M=st.floats(min_value=0, max_value=1e8), e=st.floats(min_value=0, max_value=1 - 2**-53))
def test_elliptic_is_exactly_odd(M, e):
    assert kepler.eccentric_anomaly(-M, e) == -kepler.eccentric_anomaly(M, e)


@given(e=st.floats(min_value=0, max_value=1 - 2**-53), M=st.floats(min_value=0, max_value=3.14))
def test_elliptic_is_monotone_within_a_revolution(e, M):
    M2 = np.nextafter(M, 4.0) * (1 + 1e-9)
    assert kepler.eccentric_anomaly(M2, e) >= kepler.eccentric_anomaly(M, e)


def test_exact_values():
    assert kepler.eccentric_anomaly(0.0, 0.9) == 0.0
    assert kepler.eccentric_anomaly(0.7, 0.0) == 0.7  # e = 0: E = M
    assert kepler.eccentric_anomaly(0.7, -0.0) == 0.7  # EDGE 6: -0.0 is 0
    assert math.copysign(1, kepler.eccentric_anomaly(-0.0, 0.5)) == -1  # EDGE 10: -0.0 -> -0.0
    assert kepler.eccentric_anomaly(math.pi, 0.999) == math.pi  # EDGE 13
    assert kepler.hyperbolic_anomaly(0.0, 1.5) == 0.0  # EDGE 9
    assert kepler.parabolic_anomaly(0.0) == 0.0


def hyperbolic_cases(rng, n):
    generic = [(10 ** rng.uniform(-10, 6), 1 + 10 ** rng.uniform(-3, 6)) for _ in range(n)]
    near_parabolic = [(10 ** rng.uniform(-12, 1), 1 + 10 ** rng.uniform(-15, -3)) for _ in range(n)]
    extreme = [(10 ** rng.uniform(6, 300), 1 + 10 ** rng.uniform(-15, 12)) for _ in range(n)]
    return generic + near_parabolic + extreme


@pytest.mark.parametrize("seed", [3, 4])
def test_hyperbolic_within_4_ulp_of_the_true_root(seed):
    cases = hyperbolic_cases(np.random.default_rng(seed), 60)
    M, e = np.array(cases).T
    H = kepler.hyperbolic_anomaly(M, e)
    assert worst_ulps(H, [mpref.kepler_H(m, ee) for m, ee in cases]) <= HYPERBOLIC_ULPS


@pytest.mark.parametrize(
    "M, e",
    [
        (1e12, 1.5),
        (1e308, 1.5),
        (1e-3, 1 + 2**-52),
        (5e-324, 1 + 2**-52),
        (1.0, 1e12),
        (1e-300, 1e12),
        (1e6, 1e6),
        # the two worst of 2e4 random pairs over M in [1e-12, 1e300], e - 1 in [1e-15, 1e12] (tests/stability) while
        # the logarithmic form subtracted log(e / 2) from log(M + H): 2.17 and 2.09 ulp then, 0.17 and 0.09 now
        (1040404391182992.0, 2509818.5830641184),
        (4.213727533247536e32, 162342761.4537636),
    ],
)
def test_hyperbolic_hard_corners(M, e):  # EDGE 4, 19, 20, 21
    assert worst_ulps(kepler.hyperbolic_anomaly(M, e), [mpref.kepler_H(M, e)]) <= HYPERBOLIC_ULPS


@given(M=st.floats(min_value=0, max_value=1e6), e=st.floats(min_value=1 + 2**-52, max_value=1e6))
def test_hyperbolic_property_against_mpmath_and_odd(M, e):
    H = kepler.hyperbolic_anomaly(M, e)
    assert kepler.hyperbolic_anomaly(-M, e) == -H
    assert worst_ulps(H, [mpref.kepler_H(M, e)]) <= HYPERBOLIC_ULPS


def test_barker_within_2_ulp():
    """Measured worst 1.00 ulp over W from 1e-300 to 1e300, negative W and the extremes."""
    rng = np.random.default_rng(5)
    W = np.concatenate([10 ** rng.uniform(-300, 300, 300), -(10 ** rng.uniform(-5, 5, 100)), [1e308, 5e-324]])
    D = kepler.parabolic_anomaly(W)
    assert worst_ulps(D, [mpref.barker_D(w) for w in W]) <= BARKER_ULPS


def test_two_pi_parts_sum_to_two_pi():
    with mpmath.workdps(60):
        total = mpmath.mpf(TWO_PI_1) + TWO_PI_2 + TWO_PI_3
        assert abs(total - 2 * mpmath.pi) < mpmath.mpf(2) ** -155


def test_reduction_keeps_low_order_bits():
    hi, lo = kepler.reduce_mean_anomaly(np.array(1e12))
    with mpmath.workdps(60):
        exact = mpmath.mpf(1e12) - 2 * mpmath.pi * mpmath.nint(mpmath.mpf(1e12) / (2 * mpmath.pi))
        assert abs(mpmath.mpf(float(hi)) + mpmath.mpf(float(lo)) - exact) < mpmath.mpf(10) ** -28


@pytest.mark.parametrize(
    "call, fragment",
    [
        (lambda: kepler.eccentric_anomaly(0.5, 1.0), "parabolic_anomaly (Barker)"),  # EDGE 1
        (lambda: kepler.eccentric_anomaly(0.5, -0.1), "outside [0.0, 1.0)"),  # EDGE 5
        (lambda: kepler.eccentric_anomaly(0.5, float("nan")), "not finite"),  # EDGE 7
        (lambda: kepler.eccentric_anomaly(float("inf"), 0.5), "mean anomaly M = inf"),  # EDGE 17
        (lambda: kepler.eccentric_anomaly(1e300, 0.5), "too large for an exact reduction"),  # EDGE 16
        (lambda: kepler.hyperbolic_anomaly(0.5, 1.0), "outside (1.0, inf)"),
        (lambda: kepler.hyperbolic_anomaly(float("nan"), 2.0), "not finite"),
        (lambda: kepler.parabolic_anomaly(float("inf")), "not finite"),
    ],
)
def test_bad_input_is_a_clear_error(call, fragment):
    with pytest.raises(OrbitDomainError, match=fragment.replace("(", r"\(").replace(")", r"\)").replace("[", r"\[")):
        call()


def test_arrays_broadcast_and_int_inputs_are_accepted():
    E = kepler.eccentric_anomaly(np.array([[1], [2]]), np.array([0, 0.5, 0.9]))
    assert E.shape == (2, 3) and E.dtype == np.float64
    assert kepler.eccentric_anomaly(1, 0) == 1.0  # EDGE 25: ints accepted
