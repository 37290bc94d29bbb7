"""The one power-series family the core needs, and Horner's rule to evaluate it.

x - sin x, sinh x - x (orbits.core.twobody.kepler), the Stumpff functions c2 and c3 (orbits.core.twobody.propagate)
and the
compiled kernels' sine, cosine and exponential (orbits.core._fast_math) are all sums of the form

    sum_{k < terms} sign**k x**k / (2k + first)!

in x = y**2. Coefficients are generated here once, in float64, the factorial built by exact integer steps
times a float (exact below 23!), each coefficient rounded once.
"""

import numpy as np
from numpy.typing import ArrayLike


def factorial_series(first: int, sign: float, terms: int) -> tuple[float, ...]:
    """Coefficients, highest degree first, of sum_{k < terms} sign**k x**k / (2k + first)!."""
    coefficients, factorial = [], 1.0
    for n in range(2, first + 1):
        factorial *= n
    for k in range(terms):
        coefficients.append(sign**k / factorial)
        factorial *= (2 * k + first + 1) * (2 * k + first + 2)
    return tuple(coefficients[::-1])


def horner(coefficients: tuple[float, ...], x: ArrayLike) -> np.ndarray:
    """sum_k c_k x**k by Horner's rule, the coefficients given highest degree first; float64 arrays."""
    x = np.asarray(x, dtype=float)
    total = np.zeros_like(x)
    for c in coefficients:
        total = total * x + c
    return total
