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
from orbits.validate.nbody import ExponentialDrag, NBodyProblem, NBodyResult, ZonalHarmonics, python_sigint, report

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
        extras = _reboundx_effects(sim, problem, integrator)  # refuses velocity-dependent terms under WHFast
        settings = _configure_whfast(sim, dt)
        if extras is not None:
            settings = {**settings, **extras[1]}
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
        extras = _reboundx_effects(sim, problem, integrator)  # kept alive while the simulation runs
        settings = configure(sim)
        if extras is not None:
            settings = {**settings, **extras[1]}
        if problem.kicks:
            settings = {**settings, "impulses": len(problem.kicks), "at an impulse": "a new simulation from the "
                        "kicked state"}
        setup_time += time.perf_counter() - start
        start = time.perf_counter()
        for k in arc.outputs:
            _integrate_to(sim, float(problem.times[k]))
            reached[k] = sim.t
            positions[k], velocities[k] = _snapshot(sim)
            report(problem.times[k], problem.times[-1])
        if sim.t < arc.end:
            _integrate_to(sim, arc.end)
        r, v = _snapshot(sim)
        wall_time += time.perf_counter() - start
    return reached, positions, velocities, wall_time, setup_time, settings


def _integrate_to(sim, t: float) -> None:
    """sim.integrate(t, exact_finish_time=1), with Python's Ctrl-C handler back in place after it (rebound installs
    its own during the call and leaves it behind: orbits.validate.nbody.python_sigint). A Ctrl-C that reached
    rebound's handler after its loop last looked (as the call returns, before Python's handler is back) is only in
    rebound's flag, which its next call clears: it raises KeyboardInterrupt here."""
    with python_sigint():
        sim.integrate(t, exact_finish_time=1)
    if _interrupt_flag().value:
        raise KeyboardInterrupt


def _interrupt_flag():
    """rebound's C flag reb_sigint, set by its SIGINT handler and cleared at the start of every integrate call."""
    import ctypes

    import rebound

    return ctypes.c_int.in_dll(rebound.clibrebound, "reb_sigint")


def _reboundx_effects(sim, problem: NBodyProblem, integrator: str):
    """Attach the REBOUNDx effects the problem asks for: "gr" (body 0's 1PN field, Anderson et al. 1975),
    "gravitational_harmonics" for ZonalHarmonics, and a force of this module for ExponentialDrag; return (the
    REBOUNDx extras and what must stay alive with them, their settings) or None."""
    if problem.speed_of_light is None and not problem.forces:
        return None
    velocity_dependent = problem.speed_of_light is not None or any(
        isinstance(f, ExponentialDrag) for f in problem.forces)
    if integrator == "whfast" and velocity_dependent:
        raise OrbitDomainError("the post-Newtonian term and drag are velocity dependent: integrate them with ias15 "
                               "or bs, not whfast")
    try:
        import reboundx
    except ImportError:
        raise OrbitDomainError("the post-Newtonian term and the extra forces need REBOUNDx: pip install reboundx "
                               "(it comes with orbits[ephemeris])") from None
    extras = reboundx.Extras(sim)
    settings, alive = {"reboundx": reboundx.__version__}, [extras]
    if problem.speed_of_light is not None:
        gr = extras.load_force("gr")
        extras.add_force(gr)
        gr.params["c"] = problem.speed_of_light
        sim.particles[0].params["gr_source"] = 1
        settings.update(post_newtonian="REBOUNDx gr, source body 0", speed_of_light=problem.speed_of_light)
    for force in problem.forces:
        if isinstance(force, ZonalHarmonics):
            alive.append(_zonal_harmonics(extras, sim, force, problem.n_active))
            settings[f"zonal_harmonics[{force.source}]"] = ("REBOUNDx gravitational_harmonics (J2, J4), axis z"
                                                            + ("; J3 a REBOUNDx force in Python" if force.j3 else ""))
        else:
            alive.append(_drag(extras, problem, force))
            settings[f"drag[{force.source}]"] = "exponential atmosphere, a REBOUNDx force written in Python"
    return alive, settings


def _zonal_harmonics(extras, sim, force: ZonalHarmonics, n_active: int):
    """REBOUNDx's gravitational_harmonics on the source body (its spin axis z, the effect's default)."""
    harmonics = extras.load_force("gravitational_harmonics")
    extras.add_force(harmonics)
    source = sim.particles[force.source]
    source.params["J2"] = force.j2
    source.params["J4"] = force.j4
    source.params["R_eq"] = force.radius
    if force.j3 == 0.0:
        return harmonics
    return harmonics, _third_zonal(extras, n_active, force)


def _third_zonal(extras, n_active: int, force: ZonalHarmonics):
    """J3, which REBOUNDx's harmonics lack, as a REBOUNDx force in Python (c = z**2 / r**2, d = r_j - r_source):
    a_xy = (5/2) mu J3 R**3 (7c - 3) z d_xy / r**7, a_z = (1/2) mu J3 R**3 (35 c**2 - 30 c + 3) / r**5, with the
    reaction -(m_j / m_source) a on the source."""
    import math

    source, j3r3 = force.source, force.j3 * force.radius**3

    def accelerate(simulation, effect, particles, n):
        centre = particles[source]
        mu = simulation.contents.G * centre.m
        for j in range(n):
            if j == source:
                continue
            p = particles[j]
            dx, dy, dz = p.x - centre.x, p.y - centre.y, p.z - centre.z
            r2 = dx * dx + dy * dy + dz * dz
            r5 = r2 * r2 * math.sqrt(r2)
            c = dz * dz / r2
            planar = 2.5 * mu * j3r3 * (7.0 * c - 3.0) * dz / (r5 * r2)
            ax, ay, az = planar * dx, planar * dy, 0.5 * mu * j3r3 * ((35.0 * c - 30.0) * c + 3.0) / r5
            p.ax += ax
            p.ay += ay
            p.az += az
            if j < n_active:
                share = p.m / centre.m
                centre.ax -= share * ax
                centre.ay -= share * ay
                centre.az -= share * az

    third = extras.create_force("third_zonal_harmonic")
    third.force_type = "pos"
    third.update_accelerations = accelerate
    extras.add_force(third)
    return third, accelerate


def _drag(extras, problem: NBodyProblem, force: ExponentialDrag):
    """A velocity-dependent REBOUNDx force: a = -(1/2) rho B |v| v on each test particle, relative to the source."""
    import math

    first, source = problem.n_active, force.source
    reference, base, scale_height = force.reference, force.base, force.scale_height

    def accelerate(simulation, effect, particles, n):
        centre = particles[source]
        for j in range(first, n):
            p = particles[j]
            dx, dy, dz = p.x - centre.x, p.y - centre.y, p.z - centre.z
            vx, vy, vz = p.vx - centre.vx, p.vy - centre.vy, p.vz - centre.vz
            r = math.sqrt(dx * dx + dy * dy + dz * dz)
            k = -0.5 * reference * math.exp(-(r - base) / scale_height) * math.sqrt(vx * vx + vy * vy + vz * vz)
            p.ax += k * vx
            p.ay += k * vy
            p.az += k * vz

    drag = extras.create_force("exponential_drag")
    drag.force_type = "vel"
    drag.update_accelerations = accelerate
    extras.add_force(drag)
    return drag, accelerate


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


def kepler_solver():
    """rebound's M_to_E as a function of a list of (e, M) pairs returning the list of E (its per-call Python API:
    the peer of orbits' Kepler solver in the benchmarks)."""
    import rebound

    def solve(pairs: list) -> list:
        return [rebound.M_to_E(e, mean) for e, mean in pairs]

    return solve
