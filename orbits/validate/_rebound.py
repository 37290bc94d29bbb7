"""rebound adapter: integrate an NBodyProblem with IAS15 or WHFast (G = 1, Cartesian states only).

Time bookkeeping, measured with rebound 5.2.2 on a two-body orbit:

* IAS15 is driven with ``integrate(t, exact_finish_time=1)``; ``sim.t`` then equals the requested time
  exactly. It is a float64 running sum of the adaptive steps, so it differs from the exact sum of the steps
  taken by ~1e-11 after 5e4 steps (1000 orbits at e = 0.5), below IAS15's own error there (~1e-10).
* WHFast is advanced by whole steps with ``sim.steps(n)``: every step is exactly ``dt``, so the state is at
  ``n * dt``. ``sim.t`` accumulates ``t += dt`` in float64 and drifts from ``n * dt`` by 2e-12 after 1e3
  steps, 2e-8 after 1e5 and 3e-6 after 1e6 (dt = 2 pi / 100), so ``n * dt`` is reported, never ``sim.t``.
  ``integrate(t, exact_finish_time=0)`` would overshoot by up to one step and report the drifting clock.
"""

from __future__ import annotations

import time

import numpy as np

from orbits.core.errors import OrbitDomainError
from orbits.nbody import NBodyProblem, NBodyResult, report

INTEGRATORS = ("ias15", "whfast", "bs")
#: IAS15's step-size rules. PRS23 (the default) stalls on a ring of small bodies about a dominant central mass
#: (it reacts to the round-off in the central body's acceleration: a ring of 7 about 1000 times their mass
#: made no progress in 60 s); "global" integrates that ring in 800 steps (tests/validation/test_long_runs.py).
ADAPTIVE_MODES = ("PRS23", "global", "individual", "aarseth85")


def integrate(
    problem: NBodyProblem, integrator: str = "ias15", epsilon: float = 1e-9, dt: float | None = None,
    adaptive_mode: str = "PRS23",
) -> NBodyResult:
    """Integrate ``problem`` with rebound and return the states at ``problem.times`` (WHFast: at steps x dt).

    ``epsilon`` is the accuracy parameter of IAS15, and the relative and absolute tolerance of the
    Gragg-Bulirsch-Stoer integrator "bs" (ignored by WHFast); ``dt`` is the WHFast step, required for WHFast
    and rejected by the adaptive integrators, which choose their own steps; ``adaptive_mode`` is IAS15's
    step-size rule (ADAPTIVE_MODES).
    """
    import rebound

    if integrator not in INTEGRATORS:
        raise OrbitDomainError(
            f"integrator = {integrator!r} is not offered by the rebound backend; choose one of {INTEGRATORS}"
        )
    if integrator == "whfast" and problem.kicks:
        raise OrbitDomainError("impulses (kicks) need an adaptive integrator: integrate them with ias15 or bs, "
                               "not whfast")
    if integrator in ("ias15", "bs"):
        if dt is not None:
            raise OrbitDomainError(f"dt = {dt} is a WHFast setting; {integrator} chooses its own steps (pass dt=None)")
        configure = ((lambda sim: _configure_ias15(sim, epsilon, adaptive_mode)) if integrator == "ias15"
                     else (lambda sim: _configure_bs(sim, epsilon)))
        times, positions, velocities, wall_time, setup_time, settings = _run_adaptive(rebound, problem, integrator,
                                                                                      configure)
        time_mode = "exact finish time: integrate(t, exact_finish_time=1) lands sim.t on each requested time"
    else:
        start = time.perf_counter()
        sim = _simulation(rebound, problem.gm, problem.positions, problem.velocities, problem.n_active)
        _post_newtonian(sim, problem, integrator)  # refuses the velocity-dependent term under WHFast
        settings = _configure_whfast(sim, dt)
        com = _move_to_com(sim)
        setup_time = time.perf_counter() - start
        times, positions, velocities, wall_time = _run_whfast(sim, problem.times, dt)
        positions += com[0] + times[:, None, None] * com[1]
        velocities += com[1]
        time_mode = (
            "steps x dt: sim.steps(n) to the step count n nearest each requested time; times are "
            "n * dt, not the drifting sim.t"
        )
    return NBodyResult(
        backend="rebound",
        integrator=integrator,
        positions=positions,
        velocities=velocities,
        times=times,
        wall_time=wall_time,
        setup_time=setup_time,
        settings=settings,
        version=rebound.__version__,
        time_mode=time_mode,
    )


def _simulation(rebound, gm: np.ndarray, positions: np.ndarray, velocities: np.ndarray, n_active: int):
    """Build a G = 1 simulation holding the bodies as Cartesian states; test particles are type 0."""
    sim = rebound.Simulation()
    sim.G = 1.0
    for m, r, v in zip(gm, positions, velocities):
        sim.add(m=float(m), x=float(r[0]), y=float(r[1]), z=float(r[2]), vx=float(v[0]), vy=float(v[1]), vz=float(v[2]))
    if n_active < gm.size:
        sim.N_active = n_active
        sim.testparticle_type = 0
    return sim


def _run_adaptive(rebound, problem: NBodyProblem, integrator: str, configure):
    """IAS15 or BS over the problem's arcs: a new simulation at each impulse (IAS15 keeps predictor state that a
    kick would invalidate), started from the kicked state at the arc's start time; return (times reached,
    positions, velocities, wall time, setup time, settings)."""
    reached = np.empty_like(problem.times)
    positions = np.empty((problem.times.size, problem.n_bodies, 3))
    velocities = np.empty_like(positions)
    r, v = np.array(problem.positions, dtype=float), np.array(problem.velocities, dtype=float)
    wall_time = setup_time = 0.0
    for arc in problem.arcs():
        start = time.perf_counter()
        for kick in arc.kicks:
            v[kick.body] += kick.delta_v
        sim = _simulation(rebound, problem.gm, r, v, problem.n_active)
        sim.t = arc.start
        extras = _post_newtonian(sim, problem, integrator)  # kept alive while the simulation runs
        settings = configure(sim)
        if extras is not None:
            settings = {**settings, **extras[1]}
        if problem.kicks:
            settings = {**settings, "impulses": len(problem.kicks), "at an impulse": "a new simulation from the "
                        "kicked state"}
        setup_time += time.perf_counter() - start
        start = time.perf_counter()
        for k in arc.outputs:
            sim.integrate(float(problem.times[k]), exact_finish_time=1)
            reached[k] = sim.t
            positions[k], velocities[k] = _snapshot(sim)
            report(problem.times[k], problem.times[-1])
        if sim.t < arc.end:
            sim.integrate(arc.end, exact_finish_time=1)
        r, v = _snapshot(sim)
        wall_time += time.perf_counter() - start
    return reached, positions, velocities, wall_time, setup_time, settings


def _post_newtonian(sim, problem: NBodyProblem, integrator: str):
    """Attach REBOUNDx's "gr" effect (body 0's 1PN field, Anderson et al. 1975) when the problem asks for it;
    return (the REBOUNDx extras, their settings) or None."""
    if problem.speed_of_light is None:
        return None
    if integrator == "whfast":
        raise OrbitDomainError("the post-Newtonian term is velocity dependent: integrate it with ias15 or bs, "
                               "not whfast")
    try:
        import reboundx
    except ImportError:
        raise OrbitDomainError("the post-Newtonian term needs REBOUNDx: pip install reboundx "
                               "(it comes with orbits[ephemeris])") from None
    extras = reboundx.Extras(sim)
    gr = extras.load_force("gr")
    extras.add_force(gr)
    gr.params["c"] = problem.speed_of_light
    sim.particles[0].params["gr_source"] = 1
    return extras, {"post_newtonian": "REBOUNDx gr, source body 0", "speed_of_light": problem.speed_of_light,
                    "reboundx": reboundx.__version__}


def _configure_ias15(sim, epsilon: float, adaptive_mode: str = "PRS23") -> dict:
    """Select IAS15 with every setting pinned; return those settings."""
    if not (np.isfinite(epsilon) and epsilon > 0.0):
        raise OrbitDomainError(f"epsilon = {epsilon} must be finite and > 0 (0 would switch IAS15 to fixed steps)")
    if adaptive_mode not in ADAPTIVE_MODES:
        raise OrbitDomainError(f"adaptive_mode = {adaptive_mode!r} is not one of IAS15's: {', '.join(ADAPTIVE_MODES)}")
    sim.integrator = "ias15"
    sim.integrator.epsilon = float(epsilon)
    sim.integrator.min_dt = 0.0
    sim.integrator.adaptive_mode = adaptive_mode
    sim.dt = 1e-3
    return {"epsilon": float(epsilon), "min_dt": 0.0, "adaptive_mode": adaptive_mode, "initial_dt": 1e-3}


def _configure_bs(sim, epsilon: float) -> dict:
    """Select the Gragg-Bulirsch-Stoer integrator with eps_rel = eps_abs = epsilon; return the settings."""
    if not (np.isfinite(epsilon) and epsilon > 0.0):
        raise OrbitDomainError(f"epsilon = {epsilon} must be finite and > 0")
    sim.integrator = "bs"
    sim.integrator.eps_rel = float(epsilon)
    sim.integrator.eps_abs = float(epsilon)
    sim.dt = 1e-3
    return {"eps_rel": float(epsilon), "eps_abs": float(epsilon), "initial_dt": 1e-3}


def _configure_whfast(sim, dt: float | None) -> dict:
    """Select WHFast (Jacobi, standard kernel, no correctors, safe mode) with step ``dt``; return the settings."""
    if dt is None:
        raise OrbitDomainError(
            "integrator 'whfast' needs a step: pass dt (e.g. a few percent of the shortest orbital period)"
        )
    if not (np.isfinite(dt) and dt > 0.0):
        raise OrbitDomainError(f"dt = {dt} must be finite and > 0")
    sim.integrator = "whfast"
    sim.integrator.coordinates = "JACOBI"
    sim.integrator.kernel = "DEFAULT"
    sim.integrator.corrector = 0
    sim.integrator.corrector2 = 0
    sim.integrator.safe_mode = 1
    sim.dt = float(dt)
    return {
        "dt": float(dt),
        "coordinates": "JACOBI",
        "kernel": "DEFAULT",
        "corrector": 0,
        "corrector2": 0,
        "safe_mode": 1,
        "move_to_com": True,
    }


def _move_to_com(sim) -> np.ndarray:
    """Shift the simulation to its barycentric frame; return the removed barycentre as [[x, y, z], [vx, vy, vz]]."""
    com = sim.com()
    sim.move_to_com()
    return np.array([[com.x, com.y, com.z], [com.vx, com.vy, com.vz]])


def _snapshot(sim) -> tuple[np.ndarray, np.ndarray]:
    """Return the current (N, 3) positions and velocities."""
    xyz = np.empty((sim.N, 3))
    vxyz = np.empty((sim.N, 3))
    sim.serialize_particle_data(xyz=xyz, vxvyvz=vxyz)
    return xyz, vxyz


def _step_counts(times: np.ndarray, dt: float) -> np.ndarray:
    """Return the whole step count nearest each time; raise if two times share a count (dt too coarse)."""
    counts = np.rint(times / dt).astype(np.int64)
    clash = np.flatnonzero(np.diff(counts) == 0)
    if clash.size:
        i = int(clash[0])
        raise OrbitDomainError(
            f"dt = {dt} is too coarse for the output grid: times[{i}] = {times[i]} and "
            f"times[{i + 1}] = {times[i + 1]} both round to step {counts[i]}"
        )
    return counts


def _run_whfast(sim, times: np.ndarray, dt: float):
    """Advance by whole steps to each output; return (counts * dt, positions, velocities, wall)."""
    counts = _step_counts(times, dt)
    positions = np.empty((times.size, sim.N, 3))
    velocities = np.empty_like(positions)
    done = 0
    start = time.perf_counter()
    for k, n in enumerate(counts):
        sim.steps(int(n - done))
        done = n
        positions[k], velocities[k] = _snapshot(sim)
        report(n, counts[-1])
    return counts * float(dt), positions, velocities, time.perf_counter() - start
