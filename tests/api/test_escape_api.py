"""Unit-aware escape speed, cosmic velocities, synchronous orbits and maximum elongation (XXI.ix-xi)."""

import doctest
import math

import astropy.units as u
import numpy as np
import pytest

import orbits.encounters.escape
from orbits import (
    BODIES,
    Binary,
    CosmicVelocities,
    InsideBodyWarning,
    Orbit,
    OrbitDomainError,
    SynchronousOrbit,
    escape_speed,
    max_elongation,
)


def test_notes_cosmic_velocities_are_the_default_model():
    """g0 = 9.80665 m/s2, R = 6371 km: 7.904, 11.178, 16.65 km/s (ERRATA #54); the notes print 7.9, 11.2, 16.7."""
    notes = CosmicVelocities.from_surface_gravity()
    speeds = [notes.first_cosmic_velocity, notes.second_cosmic_velocity, notes.third_cosmic_velocity]
    assert [round(v.to_value(u.km / u.s), 3) for v in speeds] == [7.904, 11.178, 16.648]
    assert round(notes.orbital_speed.to_value(u.km / u.s), 3) == 29.785
    assert notes.quantities(["third_cosmic_velocity"])["third_cosmic_velocity"] == notes.third_cosmic_velocity


def test_cosmic_velocities_of_catalogued_bodies():
    earth = CosmicVelocities.of("Earth")  # IAU GM and equatorial radius instead of g0 and 6371 km
    assert round(earth.second_cosmic_velocity.to_value(u.km / u.s), 2) == 11.18
    assert math.isclose(earth.second_cosmic_velocity.value, escape_speed("Earth").value, rel_tol=4e-16)
    jupiter = CosmicVelocities.of("Jupiter")
    assert math.isclose(jupiter.first_cosmic_velocity.value, Orbit.circular("Jupiter", 71492 * u.km).speed.value)
    sun = CosmicVelocities.of("Sun")
    assert "third_cosmic_velocity" not in sun.quantities()
    with pytest.raises(OrbitDomainError, match="orbital speed about its primary"):
        _ = sun.third_cosmic_velocity


def test_custom_model_and_its_errors():
    mars_like = CosmicVelocities.from_surface_gravity(3.71 * u.m / u.s**2, 3389.5 * u.km, 24.07 * u.km / u.s)
    assert round(mars_like.second_cosmic_velocity.to_value(u.km / u.s), 3) == 5.015
    with pytest.raises(OrbitDomainError, match=r"surface gravity g = -1.0 m / s2 is outside .*\(0, inf\)"):
        CosmicVelocities.from_surface_gravity(-1 * u.m / u.s**2)
    with pytest.raises(u.UnitConversionError, match="surface gravity g"):
        CosmicVelocities.from_surface_gravity(1 * u.m / u.s)


def test_escape_speed_from_bodies_masses_and_binaries():
    earth = BODIES["Earth"]
    assert escape_speed("Earth").value == math.sqrt(2 * earth.gm / earth.radius)
    at_leo = escape_speed(earth.mass * u.kg, 7000 * u.km)
    assert math.isclose(at_leo.value, math.sqrt(2) * Orbit.circular("Earth", 7000 * u.km).speed.value, rel_tol=1e-15)
    pair = Binary.from_elements("Sun", "Jupiter", a=5.2 * u.AU, e=0.048)
    assert escape_speed(pair, 40 * u.AU) == pair.escape_speed(40 * u.AU)
    assert escape_speed("Earth", [7000, 42164] * u.km).shape == (2,)


@pytest.mark.parametrize(
    "call, error, fragment",
    [
        (lambda: escape_speed("Earth", 0 * u.km), OrbitDomainError, r"distance r = 0.0 m is outside .*\(0, inf\) m"),
        (lambda: escape_speed("Earth", -1 * u.km), OrbitDomainError, "distance r = -1000.0 m"),
        (lambda: escape_speed("Earth", math.nan * u.km), OrbitDomainError, "distance r = nan m"),
        (lambda: escape_speed(-5 * u.kg, 1 * u.km), OrbitDomainError, r"primary mass M = -5.0 kg is outside"),
        (lambda: escape_speed(5 * u.kg), TypeError, "has no surface"),
        (lambda: escape_speed("Earth", 7000), TypeError, "has no unit"),
        (lambda: SynchronousOrbit.of("Earth", period=-1 * u.h), OrbitDomainError, "rotation period T = -3600.0 s"),
        (lambda: SynchronousOrbit.of("Earth", period=0 * u.h), OrbitDomainError, r"\(0, inf\) s"),
        (lambda: SynchronousOrbit.of(5.97e24 * u.kg), TypeError, "has no rotation"),
        (lambda: max_elongation(1 * u.AU, 1 * u.AU), OrbitDomainError, r"outside the allowed range \(0, R\) m"),
        (lambda: max_elongation(-1 * u.AU, 1 * u.AU), OrbitDomainError, "inner orbit radius r = "),
        (lambda: max_elongation("Sun", "Earth"), OrbitDomainError, "Sun has no orbit"),
    ],
)
def test_bad_input_names_quantity_value_range_and_unit(call, error, fragment):
    with pytest.raises(error, match=fragment):
        call()


def test_geostationary_orbit_of_the_earth():
    """XXI.x: 42164.17 km from the centre, 35786 km up (the notes), a sidereal day, 3.0747 km/s."""
    geo = SynchronousOrbit.of("Earth")
    assert round(geo.orbit_radius.to_value(u.km), 2) == 42164.17
    assert round(geo.altitude.to_value(u.km)) == 35786
    assert round(geo.orbital_speed.to_value(u.km / u.s), 4) == 3.0747
    circle = Orbit.circular("Earth", geo.orbit_radius)
    assert math.isclose(circle.period.value, geo.period.value, rel_tol=4e-16)
    assert math.isclose(circle.mean_motion.value, geo.angular_velocity.value, rel_tol=4e-16)


def test_synchronous_orbits_of_any_rotating_body():
    jupiter = SynchronousOrbit.of("Jupiter")
    assert round(jupiter.orbit_radius.to_value(u.km)) == 160009  # 2.24 Jupiter radii
    custom = SynchronousOrbit.of(6.4171e23 * u.kg, period=88642.66 * u.s, radius=3396.2 * u.km)  # Mars
    assert round(custom.altitude.to_value(u.km)) == 17032
    with pytest.warns(InsideBodyWarning, match=r"radius r = 5076\.85 km lies inside the body \(radius 6378\.1 km\)"):
        fast = SynchronousOrbit.of("Earth", period=1 * u.h)  # 'escape geo --rotation-period "1 min"' said nothing
    assert "altitude" not in fast.quantities()
    with pytest.raises(OrbitDomainError, match="lies inside the body"):
        _ = fast.altitude
    several = SynchronousOrbit.of("Earth", period=[12, 24] * u.h)
    assert several.orbit_radius.shape == (2,)
    ratio = (several.orbit_radius[1] / several.orbit_radius[0]).value
    assert math.isclose(ratio, 2 ** (2 / 3), rel_tol=4e-16)


def test_maximum_elongation_of_venus_and_of_the_earth_from_jupiter():
    """XXI.xi: Venus at 0.723 AU seen from 1 AU reaches 46.3 degrees; the Earth seen from Jupiter 11.1 degrees."""
    assert round(max_elongation(0.723 * u.AU, 1 * u.AU).to_value(u.deg), 1) == 46.3
    assert round(max_elongation("Earth", "Jupiter").to_value(u.deg), 1) == 11.1
    many = max_elongation([0.387, 0.723] * u.AU, "Earth")
    np.testing.assert_allclose(
        many.to_value(u.deg), np.degrees(np.arcsin(np.array([0.387, 0.723]) / 1.00000261)), rtol=1e-14
    )


def test_module_examples_run():
    assert doctest.testmod(orbits.encounters.escape).failed == 0
