"""Kepler solvers swept against mpmath over the whole domain the API accepts, on both paths: 2e4 fresh random
pairs each run for each conic (the README's figures are these bounds), 1e6 plus a log grid behind `slow`."""

import math

import mpref
import numpy as np
import pytest

from orbits.core.twobody import kepler
from orbits.tools import reference

#: the README's bounds, in ulps of the exact root (worst measured over 15 fresh samples of 2e4 each, both paths,
#: native and AVX2 profiles: elliptic 1.61, hyperbolic 1.41, parabolic 1.34)
ELLIPTIC_ULPS, HYPERBOLIC_ULPS, PARABOLIC_ULPS = 3.0, 2.0, 2.0
SAMPLE = 20_000
#: the slow tier's bound on its 1e6 pairs and log grid
BOUND_ULPS = 4


def random_elliptic(rng, n):
    """A third generic, a third within 1e-6 of e = 1 with small M, a third with |M| up to the largest the API takes
    (kepler.MAX_MEAN_ANOMALY, 7.1e15: 2**50 revolutions)."""
    k = n // 3
    top = math.log10(kepler.MAX_MEAN_ANOMALY)
    M = np.concatenate([rng.uniform(-20, 20, k), 10 ** rng.uniform(-16, 0, k), 10 ** rng.uniform(2, top, n - 2 * k)])
    e = np.concatenate([rng.uniform(0, 1, k), 1 - 10 ** rng.uniform(-16, -6, k), rng.uniform(0, 1, n - 2 * k)])
    return np.minimum(M, kepler.MAX_MEAN_ANOMALY) * rng.choice([-1.0, 1.0], n), e


def worst_elliptic(M, e):
    E = kepler.eccentric_anomaly(M, e)
    return max(reference.kepler_E_ulps(x, m, ee) for x, m, ee in zip(E, M, e))


def test_elliptic_sweep(path, fresh_seed, record):
    """0 <= e < 1 (1 - e down to 1e-16), |M| up to kepler.MAX_MEAN_ANOMALY."""
    M, e = random_elliptic(np.random.default_rng(fresh_seed), SAMPLE)
    worst = worst_elliptic(M, e)
    record(f"Kepler elliptic sweep ({path})", M.size, worst, "ulp")
    assert worst <= ELLIPTIC_ULPS, fresh_seed


def test_hyperbolic_sweep(path, fresh_seed, record):
    """M from 1e-12 to 1e300 and e - 1 from 1e-15 to 1e12."""
    rng = np.random.default_rng(fresh_seed)
    M, e = 10 ** rng.uniform(-12, 300, SAMPLE), 1 + 10 ** rng.uniform(-15, 12, SAMPLE)
    H = kepler.hyperbolic_anomaly(M, e)
    worst = max(reference.kepler_H_ulps(x, m, ee) for x, m, ee in zip(H, M, e))
    record(f"Kepler hyperbolic sweep ({path})", SAMPLE, worst, "ulp")
    assert worst <= HYPERBOLIC_ULPS, fresh_seed


def test_parabolic_sweep(path, fresh_seed, record):
    """Barker's equation, W of either sign from 1e-300 to 1e300 in magnitude."""
    rng = np.random.default_rng(fresh_seed)
    W = 10 ** rng.uniform(-300, 300, SAMPLE) * rng.choice([-1.0, 1.0], SAMPLE)
    D = kepler.parabolic_anomaly(W)
    worst = max(float(mpref.ulp_error(float(d), mpref.barker_D(w))) for d, w in zip(D, W))
    record(f"Kepler parabolic sweep ({path})", SAMPLE, worst, "ulp")
    assert worst <= PARABOLIC_ULPS, fresh_seed


@pytest.mark.slow
def test_elliptic_sweep_1e6_and_log_grid(record, slow_scale, fresh_seed):
    """1e6 random pairs and a 1000 x 1000 log grid over (1 - e, M) in [1e-16, 1]**2, times ORBITS_SLOW_SCALE."""
    n = max(1000, int(1_000_000 * slow_scale))
    M, e = random_elliptic(np.random.default_rng(fresh_seed), n)
    side = max(30, int(1000 * slow_scale**0.5))
    gap, mean = np.meshgrid(np.logspace(-16, 0, side), np.logspace(-16, 0, side))
    grid_e = np.minimum(1 - gap.ravel(), np.nextafter(1.0, 0.0))
    worst_random = worst_elliptic(M, e)
    worst_grid = worst_elliptic(mean.ravel(), grid_e)
    record("Kepler elliptic sweep (slow, random)", n, worst_random, "ulp")
    record("Kepler elliptic sweep (slow, log grid in 1-e and M)", side * side, worst_grid, "ulp")
    assert max(worst_random, worst_grid) <= BOUND_ULPS, fresh_seed
