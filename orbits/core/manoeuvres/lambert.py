"""Lambert's problem: the conic from r1 to r2 in a given time of flight, every revolution count and branch.

    >>> import numpy as np
    >>> from orbits.core.manoeuvres.lambert import solve
    >>> mu = 1.32712440018e20  # the Sun, m3/s2
    >>> au = 1.495978707e11
    >>> sol = solve([au, 0, 0], [0, 1.5 * au, 0], 200 * 86400.0, mu)
    >>> np.round(sol.v1 / 1e3, 3)  # km/s
    array([14.727, 27.069,  0.   ])

The algorithm is Izzo's (2015, Celest. Mech. Dyn. Astr. 121, 1-15): the non-dimensional time of flight
T = tof sqrt(2 mu / s**3) as a function of x (x = cos(alpha / 2) on ellipses, cosh(alpha / 2) on hyperbolas,
x = 1 the parabola) and of lambda = sqrt(r1 r2) cos(theta / 2) / s, solved by Householder's fourth-order
iteration inside a bracket; the velocities follow from Izzo's eq. (14)-(15). Written here from the equations,
with these changes for accuracy (no peer does them; the tests prove each):

- The transfer angle comes from atan2(|r1 x r2|, r1 . r2): only its half, h, is used, and
  lambda = sqrt(r1 r2) cos(h) / s, k = 1 - lambda**2 = c / s and sigma = 2 sqrt(r1 r2) sin(h) / c with the chord
  c = hypot(r1 - r2, 2 sqrt(r1 r2) sin h) are all computed from (|r1|, |r2|, h), so that they describe one
  geometry exactly (r2 turned by about one ulp): nothing cancels near theta = 0, pi or 2 pi, where
  lambda = sqrt(1 - c / s) and sigma = sqrt(1 - rho**2) of the papers lose up to half the digits.
- 1 - lambda**2 is carried as k = c / s (y = sqrt(k + lambda**2 x**2)), never recomputed.
- T(x) is evaluated in a form free of cancellation on every conic, through the parabola, without
  hypergeometric series: with psi = (alpha - beta) / 2, phi = (alpha + beta) / 2 and w = sqrt|1 - x**2|,
      T = (psi / w)**3 C(psi) + u Q + pi N / w**3,   u = y - lambda x,  Q = (1 + lambda**2 x**2) / (1 + x y) + lambda
  (Lagrange's equation split as (psi - sin psi) + sin psi (1 - cos phi), both terms >= 0 for lambda >= 0);
  C(z) = (z - sin z) / z**3 (ellipse) or (sinh z - z) / z**3 (hyperbola) is a Taylor series for z < 2, so the
  parabola x = 1 is an ordinary point. For lambda < 0 the two halves of Lagrange's equation add up
  (T = 4 ((alpha / 2 w)**3 C(alpha) + (|beta| / 2 w)**3 C(|beta|)) + pi N / w**3) and are used directly.
- Derivatives: Izzo's recurrences, with lambda**3 x - y = -k (1 + lambda**2 x**2 (1 + lambda**2)) /
  (lambda**3 x + y); within 1e-3 of the parabola their Taylor series at x = 1 (they cancel there).
- Multiple revolutions: the minimum time T_min(N) and its x_min are found first (Halley on dT/dx = 0); each
  branch is then solved inside its own bracket, (-1, x_min) or (x_min, 1), from a start on the parabola
  T ~ T_min + T''(x_min) (x - x_min)**2 / 2 when T is within 10 % of T_min, so N at its minimum time converges.

Which solution:
- revolutions N >= 0: complete revolutions before arrival; N > 0 has no solution below T_min(N)
  (OrbitDomainError naming T_min), two at larger T and one (x_min) at T_min.
- branch "left" or "right" (N > 0 only): Izzo's branches, x < x_min or x > x_min; "right" is poliastro's,
  hapsira's and lamberthub's low_path=True.
- The sense of motion: the orbit's angular momentum points along r1 x r2 or against it. With `normal` given,
  along the side where (r1 x r2) . normal > 0; otherwise +z (prograde) or -z (retrograde) plays that role, and
  when (r1 x r2)_z = 0 exactly the short way (theta < pi) is taken. Collinear r1 and r2 (r1 x r2 = 0) have no
  plane: opposite directions (theta = pi) need `normal`, whose part perpendicular to r1 is then the orbit's
  normal; the same direction (theta = 0 or 2 pi) is a radial or undetermined orbit and always an error.

Accuracy (tests/core/test_lambert.py, each v1 propagated at 60 digits by orbits.tools.reference.propagate):
the arrival point is within 1e-13 |r2| on random geometry of every conic and revolution count and on the hard
cases (angles within 1e-8 of 0, pi and 2 pi, exactly pi, the parabolic time, N = 5 at T_min, short and long
flights, SI and unit scale); measured figures are in that file. Speed: a compiled port of this algorithm
(orbits/core/manoeuvres/_fast_lambert.py) runs batches of _fast.AUTO_MIN_BATCH and more (see orbits.core._fast);
`orbits bench lambert` compares both with the peers installed.
"""

from typing import NamedTuple

import numpy as np
from numpy.typing import ArrayLike

from orbits.core import _fast
from orbits.core.checks import broadcast, broadcast_shape, check_finite, require_positive
from orbits.core.errors import ConvergenceError, DegenerateOrbitError, OrbitDomainError
from orbits.core.manoeuvres._lambert_shared import (
    AT_MINIMUM,
    C3_ELLIPSE,
    C3_HYPERBOLA,
    MAX_ITERATIONS,
    NEAR_MINIMUM,
    PARABOLA_ZONE,
    SERIES_LIMIT,
    STEP_TOLERANCE,
    ZERO_REVOLUTION_TOLERANCE,
)
from orbits.core.series import horner

BRANCHES = ("left", "right")


class Geometry(NamedTuple):
    """The transfer geometry, from (r1, r2) and the sense of motion; arrays over the batch (vectors (..., 3))."""

    r1: np.ndarray  # |r1| (m)
    r2: np.ndarray  # |r2| (m)
    sin_half: np.ndarray  # sin(theta / 2) >= 0
    cos_half: np.ndarray  # cos(theta / 2), < 0 beyond pi
    angle: np.ndarray  # theta in (0, 2 pi) (rad), the angle swept after the complete revolutions
    r1_hat: np.ndarray
    r2_hat: np.ndarray
    t1_hat: np.ndarray  # unit normal x r1_hat: the direction of motion at r1 on a circle
    t2_hat: np.ndarray


class Solution(NamedTuple):
    """Lambert's solution: velocities (m/s) at both ends, the transfer angle, Izzo's x and the semi-major axis."""

    v1: np.ndarray
    v2: np.ndarray
    angle: np.ndarray  # theta in (0, 2 pi) (rad), not counting the complete revolutions
    x: np.ndarray
    semi_major_axis: np.ndarray  # m; inf on the parabola, < 0 on hyperbolas


def _norm(v):
    return np.sqrt(v[..., 0] * v[..., 0] + v[..., 1] * v[..., 1] + v[..., 2] * v[..., 2])


def _cross(a, b):
    """a x b over the last axis (np.cross is several times slower on (n, 3) arrays)."""
    out = np.empty(np.broadcast_shapes(a.shape, b.shape))
    out[..., 0] = a[..., 1] * b[..., 2] - a[..., 2] * b[..., 1]
    out[..., 1] = a[..., 2] * b[..., 0] - a[..., 0] * b[..., 2]
    out[..., 2] = a[..., 0] * b[..., 1] - a[..., 1] * b[..., 0]
    return out


def _unit(v):
    return v / _norm(v)[..., None]


def _position(vec, name):
    """A finite float array (..., 3) of positions (m)."""
    vec = np.asarray(vec, dtype=float)
    if vec.shape[-1:] != (3,):
        raise OrbitDomainError(f"position {name} must have a last axis of length 3; got shape {vec.shape}")
    check_finite(vec, f"position {name}", "m")
    return vec


def geometry(r1: ArrayLike, r2: ArrayLike, prograde: bool = True, normal: ArrayLike | None = None) -> Geometry:
    """Radii, half transfer angle and in-plane directions of the transfer r1 -> r2 (m, rad); see the module notes.

    Raises DegenerateOrbitError for collinear r1 and r2 without a usable `normal`, and for the same direction.
    """
    r1, r2 = broadcast(r1=_position(r1, "r1"), r2=_position(r2, "r2"))
    n1, n2 = _norm(r1), _norm(r2)
    require_positive(n1, "|r1|", "m")
    require_positive(n2, "|r2|", "m")
    cross = _cross(r1, r2)
    size = _norm(cross)
    dot = r1[..., 0] * r2[..., 0] + r1[..., 1] * r2[..., 1] + r1[..., 2] * r2[..., 2]
    reference = np.array([0.0, 0.0, 1.0 if prograde else -1.0]) if normal is None else _normal(normal)
    side = np.sum(cross * reference, axis=-1)
    if normal is not None and np.any((side == 0) & (size > 0)):
        i = _first(((side == 0) & (size > 0)).reshape(size.shape))
        raise OrbitDomainError(f"normal lies in the transfer plane of r1 = {_vec(r1, i)} m and r2 = {_vec(r2, i)} m: "
                               f"it cannot tell the sense of motion; give one with (r1 x r2) . normal != 0")
    collinear = size == 0
    if np.any(collinear & (dot > 0)):
        i = _first(collinear & (dot > 0))
        raise DegenerateOrbitError(
            f"r1 = {_vec(r1, i)} m and r2 = {_vec(r2, i)} m point the same way (transfer angle 0 or 2 pi): the only "
            f"transfers are radial or undetermined; Lambert's problem needs r1 and r2 not on one ray from the centre")
    if np.any(collinear) and normal is None:
        i = _first(collinear)
        raise DegenerateOrbitError(
            f"r1 = {_vec(r1, i)} m and r2 = {_vec(r2, i)} m are opposite (transfer angle pi): every plane through "
            f"them holds a transfer; give normal=(x, y, z) (--normal X,Y,Z), the orbit's angular momentum direction")
    long_way = side < 0
    half = 0.5 * np.arctan2(size, dot)  # in [0, pi / 2]
    orbit_normal = np.where(collinear[..., None], reference, cross * np.where(long_way, -1.0, 1.0)[..., None])
    t1 = _cross(orbit_normal, r1)
    if np.any(_norm(t1) == 0):
        raise DegenerateOrbitError("normal is parallel to r1: it gives no orbit plane through r1 and r2")
    return Geometry(
        n1, n2, np.sin(half), np.where(long_way, -1.0, 1.0) * np.cos(half),
        np.where(long_way, 2.0 * np.pi - 2.0 * half, 2.0 * half),
        r1 / n1[..., None], r2 / n2[..., None], _unit(t1), _unit(_cross(orbit_normal, r2)),
    )


def _normal(normal):
    normal = np.asarray(normal, dtype=float)
    check_finite(normal, "normal", "(any unit)")
    if normal.shape[-1:] != (3,) or np.any(_norm(normal) == 0):
        raise OrbitDomainError(f"normal = {normal.tolist()!r} must be a nonzero 3-vector (the orbit's angular "
                               f"momentum direction)")
    return normal


def _first(mask):
    return tuple(np.argwhere(mask)[0])


def _vec(v, i):
    return "(" + ", ".join(f"{float(c):.17g}" for c in v[i]) + ")"


# ---- the time-of-flight equation -----------------------------------------------------------------------


def _c3(z, sin_z, elliptic):
    """(z - sin z) / z**3 (elliptic) or (sinh z - z) / z**3 (hyperbolic), z >= 0, given sin z or sinh z."""
    series = z < SERIES_LIMIT
    q = np.where(series, z * z, 1.0)
    taylor = np.where(elliptic, horner(C3_ELLIPSE, q), horner(C3_HYPERBOLA, q))
    big = np.where(series, 1.0, z)
    direct = np.where(elliptic, big - sin_z, sin_z - big) / (big * big * big)
    return np.where(series, taylor, direct)


def _ratio(angle, w, limit):
    """angle / w, and `limit` where w = 0 (the parabola)."""
    return np.where(w > 0, angle / np.where(w > 0, w, 1.0), limit)


def time_of_flight(x: ArrayLike, lam: ArrayLike, k: ArrayLike, revolutions: ArrayLike = 0) -> np.ndarray:
    """Non-dimensional time of flight T(x) = tof sqrt(2 mu / s**3) of Izzo's x, lambda, k = 1 - lambda**2 and N.

    x > -1 (x < 1 ellipses, 1 the parabola, > 1 hyperbolas; N > 0 needs x < 1); lambda in [-1, 1], k = c / s > 0.
    Cancellation-free on every conic (module notes); within a few ulp of mpmath (tests/core/test_lambert.py).
    """
    x, lam, k, revolutions = np.broadcast_arrays(*(np.asarray(a, dtype=float) for a in (x, lam, k, revolutions)))
    return _time_of_flight(x, lam, k, revolutions)[0]


def _time_of_flight(x, lam, k, revolutions):
    """(T, y) for broadcast float arrays; see time_of_flight."""
    d = (1.0 - x) * (1.0 + x)  # 1 - x**2
    elliptic = d > 0
    w = np.sqrt(np.abs(d))
    y = np.sqrt(k + lam * lam * x * x)
    lx = lam * x
    u = np.where(lx > 0, k / (y + np.where(lx > 0, lx, 0.0)), y - lx)  # y - lambda x, without cancellation
    # lambda >= 0: the psi / phi form
    s_psi = w * u  # sin psi or sinh psi
    psi = np.where(elliptic, np.arctan2(s_psi, x * y + lam * d), np.arcsinh(s_psi))
    ratio = _ratio(psi, w, u)
    one_plus_xy = np.where(x >= 0, 1.0 + x * y, 1.0)
    q = np.where(x >= 0, (1.0 + lx * lx) / one_plus_xy, (1.0 - x * y) / np.where(x >= 0, 1.0, d)) + lam
    t_psi = ratio**3 * _c3(psi, s_psi, elliptic) + u * q
    # lambda < 0: alpha / 2 = acos x or acosh x, |beta| / 2 = asin or asinh(|lambda| w)
    a = np.abs(lam)
    half_alpha = np.where(elliptic, np.arctan2(w, x), np.arcsinh(w))
    half_beta = np.where(elliptic, np.arcsin(np.minimum(a * w, 1.0)), np.arcsinh(a * w))
    ra, rb = _ratio(half_alpha, w, 1.0), _ratio(half_beta, w, a)
    c_alpha = _c3(2.0 * half_alpha, 2.0 * x * w, elliptic)
    c_beta = _c3(2.0 * half_beta, 2.0 * a * w * y, elliptic)
    t_ab = 4.0 * (ra**3 * c_alpha + rb**3 * c_beta)
    t = np.where(lam >= 0, t_psi, t_ab)
    multi = revolutions > 0
    cube = np.where(multi & elliptic, w * w * w, 1.0)
    return t + np.where(multi, np.pi * revolutions / cube, 0.0), y


def _parabola_taylor(lam, k):
    """T', T'', T''' at x = 1 and T'''' / 24 (Taylor coefficients of T(x) at the parabola, N = 0), from Izzo's
    recurrence (1 - x**2) T' = 3 x T - 2 + 2 lambda**3 x / y; 1 - lambda = k / (1 + lambda) for lambda > 0."""
    one_minus = np.where(lam > 0, k / (1.0 + np.abs(lam)), 1.0 - lam)
    l2 = lam * lam
    l3, l4, l5 = l2 * lam, l2 * l2, l2 * l2 * lam
    a1 = -2.0 / 5.0 * one_minus * (1.0 + lam + l2 + l3 + l4)
    a2 = one_minus * (15.0 * l5 * lam + 15.0 * l5 + 8.0 * (l4 + l3 + l2 + lam + 1.0)) / 35.0
    a3 = -one_minus * (35.0 * l4 * l4 + 35.0 * l4 * l3 + 8.0 * (l5 * lam + l5 + l4 + l3 + l2 + lam + 1.0)) / 63.0
    return a1, a2, a3


def _derivatives(x, t, y, lam, k, revolutions):
    """dT/dx, d2T/dx2, d3T/dx3 (Izzo's recurrences, cancellation-free; Taylor at x = 1 within PARABOLA_ZONE)."""
    d = (1.0 - x) * (1.0 + x)
    near = (np.abs(x - 1.0) < PARABOLA_ZONE) & (revolutions == 0)
    ds = np.where(near, 1.0, d)
    lam2 = lam * lam
    lx = lam * x
    positive = lx > 0
    g = np.where(positive, -k * (1.0 + lx * lx * (1.0 + lam2)) / (lam2 * lx + y), lam2 * lx - y)  # lambda**3 x - y
    d1 = (3.0 * t * x + 2.0 * g / y) / ds
    lam3k_y3 = k * lam2 * lam / (y * y * y)
    d2 = (3.0 * t + 5.0 * x * d1 + 2.0 * lam3k_y3) / ds
    d3 = (8.0 * d1 + 7.0 * x * d2 - 6.0 * lam3k_y3 * lam2 * x / (y * y)) / ds
    if np.any(near):
        a1, a2, a3 = _parabola_taylor(lam, k)
        h = x - 1.0
        d1 = np.where(near, a1 + h * (2.0 * a2 + 3.0 * a3 * h), d1)
        d2 = np.where(near, 2.0 * a2 + 6.0 * a3 * h, d2)
        d3 = np.where(near, 6.0 * a3, d3)
    return d1, d2, d3


# ---- the root of T(x) = T ------------------------------------------------------------------------------


def _minimum_time(lam, k, revolutions):
    """(x_min, T_min) of N > 0 revolutions: Halley on dT/dx = 0 from x = 0 inside (-1, 1)."""
    x = np.zeros_like(lam)
    lo, hi = np.full_like(lam, -1.0), np.ones_like(lam)
    active = np.arange(lam.size)
    for _ in range(MAX_ITERATIONS):
        xa, la, ka, na = x[active], lam[active], k[active], revolutions[active]
        t, y = _time_of_flight(xa, la, ka, na)
        d1, d2, d3 = _derivatives(xa, t, y, la, ka, na)
        lo[active] = np.where(d1 < 0, xa, lo[active])
        hi[active] = np.where(d1 > 0, xa, hi[active])
        step = -2.0 * d1 * d2 / (2.0 * d2 * d2 - d1 * d3)
        new = _inside(xa + step, xa, lo[active], hi[active])
        x[active] = new
        active = active[np.abs(new - xa) > STEP_TOLERANCE]
        if active.size == 0:
            break
    else:
        raise ConvergenceError(f"minimum time of {int(revolutions.flat[0])} revolutions: no convergence in "
                               f"{MAX_ITERATIONS} Halley steps (lambda = {float(lam.flat[0])!r})")
    return x, _time_of_flight(x, lam, k, revolutions)[0]


def _inside(x, previous, lo, hi):
    """x, or the middle of (lo, hi) when x is not strictly inside (hi may be inf: then twice as far from lo);
    x equal to the previous iterate (a step below its ulp) stays."""
    outside = ~((x > lo) & (x < hi)) & (x != previous)
    middle = np.where(np.isfinite(hi), 0.5 * (lo + np.where(np.isfinite(hi), hi, 0.0)), 2.0 * np.abs(lo) + 1.0)
    return np.where(outside, middle, x)


def _zero_revolution_start(lam, k, t):
    """Izzo's starting x for N = 0 (eq. 30, with the corrected middle piece); 1 - lambda**n via k."""
    one_minus = np.where(lam > 0, k / (1.0 + np.abs(lam)), 1.0 - lam)
    l2 = lam * lam
    t0 = np.arctan2(np.sqrt(k), lam) + lam * np.sqrt(k)  # acos(lambda) + lambda sqrt(1 - lambda**2)
    t1 = 2.0 / 3.0 * one_minus * (1.0 + lam + l2)
    one_minus_l5 = one_minus * (1.0 + lam + l2 + l2 * lam + l2 * l2)
    long_flight = (t0 / t) ** (2.0 / 3.0) - 1.0
    short = 2.5 * t1 / t * (t1 - t) / one_minus_l5 + 1.0
    with np.errstate(divide="ignore", invalid="ignore"):  # log(t1 / t0) is 0 only where this piece is unused
        middle = np.exp(np.log(2.0) * np.log(t / t0) / np.log(t1 / t0)) - 1.0
    return np.where(t >= t0, long_flight, np.where(t < t1, short, np.where(np.isfinite(middle), middle, 0.0)))


def _multi_revolution_start(lam, t, revolutions, right, x_min, t_min, curvature):
    """Izzo's starts of the left and right branches, or the quadratic model near T_min, inside the branch."""
    n = revolutions
    left_q = ((n * np.pi + np.pi) / (8.0 * t)) ** (2.0 / 3.0)
    right_q = (8.0 * t / (n * np.pi)) ** (2.0 / 3.0)
    izzo = np.where(right, (right_q - 1.0) / (right_q + 1.0), (left_q - 1.0) / (left_q + 1.0))
    offset = np.sqrt(2.0 * np.maximum(t - t_min, 0.0) / curvature)
    quadratic = x_min + np.where(right, offset, -offset)
    near = (t - t_min) < NEAR_MINIMUM * t_min
    inside = np.where(right, (izzo > x_min) & (izzo < 1.0), (izzo < x_min) & (izzo > -1.0))
    return np.where(near | ~inside, quadratic, izzo)


def _householder(x, t, lam, k, revolutions, lo, hi, decreasing, active):
    """x with T(x) = t by Householder's fourth-order steps from x, kept inside (lo, hi) by bisection; only the
    elements listed in `active` (indices) are solved, the others are left as they are."""
    for _ in range(MAX_ITERATIONS):
        if active.size == 0:
            return x
        xa, ta, la, ka, na = x[active], t[active], lam[active], k[active], revolutions[active]
        value, y = _time_of_flight(xa, la, ka, na)
        f = value - ta
        d1, d2, d3 = _derivatives(xa, value, y, la, ka, na)
        later = (f > 0) == decreasing[active]  # the root lies at larger x
        lo[active] = np.where(later & (f != 0), xa, lo[active])
        hi[active] = np.where(~later & (f != 0), xa, hi[active])
        d1_2 = d1 * d1
        step = -f * (d1_2 - 0.5 * f * d2) / (d1 * (d1_2 - f * d2) + d3 * f * f / 6.0)
        new = np.where(f == 0, xa, _inside(xa + step, xa, lo[active], hi[active]))
        x[active] = new
        tolerance = np.where(na == 0, ZERO_REVOLUTION_TOLERANCE, STEP_TOLERANCE)
        active = active[np.abs(new - xa) > tolerance * np.maximum(1.0, np.abs(xa))]
    raise ConvergenceError(f"Lambert's problem: no convergence in {MAX_ITERATIONS} Householder steps, e.g. at "
                           f"lambda = {float(lam[active[0]])!r}, T = {float(t[active[0]])!r}, "
                           f"N = {int(revolutions[active[0]])}")


def find_x(lam: ArrayLike, k: ArrayLike, t: ArrayLike, revolutions: ArrayLike = 0, branch: str = "right",
           scale: ArrayLike = 1.0) -> np.ndarray:
    """Izzo's x solving T(x) = t for lambda, k = 1 - lambda**2 and N revolutions on the given branch.

    `scale` converts T to seconds for the error message of an infeasible N (sqrt(s**3 / (2 mu)), s).
    Raises OrbitDomainError when t < T_min(N).
    """
    if branch not in BRANCHES:
        raise OrbitDomainError(f"branch = {branch!r} must be one of {', '.join(BRANCHES)}")
    lam, k, t, revolutions, scale = (
        np.array(a, dtype=float).reshape(-1) for a in np.broadcast_arrays(lam, k, t, revolutions, scale))
    x = _zero_revolution_start(lam, k, t)
    lo, hi = np.full_like(x, -1.0), np.full_like(x, np.inf)
    decreasing = np.ones(x.shape, dtype=bool)
    x = np.where(x > -1.0, x, -0.5)  # Izzo's start can round to -1 on very long flights
    solved = np.zeros(x.shape, dtype=bool)
    multi = np.flatnonzero(revolutions > 0)
    if multi.size:
        x[multi], lo[multi], hi[multi], decreasing[multi], solved[multi] = _multi_revolution_setup(
            lam[multi], k[multi], t[multi], revolutions[multi], branch == "right", scale[multi])
    return _householder(x, t, lam, k, revolutions, lo, hi, decreasing, np.flatnonzero(~solved))


def _multi_revolution_setup(lam, k, t, revolutions, right, scale):
    """(start, lo, hi, decreasing, solved) of N > 0; at T_min (to AT_MINIMUM) x_min is the solution of both."""
    x_min, t_min = _minimum_time(lam, k, revolutions)
    infeasible = t < t_min * (1.0 - AT_MINIMUM)
    if np.any(infeasible):
        i = np.flatnonzero(infeasible)[0]
        n, tof, shortest = int(revolutions[i]), float(t[i] * scale[i]), float(t_min[i] * scale[i])
        raise OrbitDomainError(
            f"revolutions N = {n} is infeasible: the time of flight {tof!r} s is shorter than the fastest "
            f"{n}-revolution transfer, T_min = {shortest!r} s; give fewer revolutions or a time of flight >= T_min")
    at_minimum = t <= t_min
    t_safe = np.maximum(t, t_min)
    d1, curvature, _ = _derivatives(x_min, t_min, np.sqrt(k + lam * lam * x_min * x_min), lam, k, revolutions)
    start = _multi_revolution_start(lam, t_safe, revolutions, right, x_min, t_min, curvature)
    lo = np.full_like(x_min, -1.0) if not right else x_min.copy()
    hi = np.ones_like(x_min) if right else x_min.copy()
    return np.where(at_minimum, x_min, start), lo, hi, np.full(lam.shape, not right), at_minimum


# ---- velocities --------------------------------------------------------------------------------------


def solve(r1: ArrayLike, r2: ArrayLike, tof: ArrayLike, mu: ArrayLike, revolutions: ArrayLike = 0,
          branch: str = "right", prograde: bool = True, normal: ArrayLike | None = None) -> Solution:
    """Velocities v1, v2 (m/s) of the conic from r1 (m) at t = 0 to r2 (m) at t = tof (s) about mu (m3/s2).

    Parameters
    ----------
    r1, r2 : array_like (..., 3), positions (m), broadcast together with tof (s) > 0 and mu (m3/s2) > 0.
    revolutions : int or array of ints >= 0, complete revolutions before arrival.
    branch : "left" or "right", which of the two solutions of N > 0 (module notes).
    prograde : the sense of motion about +z when `normal` is None (module notes).
    normal : array_like (..., 3), optional, the side the orbit's angular momentum points to; needed when r1 and
        r2 are opposite.

    Returns a Solution of arrays. Raises OrbitDomainError (infeasible N, bad input) or DegenerateOrbitError
    (collinear without `normal`). Accuracy: the propagated v1 reaches r2 within 1e-13 |r2|
    (tests/core/test_lambert.py).
    """
    if branch not in BRANCHES:
        raise OrbitDomainError(f"branch = {branch!r} must be one of {', '.join(BRANCHES)}")
    tof, mu = np.asarray(tof, dtype=float), np.asarray(mu, dtype=float)
    require_positive(tof, "time of flight", "s")
    require_positive(mu, "gravitational parameter mu", "m3/s2")
    revolutions = _revolutions(revolutions)
    r1, r2 = _position(r1, "r1"), _position(r2, "r2")
    shape = broadcast_shape(r1=r1.shape[:-1], r2=r2.shape[:-1], tof=tof.shape, mu=mu.shape,
                            revolutions=revolutions.shape, normal=() if normal is None else np.shape(normal)[:-1])
    if _fast.use(int(np.prod(shape)), "manoeuvres._fast_lambert.solve"):
        solution = _compiled(r1, r2, tof, mu, revolutions, branch, prograde, normal, shape)
        if solution is not None:
            return solution
    geo = geometry(r1, r2, prograde, normal)
    shape = np.broadcast_shapes(geo.r1.shape, shape)
    c, s, lam, k, sigma, rho, t, scale, gamma = _scalars(geo, mu, tof, shape)
    n = np.broadcast_to(revolutions, shape).reshape(-1)
    x = find_x(lam, k, t, n, branch, scale)
    y = np.sqrt(k + lam * lam * x * x)
    return _velocities(geo, shape, x, y, lam, k, sigma, rho, gamma, s)


#: one unit of rounding of a float64 input, relative to itself, and the nudge the conditioning is measured with
ROUNDING = 2.0**-53
NUDGE = 2.0**-40


def arrival_conditioning(r1: ArrayLike, v1: ArrayLike, r2: ArrayLike, tof: ArrayLike, mu: ArrayLike) -> np.ndarray:
    """kappa (dimensionless, the batch's shape): how far the arrival point of (r1, v1) may lie from r2, as a
    fraction of |r2|: the larger of the two figures of arrival_rounding, the arrival's shift under the inputs'
    rounding and the answer's own miss. This solver lands within 20 kappa plus 1e-12 of |r2|
    (tests/stability/test_lambert_sweep.py). kappa beyond ILL_CONDITIONED (orbits.core.errors: a flight the long way
    round a focus it grazes, or many revolutions in little time) says the answer cannot be flown to its digits."""
    shift, miss = arrival_rounding(r1, v1, r2, tof, mu)
    return np.maximum(shift, miss)


def arrival_rounding(r1: ArrayLike, v1: ArrayLike, r2: ArrayLike, tof: ArrayLike,
                     mu: ArrayLike) -> tuple[np.ndarray, np.ndarray]:
    """(shift, miss), dimensionless fractions of |r2| in the batch's shape.

    shift: how far the arrival point moves when one component of r1 or of v1, or the time of flight, moves by its
    float64 rounding (2**-53 of itself): the largest such shift, each measured by propagating the nudged state
    (orbits.core.twobody.propagate) and scaled from a nudge of NUDGE of itself, large enough that the propagator's
    own rounding (a few shifts) is 1e-3 of the shift; where that nudge leaves the linear range (a shift beyond 1e-4
    of |r2|), from a nudge of 2**-52 itself. A rounding of mu moves the arrival by half the v1 and tof terms (the
    two-body problem is unchanged under mu -> c mu, v -> sqrt(c) v, t -> t / sqrt(c)). inf where a rounding makes
    the orbit radial (a flight through the focus). No solver does better than about this shift.

    miss: |r(tof) - r2| / |r2| for v1 as given, from the same propagation (inf with the shift). Where a transfer
    needs a v1 finer than float64 holds (the long way round in 1e-9 of a period, passing within 1e-20 of the focus),
    the answer lands far from the point the shift was measured at, and only its own miss says so."""
    r1, v1, r2 = (np.asarray(x, dtype=float) for x in (r1, v1, r2))
    shape = np.broadcast_shapes(r1.shape[:-1], v1.shape[:-1], r2.shape[:-1], np.shape(tof), np.shape(mu))
    start = np.concatenate([np.broadcast_to(r1, (*shape, 3)), np.broadcast_to(v1, (*shape, 3))], axis=-1)
    tof, mu = np.broadcast_to(np.asarray(tof, dtype=float), shape), np.broadcast_to(np.asarray(mu, dtype=float), shape)
    end = np.broadcast_to(r2, (*shape, 3))
    size = _norm(end)
    shift, arrival = _largest_shift(start, tof, mu, NUDGE)
    shift = shift / size
    beyond = shift * (NUDGE / ROUNDING) > 1e-4
    if np.any(beyond):
        shift = np.where(beyond, _largest_shift(start, tof, mu, 2.0 * ROUNDING)[0] / size, shift)
    return shift, np.where(np.isinf(shift), np.inf, _norm(arrival - end) / size)


def _largest_shift(start, tof, mu, nudge):
    """The largest move of the arrival point (m) when one of r1's, v1's components or tof moves by `nudge` of
    itself, scaled to a move of ROUNDING, and the arrival point itself (m): eight propagations a transfer (the
    solution, six components, the flight)."""
    from orbits.core.twobody.propagate import propagate

    factors = np.ones((8, *start.shape))
    factors[np.arange(1, 7), ..., np.arange(6)] += nudge
    states = start * factors
    times = tof * np.where(np.arange(8) == 7, 1.0 + nudge, 1.0).reshape((8,) + (1,) * tof.ndim)
    # a state that rounding makes radial (r x v = 0: a flight through the focus) has no arrival to compare
    radial = np.any(_norm(_cross(states[..., :3], states[..., 3:])) == 0.0, axis=0)
    stand_in = np.array([1.0, 0.0, 0.0, 0.0, 1.0, 0.0])
    states = np.where(radial[..., None], stand_in, states)
    ends, _ = propagate(states[..., :3], states[..., 3:], np.where(radial, 1.0, mu), np.where(radial, 1.0, times))
    shift = np.where(radial, np.inf, np.max(_norm(ends[1:] - ends[0]), axis=0) * (ROUNDING / nudge))
    return shift, ends[0]


#: the most complete revolutions a transfer may make: 2**50, as many turns as an angle is reduced exactly over
MAX_REVOLUTIONS = 2**50


def _revolutions(revolutions):
    """The revolution counts as an integer array, each a whole number in [0, MAX_REVOLUTIONS]."""
    if isinstance(revolutions, int) and not isinstance(revolutions, bool) and revolutions > MAX_REVOLUTIONS:
        raise OrbitDomainError(f"revolutions N = {revolutions} is outside [0, 2**50]: a transfer of more turns "
                               f"cannot place its end point in float64")
    n = np.asarray(revolutions)
    whole = np.issubdtype(n.dtype, np.integer) or (
        np.issubdtype(n.dtype, np.floating) and np.all(np.isfinite(n)) and np.all(n == np.round(n)))
    if not whole or np.any(n < 0):
        bad = n.flat[0] if not whole and n.size else n[n < 0].flat[0] if n.size else n
        raise OrbitDomainError(f"revolutions N = {bad!r} must be a whole number >= 0")
    if np.any(n > MAX_REVOLUTIONS):
        raise OrbitDomainError(f"revolutions N = {n[n > MAX_REVOLUTIONS].flat[0]!r} is outside [0, 2**50]: a "
                               f"transfer of more turns cannot place its end point in float64")
    return n.astype(np.int64)


def _scalars(geo, mu, tof, shape):
    """(c, s, lambda, k, sigma, rho, T, seconds per unit T, gamma) over the broadcast shape, flattened."""
    r1, r2, sin_half, cos_half = (np.broadcast_to(a, shape).reshape(-1) for a in geo[:4])
    mu, tof = (np.broadcast_to(a, shape).reshape(-1) for a in (mu, tof))
    root = np.sqrt(r1) * np.sqrt(r2)
    c = np.hypot(r1 - r2, 2.0 * root * sin_half)
    s = 0.5 * (r1 + r2 + c)
    scale = s / np.sqrt(2.0 * mu / s)  # sqrt(s**3 / (2 mu)), s
    return c, s, root * cos_half / s, c / s, 2.0 * root * sin_half / c, (r1 - r2) / c, tof / scale, scale, \
        np.sqrt(0.5 * mu * s)


def _velocities(geo, shape, x, y, lam, k, sigma, rho, gamma, s):
    """Izzo's eq. (14)-(15) with 1 -+ rho = sigma**2 / (1 +- rho) and y + lambda x = k / (y - lambda x) where they
    would cancel; the Solution in the broadcast shape."""
    r1, r2 = (np.broadcast_to(a, shape).reshape(-1) for a in geo[:2])
    # each branch divides by the larger of 1 + rho and 1 - rho, so neither can be zero (np.where evaluates both)
    plus = np.where(rho >= 0, 1.0 + rho, sigma * sigma / np.where(rho >= 0, 1.0, 1.0 - rho))  # 1 + rho
    minus = np.where(rho >= 0, sigma * sigma / np.where(rho >= 0, 1.0 + rho, 1.0), 1.0 - rho)  # 1 - rho
    ly = lam * y
    lx = lam * x
    tangential = gamma * sigma * np.where(lx < 0, k / np.where(lx < 0, y - lx, 1.0), y + lx)
    vr1 = gamma * (ly * minus - x * plus) / r1
    vr2 = -gamma * (ly * plus - x * minus) / r2
    vectors = [np.broadcast_to(a, (*shape, 3)).reshape(-1, 3) for a in geo[5:9]]
    v1 = vr1[:, None] * vectors[0] + (tangential / r1)[:, None] * vectors[2]
    v2 = vr2[:, None] * vectors[1] + (tangential / r2)[:, None] * vectors[3]
    d = (1.0 - x) * (1.0 + x)
    a = np.where(d != 0, s / (2.0 * np.where(d != 0, d, 1.0)), np.inf)
    angle = np.broadcast_to(geo.angle, shape)
    return Solution(v1.reshape(*shape, 3), v2.reshape(*shape, 3), angle.copy(), x.reshape(shape),
                    a.reshape(shape))


def _compiled(r1, r2, tof, mu, revolutions, branch, prograde, normal, shape):
    """The compiled kernel's Solution, or None when it leaves an element unsolved (the NumPy path then raises)."""
    _fast.announce("_fast_lambert")
    from orbits.core.manoeuvres import _fast_lambert

    vectors = [np.ascontiguousarray(np.broadcast_to(vec, (*shape, 3)).reshape(-1, 3)) for vec in (r1, r2)]
    reference = np.array([0.0, 0.0, 1.0 if prograde else -1.0]) if normal is None else _normal(normal)
    reference = np.ascontiguousarray(np.broadcast_to(reference, (*shape, 3)).reshape(-1, 3))
    flat = [np.ascontiguousarray(np.broadcast_to(a, shape).reshape(-1), dtype=float) for a in (tof, mu, revolutions)]
    size = flat[0].size
    v1, v2 = np.empty((size, 3)), np.empty((size, 3))
    x, angle, a = np.empty(size), np.empty(size), np.empty(size)
    given, right = float(normal is not None), float(branch == "right")
    if _fast.run(_fast_lambert.solve, size, *vectors, *flat, reference, given, right, v1, v2, x, angle, a):
        return None
    return Solution(v1.reshape(*shape, 3), v2.reshape(*shape, 3), angle.reshape(shape), x.reshape(shape),
                    a.reshape(shape))
