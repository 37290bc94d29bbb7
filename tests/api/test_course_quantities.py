"""The course's quantities a user can ask for, each against an independent reference: U, K and the speed at any r
on an orbit, |A| and A . r of the Laplace-Runge-Lenz vector, the area swept between two times, the accelerations of
the damped and driven oscillators, the projectile and the vertical circle, and each body's kinetic energy before
and after a collision."""

import math

import astropy.units as u
import mpmath
import numpy as np
import pytest
from scipy.integrate import solve_ivp

from orbits import (
    BODIES,
    Collision,
    DampedOscillator,
    DrivenOscillator,
    Orbit,
    OrbitDomainError,
    Projectile,
    VerticalCircle,
    energy_transfer,
)

KG = 1000 * u.kg


def derivative(f, t, h=1e-3):
    """f'(t) by the five-point stencil: truncation ~h**4 f^(5) / 30, plus the rounding of f over h."""
    return (8 * (f(t + h) - f(t - h)) - (f(t + 2 * h) - f(t - 2 * h))) / (12 * h)


@pytest.mark.parametrize("e, nu", [(0.1, 60.0), (0.7, -130.0), (1.0, 90.0), (2.5, 45.0)])
def test_energies_and_speed_at_any_r_are_those_of_the_state_there(e, nu):
    """U(r), K(r) and v(r) against the orbit rebuilt at the true anomaly where |r| = r, whose U, K and |v| come from
    its state vectors (measured within 1.3e-15)."""
    orbit = Orbit.from_elements("Earth", q=8000 * u.km, e=e, mass=KG)
    there = Orbit.from_elements("Earth", q=8000 * u.km, e=e, nu=nu * u.deg, mass=KG)
    r = there.radius
    assert orbit.potential_energy_at(r).value == pytest.approx(there.potential_energy.value, rel=2e-15)
    assert orbit.kinetic_energy_at(r).value == pytest.approx(there.kinetic_energy.value, rel=1e-14)
    assert orbit.speed_at(r).value == pytest.approx(there.speed.value, rel=1e-14)
    if e < 1:
        total = orbit.potential_energy_at(r) + orbit.kinetic_energy_at(r)
        assert total.value == pytest.approx(orbit.energy.value, rel=1e-14)


def test_energies_at_r_need_the_mass_and_a_reachable_r():
    orbit = Orbit.from_elements("Earth", a=8000 * u.km, e=0.1)
    with pytest.raises(OrbitDomainError, match="needs the orbiting body's mass"):
        orbit.potential_energy_at(7500 * u.km)
    heavy = Orbit.from_elements("Earth", a=8000 * u.km, e=0.1, mass=KG)
    with pytest.raises(OrbitDomainError, match=r"distance r = 9000 km is outside \[7200 km, 8800 km\]"):
        heavy.kinetic_energy_at(9000 * u.km)  # within 2a, where vis-viva still gives a number, but past Q
    with pytest.raises(OrbitDomainError, match="from the periapsis to the apoapsis"):
        heavy.speed_at(7000 * u.km)
    assert heavy.speed_at(8800 * u.km) == heavy.apoapsis_speed  # the apsides are reached


@pytest.mark.parametrize("e, nu", [(0.0, 10.0), (0.3, 75.0), (0.9, 170.0), (1.8, -60.0)])
def test_laplace_runge_lenz_length_and_projection_on_r(e, nu):
    """|A| = m k e and A . r = L**2 - m k r against the vector A = p x L - m k r_hat built from the state vectors
    (measured within 4e-15 of |A| r)."""
    orbit = Orbit.from_elements("Earth", q=7000 * u.km, e=e, inc=30 * u.deg, nu=nu * u.deg, mass=KG)
    vector = orbit.laplace_runge_lenz.value
    magnitude = np.linalg.norm(vector)
    along = vector @ orbit.r.to_value(u.m)
    scale_a = KG.value**2 * BODIES["Earth"].gm  # m**2 mu: e_vec of a circle from the state is ~1e-16, not 0
    assert abs(orbit.laplace_runge_lenz_magnitude.value - magnitude) < 4e-15 * scale_a
    scale = orbit.laplace_runge_lenz_magnitude.value * orbit.radius.value + orbit.angular_momentum.value ** 2
    assert abs(orbit.laplace_runge_lenz_along_r.value - along) < 1e-14 * scale
    assert {"laplace_runge_lenz_magnitude", "laplace_runge_lenz_along_r"} <= set(orbit.quantities())
    assert "laplace_runge_lenz_magnitude" not in Orbit.from_elements("Earth", q=7000 * u.km, e=e).quantities()


@pytest.mark.parametrize("e", [0.0, 0.6, 1.0, 1.5])
def test_area_swept_is_the_integral_of_r2_dnu_over_2(e):
    """A(t1, t2) = h (t2 - t1) / 2 against mpmath's quadrature of r**2 / 2 over the true anomaly between the
    propagated positions (measured within 4e-15), and pi a b over a whole period."""
    orbit = Orbit.from_elements("Earth", q=7000 * u.km, e=e, nu=-20 * u.deg)  # periapsis on +x, in the xy plane
    t1, t2 = 300 * u.s, 2400 * u.s
    nus = np.unwrap([np.arctan2(*orbit.propagate(t)[0].value[1::-1]) for t in (t1, t2)])  # polar angles
    p = orbit.semilatus_rectum.value
    quadrature = mpmath.quad(lambda nu: (p / (1 + e * mpmath.cos(nu))) ** 2 / 2, nus)
    assert orbit.area_swept(t1, t2).value == pytest.approx(float(quadrature), rel=1e-13)
    assert orbit.area_swept(t2, t1).value == -orbit.area_swept(t1, t2).value
    if e < 1:
        whole = orbit.area_swept(0 * u.s, orbit.period)
        ab = orbit.semi_major_axis.value * orbit.semi_minor_axis.value
        assert whole.value == pytest.approx(math.pi * ab, rel=1e-15)


def test_damped_oscillator_acceleration_is_the_derivative_of_its_velocity():
    """x''(t) against the numerical derivative of the closed-form velocity, in every regime (measured within
    2.7e-11 m/s2, the stencil's rounding)."""
    for b in (0.3, 2.0, 5.0):  # under, critically and over damped at omega0 = 1
        spring = DampedOscillator.of(1 * u.rad / u.s, b / u.s, 0.5 * u.m, 0.2 * u.m / u.s)
        for t in (0.0, 0.7, 3.0):
            numeric = derivative(lambda s, spring=spring: float(spring.velocity_at(s * u.s).value), t)
            assert spring.acceleration_at(t * u.s).value == pytest.approx(numeric, abs=3e-10)
        assert spring.initial_acceleration.value == pytest.approx(spring.acceleration_at(0 * u.s).value, rel=1e-15)
        assert "initial_acceleration" in spring.quantities()


def test_driven_oscillator_acceleration_satisfies_the_equation_of_motion():
    drive = DrivenOscillator.of(2 * u.rad / u.s, 0.3 / u.s, 1.5 * u.m / u.s**2, 1.7 * u.rad / u.s)
    t = np.linspace(0, 10, 7) * u.s
    left = (drive.acceleration_at(t) + 0.3 / u.s * drive.velocity_at(t) + (2 / u.s) ** 2 * drive.position_at(t))
    assert np.allclose(left.to_value(u.m / u.s**2), 1.5 * np.cos(1.7 * t.value), rtol=0, atol=2e-15)
    assert drive.acceleration_amplitude.value == pytest.approx(1.7**2 * drive.amplitude.value, rel=1e-15)


def test_projectile_accelerations_against_the_velocity_and_an_integration():
    """No drag: (0, -g). Linear drag: the derivative of the closed-form velocity. Quadratic drag: the velocity of a
    scipy integration of the equations of motion, differentiated at launch and landing."""
    plain = Projectile.launch(20 * u.m / u.s, 45 * u.deg)
    a_x, a_y = plain.acceleration_at([0.5, 1.5] * u.s)
    assert np.all(a_x.value == 0) and np.all(a_y.value == -9.80665)
    assert plain.launch_acceleration.value == plain.landing_acceleration.value == 9.80665
    dragged = plain.with_linear_drag(0.2 / u.s)
    for t in (0.3, 1.2):
        for k in range(2):
            numeric = derivative(lambda s, k=k: float(dragged.velocity_at(s * u.s)[k].value), t)
            assert dragged.acceleration_at(t * u.s)[k].value == pytest.approx(numeric, abs=1.2e-11)  # measured 1.2e-12
    ball = Projectile.launch(30 * u.m / u.s, 40 * u.deg, 2 * u.m).with_quadratic_drag(25 * u.m / u.s)
    g, vt = 9.80665, 25.0

    def motion(t, state):
        speed = math.hypot(state[2], state[3])
        return [state[2], state[3], -g / vt**2 * speed * state[2], -g - g / vt**2 * speed * state[3]]

    v0 = [30 * math.cos(math.radians(40)), 30 * math.sin(math.radians(40))]
    flight = ball.time_of_flight.value
    track = solve_ivp(motion, (0, flight), [0, 2, *v0], rtol=1e-12, atol=1e-12, dense_output=True)
    h = 1e-4
    for when, step, expected in ((0.0, h, ball.launch_acceleration), (flight, -h, ball.landing_acceleration)):
        v0, v1, v2 = (track.sol(when + k * step)[2:] for k in range(3))
        dv = (-3 * v0 + 4 * v1 - v2) / (2 * step)  # one-sided, second order
        assert np.linalg.norm(dv) == pytest.approx(expected.value, rel=1e-7)
    assert {"launch_acceleration", "landing_acceleration"} <= set(ball.quantities())


def test_vertical_circle_accelerations_against_an_integration_of_the_swing():
    """theta'' = -(g / R) sin(theta) integrated by scipy: R theta'**2 is the centripetal and R theta'' the tangential
    acceleration (measured within 1e-11); at the bottom u**2 / R, at the top (u**2 - 4 g R) / R."""
    circle = VerticalCircle.of(1.5 * u.m, 9 * u.m / u.s)
    g, radius = 9.80665, 1.5
    swing = solve_ivp(lambda t, y: [y[1], -g / radius * math.sin(y[0])], (0, 0.4), [0.0, 9 / radius],
                      rtol=1e-13, atol=1e-13)
    theta, rate = swing.y[0, -1], swing.y[1, -1]
    centripetal, tangential = circle.acceleration_at(theta * u.rad)
    assert centripetal.value == pytest.approx(radius * rate**2, rel=1e-10)
    assert tangential.value == pytest.approx(-g * math.sin(theta), rel=1e-15)
    assert circle.acceleration_at_bottom.value == 81 / 1.5
    assert circle.acceleration_at_top.value == pytest.approx((81 - 4 * g * radius) / radius, rel=1e-14)
    assert {"acceleration_at_bottom", "acceleration_at_top"} <= set(circle.quantities())
    low = VerticalCircle.of(1.5 * u.m, 3 * u.m / u.s)
    assert "acceleration_at_top" not in low.quantities()


@pytest.mark.parametrize("ratio, e", [(0.5, 1.0), (3.0, 1.0), (2.0, 0.4)])
def test_each_bodys_kinetic_energy_before_and_after_a_collision(ratio, e):
    """Body 2 at rest: K2' / K1 is energy_transfer(m1 / m2, e), (1 + e)**2 r / (1 + r)**2 (IX); the shares add up
    to the totals, and K1 + K2 - K1' - K2' is the energy lost."""
    hit = Collision.head_on(ratio * u.kg, 4 * u.m / u.s, 1 * u.kg, 0 * u.m / u.s, restitution=e)
    assert hit.kinetic_energy2_before.value == 0
    share = hit.kinetic_energy2_after / hit.kinetic_energy1_before
    assert share.value == pytest.approx(energy_transfer(ratio, e).value, rel=1e-15)
    assert (hit.kinetic_energy1_before + hit.kinetic_energy2_before).value == hit.kinetic_energy_before.value
    after = hit.kinetic_energy1_after + hit.kinetic_energy2_after
    assert after.value == pytest.approx(hit.kinetic_energy_after.value, rel=1e-15)
    lost = hit.kinetic_energy_before - after
    assert lost.value == pytest.approx(hit.energy_lost.value, rel=1e-13, abs=1e-15)
    assert {"kinetic_energy1_after", "kinetic_energy2_after"} <= set(hit.quantities())
    assert BODIES["Earth"].gm > 0  # the catalogue is loaded alongside (the package's lazy facade)
