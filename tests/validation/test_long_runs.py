"""Runs that used to hang or end in a traceback: rings about a dominant central mass in both backends, a backend
that blows up (a failed check with the reason), and the output grid lookup in linear time."""

import dataclasses
import math

import numpy as np
import pytest

from orbits.validate import backends, run, scenes
from orbits.validate.builders import ring_problem
from orbits.validate.scenes import _nearest

pytestmark = pytest.mark.skipif(not (backends.available("rebound") and backends.available("heyoka")),
                                reason="needs rebound and heyoka")

SETTINGS = {"rebound": {"adaptive_mode": "global"}, "heyoka": {"tol": 1e-16}}


@pytest.mark.parametrize("backend", ["rebound", "heyoka"])
def test_a_ring_stabilised_by_a_central_mass_keeps_its_shape(backend):
    """7 bodies about 1000 times their mass (above the threshold for n = 7): 50 periods, the chords stay exact
    to round-off. IAS15 needs its global step rule here (PRS23 stalls: orbits.validate._rebound)."""
    problem, expected = ring_problem(7, np.linspace(0, 100 * np.pi, 400)[1:], 1000.0)
    result = backends.integrate(backend, problem, **SETTINGS[backend])
    assert np.max(expected.shape_deviations(result.positions)) < 2.5e-12  # measured 8e-14 (rebound), 2.4e-13 (heyoka)


@pytest.mark.parametrize("backend", ["rebound", "heyoka"])
@pytest.mark.parametrize("n, central_ratio", [(8, 100.0), (7, 5.0)])
def test_a_ring_below_the_threshold_breaks_up_when_predicted(backend, n, central_ratio):
    _, probe = ring_problem(n, [1.0], central_ratio)
    problem, expected = ring_problem(n, np.linspace(0, 2.5 * probe.breakup_time, 400)[1:], central_ratio)
    result = backends.integrate(backend, problem, **SETTINGS[backend])
    ratio = expected.measured_breakup_time(result.times, result.positions) / expected.breakup_time
    assert abs(math.log(ratio)) < 0.15  # measured 0.94-1.05 (|ln| <= 0.062); the output grid resolves 0.6 %


def test_an_integration_that_blows_up_is_a_failed_check_with_the_reason(monkeypatch):
    def blow_up(problem, **settings):
        raise RuntimeError("propagation stopped at t = 3: err_nf_state\nsecond line")

    broken = dataclasses.replace(backends.BACKENDS["heyoka"], integrate=blow_up)
    monkeypatch.setitem(backends.BACKENDS, "heyoka", broken)
    report = run.validate([scenes.load("circular")])
    scene = report.scenes[0]
    assert not report.passed and scene.time_modes["heyoka"].startswith("failed: RuntimeError")
    failed = [c for c in scene.checks if not c.passed]
    assert [c.quantity for c in failed] == ["heyoka integration failed: RuntimeError: propagation stopped at t = 3: "
                                            "err_nf_state"]
    assert all(c.passed for c in scene.checks if c is not failed[0])  # rebound's checks still ran


def test_the_nearest_output_time_is_found_by_bisection():
    rng = np.random.default_rng(1)
    grid = np.unique(rng.uniform(0, 1e6, 5000))
    times = np.concatenate([grid[::7], rng.uniform(-10, 1e6 + 10, 2000), np.nextafter(grid[::11], np.inf)])
    brute = np.array([np.argmin(np.abs(grid - t)) for t in times])
    found = _nearest(grid, times)
    assert np.all(np.abs(grid[found] - times) == np.abs(grid[brute] - times))
    assert list(_nearest(grid[:1], [5.0, -1.0])) == [0, 0]


@pytest.mark.parametrize("backend", ["rebound", "heyoka"])
def test_integrations_report_their_progress(backend):
    """What the command line's live bar shows: fractions of the span that only grow and end at 1."""
    from orbits.validate.nbody import reporting

    problem, _ = ring_problem(7, np.linspace(0, 2000 * np.pi, 400)[1:], 1000.0)
    seen = []
    with reporting(seen.append):
        backends.integrate(backend, problem, **SETTINGS[backend])
    assert seen[-1] == 1.0 and all(a <= b for a, b in zip(seen, seen[1:])) and 0 < seen[0] < 1


def test_a_span_of_more_than_a_million_periods_is_refused_at_load_time(tmp_path):
    """A 90-minute orbit for 1e12 yr would run for days: refused before anything runs."""
    from orbits.core.errors import SceneError
    from orbits.validate.scene import BUILTIN_DIR

    source = (BUILTIN_DIR / "circular.toml").read_text()
    path = tmp_path / "long.toml"
    path.write_text(source.replace("periods = 100", 'span = "1e12 yr"').replace("outputs = 200", "outputs = 10"))
    with pytest.raises(SceneError, match=r"time.span: a run of 3.15576e\+19 s is 5.\d+e\+15 periods of the fastest "
                                         r"orbit \('Earth' and 'satellite', period 5828.52 s\).*at most 1e\+06"):
        scenes.load(path)
