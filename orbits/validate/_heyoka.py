"""heyoka adapter: integrate an NBodyProblem with heyoka's Taylor integrator (G = 1, float64).

* Masses are runtime parameters (``heyoka.par[i]``), so one compiled integrator serves every problem with
  the same (N, n_active, tol, high_accuracy). Compiled integrators are kept in ``_CACHE``; each call works
  on a copy, so the cached template is never mutated and calls are re-entrant.
* Test particles use heyoka's restricted form of ``model.nbody``: only the first ``n_active`` bodies get a
  mass, and heyoka then omits every term sourced by the remaining bodies. This is exact (no 0 * x terms) and
  cheaper than passing zero masses, which heyoka would keep as live parameters.
* Outputs come from ``propagate_grid``, which lands on each grid time exactly; heyoka keeps time in
  double-length arithmetic, so there is no clock drift.
* heyoka has an on-disk cache of compiled code (SQLite, default ``~/.cache/heyoka``). heyoka itself reads
  ``HEYOKA_CACHE_DIR`` once, when the library loads; ``integrate`` re-reads it on every call and points
  heyoka's cache at it, so setting the variable after import also works.
* Systems with N >= 4 are compiled in compact mode: the compile time of full unrolling grows steeply with N,
  compact mode keeps it short at the price of a slower step. The choice is reported in ``settings``.
"""

from __future__ import annotations

import contextlib
import copy
import os
import time
from collections.abc import Callable, Iterator

import numpy as np

from orbits.core.errors import OrbitDomainError
from orbits.validate.nbody import ExponentialDrag, NBodyProblem, NBodyResult, ZonalHarmonics, python_sigint, report

COMPACT_MODE_MIN_BODIES = 4

_CACHE: dict[tuple, object] = {}


FP_TYPES = {"float64": np.float64, "long double": np.longdouble}


def integrate(
    problem: NBodyProblem, tol: float = 1e-16, high_accuracy: bool = True, fp_type: str = "float64"
) -> NBodyResult:
    """Integrate ``problem`` with heyoka's adaptive Taylor method and return the states at ``problem.times``.

    ``tol`` is heyoka's relative/absolute error tolerance (it also sets the Taylor order); ``high_accuracy``
    enables heyoka's compensated summation and extra-precise polynomial evaluation; ``fp_type`` "long double"
    integrates in x87 extended precision (64-bit mantissa on x86-64), with the initial state and output
    converted from and to float64. Raises RuntimeError with heyoka's outcome if the propagation does not
    reach the last time.
    """
    import heyoka

    if not (np.isfinite(tol) and tol > 0.0):
        raise OrbitDomainError(f"tol = {tol} must be finite and > 0")
    if fp_type not in FP_TYPES:
        raise OrbitDomainError(f"fp_type = {fp_type!r} is not offered; choose one of {sorted(FP_TYPES)}")
    _follow_cache_dir(heyoka)
    compact_mode = problem.n_bodies >= COMPACT_MODE_MIN_BODIES
    post_newtonian = problem.speed_of_light is not None
    forces = tuple((type(f).__name__, f.source) for f in problem.forces)
    key = (problem.n_bodies, problem.n_active, float(tol), bool(high_accuracy), compact_mode, fp_type, post_newtonian,
           forces)
    start = time.perf_counter()
    cache_hit = key in _CACHE
    if not cache_hit:
        with python_sigint():
            _CACHE[key] = _compile(heyoka, *key)
    ta = copy.copy(_CACHE[key])
    setup_time = time.perf_counter() - start
    dtype = FP_TYPES[fp_type]
    ta.state[:] = np.hstack([problem.positions, problem.velocities]).ravel().astype(dtype)
    pars = problem.gm[: problem.n_active]
    if post_newtonian:
        pars = np.append(pars, 1.0 / problem.speed_of_light**2)
    pars = np.append(pars, _force_parameters(problem.forces))
    ta.pars[:] = pars.astype(dtype)
    start = time.perf_counter()
    with python_sigint():  # its step callback is Python: a Ctrl-C raises there, whatever handler was left behind
        states = _propagate_arcs(heyoka, ta, problem, dtype)
    wall_time = time.perf_counter() - start
    states = states.reshape(problem.times.size, problem.n_bodies, 6)
    settings = {
        "tol": float(tol),
        "high_accuracy": bool(high_accuracy),
        "order": ta.order,
        "compact_mode": compact_mode,
        "fp_type": fp_type,
        "cache_hit": cache_hit,
    }
    if problem.kicks:
        settings.update(impulses=len(problem.kicks))
    if post_newtonian:
        settings.update(post_newtonian="REBOUNDx gr form (Anderson et al. 1975) to O(1/c^2), source body 0",
                        speed_of_light=problem.speed_of_light)
    for force in problem.forces:
        what = "zonal_harmonics" if isinstance(force, ZonalHarmonics) else "drag"
        settings[f"{what}[{force.source}]"] = "the same force in heyoka's expression system"
    return NBodyResult(
        backend="heyoka",
        integrator="taylor_adaptive",
        positions=states[..., :3].copy(),
        velocities=states[..., 3:].copy(),
        times=problem.times.copy(),
        wall_time=wall_time,
        setup_time=setup_time,
        settings=settings,
        version=heyoka.__version__,
        time_mode="propagate_grid from t = 0 lands exactly on each requested time",
    )


def _propagate_arcs(heyoka, ta, problem: NBodyProblem, dtype) -> np.ndarray:
    """(K, 6 N) float64 states at the problem's K times: over each arc, the kicks added to the state at its start,
    propagate_grid through its outputs, then propagate_until its end (the next kick)."""
    end = float(problem.times[-1])
    states = np.empty((problem.times.size, 6 * problem.n_bodies))
    for arc in problem.arcs():
        for kick in arc.kicks:
            ta.state[6 * kick.body + 3: 6 * kick.body + 6] += kick.delta_v.astype(dtype)
        if arc.outputs.size:
            grid, skip = _grid(problem.times[arc.outputs], arc.start)
            outcome, *_, rows = ta.propagate_grid(grid.astype(dtype), callback=lambda ta: _interruptible(ta, end))
            _require_time_limit(heyoka, ta, outcome, grid[-1])
            states[arc.outputs] = rows[skip:]
        if ta.time < arc.end:
            outcome = ta.propagate_until(dtype(arc.end), callback=lambda ta: _interruptible(ta, end))[0]
            _require_time_limit(heyoka, ta, outcome, arc.end)
    return states


def _require_time_limit(heyoka, ta, outcome, target: float) -> None:
    """Raise RuntimeError with heyoka's outcome unless the propagation reached its target time."""
    if outcome != heyoka.taylor_outcome.time_limit:
        raise RuntimeError(
            f"heyoka stopped at t = {ta.time} with outcome {outcome}; it must reach t = {target} (outcome time_limit)"
        )


def _interruptible(ta, end: float) -> bool:
    """Called by heyoka after every step: reports progress, and, being Python, lets a pending Ctrl-C raise
    KeyboardInterrupt at once (without it heyoka runs to the end of the grid first). About 5 us a step; it never
    stops the run itself."""
    report(float(ta.time), end)
    return True


def clear_cache() -> None:
    """Forget every compiled integrator held by this module (heyoka's own memory and disk caches are kept)."""
    _CACHE.clear()


def _follow_cache_dir(heyoka) -> None:
    """Point heyoka's on-disk compilation cache at $HEYOKA_CACHE_DIR when it is set and differs."""
    path = os.environ.get("HEYOKA_CACHE_DIR")
    if path and str(heyoka.llvm_state.get_diskcache_path()) != path:
        heyoka.llvm_state.set_diskcache_path(path)


def _compile(heyoka, n_bodies, n_active, tol, high_accuracy, compact_mode, fp_type, post_newtonian, forces):
    """Build the G = 1 N-body Taylor integrator whose active masses are runtime parameters par[0..n_active)
    (and, with the post-Newtonian term, 1 / c**2 in par[n_active]; then the forces' parameters, _force_parameters)."""
    dtype = FP_TYPES[fp_type]
    masses = [heyoka.par[i] for i in range(n_active)]
    system = heyoka.model.nbody(n_bodies, masses=masses, Gconst=1.0)
    if post_newtonian:
        system = _with_post_newtonian(system, masses, heyoka.par[n_active])
    system, n_pars = _with_forces(heyoka, system, masses, forces, n_active + post_newtonian)
    return heyoka.taylor_adaptive(
        system,
        np.zeros(6 * n_bodies, dtype=dtype),
        pars=np.zeros(n_pars, dtype=dtype),
        tol=dtype(tol),
        high_accuracy=high_accuracy,
        compact_mode=compact_mode,
        fp_type=dtype,
    )


def _with_post_newtonian(system: list, masses: list, inverse_c2) -> list:
    """Add body 0's 1PN field to the Newtonian equations, as REBOUNDx's "gr" effect does: in Jacobi coordinates
    (r, v, a: each body relative to the barycentre of those before it; a the Newtonian acceleration), body i >= 1
    gets  g = B r - A a - D v  with mu = G m_0,
        A = (v**2 / 2 + 3 mu / r) / c**2,   B = (mu / r - 3 v**2 / 2) mu / (r**3 c**2),
        D = (v . a - 3 mu (r . v) / r**3) / c**2,
    and the Jacobi accelerations go back to inertial ones with the barycentre unaccelerated. REBOUNDx solves
    v_canonical = v / (1 - A) by iteration and keeps the O(1/c**4) products; they change g by 1e-8 of itself
    in the solar system, below 1e-16 of the Newtonian acceleration."""
    n = len(system) // 6
    position = [[system[6 * i + k][0] for k in range(3)] for i in range(n)]
    velocity = [[system[6 * i + 3 + k][0] for k in range(3)] for i in range(n)]
    newton = [[system[6 * i + 3 + k][1] for k in range(3)] for i in range(n)]
    r_j, v_j, a_j = (_to_jacobi(x, masses) for x in (position, velocity, newton))
    mu = masses[0]
    g_j = [[0.0, 0.0, 0.0]]
    for r, v, a in zip(r_j[1:], v_j[1:], a_j[1:]):
        rr = _dot(r, r) ** 0.5
        v2, rv, va = _dot(v, v), _dot(r, v), _dot(v, a)
        big_a = (0.5 * v2 + 3.0 * mu / rr) * inverse_c2
        big_b = (mu / rr - 1.5 * v2) * mu / rr**3 * inverse_c2
        big_d = (va - 3.0 * mu * rv / rr**3) * inverse_c2
        g_j.append([big_b * r[k] - big_a * a[k] - big_d * v[k] for k in range(3)])
    g = _from_jacobi(g_j, masses)
    out = list(system)
    for i in range(n):
        for k in range(3):
            var, rhs = system[6 * i + 3 + k]
            out[6 * i + 3 + k] = (var, rhs + g[i][k])
    return out


def _force_parameters(forces: tuple) -> list[float]:
    """The runtime parameters of the forces, in the order _with_forces reads them: (J2 R**2, J4 R**4) for
    zonal harmonics (J3 R**3 between them), (rho0 B, base, 1 / H) for drag."""
    values = []
    for force in forces:
        if isinstance(force, ZonalHarmonics):
            values += [force.j2 * force.radius**2, force.j3 * force.radius**3, force.j4 * force.radius**4]
        elif isinstance(force, ExponentialDrag):
            values += [force.reference, force.base, 1.0 / force.scale_height]
    return values


def _with_forces(heyoka, system: list, masses: list, forces: tuple, first: int) -> tuple[list, int]:
    """Add the forces (kind name, source) to the equations, their parameters from par[first] on; return the new
    system and the total parameter count. Zonal harmonics, as REBOUNDx's gravitational_harmonics writes them
    (c = cos**2 of the colatitude, d = r_j - r_source, mu = G m_source):
        a_xy = [3/2 mu J2 R**2 (5c - 1) / r**5 + 5/8 mu J4 R**4 (63c**2 - 42c + 3) / r**7] d_xy,
        a_z  = [3/2 mu J2 R**2 (5c - 3) / r**5 + 5/8 mu J4 R**4 (63c**2 - 70c + 15) / r**7] d_z,
    plus J3's a_xy = (5/2) mu J3 R**3 (7c - 3) z d_xy / r**7, a_z = (1/2) mu J3 R**3 (35c**2 - 30c + 3) / r**5,
    on every body j, with -(m_j / m_source) a on the source; drag a = -(1/2) rho0 B exp(-(r - base) / H) |v| v on
    each test particle, r and v relative to the source."""
    n = len(system) // 6
    n_active = len(masses)
    position = [[system[6 * i + k][0] for k in range(3)] for i in range(n)]
    velocity = [[system[6 * i + 3 + k][0] for k in range(3)] for i in range(n)]
    extra = [[0.0, 0.0, 0.0] for _ in range(n)]
    k = first
    for kind, source in forces:
        mu = masses[source]
        if kind == ZonalHarmonics.__name__:
            j2r2, j3r3, j4r4 = heyoka.par[k], heyoka.par[k + 1], heyoka.par[k + 2]
            k += 3
            for j in range(n):
                if j == source:
                    continue
                d = [position[j][i] - position[source][i] for i in range(3)]
                r2 = _dot(d, d)
                c = d[2] * d[2] / r2
                second = 1.5 * mu * j2r2 / (r2 * r2 * heyoka.sqrt(r2))
                fourth = 0.625 * mu * j4r4 / (r2 * r2 * r2 * heyoka.sqrt(r2))
                planar = second * (5.0 * c - 1.0) + fourth * ((63.0 * c - 42.0) * c + 3.0)
                axial = second * (5.0 * c - 3.0) + fourth * ((63.0 * c - 70.0) * c + 15.0)
                third = 2.5 * mu * j3r3 * (7.0 * c - 3.0) * d[2] / (r2 * r2 * r2 * heyoka.sqrt(r2))
                planar = planar + third
                axial = axial * d[2] + 0.5 * mu * j3r3 * ((35.0 * c - 30.0) * c + 3.0) / (r2 * r2 * heyoka.sqrt(r2))
                a = [planar * d[0], planar * d[1], axial]
                for i in range(3):
                    extra[j][i] = extra[j][i] + a[i]
                    if j < n_active:
                        extra[source][i] = extra[source][i] - masses[j] / mu * a[i]
        else:
            reference, base, inverse_h = heyoka.par[k], heyoka.par[k + 1], heyoka.par[k + 2]
            k += 3
            for j in range(n_active, n):
                d = [position[j][i] - position[source][i] for i in range(3)]
                v = [velocity[j][i] - velocity[source][i] for i in range(3)]
                factor = -0.5 * reference * heyoka.exp((base - heyoka.sqrt(_dot(d, d))) * inverse_h) * heyoka.sqrt(
                    _dot(v, v))
                for i in range(3):
                    extra[j][i] = extra[j][i] + factor * v[i]
    out = list(system)
    for j in range(n):
        for i in range(3):
            if not isinstance(extra[j][i], float):
                var, rhs = system[6 * j + 3 + i]
                out[6 * j + 3 + i] = (var, rhs + extra[j][i])
    return out, k


def _dot(a, b):
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]


def _to_jacobi(x: list, masses: list) -> list:
    """Jacobi vectors: x_j[0] the barycentre, x_j[i] = x[i] - (barycentre of bodies 0..i-1)."""
    total, centre = masses[0], list(x[0])
    out = [None]
    for i in range(1, len(x)):
        out.append([x[i][k] - centre[k] for k in range(3)])
        new_total = total + masses[i]
        centre = [(total * centre[k] + masses[i] * x[i][k]) / new_total for k in range(3)]
        total = new_total
    out[0] = centre
    return out


def _from_jacobi(x_j: list, masses: list) -> list:
    """Inverse of _to_jacobi: from the last body down, R_(i-1) = R_i - (m_i / M_i) x_j[i], x[i] = R_(i-1) + x_j[i]."""
    totals = [masses[0]]
    for m in masses[1:]:
        totals.append(totals[-1] + m)
    centre = list(x_j[0])
    out = [None] * len(x_j)
    for i in range(len(x_j) - 1, 0, -1):
        previous = [centre[k] - masses[i] / totals[i] * x_j[i][k] for k in range(3)]
        out[i] = [previous[k] + x_j[i][k] for k in range(3)]
        centre = previous
    out[0] = centre
    return out


def _grid(times: np.ndarray, start: float) -> tuple[np.ndarray, int]:
    """Return the propagate_grid grid (it must start at the integrator's time, `start`) and how many leading rows
    to drop."""
    if times[0] == start:
        return times, 0
    return np.concatenate(([start], times)), 1


# ---- heyoka's closed-form functions, the peers of orbits' own in the benchmarks ----------------------------------


@contextlib.contextmanager
def _threads(heyoka, threads: int) -> Iterator[None]:
    """Run heyoka's compiled functions on `threads` threads inside the block."""
    previous = heyoka.get_nthreads()
    heyoka.set_nthreads(threads)
    try:
        yield
    finally:
        heyoka.set_nthreads(previous)


@contextlib.contextmanager
def pinned_threads(count: int) -> Iterator[None]:
    """heyoka's compiled functions on `count` threads inside the block: a benchmark pins them once around its timing
    loop and times each solver's `bare` call, the cfunc alone."""
    import heyoka

    with _threads(heyoka, count):
        yield


def kepler_solver(threads: int = 1) -> Callable[[np.ndarray], np.ndarray]:
    """heyoka's kepE compiled as a cfunc: a function of a (2, n) array of (e, M) returning E (n,), run on `threads`
    threads (elliptic only: NaN for e >= 1)."""
    import heyoka

    _follow_cache_dir(heyoka)
    e, mean = heyoka.make_vars("e", "M")
    cf = heyoka.cfunc([heyoka.kepE(e, mean)], [e, mean])

    def solve(inputs: np.ndarray) -> np.ndarray:
        with _threads(heyoka, threads):
            return cf(inputs)[0]

    solve.bare = lambda inputs: cf(inputs)[0]  # the cfunc alone, on the threads set around it (pinned_threads)
    return solve


def lagrange_propagator(threads: int = 1) -> Callable[[np.ndarray], np.ndarray]:
    """heyoka's lagrange_prop (heyoka >= 7.11) compiled as a cfunc: a function of an (8, n) array of
    (x, y, z, vx, vy, vz, mu, t) returning the (6, n) propagated states, run on `threads` threads (elliptic only).
    Raises ImportError on an older heyoka."""
    import heyoka

    if not hasattr(heyoka.model, "lagrange_prop"):
        raise ImportError("heyoka.model.lagrange_prop (heyoka >= 7.11)", name="heyoka >= 7.11")
    _follow_cache_dir(heyoka)
    variables = heyoka.make_vars("x", "y", "z", "vx", "vy", "vz", "mu", "t")
    pos, vel = heyoka.model.lagrange_prop(pos0=variables[:3], vel0=variables[3:6], mu=variables[6], tm=variables[7])
    cf = heyoka.cfunc(list(pos) + list(vel), variables)

    def propagate(inputs: np.ndarray) -> np.ndarray:
        with _threads(heyoka, threads):
            return cf(inputs)

    propagate.bare = cf  # the cfunc alone, on the threads set around it (pinned_threads)
    return propagate
