"""orbits.perturb.secular: the unit-aware designs, decay and Kozai-Lidov objects, their one-line errors."""

import astropy.units as u
import numpy as np
import pytest

from orbits import Orbit, OrbitDomainError
from orbits.perturb.secular import (
    DragDecay,
    KozaiLidov,
    SecularOrbit,
    frozen,
    relativistic_periapsis_advance,
    repeat_ground_track,
    sun_synchronous,
)


def test_secular_orbit_rates_and_mean_element_propagation():
    iss = SecularOrbit.of(Orbit.circular("Earth", 6778 * u.km, inc=51.64 * u.deg))
    assert iss.node_rate.to_value(u.deg / u.day) == pytest.approx(-4.998, abs=1e-3)
    later = iss.at(1 * u.day)
    turned = (later.ascending_node - iss.orbit.ascending_node).to_value(u.deg) - 360.0
    assert turned == pytest.approx(iss.node_rate.to_value(u.deg / u.day), rel=1e-12)
    assert set(iss.quantities()) == {"node_rate", "periapsis_rate", "mean_anomaly_rate", "nodal_period", "accuracy"}


def test_designs_give_back_their_targets():
    design = sun_synchronous("Earth", altitude=700 * u.km)
    # the catalogue GM (IAU 2015 nominal)
    assert design.inclination.to_value(u.deg) == pytest.approx(98.18776, abs=1e-5)
    assert design.secular.node_rate.to_value(u.rad / u.s) == pytest.approx(
        design.extra["node_rate_target"].to_value(u.rad / u.s), rel=1e-14)
    back = sun_synchronous("Earth", inc=design.inclination)
    assert back.semi_major_axis.to_value(u.m) == pytest.approx(design.semi_major_axis.to_value(u.m), rel=1e-14)
    assert frozen("Earth", altitude=700 * u.km, inc=98.19 * u.deg).eccentricity.value == pytest.approx(1.0432e-3,
                                                                                                       rel=1e-3)
    track = repeat_ground_track("Earth", revolutions=127, days=10, inc=66.04 * u.deg)
    assert track.semi_major_axis.to_value(u.km) == pytest.approx(7714.43, rel=4e-5)


def test_drag_decay_and_kozai_lidov_objects():
    decay = DragDecay.of("Earth", altitude=280 * u.km, ballistic=0.022 * u.m**2 / u.kg)
    assert decay.lifetime.to_value(u.day) == pytest.approx(5.9884, rel=1e-4)
    assert decay.altitude_after(decay.lifetime).to_value(u.km) == pytest.approx(250.0, abs=1e-6)
    kozai = KozaiLidov.of("Sun", "Jupiter", a=1 * u.AU, a_out=5.2 * u.AU, inc=65 * u.deg)
    assert kozai.eccentricity_range[1].value == pytest.approx(kozai.maximum_eccentricity_from_circular.value,
                                                              rel=1e-5)
    per_orbit, rate = relativistic_periapsis_advance(Orbit.from_body("Mercury"))
    assert (rate * 36525 * u.day).to_value(u.arcsec) == pytest.approx(42.98, abs=0.005)


def test_drag_decay_runs_through_the_band_below_its_altitude():
    """An orbit at a band's base decays through the band below (a lifetime, not zero); a band may start at the
    surface; the breakdown altitude ends the closed form when it lies above the band's base."""
    at_base = DragDecay.of("Earth", altitude=400 * u.km, ballistic=0.005 * u.m**2 / u.kg)
    assert at_base.quantities()["base_altitude"].to_value(u.km) == pytest.approx(350.0)
    assert at_base.lifetime.to_value(u.day) > 100.0
    mars = DragDecay.of("Mars", altitude=200 * u.km, ballistic=0.01 * u.m**2 / u.kg, density=0.020 * u.kg / u.m**3,
                        scale_height=11.1 * u.km, base_altitude=0 * u.km)
    breakdown = mars.breakdown_altitude.to_value(u.km)
    assert breakdown > 100.0  # measured 157.3 km, far above the surface
    assert mars.altitude_after(mars.lifetime).to_value(u.km) == pytest.approx(breakdown, rel=1e-12)
    per_revolution = 2 * np.pi * 0.01 * mars.quantities()["density_at_base"].value * np.exp(-breakdown / 11.1) * (
        mars.a0 - 200e3 + breakdown * 1e3) ** 2
    assert per_revolution == pytest.approx(11.1e3, rel=1e-12)  # the decay in a revolution is H there


@pytest.mark.parametrize("primary, altitude, ballistic, band", [
    ("Earth", 400, 0.005, None),  # the breakdown would lie at -98.6 km, below the band's base (350 km)
    ("Earth", 600, 0.005, None),  # -172.8 km
    ("Moon", 100, 0.01, (1e-12, 30.0, 50.0)),  # a thin band over the Moon: -223 km
])
def test_no_breakdown_altitude_where_the_decay_stays_under_h_down_to_the_base(primary, altitude, ballistic, band):
    """Where the decay per revolution would reach H only below the band's base (where the band's law is none), the
    closed form ends at the base: breakdown_altitude is not in the table and, asked for, is refused in one line
    naming the base; never a negative altitude shown as an answer. The lifetime ends at the base."""
    extra = {} if band is None else dict(density=band[0] * u.kg / u.m**3, scale_height=band[1] * u.km,
                                         base_altitude=band[2] * u.km)
    decay = DragDecay.of(primary, altitude=altitude * u.km, ballistic=ballistic * u.m**2 / u.kg, **extra)
    assert "breakdown_altitude" not in decay.quantities()
    with pytest.raises(OrbitDomainError, match="no breakdown altitude: .* down to the band's base"):
        decay.quantities(["breakdown_altitude"])
    base = decay.quantities()["base_altitude"]
    assert decay.altitude_after(decay.lifetime).to_value(u.km) == pytest.approx(base.to_value(u.km), rel=1e-9)


@pytest.mark.parametrize("call, message", [
    (lambda: SecularOrbit.of(Orbit.circular("Ceres", 1000 * u.km)), "Ceres has no J2 in the catalogue"),
    (lambda: sun_synchronous("Earth", a=20_000 * u.km, e=0.1), "no sun-synchronous orbit at a = 20000 km, e = 0.1"),
    (lambda: sun_synchronous("Earth", altitude=700 * u.km, e=0.99), "lies inside Earth"),
    (lambda: DragDecay.of("Earth", altitude=300 * u.km, ballistic=0.01 * u.m**2 / u.kg, density=1e-11 * u.kg / u.m**3,
                          scale_height=50 * u.km, base_altitude=350 * u.km), "not above the atmosphere band's base"),
    (lambda: DragDecay.of("Earth", altitude=160 * u.km, ballistic=0.1 * u.m**2 / u.kg),
     "sinks 35.66 km a revolution, more than the scale height H = 22.523 km"),
    (lambda: DragDecay.of("Earth", altitude=100 * u.km, ballistic=0.01 * u.m**2 / u.kg),
     r"outside the table, \(100, 1500\] km"),
    (lambda: frozen("Earth", altitude=700 * u.km, inc=63.43494882292201 * u.deg), "critical inclination"),
    (lambda: frozen("Earth", altitude=700 * u.km, inc=63.4349 * u.deg), "close to the critical inclination"),
    (lambda: frozen("Earth", a=1 * u.km, inc=98 * u.deg), "a = 1 km lies inside Earth"),
    (lambda: repeat_ground_track("Earth", revolutions=1, days=1_000_000, inc=98 * u.deg), "beyond Earth's Hill sphere"),
    (lambda: repeat_ground_track("Moon", revolutions=1, days=1, inc=90 * u.deg), "beyond Moon's Hill sphere"),
    (lambda: repeat_ground_track("Earth", revolutions=15, days=1, inc=0 * u.deg), "equatorial orbit has no node"),
    (lambda: repeat_ground_track("Earth", revolutions=1_000_000, days=1, inc=98 * u.deg), "outside the body"),
    (lambda: KozaiLidov.of("Sun", "Jupiter", a=1 * u.AU, a_out=5.2 * u.AU, inc=90 * u.deg), "a radial orbit"),
    (lambda: KozaiLidov.of("Sun", "Jupiter", a=1 * u.AU, a_out=5.2 * u.AU, inc=89.999999 * u.deg), "a radial orbit"),
    (lambda: KozaiLidov.of("Sun", "Jupiter", a=1 * u.AU, a_out=5.2 * u.AU, inc=65 * u.deg, e=1e-9),
     r"outside \[1e-06, 1\)"),
    (lambda: KozaiLidov.of(1 * u.solMass, 1 * u.solMass, a=1 * u.AU, a_out=12 * u.AU, inc=65 * u.deg, e_out=0.8),
     "below 28.75, Mardling and Aarseth's stability limit"),
    (lambda: KozaiLidov.of("Sun", "Jupiter", a=1 * u.AU, a_out=1.0000001 * u.AU, inc=65 * u.deg),
     "not hierarchical"),
])
def test_bad_inputs_are_one_line_errors(call, message):
    with pytest.raises(OrbitDomainError, match=message) as err:
        call()
    assert "\n" not in str(err.value)


def test_a_backwards_turning_body_has_repeat_ground_tracks():
    """Venus turns backwards once in 243 d: 15 revolutions a Venus day want n = 15 |Omega_Venus - dOmega/dt|, a
    Kepler a of 252,631 km (the J2 of a slow rotator changes it in the sixth digit); it was refused as 'not
    positive'."""
    venus = repeat_ground_track("Venus", revolutions=15, days=1, inc=98 * u.deg)
    kepler = np.cbrt(venus.primary.gm / (15 * 2 * np.pi / venus.primary.rotation_period) ** 2)
    assert venus.semi_major_axis.to_value(u.m) == pytest.approx(kepler, rel=1e-4)
