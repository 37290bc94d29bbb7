"""The numbers the notebooks show, checked here (the notebooks teach and hold no assert).

One section per notebook, in its order; each test computes what its notebook computes, through the same public
API, and holds it to the tolerance the notebook once asserted (the measured figure in a comment). Checks that need
a long integration are made where their subject is tested, and named at the end of each section.
"""

import math

import astropy.units as u
import numpy as np
import pytest

from orbits import anomalies
from orbits.tools.reference import kepler_E, ulp_error

# 01 Kepler's equation -------------------------------------------------------------------------------------------


def test_kepler_hard_corner_within_4_ulp():
    """e = 1 - 1e-12, M = 1e-9 rad: measured 0.64 ulp from the 60-digit root."""
    e, M = 1 - 1e-12, 1e-9
    E = anomalies(e, mean_anomaly=M * u.rad)["eccentric_anomaly"].to_value(u.rad)
    assert ulp_error(E, kepler_E(M, e)) <= 4


def test_kepler_sweep_of_300_within_4_ulp():
    """The notebook's 300 cases (seed 0): ordinary, singular corner, huge M. Measured worst 1.00 ulp."""
    rng = np.random.default_rng(0)
    Ms = np.concatenate([rng.uniform(-10, 10, 100), 10 ** rng.uniform(-12, -3, 100), 10 ** rng.uniform(3, 12, 100)])
    es = np.concatenate([rng.uniform(0, 1, 100), 1 - 10 ** rng.uniform(-15, -6, 100), rng.uniform(0, 1, 100)])
    Es = anomalies(es, mean_anomaly=Ms * u.rad)["eccentric_anomaly"].to_value(u.rad)
    assert max(float(ulp_error(E, kepler_E(M, e))) for M, e, E in zip(Ms, es, Es)) <= 4


def test_hyperbolic_and_parabolic_roots_satisfy_their_equations():
    """e sinh H - H = 1e6 at e = 1.5: residual measured -3.5e-10, the round-off of evaluating it at 1e6 (one ulp of
    1e6 is 1.2e-10). Barker's D + D**3/3 = 2: measured exactly 2."""
    H = anomalies(1.5, mean_anomaly=1e6 * u.rad)["hyperbolic_anomaly"].to_value(u.rad)
    assert abs(1.5 * np.sinh(H) - H - 1e6) <= 4e-9
    D = anomalies(1.0, mean_anomaly=2.0)["parabolic_anomaly"].value
    assert abs(D + D**3 / 3 - 2.0) <= 4.5e-16


def test_co_vertex_to_co_vertex_is_the_courses_t1():
    """T1 / T = 1/2 - e/pi at e = 0.9, from the mean anomaly at E = 90 deg: measured 1.1e-16 apart."""
    e = 0.9
    quarter = anomalies(e, true_anomaly=np.arccos(-e) * u.rad)["mean_anomaly"]
    assert abs((2 * quarter / (360 * u.deg)).to_value(u.one) - (0.5 - e / np.pi)) <= 1e-15


# 02 Orbits about a fixed star -----------------------------------------------------------------------------------


@pytest.fixture(scope="module")
def earth_orbit():
    from orbits import BODIES, Orbit

    return Orbit.from_elements("Sun", a=1.00000261 * u.AU, e=0.01671123, mass=BODIES["Earth"].mass * u.kg)


def test_earths_year_and_eccentricity(earth_orbit):
    """Kepler III with the Standish (1992) a and the IAU GM of the Sun: 365.25833 d; e = c / a exactly 0.01671123
    (measured 0 apart)."""
    assert round(earth_orbit.period.to_value(u.day), 4) == 365.2583
    assert abs((earth_orbit.focal_distance / earth_orbit.semi_major_axis).to_value(u.one) - 0.01671123) <= 1e-15


def test_low_and_geostationary_orbits():
    """6778 km: 92.56 min. 42164.17 km: 86164.096 s, within 0.06 s of the sidereal day 86164.0905 s, 35786 km above
    the WGS 84 equatorial radius."""
    from orbits import Orbit

    leo = Orbit.circular("Earth", 6778 * u.km)
    geo = Orbit.circular("Earth", 42164.17 * u.km)
    assert round(leo.period.to_value(u.min), 2) == 92.56
    assert abs(geo.period.to_value(u.s) - 86164.0905) <= 0.06
    assert round((geo.radius - 6378.137 * u.km).to_value(u.km)) == 35786


def test_a_grid_of_orbits_obeys_keplers_third_law():
    """The period depends on a alone (the three rows equal exactly); 30 AU: 30**1.5 = 164.32 yr."""
    from orbits import Orbit

    grid = Orbit.from_elements("Sun", a=np.linspace(0.4, 30, 5) * u.AU, e=np.array([[0.0], [0.5], [0.9]]))
    assert np.all(grid.period == grid.period[0])
    assert round(grid.period[0, -1].to_value(u.yr), 2) == 164.32


def near_parabolic_comet():
    from orbits import Orbit

    return Orbit.from_elements("Sun", q=0.5 * u.AU, e=0.999999, nu=-90 * u.deg)


def test_the_comets_dots_are_inside_its_picture(earth_orbit):
    """The comet every 20 days for 200 days, drawn over the window of 10 q: every dot inside the axes, and the
    window under 20 AU wide (not a 1e6 AU line)."""
    from orbits.plot import orbits

    comet = near_parabolic_comet()
    positions, _ = comet.propagate(np.arange(20, 201, 20) * u.day)
    _, ax = orbits(comet, earth_orbit, labels=["comet, e = 0.999999", "Earth"])
    shown = positions.to_value(u.AU)
    ax.plot(shown[:, 0], shown[:, 1], "o")
    x_low, x_high = sorted(ax.get_xlim())
    y_low, y_high = sorted(ax.get_ylim())
    assert np.all((x_low < shown[:, 0]) & (shown[:, 0] < x_high) & (y_low < shown[:, 1]) & (shown[:, 1] < y_high))
    assert x_high - x_low < 20  # AU


def test_the_comets_distances():
    """At nu = -90 deg r = p = q (1 + e) (measured 0 apart); after 50 and 100 days 0.56844747 and 1.38102567 AU."""
    r, _ = near_parabolic_comet().propagate([0, 50, 100] * u.day)
    distances = np.linalg.norm(r, axis=-1).to_value(u.AU)
    assert abs(distances[0] / (0.5 * (1 + 0.999999)) - 1) <= 1e-15
    assert list(distances.round(8)) == [0.9999995, 0.56844747, 1.38102567]


# 03 Binaries, flybys and escape ---------------------------------------------------------------------------------


def test_earth_moon_barycentre_and_month():
    """The Earth 4670.7 km from the barycentre; Kepler III 27.285 d (the observed sidereal month is 27.322 d)."""
    from orbits import Binary

    pair = Binary.from_elements("Earth", "Moon", a=384399 * u.km, e=0.0549)
    assert round(pair.star1.semi_major_axis.to_value(u.km), 1) == 4670.7
    assert round(pair.period.to_value(u.day), 3) == 27.285


def test_binary_star_period_and_speeds():
    """1 + 0.5 solar masses, a = 1 AU: 298.23 d; the lighter star twice as fast (m1 / m2 = 2; measured 0 apart)."""
    from orbits import Binary

    binary = Binary.from_elements(1 * u.solMass, 0.5 * u.solMass, a=1 * u.AU, e=0.5, nu=60 * u.deg)
    assert round(binary.period.to_value(u.day), 2) == 298.23
    assert abs(binary.star2.periapsis_speed / binary.star1.periapsis_speed - 2) <= 4.5e-16


@pytest.fixture(scope="module")
def binary_on_the_sky():
    from orbits import Binary

    return Binary.from_elements(1 * u.solMass, 0.5 * u.solMass, a=1 * u.AU, e=0.5, inc=60 * u.deg, raan=30 * u.deg,
                                argp=100 * u.deg, nu=60 * u.deg, com_v=[0, 0, 20] * u.km / u.s)


def test_sky_position_is_the_textbook_projection(binary_on_the_sky):
    """57.31 mas at position angle 199.69 deg from 10 pc; the textbook projection rho = r sqrt(cos^2(w + nu) +
    sin^2(w + nu) cos^2 i), tan(theta - Omega) = tan(w + nu) cos i agrees: measured 4.4e-16 in rho, 2.8e-14 deg."""
    rho, theta = binary_on_the_sky.sky_position()
    rho_mas = (rho / (10 * u.pc)).to_value(u.mas, u.dimensionless_angles())
    e, nu, omega, inc, node = 0.5, *np.radians([60, 100, 60, 30])
    r_au = (1 - e**2) / (1 + e * np.cos(nu))  # 1 AU at 10 pc is 100 mas
    rho_hand = 100 * r_au * np.hypot(np.cos(omega + nu), np.sin(omega + nu) * np.cos(inc))
    theta_hand = np.degrees(node + np.arctan2(np.sin(omega + nu) * np.cos(inc), np.cos(omega + nu))) % 360
    assert round(rho_mas, 2) == 57.31 and round(theta.to_value(u.deg), 2) == 199.69
    assert abs(rho_mas / rho_hand - 1) <= 3e-15
    assert abs(theta.to_value(u.deg) - theta_hand) <= 3e-13  # deg


def test_radial_velocity_amplitudes_and_mass_function(binary_on_the_sky):
    """K1 = 12.1595495 km/s, and by hand 2 pi a1 sin i / (P sqrt(1 - e^2)) with astropy's G (measured 2.2e-16
    apart); K2 / K1 = m1 / m2 = 2; f(M) = (m2 sin i)^3 / (m1 + m2)^2 (measured 0 apart)."""
    from astropy.constants import G

    seen = binary_on_the_sky
    k1, k2 = seen.rv_semi_amplitude1, seen.rv_semi_amplitude2
    e, inc = 0.5, np.radians(60)
    period = 2 * np.pi * np.sqrt((1 * u.AU) ** 3 / (G * 1.5 * u.solMass))
    k1_hand = 2 * np.pi * (1 / 3 * u.AU) * np.sin(inc) / (period * np.sqrt(1 - e**2))  # a1 = a m2 / (m1 + m2)
    assert abs(k1.to_value(u.km / u.s) - 12.15955) <= 1e-4
    assert abs((k1 / k1_hand).to_value(u.one) - 1) <= 2e-15
    assert abs(k2 / k1 - 2) <= 4.5e-16
    assert abs(seen.mass_function.to_value(u.solMass) / ((0.5 * np.sin(inc)) ** 3 / 1.5**2) - 1) <= 1e-15


def test_the_curve_gives_back_the_companion(binary_on_the_sky):
    """Star 1's P, K1 and e with i = 60 deg give back 0.5 solar masses (measured 5.6e-17 apart); sin i = 1 says at
    least 0.4169."""
    from orbits import SpectroscopicBinary

    seen = binary_on_the_sky
    back = SpectroscopicBinary.from_curve(seen.period, seen.rv_semi_amplitude1, 0.5, primary_mass=1 * u.solMass,
                                          inc=60 * u.deg)
    assert abs(back.companion_mass.to_value(u.solMass) - 0.5) <= 5e-16
    assert round(back.minimum_companion_mass.to_value(u.solMass), 4) == 0.4169


def test_51_pegasi_b_and_the_suns_reflex():
    """P = 4.2293 d, K = 59 m/s, e = 0 about one solar mass: m sin i = 0.4696 Jupiter masses, within the published
    0.47 +- 0.02 (Mayor & Queloz 1995, Nature 378, 355). Jupiter moves the Sun by 12.5 m/s (edge-on)."""
    from orbits import Binary, SpectroscopicBinary

    peg = SpectroscopicBinary.from_curve(4.2293 * u.day, 59 * u.m / u.s, 0.0, primary_mass=1 * u.solMass)
    m_sin_i = peg.minimum_companion_mass.to_value(u.jupiterMass)
    assert abs(m_sin_i - 0.47) <= 0.02
    assert round(m_sin_i, 4) == 0.4696
    sun = Binary.from_elements("Sun", "Jupiter", a=5.2026 * u.AU, e=0.0484, inc=90 * u.deg)
    assert round(sun.rv_semi_amplitude1.to_value(u.m / u.s), 1) == 12.5


def test_jupiter_flyby():
    """5.6 km/s aimed to pass 200,000 km from Jupiter: b = 1,286,818 km, 36.03 km/s at the closest pass, turned by
    144.66 deg."""
    from orbits import Flyby

    jupiter = Flyby.past("Jupiter", v_inf=5.6 * u.km / u.s, periapsis=200_000 * u.km)
    assert round(jupiter.impact_parameter.to_value(u.km)) == 1286818
    assert round(jupiter.periapsis_speed.to_value(u.km / u.s), 2) == 36.03
    assert round(jupiter.deflection_angle.to_value(u.deg), 2) == 144.66


def test_cosmic_velocities_geostationary_altitude_and_elongation():
    """The course's 7.9, 11.2 and 16.7 km/s are 7.904, 11.178 and 16.648 km/s; 35786.1 km; Venus 46.3 deg."""
    from orbits import CosmicVelocities, SynchronousOrbit, max_elongation

    v = CosmicVelocities.from_surface_gravity()
    speeds = (v.first_cosmic_velocity, v.second_cosmic_velocity, v.third_cosmic_velocity)
    assert [round(float(x.to_value(u.km / u.s)), 3) for x in speeds] == [7.904, 11.178, 16.648]
    assert round(SynchronousOrbit.of("Earth").altitude.to_value(u.km), 1) == 35786.1
    assert round(max_elongation(0.723 * u.AU, 1 * u.AU).to_value(u.deg), 1) == 46.3


# 04 Lagrange points and rings -----------------------------------------------------------------------------------


def test_earth_moon_collinear_points_and_their_e_folding_times():
    """L1 58,019 km and L2 64,515 km from the Moon; e-folding 1.48, 2.01 and 24.41 d at L1..L3 (against mpmath in
    tests/api/test_lagrange_rings.py); L4 and L5 stable (mu = 0.01215 < 0.03852)."""
    from orbits import RestrictedThreeBody

    em = RestrictedThreeBody.from_primaries("Earth", "Moon")
    assert list(em.distances_to_secondary[:2].to_value(u.km).round()) == [58019, 64515]
    assert list(em.e_folding_times[:3].to_value(u.day).round(2)) == [1.48, 2.01, 24.41]
    assert em.triangular_points_stable


def test_maxwells_ring_of_eight():
    """The threshold central mass of 8 bodies of 1e20 kg: 2.122610637695383e22 kg (beta_c = 212.26 = 0.41457 n**3,
    which tests/core/test_rings.py checks against a Cartesian linearisation); unstable at 0.8 of it, stable at
    1.25."""
    from orbits import Ring

    ring = Ring.from_masses(8, 1e20 * u.kg, 1e5 * u.km)
    assert abs(ring.central_mass_threshold.to_value(u.kg) / 2.122610637695383e22 - 1) <= 1e-12
    for factor in (0.8, 1.25):
        heavy = Ring.from_masses(8, 1e20 * u.kg, 1e5 * u.km, central_mass=factor * ring.central_mass_threshold)
        assert heavy.linearly_stable == (factor > 1)


# The integrations of notebook 04 are checked where their subject is tested:
# - the lagrange_L4_L5 and lagrange_unstable scenes pass: tests/validation/test_model_scenes.py
#   (test_lagrange_and_ring_scenes_agree_with_both_backends);
# - the particle leaving L1 at the eigenvalue rate (within 1.7e-3; measured 1.7e-4), the tadpole between 45-50 and
#   70-75 deg from the Moon, the horseshoe through L3 turning 10-16 deg from the Earth:
#   tests/api/test_rotating_frame_pictures.py;
# - a ring of six breaking up at 0.94-1.19 times the predicted time, with both integrators:
#   tests/validation/test_lagrange_rings_integration.py (test_rings_hold_their_shape_until_the_predicted_breakup).


# 05 The expanding universe --------------------------------------------------------------------------------------


def test_the_courses_einstein_de_sitter_age():
    """H = 0.5e-10 / yr: t = 2 / (3 H) = 1.3333e10 yr (measured 1.1e-16 apart), the course's 1.33e10 yr;
    H0 = 48.89 km/s/Mpc."""
    from orbits import Cosmology

    course = Cosmology.einstein_de_sitter(0.5e-10 / u.yr)
    assert abs(course.age().to_value(u.yr) / (4e10 / 3) - 1) <= 4e-16
    assert round(course.age().to_value(u.yr) / 1e10, 2) == 1.33
    assert round(course.hubble_constant.to_value(u.km / u.s / u.Mpc), 2) == 48.89


@pytest.fixture(scope="module")
def friedmann_models():
    from orbits import Cosmology

    H0 = 67.66 * u.km / u.s / u.Mpc
    return {"Einstein-de Sitter": Cosmology.einstein_de_sitter(H0),
            "open": Cosmology.from_densities(H0, Om0=0.3, Ol0=0.0),
            "flat": Cosmology.from_densities(H0, Om0=0.31, Ol0=0.69)}


def test_friedmann_ages_and_distances(friedmann_models):
    """H0 = 67.66 km/s/Mpc: ages 9.634, 11.688 and 13.805 Gyr; comoving distances to z = 1: 2596, 2892, 3398 Mpc."""
    ages = [round(model.age().to_value(u.Gyr), 3) for model in friedmann_models.values()]
    distances = [round(model.comoving_distance(1).to_value(u.Mpc)) for model in friedmann_models.values()]
    assert ages == [9.634, 11.688, 13.805] and distances == [2596, 2892, 3398]


def test_planck18_distances_agree_with_astropy():
    """D_L, D_A, m - M, V_C and lookback time at z = 0.1, 0.5, 1, 3 against astropy's FlatLambdaCDM with the same
    parameters (its own quadrature): measured 6.7e-15 relative at worst."""
    from astropy.cosmology import FlatLambdaCDM

    from orbits import Cosmology

    planck = Cosmology.planck18()
    reference = FlatLambdaCDM(67.66, 0.30966, Tcmb0=0)
    worst = 0.0
    for z in (0.1, 0.5, 1.0, 3.0):
        ours = [planck.luminosity_distance(z).to_value(u.Mpc), planck.angular_diameter_distance(z).to_value(u.Mpc),
                planck.distance_modulus(z).to_value(u.mag), planck.comoving_volume(z).to_value(u.Gpc**3),
                planck.lookback_time(z).to_value(u.Gyr)]
        theirs = [reference.luminosity_distance(z).to_value(u.Mpc),
                  reference.angular_diameter_distance(z).to_value(u.Mpc), reference.distmod(z).value,
                  reference.comoving_volume(z).to_value(u.Gpc**3), reference.lookback_time(z).to_value(u.Gyr)]
        worst = max(worst, *(abs(a / b - 1) for a, b in zip(ours, theirs)))
    assert worst < 1e-12


def test_planck18_is_fainter_than_einstein_de_sitter_at_z_1(friedmann_models):
    """m - M at z = 1: Planck 2018 minus Einstein-de Sitter (same H0) = 0.585 mag."""
    from orbits import Cosmology

    gap = (Cosmology.planck18().distance_modulus(1) - friedmann_models["Einstein-de Sitter"].distance_modulus(1))
    assert round(gap.to_value(u.mag), 2) == 0.59


def test_closed_universe_turnaround_and_crunch_are_the_cycloids():
    """Om = 2, no Lambda: turnaround pi Om / (2 H0 (Om - 1)**1.5) = 45.4009 Gyr and the crunch at twice that
    (each measured 2.2e-16 apart)."""
    from orbits import Cosmology

    H0 = 67.66 * u.km / u.s / u.Mpc
    closed = Cosmology.from_densities(H0, Om0=2.0, Ol0=0.0)
    turnaround = np.pi * 2.0 / (2 * H0 * (2.0 - 1) ** 1.5)
    assert abs((closed.turnaround_time / turnaround).to_value(u.one) - 1) < 1e-15
    assert abs((closed.big_crunch_time / (2 * turnaround)).to_value(u.one) - 1) < 1e-15


# The expanding_universe scene passing with both integrators: tests/validation/test_model_scenes.py
# (test_expanding_universe_agrees_with_both_backends).


# 06 Validation --------------------------------------------------------------------------------------------------


@pytest.fixture(scope="module")
def four_scenes():
    from orbits.validate import scene, validate

    return validate([scene.load(name) for name in ("circular", "eccentric", "near_parabolic", "flyby")])


def test_four_builtin_scenes_pass_within_3e_10(four_scenes):
    """Every check passes; the worst position error of the four is 3.0e-11 (eccentric, 100 orbits, heyoka)."""
    assert four_scenes.passed
    worst = max(max(c.errors.values()) for s in four_scenes.scenes for c in s.checks
                if c.quantity.startswith("positions"))
    assert worst <= 3e-10


def test_the_residual_picture_of_the_four_scenes(four_scenes):
    """Left: the two 100-orbit scenes x two integrators on log axes, each ending at 100 periods; right: the two
    passages x two integrators over the fraction of the run; both legends below their panels, off the data."""
    from orbits.plot import validation_residuals

    fig, (whole, passages) = validation_residuals(four_scenes)
    assert whole.get_xscale() == "log" and whole.get_yscale() == "log" and len(whole.get_lines()) == 4
    assert all(abs(line.get_xdata()[-1] - 100) < 1e-12 for line in whole.get_lines())
    assert len(passages.get_lines()) == 4 and passages.get_xlim() == (0.0, 1.0)
    fig.canvas.draw()
    for ax in (whole, passages):
        assert ax.get_legend().get_window_extent().y1 <= ax.get_window_extent().y0


def test_the_track_picture_names_each_scene(four_scenes):
    from orbits.plot import validation_tracks

    _, panels = validation_tracks(four_scenes)
    assert [ax.get_title().split("\n")[0] for ax in panels] == ["circular", "eccentric", "near_parabolic", "flyby"]


# 07 Collisions, rotation, uniform gravity and oscillations ------------------------------------------------------


def test_energy_handed_over_in_a_collision():
    """Elastic 4 r / (1 + r)**2: 8/9 at r = 2 and 1 at r = 1 (each measured 0 apart); restitution 0.5 keeps a
    quarter of the internal kinetic energy."""
    from orbits import Collision, energy_transfer

    assert math.isclose(energy_transfer(2).value, 8 / 9, rel_tol=1e-15)
    assert math.isclose(energy_transfer(1).value, 1.0, rel_tol=1e-15)
    hit = Collision.head_on(2 * u.kg, 3 * u.m / u.s, 1 * u.kg, -1 * u.m / u.s, restitution=0.5)
    assert math.isclose(hit.internal_kinetic_energy_after.value, 0.25 * hit.internal_kinetic_energy_before.value)


def test_the_slingshot_as_a_collision():
    """Jupiter at 13.07 km/s met head-on at 10 km/s: v' = 2 U - v = 36.14 km/s."""
    from orbits import slingshot

    assert math.isclose(slingshot(13.07 * u.km / u.s, -10 * u.km / u.s).to_value(u.km / u.s), 36.14, rel_tol=1e-12)


def test_a_rotation_is_one_turn_about_one_axis():
    """The principal-angle rotation rebuilt from its axis and angle: measured 1.1e-16 apart."""
    from orbits import Rotation

    turn = Rotation.from_principal_angles(10 * u.deg, -20 * u.deg, 30 * u.deg)
    again = Rotation.from_axis_angle(turn.axis, turn.angle)
    assert np.max(np.abs(again.matrix - turn.matrix)) < 1e-15


def test_rolling_race_accelerations():
    """a = g sin(30 deg) / (1 + k): 5/7, 2/3 and 1/2 of it for the ball, cylinder and hoop."""
    from orbits import RigidBody

    bodies = {"ball": RigidBody.solid_sphere(1 * u.kg, 0.1 * u.m),
              "cylinder": RigidBody.solid_cylinder(1 * u.kg, 0.1 * u.m, 0.3 * u.m),
              "hoop": RigidBody.thin_hoop(1 * u.kg, 0.1 * u.m)}
    for name, share in (("ball", 5 / 7), ("cylinder", 2 / 3), ("hoop", 1 / 2)):
        rolling = bodies[name].rolling_down(30 * u.deg)
        assert math.isclose(rolling.acceleration.value, share * 9.80665 * 0.5, rel_tol=1e-14)


def test_effective_gravity_and_a_thrown_ball():
    """omega**2 R = 0.0339 m/s2 less at the equator than at the pole; the ball at 20 m/s and 45 deg lands 40.789 m
    away without drag and 30.726 m with quadratic drag (v_t = 30 m/s)."""
    from orbits import EffectiveGravity, Projectile

    equator, pole = EffectiveGravity.on_earth(0 * u.deg), EffectiveGravity.on_earth(90 * u.deg)
    assert round((pole.downward - equator.downward).value, 4) == 0.0339
    ball = Projectile.launch(20 * u.m / u.s, 45 * u.deg)
    assert round(ball.range.value, 3) == 40.789
    assert round(ball.with_quadratic_drag(30 * u.m / u.s).range.value, 3) == 30.726


def test_pendulum_at_170_degrees():
    """T / T0 = 4 K(sin^2(85 deg)) / (2 pi) = 2.439363."""
    from orbits import Pendulum

    assert round(Pendulum.simple(1 * u.m, 170 * u.deg).period_ratio.value, 6) == 2.439363


def test_damping_regimes_and_the_vertical_circle():
    """b = 0.4, 2 and 5 / s at omega0 = 1 rad/s: under-, critically and over-damped. A string at u = sqrt(5 g R)
    loops with N = 0 at the top (measured 4e-15 N); at u = 2 sqrt(g R) it slackens between 90 and 180 deg (131.8)."""
    from orbits import DampedOscillator, VerticalCircle

    regimes = [DampedOscillator.of(1 / u.s, b / u.s, 1 * u.m).regime for b in (0.4, 2.0, 5.0)]
    assert regimes == ["underdamped", "critically damped", "overdamped"]
    g, radius = 9.80665, 1.0
    top = VerticalCircle.of(radius * u.m, math.sqrt(5 * g * radius) * u.m / u.s, mass=1 * u.kg)
    assert top.regime == "loops" and abs(top.normal_force_at_top.value) < 1e-13
    slack = VerticalCircle.of(radius * u.m, 2 * math.sqrt(g * radius) * u.m / u.s)
    assert math.pi / 2 < slack.leaving_angle.value < math.pi


# 08 Rockets, manoeuvres and Lambert's problem -------------------------------------------------------------------


def test_rocket_equation():
    """100 t -> 40 t at Isp = 300 s: delta-v = v_e ln(m0 / mf) = 2.695723 km/s (measured 0 apart)."""
    from orbits import Rocket

    stage = Rocket.single_stage(100 * u.t, 40 * u.t, isp=300 * u.s, thrust=2 * u.MN)
    v_e = (300 * u.s * 9.80665 * u.m / u.s**2).to_value(u.km / u.s)
    assert np.isclose(stage.delta_v.to_value(u.km / u.s), v_e * np.log(100 / 40), rtol=1e-15)


def test_hohmann_and_bi_elliptic():
    """6678 -> 42164 km: 3.893 km/s in 5.275 h. Through 60 r2 from 7000 km: Hohmann wins at a radius ratio of 10
    (by 117.7 m/s), the bi-elliptic route at 20 (by 204.0 m/s)."""
    from orbits import BiElliptic, Hohmann

    leo_geo = Hohmann.between("Earth", 6678 * u.km, 42164 * u.km)
    assert round(leo_geo.delta_v.to_value(u.km / u.s), 3) == 3.893
    assert round(leo_geo.transfer_time.to_value(u.h), 3) == 5.275
    savings = [BiElliptic.between("Earth", 7000 * u.km, r * 7000 * u.km, 60 * r * 7000 * u.km).saving.value
               for r in (10, 15, 20)]
    assert savings[0] < 0 < savings[2]


def test_third_cosmic_velocity_and_a_lambert_arc():
    """Patched conics from the surface: 16.648 km/s. 1 AU -> 1.5 AU a quarter turn apart in 200 d: e = 0.4819."""
    from orbits import Departure, lambert

    assert round(Departure.third_cosmic().departure_speed.to_value(u.km / u.s), 3) == 16.648
    transfer = lambert([1, 0, 0] * u.AU, [0, 1.5, 0] * u.AU, 200 * u.day, "Sun")
    assert round(float(transfer.eccentricity), 4) == 0.4819


def test_the_2026_mars_window_on_a_5_day_grid():
    """NASA/TM-2010-216764 (Burke, Falck and McGuire 2010), 2026 Type II: least C3 9.144 km2/s2; this 5-day grid
    from the Earth-Moon barycentre finds 9.1482 (a 1-day grid 9.1431, tests/api/test_porkchop.py)."""
    from orbits import Porkchop

    window = Porkchop.between("EMB", "Mars", launch=("2026-09-01", "2027-01-31"),
                              arrival=("2027-06-01", "2028-03-01"), step=5 * u.day)
    assert abs(window.minimum_c3.c3.to_value(u.km**2 / u.s**2) / 9.144 - 1) < 2e-3
