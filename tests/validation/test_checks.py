"""The checks measure the integrated trajectory, so that a state that did not move cannot pass them."""

import numpy as np
import pytest

from orbits.validate import predict, scene


@pytest.mark.parametrize("name", ["flyby", "near_parabolic", "stellar_encounter"])
def test_the_closest_approach_is_the_separation_reached_at_the_predicted_time(name):
    s = scene.load(name)
    index = s.orbiting[0]
    q, t_p = predict.closest_approach_of(s, index)
    exact_r, exact_v = predict.two_body_states(s, np.array([t_p]))
    reached = predict.measured_closest_approach(s, index, exact_r[0], exact_v[0])
    assert abs(reached - q) <= 4e-15 * q  # the closed-form state at t_p is at periapsis (measured 4e-16)
    start = predict.measured_closest_approach(s, index, s.positions, s.velocities)
    assert abs(start - q) > 1e-3 * q  # the initial state is far from periapsis: it fails the check
