"""Secular motion of an orbit about an oblate body, and the orbit designs built on it (float64, SI, radians).

The body's field is U = -(mu / r) [1 - sum_n J_n (R / r)**n P_n(sin(latitude))], axis of symmetry z. Averaged over
one revolution, J2 turns the node, the periapsis and the mean anomaly at constant rates (first order in J2; n =
sqrt(mu / a**3), p = a (1 - e**2), k = J2 (R / p)**2):

    dOmega/dt = -(3/2) n k cos i
    domega/dt =  (3/4) n k (4 - 5 sin**2 i)
    dM/dt     =  n + (3/4) n k sqrt(1 - e**2) (2 - 3 sin**2 i)

These are rates of mean elements. Osculating elements differ from mean ones by short-period terms of relative size
O(k), and the neglected second-order terms (J2**2 and J4, which is of that size for the Earth) are O(k) relative
to the rates: a rate evaluated from osculating elements, or compared with a full integration, agrees to O(k)
relative (0.1 % for a low Earth orbit), not to round-off. The designs below solve these rates for one element:

- sun-synchronous: dOmega/dt equal to the mean Sun's motion, solved for i (or a);
- critical inclination: domega/dt = 0, sin**2 i = 4/5, i = arctan 2 (63.43 deg) or pi - arctan 2 (116.57 deg);
- frozen orbit: with J3, whose averaged term (3/2) (mu J3 R**3 / a**4) e sin i (1 - 5/4 sin**2 i) sin(omega) /
  (1 - e**2)**(5/2) couples e and omega, de/dt = domega/dt = 0 at omega = 90 or 270 deg and the e solving
  e (1 - e**2) + (q s / 2) [sin i (1 + 4 e**2) - e**2 cos**2 i (4 - 15 sin**2 i) / (sin i (4 - 5 sin**2 i))] = 0,
  q = (J3 / J2) (R / a), s = sin(omega); to leading order e = -(J3 / (2 J2)) (R / a) sin i s;
- repeat ground track: k revolutions (nodal periods, 2 pi / (dM/dt + domega/dt)) in d days (of the body's
  rotation relative to the node, 2 pi / (Omega_body - dOmega/dt)), solved for a.
"""

import numpy as np
from numpy.typing import ArrayLike

from orbits.core.errors import ConvergenceError, OrbitDomainError

#: the mean Sun's motion (rad/s), 360 deg per tropical year of 365.2421897 d (Vallado, Fundamentals of Astrodynamics
#: and Applications, 4th ed., 2013): what a sun-synchronous node follows
SUN_RATE = 2.0 * np.pi / (365.2421897 * 86_400.0)
#: the two inclinations (rad) where the periapsis stands still under J2: arctan(2) and pi - arctan(2)
CRITICAL_INCLINATIONS = (float(np.arctan(2.0)), float(np.pi - np.arctan(2.0)))


def oblateness_factor(p: ArrayLike, j2: ArrayLike, radius: ArrayLike) -> np.ndarray:
    """k = J2 (R / p)**2 (dimensionless): the size of J2's rates relative to n, and their relative accuracy."""
    return np.asarray(j2, dtype=float) * (np.asarray(radius, dtype=float) / np.asarray(p, dtype=float)) ** 2


def osculating_semi_major_axis(a: ArrayLike, e: ArrayLike, inc: ArrayLike, argp: ArrayLike, nu: ArrayLike,
                               j2: ArrayLike, radius: ArrayLike) -> np.ndarray:
    """The osculating semi-major axis (m) at true anomaly nu of the orbit whose mean elements are a, e, i, omega:
    Brouwer's (1959) first-order short-period term,

        a_osc = a [1 + g ((3 cos**2 i - 1) ((a/r)**3 - eta**-3) + 3 sin**2 i (a/r)**3 cos(2 omega + 2 nu))],

    g = (J2 / 2) (R / a)**2, eta = sqrt(1 - e**2), a/r = (1 + e cos nu) / eta**2. Its average over the mean
    anomaly is a; it leaves O(J2**2) (k**2 relative). Started from it, an integrated orbit keeps the mean a the
    rates were solved for (a repeat ground track then closes within a kilometre instead of 150 km)."""
    a, e = np.asarray(a, dtype=float), np.asarray(e, dtype=float)
    eta2 = (1.0 - e) * (1.0 + e)
    a_over_r3 = ((1.0 + e * np.cos(nu)) / eta2) ** 3
    cos2 = np.cos(inc) ** 2
    g = 0.5 * np.asarray(j2, dtype=float) * (np.asarray(radius, dtype=float) / a) ** 2
    return a * (1.0 + g * ((3.0 * cos2 - 1.0) * (a_over_r3 - eta2**-1.5)
                           + 3.0 * (1.0 - cos2) * a_over_r3 * np.cos(2.0 * (np.asarray(argp) + np.asarray(nu)))))


def _mean_motion(a, mu):
    return np.sqrt(np.asarray(mu, dtype=float) / np.asarray(a, dtype=float) ** 3)


def node_rate(a: ArrayLike, e: ArrayLike, inc: ArrayLike, mu: ArrayLike, j2: ArrayLike, radius: ArrayLike):
    """dOmega/dt = -(3/2) n J2 (R / p)**2 cos i (rad/s), first order in J2 (module docstring)."""
    e = np.asarray(e, dtype=float)
    k = oblateness_factor(np.asarray(a, dtype=float) * (1.0 - e) * (1.0 + e), j2, radius)
    return -1.5 * _mean_motion(a, mu) * k * np.cos(inc)


def periapsis_rate(a: ArrayLike, e: ArrayLike, inc: ArrayLike, mu: ArrayLike, j2: ArrayLike, radius: ArrayLike):
    """domega/dt = (3/4) n J2 (R / p)**2 (4 - 5 sin**2 i) (rad/s), first order in J2."""
    e = np.asarray(e, dtype=float)
    k = oblateness_factor(np.asarray(a, dtype=float) * (1.0 - e) * (1.0 + e), j2, radius)
    return 0.75 * _mean_motion(a, mu) * k * (4.0 - 5.0 * np.sin(inc) ** 2)


def mean_anomaly_rate(a: ArrayLike, e: ArrayLike, inc: ArrayLike, mu: ArrayLike, j2: ArrayLike, radius: ArrayLike):
    """dM/dt = n [1 + (3/4) J2 (R / p)**2 sqrt(1 - e**2) (2 - 3 sin**2 i)] (rad/s), first order in J2."""
    e = np.asarray(e, dtype=float)
    k = oblateness_factor(np.asarray(a, dtype=float) * (1.0 - e) * (1.0 + e), j2, radius)
    root = np.sqrt((1.0 - e) * (1.0 + e))
    return _mean_motion(a, mu) * (1.0 + 0.75 * k * root * (2.0 - 3.0 * np.sin(inc) ** 2))


def nodal_period(a: ArrayLike, e: ArrayLike, inc: ArrayLike, mu: ArrayLike, j2: ArrayLike, radius: ArrayLike):
    """Draconitic period 2 pi / (dM/dt + domega/dt) (s): from one ascending node to the next."""
    return 2.0 * np.pi / (mean_anomaly_rate(a, e, inc, mu, j2, radius) + periapsis_rate(a, e, inc, mu, j2, radius))


def sun_synchronous_inclination(a: ArrayLike, e: ArrayLike, mu: ArrayLike, j2: ArrayLike, radius: ArrayLike,
                                rate: ArrayLike) -> np.ndarray:
    """i (rad) whose node turns at `rate` (rad/s): cos i = -rate / ((3/2) n J2 (R / p)**2).

    Raises OrbitDomainError where |cos i| would exceed 1 (the orbit is too high or too eccentric for J2 to turn
    its node that fast), naming the largest semi-major axis that can."""
    e = np.asarray(e, dtype=float)
    a = np.asarray(a, dtype=float)
    scale = 1.5 * _mean_motion(a, mu) * oblateness_factor(a * (1.0 - e) * (1.0 + e), j2, radius)
    cosine = -np.asarray(rate, dtype=float) / scale
    bad = ~(np.abs(cosine) <= 1.0)
    if np.any(bad):
        a_bad, e_bad, limit = (float(x[bad].flat[0]) for x in np.broadcast_arrays(
            a, e, sun_synchronous_semi_major_axis(np.pi, e, mu, j2, radius, rate), bad)[:3])
        raise OrbitDomainError(
            f"no sun-synchronous orbit at a = {a_bad / 1e3:.6g} km, e = {e_bad:.6g}: J2 cannot turn its node that "
            f"fast at any inclination; at e = {e_bad:.6g} it needs a <= {limit / 1e3:.6g} km (i = 180 deg)")
    return np.arccos(cosine)


def sun_synchronous_semi_major_axis(inc: ArrayLike, e: ArrayLike, mu: ArrayLike, j2: ArrayLike, radius: ArrayLike,
                                    rate: ArrayLike) -> np.ndarray:
    """a (m) whose node turns at `rate` (rad/s) at inclination i: a**(7/2) = -(3/2) sqrt(mu) J2 R**2 cos i /
    (rate (1 - e**2)**2). Raises OrbitDomainError where i turns the node the other way (cos i rate >= 0)."""
    e = np.asarray(e, dtype=float)
    rate = np.asarray(rate, dtype=float)
    numerator = -1.5 * np.sqrt(np.asarray(mu, dtype=float)) * np.asarray(j2, dtype=float) * np.asarray(
        radius, dtype=float) ** 2 * np.cos(inc)
    ratio = numerator / (rate * ((1.0 - e) * (1.0 + e)) ** 2)
    bad = ~(ratio > 0.0)
    if np.any(bad):
        inc_bad = float(np.broadcast_to(np.asarray(inc, dtype=float), bad.shape)[bad].flat[0])
        raise OrbitDomainError(
            f"inclination i = {np.degrees(inc_bad):.6g} deg turns the node the wrong way (or not at all) for a "
            f"sun-synchronous orbit about a body with J2 > 0: it must be retrograde, i in (90, 180) deg")
    return ratio ** (2.0 / 7.0)


def frozen_eccentricity(a: ArrayLike, inc: ArrayLike, j2: ArrayLike, j3: ArrayLike, radius: ArrayLike,
                        argp: ArrayLike = 0.5 * np.pi) -> np.ndarray:
    """e of the frozen orbit (module docstring) at a (m) and i (rad) with omega = 90 or 270 deg, by Newton's method
    from the leading-order e = -(J3 / (2 J2)) (R / a) sin i sin(omega). Raises OrbitDomainError where no frozen
    e in (0, 1) exists for that omega (then the other omega has one), near the critical inclination (where J2 does
    not turn the periapsis and the frozen e is no longer small) or for an equatorial orbit."""
    inc = np.asarray(inc, dtype=float)
    sine = np.sin(inc)
    s = np.sin(np.asarray(argp, dtype=float))
    if np.any(np.abs(np.abs(s) - 1.0) > 1e-12):
        raise OrbitDomainError("a frozen orbit has omega = 90 or 270 deg (sin(omega) = +-1): de/dt vanishes only "
                               "there")
    if np.any(sine <= 1e-8):
        raise OrbitDomainError("an equatorial orbit (sin i = 0) has no frozen eccentricity: J3 does not act on it")
    q = np.asarray(j3, dtype=float) / np.asarray(j2, dtype=float) * np.asarray(radius, dtype=float) / np.asarray(
        a, dtype=float)
    drift = 4.0 - 5.0 * sine**2
    if np.any(np.abs(drift) < 1e-9):
        low, high = np.degrees(CRITICAL_INCLINATIONS)
        raise OrbitDomainError(f"no frozen orbit at the critical inclination ({low:.2f} or {high:.2f} deg): J2 does "
                               f"not turn the periapsis there, so nothing balances J3")
    curvature = np.cos(inc) ** 2 * (4.0 - 15.0 * sine**2) / (sine * drift)
    e = -0.5 * q * sine * s
    for _ in range(50):
        g = e * (1.0 - e * e) + 0.5 * q * s * (sine * (1.0 + 4.0 * e * e) - e * e * curvature)
        slope = 1.0 - 3.0 * e * e + q * s * e * (4.0 * sine - curvature)
        step = g / slope
        e = e - step
        if np.all(np.abs(step) <= 4e-16 * np.abs(e)):
            break
    else:
        raise ConvergenceError("the frozen-eccentricity iteration did not converge in 50 Newton steps")
    bad = ~((e > 0.0) & (e < 1.0)) | (np.abs(e) > 10.0 * np.abs(0.5 * q * sine) + 1e-300)
    if np.any(bad):
        raise OrbitDomainError(
            f"no frozen orbit with omega = {90 if np.all(s > 0) else 270} deg here (e would be "
            f"{float(np.broadcast_to(e, bad.shape)[bad].flat[0]):.4g}): try the other omega, or an inclination away "
            f"from the critical {np.degrees(CRITICAL_INCLINATIONS[0]):.2f} and "
            f"{np.degrees(CRITICAL_INCLINATIONS[1]):.2f} deg")
    return e


def repeat_ground_track_semi_major_axis(revolutions: ArrayLike, days: ArrayLike, e: ArrayLike, inc: ArrayLike,
                                        mu: ArrayLike, j2: ArrayLike, radius: ArrayLike,
                                        rotation_rate: ArrayLike) -> np.ndarray:
    """a (m) of an orbit that makes `revolutions` nodal periods while the body turns `days` times under its node:
    revolutions |Omega_body - dOmega/dt| = days (dM/dt + domega/dt), rotation_rate Omega_body (rad/s) the body's
    sidereal spin (negative for a body turning backwards, Venus or Uranus). Solved by fixed-point iteration on n
    from the Kepler value (contraction O(J2 (R / p)**2))."""
    ratio = np.asarray(revolutions, dtype=float) / np.asarray(days, dtype=float)
    spin = np.asarray(rotation_rate, dtype=float)
    mu = np.asarray(mu, dtype=float)
    a = np.cbrt(mu / (ratio * np.abs(spin)) ** 2)
    if np.any(~(a > np.asarray(radius, dtype=float))):
        raise OrbitDomainError("no repeat-ground-track orbit outside the body: that many revolutions a day need a "
                               "below its radius")
    for _ in range(100):
        perturbation = (mean_anomaly_rate(a, e, inc, mu, j2, radius) - _mean_motion(a, mu)
                        + periapsis_rate(a, e, inc, mu, j2, radius))
        n = ratio * np.abs(spin - node_rate(a, e, inc, mu, j2, radius)) - perturbation
        if np.any(~(n > 0.0)):
            raise OrbitDomainError("no repeat-ground-track orbit: the required mean motion is not positive (J2's "
                                   "terms outrun it: the orbit would lie deep inside the body)")
        updated = np.cbrt(mu / n**2)
        if np.all(np.abs(updated - a) <= 4e-16 * updated):
            return updated
        a = updated
    raise ConvergenceError("the repeat-ground-track iteration did not converge in 100 steps")
