"""Safeguarded root finding, vectorised over arrays: Halley for the Kepler solvers and the universal-variable
propagator, Newton (rtsafe) for the Friedmann scale factor. Both keep a bracket and bisect when a step leaves it."""

from collections.abc import Callable

import numpy as np
from numpy.typing import ArrayLike

from orbits.core.errors import ConvergenceError

MAX_ITERATIONS = 60
NEWTON_MAX_ITERATIONS = 100


def halley_in_bracket(
    x: np.ndarray,
    lo: np.ndarray,
    hi: np.ndarray,
    residual: Callable[[np.ndarray, tuple[np.ndarray, ...]], tuple[np.ndarray, np.ndarray, np.ndarray]],
    what: str,
    inputs: dict[str, ArrayLike],
) -> np.ndarray:
    """Safeguarded Halley iteration for an increasing function inside [lo, hi].

    residual(x, active) returns (f, f', f'') at the points x[active]. Steps leaving the bracket are
    replaced by bisection. Iterates until the last step is below 2**-26 relative (Halley's cubic
    convergence then puts the iterate at the root to rounding), then takes one polishing Newton step.
    """
    active = np.ones(x.shape, dtype=bool)
    for _ in range(MAX_ITERATIONS):
        idx = np.nonzero(active)
        if idx[0].size == 0:
            break
        x[idx], lo[idx], hi[idx], done = halley_step(x[idx], lo[idx], hi[idx], *residual(x[idx], idx))
        active[idx] = ~done
    if np.any(active):
        i = tuple(np.argwhere(active)[0])
        at = ", ".join(f"{k} = {float(np.asarray(v)[i])!r}" for k, v in inputs.items())
        raise ConvergenceError(
            f"{what} did not converge in {MAX_ITERATIONS} iterations at {at}; last iterate {float(x[i])!r}, "
            f"bracket [{float(lo[i])!r}, {float(hi[i])!r}]"
        )
    f, df, _ = residual(x, np.nonzero(np.ones(x.shape, dtype=bool)))
    with np.errstate(all="ignore"):
        polished = x - f / df
    return np.where(np.isfinite(polished) & (f != 0), polished, x)


def halley_step(
    x: np.ndarray, lo: np.ndarray, hi: np.ndarray, f: np.ndarray, df: np.ndarray, d2f: np.ndarray
) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    """One safeguarded Halley step of an increasing function: (x, lo, hi, converged). The bracket [lo, hi] first
    moves to x by the sign of f = f(x); a step that leaves it is replaced by bisection. Converged when f == 0,
    when the Halley step was below 2**-26 relative, or when the bracket is down to 2**-52 relative. The compiled
    solvers' _halley_step (orbits/core/twobody/_fast_kepler.py) is its port."""
    lo, hi = np.where(f < 0, x, lo), np.where(f > 0, x, hi)
    with np.errstate(all="ignore"):
        new = x - f / (df - 0.5 * f * d2f / df)
    inside = np.isfinite(new) & (new >= lo) & (new <= hi)
    new = np.where(inside, new, 0.5 * (lo + hi))
    done = (f == 0) | (inside & (np.abs(new - x) <= 2.0**-26 * np.abs(new))) | (hi - lo <= 2.0**-52 * np.abs(new))
    return new, lo, hi, done


def newton_in_bracket(
    y: np.ndarray,
    lo: np.ndarray,
    hi: np.ndarray,
    residual: Callable[[np.ndarray, np.ndarray], tuple[np.ndarray, np.ndarray]],
) -> np.ndarray:
    """Newton's method for an increasing function of y inside [lo, hi], safeguarded as in rtsafe: a step that
    leaves the bracket or fails to halve the previous one is replaced by bisection.

    residual(y, rows) returns (f, f') at y for those rows. Stops after the step taken from a point where
    |f| <= 2**-40 (f is a relative residual, so quadratic convergence then leaves y within rounding of the
    root), or when the bracket has shrunk to rounding (near a turnaround, where f' grows without bound).
    """
    active = np.ones(y.shape, dtype=bool)
    last_step = hi - lo
    for _ in range(NEWTON_MAX_ITERATIONS):
        rows = np.flatnonzero(active)
        if rows.size == 0:
            return y
        f, slope = residual(y[rows], rows)
        lo[rows] = np.where(f <= 0, y[rows], lo[rows])
        hi[rows] = np.where(f >= 0, y[rows], hi[rows])
        with np.errstate(all="ignore"):
            step = -f / slope
        newton = np.isfinite(slope) & np.isfinite(step) & (np.abs(step) <= 0.5 * last_step[rows])
        newton &= (y[rows] + step >= lo[rows]) & (y[rows] + step <= hi[rows])
        new = np.where(newton, y[rows] + np.where(newton, step, 0.0), 0.5 * (lo[rows] + hi[rows]))
        last_step[rows] = np.abs(new - y[rows])
        y[rows] = new
        collapsed = hi[rows] - lo[rows] <= 2.0**-52 * np.maximum(1.0, np.abs(new))
        active[rows] = ~((newton & (np.abs(f) <= 2.0**-40)) | (f == 0) | collapsed)
    i = np.flatnonzero(active)[0]
    raise ConvergenceError(
        f"scale factor a(t): Newton's method in ln a did not converge in {NEWTON_MAX_ITERATIONS} iterations; "
        f"last ln a = {float(y[i])!r}, bracket [{float(lo[i])!r}, {float(hi[i])!r}]"
    )
