"""Tanh-sinh (double-exponential) quadrature over many intervals at once, for the Friedmann integrals."""

import functools
from collections.abc import Callable

import numpy as np
from numpy.typing import ArrayLike

from orbits.core.errors import ConvergenceError

_TS_STEP = 0.5  # level-0 step in the tanh-sinh variable s
_TS_S_MAX = 4.5  # nodes s in [-4.5, 4.5] reach exp(-pi sinh 4.5) ~ 1e-61 of the width from each end
_TS_LEVELS = 8  # finest step 0.5 / 2**7 (2305 nodes)
_TS_MIN_LEVEL = 3
_TS_TOLERANCE = 2.0**-36  # successive levels agree to this: the error then is ~ its square (double exponential)
_TS_CHUNK = 2048  # elements integrated at once (bounds memory)


@functools.cache
def _ts_level(level):
    """Nodes of one tanh-sinh level: (s < 0 mask, fraction q of the width to the nearer end, weight).

    x = lo + width q near lo (s < 0) or hi - width q near hi; dx = width pi cosh(s) q (1 - q) ds, with
    q = e / (1 + e), e = exp(-pi sinh|s|), computed without cancellation at both ends.
    """
    h = _TS_STEP / 2**level
    n = round(_TS_S_MAX / h)
    s = np.arange(-n, n + 1) * h if level == 0 else np.arange(-n + 1, n, 2) * h
    e = np.exp(-np.pi * np.sinh(np.abs(s)))
    q = e / (1.0 + e)
    return s < 0, q, np.pi * np.cosh(s) * q * (1.0 - q)


def tanh_sinh(
    integrand: Callable[[np.ndarray, np.ndarray, np.ndarray], np.ndarray], lo: ArrayLike, hi: ArrayLike
) -> np.ndarray:
    """int_lo^hi integrand(x, d, hi) dx for 1-D arrays of finite lo <= hi; d = hi - x, exact near hi.

    Levels halve the step until two successive estimates agree to 2**-36 relative (double-exponential
    convergence then leaves an error near the square of that). Raises ConvergenceError otherwise.
    """
    lo, hi = np.broadcast_arrays(np.asarray(lo, dtype=float), np.asarray(hi, dtype=float))
    out = np.zeros(lo.shape)
    for start in range(0, lo.size, _TS_CHUNK):
        rows = slice(start, start + _TS_CHUNK)
        out[rows] = _chunk(integrand, lo[rows], hi[rows])
    return out


def _chunk(integrand, lo, hi):
    width = hi - lo
    total = np.zeros(lo.shape)
    estimate = np.zeros(lo.shape)
    active = width > 0
    for level in range(_TS_LEVELS):
        rows = np.flatnonzero(active)
        if rows.size == 0:
            return estimate
        low_side, q, weight = _ts_level(level)
        w = width[rows, None]
        x = np.where(low_side, lo[rows, None] + w * q, hi[rows, None] - w * q)
        d = np.where(low_side, w * (1.0 - q), w * q)
        with np.errstate(under="ignore"):
            total[rows] += np.sum(weight * integrand(x, d, hi[rows, None]), axis=-1)
        new = width[rows] * total[rows] * (_TS_STEP / 2**level)
        settled = np.abs(new - estimate[rows]) <= _TS_TOLERANCE * np.abs(new)
        estimate[rows] = new
        if level >= _TS_MIN_LEVEL:
            active[rows[settled]] = False
    if np.any(active):
        i = np.flatnonzero(active)[0]
        raise ConvergenceError(
            f"tanh-sinh quadrature over [{float(lo[i])!r}, {float(hi[i])!r}] did not converge in {_TS_LEVELS} levels "
            f"(last estimate {float(estimate[i])!r}); the model may be too close to a loitering universe"
        )
    return estimate
