"""Validation backends (rebound IAS15/WHFast, heyoka Taylor) against analytic and mpmath Kepler references."""

from __future__ import annotations

import math
import re
import subprocess
import sys

import mpmath
import numpy as np
import pytest

from orbits.core.errors import OrbitDomainError
from orbits.validate import _heyoka, _rebound, backends
from orbits.validate.nbody import Kick, NBodyProblem

TWO_PI = 2.0 * math.pi
DT = TWO_PI / 100.0

CONFIGS = {
    "ias15": ("rebound", {"integrator": "ias15", "epsilon": 1e-9}),
    "whfast": ("rebound", {"integrator": "whfast", "dt": DT}),
    "heyoka": ("heyoka", {"tol": 1e-16, "high_accuracy": True}),
}


def run(config: str, problem: NBodyProblem):
    """Integrate ``problem`` with one of CONFIGS through the public registry."""
    name, settings = CONFIGS[config]
    return backends.integrate(name, problem, **settings)


def kepler_reference(r0, v0, mu, times, digits: int = 30) -> np.ndarray:
    """Positions at ``times`` of the two-body relative orbit from (r0, v0) under ``mu``, via mpmath.

    Elliptic f and g functions: the eccentric-anomaly change dE solves
    n t = dE - (1 - r0/a) sin dE + (r0.v0 / sqrt(mu a)) (1 - cos dE), solved by findroot at ``digits`` digits
    starting from the exact float64 initial state, so initial-condition rounding is not counted as error.
    """
    with mpmath.workdps(digits):
        r0 = [mpmath.mpf(float(c)) for c in r0]
        v0 = [mpmath.mpf(float(c)) for c in v0]
        mu = mpmath.mpf(float(mu))
        rn = mpmath.sqrt(sum(c * c for c in r0))
        a = 1 / (2 / rn - sum(c * c for c in v0) / mu)
        n = mpmath.sqrt(mu / a**3)
        ecos, esin = 1 - rn / a, sum(p * q for p, q in zip(r0, v0)) / mpmath.sqrt(mu * a)
        out = []
        for t in times:
            mean = n * mpmath.mpf(float(t))
            turns = mpmath.floor(mean / (2 * mpmath.pi))
            m = mean - 2 * mpmath.pi * turns
            de = mpmath.findroot(lambda x, m=m: x - ecos * mpmath.sin(x) + esin * (1 - mpmath.cos(x)) - m, m)
            f = 1 - a / rn * (1 - mpmath.cos(de))
            g = mpmath.mpf(float(t)) - (de + 2 * mpmath.pi * turns - mpmath.sin(de)) / n
            out.append([float(f * p + g * q) for p, q in zip(r0, v0)])
    return np.array(out)


def circular_problem(times, central_gm: float = 1.0) -> NBodyProblem:
    """Central mass at rest at the origin and a test particle on the unit circle in the xy plane."""
    return NBodyProblem(
        gm=[central_gm, 0.0],
        positions=[[0.0, 0.0, 0.0], [1.0, 0.0, 0.0]],
        velocities=[[0.0, 0.0, 0.0], [0.0, math.sqrt(central_gm), 0.0]],
        n_active=1,
        times=times,
    )


def rotation(inclination: float, node: float) -> np.ndarray:
    """Rotation taking the xy plane to a plane of the given inclination and ascending node."""
    ci, si, cn, sn = math.cos(inclination), math.sin(inclination), math.cos(node), math.sin(node)
    return np.array([[cn, -sn, 0.0], [sn, cn, 0.0], [0.0, 0.0, 1.0]]) @ np.array(
        [[1.0, 0.0, 0.0], [0.0, ci, -si], [0.0, si, ci]]
    )


def eccentric_binary(times) -> NBodyProblem:
    """Star (gm 1) and planet (gm 1e-3) on an e = 0.5, a = 1 relative orbit, tilted, with a drifting barycentre."""
    gm = np.array([1.0, 1e-3])
    mu, e = gm.sum(), 0.5
    rot = rotation(0.5, 0.7)
    rel_r = rot @ [1.0 - e, 0.0, 0.0]
    rel_v = rot @ [0.0, math.sqrt(mu * (1.0 + e) / (1.0 - e)), 0.0]
    com_r, com_v = np.array([0.1, -0.2, 0.05]), np.array([1e-3, -2e-3, 5e-4])
    positions = [com_r - gm[1] / mu * rel_r, com_r + gm[0] / mu * rel_r]
    velocities = [com_v - gm[1] / mu * rel_v, com_v + gm[0] / mu * rel_v]
    return NBodyProblem(gm=gm, positions=positions, velocities=velocities, n_active=2, times=times)


def three_body(times) -> NBodyProblem:
    """Star and two non-crossing eccentric, mutually inclined planets (a ~ 1.1 and ~ 2.4)."""
    return NBodyProblem(
        gm=[1.0, 1e-3, 3e-4],
        positions=[[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, -2.5, 0.1]],
        velocities=[[0.0, 0.0, 0.0], [0.0, 1.05, 0.02], [0.97 * math.sqrt(0.4), 0.0, 0.0]],
        n_active=3,
        times=times,
    )


def energy(gm, positions, velocities) -> np.ndarray:
    """Total energy (G = 1) at each output of (K, N, 3) arrays; bodies with gm = 0 contribute nothing."""
    kinetic = 0.5 * np.einsum("i,kij,kij->k", gm, velocities, velocities)
    potential = np.zeros(len(positions))
    for i in range(len(gm)):
        for j in range(i + 1, len(gm)):
            potential -= gm[i] * gm[j] / np.linalg.norm(positions[:, i] - positions[:, j], axis=-1)
    return kinetic + potential


@pytest.fixture
def heyoka_cache_dir(tmp_path, monkeypatch):
    """Point HEYOKA_CACHE_DIR at a temporary directory; restore heyoka's disk-cache path afterwards."""
    heyoka = pytest.importorskip("heyoka")
    original = heyoka.llvm_state.get_diskcache_path()
    monkeypatch.setenv("HEYOKA_CACHE_DIR", str(tmp_path))
    yield tmp_path
    heyoka.llvm_state.set_diskcache_path(original)


@pytest.mark.parametrize("config", CONFIGS)
def test_circular_orbit_matches_exact_circle(config):
    """(a) Test particle on the unit circle around gm = 1: r(t) = (cos t, sin t, 0) over 10 periods."""
    result = run(config, circular_problem(np.linspace(0.0, 10 * TWO_PI, 41)))
    t = result.times
    assert result.positions.shape == (41, 2, 3)
    np.testing.assert_allclose(result.times, np.linspace(0.0, 10 * TWO_PI, 41), rtol=0, atol=DT / 2)
    exact_r = np.stack([np.cos(t), np.sin(t), np.zeros_like(t)], axis=-1)
    exact_v = np.stack([-np.sin(t), np.cos(t), np.zeros_like(t)], axis=-1)
    assert np.abs(result.positions[:, 1] - exact_r).max() < 1e-10
    assert np.abs(result.velocities[:, 1] - exact_v).max() < 1e-10
    assert np.array_equal(result.positions[:, 0], np.zeros((41, 3)))


@pytest.mark.parametrize("config", CONFIGS)
def test_eccentric_binary_matches_mpmath_kepler(config):
    """(b) e = 0.5 star-planet pair over 100 periods: each body within 1e-9 (relative) of the mpmath orbit."""
    times = np.linspace(0.0, 100 * TWO_PI, 51)[1:] + 0.123
    problem = eccentric_binary(times)
    result = run(config, problem)
    gm = problem.gm
    rel = kepler_reference(
        problem.positions[1] - problem.positions[0],
        problem.velocities[1] - problem.velocities[0],
        gm.sum(),
        result.times,
    )
    com = (gm @ problem.positions + np.outer(result.times, gm @ problem.velocities)) / gm.sum()
    expected = np.stack([com - gm[1] / gm.sum() * rel, com + gm[0] / gm.sum() * rel], axis=1)
    scale = np.linalg.norm(rel, axis=-1)[:, None]
    error = np.linalg.norm(result.positions - expected, axis=-1) / scale
    assert error.max() < 1e-9
    assert np.linalg.norm(rel[0] - rel[-1]) > 0.1  # the sampled states really are spread along the orbit


@pytest.mark.parametrize("config", CONFIGS)
def test_energy_and_angular_momentum_are_conserved(config):
    """(c) Three massive bodies over 20 periods: energy and angular momentum drift, kinetic energy swings."""
    problem = three_body(np.linspace(0.0, 20 * TWO_PI, 41))
    result = run(config, problem)
    total = energy(problem.gm, result.positions, result.velocities)
    kinetic = 0.5 * np.einsum("i,kij,kij->k", problem.gm, result.velocities, result.velocities)
    momentum = np.einsum("i,kij->kj", problem.gm, np.cross(result.positions, result.velocities))
    energy_tol = 1e-6 if config == "whfast" else 1e-13  # WHFast: bounded O(dt^2) oscillation, not drift
    assert np.abs(total / total[0] - 1.0).max() < energy_tol
    assert np.linalg.norm(momentum - momentum[0], axis=-1).max() < 1e-13 * np.linalg.norm(momentum[0])
    assert np.ptp(kinetic) > 1e-2 * kinetic[0]


@pytest.mark.parametrize("config", CONFIGS)
def test_test_particle_does_not_perturb_massive_bodies(config):
    """(d) Adding a massless particle leaves the massive trajectories unchanged; a 1e-9 mass visibly does not."""
    times = np.linspace(0.0, 10 * TWO_PI, 21)
    base = three_body(times)
    pair = NBodyProblem(
        gm=base.gm[:2], positions=base.positions[:2], velocities=base.velocities[:2], n_active=2, times=times
    )
    with_particle = NBodyProblem(
        gm=[1.0, 1e-3, 0.0], positions=base.positions, velocities=base.velocities, n_active=2, times=times
    )
    with_small_mass = NBodyProblem(
        gm=[1.0, 1e-3, 1e-9], positions=base.positions, velocities=base.velocities, n_active=3, times=times
    )
    alone = run(config, pair).positions
    beside_particle = run(config, with_particle).positions[:, :2]
    beside_mass = run(config, with_small_mass).positions[:, :2]
    if config == "heyoka":
        # heyoka's step-size control reads every state variable, test particles included, so the step
        # sequence (not the forces) changes; the massive equations hold no test-particle terms.
        assert np.abs(beside_particle - alone).max() < 1e-12
    else:
        assert np.array_equal(beside_particle, alone)
    assert np.abs(beside_mass - alone).max() > 1e-9


def test_whfast_reports_true_time_steps_times_dt():
    """(e) WHFast outputs sit at n * dt (n nearest each request), not at rebound's drifting sim.t."""
    rebound = pytest.importorskip("rebound")
    n_steps = 100_000
    requested = np.array([0.4, 2.6, n_steps + 0.3]) * DT
    result = backends.integrate("rebound", circular_problem(requested), integrator="whfast", dt=DT)
    assert np.array_equal(result.times, np.array([0, 3, n_steps]) * DT)
    assert result.settings["dt"] == DT and "steps x dt" in result.time_mode

    sim = rebound.Simulation()
    sim.add(m=1.0)
    sim.add(m=0.0, x=1.0, vy=1.0)
    sim.integrator = "whfast"
    sim.dt = DT
    sim.steps(n_steps)
    assert abs(sim.t - n_steps * DT) > 1e-9  # rebound's clock has drifted by ~2e-8

    final = result.positions[-1, 1, :2]
    assert np.linalg.norm(final - [math.cos(result.times[-1]), math.sin(result.times[-1])]) < 1e-9
    assert np.linalg.norm(final - [math.cos(sim.t), math.sin(sim.t)]) > 1e-8


def test_ias15_and_heyoka_land_exactly_on_requested_times():
    """IAS15 (exact finish time) and heyoka (propagate_grid) report exactly the requested times."""
    times = np.array([0.3, 1.7, 5.0])
    for config in ("ias15", "heyoka"):
        assert np.array_equal(run(config, circular_problem(times)).times, times)


def test_heyoka_cache_reuses_compiled_integrator(heyoka_cache_dir):
    """(g) Same (N, n_active, tol) reuses the compiled integrator; masses are runtime parameters."""
    heyoka = pytest.importorskip("heyoka")
    _heyoka.clear_cache()
    heyoka.llvm_state.clear_memcache()
    times = np.linspace(0.0, TWO_PI, 9)
    first = _heyoka.integrate(circular_problem(times))
    second = _heyoka.integrate(circular_problem(times))
    heavier = _heyoka.integrate(circular_problem(times, central_gm=4.0))
    assert not first.settings["cache_hit"]
    assert second.settings["cache_hit"] and heavier.settings["cache_hit"]
    assert second.setup_time < 0.05 and second.setup_time < first.setup_time
    assert np.array_equal(first.positions, second.positions)  # reuse leaks no state between calls
    exact = np.stack([np.cos(2 * times), np.sin(2 * times)], axis=-1)  # gm = 4 at r = 1: angular rate 2
    assert np.abs(heavier.positions[:, 1, :2] - exact).max() < 1e-12
    assert str(heyoka.llvm_state.get_diskcache_path()) == str(heyoka_cache_dir)
    assert any(heyoka_cache_dir.iterdir())  # the fresh compile was written to HEYOKA_CACHE_DIR


def test_results_record_backend_metadata():
    """Each result names its backend, integrator, library version and pinned settings."""
    problem = circular_problem([1.0])
    ias15, whfast, heyoka = (run(config, problem) for config in CONFIGS)
    assert (ias15.backend, ias15.integrator, ias15.settings["epsilon"]) == ("rebound", "ias15", 1e-9)
    assert (whfast.integrator, whfast.settings["safe_mode"], whfast.settings["move_to_com"]) == ("whfast", 1, True)
    assert (heyoka.backend, heyoka.settings["tol"], heyoka.settings["high_accuracy"]) == ("heyoka", 1e-16, True)
    assert heyoka.settings["order"] >= 20
    for result in (ias15, whfast, heyoka):
        assert result.version[0].isdigit() and result.wall_time >= 0.0 and result.setup_time >= 0.0


def test_heyoka_raises_on_failed_propagation():
    """A collision (two bodies falling from rest, meeting at t = pi / 4) makes heyoka stop with err_nf_state,
    reported as RuntimeError."""
    problem = NBodyProblem(
        gm=[1.0, 1.0], positions=[[0, 0, 0], [1, 0, 0]], velocities=np.zeros((2, 3)), n_active=2, times=[1.0]
    )
    with pytest.raises(RuntimeError, match="err_nf_state"):
        _heyoka.integrate(problem)


def test_registry_flags_and_lazy_availability():
    """The registry matches the adapters and the installed heyoka build, and probes without importing."""
    heyoka = pytest.importorskip("heyoka")
    assert backends.BACKENDS["rebound"].integrators == _rebound.INTEGRATORS
    assert backends.BACKENDS["heyoka"].supports_extended_precision == (
        hasattr(heyoka, "taylor_adaptive_ldbl") or hasattr(heyoka, "taylor_adaptive_f128")
    )
    assert all(info.supports_test_particles for info in backends.BACKENDS.values())
    probe = (
        "import sys; from orbits.validate import backends; "
        "assert backends.available('rebound') and backends.available('heyoka'); "
        "assert 'rebound' not in sys.modules and 'heyoka' not in sys.modules"
    )
    subprocess.run([sys.executable, "-c", probe], check=True)


def _problem(**changes) -> NBodyProblem:
    """A valid two-body problem with some fields replaced."""
    fields = {
        "gm": [1.0, 0.0],
        "positions": [[0.0, 0.0, 0.0], [1.0, 0.0, 0.0]],
        "velocities": [[0.0, 0.0, 0.0], [0.0, 1.0, 0.0]],
        "n_active": 1,
        "times": [0.0, 1.0, 2.0],
    }
    return NBodyProblem(**{**fields, **changes})


@pytest.mark.parametrize(
    ("changes", "fragment"),
    [
        ({"gm": [1.0]}, "N >= 2"),
        ({"gm": [[1.0, 0.0]]}, "expected (N,)"),
        ({"positions": [[0.0, 0.0], [1.0, 0.0]]}, "positions has shape (2, 2); expected (2, 3)"),
        ({"velocities": [[0.0, 0.0, 0.0], [math.nan, 1.0, 0.0]]}, "velocities[1, 0] = nan is not finite"),
        ({"gm": [-1.0, 0.0]}, "gm[0] = -1.0 but body 0 is active"),
        ({"gm": [1.0, 0.0], "n_active": 2}, "active bodies need gm > 0"),
        ({"gm": [1.0, 1e-3]}, "test particles need gm = 0"),
        ({"n_active": 0}, "n_active = 0 must be an integer in [1, N = 2]"),
        ({"n_active": 1.5}, "n_active = 1.5 is not an integer"),
        ({"n_active": True}, "n_active = True must be an integer"),
        ({"times": []}, "non-empty"),
        ({"times": [-1.0, 1.0]}, "times[0] = -1.0 is negative"),
        ({"times": [0.0, 1.0, 1.0]}, "not strictly increasing at index 2"),
        ({"times": [0.0, math.inf]}, "times[1] = inf is not finite"),
        ({"times": "soon"}, "times cannot be read as a float64 array"),
        ({"kicks": ((0.5, 1, [0, 1, 0]),)}, "is not an orbits.validate.nbody.Kick"),
        ({"kicks": (Kick(0.5, 2, [0, 1, 0]),)}, "body index in [0, N = 2)"),
        ({"kicks": (Kick(3.0, 1, [0, 1, 0]),)}, "after the last output time 2.0"),
        ({"kicks": (Kick(1.0, 1, [0, 1, 0]), Kick(0.5, 1, [0, 1, 0]))}, "list kicks in time order"),
    ],
)
def test_problem_validation_messages(changes, fragment):
    """(f) Invalid problems raise OrbitDomainError (a ValueError) naming the offending value."""
    with pytest.raises(OrbitDomainError) as info:
        _problem(**changes)
    assert isinstance(info.value, ValueError)
    assert fragment in str(info.value)


@pytest.mark.parametrize(("make", "fragment"), [
    (lambda: Kick(-1.0, 1, [0, 0, 0]), "kick time = -1.0 must be a finite number >= 0"),
    (lambda: Kick(math.nan, 1, [0, 0, 0]), "kick time = nan"),
    (lambda: Kick(1.0, 1, [0, math.inf, 0]), "kick delta_v[1] = inf is not finite"),
    (lambda: Kick(1.0, 1, [0, 0]), "kick delta_v has shape (2,); expected (3,)"),
])
def test_kick_validation_messages(make, fragment):
    with pytest.raises(OrbitDomainError, match=re.escape(fragment)):
        make()


@pytest.mark.parametrize("name", ["rebound", "heyoka"])
def test_kicks_change_the_orbit_where_and_when_they_act(name):
    """A particle on the unit circle (gm = 1) is kicked radially outward by 0.1 at t = 1 and along z by 0.05 at
    t = 2.5; outputs before a kick follow the circle, an output at a kick time shows the kicked state, and every
    output equals the closed-form propagation of the kicked states (the library's propagator, good to 1e-15)
    within 1e-14 (measured 1.5e-15 rebound, 6.7e-16 heyoka)."""
    from orbits.core.twobody.propagate import propagate

    times = np.array([0.5, 1.0, 2.0, 2.5, 4.0])
    kicks = (Kick(1.0, 1, [math.cos(1.0) * 0.1, math.sin(1.0) * 0.1, 0.0]), Kick(2.5, 1, [0.0, 0.0, 0.05]))
    problem = NBodyProblem([1.0, 0.0], [[0, 0, 0], [1, 0, 0]], [[0, 0, 0], [0, 1, 0]], 1, times, kicks=kicks)
    result = backends.integrate(name, problem)
    r, v = np.array([1.0, 0.0, 0.0]), np.array([0.0, 1.0, 0.0])
    expected, t = [], 0.0
    for when in times:
        for kick in kicks:
            if t < kick.time <= when:
                r, v = propagate(r, v, 1.0, kick.time - t)
                v, t = v + kick.delta_v, kick.time
        r_k, v_k = propagate(r, v, 1.0, when - t)
        expected.append(np.concatenate([r_k, v_k]))
    got = np.concatenate([result.positions[:, 1], result.velocities[:, 1]], axis=-1)
    assert np.abs(got - np.array(expected)).max() < 1e-14
    assert got[1, 3] != pytest.approx(-math.sin(1.0))  # the output at t = 1 is after the kick
    assert result.settings["impulses"] == 2


def test_problem_is_frozen_float64_copy():
    """Problem arrays are read-only float64 copies, so a caller cannot mutate them afterwards."""
    positions = np.array([[0, 0, 0], [1, 0, 0]])
    problem = _problem(positions=positions)
    positions[1, 0] = 5
    assert problem.positions.dtype == np.float64 and problem.positions[1, 0] == 1.0
    with pytest.raises(ValueError):
        problem.times[0] = 3.0


@pytest.mark.parametrize(
    ("call", "fragment"),
    [
        (lambda p: _rebound.integrate(p, integrator="whfast"), "needs a step: pass dt"),
        (lambda p: _rebound.integrate(p, dt=0.1), "dt = 0.1 is a WHFast setting"),
        (lambda p: _rebound.integrate(p, integrator="mercurius"), "'mercurius' is not offered"),
        (lambda p: _rebound.integrate(p, integrator="whfast", dt=-1.0), "dt = -1.0 must be finite and > 0"),
        (lambda p: _rebound.integrate(p, integrator="whfast", dt=5.0), "both round to step 0"),
        (lambda p: _rebound.integrate(p, epsilon=0.0), "epsilon = 0.0 must be finite and > 0"),
        (lambda p: _heyoka.integrate(p, tol=0.0), "tol = 0.0 must be finite and > 0"),
        (lambda p: backends.integrate("mercury6", p), "backend = 'mercury6' is unknown"),
        (lambda p: backends.available("mercury6"), "choose one of ['heyoka', 'rebound']"),
        (lambda p: _rebound.integrate(NBodyProblem(p.gm, p.positions, p.velocities, 1, p.times,
                                                   kicks=(Kick(1.0, 1, [0, 0.1, 0]),)), integrator="whfast", dt=0.1),
         "impulses (kicks) need an adaptive integrator"),
    ],
)
def test_adapter_setting_errors(call, fragment):
    """(f) Bad adapter settings raise OrbitDomainError with a message naming the setting."""
    with pytest.raises(OrbitDomainError) as info:
        call(_problem())
    assert fragment in str(info.value)
