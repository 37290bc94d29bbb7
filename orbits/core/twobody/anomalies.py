"""Conversions between the true anomaly nu and the mean, eccentric, hyperbolic and parabolic anomalies.

Float64 arrays, radians, broadcasting. Conventions:
- elliptic (0 <= e < 1): M = E - e sin E, tan(nu/2) = sqrt((1+e)/(1-e)) tan(E/2); nu, E, M in [-pi, pi];
- hyperbolic (e > 1): M = e sinh H - H, tan(nu/2) = sqrt((e+1)/(e-1)) tanh(H/2); |nu| < arccos(-1/e);
- parabolic (e = 1): D = tan(nu/2), Barker's W = D + D**3 / 3 plays the part of M; |nu| < pi.
The mixed-conic functions (mean_from_true, true_from_mean, time_since_periapsis) choose the branch
per element from e. Each checks its inputs (check_true_anomalies, check_eccentricities) for direct callers; the
unit-aware API, which has checked them where they entered, calls the `_unchecked` twins.
"""

import numpy as np
from numpy.typing import ArrayLike

from orbits.core.checks import broadcast, check_finite
from orbits.core.errors import OrbitDomainError
from orbits.core.twobody.elements import require_inside_asymptotes
from orbits.core.twobody.kepler import (
    eccentric_anomaly,
    hyperbolic_anomaly,
    parabolic_anomaly,
    sinh_minus_x,
    x_minus_sin,
)


def _as_arrays(**values):
    """The named values as float64 arrays broadcast together (checks.broadcast: a mismatch names them)."""
    return broadcast(**values)


def true_from_eccentric(E: ArrayLike, e: ArrayLike) -> float | np.ndarray:
    """nu = 2 atan2(sqrt(1+e) sin(E/2), sqrt(1-e) cos(E/2)) (rad), 0 <= e < 1."""
    E, e = _as_arrays(E=E, e=e)
    return 2.0 * np.arctan2(np.sqrt(1.0 + e) * np.sin(0.5 * E), np.sqrt(1.0 - e) * np.cos(0.5 * E))


def eccentric_from_true(nu: ArrayLike, e: ArrayLike) -> float | np.ndarray:
    """E = 2 atan2(sqrt(1-e) sin(nu/2), sqrt(1+e) cos(nu/2)) (rad), 0 <= e < 1."""
    nu, e = _as_arrays(nu=nu, e=e)
    return 2.0 * np.arctan2(np.sqrt(1.0 - e) * np.sin(0.5 * nu), np.sqrt(1.0 + e) * np.cos(0.5 * nu))


def mean_from_eccentric(E: ArrayLike, e: ArrayLike) -> float | np.ndarray:
    """M = E - e sin E = (1 - e) E + e (E - sin E) (rad), without cancellation near e = 1."""
    E, e = _as_arrays(E=E, e=e)
    return (1.0 - e) * E + e * x_minus_sin(E)


def true_from_hyperbolic(H: ArrayLike, e: ArrayLike) -> float | np.ndarray:
    """nu = 2 atan2(sqrt(e+1) tanh(H/2), sqrt(e-1)) (rad), e > 1 (no overflow for large H)."""
    H, e = _as_arrays(H=H, e=e)
    return 2.0 * np.arctan2(np.sqrt(e + 1.0) * np.tanh(0.5 * H), np.sqrt(e - 1.0))


def hyperbolic_from_true(nu: ArrayLike, e: ArrayLike) -> float | np.ndarray:
    """H = 2 atanh(sqrt((e-1)/(e+1)) tan(nu/2)) (rad), e > 1 and 1 + e cos nu > 0."""
    nu, e = _as_arrays(nu=nu, e=e)
    check_finite(nu, "true anomaly nu", "rad")
    require_inside_asymptotes(e, nu)
    return _hyperbolic_from_true(nu, e)


def _hyperbolic_from_true(nu, e):
    t = np.sqrt(e - 1.0) * np.sin(0.5 * nu) / (np.sqrt(e + 1.0) * np.cos(0.5 * nu))
    return 2.0 * np.arctanh(t)


def mean_from_hyperbolic(H: ArrayLike, e: ArrayLike) -> float | np.ndarray:
    """M = e sinh H - H = (e - 1) H + e (sinh H - H) (rad), without cancellation near e = 1."""
    H, e = _as_arrays(H=H, e=e)
    return (e - 1.0) * H + e * sinh_minus_x(H)


def true_from_parabolic(D: ArrayLike) -> float | np.ndarray:
    """nu = 2 atan(D) (rad) for D = tan(nu/2)."""
    return 2.0 * np.arctan(np.asarray(D, dtype=float))


def parabolic_from_true(nu: ArrayLike) -> float | np.ndarray:
    """D = tan(nu/2) for |nu| < pi; nu = +/-pi lies at infinite distance and is rejected."""
    nu = np.asarray(nu, dtype=float)
    check_finite(nu, "true anomaly nu", "rad")
    _require_finite_on_parabola(nu)
    return np.tan(0.5 * nu)


def _require_finite_on_parabola(nu):
    if np.any(np.abs(nu) >= np.pi):
        bad = nu[np.abs(nu) >= np.pi].flat[0]
        raise OrbitDomainError(
            f"true anomaly nu = {float(bad)!r} rad lies at infinite distance on a parabola; allowed |nu| < pi rad"
        )


def check_eccentricities(e: np.ndarray) -> None:
    """Raise unless every e is finite and >= 0."""
    check_finite(e, "eccentricity e", "(dimensionless)")
    if np.any(e < 0):
        raise OrbitDomainError(f"eccentricity e = {float(e[e < 0].flat[0])!r} is negative; allowed e >= 0")


def check_true_anomalies(nu: np.ndarray, e: np.ndarray) -> None:
    """Raise unless e is finite and >= 0 and nu is a finite point of its conic: |nu| < pi on a parabola, inside
    the asymptotes of a hyperbola (arrays of one shape)."""
    check_eccentricities(e)
    check_finite(nu, "true anomaly nu", "rad")
    _require_finite_on_parabola(nu[e == 1.0])
    require_inside_asymptotes(e, nu)


def mean_from_true(nu: ArrayLike, e: ArrayLike) -> np.ndarray:
    """Mean anomaly from the true anomaly for any conic: M (e != 1, rad) or Barker's W (e = 1)."""
    nu, e = _as_arrays(nu=nu, e=e)
    check_true_anomalies(nu, e)
    return mean_from_true_unchecked(nu, e)


def mean_from_true_unchecked(nu: ArrayLike, e: ArrayLike) -> np.ndarray:
    """mean_from_true for inputs that passed check_true_anomalies."""
    nu, e = _as_arrays(nu=nu, e=e)
    out = np.empty_like(nu)
    ell, par, hyp = e < 1.0, e == 1.0, e > 1.0
    out[ell] = mean_from_eccentric(eccentric_from_true(nu[ell], e[ell]), e[ell])
    d = np.tan(0.5 * nu[par])
    out[par] = d + d**3 / 3.0
    out[hyp] = mean_from_hyperbolic(_hyperbolic_from_true(nu[hyp], e[hyp]), e[hyp])
    return out


def true_from_mean(M: ArrayLike, e: ArrayLike) -> np.ndarray:
    """True anomaly (rad) from the mean anomaly M (e != 1) or Barker's W (e = 1), for any conic."""
    M, e = _as_arrays(M=M, e=e)
    check_eccentricities(e)
    out = np.empty_like(M)
    ell, par, hyp = e < 1.0, e == 1.0, e > 1.0
    out[ell] = true_from_eccentric(eccentric_anomaly(M[ell], e[ell]), e[ell])
    out[par] = true_from_parabolic(parabolic_anomaly(M[par]))
    out[hyp] = true_from_hyperbolic(hyperbolic_anomaly(M[hyp], e[hyp]), e[hyp])
    return out


def mean_motion(p: ArrayLike, e: ArrayLike, mu: ArrayLike) -> float | np.ndarray:
    """n (rad/s): sqrt(mu / |a|**3) with a = p / (1 - e**2) for e != 1, and 2 sqrt(mu / p**3) for e = 1.

    For e = 1 this is the rate of Barker's W = D + D**3 / 3 (W = n t), so t = M / n on every conic.
    """
    p, e, mu = _as_arrays(p=p, e=e, mu=mu)
    one_minus_e2 = np.abs((1.0 - e) * (1.0 + e))
    return np.where(e == 1.0, 2.0, one_minus_e2**1.5) * np.sqrt(mu / p**3)


def time_since_periapsis(nu: ArrayLike, p: ArrayLike, e: ArrayLike, mu: ArrayLike) -> float | np.ndarray:
    """t - T (s) at true anomaly nu (rad) on the conic (p in m, mu in m**3/s**2): M / n on every conic."""
    return mean_from_true(nu, e) / mean_motion(p, e, mu)


def time_since_periapsis_unchecked(nu: ArrayLike, p: ArrayLike, e: ArrayLike, mu: ArrayLike) -> float | np.ndarray:
    """time_since_periapsis for inputs that passed check_true_anomalies."""
    return mean_from_true_unchecked(nu, e) / mean_motion(p, e, mu)
