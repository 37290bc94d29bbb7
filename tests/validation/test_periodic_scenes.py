"""Periodic orbits flown in rebound and heyoka as test particles of two moving primaries (inertial frame, G = 1):
closure after one period (and ten for the orbits that keep), the period from the integration, the Jacobi constant,
and the departure of an unstable orbit at its eigenvalue's rate; Earth-Moon and Sun-Earth."""

import astropy.units as u
import numpy as np
import pytest

from orbits import PeriodicOrbit
from orbits.validate import models, run
from orbits.validate import periodic as scenes

SCENE_NAMES = ["periodic_dro", "periodic_halo", "periodic_lyapunov", "periodic_nrho"]


def test_the_built_in_scenes_are_registered_and_summarised():
    assert set(SCENE_NAMES) <= set(models.builtin_names())
    assert models.summary("periodic_nrho").startswith("The Earth-Moon L2 southern 9:2 synodic-resonant")


ORBITS = {
    "SE L1 lyapunov": ("se", "lyapunov", "L1", {"ax": 200_000 * u.km}),
    "SE L2 halo": ("se", "halo", "L2", {"az": 120_000 * u.km}),
    "SE L1 southern halo": ("se", "halo", "L1", {"az": 120_000 * u.km, "branch": "southern"}),
    "SE L1 vertical": ("se", "vertical", "L1", {"az": 200_000 * u.km}),
    "SE DRO": ("se", "distant_retrograde", None, {"ax": 500_000 * u.km}),
    "EM L2 lyapunov": ("em", "lyapunov", "L2", {"ax": 20_000 * u.km}),
    "EM L1 halo": ("em", "halo", "L1", {"az": 10_000 * u.km}),
    "EM L2 vertical": ("em", "vertical", "L2", {"az": 20_000 * u.km}),
}


@pytest.mark.parametrize("key", ORBITS)
def test_orbits_close_in_rebound_and_heyoka(request, key):
    """Every check within the scenes' tolerances (orbits.validate.periodic.TOLERANCES, ten times the worst
    measured): closure after one period at most 9.1e-11 of the size (a Sun-Earth vertical orbit), the period to
    5.7e-12, the Jacobi constant to 1.6e-15 here, the departure per period to 1.6e-5 of |lambda_max|."""
    pair, family, point, targets = ORBITS[key]
    system = request.getfixturevalue(pair)
    constructor = getattr(PeriodicOrbit, family)
    orbit = constructor(system, point, **targets) if point else constructor(system, **targets)
    report = run.validate([scenes.periodic_scene(key, key, orbit)]).scenes[0]
    assert report.passed, [(c.quantity, c.errors) for c in report.checks if not c.passed]
    quantities = [c.quantity for c in report.checks]
    assert quantities[0] == "closure after one period: |dr| / size"
    assert ("departure per period vs |largest eigenvalue|" in quantities) == (not orbit.stable)
    keeps = float(np.max(np.abs(orbit.eigenvalues))) <= scenes.KEEPABLE_GROWTH
    assert ("closure after 10 periods: |dr| / size" in quantities) == keeps


@pytest.mark.parametrize("name", SCENE_NAMES)
def test_the_built_in_scenes_pass(name):
    report = run.validate([models.build(name)]).scenes[0]
    assert report.passed, [(c.quantity, c.errors) for c in report.checks if not c.passed]
    closure = report.checks[0]
    assert max(closure.errors.values()) < 3e-11  # measured at most 2.9e-12 (the halo)


def test_the_departure_is_the_eigenvalue_not_the_initial_offset(em):
    """The measured growth per period follows |lambda_max| (995.9 for this Lyapunov orbit) for any offset in the
    linear range; a particle started on the orbit itself stays within its closure."""
    orbit = PeriodicOrbit.lyapunov(em, "L1", ax=20_000 * u.km)
    expected = float(np.max(np.abs(orbit.eigenvalues)))
    for offset in (1e-12, 1e-10):
        report = run.validate([scenes.periodic_scene("lyapunov", "", orbit, offset=offset)]).scenes[0]
        growth = next(c for c in report.checks if c.quantity.startswith("departure"))
        assert all(abs(value / expected - 1.0) < 1e-3 for value in growth.values.values())


def test_a_scene_file_can_ask_for_fewer_periods():
    scene = models.build("periodic_dro", {"periods": 3})
    assert scene.problem.times.size == 4  # just before one period, then 1, 2, 3 periods
    with pytest.raises(Exception, match="periods"):
        models.build("periodic_dro", {"periods": 0})
