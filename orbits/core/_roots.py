"""Safeguarded root finding shared by the Kepler solvers and the universal-variable propagator."""

import numpy as np

from orbits.errors import ConvergenceError

MAX_ITERATIONS = 60


def halley_in_bracket(x, lo, hi, residual, what, inputs):
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
        xa = x[idx]
        f, df, d2f = residual(xa, idx)
        lo[idx] = np.where(f < 0, xa, lo[idx])
        hi[idx] = np.where(f > 0, xa, hi[idx])
        with np.errstate(all="ignore"):
            step = -f / (df - 0.5 * f * d2f / df)
        new = xa + step
        inside = np.isfinite(new) & (new >= lo[idx]) & (new <= hi[idx])
        new = np.where(inside, new, 0.5 * (lo[idx] + hi[idx]))
        moved = np.abs(new - xa)
        x[idx] = new
        done = (f == 0) | (inside & (moved <= 2.0**-26 * np.abs(new)))
        done |= hi[idx] - lo[idx] <= 2.0**-52 * np.abs(new)
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
