"""Compiled universal-variable propagator (orbits/core/twobody/_fast_propagate.py) against NumPy and mpmath."""

import math

import mpref
import numpy as np
import pytest

from orbits.core import _fast
from orbits.core.errors import DegenerateOrbitError, OrbitDomainError
from orbits.core.twobody import elements
from orbits.core.twobody.propagate import propagate

pytest.importorskip("numba")

MU = 3.986004418e14


def mixed_states(rng, n):
    """Ellipses (e < 0.95), hyperbolas (e - 1 from 1e-6 to 3) and near-parabolic orbits (|1 - e| < 1e-3),
    over up to 10 periods (ellipses) or 10 * 2 pi sqrt(p**3 / mu) either way."""
    third = n // 3
    e = np.concatenate(
        [
            rng.uniform(0, 0.95, third),
            1 + 10 ** rng.uniform(-6, 0.5, third),
            1 + rng.uniform(-1e-3, 1e-3, n - 2 * third),
        ]
    )
    p = 7e6 * rng.uniform(1, 3, n)
    angles = rng.uniform(0, np.pi, n), rng.uniform(0, 2 * np.pi, n), rng.uniform(0, 2 * np.pi, n), rng.uniform(-1, 1, n)
    r0, v0 = elements.elements_to_state(p, e, *angles, MU)
    with np.errstate(invalid="ignore"):
        period = np.where(e < 1, 2 * np.pi * np.sqrt((p / np.abs(1 - e * e)) ** 3 / MU), 2 * np.pi * np.sqrt(p**3 / MU))
    return r0, v0, rng.uniform(-10, 10, n) * period


def relative(a, b):
    return np.linalg.norm(a - b, axis=-1) / np.linalg.norm(b, axis=-1)


def test_compiled_and_numpy_agree():
    r0, v0, dt = mixed_states(np.random.default_rng(61), 30_000)
    previous = _fast.set_enabled(True)  # the kernels at every batch size
    try:
        r, v = propagate(r0, v0, MU, dt)
        _fast.set_enabled(False)
        r_np, v_np = propagate(r0, v0, MU, dt)
    finally:
        _fast.set_enabled(previous)
    # Positions relative to |r|: measured 2.3e-15. Velocities relative to max(|v|, |v0|), the size of the terms of
    # v = f' r0 + g' v0, whose rounding is what an ill-conditioned velocity (near apoapsis of e -> 1, |v| down to
    # 3e-5 |v0| here) keeps of it: measured 8.3e-16 (relative to |v| alone 8e-12, within 0.7 eps (1 + e) / (1 - e)).
    speed = np.maximum(np.linalg.norm(v_np, axis=-1), np.linalg.norm(v0, axis=-1))
    assert np.max(relative(r, r_np)) <= 1e-14
    assert np.max(np.linalg.norm(v - v_np, axis=-1) / speed) <= 5e-15


@pytest.mark.parametrize("jit", [True, False], ids=["compiled", "numpy"])
def test_mixed_conics_against_mpmath(jit):
    """Both paths against mpmath on 60 mixed states: positions to 5e-15 (measured 5.4e-16), velocities to 8e-13
    (measured 7.6e-14) relative, on either path."""
    r0, v0, dt = mixed_states(np.random.default_rng(62), 60)
    previous = _fast.set_enabled(jit)
    try:
        r, v = propagate(r0, v0, MU, dt)
    finally:
        _fast.set_enabled(previous)
    references = [[np.array([float(x) for x in ref]) for ref in mpref.propagate(r0[i], v0[i], MU, dt[i])]
                  for i in range(len(dt))]
    r_ref, v_ref = (np.array(column) for column in zip(*references))
    assert np.max(relative(r, r_ref)) <= 5e-15
    assert np.max(relative(v, v_ref)) <= 8e-13


def test_safeguarded_pass_matches_the_vectorised_pass():
    """Pass 2 (bracketed Halley from the same starter) gives the pass-1 root, checked state by state."""
    from orbits.core.twobody import _fast_universal as kernel

    r0, v0, dt = mixed_states(np.random.default_rng(63), 300)
    mu = np.full(len(dt), MU)
    for i in range(len(dt)):
        scaled = kernel._scaled(*r0[i], *v0[i], mu[i], dt[i])
        problem, p, coefficients = scaled[9:13], kernel._semilatus(scaled), kernel._coefficients(scaled)
        chi_safe = kernel._solve_universal(*problem, p, *coefficients)
        x, lo, hi = kernel._starter(*problem, p, *coefficients), 0.0, math.inf
        for _ in range(kernel.FIXED_STEPS):
            x, lo, hi, _ = kernel._fixed_step(x, lo, hi, *problem, *coefficients)
        chi_fixed, _ = kernel._polish(x, *problem, *coefficients)
        assert abs(chi_safe - chi_fixed) <= 1e-14 * chi_fixed


@pytest.mark.parametrize(
    "args, error, fragment",
    [
        (([1e7, 0, 0], [-1e3, 0, 0], MU, 10.0), DegenerateOrbitError, "radial"),
        (([1e7, 0, 0], [0, 7e3, 0], MU, np.array([1.0, np.nan])), OrbitDomainError, "not finite"),
        (([1e7, 0, 0], [0, 7e3, 0], -MU, 1.0), OrbitDomainError, "must be positive"),
        (([0, 0, 0], [0, 7e3, 0], MU, 1.0), OrbitDomainError, "coincides with the primary"),
        (([1e7, 0], [0, 7e3], MU, 1.0), OrbitDomainError, "last axis of length 3"),
    ],
)
def test_invalid_input_raises_the_numpy_message(args, error, fragment):
    with pytest.raises(error, match=fragment):
        propagate(*(np.asarray(a, dtype=float) for a in args))


def test_one_compilation_for_every_input_layout():
    from orbits.core.twobody import _fast_propagate as kernel

    r0, v0 = np.array([7e6, 1e5, 0.0]), np.array([0.0, 7.5e3, 10.0])
    propagate(r0, v0, MU, 10.0)
    propagate(np.broadcast_to(r0, (4, 3)), v0, np.float32(MU), np.arange(4.0))
    propagate(np.tile(r0, (5, 1))[:, None, :], v0, MU, np.arange(3.0))
    assert len(kernel.propagate.signatures) == 1
