"""The unit-aware Flyby (XXI.vi, XXII.vi): N-body integrations from 2000 b, the inverse problem and errors.

Integrations use G = 1 code units through orbits.validate.backends (GMs given in m3/s2 are the code masses).
The initial state is built from the two invariants alone: at distance 2000 b on the incoming branch, speed
sqrt(u**2 + 2 mu / r) from the energy and transverse speed u b / r from the angular momentum. The time of
periapsis passage is an mpmath solution of the hyperbolic Kepler equation for that state. The deflection is
measured directly: the angle between the velocity far out on the outgoing branch (1e8 b) and the reversed
velocity far out on the time-reversed incoming branch, where the remaining bend is O((b / D)**2) = 1e-16.
"""

import doctest
import math

import astropy.units as u
import mpmath
import numpy as np
import pytest

import orbits.encounters.flyby
from orbits import BODIES, Flyby, OrbitDomainError
from orbits._common.constants import G
from orbits.validate.backends import integrate
from orbits.validate.nbody import NBodyProblem

GM = u.m**3 / u.s**2
FAR = 1e8  # impact parameters: where the outgoing and reversed incoming velocities are read


def incoming_state(b, v_inf, mu, distance):
    """Relative (r, v) at `distance` on the incoming branch of the hyperbola with these invariants."""
    speed = math.sqrt(v_inf**2 + 2 * mu / distance)
    transverse = v_inf * b / distance
    return np.array([distance, 0.0, 0.0]), np.array([-math.sqrt(speed**2 - transverse**2), transverse, 0.0])


def time_to_periapsis(r, v, mu):
    """(e sinh H - H) / n for the hyperbola through (r, v): mpmath at 40 digits."""
    with mpmath.workdps(40):
        mu = mpmath.mpf(mu)
        radius = mpmath.sqrt(mpmath.fsum(mpmath.mpf(x) ** 2 for x in r))
        a = 1 / (2 / radius - mpmath.fsum(mpmath.mpf(x) ** 2 for x in v) / mu)
        h2 = mpmath.fsum(mpmath.mpf(x) ** 2 for x in np.cross(r, v))
        e = mpmath.sqrt(1 - h2 / (mu * a))
        big_h = mpmath.acosh((1 - radius / a) / e)
        return float((e * mpmath.sinh(big_h) - big_h) / mpmath.sqrt(mu / (-a) ** 3))


def angle_between(a, b):
    return math.atan2(np.linalg.norm(np.cross(a, b)), a @ b)


def fly(backend, gm, b, v_inf, settings):
    """Integrate the encounter of masses gm (G = 1) from 2000 b.

    Returns (closest, far, deflection): the barycentric (positions, velocities) of both bodies at closest
    approach and far out (1e8 b) on the outgoing branch, and the deflection measured far out on both branches.
    """
    mu = sum(gm)
    r, v = incoming_state(b, v_inf, mu, 2000 * b)
    t_p = time_to_periapsis(r, v, mu)
    x = np.array(gm) / mu
    active = 2 if gm[1] > 0 else 1

    def states(r_rel, v_rel, times):
        problem = NBodyProblem(
            gm=gm,
            positions=[-x[1] * r_rel, x[0] * r_rel],
            velocities=[-x[1] * v_rel, x[0] * v_rel],
            n_active=active,
            times=times,
        )
        result = integrate(backend, problem, **settings)
        return result.positions, result.velocities

    positions, velocities = states(r, v, [t_p, t_p + FAR * b / v_inf])
    _, reversed_velocities = states(r, -v, [FAR * b / v_inf])
    out = velocities[1, 1] - velocities[1, 0]
    back = -(reversed_velocities[0, 1] - reversed_velocities[0, 0])
    return (positions[0], velocities[0]), (positions[1], velocities[1]), angle_between(back, out)


@pytest.mark.parametrize("k", [0.05, 1.0, 20.0])
@pytest.mark.parametrize("backend, settings", [("rebound", {"integrator": "ias15", "epsilon": 1e-9}), ("heyoka", {})])
def test_closest_approach_speed_and_deflection_past_a_fixed_star(backend, settings, k):
    """XXI.vi against IAS15 and heyoka (a test particle about gm = 1): R, w and the deflection to 1e-12
    (measured at worst 3.1e-15, 1.3e-15 and 7.5e-15; the ERRATA's own check reached 1e-10), for deflections of
    174, 90 and 5.7 degrees."""
    b, v_inf = k, 1.0  # k = b v_inf**2 / mu with mu = 1
    encounter = Flyby.past(1.0 * GM, v_inf * u.m / u.s, b * u.m)
    (positions, velocities), _, deflection = fly(backend, [1.0, 0.0], b, v_inf, settings)
    assert abs(np.linalg.norm(positions[1]) / encounter.periapsis_distance.value - 1) < 1e-12
    assert abs(np.linalg.norm(velocities[1]) / encounter.periapsis_speed.value - 1) < 1e-12
    assert abs(deflection / encounter.deflection_angle.value - 1) < 1e-12
    assert np.array_equal(positions[0], np.zeros(3))  # the star stays fixed


def test_hyperbola_elements_and_invariants_measured_on_the_trajectory():
    """IAS15: e = R w**2 / mu - 1, p = (R w)**2 / mu and a = 1 / (2 / R - w**2 / mu) from the integrated closest
    approach, and h = |r x v| there; nu_inf = (pi + delta) / 2; the speed and E / m far out (1e8 b, where r x v
    would cancel 8 digits); all to 1e-12 (measured 4.4e-16)."""
    b, v_inf, mu = 0.3, 1.7, 1.0
    encounter = Flyby.past(mu * GM, v_inf * u.m / u.s, b * u.m, mass=2.0 * u.kg)
    (positions, velocities), (far_r, far_v), deflection = fly("rebound", [mu, 0.0], b, v_inf, {"epsilon": 1e-9})
    big_r, w = np.linalg.norm(positions[1]), np.linalg.norm(velocities[1])
    measured = {
        "eccentricity": big_r * w**2 / mu - 1,
        "semilatus_rectum": (big_r * w) ** 2 / mu,
        "semi_major_axis": 1 / (2 / big_r - w**2 / mu),
        "asymptote_true_anomaly": (math.pi + deflection) / 2,
        "specific_energy": far_v[1] @ far_v[1] / 2 - mu / np.linalg.norm(far_r[1]),
        "specific_angular_momentum": np.linalg.norm(np.cross(positions[1], velocities[1])),
        "energy": 2.0 * (far_v[1] @ far_v[1] / 2 - mu / np.linalg.norm(far_r[1])),
        "angular_momentum": 2.0 * np.linalg.norm(np.cross(positions[1], velocities[1])),
    }
    table = encounter.quantities(list(measured))
    for name, value in measured.items():
        assert abs(value / table[name].si.value - 1) < 1e-12, name
    speed_far = encounter.speed_at(np.linalg.norm(far_r[1]) * u.m).value
    assert abs(np.linalg.norm(far_v[1]) / speed_far - 1) < 1e-12


def test_impact_parameter_for_a_wanted_closest_approach_is_flown():
    """The inverse problem: b from the wanted R, then IAS15 from 2000 b comes within 1e-12 of R."""
    wanted = 0.3
    encounter = Flyby.past(1.0 * GM, 2.0 * u.m / u.s, periapsis=wanted * u.m)
    b = encounter.impact_parameter.value
    (positions, _), _, _ = fly("rebound", [1.0, 0.0], b, 2.0, {"integrator": "ias15", "epsilon": 1e-9})
    assert abs(np.linalg.norm(positions[1]) / wanted - 1) < 1e-12


def test_two_finite_masses_both_stars_at_closest_approach_against_heyoka():
    """XXII.vi with heyoka (gm 1 and 0.4): the separation R, both stars' speeds M zeta and m zeta and distances
    from the centre of mass at closest approach, and the deflection, to 1e-12 (measured <= 3e-15)."""
    gm1, gm2, b, v_inf = 1.0, 0.4, 0.8, 1.3
    encounter = Flyby.between(gm1 * GM, gm2 * GM, v_inf * u.m / u.s, b * u.m)
    (positions, velocities), (far_r, far_v), deflection = fly("heyoka", [gm1, gm2], b, v_inf, {})
    assert abs(np.linalg.norm(positions[1] - positions[0]) / encounter.periapsis_distance.value - 1) < 1e-12
    x = np.array([gm1, gm2]) / (gm1 + gm2)
    com_r, com_v = x @ positions, x @ velocities  # measured: rounding lets the CM drift by 1e-13 b
    far_com_r, far_com_v = x @ far_r, x @ far_v
    for k, star in enumerate((encounter.star1, encounter.star2)):
        assert abs(np.linalg.norm(velocities[k] - com_v) / star.periapsis_speed.value - 1) < 1e-12
        assert abs(np.linalg.norm(positions[k] - com_r) / star.periapsis_distance.value - 1) < 1e-12
        assert abs(deflection / star.deflection_angle.value - 1) < 1e-12
        far_speed = star.speed_at(np.linalg.norm(far_r[k] - far_com_r) * u.m).value  # tends to m_j v_inf / (m1 + m2)
        assert abs(np.linalg.norm(far_v[k] - far_com_v) / far_speed - 1) < 1e-12
    with mpmath.workdps(40):  # the notes' zeta = (sqrt(G**2 + (m + M)**2 eta**4 b**2) + G) / ((m + M) eta b), G = 1
        total, eta = mpmath.mpf(gm1 + gm2), mpmath.mpf(v_inf) / (gm1 + gm2)
        zeta = (mpmath.sqrt(1 + total**2 * eta**4 * b**2) + 1) / (total * eta * b)
        assert abs(encounter.star1.periapsis_speed.value / float(gm2 * zeta) - 1) < 1e-15
        assert abs(encounter.star2.periapsis_speed.value / float(gm1 * zeta) - 1) < 1e-15


def test_energies_and_angular_momentum_of_both_forms():
    """XXI.vi: E = m u**2 / 2, L = m u b, K = E - U; XXII.vi: E = m M (m + M) eta**2 / 2, L = m M b eta."""
    jupiter = BODIES["Jupiter"]
    probe = Flyby.past("Jupiter", 5.6 * u.km / u.s, 1e6 * u.km, mass=722 * u.kg)
    assert math.isclose(probe.energy.to_value(u.J), 722 * 5.6e3**2 / 2, rel_tol=1e-15)
    assert math.isclose(probe.angular_momentum.si.value, 722 * 5.6e3 * 1e9, rel_tol=1e-15)
    r = 3e8 * u.m
    k = probe.kinetic_energy_at(r).to_value(u.J)
    assert math.isclose(k, 722 * probe.speed_at(r).value ** 2 / 2, rel_tol=1e-14)
    assert math.isclose(probe.potential_energy_at(r).to_value(u.J), -jupiter.gm * 722 / 3e8, rel_tol=1e-15)
    with pytest.warns(orbits.InsideBodyWarning, match="they collide"):  # the notes' example: a collision
        pair = Flyby.between("Sun", "Jupiter", 1 * u.km / u.s, 1 * u.AU)
    m, big = jupiter.mass, BODIES["Sun"].mass
    eta = 1e3 / (m + big)
    assert math.isclose(pair.energy.to_value(u.J), m * big * (m + big) * eta**2 / 2, rel_tol=1e-14)
    assert math.isclose(pair.angular_momentum.si.value, m * big * u.AU.to(u.m) * eta, rel_tol=1e-14)
    assert math.isclose(pair.star1.speed_at_infinity.value + pair.star2.speed_at_infinity.value, 1e3, rel_tol=1e-15)
    with pytest.raises(OrbitDomainError, match="needs the moving body's mass"):
        _ = Flyby.past("Jupiter", 5.6 * u.km / u.s, 1e6 * u.km).energy
    with pytest.raises(OrbitDomainError, match="two finite masses only"):
        _ = probe.star1


def test_the_hyperbola_as_an_orbit():
    encounter = Flyby.past("Jupiter", 5.6 * u.km / u.s, periapsis=2e5 * u.km)
    orbit = encounter.orbit
    assert math.isclose(orbit.periapsis_distance.to_value(u.km), 2e5, rel_tol=1e-15)
    assert math.isclose(orbit.semi_major_axis.value, encounter.semi_major_axis.value, rel_tol=1e-14)
    r, v = orbit.propagate(1 * u.day)
    assert math.isclose(np.linalg.norm(v.value), encounter.speed_at(np.linalg.norm(r.value) * u.m).value, rel_tol=1e-14)


def test_arrays_broadcast():
    with pytest.warns(orbits.InsideBodyWarning, match=r"Flyby \(1 of 6\): .* inside Jupiter"):
        encounters = Flyby.past("Jupiter", [[3], [6]] * u.km / u.s, [1e6, 2e6, 4e6] * u.km)
    assert encounters.shape == (2, 3) and encounters.deflection_angle.shape == (2, 3)
    single = Flyby.past("Jupiter", 6 * u.km / u.s, 2e6 * u.km)
    assert encounters.periapsis_distance[1, 1] == single.periapsis_distance


@pytest.mark.parametrize(
    "call, error, fragment",
    [
        (lambda: Flyby.past("Earth", 1 * u.km / u.s, -1 * u.km), OrbitDomainError, r"impact parameter b = -1000.0 m "),
        (lambda: Flyby.past("Earth", 0 * u.km / u.s, 1 * u.km), OrbitDomainError, r"v_inf = 0.0 m / s is outside"),
        (lambda: Flyby.past("Earth", 1 * u.km / u.s, periapsis=0 * u.km), OrbitDomainError, r"\(0, inf\) m"),
        (lambda: Flyby.past("Earth", 1 * u.km / u.s), TypeError, "exactly one of the impact parameter b"),
        (lambda: Flyby.past("Earth", 1 * u.km / u.s, 1 * u.km, periapsis=1 * u.km), TypeError, "exactly one"),
        (lambda: Flyby.between("Sun", -1 * u.kg, 1 * u.km / u.s, 1 * u.AU), OrbitDomainError, "mass m2 = -1.0 kg"),
        (lambda: Flyby.past("Earth", 1, 1 * u.km), TypeError, "has no unit"),
        (lambda: Flyby.past("Earth", 1 * u.km / u.s, 1e5 * u.km).quantities(["R"]), KeyError, "unknown quantities"),
    ],
)
def test_bad_input_names_quantity_value_range_and_unit(call, error, fragment):
    with pytest.raises(error, match=fragment):
        call()


def test_quantities_tables():
    fixed = Flyby.past("Jupiter", 5.6 * u.km / u.s, 1e6 * u.km)
    assert "energy" not in fixed.quantities() and "star1_periapsis_speed" not in fixed.quantities()
    with pytest.warns(orbits.InsideBodyWarning, match="they collide"):
        pair = Flyby.between("Sun", "Jupiter", 1 * u.km / u.s, 1 * u.AU)
    assert list(pair.quantities()) == orbits.encounters.flyby.QUANTITY_NAMES
    assert pair.quantities(["star2_periapsis_speed"])["star2_periapsis_speed"] == pair.star2.periapsis_speed
    assert math.isclose(pair.mass.item(), BODIES["Sun"].mass * BODIES["Jupiter"].mass / (pair.mu.item() / G))


def test_module_examples_run():
    assert doctest.testmod(orbits.encounters.flyby).failed == 0


def test_a_flyby_inside_the_bodies_is_a_collision_said_once():
    """Flyby.between adds the two catalogue radii, Flyby.past takes the primary's; the relative Orbit does not say
    it a second time."""
    import warnings

    from orbits import InsideBodyWarning

    with warnings.catch_warnings(record=True) as said:
        warnings.simplefilter("always")
        crash = Flyby.between("Sun", "Jupiter", 1 * u.km / u.s, b=1 * u.AU)
        assert crash.orbit.e > 1
    assert [str(w.message) for w in said] == [
        "Flyby: closest approach 84235.41 km is inside the Sun and Jupiter (radii added: 767192 km): they collide"]
    assert issubclass(said[0].category, InsideBodyWarning)
    with pytest.warns(InsideBodyWarning, match="inside Jupiter"):
        Flyby.past("Jupiter", 5.6 * u.km / u.s, periapsis=50_000 * u.km)
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        assert Flyby.past("Jupiter", 5.6 * u.km / u.s, periapsis=200_000 * u.km).orbit.e > 1
