"""Uniform effective gravity (notes XX): effective gravity, the conical pendulum, projectiles with and without drag.
References: identities, mpmath at 40 digits, and the errata (heyoka integrations: tests/validation/)."""

import math

import mpmath
import numpy as np
import pytest

from orbits.core.errors import OrbitDomainError
from orbits.core.mechanics import projectile, rotation

G0 = 9.80665


@pytest.mark.parametrize("degrees", [0.0, 20.0, 45.0, 70.0, 90.0, -35.0])
def test_effective_gravity_is_gravity_plus_the_centrifugal_acceleration(degrees):
    """ERRATA #28: projecting -g r_hat - omega x (omega x r) on local (toward equator, down) axes gives
    (omega**2 R sin(2 phi) / 2, a_g - omega**2 R cos**2 phi); the notes' x toward the pole needs the minus sign."""
    a_g, omega, radius = 9.82, 7.292115e-5, 6.371e6
    phi = math.radians(degrees)
    up = np.array([math.cos(phi), 0.0, math.sin(phi)])
    north = np.array([-math.sin(phi), 0.0, math.cos(phi)])
    total = -a_g * up + rotation.fictitious_acceleration([0, 0, omega], radius * up)
    toward_pole = np.sign(phi) * north if phi != 0 else north
    horizontal, down = projectile.effective_gravity(a_g, omega, radius, phi)
    assert -total @ up == pytest.approx(down, rel=1e-15)
    assert total @ toward_pole == pytest.approx(-abs(horizontal), abs=1e-15 * a_g)  # toward the equator
    notes_x = omega**2 * radius * math.sin(2 * abs(phi)) / 2  # the notes' sign, toward the pole
    assert abs(total @ toward_pole - notes_x) == pytest.approx(2 * notes_x, abs=1e-15 * a_g)


def test_effective_gravity_is_least_at_the_equator_and_a_g_at_the_poles():
    a_g, omega, radius = 9.82, 7.292115e-5, 6.371e6
    _, equator = projectile.effective_gravity(a_g, omega, radius, 0.0)
    horizontal, pole = projectile.effective_gravity(a_g, omega, radius, math.pi / 2)
    assert equator == a_g - omega**2 * radius and pole == pytest.approx(a_g, rel=1e-16)
    assert abs(horizontal) < 1e-15 * a_g


def test_conical_pendulum():
    """ERRATA #29: g tan(theta) = omega**2 L sin(theta), v = omega L sin(theta), N = m g sec(theta) balances the
    weight; the angle from omega inverts the rate."""
    g, length, theta = G0, 1.5, math.radians(40.0)
    omega = projectile.conical_pendulum_rate(g, length, theta)
    assert g * math.tan(theta) == pytest.approx(omega**2 * length * math.sin(theta), rel=4e-16)
    assert projectile.conical_pendulum_speed(g, length, theta) == pytest.approx(omega * length * math.sin(theta),
                                                                               rel=2e-15)  # measured 2.2e-16
    assert projectile.conical_pendulum_angle(g, length, omega) == pytest.approx(theta, rel=4e-15)
    with pytest.raises(OrbitDomainError, match=r"g / \(omega\*\*2 L\) = .* \(0, 1\)"):
        projectile.conical_pendulum_angle(g, length, 1.0)


def test_drag_free_projectile_of_the_notes():
    """ERRATA #30: apex at v_y / g, height h + v_y**2 / (2 g); landing at (v_y + sqrt(v_y**2 + 2 g h)) / g; h = 0
    gives 2 v_y / g, range 2 v_x v_y / g and the mirror velocity (v_x, -v_y)."""
    v_x, v_y, g = 12.0, 9.0, G0
    t = projectile.free_flight_time(v_y, 0.0, g)
    assert t == pytest.approx(2 * v_y / g, rel=4e-16)
    x, y = projectile.free_position(v_x, v_y, 0.0, g, t)
    assert x == pytest.approx(2 * v_x * v_y / g, rel=4e-16) and abs(y) < 1e-14
    assert projectile.free_velocity(v_x, v_y, g, t)[1] == pytest.approx(-v_y, rel=4e-16)
    apex = projectile.free_apex_time(v_y, g)
    before, after = projectile.free_position(v_x, v_y, 0.0, g, apex - 0.3), projectile.free_position(
        v_x, v_y, 0.0, g, apex + 0.3)
    assert before[1] == pytest.approx(after[1], rel=1e-15)  # time symmetry about the apex
    assert projectile.free_apex_height(v_y, 2.0, g) == pytest.approx(2.0 + v_y**2 / (2 * g), rel=4e-16)


@pytest.mark.parametrize("v_y, h", [(5.0, 10.0), (-5.0, 10.0), (-1e4, 1e-3), (0.0, 3.0), (1e-8, 0.0)])
def test_drag_free_flight_time_against_mpmath(v_y, h):
    """The root of h + v_y t - g t**2 / 2 = 0: within 2 ulp of mpmath even when thrown down hard (measured 1)."""
    with mpmath.workdps(40):
        exact = (mpmath.mpf(v_y) + mpmath.sqrt(mpmath.mpf(v_y) ** 2 + 2 * mpmath.mpf(G0) * h)) / G0
    got = projectile.free_flight_time(v_y, h, G0)
    assert abs(got - float(exact)) <= 2 * math.ulp(float(exact))


@pytest.mark.parametrize("z", [0.0, 1e-300, 1e-9, 1e-3, 0.3, 0.999, 1.0, 3.0, 40.0, 800.0])
def test_linear_drag_helpers_against_mpmath(z):
    """(1 - e^-z)/z, (z - 1 + e^-z)/z**2, log1p(z)/z, (z - log1p(z))/z**2: within 6 ulp (measured 1)."""
    with mpmath.workdps(700):  # z = 1e-300 needs 600 digits for z - 1 + e^-z
        zz = mpmath.mpf(z)
        if z == 0:
            exact = [1, 0.5, 1, 0.5]
        else:
            exact = [(1 - mpmath.exp(-zz)) / zz, (zz - 1 + mpmath.exp(-zz)) / zz**2, mpmath.log1p(zz) / zz,
                     (zz - mpmath.log1p(zz)) / zz**2]
    got = [projectile._relaxation(z), projectile._settling(z), projectile._log_ratio(z), projectile._log_excess(z)]
    for a, b in zip(got, exact):
        assert abs(float(a) - float(b)) <= 6 * math.ulp(float(b))


def test_linear_drag_corrected_formulas_satisfy_the_equation():
    """ERRATA #33-#35: y = h - g t / b + (v_y / b + g / b**2)(1 - e^-bt) satisfies y'' = -b y' - g, y(0) = h,
    y'(0) = v_y; the notes' y (with +g t / b) starts at -v_y and leaves a residual 2 g; the velocity tends to
    (0, -g / b) (ERRATA #36)."""
    v_x, v_y, h, g, b = 7.0, 11.0, 4.0, G0, 0.8
    assert projectile.linear_drag_position(v_x, v_y, h, g, b, 0.0) == (0.0, h)
    assert projectile.linear_drag_velocity(v_x, v_y, g, b, 0.0) == (v_x, v_y)
    with mpmath.workdps(30):
        def corrected(t):
            return h - g * t / b + (v_y / b + g / b**2) * (1 - mpmath.exp(-b * t))

        def notes(t):
            return h + g * t / b - (v_y / b + g / b**2) * (1 - mpmath.exp(-b * t))

        for t in (0.0, 0.7, 2.0):
            residual = mpmath.diff(corrected, t, 2) + b * mpmath.diff(corrected, t) + g
            assert abs(residual) < 1e-20
            assert float(mpmath.diff(notes, t, 2) + b * mpmath.diff(notes, t) + g) == pytest.approx(2 * g)
            assert projectile.linear_drag_position(v_x, v_y, h, g, b, t)[1] == pytest.approx(float(corrected(t)),
                                                                                           rel=4e-16)
            assert projectile.linear_drag_velocity(v_x, v_y, g, b, t)[1] == pytest.approx(
                float(mpmath.diff(corrected, t)), rel=1e-15)
        assert float(mpmath.diff(notes, 0)) == pytest.approx(-v_y)
    late = projectile.linear_drag_velocity(v_x, v_y, g, b, 100.0)
    assert late[0] == pytest.approx(0.0, abs=1e-30) and late[1] == pytest.approx(-g / b, rel=1e-15)


def test_linear_drag_tends_to_the_drag_free_motion():
    """b -> 0 reproduces XX.iii exactly: no 1 - e^-bt cancellation."""
    t = np.linspace(0.0, 3.0, 7)
    for b in (0.0, 1e-300, 1e-20):
        np.testing.assert_allclose(projectile.linear_drag_position(5.0, 8.0, 1.0, G0, b, t),
                                   projectile.free_position(5.0, 8.0, 1.0, G0, t), rtol=1e-15, atol=1e-15)
    assert projectile.linear_drag_flight_time(8.0, 1.0, G0, 0.0) == projectile.free_flight_time(8.0, 1.0, G0)
    assert projectile.linear_drag_apex_height(8.0, 1.0, G0, 1e-12) == pytest.approx(
        projectile.free_apex_height(8.0, 1.0, G0), rel=1e-12)


@pytest.mark.parametrize("v_y, h, b", [(15.0, 0.0, 0.4), (3.0, 20.0, 3.0), (-30.0, 50.0, 0.5), (-1.0, 50.0, 0.5),
                                       (40.0, 0.0, 1e-5), (2.0, 1e4, 0.1)])
def test_linear_drag_flight_time_against_mpmath(v_y, h, b):
    """The landing time of the closed-form y solved at 40 digits (mpmath.findroot): within 4 ulp (measured 2)."""
    got = float(projectile.linear_drag_flight_time(v_y, h, G0, b))
    with mpmath.workdps(40):
        vy, height, rate, g = (mpmath.mpf(x) for x in (v_y, h, b, G0))

        def y(t):
            return height - g * t / rate + (vy / rate + g / rate**2) * (1 - mpmath.exp(-rate * t))

        exact = mpmath.findroot(y, got)
    assert abs(got - float(exact)) <= 4 * math.ulp(float(exact))


def test_quadratic_drag_terminal_speed_has_the_mass():
    """ERRATA #32: v_t = sqrt(2 m g / (C rho A)), where drag equals weight; the notes' sqrt(2 g / (C rho A)) is not
    a speed (it is off by sqrt(m kg))."""
    m, c, rho, area = 0.145, 0.47, 1.225, math.pi * 0.0366**2
    v_t = projectile.quadratic_drag_terminal_speed(m, G0, c, rho, area)
    assert 0.5 * c * rho * area * v_t**2 == pytest.approx(m * G0, rel=4e-16)
    assert math.sqrt(2 * G0 / (c * rho * area)) == pytest.approx(v_t / math.sqrt(m))


@pytest.mark.parametrize("upper, lower", [(3.0, 2.999999), (1e-8, 1e-9), (-0.5, -0.5000001), (2.0, -1.0),
                                          (1e5, 99999.0)])
def test_hodograph_difference_against_mpmath(upper, lower):
    """G(p) = p sqrt(1 + p**2) + asinh(p) differences without cancellation: within 4 ulp (measured 1)."""
    with mpmath.workdps(40):
        def big_g(p):
            p = mpmath.mpf(p)
            return p * mpmath.sqrt(1 + p * p) + mpmath.asinh(p)

        exact = float(big_g(upper) - big_g(lower))
    assert abs(float(projectile._hodograph_step(upper, lower - upper)) + exact) <= 4 * math.ulp(exact)
    assert abs(float(projectile._hodograph_step(lower, upper - lower)) - exact) <= 4 * math.ulp(exact)


@pytest.mark.parametrize("ratio", [1e10, 1e12, 1e15])
@pytest.mark.parametrize("angle, height", [(-0.3, 2.0), (-1.5, 1.0)])
def test_a_fast_launch_downwards_lands_within_its_own_tiny_bend(ratio, angle, height):
    """Thrown down 1e10 to 1e15 times faster than v_t, the path is straight to within g t / v ~ 1 / ratio**2: the
    speed falls as v0 exp(-s) along it (units of v_t and v_t**2 / g), so t = (exp(s) - 1) / v0 with s = h / sin|angle|.
    The landing is found in the drop of the slope p, which is far below p's last bit here."""
    with mpmath.workdps(40):
        exact = float(mpmath.expm1(mpmath.mpf(height) / mpmath.sin(-mpmath.mpf(angle))) / ratio)
    total = float(projectile.quadratic_drag_flight(ratio, angle, height, 1.0, 1.0)[0])
    assert abs(total / exact - 1) < 6e-14  # measured 6.2e-15


def test_quadratic_drag_reduces_to_drag_free_without_drag_and_shortens_the_flight():
    """A huge v_t leaves the drag-free range, apex and time (to 1e-9, the size of the drag left); drag shortens
    the range and puts the apex past the middle of the flight, nearer the landing point."""
    speed, angle = 20.0, math.radians(50.0)
    free_t = projectile.free_flight_time(speed * math.sin(angle), 0.0, G0)
    total, reach, apex_y, apex_t, apex_x, landing, _ = projectile.quadratic_drag_flight(speed, angle, 0.0, 1e6, G0)
    assert total == pytest.approx(free_t, rel=1e-9) and reach == pytest.approx(speed * math.cos(angle) * free_t,
                                                                                rel=1e-9)
    assert apex_y == pytest.approx(projectile.free_apex_height(speed * math.sin(angle), 0.0, G0), rel=1e-9)
    total, reach, apex_y, apex_t, apex_x, landing, _ = projectile.quadratic_drag_flight(speed, angle, 0.0, 15.0, G0)
    assert reach < speed * math.cos(angle) * free_t and apex_x > reach / 2 and apex_t < total / 2
    assert landing < speed
