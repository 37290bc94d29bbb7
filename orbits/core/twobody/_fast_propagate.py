"""Compiled two-body propagator (numba): a port of orbits.core.twobody.propagate's algorithm.

Imported only through orbits.core.twobody.propagate, when orbits.core._fast.use lets a batch run compiled. Every step
is the NumPy version's, function for function (same names). The states are sorted once by |r0| |v0|**2 against
2 mu: the bound ones go through the elliptic pass, the open ones through the hyperbolic pass, each block by block
of _BLOCK states, and what either leaves (exact parabolas, invalid input and any solve it does not certify) goes
through the universal passes (orbits/core/twobody/_fast_universal.py).
- The elliptic pass: A, 1 / a, n, n dt and e sin E0 in double-double arithmetic (_elliptic_setup), the local
  starter or Markley's (_elliptic_starter), one sixth-order and one Newton step on F(x) = m with exact products
  where it cancels (_elliptic_residual), the certificate, the Lagrange f and g in x from the last evaluation.
- The hyperbolic pass: A, 1 / |a|, n, n dt and e sinh H0 in double-double arithmetic (_hyperbolic_setup), the
  logarithmic and the parabolic starter (_hyperbolic_starters), the better by Newton step length,
  HYPERBOLIC_STEPS bracketed sixth-order steps and a Newton step on F(x) = m with exact products where it cancels
  (_hyperbolic_residual), the certificate, and the Lagrange f and g from the sinh x - x, cosh x - 1 and exp x of
  the last evaluation, carried through the Newton step.
A fix is made in propagate.py and ported here; tests/core/test_propagate.py and test_propagate_long_flights.py
hold both paths to the same mpmath bounds. What is the kernel's own:
- The passes run branch-free on blocks of states whose quantities sit in 1-D scratch rows, so LLVM vectorises
  every loop (loops over (n, 3) arrays, or one loop storing six rows, it does not). A selection whose branch
  loads from memory (`row[j] if c else 0.0`) is not vectorised either: a product, or values loaded before the
  selection, are (a third of the time, measured on the radial check).
- sin, cos, exp, atan2 (to 2e-8, a starter), the starters' logarithm (to 3e-6) and cube root (to 5e-10,
  division free) come from orbits.core._fast_math, so the two paths agree to rounding, not bit for bit.
- Divisions cost the vectorised loops as much as a dozen multiplications: the double-double quotients of
  the setups share reciprocals (_dd_over), exact products are one FMA (_two_product), and the loops
  free of error-free transformations let LLVM fuse a * b + c (jit(contract=True)).
Throughput against heyoka's lagrange_prop is in the README's Benchmarks section (orbits bench propagate).
"""

import math

import numpy as np

from orbits.core._fast import jit
from orbits.core._fast_math import (
    _atan2_approx,
    _cbrt_approx,
    _dd_add,
    _dd_dot,
    _dd_mul,
    _dd_over,
    _dd_root,
    _exp,
    _fma,
    _horner,
    _log_approx,
    _two_sum,
)
from orbits.core.twobody._fast_kepler import _markley_starter, _reduce, _sixth_order_step
from orbits.core.twobody._fast_universal import (
    _BLOCK,
    _DT,
    _MU,
    _RX,
    _RY,
    _RZ,
    _VX,
    _VY,
    _VZ,
    _gather_block,
    _universal_passes,
)
from orbits.core.twobody._kepler_shared import (
    COSH_MINUS_ONE,
    MAX_MEAN_ANOMALY,
    ONE_MINUS_COS,
    PI_1,
    PI_2,
    SINH_MINUS_X,
    TWO_PI_1,
    X_MINUS_SIN,
)
from orbits.core.twobody._propagate_shared import (
    BRACKET_WIDTH,
    ELLIPTIC_ERROR,
    ELLIPTIC_STEP,
    HYPERBOLIC_STEPS,
    LOCAL_STARTER_STEP,
    SERIES_LIMIT,
    SMALLEST_MEAN_MOTION_SQUARED,
)

COSH_TAIL = COSH_MINUS_ONE[:-1]  # (cosh x - 1 - x**2 / 2) / x**4 as a series in x**2
COS_TAIL = ONE_MINUS_COS[:-1]  # (1 - cos x - x**2 / 2) / x**4

# Rows of the per-block scratch array after the input rows (orbits/core/twobody/_fast_universal.py), the elliptic
# pass's:
_A, _EC, _ES, _M, _N, _BACK, _LO, _HI, _X, _OK, _SIN, _OMC, _R_OVER_A = range(8, 21)
_E_OUT = 21  # rows 21..26: r and v of the result
_BARKER = 27  # the hyperbolic pass's parabolic starter
_M_LO, _XMS = 28, 29


# --- the elliptic pass (propagate._elliptic_pass) ---------------------------------------------------


@jit(inline=True)
def _exact_product(a, b):
    """(a * b rounded, its rounding error), as _fast_math._two_product, with the product itself formed by an FMA
    with zero: the loops compiled with contraction cannot then fuse it into the sums of the error-free
    transformations that follow (which would count its error twice)."""
    p = _fma(a, b, 0.0)
    return p, _fma(a, b, -p)


@jit(inline=True)
def _elliptic_setup(rx, ry, rz, vx, vy, vz, mu, dt):
    """propagate._elliptic_setup for one state: (A, ec, es, m, m_lo, n, back, eligible), in double-double
    arithmetic as there (quotients by reciprocals: _dd_over)."""
    a_hi, a_lo, alpha_hi, n2_hi, n_hi, n_lo, m_hi, m_lo, es = _conic_terms(rx, ry, rz, vx, vy, vz, mu, dt, True)
    eligible = alpha_hi > 0.0 and n2_hi >= SMALLEST_MEAN_MOTION_SQUARED and abs(m_hi) <= MAX_MEAN_ANOMALY
    hi, lo = _reduce(m_hi if eligible else 0.0, m_lo if eligible else 0.0)
    back = -1.0 if hi < 0.0 else 1.0
    return a_hi + a_lo, (1.0 - a_hi) - a_lo, back * es, back * hi, back * lo, n_hi + n_lo, back, eligible


@jit(inline=True)
def _conic_terms(rx, ry, rz, vx, vy, vz, mu, dt, bound):
    """propagate._conic_terms for one state: (A hi, lo, k hi, n**2 hi, n hi, lo, M hi, lo, s)."""
    inverse_mu = 1.0 / mu
    r2_hi, r2_lo = _dd_dot(rx, ry, rz, rx, ry, rz)
    r_hi, r_lo, inverse_r = _dd_root(r2_hi, r2_lo)
    v2_hi, v2_lo = _dd_dot(vx, vy, vz, vx, vy, vz)
    w_hi, w_lo = _dd_mul(r_hi, r_lo, v2_hi, v2_lo)
    w_hi, w_lo = _dd_over(w_hi, w_lo, mu, 0.0, inverse_mu)
    a_hi, a_lo = _dd_add(2.0, 0.0, -w_hi, -w_lo) if bound else _dd_add(w_hi, w_lo, -2.0, 0.0)
    k_hi, k_lo = _dd_over(a_hi, a_lo, r_hi, r_lo, inverse_r)
    square_hi, square_lo = _dd_mul(k_hi, k_lo, k_hi, k_lo)
    cube_hi, cube_lo = _dd_mul(square_hi, square_lo, k_hi, k_lo)
    n2_hi, n2_lo = _dd_mul(cube_hi, cube_lo, mu, 0.0)
    n_hi, n_lo, _ = _dd_root(n2_hi, n2_lo)
    m_hi, m_lo = _dd_mul(n_hi, n_lo, dt, 0.0)
    rv_hi, rv_lo = _dd_dot(rx, ry, rz, vx, vy, vz)
    q_hi, q_lo = _dd_over(k_hi, k_lo, mu, 0.0, inverse_mu)
    q_hi, q_lo, _ = _dd_root(q_hi, q_lo)
    es_hi, es_lo = _dd_mul(rv_hi, rv_lo, q_hi, q_lo)
    return a_hi, a_lo, k_hi, n2_hi, n_hi, n_lo, m_hi, m_lo, es_hi + es_lo


@jit(inline=True)
def _trig_terms(x):
    """propagate._trig_terms, branch free: (sin x, x - sin x, 1 - cos x as hi + lo), x in [0, pi + 2]."""
    reflect = x >= SERIES_LIMIT
    z = (PI_1 - x) + PI_2 if reflect else x
    square, square_lo = _exact_product(z, z)
    z_minus_sin = square * z * _horner(X_MINUS_SIN, square)
    hi, lo = _two_sum(0.5 * square, 0.5 * square_lo + square * square * _horner(COS_TAIL, square))
    sin = z - z_minus_sin
    return sin, (x - sin if reflect else z_minus_sin), (2.0 - hi if reflect else hi), (0.0 if reflect else lo)


@jit(inline=True)
def _elliptic_radius(A, ec, es, x, sin, x_minus_sin, one_minus_cos):
    """propagate._elliptic_radius: r / a = F'(x)."""
    p, e = _exact_product(es, x)
    near = (A + p) + ((e - es * x_minus_sin) + ec * one_minus_cos)
    return near if x < SERIES_LIMIT else (A + ec * one_minus_cos) + es * sin


@jit(inline=True)
def _elliptic_residual(x, A, ec, es, m, m_lo):
    """propagate._elliptic_residual: (F - m, F', F'', sin x, x - sin x, 1 - cos x)."""
    sin, x_minus_sin, one_minus_cos, one_minus_cos_lo = _trig_terms(x)
    p1, e1 = _exact_product(A, x)
    p2, e2 = _exact_product(es, one_minus_cos)
    s, t = _two_sum(p1, p2)
    s, u = _two_sum(s, -m)
    f = s + ((t + u) + (((e1 + e2) + es * one_minus_cos_lo) - m_lo) + ec * x_minus_sin)
    df = _elliptic_radius(A, ec, es, x, sin, x_minus_sin, one_minus_cos)
    d2f = ec * sin + es * (1.0 - one_minus_cos)
    return f, df, d2f, sin, x_minus_sin, one_minus_cos


@jit(inline=True)
def _elliptic_starter(A, ec, es, m):
    """propagate._elliptic_starter: (the local starter or Markley's, lo, hi); atan2 to 2e-8."""
    e = math.sqrt(ec * ec + es * es)
    E0 = _atan2_approx(es, ec)
    M1 = (E0 - es) + m
    turns = np.rint(M1 * (1.0 / TWO_PI_1))
    M1 = M1 - turns * TWO_PI_1
    markley = math.copysign(_markley_starter(abs(M1), min(e, 1.0)), M1) + turns * TWO_PI_1 - E0
    local = 2.0 * m / (A + math.sqrt(max(A * A + 2.0 * es * m, 0.0)))
    square = local * local
    left_out = abs(square * local * (ec / 6.0 - es * local / 24.0))
    local_good = left_out < LOCAL_STARTER_STEP * abs(A + es * local + 0.5 * ec * square)
    lo, hi = max(m - BRACKET_WIDTH * e, 0.0), m + BRACKET_WIDTH * e
    return min(max(local if local_good else markley, lo), hi), lo, hi




@jit
def _setup_elliptic_block(n, scratch):
    """The elliptic problem of the block's states (vectorised; double-double, so without contraction).
    Non-finite input and mu <= 0 are not eligible (they leave alpha <= 0, n**2 or n dt NaN or out of range), nor
    are open orbits; radial states are set aside by _exclude_radial. The universal passes then count the
    invalid ones."""
    rx, ry, rz, vx, vy, vz = scratch[_RX], scratch[_RY], scratch[_RZ], scratch[_VX], scratch[_VY], scratch[_VZ]
    mu, dt = scratch[_MU], scratch[_DT]
    a, ec, es, m, mean_motion, back = scratch[_A], scratch[_EC], scratch[_ES], scratch[_M], scratch[_N], scratch[_BACK]
    m_lo, ok = scratch[_M_LO], scratch[_OK]
    for j in range(n):
        a[j], ec[j], es[j], m[j], m_lo[j], mean_motion[j], back[j], eligible = _elliptic_setup(
            rx[j], ry[j], rz[j], vx[j], vy[j], vz[j], mu[j], dt[j])
        ok[j] = eligible


@jit
def _exclude_radial(n, scratch):
    """Leave radial states (r x v = 0, which the NumPy version refuses) to the universal passes (vectorised; h
    rounded as there, without contraction)."""
    rx, ry, rz, vx, vy, vz = scratch[_RX], scratch[_RY], scratch[_RZ], scratch[_VX], scratch[_VY], scratch[_VZ]
    ok = scratch[_OK]
    for j in range(n):
        hx, hy, hz = ry[j] * vz[j] - rz[j] * vy[j], rz[j] * vx[j] - rx[j] * vz[j], rx[j] * vy[j] - ry[j] * vx[j]
        ok[j] = ok[j] * (hx * hx + hy * hy + hz * hz > 0.0)  # a product, not a conditional load: vectorised


@jit(contract=True)
def _start_elliptic_block(n, scratch):
    """The starter and the bracket (vectorised)."""
    a, ec, es, m = scratch[_A], scratch[_EC], scratch[_ES], scratch[_M]
    lo, hi, x = scratch[_LO], scratch[_HI], scratch[_X]
    for j in range(n):
        x[j], lo[j], hi[j] = _elliptic_starter(a[j], ec[j], es[j], m[j])


@jit(contract=True)
def _sixth_order_elliptic_block(n, scratch):
    """One sixth-order step from the starter, kept in [lo, hi] (vectorised)."""
    a, ec, es, m, m_lo = scratch[_A], scratch[_EC], scratch[_ES], scratch[_M], scratch[_M_LO]
    lo, hi, x = scratch[_LO], scratch[_HI], scratch[_X]
    for j in range(n):
        f, df, d2f, _, _, _ = _elliptic_residual(x[j], a[j], ec[j], es[j], m[j], m_lo[j])
        step, _ = _sixth_order_step(f, df, d2f, 1.0 - df, -1.0)
        x[j] = min(max(x[j] + step, lo[j]), hi[j])


@jit(contract=True)
def _newton_elliptic_block(n, scratch):
    """One Newton step, the certificate, and the trigonometric terms and r / a at the root (vectorised)."""
    a, ec, es, m, m_lo = scratch[_A], scratch[_EC], scratch[_ES], scratch[_M], scratch[_M_LO]
    x, ok, r_over_a = scratch[_X], scratch[_OK], scratch[_R_OVER_A]
    sin_row, x_minus_sin_row, omc_row = scratch[_SIN], scratch[_XMS], scratch[_OMC]
    for j in range(n):
        x_j = x[j]
        f, df, d2f, sin, x_minus_sin, one_minus_cos = _elliptic_residual(x_j, a[j], ec[j], es[j], m[j], m_lo[j])
        step = f / df
        x_j = x_j - step
        certified = abs(step) <= ELLIPTIC_STEP * x_j and abs(d2f) * step * step <= ELLIPTIC_ERROR * abs(df) * x_j
        ok[j] = ok[j] > 0.0 and certified
        sin, x_minus_sin, one_minus_cos = (sin - step * (1.0 - one_minus_cos), x_minus_sin - step * one_minus_cos,
                                           one_minus_cos - step * sin)
        x[j], sin_row[j], x_minus_sin_row[j], omc_row[j] = x_j, sin, x_minus_sin, one_minus_cos
        r_over_a[j] = _elliptic_radius(a[j], ec[j], es[j], x_j, sin, x_minus_sin, one_minus_cos)


@jit(contract=True)
def _elliptic_positions(n, scratch):
    """r = f r0 + g v0 into the output rows (propagate._elliptic_lagrange; vectorised)."""
    rx, ry, rz, vx, vy, vz = scratch[_RX], scratch[_RY], scratch[_RZ], scratch[_VX], scratch[_VY], scratch[_VZ]
    a, es, mean_motion, back = scratch[_A], scratch[_ES], scratch[_N], scratch[_BACK]
    x, sin, x_minus_sin, one_minus_cos = scratch[_X], scratch[_SIN], scratch[_XMS], scratch[_OMC]
    out_x, out_y, out_z = scratch[_E_OUT], scratch[_E_OUT + 1], scratch[_E_OUT + 2]
    for j in range(n):
        x_j, a_j, es_j, omc_j = x[j], a[j], es[j], one_minus_cos[j]
        p1, e1 = _exact_product(a_j, x_j)
        p2, e2 = _exact_product(es_j, omc_j)
        near = (p1 + p2) + ((e1 + e2) - a_j * x_minus_sin[j])
        far = a_j * sin[j] + es_j * omc_j
        g = back[j] * (near if x_j < SERIES_LIMIT else far) / mean_motion[j]
        f = 1.0 - omc_j / a_j
        out_x[j], out_y[j], out_z[j] = f * rx[j] + g * vx[j], f * ry[j] + g * vy[j], f * rz[j] + g * vz[j]


@jit(contract=True)
def _elliptic_velocities(n, scratch):
    """v = f' r0 + g' v0 into the output rows (vectorised)."""
    rx, ry, rz, vx, vy, vz = scratch[_RX], scratch[_RY], scratch[_RZ], scratch[_VX], scratch[_VY], scratch[_VZ]
    a, mean_motion, back = scratch[_A], scratch[_N], scratch[_BACK]
    sin, one_minus_cos, r_over_a = scratch[_SIN], scratch[_OMC], scratch[_R_OVER_A]
    out_x, out_y, out_z = scratch[_E_OUT + 3], scratch[_E_OUT + 4], scratch[_E_OUT + 5]
    for j in range(n):
        f_dot = -back[j] * mean_motion[j] * sin[j] / (a[j] * r_over_a[j])
        g_dot = 1.0 - one_minus_cos[j] / r_over_a[j]
        out_x[j], out_y[j] = f_dot * rx[j] + g_dot * vx[j], f_dot * ry[j] + g_dot * vy[j]
        out_z[j] = f_dot * rz[j] + g_dot * vz[j]


# --- the hyperbolic pass (propagate._hyperbolic_pass) -----------------------------------------------


@jit(inline=True)
def _hyperbolic_setup(rx, ry, rz, vx, vy, vz, mu, dt):
    """propagate._hyperbolic_setup for one state: (A, ec, es, m, m_lo, n, back, eligible), in double-double
    arithmetic as there (quotients by reciprocals: _dd_over)."""
    a_hi, a_lo, beta_hi, n2_hi, n_hi, n_lo, m_hi, m_lo, es = _conic_terms(rx, ry, rz, vx, vy, vz, mu, dt, False)
    eligible = beta_hi > 0.0 and n2_hi >= SMALLEST_MEAN_MOTION_SQUARED and abs(m_hi) < np.inf
    back = -1.0 if m_hi < 0.0 else 1.0
    ec = (1.0 + a_hi) + a_lo
    return a_hi + a_lo, ec, back * es, back * m_hi, back * m_lo, n_hi + n_lo, back, eligible


@jit(inline=True)
def _hyperbolic_exponentials(rx, ry, rz, vx, vy, vz, mu, A, ec, es):
    """propagate._hyperbolic_exponentials: (grow, decay, P)."""
    hx, hy, hz = ry * vz - rz * vy, rz * vx - rx * vz, rx * vy - ry * vx
    P = A / math.sqrt(rx * rx + ry * ry + rz * rz) * (hx * hx + hy * hy + hz * hz) / mu
    larger = ec + abs(es)
    smaller = (1.0 + P) / larger
    inward = es < 0.0
    grow = smaller if inward else larger
    decay = larger if inward else smaller
    return grow, decay, P


@jit(inline=True)
def _hyperbolic_functions(x):
    """propagate.hyperbolic_functions, branch free: (sinh x - x, cosh x - 1 as hi + lo, exp x, exp -x)."""
    square, square_lo = _exact_product(x, x)
    series_shm = square * x * _horner(SINH_MINUS_X, square)
    series_chm, series_lo = _two_sum(0.5 * square, 0.5 * square_lo + square * square * _horner(COSH_TAIL, square))
    small = x < SERIES_LIMIT
    exp = 1.0 + ((x + series_shm) + series_chm) if small else _exp(x)
    inverse = 1.0 / exp
    shm = series_shm if small else 0.5 * (exp - inverse) - x
    chm = series_chm if small else 0.5 * (exp + inverse) - 1.0
    return shm, chm, (series_lo if small else 0.0), exp, inverse


@jit(inline=True)
def _open_radius(A, ec, es, grow, decay, x, shm, chm, exp, inverse):
    """propagate._open_radius: r / |a| = F'(x), in the form whose terms are the smaller."""
    p, e = _exact_product(es, x)
    near = (A + p) + ((e + es * shm) + ec * chm)
    far_terms = 0.5 * (grow * exp + decay * inverse)
    far = x > 1.0 and far_terms + 1.0 < A + abs(ec * chm) + abs(es) * (x + shm)
    return far_terms - 1.0 if far else near


@jit(inline=True)
def _hyperbolic_residual(x, A, ec, es, grow, decay, m, m_lo):
    """propagate._hyperbolic_residual: (F - m, F', F'', sinh x - x, cosh x - 1, exp x, exp -x)."""
    shm, chm, chm_lo, exp, inverse = _hyperbolic_functions(x)
    p1, e1 = _exact_product(A, x)
    p2, e2 = _exact_product(es, chm)
    s, t = _two_sum(p1, p2)
    s, u = _two_sum(s, -m)
    near = s + ((t + u) + (((e1 + e2) + es * chm_lo) - m_lo) + ec * shm)
    near_terms = abs(p1) + abs(p2) + abs(ec * shm)
    far_sum = 0.5 * (grow * (exp - 1.0) + decay * (1.0 - inverse))
    far = x > 1.0 and far_sum + x < near_terms
    f = ((far_sum - x) - m) - m_lo if far else near
    df = _open_radius(A, ec, es, grow, decay, x, shm, chm, exp, inverse)
    d2f = 0.5 * (grow * exp - decay * inverse)
    return (f if np.isfinite(f) else np.inf), df, d2f, shm, chm, exp, inverse


@jit(inline=True)
def _hyperbolic_starters(A, es, grow, P, m):
    """propagate._hyperbolic_starters: (the logarithmic starter, the parabolic starter, hi); logarithm to 3e-6,
    cube root to 5e-10."""
    hi = m * (1.0 + math.sqrt(1.0 + P)) / P
    ratio = 2.0 * m / grow
    log_guess = _log_approx(ratio) if 2.2250738585072014e-308 <= ratio < np.inf else -1.0
    local = 2.0 * m / (A + math.sqrt(max(A * A + 2.0 * es * m, 0.0)))
    first = log_guess if log_guess > 0.0 else local
    root_p = math.sqrt(P)
    d0 = es / root_p
    w = d0 + d0 * d0 * d0 / 3.0 + 2.0 * m / (P * root_p)
    c = _cbrt_approx(1.5 * abs(w) + math.sqrt(2.25 * w * w + 1.0))
    barker = root_p * (math.copysign(c - 1.0 / c, w) - d0)
    barker = barker if np.isfinite(barker) else first
    return min(max(first, 0.0), hi), min(max(barker, 0.0), hi), hi


@jit(inline=True)
def _bracketed_step(x, lo, hi, f, df, d2f):
    """One sixth-order step kept in [lo, hi] (bisection when it leaves), lo and hi first moved to x by the sign of
    f: (x, lo, hi), as in propagate._solve_hyperbolic."""
    lo = x if f < 0.0 else lo
    hi = x if f > 0.0 else hi
    new = x + _sixth_order_step(f, df, d2f, df + 1.0, 1.0)[0]
    return (new if (np.isfinite(new) and lo <= new <= hi) else 0.5 * (lo + hi)), lo, hi


# Rows of the hyperbolic pass; it shares _A .. _OK, _M_LO, _R_OVER_A, _BARKER and the output rows with the elliptic pass
_GROW_H, _DECAY_H, _P_H, _SHM, _CHM, _EXP, _INV = range(30, 37)
_ROWS = 37


@jit
def _setup_hyperbolic_block(n, scratch):
    """The hyperbolic problem of the block's states (vectorised; double-double, so without contraction); bound
    orbits, exact parabolas and invalid input are not eligible. Two loops: one loop storing all eleven rows needs
    more run-time alias checks than LLVM's vectoriser makes, and ran at scalar speed (72 ns a state)."""
    rx, ry, rz, vx, vy, vz = scratch[_RX], scratch[_RY], scratch[_RZ], scratch[_VX], scratch[_VY], scratch[_VZ]
    mu, dt = scratch[_MU], scratch[_DT]
    a, ec, es, m, mean_motion, back = scratch[_A], scratch[_EC], scratch[_ES], scratch[_M], scratch[_N], scratch[_BACK]
    m_lo, ok = scratch[_M_LO], scratch[_OK]
    for j in range(n):
        a[j], ec[j], es[j], m[j], m_lo[j], mean_motion[j], back[j], eligible = _hyperbolic_setup(
            rx[j], ry[j], rz[j], vx[j], vy[j], vz[j], mu[j], dt[j])
        ok[j] = eligible
    grow, decay, p = scratch[_GROW_H], scratch[_DECAY_H], scratch[_P_H]
    for j in range(n):
        grow[j], decay[j], p[j] = _hyperbolic_exponentials(rx[j], ry[j], rz[j], vx[j], vy[j], vz[j], mu[j], a[j], ec[j],
                                                           es[j])


@jit(contract=True)
def _start_hyperbolic_block(n, scratch):
    """Both starters and hi (vectorised)."""
    a, es, grow, p, m = scratch[_A], scratch[_ES], scratch[_GROW_H], scratch[_P_H], scratch[_M]
    x, barker, hi = scratch[_X], scratch[_BARKER], scratch[_HI]
    for j in range(n):
        x[j], barker[j], hi[j] = _hyperbolic_starters(a[j], es[j], grow[j], p[j], m[j])


@jit(contract=True)
def _first_step_hyperbolic_block(n, scratch):
    """The better starter by Newton step length and the first sixth-order step from it (vectorised)."""
    a, ec, es, grow, decay = scratch[_A], scratch[_EC], scratch[_ES], scratch[_GROW_H], scratch[_DECAY_H]
    m, m_lo, x, barker, lo, hi = scratch[_M], scratch[_M_LO], scratch[_X], scratch[_BARKER], scratch[_LO], scratch[_HI]
    for j in range(n):
        first_j, barker_j = x[j], barker[j]  # loaded before the selection: a conditional load stops the vectoriser
        f_1, df_1, d2f_1, _, _, _, _ = _hyperbolic_residual(first_j, a[j], ec[j], es[j], grow[j], decay[j], m[j],
                                                            m_lo[j])
        f_b, df_b, d2f_b, _, _, _, _ = _hyperbolic_residual(barker_j, a[j], ec[j], es[j], grow[j], decay[j], m[j],
                                                            m_lo[j])
        step_b = abs(f_b / df_b)
        barker_better = np.isfinite(step_b) and not (abs(f_1 / df_1) <= step_b)
        start = barker_j if barker_better else first_j
        f, df, d2f = (f_b, df_b, d2f_b) if barker_better else (f_1, df_1, d2f_1)
        x[j], lo[j], hi[j] = _bracketed_step(start, 0.0, hi[j], f, df, d2f)


@jit(contract=True)
def _step_hyperbolic_block(n, scratch):
    """One more sixth-order step (vectorised)."""
    a, ec, es, grow, decay = scratch[_A], scratch[_EC], scratch[_ES], scratch[_GROW_H], scratch[_DECAY_H]
    m, m_lo, x, lo, hi = scratch[_M], scratch[_M_LO], scratch[_X], scratch[_LO], scratch[_HI]
    for j in range(n):
        f, df, d2f, _, _, _, _ = _hyperbolic_residual(x[j], a[j], ec[j], es[j], grow[j], decay[j], m[j], m_lo[j])
        x[j], lo[j], hi[j] = _bracketed_step(x[j], lo[j], hi[j], f, df, d2f)


@jit(contract=True)
def _newton_hyperbolic_block(n, scratch):
    """The Newton step, the certificate, and the terms and r / |a| at the root (vectorised)."""
    a, ec, es, grow, decay = scratch[_A], scratch[_EC], scratch[_ES], scratch[_GROW_H], scratch[_DECAY_H]
    m, m_lo, x, ok = scratch[_M], scratch[_M_LO], scratch[_X], scratch[_OK]
    shm_row, chm_row, exp_row, inverse_row, r_over_a = (scratch[_SHM], scratch[_CHM], scratch[_EXP], scratch[_INV],
                                                        scratch[_R_OVER_A])
    for j in range(n):
        x_j = x[j]
        f, df, d2f, shm, chm, exp, inverse = _hyperbolic_residual(x_j, a[j], ec[j], es[j], grow[j], decay[j], m[j],
                                                                  m_lo[j])
        step = f / df
        certified = abs(step) <= ELLIPTIC_STEP * x_j and abs(d2f) * step * step <= ELLIPTIC_ERROR * df * x_j
        ok[j] = ok[j] > 0.0 and certified
        shm, chm = shm - step * chm, chm - step * (x_j + shm)
        x_j = x_j - step
        exp, inverse = exp * (1.0 - step), inverse * (1.0 + step)
        x[j], shm_row[j], chm_row[j], exp_row[j], inverse_row[j] = x_j, shm, chm, exp, inverse
        r_over_a[j] = _open_radius(a[j], ec[j], es[j], grow[j], decay[j], x_j, shm, chm, exp, inverse)


@jit(contract=True)
def _hyperbolic_positions(n, scratch):
    """r = f r0 + g v0 into the output rows (propagate._hyperbolic_lagrange; vectorised)."""
    rx, ry, rz, vx, vy, vz = scratch[_RX], scratch[_RY], scratch[_RZ], scratch[_VX], scratch[_VY], scratch[_VZ]
    a, es, grow, decay, mean_motion, back = (scratch[_A], scratch[_ES], scratch[_GROW_H], scratch[_DECAY_H],
                                             scratch[_N], scratch[_BACK])
    x, shm, chm, exp, inverse = scratch[_X], scratch[_SHM], scratch[_CHM], scratch[_EXP], scratch[_INV]
    out_x, out_y, out_z = scratch[_E_OUT], scratch[_E_OUT + 1], scratch[_E_OUT + 2]
    for j in range(n):
        x_j, chm_j = x[j], chm[j]
        p1, e1 = _exact_product(a[j], x_j)
        p2, e2 = _exact_product(es[j], chm_j)
        near = (p1 + p2) + ((e1 + e2) + a[j] * shm[j])
        far_sum = 0.5 * (grow[j] * (exp[j] - 1.0) + decay[j] * (1.0 - inverse[j]))
        sinh = x_j + shm[j]
        far = x_j > 1.0 and far_sum + sinh < abs(p1) + abs(p2)
        g = back[j] * (far_sum - sinh if far else near) / mean_motion[j]
        f = 1.0 - chm_j / a[j]
        out_x[j], out_y[j], out_z[j] = f * rx[j] + g * vx[j], f * ry[j] + g * vy[j], f * rz[j] + g * vz[j]


@jit(contract=True)
def _hyperbolic_velocities(n, scratch):
    """v = f' r0 + g' v0 into the output rows (vectorised)."""
    rx, ry, rz, vx, vy, vz = scratch[_RX], scratch[_RY], scratch[_RZ], scratch[_VX], scratch[_VY], scratch[_VZ]
    a, mean_motion, back = scratch[_A], scratch[_N], scratch[_BACK]
    x, shm, chm, r_over_a = scratch[_X], scratch[_SHM], scratch[_CHM], scratch[_R_OVER_A]
    out_x, out_y, out_z = scratch[_E_OUT + 3], scratch[_E_OUT + 4], scratch[_E_OUT + 5]
    for j in range(n):
        f_dot = -back[j] * mean_motion[j] * (x[j] + shm[j]) / (a[j] * r_over_a[j])
        g_dot = 1.0 - chm[j] / r_over_a[j]
        out_x[j], out_y[j] = f_dot * rx[j] + g_dot * vx[j], f_dot * ry[j] + g_dot * vy[j]
        out_z[j] = f_dot * rz[j] + g_dot * vz[j]


# --- the passes and the driver ----------------------------------------------------------------------------


@jit
def _store_block(index, first, n, scratch, r, v, pending, count):
    """Copy the output rows into r[index[first:first + n]], v[...]; the states not certified go on the list
    `pending` for the universal passes (from position count on), in a loop of their own. Returns the new count."""
    x, y, z = scratch[_E_OUT], scratch[_E_OUT + 1], scratch[_E_OUT + 2]
    u, w, q = scratch[_E_OUT + 3], scratch[_E_OUT + 4], scratch[_E_OUT + 5]
    rows, ok = index[first:first + n], scratch[_OK]
    for j in range(n):
        i = rows[j]
        r[i, 0], r[i, 1], r[i, 2], v[i, 0], v[i, 1], v[i, 2] = x[j], y[j], z[j], u[j], w[j], q[j]
    for j in range(n):
        if ok[j] == 0.0:
            pending[count] = rows[j]
            count += 1
    return count


@jit
def _elliptic_pass(index, r0, v0, mu, dt, r, v, scratch, pending, count):
    """The elliptic pass on the states index[...], block by block (vectorised): r, v of the certified ones; the
    others added to pending from position count on. Returns the new count."""
    for first in range(0, index.size, _BLOCK):
        n = min(_BLOCK, index.size - first)
        _gather_block(index, first, n, r0, v0, mu, dt, scratch)
        _setup_elliptic_block(n, scratch)
        _exclude_radial(n, scratch)
        _start_elliptic_block(n, scratch)
        _sixth_order_elliptic_block(n, scratch)
        _newton_elliptic_block(n, scratch)
        _elliptic_positions(n, scratch)
        _elliptic_velocities(n, scratch)
        count = _store_block(index, first, n, scratch, r, v, pending, count)
    return count


@jit
def _hyperbolic_pass(index, r0, v0, mu, dt, r, v, scratch, pending, count):
    """The hyperbolic pass on the states index[...], as _elliptic_pass."""
    for first in range(0, index.size, _BLOCK):
        n = min(_BLOCK, index.size - first)
        _gather_block(index, first, n, r0, v0, mu, dt, scratch)
        _setup_hyperbolic_block(n, scratch)
        _exclude_radial(n, scratch)
        _start_hyperbolic_block(n, scratch)
        _first_step_hyperbolic_block(n, scratch)
        for _ in range(HYPERBOLIC_STEPS - 1):
            _step_hyperbolic_block(n, scratch)
        _newton_hyperbolic_block(n, scratch)
        _hyperbolic_positions(n, scratch)
        _hyperbolic_velocities(n, scratch)
        count = _store_block(index, first, n, scratch, r, v, pending, count)
    return count


@jit
def _sort_by_conic(start, stop, r0, v0, mu, bound, open_):
    """Indices start .. stop - 1 into bound[:k] and open_[:l] by |r0| |v0|**2 against 2 mu (propagate._open;
    non-finite input counts as bound: the elliptic pass refuses it). Returns (bound count, open count)."""
    n_bound, n_open = 0, 0
    for i in range(start, stop):  # branch free: on mixed states a branch is mispredicted half the time
        radius = math.sqrt(r0[i, 0] * r0[i, 0] + r0[i, 1] * r0[i, 1] + r0[i, 2] * r0[i, 2])
        is_open = radius * (v0[i, 0] * v0[i, 0] + v0[i, 1] * v0[i, 1] + v0[i, 2] * v0[i, 2]) > 2.0 * mu[i]
        open_[n_open], bound[n_bound] = i, i
        n_open += is_open
        n_bound += not is_open
    return n_bound, n_open


@jit
def propagate(start, stop, r0, v0, mu, dt, r, v):
    """r[i], v[i] at t0 + dt[i] from r0[i], v0[i] about mu[i]; returns invalid * 2**32 + unconverged.

    The elliptic pass on the bound states, the hyperbolic pass on the open ones, block by block (vectorised); the
    universal passes on the states they do not certify (exact parabolas, invalid input and any solve they cannot
    vouch for).
    """
    scratch = np.empty((_ROWS, _BLOCK))
    bound, open_ = np.empty(stop - start, np.int64), np.empty(stop - start, np.int64)
    pending = np.empty(stop - start, np.int64)
    n_bound, n_open = _sort_by_conic(start, stop, r0, v0, mu, bound, open_)
    count = _elliptic_pass(bound[:n_bound], r0, v0, mu, dt, r, v, scratch, pending, 0)
    count = _hyperbolic_pass(open_[:n_open], r0, v0, mu, dt, r, v, scratch, pending, count)
    return _universal_passes(pending[:count], r0, v0, mu, dt, r, v, scratch)
