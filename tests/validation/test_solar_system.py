"""The solar_system scene: DE421 states integrated by rebound and heyoka, with and without the Sun's 1PN term,
against DE421; Mercury's perihelion against general relativity's 42.98 arcsec per century."""

import numpy as np
import pytest

from orbits.core.errors import SceneError
from orbits.validate import _heyoka, _rebound, models, validate_scene
from orbits.validate.nbody import NBodyProblem


@pytest.fixture(scope="module")
def report():
    return validate_scene(models.build("solar_system"))


def test_the_scene_passes_with_both_integrators(report):
    assert report.passed, [(c.quantity, c.errors) for c in report.checks if not c.passed]
    names = [c.quantity for c in report.checks]
    assert any(n.startswith("Mercury: max km") for n in names) and any("mutual agreement" in n for n in names)
    assert report.settings["rebound"]["post_newtonian"].startswith("REBOUNDx gr")


def test_the_1pn_term_brings_mercury_and_earth_to_the_kilometre(report):
    """Measured 0.63 km (Mercury) and 3.3 km (Earth) at most over 10 years at the scene's 120 outputs (0.68 km for
    Mercury sampled daily); 1,820 and 612 km without it."""
    values = {c.quantity.split(":")[0]: c.values["heyoka"] for c in report.checks if "max km" in c.quantity}
    assert values["Mercury"] < 2.0 and values["Earth"] < 10.0


def test_from_1950_the_floors_larger_epoch_is_reached_and_passes():
    """The tolerances are 3x the worse of two measured epochs (orbits/validate/models.py SOLAR_SYSTEM_FLOOR_KM).
    From 1950 the Jupiter system, a point here, misses DE421 by 20.7 km (0.94 km from J2000) and Mars by 5.8 km:
    the floor is reached there, so the bound is the physics', not slack. Measured 20.7 and 5.8 km."""
    earlier = validate_scene(models.build("solar_system", {"epoch": "1950-01-01"}))
    assert earlier.passed, [(c.quantity, c.errors) for c in earlier.checks if not c.passed]
    values = {c.quantity.split(":")[0]: c.values["heyoka"] for c in earlier.checks if "max km" in c.quantity}
    floors = models.SOLAR_SYSTEM_FLOOR_KM[True]
    assert 0.9 * floors["Jupiter"] <= values["Jupiter"] <= floors["Jupiter"] * 1.01, values["Jupiter"]
    assert values["Mars"] <= floors["Mars"] * 1.01


def test_without_relativity_mercurys_perihelion_lags_by_gr_advance():
    """The Newtonian perihelion trails DE421 by GR's 42.98 arcsec/century: measured 4.29818 arcsec in 10
    years against 4.29805 (relative 3.1e-5), the public relativistic_periapsis_advance of Standish's mean orbit."""
    newtonian = validate_scene(models.build("solar_system", {"post_newtonian": False}))
    lag = next(c for c in newtonian.checks if c.quantity.startswith("Mercury perihelion lag"))
    assert lag.passed and lag.analytic == pytest.approx(4.298, abs=5e-4)  # Clemence 1947, Will 2014: 42.98 / cy
    for backend in ("rebound", "heyoka"):
        assert lag.values[backend] == pytest.approx(4.298, rel=5e-4)
    mercury = next(c for c in newtonian.checks if c.quantity.startswith("Mercury: max km"))
    assert 1500 < mercury.values["rebound"] < 2200  # measured 1,820 km: relativity is what was missing


def test_the_two_1pn_implementations_agree_and_advance_periapsis_as_gr_predicts():
    """A strongly relativistic test (c = 1000 in code units, a = 1, e = 0.6, 20 orbits): REBOUNDx's gr, iterated,
    and the heyoka equations truncated at 1/c**2 differ by O(1/c**4): measured 8.4e-8 apart (1.0e-5 at c = 300,
    the 1/c**4 scaling), and the periapsis advances by 6 pi / (c**2 (1 - e**2)) per orbit to 7.8e-4."""
    r, v = [0.4, 0.0, 0.0], [0.0, np.sqrt(1.6 / 0.4), 0.0]  # periapsis of a = 1, e = 0.6 about a unit mass
    gm, c, orbits = np.array([1.0, 1e-9]), 1000.0, 20
    problem = NBodyProblem(gm, [[0, 0, 0], r], [[0, 0, 0], v], 2, np.array([orbits * 2 * np.pi]), c)
    a = _rebound.integrate(problem, "ias15", 1e-9)
    b = _heyoka.integrate(problem)
    assert np.linalg.norm(a.positions[-1, 1] - b.positions[-1, 1]) < 3e-7
    rel_r, rel_v = b.positions[-1, 1] - b.positions[-1, 0], b.velocities[-1, 1] - b.velocities[-1, 0]
    mu = 1.0 + 1e-9
    e = ((rel_v @ rel_v - mu / np.linalg.norm(rel_r)) * rel_r - (rel_r @ rel_v) * rel_v) / mu
    predicted = orbits * 6 * np.pi / (c**2 * (1 - 0.6**2))
    assert np.arctan2(e[1], e[0]) == pytest.approx(predicted, rel=3e-3)


@pytest.mark.parametrize("parameters, message", [
    ({"epoch": "1800-01-01"}, "outside DE421"),
    ({"epoch": "2050-01-01", "years": 10}, "outside DE421"),
    ({"years": 0}, "outside"),
    ({"post_newtonian": "yes"}, "true or false"),
    ({"epoch": 2000}, "date string"),
])
def test_bad_parameters_are_one_line_scene_errors(parameters, message):
    with pytest.raises(SceneError, match=message):
        models.build("solar_system", parameters)


def test_the_post_newtonian_term_needs_massive_bodies_and_an_adaptive_integrator():
    from orbits.core.errors import OrbitDomainError

    with pytest.raises(OrbitDomainError, match="n_active"):
        NBodyProblem([1.0, 0.0], [[0, 0, 0], [1, 0, 0]], [[0, 0, 0], [0, 1, 0]], 1, [1.0], 1e4)
    problem = NBodyProblem([1.0, 1e-9], [[0, 0, 0], [1, 0, 0]], [[0, 0, 0], [0, 1, 0]], 2, [1.0], 1e4)
    with pytest.raises(OrbitDomainError, match="whfast"):
        _rebound.integrate(problem, "whfast", dt=0.01)
