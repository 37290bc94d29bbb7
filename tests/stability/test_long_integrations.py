"""Long integrations against the closed form: IAS15 and heyoka over up to 1e4 periods, and the growth laws
of their errors. Spans are 1e4 periods times ORBITS_SLOW_SCALE (CI default 0.05: 500 periods)."""

import numpy as np
import pytest

from orbits.core import elements
from orbits.core.propagate import propagate
from orbits.nbody import NBodyProblem
from orbits.tools import precision
from orbits.validate import backends

pytestmark = pytest.mark.slow


def kepler_run(backend, e, periods, outputs=200, **settings):
    """Integrate a test particle on an a = 1, mu = 1 orbit; return times, positions, velocities and the
    closed-form positions at the times actually reached."""
    r0, v0 = elements.elements_to_state(1 - e * e, e, 0.3, 0.2, 0.1, 0.0, 1.0)
    times = np.linspace(0, periods * 2 * np.pi, outputs + 1)[1:]
    problem = NBodyProblem(np.array([1.0, 0.0]), np.array([np.zeros(3), r0]), np.array([np.zeros(3), v0]), 1, times)
    result = backends.integrate(backend, problem, **settings)
    exact, _ = propagate(r0, v0, 1.0, result.times)
    return result, exact, (r0, v0)


def invariants(r, v):
    energy = 0.5 * np.sum(v * v, -1) - 1 / np.linalg.norm(r, axis=-1)
    return energy, elements.eccentricity_vector(r, v, 1.0)


def growth_exponent(times, errors):
    """Slope of log(error) against log(time) over the second half of the run (where the law has set in)."""
    half = slice(len(times) // 2, None)
    keep = errors[half] > 0
    return np.polyfit(np.log(times[half][keep]), np.log(errors[half][keep]), 1)[0]


@pytest.mark.parametrize("e", [0.0, 0.5, 0.9, 0.99])
def test_ias15_over_1e4_periods_against_the_closed_form(e, slow_scale, record):
    """EDGE_CASES 6.3: |dr|/a <= 1e-7, |dE/E| <= 3e-13, |de| <= 1e-13 (measured: 6e-10 .. 6e-8 in position)."""
    periods = max(50, int(1e4 * slow_scale))
    result, exact, (r0, v0) = kepler_run("rebound", e, periods, integrator="ias15", epsilon=1e-9)
    position = np.max(np.linalg.norm(result.positions[:, 1] - exact, axis=-1))
    energy, e_vec = invariants(result.positions[:, 1], result.velocities[:, 1])
    energy0, e_vec0 = invariants(r0, v0)
    energy_drift = np.max(np.abs(energy / energy0 - 1))
    lrl_drift = np.max(np.linalg.norm(e_vec - e_vec0, axis=-1))
    record(f"IAS15 vs closed form, e = {e}, {periods} periods: position / a", 1, position, "")
    record(f"IAS15 vs closed form, e = {e}, {periods} periods: energy", 1, energy_drift, "relative")
    record(f"IAS15 vs closed form, e = {e}, {periods} periods: LRL vector", 1, lrl_drift, "")
    assert position <= 1e-7 and energy_drift <= 3e-13 and lrl_drift <= 1e-13


@pytest.mark.parametrize("e", [0.0, 0.5, 0.9])
def test_heyoka_at_machine_tolerance(e, slow_scale, record):
    """heyoka with tol = eps and high_accuracy: energy and e-vector within 1000 eps over the run."""
    periods = max(50, int(1e4 * slow_scale))
    result, exact, (r0, v0) = kepler_run("heyoka", e, periods, tol=2.0**-52, high_accuracy=True)
    energy, e_vec = invariants(result.positions[:, 1], result.velocities[:, 1])
    energy0, e_vec0 = invariants(r0, v0)
    drift = max(np.max(np.abs(energy / energy0 - 1)), np.max(np.linalg.norm(e_vec - e_vec0, axis=-1)))
    position = np.max(np.linalg.norm(result.positions[:, 1] - exact, axis=-1))
    record(f"heyoka tol = eps vs closed form, e = {e}: invariants", 1, drift, "relative")
    record(f"heyoka tol = eps vs closed form, e = {e}: position / a", 1, position, "")
    assert drift <= 1000 * 2**-52 and position <= 1e-7


def test_brouwer_law_for_ias15(slow_scale, record):
    """Round-off makes IAS15's energy error a random walk, |dE| ~ t**0.5 (Brouwer 1937), and its phase error
    grow as t**1.5; fitted exponents must fall near those laws."""
    periods = max(200, int(1e4 * slow_scale))
    result, exact, (r0, v0) = kepler_run("rebound", 0.5, periods, outputs=400, integrator="ias15", epsilon=1e-9)
    energy, _ = invariants(result.positions[:, 1], result.velocities[:, 1])
    energy_error = np.abs(energy / invariants(r0, v0)[0] - 1)
    running_max = np.maximum.accumulate(energy_error)
    position = np.maximum.accumulate(np.linalg.norm(result.positions[:, 1] - exact, axis=-1))
    energy_slope = growth_exponent(result.times, running_max)
    position_slope = growth_exponent(result.times, position)
    record("IAS15 Brouwer law: energy error exponent (expect 0.5)", 1, energy_slope, "")
    record("IAS15 Brouwer law: position error exponent (expect 1.5)", 1, position_slope, "")
    assert 0.1 <= energy_slope <= 1.0
    assert 0.9 <= position_slope <= 2.3


def test_whfast_error_on_the_l4_problem_is_bounded_and_second_order(slow_scale, record):
    """Fixed-step WHFast (it is exact for a pure Kepler orbit) on the Earth-Moon L4 particle: the error is a
    bounded O(dt**2) oscillation, with no secular phase drift, because the shadow orbit keeps the primaries'
    exact rotation rate. Measured: max error 1.3e-5 at dt = P/100 over 100 periods, flat in time."""
    problem = precision.l4_problem(periods=max(100, int(2000 * slow_scale)))
    times = np.linspace(0, problem.t_end, 201)[1:]
    nbody = NBodyProblem(problem.gm, problem.positions, problem.velocities, problem.n_active, times)

    def errors(steps_per_period):
        result = backends.integrate("rebound", nbody, integrator="whfast", dt=problem.period / steps_per_period)
        return np.array(
            [np.max(np.linalg.norm(p - problem.analytic(t), axis=-1)) for t, p in zip(result.times, result.positions)]
        )

    coarse, fine = errors(100), errors(200)
    slope = growth_exponent(times, np.maximum.accumulate(coarse))
    order = np.log2(coarse.max() / fine.max())
    record("WHFast on the L4 problem: growth exponent in time (bounded: ~0)", 1, slope, "")
    record("WHFast on the L4 problem: order in dt (expect 2)", 1, order, "")
    assert slope <= 0.3 and coarse.max() <= 2 * coarse[: len(coarse) // 10].max()
    assert 1.7 <= order <= 2.3
