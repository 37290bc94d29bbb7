"""Oscillations (notes XXV): the AGM and K(m) against mpmath, pendulums, damped and driven oscillators, the
vertical circle, and every erratum of XXV (integrations against heyoka: tests/validation/)."""

import math

import mpmath
import numpy as np
import pytest

from orbits.core.mechanics import oscillations

G0 = 9.80665


@pytest.mark.parametrize("complement", [1.0, 0.9, 0.5, 1e-2, 1e-5, 1e-10, 1e-16, 1e-300])
def test_complete_elliptic_integral_by_the_agm_against_mpmath(complement):
    """K(m) = pi / (2 AGM(1, sqrt(1 - m))) against mpmath.ellipk(1 - k'**2) at 40 digits: within 2 ulp (measured
    1 ulp) down to k' = 1e-300 (m within 1e-600 of 1)."""
    with mpmath.workdps(700):
        exact = float(mpmath.ellipk(1 - mpmath.mpf(complement) ** 2))
    got = float(oscillations.ellipk_from_complement(complement))
    assert abs(got - exact) <= 2 * math.ulp(exact)
    if complement > 1e-8:
        assert float(oscillations.ellipk(1 - complement**2)) == pytest.approx(exact, rel=1e-15 / complement**2)


@pytest.mark.parametrize("degrees", [0.0, 1e-6, 10.0, 90.0, 170.0, 179.0, 179.999999])
def test_exact_pendulum_period_against_mpmath(degrees):
    """T = 4 K(sin**2(theta0 / 2)) / omega0 (mpmath.ellipk at 40 digits): within 3 ulp (measured 2) up to
    theta0 = 180 - 1e-6 degrees; at small amplitude T -> 2 pi / omega0 = 2 pi sqrt(L / g) (ERRATA #88)."""
    omega0 = math.sqrt(G0 / 0.75)
    theta0 = math.radians(degrees)
    with mpmath.workdps(40):
        exact = float(4 * mpmath.ellipk(mpmath.sin(mpmath.mpf(theta0) / 2) ** 2) / omega0)
    got = float(oscillations.pendulum_period(omega0, theta0))
    assert abs(got - exact) <= 3 * math.ulp(exact)


def test_period_series_converges_to_the_exact_period():
    """1 + theta0**2 / 16 + ... : the series' error falls with each term; at 10 degrees four terms give 1e-9."""
    theta0 = math.radians(10.0)
    exact = float(oscillations.pendulum_period(1.0, theta0)) / (2 * math.pi)
    errors = [abs(float(oscillations.pendulum_period_series(theta0, n)) - exact) for n in (1, 2, 3, 4)]
    assert errors == sorted(errors, reverse=True) and errors[-1] < 1e-9
    assert float(oscillations.pendulum_period_series(theta0, 2)) == pytest.approx(1 + theta0**2 / 16, rel=1e-4)


def test_pendulum_frequencies_with_the_corrected_forms():
    """ERRATA #86: Omega = sqrt(kappa / I); #89-#90: a rod of length l pivoted at an end (I = m l**2 / 3,
    L = l / 2) has omega = sqrt(m g L / I) = sqrt(3 g / (2 l)), whereas the notes' sqrt(I / (m g L)) is its
    reciprocal, a time; XXV.iii: omega = sqrt(k / mu)."""
    m, rod = 2.0, 1.2
    omega = oscillations.physical_pendulum_frequency(m, G0, rod / 2, m * rod**2 / 3)
    assert omega == pytest.approx(math.sqrt(3 * G0 / (2 * rod)), rel=4e-16)
    notes = math.sqrt((m * rod**2 / 3) / (m * G0 * rod / 2))
    assert notes * omega == pytest.approx(1.0)
    assert oscillations.torsion_frequency(8.0, 2.0) == 2.0
    assert oscillations.spring_pair_frequency(12.0, 1.0, 3.0) == pytest.approx(4.0, rel=4e-16)
    point = oscillations.physical_pendulum_frequency(m, G0, rod, m * rod**2)  # a point mass: the simple pendulum
    assert point == pytest.approx(oscillations.simple_pendulum_frequency(G0, rod), rel=4e-16)


def test_notes_underdamped_example():
    """ERRATA #92, #93: k = 3, b = 1.1, A = 0.7, phi = 0.4, t = 0.3 gives x' = 0.357268 and x'' = -1.779677; the
    notes' arctan phase gives -0.357268 and -0.618807. The corrected forms are the derivatives (mpmath.diff)."""
    k, b, amplitude, phase, t = 3.0, 1.1, 0.7, 0.4, 0.3
    x, v, a = oscillations.underdamped_notes(amplitude, phase, k, b, t)
    assert round(float(v), 6) == 0.357268 and round(float(a), 6) == -1.779677
    wd = math.sqrt(4 * k - b * b) / 2
    psi = wd * t + phase
    text = math.atan(-math.sqrt(4 * k - b * b) / b)
    envelope = amplitude * math.exp(-b * t / 2)
    assert round(envelope * math.sqrt(k) * math.sin(psi + text), 6) == -0.357268
    assert round(envelope * k * math.sin(psi + text), 6) == -0.618807
    with mpmath.workdps(30):
        def position(s):
            return amplitude * mpmath.exp(-b * s / 2) * mpmath.sin(wd * s + phase)

        assert float(mpmath.diff(position, t)) == pytest.approx(float(v), rel=1e-15)
        assert float(mpmath.diff(position, t, 2)) == pytest.approx(float(a), rel=1e-15)


def test_notes_damped_energy_is_exact_with_the_correction():
    """ERRATA #95: K + U = (m A**2 k / 2) e^(-bt) [1 + (b / (2 sqrt k)) cos(2 psi + delta)], equal to
    m x'**2 / 2 + m k x**2 / 2; the notes' e^(-bt) form is off by b / (2 sqrt k) in relative terms."""
    m, k, b, amplitude, phase = 1.5, 3.0, 1.1, 0.7, 0.4
    t = np.linspace(0, 4, 9)
    x, v, _ = oscillations.underdamped_notes(amplitude, phase, k, b, t)
    energy = 0.5 * m * v**2 + 0.5 * m * k * x**2
    np.testing.assert_allclose(oscillations.underdamped_energy_notes(m, amplitude, phase, k, b, t), energy,
                               rtol=1e-14)
    notes = 0.5 * m * amplitude**2 * k * np.exp(-b * t)
    assert np.max(np.abs(notes / energy - 1)) > 0.25


def test_notes_critical_and_overdamped_derivatives():
    """ERRATA #96, #97 (critical x' and x'' corrected) and #98 (overdamped, correct): against mpmath.diff."""
    t = 0.8
    with mpmath.workdps(30):
        amplitude, rate, b = 1.2, -0.8, 2.0
        x, v, a = oscillations.critically_damped_notes(amplitude, rate, b, t)

        def critical(s):
            return amplitude * (1 + rate * s) * mpmath.exp(-b * s / 2)

        assert float(mpmath.diff(critical, t)) == pytest.approx(float(v), rel=1e-15)
        assert float(mpmath.diff(critical, t, 2)) == pytest.approx(float(a), rel=1e-15)
        notes_v = amplitude * (rate - b * (1 + rate * t)) / 2 * math.exp(-b * t / 2)
        assert abs(notes_v - float(v)) > 0.1
        amplitude, ratio, k, b = 0.5, 1.5, 2.0, 5.0
        x, v, a = oscillations.overdamped_notes(amplitude, ratio, k, b, t)
        root = mpmath.sqrt(b * b - 4 * k)

        def over(s):
            return amplitude * mpmath.exp(-b * s / 2) * (mpmath.exp(root / 2 * s) + ratio * mpmath.exp(-root / 2 * s))

        assert float(mpmath.diff(over, t)) == pytest.approx(float(v), rel=1e-14)
        assert float(mpmath.diff(over, t, 2)) == pytest.approx(float(a), rel=1e-14)


def exact_damped(k, b, x0, v0, t):
    """x(t) of x'' + b x' + k x = 0 at 50 digits from the characteristic roots (complex when underdamped), with
    the repeated-root form at b**2 = 4k."""
    with mpmath.workdps(50):
        k, b, x0, v0, t = (mpmath.mpf(z) for z in (k, b, x0, v0, t))
        disc = b * b - 4 * k
        if disc == 0:
            lam = -b / 2
            return float((x0 + (v0 - lam * x0) * t) * mpmath.exp(lam * t))
        root = mpmath.sqrt(mpmath.mpc(disc))
        l1, l2 = (-b + root) / 2, (-b - root) / 2
        c1 = (v0 - l2 * x0) / (l1 - l2)
        c2 = x0 - c1
        return float(mpmath.re(c1 * mpmath.exp(l1 * t) + c2 * mpmath.exp(l2 * t)))


@pytest.mark.parametrize("k, b", [(3.0, 1.1), (1.0, 2.0), (1.0, 2.0 + 1e-10), (1.0, 2.0 - 1e-10), (2.0, 7.0),
                                  (1.0, 1e4), (100.0, 0.0)])
def test_damped_motion_against_mpmath_in_every_regime(k, b):
    """The one formula for all regimes against the 50-digit solution: within 1.5e-15 of the initial scale, also
    1e-10 from critical damping, where the textbook forms divide by ~0 (measured 1.2e-16)."""
    x0, v0 = 0.7, -1.3
    scale = max(abs(x0), abs(v0) / math.sqrt(k))
    for t in (0.0, 0.3, 2.0, 9.0, 500.0):
        got, _ = oscillations.damped_motion(k, b, x0, v0, t)
        assert abs(float(got) - exact_damped(k, b, x0, v0, t)) < 1.5e-15 * scale


def test_damped_motion_is_continuous_across_critical_damping_and_its_regimes_are_named():
    t = np.linspace(0, 10, 11)
    below, above = (oscillations.damped_motion(1.0, 2.0 + d, 1.0, 0.0, t)[0] for d in (-1e-12, 1e-12))
    assert np.max(np.abs(below - above)) < 1e-11
    assert list(oscillations.damping_regime(1.0, [1.0, 2.0, 3.0])) == [0, 1, 2]
    assert oscillations.damped_frequency(3.0, 1.1) == pytest.approx(math.sqrt(4 * 3.0 - 1.21) / 2, rel=4e-16)


def test_driven_oscillator_resonances():
    """XXV.vii, ERRATA #106: the velocity amplitude peaks at w = omega0 (F0 / (m b) there) for every damping;
    the displacement amplitude peaks at sqrt(omega0**2 - b**2 / 2); the phase lag is pi/2 at w = omega0."""
    omega0, force = 2.0, 1.5
    w = np.linspace(0.01, 6.0, 200001)
    for b in (0.05, 0.5, 2.0):
        velocity = oscillations.driven_velocity_amplitude(omega0, b, force, w)
        assert w[np.argmax(velocity)] == pytest.approx(omega0, abs=1e-4)
        assert float(oscillations.driven_velocity_amplitude(omega0, b, force, omega0)) == pytest.approx(force / b,
                                                                                                      rel=4e-16)
        amplitude = oscillations.driven_amplitude(omega0, b, force, w)
        assert w[np.argmax(amplitude)] == pytest.approx(oscillations.displacement_resonance(omega0, b), abs=1e-4)
        assert oscillations.driven_phase_lag(omega0, b, omega0) == pytest.approx(math.pi / 2, rel=4e-16)
    assert oscillations.displacement_resonance(1.0, 2.0) == 0.0  # no peak when b**2 >= 2 omega0**2


def test_vertical_circle_thresholds_and_forces():
    """ERRATA #99-#105: v at the bottom is u; at the top N = m (u**2 - 5 g R) / R, so a string stays taut over
    the top from u = sqrt(5 g R) (the notes' N gives sqrt(3 g R)); theta'' = -(g / R) sin(theta); theta_m =
    arccos(1 - u**2 / (2 g R)); the string slackens between pi/2 and pi; a rod just reaches the top at 2 sqrt(gR)."""
    g, radius, m = G0, 1.2, 0.4
    five = math.sqrt(5 * g * radius)
    assert oscillations.circle_speed(five, g, radius, 0.0) == five  # ERRATA #103: u at the lowest point
    assert abs(oscillations.circle_normal_force(m, five, g, radius, math.pi)) < 1e-14 * m * g  # ERRATA #101
    top = oscillations.circle_normal_force(m, 2 * five, g, radius, math.pi)
    assert top == pytest.approx(m * ((2 * five) ** 2 - 5 * g * radius) / radius, rel=1e-15)
    notes_top = m / radius * (five**2 - 2 * g * radius + g * radius * math.cos(math.pi))
    assert notes_top == pytest.approx(2 * m * g)  # the notes' N is not 0 at u = sqrt(5 g R)
    assert oscillations.circle_angular_acceleration(g, radius, 0.5) < 0  # ERRATA #100: restoring
    u = math.sqrt(0.5 * g * radius)  # theta_m = arccos(3/4)
    assert oscillations.turning_angle(u, g, radius) == pytest.approx(math.acos(1 - u**2 / (2 * g * radius)))
    assert oscillations.turning_angle(u, g, radius) == pytest.approx(math.acos(0.75), rel=4e-16)
    assert math.acos(u**2 / (2 * g * radius)) == pytest.approx(math.acos(0.25))  # ERRATA #102: the notes' form
    for ratio in (1.5, 2.0, 2.2):  # between sqrt(2) and sqrt(5)
        angle = oscillations.leaving_angle(ratio * math.sqrt(g * radius), g, radius)
        assert math.pi / 2 < angle < math.pi  # ERRATA #104
        assert abs(oscillations.circle_normal_force(m, ratio * math.sqrt(g * radius), g, radius, angle)) < 1e-14
    assert math.isnan(oscillations.leaving_angle(five * 1.01, g, radius))
    edge = 2 * math.sqrt(g * radius)
    assert oscillations.turning_angle(edge, g, radius) == math.pi  # ERRATA #105: reaches the top, asymptotically
    assert oscillations.circle_speed(edge, g, radius, math.pi) == 0.0


@pytest.mark.parametrize("ratio", [0.1, 1.0, 1.99, 2.01, 3.0, 10.0])
def test_loop_and_swing_periods_against_the_notes_integrals(ratio):
    """ERRATA #99: T1 = R int_0^2pi d theta / v and T2 = 4 R int_0^theta_m d theta / v (mpmath.quad at 30 digits)
    equal the AGM forms within 4 ulp away from the separatrix u = 2 sqrt(g R) (measured 1); near it the rounding of
    u - 2 sqrt(g R) is amplified (measured 14 ulp at u = 1.99 sqrt(g R), 9 at 2.01)."""
    g, radius = G0, 0.9
    speed = ratio * math.sqrt(g * radius)
    with mpmath.workdps(30):
        u, gr = mpmath.mpf(speed), mpmath.mpf(g) * mpmath.mpf(radius)

        def inverse_speed(theta):
            return radius / mpmath.sqrt(u**2 - 2 * gr * (1 - mpmath.cos(theta)))

        if ratio > 2:
            exact = float(mpmath.quad(inverse_speed, [0, mpmath.pi, 2 * mpmath.pi]))
            got = float(oscillations.loop_period(speed, g, radius))
        else:
            theta_m = 2 * mpmath.asin(u / (2 * mpmath.sqrt(gr)))
            exact = float(4 * mpmath.quad(inverse_speed, [0, theta_m]))
            got = float(oscillations.swing_period(speed, g, radius))
    conditioning = 1 + 0.1 * 2 / abs(2 - ratio)  # the rounding of u - 2 sqrt(g R), amplified near the separatrix
    assert abs(got - exact) <= 4 * conditioning * math.ulp(exact)


@pytest.mark.parametrize("degrees", [1.0, 10.0, 60.0, 120.0, 170.0, 179.0, 179.9])
def test_exact_pendulum_angle_against_mpmath_jacobi_functions(degrees):
    """theta(t) = 2 asin(k sn(omega0 t + K, k**2)) (released from rest at theta0, k = sin(theta0 / 2)) against
    mpmath's ellipfun at 40 digits over three periods: within 1e-13 theta0 (measured 9.7e-15 at 179 deg, 2-5e-15
    elsewhere)."""
    theta0, omega0 = math.radians(degrees), 1.3
    t = np.linspace(0.0, 3 * float(oscillations.pendulum_period(omega0, theta0)), 61)
    theta = oscillations.pendulum_angle(omega0, theta0, t)
    with mpmath.workdps(40):
        k = mpmath.sin(mpmath.mpf(theta0) / 2)
        quarter = mpmath.ellipk(k * k)
        exact = [2 * mpmath.asin(k * mpmath.ellipfun("sn", omega0 * mpmath.mpf(float(s)) + quarter, m=k * k))
                 for s in t]
        worst = max(abs(mpmath.mpf(float(a)) - b) for a, b in zip(theta, exact))
    assert float(worst) < 1e-13 * theta0
