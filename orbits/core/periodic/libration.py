"""First guesses for the periodic orbits about the collinear points: the linearised planar and vertical oscillations,
and Richardson's third-order halo orbit (D. L. Richardson, "Analytic construction of periodic orbits about the
collinear points", Celestial Mechanics 22, 241-253, 1980).

Local coordinates about a collinear point L: state = L + gamma (xi, eta, zeta) in the rotating frame of
orbits.core.threebody.lagrange (xi along +x for all three points), gamma the distance from L to the nearer primary
(L1, L2:
the secondary; L3: the primary), time unchanged (n = 1). The gravity of the primaries expands in Legendre
polynomials, sum_n c_n rho**n P_n(xi / rho), with

    L1: c_n = (mu + (-1)**n (1 - mu) gamma**(n+1) / (1 - gamma)**(n+1)) / gamma**3,
    L2: c_n = (-1)**n (mu + (1 - mu) gamma**(n+1) / (1 + gamma)**(n+1)) / gamma**3,
    L3: c_n = (1 - mu + mu gamma**(n+1) / (1 + gamma)**(n+1)) / gamma**3,

so that xi'' - 2 eta' - (1 + 2 c2) xi = d/dxi sum_(n>=3) c_n rho**n P_n, and likewise for eta and zeta. The linear
motion is a saddle, an in-plane centre of frequency lambda (lambda**4 + (c2 - 2) lambda**2 - (c2 - 1)(1 + 2 c2) = 0)
with eta / xi amplitude ratio k = (lambda**2 + 1 + 2 c2) / (2 lambda), and a vertical centre of frequency sqrt(c2).

Richardson's Lindstedt-Poincare solution to third order in the amplitudes Ax, Az (units of gamma) locks the two
frequencies: l1 Ax**2 + l2 Az**2 + lambda**2 - c2 = 0, and runs at frequency lambda (1 + s1 Ax**2 + s2 Az**2). Its
series is formally third order, but along a halo family no order in the amplitude can be observed: the frequency
lock keeps Ax near its least value (0.10 to 0.18 gamma about the Earth-Moon and Sun-Earth L1 and L2), so A =
sqrt(Ax**2 + Az**2) / gamma never tends to zero. What holds, and tests/core/test_periodic_core.py measures, is a
bound over Az = 0.01 .. 0.3 gamma: the corrected halo through the same crossing has a period within 4 A**4 of
Richardson's (measured 3.78 A**4) and a state within 10 A**3 (measured 9.1 A**3). Its class (delta = +1 or -1)
sets which side of the x-y plane the orbit bulges to.
"""

import math
from dataclasses import dataclass

import numpy as np

from orbits.core.errors import OrbitDomainError
from orbits.core.threebody import lagrange


def collinear_index(point: str) -> int:
    """0, 1, 2 for L1, L2, L3; OrbitDomainError naming the collinear points otherwise."""
    k = lagrange.point_index(point)
    if k > 2:
        raise OrbitDomainError(f"{point} is not a collinear point: the families about it start at L1, L2 or L3 "
                               f"(L4 and L5 have no saddle and no halo, Lyapunov or vertical families here)")
    return k


def distance_to_nearer_primary(mu: float, point: str) -> float:
    """gamma (units of r): L1 and L2 from the secondary, L3 from the primary."""
    rho_1, rho_2, s_3 = lagrange.collinear_offsets(mu)
    return float((rho_1, rho_2, s_3)[collinear_index(point)])


def legendre_coefficient(mu: float, point: str, n: int) -> float:
    """c_n of the Legendre expansion about a collinear point (module docstring), dimensionless."""
    gamma = distance_to_nearer_primary(mu, point)
    k = collinear_index(point)
    if k == 0:
        value = mu + (-1) ** n * (1.0 - mu) * (gamma / (1.0 - gamma)) ** (n + 1)
    elif k == 1:
        value = (-1) ** n * (mu + (1.0 - mu) * (gamma / (1.0 + gamma)) ** (n + 1))
    else:
        value = 1.0 - mu + mu * (gamma / (1.0 + gamma)) ** (n + 1)
    return value / gamma**3


@dataclass(frozen=True)
class Linearisation:
    """The linear motion about a collinear point: in-plane frequency `planar` (lambda), vertical frequency
    `vertical` (sqrt(c2)), amplitude ratio `k` = eta / xi of the in-plane mode, and c2 (units of n)."""

    point: str
    gamma: float
    position: float
    c2: float
    planar: float
    vertical: float
    k: float


def linearisation(mu: float, point: str) -> Linearisation:
    """The Linearisation of the motion about `point` (L1, L2 or L3)."""
    k = collinear_index(point)
    c2 = legendre_coefficient(mu, point, 2)
    planar = math.sqrt(0.5 * (2.0 - c2 + math.sqrt(9.0 * c2 * c2 - 8.0 * c2)))
    ratio = (planar * planar + 1.0 + 2.0 * c2) / (2.0 * planar)
    return Linearisation(point, distance_to_nearer_primary(mu, point), float(lagrange.positions(mu)[k, 0]), c2,
                         planar, math.sqrt(c2), ratio)


def planar_guess(mu: float, point: str, ax: float) -> tuple[np.ndarray, float]:
    """(state at the crossing nearer the primary-side, half period) of the linear planar oscillation of x amplitude
    ax (units of r): xi = -ax cos(lambda t), eta = k ax sin(lambda t)."""
    lin = linearisation(mu, point)
    state = np.array([lin.position - ax, 0.0, 0.0, 0.0, lin.k * ax * lin.planar, 0.0])
    return state, math.pi / lin.planar


def vertical_guess(mu: float, point: str, az: float) -> tuple[np.ndarray, float]:
    """(state on the x axis, half period) of the linear vertical oscillation of z amplitude az (units of r):
    zeta = az sin(sqrt(c2) t), crossing the x axis going up at t = 0 and down at half the period."""
    lin = linearisation(mu, point)
    return np.array([lin.position, 0.0, 0.0, 0.0, 0.0, az * lin.vertical]), math.pi / lin.vertical


@dataclass(frozen=True)
class Richardson:
    """Richardson's third-order halo orbit about a collinear point for amplitude az (units of r) and class
    `delta` (+1 or -1): the coefficients (dimensionless), the locked ax (units of r), its period (units of 1 / n),
    and its states at any times."""

    mu: float
    point: str
    az: float
    delta: float
    ax: float
    period: float
    coefficients: dict

    def states(self, t) -> np.ndarray:
        """Rotating-frame states (..., 6) at times t (units of 1 / n) from the crossing where zeta = delta Az."""
        c = self.coefficients
        lin = c["linearisation"]
        gamma = lin.gamma
        ax, az, d = self.ax / gamma, self.az / gamma, self.delta
        rate = 2.0 * math.pi / self.period
        tau = rate * np.asarray(t, dtype=float)
        x1, x2, x3 = -ax, c["a23"] * ax**2 - c["a24"] * az**2, c["a31"] * ax**3 - c["a32"] * ax * az**2
        y1, y2, y3 = lin.k * ax, c["b21"] * ax**2 - c["b22"] * az**2, c["b31"] * ax**3 - c["b32"] * ax * az**2
        z1, z2, z3 = d * az, d * c["d21"] * ax * az, d * (c["d32"] * az * ax**2 - c["d31"] * az**3)
        x0 = c["a21"] * ax**2 + c["a22"] * az**2
        cos1, cos2, cos3 = np.cos(tau), np.cos(2.0 * tau), np.cos(3.0 * tau)
        sin1, sin2, sin3 = np.sin(tau), np.sin(2.0 * tau), np.sin(3.0 * tau)
        xi = x0 + x1 * cos1 + x2 * cos2 + x3 * cos3
        eta = y1 * sin1 + y2 * sin2 + y3 * sin3
        zeta = z1 * cos1 + z2 * (cos2 - 3.0) + z3 * cos3
        dxi = -rate * (x1 * sin1 + 2.0 * x2 * sin2 + 3.0 * x3 * sin3)
        deta = rate * (y1 * cos1 + 2.0 * y2 * cos2 + 3.0 * y3 * cos3)
        dzeta = -rate * (z1 * sin1 + 2.0 * z2 * sin2 + 3.0 * z3 * sin3)
        local = np.stack([xi, eta, zeta, dxi, deta, dzeta], axis=-1) * gamma
        return local + np.array([lin.position, 0.0, 0.0, 0.0, 0.0, 0.0])


def richardson_coefficients(mu: float, point: str) -> dict:
    """Richardson's coefficients a21 ... d32, s1, s2, l1, l2 and Delta = lambda**2 - c2 about a collinear point."""
    lin = linearisation(mu, point)
    c2, c3, c4 = (legendre_coefficient(mu, point, n) for n in (2, 3, 4))
    lam, k = lin.planar, lin.k
    lam2, k2 = lam * lam, k * k
    d1 = 3.0 * lam2 / k * (k * (6.0 * lam2 - 1.0) - 2.0 * lam)
    d2 = 8.0 * lam2 / k * (k * (11.0 * lam2 - 1.0) - 2.0 * lam)
    a21 = 3.0 * c3 * (k2 - 2.0) / (4.0 * (1.0 + 2.0 * c2))
    a22 = 3.0 * c3 / (4.0 * (1.0 + 2.0 * c2))
    a23 = -3.0 * c3 * lam / (4.0 * k * d1) * (3.0 * k**3 * lam - 6.0 * k * (k - lam) + 4.0)
    a24 = -3.0 * c3 * lam / (4.0 * k * d1) * (2.0 + 3.0 * k * lam)
    b21 = -3.0 * c3 * lam / (2.0 * d1) * (3.0 * k * lam - 4.0)
    b22 = 3.0 * c3 * lam / d1
    d21 = -c3 / (2.0 * lam2)
    a31 = (-9.0 * lam / (4.0 * d2) * (4.0 * c3 * (k * a23 - b21) + k * c4 * (4.0 + k2))
           + (9.0 * lam2 + 1.0 - c2) / (2.0 * d2) * (3.0 * c3 * (2.0 * a23 - k * b21) + c4 * (2.0 + 3.0 * k2)))
    a32 = (-9.0 * lam / (4.0 * d2) * (4.0 * c3 * (k * a24 - b22) + k * c4)
           - 3.0 / (2.0 * d2) * (9.0 * lam2 + 1.0 - c2) * (c3 * (k * b22 + d21 - 2.0 * a24) - c4))
    b31 = 3.0 / (8.0 * d2) * (8.0 * lam * (3.0 * c3 * (k * b21 - 2.0 * a23) - c4 * (2.0 + 3.0 * k2))
                              + (9.0 * lam2 + 1.0 + 2.0 * c2) * (4.0 * c3 * (k * a23 - b21) + k * c4 * (4.0 + k2)))
    b32 = (9.0 * lam * (c3 * (k * b22 + d21 - 2.0 * a24) - c4)
           + 3.0 / 8.0 * (9.0 * lam2 + 1.0 + 2.0 * c2) * (4.0 * c3 * (k * a24 - b22) + k * c4)) / d2
    d31 = 3.0 / (64.0 * lam2) * (4.0 * c3 * a24 + c4)
    d32 = 3.0 / (64.0 * lam2) * (4.0 * c3 * (a23 - d21) + c4 * (4.0 + k2))
    denominator = 2.0 * lam * (lam * (1.0 + k2) - 2.0 * k)
    s1 = (1.5 * c3 * (2.0 * a21 * (k2 - 2.0) - a23 * (k2 + 2.0) - 2.0 * k * b21)
          - 0.375 * c4 * (3.0 * k2 * k2 - 8.0 * k2 + 8.0)) / denominator
    s2 = (1.5 * c3 * (2.0 * a22 * (k2 - 2.0) + a24 * (k2 + 2.0) + 2.0 * k * b22 + 5.0 * d21)
          + 0.375 * c4 * (12.0 - k2)) / denominator
    l1 = -1.5 * c3 * (2.0 * a21 + a23 + 5.0 * d21) - 0.375 * c4 * (12.0 - k2) + 2.0 * lam2 * s1
    l2 = 1.5 * c3 * (a24 - 2.0 * a22) + 1.125 * c4 + 2.0 * lam2 * s2
    return {"linearisation": lin, "c2": c2, "c3": c3, "c4": c4, "a21": a21, "a22": a22, "a23": a23, "a24": a24,
            "b21": b21, "b22": b22, "d21": d21, "a31": a31, "a32": a32, "b31": b31, "b32": b32, "d31": d31,
            "d32": d32, "s1": s1, "s2": s2, "l1": l1, "l2": l2, "delta": lam2 - c2}


def richardson_halo(mu: float, point: str, az: float, northern: bool = True) -> Richardson:
    """Richardson's third-order halo orbit of z amplitude az (units of r) about L1 or L2, bulging north (+z, along
    the binary's spin) or south. Its x amplitude follows from the frequency lock l1 Ax**2 + l2 Az**2 + Delta = 0."""
    if collinear_index(point) > 1:
        raise OrbitDomainError(f"halo orbits are offered about L1 and L2, not {point}")
    c = richardson_coefficients(mu, point)
    gamma = c["linearisation"].gamma
    a = az / gamma
    ax_squared = -(c["delta"] + c["l2"] * a * a) / c["l1"]
    if not ax_squared > 0.0:
        raise OrbitDomainError(f"Richardson's frequency lock has no real x amplitude for Az = {az:.6g} r")
    ax = math.sqrt(ax_squared)
    frequency = c["linearisation"].planar * (1.0 + c["s1"] * ax_squared + c["s2"] * a * a)
    # the zeta offset d21 Ax Az (cos 2 tau - 3) pushes the orbit to the side of -delta d21: choose delta for the side
    delta = -math.copysign(1.0, c["d21"]) * (1.0 if northern else -1.0)
    return Richardson(float(mu), point, float(az), delta, ax * gamma, 2.0 * math.pi / frequency, c)
