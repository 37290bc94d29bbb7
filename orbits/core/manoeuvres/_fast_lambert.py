"""Compiled Lambert solver (numba): orbits.core.manoeuvres.lambert's algorithm, one transfer at a time.

Imported only through orbits.core.manoeuvres.lambert when the compiled kernels are enabled (see orbits.core._fast).
The same steps as the NumPy version, in the same order and with the same formulas: the geometry from the
half transfer angle, the cancellation-free T(x) (only the form each lambda needs is evaluated here, where the
NumPy version evaluates both and selects), Izzo's starts, the minimum time of N > 0 revolutions and the
bracketed Householder iteration, then Izzo's velocities. Both agree to a few ulp
(tests/core/test_lambert.py compares them on every case it runs).

The kernel returns the number of elements it could not solve: invalid geometry (collinear, a normal in the
plane), an infeasible revolution count or no convergence. Their outputs are NaN, and the caller then runs the
NumPy version, which raises the error that names the problem.
"""

import math

from orbits.core._fast import jit
from orbits.core._fast_math import _horner
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

_NAN = math.nan


@jit(inline=True)
def _c3(z, sin_z, elliptic):
    """(z - sin z) / z**3 (elliptic) or (sinh z - z) / z**3, z >= 0, given sin z or sinh z."""
    if z < SERIES_LIMIT:
        return _horner(C3_ELLIPSE, z * z) if elliptic else _horner(C3_HYPERBOLA, z * z)
    return ((z - sin_z) if elliptic else (sin_z - z)) / (z * z * z)


@jit(inline=True)
def _ratio(angle, w, limit):
    return angle / w if w > 0 else limit


@jit(inline=True)
def _time_of_flight(x, lam, k, n):
    """(T, y) of Izzo's x (orbits.core.manoeuvres.lambert.time_of_flight)."""
    d = (1.0 - x) * (1.0 + x)
    elliptic = d > 0
    w = math.sqrt(abs(d))
    y = math.sqrt(k + lam * lam * x * x)
    lx = lam * x
    if lam >= 0:
        u = k / (y + lx) if lx > 0 else y - lx
        s_psi = w * u
        psi = math.atan2(s_psi, x * y + lam * d) if elliptic else math.asinh(s_psi)
        ratio = _ratio(psi, w, u)
        q = ((1.0 + lx * lx) / (1.0 + x * y) if x >= 0 else (1.0 - x * y) / d) + lam
        t = ratio * ratio * ratio * _c3(psi, s_psi, elliptic) + u * q
    else:
        a = -lam
        half_alpha = math.atan2(w, x) if elliptic else math.asinh(w)
        half_beta = math.asin(min(a * w, 1.0)) if elliptic else math.asinh(a * w)
        ra, rb = _ratio(half_alpha, w, 1.0), _ratio(half_beta, w, a)
        c_alpha = _c3(2.0 * half_alpha, 2.0 * x * w, elliptic)
        c_beta = _c3(2.0 * half_beta, 2.0 * a * w * y, elliptic)
        t = 4.0 * (ra * ra * ra * c_alpha + rb * rb * rb * c_beta)
    if n > 0:
        t += math.pi * n / (w * w * w)
    return t, y


@jit(inline=True)
def _derivatives(x, t, y, lam, k, n):
    """dT/dx, d2T/dx2, d3T/dx3 (orbits.core.manoeuvres.lambert._derivatives)."""
    if n == 0 and abs(x - 1.0) < PARABOLA_ZONE:
        one_minus = k / (1.0 + abs(lam)) if lam > 0 else 1.0 - lam
        l2 = lam * lam
        l3, l4, l5 = l2 * lam, l2 * l2, l2 * l2 * lam
        a1 = -2.0 / 5.0 * one_minus * (1.0 + lam + l2 + l3 + l4)
        a2 = one_minus * (15.0 * l5 * lam + 15.0 * l5 + 8.0 * (l4 + l3 + l2 + lam + 1.0)) / 35.0
        a3 = -one_minus * (35.0 * l4 * l4 + 35.0 * l4 * l3 + 8.0 * (l5 * lam + l5 + l4 + l3 + l2 + lam + 1.0)) / 63.0
        h = x - 1.0
        return a1 + h * (2.0 * a2 + 3.0 * a3 * h), 2.0 * a2 + 6.0 * a3 * h, 6.0 * a3
    d = (1.0 - x) * (1.0 + x)
    lam2 = lam * lam
    lx = lam * x
    g = -k * (1.0 + lx * lx * (1.0 + lam2)) / (lam2 * lx + y) if lx > 0 else lam2 * lx - y
    d1 = (3.0 * t * x + 2.0 * g / y) / d
    lam3k_y3 = k * lam2 * lam / (y * y * y)
    d2 = (3.0 * t + 5.0 * x * d1 + 2.0 * lam3k_y3) / d
    d3 = (8.0 * d1 + 7.0 * x * d2 - 6.0 * lam3k_y3 * lam2 * x / (y * y)) / d
    return d1, d2, d3


@jit(inline=True)
def _inside(x, previous, lo, hi):
    if (x > lo and x < hi) or x == previous:
        return x
    return 0.5 * (lo + hi) if math.isfinite(hi) else 2.0 * abs(lo) + 1.0


@jit(inline=True)
def _minimum_time(lam, k, n):
    """(x_min, T_min) of n > 0 revolutions; x_min NaN if Halley does not converge."""
    x, lo, hi = 0.0, -1.0, 1.0
    for _ in range(MAX_ITERATIONS):
        t, y = _time_of_flight(x, lam, k, n)
        d1, d2, d3 = _derivatives(x, t, y, lam, k, n)
        if d1 < 0:
            lo = x
        elif d1 > 0:
            hi = x
        new = _inside(x - 2.0 * d1 * d2 / (2.0 * d2 * d2 - d1 * d3), x, lo, hi)
        done = abs(new - x) <= STEP_TOLERANCE
        x = new
        if done:
            return x, _time_of_flight(x, lam, k, n)[0]
    return _NAN, _NAN


@jit(inline=True)
def _zero_revolution_start(lam, k, t):
    one_minus = k / (1.0 + abs(lam)) if lam > 0 else 1.0 - lam
    l2 = lam * lam
    t0 = math.atan2(math.sqrt(k), lam) + lam * math.sqrt(k)
    t1 = 2.0 / 3.0 * one_minus * (1.0 + lam + l2)
    if t >= t0:
        x = (t0 / t) ** (2.0 / 3.0) - 1.0
    elif t < t1:
        x = 2.5 * t1 / t * (t1 - t) / (one_minus * (1.0 + lam + l2 + l2 * lam + l2 * l2)) + 1.0
    else:
        x = math.exp(math.log(2.0) * math.log(t / t0) / math.log(t1 / t0)) - 1.0
        if not math.isfinite(x):
            x = 0.0
    return x if x > -1.0 else -0.5


@jit(inline=True)
def _find_x(lam, k, t, n, right):
    """Izzo's x with T(x) = t (orbits.core.manoeuvres.lambert.find_x); NaN if infeasible or unconverged."""
    lo, hi, decreasing = -1.0, math.inf, True
    tolerance = ZERO_REVOLUTION_TOLERANCE if n == 0 else STEP_TOLERANCE
    if n == 0:
        x = _zero_revolution_start(lam, k, t)
    else:
        x_min, t_min = _minimum_time(lam, k, n)
        if not (t >= t_min * (1.0 - AT_MINIMUM)):  # also NaN
            return _NAN
        if t <= t_min:
            return x_min
        d1, curvature, d3 = _derivatives(x_min, t_min, math.sqrt(k + lam * lam * x_min * x_min), lam, k, n)
        if right:
            q = (8.0 * t / (n * math.pi)) ** (2.0 / 3.0)
            lo, hi, decreasing = x_min, 1.0, False
        else:
            q = ((n * math.pi + math.pi) / (8.0 * t)) ** (2.0 / 3.0)
            hi = x_min
        x = (q - 1.0) / (q + 1.0)
        if t - t_min < NEAR_MINIMUM * t_min or not (x > lo and x < hi):
            offset = math.sqrt(2.0 * (t - t_min) / curvature)
            x = x_min + offset if right else x_min - offset
    for _ in range(MAX_ITERATIONS):
        value, y = _time_of_flight(x, lam, k, n)
        f = value - t
        if f == 0:
            return x
        d1, d2, d3 = _derivatives(x, value, y, lam, k, n)
        if (f > 0) == decreasing:
            lo = x
        else:
            hi = x
        d1_2 = d1 * d1
        step = -f * (d1_2 - 0.5 * f * d2) / (d1 * (d1_2 - f * d2) + d3 * f * f / 6.0)
        new = _inside(x + step, x, lo, hi)
        done = abs(new - x) <= tolerance * max(1.0, abs(x))
        x = new
        if done:
            return x
    return _NAN


@jit
def solve(start, stop, r1, r2, tof, mu, revolutions, reference, given_normal, right, v1, v2, x_out, angle, a_out):
    """Lambert's problem for elements [start, stop) of flat inputs (orbits.core.manoeuvres.lambert.solve); returns the
    count of elements left unsolved (outputs NaN), which the caller re-runs in NumPy to raise its error.

    r1, r2, reference: (n, 3); tof, mu, revolutions (float): (n,); given_normal, right: 1.0 or 0.0 for all.
    Outputs v1, v2 (n, 3), x_out, angle, a_out (n,)."""
    unsolved = 0
    for i in range(start, stop):
        a1, a2, a3 = r1[i, 0], r1[i, 1], r1[i, 2]
        b1, b2, b3 = r2[i, 0], r2[i, 1], r2[i, 2]
        n1 = math.sqrt(a1 * a1 + a2 * a2 + a3 * a3)
        n2 = math.sqrt(b1 * b1 + b2 * b2 + b3 * b3)
        c1, c2, c3 = a2 * b3 - a3 * b2, a3 * b1 - a1 * b3, a1 * b2 - a2 * b1
        size = math.sqrt(c1 * c1 + c2 * c2 + c3 * c3)
        dot = a1 * b1 + a2 * b2 + a3 * b3
        e1, e2, e3 = reference[i, 0], reference[i, 1], reference[i, 2]
        side = c1 * e1 + c2 * e2 + c3 * e3
        ok = n1 > 0 and n2 > 0 and not (given_normal and side == 0 and size > 0)
        ok = ok and not (size == 0 and (dot > 0 or not given_normal))
        if not ok:
            unsolved += _unsolved(i, v1, v2, x_out, angle, a_out)
            continue
        sign = -1.0 if side < 0 else 1.0
        if size == 0:
            m1, m2, m3 = e1, e2, e3
        else:
            m1, m2, m3 = sign * c1, sign * c2, sign * c3
        half = 0.5 * math.atan2(size, dot)
        sin_half, cos_half = math.sin(half), sign * math.cos(half)
        angle[i] = 2.0 * math.pi - 2.0 * half if side < 0 else 2.0 * half
        root = math.sqrt(n1) * math.sqrt(n2)
        c = math.hypot(n1 - n2, 2.0 * root * sin_half)
        s = 0.5 * (n1 + n2 + c)
        lam, k = root * cos_half / s, c / s
        sigma, rho = 2.0 * root * sin_half / c, (n1 - n2) / c
        t = tof[i] / (s / math.sqrt(2.0 * mu[i] / s))
        x = _find_x(lam, k, t, revolutions[i], right > 0)
        t1x, t1y, t1z = m2 * a3 - m3 * a2, m3 * a1 - m1 * a3, m1 * a2 - m2 * a1
        t1n = math.sqrt(t1x * t1x + t1y * t1y + t1z * t1z)
        if not (math.isfinite(x) and t1n > 0):
            unsolved += _unsolved(i, v1, v2, x_out, angle, a_out)
            continue
        t2x, t2y, t2z = m2 * b3 - m3 * b2, m3 * b1 - m1 * b3, m1 * b2 - m2 * b1
        t2n = math.sqrt(t2x * t2x + t2y * t2y + t2z * t2z)
        y = math.sqrt(k + lam * lam * x * x)
        gamma = math.sqrt(0.5 * mu[i] * s)
        plus = 1.0 + rho if rho >= 0 else sigma * sigma / (1.0 - rho)
        minus = sigma * sigma / (1.0 + rho) if rho >= 0 else 1.0 - rho
        ly, lx = lam * y, lam * x
        tangential = gamma * sigma * (k / (y - lx) if lx < 0 else y + lx)
        vr1 = gamma * (ly * minus - x * plus) / n1
        vr2 = -gamma * (ly * plus - x * minus) / n2
        vt1, vt2 = tangential / n1 / t1n, tangential / n2 / t2n
        v1[i, 0], v1[i, 1], v1[i, 2] = vr1 * a1 / n1 + vt1 * t1x, vr1 * a2 / n1 + vt1 * t1y, vr1 * a3 / n1 + vt1 * t1z
        v2[i, 0], v2[i, 1], v2[i, 2] = vr2 * b1 / n2 + vt2 * t2x, vr2 * b2 / n2 + vt2 * t2y, vr2 * b3 / n2 + vt2 * t2z
        x_out[i] = x
        d = (1.0 - x) * (1.0 + x)
        a_out[i] = s / (2.0 * d) if d != 0 else math.inf
    return unsolved


@jit(inline=True)
def _unsolved(i, v1, v2, x_out, angle, a_out):
    for j in range(3):
        v1[i, j] = _NAN
        v2[i, j] = _NAN
    x_out[i] = angle[i] = a_out[i] = _NAN
    return 1
