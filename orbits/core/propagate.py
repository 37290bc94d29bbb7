"""Universal-variable (Stumpff) two-body propagator: r, v at t0 + dt from r0, v0, for every conic.

Float64 arrays, SI units; r0, v0 of shape (..., 3), mu and dt broadcast against the batch shape.

Method (Goodyear 1965, in the G-function form of Stiefel & Scheifele): the state is scaled to
|r0| = 1, mu = 1 (which keeps 1e-30 m and 1e30 m orbits in range), elliptic times are reduced
modulo the period, negative times are handled by time reversal (r, v, -dt) -> (r, -v, dt), and the
universal Kepler equation
    r0 G1(chi) + sigma0 G2(chi) + G3(chi) = dt,   G_k = chi**k c_k(alpha chi**2)
is solved for chi by bracketed Halley iteration (F' = r > 0, so the root is unique). The Stumpff
functions c_k come from their series for |z| <= 1 and from cancellation-free closed forms beyond
(z > 0: 2 sin(s/2)**2 / z and (s - sin s) / s**3; z < 0 likewise with sinh), so orbits with
|1 - e| down to 1e-16 and exact parabolas propagate without a special case.
Radial orbits (r x v = 0) raise DegenerateOrbitError: the collision with the primary is not
regularised here.

Speed: with numba installed the same algorithm runs compiled, one state at a time
(orbits/core/_fast_propagate.py); this NumPy version runs otherwise (ORBITS_JIT=0) and re-runs any
batch the kernel flags, so that invalid input raises the same messages. Timings are in the README's
Benchmarks section.
"""

import numpy as np
from numpy.typing import ArrayLike

from orbits.core import _dd, _fast
from orbits.core._roots import halley_in_bracket
from orbits.core.checks import check_finite
from orbits.core.elements import check_state
from orbits.core.errors import DegenerateOrbitError
from orbits.core.kepler import TWO_PI_1, TWO_PI_2, sinh_minus_x, x_minus_sin
from orbits.core.series import factorial_series, horner

#: c_k(z) = sum_j (-z)**j / (2j + k)! for k = 2, 3, to 12 terms (|z| <= 1)
C2_SERIES, C3_SERIES = factorial_series(2, -1.0, 12), factorial_series(3, -1.0, 12)


def stumpff(z: ArrayLike) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    """Stumpff functions (c0, c1, c2, c3) of z: c0 = cos sqrt z, c1 = sin sqrt z / sqrt z, c2, c3.

    Overflows to inf (not NaN) for z below about -5e5, where cosh sqrt(-z) exceeds float64.
    """
    z = np.asarray(z, dtype=float)
    c0, c1, c2, c3 = (np.empty_like(z) for _ in range(4))
    small, pos, neg = np.abs(z) <= 1.0, z > 1.0, z < -1.0
    zs = z[small]
    c2[small], c3[small] = horner(C2_SERIES, zs), horner(C3_SERIES, zs)
    c0[small], c1[small] = 1.0 - zs * c2[small], 1.0 - zs * c3[small]
    s = np.sqrt(z[pos])
    c0[pos], c1[pos] = np.cos(s), np.sin(s) / s
    c2[pos], c3[pos] = 2.0 * np.sin(0.5 * s) ** 2 / z[pos], x_minus_sin(s) / (s * z[pos])
    s = np.sqrt(-z[neg])
    with np.errstate(over="ignore"):
        c0[neg], c1[neg] = np.cosh(s), np.sinh(s) / s
        c2[neg], c3[neg] = 2.0 * np.sinh(0.5 * s) ** 2 / -z[neg], sinh_minus_x(s) / (s * -z[neg])
    return c0, c1, c2, c3


def _g_functions(chi, alpha):
    """G_k = chi**k c_k(alpha chi**2), k = 0..3."""
    with np.errstate(over="ignore", invalid="ignore"):  # huge chi on hyperbolas: inf, handled by callers
        c0, c1, c2, c3 = stumpff(alpha * chi * chi)
        return c0, chi * c1, chi * chi * c2, chi * chi * chi * c3


def _vallado_guess(tau, r0, sigma0, alpha):
    """tau alpha on ellipses; on hyperbolas Vallado's logarithmic guess, the exponential regime where Halley's
    method from a linear guess would crawl: chi0 = sqrt(-a) ln(-2 alpha tau / (sigma0 + sqrt(-a) (1 - alpha r0))),
    a = 1 / alpha (tau / r0 where it is not usable)."""
    with np.errstate(divide="ignore", invalid="ignore", over="ignore"):
        sqrt_minus_a = np.sqrt(-1.0 / alpha)
        log_guess = sqrt_minus_a * np.log(-2.0 * alpha * tau / (sigma0 + sqrt_minus_a * (1.0 - alpha * r0)))
    linear_guess = np.where(alpha > 0, tau * alpha, tau / r0)
    return np.maximum(np.where((alpha < 0) & np.isfinite(log_guess) & (log_guess > 0), log_guess, linear_guess), 0.0)


def _barker_guess(tau, sigma0, p):
    """chi on the parabola with the same p = h**2 and r0.v0: sqrt(p) (D - D0), D = tan(nu / 2) from Barker's
    equation D + D**3 / 3 = D0 + D0**3 / 3 + 2 tau / p**1.5 (Cardano)."""
    with np.errstate(over="ignore", invalid="ignore"):
        root_p = np.sqrt(p)
        d0 = sigma0 / root_p
        w = d0 + d0 * d0 * d0 / 3.0 + 2.0 * tau / (p * root_p)
        c = np.cbrt(1.5 * np.abs(w) + np.sqrt(2.25 * w * w + 1.0))
        guess = root_p * (np.copysign(c - 1.0 / c, w) - d0)
    return np.where(np.isfinite(guess), np.maximum(guess, 0.0), 0.0)


def _starter(tau, r0, sigma0, alpha, p, residual):
    """First guess for chi: the better, by the length of the Newton step from each, of Vallado's guess and the
    parabolic (Barker) guess. The compiled kernel (orbits.core._fast_propagate) ports this starter."""
    vallado, barker = _vallado_guess(tau, r0, sigma0, alpha), _barker_guess(tau, sigma0, p)
    every = np.nonzero(np.ones(tau.shape, dtype=bool))
    f_v, df_v, _ = residual(vallado, every)
    f_b, df_b, _ = residual(barker, every)
    with np.errstate(divide="ignore", invalid="ignore", over="ignore"):
        step_v, step_b = np.abs(f_v / df_v), np.abs(f_b / df_b)
    barker_better = np.isfinite(step_b) & ~(step_v <= step_b)  # a step that overflowed is never the better
    return np.where(barker_better, barker, vallado)


def _solve_universal(tau, r0, sigma0, alpha, p):
    """chi >= 0 with r0 G1 + sigma0 G2 + G3 = tau >= 0 (scaled units, mu = 1; p = h**2)."""

    def residual(chi, idx):
        g0, g1, g2, g3 = _g_functions(chi, alpha[idx])
        with np.errstate(over="ignore", invalid="ignore"):
            f = (r0[idx] * g1 + sigma0[idx] * g2 + g3) - tau[idx]
            df = r0[idx] * g0 + sigma0[idx] * g1 + g2
            d2f = sigma0[idx] * g0 + (1.0 - alpha[idx] * r0[idx]) * g1
        # F is increasing, so a non-finite value (overflow at huge chi) lies above the root.
        return np.where(np.isfinite(f), f, np.inf), df, d2f

    all_idx = np.nonzero(np.ones(tau.shape, dtype=bool))
    hi = np.maximum(tau / r0, 1e-300)
    for _ in range(2100):  # grow the bracket until F(hi) >= 0; F grows at least linearly in chi
        f, _, _ = residual(hi, all_idx)
        short = ~(f >= 0)
        if not np.any(short):
            break
        hi = np.where(short, 2.0 * hi, hi)
    lo = np.zeros_like(tau)
    start = np.clip(_starter(tau, r0, sigma0, alpha, p, residual), lo, hi)
    return halley_in_bracket(start, lo, hi, residual, "universal Kepler solve", {"dt": tau, "alpha": alpha})


def _reduce_by_periods(r0, v0, mu, dt):
    """(dt - k P with k = round(dt / P) on ellipses, unchanged on open orbits; alpha [1/m]), where
    alpha = 2 / |r0| - |v0|**2 / mu and P = 2 pi / sqrt(mu alpha**3).

    alpha and P are formed in double-double arithmetic: a rounding error of 1e-16 in P would otherwise
    grow into a 1e-11 phase error after 1e3 periods of an e = 0.9 orbit, and alpha formed in float64
    from the scaled state loses to cancellation the digits that the solve needs near e = 1 (measured
    on the benchmark's mixed states: worst position error 4.9e-11 with it, 6.6e-16 with this alpha).
    """
    zero = np.zeros_like(dt)
    r_norm = _dd.sqrt(_dd.dot(r0, r0))
    v2_over_mu = _dd.div(_dd.dot(v0, v0), (mu, zero))
    alpha = _dd.add(_dd.div((2.0 + zero, zero), r_norm), (-v2_over_mu[0], -v2_over_mu[1]))
    alpha_si = alpha[0] + alpha[1]
    bound = alpha[0] > 0
    if not np.any(bound):
        return dt, alpha_si
    alpha = (np.where(bound, alpha[0], 1.0), np.where(bound, alpha[1], 0.0))
    n = _dd.mul(_dd.sqrt((mu, zero)), _dd.mul(alpha, _dd.sqrt(alpha)))
    period = _dd.div((TWO_PI_1 + zero, TWO_PI_2 + zero), n)
    turns = np.where(bound, np.rint(dt / period[0]), 0.0)
    p_hi, p_lo = _dd.two_product(turns, period[0])
    reduced = _dd.add((dt, zero), (-p_hi, -(p_lo + turns * period[1])))
    return reduced[0] + reduced[1], alpha_si


def propagate(r0: ArrayLike, v0: ArrayLike, mu: ArrayLike, dt: ArrayLike) -> tuple[np.ndarray, np.ndarray]:
    """State (r [m], v [m/s]) at t0 + dt [s] on the Kepler orbit through r0 [m], v0 [m/s] about mu [m**3/s**2].

    Accuracy against an mpmath reference (tests/core/test_propagate.py): positions within 5e-15 relative over
    +-1000 periods for e up to 1 - 1e-6 (measured 5.6e-16) and within 1e-14 for |1 - e| down to 1e-12;
    velocities within 40 eps / sqrt(1 - e) (measured 4.1 eps / sqrt(1 - e)); near-parabolic hyperbolas flown for
    1e9 s within 1e-14 in position. The compiled kernel (orbits.core._fast_propagate) ports this algorithm.
    """
    if _fast.enabled():  # at every batch size: on hyperbolas this NumPy version is still less accurate (issue 14)
        result = _propagate_compiled(r0, v0, mu, dt)
        if result is not None:
            return result
    return _propagate_numpy(r0, v0, mu, dt)


def _propagate_compiled(r0, v0, mu, dt):
    """propagate by the compiled kernel; None if the inputs need the NumPy version's checks to raise."""
    _fast.announce("_fast_propagate")
    from orbits.core import _fast_propagate

    r0, v0, mu, dt = (np.asarray(x, dtype=float) for x in (r0, v0, mu, dt))
    if r0.shape[-1:] != (3,) or v0.shape[-1:] != (3,):
        return None
    try:
        batch = np.broadcast_shapes(r0.shape[:-1], v0.shape[:-1], mu.shape, dt.shape)
    except ValueError:
        return None
    r0, v0 = (_contiguous(x, batch + (3,)).reshape(-1, 3) for x in (r0, v0))
    mu, dt = (_contiguous(x, batch).reshape(-1) for x in (mu, dt))
    r, v = np.empty_like(r0), np.empty_like(v0)
    if _fast.run(_fast_propagate.propagate, dt.size, r0, v0, mu, dt, r, v):
        return None
    return r.reshape(batch + (3,)), v.reshape(batch + (3,))


def _contiguous(x, shape):
    """x broadcast to shape as a writable C-contiguous array (copied only if needed): every call then
    passes the kernel the same array types, so numba compiles it once."""
    if x.shape != shape:
        x = np.broadcast_to(x, shape)
    return np.require(x, requirements=["C", "W"])


def _propagate_numpy(r0, v0, mu, dt):
    """propagate in NumPy (masked iterations over the whole batch)."""
    r0, v0, mu = check_state(r0, v0, mu)
    dt = np.asarray(dt, dtype=float)
    check_finite(dt, "time step dt", "s")
    batch = np.broadcast_shapes(mu.shape, dt.shape)
    r0, v0 = np.broadcast_to(r0, batch + (3,)).reshape(-1, 3), np.broadcast_to(v0, batch + (3,)).reshape(-1, 3)
    mu, dt = np.broadcast_to(mu, batch).reshape(-1), np.broadcast_to(dt, batch).reshape(-1)
    h = np.cross(r0, v0)
    if np.any(np.sum(h * h, axis=-1) == 0):
        raise DegenerateOrbitError(
            "the state is radial (r x v = 0): the propagator does not regularise the collision with "
            "the primary; give the orbit a non-zero angular momentum"
        )
    dt, alpha_si = _reduce_by_periods(r0, v0, mu, dt)
    length = np.sqrt(np.sum(r0 * r0, axis=-1))
    speed_scale = np.sqrt(mu / length)
    x, w, tau = r0 / length[..., None], v0 / speed_scale[..., None], dt * speed_scale / length
    r_scaled = np.sqrt(np.sum(x * x, axis=-1))
    alpha = alpha_si * length
    backwards = np.signbit(tau)
    w = np.where(backwards[..., None], -w, w)
    tau = np.abs(tau)
    sigma0 = np.sum(x * w, axis=-1)
    h_scaled = np.cross(x, w)
    chi = _solve_universal(tau, r_scaled, sigma0, alpha, np.sum(h_scaled * h_scaled, axis=-1))
    g0, g1, g2, g3 = _g_functions(chi, alpha)
    r_new = r_scaled * g0 + sigma0 * g1 + g2
    f, g = 1.0 - g2 / r_scaled, r_scaled * g1 + sigma0 * g2
    f_dot, g_dot = -g1 / (r_new * r_scaled), 1.0 - g2 / r_new
    x_new = f[..., None] * x + g[..., None] * w
    w_new = f_dot[..., None] * x + g_dot[..., None] * w
    w_new = np.where(backwards[..., None], -w_new, w_new)
    r, v = x_new * length[..., None], w_new * speed_scale[..., None]
    r, v = np.where(dt[..., None] == 0, r0, r), np.where(dt[..., None] == 0, v0, v)  # dt = 0: exactly r0, v0
    return r.reshape(batch + (3,)), v.reshape(batch + (3,))
