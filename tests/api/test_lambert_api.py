"""orbits.lambert (orbits/manoeuvres/lambert.py): the unit-aware Lambert solver: units, the result object, errors,
repr."""

import astropy.units as u
import numpy as np
import pytest

import orbits
from orbits import DegenerateOrbitError, OrbitDomainError, lambert
from orbits.constants import BODIES
from orbits.core import lambert as core
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
    q = t.quantities()
    assert list(q) == ["v1", "v2", "departure_speed", "arrival_speed", "transfer_angle", "total_angle",
                       "semi_major_axis", "eccentricity", "time_of_flight"]
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
