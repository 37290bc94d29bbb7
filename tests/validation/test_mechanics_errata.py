"""The errata of sections IX, X, XX and XXV that no other test names, each against an independent reference: a
heyoka integration of the equations of motion, mpmath, or exact rational arithmetic.

#2 and #4 (IX), #17 and #18 (X.ii), #31 (XX.iv), #85, #87, #91 and #94 (XXV). The others of these sections are
tested in tests/core/test_collisions.py, test_rocket.py, test_projectile.py, test_oscillations.py and
tests/validation/test_mechanics_integration.py, each test naming its erratum.
"""

import math
from fractions import Fraction

import mpmath
import numpy as np
import pytest

from orbits.core.manoeuvres import rocket
from orbits.core.mechanics import collisions, oscillations, projectile

hy = pytest.importorskip("heyoka")


def integrator(equations, state, **kwargs):
    return hy.taylor_adaptive(equations, list(map(float, state)), high_accuracy=True, **kwargs)


# ---- IX --------------------------------------------------------------------------------------------------------

@pytest.mark.parametrize("m1, m2", [(1.0, 1.0), (3.0, 7.0), (1e-3, 5.97e24), (2.5, 0.4)])
def test_erratum_2_reduced_mass(m1, m2):
    """#2 (IX.iii, correct as printed): mu = m1 m2 / (m1 + m2), within 1 ulp of mpmath (measured 0.2 ulp)."""
    with mpmath.workdps(40):
        exact = mpmath.mpf(m1) * m2 / (mpmath.mpf(m1) + m2)
        assert abs(mpmath.mpf(float(collisions.reduced_mass(m1, m2))) - exact) <= mpmath.mpf(
            float(np.spacing(float(exact))))


def test_erratum_4_only_the_radial_relative_velocity_vanishes_at_closest_approach_in_2d():
    """#4 (IX.v, ambiguous): in 1-D the internal kinetic energy is zero at the closest approach (tested with the
    contact integration in test_mechanics_integration.py); in 2-D only the radial part of the relative velocity
    vanishes. Two discs meet off-centre through a radial spring contact (relative motion, reduced mass mu); at
    the closest approach K_int = L**2 / (2 mu rho_min**2) > 0, the angular momentum L kept (measured 0, and K_int
    0.41 of its value at contact)."""
    m1, m2, k, touch = 2.0, 3.0, 400.0, 1.0
    mu = float(collisions.reduced_mass(m1, m2))
    x, y, vx, vy = hy.make_vars("x", "y", "vx", "vy")
    rho = hy.sqrt(x**2 + y**2)
    push = k * (touch - rho) / (mu * rho)  # radial repulsion, only while in contact (rho < touch)
    equations = [(x, vx), (y, vy), (vx, push * x), (vy, push * y)]
    offset, speed = 0.6, 1.5  # the relative velocity at contact, and its lever arm
    start = [-math.sqrt(touch**2 - offset**2), offset, speed, 0.0]
    closest = []
    radial = hy.nt_event(x * vx + y * vy, lambda ta, t, d: closest.append(t))
    ta = integrator(equations, start, nt_events=[radial])
    ta.propagate_until(0.1)  # the first closest approach, well inside the contact (the model holds only there)
    at = integrator(equations, start)
    at.propagate_until(closest[0])
    px, py, wx, wy = at.state
    rho_min = math.hypot(px, py)
    assert rho_min < 0.95 * touch
    internal = float(collisions.internal_kinetic_energy(m1, np.array([wx, wy]), m2, np.zeros(2), vectors=True))
    angular_momentum = mu * offset * speed
    assert internal > 0.1 * 0.5 * mu * speed**2  # far from 0
    assert internal == pytest.approx(angular_momentum**2 / (2 * mu * rho_min**2), rel=4e-15)


# ---- X.ii --------------------------------------------------------------------------------------------------------

def test_errata_17_and_18_mass_bookkeeping_of_one_ejected_lump():
    """#17: after ejecting dm the body's mass is m - dm (OCR: 'm dm'); #18 (correct): momentum m v = (m - dm) v' +
    dm (v + v_rel) gives (m - dm) dv + dm v_rel = 0, exactly, in rational arithmetic; summed over lumps it is
    rocket.velocity_change (tests/core/test_rocket.py)."""
    m, v, v_rel, dm = Fraction(7), Fraction(3, 2), Fraction(-5), Fraction(1, 9)
    remaining = m - dm
    after = (m * v - dm * (v + v_rel)) / remaining  # momentum kept
    assert remaining == Fraction(62, 9) and remaining * (after - v) + dm * v_rel == 0
    assert float(after - v) == pytest.approx(float(rocket.velocity_change(float(v_rel), float(m), float(remaining))),
                                             rel=0.01)  # one lump of 1.6 % of the mass: the log to first order


# ---- XX.iv -------------------------------------------------------------------------------------------------------

def test_erratum_31_quadratic_drag_acts_against_the_velocity_not_along_r():
    """#31: f = -(1/2) C rho A |r'|**2 times the unit vector of r', not of r. The library's flight (drag along
    -v, hodograph quadrature) lands where heyoka integrating that law lands (measured 0 difference); the
    misprinted law (along -r) lands 6 % short."""
    g, v_t, speed, angle = 9.80665, 30.0, 40.0, math.radians(50.0)
    x, y, vx, vy = hy.make_vars("x", "y", "vx", "vy")
    k = g / v_t**2
    laws = {"velocity": (-k * hy.sqrt(vx**2 + vy**2) * vx, -k * hy.sqrt(vx**2 + vy**2) * vy),
            "position": (-k * (vx**2 + vy**2) * x / hy.sqrt(x**2 + y**2 + 1e-300),
                         -k * (vx**2 + vy**2) * y / hy.sqrt(x**2 + y**2 + 1e-300))}
    total, reach = (float(q) for q in projectile.quadratic_drag_flight(speed, angle, 0.0, v_t, g)[:2])
    landing = {}
    for name, (ax, ay) in laws.items():
        nudge = 0.0 if name == "velocity" else 1e-9  # the misprinted law is singular at r = 0
        start = [nudge * math.cos(angle), nudge * math.sin(angle), speed * math.cos(angle), speed * math.sin(angle)]
        ta = integrator([(x, vx), (y, vy), (vx, ax), (vy, ay - g)], start,
                        t_events=[hy.t_event(y, direction=hy.event_direction.negative)])
        ta.propagate_until(1e3)
        landing[name] = ta.state[0]
    assert abs(landing["velocity"] - reach) < 2e-15 * reach  # measured 0
    assert abs(landing["position"] - reach) > 0.03 * reach


# ---- XXV --------------------------------------------------------------------------------------------------------

@pytest.mark.parametrize("omega, x0, v0", [(2.0, 0.3, 0.0), (0.7, -1.2, 2.5), (15.0, 0.0, -4.0)])
def test_erratum_85_simple_harmonic_energy(omega, x0, v0):
    """#85 (correct): x = A sin(w t + phi) + C with k = m w**2, K + U = m w**2 A**2 / 2 at every instant (the
    undamped oscillator, b = 0, per unit mass: w**2 A**2 / 2 with A = sqrt(x0**2 + (v0 / w)**2); measured
    5.6e-16 over three periods, and x within 1.9e-15 A of the sine)."""
    t = np.linspace(0.0, 6 * math.pi / omega, 301)
    x, v = oscillations.damped_motion(omega**2, 0.0, x0, v0, t)
    amplitude = math.hypot(x0, v0 / omega)
    energy = 0.5 * v * v + 0.5 * omega**2 * x * x
    assert np.max(np.abs(energy / (0.5 * omega**2 * amplitude**2) - 1)) < 4e-15
    phase = math.atan2(x0, v0 / omega)
    assert np.max(np.abs(x - amplitude * np.sin(omega * t + phase))) < 4e-15 * amplitude


def test_erratum_87_two_bodies_on_a_spring():
    """#87 (correct): omega = sqrt(k / mu); started through equilibrium with relative speed R omega, the
    relative coordinate is y = R sin(omega t), body 1 moves by (mu R / m1) sin(omega t) (centre of mass at
    rest), K = (k R**2 / 2) cos**2, U = (k R**2 / 2) sin**2; against heyoka (measured 1.5e-15)."""
    m1, m2, k, amplitude = 2.0, 5.0, 30.0, 0.4
    omega = float(oscillations.spring_pair_frequency(k, m1, m2))
    mu = m1 * m2 / (m1 + m2)
    assert omega == pytest.approx(math.sqrt(k / mu), rel=1e-15)
    x1, x2, v1, v2 = hy.make_vars("x1", "x2", "v1", "v2")
    stretch = x2 - x1
    equations = [(x1, v1), (x2, v2), (v1, k * stretch / m1), (v2, -k * stretch / m2)]
    relative_speed = amplitude * omega
    ta = integrator(equations, [0.0, 0.0, -relative_speed * m2 / (m1 + m2), relative_speed * m1 / (m1 + m2)])
    times = np.linspace(0.0, 4 * math.pi / omega, 97)
    states = ta.propagate_grid(times)[-1]
    y = states[:, 1] - states[:, 0]
    assert np.max(np.abs(y - amplitude * np.sin(omega * times))) < 1e-14 * amplitude
    assert np.max(np.abs(states[:, 0] + mu * amplitude / m1 * np.sin(omega * times))) < 1e-14 * amplitude
    kinetic = 0.5 * m1 * states[:, 2] ** 2 + 0.5 * m2 * states[:, 3] ** 2
    potential = 0.5 * k * y**2
    scale = 0.5 * k * amplitude**2
    assert np.max(np.abs(kinetic - scale * np.cos(omega * times) ** 2)) < 1e-14 * scale
    assert np.max(np.abs(potential - scale * np.sin(omega * times) ** 2)) < 1e-14 * scale


@pytest.mark.parametrize("k, b", [(3.0, 1.1), (1.0, 0.01), (4.0, 3.9)])
def test_erratum_91_underdamped_solution(k, b):
    """#91 (correct): x = A e^(-bt/2) sin(w_d t + phi) + C with w_d = sqrt(4k - b**2) / 2 solves x'' = -k (x - C)
    - b x': the frequency against mpmath (measured 0) and the equation with the returned derivatives
    (measured 1.7e-15 of k A e^(-bt/2))."""
    with mpmath.workdps(40):
        exact = mpmath.sqrt(4 * mpmath.mpf(k) - mpmath.mpf(b) ** 2) / 2
    assert float(oscillations.damped_frequency(k, b)) == pytest.approx(float(exact), rel=2.3e-16)
    t = np.linspace(0.0, 10.0, 201)
    x, v, a = oscillations.underdamped_notes(0.7, 0.4, k, b, t)
    envelope = 0.7 * np.exp(-0.5 * b * t)
    assert np.max(np.abs(a + k * x + b * v) / (k * envelope)) < 4e-15


def test_erratum_94_kinetic_and_potential_energy_of_the_damped_oscillator():
    """#94 (correct as printed): K = (m A**2 k / 2) e^(-bt) sin**2(psi + delta'), U = (m A**2 k / 2) e^(-bt)
    sin**2(psi) (sin**2 does not see the notes' pi error in delta); their sum is underdamped_energy_notes
    (measured 1.6e-15 relative)."""
    mass, amplitude, phase, k, b = 1.7, 0.7, 0.4, 3.0, 1.1
    t = np.linspace(0.0, 8.0, 161)
    x, v, _ = oscillations.underdamped_notes(amplitude, phase, k, b, t)
    psi = float(oscillations.damped_frequency(k, b)) * t + phase
    delta_notes = math.atan(-2 * math.sqrt(k - b * b / 4) / b)  # the notes' delta', pi away from the true delta
    scale = 0.5 * mass * amplitude**2 * k * np.exp(-b * t)
    kinetic, potential = 0.5 * mass * v * v, 0.5 * mass * k * x * x
    assert np.max(np.abs(kinetic - scale * np.sin(psi + delta_notes) ** 2) / scale) < 4e-15
    assert np.max(np.abs(potential - scale * np.sin(psi) ** 2) / scale) < 4e-15
    total = oscillations.underdamped_energy_notes(mass, amplitude, phase, k, b, t)
    assert np.max(np.abs((kinetic + potential) / total - 1)) < 4e-15
