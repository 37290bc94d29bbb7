"""orbits.lambert (orbits/manoeuvres/lambert.py): the unit-aware Lambert solver: units, the result object, errors,
repr."""

import astropy.units as u
import numpy as np
import pytest

import orbits
from orbits import DegenerateOrbitError, OrbitDomainError, lambert
from orbits._common.constants import BODIES
from orbits.core.manoeuvres import lambert as core
from orbits.tools.bench.lambert import arrival_error


def test_units_in_and_out_match_the_si_core():
    transfer = lambert([1, 0, 0] * u.AU, [0, 1.5, 0] * u.AU, 200 * u.day, "Sun")
    si = core.solve([u.AU.to(u.m), 0, 0], [0, 1.5 * u.AU.to(u.m), 0], 200 * 86400.0, BODIES["Sun"].gm)
    np.testing.assert_array_equal(transfer.v1.to_value(u.m / u.s), si.v1)
    np.testing.assert_array_equal(transfer.v2.to_value(u.m / u.s), si.v2)
    assert transfer.transfer_angle.to_value(u.deg) == pytest.approx(90.0, abs=1e-12)
    assert transfer.semi_major_axis.unit == u.m and transfer.eccentricity.unit == u.one
    r1 = [u.AU.to(u.m), 0, 0]
    r2 = [0, 1.5 * u.AU.to(u.m), 0]
    assert arrival_error(r1, si.v1, r2, 200 * 86400.0, BODIES["Sun"].gm) < 1e-13  # measured 4e-16


def test_other_units_and_a_gm_give_the_same_transfer():
    a = lambert([1, 0, 0] * u.AU, [0, 1.5, 0] * u.AU, 200 * u.day, "Sun")
    b = lambert(([1, 0, 0] * u.AU).to(u.km), ([0, 1.5, 0] * u.AU).to(u.km), (200 * u.day).to(u.yr),
                BODIES["Sun"].gm * u.m**3 / u.s**2)
    np.testing.assert_allclose(b.v1.to_value(u.m / u.s), a.v1.to_value(u.m / u.s), rtol=1e-14, atol=1e-9)


def test_eccentricity_and_semi_major_axis_are_the_conics():
    """e and a from the state at r1 (vis-viva) agree with the solver's a = s / (2 (1 - x**2))."""
    t = lambert([1, 0, 0] * u.AU, [0, 1.5, 0.2] * u.AU, 150 * u.day, "Sun")
    r, v, mu = t.r1, t.v1_si, t.mu
    a = 1 / (2 / np.linalg.norm(r) - v @ v / mu)
    assert t.semi_major_axis.to_value(u.m) == pytest.approx(a, rel=1e-13)
    h = np.cross(r, v)
    e = np.linalg.norm(np.cross(v, h) / mu - r / np.linalg.norm(r))
    assert t.eccentricity.value == pytest.approx(e, rel=1e-13)


def test_broadcasting_over_times_and_revolutions():
    t = lambert([1, 0, 0] * u.AU, [0, 1.5, 0] * u.AU, [200, 900] * u.day, "Sun", revolutions=[0, 1], branch="left")
    assert t.shape == (2,) and t.v1.shape == (2, 3)
    assert t.total_angle[1].to_value(u.deg) == pytest.approx(450.0)


def test_repr_is_one_line():
    text = repr(lambert([1, 0, 0] * u.AU, [0, 1.5, 0] * u.AU, 200 * u.day, "Sun"))
    assert text == ("LambertTransfer(|v1| = 30.81575 km / s, |v2| = 18.92596 km / s, theta = 90 deg, "
                    "a = 1.075769 AU, e = 0.481889, tof = 200 d, about Sun)")
    many = repr(lambert([1, 0, 0] * u.AU, [0, 1.5, 0] * u.AU, [200, 900] * u.day, revolutions=[0, 1]))
    assert "\n" not in many and "N = 0, 1 (right)" in many


def test_quantities_and_html():
    t = lambert([7000, 0, 0] * u.km, [0, 8000, 1000] * u.km, 40 * u.min, "Earth")
    with pytest.warns(orbits.InsideBodyWarning, match="closest approach 3876.922 km .* passes through the Earth"):
        q = t.quantities()  # the transfer's elements come from its Orbit, which sees it dive through the Earth
    assert list(q) == ["v1", "v2", "departure_speed", "arrival_speed", "transfer_angle", "total_angle",
                       "semi_major_axis", "eccentricity", "inclination", "ascending_node", "argument_of_periapsis",
                       "periapsis_distance", "departure_true_anomaly", "time_of_flight", "conditioning"]
    assert t.quantities(["eccentricity"]).keys() == {"eccentricity"}
    assert "LambertTransfer" in t._repr_html_()


def test_the_public_name_is_the_function_whatever_was_imported_first():
    import importlib

    importlib.import_module("orbits.manoeuvres.lambert")
    assert orbits.lambert is lambert and callable(lambert)


@pytest.mark.parametrize(("args", "kwargs", "error", "message"), [
    (([1, 0, 0], [0, 1.5, 0] * u.AU, 200 * u.day), {}, TypeError, "position r1"),
    (([1, 0, 0] * u.AU, [0, 1.5, 0] * u.AU, 200 * u.m), {}, u.UnitConversionError, "time of flight"),
    (([1, 0, 0] * u.AU, [0, 1.5, 0] * u.AU, -2 * u.day), {}, OrbitDomainError, "time of flight"),
    (([1, 0, 0] * u.AU, [-2, 0, 0] * u.AU, 200 * u.day), {}, DegenerateOrbitError, "give normal"),
    (([1, 0, 0] * u.AU, [2, 0, 0] * u.AU, 200 * u.day), {}, DegenerateOrbitError, "same way"),
    (([1, 0, 0] * u.AU, [0, 1.5, 0] * u.AU, 20 * u.day), {"revolutions": 2}, OrbitDomainError, "infeasible"),
    (([1, 0, 0] * u.AU, [0, 1.5, 0] * u.AU, 200 * u.day), {"branch": "up"}, OrbitDomainError, "branch"),
    (([1, 0, 0] * u.AU, [0, 1.5, 0] * u.AU, 200 * u.day, "Pluto?"), {}, KeyError, "Pluto"),
])
def test_errors(args, kwargs, error, message):
    with pytest.raises(error, match=message):
        lambert(*args, **kwargs)


def test_opposite_positions_with_a_normal():
    t = lambert([1, 0, 0] * u.AU, [-1.2, 0, 0] * u.AU, 250 * u.day, normal=[0, 0, 1])
    assert t.transfer_angle.to_value(u.deg) == 180.0 and np.cross(t.r1, t.v1_si)[2] > 0


def test_between_bodies_on_dates_is_the_porkchop_cell_and_reaches_mars():
    """Earth 2026-11-26 to Mars 2027-08-15: the porkchop cell of the same dates to 1e-12 (the same states, mass and
    plane rule), and v1 propagated at 60 digits (orbits.tools.reference) from the Earth's DE421 position as astropy
    reads it reaches astropy's DE421 Mars within 1e-12 of its distance."""
    from astropy.coordinates import get_body_barycentric_posvel
    from astropy.time import Time

    from orbits import Porkchop
    from orbits.ephemeris import positions as ephemeris
    from orbits.tools.reference import propagate

    trip = lambert("Earth", "Mars", depart="2026-11-26", arrive="2027-08-15", source="de421")
    cell = Porkchop.between("Earth", "Mars", ("2026-11-26", "2026-11-26"), ("2027-08-15", "2027-08-15"),
                            source="de421")
    assert cell.shape == (1, 1)
    for ours, theirs in ((trip.v1_si, cell.v1_si[0, 0]), (trip.v2_si, cell.v2_si[0, 0])):
        assert np.linalg.norm(ours - theirs) <= 1e-12 * np.linalg.norm(theirs)  # measured 0
    assert trip.c3.value == pytest.approx(cell.c3[0, 0].unmasked.value, rel=1e-12)
    assert trip.arrival_v_inf.value == pytest.approx(cell.arrival_v_inf[0, 0].unmasked.value, rel=1e-12)

    def heliocentric(name, when):
        kernel = ephemeris.kernel_path()
        r, v = get_body_barycentric_posvel(name, when, ephemeris=kernel)
        r_sun, v_sun = get_body_barycentric_posvel("sun", when, ephemeris=kernel)
        return (r - r_sun).xyz.to_value(u.m), (v - v_sun).xyz.to_value(u.m / u.s)

    depart, arrive = (Time(t, scale="utc") for t in ("2026-11-26", "2027-08-15"))
    r_earth, v_earth = heliocentric("earth", depart)
    r_mars, v_mars = heliocentric("mars", arrive)
    r, v = propagate(r_earth, trip.v1_si, float(trip.mu), float(trip.tof))
    miss = np.linalg.norm(np.array([float(x) for x in r]) - r_mars) / np.linalg.norm(r_mars)
    assert miss < 1e-12  # measured 3.0e-15
    assert trip.c3.value == pytest.approx(np.sum((trip.v1_si - v_earth) ** 2), rel=2e-15)
    assert trip.arrival_v_inf.value == pytest.approx(
        np.linalg.norm(np.array([float(x) for x in v]) - v_mars), rel=1e-13)  # measured 1.2e-14
    normal = np.cross(trip.r1, trip.v1_si)
    assert normal @ orbits.manoeuvres.lambert.ECLIPTIC_POLE > 0  # prograde about the ecliptic pole
    assert trip.inclination.to_value(u.deg) < 2  # the transfer lies near the ecliptic, as the planets do


def test_between_bodies_errors_and_elements_without_bodies():
    with pytest.raises(OrbitDomainError, match="needs the dates depart=... and arrive=..."):
        lambert("Earth", "Mars", depart="2026-11-26")
    with pytest.raises(OrbitDomainError, match="the time of flight is arrive - depart"):
        lambert("Earth", "Mars", 200 * u.day, depart="2026-11-26", arrive="2027-08-15")
    with pytest.raises(OrbitDomainError, match="must be after depart"):
        lambert("Earth", "Mars", depart="2027-08-15", arrive="2026-11-26")
    with pytest.raises(OrbitDomainError, match="both ends are Mars"):
        lambert("mars", "Mars", depart="2026-11-26", arrive="2027-08-15")
    with pytest.raises(OrbitDomainError, match="depart and arrive are dates of a transfer between bodies"):
        lambert([1, 0, 0] * u.AU, [0, 1.5, 0] * u.AU, 200 * u.day, depart="2026-11-26")
    plain = lambert([1, 0, 0] * u.AU, [0, 1.5, 0] * u.AU, 200 * u.day, "Sun")
    assert plain.inclination == 0 * u.rad and "c3" not in plain.quantities()
    with pytest.raises(OrbitDomainError, match="needs the bodies at both ends"):
        _ = plain.c3
    assert plain.periapsis_distance.to_value(u.AU) == pytest.approx(
        plain.semi_major_axis.to_value(u.AU) * (1 - plain.eccentricity.value), rel=1e-14)


def test_a_transfer_faster_than_a_hundredth_of_light_is_refused():
    """One second from the Earth to Hygiea asked 6.5e8 km/s, answered without a word; the refusal starts at 1 % of
    c, where (v / c)**2 = 1e-4 and the Newtonian transfer stops meaning anything. 3000 km/s passes just under it."""
    with pytest.raises(OrbitDomainError, match="of the speed of light"):
        lambert("Earth", "Hygiea", depart="2030-01-01", arrive="2030-01-01T00:00:01")
    fast = lambert([1e9, 0, 0] * u.km, [0, 1e9, 0] * u.km, 1e9 / 2900.0 * np.sqrt(2) * u.s, "Sun")
    assert np.linalg.norm(fast.v1.to_value(u.km / u.s)) < 2998.0
