"""Two-body propagator: r, v at t0 + dt from r0, v0, for every conic (an elliptic and a hyperbolic pass, then
universal variables).

Float64 arrays, SI units; r0, v0 of shape (..., 3), mu and dt broadcast against the batch shape.

Method. Bound states (|r0| |v0|**2 <= 2 mu in float64) go through the elliptic pass, open ones through the
hyperbolic pass; what neither certifies (exact parabolas, a state on the other side of e = 1 than float64 said,
a solve it cannot vouch for: no ellipse of 2e5 random ones, 0.1 % of random inbound hyperbolas) goes through
the universal passes.

Both passes solve the universal Kepler equation in a scaled anomaly x, multiplied by the mean motion n. Elliptic:
x = chi / sqrt(a) = E - E0,
    F(x) = A x + ec (x - sin x) + es (1 - cos x) = m,   A = |r0| / a = 1 - ec,  (ec, es) = e (cos E0, sin E0),
m = n dt reduced modulo 2 pi; hyperbolic: x = chi sqrt(-alpha) = H - H0,
    F(x) = A x + ec (sinh x - x) + es (cosh x - 1) = m,   A = |r0| / |a| = ec - 1,  (ec, es) = e (cosh H0, sinh H0),
m = n dt (time reversal for dt < 0, as below). F' = r / |a| > 0. A, 1 / a, n, n dt and es come from
double-double arithmetic (A loses log2(1 / A) bits to cancellation near periapsis as e -> 1; a rounded n would
be a phase error growing with the number of periods; near e = 1 the solve magnifies the rounding of es). The
terms of F are free of cancellation (series below 2), and F is summed with exact products: on the way in to
periapsis near e = 1, A x and es (1 - cos x) (or es (cosh x - 1)) cancel, and rounded they cost up to 4x the
input's own conditioning. Far out on a hyperbola's way in, where ec and -es nearly cancel, F, r and g are
summed in the anomaly form instead, e exp(+-H0) = ec +- es (the smaller from e**2 = 1 + beta h**2 / mu).
Elliptic starter: the root of the quadratic model A x + es x**2 / 2 = m where the terms it leaves out are small
(short arcs), else Markley's (through E0 = atan2(es, ec)); one sixth-order step in [m - 2 e, m + 2 e].
Hyperbolic starter: the better, by Newton step length, of the logarithmic one (Vallado's, log(2 m / e exp H0))
and the parabola's with the same h and r0 . v0 (Barker's equation); HYPERBOLIC_STEPS sixth-order steps in
[0, m / (e - 1)]. Then one Newton step and a certificate on that step and its own error; r and v follow from
the Lagrange f and g built from the trigonometric or hyperbolic terms of that last evaluation, carried through
the Newton step to first order (_elliptic_lagrange, _hyperbolic_lagrange).

The universal passes (Goodyear 1965, in the G-function form of Stiefel & Scheifele): the state is scaled to
|r0| = 1, mu = 1 (which keeps 1e-30 m and 1e30 m orbits in range), elliptic times are reduced
modulo the period, negative times are handled by time reversal (r, v, -dt) -> (r, -v, dt), and the
universal Kepler equation
    r0 G1(chi) + sigma0 G2(chi) + G3(chi) = dt,   G_k = chi**k c_k(alpha chi**2)
is solved for chi (F' = r > 0, so the root is unique) in two passes:
1. from the starter (the better, by Newton step length, of Vallado's guess and the parabolic guess),
   FIXED_STEPS Halley steps kept inside [lo, hi] (initially [0, inf): a step leaving it bisects, or
   doubles while hi is unbounded), one polishing Newton step, and a certificate: the last Halley step
   below 2**-26 and the Newton step below 2**-40 relative;
2. the states pass 1 does not certify (none of the benchmark's mixed states) run the safeguarded
   iteration: the bracket [0, hi] grown by doubling until F(hi) >= 0, Halley from the starter with
   bisection (orbits.core._roots.halley_in_bracket), then the polishing step.
The Stumpff functions c_k come from their series for |z| <= 1 and from cancellation-free closed forms
beyond (z > 0: sin s and cos s of s = sqrt z, 1 - cos s = sin**2 s / (1 + cos s) while cos s > 0;
z < 0: E = exp t of t = sqrt(-z), cosh t - 1 = sinh t tanh(t / 2), tanh(t / 2) = (1 - 1/E) / (1 + 1/E);
s - sin s and sinh t - t from their series below 2), so orbits with |1 - e| down to 1e-16 and exact
parabolas propagate without a special case.
On a hyperbola (beta = -alpha > 0) started far out on its way in, the terms r0 G1 and sigma0 G2 nearly cancel
(digits lost grow with r0 / q: 3e-12 near the asymptote). Where alpha chi**2 < -1 and its terms are smaller, F
is summed in the hyperbolic anomaly H = H0 + sqrt(beta) chi instead: F = e sinh H / beta**1.5 - (sigma0 + chi)
/ beta, with e exp(+-H0) from 1 + r0 beta +- sigma0 sqrt(beta) and, for the one that cancels, from their
product e**2 = 1 + beta h**2; likewise r and the Lagrange g, each where that form cancels less.
Radial orbits (r x v = 0) raise DegenerateOrbitError: the collision with the primary is not regularised.

Speed: the compiled kernel (orbits/core/twobody/_fast_propagate.py, _fast_universal.py) ports this algorithm step by
step (its sin, cos, exp, atan2, log and cube root are its own, and it may fuse a * b + c, so the two agree to
rounding). Batches from orbits.core._fast.AUTO_MIN_BATCH states run compiled, smaller ones here without numba;
a batch the kernel flags runs here, so that invalid input raises the same messages. Timings: README, Benchmarks.
"""

from typing import NamedTuple

import numpy as np
from numpy.typing import ArrayLike

from orbits.core import _dd, _fast
from orbits.core._roots import halley_in_bracket
from orbits.core.checks import broadcast_shape, check_finite
from orbits.core.errors import DegenerateOrbitError
from orbits.core.series import horner
from orbits.core.twobody._kepler_shared import (
    COSH_MINUS_ONE,
    MAX_MEAN_ANOMALY,
    ONE_MINUS_COS,
    PI_1,
    PI_2,
    SINH_MINUS_X,
    TWO_PI_1,
    TWO_PI_2,
    X_MINUS_SIN,
)
from orbits.core.twobody._propagate_shared import (
    BRACKET_DOUBLINGS,
    BRACKET_WIDTH,
    C2_SERIES,
    C3_SERIES,
    ELLIPTIC_ERROR,
    ELLIPTIC_STEP,
    FIXED_STEPS,
    HYPERBOLIC_STEPS,
    LOCAL_STARTER_STEP,
    SERIES_LIMIT,
    SMALLEST_MEAN_MOTION_SQUARED,
)
from orbits.core.twobody.elements import check_state
from orbits.core.twobody.kepler import markley_starter, reduce_two_pi, sixth_order_step


def stumpff(z: ArrayLike) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    """Stumpff functions (c0, c1, c2, c3) of z: c0 = cos sqrt z, c1 = sin sqrt z / sqrt z, c2, c3.

    The formulas of the module docstring, which the compiled kernel uses too. Overflows to inf (not NaN) for z
    below about -5e5, where cosh sqrt(-z) exceeds float64.
    """
    z = np.asarray(z, dtype=float)
    c0, c1, c2, c3 = (np.empty_like(z) for _ in range(4))
    small, pos, neg = np.abs(z) <= 1.0, z > 1.0, z < -1.0
    zs = z[small]
    c2[small], c3[small] = horner(C2_SERIES, zs), horner(C3_SERIES, zs)
    c0[small], c1[small] = 1.0 - zs * c2[small], 1.0 - zs * c3[small]
    zp = z[pos]
    s = np.sqrt(zp)
    sin, cos = np.sin(s), np.cos(s)
    one_minus_cos = np.where(cos > 0.0, sin * sin / (1.0 + np.maximum(cos, 0.0)), 1.0 - cos)
    s_minus_sin = np.where(s < SERIES_LIMIT, s * s * s * horner(X_MINUS_SIN, zp), s - sin)
    c0[pos], c1[pos], c2[pos], c3[pos] = cos, sin / s, one_minus_cos / zp, s_minus_sin / (s * zp)
    zn = -z[neg]
    t = np.sqrt(zn)
    with np.errstate(over="ignore"):
        exp = np.exp(t)
        inverse = 1.0 / exp
        sinh, cosh = 0.5 * (exp - inverse), 0.5 * (exp + inverse)
        cosh_minus_one = sinh * ((1.0 - inverse) / (1.0 + inverse))
        sinh_minus_t = np.where(t < SERIES_LIMIT, t * t * t * horner(SINH_MINUS_X, zn), sinh - t)
        c0[neg], c1[neg], c2[neg], c3[neg] = cosh, sinh / t, cosh_minus_one / zn, sinh_minus_t / (t * zn)
    return c0, c1, c2, c3


def _g_functions(chi, alpha):
    """G_k = chi**k c_k(alpha chi**2), k = 0..3."""
    with np.errstate(over="ignore", invalid="ignore"):  # huge chi on hyperbolas: inf, handled by callers
        c0, c1, c2, c3 = stumpff(alpha * chi * chi)
        return c0, chi * c1, chi * chi * c2, chi * chi * chi * c3


def _hyperbolic_coefficients(r0, sigma0, alpha, p):
    """(grow, decay) = (e exp H0, e exp -H0) of a hyperbola (0 on other orbits), H0 the hyperbolic anomaly at
    t0: with beta = -alpha, 1 + r0 beta = e cosh H0 and sigma0 sqrt(beta) = e sinh H0, and the smaller of the
    two from grow decay = e**2 = 1 + beta p, p = h**2 (the difference cancels on the way in or out)."""
    beta = np.where(alpha < 0.0, -alpha, 0.0)
    e_cosh, e_sinh = 1.0 + r0 * beta, sigma0 * np.sqrt(beta)
    larger = e_cosh + np.abs(e_sinh)
    smaller = (1.0 + beta * p) / larger
    grow, decay = np.where(sigma0 < 0.0, smaller, larger), np.where(sigma0 < 0.0, larger, smaller)
    return np.where(alpha < 0.0, grow, 0.0), np.where(alpha < 0.0, decay, 0.0)


def _hyperbolic_terms(chi, alpha, grow, decay):
    """(e sinh H, e cosh H) at chi: H = H0 + sqrt(-alpha) chi (only where alpha chi**2 < -1)."""
    with np.errstate(over="ignore", invalid="ignore"):
        exp = np.exp(np.sqrt(np.maximum(-alpha * chi * chi, 1.0)))
        inverse = 1.0 / exp
        return 0.5 * (grow * exp - decay * inverse), 0.5 * (grow * exp + decay * inverse)


def _inverse_powers(alpha):
    """(1 / beta, 1 / sqrt(beta), 1 / beta**1.5), beta = -alpha (meaningful on hyperbolas only): one division
    instead of one per term (the kernel's vectorised loops pay for every division)."""
    with np.errstate(divide="ignore", invalid="ignore", over="ignore"):
        inverse = 1.0 / -alpha
        inverse_root = np.sqrt(np.maximum(-alpha, 0.0)) * inverse
        return inverse, inverse_root, inverse * inverse_root


def _anomaly_form(chi, r0, sigma0, alpha, g, e_sinh, inverse, inverse_15):
    """Where F is better summed in the hyperbolic anomaly H (beta = -alpha) as
    F = e sinh H / beta**1.5 - (sigma0 + chi) / beta than as r0 G1 + sigma0 G2 + G3: alpha chi**2 < -1 and the
    terms of the first are smaller, so that less cancels. That is the case on a hyperbola flown from far out on
    its way in, where sigma0 G2 nearly cancels r0 G1; near e = 1 with |H| small it is e sinh H - H that
    cancels, and the G form is kept."""
    g0, g1, g2, g3 = g
    with np.errstate(over="ignore", invalid="ignore"):
        g_terms = np.abs(r0 * g1) + np.abs(sigma0 * g2) + np.abs(g3)
        h_terms = np.abs(e_sinh) * inverse_15 + (np.abs(sigma0) + chi) * inverse
        return (alpha * chi * chi < -1.0) & (h_terms < g_terms)


def _residual(chi, tau, r0, sigma0, alpha, grow, decay):
    """(F - tau, F', F'') with F = r0 G1 + sigma0 G2 + G3; F is increasing, so a non-finite F (overflow at huge
    chi) counts as +inf, above the root. In the anomaly form (see _anomaly_form) F' = (e cosh H - 1) / beta and
    F'' = e sinh H / sqrt(beta)."""
    g0, g1, g2, g3 = g = _g_functions(chi, alpha)
    e_sinh, e_cosh = _hyperbolic_terms(chi, alpha, grow, decay)
    inverse, inverse_root, inverse_15 = _inverse_powers(alpha)
    with np.errstate(over="ignore", invalid="ignore"):
        f = (r0 * g1 + sigma0 * g2 + g3) - tau
        df = r0 * g0 + sigma0 * g1 + g2
        d2f = sigma0 * g0 + (1.0 - alpha * r0) * g1
        f_h = (e_sinh * inverse_15 - (sigma0 + chi) * inverse) - tau
        df_h, d2f_h = (e_cosh - 1.0) * inverse, e_sinh * inverse_root
    far = _anomaly_form(chi, r0, sigma0, alpha, g, e_sinh, inverse, inverse_15)
    f, df, d2f = np.where(far, f_h, f), np.where(far, df_h, df), np.where(far, d2f_h, d2f)
    return np.where(np.isfinite(f), f, np.inf), df, d2f


def _vallado_guess(tau, r0, sigma0, alpha):
    """tau alpha on ellipses; on hyperbolas Vallado's logarithmic guess, the exponential regime where Halley's
    method from a linear guess would crawl: chi0 = sqrt(-a) ln(-2 alpha tau / (sigma0 + sqrt(-a) (1 - alpha r0))),
    a = 1 / alpha (tau / r0 where it is not usable)."""
    with np.errstate(divide="ignore", invalid="ignore", over="ignore"):
        sqrt_minus_a = np.sqrt(np.maximum(-1.0 / alpha, 0.0))
        ratio = -2.0 * alpha * tau / (sigma0 + sqrt_minus_a * (1.0 - alpha * r0))
        usable = (alpha < 0.0) & (ratio >= np.finfo(float).tiny) & (ratio < np.inf)
        log_guess = sqrt_minus_a * np.log(np.where(usable, ratio, 1.0))
    linear_guess = np.where(alpha > 0.0, tau * alpha, tau / r0)
    return np.maximum(np.where(usable & (log_guess > 0.0), log_guess, linear_guess), 0.0)


def _barker_guess(tau, sigma0, p):
    """chi on the parabola with the same p = h**2 and r0.v0: sqrt(p) (D - D0), D = tan(nu / 2) from Barker's
    equation D + D**3 / 3 = D0 + D0**3 / 3 + 2 tau / p**1.5 (Cardano); 0 where negative, overflowing or p = 0."""
    with np.errstate(over="ignore", invalid="ignore", divide="ignore"):
        root_p = np.sqrt(p)
        d0 = sigma0 / root_p
        w = d0 + d0 * d0 * d0 / 3.0 + 2.0 * tau / (p * root_p)
        c = np.cbrt(1.5 * np.abs(w) + np.sqrt(2.25 * w * w + 1.0))
        guess = root_p * (np.copysign(c - 1.0 / c, w) - d0)
        return np.where((guess > 0.0) & (guess < np.inf), guess, 0.0)


def _starter(tau, r0, sigma0, alpha, p, grow, decay):
    """First guess for chi: the better, by the length of the Newton step from each, of Vallado's guess and the
    parabolic (Barker) guess (a step that overflowed is never the better)."""
    vallado, barker = _vallado_guess(tau, r0, sigma0, alpha), _barker_guess(tau, sigma0, p)
    f_v, df_v, _ = _residual(vallado, tau, r0, sigma0, alpha, grow, decay)
    f_b, df_b, _ = _residual(barker, tau, r0, sigma0, alpha, grow, decay)
    with np.errstate(divide="ignore", invalid="ignore", over="ignore"):
        step_v, step_b = np.abs(f_v / df_v), np.abs(f_b / df_b)
    barker_better = np.isfinite(step_b) & ~(step_v <= step_b)
    return np.where(barker_better, barker, vallado)


def _fixed_step(x, lo, hi, tau, r0, sigma0, alpha, grow, decay):
    """One Halley step kept inside [lo, hi] (lo and hi first moved to x by the sign of F - tau): bisection, or
    doubling while hi is +inf, when the step leaves the bracket. Returns (x, lo, hi, |step|)."""
    f, df, d2f = _residual(x, tau, r0, sigma0, alpha, grow, decay)
    lo, hi = np.where(f < 0.0, x, lo), np.where(f > 0.0, x, hi)
    with np.errstate(all="ignore"):
        new = x - f / (df - 0.5 * f * d2f / df)
        inside = np.isfinite(new) & (lo <= new) & (new <= hi)
        fallback = np.where(hi < np.inf, 0.5 * (lo + hi), 2.0 * np.fmax(np.fmax(lo, x), 1e-300))
    new = np.where(inside, new, fallback)
    return new, lo, hi, np.abs(new - x)


def _polish(x, tau, r0, sigma0, alpha, grow, decay):
    """(x after one Newton step, the step): the last step of both passes."""
    f, df, _ = _residual(x, tau, r0, sigma0, alpha, grow, decay)
    with np.errstate(all="ignore"):
        step = f / df
        polished = x - step
    return np.where(np.isfinite(polished) & (f != 0), polished, x), step


def _solve_certified(tau, r0, sigma0, alpha, p, grow, decay):
    """Pass 1: (chi, certified) after FIXED_STEPS bracketed Halley steps from the starter and the polish."""
    x, lo, hi = _starter(tau, r0, sigma0, alpha, p, grow, decay), np.zeros_like(tau), np.full_like(tau, np.inf)
    for _ in range(FIXED_STEPS):
        x, lo, hi, last = _fixed_step(x, lo, hi, tau, r0, sigma0, alpha, grow, decay)
    chi, step = _polish(x, tau, r0, sigma0, alpha, grow, decay)
    return chi, (last <= 2.0**-26 * x) & (np.abs(step) <= 2.0**-40 * x)


def _solve_safeguarded(tau, r0, sigma0, alpha, p, grow, decay):
    """Pass 2: chi by Halley inside a bracket grown from tau / r0 until F(hi) >= tau, from the starter."""
    hi = np.maximum(tau / r0, 1e-300)
    for _ in range(BRACKET_DOUBLINGS):
        short = ~(_residual(hi, tau, r0, sigma0, alpha, grow, decay)[0] >= 0)
        if not np.any(short):
            break
        hi = np.where(short, 2.0 * hi, hi)
    lo = np.zeros_like(tau)
    start = np.clip(_starter(tau, r0, sigma0, alpha, p, grow, decay), lo, hi)

    def residual(chi, idx):
        return _residual(chi, tau[idx], r0[idx], sigma0[idx], alpha[idx], grow[idx], decay[idx])

    return halley_in_bracket(start, lo, hi, residual, "universal Kepler solve", {"dt": tau, "alpha": alpha})


def _solve_universal(tau, r0, sigma0, alpha, p, grow, decay):
    """chi >= 0 with r0 G1 + sigma0 G2 + G3 = tau >= 0 (scaled units, mu = 1; p = h**2): pass 1, then pass 2 on
    the states pass 1 leaves uncertified."""
    chi, certified = _solve_certified(tau, r0, sigma0, alpha, p, grow, decay)
    redo = ~certified
    if np.any(redo):
        chi[redo] = _solve_safeguarded(*(x[redo] for x in (tau, r0, sigma0, alpha, p, grow, decay)))
    return chi


def _reduce_by_periods(r0, v0, mu, dt):
    """(dt - k P with k = round(dt / P) on ellipses, unchanged on open orbits; alpha [1/m]; k; P), where
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
        return dt, alpha_si, np.zeros_like(dt), np.full_like(dt, np.nan)
    alpha = (np.where(bound, alpha[0], 1.0), np.where(bound, alpha[1], 0.0))
    n = _dd.mul(_dd.sqrt((mu, zero)), _dd.mul(alpha, _dd.sqrt(alpha)))
    period = _dd.div((TWO_PI_1 + zero, TWO_PI_2 + zero), n)
    turns = np.where(bound, np.rint(dt / period[0]), 0.0)
    p_hi, p_lo = _dd.two_product(turns, period[0])
    reduced = _dd.add((dt, zero), (-p_hi, -(p_lo + turns * period[1])))
    return reduced[0] + reduced[1], alpha_si, turns, np.where(bound, period[0], np.nan)


def propagate(r0: ArrayLike, v0: ArrayLike, mu: ArrayLike, dt: ArrayLike) -> tuple[np.ndarray, np.ndarray]:
    """State (r [m], v [m/s]) at t0 + dt [s] on the Kepler orbit through r0 [m], v0 [m/s] about mu [m**3/s**2].

    Accuracy against an mpmath reference on broad random sets drawn afresh each run, on the NumPy and the compiled
    path (tests/stability/test_propagate_sweep.py): in every class positions within 10 times the conditioning (the
    change of the exact state when each input moves by 2**-53 of itself) plus 2**-53, worst measured 6.6 times
    over samples of 2000 a class (40 times on flights grazing the focus or starting nearly radial, measured 16);
    that is at most 5.3e-15 of |r| measured on ellipses (e up to 0.9, and 1 - e from 1e-6 to 0.1) over +-1000
    periods, 1.5e-14 on near-parabolic orbits (|1 - e| from 1e-12 to 1e-6, either side) and 1.3e-14 on
    hyperbolas (e - 1 up to 10), median 1e-16. Over 1000 periods at e = 0.99 the conditioning is
    along the track and reaches 1.5e-12 of |r| (worst measured 4.5e-13, 0.29 of it); velocities near apoapsis at
    1 - e = 1e-6 are as good as theirs (up to 1.8e-10, below 0.01 of it).
    Batches from orbits.core._fast.AUTO_MIN_BATCH states on run the compiled port of this algorithm (ORBITS_JIT
    decides).
    """
    if _fast.use(_batch_size(r0, v0, mu, dt), "twobody._fast_propagate.propagate"):
        result = _propagate_compiled(r0, v0, mu, dt)
        if result is not None:
            return result
    return _propagate_numpy(r0, v0, mu, dt)


def _batch_size(r0, v0, mu, dt):
    """Number of states the call propagates (0 if the shapes do not broadcast: the NumPy version then raises)."""
    try:
        shape = np.broadcast_shapes(np.shape(r0)[:-1], np.shape(v0)[:-1], np.shape(mu), np.shape(dt))
    except ValueError:
        return 0
    return int(np.prod(shape))


def _propagate_compiled(r0, v0, mu, dt):
    """propagate by the compiled kernel; None if the inputs need the NumPy version's checks to raise."""
    _fast.announce("_fast_propagate")
    from orbits.core.twobody import _fast_propagate

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
    return _fast.kernel_array(x)


def _lagrange(chi, r0, sigma0, alpha, grow, decay):
    """(r, f, g, f', g') at chi: f = 1 - G2 / r0, g = r0 G1 + sigma0 G2, f' = -G1 / (r r0), g' = 1 - G2 / r with
    r = r0 G0 + sigma0 G1 + G2. Where alpha chi**2 < -1, r = (e cosh H - 1) / beta and
    g = e sinh H / beta**1.5 - (sigma0 + G1) / beta instead, each where its terms are the smaller (as in
    _anomaly_form, but judged for r and g on their own: far out on a long flight F is better summed in H, g not)."""
    g0, g1, g2, _ = _g_functions(chi, alpha)
    e_sinh, e_cosh = _hyperbolic_terms(chi, alpha, grow, decay)
    inverse, _, inverse_15 = _inverse_powers(alpha)
    with np.errstate(over="ignore", invalid="ignore", divide="ignore"):
        possible = alpha * chi * chi < -1.0
        r_terms, r_terms_h = np.abs(r0 * g0) + np.abs(sigma0 * g1) + np.abs(g2), (np.abs(e_cosh) + 1.0) * inverse
        g_terms = np.abs(r0 * g1) + np.abs(sigma0 * g2)
        g_terms_h = np.abs(e_sinh) * inverse_15 + (np.abs(sigma0) + np.abs(g1)) * inverse
        r = np.where(possible & (r_terms_h < r_terms), (e_cosh - 1.0) * inverse, r0 * g0 + sigma0 * g1 + g2)
        g = np.where(possible & (g_terms_h < g_terms), e_sinh * inverse_15 - (sigma0 + g1) * inverse,
                     r0 * g1 + sigma0 * g2)
    return r, 1.0 - g2 / r0, g, -g1 / (r * r0), 1.0 - g2 / r


def _elliptic_setup(r0, v0, mu, dt):
    """The elliptic pass's problem, state by state: (A, ec, es, m, m_lo, n, back, eligible).

    A = |r0| / a = 2 - |r0| |v0|**2 / mu, (ec, es) = (e cos E0, e sin E0) = (1 - A, back (r0 . v0) sqrt(1 / (a mu))),
    n = sqrt(mu / a**3) the mean motion and m + m_lo = |n dt| reduced modulo 2 pi, in [0, pi]; back = -1 where the
    reduced n dt is negative (the state then runs forward with -v0, as in the universal passes). A, 1 / a, n,
    n dt and es are formed in double-double arithmetic: A loses log2(1 / A) bits to cancellation near periapsis
    as e -> 1, n rounded in float64 would be a phase error of 6e-14 after 100 periods, and near e = 1 the solve
    magnifies the rounding of es several times. eligible: a bound orbit whose n**2 is clear of the subnormal
    range and whose n dt is reduced exactly.
    """
    with np.errstate(all="ignore"):  # open orbits: NaN mean motion, not eligible
        A, alpha, n_squared, n, M, es = _conic_terms(r0, v0, mu, dt, bound=True)
        eligible = (alpha[0] > 0) & (n_squared[0] >= SMALLEST_MEAN_MOTION_SQUARED) & (np.abs(M[0]) <= MAX_MEAN_ANOMALY)
        hi, lo = reduce_two_pi(np.where(eligible, M[0], 0.0), np.where(eligible, M[1], 0.0))
        back = np.where(hi < 0, -1.0, 1.0)
    return A[0] + A[1], (1.0 - A[0]) - A[1], back * es, back * hi, back * lo, n[0] + n[1], back, eligible


def _conic_terms(r0, v0, mu, dt, bound):
    """What the elliptic and hyperbolic passes both set up, in double-double arithmetic: (A, k, n**2, n, M, s) with
    A = |r0| / |a| (2 - |r0| |v0|**2 / mu for a bound orbit, its negative for an open one), k = A / |r0| = 1 / |a|,
    n**2 = mu k**3, M = n dt (double-double pairs) and s = (r0 . v0) sqrt(k / mu) (float64). NaN where the orbit
    is of the other kind; call under np.errstate(all="ignore")."""
    zero = np.zeros_like(dt)
    r = _dd.sqrt(_dd.dot(r0, r0))
    w = _dd.div(_dd.mul(r, _dd.dot(v0, v0)), (mu, zero))  # |r0| |v0|**2 / mu
    A = _dd.add((2.0 + zero, zero), (-w[0], -w[1])) if bound else _dd.add(w, (-2.0 + zero, zero))
    k = _dd.div(A, r)
    n_squared = _dd.mul(_dd.mul(_dd.mul(k, k), k), (mu, zero))
    n = _dd.sqrt(n_squared)
    M = _dd.mul(n, (dt, zero))
    s = _dd.mul(_dd.dot(r0, v0), _dd.sqrt(_dd.div(k, (mu, zero))))
    return A, k, n_squared, n, M, s[0] + s[1]


def _trig_terms(x):
    """(sin x, x - sin x, 1 - cos x as hi + lo) for x in [0, pi + 2], free of cancellation, from one evaluation of
    two series in z = x below SERIES_LIMIT, else in z = pi - x (|z| < 2): z - sin z = z**3 P(z**2) and 1 - cos z =
    z**2 / 2 + z**4 Q(z**2) from the exact z**2, so that lo carries what the rounding of z**2 / 2 drops (as
    hyperbolic_functions does for cosh x - 1). Reflected: sin x = sin z, 1 - cos x = 2 - (1 - cos z) (lo = 0)."""
    x = np.asarray(x, dtype=float)
    reflect = x >= SERIES_LIMIT
    z = np.where(reflect, (PI_1 - x) + PI_2, x)
    square, square_lo = _dd.two_product(z, z)
    z_minus_sin = square * z * horner(X_MINUS_SIN, square)
    hi, lo = _dd.two_sum(0.5 * square, 0.5 * square_lo + square * square * horner(ONE_MINUS_COS[:-1], square))
    sin = z - z_minus_sin
    return sin, np.where(reflect, x - sin, z_minus_sin), np.where(reflect, 2.0 - hi, hi), np.where(reflect, 0.0, lo)


def _elliptic_residual(x, A, ec, es, m, m_lo):
    """(F - m, F', F'', sin x, x - sin x, 1 - cos x) of
        F(x) = A x + ec (x - sin x) + es (1 - cos x) = M(E0 + x) - M(E0),
    the mean anomaly swept as the eccentric anomaly advances by x (the universal Kepler equation in x =
    chi / sqrt(a), times n). Free of cancellation in its terms (_trig_terms), and summed with exact products: on
    the way in to periapsis near e = 1, A x and es (1 - cos x) cancel (as in the hyperbolic pass). F' = r / a > 0,
    so the root is unique."""
    sin, x_minus_sin, one_minus_cos, one_minus_cos_lo = _trig_terms(x)
    p1, e1 = _dd.two_product(A, x)
    p2, e2 = _dd.two_product(es, one_minus_cos)
    s, t = _dd.two_sum(p1, p2)
    s, u = _dd.two_sum(s, -m)
    f = s + ((t + u) + (((e1 + e2) + es * one_minus_cos_lo) - m_lo) + ec * x_minus_sin)
    df = _elliptic_radius(A, ec, es, x, sin, x_minus_sin, one_minus_cos)
    d2f = ec * sin + es * (1.0 - one_minus_cos)
    return f, df, d2f, sin, x_minus_sin, one_minus_cos


def _elliptic_radius(A, ec, es, x, sin, x_minus_sin, one_minus_cos):
    """r / a = F' = A + ec (1 - cos x) + es sin x, with es sin x = es x - es (x - sin x) and es x exact below
    SERIES_LIMIT."""
    p, e = _dd.two_product(es, x)
    return np.where(x < SERIES_LIMIT, (A + p) + ((e - es * x_minus_sin) + ec * one_minus_cos),
                    (A + ec * one_minus_cos) + es * sin)


def _elliptic_starter(A, ec, es, m):
    """(starter, lo, hi) for the root x of F(x) = m in [lo, hi] = [m - 2 e, m + 2 e] (|F(x) - x| <= 2 e), lo >= 0:
    the local starter where its Newton step, estimated from the cubic and quartic terms it leaves out, is below
    LOCAL_STARTER_STEP, else Markley's.

    Markley's: E1 = kepler.markley_starter(M0 + m, e) - E0, with E0 = atan2(es, ec) and M0 = E0 - es; within
    about 1e-3 rad, so it fails short flights (x below 1e-3). The local one: the root x_l of the quadratic model
    A x + es x**2 / 2 = m (2 m / A where it has none), good while x is small; F(x_l) - m = ec x_l**3 / 6 -
    es x_l**4 / 24 + ... over F'(x_l) ~ A + es x_l + ec x_l**2 / 2 estimates its Newton step. With the sixth-order
    step that follows (_solve_elliptic), this certified every one of 2e5 random (e, E0, m) with e up to 1 - 1e-9
    and flights from 1e-7 to 1e4 periods for thresholds from 1e-6 to 1e-4 (97 left at 1e-3)."""
    e = np.sqrt(ec * ec + es * es)
    E0 = np.arctan2(es, ec)
    M1 = (E0 - es) + m
    turns = np.rint(M1 / TWO_PI_1)
    M1 = M1 - turns * TWO_PI_1
    markley = np.copysign(markley_starter(np.abs(M1), np.minimum(e, 1.0)), M1) + turns * TWO_PI_1 - E0
    local = 2.0 * m / (A + np.sqrt(np.maximum(A * A + 2.0 * es * m, 0.0)))
    square = local * local
    left_out = np.abs(square * local * (ec / 6.0 - es * local / 24.0))
    local_good = left_out < LOCAL_STARTER_STEP * np.abs(A + es * local + 0.5 * ec * square)
    lo, hi = np.maximum(m - BRACKET_WIDTH * e, 0.0), m + BRACKET_WIDTH * e
    return np.clip(np.where(local_good, local, markley), lo, hi), lo, hi


def _solve_elliptic(A, ec, es, m, m_lo):
    """(x, sin x, x - sin x, 1 - cos x, certified) at the root x of F(x) = m + m_lo (_elliptic_residual): one
    sixth-order step from the starter (kepler.sixth_order_step; the third derivative of F is 1 - F', the fourth
    and fifth -F'' and F' - 1) kept in [lo, hi], one Newton step, certified when that step d is below
    ELLIPTIC_STEP x and its own error |F''| d**2 / (2 F') below ELLIPTIC_ERROR x / 2 (F' and F'' change by less
    than 1e-3 over the step, so the local estimate holds); the trigonometric terms then follow the Newton step to
    first order (the second-order terms, of the order of the step squared, are below 2**-52 of them)."""
    x, lo, hi = _elliptic_starter(A, ec, es, m)
    f, df, d2f, *_ = _elliptic_residual(x, A, ec, es, m, m_lo)
    x = np.clip(x + sixth_order_step(f, df, d2f, 1.0 - df, -1.0)[0], lo, hi)
    f, df, d2f, sin, x_minus_sin, one_minus_cos = _elliptic_residual(x, A, ec, es, m, m_lo)
    step = f / df
    certified = (np.abs(step) <= ELLIPTIC_STEP * (x - step)) & (
        np.abs(d2f) * step * step <= ELLIPTIC_ERROR * np.abs(df) * (x - step))
    sin, x_minus_sin, one_minus_cos = (sin - step * (1.0 - one_minus_cos), x_minus_sin - step * one_minus_cos,
                                       one_minus_cos - step * sin)
    return x - step, sin, x_minus_sin, one_minus_cos, certified


def _elliptic_lagrange(A, ec, es, n, back, x, sin, x_minus_sin, one_minus_cos):
    """(f, g, f', g') of r = f r0 + g v0, v = f' r0 + g' v0 at the root x, with r / a = F'(x) (_elliptic_radius):
    f = 1 - (1 - cos x) / A, g = back (A sin x + es (1 - cos x)) / n, f' = -back n sin x / (A r / a), g' = 1 -
    (1 - cos x) / (r / a) (the universal f and g with G1 = sin x sqrt(a), G2 = a (1 - cos x)); below
    SERIES_LIMIT, A sin x = A x - A (x - sin x) and the products A x and es (1 - cos x) exact, since they cancel
    near e = 1 on the way in."""
    r_over_a = _elliptic_radius(A, ec, es, x, sin, x_minus_sin, one_minus_cos)
    p1, e1 = _dd.two_product(A, x)
    p2, e2 = _dd.two_product(es, one_minus_cos)
    g = np.where(x < SERIES_LIMIT, (p1 + p2) + ((e1 + e2) - A * x_minus_sin), A * sin + es * one_minus_cos)
    return (1.0 - one_minus_cos / A, back * g / n, -back * n * sin / (A * r_over_a), 1.0 - one_minus_cos / r_over_a)


def _elliptic_pass(r0, v0, mu, dt):
    """(r, v, certified): the elliptic pass on flat (n, 3) r0, v0 and (n,) mu, dt; the states it does not certify
    (open orbits, and any whose solve it cannot vouch for) have meaningless r, v."""
    A, ec, es, m, m_lo, n, back, eligible = _elliptic_setup(r0, v0, mu, dt)
    with np.errstate(all="ignore"):
        x, sin, x_minus_sin, one_minus_cos, certified = _solve_elliptic(A, ec, es, m, m_lo)
        f, g, f_dot, g_dot = _elliptic_lagrange(A, ec, es, n, back, x, sin, x_minus_sin, one_minus_cos)
        r = f[:, None] * r0 + g[:, None] * v0
        v = f_dot[:, None] * r0 + g_dot[:, None] * v0
    return r, v, certified & eligible


# --- the hyperbolic pass -------------------------------------------------------------------------------------------


def _hyperbolic_setup(r0, v0, mu, dt):
    """The hyperbolic pass's problem, state by state: (A, ec, es, m, m_lo, n, back, eligible).

    With beta = -alpha = 1 / |a| and H0 the hyperbolic anomaly at t0: A = beta |r0| = |r0| |v0|**2 / mu - 2,
    (ec, es) = (e cosh H0, e sinh H0) = (1 + A, back (r0 . v0) sqrt(beta / mu)), the mean motion
    n = sqrt(mu beta**3) and m + m_lo = |n dt| (back = -1 where dt < 0: the state then runs forward with -v0).
    A, beta, n and n dt are formed in double-double arithmetic (A cancels near e = 1). eligible: an open orbit
    whose n**2 is clear of the subnormal range (not an exact parabola) and whose n dt is finite.
    """
    with np.errstate(all="ignore"):  # bound orbits: NaN mean motion, not eligible
        A, beta, n_squared, n, M, es = _conic_terms(r0, v0, mu, dt, bound=False)
        eligible = (beta[0] > 0) & (n_squared[0] >= SMALLEST_MEAN_MOTION_SQUARED) & np.isfinite(M[0])
        back = np.where(M[0] < 0, -1.0, 1.0)
        ec = (1.0 + A[0]) + A[1]
    return A[0] + A[1], ec, back * es, back * M[0], back * M[1], n[0] + n[1], back, eligible


def _hyperbolic_exponentials(r0, v0, mu, A, ec, es):
    """(grow, decay, P): e exp(+-H0) = ec +- es, the one that cancels (decay on the way out, grow on the way in)
    from grow decay = e**2 = 1 + P, P = e**2 - 1 = beta h**2 / mu, beta = A / |r0|."""
    with np.errstate(all="ignore"):
        h = np.cross(r0, v0)
        P = A / np.sqrt(np.sum(r0 * r0, axis=-1)) * np.sum(h * h, axis=-1) / mu
        larger = ec + np.abs(es)
        smaller = (1.0 + P) / larger
    return np.where(es < 0, smaller, larger), np.where(es < 0, larger, smaller), P


def hyperbolic_functions(x: ArrayLike) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    """(sinh x - x, cosh x - 1 as hi + lo, exp x, exp -x) for x >= 0, free of cancellation: series below
    SERIES_LIMIT (cosh x - 1 = x**2 / 2 + x**4 Q(x**2) with x**2 exact, so that its low part carries what the
    rounding of x**2 / 2 drops), from exp x beyond (where cosh x >= 3.7, so cosh x - 1 loses under half a bit; lo
    = 0). The series region gives exp x = 1 + sinh x + (cosh x - 1); exp x is inf beyond about 709."""
    x = np.asarray(x, dtype=float)
    small = x < SERIES_LIMIT
    square, square_lo = _dd.two_product(x, x)
    series_shm = square * x * horner(SINH_MINUS_X, square)
    series_chm, series_lo = _dd.two_sum(0.5 * square, 0.5 * square_lo + square * square * horner(COSH_MINUS_ONE[:-1],
                                                                                                 square))
    with np.errstate(over="ignore", invalid="ignore"):
        exp = np.where(small, 1.0 + ((x + series_shm) + series_chm), np.exp(x))
        inverse = 1.0 / exp
        shm = np.where(small, series_shm, 0.5 * (exp - inverse) - x)
        chm = np.where(small, series_chm, 0.5 * (exp + inverse) - 1.0)
    return shm, chm, np.where(small, series_lo, 0.0), exp, inverse


def _hyperbolic_residual(x, A, ec, es, grow, decay, m, m_lo):
    """(F - m, F', F'', terms) of the hyperbolic pass's equation in x = H - H0 >= 0, the universal Kepler
    equation in x = sqrt(beta) chi times n:
        F(x) = A x + ec (sinh x - x) + es (cosh x - 1) = M(H0 + x) - M(H0),   F' = r / |a| > 0,
    summed with exact products (A x and es (cosh x - 1) cancel on the way in to periapsis near e = 1: rounded, they
    cost up to 4x the input's conditioning), or, where x > 1 and its terms are the smaller, in the anomaly form
        F = (grow (exp x - 1) + decay (1 - exp -x)) / 2 - x
    (far out on the way in, where the first form cancels). `terms` = (sinh x - x, cosh x - 1, exp x, exp -x),
    to build f and g."""
    shm, chm, chm_lo, exp, inverse = hyperbolic_functions(x)
    with np.errstate(over="ignore", invalid="ignore"):
        p1, e1 = _dd.two_product(A, x)
        p2, e2 = _dd.two_product(es, chm)
        s, t = _dd.two_sum(p1, p2)
        s, u = _dd.two_sum(s, -m)
        near = s + ((t + u) + (((e1 + e2) + es * chm_lo) - m_lo) + ec * shm)
        near_terms = np.abs(p1) + np.abs(p2) + np.abs(ec * shm)
        far_sum = 0.5 * (grow * (exp - 1.0) + decay * (1.0 - inverse))
        far = (x > 1.0) & (far_sum + x < near_terms)
        f = np.where(far, ((far_sum - x) - m) - m_lo, near)
        df = _open_radius(A, ec, es, grow, decay, x, shm, chm, exp, inverse)
        d2f = 0.5 * (grow * exp - decay * inverse)
    return np.where(np.isfinite(f), f, np.inf), df, d2f, (shm, chm, exp, inverse)


def _open_radius(A, ec, es, grow, decay, x, shm, chm, exp, inverse):
    """r / |a| = F' = A + ec (cosh x - 1) + es sinh x, or (grow exp x + decay exp -x) / 2 - 1 where x > 1 and
    its terms are the smaller (far out, where es sinh x cancels ec (cosh x - 1)); es x exactly."""
    p, e = _dd.two_product(es, x)
    near = (A + p) + ((e + es * shm) + ec * chm)
    far_terms = 0.5 * (grow * exp + decay * inverse)
    far = (x > 1.0) & (far_terms + 1.0 < A + np.abs(ec * chm) + np.abs(es) * (x + shm))
    return np.where(far, far_terms - 1.0, near)


def _hyperbolic_starters(A, es, grow, P, m):
    """(the logarithmic starter, the parabolic starter, hi) for the root x of F(x) = m in [0, hi], hi = m / (e - 1)
    (F' = r / |a| >= q / |a| = e - 1, e - 1 = P / (1 + e)).

    The logarithmic one (Vallado's guess in x): F ~ grow exp(x) / 2 for large x, so x = log(2 m / grow)
    where that is positive, else the root of the quadratic model A x + es x**2 / 2 = m (2 m / A where it has
    none). The parabolic one: x on the parabola with the same p and r0 . v0 (Barker's equation),
    sqrt(P) (D - D0), D + D**3 / 3 = D0 + D0**3 / 3 + 2 m / P**1.5, D0 = es / sqrt(P)."""
    with np.errstate(all="ignore"):
        hi = m * (1.0 + np.sqrt(1.0 + P)) / P
        log_guess = np.log(2.0 * m / grow)
        local = 2.0 * m / (A + np.sqrt(np.maximum(A * A + 2.0 * es * m, 0.0)))
        first = np.where(log_guess > 0.0, log_guess, local)
        root_p = np.sqrt(P)
        d0 = es / root_p
        w = d0 + d0 * d0 * d0 / 3.0 + 2.0 * m / (P * root_p)
        c = np.cbrt(1.5 * np.abs(w) + np.sqrt(2.25 * w * w + 1.0))
        barker = root_p * (np.copysign(c - 1.0 / c, w) - d0)
        barker = np.where(np.isfinite(barker), barker, first)
    return np.clip(first, 0.0, hi), np.clip(barker, 0.0, hi), hi


def _solve_hyperbolic(A, ec, es, grow, decay, P, m, m_lo):
    """(x, the terms at x, r / |a| at x, certified): the better starter by Newton step length, HYPERBOLIC_STEPS
    sixth-order steps (kepler.sixth_order_step; the third derivative of F is F' + 1, the fourth and fifth F'' and
    F' + 1) kept in [lo, hi] (bisection when a step leaves it), one Newton step, certified as the elliptic pass's
    (ELLIPTIC_STEP, ELLIPTIC_ERROR); the terms then follow the Newton step to first order. Two sixth-order steps
    leave none of the benchmark's 99798 open states and 0.1 % of 1e5 random hyperbolas (e - 1 from 1e-6 to 10,
    flights to 1e4 sqrt(p**3 / mu)) uncertified (three Halley steps: none and 0.04 %, at one more evaluation)."""
    coefficients = (A, ec, es, grow, decay, m, m_lo)
    first, barker, hi = _hyperbolic_starters(A, es, grow, P, m)
    f_1, df_1, d2f_1, _ = _hyperbolic_residual(first, *coefficients)
    f_b, df_b, d2f_b, _ = _hyperbolic_residual(barker, *coefficients)
    with np.errstate(all="ignore"):
        barker_better = np.isfinite(f_b / df_b) & ~(np.abs(f_1 / df_1) <= np.abs(f_b / df_b))
    x = np.where(barker_better, barker, first)
    f, df, d2f = (np.where(barker_better, a, b) for a, b in ((f_b, f_1), (df_b, df_1), (d2f_b, d2f_1)))
    lo = np.zeros_like(x)
    for step in range(HYPERBOLIC_STEPS):
        if step:
            f, df, d2f, _ = _hyperbolic_residual(x, *coefficients)
        lo, hi = np.where(f < 0, x, lo), np.where(f > 0, x, hi)
        with np.errstate(all="ignore"):
            new = x + sixth_order_step(f, df, d2f, df + 1.0, 1.0)[0]
        x = np.where(np.isfinite(new) & (lo <= new) & (new <= hi), new, 0.5 * (lo + hi))
    f, df, d2f, (shm, chm, exp, inverse) = _hyperbolic_residual(x, *coefficients)
    with np.errstate(all="ignore"):
        step = f / df
        certified = (np.abs(step) <= ELLIPTIC_STEP * x) & (np.abs(d2f) * step * step <= ELLIPTIC_ERROR * df * x)
        shm, chm = shm - step * chm, chm - step * (x + shm)
        x = x - step
        exp, inverse = exp * (1.0 - step), inverse * (1.0 + step)
        r_over_a = _open_radius(A, ec, es, grow, decay, x, shm, chm, exp, inverse)
    return x, (shm, chm, exp, inverse), r_over_a, certified


def _hyperbolic_lagrange(A, es, grow, decay, m, n, back, x, terms, r_over_a):
    """(f, g, f', g') at the root x: f = 1 - (cosh x - 1) / A, g = back (A sinh x + es (cosh x - 1)) / n, or
    back ((grow (exp x - 1) + decay (1 - exp -x)) / 2 - sinh x) / n where x > 1 and its terms are the smaller
    (far out on the way in), f' = -back n sinh x / (A r / |a|), g' = 1 - (cosh x - 1) / (r / |a|) (the universal
    f and g with G1 = sinh x / sqrt(beta), G2 = (cosh x - 1) / beta)."""
    shm, chm, exp, inverse = terms
    sinh = x + shm
    with np.errstate(all="ignore"):
        p1, e1 = _dd.two_product(A, x)
        p2, e2 = _dd.two_product(es, chm)
        near = (p1 + p2) + ((e1 + e2) + A * shm)
        far_sum = 0.5 * (grow * (exp - 1.0) + decay * (1.0 - inverse))
        far = (x > 1.0) & (far_sum + sinh < np.abs(p1) + np.abs(p2))
        g = np.where(far, far_sum - sinh, near)
        return 1.0 - chm / A, back * g / n, -back * n * sinh / (A * r_over_a), 1.0 - chm / r_over_a


def _hyperbolic_pass(r0, v0, mu, dt):
    """(r, v, certified): the hyperbolic pass on flat (n, 3) r0, v0 and (n,) mu, dt of open orbits; the states
    it does not certify (exact parabolas, and any whose solve it cannot vouch for) have meaningless r, v."""
    A, ec, es, m, m_lo, n, back, eligible = _hyperbolic_setup(r0, v0, mu, dt)
    grow, decay, P = _hyperbolic_exponentials(r0, v0, mu, A, ec, es)
    with np.errstate(all="ignore"):
        x, terms, r_over_a, certified = _solve_hyperbolic(A, ec, es, grow, decay, P, m, m_lo)
        f, g, f_dot, g_dot = _hyperbolic_lagrange(A, es, grow, decay, m, n, back, x, terms, r_over_a)
        r = f[:, None] * r0 + g[:, None] * v0
        v = f_dot[:, None] * r0 + g_dot[:, None] * v0
    return r, v, certified & eligible


def _propagate_numpy(r0, v0, mu, dt):
    """propagate in NumPy: the elliptic pass on the bound states, the hyperbolic pass on the open ones, the
    universal passes on what they leave."""
    r0, v0, mu = check_state(r0, v0, mu)
    dt = np.asarray(dt, dtype=float)
    check_finite(dt, "time step dt", "s")
    batch = broadcast_shape(**{"r0, v0 and mu": mu.shape, "dt": dt.shape})
    r0, v0 = np.broadcast_to(r0, batch + (3,)).reshape(-1, 3), np.broadcast_to(v0, batch + (3,)).reshape(-1, 3)
    mu, dt = np.broadcast_to(mu, batch).reshape(-1), np.broadcast_to(dt, batch).reshape(-1)
    h = np.cross(r0, v0)
    if np.any(np.sum(h * h, axis=-1) == 0):
        raise DegenerateOrbitError(
            "the state is radial (r x v = 0): the propagator does not regularise the collision with "
            "the primary; give the orbit a non-zero angular momentum"
        )
    r, v, done = np.empty_like(r0), np.empty_like(v0), np.zeros(dt.shape, dtype=bool)
    for states, conic_pass in ((~_open(r0, v0, mu), _elliptic_pass), (_open(r0, v0, mu), _hyperbolic_pass)):
        if np.any(states):
            r[states], v[states], done[states] = conic_pass(r0[states], v0[states], mu[states], dt[states])
    rest = ~done
    if np.any(rest):
        r[rest], v[rest] = _universal_passes(r0[rest], v0[rest], mu[rest], dt[rest])
    return r.reshape(batch + (3,)), v.reshape(batch + (3,))


def _open(r0, v0, mu):
    """Whether each state is open, |r0| |v0|**2 > 2 mu in float64: which pass it goes to (a pass refuses a state
    on the wrong side by its double-double alpha, and leaves it to the universal passes)."""
    return np.sqrt(np.sum(r0 * r0, axis=-1)) * np.sum(v0 * v0, axis=-1) > 2.0 * mu


class Scaled(NamedTuple):
    """The universal passes' problem, flat arrays over the states: SI scales (length = |r0| [m], speed = sqrt(mu /
    |r0|) [m/s]), the scaled state x = r0 / length, w = v0 / speed (w negated where the flight runs backwards),
    tau = |reduced dt| speed / length, r0 = |x|, sigma0 = x . w, alpha = 2 / r0 - |w|**2 (from double-double
    arithmetic), p = |x x w|**2, the hyperbolic coefficients (grow, decay), backwards, the reduced dt [s], and
    the whole periods `turns` taken off it, of length `period` [s] (0 and NaN on open orbits)."""

    length: np.ndarray
    speed: np.ndarray
    x: np.ndarray
    w: np.ndarray
    tau: np.ndarray
    r0: np.ndarray
    sigma0: np.ndarray
    alpha: np.ndarray
    p: np.ndarray
    grow: np.ndarray
    decay: np.ndarray
    backwards: np.ndarray
    dt: np.ndarray
    turns: np.ndarray
    period: np.ndarray


def scaled_problem(r0: np.ndarray, v0: np.ndarray, mu: np.ndarray, dt: np.ndarray) -> Scaled:
    """The Scaled problem of flat (n, 3) r0 [m], v0 [m/s] and (n,) mu [m**3/s**2], dt [s] (checked by the caller)."""
    dt, alpha_si, turns, period = _reduce_by_periods(r0, v0, mu, dt)
    length = np.sqrt(np.sum(r0 * r0, axis=-1))
    speed = np.sqrt(mu / length)
    x, w, tau = r0 / length[..., None], v0 / speed[..., None], dt * speed / length
    r_scaled = np.sqrt(np.sum(x * x, axis=-1))
    alpha = alpha_si * length
    backwards = np.signbit(tau)
    w = np.where(backwards[..., None], -w, w)
    tau = np.abs(tau)
    sigma0 = np.sum(x * w, axis=-1)
    h_scaled = np.cross(x, w)
    p = np.sum(h_scaled * h_scaled, axis=-1)
    grow, decay = _hyperbolic_coefficients(r_scaled, sigma0, alpha, p)
    return Scaled(length, speed, x, w, tau, r_scaled, sigma0, alpha, p, grow, decay, backwards, dt, turns, period)


def universal_anomaly(s: Scaled) -> np.ndarray:
    """chi >= 0 with r0 G1 + sigma0 G2 + G3 = tau for the Scaled problem s (pass 1, then pass 2 where needed)."""
    return _solve_universal(s.tau, s.r0, s.sigma0, s.alpha, s.p, s.grow, s.decay)


def _universal_passes(r0, v0, mu, dt):
    """(r, v) by the universal-variable passes, for flat (n, 3) r0, v0 and (n,) mu, dt."""
    s = scaled_problem(r0, v0, mu, dt)
    chi = universal_anomaly(s)
    r_new, f, g, f_dot, g_dot = _lagrange(chi, s.r0, s.sigma0, s.alpha, s.grow, s.decay)
    x_new = f[..., None] * s.x + g[..., None] * s.w
    w_new = f_dot[..., None] * s.x + g_dot[..., None] * s.w
    w_new = np.where(s.backwards[..., None], -w_new, w_new)
    r, v = x_new * s.length[..., None], w_new * s.speed[..., None]
    return np.where(s.dt[..., None] == 0, r0, r), np.where(s.dt[..., None] == 0, v0, v)  # dt = 0: exactly r0, v0
