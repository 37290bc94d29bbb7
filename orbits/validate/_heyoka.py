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

import copy
import os
import time

import numpy as np

from orbits.core.errors import OrbitDomainError
from orbits.nbody import NBodyProblem, NBodyResult, report

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
    key = (problem.n_bodies, problem.n_active, float(tol), bool(high_accuracy), compact_mode, fp_type, post_newtonian)
    start = time.perf_counter()
    cache_hit = key in _CACHE
    if not cache_hit:
        _CACHE[key] = _compile(heyoka, *key)
    ta = copy.copy(_CACHE[key])
    setup_time = time.perf_counter() - start
    dtype = FP_TYPES[fp_type]
    ta.state[:] = np.hstack([problem.positions, problem.velocities]).ravel().astype(dtype)
    pars = problem.gm[: problem.n_active]
    if post_newtonian:
        pars = np.append(pars, 1.0 / problem.speed_of_light**2)
    ta.pars[:] = pars.astype(dtype)
    start = time.perf_counter()
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


def _compile(heyoka, n_bodies, n_active, tol, high_accuracy, compact_mode, fp_type, post_newtonian):
    """Build the G = 1 N-body Taylor integrator whose active masses are runtime parameters par[0..n_active)
    (and, with the post-Newtonian term, 1 / c**2 in par[n_active])."""
    dtype = FP_TYPES[fp_type]
    masses = [heyoka.par[i] for i in range(n_active)]
    system = heyoka.model.nbody(n_bodies, masses=masses, Gconst=1.0)
    if post_newtonian:
        system = _with_post_newtonian(system, masses, heyoka.par[n_active])
    return heyoka.taylor_adaptive(
        system,
        np.zeros(6 * n_bodies, dtype=dtype),
        pars=np.zeros(n_active + post_newtonian, dtype=dtype),
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
