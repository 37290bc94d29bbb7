"""The propagator swept against the mpmath reference (orbits.tools.reference) on broad random sets, per conic
class, on both paths: the figures the README states.

Each class draws 2000 fresh states each run (times ORBITS_SLOW_SCALE; tests/conftest.py's fresh_seed) with random
orientation,
semi-latus rectum 7000-21000 km about the Earth and flights either way: ellipses over up to +-1000 periods,
near-parabolic and hyperbolic orbits over 1e-2 to 1e4 times sqrt(p**3 / mu). Two bounds per class and path:
- the worst |dr| / |r| and |dv| / |v| themselves;
- the worst error over its conditioning plus eps = 2**-53 (the rounding of the result itself): the conditioning is
  the change of the exact state when every input (r0, v0 and dt) moves by eps of itself, independently, c =
  |(sum_j (Phi_ij x0_j)**2)_i| eps / |r| from the state-transition matrix Phi (and |v dt| eps for dt). Over long
  spans on eccentric orbits c is large (1000 periods at e = 0.99: an along-track 3e-10 s in 6.3e8 s) and the
  error is measured against it; near the parabola it tells a real loss from the input's own uncertainty.
Bounds are within about 10x of the worst measured at full size (ORBITS_SLOW_SCALE=1), written beside each; on
every class and path the position error also stays within CONDITIONING_BOUND times its conditioning plus eps, the
README's figure.
"""

import math

import mpmath
import mpref
import numpy as np
import pytest
from flights import grazing_flight

from orbits.core.errors import OrbitDomainError
from orbits.core.twobody import elements
from orbits.core.twobody.propagate import _propagate_compiled, _propagate_numpy
from orbits.core.twobody.transition import transition_matrix

MU_EARTH = 3.986004418e14
EPS = 2.0**-53
FULL_SIZE = 2000
#: every class, both paths: |dr| / |r| <= this many times (conditioning + eps) (worst measured 6.6, hyperbolas on
#: the NumPy path)
CONDITIONING_BOUND = 10.0
#: the same on flights grazing the focus or starting nearly radial (worst measured 16)
GRAZING_BOUND = 40.0

#: class: (eccentricities from uniform draws u, span: periods for ellipses, else None)
CLASSES = {
    "elliptic": (lambda u: 0.9 * u, 1000.0),
    "high-e elliptic": (lambda u: 1 - 10 ** (-1 - 5 * u), 1000.0),
    "e = 0.99": (lambda u: np.full_like(u, 0.99), 1000.0),
    "near-parabolic elliptic": (lambda u: 1 - 10 ** (-6 - 6 * u), None),
    "near-parabolic hyperbolic": (lambda u: 1 + 10 ** (-6 - 6 * u), None),
    "hyperbolic": (lambda u: 1 + 10 ** (-6 + 7 * u), None),
}

#: Worst measured at full size (2000 fresh states a class, over several runs), per class and path: (|dr| / |r|,
#: |dv| / |v|, |dr| / |r| over its conditioning + eps, |dv| / |v| over its conditioning + eps); the bounds are 10x
#: these (those over the conditioning at least 1), but for |dv| / |v|, which is bounded through its conditioning
#: alone. The large |dv| / |v| of the
#: high-e class is conditioning (near apoapsis at 1 - e = 1e-6 the speed is 5e-7 of its periapsis value), as is
#: the 4.5e-13 in position over 1000 periods at e = 0.99 (0.29 of its conditioning). Median |dr| / |r|: 0.9-1.5e-16.
MEASURED = {
    "elliptic": {"compiled": (4e-15, 2.5e-15, 1, 1.1), "numpy": (3.6e-15, 2.5e-15, 1, 1.3)},
    "high-e elliptic": {"compiled": (5.2e-15, 1.8e-10, 0.048, 0.0049), "numpy": (4.7e-15, 1.1e-11, 0.11, 0.0091)},
    "e = 0.99": {"compiled": (2e-14, 3.8e-14, 0.29, 0.16), "numpy": (4.5e-13, 2.3e-13, 0.29, 0.15)},
    "near-parabolic elliptic": {"compiled": (5.3e-15, 1.1e-14, 5.3, 3.1), "numpy": (3.8e-15, 1.1e-14, 4.6, 7.3)},
    "near-parabolic hyperbolic": {"compiled": (4.3e-15, 9.1e-15, 4.1, 3.6), "numpy": (1.5e-14, 9.2e-15, 6.3, 3)},
    "hyperbolic": {"compiled": (3.2e-15, 6.9e-15, 4.9, 11), "numpy": (1.3e-14, 6.9e-15, 6.6, 4.5)},
}


def draw(name, n, seed):
    """(r0, v0, dt) of the first n of the class's FULL_SIZE random states drawn from `seed`."""
    rng = np.random.default_rng([seed, list(CLASSES).index(name)])
    eccentricity, span = CLASSES[name]
    u = rng.uniform(0, 1, (9, FULL_SIZE))[:, :n]
    e, p = eccentricity(u[0]), 7e6 * (1 + 2 * u[1])
    angles = math.pi * u[2], 2 * math.pi * u[3], 2 * math.pi * u[4]
    limit = np.where(e > 1, np.arccos(-1 / np.maximum(e, 1.0)), math.pi)  # the asymptotes' true anomaly
    nu = (2 * u[5] - 1) * np.where(e > 1, 0.95, 1.0) * limit
    r0, v0 = elements.elements_to_state(p, e, *angles, nu, MU_EARTH)
    sign = np.where(u[6] < 0.5, -1.0, 1.0)
    if span is not None:
        period = 2 * math.pi * np.sqrt((p / ((1 - e) * (1 + e))) ** 3 / MU_EARTH)
        return r0, v0, sign * span * u[7] * period
    return r0, v0, sign * 10 ** (-2 + 6 * u[8]) * np.sqrt(p**3 / MU_EARTH)


def errors_and_conditioning(name, n, path, seed):
    """Per state: |dr| / |r|, |dv| / |v| against mpmath, and the position and velocity conditioning."""
    r0, v0, dt = draw(name, n, seed)
    if path == "numpy":
        r, v = _propagate_numpy(r0, v0, MU_EARTH, dt)
    else:
        pytest.importorskip("numba")
        result = _propagate_compiled(r0, v0, MU_EARTH, dt)
        assert result is not None, "the compiled kernel deferred to the NumPy implementation"
        r, v = result
    errors = np.empty((n, 2))
    for i in range(n):
        for k, (x, exact) in enumerate(zip((r[i], v[i]), mpref.propagate(r0[i], v0[i], MU_EARTH, dt[i]))):
            errors[i, k] = float(mpmath.norm([mpmath.mpf(float(a)) - b for a, b in zip(x, exact)]) / mpmath.norm(exact))
    phi = transition_matrix(r0, v0, MU_EARTH, dt)
    moves = phi * np.concatenate([r0, v0], axis=-1)[:, None, :] * EPS
    drift = np.sqrt(np.sum(moves[:, :3] ** 2, axis=-1) + (v * dt[:, None] * EPS) ** 2)
    conditioning = np.stack([np.linalg.norm(drift, axis=-1) / np.linalg.norm(r, axis=-1),
                             np.linalg.norm(np.sqrt(np.sum(moves[:, 3:] ** 2, axis=-1)), axis=-1)
                             / np.linalg.norm(v, axis=-1)], axis=-1)
    return errors, conditioning + EPS


@pytest.mark.slow
@pytest.mark.parametrize("path", ["compiled", "numpy"])
@pytest.mark.parametrize("name", list(CLASSES))
def test_broad_random_sets_against_mpmath(name, path, slow_scale, record, fresh_seed):
    """Both paths, every class: worst relative errors and worst errors over the conditioning within about 10x of
    what was measured at full size (MEASURED), positions within CONDITIONING_BOUND of theirs."""
    n = max(40, int(FULL_SIZE * slow_scale))
    errors, conditioning = errors_and_conditioning(name, n, path, fresh_seed)
    worst, worst_ratio = errors.max(axis=0), (errors / conditioning).max(axis=0)
    record(f"propagation {name} ({path}): |dr|/r", n, worst[0], "relative")
    record(f"propagation {name} ({path}): |dr|/r / (cond + eps)", n, worst_ratio[0], "")
    # 10x the worst measured; over the conditioning never below 1 (within its conditioning is as good as float64
    # allows: a fresh sample of the benign high-e class found a velocity ratio of 0.056 where 0.0049 was measured)
    measured = MEASURED[name][path]
    bounds = [10 * figure for figure in measured[:2]] + [max(10 * figure, 1.0) for figure in measured[2:]]
    assert worst[0] <= bounds[0], (fresh_seed, worst, bounds[0])
    assert worst_ratio[0] <= min(bounds[2], CONDITIONING_BOUND), (fresh_seed, worst_ratio)
    # velocities over their conditioning only: near apoapsis at 1 - e = 1e-6 the conditioning itself sets |dv| / |v|
    # (1.1e-11 in one sample of 2000, 1.8e-10 in another), while the ratio stays below 0.01
    assert worst_ratio[1] <= bounds[3], (fresh_seed, worst_ratio, bounds[3])


def test_grazing_and_near_radial_flights_within_their_conditioning(path, fresh_seed, record):
    """Flights past the focus at 1e-7 to 0.1 of r0, or along a nearly radial leg (tests/flights.py), 40 fresh a run:
    positions within GRAZING_BOUND times their conditioning plus eps (measured at most 16 times over about 1000
    flights on both paths)."""
    rng = np.random.default_rng(fresh_seed)
    if path == "compiled":
        pytest.importorskip("numba")
    solve = _propagate_numpy if path == "numpy" else _propagate_compiled
    worst = 0.0
    for _ in range(40):
        r0, v0, dt = grazing_flight(rng)
        try:
            transition_matrix(r0, v0, 1.0, dt)
        except OrbitDomainError:  # Phi itself leaves float64 so close to the focus: no conditioning to hold to
            continue
        r, v = solve(r0[None], v0[None], np.array([1.0]), np.array([dt]))
        exact = mpref.propagate(r0, v0, 1.0, dt)[0]
        error = float(mpmath.norm([mpmath.mpf(float(a)) - b for a, b in zip(r[0], exact)]) / mpmath.norm(exact))
        reference = np.array(mpref.transition_matrix(r0, v0, 1.0, dt), dtype=float)
        moves = reference[:3] * np.concatenate([r0, v0])[None, :] * EPS
        drift = np.sqrt(np.sum(moves**2, axis=-1) + (v[0] * dt * EPS) ** 2)
        ratio = error / (np.linalg.norm(drift) / np.linalg.norm(r[0]) + EPS)
        worst = max(worst, ratio)
        assert ratio <= GRAZING_BOUND, (fresh_seed, path, r0, v0, dt, error, ratio)
    record(f"propagation grazing ({path}): |dr|/r / (cond + eps)", 40, worst, "")
