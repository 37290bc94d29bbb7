"""Decay of a circular orbit by drag in an exponential atmosphere (float64, SI).

The drag acceleration is a = -(1/2) rho(r) B |v| v, with B = C_D A / m (m**2/kg) and rho(r) = rho0 exp(-(r - r0) /
H) above the base radius r0 (the atmosphere does not turn with the body here: v is the inertial velocity). On a
circular orbit (v**2 = mu / a) Gauss's equation da/dt = 2 a**2 v . f / mu gives

    da/dt = -B rho(a) sqrt(mu a),

and the time to decay from a0 to a is t = int_a^a0 da' / (B rho(a') sqrt(mu a')), in closed form with Dawson's
integral: with S(x) = sum_k (2k - 1)!! / (2 x)**k (its asymptotic series, x = a / H),

    t = H / (B rho(a0) sqrt(mu a0)) [S(a0 / H) - sqrt(a0 / a) exp(-(a0 - a) / H) S(a / H)].

The series converges to round-off for a / H >= MIN_RADIUS_OVER_SCALE_HEIGHT (an atmosphere thin beside the orbit,
which the exponential model needs anyway). The closed form assumes the orbit stays circular while it shrinks: the
decay in one revolution, 2 pi B rho(a) a**2, must be small beside H. Its ratio to H is the model's relative error
order; where it reaches 1 (`breakdown_radius`) the orbit spirals in within a revolution and the form stops holding.
"""

import numpy as np
from numpy.typing import ArrayLike

from orbits.core.errors import ConvergenceError, OrbitDomainError

#: the smallest a / H for which S(a / H) is summed to round-off by SERIES_TERMS terms
MIN_RADIUS_OVER_SCALE_HEIGHT = 50.0
#: terms of S: at a / H = 50 the 30th is 3e-20 of the first
SERIES_TERMS = 30


def density(r: ArrayLike, rho0: ArrayLike, base: ArrayLike, scale_height: ArrayLike) -> np.ndarray:
    """rho = rho0 exp(-(r - r0) / H) (kg/m**3) at radius r (m)."""
    return np.asarray(rho0, dtype=float) * np.exp(-(np.asarray(r, dtype=float) - base) / scale_height)


def decay_rate(a: ArrayLike, mu: ArrayLike, b: ArrayLike, rho0: ArrayLike, base: ArrayLike,
               scale_height: ArrayLike) -> np.ndarray:
    """da/dt = -B rho(a) sqrt(mu a) (m/s) of a circular orbit of radius a (m); B = C_D A / m (m**2/kg)."""
    a = np.asarray(a, dtype=float)
    return -np.asarray(b, dtype=float) * density(a, rho0, base, scale_height) * np.sqrt(mu * a)


def decay_per_revolution(a: ArrayLike, b: ArrayLike, rho0: ArrayLike, base: ArrayLike,
                         scale_height: ArrayLike) -> np.ndarray:
    """|da| in one revolution, 2 pi B rho(a) a**2 (m): divided by H, the closed form's relative error order."""
    a = np.asarray(a, dtype=float)
    return 2.0 * np.pi * np.asarray(b, dtype=float) * density(a, rho0, base, scale_height) * a * a


def _dawson_series(x):
    """S(x) = sum_(k >= 0) (2k - 1)!! / (2x)**k (the first term 1), for x >= MIN_RADIUS_OVER_SCALE_HEIGHT."""
    term = np.ones_like(x)
    total = np.ones_like(x)
    for k in range(1, SERIES_TERMS):
        term = term * (2 * k - 1) / (2.0 * x)
        total = total + term
    return total


def _check_thin(a, scale_height):
    """a / H, checked to be at least MIN_RADIUS_OVER_SCALE_HEIGHT."""
    ratio = np.asarray(np.asarray(a, dtype=float) / scale_height)
    bad = ~(ratio >= MIN_RADIUS_OVER_SCALE_HEIGHT)
    if np.any(bad):
        raise OrbitDomainError(f"orbit radius / scale height = {float(ratio[bad].flat[0]):.4g} is below "
                               f"{MIN_RADIUS_OVER_SCALE_HEIGHT:g}: the atmosphere must be thin beside the orbit")
    return ratio


def decay_time(a0: ArrayLike, a: ArrayLike, mu: ArrayLike, b: ArrayLike, rho0: ArrayLike, base: ArrayLike,
               scale_height: ArrayLike) -> np.ndarray:
    """Time (s) for a circular orbit to shrink from a0 to a <= a0 (m), the Dawson closed form of the module
    docstring; exact within the model to a few ulp (tests/core/test_drag.py, against mpmath quadrature)."""
    a0 = np.asarray(a0, dtype=float)
    a = np.asarray(a, dtype=float)
    x0, x = _check_thin(a0, scale_height), _check_thin(a, scale_height)
    scale = scale_height / (np.asarray(b, dtype=float) * density(a0, rho0, base, scale_height) * np.sqrt(mu * a0))
    return scale * (_dawson_series(x0) - np.sqrt(a0 / a) * np.exp(-(a0 - a) / scale_height) * _dawson_series(x))


def radius_after(t: ArrayLike, a0: ArrayLike, mu: ArrayLike, b: ArrayLike, rho0: ArrayLike, base: ArrayLike,
                 scale_height: ArrayLike) -> np.ndarray:
    """Radius a (m) a time t >= 0 (s) after a0: decay_time(a0, a) = t solved by Newton's method from a0.

    decay_time is decreasing and concave in a, so every Newton step (an Euler step at the current rate) lands
    above the root and the iteration climbs down to it monotonically. The caller keeps t below the lifetime."""
    t = np.asarray(t, dtype=float)
    a0 = np.asarray(a0, dtype=float)
    a = np.broadcast_to(a0, np.broadcast_shapes(t.shape, a0.shape)).copy()
    for _ in range(200):
        miss = decay_time(a0, a, mu, b, rho0, base, scale_height) - t
        step = -miss * decay_rate(a, mu, b, rho0, base, scale_height)  # Newton: d time / da = 1 / (da/dt)
        a = a + step
        if np.all(np.abs(step) <= 4e-16 * a):
            return a
    raise ConvergenceError("the decay-radius iteration did not converge in 200 Newton steps")


def breakdown_radius(mu: ArrayLike, b: ArrayLike, rho0: ArrayLike, base: ArrayLike,
                     scale_height: ArrayLike, start: ArrayLike) -> np.ndarray:
    """Radius (m) where the decay in one revolution equals the scale height, 2 pi B rho(a) a**2 = H, found by
    Newton's method on ln(2 pi B rho(a) a**2 / H) from `start` (m); below it the closed form does not hold."""
    a = np.asarray(start, dtype=float).copy()
    for _ in range(100):
        g = np.log(decay_per_revolution(a, b, rho0, base, scale_height) / scale_height)
        slope = 2.0 / a - 1.0 / scale_height
        step = -g / slope
        a = a + step
        if np.all(np.abs(step) <= 4e-16 * a):
            return a
    raise ConvergenceError("the breakdown-radius iteration did not converge in 100 Newton steps")
