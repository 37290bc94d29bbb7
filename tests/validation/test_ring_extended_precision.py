"""Rings in heyoka's extended precision: a smaller round-off seed breaks the ring later, as predicted.

Measured (heyoka, tol 1e-19, long double state): n = 4, 6, 8 break up at 0.988, 1.016 and 1.020 times the time
predicted for a long-double seed (5e-20), 1.16-1.20 times later than the float64 run of the same ring (predicted
1.25). The window on the first ratio is the measured range widened by ln(10) / ln(1e-3 / 5e-20) = 0.061 on each
side, what a factor 10 in the effective seed would move it: [0.926, 1.081].
"""

import math

import numpy as np
import pytest

from orbits.validate import backends
from orbits.validate.builders import ring_problem

pytestmark = pytest.mark.skipif(not backends.available("heyoka"), reason="heyoka is not installed")

#: ln(10) / ln(1e-3 / 5e-20): how far a factor 10 in the long-double seed moves the break-up ratio
SEED_DECADE = math.log(10) / math.log(1e-3 / 5e-20)


@pytest.mark.parametrize("n", [4, 6, 8])
def test_long_double_ring_breaks_up_later_as_predicted(n):
    _, probe = ring_problem(n, [1.0], extended=True)
    times = np.linspace(0, 1.6 * probe.breakup_time, 500)[1:]
    single, single_expected = ring_problem(n, times)
    extended, expected = ring_problem(n, times, extended=True)
    assert extended.positions.dtype == np.longdouble and single.positions.dtype == np.float64
    fast = backends.integrate("heyoka", single, tol=1e-16)
    slow = backends.integrate("heyoka", extended, tol=1e-19, fp_type="long double")
    assert slow.settings["fp_type"] == "long double"
    t_single = single_expected.measured_breakup_time(fast.times, fast.positions)
    t_extended = expected.measured_breakup_time(slow.times, slow.positions)
    ratio = t_extended / expected.breakup_time
    assert 0.988 - SEED_DECADE <= ratio <= 1.020 + SEED_DECADE, ratio
    # predicted: ln(1e-3 / 5e-20) / ln(1e-3 / 1e-16) = 1.25 times later; measured 1.16-1.20
    assert t_extended > 1.1 * t_single, (t_extended, t_single)
