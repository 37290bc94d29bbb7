"""Compiled integration of the restricted problem (numba): a port of orbits.core.dop853.integrate driving
orbits.core.periodic.cr3bp.vector_field (states about an Origin), with and without the state transition matrix.

Imported only through orbits.core.periodic.shooting, when orbits.core._fast.use lets a correction run compiled. Step for
step the NumPy version's: the same first step, stages, error norm on the six state components, step-size rule,
landing on output times and stopping rules, with the coefficients from orbits.core._dop853_shared. The sums run in
another order than NumPy's matrix products, so the two agree to rounding (tests/core/test_periodic_core.py), not bit
for bit. One call integrates a batch of trajectories (the arcs of a multiple-shooting correction), each to its own
duration; status[i] is 0, or MAX_STEPS_REACHED / STEP_UNDERFLOW for a trajectory the NumPy version would stop with a
ConvergenceError.
"""

import math

import numpy as np

from orbits.core._dop853_shared import E3, E5, GROW, MAX_STEPS, ORDER, SAFETY, SHRINK, SMALLEST_STEP, A, B
from orbits.core._fast import jit

MAX_STEPS_REACHED = 1
STEP_UNDERFLOW = 2


@jit
def _pull(a, x, y, z, out):
    """orbits.core.periodic.cr3bp._pull into out[0:4]: the pull less its value at the origin, and |d|**2."""
    dx = a + x
    rho = y * y + z * z
    s = dx * dx + rho
    d = math.sqrt(s)
    inverse_cube = 1.0 / (s * d)
    out[1], out[2], out[3] = y * inverse_cube, z * inverse_cube, s
    if a == 0.0:
        out[0] = x * inverse_cube
        return
    span = abs(a)
    delta = x * (2.0 * a + x) + rho
    change = -delta * (s + d * span + a * a) / ((d + span) * s * d * a * a * span)
    out[0] = x * inverse_cube + a * change


@jit
def _field(mu, a1, a2, y, out, transition, pulls):
    """out = f(y) about the origin at offsets a1, a2 from the primaries: the state's derivative, and Phi' = A Phi
    when `transition` (y holds Phi row by row after the state); pulls is (2, 4) scratch."""
    one_minus = 1.0 - mu
    x, yy, z, vx, vy = y[0], y[1], y[2], y[3], y[4]
    _pull(a1, x, yy, z, pulls[0])
    _pull(a2, x, yy, z, pulls[1])
    out[0], out[1], out[2] = vx, vy, y[5]
    out[3] = x + 2.0 * vy - one_minus * pulls[0, 0] - mu * pulls[1, 0]
    out[4] = yy - 2.0 * vx - one_minus * pulls[0, 1] - mu * pulls[1, 1]
    out[5] = -one_minus * pulls[0, 2] - mu * pulls[1, 2]
    if not transition:
        return
    s1, s2 = pulls[0, 3], pulls[1, 3]
    dx1, dx2 = x + a1, x + a2
    g1, g2 = one_minus / (s1 * math.sqrt(s1)), mu / (s2 * math.sqrt(s2))
    g = g1 + g2
    h1, h2 = 3.0 * g1 / s1, 3.0 * g2 / s2
    hx = h1 * dx1 + h2 * dx2
    hh = h1 + h2
    uxx = 1.0 - g + h1 * dx1 * dx1 + h2 * dx2 * dx2
    uyy = 1.0 - g + hh * yy * yy
    uzz = -g + hh * z * z
    uxy, uxz, uyz = hx * yy, hx * z, hh * yy * z
    for j in range(6):
        p0, p1, p2 = y[6 + j], y[12 + j], y[18 + j]
        q0, q1, q2 = y[24 + j], y[30 + j], y[36 + j]
        out[6 + j], out[12 + j], out[18 + j] = q0, q1, q2
        out[24 + j] = uxx * p0 + uxy * p1 + uxz * p2 + 2.0 * q1
        out[30 + j] = uxy * p0 + uyy * p1 + uyz * p2 - 2.0 * q0
        out[36 + j] = uxz * p0 + uyz * p1 + uzz * p2


@jit
def _rms(values, y, n, rtol, atol):
    """sqrt(mean((values / (atol + rtol |y|))**2)) over the first n components."""
    total = 0.0
    for i in range(n):
        w = values[i] / (atol + rtol * abs(y[i]))
        total += w * w
    return math.sqrt(total / n)


@jit
def _first_step(mu, a1, a2, y, f0, n, span, rtol, atol, transition, work, f1, pulls):
    """The NumPy version's starting step (Hairer, Norsett and Wanner, II.4)."""
    d0, d1 = _rms(y, y, n, rtol, atol), _rms(f0, y, n, rtol, atol)
    h0 = 1e-6 if d0 < 1e-5 or d1 < 1e-5 else 0.01 * d0 / d1
    if span > 0.0:
        h0 = min(h0, span)
    for i in range(y.size):
        work[i] = y[i] + h0 * f0[i]
    _field(mu, a1, a2, work, f1, transition, pulls)
    for i in range(n):
        work[i] = f1[i] - f0[i]
    d2 = _rms(work, y, n, rtol, atol) / h0
    big = max(d1, d2)
    h1 = max(1e-6, h0 * 1e-3) if big <= 1e-15 else (0.01 / big) ** (1.0 / (ORDER + 1))
    h = min(100.0 * h0, h1)
    return min(h, span) if span > 0.0 else h


@jit
def _step(mu, a1, a2, y, h, stages, n, rtol, atol, transition, work, y_new, pulls):
    """One step of size h from y (stages[0] = f(y)) into y_new; returns the scaled error norm (inf where a stage
    meets a singularity)."""
    dim = y.size
    for s in range(1, 12):
        for i in range(dim):
            total = 0.0
            for j in range(s):
                total += A[s, j] * stages[j, i]
            work[i] = y[i] + h * total
        _field(mu, a1, a2, work, stages[s], transition, pulls)
    for i in range(dim):
        total = 0.0
        for j in range(12):
            total += B[j] * stages[j, i]
        y_new[i] = y[i] + h * total
    e5, e3 = 0.0, 0.0
    for i in range(n):
        scale = atol + rtol * max(abs(y[i]), abs(y_new[i]))
        a5, a3 = 0.0, 0.0
        for j in range(12):
            a5 += E5[j] * stages[j, i]
            a3 += E3[j] * stages[j, i]
        a5 /= scale
        a3 /= scale
        e5 += a5 * a5
        e3 += a3 * a3
    if not (math.isfinite(e5) and math.isfinite(e3)):
        return math.inf
    if e5 == 0.0 and e3 == 0.0:
        return 0.0
    return abs(h) * e5 / math.sqrt((e5 + 0.01 * e3) * n)


@jit
def _integrate_one(mu, a1, a2, y0, t_end, marks, n_marks, rtol, atol, transition, end, states, counts):
    """One trajectory (the NumPy integrate's loop); returns its status."""
    dim = y0.size
    n = 6
    y = y0.copy()
    stages = np.empty((12, dim))
    work = np.empty(dim)
    y_new = np.empty(dim)
    f1 = np.empty(dim)
    pulls = np.empty((2, 4))
    direction = 1.0 if t_end >= 0.0 else -1.0
    _field(mu, a1, a2, y, stages[0], transition, pulls)
    h = direction * _first_step(mu, a1, a2, y, stages[0], n, abs(t_end), rtol, atol, transition, work, f1, pulls)
    evaluations, steps, rejected = 2, 0, 0
    t = 0.0
    k = 0
    while k < n_marks and marks[k] * direction <= 0.0:
        states[k, :] = y
        k += 1
    status = 0
    for m in range(k, n_marks + 1):
        target = marks[m] if m < n_marks else t_end
        while (target - t) * direction > 0.0:
            if steps + rejected >= MAX_STEPS:
                status = MAX_STEPS_REACHED
                break
            landing = (t + h - target) * direction >= 0.0
            step = target - t if landing else h
            norm = _step(mu, a1, a2, y, step, stages, n, rtol, atol, transition, work, y_new, pulls)
            evaluations += 11
            factor = SAFETY * norm ** (-1.0 / ORDER) if norm > 0.0 else GROW
            if norm <= 1.0:
                t = target if landing else t + step
                y[:] = y_new
                _field(mu, a1, a2, y, stages[0], transition, pulls)
                evaluations += 1
                steps += 1
                if not landing or abs(step) >= abs(h):
                    h = step * min(GROW, max(SHRINK, factor))
            else:
                rejected += 1
                h = step * max(SHRINK, factor)
                if abs(h) < SMALLEST_STEP * max(abs(t), 1.0):
                    status = STEP_UNDERFLOW
                    break
        if status != 0:
            break
        if m < n_marks:
            states[m, :] = y
    end[:] = y
    counts[0], counts[1], counts[2] = steps, rejected, evaluations
    return status


@jit
def integrate(start, stop, mu, a1, a2, y0, durations, marks, n_marks, rtol, atol, transition, ends, states, counts,
              status):
    """Trajectories start .. stop - 1 of a batch about the origin at offsets a1, a2 from the primaries (orbits.core.
    cr3bp.Origin): y0 (B, dim), durations (B,), output times marks (B, K) of which the
    first n_marks[i] count; fills ends (B, dim), states (B, K, dim), counts (B, 3) = (steps, rejected,
    evaluations) and status (B,). Returns how many trajectories stopped early."""
    failed = 0
    for i in range(start, stop):
        status[i] = _integrate_one(mu, a1, a2, y0[i], durations[i], marks[i], n_marks[i], rtol, atol, transition,
                                   ends[i], states[i], counts[i])
        if status[i] != 0:
            failed += 1
    return failed
