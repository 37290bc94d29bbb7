"""Section XXII of the notes: two finite masses m1, m2 moving about their centre of mass (CM).

Float64 arrays in SI units (masses in kg, or gravitational parameters G m in m**3/s**2 wherever only their
ratio enters; p in m; times in s; angles in rad); everything broadcasts.

Labels: star 1 (mass m1) is the notes' M and star 2 (mass m2) the notes' m, so the mass fraction
mu = m2 / (m1 + m2) is the notes' m / (M + m) and m2 / m1 -> 0 is the fixed star of section XXI.
The relative vector r = r2 - r1 follows a Kepler orbit with parameter G (m1 + m2) (XXII.i). Star i moves on
the same conic scaled by its share s_i = m_j / (m1 + m2) of the separation (star 2 along r, star 1 opposite,
m1 |r1| = m2 |r2|), and that scaled conic is itself a Kepler orbit about a fixed centre at the CM with
parameter G m_j**3 / (m1 + m2)**2 (XXII.iii: a**3 / T**2 = G M**3 / ((m + M)**2 4 pi**2)).

Every fraction is formed from the masses themselves, never as 1 - (other fraction), and in double-double
arithmetic, so m2 / m1 = 1e-15 loses nothing (row 45 of tests/stability/EDGE_CASES.md): tests/core/test_binary.py
measures <= 0.5 ulp (correct rounding) for the fractions and the reduced mass against mpmath.
"""

import numpy as np
from numpy.typing import ArrayLike

from orbits.core import _dd
from orbits.core.errors import OrbitDomainError
from orbits.core.twobody import propagate as kepler_propagate
from orbits.core.twobody.elements import wrap_pi, wrap_two_pi

FOUR_PI_SQUARED = 4.0 * np.pi**2


def require_bound(e: ArrayLike, quantity: str) -> None:
    """Raise OrbitDomainError unless 0 <= e < 1: `quantity` exists on bound (elliptic) orbits only."""
    e = np.asarray(e, dtype=float)
    bad = ~((e >= 0) & (e < 1))
    if np.any(bad):
        value = float(e[bad].flat[0])
        raise OrbitDomainError(
            f"{quantity} needs a bound orbit: eccentricity e = {value!r} is outside the allowed range [0, 1)"
        )


def _fraction(m, total):
    """m / (m1 + m2) as a double-double, with the sum `total` kept exact (a double-double from two_sum)."""
    m = np.asarray(m, dtype=float)
    return _dd.div((m, np.zeros_like(m)), total)


def mass_fractions(m1: ArrayLike, m2: ArrayLike) -> tuple[float | np.ndarray, float | np.ndarray]:
    """(x1, x2) = (m1 / (m1 + m2), m2 / (m1 + m2)) (dimensionless), each within 0.5 ulp (plus 2**-100 relative).

    The sum is kept exact in double-double arithmetic, so neither fraction is ever formed as 1 - the other.
    x2 is the notes' mu = m / (M + m); star 1 sits at x2 |r| from the CM and star 2 at x1 |r| (XXII.i, mr = MR).
    Masses or parameters G m up to about 1e300 (the Veltkamp split of orbits.core._dd).
    """
    total = _dd.two_sum(np.asarray(m1, dtype=float), np.asarray(m2, dtype=float))
    return _fraction(m1, total)[0], _fraction(m2, total)[0]


def reduced_mass(m1: ArrayLike, m2: ArrayLike) -> float | np.ndarray:
    """m1 m2 / (m1 + m2) = m1 x2 (kg, or m**3/s**2 for G m inputs), in double-double: within 0.5 ulp (plus
    2**-100 relative) and free of the overflow of m1 m2."""
    m1 = np.asarray(m1, dtype=float)
    total = _dd.two_sum(m1, np.asarray(m2, dtype=float))
    return _dd.mul((m1, np.zeros_like(m1)), _fraction(m2, total))[0]


def star_parameter(gm_other: ArrayLike, gm_total: ArrayLike) -> float | np.ndarray:
    """G m_j**3 / (m1 + m2)**2 = G m_j x_j**2 (m**3/s**2): the fixed-centre parameter of star i's orbit about
    the CM (XXII.iii); m_j is the other star's mass."""
    share = gm_other / gm_total
    return gm_other * share * share


def semi_major_axis_from_period(period: ArrayLike, mu: ArrayLike) -> float | np.ndarray:
    """a = (mu T**2 / (4 pi**2))**(1/3) = cbrt(mu (T / (2 pi))**2) (m) of a Kepler orbit of period T (s) with
    parameter mu (m**3/s**2): Kepler's third law solved for a (XXI.iii, XXII.iii)."""
    return _dd.cbrt(mu * (period / (2.0 * np.pi)) ** 2)


def kepler_constant(mu: ArrayLike) -> float | np.ndarray:
    """a**3 / T**2 = mu / (4 pi**2) (m**3/s**2), Kepler's third law (XXII.iii).

    With mu = G (m1 + m2) it is the relative orbit's (a + q)**3 / T**2; with star_parameter it is each star's
    a**3 / T**2 = G M**3 / ((m + M)**2 4 pi**2) and q**3 / T**2 = G m**3 / ((m + M)**2 4 pi**2).
    """
    return mu / FOUR_PI_SQUARED


def star_angles(e: ArrayLike, argp: ArrayLike, nu: ArrayLike, opposite: ArrayLike) -> tuple[np.ndarray, np.ndarray]:
    """(omega, nu) (rad) of a star's orbit about the CM from the relative orbit's omega and nu.

    Star 2 (opposite=False) moves along r and keeps them. Star 1 (opposite=True) moves along -r: its
    eccentricity vector is -e_rel, so omega + pi; when e = 0 omega stays 0 (the convention of
    orbits.core.twobody.elements) and the argument of latitude nu takes the pi instead. Returns omega in [0, 2 pi)
    and nu in (-pi, pi].
    """
    circular = np.asarray(e) == 0
    return (
        wrap_two_pi(argp + np.where(opposite & ~circular, np.pi, 0.0)),
        wrap_pi(nu + np.where(opposite & circular, np.pi, 0.0)),
    )


def barycentric_states(
    r: ArrayLike, v: ArrayLike, x1: ArrayLike, x2: ArrayLike
) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    """(r1, v1, r2, v2) (m, m/s) about the CM from the relative state r = r2 - r1, v = v2 - v1 (XXII.i):
    r1 = -x2 r, r2 = x1 r and likewise for v; x1, x2 from mass_fractions, shape (...), vectors (..., 3)."""
    x1, x2 = np.asarray(x1)[..., None], np.asarray(x2)[..., None]
    return -x2 * r, -x2 * v, x1 * r, x1 * v


def center_of_mass(r1: ArrayLike, r2: ArrayLike, x1: ArrayLike, x2: ArrayLike) -> np.ndarray:
    """x1 r1 + x2 r2 (m, or m/s for velocities): the CM (or its velocity) of the pair, vectors (..., 3)."""
    return np.asarray(x1)[..., None] * r1 + np.asarray(x2)[..., None] * r2


def propagate(
    r: ArrayLike, v: ArrayLike, com_r: ArrayLike, com_v: ArrayLike, gm1: ArrayLike, gm2: ArrayLike, dt: ArrayLike
) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    """(r1, v1, r2, v2) (m, m/s) of both stars a time dt (s) later, in the frame where the CM is at com_r (m)
    moving with com_v (m/s) at dt = 0 (zeros: the CM frame).

    The relative state r, v (m, m/s) goes through the universal-variable propagator with G (m1 + m2)
    (orbits.core.twobody.propagate: 1e-12 relative over 1e3 periods), is split by barycentric_states and the CM
    drift com_r + com_v dt is added. Broadcasts the batch shapes of r, gm1, gm2 and dt.
    """
    r_rel, v_rel = kepler_propagate.propagate(r, v, gm1 + gm2, dt)
    x1, x2 = mass_fractions(gm1, gm2)
    dt = np.asarray(dt, dtype=float)[..., None]
    r1, v1, r2, v2 = barycentric_states(r_rel, v_rel, x1, x2)
    drift = com_r + com_v * dt
    return r1 + drift, v1 + com_v, r2 + drift, v2 + com_v


# ---- what an observer measures: the orbit on the sky and the radial velocities ------------------------------
#
# The sky frame is that of visual and spectroscopic binaries (Thiele-Innes): x toward the north, y toward the
# east, z along the line of sight AWAY from the observer, so that a radial velocity dz/dt > 0 is a recession
# (a redshift). The elements i, Omega, omega of the relative orbit r = r2 - r1 (star 2 about star 1) are read
# in that frame by orbits.core.twobody.elements: Omega is the position angle of the ascending node (where star 2
# recedes), omega star 2's argument of periastron from it, and i < 90 deg means the position angle of star 2
# increases (north through east: counterclockwise on a sky drawn north up, east left).


def radial_velocity_semi_amplitude(a: ArrayLike, period: ArrayLike, inc: ArrayLike, e: ArrayLike) -> np.ndarray:
    """K = 2 pi a sin i / (P sqrt(1 - e**2)) (m/s) of an orbit of semi-major axis a (m) and period P (s) seen at
    inclination i (rad), 0 <= e < 1: half the peak-to-peak line-of-sight velocity.

    With a star's semi-major axis about the centre of mass (a_i = m_j a / (m1 + m2)) it is that star's K_i; with
    the relative a it is K1 + K2. sqrt(1 - e**2) is formed as sqrt((1 - e)(1 + e)).
    """
    e = np.asarray(e, dtype=float)
    require_bound(e, "a radial-velocity semi-amplitude")
    return 2.0 * np.pi * a * np.sin(inc) / (period * np.sqrt((1.0 - e) * (1.0 + e)))


def radial_velocity(k: ArrayLike, e: ArrayLike, argp: ArrayLike, nu: ArrayLike) -> np.ndarray:
    """v_z = K (cos(omega + nu) + e cos omega) (m/s, > 0 receding) of a body of semi-amplitude K (m/s) at true
    anomaly nu with argument of periastron omega (rad): the line-of-sight component of the Kepler velocity
    (star 1's omega is star 2's + pi, so its curve is -K1 / K2 times star 2's)."""
    return k * (np.cos(argp + nu) + e * np.cos(argp))


def mass_function_parameter(period: ArrayLike, k: ArrayLike, e: ArrayLike) -> np.ndarray:
    """G f(M) = P K**3 (1 - e**2)**(3/2) / (2 pi) (m**3/s**2) from one star's period P (s) and semi-amplitude K
    (m/s): G (m_j sin i)**3 / (m1 + m2)**2 for the other star's mass m_j (the mass function times G)."""
    e = np.asarray(e, dtype=float)
    require_bound(e, "a mass function")
    one_minus_e2 = (1.0 - e) * (1.0 + e)
    return period * k**3 * one_minus_e2 * np.sqrt(one_minus_e2) / (2.0 * np.pi)


def companion_parameter(gm_function: ArrayLike, gm1: ArrayLike, sin_i: ArrayLike = 1.0) -> np.ndarray:
    """G m2 (m**3/s**2) solving the cubic (m2 sin i)**3 = f(M) (m1 + m2)**2, from G f(M) and G m1 (m**3/s**2):
    the companion's mass from the mass function, the minimum mass for sin i = 1.

    The cubic has exactly one positive root (one sign change). With q = m2 / m1 and phi = f / (m1 sin**3 i) it is
    h(s) = 3 s - 2 ln(1 + e**s) - ln phi = 0 in s = ln q; h rises (h' in (1, 3]) and is concave, so Newton's
    method from s = ln(phi) / 3 (where h <= 0) climbs monotonically to the root. Two last Newton steps on the
    relative residual R = (q / (1 + q))**2 q / phi - 1 (whose rounding is a few ulp, where ln phi's is ulp(ln phi))
    polish q. Within 2 ulp of mpmath's root of the cubic (measured 1.2) over phi from 1e-30 to 1e30
    (tests/core/test_binary.py).
    """
    gm_function, gm1, sin_i = np.broadcast_arrays(*(np.asarray(x, dtype=float) for x in (gm_function, gm1, sin_i)))
    phi = gm_function / gm1 / sin_i**3
    log_phi = np.log(phi)
    s = log_phi / 3.0
    for _ in range(100):
        q = np.exp(s)
        step = (3.0 * s - 2.0 * np.log1p(q) - log_phi) / (3.0 - 2.0 * q / (1.0 + q))
        s = s - step
        if np.all(np.abs(step) <= 1e-12):
            break
    q = np.exp(s)
    for _ in range(2):
        share = q / (1.0 + q)
        residual = share * share * (q / phi) - 1.0
        q = q - q * residual / (3.0 - 2.0 * share)  # d ln(q**3 / (1 + q)**2) / d ln q = 3 - 2 q / (1 + q)
    return gm1 * q
