"""Compiled universal-variable passes of the two-body propagator (numba): a port of orbits.core.twobody.propagate's.

The states the elliptic and hyperbolic passes leave (exact parabolas, invalid input and any solve those passes do
not certify) and the state-transition matrix (orbits/core/twobody/_fast_transition.py) come here: period reduction of dt
and alpha = 2 / r - v**2 / mu in double-double arithmetic, scaling to |r0| = 1 and mu = 1, time reversal for
dt < 0, the starter (_vallado_guess, _barker_guess, _starter), pass 1 (FIXED_STEPS bracketed Halley steps,
_polish, the certificate) vectorised block by block, pass 2 on the uncertified states (_solve_universal: bracket
grown by doubling, safeguarded Halley), the Stumpff formulas and the Lagrange f and g, each named after its
NumPy original. Its sin, cos, exp and cube root come from orbits.core._fast_math, so the two paths agree to
rounding, not bit for bit.
"""

import math

import numpy as np

from orbits.core._fast import jit
from orbits.core._fast_math import (
    _cbrt_approx,
    _dd_add,
    _dd_div,
    _dd_dot,
    _dd_mul,
    _dd_sqrt,
    _exp,
    _horner,
    _log_approx,
    _sin_cos,
    _two_product,
)
from orbits.core._roots import MAX_ITERATIONS
from orbits.core.twobody._fast_kepler import _INVALID, _halley_step
from orbits.core.twobody._kepler_shared import SINH_MINUS_X, TWO_PI_1, TWO_PI_2, X_MINUS_SIN
from orbits.core.twobody._propagate_shared import BRACKET_DOUBLINGS, C2_SERIES, C3_SERIES, FIXED_STEPS, SERIES_LIMIT

# Rows of the per-block scratch array (LLVM vectorises loops over 1-D rows, not over (n, 3) arrays): the inputs,
# then the universal pass 1's quantities.
_RX, _RY, _RZ, _VX, _VY, _VZ, _MU, _DT = range(8)
_TAU, _R0, _SIGMA0, _ALPHA, _GROW, _DECAY, _CHI, _LO_U, _HI_U, _LAST = range(8, 18)
_OUT = 18  # rows 18..23: r and v of the result
_ROWS = 24
_BLOCK = 256  # states per block: the scratch rows stay in the L1 cache between the steps


@jit(inline=True)
def _reduce_by_periods(rx, ry, rz, vx, vy, vz, mu, dt):
    """(dt - k P with k = round(dt / P) on ellipses, dt on open orbits; alpha = 2 / r - v**2 / mu [1/m]; k; P),
    from double-double arithmetic (propagate._reduce_by_periods)."""
    r2_hi, r2_lo = _dd_dot(rx, ry, rz, rx, ry, rz)
    r_hi, r_lo = _dd_sqrt(r2_hi, r2_lo)
    v2_hi, v2_lo = _dd_dot(vx, vy, vz, vx, vy, vz)
    v2_hi, v2_lo = _dd_div(v2_hi, v2_lo, mu, 0.0)
    two_hi, two_lo = _dd_div(2.0, 0.0, r_hi, r_lo)
    alpha_hi, alpha_lo = _dd_add(two_hi, two_lo, -v2_hi, -v2_lo)
    alpha = alpha_hi + alpha_lo
    bound = alpha_hi > 0.0
    alpha_hi, alpha_lo = (alpha_hi, alpha_lo) if bound else (1.0, 0.0)  # branch free: open orbits keep dt
    root_hi, root_lo = _dd_sqrt(alpha_hi, alpha_lo)
    a3_hi, a3_lo = _dd_mul(alpha_hi, alpha_lo, root_hi, root_lo)
    root_mu_hi, root_mu_lo = _dd_sqrt(mu, 0.0)
    n_hi, n_lo = _dd_mul(root_mu_hi, root_mu_lo, a3_hi, a3_lo)
    p_hi, p_lo = _dd_div(TWO_PI_1, TWO_PI_2, n_hi, n_lo)
    turns = np.rint(dt / p_hi)
    q_hi, q_lo = _two_product(turns, p_hi)
    hi, lo = _dd_add(dt, 0.0, -q_hi, -(q_lo + turns * p_lo))
    return (hi + lo if bound else dt), alpha, (turns if bound else 0.0), (p_hi if bound else np.nan)


# --- Stumpff functions and the universal Kepler equation -----------------------------------------


@jit(inline=True)
def _stumpff(z):
    """propagate.stumpff, branch free: series for |z| <= 1, else sin and cos (z > 1) or exp (z < -1) of
    s = sqrt(|z|) from orbits.core._fast_math, in the same formulas; overflows to inf beyond z = -5e5.
    Returns (c0, c1, c2, c3, exp sqrt(max(-z, 1)), its inverse): the hyperbolic terms reuse the exponential."""
    c2_series, c3_series = _horner(C2_SERIES, z), _horner(C3_SERIES, z)
    s = math.sqrt(max(z, 1.0))
    sin, cos = _sin_cos(s)
    one_minus_cos = sin * sin / (1.0 + cos) if cos > 0.0 else 1.0 - cos
    s_minus_sin = s * s * s * _horner(X_MINUS_SIN, z) if s < SERIES_LIMIT else s - sin
    t = math.sqrt(max(-z, 1.0))
    exp = _exp(t)
    inverse = 1.0 / exp
    sinh, cosh = 0.5 * (exp - inverse), 0.5 * (exp + inverse)
    cosh_minus_one = sinh * ((1.0 - inverse) / (1.0 + inverse))
    sinh_minus_t = t * t * t * _horner(SINH_MINUS_X, -z) if t < SERIES_LIMIT else sinh - t
    if abs(z) <= 1.0:
        return 1.0 - z * c2_series, 1.0 - z * c3_series, c2_series, c3_series, exp, inverse
    if z > 0.0:
        return cos, sin / s, one_minus_cos / z, s_minus_sin / (s * z), exp, inverse
    return cosh, sinh / t, cosh_minus_one / -z, sinh_minus_t / (t * -z), exp, inverse


@jit(inline=True)
def _g_functions(chi, alpha, grow, decay):
    """(G0, G1, G2, G3, e sinh H, e cosh H) at chi: propagate._g_functions and propagate._hyperbolic_terms."""
    c0, c1, c2, c3, exp, inverse = _stumpff(alpha * chi * chi)
    e_sinh, e_cosh = 0.5 * (grow * exp - decay * inverse), 0.5 * (grow * exp + decay * inverse)
    return c0, chi * c1, chi * chi * c2, chi * chi * chi * c3, e_sinh, e_cosh


@jit(inline=True)
def _hyperbolic_coefficients(r0, sigma0, alpha, p):
    """propagate._hyperbolic_coefficients: (e exp H0, e exp -H0) of a hyperbola, 0 on other orbits."""
    beta = -alpha if alpha < 0.0 else 0.0
    e_cosh, e_sinh = 1.0 + r0 * beta, sigma0 * math.sqrt(beta)
    larger = e_cosh + abs(e_sinh)
    smaller = (1.0 + beta * p) / larger
    grow, decay = (smaller, larger) if sigma0 < 0.0 else (larger, smaller)
    return (grow, decay) if alpha < 0.0 else (0.0, 0.0)


@jit(inline=True)
def _inverse_powers(alpha):
    """propagate._inverse_powers: (1 / beta, 1 / sqrt(beta), 1 / beta**1.5), beta = -alpha."""
    inverse = 1.0 / -alpha
    inverse_root = math.sqrt(max(-alpha, 0.0)) * inverse
    return inverse, inverse_root, inverse * inverse_root


@jit(inline=True)
def _anomaly_form(chi, r0, sigma0, alpha, g1, g2, g3, e_sinh, inverse, inverse_15):
    """propagate._anomaly_form: whether F is better summed in the hyperbolic anomaly than in the G form."""
    g_terms = abs(r0 * g1) + abs(sigma0 * g2) + abs(g3)
    h_terms = abs(e_sinh) * inverse_15 + (abs(sigma0) + chi) * inverse
    return alpha * chi * chi < -1.0 and h_terms < g_terms


@jit(inline=True)
def _universal_residual(chi, tau, r0, sigma0, alpha, grow, decay):
    """propagate._residual: (F - tau, F', F'') with F = r0 G1 + sigma0 G2 + G3, in the hyperbolic anomaly where
    _anomaly_form says so; a non-finite F counts as +inf."""
    g0, g1, g2, g3, e_sinh, e_cosh = _g_functions(chi, alpha, grow, decay)
    f = (r0 * g1 + sigma0 * g2 + g3) - tau
    df = r0 * g0 + sigma0 * g1 + g2
    d2f = sigma0 * g0 + (1.0 - alpha * r0) * g1
    inverse, inverse_root, inverse_15 = _inverse_powers(alpha)
    f_h = (e_sinh * inverse_15 - (sigma0 + chi) * inverse) - tau
    df_h, d2f_h = (e_cosh - 1.0) * inverse, e_sinh * inverse_root
    far = _anomaly_form(chi, r0, sigma0, alpha, g1, g2, g3, e_sinh, inverse, inverse_15)
    f, df, d2f = (f_h, df_h, d2f_h) if far else (f, df, d2f)
    return (f if np.isfinite(f) else np.inf), df, d2f


@jit(inline=True)
def _vallado_guess(tau, r0, sigma0, alpha):
    """propagate._vallado_guess, branch free: tau alpha on ellipses, Vallado's logarithmic guess on hyperbolas
    (with a 3e-6 logarithm, plenty for a first guess)."""
    sqrt_minus_a = math.sqrt(max(-1.0 / alpha, 0.0))
    ratio = -2.0 * alpha * tau / (sigma0 + sqrt_minus_a * (1.0 - alpha * r0))
    usable = alpha < 0.0 and 2.2250738585072014e-308 <= ratio < np.inf
    guess = sqrt_minus_a * _log_approx(ratio if usable else 1.0)
    linear = tau * alpha if alpha > 0.0 else tau / r0
    return max(guess if (usable and guess > 0.0) else linear, 0.0)


@jit(inline=True)
def _barker_guess(tau, sigma0, p):
    """propagate._barker_guess (cube root to 1e-11): chi on the parabola with the same p = h**2 and r0.v0;
    0 where that is negative or overflows."""
    root_p = math.sqrt(p)
    d0 = sigma0 / root_p
    w = d0 + d0 * d0 * d0 / 3.0 + 2.0 * tau / (p * root_p)
    c = _cbrt_approx(1.5 * abs(w) + math.sqrt(2.25 * w * w + 1.0))
    guess = root_p * (math.copysign(c - 1.0 / c, w) - d0)
    return guess if 0.0 < guess < np.inf else 0.0


@jit(inline=True)
def _starter(tau, r0, sigma0, alpha, p, grow, decay):
    """propagate._starter: the better of Vallado's guess and the parabolic guess, by Newton step length.

    Measured on the benchmark's mixed states (1e5; safeguarded Halley iterations to convergence):
    ellipses 3.2 / 3.1 / 2.95 mean steps (Vallado / parabolic / better of the two), hyperbolas 5.9 /
    3.0 / 2.45 with 62 % / 8 % / 0 % needing more than 5, near-parabolic orbits 5.4 / 2.5 / 2.5.
    """
    vallado, barker = _vallado_guess(tau, r0, sigma0, alpha), _barker_guess(tau, sigma0, p)
    f_v, df_v, _ = _universal_residual(vallado, tau, r0, sigma0, alpha, grow, decay)
    f_b, df_b, _ = _universal_residual(barker, tau, r0, sigma0, alpha, grow, decay)
    step_v, step_b = abs(f_v / df_v), abs(f_b / df_b)
    barker_better = np.isfinite(step_b) and not (step_v <= step_b)
    return barker if barker_better else vallado


@jit
def _residual_call(chi, tau, r0, sigma0, alpha, grow, decay):
    """_universal_residual as a function call: pass 2 calls it instead of inlining three more copies
    (measured: compiling the propagation kernel took 35 s with them inlined, see the module docstring)."""
    return _universal_residual(chi, tau, r0, sigma0, alpha, grow, decay)


@jit
def _solve_universal(tau, r0, sigma0, alpha, p, grow, decay):
    """Pass 2, propagate._solve_safeguarded: chi >= 0 with F(chi) = tau; NaN if the iteration cap is hit."""
    hi = max(tau / r0, 1e-300)
    for _ in range(BRACKET_DOUBLINGS):
        if _residual_call(hi, tau, r0, sigma0, alpha, grow, decay)[0] >= 0.0:
            break
        hi *= 2.0
    lo = 0.0
    x = min(max(_starter(tau, r0, sigma0, alpha, p, grow, decay), lo), hi)
    for _ in range(MAX_ITERATIONS):
        f, df, d2f = _residual_call(x, tau, r0, sigma0, alpha, grow, decay)
        if f < 0:
            lo = x
        if f > 0:
            hi = x
        x, done = _halley_step(x, f, df, d2f, lo, hi)
        if done:
            f, df, _ = _residual_call(x, tau, r0, sigma0, alpha, grow, decay)
            polished = x - f / df
            return polished if (np.isfinite(polished) and f != 0) else x
    return np.nan


@jit(inline=True)
def _polish(x, tau, r0, sigma0, alpha, grow, decay):
    """propagate._polish: (x after one Newton step, the step)."""
    f, df, _ = _universal_residual(x, tau, r0, sigma0, alpha, grow, decay)
    step = f / df
    polished = x - step
    return (polished if (np.isfinite(polished) and f != 0) else x), step


@jit(inline=True)
def _fixed_step(x, lo, hi, tau, r0, sigma0, alpha, grow, decay):
    """propagate._fixed_step, branch free: one Halley step (x, lo, hi, |step|), bisecting or doubling when the
    step leaves the bracket [lo, hi] (hi may still be +inf)."""
    f, df, d2f = _universal_residual(x, tau, r0, sigma0, alpha, grow, decay)
    lo = x if f < 0.0 else lo
    hi = x if f > 0.0 else hi
    new = x - f / (df - 0.5 * f * d2f / df)
    inside = np.isfinite(new) and lo <= new <= hi
    fallback = 0.5 * (lo + hi) if hi < np.inf else 2.0 * max(lo, x, 1e-300)
    new = new if inside else fallback
    return new, lo, hi, abs(new - x)


# --- one state --------------------------------------------------------------------------------------


@jit(inline=True)
def _scaled(rx, ry, rz, vx, vy, vz, mu, dt):
    """The scaled problem (|r0| = 1, mu = 1, dt reduced and made positive by time reversal):
    (length, speed, back, x, y, z, u, v, w, tau, r0, sigma0, alpha, reduced dt, periods taken off, period)."""
    dt, alpha_si, turns, period = _reduce_by_periods(rx, ry, rz, vx, vy, vz, mu, dt)
    length = math.sqrt(rx * rx + ry * ry + rz * rz)
    speed = math.sqrt(mu / length)
    x, y, z = rx / length, ry / length, rz / length
    u, v, w = vx / speed, vy / speed, vz / speed
    tau = dt * speed / length
    r0 = math.sqrt(x * x + y * y + z * z)
    alpha = alpha_si * length  # not 2 / r0 - |w|**2, whose cancellation near e = 1 costs digits
    back = -1.0 if tau < 0.0 else 1.0
    u, v, w, tau = back * u, back * v, back * w, abs(tau)
    return length, speed, back, x, y, z, u, v, w, tau, r0, x * u + y * v + z * w, alpha, dt, turns, period


@jit(inline=True)
def _semilatus(scaled):
    """p = |x x w|**2 of the scaled state (|r0| = 1, mu = 1)."""
    x, y, z, u, v, w = scaled[3], scaled[4], scaled[5], scaled[6], scaled[7], scaled[8]
    hx, hy, hz = y * w - z * v, z * u - x * w, x * v - y * u
    return hx * hx + hy * hy + hz * hz


@jit(inline=True)
def _coefficients(scaled):
    """(grow, decay) = (e exp H0, e exp -H0) of the scaled problem (0, 0 unless it is a hyperbola)."""
    return _hyperbolic_coefficients(scaled[10], scaled[11], scaled[12], _semilatus(scaled))


@jit(inline=True)
def _valid(rx, ry, rz, vx, vy, vz, mu, dt):
    """Finite state, mu and dt, mu > 0 and r x v != 0 (the NumPy version raises otherwise)."""
    hx, hy, hz = ry * vz - rz * vy, rz * vx - rx * vz, rx * vy - ry * vx
    finite = np.isfinite(rx) and np.isfinite(ry) and np.isfinite(rz) and np.isfinite(vx) and np.isfinite(vy)
    finite = finite and np.isfinite(vz) and np.isfinite(mu) and np.isfinite(dt)
    return finite and mu > 0.0 and hx * hx + hy * hy + hz * hz > 0.0


@jit(inline=True)
def _state_at(chi, scaled):
    """(r, v) as six floats from the Lagrange f and g at chi, as propagate._lagrange; NaN where chi is NaN."""
    length, speed, back, x, y, z, u, v, w, tau, r0, sigma0, alpha, dt, _, _ = scaled
    grow, decay = _coefficients(scaled)
    g0, g1, g2, g3, e_sinh, e_cosh = _g_functions(chi, alpha, grow, decay)
    inverse, _, inverse_15 = _inverse_powers(alpha)
    possible = alpha * chi * chi < -1.0
    r_terms, r_terms_h = abs(r0 * g0) + abs(sigma0 * g1) + abs(g2), (abs(e_cosh) + 1.0) * inverse
    g_terms, g_terms_h = abs(r0 * g1) + abs(sigma0 * g2), abs(e_sinh) * inverse_15 + (abs(sigma0) + abs(g1)) * inverse
    r_new = (e_cosh - 1.0) * inverse if (possible and r_terms_h < r_terms) else r0 * g0 + sigma0 * g1 + g2
    g_far = e_sinh * inverse_15 - (sigma0 + g1) * inverse
    f, g = 1.0 - g2 / r0, (g_far if (possible and g_terms_h < g_terms) else r0 * g1 + sigma0 * g2)
    f_dot, g_dot = -g1 / (r_new * r0), 1.0 - g2 / r_new
    vel_scale = back * speed
    return (
        (f * x + g * u) * length,
        (f * y + g * v) * length,
        (f * z + g * w) * length,
        (f_dot * x + g_dot * u) * vel_scale,
        (f_dot * y + g_dot * v) * vel_scale,
        (f_dot * z + g_dot * w) * vel_scale,
    )



# --- the universal passes, on the states the elliptic pass leaves ---------------------------------


@jit
def _gather_block(index, first, n, r0, v0, mu, dt, scratch):
    """Copy states index[first .. first + n - 1] into the input rows (row views, one statement each: LLVM
    vectorises the loop with gathers; with the rows indexed through scratch it ran at 6 ns a state)."""
    rx, ry, rz, vx, vy, vz = scratch[_RX], scratch[_RY], scratch[_RZ], scratch[_VX], scratch[_VY], scratch[_VZ]
    mu_row, dt_row, rows = scratch[_MU], scratch[_DT], index[first:first + n]
    for j in range(n):
        i = rows[j]
        rx[j], ry[j], rz[j], vx[j], vy[j], vz[j] = r0[i, 0], r0[i, 1], r0[i, 2], v0[i, 0], v0[i, 1], v0[i, 2]
        mu_row[j], dt_row[j] = mu[i], dt[i]


@jit
def _setup_block(n, scratch):
    """Scaled problem and starter of the block's states (vectorised); returns how many are invalid."""
    rx, ry, rz, vx, vy, vz = scratch[_RX], scratch[_RY], scratch[_RZ], scratch[_VX], scratch[_VY], scratch[_VZ]
    mu, dt = scratch[_MU], scratch[_DT]
    tau, r0, sigma0, alpha = scratch[_TAU], scratch[_R0], scratch[_SIGMA0], scratch[_ALPHA]
    grow, decay, chi, lo, hi = scratch[_GROW], scratch[_DECAY], scratch[_CHI], scratch[_LO_U], scratch[_HI_U]
    invalid = 0
    for j in range(n):
        invalid += not _valid(rx[j], ry[j], rz[j], vx[j], vy[j], vz[j], mu[j], dt[j])
        scaled = _scaled(rx[j], ry[j], rz[j], vx[j], vy[j], vz[j], mu[j], dt[j])
        tau[j], r0[j], sigma0[j], alpha[j] = scaled[9], scaled[10], scaled[11], scaled[12]
        p = _semilatus(scaled)
        grow[j], decay[j] = _hyperbolic_coefficients(r0[j], sigma0[j], alpha[j], p)
        chi[j] = _starter(tau[j], r0[j], sigma0[j], alpha[j], p, grow[j], decay[j])
        lo[j], hi[j] = 0.0, np.inf
    return invalid


@jit
def _step_block(n, scratch):
    """One branch-free Halley step for each state of the block (vectorised)."""
    tau, r0, sigma0, alpha = scratch[_TAU], scratch[_R0], scratch[_SIGMA0], scratch[_ALPHA]
    grow, decay = scratch[_GROW], scratch[_DECAY]
    chi, lo, hi, last = scratch[_CHI], scratch[_LO_U], scratch[_HI_U], scratch[_LAST]
    for j in range(n):
        chi[j], lo[j], hi[j], last[j] = _fixed_step(chi[j], lo[j], hi[j], tau[j], r0[j], sigma0[j], alpha[j],
                                                    grow[j], decay[j])


@jit
def _certify_block(n, scratch):
    """Polish chi and certify it (vectorised), as propagate._solve_certified: NaN unless the last Halley step
    was below 2**-26 relative and the polishing step below 2**-40."""
    tau, r0, sigma0, alpha = scratch[_TAU], scratch[_R0], scratch[_SIGMA0], scratch[_ALPHA]
    grow, decay, chi, last = scratch[_GROW], scratch[_DECAY], scratch[_CHI], scratch[_LAST]
    for j in range(n):
        x, step = _polish(chi[j], tau[j], r0[j], sigma0[j], alpha[j], grow[j], decay[j])
        certified = last[j] <= 2.0**-26 * chi[j] and abs(step) <= 2.0**-40 * chi[j]
        chi[j] = x if certified else np.nan


@jit
def _evaluate_positions(n, scratch):
    """r at chi into the output rows (vectorised; r and v in one loop need more runtime alias checks than
    LLVM's vectoriser makes); r0 itself where the reduced dt is 0."""
    rx, ry, rz, vx, vy, vz = scratch[_RX], scratch[_RY], scratch[_RZ], scratch[_VX], scratch[_VY], scratch[_VZ]
    mu, dt, chi = scratch[_MU], scratch[_DT], scratch[_CHI]
    out_x, out_y, out_z = scratch[_OUT], scratch[_OUT + 1], scratch[_OUT + 2]
    for j in range(n):
        scaled = _scaled(rx[j], ry[j], rz[j], vx[j], vy[j], vz[j], mu[j], dt[j])
        x, y, z, _, _, _ = _state_at(chi[j], scaled)
        still = scaled[13] == 0.0
        out_x[j], out_y[j], out_z[j] = (rx[j], ry[j], rz[j]) if still else (x, y, z)


@jit
def _evaluate_velocities(n, scratch):
    """v at chi into the output rows, as _evaluate_positions."""
    rx, ry, rz, vx, vy, vz = scratch[_RX], scratch[_RY], scratch[_RZ], scratch[_VX], scratch[_VY], scratch[_VZ]
    mu, dt, chi = scratch[_MU], scratch[_DT], scratch[_CHI]
    out_x, out_y, out_z = scratch[_OUT + 3], scratch[_OUT + 4], scratch[_OUT + 5]
    for j in range(n):
        scaled = _scaled(rx[j], ry[j], rz[j], vx[j], vy[j], vz[j], mu[j], dt[j])
        _, _, _, x, y, z = _state_at(chi[j], scaled)
        still = scaled[13] == 0.0
        out_x[j], out_y[j], out_z[j] = (vx[j], vy[j], vz[j]) if still else (x, y, z)


@jit
def _scatter_block(index, first, n, scratch, r, v):
    """Copy the output rows into r[index[first:first + n]], v[...]."""
    for j in range(n):
        i = index[first + j]
        for k in range(3):
            r[i, k] = scratch[_OUT + k, j]
            v[i, k] = scratch[_OUT + 3 + k, j]


@jit
def _universal_passes(index, r0, v0, mu, dt, r, v, scratch):
    """The universal passes on the states index[...]: pass 1 (FIXED_STEPS branch-free Halley steps, vectorised,
    block by block), then pass 2 on those it leaves uncertified (NaN); returns invalid * 2**32 + unconverged."""
    invalid = 0
    for first in range(0, index.size, _BLOCK):
        n = min(_BLOCK, index.size - first)
        _gather_block(index, first, n, r0, v0, mu, dt, scratch)
        invalid += _setup_block(n, scratch)
        for _ in range(FIXED_STEPS):
            _step_block(n, scratch)
        _certify_block(n, scratch)
        _evaluate_positions(n, scratch)
        _evaluate_velocities(n, scratch)
        _scatter_block(index, first, n, scratch, r, v)
    if invalid:
        return invalid * _INVALID
    unconverged = 0
    for i in index:
        if np.isnan(r[i, 0]):
            scaled = _scaled(r0[i, 0], r0[i, 1], r0[i, 2], v0[i, 0], v0[i, 1], v0[i, 2], mu[i], dt[i])
            grow, decay = _coefficients(scaled)
            chi = _solve_universal(scaled[9], scaled[10], scaled[11], scaled[12], _semilatus(scaled), grow, decay)
            state = _state_at(chi, scaled)
            for k in range(3):
                r[i, k] = r0[i, k] if scaled[13] == 0.0 else state[k]
                v[i, k] = v0[i, k] if scaled[13] == 0.0 else state[3 + k]
            unconverged += np.isnan(chi)
    return unconverged

