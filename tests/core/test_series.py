"""The shared power series: coefficients against exact rationals, and Horner's rule against mpmath sums."""

from fractions import Fraction
from math import factorial

import mpmath
import numpy as np
import pytest

from orbits.core.series import factorial_series, horner


@pytest.mark.parametrize("first, sign, terms", [(2, -1.0, 12), (3, -1.0, 12), (3, -1.0, 14), (3, 1.0, 14),
                                                (4, -1.0, 7)])
def test_coefficients_are_the_correctly_rounded_reciprocal_factorials(first, sign, terms):
    """sign**k / (2k + first)! rounded once while the factorial is exact in float64 (up to 22!); beyond it the
    factorial itself is rounded and a coefficient may be 1 ulp off (measured: 23! and 29!, 1 ulp); the sum is
    checked against mpmath below."""
    coefficients = factorial_series(first, sign, terms)[::-1]
    for k, c in enumerate(coefficients):
        n = 2 * k + first
        exact = float(Fraction(int(sign) ** k, factorial(n)))  # float(Fraction) rounds correctly
        assert c == exact if n <= 22 else abs(c - exact) <= np.spacing(abs(exact))


def test_horner_sums_the_series_of_x_minus_sin():
    """x**3 P(x**2) with P = factorial_series(3, -1, 14) is x - sin x to within 2 ulp for |x| < 2 (measured 1)."""
    coefficients = factorial_series(3, -1.0, 14)
    for x in np.linspace(-2.0, 2.0, 41)[np.linspace(-2.0, 2.0, 41) != 0]:
        value = float(horner(coefficients, x * x) * x**3)
        with mpmath.workdps(50):
            exact = mpmath.mpf(x) - mpmath.sin(mpmath.mpf(x))
        assert abs(value - float(exact)) <= 2 * np.spacing(abs(float(exact)))
