"""Collisions (notes IX) on float64 arrays: the notes' special cases, the errata, identities and mpmath."""

import math

import mpmath
import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st

from orbits.core.errors import OrbitDomainError
from orbits.core.mechanics import collisions

masses = st.floats(1e-6, 1e6)
speeds = st.floats(-1e3, 1e3)
restitutions = st.floats(0.0, 1.0)


def reference_after(m1, v1, m2, v2, e):
    """The notes' (1 + e) v_c - e v_i at 50 digits (IX.xi)."""
    with mpmath.workdps(50):
        m1, v1, m2, v2, e = (mpmath.mpf(x) for x in (m1, v1, m2, v2, e))
        vc = (m1 * v1 + m2 * v2) / (m1 + m2)
        return float((1 + e) * vc - e * v1), float((1 + e) * vc - e * v2)


@given(masses, speeds, masses, speeds, restitutions)
def test_velocities_after_agree_with_the_notes_formula_at_50_digits(m1, v1, m2, v2, e):
    """ERRATA #12: v1' = (1 + e) v_c - e v1, v2' = (1 + e) v_c - e v2; our form through the mass fractions and
    the relative velocity is within 10 ulp of the larger speed (measured 8.0 ulp over 20000 log-uniform random
    cases: the kick (1 + e)(v1 - v2) is up to 4 times the larger speed and is rounded twice)."""
    got = collisions.velocities_after(m1, v1, m2, v2, e)
    want = reference_after(m1, v1, m2, v2, e)
    scale = max(abs(v1), abs(v2), 1e-300)
    for a, b in zip(got, want):
        assert abs(a - b) <= 10 * math.ulp(scale)


@given(masses, speeds, masses, speeds, restitutions)
def test_momentum_and_the_relative_velocity(m1, v1, m2, v2, e):
    """Momentum is conserved and v2' - v1' = e (v1 - v2) (IX.vi, ERRATA #5), K_int' = e**2 K_int (IX.xi)."""
    a1, a2 = collisions.velocities_after(m1, v1, m2, v2, e)
    scale = (m1 + m2) * max(abs(v1), abs(v2))
    assert abs((m1 * a1 + m2 * a2) - (m1 * v1 + m2 * v2)) <= 8 * math.ulp(scale)
    assert abs((a2 - a1) - e * (v1 - v2)) <= 4 * math.ulp(2 * max(abs(v1), abs(v2), 1e-300))
    before = collisions.internal_kinetic_energy(m1, v1, m2, v2)
    after = collisions.internal_kinetic_energy(m1, a1, m2, a2)
    mu = collisions.reduced_mass(m1, m2)  # K_int' = e**2 K_int, to the rounding of v2' - v1' (a difference)
    assert abs(math.sqrt(after) - e * math.sqrt(before)) <= math.sqrt(mu / 2) * 4 * math.ulp(2 * max(abs(v1), abs(v2)))
    total_before = collisions.kinetic_energy(m1, v1) + collisions.kinetic_energy(m2, v2)
    total_after = collisions.kinetic_energy(m1, a1) + collisions.kinetic_energy(m2, a2)
    assert total_after <= total_before * (1 + 1e-14)  # ERRATA #1: after <= before, not before <= after


def test_notes_special_cases_of_the_elastic_and_inelastic_collision():
    """IX.vii, ix, xi (ERRATA #6, #9, #12): equal masses swap; a heavy body is undisturbed; a light one bounces."""
    assert collisions.velocities_after(2.0, 3.0, 2.0, -1.0) == (-1.0, 3.0)
    assert collisions.velocities_after(2.0, 3.0, 2.0, -1.0, 0.0) == (1.0, 1.0)  # both at v_c
    assert collisions.velocities_after(2.0, 3.0, 2.0, -1.0, 0.5) == (0.0, 2.0)  # ((1-e)v1 + (1+e)v2) / 2
    heavy, light = collisions.velocities_after(1e30, 2.0, 1.0, 0.5, 0.6)
    assert heavy == 2.0 and light == pytest.approx((1 + 0.6) * 2.0 - 0.6 * 0.5, rel=1e-15)
    light, heavy = collisions.velocities_after(1.0, 4.0, 1e30, 0.0, 0.6)
    assert light == pytest.approx(-0.6 * 4.0, rel=1e-15) and heavy == pytest.approx(0.0, abs=1e-29)
    v1, v2 = collisions.velocities_after(3.0, 2.0, 1.0, 0.0)  # v2 = 0: ((m1 - m2) v1, 2 m1 v1) / (m1 + m2)
    assert (v1, v2) == (1.0, 3.0)
    assert collisions.center_of_mass_velocity(3.0, 2.0, 1.0, 0.0) == 1.5


def test_wall_bounce_is_the_heavy_limit():
    """v' = (1 + e) U - e v, the m1 -> infinity limit of IX.xi (ERRATA #12); elastic: 2 U - v (the slingshot)."""
    assert collisions.bounce_off_moving_wall(13.0, -30.0) == 56.0
    limit = collisions.velocities_after(1e300, 13.0, 1.0, -30.0, 0.8)[1]
    assert collisions.bounce_off_moving_wall(13.0, -30.0, 0.8) == pytest.approx(limit, rel=1e-15)


def test_energy_transfer_to_a_body_at_rest_has_the_factor_four():
    """ERRATA #7: K2'/K1 = 4 r / (1 + r)**2 = 4 m1 m2 / (m1 + m2)**2 (the notes write m1 m2 / (m1 + m2)**2);
    1 at r = 1 and 8/9 at r = 1/2 and 2, as the notes say. ERRATA #8: K1'/K1 = ((1 - r) / (1 + r))**2."""
    r = np.array([1.0, 0.5, 2.0])
    assert collisions.energy_transfer_ratio(r) == pytest.approx([1.0, 8 / 9, 8 / 9], rel=1e-15)
    m1, m2 = 1.0, 2.0
    notes_second_form = m1 * m2 / (m1 + m2) ** 2
    assert collisions.energy_transfer_ratio(m1 / m2) == pytest.approx(4 * notes_second_form, rel=1e-15)
    assert notes_second_form == pytest.approx(2 / 9)  # not the stated 8/9
    for ratio in (0.1, 0.5, 1.0, 3.0, 50.0):
        for e in (1.0, 0.7, 0.0):
            v1, v2 = collisions.velocities_after(ratio, 3.0, 1.0, 0.0, e)
            k1 = collisions.kinetic_energy(ratio, 3.0)
            assert collisions.energy_transfer_ratio(ratio, e) == pytest.approx(
                collisions.kinetic_energy(1.0, v2) / k1, rel=1e-14)
            assert collisions.energy_kept_ratio(ratio, e) == pytest.approx(
                collisions.kinetic_energy(ratio, v1) / k1, rel=1e-14, abs=1e-16)


def test_restitution_range_and_internal_energy_after():
    """ERRATA #10: e = 0 leaves no internal energy (case ix); 0 < e < 1 leaves 0 < K_int' < K_int."""
    assert collisions.internal_kinetic_energy(1.0, *collisions.velocities_after(1.0, 2.0, 3.0, -1.0, 0.0)[:1],
                                              3.0, collisions.velocities_after(1.0, 2.0, 3.0, -1.0, 0.0)[1]) == 0.0
    before = collisions.internal_kinetic_energy(1.0, 2.0, 3.0, -1.0)
    a1, a2 = collisions.velocities_after(1.0, 2.0, 3.0, -1.0, 0.5)
    assert 0 < collisions.internal_kinetic_energy(1.0, a1, 3.0, a2) < before
    for bad in (-0.1, 1.5, math.nan):
        with pytest.raises(OrbitDomainError, match=r"coefficient of restitution e = .* \[0, 1\]|not finite"):
            collisions.check_restitution(bad)


def test_internal_energy_is_the_reduced_mass_form():
    """ERRATA #3: total K - (m1 + m2) v_c**2 / 2 = mu (v1 - v2)**2 / 2; #13: k x**2 / 2 = K_int."""
    m1, v1, m2, v2 = 2.0, 5.0, 3.0, -1.0
    vc = collisions.center_of_mass_velocity(m1, v1, m2, v2)
    total = collisions.kinetic_energy(m1, v1) + collisions.kinetic_energy(m2, v2)
    assert total - 0.5 * (m1 + m2) * vc**2 == pytest.approx(collisions.internal_kinetic_energy(m1, v1, m2, v2),
                                                            rel=2e-15)  # measured 2.2e-16
    x = collisions.spring_compression(m1, v1, m2, v2, 40.0)
    assert 0.5 * 40.0 * x**2 == pytest.approx(collisions.internal_kinetic_energy(m1, v1, m2, v2), rel=1e-15)


def test_oblique_collision_in_the_notes_model_and_along_a_contact_normal():
    """ERRATA #14: v_t is perpendicular to v2 - v1 and v_i = v_t + (v_i . n) n; the notes' model collides the
    components along the relative velocity; an impulse along a contact normal keeps the tangential components."""
    v1, v2 = np.array([3.0, 1.0, 0.0]), np.array([-1.0, 2.0, 0.5])
    m1, m2, e = 2.0, 5.0, 0.7
    foot = collisions.perpendicular_foot(v1, v2)
    n = collisions.line_of_impact(v1, v2)
    assert abs(np.dot(foot, v2 - v1)) < 4e-16 * np.dot(v2 - v1, v2 - v1)  # measured 0
    np.testing.assert_allclose(foot + np.dot(v1, n) * n, v1, rtol=0, atol=4e-16 * 3)
    a1, a2 = collisions.oblique_velocities_after(m1, v1, m2, v2, e)
    along = collisions.velocities_after(m1, np.dot(v1, n), m2, np.dot(v2, n), e)
    np.testing.assert_allclose(a1, foot + along[0] * n, atol=2e-15)
    np.testing.assert_allclose(a2, foot + along[1] * n, atol=2e-15)
    np.testing.assert_allclose(m1 * a1 + m2 * a2, m1 * v1 + m2 * v2, rtol=0, atol=1e-14)
    normal = np.array([1.0, 0.0, 0.0])
    b1, b2 = collisions.oblique_velocities_after(m1, v1, m2, v2, e, normal)
    assert list(b1[1:]) == list(v1[1:]) and list(b2[1:]) == list(v2[1:])
    assert b2[0] - b1[0] == pytest.approx(e * (v1[0] - v2[0]), rel=1e-15)
    with pytest.raises(OrbitDomainError, match=r"approach speed .* \(0, inf\) m/s"):
        collisions.oblique_velocities_after(m1, v1, m2, v2, e, -normal)
    with pytest.raises(OrbitDomainError, match="never collide"):
        collisions.line_of_impact(v1, v1)


def test_spring_dashpot_restitution():
    """e(0) = 1 (a spring is elastic); e falls as exp(-pi zeta / sqrt(1 - zeta**2)); checked by integration in
    tests/validation/test_mechanics_integration.py."""
    assert collisions.restitution_of_spring_dashpot(0.0) == 1.0
    assert collisions.restitution_of_spring_dashpot(0.5) == pytest.approx(math.exp(-math.pi / math.sqrt(3)))


def test_energy_lost_is_the_drop_in_kinetic_energy():
    """(1 - e**2) mu v_n**2 / 2 against K - K' summed at 50 digits from the velocities after (independent of the
    closed form): head-on, oblique along a given normal and along the relative velocity; exactly 0 when elastic.
    Measured 6.7e-16 at most (relative; the velocities after are float64, so K' carries their rounding)."""
    cases = [
        (2.0, 3.0, 1.0, -1.0, 0.5, None, False),
        (0.3, 12.5, 7.0, 0.25, 0.8, None, False),
        (2.0, [3.0, 1.0, 0.0], 1.0, [-1.0, 0.5, 0.2], 0.6, [1.0, 2.0, 0.0], True),
        (5.0, [0.0, 4.0, 1.0], 3.0, [1.0, -2.0, 0.0], 0.3, None, True),
    ]
    with mpmath.workdps(50):
        for m1, v1, m2, v2, e, normal, vectors in cases:
            if vectors:
                w1, w2 = collisions.oblique_velocities_after(m1, v1, m2, v2, e, normal)
            else:
                w1, w2 = collisions.velocities_after(m1, v1, m2, v2, e)

            def kinetic(m, v):
                return mpmath.mpf(m) * sum(mpmath.mpf(float(x)) ** 2 for x in np.atleast_1d(v)) / 2

            drop = kinetic(m1, v1) + kinetic(m2, v2) - kinetic(m1, w1) - kinetic(m2, w2)
            lost = collisions.energy_lost(m1, v1, m2, v2, e, normal, vectors)
            assert abs(float((lost - drop) / drop)) <= 4e-15, (m1, v1, e)
            assert collisions.energy_lost(m1, v1, m2, v2, 1.0, normal, vectors) == 0.0
