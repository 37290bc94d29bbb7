"""The unit-aware Orbit: constructors, units policy, errors, broadcasting, and agreement with the core."""

import math
import subprocess
import sys

import astropy.units as u
import numpy as np
import pytest

from orbits import BODIES, Orbit, OrbitDomainError
from orbits._common.constants import G


def test_circular_leo_period_matches_keplers_third_law():
    orbit = Orbit.circular("Earth", 6778 * u.km)
    expected = 2 * math.pi * math.sqrt(6.778e6**3 / BODIES["Earth"].gm)
    assert orbit.period.unit == u.s
    assert math.isclose(orbit.period.value, expected, rel_tol=1e-15)


def test_every_size_element_gives_the_same_orbit():
    by_a = Orbit.from_elements("Earth", a=10000 * u.km, e=0.3)
    by_p = Orbit.from_elements("Earth", p=9100 * u.km, e=0.3)
    by_q = Orbit.from_elements("Earth", q=7000 * u.km, e=0.3)
    for other in (by_a, by_p, by_q):
        assert math.isclose(other.semi_major_axis.to_value(u.km), 10000, rel_tol=1e-15)


def test_unit_invariance_km_versus_au():  # EDGE 6.2: results agree to a few ulp after conversion
    a_km = Orbit.from_elements("Sun", a=149_597_870.7 * u.km, e=0.2, nu=40 * u.deg)
    a_au = Orbit.from_elements("Sun", a=1 * u.AU, e=0.2, nu=0.6981317007977318 * u.rad)
    for name in ("period", "periapsis_speed", "radius", "time_since_periapsis"):
        x, y = getattr(a_km, name), getattr(a_au, name)
        assert abs((x - y) / y).to_value(u.one) <= 4 * 2**-53


def test_mass_of_primary_or_gm_or_body():
    by_name = Orbit.circular("Earth", 7000 * u.km)
    by_gm = Orbit.circular(BODIES["Earth"].gm * u.m**3 / u.s**2, 7000 * u.km)
    by_mass = Orbit.circular(BODIES["Earth"].gm / G * u.kg, 7000 * u.km)
    assert by_name.period == by_gm.period
    assert math.isclose(by_mass.period.value, by_name.period.value, rel_tol=4e-16)


def test_from_vectors_round_trip_and_propagate():
    r = [7000.0, 1200.0, -300.0] * u.km
    v = [-0.5, 7.4, 1.1] * u.km / u.s
    orbit = Orbit.from_vectors("Earth", r, v)
    np.testing.assert_allclose(orbit.r.to_value(u.km), r.value, rtol=1e-14)
    np.testing.assert_allclose(orbit.v.to_value(u.km / u.s), v.value, rtol=1e-14)
    r_t, v_t = orbit.propagate([0, 1, 2] * orbit.period)
    np.testing.assert_allclose(r_t.to_value(u.km), np.broadcast_to(r.value, (3, 3)), rtol=1e-12)
    later = orbit.at(30 * u.min)
    assert math.isclose(later.semi_major_axis.value, orbit.semi_major_axis.value, rel_tol=1e-13)


def test_propagate_with_the_state_transition_matrix_moves_a_covariance():
    """stm=True adds Phi = d(r, v) / d(r0, v0) (SI); a small change of v0 moves r by Phi_rv dv0 to first order."""
    orbit = Orbit.from_vectors("Earth", [7000.0, 1200.0, -300.0] * u.km, [-0.5, 7.4, 1.1] * u.km / u.s)
    r_t, v_t, phi = orbit.propagate([10, 20] * u.min, stm=True)
    assert phi.shape == (2, 6, 6) and r_t.shape == (2, 3) and v_t.unit == u.m / u.s
    kick = np.array([0.0, 1e-3, 0.0])  # m/s
    nudged = Orbit.from_vectors("Earth", orbit.r, orbit.v + kick * u.m / u.s)
    moved = nudged.propagate(20 * u.min)[0].to_value(u.m) - r_t[1].to_value(u.m)
    np.testing.assert_allclose(moved, phi[1, :3, 3:] @ kick, rtol=1e-6)  # measured 1.7e-7 (second order, rounding)
    covariance = np.diag([1e2, 1e2, 1e2, 1e-4, 1e-4, 1e-4])
    assert np.all(np.linalg.eigvalsh(phi[1] @ covariance @ phi[1].T) > 0)


def test_arrays_of_orbits_broadcast():
    orbits = Orbit.from_elements("Earth", a=[14000, 16000, 18000] * u.km, e=np.array([[0.0], [0.5]]))
    assert orbits.shape == (2, 3)
    assert orbits.period.shape == (2, 3)
    assert orbits.r.shape == (2, 3, 3)
    single = Orbit.from_elements("Earth", a=16000 * u.km, e=0.5)
    assert orbits.period[1, 1] == single.period


def test_energy_needs_the_mass_and_then_matches_the_notes():
    orbit = Orbit.from_elements("Sun", a=1 * u.AU, e=0.0167, mass=5.97e24 * u.kg)
    mu, m, a = BODIES["Sun"].gm, 5.97e24, u.AU.to(u.m)
    assert math.isclose(orbit.energy.to_value(u.J), -mu * m / (2 * a), rel_tol=1e-15)  # E = -GMm/(2a)
    total = orbit.kinetic_energy + orbit.potential_energy
    assert math.isclose(total.to_value(u.J), orbit.energy.to_value(u.J), rel_tol=1e-13)
    with pytest.raises(OrbitDomainError, match="mass="):
        _ = Orbit.circular("Earth", 7000 * u.km).energy


def test_quantities_table_and_only():
    orbit = Orbit.from_elements("Earth", a=8000 * u.km, e=0.1)
    everything = orbit.quantities()
    assert "period" in everything and "energy" not in everything  # no mass given: left out
    assert list(orbit.quantities(["period", "eccentricity"])) == ["period", "eccentricity"]
    with pytest.raises(KeyError, match="unknown quantities"):
        orbit.quantities(["perod"])


def test_hyperbola_has_no_period():
    flyby = Orbit.from_elements("Earth", a=-20000 * u.km, e=1.5)
    assert flyby.semi_major_axis.value < 0
    with pytest.raises(OrbitDomainError, match="ellipses only"):
        _ = flyby.period
    assert "period" not in flyby.quantities()


@pytest.mark.parametrize(
    "kwargs, error, fragment",
    [
        (dict(a=7000, e=0.1), TypeError, "has no unit"),  # EDGE 60
        (dict(a=7000 * u.s, e=0.1), u.UnitConversionError, "cannot be converted"),  # EDGE 59
        (dict(a=-7000 * u.km, e=0.1), OrbitDomainError, "a > 0 for a bound orbit"),  # EDGE 26
        (dict(a=7000 * u.km, e=1.5), OrbitDomainError, "a < 0 for a hyperbola"),  # EDGE 27
        (dict(a=0 * u.km, e=0.1), OrbitDomainError, "bound orbit"),  # EDGE 28
        (dict(a=7000 * u.km, e=1.0), OrbitDomainError, "give q or p"),  # EDGE 29
        (dict(a=np.nan * u.km, e=0.1), OrbitDomainError, "not finite"),  # EDGE 30
        (dict(a=7000 * u.km, e=-0.1), OrbitDomainError, r"outside \[0, inf\)"),
        (dict(a=7000 * u.km, e=0.1, inc=0.5), TypeError, "has no unit"),
        (dict(a=7000 * u.km, e=True), TypeError, "boolean"),
        (dict(a=7000 * u.km, p=6000 * u.km, e=0.1), TypeError, "exactly one size element"),
        (dict(a=[7000, 8000] * u.km, e=[0.1, 0.2, 0.3]), OrbitDomainError, r"e \(3,\), a \(2,\)"),
        (dict(q=7000 * u.km, e=2.0, nu=150 * u.deg), OrbitDomainError, "asymptote"),
        (dict(a=7000 * u.km, e=0.1, mass=[1, 2] * u.kg), OrbitDomainError, r"mass m has shape \(2,\), more than"),
        (dict(a=[7000, 8000] * u.km, mass=[1, 2, 3] * u.kg), OrbitDomainError, r"mass m \(3,\), orbits \(2,\)"),
        (dict(a=np.full((2**13, 1), 7000) * u.km, e=np.zeros(2**13)), OrbitDomainError,
         "the broadcast of e, a.*: 67,108,864 elements, more than"),
    ],
)
def test_bad_input_is_a_clear_error(kwargs, error, fragment):
    with pytest.raises(error, match=fragment):
        Orbit.from_elements("Earth", **kwargs)


@pytest.mark.parametrize("primary", [-5 * u.kg, 0 * u.m**3 / u.s**2, "Vulcan"])
def test_bad_primary(primary):
    with pytest.raises((OrbitDomainError, KeyError)):
        Orbit.circular(primary, 7000 * u.km)


def test_import_orbits_does_not_load_heavy_backends():
    code = "import sys, orbits; print(sorted(m for m in ('rebound', 'heyoka', 'matplotlib') if m in sys.modules))"
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True).stdout
    assert out.strip() == "[]"


def test_an_orbit_through_its_primary_says_so_whichever_constructor_built_it():
    """Periapsis below the catalogue body's equatorial radius: an InsideBodyWarning naming how many orbits of an
    array, from from_elements, circular and from_vectors alike; a GM or mass that is no catalogue body's, or an
    orbit above the surface, says nothing."""
    import warnings

    from orbits import InsideBodyWarning

    with pytest.warns(InsideBodyWarning, match=r"Orbit \(1 of 3\): closest approach 6300 km is inside the Earth"):
        Orbit.from_elements("Earth", a=[7000, 8000, 9000] * u.km, e=0.1)
    with pytest.warns(InsideBodyWarning, match="inside the Earth"):
        Orbit.circular("Earth", 6000 * u.km)
    with pytest.warns(InsideBodyWarning, match="closest approach 1500 km is inside the Moon"):
        Orbit.from_vectors("Moon", [1500, 0, 0] * u.km, [0, 2.0, 0] * u.km / u.s)  # faster than circular there
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        Orbit.from_elements("Earth", a=[7000, 8000, 9000] * u.km, e=0.05)  # q = 6650 km and up: above
        Orbit.from_elements(3.986e14 * u.m**3 / u.s**2, a=7000 * u.km, e=0.5)  # a GM, no catalogue radius
        Orbit.from_body("Mars")


def test_a_propagation_longer_than_float64_can_follow_says_so():
    """A low orbit followed for 1e80 s came back as a position like any other: its mean anomaly, 1e77 rad, carries
    no digit. The warning starts where rounding alone moves the body by 1e-8 of |r| along its track (3 n |dt|
    2**-53: about 5 million revolutions), checked here against the spread the rounding of dt itself causes."""
    import warnings

    from orbits import IllConditionedWarning

    leo = Orbit.circular("Earth", radius=7000 * u.km)
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        leo.propagate(100 * u.yr)  # 5.4e5 revolutions: 1.1e-9, quiet
    with pytest.warns(IllConditionedWarning, match=r"^ill-conditioned propagation: over 5\.41e\+06 revolutions .* "
                                                   r"up to 1\.1e-08 of \|r\|; about 7 digits"):
        leo.propagate(1000 * u.yr)
    with pytest.warns(IllConditionedWarning, match="no digit of it can be trusted"):
        leo.propagate(1e80 * u.s)
    # the estimate against the real thing: one ulp of dt at 1e15 s (0.125 s) moves the body by 0.375 of it
    dt = 1e15
    with pytest.warns(IllConditionedWarning):
        near, _ = leo.propagate([dt, np.nextafter(dt, np.inf)] * u.s)
    moved = float(np.linalg.norm(near[1] - near[0]).to_value(u.m)) / 7e6
    n = float(np.sqrt(BODIES["Earth"].gm / 7e6**3))
    assert 0.1 < moved / (3 * n * dt * 2.0**-53) < 1.0
