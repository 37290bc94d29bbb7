"""Compiled Kepler solvers (numba): the algorithms of orbits.core.twobody.kepler, one element at a time.

Imported only through orbits.core.twobody.kepler when the compiled kernels are enabled (see orbits.core._fast).
Every kernel has the signature kernel(start, stop, inputs..., out) and returns
``invalid * 2**32 + unconverged``: invalid counts inputs outside the domain (the caller then raises the
NumPy checks' error message), unconverged counts solves that hit the iteration cap (ConvergenceError).

Elliptic solver (kepler._elliptic_single_pass), in blocks of _BLOCK elements, each in two vectorised stages
(AVX2 or AVX-512) whose short dependency chains the CPU overlaps:
1. Exact reduction of M modulo 2 pi and Markley's (1995) starter, without contraction (the reduction's
   double-double parts stay exact); the starter's cube root to 2e-5 (_cbrt_rough), below its own 2.8e-4.
2. With fused multiply-adds: one evaluation of sin x, x - sin x and 1 - cos x from Taylor polynomials on
   [0, 2] and, past x = 2, on pi - x (no libm call, which would block the vectoriser), and one sixth-order step.
   Elements whose Newton step exceeds SINGLE_PASS_ACCEPT x are marked NaN.
Then the safeguarded Halley iteration of orbits.core._roots from the cubic starter on the marked elements
(none of 1.6e6 random pairs over every e < 1 needed it; tests call it directly). Every loop runs over views with
range(n): LLVM then vectorises it behind a run-time alias check that distinct arrays pass whatever their
addresses (a range(start, stop) loop over the whole arrays fell back to scalar code when the output began less
than 32 bytes after an input). Throughput against heyoka's kepE is in the README's Benchmarks section.
Measured along the way: without numba-level inlining of the helpers LLVM does not vectorise, and a chain of ifs
for the quadrant of sin and cos stops the vectoriser too (hence the arithmetic selections); moving the starter
into the second stage cost a quarter of the speed.

The hyperbolic solver has two passes too (the first: two bracketed sixth-order steps on the series form, with
its own exp, vectorised; a port with libm calls ran five times slower). Barker's equation is a branch-free closed
form.
"""

import math

import numpy as np

from orbits.core._fast import jit
from orbits.core._fast_math import _cbrt, _cbrt_normal, _cbrt_rough, _exp, _horner, _log_approx, _two_product, _two_sum
from orbits.core._roots import MAX_ITERATIONS
from orbits.core.twobody._kepler_shared import (
    COSH_MINUS_ONE,
    HYPERBOLIC_FIXED_STEPS,
    INVERSE_TWO_PI,
    LOG_FORM_LIMIT,
    MARKLEY_SCALE,
    MAX_MEAN_ANOMALY,
    ONE_MINUS_COS,
    PI_1,
    PI_2,
    SERIES_LIMIT,
    SINGLE_PASS_ACCEPT,
    SINH_MINUS_X,
    TINY_MEAN_ANOMALY,
    TWO_PI_1,
    TWO_PI_2,
    TWO_PI_3,
    X_MINUS_SIN,
)

assert HYPERBOLIC_FIXED_STEPS == 2, "_hyperbolic_fixed writes its two steps out"
_INVALID = 1 << 32


@jit(inline=True)
def _reduce(M, M_lo):
    """(hi, lo) = M + M_lo - 2 pi round(M / 2 pi) in [-pi, pi] as a double-double (kepler.reduce_two_pi)."""
    k = np.rint(M * INVERSE_TWO_PI)
    p1, e1 = _two_product(k, TWO_PI_1)
    p2, e2 = _two_product(k, TWO_PI_2)
    hi, lo = _two_sum(M - p1, -e1)
    hi, t = _two_sum(hi, -p2)
    lo = lo + t - e2 - k * TWO_PI_3 + M_lo
    hi, lo = _two_sum(hi, lo)
    shift = -1.0 if hi > np.pi else (1.0 if hi < -np.pi else 0.0)
    hi, t = _two_sum(hi + shift * TWO_PI_1, shift * TWO_PI_2)
    return _two_sum(hi, lo + t)


@jit(inline=True)
def _trig(x):
    """(sin x, x - sin x, 1 - cos x) for x in [0, pi], each free of cancellation, no libm call."""
    reflect = x >= 2.0
    z = (PI_1 - x) + PI_2 if reflect else x  # pi - x, exact to rounding of the final sum
    z2 = z * z
    z_minus_sin = z2 * z * _horner(X_MINUS_SIN, z2)
    one_minus_cos = z2 * _horner(ONE_MINUS_COS, z2)
    sin = z - z_minus_sin
    x_minus_sin = x - sin if reflect else z_minus_sin
    return sin, x_minus_sin, (2.0 - one_minus_cos if reflect else one_minus_cos)


@jit(inline=True)
def _elliptic_residual(x, m, m_lo, e, one_minus_e):
    """(f, f', f'') of f(x) = (1 - e) x - m + e (x - sin x) - m_lo."""
    sin, x_minus_sin, one_minus_cos = _trig(x)
    return ((one_minus_e * x - m) + e * x_minus_sin) - m_lo, one_minus_e + e * one_minus_cos, e * sin


@jit(inline=True)
def _markley_starter(m, e):
    """kepler.markley_starter: Markley's (1995, Celest. Mech. 63, 101) starter for E in [0, pi] from m in
    [0, pi], written with two divisions."""
    alpha = (3.0 * np.pi**2 + 1.6 * np.pi * (np.pi - m) / (1.0 + e)) * MARKLEY_SCALE
    d = 3.0 * (1.0 - e) + alpha * e
    q = 2.0 * alpha * d * (1.0 - e) - m * m
    r = 3.0 * alpha * d * (d - 1.0 + e) * m + m * m * m
    w = _cbrt_rough(abs(r) + math.sqrt(q * q * q + r * r))
    w = w * w
    denominator = w * w + w * q + q * q
    return (2.0 * r * w + m * denominator) / (denominator * d)


@jit(inline=True)
def _cubic_root(linear, cubic, rhs):
    """Positive root of linear x + cubic x**3 = rhs, cancellation free (kepler._cubic_root)."""
    q = rhs / cubic
    scale = _cbrt(q) if np.isfinite(q) else _cbrt(rhs) / _cbrt(cubic)
    ps = (linear / cubic) / (scale * scale)
    if ps > 1e30:
        return rhs / linear
    w = _cbrt(0.5 + math.sqrt(0.25 + ps * ps * ps / 27.0))
    v = ps / (3.0 * w)
    return scale / (w * w + ps / 3.0 + v * v)


_ELLIPTIC, _HYPERBOLIC_SERIES, _HYPERBOLIC_LOG = 0, 1, 2


@jit(inline=True)
def _hyperbolic_trig(x):
    """(sinh x, sinh x - x, cosh x - 1) for x >= 0, free of cancellation and branch free: series below 2,
    one exp (orbits.core._fast_math) above."""
    x2 = x * x
    series_sinh_minus_x = _horner(SINH_MINUS_X, x2) * x2 * x
    series_cosh_minus_one = _horner(COSH_MINUS_ONE, x2) * x2
    exp = _exp(x)
    sinh = 0.5 * (exp - 1.0 / exp)
    if x < SERIES_LIMIT:
        return x + series_sinh_minus_x, series_sinh_minus_x, series_cosh_minus_one
    return sinh, sinh - x, 0.5 * (exp + 1.0 / exp) - 1.0


@jit(inline=True)
def _residual(kind, x, a, b, c, d):
    """(f, f', f'') of the equation `kind` at x; a, b, c, d are its parameters (see the callers)."""
    if kind == _ELLIPTIC:  # a = m, b = m_lo, c = e, d = 1 - e
        return _elliptic_residual(x, a, b, c, d)
    if kind == _HYPERBOLIC_SERIES:  # a = M, c = e, d = e - 1
        sinh, sinh_minus_x, cosh_minus_one = _hyperbolic_trig(x)
        return (d * x - a) + c * sinh_minus_x, d + c * cosh_minus_one, c * sinh
    q = math.exp(-2.0 * x)  # log form: a = M, b = e / 2
    mh = a + x
    ratio = mh / b
    log_ratio = math.log(ratio) if ratio < np.inf else math.log(mh) - math.log(b)
    f = (x + math.log1p(-q)) - log_ratio
    return f, 1.0 + 2.0 * q / (1.0 - q) - 1.0 / mh, -4.0 * q / (1.0 - q) ** 2 + (1.0 / mh) ** 2


@jit(inline=True)
def _halley_step(x, f, df, d2f, lo, hi):
    """(next iterate, converged) of orbits.core._roots.halley_in_bracket, lo and hi already updated
    from the sign of f: the Halley step if it stays in [lo, hi], else bisection; converged when the
    step was below 2**-26 relative, f == 0 or the bracket is down to an ulp."""
    new = x - f / (df - 0.5 * f * d2f / df)
    inside = np.isfinite(new) and lo <= new <= hi
    if not inside:
        new = 0.5 * (lo + hi)
    done = f == 0 or (inside and abs(new - x) <= 2.0**-26 * abs(new)) or hi - lo <= 2.0**-52 * abs(new)
    return new, done


@jit
def _halley(kind, x, lo, hi, a, b, c, d):
    """Safeguarded Halley iteration in [lo, hi] then one Newton polish (orbits.core._roots); NaN if capped."""
    for _ in range(MAX_ITERATIONS):
        f, df, d2f = _residual(kind, x, a, b, c, d)
        if f < 0:
            lo = x
        if f > 0:
            hi = x
        x, done = _halley_step(x, f, df, d2f, lo, hi)
        if done:
            f, df, _ = _residual(kind, x, a, b, c, d)
            polished = x - f / df
            return polished if (np.isfinite(polished) and f != 0) else x
    return np.nan


@jit
def _elliptic_safeguarded(M, e):
    """Pass 2: E by safeguarded Halley from the cubic starter (kepler._solve_elliptic_positive)."""
    e = e + 0.0
    hi, lo = _reduce(M, 0.0)
    sign = -1.0 if (hi < 0.0 or (hi == 0.0 and math.copysign(1.0, M) < 0.0)) else 1.0
    m, m_lo = abs(hi), sign * lo
    one_minus_e = 1.0 - e
    upper = min(min(m + e, np.pi), m / one_minus_e)
    start = min(max(_cubic_root(one_minus_e, e / 6.0, m), m), upper)
    return sign * _halley(_ELLIPTIC, start, m, upper, m, m_lo, e, one_minus_e)


@jit(inline=True)
def _sixth_order_step(f, f1, s, c, sign):
    """kepler.sixth_order_step: (the root offset of the Taylor polynomial of order five, the Newton step)."""
    inverse = 1.0 / f1
    t = -f * inverse
    a2, a3 = (0.5 * inverse) * s, (inverse * (1.0 / 6.0)) * c
    a4, a5 = (sign * (1.0 / 12.0)) * a2, (sign * 0.05) * a3
    a2_squared = a2 * a2
    b3 = 2.0 * a2_squared - a3
    b4 = a2 * (5.0 * a3 - 5.0 * a2_squared) - a4
    b5 = a2_squared * (14.0 * a2_squared - 21.0 * a3) + (6.0 * a2 * a4 + 3.0 * a3 * a3) - a5
    return t * (1.0 + t * (-a2 + t * (b3 + t * (b4 + t * b5)))), t


@jit
def _elliptic_reduce_block(M, e, m, m_lo, sign, start):
    """Stage 1 of the single pass on a block (vectorised, without contraction: the reduction's double-double
    parts must stay exact): m + m_lo = |M reduced| in [0, pi], its sign and Markley's starter. Returns how many
    (M, e) are outside the domain."""
    invalid = 0
    for j in range(M.size):
        M_j, e_j = M[j], e[j]
        invalid += not (abs(M_j) <= MAX_MEAN_ANOMALY and 0.0 <= e_j < 1.0)
        hi, lo = _reduce(M_j, 0.0)
        s = -1.0 if (hi < 0.0 or (hi == 0.0 and math.copysign(1.0, M_j) < 0.0)) else 1.0
        m_j = abs(hi)
        m[j], m_lo[j], sign[j] = m_j, s * lo, s
        start[j] = _markley_starter(m_j, e_j + 0.0)
    return invalid


@jit(contract=True)
def _elliptic_solve_block(e, m, m_lo, sign, start, out):
    """Stage 2 (vectorised, with fused multiply-adds): one trigonometric evaluation at the starter and the
    sixth-order step (kepler._elliptic_single_pass); NaN where the step is not certified."""
    for j in range(out.size):
        e_j, m_j = e[j] + 0.0, m[j]
        one_minus_e = 1.0 - e_j
        upper = min(m_j + e_j, np.pi)  # E - M = e sin E is in [0, e]
        x = min(max(start[j], m_j), upper)
        sin, x_minus_sin, one_minus_cos = _trig(x)
        f = ((one_minus_e * x - m_j) + e_j * x_minus_sin) - m_lo[j]
        f1 = one_minus_e + e_j * one_minus_cos
        step, t = _sixth_order_step(f, f1, e_j * sin, e_j * (1.0 - one_minus_cos), -1.0)
        x = min(max(x + step, m_j), upper) if abs(t) <= SINGLE_PASS_ACCEPT * x else np.nan
        x = m_j / one_minus_e if (m_j < TINY_MEAN_ANOMALY and e_j > 0.0) else x
        x = m_j if e_j == 0.0 else x
        out[j] = sign[j] * x


_BLOCK = 1024  # elements per block: the stages' scratch rows stay in the L1 cache


@jit
def elliptic(start, stop, M, e, out):
    """out[i] = E(M[i], e[i]) for start <= i < stop; returns invalid * 2**32 + unconverged. The single pass in two
    stages per block of _BLOCK elements, then the safeguarded iteration on the elements it leaves NaN. Loops run
    over views with range(n), which LLVM vectorises with a run-time alias check whatever the arrays' layout."""
    M, e, out = M[start:stop], e[start:stop], out[start:stop]
    m, m_lo, sign, starter = np.empty(_BLOCK), np.empty(_BLOCK), np.empty(_BLOCK), np.empty(_BLOCK)
    invalid = 0
    for first in range(0, out.size, _BLOCK):
        last = min(first + _BLOCK, out.size)
        size = last - first
        invalid += _elliptic_reduce_block(M[first:last], e[first:last], m[:size], m_lo[:size], sign[:size],
                                          starter[:size])
        _elliptic_solve_block(e[first:last], m[:size], m_lo[:size], sign[:size], starter[:size], out[first:last])
    if invalid:
        return invalid * _INVALID
    unconverged = 0
    for i in range(out.size):
        if np.isnan(out[i]):
            out[i] = _elliptic_safeguarded(M[i], e[i])
            unconverged += np.isnan(out[i])
    return unconverged


@jit
def _hyperbolic_one(M, e):
    """H >= 0 for M >= 0 (kepler._solve_hyperbolic_positive)."""
    if M == 0.0:
        return 0.0
    em1 = e - 1.0
    if M < TINY_MEAN_ANOMALY:
        return M / em1
    lower = math.asinh(M / e)
    upper_log = lower + math.log(e) - math.log(em1)
    if lower > LOG_FORM_LIMIT:
        return _halley(_HYPERBOLIC_LOG, lower, lower, upper_log, M, 0.5 * e, e, em1)
    hi = max(min(min(_cubic_root(em1, e / 6.0, M), M / em1), upper_log), lower)
    start = lower if lower > 3.0 else hi
    return _halley(_HYPERBOLIC_SERIES, start, lower, hi, M, 0.0, e, em1)


@jit(inline=True)
def _hyperbolic_bounds(M, e):
    """(lower, upper) bracket of H from 3e-6 logarithms, widened by 1e-5 (1 + |bound|) to stay bounds:
    asinh(M / e) <= H <= asinh(M / e) + log(e / (e - 1))."""
    ratio = M / e
    lower = _log_approx(2.0 * ratio if ratio > 1e150 else ratio + math.sqrt(ratio * ratio + 1.0))
    upper = lower + _log_approx(e) - _log_approx(e - 1.0)
    return max(lower - 1e-5 * (1.0 + lower), 0.0), upper + 1e-5 * (1.0 + upper)


@jit(inline=True)
def _hyperbolic_step(x, lo, hi, M, e, em1):
    """One bracketed sixth-order step on the series form (kepler._hyperbolic_fixed_pass): (x, lo, hi)."""
    f, df, d2f = _residual(_HYPERBOLIC_SERIES, x, M, 0.0, e, em1)
    lo = x if f < 0 else lo
    hi = x if f > 0 else hi
    new = x + _sixth_order_step(f, df, d2f, df + 1.0, 1.0)[0]
    return (new if (np.isfinite(new) and lo <= new <= hi) else 0.5 * (lo + hi)), lo, hi


@jit(inline=True)
def _hyperbolic_fixed(M, e):
    """H >= 0 for M >= 0, or NaN if not certified: pass 1, branch free so that its loop vectorises.

    Two bracketed sixth-order steps from the starter of kepler._solve_hyperbolic_series_form, with the pure
    cubic bound cbrt(6 M / e) for the cubic model root, then the Newton polish (kepler._hyperbolic_fixed_pass).
    Certified when the polishing step is below 2**-40 relative. The logarithmic form (asinh(M / e) > 20) is
    left to pass 2.
    """
    em1 = e - 1.0
    lower, upper = _hyperbolic_bounds(M, e)
    hi = max(min(min(_cbrt_normal(6.0 * M / e), M / em1), upper), lower)
    x, lo = (lower if lower > 3.0 else hi), lower
    # Written out: LLVM vectorises only innermost loops, and a loop over the steps would be one.
    x, lo, hi = _hyperbolic_step(x, lo, hi, M, e, em1)
    x, lo, hi = _hyperbolic_step(x, lo, hi, M, e, em1)
    f, df, _ = _residual(_HYPERBOLIC_SERIES, x, M, 0.0, e, em1)
    step = f / df
    polished = x - step if (np.isfinite(x - step) and f != 0) else x
    certified = abs(step) <= 2.0**-40 * x and lower <= LOG_FORM_LIMIT
    H = polished if certified else np.nan
    H = M / em1 if M < TINY_MEAN_ANOMALY else H
    return 0.0 if M == 0.0 else H


@jit
def hyperbolic(start, stop, M, e, out):
    """out[i] = H(M[i], e[i]); returns invalid * 2**32 + unconverged. Pass 1 (_hyperbolic_fixed) runs
    on every element, vectorised (over views, with range(n)); pass 2 (the safeguarded iteration) on those it
    leaves NaN."""
    M, e, out = M[start:stop], e[start:stop], out[start:stop]
    invalid = 0
    for i in range(out.size):
        M_i, e_i = M[i], e[i]
        invalid += not (np.isfinite(M_i) and 1.0 < e_i < np.inf)
        H = _hyperbolic_fixed(abs(M_i), e_i)
        out[i] = -H if math.copysign(1.0, M_i) < 0.0 else H
    if invalid:
        return invalid * _INVALID
    unconverged = 0
    for i in range(out.size):
        if np.isnan(out[i]):
            H = _hyperbolic_one(abs(M[i]), e[i])
            out[i] = -H if math.copysign(1.0, M[i]) < 0.0 else H
            unconverged += np.isnan(H)
    return unconverged


_CBRT_3 = 3.0 ** (1.0 / 3.0)


@jit(inline=True)
def _barker_one(w):
    """D >= 0 with D + D**3 / 3 = w >= 0 (kepler.parabolic_anomaly), branch free so the loop vectorises:
    two fixed-point steps below w = 1e-4, else the cancellation-free Cardano root and one Newton step."""
    d1 = w - w**3 / 3.0
    small = w - d1**3 / 3.0
    scale = _cbrt_normal(max(w, 1e-4)) * _CBRT_3  # x = scale y turns D**3 + 3 D = 3 w into y**3 + ps y = 1
    ps = 3.0 / (scale * scale)
    c = _cbrt_normal(0.5 + math.sqrt(0.25 + ps * ps * ps / 27.0))
    v = ps / (3.0 * c)
    d = scale / (c * c + ps / 3.0 + v * v)
    polished = d - ((d - w) + d * (d / 3.0) * d) / (1.0 + d * d)
    return small if w < 1e-4 else (polished if np.isfinite(polished) else d)


@jit
def parabolic(start, stop, W, out):
    """out[i] = D(W[i]), Barker's equation; returns invalid * 2**32 (vectorised over views, with range(n))."""
    W, out = W[start:stop], out[start:stop]
    invalid = 0
    for i in range(out.size):
        W_i = W[i]
        invalid += not np.isfinite(W_i)
        out[i] = math.copysign(_barker_one(abs(W_i)), W_i)
    return invalid * _INVALID
