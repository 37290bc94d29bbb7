"""Long integrations against the closed form: IAS15 and heyoka over up to 1e4 periods, and the growth laws
of their errors. Spans are 1e4 periods times ORBITS_SLOW_SCALE (0.05 when unset, as in CI: 500 periods; tests/sizes.py).

The errors grow with the span, so each bound is looked up for the span that runs: the tables below hold the
worst error measured (2-core machine, over the test's eccentricities) at spans from 50 to 1e4 periods, and a
span uses the next longer row. Spans beyond 1e4 periods (ORBITS_SLOW_SCALE > 1) have no measured bound and skip.
"""

import numpy as np
import pytest

from orbits.core.twobody import elements
from orbits.core.twobody.propagate import propagate
from orbits.tools import precision
from orbits.validate import backends
from orbits.validate.nbody import NBodyProblem

pytestmark = pytest.mark.slow

#: IAS15 (epsilon 1e-9), e = 0, 0.5, 0.9, 0.99: bounds on (position error / a, |dE / E|, |de|) for runs of up to
#: that many periods. Energy keeps the 3e-13 target of EDGE_CASES.md where it holds; elsewhere each bound is ~10x
#: the worst measured (the comment; e = 0.99 sets position and energy, the LRL vector varies).
IAS15_BOUNDS = {
    500: (2e-8, 3e-13, 4e-14),  # measured 1.9e-9, 2.0e-13 (at 200 periods), 3.7e-15 (over 50..500 periods)
    1000: (4e-8, 3e-13, 4e-14),  # measured 3.8e-9, 1.7e-13, 3.8e-15
    2000: (2e-7, 4e-12, 1e-13),  # measured 1.7e-8, 4.0e-13, 1.0e-14
    5000: (2e-6, 8e-12, 3e-13),  # measured 1.5e-7, 7.4e-13, 2.7e-14
    10000: (3e-6, 8e-12, 3e-13),  # measured 2.4e-7, 6.3e-13, 1.3e-14 (the targets 1e-7 and 3e-13 fail here)
}

#: heyoka (tol = eps, high_accuracy), e = 0, 0.5, 0.9: bounds on (energy and e-vector drift, position error / a).
#: The drift keeps 1000 eps where it holds.
HEYOKA_BOUNDS = {
    500: (1000 * 2.0**-52, 2e-8),  # measured 1.5e-13, 1.7e-9 (e = 0.9, over 50..500 periods)
    1000: (3e-12, 5e-8),  # measured 2.3e-13, 4.2e-9
    2000: (4e-12, 2e-7),  # measured 3.8e-13, 1.5e-8
    5000: (6e-12, 7e-7),  # measured 5.8e-13, 6.4e-8
    10000: (6e-12, 9e-7),  # measured 5.6e-13, 8.2e-8
}


def bounds_for(table, periods):
    """The row of `table` for a run of `periods`: the first span at or above it."""
    spans = [span for span in sorted(table) if span >= periods]
    if not spans:
        pytest.skip(f"{periods} periods: no bound was measured beyond {max(table)} periods (ORBITS_SLOW_SCALE <= 1)")
    return table[spans[0]]


def kepler_run(backend, e, periods, outputs=200, angles=(0.3, 0.2, 0.1), times=None, **settings):
    """Integrate a test particle on an a = 1, mu = 1 orbit; return times, positions, velocities and the
    closed-form positions at the times actually reached."""
    r0, v0 = elements.elements_to_state(1 - e * e, e, *angles, 0.0, 1.0)
    if times is None:
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
    """Position, energy and LRL vector against the closed form, to the bounds of IAS15_BOUNDS for the span."""
    periods = max(50, int(1e4 * slow_scale))
    position_bound, energy_bound, lrl_bound = bounds_for(IAS15_BOUNDS, periods)
    result, exact, (r0, v0) = kepler_run("rebound", e, periods, integrator="ias15", epsilon=1e-9)
    position = np.max(np.linalg.norm(result.positions[:, 1] - exact, axis=-1))
    energy, e_vec = invariants(result.positions[:, 1], result.velocities[:, 1])
    energy0, e_vec0 = invariants(r0, v0)
    energy_drift = np.max(np.abs(energy / energy0 - 1))
    lrl_drift = np.max(np.linalg.norm(e_vec - e_vec0, axis=-1))
    record(f"IAS15 vs closed form, e = {e}, {periods} periods: position / a", 1, position, "")
    record(f"IAS15 vs closed form, e = {e}, {periods} periods: energy", 1, energy_drift, "relative")
    record(f"IAS15 vs closed form, e = {e}, {periods} periods: LRL vector", 1, lrl_drift, "")
    assert position <= position_bound, position
    assert energy_drift <= energy_bound, energy_drift
    assert lrl_drift <= lrl_bound, lrl_drift


@pytest.mark.parametrize("e", [0.0, 0.5, 0.9])
def test_heyoka_at_machine_tolerance(e, slow_scale, record):
    """heyoka with tol = eps and high_accuracy: energy and e-vector drift and position against the closed form,
    to the bounds of HEYOKA_BOUNDS for the span (1000 eps for the drift up to 500 periods)."""
    periods = max(50, int(1e4 * slow_scale))
    drift_bound, position_bound = bounds_for(HEYOKA_BOUNDS, periods)
    result, exact, (r0, v0) = kepler_run("heyoka", e, periods, tol=2.0**-52, high_accuracy=True)
    energy, e_vec = invariants(result.positions[:, 1], result.velocities[:, 1])
    energy0, e_vec0 = invariants(r0, v0)
    drift = max(np.max(np.abs(energy / energy0 - 1)), np.max(np.linalg.norm(e_vec - e_vec0, axis=-1)))
    position = np.max(np.linalg.norm(result.positions[:, 1] - exact, axis=-1))
    record(f"heyoka tol = eps vs closed form, e = {e}: invariants", 1, drift, "relative")
    record(f"heyoka tol = eps vs closed form, e = {e}: position / a", 1, position, "")
    assert drift <= drift_bound, drift
    assert position <= position_bound, position


#: Orientations (inclination, node, argument of periapsis) of the Brouwer ensemble: the same e = 0.5 orbit, each
#: with its own sequence of round-off errors.
BROUWER_ORIENTATIONS = [tuple(angles) for angles in np.random.default_rng(7).uniform(0, 3, (24, 3))]


def test_brouwer_law_for_ias15(slow_scale, record):
    """Round-off makes IAS15's energy error a random walk, |dE| ~ t**0.5 (Brouwer 1937), and its phase error, hence
    the position error, grow as t**1.5. The law holds for the ensemble, not for one run: the exponent fitted to a
    single run is one draw of a noisy statistic (measured over 12 orientations of this orbit at 500 periods:
    energy 0.0 to 1.2, position 0.5 to 3.3; the old single run gave 0.27 and 1.21). So the exponents are fitted
    to the RMS errors of 24 orientations, at outputs spaced evenly in log t from 1 period to the end: position
    over the whole run, energy over its second half in log t (before it the error sits at its round-off floor).
    Measured for 9 such ensembles (8 at 500 periods, 1 at 1e4): energy 0.385 to 0.514, position 1.436 to 1.544
    (1.500 at 1e4 periods); with 12 orientations instead, 17 ensembles of 200 to 1e4 periods spread 0.32 to 0.64
    and 1.42 to 1.55. The windows, [0.3, 0.6] and [1.35, 1.65], are centred on Brouwer's exponents and lie 3.9 and
    4.7 standard deviations of the 24-run exponent (0.038 and 0.031) from its mean (0.451 and 1.494)."""
    periods = max(200, int(1e4 * slow_scale))
    times = 2 * np.pi * np.geomspace(1, periods, 100)
    energy_errors, position_errors = [], []
    for angles in BROUWER_ORIENTATIONS:
        result, exact, (r0, v0) = kepler_run(
            "rebound", 0.5, periods, angles=angles, times=times, integrator="ias15", epsilon=1e-9
        )
        energy, _ = invariants(result.positions[:, 1], result.velocities[:, 1])
        energy_errors.append(energy / invariants(r0, v0)[0] - 1)
        position_errors.append(np.linalg.norm(result.positions[:, 1] - exact, axis=-1))
    energy_rms = np.sqrt(np.mean(np.square(energy_errors), axis=0))
    position_rms = np.sqrt(np.mean(np.square(position_errors), axis=0))
    late = slice(len(times) // 2, None)
    energy_slope = np.polyfit(np.log(times[late]), np.log(energy_rms[late]), 1)[0]
    position_slope = np.polyfit(np.log(times), np.log(position_rms), 1)[0]
    record("IAS15 Brouwer law, RMS of 24 runs: energy error exponent (expect 0.5)", 1, energy_slope, "")
    record("IAS15 Brouwer law, RMS of 24 runs: position error exponent (expect 1.5)", 1, position_slope, "")
    assert 0.3 <= energy_slope <= 0.6, energy_slope
    assert 1.35 <= position_slope <= 1.65, position_slope


def test_whfast_error_on_the_l4_problem_is_bounded_and_second_order(slow_scale, record):
    """Fixed-step WHFast (it is exact for a pure Kepler orbit) on the Earth-Moon L4 particle: the error is a
    bounded O(dt**2) oscillation, with no secular phase drift, because the shadow orbit keeps the primaries'
    exact rotation rate. Measured over 100 to 2000 periods at dt = P/100: max error 1.8e-5 (bound 2e-4), growth
    exponent 0 to 0.072 (bound 0.3), max error 1.07 to 1.58 times that of the first tenth of the run (bound 2),
    order in dt 1.9984 to 2.0002 (bound 2 +- 0.02)."""
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
    assert coarse.max() <= 2e-4, coarse.max()
    assert slope <= 0.3 and coarse.max() <= 2 * coarse[: len(coarse) // 10].max()
    assert 1.98 <= order <= 2.02, order
