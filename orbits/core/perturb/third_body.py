"""The secular (Kozai-Lidov) oscillation of an orbit perturbed by a distant third body, quadrupole order, test
particle (float64, radians).

A test particle on (a, e, i, omega) about a mass m0, perturbed by m3 on an outer orbit (a_out, e_out), feels
after averaging over both orbits the quadrupole potential (i relative to the outer orbit's plane)

    R = C [2 + 3 e**2 - 3 sin**2 i (1 - e**2 + 5 e**2 sin**2 omega)],   C = G m3 a**2 / (8 b**3),

b = a_out sqrt(1 - e_out**2). Its time scale is tau = (m0 / m3) (b / a)**3 / n, n the inner mean motion:
de/dt = (15/8) e sqrt(1 - e**2) sin**2 i sin(2 omega) / tau. Two quantities are conserved, the Kozai constant
Theta = (1 - e**2) cos**2 i (the z-angular momentum) and W = R / C. With x = e**2 they give

    (dx/dt)**2 = Q(x) / (4 tau**2),   Q(x) = (6x - kappa) (-9x**2 + (9 - 15 Theta - kappa) x + kappa),
    kappa = 1 + W - 3 Theta,

a cubic with roots r1 <= x_min <= x_max: e oscillates between sqrt(x_min) and sqrt(x_max) with period
8 tau K(m) / sqrt(54 (x_max - r1)), m = (x_max - x_min) / (x_max - r1). From e0 -> 0 this gives
e_max = sqrt(1 - (5/3) cos**2 i0), above the critical inclination arccos(sqrt(3/5)) = 39.23 deg (and below its
supplement); nearer the plane e stays small.

The quadrupole order neglects the octupole term, relative size eps_oct = (a / a_out) e_out / (1 - e_out**2)
(zero for a circular outer orbit), the hexadecapole, (a / a_out)**2, and the double averaging, which fails at
relative order eps_sa = (a / b)**(3/2) m3 / sqrt(m0 (m0 + m3)) (the outer period over the oscillation time).
"""

import numpy as np
from numpy.typing import ArrayLike

from orbits.core.errors import OrbitDomainError
from orbits.core.mechanics.oscillations import ellipk_from_complement

#: arccos(sqrt(3/5)) (rad), 39.23 deg: above it (and below its supplement) a circular orbit's e grows
CRITICAL_INCLINATION = float(np.arctan(np.sqrt(2.0 / 3.0)))


def timescale(a: ArrayLike, mu_inner: ArrayLike, mass_ratio: ArrayLike, a_out: ArrayLike,
              e_out: ArrayLike) -> np.ndarray:
    """tau = (m0 / m3) (b / a)**3 / n (s), b = a_out sqrt(1 - e_out**2), n = sqrt(G m0 / a**3); mass_ratio is
    m3 / m0 and mu_inner G m0 (m**3/s**2)."""
    a = np.asarray(a, dtype=float)
    e_out = np.asarray(e_out, dtype=float)
    b = np.asarray(a_out, dtype=float) * np.sqrt((1.0 - e_out) * (1.0 + e_out))
    return (b / a) ** 3 / (np.asarray(mass_ratio, dtype=float) * np.sqrt(mu_inner / a**3))


def maximum_eccentricity_from_circular(inc: ArrayLike) -> np.ndarray:
    """e_max = sqrt(1 - (5/3) cos**2 i0) reached from e0 -> 0 at inclination i0 (rad); 0 where |cos i0| >=
    sqrt(3/5), the orbit staying circular."""
    cosine = np.cos(np.asarray(inc, dtype=float))
    return np.sqrt(np.maximum(1.0 - (5.0 / 3.0) * cosine * cosine, 0.0))


def kozai_constant(e: ArrayLike, inc: ArrayLike) -> np.ndarray:
    """Theta = (1 - e**2) cos**2 i, conserved by the quadrupole motion; sqrt(1 - e**2) cos i keeps its sign."""
    e = np.asarray(e, dtype=float)
    return (1.0 - e) * (1.0 + e) * np.cos(inc) ** 2


def octupole_parameter(a: ArrayLike, a_out: ArrayLike, e_out: ArrayLike) -> np.ndarray:
    """eps_oct = (a / a_out) e_out / (1 - e_out**2): the octupole term's size beside the quadrupole's."""
    e_out = np.asarray(e_out, dtype=float)
    return np.asarray(a, dtype=float) / a_out * e_out / ((1.0 - e_out) * (1.0 + e_out))


def averaging_parameter(a: ArrayLike, a_out: ArrayLike, e_out: ArrayLike, mass_ratio: ArrayLike) -> np.ndarray:
    """eps_sa = (a / b)**(3/2) q / sqrt(1 + q), q = m3 / m0: where the double average stops holding (Luo, Katz
    and Dong 2016), the relative size of the terms it drops."""
    e_out = np.asarray(e_out, dtype=float)
    b = np.asarray(a_out, dtype=float) * np.sqrt((1.0 - e_out) * (1.0 + e_out))
    q = np.asarray(mass_ratio, dtype=float)
    return (np.asarray(a, dtype=float) / b) ** 1.5 * q / np.sqrt(1.0 + q)


def _roots(e, inc, argp):
    """(r1, x_min, x_max): the roots of Q in increasing order, for the motion through (e, i, omega)."""
    e = np.asarray(e, dtype=float)
    x = e * e
    theta = kozai_constant(e, inc)
    sin2i = np.sin(inc) ** 2
    w = 2.0 + 3.0 * x - 3.0 * sin2i * (1.0 - x + 5.0 * x * np.sin(argp) ** 2)
    kappa = 1.0 + w - 3.0 * theta
    # -9 x**2 + beta x + kappa = 0, by the cancellation-free pair of formulas
    beta = 9.0 - 15.0 * theta - kappa
    root = np.sqrt(beta * beta + 36.0 * kappa)
    big = np.where(beta >= 0.0, (beta + root) / 18.0, (beta - root) / 18.0)
    with np.errstate(divide="ignore", invalid="ignore"):
        small = np.where(big != 0.0, -kappa / (9.0 * big), 0.0)
    roots = np.sort(np.stack(np.broadcast_arrays(kappa / 6.0, big, small), axis=-1), axis=-1)
    return roots[..., 0], roots[..., 1], roots[..., 2]


def eccentricity_range(e: ArrayLike, inc: ArrayLike, argp: ArrayLike) -> tuple[np.ndarray, np.ndarray]:
    """(e_min, e_max) of the quadrupole oscillation through e (> 0), i and omega (rad)."""
    _, low, high = _roots(e, inc, argp)
    return np.sqrt(np.maximum(low, 0.0)), np.sqrt(np.minimum(high, 1.0))


def oscillation_period(e: ArrayLike, inc: ArrayLike, argp: ArrayLike, tau: ArrayLike) -> np.ndarray:
    """Period (s) of e's quadrupole oscillation through (e, i, omega): 8 tau K(m) / sqrt(54 (x_max - r1)), tau
    from `timescale`. Infinite on the separatrix (e0 = 0 exactly, where the motion takes forever to leave)."""
    first, low, high = _roots(e, inc, argp)
    span = high - first
    if np.any(~(span > 0.0)):
        raise OrbitDomainError("the quadrupole motion through this (e, i, omega) does not oscillate (e = 0 and i "
                               "below the critical inclination): it has no period")
    complement = np.sqrt(np.maximum(low - first, 0.0) / span)
    with np.errstate(divide="ignore"):
        return 8.0 * np.asarray(tau, dtype=float) * np.where(
            complement > 0.0, ellipk_from_complement(np.where(complement > 0.0, complement, 1.0)), np.inf
        ) / np.sqrt(54.0 * span)
