"""Every closed form of orbits.core.{collisions, projectile, oscillations, rotation (rolling)} against a heyoka
integration of the same equations of motion (notes IX, XI, XX, XXV).

heyoka's Taylor integrator runs at tol = eps with high_accuracy; events (t_event, nt_event) locate apexes,
landings, turning points and the end of a contact to about eps of the time. Each bound is about 10x what was
measured (the figure is in a comment); the measurement is the largest over the cases listed.
"""

import math

import astropy.units as u
import numpy as np
import pytest

from orbits import Collision, RigidBody
from orbits.core.mechanics import collisions, oscillations, projectile, rotation

hy = pytest.importorskip("heyoka")


def integrator(equations, state, **kwargs):
    return hy.taylor_adaptive(equations, list(map(float, state)), high_accuracy=True, **kwargs)


def first_crossing(equations, state, pars, expression, direction, settle):
    """(time, state) where `expression` first crosses zero in `direction` after the time `settle` (an event at the
    start, such as a launch from y = 0, would otherwise be taken or hidden by heyoka's cooldown)."""
    ta = integrator(equations, state, pars=pars)
    ta.propagate_until(settle)
    ta = integrator(equations, ta.state, pars=pars, time=settle, t_events=[hy.t_event(expression, direction=direction)])
    ta.propagate_until(settle + 1e4)
    return ta.time, ta.state.copy()


def relative(a, b):
    return float(np.max(np.abs(np.asarray(a) - np.asarray(b)) / np.maximum(np.abs(b), 1e-300)))


# ---- XXV.iv, XXV.vi: the pendulum and the vertical circle ---------------------------------------------------

@pytest.fixture(scope="module")
def pendulum_equations():
    theta, rate = hy.make_vars("theta", "rate")
    omega_squared = hy.par[0]
    return theta, rate, [(theta, rate), (rate, -omega_squared * hy.sin(theta))]


def turning_times(pendulum_equations, omega0, theta0, rate0, t_max):
    """Times where theta' = 0 crossing from positive to negative (the far turning point) and theta at them."""
    theta, rate, equations = pendulum_equations
    found = []
    event = hy.nt_event(rate, lambda ta, t, d: found.append(t), direction=hy.event_direction.negative)
    ta = integrator(equations, [theta0, rate0], pars=[omega0**2], nt_events=[event])
    ta.propagate_until(t_max)
    return np.array(found)


#: (amplitude in degrees, bound on the relative period difference): near the separatrix the integration itself is
#: ill-conditioned (the period's sensitivity to the energy grows like 1 / (pi - theta0)**2), so the bound widens with
#: the measured error of heyoka; the closed form is within 1.3e-16 of mpmath there (tests/core/test_oscillations.py)
PERIOD_CASES = [(1.0, 2e-15), (60.0, 2e-15), (120.0, 1e-14), (170.0, 1e-13), (179.0, 5e-12), (179.9, 5e-11)]
# measured 1.8e-16, 1.6e-16, 1.0e-15, 9.1e-15, 5.6e-13, 5.1e-12


@pytest.mark.parametrize("degrees, bound", PERIOD_CASES)
def test_large_amplitude_period_equals_the_integrated_one(pendulum_equations, degrees, bound):
    """T = 2 pi / (omega0 AGM(1, cos(theta0 / 2))) (XXV.vi T2) against the spacing of the integrated turning
    points of theta'' = -omega0**2 sin(theta) released from rest (ERRATA #88: the minus sign)."""
    omega0, theta0 = 2.5, math.radians(degrees)
    period = float(oscillations.pendulum_period(omega0, theta0))
    times = turning_times(pendulum_equations, omega0, -theta0, 0.0, 3.2 * period)  # released at -theta0
    assert len(times) == 3
    measured = np.diff(np.concatenate([[0.0], times]))[1:]  # full periods between far turning points
    assert relative(measured, period) < bound
    assert relative(times[0], period / 2) < bound


#: (fp type, periods, bound on |theta - closed form| in rad): in extended precision over 3 periods (measured
#: 1.4e-14); where long double is float64 (e.g. arm64 macOS) heyoka's own phase drift near the separatrix limits a
#: float64 integration to one period (measured 1.4e-13 there, 1.1e-12 over 3)
PENDULUM_RUN = ((np.longdouble, 3, 1.5e-13) if np.finfo(np.longdouble).eps < 1e-18 else (np.float64, 1, 1.5e-12))


def test_exact_pendulum_motion_follows_the_integration(pendulum_equations):
    """theta(t) by the Jacobi elliptic function against the integrated swing at 170 degrees.

    Near the separatrix the period is sensitive to the energy, so heyoka's rounding in float64 drifts the phase:
    1.1e-12 rad after 3 periods, at the bottom of the swing where theta' is largest (not at the turning points).
    Integrated in extended precision (eps = 1.1e-19) the drift is gone and what is left is the closed form's own
    float64 error."""
    theta, rate, equations = pendulum_equations
    fp_type, periods, bound = PENDULUM_RUN
    omega0, theta0 = 3.0, math.radians(170.0)
    period = float(oscillations.pendulum_period(omega0, theta0))
    grid = np.linspace(0.0, periods * period, 20 * periods + 1)
    ta = hy.taylor_adaptive(equations, np.array([theta0, 0.0], dtype=fp_type), high_accuracy=True,
                            pars=np.array([omega0**2], dtype=fp_type), fp_type=fp_type)
    states = ta.propagate_grid(grid.astype(fp_type))[-1]
    closed = oscillations.pendulum_angle(omega0, theta0, grid)
    assert float(np.max(np.abs(closed - states[:, 0]))) < bound


@pytest.mark.parametrize("ratio", [2.01, 2.5, 4.0, 10.0])
def test_loop_period_is_the_integrated_time_round_the_circle(pendulum_equations, ratio):
    """T1 = 2 pi R / (u AGM(1, sqrt(1 - 4 g R / u**2))) for u > 2 sqrt(g R): the time for theta to gain 2 pi."""
    theta, rate, equations = pendulum_equations
    g, radius = 9.80665, 1.5
    u = ratio * math.sqrt(g * radius)
    ta = integrator(equations, [0.0, u / radius], pars=[g / radius], t_events=[hy.t_event(theta - 2 * math.pi)])
    ta.propagate_until(1e4)
    assert relative(ta.time, oscillations.loop_period(u, g, radius)) < 5e-14  # measured 5.1e-15


@pytest.mark.parametrize("ratio", [0.05, 0.9, 1.9, 1.999])
def test_swing_period_and_turning_angle_match_the_integration(pendulum_equations, ratio):
    """T2 and theta_m = arccos(1 - u**2 / (2 g R)) (ERRATA #102; the notes' arccos(u**2 / (2 g R)) is wrong)."""
    theta, rate, equations = pendulum_equations
    g, radius = 9.80665, 0.8
    u = ratio * math.sqrt(g * radius)
    period = float(oscillations.swing_period(u, g, radius))
    times = turning_times(pendulum_equations, math.sqrt(g / radius), 0.0, u / radius, 1.1 * period)
    assert relative(times[0], period / 4) < 7e-14  # measured 7.1e-15
    ta = integrator(equations, [0.0, u / radius], pars=[g / radius])
    ta.propagate_until(float(times[0]))
    theta_m = ta.state[0]
    expected = float(oscillations.turning_angle(u, g, radius))
    assert abs(theta_m - expected) < 1.5e-14 * max(1.0, expected)  # measured 1.4e-15 rad
    notes = math.acos(min(1.0, u**2 / (2 * g * radius)))
    assert abs(notes - expected) > 0.1  # the notes' form is far off


def test_normal_force_and_the_point_where_a_string_slackens(pendulum_equations):
    """N = m R theta'**2 + m g cos(theta) from the integrated motion equals (m/R)(u**2 - 2 g R + 3 g R cos(theta))
    (ERRATA #101), and N = 0 where cos(theta) = (2 g R - u**2) / (3 g R) (ERRATA #104: beyond the horizontal)."""
    theta, rate, equations = pendulum_equations
    g, radius, mass = 9.80665, 2.0, 0.3
    u = 2.0 * math.sqrt(g * radius)  # between sqrt(2 g R) and sqrt(5 g R)
    grid = np.linspace(0.0, 0.6, 31)
    states = integrator(equations, [0.0, u / radius], pars=[g / radius]).propagate_grid(grid)[-1]
    newton = mass * radius * states[:, 1] ** 2 + mass * g * np.cos(states[:, 0])
    closed = oscillations.circle_normal_force(mass, u, g, radius, states[:, 0])
    assert np.max(np.abs(newton - closed)) < 2e-14 * mass * g  # measured 1.8e-15 m g
    slack = g * hy.cos(theta) + radius * rate**2  # N / m
    ta = integrator(equations, [0.0, u / radius], pars=[g / radius], t_events=[hy.t_event(slack)])
    ta.propagate_until(100.0)
    expected = float(oscillations.leaving_angle(u, g, radius))
    assert math.pi / 2 < expected < math.pi
    assert abs(ta.state[0] - expected) < 5e-15  # measured 4.4e-16 rad


# ---- XXV.v, XXV.vii: damped and driven oscillators ------------------------------------------------------------

@pytest.fixture(scope="module")
def oscillator():
    x, v = hy.make_vars("x", "v")
    k, b, force, drive = hy.par[0], hy.par[1], hy.par[2], hy.par[3]
    return [(x, v), (v, -k * x - b * v + force * hy.cos(drive * hy.time))]


@pytest.mark.parametrize("k, b", [(3.0, 1.1), (1.0, 2.0), (1.0, 2.0 + 1e-7), (1.0, 2.0 - 1e-7), (2.0, 7.0),
                                  (100.0, 0.01)])
def test_damped_motion_in_every_regime_follows_the_integration(oscillator, k, b):
    """x'' = -k x - b x' from (x0, v0): under-, critically and over-damped, and within 1e-7 of critical."""
    x0, v0 = 0.7, -1.3
    grid = np.linspace(0.0, 12.0, 49)
    states = integrator(oscillator, [x0, v0], pars=[k, b, 0.0, 0.0]).propagate_grid(grid)[-1]
    x, v = oscillations.damped_motion(k, b, x0, v0, grid)
    scale = max(abs(x0), abs(v0) / math.sqrt(k))
    assert np.max(np.abs(x - states[:, 0])) < 7e-14 * scale  # measured 6.8e-15
    assert np.max(np.abs(v - states[:, 1])) < 1e-13 * scale * math.sqrt(k)  # measured 9.3e-15


def test_notes_damped_forms_with_their_corrected_derivatives(oscillator):
    """The notes' (A, phi), (A, B) parametrisations: x, x' from the integration, x'' from the equation."""
    k, b, amplitude, phase = 3.0, 1.1, 0.7, 0.4
    grid = np.linspace(0.0, 5.0, 21)
    x, v, a = oscillations.underdamped_notes(amplitude, phase, k, b, grid)
    states = integrator(oscillator, [x[0], v[0]], pars=[k, b, 0.0, 0.0]).propagate_grid(grid)[-1]
    assert np.max(np.abs(states[:, 0] - x)) < 2e-15 and np.max(np.abs(states[:, 1] - v)) < 2e-15  # measured 2.2e-16
    assert np.max(np.abs(a - (-k * states[:, 0] - b * states[:, 1]))) < 7e-15  # measured 6.7e-16
    b = 2.0
    x, v, a = oscillations.critically_damped_notes(1.2, -0.8, b, grid)
    states = integrator(oscillator, [x[0], v[0]], pars=[b * b / 4, b, 0.0, 0.0]).propagate_grid(grid)[-1]
    assert np.max(np.abs(states[:, 1] - v)) < 3e-15  # measured 3.3e-16
    assert np.max(np.abs(a - (-b * b / 4 * states[:, 0] - b * states[:, 1]))) < 7e-15  # measured 6.7e-16
    k, b = 2.0, 5.0
    x, v, a = oscillations.overdamped_notes(0.5, 1.5, k, b, grid)
    states = integrator(oscillator, [x[0], v[0]], pars=[k, b, 0.0, 0.0]).propagate_grid(grid)[-1]
    assert np.max(np.abs(states[:, 1] - v)) < 2e-15  # measured 1.1e-16
    assert np.max(np.abs(a - (-k * states[:, 0] - b * states[:, 1]))) < 1e-14  # measured 1.1e-15


@pytest.mark.parametrize("drive", [0.3, 1.9, 2.0, 2.1, 6.0])
def test_driven_steady_state_is_a_solution(oscillator, drive):
    """Started on the steady state A cos(w t - delta), the integration stays on it (XXV.vii)."""
    omega0, b, force = 2.0, 0.25, 1.7
    grid = np.linspace(0.0, 20.0, 41)
    x, v = oscillations.driven_steady_state(omega0, b, force, drive, grid)
    states = integrator(oscillator, [x[0], v[0]], pars=[omega0**2, b, force, drive]).propagate_grid(grid)[-1]
    amplitude = float(oscillations.driven_amplitude(omega0, b, force, drive))
    assert np.max(np.abs(states[:, 0] - x)) < 4e-13 * amplitude  # measured 4.0e-14
    assert np.max(np.abs(states[:, 1] - v)) < 1.5e-13 * amplitude * drive  # measured 1.3e-14


# ---- XX: projectiles ------------------------------------------------------------------------------------------

@pytest.fixture(scope="module")
def linear_drag():
    x, y, vx, vy = hy.make_vars("x", "y", "vx", "vy")
    g, b = hy.par[0], hy.par[1]
    return y, vy, [(x, vx), (y, vy), (vx, -b * vx), (vy, -b * vy - g)]


@pytest.mark.parametrize("b, angle, height", [(0.3, 45.0, 0.0), (2.0, 70.0, 5.0), (1e-6, 30.0, 0.0),
                                              (0.5, -20.0, 40.0), (5.0, 85.0, 1.0)])
def test_linear_drag_closed_forms_follow_the_integration(linear_drag, b, angle, height):
    """x, y, v_x, v_y (ERRATA #34, #35: the corrected y and v_y), apex and landing against the integration."""
    y, vy, equations = linear_drag
    g, speed = 9.80665, 25.0
    v_x, v_y = speed * math.cos(math.radians(angle)), speed * math.sin(math.radians(angle))
    flight = float(projectile.linear_drag_flight_time(v_y, height, g, b))
    grid = np.linspace(0.0, flight, 25)
    states = integrator(equations, [0, height, v_x, v_y], pars=[g, b]).propagate_grid(grid)[-1]
    x_c, y_c = projectile.linear_drag_position(v_x, v_y, height, g, b, grid)
    vx_c, vy_c = projectile.linear_drag_velocity(v_x, v_y, g, b, grid)
    size = max(float(np.max(np.abs(states[:, :2]))), 1.0)
    position_error = max(np.max(np.abs(x_c - states[:, 0])), np.max(np.abs(y_c - states[:, 1])))
    velocity_error = max(np.max(np.abs(vx_c - states[:, 2])), np.max(np.abs(vy_c - states[:, 3])))
    assert position_error < 5e-15 * size  # measured 4.3e-16
    assert velocity_error < 3e-15 * speed  # measured 2.8e-16
    landed, _ = first_crossing(equations, [0, height, v_x, v_y], [g, b], y, hy.event_direction.negative, flight / 2)
    assert relative(landed, flight) < 2e-15  # measured 1.7e-16
    if v_y > 0:
        apex = integrator(equations, [0, height, v_x, v_y], pars=[g, b], t_events=[hy.t_event(vy)])
        apex.propagate_until(1e3)
        assert relative(apex.time, projectile.linear_drag_apex_time(v_y, g, b)) < 2e-15  # measured 0
        apex_height = projectile.linear_drag_apex_height(v_y, height, g, b)
        assert relative(apex.state[1], apex_height) < 2e-15  # measured 1.5e-16


@pytest.fixture(scope="module")
def quadratic_drag():
    x, y, vx, vy = hy.make_vars("x", "y", "vx", "vy")
    g, inverse_vt2 = hy.par[0], hy.par[1]
    speed = hy.sqrt(vx**2 + vy**2)
    drag = g * inverse_vt2 * speed
    return y, vy, [(x, vx), (y, vy), (vx, -drag * vx), (vy, -drag * vy - g)]


@pytest.mark.parametrize("speed, angle, height", [(20.0, 45.0, 0.0), (300.0, 45.0, 0.0), (5.0, 10.0, 2.0),
                                                  (50.0, 80.0, 0.0), (40.0, -30.0, 100.0), (30.0, 0.0, 10.0),
                                                  (3000.0, 60.0, 0.0), (50.0, 89.99, 0.0)])
def test_quadratic_drag_range_apex_and_flight_time_match_the_integration(quadratic_drag, speed, angle, height):
    """The hodograph quadrature's flight time, range, apex and landing speed against the integrated motion with
    drag -(g / v_t**2)|v| v (v_t = sqrt(2 m g / (C rho A)), ERRATA #32)."""
    y, vy, equations = quadratic_drag
    g, v_t = 9.80665, 30.0
    theta = math.radians(angle)
    start = [0.0, height, speed * math.cos(theta), speed * math.sin(theta)]
    total, reach, apex_y, apex_t, apex_x, landing_speed, landing_angle = (
        float(q) for q in projectile.quadratic_drag_flight(speed, theta, height, v_t, g))
    landed, state = first_crossing(equations, start, [g, 1 / v_t**2], y, hy.event_direction.negative, total / 2)
    size = max(reach, apex_y)
    assert relative(landed, total) < 4e-13  # measured 3.7e-14
    assert abs(state[0] - reach) < 4e-13 * size  # measured 3.4e-14
    assert relative(math.hypot(state[2], state[3]), landing_speed) < 3e-15  # measured 2.5e-16
    assert abs(math.atan2(state[3], state[2]) - landing_angle) < 2e-14  # measured 1.8e-15 rad
    if angle > 0:
        top = integrator(equations, start, pars=[g, 1 / v_t**2], t_events=[hy.t_event(vy)])
        top.propagate_until(1e4)
        assert relative(top.time, apex_t) < 6e-13 and relative(top.state[1], apex_y) < 6e-13  # measured 5.7e-14
        assert abs(top.state[0] - apex_x) < 4e-13 * size  # measured 3.3e-14


@pytest.mark.parametrize("ratio", [1e3, 1e6, 1e9, 2e11])
@pytest.mark.parametrize("angle", [10.0, 45.0, 80.0])
def test_launches_far_faster_than_the_terminal_speed_match_the_integration(quadratic_drag, ratio, angle):
    """Launched 1e3 to 2e11 times faster than v_t (20 m/s against v_t = 1e-10 m/s never returned: the quadrature's
    panels stalled where the branch point lay within p0's last bit), in units of v_t and v_t / g."""
    y, _, equations = quadratic_drag
    theta = math.radians(angle)
    start = [0.0, 0.0, ratio * math.cos(theta), ratio * math.sin(theta)]
    total, reach, apex_y, _, _, landing_speed, landing_angle = (
        float(q) for q in projectile.quadratic_drag_flight(ratio, theta, 0.0, 1.0, 1.0))
    landed, state = first_crossing(equations, start, [1.0, 1.0], y, hy.event_direction.negative, total / 2)
    assert relative(landed, total) < 1e-14  # measured 9.4e-16
    assert abs(state[0] - reach) < 7e-15 * max(reach, apex_y)  # measured 6.6e-16
    assert relative(math.hypot(state[2], state[3]), landing_speed) < 2e-15  # measured 1.2e-16
    assert abs(math.atan2(state[3], state[2]) - landing_angle) < 5e-15  # measured 4.4e-16 rad


@pytest.mark.parametrize("speed", [0.0, 20.0, -10.0, -30.0, -45.0])
def test_vertical_quadratic_drag_flights_match_the_integration(speed):
    """Straight up, dropped, and thrown down slower than, at and faster than v_t: closed forms against the 1-D
    equations y'' = -g -+ (g / v_t**2) y'**2 (rising, falling), integrated piecewise (|v| v has a kink at v = 0
    that a Taylor integrator must not step across)."""
    y, v = hy.make_vars("y", "v")
    g, v_t, height = 9.80665, 30.0, 50.0
    rising = [(y, v), (v, -g - g / v_t**2 * v**2)]
    falling = [(y, v), (v, -g + g / v_t**2 * v**2)]
    angle = math.pi / 2 if speed >= 0 else -math.pi / 2
    total, reach, apex_y, apex_t, _, landing_speed, _ = (
        float(q) for q in projectile.quadratic_drag_flight(abs(speed), angle, height, v_t, g))
    start, begin = [height, speed], 0.0
    if speed > 0:
        up = integrator(rising, start, t_events=[hy.t_event(v)])
        up.propagate_until(1e4)
        assert relative(up.time, apex_t) < 2e-15 and relative(up.state[0], apex_y) < 2e-15  # measured 1.2e-16
        start, begin = [up.state[0], 0.0], up.time
    down = integrator(falling, start, time=begin, t_events=[hy.t_event(y)])
    down.propagate_until(1e4)
    assert relative(down.time, total) < 2e-15 and reach == 0.0  # measured 1.7e-16
    assert relative(abs(down.state[1]), landing_speed) < 2e-15  # measured 1.5e-16


def test_conical_pendulum_keeps_its_cone(quadratic_drag):
    """A spherical pendulum started at theta0 with phi' = sqrt(g / (L cos(theta0))) (XX.ii) keeps theta = theta0."""
    theta, phi, rate, spin = hy.make_vars("theta", "phi", "rate", "spin")
    g, length, theta0 = 9.80665, 1.3, math.radians(35.0)
    omega = float(projectile.conical_pendulum_rate(g, length, theta0))
    equations = [(theta, rate), (phi, spin),
                 (rate, hy.sin(theta) * hy.cos(theta) * spin**2 - g / length * hy.sin(theta)),
                 (spin, -2.0 * rate * spin * hy.cos(theta) / hy.sin(theta))]
    grid = np.linspace(0.0, 10 * 2 * math.pi / omega, 41)
    states = integrator(equations, [theta0, 0.0, 0.0, omega]).propagate_grid(grid)[-1]
    assert np.max(np.abs(states[:, 0] - theta0)) < 3e-15  # measured 2.2e-16 rad
    assert relative(states[-1, 1], omega * grid[-1]) < 4e-15  # measured 3.4e-16
    speed = float(projectile.conical_pendulum_speed(g, length, theta0))
    assert relative(speed, omega * length * math.sin(theta0)) < 1e-15  # measured 2.2e-16


# ---- IX: a collision as a contact force -----------------------------------------------------------------------

@pytest.fixture(scope="module")
def contact():
    """Two bodies on a line, body 1 behind body 2, in contact through a spring k and a dashpot c acting on the
    overlap d = x1 - x2 > 0 (started at d = 0 with v1 > v2); the contact ends when d returns to 0."""
    x1, x2, v1, v2 = hy.make_vars("x1", "x2", "v1", "v2")
    m1, m2, k, c = hy.par[0], hy.par[1], hy.par[2], hy.par[3]
    push = k * (x1 - x2) + c * (v1 - v2)
    return x1, x2, v1, v2, [(x1, v1), (x2, v2), (v1, -push / m1), (v2, push / m2)]


@pytest.mark.parametrize("m1, m2, v1, v2", [(1.0, 1.0, 2.0, 0.0), (3.0, 1.0, 1.5, -0.5), (1.0, 1e3, 4.0, 0.1),
                                            (2.0, 0.5, 0.3, -2.0)])
@pytest.mark.parametrize("zeta", [0.0, 0.1, 0.5])
def test_contact_integration_gives_the_restitution_formulas(contact, m1, m2, v1, v2, zeta):
    """A spring-dashpot contact of damping ratio zeta has e = exp(-pi zeta / sqrt(1 - zeta**2)); the integrated
    velocities after the contact equal velocities_after(m1, v1, m2, v2, e) (IX.xi, ERRATA #12); the largest
    compression of the pure spring is |v1 - v2| sqrt(mu / k) (IX.xii); K_int = 0 at closest approach (IX.v)."""
    x1, x2, v1s, v2s, equations = contact
    k = 50.0
    mu = float(collisions.reduced_mass(m1, m2))
    c = 2.0 * zeta * math.sqrt(k * mu)
    end = hy.t_event(x1 - x2, direction=hy.event_direction.negative)
    closest = []
    turn = hy.nt_event(v1s - v2s, lambda ta, t, d: closest.append(t))
    ta = integrator(equations, [0.0, 0.0, v1, v2], pars=[m1, m2, k, c], t_events=[end], nt_events=[turn])
    ta.propagate_until(1e3)
    assert len(closest) == 1
    there = integrator(equations, [0.0, 0.0, v1, v2], pars=[m1, m2, k, c])
    there.propagate_until(closest[0])
    e = float(collisions.restitution_of_spring_dashpot(zeta))
    after1, after2 = collisions.velocities_after(m1, v1, m2, v2, e)
    scale = abs(v1 - v2)
    assert abs(ta.state[2] - after1) < 5e-15 * scale and abs(ta.state[3] - after2) < 5e-15 * scale  # measured 4.4e-16
    p1, p2, w1, w2 = there.state
    assert collisions.internal_kinetic_energy(m1, w1, m2, w2) < 3e-31 * mu * scale**2  # measured 2.5e-32
    before = collisions.kinetic_energy(m1, v1) + collisions.kinetic_energy(m2, v2)
    at_closest = collisions.kinetic_energy(m1, w1) + collisions.kinetic_energy(m2, w2)
    after = collisions.kinetic_energy(m1, ta.state[2]) + collisions.kinetic_energy(m2, ta.state[3])
    assert at_closest <= after * (1 + 1e-14) and after <= before * (1 + 1e-14)  # ERRATA #1, #11: KE order
    mechanical_closest = at_closest + 0.5 * k * (p1 - p2) ** 2
    assert after <= mechanical_closest * (1 + 1e-14) <= before * (1 + 2e-14)  # ERRATA #11: mechanical energy
    if zeta == 0:
        compression = float(collisions.spring_compression(m1, v1, m2, v2, k))
        assert relative(p1 - p2, compression) < 2e-15  # measured 1.4e-16


def contact_along(dimension):
    """(overlap, equations) of two smooth bodies in `dimension` (2 or 3) dimensions pushed apart only along a fixed
    unit normal n = (p4, p5[, p6]) by a spring k = p2 and a dashpot c = p3 on the overlap d = (x1 - x2) . n
    (masses p0, p1): x1'' = -(k d + c d') n / m1, x2'' = +(k d + c d') n / m2; state (x1, x2, v1, v2)."""
    x1, x2, v1, v2 = ([hy.expression(f"{name}{i}") for i in range(dimension)] for name in ("x1", "x2", "v1", "v2"))
    m1, m2, k, c = hy.par[0], hy.par[1], hy.par[2], hy.par[3]
    n = [hy.par[4 + i] for i in range(dimension)]
    overlap = hy.sum([(a - b) * ni for a, b, ni in zip(x1, x2, n)])
    push = k * overlap + c * hy.sum([(a - b) * ni for a, b, ni in zip(v1, v2, n)])
    return overlap, ([(x, v) for x, v in zip(x1 + x2, v1 + v2)] + [(v, -push * ni / m1) for v, ni in zip(v1, n)]
                     + [(v, push * ni / m2) for v, ni in zip(v2, n)])


@pytest.mark.parametrize("m1, v1, m2, v2, normal", [
    (1.0, [2.0, 0.5], 1.0, [0.0, 0.0], [1.0, 0.0]),
    (3.0, [1.5, -0.7], 1.0, [-0.5, 2.0], [math.cos(0.5), math.sin(0.5)]),
    (1.0, [4.0, 3.0], 1e3, [0.1, -0.2], [0.6, 0.8]),
    (2.0, [0.3, 1.0], 0.5, [-2.0, -1.0], None),  # the notes' model: n along v1 - v2
    (2.0, [0.3, 1.0, -0.4], 0.5, [-2.0, -1.0, 0.7], [2.0, 1.0, -2.0])])
@pytest.mark.parametrize("zeta", [0.0, 0.1, 0.5, 0.9])
def test_oblique_contact_integration_gives_the_oblique_velocities(m1, v1, m2, v2, normal, zeta):
    """Two smooth bodies meeting with 2-D (and one 3-D) velocities, the contact force a spring-dashpot along the
    fixed normal n only, of damping ratio zeta, so e = exp(-pi zeta / sqrt(1 - zeta**2)): the integrated velocity
    vectors after the contact (tangential parts untouched, normal parts per e) equal Collision.oblique's and
    oblique_velocities_after's v1' = v1 - (1 + e) x2 ((v1 - v2) . n) n, v2' = v2 + (1 + e) x1 ((v1 - v2) . n) n
    (IX.xiii, ERRATA #14)."""
    v1, v2 = np.array(v1), np.array(v2)
    dimension, k = len(v1), 50.0
    n = v1 - v2 if normal is None else np.array(normal)
    n = n / np.linalg.norm(n)
    e = math.exp(-math.pi * zeta / math.sqrt(1.0 - zeta**2))
    c = 2.0 * zeta * math.sqrt(k * m1 * m2 / (m1 + m2))
    overlap, equations = contact_along(dimension)
    ta = integrator(equations, [0.0] * (2 * dimension) + list(v1) + list(v2), pars=[m1, m2, k, c, *n],
                    t_events=[hy.t_event(overlap, direction=hy.event_direction.negative)])
    ta.propagate_until(1e3)
    assert ta.time < 1e3  # the contact ended
    after1, after2 = ta.state[2 * dimension:3 * dimension], ta.state[3 * dimension:]
    speed = u.m / u.s
    hit = Collision.oblique(m1 * u.kg, v1 * speed, m2 * u.kg, v2 * speed, restitution=e, normal=normal)
    closed = collisions.oblique_velocities_after(m1, v1, m2, v2, e, normal)
    scale = np.linalg.norm(v1 - v2)
    for library in ((hit.velocity1_after.to_value(speed), hit.velocity2_after.to_value(speed)), closed):
        assert np.max(np.abs(after1 - library[0])) < 4e-15 * scale  # measured 3.5e-16 (both vectors)
        assert np.max(np.abs(after2 - library[1])) < 4e-15 * scale


# ---- XI: rolling without slipping down an incline ------------------------------------------------------------

@pytest.fixture(scope="module")
def rolling_lagrangian():
    """(s, v, equations, s'' as a compiled function of (s, v)) for a body of mass m = p0, moment I = p1 about its
    axis and rolling radius r = p2 on an incline of angle alpha = p3 under gravity g = p4, s (m) the distance down
    the slope: L = m v**2 / 2 + I (v / r)**2 / 2 + m g sin(alpha) s (translation, rotation at omega = v / r, the
    no-slip constraint, and the height lost), its Euler-Lagrange equation
    s'' = (dL/ds - d2L/dv ds v) / d2L/dv2 derived by heyoka's symbolic diff."""
    s, v = hy.make_vars("s", "v")
    m, moment, r, alpha, g = hy.par[0], hy.par[1], hy.par[2], hy.par[3], hy.par[4]
    lagrangian = m * v**2 / 2 + moment * (v / r) ** 2 / 2 + m * g * hy.sin(alpha) * s
    momentum = hy.diff(lagrangian, v)
    acceleration = (hy.diff(lagrangian, s) - hy.diff(momentum, s) * v) / hy.diff(momentum, v)
    return s, v, [(s, v), (v, acceleration)], hy.cfunc([acceleration], vars=[s, v])


ROLLERS = {"solid sphere": (0.4, lambda m, r: RigidBody.solid_sphere(m, r)),
           "spherical shell": (2 / 3, lambda m, r: RigidBody.spherical_shell(m, r)),
           "solid cylinder": (0.5, lambda m, r: RigidBody.solid_cylinder(m, r, 0.3 * u.m)),
           "thin hoop": (1.0, lambda m, r: RigidBody.thin_hoop(m, r))}


@pytest.mark.parametrize("body", list(ROLLERS))
@pytest.mark.parametrize("degrees", [3.0, 25.0, 70.0, 89.0])
def test_rolling_down_an_incline_follows_the_lagrangian_integration(rolling_lagrangian, body, degrees):
    """a = g sin(alpha) / (1 + k), v = sqrt(2 g h / (1 + k)) and mu_s = tan(alpha) k / (1 + k) (XI, k = I / (m r**2))
    from RigidBody.rolling_down and orbits.core.mechanics.rotation against the integrated motion: s = a t**2 / 2, v =
    a t on
    a grid, the speed where the height lost s sin(alpha) reaches h, and the friction the integration needs,
    f = m g sin(alpha) - m s'' (Newton for the centre) = I (s'' / r) / r (Euler for the spin), over the normal
    force m g cos(alpha). I = k m r**2 with k given here (2/5, 2/3, 1/2, 1), not taken from the library."""
    s, v, equations, acceleration_of = rolling_lagrangian
    factor, make = ROLLERS[body]
    g, mass, radius, height, alpha = 9.80665, 2.5, 0.15, 1.7, math.radians(degrees)
    pars = [mass, factor * mass * radius**2, radius, alpha, g]
    rolling = make(mass * u.kg, radius * u.m).rolling_down(degrees * u.deg, g=g * u.m / u.s**2)
    library = (rolling.acceleration.to_value(u.m / u.s**2), rolling.speed_after(height * u.m).to_value(u.m / u.s),
               rolling.friction_coefficient.to_value(u.dimensionless_unscaled))
    core = (rotation.rolling_acceleration(g, alpha, factor), rotation.rolling_speed(g, height, factor),
            rotation.rolling_friction_coefficient(alpha, factor))
    length = height / math.sin(alpha)
    grid = np.linspace(0.0, math.sqrt(2 * length / library[0]), 17)
    states = integrator(equations, [0.0, 0.0], pars=pars).propagate_grid(grid)[-1]
    ta = integrator(equations, [0.0, 0.0], pars=pars, t_events=[hy.t_event(s * math.sin(alpha) - height)])
    ta.propagate_until(1e3)
    assert ta.time < 1e3  # the height was reached
    newton = mass * g * math.sin(alpha) - mass * acceleration_of(ta.state, pars=pars)[0]
    euler = factor * mass * radius**2 * (acceleration_of(ta.state, pars=pars)[0] / radius) / radius
    assert relative(euler, newton) < 4e-15  # measured 3.5e-16: the integration obeys both laws with one f
    for a, speed, mu in (library, core):
        assert np.max(np.abs(states[:, 0] - a * grid**2 / 2)) < 4e-15 * length  # measured 3.9e-16
        assert np.max(np.abs(states[:, 1] - a * grid)) < 4e-15 * a * grid[-1]  # measured 4.0e-16
        assert relative(ta.state[1], speed) < 5e-15  # measured 4.4e-16
        assert relative(newton / (mass * g * math.cos(alpha)), mu) < 4e-15  # measured 3.5e-16
