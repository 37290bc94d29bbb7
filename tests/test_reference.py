"""Self-checks of the mpmath references in tests/mpref.py: residuals, closed forms, invariants."""

import math

import mpmath
import pytest
from mpmath import mp, mpf

import orbits.tools.reference as mpref

TINY = mpf(10) ** -45
ONE_MINUS = 1 - 2**-53  # largest float below 1
ONE_PLUS = 1 + 2**-52  # smallest float above 1

ELLIPTIC = [
    (M, e)
    for e in (0.0, 0.3, 0.99, 1 - 1e-9, ONE_MINUS)
    for M in (5e-324, 1e-300, 1e-12, 0.5, 3.0, math.pi - 1e-12, math.pi, -2.0, 7.5, 1e300)
]
HYPERBOLIC = [
    (M, e) for e in (ONE_PLUS, 1 + 1e-9, 1.5, 1e3, 1e12) for M in (5e-324, 1e-300, 1e-6, 1.0, -4.0, 1e6, 1e300)
]


def reduced(M):
    with mp.workdps(400):
        return M - 2 * mp.pi * mpmath.nint(mpf(M) / (2 * mp.pi))


@pytest.mark.parametrize("M, e", ELLIPTIC)
def test_kepler_E_residual_and_range(M, e):
    E = mpref.kepler_E(M, e)
    with mp.workdps(400):
        Mr = reduced(M)
        assert -mp.pi <= E <= mp.pi
        assert abs(E - mpf(e) * mpmath.sin(E) - Mr) <= TINY * abs(Mr)


@pytest.mark.parametrize("e", [0.0, 0.5, ONE_MINUS])
def test_kepler_E_closed_cases(e):
    with mp.workdps(80):
        assert mpref._solve_elliptic(mp.pi, mpf(e)) == mp.pi
        # float pi = pi + d: E = pi + d / (1 + e) + O(d^3), since E - e sin E is flat to 2nd order there
        d = mpf(math.pi) - mp.pi
        assert abs(mpref.kepler_E(math.pi, e) - (mp.pi + d / (1 + mpf(e)))) <= TINY
        assert mpref.kepler_E(0.0, e) == 0
        assert mpref.kepler_E(-1.25, e) == -mpref.kepler_E(1.25, e)
        assert mpref.kepler_E(-math.pi, e) == -mpref.kepler_E(math.pi, e)
        assert abs(mpref.kepler_E(2.5, 0.0) - mpf(2.5)) <= TINY


def test_kepler_E_tiny_anomaly_is_linear():
    # For E < 1e-280 the cubic term is far below 1e-45 relative: E = M / (1 - e) exactly.
    with mp.workdps(80):
        assert abs(mpref.kepler_E(1e-300, ONE_MINUS) / (mpf(1e-300) * 2**53) - 1) <= TINY


@pytest.mark.parametrize("M, e", HYPERBOLIC)
def test_kepler_H_residual(M, e):
    H = mpref.kepler_H(M, e)
    with mp.workdps(120):
        assert abs(mpf(e) * mpmath.sinh(H) - H - mpf(M)) <= TINY * abs(mpf(M))


def test_kepler_H_odd_and_zero():
    assert mpref.kepler_H(0.0, 2.0) == 0
    with mp.workdps(80):
        assert mpref.kepler_H(-3.0, 1.5) == -mpref.kepler_H(3.0, 1.5)


@pytest.mark.parametrize("W", [5e-324, 1e-300, 1e-8, 0.75, -2.5, 1e8, 1e300])
def test_barker_matches_trigonometric_closed_form(W):
    D = mpref.barker_D(W)
    with mp.workdps(80):
        closed = 2 * mpmath.sinh(mpmath.asinh(mpf(1.5) * mpf(W)) / 3)
        assert abs(D / closed - 1) <= TINY
        assert abs(D + D**3 / 3 - mpf(W)) <= TINY * abs(mpf(W))


@pytest.mark.parametrize("E, e", [(0.3, 0.1), (-2.0, 0.9), (3.0, ONE_MINUS), (1e-8, 1 - 1e-9), (7.0, 0.5)])
def test_true_from_E_identities(E, e):
    nu = mpref.true_from_E(E, e)
    with mp.workdps(80):
        E, e = mpf(E), mpf(e)
        assert abs((1 - e * mpmath.cos(E)) * (1 + e * mpmath.cos(nu)) - (1 - e**2)) <= TINY
        assert abs(mpmath.sqrt(1 - e) * mpmath.tan(nu / 2) - mpmath.sqrt(1 + e) * mpmath.tan(E / 2)) <= TINY
        assert abs(nu - E) < mp.pi  # same revolution


def test_true_from_E_at_float_pi():
    # E = pi + d gives nu = pi + d sqrt((1 - e) / (1 + e)) + O(d^3)
    with mp.workdps(80):
        d = mpf(math.pi) - mp.pi
        slope = mpmath.sqrt((1 - mpf(0.7)) / (1 + mpf(0.7)))
        assert abs(mpref.true_from_E(math.pi, 0.7) - (mp.pi + d * slope)) <= TINY


@pytest.mark.parametrize("H, e", [(0.3, 1.1), (-2.0, 3.0), (1e-8, 1 + 1e-9), (40.0, 1e6)])
def test_true_from_H_identity(H, e):
    nu = mpref.true_from_H(H, e)
    with mp.workdps(80):
        H, e = mpf(H), mpf(e)
        identity = (e * mpmath.cosh(H) - 1) * (1 + e * mpmath.cos(nu)) / (e**2 - 1)
        assert abs(identity - 1) <= TINY * e * mpmath.cosh(H)  # 1 + e cos nu is a cancellation


@pytest.mark.parametrize("t", [0.7, -2.0, 2 * math.pi * 1000 + 0.3])
def test_propagate_circular_orbit_rotates(t):
    r, v = mpref.propagate([1.0, 0.0, 0.0], [0.0, 1.0, 0.0], 1.0, t)
    with mp.workdps(80):
        c, s = mpmath.cos(mpf(t)), mpmath.sin(mpf(t))
        assert max(abs(x - y) for x, y in zip(r + v, [c, s, 0, -s, c, 0])) <= 1e4 * TINY


def test_propagate_exact_parabola_matches_barker_closed_form():
    # mu = 2, r0 = 1 at pericentre, v0 = 2: energy exactly 0, p = 2, W = 2 sqrt(mu / p^3) t = t.
    r, v = mpref.propagate([1.0, 0.0, 0.0], [0.0, 2.0, 0.0], 2.0, 3.0)
    with mp.workdps(80):
        D = 2 * mpmath.sinh(mpmath.asinh(mpf(4.5)) / 3)
        assert abs(r[0] - (1 - D**2)) <= TINY and abs(r[1] - 2 * D) <= TINY


STATES = [
    ([1.0, 0.2, 0.1], [0.1, 0.9, 0.3], 1.0, 5.0),  # ellipse
    ([1.0, 0.2, 0.1], [0.1, 3.0, 0.3], 1.0, 50.0),  # hyperbola
    ([1.0, 0.0, 0.0], [0.0, math.sqrt(2) * (1 - 1e-12), 0.0], 1.0, 3.0),  # e = 1 - 2e-12
    ([1.0, 0.0, 0.0], [0.0, math.sqrt(2) * (1 + 1e-12), 0.0], 1.0, -30.0),  # e = 1 + 2e-12
    ([1.0, 0.0, 0.0], [0.0, 2.0, 0.0], 2.0, 1.5),  # exact parabola
    ([1.0, 0.0, 0.0], [1e-7, 1e-13, 0.0], 1.0, 0.5),  # nearly radial, e = 1 - 1e-26
    ([1.496e11, 1e9, 0.0], [1e3, 2.98e4, 5e2], 1.32712440018e20, 3.15576e7),  # SI units
]


def energy_and_h(r, v, mu):
    h = [r[1] * v[2] - r[2] * v[1], r[2] * v[0] - r[0] * v[2], r[0] * v[1] - r[1] * v[0]]
    return mpref._dot(v, v) / 2 - mu / mpmath.sqrt(mpref._dot(r, r)), h


@pytest.mark.parametrize("r0, v0, mu, t", STATES)
def test_propagate_conserves_energy_and_angular_momentum(r0, v0, mu, t):
    r, v = mpref.propagate(r0, v0, mu, t)
    with mp.workdps(120):
        e0, h0 = energy_and_h([mpf(x) for x in r0], [mpf(x) for x in v0], mpf(mu))
        e1, h1 = energy_and_h(r, v, mpf(mu))
        scale = mpf(mu) / mpmath.sqrt(mpref._dot(r, r))
        assert abs(e1 - e0) <= TINY * scale
        assert max(abs(a - b) for a, b in zip(h0, h1)) <= TINY * mpmath.norm(h0 + [scale])


@pytest.mark.parametrize("r0, v0, mu, t", STATES)
def test_propagate_solves_the_two_body_ode_and_reverses(r0, v0, mu, t):
    """v = dr/dt and d2r/dt2 = -mu r / |r|^3 by central differences; propagating back returns r0."""
    with mp.workdps(80):
        h = mpf(2) ** -40 * max(1, abs(mpf(t)))
        (rm, _), (r, v), (rp, _) = (mpref.propagate(r0, v0, mu, mpf(t) + k * h) for k in (-1, 0, 1))
        rnorm = mpmath.norm(r)
        acc = [(a - 2 * b + c) / h**2 for a, b, c in zip(rm, r, rp)]
        assert max(abs(x - (a - c) / (2 * h)) for x, a, c in zip(v, rp, rm)) <= 1e-18 * mpmath.norm(v)
        assert max(abs(x + mu * y / rnorm**3) for x, y in zip(acc, r)) <= 1e-15 * mu / rnorm**2
        back, _ = mpref.propagate(r, v, mu, -mpf(t))
        assert max(abs(a - mpf(b)) for a, b in zip(back, r0)) <= 1e-40 * mpmath.norm(r0)


def test_ulp_and_relative_error():
    with mp.workdps(80):
        assert mpref.ulp_error(1.0, mpf(1) + mpf(2) ** -52) == 1
        assert mpref.ulp_error(1.0, mpf(1) - mpf(2) ** -60) == mpf(2) ** -8  # ulp of 1.0 (nearest float)
        assert mpref.ulp_error(5e-324, mpf(0)) == 1
        assert mpref.ulp_error(0.1, mpf(1) / 10) < mpf("0.5")
        assert mpref.rel_error(1.5, mpf(1)) == mpf("0.5")
        assert mpref.rel_error(0.0, mpf(0)) == 0
        assert mpref.rel_error(1e-300, mpf(0)) == mpf("inf")
