"""Differential correction of periodic orbits of the restricted problem: symmetric single shooting and multiple
shooting, with the state transition matrix from the variational equations (orbits.core.periodic.cr3bp,
orbits.core.dop853).

Symmetric shooting. An orbit that crosses the fixed set of a reversing symmetry R (orbits.core.periodic.cr3bp: the
x-z plane
or the x axis) perpendicularly at t = 0 and again at t = tau is periodic with period 2 tau. The unknowns are
u = (the components of the initial state the symmetry keeps, tau); the residual is F(u) = the components R
reverses of phi(x0(u), tau), which must vanish. With Phi = Phi(tau) and f the vector field at the end,

    dF/du = [Phi[reversed, kept], f[reversed]],

one more column than rows: the solutions form a one-parameter family, and one more scalar equation g(u) = 0 (a
fixed component, a period, or the pseudo-arclength condition of orbits.core.periodic.continuation)
picks a member. Newton's method on the square system converges quadratically; it stops when a step no longer
shrinks the residual (or is below SMALL_STEP), and succeeds when max |F| is below TOLERANCE, both in units of the
flow's length scale (or below NOISE_MARGIN times the integration's own noise, where the orbit's sensitivity puts
that higher). The monodromy matrix follows from the half
period without integrating the other half: M = R Phi^-1 R Phi (Phi^-1 by the symplectic identity), because
R phi_t(x) = phi_-t(R x).

Multiple shooting. N nodes X_0 ... X_(N-1) along the orbit, arcs of equal duration T / N; the residual is
phi(X_i, T / N) - X_(i+1) (with X_N = X_0), plus y(X_0) = y_0 (the phase) and either T or C(X_0) held fixed. The
system has one more equation than its rank (the Jacobi integral makes one periodicity condition redundant), so each
step is the minimum-norm least-squares solution, halved until it shrinks the residual's 2-norm (a damped Newton
method: arcs through a close approach make the full step overshoot), for up to twice MAX_ITERATIONS steps. It needs
no symmetry; the monodromy is the product of the arcs' transition matrices.
"""

import math
from dataclasses import dataclass, field

import numpy as np

from orbits.core import dop853
from orbits.core.errors import ConvergenceError
from orbits.core.periodic import cr3bp

#: the largest |residual| a corrected orbit may keep at its half period or between its arcs, in units of its flow's
#: length scale (orbits.core.periodic.cr3bp.Origin.scale: 1e-11 of 58,000 km about the Earth-Moon L1 point, of 1.5e6 km
#: about the Sun-Earth L1 point)
TOLERANCE = 1e-11
#: where the orbit's sensitivity puts the integration's noise above TOLERANCE, the corrector accepts this many times
#: that noise instead: RTOL of the flow's scale per step, amplified by |Phi(tau)| (measured: the residual of the
#: Earth-Moon 9:2 NRHO, |Phi| = 1.1e3, stalls at 1e-11 of r, 2.5 times RTOL |Phi| scale)
NOISE_MARGIN = 10.0
#: a correction has "settled" (Crossing.settled) once its residual is within this fraction of the flow's scale
SETTLED = 1e-8
#: Newton iterations before a correction is given up, and the halvings of a multiple-shooting step that does not
#: shrink the residual
MAX_ITERATIONS = 15
HALVINGS = 10
#: a correction whose residual grows this far above the least it reached is diverging: it is given up at once
DIVERGED = 1e3


@dataclass(frozen=True)
class Symmetry:
    """A reversing symmetry as the state components it keeps (`kept`, free at a crossing) and reverses (`reversed`,
    zero at a crossing), and its sign pattern R on the full state (for the monodromy)."""

    name: str
    kept: tuple[int, ...]
    reversed: tuple[int, ...]
    signs: np.ndarray = field(repr=False)


#: planar orbits crossing the x axis perpendicularly: (x, 0, 0, 0, vy, 0)
PLANAR = Symmetry("x axis, planar", (0, 4), (1, 3), cr3bp.XZ_PLANE)
#: spatial orbits crossing the x-z plane perpendicularly: (x, 0, z, 0, vy, 0)
XZ_PLANE = Symmetry("x-z plane", (0, 2, 4), (1, 3, 5), cr3bp.XZ_PLANE)
#: spatial orbits crossing the x axis perpendicularly: (x, 0, 0, 0, vy, vz)
X_AXIS = Symmetry("x axis", (0, 4, 5), (1, 2, 3), cr3bp.X_AXIS)


#: the absolute tolerance of a flow's integrations, dop853.RTOL times this fraction of its origin's length scale:
#: small enough that the relative tolerance governs the state everywhere but where a coordinate passes through 0
ATOL_SCALE = 1e-2
#: a Newton step this small (in units of the flow's length scale) cannot improve the residual in float64: the
#: correction ends there
SMALL_STEP = 1e-14


class Flow:
    """Trajectories of one binary (mu, units of orbits.core.periodic.cr3bp) written about an Origin
    (orbits.core.periodic.cr3bp: a
    collinear point, the primary or the secondary), from the NumPy integrator (orbits.core.dop853) or, when
    `compiled`, its numba port (orbits.core.periodic._fast_cr3bp), with what they cost: trajectories integrated (with or
    without the transition matrix), accepted steps, right-hand-side evaluations and Newton iterations. The
    absolute tolerance is dop853.RTOL times ATOL_SCALE of the origin's scale, so an orbit small beside the
    separation is held to its own size."""

    def __init__(self, mu: float, place: cr3bp.Origin, compiled: bool = False):
        self.mu = float(mu)
        self.origin = place
        self.compiled = bool(compiled)
        self.atol = dop853.RTOL * ATOL_SCALE * place.scale
        self.integrations = self.steps = self.evaluations = self.iterations = 0

    def barycentric(self, states) -> np.ndarray:
        """States (..., 6) about the barycentre from this flow's local states."""
        return cr3bp.to_barycentric(states, self.origin)

    def local(self, states) -> np.ndarray:
        """This flow's local states (..., 6) from states about the barycentre."""
        return cr3bp.from_barycentric(states, self.origin)

    def field(self, states) -> np.ndarray:
        """The vector field (..., 6) at local states."""
        return cr3bp.field(self.barycentric(states), self.mu)

    def __repr__(self) -> str:
        kind = "compiled" if self.compiled else "NumPy"
        return (f"Flow(mu = {self.mu:.8g} about {self.origin.name}, {kind}: {self.integrations} integrations, "
                f"{self.steps} steps, "
                f"{self.evaluations} evaluations, {self.iterations} Newton iterations)")

    def arc(self, state, duration: float, transition: bool = False, outputs=None) -> dop853.Arc:
        """The arc from `state` (6,) over `duration` (either sign), with Phi appended to `end` (42,) if
        `transition`, and the states at `outputs` (times from 0 towards duration) if given."""
        return self.arcs(np.asarray(state, dtype=float)[None], [duration], transition, outputs)[0]

    def arcs(self, states, durations, transition: bool = False, outputs=None) -> list[dop853.Arc]:
        """Arcs from each of `states` (B, 6) over each of `durations` (B,), all with the same `outputs`."""
        states = np.asarray(states, dtype=float)
        durations = np.asarray(durations, dtype=float)
        y0 = states
        if transition:
            y0 = np.concatenate([states, np.broadcast_to(np.eye(6).ravel(), (len(states), 36))], axis=1)
        arcs = self._compiled(y0, durations, transition, outputs) if self.compiled else None
        if arcs is None:
            field = cr3bp.vector_field(self.mu, self.origin, transition)
            arcs = [dop853.integrate(field, y, t, outputs=outputs, atol=self.atol, controlled=6)
                    for y, t in zip(y0, durations)]
        for arc in arcs:
            self.integrations += 1
            self.steps += arc.steps
            self.evaluations += arc.evaluations
        return arcs

    def _compiled(self, y0, durations, transition, outputs):
        """The arcs from the compiled port; None when its on-disk cache was unreadable (the NumPy path then runs)."""
        from orbits.core import _fast

        _fast.announce("_fast_cr3bp")
        from orbits.core.periodic import _fast_cr3bp

        count, dim = y0.shape
        marks = np.zeros((count, 0))
        if outputs is not None:
            marks = np.array([dop853.output_marks(outputs, t) for t in durations])
        n_marks = np.full(count, marks.shape[1], dtype=np.int64)
        ends = np.empty((count, dim))
        states = np.empty((count, marks.shape[1], dim))
        counts = np.zeros((count, 3), dtype=np.int64)
        status = np.zeros(count, dtype=np.int64)
        failed = _fast.run(_fast_cr3bp.integrate, count, self.mu, self.origin.from_primary,
                           self.origin.from_secondary, np.ascontiguousarray(y0), durations, marks, n_marks,
                           dop853.RTOL, self.atol, transition, ends, states, counts, status)
        if failed and not np.any(status):
            return None
        for i in np.flatnonzero(status):
            raise ConvergenceError(dop853.stop_message(int(status[i]) == _fast_cr3bp.MAX_STEPS_REACHED,
                                                       float(durations[i])))
        return [dop853.Arc(ends[i], states[i] if outputs is not None else None, int(counts[i, 0]),
                           int(counts[i, 1]), int(counts[i, 2])) for i in range(count)]


def use_compiled(continuation: bool) -> bool:
    """Whether corrections run the compiled integrator: under ORBITS_JIT=auto (the default) when its machine code is
    in the cache, and otherwise for continuations along a family, which integrate hundreds of trajectories and repay
    the compile, not for a single correction from a first guess; always with ORBITS_JIT=1, never with 0 or without
    numba."""
    from orbits.core import _fast

    return _fast.use(_fast.AUTO_MIN_BATCH if continuation else 1, "periodic._fast_cr3bp.integrate")


@dataclass(frozen=True, eq=False)
class Crossing:
    """A solution of the symmetric shooting problem: unknowns `u` = (kept components, tau), the initial `state`
    (about the flow's origin),
    the state and transition matrix Phi at the half period (`end`, `transition`), dF/du there (`jacobian`), the
    residual max |F| left, the Newton iterations it took, and `settled`: the first iteration whose residual was
    within SETTLED of the flow's scale (how far the prediction was from the family, a count that rounding noise
    cannot change: quadratic convergence passes that level by orders of magnitude, while the last iterations,
    spent at the noise floor, vary from one CPU to another)."""

    u: np.ndarray
    state: np.ndarray
    end: np.ndarray
    transition: np.ndarray
    jacobian: np.ndarray
    residual: float
    iterations: int
    settled: int

    @property
    def period(self) -> float:
        return 2.0 * float(self.u[-1])


class HalfPeriodMap:
    """F(u) of symmetric shooting along a Flow for one symmetry."""

    def __init__(self, flow: Flow, symmetry: Symmetry):
        self.flow, self.symmetry = flow, symmetry
        self.mu = flow.mu
        #: the continuation's metric: state components in units of the origin's length scale, tau as it is
        self.weights = np.append(np.full(len(symmetry.kept), 1.0 / flow.origin.scale), 1.0)

    def scaled(self, u) -> np.ndarray:
        """u in the continuation's metric (weights * u): a step of 1 moves the state by the origin's scale."""
        return np.asarray(u, dtype=float) * self.weights

    def state(self, u) -> np.ndarray:
        """The initial state x0(u): the kept components from u, zero elsewhere."""
        x0 = np.zeros(6)
        x0[list(self.symmetry.kept)] = u[:-1]
        return x0

    def unknowns(self, state, half_period: float) -> np.ndarray:
        """u of an initial state at a perpendicular crossing and its half period."""
        return np.append(np.asarray(state, dtype=float)[list(self.symmetry.kept)], half_period)

    def evaluate(self, u):
        """(F, dF/du, end state, Phi) at u."""
        u = np.asarray(u, dtype=float)
        if not u[-1] > 0.0:
            raise ConvergenceError(f"the half period fell to {u[-1]:.3g}: the correction left the family")
        arc = self.flow.arc(self.state(u), u[-1], transition=True)
        end, phi = arc.end[:6], arc.end[6:].reshape(6, 6)
        kept, rev = list(self.symmetry.kept), list(self.symmetry.reversed)
        jac = np.column_stack([phi[np.ix_(rev, kept)], self.flow.field(end)[rev]])
        return end[rev], jac, end, phi

    def correct(self, u, condition) -> Crossing:
        """Newton's method on F(u) = 0 and condition(u) = (g, dg/du) = 0 from u; ConvergenceError if it fails."""
        u = np.array(u, dtype=float)
        scale = self.flow.origin.scale
        accept, small = scale * TOLERANCE, scale * SMALL_STEP
        best, least, settled = None, math.inf, MAX_ITERATIONS + 1
        for iteration in range(1, MAX_ITERATIONS + 1):
            residual, jac, end, phi = self.evaluate(u)
            self.flow.iterations += 1
            g, dg = condition(u)
            size = float(np.max(np.abs(residual)))
            if not np.isfinite(size) or size > DIVERGED * least:
                break
            accept = max(scale * TOLERANCE, NOISE_MARGIN * dop853.RTOL * float(np.linalg.norm(phi, 2)) * scale)
            if best is not None and best.residual <= accept and size >= 0.5 * best.residual:
                return best  # the residual no longer shrinks: the last solution is as good as float64 allows
            least = min(least, size)
            settled = min(settled, iteration) if size <= scale * SETTLED else settled
            best = Crossing(u.copy(), self.state(u), end, phi, jac, size, iteration, settled)
            step = np.linalg.solve(np.vstack([jac, dg]), -np.append(residual, g))
            if size <= accept and float(np.max(np.abs(step))) <= small:
                return best
            u = u + step
        if best is not None and best.residual <= accept:
            return best
        last = "nan" if best is None else f"{best.residual:.3g}"
        raise ConvergenceError(f"the symmetric corrector did not converge in {MAX_ITERATIONS} iterations "
                               f"(residual {last}, tolerance {accept:.3g})")


def fixed_component(index: int, value: float):
    """condition(u) holding u[index] at value (a kept component of the initial state, or -1 for tau)."""

    def condition(u):
        gradient = np.zeros(u.size)
        gradient[index] = 1.0
        return u[index] - value, gradient

    return condition


def symmetric_monodromy(transition, signs) -> np.ndarray:
    """M = R Phi(tau)^-1 R Phi(tau), the monodromy of a symmetric orbit from its half-period transition matrix."""
    r = np.diag(np.asarray(signs, dtype=float))
    return r @ cr3bp.transition_inverse(transition) @ r @ transition


@dataclass(frozen=True, eq=False)
class ShotOrbit:
    """A solution of multiple shooting: the `nodes` (N, 6), the `period`, the arcs' transition matrices, the residual
    max |phi(X_i, T / N) - X_(i+1)| left and the Newton iterations it took."""

    nodes: np.ndarray
    period: float
    transitions: list
    residual: float
    iterations: int

    @property
    def monodromy(self) -> np.ndarray:
        """M = Phi_(N-1) ... Phi_1 Phi_0, the product of the arcs' transition matrices."""
        m = np.eye(6)
        for phi in self.transitions:
            m = phi @ m
        return m


def multiple_shooting(flow: Flow, nodes, period: float, jacobi: float | None = None) -> ShotOrbit:
    """Correct a periodic orbit from N >= 2 nodes (N, 6, about the flow's origin) spread evenly in time over one
    period guess.

    With `jacobi` None the period is held; otherwise the Jacobi constant of the first node is held at `jacobi` and
    the period is free. The first node keeps its y coordinate (the phase). ConvergenceError if it fails."""
    x = np.array(nodes, dtype=float)
    n = x.shape[0]
    period = float(period)
    phase = x[0, 1]
    accept, small = flow.origin.scale * TOLERANCE, flow.origin.scale * SMALL_STEP
    residual, jac, transitions = _shooting_system(flow, x, period, jacobi, phase)
    size = float(np.max(np.abs(residual)))
    best = ShotOrbit(x.copy(), period, transitions, size, 0)
    for iteration in range(1, 2 * MAX_ITERATIONS + 1):
        flow.iterations += 1
        step = np.linalg.lstsq(jac, -residual, rcond=None)[0]
        if size <= accept and float(np.max(np.abs(step))) <= small:
            return best
        for _ in range(HALVINGS):  # damped: the step is halved until the residual shrinks
            trial_x = x + step[: 6 * n].reshape(n, 6)
            trial_period = period + (float(step[-1]) if jacobi is not None else 0.0)
            try:
                trial = _shooting_system(flow, trial_x, trial_period, jacobi, phase)
            except ConvergenceError:
                trial = None
            if trial is not None and np.linalg.norm(trial[0]) < np.linalg.norm(residual):
                break
            step = 0.5 * step
        else:
            break
        x, period = trial_x, trial_period
        residual, jac, transitions = trial
        new_size = float(np.max(np.abs(residual)))
        stalled = new_size >= 0.5 * size and new_size <= accept
        size = new_size
        best = ShotOrbit(x.copy(), period, transitions, size, iteration)
        if stalled or size == 0.0:
            return best
    if best.residual <= accept:
        return best
    raise ConvergenceError(f"multiple shooting did not converge in {2 * MAX_ITERATIONS} iterations (residual "
                           f"{best.residual:.3g}, tolerance {accept:.3g})")


def _shooting_system(flow, x, period, jacobi, phase):
    """Residual, Jacobian and arc transition matrices of the multiple-shooting problem: rows 6i .. 6i + 5 the
    continuity of arc i, then the phase and (with a held Jacobi constant) the energy; columns the nodes, then the
    period when it is free."""
    n = x.shape[0]
    free_period = jacobi is not None
    rows = 6 * n + 1 + int(free_period)
    jac = np.zeros((rows, 6 * n + int(free_period)))
    residual = np.zeros(rows)
    arcs = flow.arcs(x, np.full(n, period / n), transition=True)
    transitions = []
    for i, arc in enumerate(arcs):
        end, phi = arc.end[:6], arc.end[6:].reshape(6, 6)
        transitions.append(phi)
        j = (i + 1) % n
        residual[6 * i: 6 * i + 6] = end - x[j]
        jac[6 * i: 6 * i + 6, 6 * i: 6 * i + 6] += phi
        jac[6 * i: 6 * i + 6, 6 * j: 6 * j + 6] -= np.eye(6)
        if free_period:
            jac[6 * i: 6 * i + 6, -1] = flow.field(end) / n
    residual[6 * n] = x[0, 1] - phase
    jac[6 * n, 1] = 1.0
    if free_period:
        first = flow.barycentric(x[0])
        residual[6 * n + 1] = float(cr3bp.jacobi_constant(first, flow.mu)) - jacobi
        jac[6 * n + 1, :6] = cr3bp.jacobi_gradient(first, flow.mu)
    return residual, jac, transitions
