"""Compiled state-transition matrix (numba): a port of orbits.core.twobody.transition, one state at a time.

Imported only through orbits.core.twobody.transition when orbits.core._fast.use lets a batch run compiled. The scaled
problem, the starter, the FIXED_STEPS bracketed Halley steps and the certificate (vectorised, block by block)
and the safeguarded iteration are the propagator's kernels (orbits/core/twobody/_fast_universal.py); then the same total
derivatives of f, g, f', g' in
(R, sigma, alpha), the same assembly in the basis (r0, v0), and the same SI scales, time reversal and secular
term as the NumPy version, state by state.
"""

import math

import numpy as np

from orbits.core._fast import jit
from orbits.core._fast_math import _horner
from orbits.core.twobody._fast_universal import (
    _BLOCK,
    _CHI,
    _INVALID,
    _ROWS,
    _certify_block,
    _coefficients,
    _gather_block,
    _scaled,
    _semilatus,
    _setup_block,
    _solve_universal,
    _step_block,
    _stumpff,
)
from orbits.core.twobody._propagate_shared import C4_SERIES, C5_SERIES, C45_SERIES_LIMIT, FIXED_STEPS


@jit(inline=True)
def _g_functions(chi, alpha):
    """transition.g_functions: (G0, .., G5)."""
    z = alpha * chi * chi
    c0, c1, c2, c3, _, _ = _stumpff(z)
    small = abs(z) <= C45_SERIES_LIMIT
    c4 = _horner(C4_SERIES, z) if small else (0.5 - c2) / z
    c5 = _horner(C5_SERIES, z) if small else (1.0 / 6.0 - c3) / z
    chi2 = chi * chi
    return c0, chi * c1, chi2 * c2, chi2 * chi * c3, chi2 * chi2 * c4, chi2 * chi2 * chi * c5


@jit(inline=True)
def _gradient(d_R, d_sigma, d_alpha, R):
    """(along r0 in grad_r0, along v0 in grad_r0, along r0 in grad_v0, along v0 in grad_v0) of a scalar with total
    derivatives d_R, d_sigma, d_alpha (transition.scaled_coefficients)."""
    return d_R / R - 2.0 * d_alpha / (R * R * R), d_sigma, d_sigma, -2.0 * d_alpha


@jit(inline=True)
def _scaled_coefficients(chi, R, sigma, alpha):
    """transition.scaled_coefficients: (f, g, f', g') and the gradient components of each (four numbers, see
    _gradient) in the scaled problem."""
    G0, G1, G2, G3, G4, G5 = _g_functions(chi, alpha)
    r = R * G0 + sigma * G1 + G2
    A0, A1, A2, A3 = -0.5 * chi * G1, -0.5 * (chi * G2 - G3), -0.5 * (chi * G3 - 2.0 * G4), -0.5 * (chi * G4 - 3.0 * G5)
    chi_R, chi_s, chi_a = -G1 / r, -G2 / r, -(R * A1 + sigma * A2 + A3) / r
    r_chi = sigma * G0 + (1.0 - alpha * R) * G1
    Dr_R, Dr_s, Dr_a = G0 + r_chi * chi_R, G1 + r_chi * chi_s, (R * A0 + sigma * A1 + A2) + r_chi * chi_a
    f, g, fd, gd = 1.0 - G2 / R, R * G1 + sigma * G2, -G1 / (r * R), 1.0 - G2 / r
    DG1_R, DG1_s, DG1_a = G0 * chi_R, G0 * chi_s, A1 + G0 * chi_a
    DG2_R, DG2_s, DG2_a = G1 * chi_R, G1 * chi_s, A2 + G1 * chi_a
    inverse_r = 1.0 / r
    grad_f = _gradient(G2 / (R * R) - DG2_R / R, -DG2_s / R, -DG2_a / R, R)
    grad_g = _gradient(G1 + R * DG1_R + sigma * DG2_R, G2 + R * DG1_s + sigma * DG2_s, R * DG1_a + sigma * DG2_a, R)
    grad_fd = _gradient(-DG1_R * inverse_r / R - fd * (Dr_R * inverse_r + 1.0 / R),
                        -DG1_s * inverse_r / R - fd * Dr_s * inverse_r,
                        -DG1_a * inverse_r / R - fd * Dr_a * inverse_r, R)
    grad_gd = _gradient(-DG2_R * inverse_r + G2 * Dr_R * inverse_r * inverse_r,
                        -DG2_s * inverse_r + G2 * Dr_s * inverse_r * inverse_r,
                        -DG2_a * inverse_r + G2 * Dr_a * inverse_r * inverse_r, R)
    return f, g, fd, gd, grad_f, grad_g, grad_fd, grad_gd


@jit(inline=True)
def _fill_block(phi, i, row, column, diagonal, q_r, q_v, p_r, p_v, basis, scale):
    """phi[i, row + a, column + b] = scale (diagonal delta_ab + r0_a grad(q)_b + v0_a grad(p)_b) with
    grad(q) = q_r r0 + q_v v0, grad(p) = p_r r0 + p_v v0 (transition._assemble)."""
    for a in range(3):
        r_a, v_a = basis[0, a], basis[1, a]
        for b in range(3):
            r_b, v_b = basis[0, b], basis[1, b]
            value = r_a * (q_r * r_b + q_v * v_b) + v_a * (p_r * r_b + p_v * v_b)
            phi[i, row + a, column + b] = scale * (value + diagonal if a == b else value)


@jit
def _transition_one(rx, ry, rz, vx, vy, vz, mu, dt, chi, phi, i, basis):
    """phi[i] (6, 6) of one state from its universal anomaly chi (pass 2 first if chi is NaN: pass 1 did not certify
    it); returns 1 if pass 2 did not converge either (phi then NaN) else 0."""
    scaled = _scaled(rx, ry, rz, vx, vy, vz, mu, dt)
    length, speed, back = scaled[0], scaled[1], scaled[2]
    grow, decay = _coefficients(scaled)
    if np.isnan(chi):
        chi = _solve_universal(scaled[9], scaled[10], scaled[11], scaled[12], _semilatus(scaled), grow, decay)
    f, g, fd, gd, grad_f, grad_g, grad_fd, grad_gd = _scaled_coefficients(chi, scaled[10], scaled[11], scaled[12])
    for k in range(3):
        basis[0, k], basis[1, k] = scaled[3 + k], scaled[6 + k]
    _fill_block(phi, i, 0, 0, f, grad_f[0], grad_f[1], grad_g[0], grad_g[1], basis, 1.0)
    _fill_block(phi, i, 0, 3, g, grad_f[2], grad_f[3], grad_g[2], grad_g[3], basis, back * length / speed)
    _fill_block(phi, i, 3, 0, fd, grad_fd[0], grad_fd[1], grad_gd[0], grad_gd[1], basis, back * speed / length)
    _fill_block(phi, i, 3, 3, gd, grad_fd[2], grad_fd[3], grad_gd[2], grad_gd[3], basis, 1.0)
    if scaled[14] != 0.0:  # whole periods taken off dt
        _secular(phi, i, basis, f, g, fd, gd, scaled, rx, ry, rz, vx, vy, vz, mu)
    return np.isnan(chi)


@jit(inline=True)
def _secular(phi, i, basis, f, g, fd, gd, scaled, rx, ry, rz, vx, vy, vz, mu):
    """phi[i] -= k (v, a) grad(P)^T for the k periods taken off dt (transition._to_si); basis rows 2 and 3 hold
    (v, a) and grad(P)."""
    length, speed, back, alpha, turns, period = scaled[0], scaled[1], scaled[2], scaled[12], scaled[14], scaled[15]
    x = (f * basis[0, 0] + g * basis[1, 0]) * length
    y = (f * basis[0, 1] + g * basis[1, 1]) * length
    z = (f * basis[0, 2] + g * basis[1, 2]) * length
    r2 = x * x + y * y + z * z
    factor = -mu / (r2 * math.sqrt(r2))
    for k in range(3):
        basis[2, k] = (fd * basis[0, k] + gd * basis[1, k]) * back * speed
    basis[2, 3], basis[2, 4], basis[2, 5] = factor * x, factor * y, factor * z
    scale = 3.0 * period / (alpha / length)  # -d P / d alpha times -2 from the gradient of alpha
    cube = length * length * length
    basis[3, 0], basis[3, 1], basis[3, 2] = scale * rx / cube, scale * ry / cube, scale * rz / cube
    basis[3, 3], basis[3, 4], basis[3, 5] = scale * vx / mu, scale * vy / mu, scale * vz / mu
    for a in range(6):
        for b in range(6):
            phi[i, a, b] -= turns * basis[2, a] * basis[3, b]


@jit
def transition(start, stop, r0, v0, mu, dt, phi):
    """phi[i] = d(r, v) / d(r0, v0) of state i, for start <= i < stop; returns invalid * 2**32 + unconverged. The
    universal anomaly by the propagator's pass 1, vectorised block by block, then the matrix state by state."""
    r0, v0, mu, dt, phi = r0[start:stop], v0[start:stop], mu[start:stop], dt[start:stop], phi[start:stop]
    index = np.arange(dt.size)
    scratch = np.empty((_ROWS, _BLOCK))
    basis = np.empty((4, 6))
    invalid, unconverged = 0, 0
    for first in range(0, dt.size, _BLOCK):
        size = min(_BLOCK, dt.size - first)
        _gather_block(index, first, size, r0, v0, mu, dt, scratch)
        invalid += _setup_block(size, scratch)
        for _ in range(FIXED_STEPS):
            _step_block(size, scratch)
        _certify_block(size, scratch)
        if invalid:
            continue
        for j in range(size):
            i = first + j
            unconverged += _transition_one(r0[i, 0], r0[i, 1], r0[i, 2], v0[i, 0], v0[i, 1], v0[i, 2], mu[i], dt[i],
                                           scratch[_CHI, j], phi, i, basis)
    return invalid * _INVALID + unconverged
