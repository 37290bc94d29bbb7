"""What an observer measures of a binary (issue 18): the apparent orbit on the sky, the radial-velocity curves,
and back from a measured curve to the mass function and the companion's mass.

The round trip runs through heyoka: the pair is integrated in the sky frame (x north, y east, z away from the
observer), star 1's radial velocity is MEASURED on the trajectory (its extrema are events where dv_z / dt = 0,
the period the time between successive maxima, the eccentricity from the extreme separations, events where
r . v = 0), and only those numbers go into SpectroscopicBinary. Code units: GMs in m3/s2, so lengths are metres
and times seconds.
"""

import math

import astropy.units as u
import numpy as np
import pytest

from orbits import OrbitDomainError
from orbits._common.constants import G
from orbits.encounters.binary import Binary, SpectroscopicBinary

hy = pytest.importorskip("heyoka")

GM = u.m**3 / u.s**2
GM1, GM2 = 1.0, 0.3
INC = 1.0  # rad, 57.3 deg


@pytest.fixture(scope="module")
def pair():
    return Binary.from_elements(GM1 * GM, GM2 * GM, a=1 * u.m, e=0.4, inc=INC * u.rad, raan=0.7 * u.rad,
                                argp=2.0 * u.rad, nu=0.5 * u.rad, com_v=[1e-3, -2e-3, 0.05] * u.m / u.s)


def two_body(gm1, gm2):
    """heyoka's two-body equations (G m = gm) in 12 variables, r1, r2, v1, v2."""
    x1, y1, z1, x2, y2, z2, u1, v1, w1, u2, v2, w2 = hy.make_vars(*"x1 y1 z1 x2 y2 z2 u1 v1 w1 u2 v2 w2".split())
    dx, dy, dz = x2 - x1, y2 - y1, z2 - z1
    inv_r3 = (dx * dx + dy * dy + dz * dz) ** -1.5
    equations = [(x1, u1), (y1, v1), (z1, w1), (x2, u2), (y2, v2), (z2, w2),
                 (u1, gm2 * dx * inv_r3), (v1, gm2 * dy * inv_r3), (w1, gm2 * dz * inv_r3),
                 (u2, -gm1 * dx * inv_r3), (v2, -gm1 * dy * inv_r3), (w2, -gm1 * dz * inv_r3)]
    return equations, gm2 * dz * inv_r3, dx * (u2 - u1) + dy * (v2 - v1) + dz * (w2 - w1)


def initial_state(binary):
    r1, v1, r2, v2 = (x.si.value for x in binary.states)
    return list(np.concatenate([r1, r2, v1, v2]))


def states_at(binary, times):
    """heyoka's states (len(times), 12) of the pair at `times` (s, increasing, > 0) after its epoch."""
    equations, _, _ = two_body(GM1, GM2)
    ta = hy.taylor_adaptive(equations, initial_state(binary), high_accuracy=True)
    _, _, _, _, _, states = ta.propagate_grid(np.concatenate([[0.0], times]))
    return states[1:]


@pytest.fixture(scope="module")
def measured(pair):
    """Events over three periods: star 1's radial-velocity maxima and minima, and the extreme separations."""
    equations, rv_rate, radial = two_body(GM1, GM2)
    found = {"rv max": [], "rv min": [], "apsis": []}
    events = [
        hy.nt_event(rv_rate, lambda ta, t, d: found["rv max"].append(t), direction=hy.event_direction.negative),
        hy.nt_event(rv_rate, lambda ta, t, d: found["rv min"].append(t), direction=hy.event_direction.positive),
        hy.nt_event(radial, lambda ta, t, d: found["apsis"].append(t)),
    ]
    ta = hy.taylor_adaptive(equations, initial_state(pair), high_accuracy=True, nt_events=events)
    ta.propagate_until(3 * pair.period.to_value(u.s))
    times = {name: np.array(t) for name, t in found.items()}
    everything = np.sort(np.concatenate(list(times.values())))
    states = states_at(pair, everything)
    at = {t: s for t, s in zip(everything, states)}
    rv = {name: np.array([at[t][8] for t in times[name]]) for name in ("rv max", "rv min")}
    separations = np.array([np.linalg.norm(at[t][3:6] - at[t][0:3]) for t in times["apsis"]])
    return times, rv, separations


def test_measured_radial_velocity_gives_back_the_mass_function_and_the_companion(pair, measured):
    times, rv, separations = measured
    period = np.mean(np.diff(times["rv max"]))
    k1 = (rv["rv max"].mean() - rv["rv min"].mean()) / 2
    q, big_q = separations.min(), separations.max()
    e = (big_q - q) / (big_q + q)
    assert period == pytest.approx(pair.period.to_value(u.s), rel=1e-14)  # measured 1.0e-15
    assert k1 == pytest.approx(pair.rv_semi_amplitude1.to_value(u.m / u.s), rel=2e-15)  # measured 2.2e-16
    assert e == pytest.approx(0.4, rel=1e-14)  # measured 4.4e-16
    spectrum = SpectroscopicBinary.from_curve(period * u.s, k1 * u.m / u.s, e, primary_mass=GM1 * GM, inc=INC * u.rad)
    truth = (GM2 * math.sin(INC)) ** 3 / (GM1 + GM2) ** 2  # G f(M) = (G m2 sin i)**3 / (G m1 + G m2)**2
    assert spectrum.mass_function.to_value(u.kg) * G == pytest.approx(truth, rel=1e-14)  # measured 1.2e-15
    assert pair.mass_function.to_value(u.kg) * G == pytest.approx(truth, rel=1e-15)
    assert spectrum.companion_mass.to_value(u.kg) * G == pytest.approx(GM2, rel=1e-14)  # measured 7.8e-16
    minimum = spectrum.minimum_companion_mass.to_value(u.kg) * G
    assert minimum < GM2 * 0.9  # sin i = 0.84: the bound lies below the truth (0.818 m2)
    gm_function = spectrum.mass_function.to_value(u.kg) * G
    assert minimum**3 == pytest.approx(gm_function * (GM1 + minimum) ** 2, rel=2e-15)  # measured 2.2e-16
    # the systemic velocity: the mean of the extremes is gamma + K e cos(omega_1), omega_1 = omega + pi
    gamma = (rv["rv max"].mean() + rv["rv min"].mean()) / 2 - k1 * 0.4 * math.cos(2.0 + math.pi)
    assert gamma == pytest.approx(0.05, rel=1e-14)  # measured 1.7e-15


def test_radial_velocities_follow_the_closed_form_and_the_integration(pair):
    period = pair.period.to_value(u.s)
    dt = np.array([0.07, 0.31, 0.55, 0.83, 1.12, 1.49, 1.96]) * period
    states = states_at(pair, dt)
    v1, v2 = pair.radial_velocities(dt * u.s)
    k1 = pair.rv_semi_amplitude1.to_value(u.m / u.s)
    np.testing.assert_allclose(v1.to_value(u.m / u.s), states[:, 8], rtol=0, atol=3e-13 * k1)  # measured 3.8e-14
    k2 = pair.rv_semi_amplitude2.to_value(u.m / u.s)
    np.testing.assert_allclose(v2.to_value(u.m / u.s), states[:, 11], rtol=0, atol=3e-13 * k2)  # measured 3.7e-14
    # gamma + K_i (cos(omega_i + nu) + e cos omega_i), star 1's omega = star 2's + pi
    from orbits.core.encounters.binary import radial_velocity

    nu = np.array([float(pair.relative.at(t).nu) for t in dt * u.s])
    k2 = pair.rv_semi_amplitude2.to_value(u.m / u.s)
    closed1 = 0.05 + radial_velocity(k1, 0.4, 2.0 + np.pi, nu)
    closed2 = 0.05 + radial_velocity(k2, 0.4, 2.0, nu)
    np.testing.assert_allclose(v1.to_value(u.m / u.s), closed1, rtol=0, atol=1e-14 * k1)  # measured 1.4e-15
    np.testing.assert_allclose(v2.to_value(u.m / u.s), closed2, rtol=0, atol=1e-14 * k2)
    assert k1 / k2 == pytest.approx(GM2 / GM1, rel=1e-15)


def test_sky_position_is_the_projected_relative_orbit(pair):
    """Separation and position angle from the integrated trajectory; the position angle grows for i < 90 deg."""
    period = pair.period.to_value(u.s)
    dt = np.array([0.11, 0.29, 0.47, 0.62, 0.88, 0.97]) * period
    states = states_at(pair, dt)
    north, east = states[:, 3] - states[:, 0], states[:, 4] - states[:, 1]
    rho, theta = pair.sky_position(dt * u.s)
    np.testing.assert_allclose(rho.to_value(u.m), np.hypot(north, east), rtol=1e-13)  # measured 1.1e-14
    np.testing.assert_allclose(theta.to_value(u.rad), np.mod(np.arctan2(east, north), 2 * np.pi), rtol=1e-13)  # 7.3e-15
    # at the ascending node (nu = -omega) star 2 sits at position angle Omega and recedes
    t_node = (pair.relative.time_since_periapsis.to_value(u.s) * -1 + _time_from_periapsis(pair, -2.0)) % period
    _, pa = pair.sky_position(t_node * u.s)
    assert pa.to_value(u.rad) == pytest.approx(0.7, rel=1e-12)
    _, v2 = pair.radial_velocities(t_node * u.s)
    assert v2.to_value(u.m / u.s) > 0.05
    later = pair.sky_position(np.linspace(0, 0.9, 50) * period * u.s)[1].to_value(u.rad)
    assert np.all(np.mod(np.diff(later), 2 * np.pi) < np.pi)  # counterclockwise on the sky (north through east)


def _time_from_periapsis(pair, nu):
    """t - T_p (s) at true anomaly nu (rad) of the relative orbit: Kepler's equation, written out here."""
    e = float(pair.relative.e)
    big_e = 2 * math.atan(math.sqrt((1 - e) / (1 + e)) * math.tan(nu / 2))
    return (big_e - e * math.sin(big_e)) / pair.mean_motion.to_value(u.rad / u.s)


def test_the_minimum_mass_of_51_pegasi_b_and_the_suns_reflex_from_jupiter():
    """51 Pegasi b (Mayor & Queloz 1995, Nature 378, 355): P = 4.2293 d, K = 59 m/s, e = 0 about a 1 solMass star
    give m sin i = 0.47 +- 0.02 Jupiter masses. Back through a Binary seen edge-on, K is 59 m/s again."""
    spectrum = SpectroscopicBinary.from_curve(4.2293 * u.day, 59 * u.m / u.s, 0.0, primary_mass=1 * u.solMass)
    assert spectrum.minimum_companion_mass.to_value(u.jupiterMass) == pytest.approx(0.47, abs=0.02)  # 0.4696
    back = Binary.from_elements(1 * u.solMass, spectrum.minimum_companion_mass, period=4.2293 * u.day,
                                inc=90 * u.deg)
    assert back.rv_semi_amplitude1.to_value(u.m / u.s) == pytest.approx(59, rel=1e-15)  # measured 1.2e-16
    sun_jupiter = Binary.from_elements("Sun", "Jupiter", a=5.2026 * u.AU, e=0.0484, inc=90 * u.deg)
    assert sun_jupiter.rv_semi_amplitude1.to_value(u.m / u.s) == pytest.approx(12.5, abs=0.1)  # the Sun's wobble
    found = SpectroscopicBinary.from_curve(sun_jupiter.period, sun_jupiter.rv_semi_amplitude1, 0.0484,
                                           primary_mass="Sun").minimum_companion_mass
    assert found.to_value(u.jupiterMass) == pytest.approx(1.0, rel=2e-15)  # measured 2.2e-16


def test_the_mass_function_is_the_same_from_the_masses_and_from_the_curve():
    many = Binary.from_elements(1 * u.solMass, [0.001, 0.1, 1.0, 10.0] * u.solMass, a=0.3 * u.AU, e=0.7,
                                inc=30 * u.deg)
    spectrum = SpectroscopicBinary.from_curve(many.period, many.rv_semi_amplitude1, 0.7)
    np.testing.assert_allclose(spectrum.mass_function.to_value(u.kg), many.mass_function.to_value(u.kg),
                               rtol=1e-14)  # measured 1.1e-15
    assert set(spectrum.quantities()) == {"mass_function", "projected_semi_major_axis"}  # no masses given


@pytest.mark.parametrize("kwargs, fragment", [
    (dict(period=-1 * u.day, semi_amplitude=1 * u.km / u.s), "period P = -86400.0 s"),
    (dict(period=1 * u.day, semi_amplitude=1 * u.km), "semi-amplitude K"),
    (dict(period=1 * u.day, semi_amplitude=1 * u.km / u.s, e=1.0), "needs a bound orbit"),
    (dict(period=1 * u.day, semi_amplitude=1 * u.km / u.s, inc=0 * u.deg), "inclination i = 0.0 deg is outside"),
])
def test_bad_spectroscopic_input_is_one_clear_error(kwargs, fragment):
    with pytest.raises((OrbitDomainError, u.UnitsError), match=fragment):
        SpectroscopicBinary.from_curve(**kwargs)


def test_companion_mass_needs_the_primary_and_the_inclination():
    spectrum = SpectroscopicBinary.from_curve(1 * u.day, 1 * u.km / u.s)
    with pytest.raises(OrbitDomainError, match="needs the primary's mass"):
        _ = spectrum.minimum_companion_mass
    with pytest.raises(OrbitDomainError, match="needs the inclination"):
        _ = SpectroscopicBinary.from_curve(1 * u.day, 1 * u.km / u.s, primary_mass="Sun").companion_mass
