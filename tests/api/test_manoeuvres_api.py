"""Unit-aware rockets, manoeuvres and gravity assists (orbits.manoeuvres): doctests, published and
notes' values, identities between the objects, broadcasting, reprs, tables and every input error."""

import doctest
import math

import astropy.units as u
import numpy as np
import pytest

import orbits
import orbits.manoeuvres.assist
import orbits.manoeuvres.impulsive
import orbits.manoeuvres.rocket
from orbits import (
    BODIES,
    BiElliptic,
    CosmicVelocities,
    Departure,
    Flyby,
    GravityAssist,
    Hohmann,
    OrbitDomainError,
    Phasing,
    PlaneChange,
    Rocket,
    combined_plane_change,
    elastic_collision,
    propellant_mass,
    velocity_change,
)

KMS = u.km / u.s


@pytest.mark.parametrize("module", [orbits.manoeuvres.rocket, orbits.manoeuvres.impulsive, orbits.manoeuvres.assist])
def test_doctests(module):
    assert doctest.testmod(module).failed == 0


def test_public_names_come_through_the_facade():
    for name in ("Rocket", "velocity_change", "propellant_mass", "Hohmann", "BiElliptic", "PlaneChange",
                 "combined_plane_change", "Phasing", "Departure", "GravityAssist", "elastic_collision"):
        assert name in orbits.__all__ and getattr(orbits, name) is not None


# ---- rockets ----------------------------------------------------------------------------------------------


def test_velocity_change_for_gain_and_ejection():
    """ERRATA #16, #20: one law, v_rel ln(m2 / m1); a vector v_rel keeps its direction."""
    gain = velocity_change(1 * KMS, 1 * u.kg, 2 * u.kg)
    ejection = velocity_change(-1 * KMS, 2 * u.t, 1 * u.t)
    assert gain.unit == u.m / u.s and gain.value == pytest.approx(1e3 * math.log(2), rel=1e-15)
    assert ejection.value == pytest.approx(1e3 * math.log(2), rel=1e-15)  # forwards, against the exhaust
    vector = velocity_change([0, 0, -3] * KMS, 5 * u.kg, 4 * u.kg)
    assert vector[2] > 0 and vector[0] == 0


def test_single_stage_rocket():
    rocket = Rocket.single_stage(100 * u.t, 40 * u.t, isp=300 * u.s, thrust=2 * u.MN)
    assert rocket.exhaust_speed[0].to_value(u.m / u.s) == pytest.approx(300 * 9.80665, rel=1e-15)
    assert rocket.delta_v.to_value(u.m / u.s) == pytest.approx(300 * 9.80665 * math.log(2.5), rel=1e-15)
    assert rocket.burn_time.to_value(u.s) == pytest.approx(60e3 * 300 * 9.80665 / 2e6, rel=1e-15)
    assert rocket.gravity_loss().to_value(u.m / u.s) == pytest.approx(9.80665 * rocket.burn_time.value, rel=1e-15)
    assert repr(rocket).startswith("Rocket(1 stage, delta-v = 2.695723 km / s") and "\n" not in repr(rocket)
    assert set(rocket.quantities()) == set(orbits.manoeuvres.rocket.ROCKET_NAMES)
    same = Rocket.single_stage(100 * u.t, 40 * u.t, exhaust_speed=300 * 9.80665 * u.m / u.s)
    assert same.delta_v == rocket.delta_v and "burn_time" not in same.quantities()


def test_staged_rocket_adds_its_stages_and_beats_one_stage():
    staged = Rocket.staged([80, 15] * u.t, [8, 2] * u.t, 1 * u.t, exhaust_speed=3 * KMS)
    assert staged.initial_mass == 106 * u.t and staged.final_mass == 3 * u.t
    first = Rocket.single_stage(106 * u.t, 26 * u.t, exhaust_speed=3 * KMS)
    second = Rocket.single_stage(18 * u.t, 3 * u.t, exhaust_speed=3 * KMS)
    assert staged.delta_v.value == pytest.approx((first.delta_v + second.delta_v).value, rel=1e-15)
    one_stage = Rocket.single_stage(106 * u.t, 11 * u.t, exhaust_speed=3 * KMS)  # the same masses, unstaged
    assert staged.delta_v > one_stage.delta_v


def test_propellant_mass_inverts_the_rocket_equation():
    fuel = propellant_mass(3.9 * KMS, 5192 * u.kg, isp=300 * u.s)
    rocket = Rocket.single_stage(5192 * u.kg, 5192 * u.kg - fuel, isp=300 * u.s)
    assert rocket.delta_v.to_value(u.m / u.s) == pytest.approx(3900, rel=1e-14)


def test_rocket_errors():
    with pytest.raises(OrbitDomainError, match=r"final mass mf = 2000.0 kg is outside the allowed range \(0, m0\)"):
        Rocket.single_stage(1 * u.t, 2 * u.t, isp=300 * u.s)
    with pytest.raises(TypeError, match="exactly one of exhaust_speed"):
        Rocket.single_stage(2 * u.t, 1 * u.t)
    with pytest.raises(TypeError, match="has no unit"):
        Rocket.single_stage(2000, 1 * u.t, isp=300 * u.s)
    with pytest.raises(OrbitDomainError, match=r"specific impulse Isp = -3.0 s is outside"):
        Rocket.single_stage(2 * u.t, 1 * u.t, isp=-3 * u.s)
    with pytest.raises(OrbitDomainError, match="needs the thrust"):
        _ = Rocket.single_stage(2 * u.t, 1 * u.t, isp=300 * u.s).burn_time
    weak = Rocket.single_stage(2 * u.t, 1 * u.t, isp=300 * u.s, thrust=10 * u.kN)
    with pytest.raises(OrbitDomainError, match=r"stage 1 thrust F = 10000.0 N is not above its weight"):
        weak.gravity_loss()
    assert weak.gravity_loss(1 * u.m / u.s**2).value > 0  # where gravity is weak it does lift off


# ---- manoeuvres ---------------------------------------------------------------------------------------------


def test_hohmann_leo_to_geo():
    """Wikipedia's example (6678 km to 42164 km: 2.42 + 1.46 = 3.88 km/s from rounded speeds); unrounded 3.893."""
    geo = Hohmann.between("Earth", 6678 * u.km, 42164 * u.km)
    assert round(geo.delta_v.to_value(KMS), 3) == 3.893
    assert geo.transfer_orbit.periapsis_distance.to_value(u.km) == pytest.approx(6678, rel=1e-15)
    assert geo.transfer_orbit.apoapsis_distance.to_value(u.km) == pytest.approx(42164, rel=1e-15)
    assert geo.transfer_orbit.period.value / 2 == pytest.approx(geo.transfer_time.value, rel=1e-15)
    assert geo.transfer_periapsis_speed.value == pytest.approx(geo.transfer_orbit.periapsis_speed.value, rel=1e-15)
    assert repr(geo) == "Hohmann(6678 -> 42164 km, delta-v = 3.892608 km / s, 5.275015 h, about Earth)"
    down = Hohmann.between("Earth", 42164 * u.km, 6678 * u.km)
    assert down.delta_v.value == pytest.approx(geo.delta_v.value, rel=1e-15)


def test_combined_plane_change_is_cheaper_than_separate_burns():
    """GTO with the 28.5 deg of Cape Canaveral removed at apogee: 4.256 km/s, less than the Hohmann transfer plus a
    separate plane change at GEO speed (3.893 + 1.514 km/s)."""
    plain = Hohmann.between("Earth", 6678 * u.km, 42164 * u.km)
    turned = Hohmann.between("Earth", 6678 * u.km, 42164 * u.km, inclination_change=28.5 * u.deg)
    separate = plain.delta_v + PlaneChange.at("Earth", 42164 * u.km, 28.5 * u.deg).delta_v
    assert round(turned.delta_v.to_value(KMS), 3) == 4.256 and turned.delta_v < separate
    alone = combined_plane_change(turned.transfer_apoapsis_speed, turned.final_speed, 28.5 * u.deg)
    assert turned.second_burn.value == pytest.approx(alone.value, rel=1e-15)
    assert turned.first_burn == plain.first_burn
    assert "turn = 28.5 deg" in repr(turned)


def test_bielliptic_against_hohmann():
    cheap = BiElliptic.between("Earth", 7000 * u.km, 105000 * u.km, 210000 * u.km)  # ratio 15, rb = 2 r2
    assert cheap.saving > 0 and cheap.hohmann_delta_v == Hohmann.between("Earth", 7000 * u.km, 105000 * u.km).delta_v
    assert cheap.transfer_time > Hohmann.between("Earth", 7000 * u.km, 105000 * u.km).transfer_time
    dear = BiElliptic.between("Earth", 7000 * u.km, 70000 * u.km, 700000 * u.km)  # ratio 10 < 11.94
    assert dear.saving < 0
    assert set(cheap.quantities()) == set(BiElliptic.NAMES)
    assert repr(cheap).startswith("BiElliptic(7000 -> 210000 -> 105000 km, delta-v = 4.028517 km / s")


def test_arrays_broadcast():
    radii = [7000, 20000, 42164] * u.km
    many = Hohmann.between("Earth", 6678 * u.km, radii)
    assert many.delta_v.shape == (3,)
    assert many.delta_v[2] == Hohmann.between("Earth", 6678 * u.km, 42164 * u.km).delta_v
    phases = Phasing.to("Earth", 7000 * u.km, [-30, 10, 30] * u.deg, 2)
    assert phases.burn.shape == (3,) and phases.burn[0] > 0 > phases.burn[2]
    with pytest.raises(OrbitDomainError, match="build it from scalars"):
        many.impulse_plan()


def test_phasing_meets_the_target():
    chase = Phasing.to("Earth", 7000 * u.km, 20 * u.deg, 2)
    target_angle = (chase.phasing_time / chase.circular_period * 2 * np.pi * u.rad + 20 * u.deg).to(u.deg)
    assert target_angle.value == pytest.approx(720, rel=1e-14)  # the target reaches the burn point with the chaser
    assert chase.phasing_apoapsis == 7000 * u.km and chase.phasing_periapsis < 7000 * u.km
    assert chase.delta_v == 2 * abs(chase.burn)
    assert repr(chase).startswith("Phasing(r = 7000 km, phase = 20 deg, k = 2, delta-v =")


def test_plane_change_and_departure():
    turn = PlaneChange.at("Earth", 7000 * u.km, 60 * u.deg)
    assert turn.delta_v.value == pytest.approx(turn.speed.value, rel=1e-15)  # 2 v sin 30 deg = v
    leo = Departure.to_excess_speed("Earth", 6678 * u.km, 0.001 * u.m / u.s)
    assert leo.departure_speed.value == pytest.approx(math.sqrt(2) * leo.parking_speed.value, rel=1e-12)


def test_the_third_cosmic_velocity_as_a_departure():
    """XXI.ix worked as an escape: from the notes' Earth's surface, the speed after the burn is CosmicVelocities'
    third cosmic velocity 16.648 km/s, the burn on top of the first cosmic velocity 8.744 km/s."""
    notes = CosmicVelocities.from_surface_gravity()
    departure = Departure.third_cosmic()
    assert departure.departure_speed.value == pytest.approx(notes.third_cosmic_velocity.value, rel=4e-16)
    assert departure.parking_speed.value == pytest.approx(notes.first_cosmic_velocity.value, rel=4e-16)
    assert round(departure.delta_v.to_value(KMS), 3) == 8.744
    from_leo = Departure.third_cosmic("Earth", 6678 * u.km)
    assert from_leo.speed_at_infinity == CosmicVelocities.of("Earth").hyperbolic_excess_speed


def test_manoeuvre_errors():
    with pytest.raises(OrbitDomainError, match=r"intermediate radius rb = 50000000.0 m is outside the allowed range "
                                               r"\[max\(r1, r2\), inf\) m"):
        BiElliptic.between("Earth", 7000 * u.km, 105000 * u.km, 50000 * u.km)
    with pytest.raises(OrbitDomainError, match=r"final orbit radius r2 = 300000.0 m is inside Earth"):
        Hohmann.between("Earth", 6678 * u.km, 300 * u.km)
    with pytest.raises(OrbitDomainError,
                       match=r"inclination change = 210 deg is outside the allowed range \[0, 180\] deg"):
        Hohmann.between("Earth", 7000 * u.km, 8000 * u.km, inclination_change=210 * u.deg)
    with pytest.raises(TypeError, match="has no unit"):
        Hohmann.between("Earth", 7000, 8000 * u.km)
    with pytest.raises(OrbitDomainError, match=r"phase = 4.36.* rad is outside the allowed range .* for 1 revolution"):
        Phasing.to("Earth", 7000 * u.km, 250 * u.deg)
    with pytest.raises(OrbitDomainError, match="phasing periapsis = .* is inside Earth"):
        Phasing.to("Earth", 7000 * u.km, 90 * u.deg)
    assert Phasing.to(3.986e14 * u.m**3 / u.s**2, 7000 * u.km, 90 * u.deg).burn < 0  # a bare GM has no surface
    with pytest.raises(OrbitDomainError, match="revolutions = 0 must be a whole number >= 1"):
        Phasing.to("Earth", 7000 * u.km, 10 * u.deg, 0)
    with pytest.raises(OrbitDomainError, match=r"coast = -1.0 s is outside"):
        Hohmann.between("Earth", 7000 * u.km, 8000 * u.km).impulse_plan(-1 * u.s)


# ---- gravity assists ------------------------------------------------------------------------------------------


def test_gravity_assist_reuses_the_flyby():
    planet = [13.06, 0, 0] * KMS
    assist = GravityAssist.past("Jupiter", [0, 7.4, 0] * KMS, planet, 200000 * u.km)
    fly = Flyby.past("Jupiter", assist.speed_at_infinity, periapsis=200000 * u.km)
    assert assist.turning_angle == fly.deflection_angle
    assert np.linalg.norm(assist.delta_v.value) == pytest.approx(assist.delta_v_magnitude.value, rel=1e-15)
    assert np.linalg.norm((assist.outgoing_velocity - planet).value) == pytest.approx(
        assist.speed_at_infinity.value, rel=1e-15)
    energy = 0.5 * (assist.outgoing_speed**2 - assist.incoming_speed**2)
    assert energy.to_value(u.J / u.kg) == pytest.approx(assist.specific_energy_change.value, rel=1e-13)
    # v_inf along +y, across the planet's path: turned towards -x (counterclockwise about +z, a pass in front of
    # the planet) it brakes the probe; turned towards +x (behind the planet) it boosts it
    front = GravityAssist.past("Jupiter", [13.06, 5, 0] * KMS, planet, 200000 * u.km)
    behind = GravityAssist.past("Jupiter", [13.06, 5, 0] * KMS, planet, 200000 * u.km, normal=[0, 0, -1])
    assert front.speed_gain < 0 < behind.speed_gain
    assert front.specific_energy_change < 0 < behind.specific_energy_change
    assert repr(assist).startswith("GravityAssist(v_inf = 15.01078 km / s, turn = 95.05752 deg")


def test_a_grazing_head_on_pass_is_the_notes_collision():
    """IX.vii, m1 >> m2: a probe meeting the planet head on leaves at 2 v1 - v2. A flyby that turns v_inf by
    nearly 180 deg (periapsis -> 0) tends to it."""
    v_planet, v_probe = 13.06 * KMS, -10 * KMS
    _, bounced = elastic_collision("Jupiter", None, v_planet, v_probe)
    assert bounced.unit == u.m / u.s and bounced.value == 2 * 13060.0 + 10000.0  # exactly 2 v1 - v2
    for periapsis in (1 * u.m, 1 * u.mm):  # k = r_p v_inf**2 / mu, the distance from a head-on bounce
        close = GravityAssist.past(1.267e17 * u.m**3 / u.s**2, [-10, 0, 0] * KMS, [13.06, 0, 0] * KMS, periapsis)
        k = (periapsis * close.speed_at_infinity**2 / (1.267e17 * u.m**3 / u.s**2)).to_value(u.one)
        miss = abs(close.outgoing_velocity[0] / bounced - 1).to_value(u.one)
        assert k / 10 < miss < 10 * k  # measured 2.5 k: 1.1e-8 and 1.1e-11
    planet_after, probe_after = elastic_collision(5.97e24 * u.kg, 722 * u.kg, 0 * KMS, 10 * KMS)
    assert probe_after.to_value(KMS) == pytest.approx(-10, rel=1e-15) and 0 < planet_after.value < 1e-17


def test_gravity_assist_errors():
    with pytest.raises(OrbitDomainError, match="v_in equals v_planet"):
        GravityAssist.past("Jupiter", [1, 0, 0] * KMS, [1, 0, 0] * KMS, 1e5 * u.km)
    with pytest.raises(OrbitDomainError, match="must be a 3-vector not parallel"):
        GravityAssist.past("Jupiter", [0, 0, 5] * KMS, [0, 0, 0] * KMS, 1e5 * u.km)
    with pytest.raises(TypeError, match="has no unit"):
        GravityAssist.past("Jupiter", [0, 5, 0], [0, 0, 0] * KMS, 1e5 * u.km)
    with pytest.raises(OrbitDomainError, match="periapsis distance rp = 2000000.0 m is inside Jupiter"):
        GravityAssist.past("Jupiter", [0, 7.4, 0] * KMS, [0, 13.06, 0] * KMS, 2000 * u.km)


@pytest.mark.parametrize("build", [
    lambda: Hohmann.between("Earth", 6678 * u.km, 42164 * u.km),
    lambda: Hohmann.between("Earth", 6678 * u.km, 42164 * u.km, inclination_change=28.5 * u.deg),
    lambda: Hohmann.between("Earth", 42164 * u.km, 6678 * u.km, inclination_change=40 * u.deg),
    lambda: BiElliptic.between("Earth", 7000 * u.km, 105000 * u.km, 210000 * u.km),
    lambda: PlaneChange.at("Earth", 7000 * u.km, 30 * u.deg),
    lambda: Phasing.to("Earth", 7000 * u.km, 20 * u.deg, 2),
], ids=["hohmann", "hohmann with plane change at GEO", "GEO to LEO with plane change", "bi-elliptic",
        "plane change", "phasing"])
def test_the_integrated_kicks_are_the_burns_reported(build):
    """The impulse plan that rebound and heyoka integrate (tests/validation/test_manoeuvres_integration.py) kicks by
    the burns the object reports, so the integration checks the figures a user reads (measured within one ulp: 2.2e-16,
    the norm of a tilted kick against its closed form)."""
    manoeuvre = build()
    kicks = np.linalg.norm(manoeuvre.impulse_plan().delta_v, axis=1)
    reported = [getattr(manoeuvre, name).to_value(u.m / u.s) for name in ("first_burn", "second_burn", "third_burn")
                if hasattr(manoeuvre, name)]
    if reported:
        np.testing.assert_allclose(kicks, reported, rtol=5e-16, atol=0)
    assert kicks.sum() == pytest.approx(manoeuvre.delta_v.to_value(u.m / u.s), rel=4e-16)


@pytest.mark.parametrize("r1, r2", [(7000, 105000), (105000, 7000)])
def test_bielliptic_with_rb_at_the_larger_radius_is_hohmann(r1, r2):
    """rb = max(r1, r2) is the degenerate bi-elliptic transfer (edges inclusive where the physics is defined): one
    burn is zero, the budget is Hohmann's, and the time adds half a circle at the larger radius."""
    degenerate = BiElliptic.between("Earth", r1 * u.km, r2 * u.km, max(r1, r2) * u.km)
    hohmann = Hohmann.between("Earth", r1 * u.km, r2 * u.km)
    zero = degenerate.third_burn if r2 > r1 else degenerate.first_burn
    assert zero == 0 * u.m / u.s
    assert degenerate.delta_v.value == pytest.approx(hohmann.delta_v.value, rel=4e-16)  # measured 0 and 2.2e-16
    assert degenerate.saving.to_value(u.m / u.s) == pytest.approx(0, abs=1e-12)
    half_circle = math.pi * math.sqrt((max(r1, r2) * 1e3) ** 3 / BODIES["Earth"].gm)
    assert degenerate.transfer_time.value == pytest.approx(hohmann.transfer_time.value + half_circle, rel=1e-15)
    with pytest.raises(OrbitDomainError, match=r"allowed range \[max\(r1, r2\), inf\)"):
        BiElliptic.between("Earth", r1 * u.km, r2 * u.km, (max(r1, r2) - 1e-6) * u.km)


def test_hohmann_between_the_mean_orbits_of_two_bodies():
    """Earth to Mars as circles of radius a: the synodic period is 1 / (1/T1 - 1/T2) of the two circular periods
    (779.9 d, the published 779.94 d of the true orbits), and a body leading by the phase angle at departure
    reaches the meeting point (pi ahead of the departure point) exactly at arrival: 44.3 deg for Mars."""
    trip = Hohmann.between_bodies("Earth", "Mars")
    mu = BODIES["Sun"].gm
    t1, t2 = (2 * math.pi * math.sqrt(r**3 / mu) for r in (trip.r1, trip.r2))
    assert trip.synodic_period.to_value(u.s) == pytest.approx(1 / (1 / t1 - 1 / t2), rel=1e-14)  # measured 1.5e-16
    assert trip.synodic_period.to_value(u.day) == pytest.approx(779.94, rel=2e-4)
    swept = trip.phase_angle.to_value(u.rad) + 2 * math.pi / t2 * trip.transfer_time.to_value(u.s)
    assert swept == pytest.approx(math.pi, rel=1e-15)
    assert trip.phase_angle.to_value(u.deg) == pytest.approx(44.35, abs=0.01)
    assert trip.r1 == BODIES["Earth"].orbit.a and trip.r2 == BODIES["Mars"].orbit.a
    venus = Hohmann.between_bodies("Earth", "Venus")
    assert -60 < venus.phase_angle.to_value(u.deg) < -50  # inward: Venus trails by 54 deg
    with pytest.raises(OrbitDomainError, match="the synodic period needs two different radii"):
        _ = Hohmann.between("Earth", 7000 * u.km, 7000 * u.km).synodic_period
    with pytest.raises(OrbitDomainError, match="Moon orbits Earth and Mars orbits Sun"):
        Hohmann.between_bodies("Moon", "Mars")
