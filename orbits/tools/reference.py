"""High-precision mpmath references (the oracle of the tests and of `orbits bench precision`).

Written directly from the mathematics, sharing no code or formula arrangement
with the float64 modules of ``orbits`` (and importing none of them).  Every
float argument is taken as its exact binary value (``mpmath.mpf(float)``); all work is done at >= 60 significant
digits, raised adaptively by the digits that cancellation near e = 1 and the
reduction of large angles cost, and every root is verified by its residual.
Results are ``mpf`` (or lists of them) carrying the full working precision;
compare them inside ``mpmath.workdps(...)`` to keep that precision.
"""

import math
from typing import TYPE_CHECKING

import mpmath
from mpmath import mp, mpf

if TYPE_CHECKING:
    from numpy.typing import ArrayLike

BASE_DPS = 60


def _lost_digits(distance_from_one):
    """Decimal digits cancelled when a quantity at this distance from 1 is formed."""
    d = abs(float(distance_from_one))
    return 0 if d >= 0.1 else math.ceil(-math.log10(max(d, 1e-300)))


def _magnitude_digits(x):
    """Decimal digits of the integer part of |x| (spent when reducing x modulo 2 pi)."""
    x = abs(float(x))
    return 0 if x < 10 else math.ceil(math.log10(x))


def _verified_root(f, lo, hi):
    """Root of the increasing function f in [lo, hi] (0 <= lo <= hi), residual-verified.

    f must return the residual relative to the equation's right-hand side, so the
    check below is a relative one (|f| <= 1e-48; the working precision is always
    >= 60 digits beyond those lost to cancellation).  The unknown is rescaled by hi
    so that the solver's absolute tolerances become relative ones even for roots
    ~1e-300.
    """
    if f(lo) >= 0:
        root = lo
    elif f(hi) <= 0:
        root = hi
    else:
        u = mpmath.findroot(lambda u: f(u * hi), (lo / hi, mpf(1)), solver="anderson", maxsteps=200)
        root = u * hi
    if not abs(f(root)) <= mpf(10) ** (12 - BASE_DPS):
        raise ArithmeticError(f"mpref root not verified: residual {f(root)}")
    return root


def _positive_cubic_root(p, w):
    """Real root x >= 0 of x**3 + p*x = w for p >= 0, w >= 0, free of cancellation."""
    if w == 0:
        return mpf(0)
    s = mpmath.sqrt(w**2 / 4 + p**3 / 27)
    a2 = mpmath.cbrt(w / 2 + s) ** 2
    return w * a2 / (a2**2 + a2 * p / 3 + p**2 / 9)


def _reduce_angle(M):
    """M - 2 pi k with k = round(M / (2 pi)), in [-pi, pi], at the working precision."""
    return M - 2 * mp.pi * mpmath.nint(M / (2 * mp.pi))


def _solve_elliptic(M, e):
    """E in [-pi, pi] with E - e sin E = M reduced, for mpf M and 0 <= e < 1."""
    Mr = _reduce_angle(M)
    m = abs(Mr)
    if m == 0:
        return mpf(0)
    # On [0, pi], g(E) = E - e sin E is increasing and convex, bounded above by the
    # cubic (1-e)E + E^3/6 (so its root is a lower bound) and below by the chord
    # through the origin; a Newton step from a lower bound overshoots the root.
    g = lambda E: (E - e * mpmath.sin(E) - m) / m
    lo = max(m, _positive_cubic_root(6 * (1 - e), 6 * m))
    newton = lo - (lo - e * mpmath.sin(lo) - m) / (1 - e * mpmath.cos(lo))
    hi = min(mp.pi, m + e, newton)
    return mpmath.sign(Mr) * _verified_root(g, min(lo, hi), hi)


def _solve_hyperbolic(M, e):
    """H with e sinh H - H = M, for mpf M and e > 1."""
    m = abs(M)
    if m == 0:
        return mpf(0)
    # On [0, inf), h(H) = e sinh H - H is increasing and convex and exceeds
    # (e-1)H + H^3/6, (e-1)H and e(exp(H) - 1)/2 - H: each gives an upper bound.
    h = lambda H: (e * mpmath.sinh(H) - H - m) / m
    cubic = _positive_cubic_root(6 * (e - 1), 6 * m)
    hi = min(cubic, m / (e - 1), mpmath.log1p(2 * (m + cubic) / e))
    lo = mpmath.asinh(m / e)
    return mpmath.sign(M) * _verified_root(h, min(lo, hi), hi)


def _solve_barker(W):
    """D with D + D^3/3 = W, for mpf W."""
    w = abs(W)
    if w == 0:
        return mpf(0)
    # D + D^3/3 is increasing and convex on [0, inf) with value 0 at 0, so
    # D <= min(W, (3W)^(1/3)) and the chord from the origin gives a lower bound.
    b = lambda D: (D + D**3 / 3 - w) / w
    hi = min(w, mpmath.cbrt(3 * w))
    lo = w * hi / (hi + hi**3 / 3)
    return mpmath.sign(W) * _verified_root(b, lo, hi)


def kepler_E(M: float, e: float) -> mpf:
    """Eccentric anomaly E in [-pi, pi] solving E - e sin E = M - 2 pi round(M / 2 pi), 0 <= e < 1."""
    if not 0 <= e < 1:
        raise ValueError(f"kepler_E needs 0 <= e < 1, got e={e!r}")
    with mp.workdps(BASE_DPS + _lost_digits(1 - e) + _magnitude_digits(M)):
        return _solve_elliptic(mpf(M), mpf(e))


def kepler_H(M: float, e: float) -> mpf:
    """Hyperbolic anomaly H solving e sinh H - H = M, e > 1."""
    if not e > 1:
        raise ValueError(f"kepler_H needs e > 1, got e={e!r}")
    with mp.workdps(BASE_DPS + _lost_digits(e - 1)):
        return _solve_hyperbolic(mpf(M), mpf(e))


def barker_D(W: float) -> mpf:
    """D = tan(nu / 2) solving Barker's equation D + D^3 / 3 = W."""
    with mp.workdps(BASE_DPS):
        return _solve_barker(mpf(W))


def true_from_E(E: float | mpf, e: float) -> mpf:
    """True anomaly nu on the same revolution as E: tan(nu/2) = sqrt((1+e)/(1-e)) tan(E/2)."""
    with mp.workdps(BASE_DPS + _magnitude_digits(E)):
        E, e = mpf(E), mpf(e)
        k = mpmath.nint(E / (2 * mp.pi))
        half = (E - 2 * mp.pi * k) / 2
        nu = 2 * mpmath.atan2(mpmath.sqrt(1 + e) * mpmath.sin(half), mpmath.sqrt(1 - e) * mpmath.cos(half))
        return nu + 2 * mp.pi * k


def true_from_H(H: float | mpf, e: float) -> mpf:
    """True anomaly nu of a hyperbola: tan(nu/2) = sqrt((e+1)/(e-1)) tanh(H/2)."""
    with mp.workdps(BASE_DPS):
        H, e = mpf(H), mpf(e)
        return 2 * mpmath.atan(mpmath.sqrt((e + 1) / (e - 1)) * mpmath.tanh(H / 2))


def _dot(a, b):
    return sum(x * y for x, y in zip(a, b))


def _cross(a, b):
    return [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]


def _conic(r0, v0, mu):
    """(|r0|, r0.v0, specific energy, |h|^2, eccentricity) of the state, at the working precision."""
    r, rv, v2 = mpmath.sqrt(_dot(r0, r0)), _dot(r0, v0), _dot(v0, v0)
    evec = [((v2 - mu / r) * x - rv * y) / mu for x, y in zip(r0, v0)]
    h = _cross(r0, v0)
    return r, rv, v2 / 2 - mu / r, _dot(h, h), mpmath.sqrt(_dot(evec, evec))


def _lagrange_coefficients(r0, v0, mu, t):
    """(f, g, fdot, gdot) of the Kepler orbit through (r0, v0), at the working precision."""
    r, rv, energy, h2, e = _conic(r0, v0, mu)
    if energy == 0:  # parabola: tan(nu/2) = D, universal anomaly chi = sqrt(p) (D - D0)
        p = h2 / mu
        D0 = rv / mpmath.sqrt(mu * p)
        D = _solve_barker(D0 + D0**3 / 3 + 2 * mpmath.sqrt(mu / p**3) * t)
        chi, r1 = mpmath.sqrt(p) * (D - D0), p * (1 + D**2) / 2
        return (
            1 - chi**2 / (2 * r),
            t - chi**3 / (6 * mpmath.sqrt(mu)),
            -mpmath.sqrt(mu) * chi / (r * r1),
            1 - chi**2 / (2 * r1),
        )
    a = -mu / (2 * energy)
    if energy < 0:
        n = mpmath.sqrt(mu / a**3)
        E0 = mpmath.atan2(rv / mpmath.sqrt(mu * a), 1 - r / a)  # e sin E0, e cos E0
        dE = _solve_elliptic(E0 - e * mpmath.sin(E0) + n * t, e) - E0
        dE -= 2 * mp.pi * mpmath.nint((dE - n * t) / (2 * mp.pi))  # keep the revolutions of n t
        r1 = a * (1 - e * mpmath.cos(E0 + dE))
        return (
            1 - a / r * (1 - mpmath.cos(dE)),
            t - (dE - mpmath.sin(dE)) / n,
            -mpmath.sqrt(mu * a) / (r * r1) * mpmath.sin(dE),
            1 - a / r1 * (1 - mpmath.cos(dE)),
        )
    n = mpmath.sqrt(mu / -(a**3))
    H0 = mpmath.asinh(rv / mpmath.sqrt(-mu * a) / e)  # r0.v0 = sqrt(-mu a) e sinh H0
    dH = _solve_hyperbolic(e * mpmath.sinh(H0) - H0 + n * t, e) - H0
    r1 = a * (1 - e * mpmath.cosh(H0 + dH))
    return (
        1 - a / r * (1 - mpmath.cosh(dH)),
        t - (mpmath.sinh(dH) - dH) / n,
        -mpmath.sqrt(-mu * a) / (r * r1) * mpmath.sinh(dH),
        1 - a / r1 * (1 - mpmath.cosh(dH)),
    )


def _propagation_digits(r0, v0, mu, t):
    """Working digits for propagate: a base, plus three times the digits lost near
    e = 1, plus the digits of the mean-anomaly growth n t (estimated at the base)."""
    with mp.workdps(BASE_DPS):
        mu = mpf(mu)
        r, _, energy, _, e = _conic([mpf(x) for x in r0], [mpf(x) for x in v0], mu)
        if energy == 0:
            return BASE_DPS
        n = mpmath.sqrt(mu * abs(2 * energy / mu) ** 3)
        return BASE_DPS + 3 * _lost_digits(1 - e) + _magnitude_digits(n * mpf(t))


def propagate(r0: "ArrayLike", v0: "ArrayLike", mu: float, t: float) -> tuple[list[mpf], list[mpf]]:
    """Two-body state (r, v) at time t of the Kepler orbit through (r0, v0) at t = 0.

    Solves the elliptic, hyperbolic or (energy exactly zero) parabolic Kepler
    equation from the conic elements and rebuilds the state with the Lagrange
    f and g coefficients.  Returns two lists of three mpf.
    """
    with mp.workdps(_propagation_digits(r0, v0, mu, t)):
        r0, v0, mu, t = [mpf(x) for x in r0], [mpf(x) for x in v0], mpf(mu), mpf(t)
        f, g, fdot, gdot = _lagrange_coefficients(r0, v0, mu, t)
        r = [f * x + g * y for x, y in zip(r0, v0)]
        v = [fdot * x + gdot * y for x, y in zip(r0, v0)]
    return r, v


def transition_matrix(r0: "ArrayLike", v0: "ArrayLike", mu: float, t: float, digits: int = 50) -> list[list[mpf]]:
    """d(r, v) / d(r0, v0) at time t, 6 x 6 (rows r, v; columns r0, v0), by central differences of propagate:
    each of the six inputs is moved by +-1e-20 of its size (of |r0| or |v0| for a zero component), so the
    truncation error (1e-40) and the rounding of the working precision (at least 60 digits: 1e-40) leave the
    matrix right to the given digits. Returns rows of mpf."""
    with mp.workdps(digits + 20):
        x0 = [mpf(x) for x in list(r0) + list(v0)]
        sizes = [mpmath.sqrt(_dot(x0[:3], x0[:3]))] * 3 + [mpmath.sqrt(_dot(x0[3:], x0[3:]))] * 3
        columns = []
        for j in range(6):
            step = (abs(x0[j]) or sizes[j]) * mpf(10) ** -20
            ends = []
            for sign in (1, -1):
                x = list(x0)
                x[j] += sign * step
                r, v = propagate(x[:3], x[3:], mu, t)
                ends.append(r + v)
            columns.append([(a - b) / (2 * step) for a, b in zip(*ends)])
        return [[columns[j][i] for j in range(6)] for i in range(6)]


def ulp_error(x: float | mpf, ref: float | mpf) -> mpf:
    """|x - ref| in float64 ulps: the spacing at the float nearest |ref| (smallest subnormal if ref == 0)."""
    with mp.workdps(BASE_DPS):
        return abs(mpf(x) - ref) / mpf(math.ulp(abs(float(ref))))


def rel_error(x: float | mpf, ref: float | mpf) -> mpf:
    """|x - ref| / |ref| (0 if both are zero, inf if only ref is)."""
    with mp.workdps(BASE_DPS):
        diff = abs(mpf(x) - ref)
        if ref == 0:
            return mpf(0) if diff == 0 else mpf("inf")
        return diff / abs(ref)


def kepler_E_ulps(E: float, M: float, e: float) -> float:
    """Distance of a float64 E from the true root of E - e sin E = M_reduced, in ulps of E.

    One Newton step at >= 60 digits from the float E gives the root to O(delta**2): for the errors of a few
    ulp that are measured here that is exact to ~1e-16 relative, at a tenth of the cost of kepler_E.
    """
    with mp.workdps(BASE_DPS + _lost_digits(1 - e) + _magnitude_digits(M)):
        x, e_mp = mpf(E), mpf(e)
        m = _reduce_angle(mpf(M))
        delta = (x - e_mp * mpmath.sin(x) - m) / (1 - e_mp * mpmath.cos(x))
        return float(abs(delta) / mpf(math.ulp(abs(float(E))) if E != 0 else 5e-324))


def kepler_H_ulps(H: float, M: float, e: float) -> float:
    """Distance of a float64 H from the true root of e sinh H - H = M, in ulps of H (one Newton step)."""
    with mp.workdps(BASE_DPS + _lost_digits(e - 1)):
        x, e_mp = mpf(H), mpf(e)
        delta = (e_mp * mpmath.sinh(x) - x - mpf(M)) / (e_mp * mpmath.cosh(x) - 1)
        return float(abs(delta) / mpf(math.ulp(abs(float(H))) if H != 0 else 5e-324))
