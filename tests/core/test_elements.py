"""State vectors <-> elements: round trips, conventions, the e, h and Laplace-Runge-Lenz vectors."""

import math

import mpmath
import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st

from orbits.core.errors import DegenerateOrbitError, OrbitDomainError
from orbits.core.twobody import elements
from orbits.core.twobody.propagate import propagate


def angle_diff(a, b):
    return np.abs(np.angle(np.exp(1j * (np.asarray(a) - np.asarray(b)))))


def random_elements(rng, n, e):
    p = 10 ** rng.uniform(-3, 3, n)
    inc = rng.uniform(1e-6, math.pi - 1e-6, n)
    raan, argp = rng.uniform(0, 2 * math.pi, (2, n))
    limit = np.where(e > 1, 0.9 * np.arccos(-1 / np.maximum(e, 1 + 1e-300)), 0.999 * math.pi)
    nu = rng.uniform(-1, 1, n) * limit
    return p, e, inc, raan, argp, nu


@pytest.mark.parametrize("family", ["elliptic", "hyperbolic"])
def test_elements_state_elements_round_trip(family):
    rng = np.random.default_rng(7)
    n = 5000
    e = rng.uniform(1e-3, 0.99, n) if family == "elliptic" else 1 + 10 ** rng.uniform(-3, 1, n)
    p, e, inc, raan, argp, nu = random_elements(rng, n, e)
    back = elements.state_to_elements(*elements.elements_to_state(p, e, inc, raan, argp, nu, 1.0), 1.0)
    assert np.max(np.abs(back[0] / p - 1)) <= 1e-13
    assert np.max(np.abs(back[1] - e) / np.maximum(e, 1)) <= 1e-14
    assert np.max(np.abs(back[2] - inc)) <= 1e-14
    assert np.max(angle_diff(back[3], raan)) <= 1e-13
    # omega and nu are conditioned by 1/e: the e vector carries an absolute error of a few ulp
    assert np.max(angle_diff(back[4], argp) * e) <= 1e-13
    assert np.max(angle_diff(back[5], nu) * e) <= 1e-13
    assert np.max(angle_diff(back[4] + back[5], argp + nu)) <= 1e-13


@given(
    x=st.lists(st.floats(min_value=-10, max_value=10), min_size=3, max_size=3),
    v=st.lists(st.floats(min_value=-2, max_value=2), min_size=3, max_size=3),
)
def test_state_elements_state_round_trip(x, v):
    r, v = np.array(x), np.array(v)
    h = np.cross(r, v)
    if np.linalg.norm(r) < 1e-3 or np.linalg.norm(h) < 1e-3 * np.linalg.norm(r) * max(np.linalg.norm(v), 1e-3):
        return  # nearly radial states are covered by the degenerate-orbit tests
    el = elements.state_to_elements(r, v, 1.0)
    r2, v2 = elements.elements_to_state(*el, 1.0)
    # EDGE 6.2: 1e-12 where 1 + e cos nu >= 1e-3; beyond, r = p / (1 + e cos nu) amplifies rounding
    tolerance = 1e-12 * max(1.0, 1e-3 / (1 + el[1] * math.cos(el[5])))
    scale_r, scale_v = np.linalg.norm(r), np.linalg.norm(v) + np.sqrt(1 / np.linalg.norm(r))
    assert np.linalg.norm(r2 - r) <= tolerance * scale_r
    assert np.linalg.norm(v2 - v) <= tolerance * scale_v


@pytest.mark.parametrize("one_minus_e", [1e-6, 1e-10, 1e-14, -1e-14, -1e-10, -1e-6])
def test_near_parabolic_round_trip_uses_p(one_minus_e):
    """EDGE 40: with p as the size element the round trip keeps 1e-12 (rebound's a-based path: 7e-2)."""
    e = 1 - one_minus_e
    for nu in (-2.0, 0.0, 1.0, 2.5):
        r, v = elements.elements_to_state(1.5, e, 0.4, 1.0, 2.0, nu, 2.0)
        r2, v2 = elements.elements_to_state(*elements.state_to_elements(r, v, 2.0), 2.0)
        assert np.linalg.norm(r2 - r) <= 1e-12 * np.linalg.norm(r)
        assert np.linalg.norm(v2 - v) <= 1e-12 * np.linalg.norm(v)


def test_conventions_for_equatorial_circular_and_retrograde():
    # i = 0: Omega := 0 and omega is the longitude of periapsis (EDGE 31)
    el = elements.state_to_elements(*elements.elements_to_state(1.0, 0.3, 0.0, 0.0, 0.7, -1.0, 1.0), 1.0)
    assert (el[2], el[3]) == (0.0, 0.0) and abs(el[4] - 0.7) < 1e-15 and abs(el[5] + 1.0) < 1e-15
    # i = pi exactly: still equatorial, Omega := 0 (EDGE 32)
    el = elements.state_to_elements(*elements.elements_to_state(1.0, 0.3, math.pi, 0.0, 0.7, 1.0, 1.0), 1.0)
    assert el[2] == math.pi and el[3] == 0.0 and abs(el[4] - 0.7) < 1e-15
    # e = 0 exactly: omega := 0 and nu is the argument of latitude (EDGE 33)
    r = np.array([1.0, 0.0, 0.0])
    el = elements.state_to_elements(r, np.array([0.0, 1.0, 0.0]), 1.0)
    assert el[1] == 0.0 and el[4] == 0.0 and el[5] == 0.0 and el[2] == 0.0
    # retrograde inclined orbit
    el = elements.state_to_elements(*elements.elements_to_state(1.0, 0.2, 2.5, 1.0, 2.0, 0.5, 1.0), 1.0)
    np.testing.assert_allclose(el[2:], [2.5, 1.0, 2.0, 0.5], rtol=1e-13)


def test_signed_zero_inputs_give_identical_results():  # EDGE 41
    r = np.array([1.0, 0.2, 0.0])
    a = elements.state_to_elements(r, np.array([0.1, 1.0, 0.0]), 1.0)
    b = elements.state_to_elements(r, np.array([0.1, 1.0, -0.0]), 1.0)
    assert all(np.array_equal(x, y) for x, y in zip(a, b))


def test_eccentricity_vector_against_mpmath():
    rng = np.random.default_rng(8)
    for _ in range(200):
        r, v, mu = rng.normal(size=3), rng.normal(size=3), rng.uniform(0.5, 2)
        e_vec = elements.eccentricity_vector(r, v, mu)
        with mpmath.workdps(50):
            R, V, MU = [mpmath.mpf(x) for x in r], [mpmath.mpf(x) for x in v], mpmath.mpf(mu)
            rn = mpmath.sqrt(sum(x * x for x in R))
            v2, rv = sum(x * x for x in V), sum(x * y for x, y in zip(R, V))
            ref = [((v2 - MU / rn) * x - rv * y) / MU for x, y in zip(R, V)]  # the textbook form
            scale = 1 + mpmath.sqrt(sum(x * x for x in ref))
            assert max(abs(mpmath.mpf(float(c)) - rc) for c, rc in zip(e_vec, ref)) <= 8 * 2**-53 * scale


def test_laplace_runge_lenz_vector_is_conserved_and_gives_e():
    """A = p x L - m k r_hat is constant along the orbit and |A| / (m k) = e (XXI.viii)."""
    r0, v0, mu, m = np.array([1.0, 0.1, 0.2]), np.array([0.1, 1.2, 0.3]), 1.3, 2.5
    A0 = elements.laplace_runge_lenz_vector(r0, v0, mu, m)
    r, v = propagate(r0, v0, mu, np.linspace(0, 30, 7))
    A = elements.laplace_runge_lenz_vector(r, v, mu, m)
    assert np.max(np.abs(A - A0)) <= 1e-13 * np.linalg.norm(A0)
    p_vec, L = m * v0, m * np.cross(r0, v0)
    direct = np.cross(p_vec, L) - m * (m * mu) * r0 / np.linalg.norm(r0)
    np.testing.assert_allclose(A0, direct, rtol=1e-14)
    e = elements.state_to_elements(r0, v0, mu)[1]
    assert abs(np.linalg.norm(A0) / (m * m * mu) - e) <= 1e-15


@pytest.mark.parametrize("v", [[0.0, 0.0, 0.0], [-0.5, 0.0, 0.0]])
def test_radial_state_is_degenerate_not_silent(v):  # EDGE 37, 38
    r = np.array([1.0, 0.0, 0.0])
    with pytest.raises(DegenerateOrbitError, match="radial"):
        elements.state_to_elements(r, np.array(v), 1.0)
    np.testing.assert_allclose(elements.eccentricity_vector(r, np.array(v), 1.0), [-1.0, 0, 0])


def test_exactly_parabolic_state():  # EDGE 39
    r, v = np.array([2.0, 0.0, 0.0]), np.array([0.0, 1.0, 0.0])  # v**2 = 2 mu / r with mu = 1
    p, e, *_ = elements.state_to_elements(r, v, 1.0)
    assert e == 1.0 and p == 4.0


@pytest.mark.parametrize(
    "args, fragment",
    [
        (([0.0, 0, 0], [1.0, 0, 0], 1.0), "coincides with the primary"),  # EDGE 36
        (([1.0, 0, 0], [0.0, 1, 0], 0.0), "must be positive"),  # EDGE 43
        (([1.0, 0, 0], [0.0, 1, 0], -1.0), "must be positive"),
        (([1.0, np.nan, 0], [0.0, 1, 0], 1.0), "not finite"),
        (([1.0, 0], [0.0, 1, 0], 1.0), "last axis of length 3"),
    ],
)
def test_bad_states(args, fragment):
    with pytest.raises(OrbitDomainError, match=fragment):
        elements.state_to_elements(*args)


@pytest.mark.parametrize(
    "args, fragment",
    [
        ((1.0, 0.5, -0.1, 0, 0, 0, 1.0), r"outside \[0, pi\]"),
        ((-1.0, 0.5, 0.1, 0, 0, 0, 1.0), "must be positive"),
        ((1.0, 2.0, 0.1, 0, 0, 2.5, 1.0), "beyond the asymptote"),
        ((1.0, 1.0, 0.1, 0, 0, math.pi, 1.0), "beyond the asymptote"),
        ((1.0, -0.2, 0.1, 0, 0, 0, 1.0), ">= 0"),
    ],
)
def test_bad_elements(args, fragment):
    with pytest.raises(OrbitDomainError, match=fragment):
        elements.elements_to_state(*args)
