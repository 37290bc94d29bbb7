"""Lagrange points and rings integrated with rebound (IAS15) and heyoka (Taylor): the linear predictions of
orbits.core.lagrange and orbits.core.rings against what the N-body codes do.

Measured on the 2-core machine (both backends): collinear points depart at the eigenvalue rate to 1e-5 and
L4/L5 of a mu = 0.1 pair (beyond Routh's ratio) to 0.6 %; round-off alone carries L1..L3 to a 1e-3 departure
at 0.88-1.23 times the predicted time; Earth-Moon L4/L5 particles stay within 7e-14 of the points for 100
periods; every Jacobi constant holds to 9e-15; rings of 3 to 8 bodies break up at 1.02-1.10 times the time
predicted for a 1e-16 seed, and Maxwell rings (heyoka) at 0.89-0.95 times.
"""

import math

import numpy as np
import pytest

from orbits.core import lagrange as lagrange_core
from orbits.validate import backends
from orbits.validate.builders import fitted_growth_rate, lagrange_test_particles_problem, ring_problem

EARTH_MOON = 0.012150584269940356
SETTINGS = {"rebound": {"integrator": "ias15", "epsilon": 1e-9}, "heyoka": {"tol": 1e-16, "high_accuracy": True}}
BACKENDS = [
    pytest.param(name, marks=pytest.mark.skipif(not backends.available(name), reason=f"{name} missing"))
    for name in SETTINGS
]


def integrate(backend, problem):
    return backends.integrate(backend, problem, **SETTINGS[backend])


def jacobi_drift(expectation, result):
    c = expectation.jacobi_constants(result.positions, result.velocities)
    return np.max(np.abs(c - expectation.jacobi_constant)) / abs(expectation.jacobi_constant)


@pytest.mark.parametrize("backend", BACKENDS)
@pytest.mark.parametrize("mu", [EARTH_MOON, 0.1])
def test_unstable_points_depart_at_the_eigenvalue_rate(backend, mu):
    """A particle 1e-10 off each unstable point, along its growing mode, until 1e-4: the fitted e-folding rate
    matches the largest Re(lambda) within 3 % (L1..L3 always; L4, L5 only beyond Routh's ratio)."""
    unstable = [p for p, rate in zip(lagrange_core.POINTS, lagrange_core.growth_rates(mu)) if rate > 0]
    assert unstable == (["L1", "L2", "L3"] if mu == EARTH_MOON else list(lagrange_core.POINTS))
    for point in unstable:
        _, (probe,) = lagrange_test_particles_problem(mu, [0.0, 1.0], [point])
        horizon = math.log(1e-4 / 1e-10) / probe.growth_rate
        problem, (expected,) = lagrange_test_particles_problem(mu, np.linspace(0, horizon, 400), [point], 1e-10)
        result = integrate(backend, problem)
        rate = fitted_growth_rate(result.times, expected.deviations(result.positions))
        assert abs(rate / expected.growth_rate - 1) < 0.03, (point, rate, expected.growth_rate)
        assert jacobi_drift(expected, result) < 1e-12


@pytest.mark.parametrize("backend", BACKENDS)
def test_earth_moon_triangular_points_stay_put_for_100_periods(backend):
    problem, expectations = lagrange_test_particles_problem(EARTH_MOON, np.linspace(0, 200 * np.pi, 401), ["L4", "L5"])
    assert all(e.growth_rate == 0.0 and e.offset == 0.0 for e in expectations)
    result = integrate(backend, problem)
    for expected in expectations:
        assert np.max(expected.deviations(result.positions)) < 1e-11
        assert jacobi_drift(expected, result) < 1e-12


@pytest.mark.parametrize("backend", BACKENDS)
def test_round_off_alone_carries_the_collinear_points_away_on_time(backend):
    """Started on the float64 point (an error of 1e-16), L1..L3 reach a 1e-3 departure within a factor 2 of
    ln(1e-3 / 1e-16) / lambda."""
    for point in ("L1", "L2", "L3"):
        _, (probe,) = lagrange_test_particles_problem(EARTH_MOON, [0.0, 1.0], [point])
        predicted = math.log(1e-3 / 1e-16) / probe.growth_rate
        problem, (expected,) = lagrange_test_particles_problem(EARTH_MOON, np.linspace(0, 2 * predicted, 800), [point])
        result = integrate(backend, problem)
        reached = np.flatnonzero(expected.deviations(result.positions) >= 1e-3)
        assert reached.size and 0.5 < result.times[reached[0]] / predicted < 2, point


@pytest.mark.parametrize("backend", BACKENDS)
@pytest.mark.parametrize("n", range(3, 9))
def test_rings_hold_their_shape_until_the_predicted_breakup(backend, n):
    """A ring of n equal masses (no central mass, unstable for n >= 3) started from its exact state keeps its
    shape to 1e-9 for a third of the predicted break-up time, then deforms by 1e-3 within a factor 2 of it."""
    _, probe = ring_problem(n, [0.0, 1.0])
    problem, expected = ring_problem(n, np.linspace(0, 2 * probe.breakup_time, 800))
    result = integrate(backend, problem)
    deviations = expected.shape_deviations(result.positions)
    assert np.max(deviations[result.times < expected.breakup_time / 3]) < 1e-9
    measured = expected.measured_breakup_time(result.times, result.positions)
    assert 0.5 < measured / expected.breakup_time < 2, (measured, expected.breakup_time)


@pytest.mark.slow
@pytest.mark.parametrize("n, factor", [(7, 0.8), (7, 1.25), (6, None)])
def test_maxwell_rings_with_heyoka(n, factor):
    """Rings about a central mass, heyoka only: rebound's IAS15 (adaptive_mode PRS23, as the adapter pins it)
    stalls with steps of 1e-17 because the central body's acceleration is pure round-off. Below the
    threshold (and for n = 6 at any mass) the ring breaks up within a factor 2 of the prediction; above it,
    it keeps its shape to 1e-8 for 30 periods."""
    from orbits.core import rings

    pytest.importorskip("heyoka")
    beta = 100.0 if factor is None else factor * rings.central_mass_threshold(n)
    _, probe = ring_problem(n, [0.0, 1.0], beta)
    span = 60 * np.pi if math.isinf(probe.breakup_time) else 2 * probe.breakup_time
    problem, expected = ring_problem(n, np.linspace(0, span, 800), beta)
    result = integrate("heyoka", problem)
    if math.isinf(expected.breakup_time):
        assert np.max(expected.shape_deviations(result.positions)) < 1e-8
    else:
        measured = expected.measured_breakup_time(result.times, result.positions)
        assert 0.5 < measured / expected.breakup_time < 2, (measured, expected.breakup_time)
