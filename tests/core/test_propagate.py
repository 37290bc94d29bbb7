"""Universal-variable propagator against the mpmath reference, conservation laws and hard corners."""

import math

import mpref
import numpy as np
import pytest

from orbits.core import elements
from orbits.core.errors import DegenerateOrbitError, OrbitDomainError
from orbits.core.propagate import propagate, stumpff

MU_EARTH = 3.986004418e14


def as_float(vector):
    return np.array([float(x) for x in vector])


def relative_state_error(r0, v0, mu, dt):
    r, v = propagate(r0, v0, mu, dt)
    r_ref, v_ref = (as_float(x) for x in mpref.propagate(r0, v0, mu, dt))
    return max(np.linalg.norm(r - r_ref) / np.linalg.norm(r_ref), np.linalg.norm(v - v_ref) / np.linalg.norm(v_ref))


@pytest.mark.parametrize("e", [0.0, 0.0167, 0.5, 0.9, 0.99])
@pytest.mark.parametrize("periods", [0.37, -0.81, 1000.3])
def test_elliptic_against_mpmath_over_1000_periods(e, periods):
    p = 7.0e6 * (1 - e * e) / (1 - e * e) * 1.3
    r0, v0 = elements.elements_to_state(p, e, 0.9, 1.1, 2.2, 0.3, MU_EARTH)
    a = p / (1 - e * e)
    dt = periods * 2 * math.pi * math.sqrt(a**3 / MU_EARTH)
    assert relative_state_error(r0, v0, MU_EARTH, dt) <= 1e-12


@pytest.mark.parametrize("one_minus_e", [1e-6, 1e-12, 0.0, -1e-12, -1e-6])
@pytest.mark.parametrize("steps", [-3.0, 0.5, 5.0, 1e4])
def test_near_parabolic_both_sides(one_minus_e, steps):
    p = 1.4e7
    r0, v0 = elements.elements_to_state(p, 1 - one_minus_e, 0.4, 0.2, 0.1, -1.5, MU_EARTH)
    dt = steps * math.sqrt(p**3 / MU_EARTH)
    assert relative_state_error(r0, v0, MU_EARTH, dt) <= 1e-12


@pytest.mark.parametrize("e", [1.5, 5.0, 100.0])
def test_hyperbolic(e):
    r0, v0 = elements.elements_to_state(2e7, e, 1.0, 0.0, 0.5, -0.5, MU_EARTH)
    for dt in (1e3, -2e3, 1e7):
        assert relative_state_error(r0, v0, MU_EARTH, dt) <= 1e-12


@pytest.mark.parametrize("scale", [1e-30, 1.0, 1e30])
def test_extreme_scales(scale):  # EDGE 42: scale-free (mu scaled as L**3 keeps the time unit)
    r0, v0 = np.array([1.0, 0.2, 0.1]) * scale, np.array([-0.2, 0.9, 0.3]) * scale
    mu = 1.1 * scale**3 if scale != 1e30 else 1.1e90
    r, v = propagate(r0, v0, mu, 7.3)
    r_ref, v_ref = propagate(r0 / scale, v0 / scale, 1.1, 7.3)
    np.testing.assert_allclose(r / scale, r_ref, rtol=1e-14)
    np.testing.assert_allclose(v / scale, v_ref, rtol=1e-14)


def test_zero_step_returns_the_state_exactly():
    r0, v0 = np.array([7e6, 1e5, -3e4]), np.array([10.0, 7.5e3, 100.0])
    r, v = propagate(r0, v0, MU_EARTH, 0.0)
    assert np.array_equal(r, r0) and np.array_equal(v, v0)


def test_conserves_energy_angular_momentum_and_eccentricity_vector():
    r0, v0 = elements.elements_to_state(9e6, 0.7, 0.3, 0.1, 0.2, 0.0, MU_EARTH)
    dt = np.linspace(-1e5, 1e6, 41)
    r, v = propagate(r0, v0, MU_EARTH, dt)
    energy = 0.5 * np.sum(v * v, -1) - MU_EARTH / np.linalg.norm(r, axis=-1)
    e0 = 0.5 * v0 @ v0 - MU_EARTH / np.linalg.norm(r0)
    assert np.max(np.abs(energy / e0 - 1)) <= 1e-13
    h = np.cross(r, v)
    assert np.max(np.abs(h - np.cross(r0, v0))) <= 1e-13 * np.linalg.norm(np.cross(r0, v0))
    assert (
        np.max(np.abs(elements.eccentricity_vector(r, v, MU_EARTH) - elements.eccentricity_vector(r0, v0, MU_EARTH)))
        <= 1e-13
    )


def test_forward_then_back_returns_home():
    """Round trip over 3 periods of a mildly eccentric orbit (at e = 0.95 the orbit itself amplifies
    a 1e-16 input perturbation 2e4-fold per period, so both legs are checked against mpmath above)."""
    r0, v0 = elements.elements_to_state(1e7, 0.3, 0.3, 0.1, 0.2, 0.1, MU_EARTH)
    r1, v1 = propagate(r0, v0, MU_EARTH, 3.4e4)
    r2, v2 = propagate(r1, v1, MU_EARTH, -3.4e4)
    np.testing.assert_allclose(r2, r0, rtol=1e-13, atol=1e-13 * np.linalg.norm(r0))


def test_broadcasting_over_states_and_times():
    r0 = np.array([[7e6, 0, 0], [0, 8e6, 0]])
    v0 = np.array([[0, 7.6e3, 0], [-7.0e3, 0, 1e3]])
    r, v = propagate(r0[:, None, :], v0[:, None, :], MU_EARTH, np.array([0.0, 100.0, 1e4]))
    assert r.shape == v.shape == (2, 3, 3)
    r_single, _ = propagate(r0[1], v0[1], MU_EARTH, 1e4)
    assert np.array_equal(r[1, 2], r_single)


def test_stumpff_functions_against_their_definitions():
    z = np.array([-50.0, -1.0, -1e-8, 0.0, 1e-8, 0.7, 1.0, 9.0])
    c0, c1, c2, c3 = stumpff(z)
    s = np.sqrt(np.abs(z))
    with np.errstate(divide="ignore", invalid="ignore"):
        pos = (np.cos(s), np.sin(s) / s, (1 - np.cos(s)) / z, (s - np.sin(s)) / s**3)
        neg = (np.cosh(s), np.sinh(s) / s, (np.cosh(s) - 1) / -z, (np.sinh(s) - s) / s**3)
    for k, ck in enumerate((c0, c1, c2, c3)):
        ref = np.where(z > 0, pos[k], neg[k])
        far = np.abs(z) >= 0.7  # the naive forms are only trustworthy away from z = 0
        np.testing.assert_allclose(ck[far], ref[far], rtol=1e-13)
    np.testing.assert_allclose((c0[3], c1[3], c2[3], c3[3]), (1, 1, 0.5, 1 / 6), rtol=0)


def test_radial_orbit_is_a_clear_error():
    with pytest.raises(DegenerateOrbitError, match="radial"):
        propagate(np.array([1e7, 0, 0]), np.array([-1e3, 0, 0]), MU_EARTH, 10.0)


def test_non_finite_time_is_rejected():
    with pytest.raises(OrbitDomainError, match="not finite"):
        propagate(np.array([1e7, 0, 0]), np.array([0, 7e3, 0]), MU_EARTH, float("nan"))
