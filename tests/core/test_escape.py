"""Section XXI.ix-xi in the numeric core: cosmic velocities, synchronous radius, maximum elongation.

References: mpmath at 50 digits written from the physics (energy conservation for the third cosmic velocity,
a brute-force maximisation of the sight angle for the elongation), the notes' and ERRATA's printed values,
and a published geostationary radius.
"""

import math

import mpmath
import mpref
import numpy as np
import pytest

from orbits._common.constants import AU, BODIES, EARTH_MEAN_RADIUS, SIDEREAL_DAY, STANDARD_GRAVITY
from orbits.core.encounters import escape
from orbits.core.twobody import twobody

EARTH_ORBIT_SPEED = math.sqrt(BODIES["Sun"].gm / BODIES["Earth"].orbit.a)


def ulps(x, ref):
    return float(mpref.ulp_error(x, ref))


def test_cosmic_velocities_reproduce_the_notes_and_the_errata():
    """XXI.ix: 7.904, 11.178 and 16.65 km/s (ERRATA #54), shown in the notes as 7.9, 11.2 and 16.7 km/s.

    The notes' 16.7 is the same patched-conic formula applied to the rounded speeds 29.8 and 11.2 km/s
    (16.67 km/s); unrounded, v3 = 16.648 km/s."""
    g, radius = STANDARD_GRAVITY, EARTH_MEAN_RADIUS
    v1 = escape.first_cosmic_velocity(g, radius) / 1e3
    v2 = escape.second_cosmic_velocity(g, radius) / 1e3
    v3 = escape.third_cosmic_velocity(EARTH_ORBIT_SPEED, v2 * 1e3) / 1e3
    assert (round(v1, 3), round(v2, 3), round(v3, 2)) == (7.904, 11.178, 16.65)
    assert (round(v1, 1), round(v2, 1)) == (7.9, 11.2)
    assert round(escape.third_cosmic_velocity(round(EARTH_ORBIT_SPEED / 1e3, 1), round(v2, 1)), 1) == 16.7


@pytest.mark.parametrize("g, radius", [(STANDARD_GRAVITY, EARTH_MEAN_RADIUS), (24.79, 7.1492e7), (1.62, 1.7374e6)])
def test_first_and_second_cosmic_velocities_within_an_ulp(g, radius):
    with mpmath.workdps(50):
        gr = mpmath.mpf(g) * mpmath.mpf(radius)
        assert ulps(escape.first_cosmic_velocity(g, radius), mpmath.sqrt(gr)) <= 1
        assert ulps(escape.second_cosmic_velocity(g, radius), mpmath.sqrt(2 * gr)) <= 1
        # the surface escape speed is also sqrt(2 mu / R) with mu = g R**2
        mu = escape.surface_gravity(g * radius**2, radius) * radius**2
        assert math.isclose(twobody.escape_speed(radius, mu), escape.second_cosmic_velocity(g, radius), rel_tol=1e-15)
        assert ulps(twobody.escape_speed(radius, mu), mpmath.sqrt(2 * mpmath.mpf(mu) / radius)) <= 1


@pytest.mark.parametrize("v_orbit, v_esc", [(EARTH_ORBIT_SPEED, 11178.38692745961), (13.06e3, 59.5e3), (1.0, 1e-3)])
def test_third_cosmic_velocity_from_energy_conservation(v_orbit, v_esc):
    """Leave the planet with the speed that, added to its orbital speed, gives the local solar escape speed
    sqrt(2 G M_sun / a): v_inf = sqrt(2) v - v; then v3**2 = v_inf**2 + v_esc**2 (within 2 ulp)."""
    with mpmath.workdps(50):
        v, ve = mpmath.mpf(v_orbit), mpmath.mpf(v_esc)
        excess = mpmath.sqrt(2 * v**2) - v
        ref = mpmath.sqrt(excess**2 + ve**2)
        assert ulps(escape.escape_excess_speed(v_orbit), excess) <= 1
    assert ulps(escape.third_cosmic_velocity(v_orbit, v_esc), ref) <= 2


def test_sqrt2_minus_1_is_correctly_rounded():
    with mpmath.workdps(50):
        assert ulps(escape.SQRT2_MINUS_1, mpmath.sqrt(2) - 1) <= 0.5


@pytest.mark.parametrize("mu, period", [(3.986004e14, SIDEREAL_DAY), (1.26686534e17, 35730.0), (4.9028e12, 2.36e6)])
def test_synchronous_radius_within_two_ulp_and_keplers_third_law(mu, period):
    radius = escape.synchronous_radius(mu, period)
    with mpmath.workdps(50):
        ref = mpmath.cbrt(mpmath.mpf(mu) * mpmath.mpf(period) ** 2 / (4 * mpmath.pi**2))
    assert ulps(radius, ref) <= 2
    assert math.isclose(twobody.period(radius, 0.0, mu), period, rel_tol=4e-16)


def test_geostationary_orbit_of_the_notes():
    """XXI.x: 42164.17 km from the centre (Vallado, Fundamentals of Astrodynamics, 4th ed., published value)
    and 35786 km above the IAU equatorial radius (ERRATA #55)."""
    earth = BODIES["Earth"]
    radius = escape.synchronous_radius(earth.gm, earth.rotation_period)
    assert abs(radius / 1e3 - 42164.17) < 0.01
    assert round((radius - earth.radius) / 1e3) == 35786


def brute_force_elongation(r, big_r):
    """Largest sight angle between the star and the inner planet, maximised over the planet's position (mpmath)."""
    with mpmath.workdps(50):
        r, big_r = mpmath.mpf(r), mpmath.mpf(big_r)

        def angle(theta):  # observer at (R, 0), star at the origin, planet at r (cos theta, sin theta)
            to_star = (-big_r, mpmath.mpf(0))
            to_planet = (r * mpmath.cos(theta) - big_r, r * mpmath.sin(theta))
            cross = to_star[0] * to_planet[1] - to_star[1] * to_planet[0]
            dot = to_star[0] * to_planet[0] + to_star[1] * to_planet[1]
            return abs(mpmath.atan2(cross, dot))

        best = mpmath.findroot(lambda t: mpmath.diff(angle, t), mpmath.acos(r / big_r))
        return angle(best)


@pytest.mark.parametrize(
    "r, big_r", [(0.723 * AU, AU), (AU, 5.2 * AU), (0.387 * AU, AU), (3.0 * (1 - 1e-12), 3.0), (1.0 - 1e-12, 1.0)]
)
def test_max_elongation_is_the_largest_sight_angle(r, big_r):
    """XXI.xi: arcsin(r / R), reached with the sight line tangent to the inner orbit; within 2 ulp of the brute
    force maximum, also at r / R = 1 - 1e-12 where float64 arcsin(r / R) is off by 1.2e5 ulp (R = 3)."""
    ref = brute_force_elongation(r, big_r)
    assert ulps(escape.max_elongation(r, big_r), ref) <= 2
    if big_r == 3.0:  # here r / R rounds, and arcsin multiplies that by 1 / sqrt(1 - (r / R)**2)
        assert ulps(math.asin(r / big_r), ref) > 1e5


def test_everything_broadcasts():
    assert escape.synchronous_radius(np.array([3.986004e14, 1.26686534e17]), SIDEREAL_DAY).shape == (2,)
    assert escape.max_elongation(np.array([[0.3], [0.7]]), np.array([1.0, 2.0, 3.0])).shape == (2, 3)
