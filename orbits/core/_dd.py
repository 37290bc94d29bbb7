"""Double-double arithmetic (unevaluated sums hi + lo of two float64 arrays), for the few places
where a result must be right to the last bit: reduction modulo 2 pi and the orbital period.
Error-free transformations after Dekker (1971) and Knuth; no FMA is assumed.
"""

import numpy as np
from numpy.typing import ArrayLike

_SPLITTER = 134217729.0  # 2**27 + 1


def split(a: ArrayLike) -> tuple[float | np.ndarray, float | np.ndarray]:
    """Veltkamp split a = hi + lo, each half with at most 26 significant bits."""
    t = _SPLITTER * a
    hi = t - (t - a)
    return hi, a - hi


def two_product(a: ArrayLike, b: ArrayLike) -> tuple[float | np.ndarray, float | np.ndarray]:
    """Exact product a * b = p + err (Dekker)."""
    p = a * b
    a_hi, a_lo = split(a)
    b_hi, b_lo = split(b)
    return p, ((a_hi * b_hi - p) + a_hi * b_lo + a_lo * b_hi) + a_lo * b_lo


def two_sum(a: ArrayLike, b: ArrayLike) -> tuple[float | np.ndarray, float | np.ndarray]:
    """Exact sum a + b = s + err (Knuth)."""
    s = a + b
    bb = s - a
    return s, (a - (s - bb)) + (b - bb)


def add(
    x: tuple[ArrayLike, ArrayLike], y: tuple[ArrayLike, ArrayLike]
) -> tuple[float | np.ndarray, float | np.ndarray]:
    """(x_hi + x_lo) + (y_hi + y_lo) as a double-double."""
    s, e = two_sum(x[0], y[0])
    return two_sum(s, e + x[1] + y[1])


def mul(
    x: tuple[ArrayLike, ArrayLike], y: tuple[ArrayLike, ArrayLike]
) -> tuple[float | np.ndarray, float | np.ndarray]:
    """(x_hi + x_lo) * (y_hi + y_lo) as a double-double."""
    p, e = two_product(x[0], y[0])
    return two_sum(p, e + x[0] * y[1] + x[1] * y[0])


def div(
    x: tuple[ArrayLike, ArrayLike], y: tuple[ArrayLike, ArrayLike]
) -> tuple[float | np.ndarray, float | np.ndarray]:
    """(x_hi + x_lo) / (y_hi + y_lo) as a double-double (one correction step)."""
    q1 = x[0] / y[0]
    r = add(x, mul(y, (-q1, np.zeros_like(q1))))
    return two_sum(q1, r[0] / y[0])


def sqrt(x: tuple[ArrayLike, ArrayLike]) -> tuple[float | np.ndarray, float | np.ndarray]:
    """Square root of a positive double-double (one Newton correction)."""
    s = np.sqrt(x[0])
    p, e = two_product(s, s)
    return two_sum(s, ((x[0] - p) - e + x[1]) / (2.0 * s))


def dot(a: np.ndarray, b: np.ndarray) -> tuple[float | np.ndarray, float | np.ndarray]:
    """Dot product along the last axis as a double-double."""
    total = (np.zeros(a.shape[:-1]), np.zeros(a.shape[:-1]))
    for k in range(a.shape[-1]):
        total = add(total, two_product(a[..., k], b[..., k]))
    return total


def cbrt(x: ArrayLike) -> float | np.ndarray:
    """Cube root within 0.51 ulp on every CPU (correctly rounded on the 6,000 arguments of tests/core/test_dd.py,
    0.4998 ulp at worst), for any float64 x (0, inf, NaN and negatives as np.cbrt).

    np.cbrt is within 1 ulp on some CPUs and 2.8 ulp on others (measured on AVX2: NumPy dispatches to
    different loops), so a result squared or multiplied on would differ by machine. Here x = m 2**(3q)
    with |m| in [1/2, 4) (exact scaling), y = np.cbrt(m), and one Newton step y + (m - y**3) / (3 y**2) with
    the residual m - y**3 formed exactly (two_product), which leaves the rounding of the last addition.
    """
    x = np.asarray(x, dtype=float)
    mantissa, exponent = np.frexp(x)
    q = exponent // 3
    m = np.ldexp(mantissa, exponent - 3 * q)
    y = np.cbrt(m)
    with np.errstate(invalid="ignore", divide="ignore"):  # 0, inf and NaN keep np.cbrt's value
        square_hi, square_lo = two_product(y, y)
        cube_hi, cube_lo = two_product(square_hi, y)
        residual = ((m - cube_hi) - cube_lo) - square_lo * y
        corrected = y + residual / (3.0 * square_hi)
    y = np.where((m != 0) & np.isfinite(m), corrected, y)
    return np.ldexp(y, q)[()]
