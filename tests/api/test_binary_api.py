"""The unit-aware Binary (section XXII): N-body integrations, the fixed-star limit, constructors and errors.

Integrations use G = 1 code units through orbits.validate.backends: the stars are given as GM Quantities in
m3/s2, so their GMs are the code masses, lengths are metres and times seconds. Each integrated quantity is
measured on the trajectory (speeds and distances about the measured centre of mass, areal rates from r x v,
periapsis passages from the root of r . v), never taken from the library.
"""

import doctest
import math

import astropy.units as u
import mpmath
import numpy as np
import pytest

import orbits.encounters.binary
from orbits import BODIES, Binary, Orbit, OrbitDomainError
from orbits._common.constants import G
from orbits.core.twobody import twobody
from orbits.validate.backends import integrate
from orbits.validate.nbody import NBodyProblem

GM = u.m**3 / u.s**2
GM1, GM2 = 1.0, 0.3


@pytest.fixture(scope="module")
def eccentric():
    """e = 0.6, tilted, started away from periapsis, with a drifting centre of mass."""
    return Binary.from_elements(
        GM1 * GM,
        GM2 * GM,
        a=1 * u.m,
        e=0.6,
        inc=0.4 * u.rad,
        raan=0.3 * u.rad,
        argp=1.0 * u.rad,
        nu=2.0 * u.rad,
        com_r=[0.1, -0.2, 0.05] * u.m,
        com_v=[1e-3, -2e-3, 5e-4] * u.m / u.s,
    )


def run(backend, pair, times, **settings):
    """Integrate the pair from its epoch states; return (positions, velocities) of shape (len(times), 2, 3)."""
    r1, v1, r2, v2 = (x.si.value for x in pair.states)
    gm = [pair.gm1.item(), pair.gm2.item()]
    problem = NBodyProblem(gm=gm, positions=[r1, r2], velocities=[v1, v2], n_active=2, times=times)
    result = integrate(backend, problem, **settings)
    return result.positions, result.velocities


def about_centre_of_mass(pair, positions, velocities):
    """Each star's distance and speed about the centre of mass measured from the integrated states."""
    x = np.array([pair.gm1.item(), pair.gm2.item()]) / (pair.gm1.item() + pair.gm2.item())
    com_r, com_v = np.einsum("i,kij->kj", x, positions), np.einsum("i,kij->kj", x, velocities)
    return (
        np.linalg.norm(positions - com_r[:, None], axis=-1),
        np.linalg.norm(velocities - com_v[:, None], axis=-1),
    )


@pytest.fixture(scope="module")
def heyoka_run(eccentric):
    """heyoka (tol 1e-16) at named events of the second and third revolutions after the epoch.

    Returns (times, positions, velocities, rows) with rows mapping each event to its output index."""
    period = eccentric.period.value
    t_p = period - eccentric.time_since_periapsis.value  # first periapsis passage after the epoch
    t1 = eccentric.covertex_times[0].value
    events = {
        "anywhere": t_p + 0.37 * period,
        "covertex_before": t_p + period - t1 / 2,
        "periapsis": t_p + period,
        "covertex_after": t_p + period + t1 / 2,
        "apoapsis": t_p + 1.5 * period,
        "periapsis_next": t_p + 2 * period,
    }
    times = np.array(list(events.values()))
    positions, velocities = run("heyoka", eccentric, times)
    return times, positions, velocities, {name: k for k, name in enumerate(events)}


def test_both_stars_periapsis_apoapsis_and_covertex_speeds_and_distances(eccentric, heyoka_run):
    """heyoka agrees with every star's speed and distance about the CM to <= 1e-14 (measured 9e-15), including
    the co-vertex speed sigma_b of ERRATA #68 and the co-vertex times T1 (separation a at t_p +/- T1 / 2)."""
    _, positions, velocities, rows = heyoka_run
    distance, speed = about_centre_of_mass(eccentric, positions, velocities)
    periapses, covertices = (
        [rows["periapsis"], rows["periapsis_next"]],
        [rows["covertex_before"], rows["covertex_after"]],
    )
    for k, star in enumerate((eccentric.star1, eccentric.star2)):
        checks = [
            (periapses, distance, star.periapsis_distance),
            (periapses, speed, star.periapsis_speed),
            ([rows["apoapsis"]], distance, star.apoapsis_distance),
            ([rows["apoapsis"]], speed, star.apoapsis_speed),
            (covertices, speed, star.covertex_speed),
            (covertices, distance, star.semi_major_axis),  # the co-vertex lies a from the focus
        ]
        for at, measured, expected in checks:
            assert np.abs(measured[at, k] / expected.value - 1).max() < 1e-14
    separation = np.linalg.norm(positions[:, 1] - positions[:, 0], axis=-1)
    assert np.abs(separation[covertices] / eccentric.relative.semi_major_axis.value - 1).max() < 1e-14


def test_period_from_successive_periapsis_passages(eccentric, heyoka_run):
    """Passages are the roots of r . v (Newton step with d(r . v)/dt = v**2 - mu / r on the integrated state);
    two successive ones are T apart to 1e-12 (measured 3e-15), and the Kepler constants follow."""
    times, positions, velocities, rows = heyoka_run
    at = [rows["periapsis"], rows["periapsis_next"]]
    r, v = positions[at, 1] - positions[at, 0], velocities[at, 1] - velocities[at, 0]
    s, ds = np.sum(r * v, axis=-1), np.sum(v * v, axis=-1) - (GM1 + GM2) / np.linalg.norm(r, axis=-1)
    measured = np.diff(times[at] - s / ds)[0]
    assert abs(measured / eccentric.period.value - 1) < 1e-12
    assert abs(eccentric.mean_motion.value * measured / (2 * math.pi) - 1) < 1e-12
    for star in (eccentric.star1, eccentric.star2):
        assert math.isclose(star.semi_major_axis.value**3 / measured**2, star.kepler_constant.value, rel_tol=1e-12)
    a = eccentric.relative.semi_major_axis.value
    assert math.isclose(a**3 / measured**2, eccentric.kepler_constant.value, rel_tol=1e-12)


def test_relative_orbit_measured_on_the_trajectory(eccentric, heyoka_run):
    """The relative orbit's apsides, speeds, e = (r2 - r1) / (r2 + r1), the time of periapsis passage, the turn
    rate |r x v| / r**2 and K, U at periapsis, from heyoka, to 1e-13 (measured <= 5e-15)."""
    times, positions, velocities, rows = heyoka_run
    r, v = positions[:, 1] - positions[:, 0], velocities[:, 1] - velocities[:, 0]
    distance, speed = np.linalg.norm(r, axis=-1), np.linalg.norm(v, axis=-1)
    peri, apo, cov = rows["periapsis"], rows["apoapsis"], rows["covertex_after"]
    rel = eccentric.relative
    measured = {
        "relative_periapsis_distance": distance[peri],
        "relative_apoapsis_distance": distance[apo],
        "relative_periapsis_speed": speed[peri],
        "relative_apoapsis_speed": speed[apo],
        "relative_covertex_speed": speed[cov],
        "eccentricity": (distance[apo] - distance[peri]) / (distance[apo] + distance[peri]),
    }
    table = eccentric.quantities(list(measured))
    for name, value in measured.items():
        assert abs(value / table[name].value - 1) < 1e-13, name
    s, ds = r[peri] @ v[peri], v[peri] @ v[peri] - (GM1 + GM2) / distance[peri]
    passage = times[peri] - s / ds  # the measured passage; the library placed it at times[peri]
    assert abs(passage - times[peri]) < 1e-13 * eccentric.period.value
    turn_rate = np.linalg.norm(np.cross(r[peri], v[peri])) / distance[peri] ** 2
    at_periapsis = Binary.from_elements(GM1 * GM, GM2 * GM, a=rel.semi_major_axis, e=rel.e.item())
    assert abs(turn_rate / at_periapsis.angular_velocity.value - 1) < 1e-13
    kinetic = 0.5 * GM1 * GM2 / (GM1 + GM2) * speed[peri] ** 2 / G
    assert abs(kinetic / at_periapsis.kinetic_energy.value - 1) < 1e-13
    assert abs(-GM1 * GM2 / distance[peri] / G / at_periapsis.potential_energy.value - 1) < 1e-13


def test_areal_rates_angular_momenta_and_energy_on_the_trajectory(eccentric, heyoka_run):
    """Joining line L / (2 mu_red) (ERRATA #58: not the notes' (h + H) / 2), each star's h / 2 and m v x r, and
    E = K + U, all constant along the heyoka trajectory to 1e-14."""
    _, positions, velocities, _ = heyoka_run
    gm = np.array([GM1, GM2])
    x = gm / gm.sum()
    com_r, com_v = np.einsum("i,kij->kj", x, positions), np.einsum("i,kij->kj", x, velocities)
    r_cm, v_cm = positions - com_r[:, None], velocities - com_v[:, None]
    rel = np.linalg.norm(np.cross(positions[:, 1] - positions[:, 0], velocities[:, 1] - velocities[:, 0]), axis=-1)
    assert np.abs(rel / 2 / eccentric.joining_line_areal_velocity.value - 1).max() < 1e-14
    h_star = np.linalg.norm(np.cross(r_cm, v_cm), axis=-1)
    notes_wrong = (h_star[:, 0] + h_star[:, 1]) / 2  # the notes' (h + H) / 2
    assert np.abs(notes_wrong / (rel / 2) - 1).min() > 0.1
    for k, star in enumerate((eccentric.star1, eccentric.star2)):
        assert np.abs(h_star[:, k] / 2 / star.areal_velocity.value - 1).max() < 1e-14
        measured_l = gm[k] / G * h_star[:, k]
        assert np.abs(measured_l / star.angular_momentum.value - 1).max() < 1e-14
    total_l = np.linalg.norm(np.einsum("i,kij->kj", gm / G, np.cross(r_cm, v_cm)), axis=-1)
    assert np.abs(total_l / eccentric.angular_momentum.value - 1).max() < 1e-14
    kinetic = 0.5 * np.einsum("i,kij,kij->k", gm, v_cm, v_cm) / G
    potential = -GM1 * GM2 / np.linalg.norm(positions[:, 1] - positions[:, 0], axis=-1) / G
    assert np.abs((kinetic + potential) / eccentric.energy.value - 1).max() < 1e-14


def test_speeds_at_a_separation_and_the_propagated_states(eccentric, heyoka_run):
    """Vis-viva for both stars (XXII.iv's M sigma, m sigma) at the measured separation, and Binary.propagate in
    the drifting frame, against heyoka (<= 3e-13 relative over three periods, measured 1.1e-13)."""
    times, positions, velocities, _ = heyoka_run
    _, speed = about_centre_of_mass(eccentric, positions, velocities)
    separation = np.linalg.norm(positions[:, 1] - positions[:, 0], axis=-1) * u.m
    v1, v2 = eccentric.speeds_at(separation)
    assert np.abs(v1.value / speed[:, 0] - 1).max() < 1e-13
    assert np.abs(v2.value / speed[:, 1] - 1).max() < 1e-13
    r1, w1, r2, w2 = eccentric.propagate(times * u.s)
    scale = np.linalg.norm(positions[:, 1] - positions[:, 0], axis=-1)[:, None]
    assert np.abs((r1.value - positions[:, 0]) / scale).max() < 3e-13
    assert np.abs((r2.value - positions[:, 1]) / scale).max() < 3e-13
    assert np.abs(w1.value - velocities[:, 0]).max() < 3e-13 * np.abs(velocities).max()
    assert np.abs(w2.value - velocities[:, 1]).max() < 3e-13 * np.abs(velocities).max()


def test_circular_binary_against_rebound_and_the_notes():
    """XXII.v with IAS15 over one period: radii M r / (m + M), m r / (m + M), speeds M sigma and m sigma with
    sigma = sqrt(G / ((m + M) r)), omega = sqrt(G (m + M) / r**3), L = m M sqrt(G r / (m + M)), E, K, U
    (the notes' forms at 40 digits; the integration to 1e-9)."""
    pair = Binary.circular(GM1 * GM, GM2 * GM, 1.7 * u.m, inc=0.2 * u.rad, nu=0.5 * u.rad)
    period = pair.period.value
    positions, velocities = run("rebound", pair, period * np.array([0.25, 0.5, 1.0]), integrator="ias15", epsilon=1e-9)
    distance, speed = about_centre_of_mass(pair, positions, velocities)
    with mpmath.workdps(40):
        big, small, r = mpmath.mpf(GM1), mpmath.mpf(GM2), mpmath.mpf(1.7)  # G = 1: the GMs are the masses
        sigma = mpmath.sqrt(1 / ((big + small) * r))
        notes = {
            "star1_radius": small * r / (big + small),
            "star2_radius": big * r / (big + small),
            "star1_speed": small * sigma,
            "star2_speed": big * sigma,
            "angular_velocity": mpmath.sqrt((big + small) / r**3),
            "angular_momentum": big * small * mpmath.sqrt(r / (big + small)) / G,
            "energy": -big * small / (2 * r) / G,
            "kinetic_energy": big * small / (2 * r) / G,
            "potential_energy": -big * small / r / G,
        }
    table = pair.quantities(list(notes))
    for name, ref in notes.items():
        assert abs(table[name].si.value / float(ref) - 1) < 4e-15, name
    assert np.abs(distance / [table["star1_radius"].value, table["star2_radius"].value] - 1).max() < 1e-9
    assert np.abs(speed / [table["star1_speed"].value, table["star2_speed"].value] - 1).max() < 1e-9
    assert np.abs(positions[-1] - np.array([x.value for x in pair.states[::2]])).max() < 1e-9


def test_a_vanishing_companion_is_the_planet_of_section_xxi():
    """m2 / m1 = 1e-15: star 2 is the fixed-star Orbit to 1e-12 (measured <= 2e-15), the pair's energy and L are
    the planet's, and star 1's tiny orbit is still exact (mass fraction and its periapsis speed to 1e-15)."""
    sun = BODIES["Sun"]
    pair = Binary.from_elements("Sun", 1e-15 * sun.gm * GM, a=1 * u.AU, e=0.0167, nu=0.8 * u.rad)
    planet = Orbit.from_elements("Sun", a=1 * u.AU, e=0.0167, nu=0.8 * u.rad, mass=1e-15 * sun.mass * u.kg)
    names = [
        "semi_major_axis",
        "periapsis_speed",
        "apoapsis_speed",
        "covertex_speed",
        "period",
        "areal_velocity",
        "speed",
        "radius",
        "angular_momentum",
        "energy",
        "kinetic_energy",
    ]
    worst = max(abs((getattr(pair.star2, n) / getattr(planet, n)).to_value(u.one) - 1) for n in names)
    assert worst <= 2e-15
    for name in ("energy", "angular_momentum", "potential_energy"):
        assert abs((getattr(pair, name) / getattr(planet, name)).to_value(u.one) - 1) <= 2e-15
    with mpmath.workdps(40):
        x2 = mpmath.mpf(1e-15 * sun.gm) / (mpmath.mpf(sun.gm) + mpmath.mpf(1e-15 * sun.gm))
        assert abs(pair.mass_fraction.value - x2) <= math.ulp(pair.mass_fraction.value) / 2
        p = mpmath.mpf(u.AU.to(u.m)) * (1 - mpmath.mpf(0.0167) ** 2)
        v1 = x2 * mpmath.sqrt((mpmath.mpf(sun.gm) + mpmath.mpf(1e-15 * sun.gm)) / p) * (1 + mpmath.mpf(0.0167))
    assert abs(pair.star1.periapsis_speed.value / float(v1) - 1) <= 1e-15


def test_star_energies_partition_the_pair():
    """Each Star carries the share m_j / (m1 + m2) of E and U; its K is its own m_i v_i**2 / 2 in the CM frame."""
    pair = Binary.from_elements("Earth", "Moon", a=384399 * u.km, e=0.0549, nu=1.2 * u.rad)
    stars = (pair.star1, pair.star2)
    for name in ("energy", "potential_energy", "kinetic_energy", "angular_momentum"):
        total = sum(getattr(star, name) for star in stars)
        assert math.isclose(total.si.value, getattr(pair, name).si.value, rel_tol=1e-15), name
    _, v1, _, v2 = pair.propagate(0 * u.s, barycentric=True)
    for star, v in zip(stars, (v1, v2)):
        own = 0.5 * star.mass * np.sum(v.value**2)
        assert math.isclose(star.kinetic_energy.to_value(u.J), own, rel_tol=1e-14)


def test_constructors_agree():
    """from_elements, from_vectors (the states of the first), period and circular describe the same pairs."""
    pair = Binary.from_elements("Earth", "Moon", a=384399 * u.km, e=0.0549, inc=5 * u.deg, nu=40 * u.deg)
    r1, v1, r2, v2 = pair.states
    again = Binary.from_vectors("Earth", "Moon", r1, v1, r2, v2)
    for name in ("period", "energy", "angular_momentum", "star1_periapsis_speed", "star2_semi_major_axis"):
        assert math.isclose(again.quantities([name])[name].value, pair.quantities([name])[name].value, rel_tol=1e-13)
    by_period = Binary.from_elements("Earth", "Moon", period=pair.period, e=0.0549)
    assert math.isclose(by_period.relative.semi_major_axis.to_value(u.km), 384399, rel_tol=1e-15)
    ring = Binary.circular("Earth", "Moon", 384399 * u.km)
    assert ring.star1.speed == ring.star1.periapsis_speed and ring.eccentricity == 0
    moon_kg = Binary.from_elements(BODIES["Earth"].mass * u.kg, BODIES["Moon"].mass * u.kg, a=384399 * u.km)
    assert math.isclose(moon_kg.period.value, ring.period.value, rel_tol=4e-16)


def test_centre_of_mass_frame_and_moving_frame():
    pair = Binary.from_elements("Sun", "Jupiter", a=5.2 * u.AU, e=0.048, com_v=[0, 0, 20] * u.km / u.s)
    r1, v1, r2, v2 = pair.propagate(1 * u.yr)
    b1, w1, b2, w2 = pair.propagate(1 * u.yr, barycentric=True)
    np.testing.assert_allclose((r2 - b2).to_value(u.km), [0, 0, 20 * u.yr.to(u.s)], rtol=1e-15)
    np.testing.assert_allclose((w1 - v1).to_value(u.km / u.s), [0, 0, -20], rtol=1e-15)
    com = (pair.mass1 * b1 + pair.mass2 * b2) / pair.total_mass
    assert np.abs(com.to_value(u.m)).max() < 1e-5  # metres, on 7.8e11 m orbits
    assert pair.center_of_mass_velocity.unit == u.m / u.s


def test_escape_speed_from_the_centre_of_mass_and_its_quadrupole_bound():
    """v**2 = 2 G (m1 + m2) / r differs from the two-star potential's by m1 m2 / (m1 + m2)**2 (d / r)**2 at most
    (plus the octupole, O((d / r)**3))."""
    pair = Binary.from_elements("Sun", "Jupiter", a=5.2 * u.AU, e=0.048, nu=1.0 * u.rad)
    states = pair.propagate(0 * u.s, barycentric=True)
    r1, r2 = states[0].to_value(u.m), states[2].to_value(u.m)
    d = np.linalg.norm(r2 - r1)
    rng = np.random.default_rng(7)
    for distance in (20 * d, 100 * d):
        point = rng.normal(size=3)
        point *= distance / np.linalg.norm(point)
        exact = math.sqrt(2 * (pair.gm1 / np.linalg.norm(point - r1) + pair.gm2 / np.linalg.norm(point - r2)))
        monopole = pair.escape_speed(distance * u.m).to_value(u.m / u.s)
        x = pair.mass_fraction.value
        assert abs(monopole**2 / exact**2 - 1) < x * (1 - x) * (d / distance) ** 2 * (1 + d / distance)
    assert math.isclose(
        pair.escape_speed(1 * u.AU).to_value(u.m / u.s), twobody.escape_speed(u.AU.to(u.m), pair.relative.mu)
    )


def test_arrays_of_binaries_broadcast():
    masses = np.array([1e-3, 1e-1, 1.0]) * BODIES["Sun"].mass * u.kg
    pair = Binary.from_elements("Sun", masses, a=[[1], [2]] * u.AU, e=0.1)
    assert pair.shape == (2, 3)
    assert pair.star1.periapsis_speed.shape == (2, 3) and pair.propagate([[0], [1]] * u.yr)[0].shape == (2, 3, 3)
    assert pair.period[1, 2] == Binary.from_elements("Sun", "Sun", a=2 * u.AU, e=0.1).period


def test_unbound_pairs_leave_out_bound_quantities():
    pair = Binary.from_elements("Sun", "Jupiter", a=-1 * u.AU, e=1.5)
    table = pair.quantities()
    assert "period" not in table and "energy" in table and table["energy"].value > 0
    with pytest.raises(OrbitDomainError, match=r"period T is defined for ellipses only \(e < 1\); .* e = 1.5"):
        pair.quantities(["period"])


@pytest.mark.parametrize(
    "kwargs, error, fragment",
    [
        ({"m2": -1 * u.kg}, OrbitDomainError, r"mass m2 = -1.0 kg is outside the allowed range \(0, inf\) kg"),
        ({"m1": 0 * GM}, OrbitDomainError, r"mass m1 = 0.0 m3 / s2 is outside the allowed range \(0, inf\) m3 / s2"),
        ({"m1": 5.0}, TypeError, r"mass m1 = 5.0 has no unit; pass a Quantity such as 5.97e24 \* u.kg"),
        ({"m1": 5 * u.m}, u.UnitConversionError, "mass m1"),
        ({"a": None, "period": -1 * u.day}, OrbitDomainError, r"period T = -86400.0 s is outside .*\(0, inf\) s"),
        (
            {"a": None, "period": 1 * u.day, "e": 1.2},
            OrbitDomainError,
            r"e = 1.2 is outside the allowed range \[0, 1\)",
        ),
        ({"period": 1 * u.day}, TypeError, "give exactly one size"),
        ({"a": 1 * u.AU, "e": 1.2}, OrbitDomainError, "need a < 0 for a hyperbola"),
    ],
)
def test_bad_input_names_quantity_value_range_and_unit(kwargs, error, fragment):
    arguments = {"m1": "Sun", "m2": "Jupiter", "a": 5.2 * u.AU, "e": 0.05, **kwargs}
    with pytest.raises(error, match=fragment):
        Binary.from_elements(arguments.pop("m1"), arguments.pop("m2"), **arguments)


def test_quantities_table_names_and_only():
    pair = Binary.from_elements("Earth", "Moon", a=384399 * u.km, e=0.0549, inc=90 * u.deg)
    table = pair.quantities()
    assert list(table) == orbits.encounters.binary.QUANTITY_NAMES
    assert all(name == name.lower() for name in table)
    only = pair.quantities(["star2_periapsis_speed", "covertex_time_apoapsis_side"])
    assert only["star2_periapsis_speed"] == pair.star2.periapsis_speed
    assert only["covertex_time_apoapsis_side"] == pair.covertex_times[1]
    with pytest.raises(KeyError, match="unknown quantities"):
        pair.quantities(["star3_speed"])


def test_module_examples_run():
    assert doctest.testmod(orbits.encounters.binary).failed == 0


def test_without_an_inclination_the_sky_quantities_ask_for_it():
    """No inclination given: K1, K2, f(M), the radial velocities and the sky position raise (never a face-on 0)
    and the table leaves them out; given i = 90 deg, K1 is the closed form 2 pi a1 / (P sqrt(1 - e**2))."""
    hot_jupiter = Binary.from_elements(1 * u.solMass, 1 * u.jupiterMass, period=4.23 * u.day)
    for name in ("rv_semi_amplitude1", "rv_semi_amplitude2", "mass_function"):
        with pytest.raises(OrbitDomainError, match="needs the inclination i of the orbit to the sky"):
            getattr(hot_jupiter, name)
        assert name not in hot_jupiter.quantities()
    for method in (hot_jupiter.radial_velocities, hot_jupiter.sky_position):
        with pytest.raises(OrbitDomainError, match="inc=... \\(90 deg: edge-on"):
            method()
    with pytest.raises(OrbitDomainError, match="inclination"):
        hot_jupiter.quantities(["rv_semi_amplitude1"])
    assert "relative_inclination" not in hot_jupiter.quantities() and "period" in hot_jupiter.quantities()
    edge_on = Binary.from_elements(1 * u.solMass, 1 * u.jupiterMass, period=4.23 * u.day, inc=90 * u.deg)
    a1 = edge_on.star1.semi_major_axis.to_value(u.m)
    expected = 2 * math.pi * a1 / edge_on.period.to_value(u.s)
    assert edge_on.rv_semi_amplitude1.to_value(u.m / u.s) == pytest.approx(expected, rel=1e-15)  # measured 0
    assert Binary.circular("Sun", "Jupiter", 5.2 * u.AU, inc=0 * u.deg).rv_semi_amplitude1 == 0 * u.m / u.s
