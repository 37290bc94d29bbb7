"""Kepler's equation for every conic, solved to the last bits of float64.

Elliptic   ``M = E - e sin E``          (0 <= e < 1), E returned in [-pi, pi]
Hyperbolic ``M = e sinh H - H``         (e > 1)
Parabolic  ``W = D + D**3 / 3``          (Barker, D = tan(nu / 2)), closed form

All functions take float64 arrays (or scalars) and broadcast. Accuracy (tests/core/test_kepler.py,
against mpmath at 50 digits): E within 4 ulp of the true root of the reduced equation for every
0 <= e <= 1 - 2**-53 and |M| <= MAX_MEAN_ANOMALY; H within 4 ulp for 1 < e <= 1e12, |M| <= 1e300.

How the accuracy is reached:
- M is reduced modulo 2 pi in triple-double arithmetic (exact products by Veltkamp splitting), so the
  reduced M keeps its low-order bits even for |M| = 1e12.
- The residual is evaluated without cancellation: E - e sin E = (1 - e) E + e (E - sin E), where
  1 - e is exact for e >= 1/2 and E - sin E comes from its Taylor series for |E| < 2; likewise
  e sinh H - H = (e - 1) H + e (sinh H - H). Large H use the logarithmic form of the equation.
- Two passes, the same in NumPy and in the compiled kernels. For E, a single pass: Markley's starter (within
  2.8e-4 relative for every e < 1), one evaluation of sin E, E - sin E and 1 - cos E (trig_reflected), and one
  sixth-order step from the residual's derivatives (sixth_order_step), certified by the size of its Newton step;
  for H (series form), two bracketed sixth-order steps and a Newton polish, certified likewise. The safeguarded
  pass, on what the first leaves: from the root of the cubic model (1 - e) E + e E**3 / 6 = M (found without
  cancellation), Halley's method inside a shrinking bracket, so it cannot diverge; a solve that does not
  converge raises ConvergenceError.

Speed: the three solvers run compiled kernels (orbits/core/twobody/_fast_kepler.py, numba, cached on disk) when
numba is installed, with the same reduction, residuals and safeguards; these NumPy implementations run
otherwise (ORBITS_JIT=0, see orbits.core._fast) and re-run any batch the kernels flag, so that invalid
input raises the same messages. Both are within 4 ulp of mpmath (tests/core/test_fast_kepler.py); timings
are in the README's Benchmarks section.
"""

import numpy as np
from numpy.typing import ArrayLike

from orbits.core import _fast
from orbits.core._dd import two_product, two_sum
from orbits.core._roots import halley_in_bracket
from orbits.core.checks import broadcast, check_eccentricity, check_finite
from orbits.core.errors import OrbitDomainError
from orbits.core.series import horner
from orbits.core.twobody._kepler_shared import (
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

_OTHER_CONICS = "; use eccentric_anomaly for e < 1, parabolic_anomaly (Barker) for e = 1, hyperbolic_anomaly for e > 1"


def _series(x, coefficients):
    """x**3 * P(x**2) for the series P with the given coefficients."""
    x2 = x * x
    return horner(coefficients, x2) * x2 * x


def x_minus_sin(x: ArrayLike) -> np.ndarray:
    """x - sin x without cancellation (series for |x| < 2), float64 arrays."""
    x = np.asarray(x, dtype=float)
    return np.where(np.abs(x) < SERIES_LIMIT, _series(x, X_MINUS_SIN), x - np.sin(x))


def sinh_minus_x(x: ArrayLike) -> np.ndarray:
    """sinh x - x without cancellation (series for |x| < 2), float64 arrays."""
    x = np.asarray(x, dtype=float)
    small = np.abs(x) < SERIES_LIMIT
    with np.errstate(over="ignore"):
        large = np.sinh(np.where(small, 0.0, x)) - x
    return np.where(small, _series(x, SINH_MINUS_X), large)


def reduce_mean_anomaly(M: ArrayLike) -> tuple[float | np.ndarray, float | np.ndarray]:
    """Reduce M (rad) to M - 2 pi k in [-pi, pi], k = round(M / 2 pi), as a double-double (hi, lo).

    Exact to about 2**-100 relative for |M| <= MAX_MEAN_ANOMALY; larger |M| raise OrbitDomainError.
    """
    M = np.asarray(M, dtype=float)
    check_finite(M, "mean anomaly M", "rad")
    too_large = np.abs(M) > MAX_MEAN_ANOMALY
    if np.any(too_large):
        bad = M[too_large].flat[0]
        raise OrbitDomainError(
            f"mean anomaly M = {float(bad)!r} rad is too large for an exact reduction modulo 2 pi; "
            f"allowed |M| <= {MAX_MEAN_ANOMALY:.6g} rad (2**50 revolutions)"
        )
    return reduce_two_pi(M, 0.0)


def reduce_two_pi(M: ArrayLike, M_lo: ArrayLike) -> tuple[float | np.ndarray, float | np.ndarray]:
    """(hi, lo) = M + M_lo - 2 pi k in [-pi, pi] as a double-double, k = round(M / 2 pi), for a double-double
    M + M_lo (|M_lo| <= ulp(M)) with |M| <= MAX_MEAN_ANOMALY (unchecked): 2 pi in three parts and exact
    products (two_product), so the result keeps about 2**-100 of |M|."""
    k = np.rint(M * INVERSE_TWO_PI)  # a multiplication (the kernels' divisions cost); k off by one at +-pi is
    p1, e1 = two_product(k, TWO_PI_1)  # shifted back below
    p2, e2 = two_product(k, TWO_PI_2)
    hi = M - p1  # exact (Sterbenz) since p1 is within a factor 2 of M whenever k != 0
    hi, lo = two_sum(hi, -e1)
    hi, t = two_sum(hi, -p2)
    lo = lo + t - e2 - k * TWO_PI_3 + M_lo
    hi, lo = two_sum(hi, lo)
    # Rounding of k can leave the result a few ulp outside [-pi, pi]: shift it back by one turn.
    shift = np.where(hi > np.pi, -1.0, np.where(hi < -np.pi, 1.0, 0.0))
    hi, t = two_sum(hi + shift * TWO_PI_1, shift * TWO_PI_2)  # hi +/- 2 pi_1 is exact (Sterbenz)
    return two_sum(hi, lo + t)


def markley_starter(m: ArrayLike, e: ArrayLike) -> np.ndarray:
    """Markley's (1995, Celest. Mech. 63, 101) starter for E in [0, pi] from M = m in [0, pi], 0 <= e <= 1:
    sin E replaced by a Pade approximant, whose cubic is solved in closed form. Within 2.7e-4 relative
    (Markley) on e <= 0.99, so one Halley step and one Newton step reach the root (the compiled elliptic
    solver's pass 1, and the elliptic pass of orbits.core.twobody.propagate). Written with two divisions, as the
    kernels (orbits/core/twobody/_fast_kepler.py) compute it."""
    alpha = (3.0 * np.pi**2 + 1.6 * np.pi * (np.pi - m) / (1.0 + e)) * MARKLEY_SCALE
    d = 3.0 * (1.0 - e) + alpha * e
    q = 2.0 * alpha * d * (1.0 - e) - m * m
    r = 3.0 * alpha * d * (d - 1.0 + e) * m + m * m * m
    w = np.cbrt(np.abs(r) + np.sqrt(q * q * q + r * r)) ** 2
    denominator = w * w + w * q + q * q
    return (2.0 * r * w + m * denominator) / (denominator * d)


def _cubic_root(linear, cubic, rhs):
    """Positive root of linear * x + cubic * x**3 = rhs (linear, cubic, rhs >= 0), cancellation free.

    With p = linear / cubic and q = rhs / cubic, x = w - p / (3 w) for w**3 = q/2 + sqrt(q**2/4 + p**3/27),
    rewritten as x = q / (w**2 + p/3 + (p / (3 w))**2).
    """
    with np.errstate(all="ignore"):  # inf / 0 intermediates (e.g. subnormal e) are routed by np.where
        q = rhs / cubic
        # x = scale * y turns the cubic into y**3 + ps * y = 1.
        scale = np.where(np.isfinite(q), np.cbrt(q), np.cbrt(rhs) / np.cbrt(cubic))
        ps = (linear / cubic) / (scale * scale)
        linear_regime = ps > 1e30  # the cubic term changes x by less than 1e-60 relative
        ps = np.where(linear_regime, 1.0, ps)
        w = np.cbrt(0.5 + np.sqrt(0.25 + ps**3 / 27.0))
        v = ps / (3.0 * w)
        return np.where(linear_regime, rhs / linear, scale / (w * w + ps / 3.0 + v * v))


def eccentric_anomaly(M: ArrayLike, e: ArrayLike) -> float | np.ndarray:
    """Eccentric anomaly E in [-pi, pi] (rad) solving M = E - e sin E, for 0 <= e < 1 and any finite M.

    M is reduced modulo 2 pi first (exactly, see reduce_mean_anomaly); the result lies in the same
    revolution as the reduced M, so E(M + 2 pi) == E(M) and E(-M) == -E(M) exactly.
    Accuracy: within 4 ulp of the exact root for e <= 1 - 2**-53 (tests/core/test_kepler.py).
    """
    M, e = broadcast(M=M, e=e)
    if _fast.use(M.size, "twobody._fast_kepler.elliptic"):
        return _compiled("elliptic", _eccentric_anomaly_numpy, M, e)
    return _eccentric_anomaly_numpy(M, e)


def _compiled(kernel, numpy_version, *inputs):
    """Run the compiled kernel of that name; on invalid or unconverged input, the NumPy version (which raises)."""
    _fast.announce("_fast_kepler")
    from orbits.core.twobody import _fast_kepler

    flat = [_fast.kernel_array(x).reshape(-1) for x in inputs]
    out = np.empty_like(flat[0])
    if _fast.run(getattr(_fast_kepler, kernel), out.size, *flat, out):
        return numpy_version(*inputs)
    return out.reshape(inputs[0].shape)[()]


def _eccentric_anomaly_numpy(M, e):
    """eccentric_anomaly for broadcast float64 arrays, in NumPy."""
    check_eccentricity(e, 0.0, 1.0, False, True, "elliptic", _OTHER_CONICS)
    with np.errstate(under="ignore"):  # subnormal and zero results are legitimate
        m_hi, m_lo = reduce_mean_anomaly(M)
        sign = np.where(np.signbit(m_hi) | ((m_hi == 0) & np.signbit(M)), -1.0, 1.0)  # keeps -0.0
        return sign * _solve_elliptic_positive(np.abs(m_hi), sign * m_lo, e + 0.0)


def _solve_elliptic_positive(m_hi, m_lo, e):
    """E in [0, pi] for reduced M = m_hi + m_lo in [0, pi] (m_lo tiny): the single pass on every element, the
    safeguarded iteration on those it does not certify (as the compiled solver)."""
    one_minus_e = 1.0 - e
    E = np.where(e == 0.0, m_hi, 0.0)
    tiny = (m_hi < TINY_MEAN_ANOMALY) & (e > 0.0)
    E = np.where(tiny, m_hi / one_minus_e, E)
    solve = (e > 0.0) & ~tiny & (m_hi > 0.0)
    if not np.any(solve):
        return E
    m, m_lo, e, one_minus_e = m_hi[solve], m_lo[solve], e[solve], one_minus_e[solve]
    x, certified = _elliptic_single_pass(m, m_lo, e, one_minus_e)
    redo = np.flatnonzero(~certified)
    if redo.size:
        r = (m[redo], m_lo[redo], e[redo], one_minus_e[redo])
        upper = np.minimum(np.minimum(r[0] + r[2], np.pi), r[0] / r[3])  # E - M = e sin E in [0, e], E <= M / (1 - e)
        x[redo] = _elliptic_safeguarded(*r, upper)
    E[solve] = x
    return E


def trig_reflected(x: ArrayLike) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """(sin x, x - sin x, 1 - cos x) for x in [0, pi + 2], each free of cancellation, from one evaluation of two
    series: in z = x below 2, else in z = pi - x (|z| < 2), where sin x = sin z, 1 - cos x = 2 - (1 - cos z) and
    x - sin x has no cancellation. Each within about 1 ulp."""
    x = np.asarray(x, dtype=float)
    reflect = x >= SERIES_LIMIT
    z = np.where(reflect, (PI_1 - x) + PI_2, x)
    z2 = z * z
    z_minus_sin = horner(X_MINUS_SIN, z2) * z2 * z
    one_minus_cos = horner(ONE_MINUS_COS, z2) * z2
    sin = z - z_minus_sin
    return sin, np.where(reflect, x - sin, z_minus_sin), np.where(reflect, 2.0 - one_minus_cos, one_minus_cos)


def sixth_order_step(f, f1, s, c, sign):
    """(d, t): the root d of the Taylor polynomial f + f1 d + s d**2 / 2 + c d**3 / 6 + sign (s d**4 / 24 +
    c d**5 / 120) of a Kepler residual (sign -1 for the elliptic equation, whose derivatives after f'' = e sin E
    and f''' = e cos E are -e sin E and -e cos E; +1 for the hyperbolic one), by series reversion in the Newton
    step t = -f / f1:
        d = t - a2 t**2 + (2 a2**2 - a3) t**3 + (5 a2 a3 - 5 a2**3 - a4) t**4
            + (14 a2**4 - 21 a2**2 a3 + 6 a2 a4 + 3 a3**2 - a5) t**5,   a_k = f^(k) / (k! f1).
    One division; the error is of order t**6 (sixth-order convergence)."""
    inverse = 1.0 / f1
    t = -f * inverse
    a2, a3 = (0.5 * inverse) * s, (inverse * (1.0 / 6.0)) * c
    a4, a5 = (sign * (1.0 / 12.0)) * a2, (sign * 0.05) * a3  # sign s / (24 f1), sign c / (120 f1)
    a2_squared = a2 * a2
    b3 = 2.0 * a2_squared - a3
    b4 = a2 * (5.0 * a3 - 5.0 * a2_squared) - a4
    b5 = a2_squared * (14.0 * a2_squared - 21.0 * a3) + (6.0 * a2 * a4 + 3.0 * a3 * a3) - a5
    return t * (1.0 + t * (-a2 + t * (b3 + t * (b4 + t * b5)))), t


def _elliptic_single_pass(m, m_lo, e, one_minus_e):
    """(E, certified): Markley's starter E1 (within 2.8e-4 relative for every 0 < e < 1, measured on 8e5 pairs),
    one evaluation of sin, E1 - sin E1 and 1 - cos E1 (trig_reflected), the residual f = (1 - e) E1 - m +
    e (E1 - sin E1) - m_lo free of cancellation, and one sixth-order step from its derivatives (sixth_order_step).
    Certified when the Newton step t is below SINGLE_PASS_ACCEPT E1: the step's truncation error is then below
    about 132 (t / E1)**6 E1 < 2**-58 E1 (E f'' / f' <= 2 on [0, pi])."""
    upper = np.minimum(m + e, np.pi)  # E - M = e sin E is in [0, e]
    x = np.clip(markley_starter(m, e), m, upper)
    sin, x_minus_sin, one_minus_cos = trig_reflected(x)
    f = ((one_minus_e * x - m) + e * x_minus_sin) - m_lo
    f1 = one_minus_e + e * one_minus_cos
    step, t = sixth_order_step(f, f1, e * sin, e * (1.0 - one_minus_cos), -1.0)
    return np.clip(x + step, m, upper), np.abs(t) <= SINGLE_PASS_ACCEPT * x


def _elliptic_residual(x, m, m_lo, e, one_minus_e):
    """(f, f', f'') of f(x) = (1 - e) x - m + e (x - sin x) - m_lo, free of cancellation."""
    f = ((one_minus_e * x - m) + e * x_minus_sin(x)) - m_lo
    df = one_minus_e + e * (2.0 * np.sin(0.5 * x) ** 2)  # 1 - e cos x, cancellation free
    return f, df, e * np.sin(x)


def _elliptic_safeguarded(m, m_lo, e, one_minus_e, upper):
    """E by the safeguarded Halley iteration in [m, upper] from the root of the cubic model (1 - e) E + e E**3 / 6
    = m (none of the benchmark's pairs needs it; tests/core/test_kepler.py runs it directly)."""
    start = np.clip(_cubic_root(one_minus_e, e / 6.0, m), m, upper)

    def residual(x, idx):
        return _elliptic_residual(x, m[idx], m_lo[idx], e[idx], one_minus_e[idx])

    return halley_in_bracket(start, m.copy(), upper.copy(), residual, "elliptic Kepler solve", {"M": m, "e": e})


def hyperbolic_anomaly(M: ArrayLike, e: ArrayLike) -> float | np.ndarray:
    """Hyperbolic anomaly H (rad) solving M = e sinh H - H, for e > 1 and any finite M.

    Odd in M exactly: H(-M) == -H(M). Accuracy: within 4 ulp of the exact root for 1 < e <= 1e12 and
    |M| <= 1e300 (tests/core/test_kepler.py). For H > 20 the equation is solved in the overflow-free
    form H + log1p(-exp(-2H)) = log((M + H) / (e / 2)).
    """
    M, e = broadcast(M=M, e=e)
    if _fast.use(M.size, "twobody._fast_kepler.hyperbolic"):
        return _compiled("hyperbolic", _hyperbolic_anomaly_numpy, M, e)
    return _hyperbolic_anomaly_numpy(M, e)


def _hyperbolic_anomaly_numpy(M, e):
    """hyperbolic_anomaly for broadcast float64 arrays, in NumPy."""
    check_finite(M, "mean anomaly M", "rad")
    check_eccentricity(e, 1.0, np.inf, True, True, "hyperbolic", _OTHER_CONICS)
    sign = np.where(np.signbit(M), -1.0, 1.0)
    with np.errstate(under="ignore"):  # subnormal and zero results are legitimate
        return sign * _solve_hyperbolic_positive(np.abs(M), e.astype(float, copy=True))


def _solve_hyperbolic_positive(M, e):
    """H >= 0 for M >= 0: the fixed pass on the series form, the safeguarded iterations (series or logarithmic
    form) on what it does not certify (as the compiled solver)."""
    shape, M, e = M.shape, M.reshape(-1), e.reshape(-1)
    H = np.zeros_like(M)
    tiny = (M < TINY_MEAN_ANOMALY) & (M > 0)
    H[tiny] = M[tiny] / (e[tiny] - 1.0)
    lower = np.arcsinh(M / e)
    log_form = lower > LOG_FORM_LIMIT
    series = (M > 0) & ~tiny & ~log_form
    if np.any(series):
        H[series], certified = _hyperbolic_fixed_pass(M[series], e[series])
        series[np.flatnonzero(series)[certified]] = False
    for mask, solver in ((series, _solve_hyperbolic_series_form), (log_form, _solve_hyperbolic_log_form)):
        if np.any(mask):
            H[mask] = solver(M[mask], e[mask], e[mask] - 1.0, lower[mask])
    return H.reshape(shape)


def _hyperbolic_series_residual(x, M, e, e_minus_1):
    """(f, f', f'') of f(H) = (e - 1) H - M + e (sinh H - H), free of cancellation."""
    f = (e_minus_1 * x - M) + e * sinh_minus_x(x)
    df = e_minus_1 + e * (2.0 * np.sinh(0.5 * x) ** 2)  # e cosh x - 1, cancellation free
    return f, df, e * np.sinh(x)


def _hyperbolic_fixed_pass(M, e):
    """(H, certified) for 0 < M with asinh(M / e) <= 20: HYPERBOLIC_FIXED_STEPS sixth-order steps (sixth_order_step:
    the residual's third derivative is e cosh H = f' + 1, its fourth and fifth f'' and f' + 1) on the series
    form from the starter of _solve_hyperbolic_series_form, with the pure cubic bound cbrt(6 M / e) for the cubic
    model's root, each kept in the bracket (bisection when it leaves; the bracket first moved by the residual's
    sign), then the Newton polish. The bracket asinh(M / e) <= H <= asinh(M / e) + log(e / (e - 1)) is widened by
    1e-5 (1 + |bound|), which keeps it a bracket with the compiled solver's 3e-6 logarithms. Certified when the
    polishing step is below 2**-40 relative: two steps certify every one of 2e5 of the benchmark's hyperbolic pairs
    and of 2e5 random pairs with M to 1e6 and e - 1 from 1e-15 to 1e6 (four Halley steps did too, at two more
    evaluations)."""
    e_minus_1 = e - 1.0
    lower = np.arcsinh(M / e)
    upper = lower + np.log(e) - np.log(e_minus_1)
    lo, upper = np.maximum(lower - 1e-5 * (1.0 + lower), 0.0), upper + 1e-5 * (1.0 + upper)
    with np.errstate(over="ignore"):
        hi = np.maximum(np.minimum(np.minimum(np.cbrt(6.0 * M / e), M / e_minus_1), upper), lo)
    x = np.where(lo > 3.0, lo, hi)
    for _ in range(HYPERBOLIC_FIXED_STEPS):
        f, df, d2f = _hyperbolic_series_residual(x, M, e, e_minus_1)
        lo, hi = np.where(f < 0, x, lo), np.where(f > 0, x, hi)
        with np.errstate(all="ignore"):
            new = x + sixth_order_step(f, df, d2f, df + 1.0, 1.0)[0]
        x = np.where(np.isfinite(new) & (lo <= new) & (new <= hi), new, 0.5 * (lo + hi))
    f, df, _ = _hyperbolic_series_residual(x, M, e, e_minus_1)
    with np.errstate(all="ignore"):
        step = f / df
        polished = x - step
    polished = np.where(np.isfinite(polished) & (f != 0), polished, x)
    return polished, np.abs(step) <= 2.0**-40 * x


def _solve_hyperbolic_series_form(M, e, e_minus_1, lower):
    """Root of (e - 1) H + e (sinh H - H) = M for moderate H (<= about 20), by the safeguarded iteration."""
    # sinh H - H >= H**3 / 6, so the root of the cubic model (e - 1) H + e H**3 / 6 = M lies above H;
    # sinh H <= M / (e - 1), and asinh(c x) <= asinh(x) + log(c) for c >= 1.
    cubic = _cubic_root(e_minus_1, e / 6.0, M)
    with np.errstate(over="ignore"):
        linear_bound = M / e_minus_1
    hi = np.maximum(np.minimum(np.minimum(cubic, linear_bound), lower + np.log(e) - np.log(e_minus_1)), lower)
    start = np.where(lower > 3.0, lower, hi)

    def residual(x, idx):
        return _hyperbolic_series_residual(x, M[idx], e[idx], e_minus_1[idx])

    return halley_in_bracket(start, lower.copy(), hi, residual, "hyperbolic Kepler solve", {"M": M, "e": e})


def _solve_hyperbolic_log_form(M, e, e_minus_1, lower):
    """Root of H + log1p(-exp(-2H)) - log((M + H) / (e / 2)) = 0 for H > 20 (no overflow). One logarithm of the
    ratio, not log(M + H) - log(e / 2): each of those rounds to half an ulp of itself, and log(M + H) exceeds H
    (2.17 ulp of H at M = 1.04e15, e = 2.51e6 that way); log(M + H) - log(e / 2) only where the ratio overflows."""
    lo = lower.copy()
    hi = lower + np.log(e) - np.log(e_minus_1)
    half_e = 0.5 * e

    def residual(x, idx):
        q = np.exp(-2.0 * x)
        mh = M[idx] + x
        with np.errstate(over="ignore"):
            ratio = mh / half_e[idx]
            log_ratio = np.where(np.isfinite(ratio), np.log(ratio), np.log(mh) - np.log(half_e[idx]))
        f = (x + np.log1p(-q)) - log_ratio
        df = 1.0 + 2.0 * q / (1.0 - q) - 1.0 / mh
        d2f = -4.0 * q / (1.0 - q) ** 2 + (1.0 / mh) ** 2
        return f, df, d2f

    return halley_in_bracket(lo.copy(), lo, hi, residual, "hyperbolic Kepler solve", {"M": M, "e": e})


def parabolic_anomaly(W: ArrayLike) -> float | np.ndarray:
    """D = tan(nu/2) solving Barker's equation W = D + D**3 / 3, in closed form.

    D is the real root of the cubic D**3 + 3 D = 3 W, evaluated by the cancellation-free Cardano form
    of _cubic_root (equivalent to D = 2 sinh(asinh(1.5 W) / 3), which loses digits for large W);
    for |W| < 1e-4 two fixed-point steps D = W - D**3 / 3 from D = W are exact to 1e-24, and larger W
    get one Newton step. Accuracy: within 2 ulp (tests/core/test_kepler.py).
    Odd in W; W = 0 gives 0 exactly; finite for every finite W.
    """
    W = np.asarray(W, dtype=float)
    if _fast.use(W.size, "twobody._fast_kepler.parabolic"):
        return _compiled("parabolic", _parabolic_anomaly_numpy, W)
    return _parabolic_anomaly_numpy(W)


def _parabolic_anomaly_numpy(W):
    """parabolic_anomaly for a float64 array, in NumPy."""
    check_finite(W, "parabolic mean anomaly W", "(dimensionless)")
    magnitude = np.abs(W)
    D = np.zeros_like(magnitude)
    small = magnitude < 1e-4
    w = magnitude[small]
    with np.errstate(under="ignore"):
        d1 = w - w**3 / 3.0
        D[small] = w - d1**3 / 3.0
    large = ~small
    w = magnitude[large]
    d = _cubic_root(np.ones(1), np.full(1, 1.0 / 3.0), w)
    with np.errstate(over="ignore"):
        polished = d - ((d - w) + d * (d / 3.0) * d) / (1.0 + d * d)  # one Newton step on the cubic
    D[large] = np.where(np.isfinite(polished), polished, d)
    return np.copysign(D, W)
