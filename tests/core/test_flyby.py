"""Sections XXI.vi / XXII.vi (hyperbolic encounters) in the numeric core, against mpmath and state vectors.

The mpmath references are the notes' difference forms R = (sqrt(G**2 M**2 + u**4 b**2) - G M) / u**2 and
w = (sqrt(...) + G M) / (u b) at 60 digits, the deflection 2 asin(1 / e) and nu_inf = arccos(-1 / e); the
library evaluates none of these forms.
"""

import math

import mpmath
import mpref
import numpy as np
import pytest

from orbits.core.encounters import flyby
from orbits.core.twobody import elements

MU = 1.26686534e17  # Jupiter's G M (m3/s2)
K_VALUES = np.logspace(-8, 8, 33)  # k = b u**2 / mu: from slow grazing passes to fast distant ones


def notes_reference(b, u, mu):
    """The notes' XXI.vi quantities, with the ERRATA #48 hyperbola, at 60 digits."""
    with mpmath.workdps(60):
        b, u, mu = mpmath.mpf(b), mpmath.mpf(u), mpmath.mpf(mu)
        root = mpmath.sqrt(mu**2 + u**4 * b**2)
        e = mpmath.sqrt(1 + (b * u**2 / mu) ** 2)
        return {
            "periapsis_distance": (root - mu) / u**2,
            "periapsis_speed": (root + mu) / (u * b),
            "eccentricity": e,
            "semi_major_axis": -mu / u**2,
            "semilatus_rectum": (u * b) ** 2 / mu,
            "deflection_angle": 2 * mpmath.asin(1 / e),
            "asymptote_true_anomaly": mpmath.acos(-1 / e),
        }


def core_values(b, u, mu):
    return {
        "periapsis_distance": flyby.periapsis_distance(b, u, mu),
        "periapsis_speed": flyby.periapsis_speed(b, u, mu),
        "eccentricity": flyby.eccentricity(b, u, mu),
        "semi_major_axis": flyby.semi_major_axis(u, mu),
        "semilatus_rectum": flyby.semilatus_rectum(b, u, mu),
        "deflection_angle": flyby.deflection_angle(b, u, mu),
        "asymptote_true_anomaly": flyby.asymptote_true_anomaly(b, u, mu),
    }


@pytest.mark.parametrize("k", K_VALUES)
def test_every_flyby_quantity_within_a_few_ulp_of_the_notes(k):
    """Measured worst over 401 k in [1e-8, 1e8] and three speeds: 2.3 ulp (R), 2.6 ulp (w), <= 1.6 ulp (others)."""
    u = 5600.0
    b = k * MU / u**2
    ref = notes_reference(b, u, MU)
    for name, value in core_values(b, u, MU).items():
        assert float(mpref.ulp_error(value, ref[name])) <= 3.0, name


def test_the_notes_difference_form_loses_every_digit_on_slow_close_passes():
    """At k = 1e-9 the printed (sqrt(G**2 M**2 + u**4 b**2) - G M) / u**2 evaluates to 0 in float64."""
    u = 1.0
    b = 1e-9 * MU / u**2
    printed = (math.sqrt(MU**2 + u**4 * b**2) - MU) / u**2
    ref = notes_reference(b, u, MU)["periapsis_distance"]
    assert printed == 0.0
    assert float(mpref.rel_error(flyby.periapsis_distance(b, u, MU), ref)) <= 4e-16


@pytest.mark.parametrize("k", [1e-6, 0.3, 1.0, 40.0, 1e6])
def test_closest_approach_and_speed_from_the_state_vectors_of_the_hyperbola(k):
    """The state at nu = 0 of the conic (p, e) lies at distance R with speed w; energy and h are u**2 / 2 and u b."""
    u = 7.3e3
    b = k * MU / u**2
    p, e = flyby.semilatus_rectum(b, u, MU), flyby.eccentricity(b, u, MU)
    r, v = elements.elements_to_state(p, e, 0.2, 0.4, 0.6, 0.0, MU)
    assert math.isclose(np.linalg.norm(r), flyby.periapsis_distance(b, u, MU), rel_tol=4e-16)
    assert math.isclose(np.linalg.norm(v), flyby.periapsis_speed(b, u, MU), rel_tol=4e-16)
    assert math.isclose(np.linalg.norm(np.cross(r, v)), u * b, rel_tol=1e-15)
    energy = 0.5 * v @ v - MU / np.linalg.norm(r)
    assert abs(energy - 0.5 * u**2) <= 4e-15 * (0.5 * v @ v)  # v**2 / 2 - mu / r cancels


@pytest.mark.parametrize("k", [1e-6, 1.0, 1e6])
def test_identities_of_the_notes(k):
    """L / m = u b = R w, w**2 = u**2 + 2 G M / R (XXI.vi) and R = a_h (e - 1) (ERRATA #48)."""
    u = 3.0e4
    b = k * MU / u**2
    big_r, w = flyby.periapsis_distance(b, u, MU), flyby.periapsis_speed(b, u, MU)
    assert math.isclose(big_r * w, u * b, rel_tol=4e-16)
    assert math.isclose(w, flyby.speed_at_distance(big_r, u, MU), rel_tol=4e-16)
    e = flyby.eccentricity(b, u, MU)
    assert math.isclose(big_r, -flyby.semi_major_axis(u, MU) * (e - 1), rel_tol=max(4e-16, 4e-16 / (e - 1)))
    assert math.isclose(flyby.asymptote_true_anomaly(b, u, MU), (math.pi + flyby.deflection_angle(b, u, MU)) / 2)


@pytest.mark.parametrize("k", K_VALUES[::4])
def test_impact_parameter_for_a_wanted_closest_approach(k):
    """The inverse b(R) = R sqrt(1 + 2 mu / (R u**2)) round-trips within 3 ulp and matches the mpmath b."""
    u = 5600.0
    big_r = k * MU / u**2
    b = flyby.impact_parameter(big_r, u, MU)
    assert math.isclose(flyby.periapsis_distance(b, u, MU), big_r, rel_tol=3 * 2**-53)
    with mpmath.workdps(60):
        # b from the energy and angular momentum: u b = R w, w**2 = u**2 + 2 mu / R
        ref = mpmath.mpf(big_r) * mpmath.sqrt(mpmath.mpf(u) ** 2 + 2 * mpmath.mpf(MU) / big_r) / u
    assert float(mpref.ulp_error(b, ref)) <= 2.0


def test_everything_broadcasts():
    b = np.array([[1e8], [1e9]])
    u = np.array([3e3, 6e3, 9e3])
    assert flyby.periapsis_distance(b, u, MU).shape == (2, 3)
    assert flyby.impact_parameter(b, u, MU).shape == (2, 3)
    assert flyby.deflection_angle(b, u, MU)[0, 0] == flyby.deflection_angle(1e8, 3e3, MU)
