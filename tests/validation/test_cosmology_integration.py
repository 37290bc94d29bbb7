"""The notes' expanding sphere (XXIV) integrated as an N-body problem with rebound IAS15 and heyoka.

A central mass (G M = 1, code units) and test-particle shells launched radially at the zero-energy speed
sqrt(2 / r) must follow r(t) = (9 (t0 + tau)**2 / 2)**(1/3) and H = v / r = 2 / (3 (t0 + tau)), t0 = sqrt(2 r0**3 / 9)
being each shell's time since its big bang. Radial orbits have h = 0; the integrators take them in their stride.
Measured: positions within 9.7e-16 relative (heyoka, tol 1e-16) and 3.2e-16 (IAS15, epsilon 1e-9), H within
8.9e-16 (heyoka) and 6.7e-16 (IAS15); each bound is about 10 times its figure.
"""

import numpy as np
import pytest

from orbits.core.cosmology.sphere import sphere_time
from orbits.core.errors import OrbitDomainError
from orbits.validate import backends
from orbits.validate.builders import expanding_sphere_problem

CONFIGS = {
    "heyoka": ("heyoka", {"tol": 1e-16, "high_accuracy": True}),
    "ias15": ("rebound", {"integrator": "ias15", "epsilon": 1e-9}),
}
#: (position, H) relative tolerances per configuration
TOLERANCES = {
    "heyoka": (1e-14, 1e-14),  # measured 9.7e-16, 8.9e-16
    "ias15": (3e-15, 7e-15),  # measured 3.2e-16, 6.7e-16
}


@pytest.fixture(scope="module")
def scene():
    return expanding_sphere_problem(8, inner_radius=1.0, outer_radius=4.0, duration=20.0, n_times=11)


def test_scene_is_the_notes_model(scene):
    problem, positions = scene
    assert problem.n_active == 1 and list(problem.gm) == [1.0] + [0.0] * 8
    r0 = np.linalg.norm(problem.positions[1:], axis=-1)
    np.testing.assert_allclose(r0, np.linspace(1.0, 4.0, 8), rtol=1e-15)
    speeds = np.linalg.norm(problem.velocities[1:], axis=-1)
    np.testing.assert_allclose(speeds, np.sqrt(2.0 / r0), rtol=1e-15)  # zero energy (XXIV.ii)
    radial = np.sum(problem.velocities[1:] * problem.positions[1:], axis=-1) / (r0 * speeds)
    np.testing.assert_allclose(radial, 1.0, rtol=1e-15)  # h = 0: purely radial
    np.testing.assert_allclose(positions[0, 1:], problem.positions[1:], rtol=1e-15)
    assert positions.shape == (11, 9, 3) and np.all(positions[:, 0] == 0)


@pytest.mark.parametrize("config", CONFIGS)
def test_integration_reproduces_r_of_t_and_the_hubble_parameter(scene, config):
    problem, positions = scene
    name, settings = CONFIGS[config]
    result = backends.integrate(name, problem, **settings)
    np.testing.assert_array_equal(result.times, problem.times)
    shells = result.positions[:, 1:]
    error = np.linalg.norm(shells - positions[:, 1:], axis=-1) / np.linalg.norm(positions[:, 1:], axis=-1)
    position_rtol, hubble_rtol = TOLERANCES[config]
    assert error.max() <= position_rtol, error.max()
    r = np.linalg.norm(shells, axis=-1)
    hubble = np.sum(result.velocities[:, 1:] * shells, axis=-1) / r**2  # radial speed / r
    t = sphere_time(np.linalg.norm(problem.positions[1:], axis=-1), 1.0) + result.times[:, None]
    np.testing.assert_allclose(hubble, 2.0 / (3.0 * t), rtol=hubble_rtol)
    assert r[-1, 0] / r[0, 0] > 10  # the inner shell expanded more than tenfold


@pytest.mark.parametrize(
    "kwargs, fragment",
    [
        ({"n_shells": 0}, "n_shells = 0 is outside the allowed range [1, inf)"),
        ({"n_shells": True}, "n_shells = True"),
        ({"n_shells": 2.5}, "n_shells = 2.5 is not an integer"),
        ({"n_times": 1}, "n_times = 1 is outside"),
        ({"inner_radius": -1.0}, "inner_radius = -1.0"),
        ({"inner_radius": 3.0, "outer_radius": 2.0}, "outer_radius = 2.0 is below inner_radius = 3.0"),
        ({"duration": np.inf}, "duration = inf"),
    ],
)
def test_scene_rejects_bad_settings(kwargs, fragment):
    with pytest.raises(OrbitDomainError) as raised:
        expanding_sphere_problem(**kwargs)
    assert fragment in str(raised.value)
