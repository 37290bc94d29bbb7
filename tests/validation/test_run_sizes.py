"""Every size of an N-body run is estimated and refused before anything is allocated or integrated, with the limit
in the message: bodies squared, outputs x bodies, and the run's length in periods of its fastest orbit, whether
the bodies come as orbit elements or as Cartesian vectors."""

import time

import numpy as np
import pytest

from orbits.core.errors import OrbitDomainError, SceneError
from orbits.validate import nbody, scene, scenes
from orbits.validate.nbody import NBodyProblem, check_span, fastest_orbit, step_weight


def refusal(data: dict) -> str:
    with pytest.raises(SceneError) as err:
        scene.from_dict(data, "s.json")
    assert "\n" not in str(err.value)
    return str(err.value)


def particles(n: int) -> list[dict]:
    """The Sun and n - 1 test particles on distinct orbits about it."""
    return [{"name": "Sun", "body": "Sun"}] + [
        {"name": f"p{k}", "test_particle": True, "orbit": {"primary": "Sun", "a": f"{1 + k * 1e-3} AU", "e": 0.1}}
        for k in range(1, n)]


def pair(span: str, position: str, velocity: str) -> dict:
    """Two suns given as Cartesian vectors, the second at `position` moving at `velocity`."""
    return {"name": "pair", "asks": ["positions"], "time": {"span": span, "outputs": 10}, "bodies": [
        {"name": "A", "mass": "1 solMass"},
        {"name": "B", "mass": "1 solMass", "position": position, "velocity": velocity}]}


def test_bodies_squared_is_bounded_before_any_body_is_read():
    """A scene of 1e5 bodies never finished loading (an all-pairs position check); 1e4 took minutes."""
    start = time.perf_counter()
    message = refusal({"name": "many", "asks": ["positions"], "time": {"span": "1 d"}, "bodies": particles(2000)})
    assert "bodies: 2000 bodies: a step sums 2000**2 = 4e+06 pair forces; at most 1e+06 (1000 bodies)" in message
    assert time.perf_counter() - start < 5  # refused before reading a body: measured 0.01 s; main loaded them all


def test_outputs_times_bodies_is_bounded_in_data_scenes_too():
    """300 particles x 1e6 outputs allocated 6.7 GiB: model scenes had a limit, data scenes none."""
    message = refusal({"name": "wide", "asks": ["positions"], "time": {"periods": 1, "outputs": 1_000_000},
                       "bodies": particles(301)})
    assert "time.outputs: outputs x bodies = 1000000 x 301 = 3.01e+08 stored states; at most 1e+07" in message
    times = [f"{k} s" for k in range(1, 40_001)]
    message = refusal({"name": "listed", "asks": ["positions"], "time": {"times": times}, "bodies": particles(301)})
    assert "time.times: outputs x bodies = 40000 x 301 = 1.2e+07 stored states" in message


@pytest.mark.parametrize("data, fragment", [
    (pair("1e9 yr", "1e7,0,0 km", "0,100,0 km/s"), "is 1.69e+11 periods of the fastest orbit ('A' and 'B', period "
                                                   "186480 s)"),
    (pair("1 yr", "1,0,0 m", "0,0,0 m/s"), "is 2.31e+17 periods of the fastest orbit ('A' and 'B', period "
                                           "1.36353e-10 s)"),
])
def test_bodies_given_as_vectors_are_held_to_the_fastest_orbit_they_make(data, fragment):
    """A close binary over 1e9 yr, two suns 1 m apart: vectors bypassed the guard, which read orbit tables only."""
    message = refusal(data)
    assert fragment in message and "at most 1e+06 are allowed: too long a run" in message


def test_an_eccentric_period_counts_for_the_steps_it_takes():
    """e = 0.999 over 1e6 periods passed the guard and ran for minutes."""
    data = {"name": "comet", "asks": ["positions"], "time": {"periods": 1_000_000, "outputs": 10}, "bodies": [
        {"name": "Sun", "body": "Sun"},
        {"name": "c", "test_particle": True, "orbit": {"primary": "Sun", "a": "1 AU", "e": 0.999}}]}
    message = refusal(data)
    assert "is 1e+06 periods of the fastest orbit ('Sun' and 'c'" in message
    assert "which count as 6.1e+06: an e = 0.999 period takes 6.1 times the integrator steps" in message
    data["time"]["periods"] = 100_000
    assert scene.from_dict(data).times.size == 10  # 6.1e5 weighted periods: allowed


def test_the_step_weight_follows_the_measured_ias15_steps():
    measured = {0.0: 36, 0.5: 51, 0.9: 97, 0.99: 159, 0.999: 221, 0.9999: 283, 0.99999: 343}  # steps per period
    for e, steps in measured.items():
        assert abs(step_weight(e) * 36 / steps - 1) < 0.07, e  # worst 6.7 % at e = 0.5


def test_the_fastest_orbit_is_the_fastest_bound_pair_and_open_pairs_have_none():
    gm = np.array([1.0, 1e-3, 0.0])
    positions = np.array([[0, 0, 0], [1, 0, 0], [0, 0.1, 0]], dtype=float)
    velocities = np.array([[0, 0, 0], [0, 1, 0], [-np.sqrt(10.0), 0, 0]], dtype=float)  # a circle of radius 0.1
    i, j, period, e, rate = fastest_orbit(gm, positions, velocities, 2)
    assert (i, j) == (0, 2) and period == pytest.approx(2 * np.pi * 0.1**1.5, rel=1e-14) and e < 1e-14
    assert fastest_orbit(gm[:2], positions[:2], velocities[:2] * 10, 2) is None  # unbound: a single passage
    check_span(1e5 * period, gm, positions, velocities, 2)  # 1e5 periods of the fastest orbit: allowed


def test_every_nbody_problem_is_held_to_the_same_rules():
    gm, r, v = np.array([1.0, 1.0]), np.array([[0, 0, 0], [1, 0, 0.0]]), np.array([[0, 0, 0], [0, 1.0, 0]])
    with pytest.raises(OrbitDomainError, match="periods of the fastest orbit .bodies 0 and 1"):
        NBodyProblem(gm, r, v, 2, np.array([1e9]))
    with pytest.raises(OrbitDomainError, match="at most 1e\\+07 are allowed"):
        NBodyProblem(gm, r, v, 2, np.linspace(1, 10, nbody.MAX_STATES // 2 + 1))
    with pytest.raises(OrbitDomainError, match="bodies 0 and 1 start at the same point: the force between them"):
        NBodyProblem(gm, np.zeros((2, 3)), v, 2, np.array([1.0]))
    many = 1001
    with pytest.raises(OrbitDomainError, match="1001 bodies: a step sums"):
        NBodyProblem(np.r_[1.0, np.zeros(many - 1)], np.arange(3 * many, dtype=float).reshape(many, 3),
                     np.zeros((many, 3)), 1, np.array([1.0]))


def test_a_special_file_is_read_no_further_than_a_scene_can_be_long():
    """`orbits validate /dev/zero` read until memory ran out."""
    with pytest.raises(SceneError, match="/dev/zero: longer than 32 MiB, the most a scene file may hold"):
        scenes.load("/dev/zero")


def test_bodies_that_start_at_one_point_are_still_found_among_many():
    bodies = particles(500)
    bodies.append({"name": "twin", "test_particle": True, "orbit": dict(bodies[123]["orbit"])})
    message = refusal({"name": "twins", "asks": ["positions"], "time": {"span": "1 d"}, "bodies": bodies})
    assert "bodies[500]: 'twin' starts at the position of bodies[123] ('p123')" in message
    signed = {"name": "zeros", "asks": ["positions"], "time": {"span": "1 d"}, "bodies": [
        {"name": "A", "mass": "1 kg", "position": "0,0,0 m"}, {"name": "B", "mass": "1 kg", "position": "-0,0,-0 m"}]}
    assert "'B' starts at the position of bodies[0] ('A')" in refusal(signed)
