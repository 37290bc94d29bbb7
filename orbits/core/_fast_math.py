"""Scalar float64 building blocks for the compiled kernels (numba), written so LLVM can vectorise them.

No function here calls libm except as a fallback outside its stated range, so a loop that inlines them
(``jit(inline=True)``) compiles to SIMD code (AVX2 or AVX-512, what the CPU has): libm calls would stop the
vectoriser. Accuracy, measured against mpmath on 1e6 points of each range:
- sin_cos(x), 0 <= x <= 64: Cody-Waite reduction by pi/2 in three parts (fdlibm's constants),
  Taylor polynomials of degree 15 and 16 on [-pi/4, pi/4]; within 1 ulp of sin and cos.
- exp(x), |x| <= 708: reduction by ln 2 in two parts, Taylor polynomial of degree 13, exact scaling by
  2**k through the exponent bits; within 1 ulp.
- atan2_approx(y, x) to 2e-8, a starter.
- log_approx(x), positive normal x: exponent bits plus 2 atanh((m - 1) / (m + 1)) to t**9, |error|
  < 3e-6; only for starting guesses.
- cbrt_rough(x) 2e-5 and cbrt_approx(x) 5e-10 relative (division free), cbrt_normal(x) within about 1 ulp (one
  Halley step more).
"""

import math

import numpy as np
from llvmlite import ir
from numba import types
from numba.extending import intrinsic

from orbits.core._fast import jit
from orbits.core.series import factorial_series

_SMALLEST_NORMAL = 2.2250738585072014e-308
_PIO2_1 = 1.57079632673412561417e00  # pi/2 = _PIO2_1 + _PIO2_2 + _PIO2_2T; the first two have 33 bits (fdlibm)
_PIO2_2 = 6.07710050630396597660e-11
_PIO2_2T = 2.02226624879595063154e-21
_LN2_HI = 6.93147180369123816490e-01  # ln 2 = _LN2_HI + _LN2_LO, _LN2_HI with 32 bits (fdlibm)
_LN2_LO = 1.90821492927058770002e-10
_SIN_MAX = 64.0
_EXP_MAX = 708.0


_SIN_POLY = factorial_series(3, -1.0, 7)  # (y - sin y) / y**3 = 1/6 - y**2/120 + ..., to y**15
_COS_POLY = factorial_series(4, -1.0, 7)  # (cos y - 1 + y**2/2) / y**4, to y**16
_EXP_POLY = tuple(1.0 / math.factorial(k) for k in range(13, -1, -1))  # exp(r), to r**13


@intrinsic
def _bits(typingctx, x):
    """The IEEE bit pattern of a float64 as an int64."""

    def codegen(context, builder, signature, args):
        return builder.bitcast(args[0], ir.IntType(64))

    return types.int64(types.float64), codegen


@intrinsic
def _from_bits(typingctx, x):
    """The float64 with the given IEEE bit pattern."""

    def codegen(context, builder, signature, args):
        return builder.bitcast(args[0], ir.DoubleType())

    return types.float64(types.int64), codegen


@jit(inline=True)
def _horner(coefficients, x):
    total = 0.0
    for c in coefficients:
        total = total * x + c
    return total


@jit(inline=True)
def _inverse_cbrt_rough(x):
    """x**(-1/3) for a positive normal x to about 1e-5 relative (vectorisable, no libm, no division): a guess on
    the bit pattern (a constant minus a third of the bits, within 3.4 %) and two Newton steps z (4 - x z**3) / 3,
    each squaring the relative error (times 2)."""
    z = _from_bits(np.int64(0x553EF0FF289DD796) - np.int64(np.float64(_bits(x)) * (1.0 / 3.0)))
    z = z * (4.0 - x * z * z * z) * (1.0 / 3.0)
    return z * (4.0 - x * z * z * z) * (1.0 / 3.0)


@jit(inline=True)
def _cbrt_rough(x):
    """Cube root of a positive normal x to about 2e-5 relative, x z**2 with z = _inverse_cbrt_rough(x): enough for a
    starter whose own error is larger (Markley's, 2.8e-4)."""
    z = _inverse_cbrt_rough(x)
    return x * z * z


@jit(inline=True)
def _cbrt_approx(x):
    """Cube root of a positive normal x to about 5e-10 relative (a starter; vectorisable, no libm, no division):
    _inverse_cbrt_rough and a third Newton step (divisions cost the vectorised kernels more than multiplications),
    then x z**2."""
    z = _inverse_cbrt_rough(x)
    z = z * (4.0 - x * z * z * z) * (1.0 / 3.0)
    return x * z * z


@jit(inline=True)
def _cbrt_normal(x):
    """Cube root of a positive normal finite x to within about 1 ulp, vectorisable: _cbrt_approx and one
    more Halley step (numba's np.cbrt goes through pow and measured 40 % slower)."""
    big = x > 1e270  # y**3 could overflow: take cbrt(x / 2**903) * 2**301
    x = x * 2.0**-903 if big else x
    y = _cbrt_approx(x)
    y3 = y * y * y
    return y * ((y3 + 2.0 * x) / (2.0 * y3 + x)) * (2.0**301 if big else 1.0)


@jit(inline=True)
def _cbrt(x):
    """Cube root of any float64: _cbrt_normal, or libm's for zero, subnormal, infinite or negative x."""
    return _cbrt_normal(x) if _SMALLEST_NORMAL <= x < np.inf else np.cbrt(x)


@jit(inline=True)
def _two_sum(a, b):
    s = a + b
    bb = s - a
    return s, (a - (s - bb)) + (b - bb)


@intrinsic
def _fma(typingctx, a, b, c):
    """a * b + c rounded once (LLVM's fma: one instruction on CPUs with FMA, a correct libm call elsewhere)."""

    def codegen(context, builder, signature, args):
        return builder.fma(args[0], args[1], args[2])

    return types.float64(types.float64, types.float64, types.float64), codegen


@jit(inline=True)
def _two_product(a, b):
    """Exact product a * b = p + err: err = fma(a, b, -p) (the same numbers as Dekker's splitting in
    orbits.core._dd, in 2 operations instead of 17)."""
    p = a * b
    return p, _fma(a, b, -p)


@jit(inline=True)
def _fast_two_sum(a, b):
    """Exact sum a + b = s + err for |a| >= |b| (Dekker)."""
    s = a + b
    return s, b - (s - a)


# double-double arithmetic on scalars (orbits.core._dd, with FMA products)


@jit(inline=True)
def _dd_add(a_hi, a_lo, b_hi, b_lo):
    s, e = _two_sum(a_hi, b_hi)
    return _fast_two_sum(s, e + a_lo + b_lo)


@jit(inline=True)
def _dd_mul(a_hi, a_lo, b_hi, b_lo):
    p, e = _two_product(a_hi, b_hi)
    return _fast_two_sum(p, e + (a_hi * b_lo + a_lo * b_hi))


@jit(inline=True)
def _dd_div(a_hi, a_lo, b_hi, b_lo):
    q1 = a_hi / b_hi
    p_hi, p_lo = _dd_mul(b_hi, b_lo, -q1, 0.0)
    r_hi, _ = _dd_add(a_hi, a_lo, p_hi, p_lo)
    return _two_sum(q1, r_hi / b_hi)


@jit(inline=True)
def _dd_sqrt(a_hi, a_lo):
    s = math.sqrt(a_hi)
    p, e = _two_product(s, s)
    return _two_sum(s, ((a_hi - p) - e + a_lo) / (2.0 * s))


@jit(inline=True)
def _dd_over(a_hi, a_lo, b_hi, b_lo, inverse):
    """_dd_div with the reciprocal inverse = 1 / b_hi given: quotient a_hi * inverse, corrected once from the exact
    remainder (the same double-double quotient; a division costs the vectorised loops as much as a dozen
    multiplications, and one reciprocal serves two quotients)."""
    q = a_hi * inverse
    p, e = _two_product(q, b_hi)
    return _fast_two_sum(q, (((a_hi - p) - e + a_lo) - q * b_lo) * inverse)


@jit(inline=True)
def _dd_root(a_hi, a_lo):
    """(_dd_sqrt(a_hi, a_lo), 1 / its high part), the correction multiplied by the reciprocal."""
    s = math.sqrt(a_hi)
    inverse = 1.0 / s
    p, e = _two_product(s, s)
    hi, lo = _fast_two_sum(s, ((a_hi - p) - e + a_lo) * (0.5 * inverse))
    return hi, lo, inverse


@jit(inline=True)
def _dd_dot(ax, ay, az, bx, by, bz):
    hi, lo = _two_product(ax, bx)
    p, e = _two_product(ay, by)
    hi, lo = _dd_add(hi, lo, p, e)
    p, e = _two_product(az, bz)
    return _dd_add(hi, lo, p, e)



#: atan(u) = u P(u**2) for |u| <= tan(pi / 8), Taylor to u**17 (error below 2e-8)
_ATAN_POLY = tuple((-1.0) ** k / (2 * k + 1) for k in range(8, -1, -1))
_TAN_PI_8 = 0.41421356237309503


@jit(inline=True)
def _atan2_approx(y, x):
    """atan2(y, x) to 2e-8 (a starter, not a result), vectorisable, one division: the octant by comparisons,
    atan(t) = pi / 4 + atan((t - 1) / (t + 1)) for t = min / max above tan(pi / 8), else the series."""
    ax, ay = abs(x), abs(y)
    big, small = max(ax, ay), min(ax, ay)
    upper = small > _TAN_PI_8 * big
    u = ((small - big) if upper else small) / max((small + big) if upper else big, 1e-300)
    angle = u * _horner(_ATAN_POLY, u * u) + (0.25 * np.pi if upper else 0.0)
    angle = 0.5 * np.pi - angle if ay > ax else angle
    angle = np.pi - angle if x < 0.0 else angle
    return math.copysign(angle, y)


@jit(inline=True)
def _sin_cos(x):
    """(sin x, cos x) for 0 <= x <= 64 (NaN beyond), vectorisable; within 1 ulp."""
    k = np.rint(x * (2.0 / np.pi))
    t = x - k * _PIO2_1  # exact: k * _PIO2_1 is exact and within a factor 2 of x (Sterbenz)
    w = k * _PIO2_2
    r = t - w
    y = r - (k * _PIO2_2T - ((t - r) - w))  # fdlibm's second reduction stage
    y2 = y * y
    s = y - y * y2 * _horner(_SIN_POLY, y2)
    c = (1.0 - 0.5 * y2) + y2 * y2 * _horner(_COS_POLY, y2)
    quadrant = np.int64(k)
    swap = (quadrant & 1) == 1  # arithmetic quadrant selection: a chain of ifs stops the vectoriser
    sin = (c if swap else s) * np.float64(1 - (quadrant & 2))
    cos = (s if swap else c) * np.float64(1 - ((quadrant + 1) & 2))
    in_range = x >= 0.0 and x <= _SIN_MAX
    return (sin if in_range else np.nan), (cos if in_range else np.nan)


@jit(inline=True)
def _exp(x):
    """exp(x) for |x| <= 708 (inf above, NaN below -708), vectorisable; within 1 ulp."""
    k = np.rint(x * (1.0 / math.log(2.0)))
    r = (x - k * _LN2_HI) - k * _LN2_LO
    scale = _from_bits((np.int64(k) + 1023) << 52)
    result = _horner(_EXP_POLY, r) * scale
    return result if abs(x) <= _EXP_MAX else (np.inf if x > 0.0 else np.nan)


@jit(inline=True)
def _log_approx(x):
    """log(x) to |error| < 3e-6 for positive normal x, vectorisable (a starter, not a result)."""
    bits = _bits(x)
    exponent = (bits >> 52) - 1023
    m = _from_bits((bits & 0xFFFFFFFFFFFFF) | 0x3FF0000000000000)  # mantissa in [1, 2)
    t = (m - 1.0) / (m + 1.0)
    t2 = t * t
    return exponent * math.log(2.0) + 2.0 * t * (1.0 + t2 * (1.0 / 3.0 + t2 * (0.2 + t2 * (1.0 / 7.0 + t2 / 9.0))))
