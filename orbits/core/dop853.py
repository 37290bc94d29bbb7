"""An explicit Runge-Kutta integrator of order 8: Dormand and Prince's DOP853, with its 5th- and 3rd-order error
estimates (Hairer, Norsett and Wanner, Solving Ordinary Differential Equations I, 2nd ed., 1993, section II.10).

It integrates y' = f(y) (autonomous) from t = 0 to t_end, landing exactly on requested output times and on t_end
(a step that would pass one is shortened to end on it). The local error of each step is estimated on the first
`controlled` components only, in the scaled RMS norm of the method (err5**2 / sqrt(err5**2 + 0.01 err3**2)) with
scale atol + rtol max(|y|, |y_new|); a step is accepted when that norm is at most 1 and the next step is
h * min(10, max(0.2, 0.9 norm**(-1/8))). Error control on the state alone makes a trajectory the same whether or
not its state transition matrix rides along, so a corrector's residual does not depend on whether it asks for
derivatives. The default tolerance, rtol = atol = 100 eps (2.2e-14), is the tightest this method honours in float64
(tests/core/test_periodic_core.py measures its global error on Kepler ellipses against Kepler's equation).

The coefficients and the step-size rule's constants live in orbits.core._dop853_shared, which the compiled port
(orbits/core/periodic/_fast_cr3bp.py) imports too.
"""

import math
from dataclasses import dataclass

import numpy as np

from orbits.core._dop853_shared import ATOL, E3, E5, GROW, MAX_STEPS, ORDER, RTOL, SAFETY, SHRINK, SMALLEST_STEP, A, B
from orbits.core.errors import ConvergenceError, OrbitDomainError


@dataclass(frozen=True, eq=False)
class Arc:
    """An integrated trajectory: `end` = y(t_end), `states` (K, n) at the requested output times (None if none were
    asked), and what it cost: accepted `steps`, `rejected` steps and right-hand-side `evaluations`."""

    end: np.ndarray
    states: np.ndarray | None
    steps: int
    rejected: int
    evaluations: int


def integrate(f, y0, t_end: float, outputs=None, rtol: float = RTOL, atol: float = ATOL,
              controlled: int | None = None) -> Arc:
    """Integrate y' = f(y) from y(0) = y0 to t_end (either sign), landing on each of `outputs` (times between 0 and
    t_end, in the direction of integration, non-decreasing) and on t_end; the first `controlled` components of y
    (all by default) set the step sizes.

    Raises ConvergenceError when the steps shrink below 1e-13 of the elapsed time or exceed MAX_STEPS (the
    trajectory runs into a singularity, such as a primary)."""
    y = np.array(y0, dtype=float)
    t_end = float(t_end)
    direction = 1.0 if t_end >= 0.0 else -1.0
    marks = output_marks(outputs, t_end)
    n = y.size if controlled is None else int(controlled)
    states = np.empty((len(marks), y.size)) if outputs is not None else None
    stages = np.empty((12, y.size))
    stages[0] = f(y)
    evaluations = 1
    h = direction * _first_step(f, y, stages[0], n, abs(t_end), rtol, atol)
    evaluations += 1
    t, steps, rejected, k = 0.0, 0, 0, 0
    while k < len(marks) and marks[k] * direction <= 0.0:  # outputs at t = 0
        states[k] = y
        k += 1
    targets = np.concatenate([marks[k:], [t_end]]) if outputs is not None else np.array([t_end])
    for target in targets:
        while (target - t) * direction > 0.0:
            if steps + rejected >= MAX_STEPS:
                raise ConvergenceError(stop_message(True, t_end))
            landing = (t + h - target) * direction >= 0.0
            step = target - t if landing else h
            y_new, norm = _step(f, y, step, stages, n, rtol, atol)
            evaluations += 11
            factor = SAFETY * norm ** (-1.0 / ORDER) if norm > 0.0 else GROW
            if norm <= 1.0:
                t = target if landing else t + step
                y = y_new
                stages[0] = f(y)
                evaluations += 1
                steps += 1
                if not landing or abs(step) >= abs(h):
                    h = step * min(GROW, max(SHRINK, factor))
            else:
                rejected += 1
                h = step * max(SHRINK, factor)
                if abs(h) < SMALLEST_STEP * max(abs(t), 1.0):
                    raise ConvergenceError(stop_message(False, t_end))
        if outputs is not None and k < len(marks):
            states[k] = y
            k += 1
    return Arc(y, states, steps, rejected, evaluations)


def output_marks(outputs, t_end: float) -> np.ndarray:
    """The requested output times as a float array, checked to run monotonically from 0 towards t_end."""
    direction = 1.0 if t_end >= 0.0 else -1.0
    if outputs is None:
        return np.zeros(0)
    marks = np.asarray(outputs, dtype=float).ravel()
    if marks.size and (np.any(np.diff(marks) * direction < 0.0) or marks[0] * direction < 0.0
                       or (marks[-1] - t_end) * direction > 0.0):
        raise OrbitDomainError(f"output times must run monotonically from 0 to t_end = {t_end:.6g}; got "
                               f"{marks[0]:.6g} ... {marks[-1]:.6g}")
    return marks


def stop_message(too_many_steps: bool, t_end: float) -> str:
    """Why an integration towards t_end stopped early (a ConvergenceError's message)."""
    if too_many_steps:
        return (f"the integration to t = {t_end:.6g} took more than {MAX_STEPS} steps: the trajectory runs into a "
                f"singularity (a primary)")
    return f"the step size of the integration to t = {t_end:.6g} fell below float64's reach: the trajectory runs " \
           f"into a singularity (a primary)"


def _step(f, y, h, stages, n, rtol, atol):
    """One DOP853 step of size h from y (stages[0] = f(y)): (y_new, scaled error norm); the norm is inf when a stage
    lands on or next to a singularity (a non-finite value, or one beyond float64), so that the step is retried
    shorter."""
    try:
        with np.errstate(over="raise", invalid="raise", divide="raise"):
            for s in range(1, 12):
                stages[s] = f(y + h * (A[s, :s] @ stages[:s]))
            y_new = y + h * (B @ stages)
            scale = atol + rtol * np.maximum(np.abs(y[:n]), np.abs(y_new[:n]))
            err5 = (E5 @ stages[:, :n]) / scale
            err3 = (E3 @ stages[:, :n]) / scale
            e5, e3 = float(err5 @ err5), float(err3 @ err3)
    except (ArithmeticError, FloatingPointError):
        return y, math.inf
    if not (math.isfinite(e5) and math.isfinite(e3)):
        return y, math.inf
    if e5 == 0.0 and e3 == 0.0:
        return y_new, 0.0
    return y_new, abs(h) * e5 / math.sqrt((e5 + 0.01 * e3) * n)


def _first_step(f, y, f0, n, span, rtol, atol):
    """Starting step from the scaled sizes of y, y' and y'' (Hairer, Norsett and Wanner, II.4), at most the span."""
    scale = atol + rtol * np.abs(y[:n])
    d0 = np.sqrt(np.mean((y[:n] / scale) ** 2))
    d1 = np.sqrt(np.mean((f0[:n] / scale) ** 2))
    h0 = 1e-6 if d0 < 1e-5 or d1 < 1e-5 else 0.01 * d0 / d1
    h0 = min(h0, span) if span > 0.0 else h0
    f1 = f(y + h0 * f0)
    d2 = np.sqrt(np.mean(((f1[:n] - f0[:n]) / scale) ** 2)) / h0
    h1 = max(1e-6, h0 * 1e-3) if max(d1, d2) <= 1e-15 else (0.01 / max(d1, d2)) ** (1.0 / (ORDER + 1))
    return min(100.0 * h0, h1, span) if span > 0.0 else min(100.0 * h0, h1)
