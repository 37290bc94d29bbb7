"""RestrictedThreeBody and Ring: units, constructors, catalogue defaults, errors, frames, and agreement with
independent objects (Binary, Orbit) and direct sums."""

import math

import astropy.units as u
import mpmath
import numpy as np
import pytest
from mpmath import mp, mpf

from orbits import BODIES, Binary, G, OrbitDomainError, RestrictedThreeBody, Ring
from orbits.core.threebody import lagrange


@pytest.fixture(scope="module")
def earth_moon():
    return RestrictedThreeBody.from_primaries("Earth", "Moon")


def test_earth_moon_from_the_catalogue(earth_moon):
    """Default separation: the Moon's catalogued mean distance; L1 about 58,000 km from the Moon, L2 about
    64,500 km beyond it (published Earth-Moon values for a = 384,400 km: 58,000 and 64,500 km)."""
    assert earth_moon.separation.to_value(u.km) == 384399.0
    mu = BODIES["Moon"].gm / (BODIES["Earth"].gm + BODIES["Moon"].gm)
    assert earth_moon.mass_ratio.value == mu
    rho = earth_moon.distances_to_secondary.to_value(u.km)
    assert abs(rho[0] - 58_000) < 100 and abs(rho[1] - 64_500) < 100
    n = math.sqrt((BODIES["Earth"].gm + BODIES["Moon"].gm) / 384399e3**3)
    assert math.isclose(earth_moon.angular_velocity.to_value(u.rad / u.s), n, rel_tol=1e-15)


def test_sun_earth_l1_and_l2(earth_moon):
    """Sun-Earth L1 and L2 lie about 1.5 million km from the Earth (1.491 and 1.501 million km)."""
    sun_earth = RestrictedThreeBody.from_primaries("Sun", "Earth")
    rho = sun_earth.distances_to_secondary.to(u.km).value
    assert abs(rho[0] - 1.4915e6) < 2e3 and abs(rho[1] - 1.5015e6) < 2e3


def test_units_and_scaling_match_the_core(earth_moon):
    r = earth_moon.r
    mu = earth_moon.mu
    assert np.allclose(earth_moon.positions.to_value(u.m), lagrange.positions(mu) * r, rtol=0, atol=1e-16 * r)
    assert earth_moon.eigenvalues.unit == 1 / u.s and earth_moon.jacobi_constants.unit == u.m**2 / u.s**2
    n = earth_moon.angular_velocity.value
    assert np.allclose(earth_moon.growth_rates.value, lagrange.growth_rates(mu) * n, rtol=1e-15)
    assert np.isinf(earth_moon.e_folding_times[3]) and earth_moon.triangular_points_stable


def test_earth_moon_e_folding_times_are_the_collinear_characteristic_roots(earth_moon):
    """The README's 1.48, 2.01 and 24.4 d at L1..L3, against mpmath at 40 digits: each point by findroot on the
    rotating-frame force, then the real root of the planar characteristic equation, lambda**2 = (c2 - 2 +
    sqrt(9 c2**2 - 8 c2)) / 2 with c2 = (1 - mu) / |x + mu|**3 + mu / |x - 1 + mu|**3 (Szebehely 1967), and
    e-folding time 1 / (lambda n). Measured 4e-16 relative."""
    n = float(earth_moon.angular_velocity.to_value(u.rad / u.s))
    expected = []
    with mp.workdps(40):
        mu = mpf(float(earth_moon.mu))
        force = lambda x: x - (1 - mu) * (x + mu) / abs(x + mu) ** 3 - mu * (x - 1 + mu) / abs(x - 1 + mu) ** 3
        for guess in ("0.84", "1.16", "-1.0"):
            x = mp.findroot(force, mpf(guess))
            c2 = (1 - mu) / abs(x + mu) ** 3 + mu / abs(x - 1 + mu) ** 3
            rate = mp.sqrt((c2 - 2 + mp.sqrt(9 * c2**2 - 8 * c2)) / 2)
            expected.append(float(1 / (rate * n)))
    days = earth_moon.e_folding_times[:3].to_value(u.day)
    np.testing.assert_allclose(earth_moon.e_folding_times[:3].to_value(u.s), expected, rtol=4e-15, atol=0)
    assert [round(d, 2 if d < 10 else 1) for d in days] == [1.48, 2.01, 24.4]


def test_masses_as_quantities_and_units_invariance():
    by_mass = RestrictedThreeBody.from_primaries(2e30 * u.kg, 1e27 * u.kg, 5 * u.AU)
    by_gm = RestrictedThreeBody.from_primaries(2e30 * G * u.m**3 / u.s**2, 1e27 * G * u.m**3 / u.s**2, 5 * u.AU)
    assert np.allclose(by_mass.positions.value, by_gm.positions.value, rtol=1e-15)
    in_km = RestrictedThreeBody.from_primaries(2e30 * u.kg, 1e27 * u.kg, 5 * 149_597_870.7 * u.km)
    assert np.allclose(in_km.positions.to_value(u.m), by_mass.positions.to_value(u.m), rtol=4e-16, atol=0)


@pytest.mark.parametrize(
    "args, error, fragment",
    [
        (("Moon", "Earth"), OrbitDomainError, "pass the heavier body as the primary"),
        ((1 * u.kg, 0 * u.kg, 1 * u.m), OrbitDomainError, "secondary mass m = 0.0 kg is outside"),
        ((1 * u.kg, -1 * u.kg, 1 * u.m), OrbitDomainError, "outside the allowed range (0, inf) kg"),
        ((1 * u.kg, 1 * u.kg, -2 * u.m), OrbitDomainError, "separation r = -2.0 m is outside"),
        ((1 * u.kg, 1 * u.kg, 2), TypeError, "has no unit"),
        ((1 * u.kg, 1 * u.kg, 2 * u.s), u.UnitConversionError, "separation r"),
        ((1 * u.kg, 1 * u.kg), OrbitDomainError, "separation r is needed"),
        (("Earth", "Sun"), OrbitDomainError, "0.99999"),
        ((1 * u.kg, np.nan * u.kg, 1 * u.m), OrbitDomainError, "nan"),
    ],
)
def test_bad_input(args, error, fragment):
    with pytest.raises(error, match=None) as err:
        RestrictedThreeBody.from_primaries(*args)
    assert fragment in str(err.value)


def test_equal_masses_are_allowed_and_symmetric():
    twins = RestrictedThreeBody.from_primaries(1 * u.M_sun, 1 * u.M_sun, 1 * u.AU)
    x = twins.positions[:, 0].to_value(u.AU)
    assert x[0] == 0.0 and abs(x[1] + x[2]) < 1e-15 and not twins.triangular_points_stable


def test_inertial_states_turn_with_the_binary(earth_moon):
    r0, v0 = earth_moon.inertial_states(0 * u.s)
    assert np.allclose(r0.value, earth_moon.positions.value, rtol=0, atol=1e-7)
    quarter = earth_moon.period / 4
    r1, v1 = earth_moon.inertial_states(quarter)
    rot = earth_moon.positions.value
    assert np.allclose(r1.value[:, 0], -rot[:, 1], atol=1e-6) and np.allclose(r1.value[:, 1], rot[:, 0], atol=1e-6)
    n = earth_moon.angular_velocity.value
    assert np.allclose(np.linalg.norm(v1.value, axis=-1), n * np.linalg.norm(rot, axis=-1), rtol=1e-15)
    times = [0, 1, 2] * u.day
    r, v = earth_moon.inertial_states(times)
    assert r.shape == (3, 5, 3) and np.allclose(np.einsum("tki,tki->tk", r.value, v.value), 0, atol=1e-3)


def test_inertial_states_in_a_tilted_plane():
    tilted = RestrictedThreeBody.from_primaries("Earth", "Moon", inc=30 * u.deg, raan=40 * u.deg, phase=70 * u.deg)
    r, v = tilted.inertial_states(3 * u.day)
    inc, raan = math.radians(30), math.radians(40)
    normal = np.array([math.sin(inc) * math.sin(raan), -math.sin(inc) * math.cos(raan), math.cos(inc)])
    assert np.max(np.abs(r.value @ normal)) < 1e-7 * tilted.r and np.max(np.abs(v.value @ normal)) < 1e-12
    h = np.cross(r.value[3], v.value[3])
    assert np.allclose(h / np.linalg.norm(h), normal, atol=1e-15)


def test_jacobi_constant_and_effective_potential(earth_moon):
    at_rest = earth_moon.jacobi_constant(earth_moon.positions, np.zeros((5, 3)) * u.m / u.s)
    assert np.allclose(at_rest.value, earth_moon.jacobi_constants.value, rtol=1e-15)
    phi = earth_moon.effective_potential(earth_moon.positions)
    assert np.allclose(-2 * phi.value, at_rest.value, rtol=1e-15) and phi.unit == u.J / u.kg
    moving = earth_moon.jacobi_constant(earth_moon.positions[3], [10, 0, 0] * u.m / u.s)
    assert math.isclose(at_rest[3].value - moving.value, 100.0, rel_tol=1e-9)


def test_zero_velocity_grid(earth_moon):
    x, y, c = earth_moon.zero_velocity_grid(extent=1.5, points=301)
    assert x.shape == y.shape == c.shape == (301, 301) and c.unit == u.m**2 / u.s**2
    assert x[0, 0].to_value(u.km) == pytest.approx(-1.5 * 384399)
    assert y[-1, 0].to_value(u.km) == pytest.approx(1.5 * 384399)
    l4_x, l4_y, _ = earth_moon.positions[3].value
    nearest = np.unravel_index(np.argmin(np.hypot(x.value - l4_x, y.value - l4_y)), c.shape)
    assert abs(c.value[nearest] / earth_moon.jacobi_constants[3].value - 1) < 1e-3  # grid node next to L4
    c_l1 = earth_moon.jacobi_constants[0].value
    assert np.all(c.value[:, 150] >= c.value.min()) and (c.value > c_l1).any() and (c.value < c_l1).any()


def test_quantities_table(earth_moon):
    table = earth_moon.quantities(points=("L1", "L4"))
    assert list(table)[:4] == ["mass_ratio", "separation", "angular_velocity", "period"]
    assert "L1_e_folding_time" in table and "L4_e_folding_time" not in table
    assert table["L1_eigenvalues"].shape == (6, 2) and table["L1_position"].unit == u.m
    only = earth_moon.quantities(only=["growth_rate", "L5_position"], points=("L2", "L3"))
    assert list(only) == ["L2_growth_rate", "L3_growth_rate", "L5_position"]
    with pytest.raises(KeyError, match="unknown quantity"):
        earth_moon.quantities(only=["spin"])
    with pytest.raises(KeyError, match="unknown points"):
        earth_moon.quantities(points=("L6",))


# ---- rings ---------------------------------------------------------------------------------------------------------


def test_two_body_ring_is_the_equal_mass_binary():
    """EDGE 53 against orbits.Binary: two masses m at radius r are a binary of separation 2r."""
    ring = Ring.from_masses(2, 3e24 * u.kg, 2e5 * u.km)
    binary = Binary.from_elements(3e24 * u.kg, 3e24 * u.kg, a=4e5 * u.km, e=0.0)
    assert math.isclose(ring.period.value, binary.period.to_value(u.s), rel_tol=2e-16)
    assert math.isclose(ring.energy.value, binary.energy.to_value(u.J), rel_tol=4e-16)
    assert math.isclose(ring.angular_momentum.value, binary.angular_momentum.value, rel_tol=4e-16)
    assert ring.speed.value**2 == G * 3e24 / (4 * 2e8)


def test_three_body_ring_is_lagrange_equilateral():
    """n = 3: omega**2 = G m / (sqrt(3) r**3), the equilateral solution with side sqrt(3) r (XXIII)."""
    ring = Ring.from_masses(3, 1 * u.M_sun, 1 * u.AU)
    expected = 2 * math.pi * math.sqrt(math.sqrt(3) * (1 * u.AU).to_value(u.m) ** 3 / ring.gm)
    assert math.isclose(ring.period.value, expected, rel_tol=4e-16)


@pytest.mark.parametrize("n", [2, 3, 5, 8])
@pytest.mark.parametrize("central", [None, 7e22 * u.kg])
def test_energies_against_direct_pair_sums(n, central):
    """U = -sum_pairs G m_i m_j / d_ij (central mass included), K = sum m v**2 / 2, L = sum m r v (mpmath)."""
    ring = Ring.from_masses(n, 1e21 * u.kg, 3e4 * u.km, central_mass=central)
    m, big, r, v = 1e21, 0.0 if central is None else 7e22, 3e7, ring.speed.value
    with mp.workdps(40):
        pts = [(r * mpmath.cos(2 * mp.pi * k / n), r * mpmath.sin(2 * mp.pi * k / n)) for k in range(n)]
        pairs = [(i, j) for i in range(n) for j in range(i + 1, n)]
        pair = sum(1 / mpmath.hypot(pts[i][0] - pts[j][0], pts[i][1] - pts[j][1]) for i, j in pairs)
        u_ref = -mpf(G) * (m * m * pair + n * big * m / r)
    assert math.isclose(ring.potential_energy.value, float(u_ref), rel_tol=1e-15)
    assert math.isclose(ring.kinetic_energy.value, n * m * v * v / 2, rel_tol=1e-15)
    assert math.isclose(ring.energy.value, float(u_ref) + n * m * v * v / 2, rel_tol=1e-14)
    assert math.isclose(ring.angular_momentum.value, n * m * r * v, rel_tol=1e-15)
    positions, velocities = ring.state_vectors()
    assert positions.shape == (n, 3) and np.allclose(np.linalg.norm(velocities.value, axis=-1), v, rtol=1e-15)


def test_ring_stability_quantities():
    unstable = Ring.from_masses(8, 1e20 * u.kg, 1e5 * u.km)
    omega = unstable.angular_velocity.value
    assert not unstable.linearly_stable and unstable.unstable_mode.value == 4
    assert math.isclose(unstable.breakup_time.value, math.log(1e13) / unstable.growth_rate.value, rel_tol=1e-15)
    assert math.isclose(unstable.growth_rate.value / omega, 1.7784822364736774, rel_tol=1e-13)
    assert unstable.eigenvalues.shape == (8, 4)
    threshold = unstable.central_mass_threshold
    stable = Ring.from_masses(8, 1e20 * u.kg, 1e5 * u.km, central_mass=1.01 * threshold)
    assert stable.linearly_stable and stable.growth_rate.value == 0.0
    with pytest.raises(OrbitDomainError, match="linearly stable"):
        _ = stable.breakup_time
    table = stable.quantities()
    assert "breakup_time" not in table and "central_mass_threshold" in table
    assert "central_mass_threshold" not in Ring.from_masses(5, 1 * u.kg, 1 * u.m).quantities()
    with pytest.raises(OrbitDomainError, match=r"\[7, "):
        Ring.from_masses(5, 1 * u.kg, 1 * u.m).quantities(only=["central_mass_threshold"])


@pytest.mark.parametrize(
    "args, kwargs, error, fragment",
    [
        ((1, 1 * u.kg, 1 * u.m), {}, OrbitDomainError, "outside [2, inf)"),
        ((2.5, 1 * u.kg, 1 * u.m), {}, TypeError, "must be an integer"),
        ((True, 1 * u.kg, 1 * u.m), {}, TypeError, "must be an integer"),
        ((3, 1 * u.kg, 0 * u.m), {}, OrbitDomainError, "ring radius r = 0.0 m is outside"),
        ((3, -1 * u.kg, 1 * u.m), {}, OrbitDomainError, "ring body mass m = -1.0 kg"),
        ((3, 1 * u.kg, 1 * u.m), {"central_mass": -5 * u.kg}, OrbitDomainError, "central mass M = -5.0 kg"),
        ((3, 1 * u.kg, 1), {}, TypeError, "has no unit"),
    ],
)
def test_ring_bad_input(args, kwargs, error, fragment):
    with pytest.raises(error) as err:
        Ring.from_masses(*args, **kwargs)
    assert fragment in str(err.value)


def test_million_body_ring_quantities():
    ring = Ring.from_masses(1_000_000, 1e10 * u.kg, 1e5 * u.km)
    table = ring.quantities()
    assert "growth_rate" not in table and "period" in table  # stability is offered up to n = 4096
    assert math.isclose(ring.csc_sum.value, 8875207.612703152, rel_tol=1e-15)
