"""Section XXII (two finite masses) in the numeric core, against mpmath evaluations of the notes' own forms.

The references are written in the notes' variables (XXII.iv: star m has semi-major axis M alpha and focal
distance M gamma, star M has m alpha and m gamma, the relative orbit (m + M) alpha), with the ERRATA's
corrections (#64 e = gamma / alpha, #68 sigma_b = sqrt(G / alpha) / (m + M)), at 50 digits. The library
forms them differently: each star as a Kepler orbit about the centre of mass with the parameter
G m_j**3 / (m1 + m2)**2 and p scaled by m_j / (m1 + m2). Star 1 is the notes' M, star 2 the notes' m.
"""

import math

import mpmath
import mpref
import numpy as np
import pytest

from orbits.core import checks
from orbits.core.encounters import binary
from orbits.core.errors import OrbitDomainError
from orbits.core.twobody import elements, twobody

DPS = 50
RATIOS = [1e-15, 1e-8, 0.012300037, 0.3, 1.0, 2.5, 7.3e3]


def ulps(x, ref):
    return float(mpref.ulp_error(x, ref))


def notes_binary(gm_big, gm_small, relative_a, e):
    """mpmath quantities of XXII.iv in the notes' variables for stars M (parameter G M) and m (G m).

    Masses enter as G M and G m with G = 1, so the notes' G m M becomes gm_big gm_small; the relative orbit
    has semi-major axis (m + M) alpha = relative_a (a length, m)."""
    with mpmath.workdps(DPS):
        big, small, e = mpmath.mpf(gm_big), mpmath.mpf(gm_small), mpmath.mpf(e)
        total = big + small
        alpha = mpmath.mpf(relative_a) / total
        gamma = e * alpha
        return {
            "r1": total * (alpha - gamma),
            "r2": total * (alpha + gamma),
            "energy": -big * small / (2 * total * alpha),
            "angular_momentum": big * small * mpmath.sqrt((alpha + gamma) * (alpha - gamma) / alpha),
            "sigma1": mpmath.sqrt((alpha + gamma) / (alpha * (alpha - gamma))) / total,
            "sigma2": mpmath.sqrt((alpha - gamma) / (alpha * (alpha + gamma))) / total,
            "sigma_b": mpmath.sqrt(1 / alpha) / total,
            "a_small": big * alpha,  # star m's semi-major axis (the notes' a)
            "a_big": small * alpha,  # star M's (the notes' q)
            "period": 2 * mpmath.pi * mpmath.sqrt((total * alpha) ** 3 / total),
            "big": big,
            "small": small,
        }


CORRECTLY_ROUNDED = 0.5 + 1e-9  # ulps: the double-double result is the float nearest the exact value


@pytest.mark.parametrize("ratio", RATIOS)
@pytest.mark.parametrize("m1", [1.98847e30, 5.9722e24, 1.0, 3e-5])
def test_mass_fractions_and_reduced_mass_are_correctly_rounded(m1, ratio):
    """EDGE_CASES #45: mu = m2 / (m1 + m2) without cancellation, even at m2 / m1 = 1e-15 (a sweep of 15000
    random ratios from 1e-16 to 1e10 measured 0.49999 ulp at worst)."""
    m2 = m1 * ratio
    x1, x2 = binary.mass_fractions(m1, m2)
    with mpmath.workdps(DPS):
        a, b = mpmath.mpf(m1), mpmath.mpf(m2)
        assert ulps(x1, a / (a + b)) <= CORRECTLY_ROUNDED
        assert ulps(x2, b / (a + b)) <= CORRECTLY_ROUNDED
        assert ulps(binary.reduced_mass(m1, m2), a * b / (a + b)) <= CORRECTLY_ROUNDED


def test_reduced_mass_of_huge_masses_does_not_overflow():
    m1, m2 = 3e200, 7e199  # m1 m2 overflows float64
    with mpmath.workdps(DPS):
        assert ulps(binary.reduced_mass(m1, m2), mpmath.mpf(m1) * m2 / (mpmath.mpf(m1) + m2)) <= CORRECTLY_ROUNDED


@pytest.mark.parametrize("ratio", [1e-15, 0.3, 1.0, 4.0])
def test_star_parameter_is_keplers_third_law_for_each_star(ratio):
    """XXII.iii: a**3 / T**2 = G M**3 / ((m + M)**2 4 pi**2), q**3 / T**2 = G m**3 / (...), with T of the pair."""
    gm1, gm2, a_rel = 1.32712440018e20, 1.32712440018e20 * ratio, 7.78e11
    period = twobody.period(a_rel, 0.0, gm1 + gm2)
    x1, x2 = binary.mass_fractions(gm1, gm2)
    for share, gm_other in ((x2, gm2), (x1, gm1)):
        mu_star = binary.star_parameter(gm_other, gm1 + gm2)
        a_star = share * a_rel
        assert math.isclose(binary.kepler_constant(mu_star), a_star**3 / period**2, rel_tol=4e-15)
        with mpmath.workdps(DPS):
            ref = mpmath.mpf(gm_other) ** 3 / (mpmath.mpf(gm1) + gm2) ** 2
            assert ulps(mu_star, ref) <= 2
    assert math.isclose(binary.kepler_constant(gm1 + gm2), a_rel**3 / period**2, rel_tol=4e-15)


@pytest.mark.parametrize("ratio", [1e-15, 0.0123, 0.3, 1.0, 3.0])
@pytest.mark.parametrize("e", [0.0, 0.0549, 0.6, 0.97])
def test_each_star_as_a_kepler_orbit_matches_the_notes(ratio, e):
    """Both stars' distances, speeds (XXII.iv's M sigma and m sigma) and periods, E and L (XXII.iv); measured
    over this grid: <= 1.9 ulp, and 4.2 ulp for the period."""
    gm1, gm2, a_rel = 3.986004e14, 3.986004e14 * ratio, 3.84399e8
    ref = notes_binary(gm1, gm2, a_rel, e)
    p = a_rel * (1 - e) * (1 + e)
    x1, x2 = binary.mass_fractions(gm1, gm2)
    with mpmath.workdps(DPS):
        # star 2 is the notes' m (speeds M sigma), star 1 the notes' M (speeds m sigma)
        stars = ((x1, gm1, ref["big"], ref["a_small"]), (x2, gm2, ref["small"], ref["a_big"]))
        for share, gm_other, factor, a_ref in stars:
            mu_star, p_star = binary.star_parameter(gm_other, gm1 + gm2), share * p
            assert ulps(twobody.semi_major_axis(p_star, e), a_ref) <= 4
            assert ulps(twobody.periapsis_speed(p_star, e, mu_star), factor * ref["sigma1"]) <= 4
            assert ulps(twobody.apoapsis_speed(p_star, e, mu_star), factor * ref["sigma2"]) <= 4
            assert ulps(twobody.covertex_speed(p_star, e, mu_star), factor * ref["sigma_b"]) <= 4
            assert ulps(twobody.periapsis_distance(p_star, e), factor * ref["r1"] / (ref["big"] + ref["small"])) <= 4
            if e > 0:
                apoapsis = factor * ref["r2"] / (ref["big"] + ref["small"])
                assert ulps(twobody.apoapsis_distance(p_star, e), apoapsis) <= 4
            assert ulps(twobody.period(p_star, e, mu_star), ref["period"]) <= 8  # each star's own Kepler III
        reduced = binary.reduced_mass(gm1, gm2)  # G m M / (m + M) with G = 1 in the reference
        assert ulps(reduced * twobody.specific_energy(p, e, gm1 + gm2), ref["energy"]) <= 4
        assert ulps(reduced * twobody.specific_angular_momentum(p, gm1 + gm2), ref["angular_momentum"]) <= 4


def test_the_notes_uncorrected_covertex_speed_is_off_by_sqrt_total_mass():
    """ERRATA #68: the notes' sigma_b = sqrt(G / ((m + M) alpha)) misses a factor 1 / sqrt(m + M)."""
    ref = notes_binary(1.0, 0.3, 1.0, 0.5)
    with mpmath.workdps(DPS):
        total = ref["big"] + ref["small"]
        alpha = 1 / total
        printed = mpmath.sqrt(1 / (total * alpha))
        assert abs(printed / ref["sigma_b"] - mpmath.sqrt(total)) < mpmath.mpf(10) ** -40


@pytest.mark.parametrize("e", [0.0, 0.4])
@pytest.mark.parametrize("inc", [0.0, 0.7, math.pi])
def test_star_angles_put_star_one_opposite_star_two(e, inc):
    """Elements of both stars (star_angles, scaled p, star_parameter) give r1 = -x2 r, r2 = x1 r and the velocities."""
    gm1, gm2, p = 5.0e14, 1.5e14, 9.0e6
    argp, nu, raan = 0.3, 2.9, 1.1
    r, v = elements.elements_to_state(p, e, inc, raan, argp, nu, gm1 + gm2)
    x1, x2 = binary.mass_fractions(gm1, gm2)
    expected = binary.barycentric_states(r, v, x1, x2)
    for star, (share, gm_other, opposite) in enumerate(((x2, gm2, True), (x1, gm1, False))):
        star_argp, star_nu = binary.star_angles(e, argp, nu, opposite)
        mu_star = binary.star_parameter(gm_other, gm1 + gm2)
        r_star, v_star = elements.elements_to_state(share * p, e, inc, raan, star_argp, star_nu, mu_star)
        np.testing.assert_allclose(r_star, expected[2 * star], rtol=0, atol=4e-15 * share * np.linalg.norm(r))
        np.testing.assert_allclose(v_star, expected[2 * star + 1], rtol=0, atol=4e-15 * share * np.linalg.norm(v))


def test_barycentric_split_conserves_the_centre_of_mass_and_momentum():
    gm1, gm2 = 2.0, 0.7
    r, v = np.array([1.0, -0.5, 0.25]), np.array([0.1, 0.9, -0.3])
    x1, x2 = binary.mass_fractions(gm1, gm2)
    r1, v1, r2, v2 = binary.barycentric_states(r, v, x1, x2)
    np.testing.assert_allclose(r2 - r1, r, rtol=1e-15)
    np.testing.assert_allclose(binary.center_of_mass(r1, r2, x1, x2), 0.0, atol=1e-16)
    np.testing.assert_allclose(gm1 * v1 + gm2 * v2, 0.0, atol=1e-16)


def test_propagate_moves_both_stars_and_the_centre_of_mass_against_mpmath():
    """Each star's position after 3.7 periods: mpmath Kepler propagation of r, split, plus the CM drift."""
    gm1, gm2 = 3.0e14, 1.0e14
    r, v = np.array([7.0e6, 1.0e6, -2.0e5]), np.array([-1.0e3, 7.2e3, 1.5e3])
    com_r, com_v = np.array([1.0e7, -2.0e7, 3.0e6]), np.array([12.0, -3.0, 4.5])
    dt = 3.7 * twobody.period(*elements.state_to_elements(r, v, gm1 + gm2)[:2], gm1 + gm2)
    r1, v1, r2, v2 = binary.propagate(r, v, com_r, com_v, gm1, gm2, dt)
    ref_r, ref_v = mpref.propagate(r, v, gm1 + gm2, dt)
    with mpmath.workdps(DPS):
        x1, x2 = mpmath.mpf(gm1) / (gm1 + gm2), mpmath.mpf(gm2) / (gm1 + gm2)
        for k in range(3):
            drift = mpmath.mpf(com_r[k]) + mpmath.mpf(com_v[k]) * dt
            assert abs(r1[k] - (drift - x2 * ref_r[k])) <= 1e-12 * np.linalg.norm(r)
            assert abs(r2[k] - (drift + x1 * ref_r[k])) <= 1e-12 * np.linalg.norm(r)
            assert abs(v1[k] - (com_v[k] - x2 * ref_v[k])) <= 1e-12 * np.linalg.norm(v)
            assert abs(v2[k] - (com_v[k] + x1 * ref_v[k])) <= 1e-12 * np.linalg.norm(v)


@pytest.mark.parametrize("e", [0.0, 0.0167, 0.7])
def test_a_vanishing_companion_reduces_to_the_fixed_star_of_section_xxi(e):
    """m2 / m1 = 1e-15: star 2's orbit about the CM equals XXI's planet about a fixed star to 1e-12 (measured
    <= 2e-15: the physical difference is m2 / m1)."""
    gm1 = 1.32712440018e20
    gm2, p = gm1 * 1e-15, 1.496e11 * (1 - e) * (1 + e)
    x1, _ = binary.mass_fractions(gm1, gm2)
    mu_star, p_star = binary.star_parameter(gm1, gm1 + gm2), x1 * p
    pairs = [
        (twobody.periapsis_speed(p_star, e, mu_star), twobody.periapsis_speed(p, e, gm1)),
        (twobody.covertex_speed(p_star, e, mu_star), twobody.covertex_speed(p, e, gm1)),
        (twobody.period(p_star, e, mu_star), twobody.period(p, e, gm1)),
        (twobody.semi_major_axis(p_star, e), twobody.semi_major_axis(p, e)),
        (twobody.areal_velocity(p_star, mu_star), twobody.areal_velocity(p, gm1)),
        (binary.reduced_mass(gm1, gm2), gm2),
    ]
    if e > 0:
        pairs.append((twobody.apoapsis_speed(p_star, e, mu_star), twobody.apoapsis_speed(p, e, gm1)))
    for got, fixed in pairs:
        assert abs(got / fixed - 1) <= 1e-12
        assert abs(got / fixed - 1) <= 2e-15


def test_require_positive_and_bound_name_quantity_value_range_and_unit():
    with pytest.raises(OrbitDomainError, match=r"mass m1 = -2.0 kg is outside the allowed range \(0, inf\) kg"):
        checks.require_positive(np.array([1.0, -2.0]), "mass m1", "kg")
    with pytest.raises(OrbitDomainError, match=r"mass m2 = nan kg"):
        checks.require_positive(math.nan, "mass m2", "kg")
    with pytest.raises(OrbitDomainError, match=r"a period needs a bound orbit: eccentricity e = 1.0 .*\[0, 1\)"):
        binary.require_bound(1.0, "a period")


# ---- what an observer measures (issue 18) -----------------------------------------------------------------------


def mp_companion(phi):
    """The positive root q of q**3 = phi (1 + q)**2 (q = m2 / m1, phi = f / m1), by mpmath at 60 digits."""
    with mpmath.workdps(60):
        phi = mpmath.mpf(phi)
        # f(q) = q**3 - phi (1 + q)**2 is increasing and convex right of its one positive root (which exceeds
        # phi / 3, where f'' = 6 q - 2 phi changes sign), so Newton from a point above the root, phi + 3 phi**(1/3)
        # + 3, descends to it monotonically
        q = phi + 3 * mpmath.cbrt(phi) + 3
        for _ in range(400):
            step = (q**3 - phi * (1 + q) ** 2) / (3 * q**2 - 2 * phi * (1 + q))
            q -= step
            if abs(step) <= mpmath.mpf(10) ** -55 * q:
                return q
        raise AssertionError(f"the mpmath reference did not converge for phi = {phi}")


@pytest.mark.parametrize("phi", np.geomspace(1e-30, 1e30, 61))
def test_companion_from_the_mass_function_solves_the_cubic_to_the_last_bits(phi):
    """Within 2 ulp of mpmath's root (measured 1.2 ulp worst over phi = 1e-30 .. 1e30: a planet to a black hole)."""
    assert ulps(binary.companion_parameter(phi, 1.0), mp_companion(phi)) <= 2.0


def test_companion_scales_with_the_primary_and_the_inclination():
    """(m2 sin i)**3 = f (m1 + m2)**2 is homogeneous: m2 scales with m1 at fixed f / m1; sin i divides f by sin**3 i."""
    gm1, sin_i = np.array([1.327e20, 3.986e14, 1.0]), 0.6
    got = binary.companion_parameter(1e-3 * gm1 * sin_i**3, gm1, sin_i)
    np.testing.assert_allclose(got / gm1, float(mp_companion(1e-3)), rtol=4e-16)
    edge_on = binary.companion_parameter(1e-3 * gm1, gm1)
    np.testing.assert_allclose(edge_on, got, rtol=4e-16)


@pytest.mark.parametrize("e", [0.0, 0.3, 0.9])
def test_radial_velocity_is_the_line_of_sight_kepler_velocity(e):
    """K (cos(omega + nu) + e cos omega) with K = 2 pi a sin i / (P sqrt(1 - e**2)) equals the z component of the
    velocity of orbits.core.twobody.elements (an independent form: the perifocal velocity rotated), to 1e-15 of K."""
    mu, a, inc, raan, argp = 3.986e14, 7.0e6, 1.1, 0.4, 2.3
    nu = np.linspace(-np.pi, np.pi, 25)
    _, v = elements.elements_to_state(a * (1 - e * e), e, inc, raan, argp, nu, mu)
    period = 2 * math.pi * math.sqrt(a**3 / mu)
    k = binary.radial_velocity_semi_amplitude(a, period, inc, e)
    np.testing.assert_allclose(binary.radial_velocity(k, e, argp, nu), v[:, 2], rtol=0, atol=1e-15 * k)
    assert float(np.ptp(v[:, 2])) <= 2 * k * (1 + 1e-15)  # the curve spans 2 K at most (sampled)


def test_mass_function_is_g_m2_sin_i_cubed_over_the_total_squared():
    """P K1**3 (1 - e**2)**1.5 / (2 pi) with star 1's K1 against (G m2 sin i)**3 / (G m1 + G m2)**2, at 50 digits."""
    gm1, gm2, a, e, inc = 1.327e20, 1.267e17, 7.8e11, 0.048, 0.9
    with mpmath.workdps(DPS):
        big, small, sin_i = mpmath.mpf(gm1), mpmath.mpf(gm2), mpmath.sin(mpmath.mpf(inc))
        reference = (small * sin_i) ** 3 / (big + small) ** 2
    period = 2 * math.pi * math.sqrt(a**3 / (gm1 + gm2))
    k1 = binary.radial_velocity_semi_amplitude(a * gm2 / (gm1 + gm2), period, inc, e)
    assert abs(binary.mass_function_parameter(period, k1, e) / float(reference) - 1) <= 2e-15  # measured 4.4e-16
    with pytest.raises(OrbitDomainError, match="a mass function needs a bound orbit"):
        binary.mass_function_parameter(period, k1, 1.0)
