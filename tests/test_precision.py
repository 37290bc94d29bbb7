"""Work-precision: the problems' references are right, errors are measured at the true elapsed time,
and the sweep sees accuracy improve with each knob."""

import numpy as np
import pytest

from orbits.core.twobody import elements
from orbits.tools import precision


def test_kepler_reference_and_closed_form_agree_to_rounding():
    problem = precision.kepler_problem(0.9, 3)
    exact = problem.reference(problem.t_end)
    assert np.max(np.abs(problem.analytic(problem.t_end) - exact)) < 1e-13
    # the reference is not the initial state: the run ends 0.37 of a period past the round number
    assert np.linalg.norm(exact[1] - problem.positions[1]) > 0.1


def test_l4_reference_is_a_rigid_rotation_that_keeps_the_equilateral_triangle():
    problem = precision.l4_problem(periods=2)
    r = problem.reference(problem.t_end)
    sides = [np.linalg.norm(r[i] - r[j]) for i, j in ((0, 1), (0, 2), (1, 2))]
    np.testing.assert_allclose(sides, 1.0, rtol=1e-15)
    com = np.sum(problem.gm[:, None] * r, axis=0)
    np.testing.assert_allclose(com, 0.0, atol=1e-16)


def test_binary_problem_has_its_centre_of_mass_at_rest_and_the_right_relative_orbit():
    problem = precision.binary_problem(periods=1)
    assert np.allclose(np.sum(problem.gm[:, None] * problem.velocities, axis=0), 0, atol=4 * 2**-52)  # ~2 ulp of |v|
    rel_r = problem.positions[1] - problem.positions[0]
    rel_v = problem.velocities[1] - problem.velocities[0]
    p, e, *_ = elements.state_to_elements(rel_r, rel_v, 1.0)
    assert e == pytest.approx(0.6, abs=1e-15) and p == pytest.approx(1 - 0.36, rel=1e-15)


def test_sweep_errors_fall_with_the_knob_and_are_measured_against_mpmath():
    problem = precision.flyby_problem()
    chosen = [m for m in precision.methods() if m.name in ("rebound IAS15", "heyoka", "rebound WHFast")]
    rows = precision.run([problem], chosen)
    by_method = {m.name: [r for r in rows if r.method == m.name] for m in chosen}
    assert rows[0].method == "orbits analytic" and rows[0].error < 1e-14
    heyoka = [r.error for r in by_method["heyoka"]]
    assert heyoka[0] > 1e-8 and heyoka[-1] < 1e-13  # tol 1e-6 is visibly worse than tol 1e-18
    ias15 = [r.error for r in by_method["rebound IAS15"]]
    assert ias15[0] > 100 * min(ias15)
    assert all(r.seconds > 0 for r in rows)


def test_whfast_error_is_taken_at_steps_times_dt():
    """A step count that does not divide the span: the error at the reached time, not at t_end, is small."""
    problem = precision.kepler_problem(0.0167, 2)
    method = precision.Method("rebound WHFast", "rebound", "steps per period", (97,), {"integrator": "whfast"})
    row = precision.run([problem], [method])[1]
    assert row.error < 1e-10  # WHFast is exact for a Kepler problem up to round-off, if compared fairly


def test_summary_names_the_fastest_run_at_target():
    rows = [precision.Row("m", "k=1", "p", 1e-6, 0.1), precision.Row("m", "k=2", "p", 1e-11, 0.3),
            precision.Row("m", "k=3", "p", 1e-12, 0.9)]
    (line,) = precision.summary(rows, target=1e-10)
    assert line["best_setting"] == "k=3" and line["fastest_at_target"] == "k=2"


def test_scipy_is_skipped_beyond_its_budget_with_a_note():
    scipy_methods = [m for m in precision.methods() if m.backend == "scipy"]
    if not scipy_methods:
        pytest.skip("scipy is not installed: its method is not offered")
    rows = precision.run([precision.kepler_problem(0.5, 1000)], scipy_methods, scipy_max_periods=200)
    assert all("skipped" in r.note and np.isnan(r.error) for r in rows[1:])
