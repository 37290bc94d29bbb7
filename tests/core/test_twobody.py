"""Section XXI quantities against independent references: state vectors, quadrature, published values."""

import math

import mpmath
import numpy as np
import pytest

from orbits._common.constants import BODIES, SIDEREAL_DAY, STANDARD_GRAVITY
from orbits.core.twobody import elements, twobody
from orbits.core.twobody.propagate import propagate

MU = 3.986004418e14


def speed_at_true_anomaly(p, e, nu):
    _, v = elements.elements_to_state(p, e, 0.3, 0.2, 0.1, nu, MU)
    return np.linalg.norm(v)


@pytest.mark.parametrize("e", [0.0, 0.0167, 0.5, 0.9, 0.999])
def test_speeds_match_state_vectors(e):
    p = 8e6
    assert math.isclose(twobody.periapsis_speed(p, e, MU), speed_at_true_anomaly(p, e, 0.0), rel_tol=1e-15)
    assert math.isclose(twobody.apoapsis_speed(p, e, MU), speed_at_true_anomaly(p, e, math.pi), rel_tol=1e-12)
    covertex_nu = math.acos(-e)  # r = a there (XXI.iv, corrected by ERRATA #44)
    assert math.isclose(twobody.covertex_speed(p, e, MU), speed_at_true_anomaly(p, e, covertex_nu), rel_tol=1e-13)
    r = p / (1 + e * math.cos(1.1))
    assert math.isclose(twobody.speed_at_radius(r, p, e, MU), speed_at_true_anomaly(p, e, 1.1), rel_tol=1e-14)


@pytest.mark.parametrize("e", [0.0167, 0.5, 0.9])
def test_distances_and_axes(e):
    p = 8e6
    a, c = twobody.semi_major_axis(p, e), twobody.focal_distance(p, e)
    assert math.isclose(twobody.periapsis_distance(p, e), a - c, rel_tol=1e-15)  # r1 = a - c
    assert math.isclose(twobody.apoapsis_distance(p, e), a + c, rel_tol=1e-15)  # r2 = a + c
    assert math.isclose(c / a, e, rel_tol=1e-15)  # ERRATA #43: e = c / a
    assert math.isclose(twobody.semi_minor_axis(p, e) ** 2, a * a - c * c, rel_tol=1e-13)
    assert math.isclose(twobody.semi_minor_axis(p, e) ** 2, a * p, rel_tol=1e-15)  # b = sqrt(a l)


@pytest.mark.parametrize("e", [0.0167, 0.5, 0.9])
def test_covertex_times_against_the_area_integral(e):
    """T1 = time from co-vertex to co-vertex through periapsis: integral of r**2 / h over nu (XXI.vii)."""
    p = 8e6
    t1, t2 = twobody.covertex_times(p, e, MU)
    with mpmath.workdps(40):
        h, nu_b = mpmath.sqrt(MU * p), mpmath.acos(-e)
        ref = mpmath.quad(lambda f: (p / (1 + e * mpmath.cos(f))) ** 2 / h, [-nu_b, 0, nu_b])
    assert abs(t1 - ref) <= 1e-14 * ref
    assert math.isclose(t1 + t2, twobody.period(p, e, MU), rel_tol=1e-15)


def test_period_returns_the_body_to_its_start():
    p, e = 9e6, 0.6
    r0, v0 = elements.elements_to_state(p, e, 0.3, 0.2, 0.1, 0.7, MU)
    r, v = propagate(r0, v0, MU, twobody.period(p, e, MU))
    assert np.linalg.norm(r - r0) <= 1e-13 * np.linalg.norm(r0)


def test_energy_angular_momentum_and_areal_velocity_from_state_vectors():
    rng = np.random.default_rng(4)
    for e in (0.0, 0.3, 0.95, 1.0, 3.0):
        p = 7e6
        nu = rng.uniform(-1, 1)
        r, v = elements.elements_to_state(p, e, 0.4, 0.5, 0.6, nu, MU)
        energy = 0.5 * v @ v - MU / np.linalg.norm(r)
        assert abs(twobody.specific_energy(p, e, MU) - energy) <= 1e-14 * MU / p
        h = np.linalg.norm(np.cross(r, v))
        assert math.isclose(twobody.specific_angular_momentum(p, MU), h, rel_tol=1e-15)
        assert math.isclose(twobody.areal_velocity(p, MU), h / 2, rel_tol=1e-15)


def test_geostationary_radius_gives_a_sidereal_day():
    """Published geostationary radius 42,164.17 km (e.g. Vallado, Fundamentals, 4th ed.) -> 1 sidereal day."""
    assert math.isclose(twobody.period(42_164_170.0, 0.0, MU), SIDEREAL_DAY, rel_tol=2e-6)


def test_notes_first_and_second_cosmic_velocities():
    """XXI.ix: sqrt(g R) = 7.9 km/s and sqrt(2 g R) = 11.2 km/s (ERRATA: 7.904 and 11.178 km/s, R = 6371 km)."""
    radius = 6.371e6
    mu = STANDARD_GRAVITY * radius**2
    assert round(twobody.circular_speed(radius, mu) / 1e3, 3) == 7.904
    assert round(twobody.escape_speed(radius, mu) / 1e3, 3) == 11.178


def test_earth_year_from_keplers_third_law():
    """Fixed-Sun period of Earth's mean orbit: 365.2583 d against the sidereal year 365.256363 d.

    The 5.4e-6 difference is physics, not rounding: the fixed-star model leaves out the Earth-Moon mass
    (1.5e-6 of T) and Standish's fitted mean a absorbs planetary perturbations. 1e-5 bounds both."""
    orbit = BODIES["Earth"].orbit
    p = orbit.a * (1 - orbit.e**2)
    days = twobody.period(p, orbit.e, BODIES["Sun"].gm) / 86400
    assert abs(days / 365.256363 - 1) < 1e-5


def test_circular_orbit_quantities():
    r = 7e6
    assert math.isclose(twobody.circular_angular_velocity(r, MU) * r, twobody.circular_speed(r, MU), rel_tol=1e-15)
    assert math.isclose(
        twobody.period(r, 0.0, MU) * twobody.circular_angular_velocity(r, MU), 2 * math.pi, rel_tol=1e-15
    )
    assert math.isclose(twobody.potential_energy(r, MU, 2.0), -2 * MU / r, rel_tol=0)
