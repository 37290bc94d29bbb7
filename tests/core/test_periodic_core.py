"""The numeric core of the periodic orbits: the integrator against Kepler's closed form, its compiled port against it,
the local coordinates against the barycentric field, the correctors' closure and Jacobi constant, the small-amplitude
and Richardson limits at their orders, the monodromy's identities and the continuation's stops.

Units of orbits.core.periodic.cr3bp: r = 1, n = 1. Mass ratios from the IAU 2015 nominal GMs of the catalogue.
"""

import math

import numpy as np
import pytest

from orbits.core import dop853
from orbits.core.errors import ConvergenceError, OrbitDomainError
from orbits.core.periodic import continuation, cr3bp, families, libration, shooting
from orbits.core.twobody import kepler

EARTH_MOON = 0.012150584269940356
SUN_EARTH = 3.0034893488507934e-06


def _kepler_state(t, e):
    """(x, y, vx, vy) of the a = 1, GM = 1 ellipse of eccentricity e from periapsis at time t (Kepler's equation)."""
    big_e = kepler.eccentric_anomaly(np.asarray(t, dtype=float), e)
    c, s = np.cos(big_e), np.sin(big_e)
    b = math.sqrt(1.0 - e * e)
    return np.stack([c - e, b * s, -s / (1.0 - e * c), b * c / (1.0 - e * c)], axis=-1)


def _kepler_field(y):
    r = y[:2]
    return np.concatenate([y[2:], -r / np.linalg.norm(r) ** 3])


@pytest.mark.parametrize("e", [0.0, 0.5, 0.9])
def test_dop853_follows_keplers_ellipse_at_its_tightest_tolerance(e):
    """Global error over one period at rtol = atol = 100 eps (measured 1.1e-13, 2.2e-12, 2.5e-10 for e = 0, 0.5,
    0.9: the periapsis passage of e = 0.9 costs the most), landing on each output time."""
    times = np.linspace(0.0, 2.0 * math.pi, 9)
    arc = dop853.integrate(_kepler_field, _kepler_state(0.0, e), 2.0 * math.pi, outputs=times)
    error = np.max(np.abs(arc.states - _kepler_state(times, e)))
    assert error < {0.0: 1.1e-12, 0.5: 2.2e-11, 0.9: 2.5e-9}[e]
    assert np.array_equal(arc.end, arc.states[-1]) and arc.steps > 0


def test_dop853_integrates_backwards_and_refuses_unordered_outputs():
    forward = dop853.integrate(_kepler_field, _kepler_state(0.0, 0.5), 1.0).end
    back = dop853.integrate(_kepler_field, forward, -1.0).end
    assert np.max(np.abs(back - _kepler_state(0.0, 0.5))) < 2.2e-13  # measured 2.2e-14
    with pytest.raises(OrbitDomainError, match="monotonically"):
        dop853.integrate(_kepler_field, _kepler_state(0.0, 0.5), 1.0, outputs=[0.5, 0.2])


def test_a_trajectory_into_a_singularity_stops_with_a_message():
    """A fall from rest at r = 1 onto a unit mass reaches it at t = pi / 2**1.5 (1.11): the steps shrink there."""
    with pytest.raises(ConvergenceError, match="singularity"):
        dop853.integrate(_kepler_field, np.array([1.0, 0.0, 0.0, 0.0]), 2.0)


@pytest.mark.parametrize("name", cr3bp.ORIGINS)
def test_the_local_field_is_the_barycentric_field_about_every_origin(name):
    """The pull less the pull at the origin, formed without cancellation, gives the same field (to 1e-14 of the
    largest term, the barycentric field's own rounding; measured 3.6e-15)."""
    place = cr3bp.origin(EARTH_MOON, name)
    rng = np.random.default_rng(1)
    for offset in rng.normal(scale=0.05, size=(20, 6)):
        local = cr3bp.vector_field(EARTH_MOON, place)(offset)
        barycentric = cr3bp.field(cr3bp.to_barycentric(offset, place), EARTH_MOON)
        assert np.max(np.abs(local - barycentric)) <= 1e-14 * max(1.0, np.max(np.abs(barycentric)))


def test_the_transition_field_carries_the_jacobian_of_the_state_field():
    """Phi' = A Phi with A the derivative of the field (central differences, step 1e-6: agreement 1e-8)."""
    place = cr3bp.origin(EARTH_MOON, "L2")
    state = np.array([0.02, 0.01, 0.03, 0.01, -0.02, 0.005])
    field = cr3bp.vector_field(EARTH_MOON, place)
    derivative = np.column_stack([(field(state + 1e-6 * e) - field(state - 1e-6 * e)) / 2e-6 for e in np.eye(6)])
    with_phi = cr3bp.vector_field(EARTH_MOON, place, True)(np.concatenate([state, np.eye(6).ravel()]))
    assert np.max(np.abs(with_phi[6:].reshape(6, 6) - derivative)) < 1e-8


def _halo(mu, point, az, northern=True, compiled=False):
    flow = shooting.Flow(mu, cr3bp.origin(mu, point), compiled)
    return (flow,) + families.first_member(flow, "halo", point, northern, az)[:2]


def test_the_compiled_port_takes_the_same_steps_as_the_numpy_integrator():
    """Same steps and evaluations, states to rounding (measured 4e-14 after a halo's half period with Phi)."""
    pytest.importorskip("numba")
    _, hmap, member = _halo(EARTH_MOON, "L2", 0.01)
    state = member.state
    numpy_flow = shooting.Flow(EARTH_MOON, cr3bp.origin(EARTH_MOON, "L2"), False)
    compiled_flow = shooting.Flow(EARTH_MOON, cr3bp.origin(EARTH_MOON, "L2"), True)
    times = np.linspace(0.0, member.period, 5)
    for transition in (False, True):
        a = numpy_flow.arc(state, member.period, transition, outputs=times)
        b = compiled_flow.arc(state, member.period, transition, outputs=times)
        assert (a.steps, a.rejected, a.evaluations) == (b.steps, b.rejected, b.evaluations)
        assert np.max(np.abs(a.states - b.states)) < 4e-13 * max(1.0, np.max(np.abs(a.states)))


#: first members corrected from their first guesses: (mass ratio, family, point, amplitude in units of the origin's
#: length scale)
CASES = [(EARTH_MOON, "lyapunov", "L1", 0.05), (EARTH_MOON, "lyapunov", "L2", 0.05), (EARTH_MOON, "halo", "L1", 0.2),
         (EARTH_MOON, "halo", "L2", 0.2), (EARTH_MOON, "vertical", "L1", 0.1), (EARTH_MOON, "dro", None, 0.5),
         (SUN_EARTH, "lyapunov", "L1", 0.05), (SUN_EARTH, "halo", "L2", 0.2), (SUN_EARTH, "vertical", "L2", 0.1),
         (SUN_EARTH, "dro", None, 0.5)]


def _member(mu, family, point, size):
    place = cr3bp.origin(mu, families.origin(family, point))
    scale = place.scale
    flow = shooting.Flow(mu, place)
    hmap, member, _ = families.first_member(flow, family, point, True, size * scale)
    return flow, hmap, member


@pytest.mark.parametrize("mu, family, point, size", CASES)
def test_a_corrected_orbit_closes_and_keeps_its_jacobi_constant(mu, family, point, size):
    """After one full period in the corrector's own integration the orbit closes to 1e-11 of its size (measured
    at most 5.8e-12, a Sun-Earth Lyapunov orbit) and its Jacobi constant holds to 3e-15 (measured 3.0e-16) at 200
    points along it."""
    flow, hmap, member = _member(mu, family, point, size)
    times = np.linspace(0.0, member.period, 200)
    arc = flow.arc(member.state, member.period, outputs=times)
    reach = families.extent(flow, member.state, member.period)
    closure = np.linalg.norm(arc.end[:3] - member.state[:3]) / np.max(reach.amplitudes)
    assert closure < 1e-11
    c = cr3bp.jacobi_constant(flow.barycentric(arc.states), mu)
    assert np.max(np.abs(c - c[0])) / abs(c[0]) < 3e-15


@pytest.mark.parametrize("mu, point", [(EARTH_MOON, "L1"), (EARTH_MOON, "L2"), (EARTH_MOON, "L3"), (SUN_EARTH, "L1")])
def test_small_lyapunov_orbits_tend_to_the_linearised_period_at_second_order(mu, point):
    """T(Ax) - 2 pi / lambda = O(Ax**2): the log-log slope over Ax = 1e-3 .. 8e-3 gamma is 2 (measured 1.998 to
    2.000), and the period converges to the linear one (relative 4e-5 at Ax = 1e-3 gamma)."""
    lin = libration.linearisation(mu, point)
    sizes = np.array([1e-3, 2e-3, 4e-3, 8e-3]) * lin.gamma
    errors = []
    for ax in sizes:
        flow = shooting.Flow(mu, cr3bp.origin(mu, point))
        member = families.first_member(flow, "lyapunov", point, True, ax)[1]
        errors.append(abs(member.period * lin.planar / (2.0 * math.pi) - 1.0))
    slope = np.polyfit(np.log(sizes), np.log(errors), 1)[0]
    assert abs(slope - 2.0) < 0.01
    assert errors[0] < 1e-4


def test_richardsons_halo_is_within_its_stated_bounds_of_the_corrected_orbit():
    """Richardson's third order: his period (frequency lambda (1 + s1 Ax**2 + s2 Az**2)) differs from the corrected
    halo's through the same crossing by at most 4 A**4, A = sqrt(Ax**2 + Az**2) / gamma (measured ratio up to 3.78,
    Earth-Moon and Sun-Earth, L1 and L2, Az = 0.01 .. 0.3 gamma), the state by at most 10 A**3 (measured 9.1).
    These are bounds, not orders: Ax stays near its smallest value (0.10 to 0.18 gamma), so A cannot go to zero
    along the family (the docstring of orbits.core.periodic.libration says so)."""
    worst_period, worst_state = 0.0, 0.0
    for mu in (EARTH_MOON, SUN_EARTH):
        for point in ("L1", "L2"):
            gamma = libration.distance_to_nearer_primary(mu, point)
            for az in (0.01, 0.04, 0.16, 0.3):
                guess = libration.richardson_halo(mu, point, az * gamma)
                flow = shooting.Flow(mu, cr3bp.origin(mu, point))
                hmap = shooting.HalfPeriodMap(flow, shooting.XZ_PLANE)
                u = hmap.unknowns(flow.local(guess.states(0.0)), 0.5 * guess.period)
                member = hmap.correct(u, shooting.fixed_component(1, u[1]))
                a = math.hypot(guess.ax, az * gamma) / gamma
                worst_period = max(worst_period, abs(member.period / guess.period - 1.0) / a**4)
                state_error = np.max(np.abs(flow.barycentric(member.state) - guess.states(0.0))) / gamma
                worst_state = max(worst_state, state_error / a**3)
    assert worst_period < 4.0
    assert worst_state < 10.0


def test_richardsons_classes_bulge_to_the_side_they_are_named_for():
    for mu in (EARTH_MOON, SUN_EARTH):
        for point in ("L1", "L2"):
            for northern in (True, False):
                flow, _, member = _halo(mu, point, 0.05 * libration.distance_to_nearer_primary(mu, point), northern)
                reach = families.extent(flow, member.state, member.period)
                assert (reach.high[2] > -reach.low[2]) == northern


def test_halo_orbits_exist_about_l1_and_l2_only():
    with pytest.raises(OrbitDomainError, match="L1 and L2"):
        libration.richardson_halo(EARTH_MOON, "L3", 0.01)
    with pytest.raises(OrbitDomainError, match="not a collinear point"):
        libration.linearisation(EARTH_MOON, "L4")


def test_the_monodromy_is_symplectic_and_the_half_period_formula_is_the_full_integration():
    """M^T W M = W to 2e-16 of |M|**2 (measured 2.1e-17 for an Earth-Moon halo with |M| = 2.9e3); R Phi^-1 R Phi from
    the half period matches Phi(T) integrated to 4e-12 of |M| (measured 4.2e-13)."""
    flow, hmap, member = _halo(EARTH_MOON, "L2", 0.02)
    m = shooting.symmetric_monodromy(member.transition, hmap.symmetry.signs)
    w = cr3bp.symplectic_form()
    size = np.max(np.abs(m))
    assert np.max(np.abs(m.T @ w @ m - w)) < 2e-16 * size**2
    full = flow.arc(member.state, member.period, transition=True).end[6:].reshape(6, 6)
    assert np.max(np.abs(full - m)) < 4e-12 * size


def test_stability_indices_from_traces_are_lambda_plus_its_inverse():
    """The traces give nu = lambda + 1 / lambda of the two nontrivial pairs (the defective pair at 1 set aside):
    a saddle pair (nu = 1159) and a centre pair (nu = 2 cos theta) of an Earth-Moon halo, to 1e-9."""
    flow, hmap, member = _halo(EARTH_MOON, "L2", 0.02)
    m = shooting.symmetric_monodromy(member.transition, hmap.symmetry.signs)
    values = np.linalg.eigvals(m)
    nontrivial = values[np.argsort(np.abs(values - 1.0))][2:]
    saddle = nontrivial[np.argmax(np.abs(nontrivial))]
    centre = nontrivial[np.argmin(np.abs(np.abs(nontrivial) - 1.0))]
    expected = [(saddle + 1.0 / saddle).real, (centre + 1.0 / centre).real]
    indices = continuation.stability_indices(m)
    assert np.allclose(indices.real, expected, rtol=1e-9) and np.all(indices.imag == 0.0)
    assert continuation.tangent_bifurcation_function(m) == pytest.approx(float(((indices[0] - 2) * (indices[1] - 2))
                                                                               .real), rel=1e-9)


def test_multiple_shooting_recovers_a_symmetric_orbit_without_its_symmetry():
    """From an Earth-Moon halo's states at 6 nodes perturbed by 1e-5, held at its period: the corrected orbit has
    the halo's Jacobi constant to 1e-12 (measured 3e-15) and its monodromy (the product of the arcs') the same
    stability indices to 1e-8."""
    flow, hmap, member = _halo(EARTH_MOON, "L2", 0.02)
    nodes = flow.arc(member.state, member.period, outputs=np.linspace(0.0, member.period, 7)[:-1]).states
    rng = np.random.default_rng(3)
    shot = shooting.multiple_shooting(flow, nodes + 1e-5 * rng.normal(size=nodes.shape), member.period)
    assert shot.residual < 1e-11 * flow.origin.scale
    c = cr3bp.jacobi_constant(flow.barycentric(np.array([shot.nodes[0], member.state])), EARTH_MOON)
    assert abs(c[0] - c[1]) < 1e-12
    expected = continuation.stability_indices(shooting.symmetric_monodromy(member.transition, hmap.symmetry.signs))
    assert np.allclose(continuation.stability_indices(shot.monodromy), expected, rtol=1e-8)


def test_respacing_in_jacobi_stops_at_the_turning_point():
    """The Earth-Moon L2 halo family's Jacobi constant falls to a least value (C = 3.0157) and rises again towards
    the Moon: spacing members evenly in C across that minimum is refused at it, and short of it the members hold
    the values asked for (regula falsi to SEARCH_TOLERANCE, 1e-13 relative; measured 2.8e-14)."""
    flow = shooting.Flow(EARTH_MOON, cr3bp.origin(EARTH_MOON, "L2"))
    hmap, member, direction = families.first_member(flow, "halo", "L2", True, 0.02)

    def measure(m):
        return float(cr3bp.jacobi_constant(flow.barycentric(m.state), EARTH_MOON))

    branch = continuation.pseudo_arclength(hmap, member, direction, 0.05, 60, max_step=0.5)
    along = [measure(m) for m in branch.members]
    turn = families.turning_point(along)
    assert turn is not None and 3.0 < along[turn] < 3.03
    with pytest.raises(families.TurningPoint, match="turns back in it near 3.01"):
        families.respace(hmap, branch, branch.members[-1], 5, measure)
    before = continuation.Branch(branch.members[: turn + 1], branch.tangents[: turn + 1], None)
    spaced = families.respace(hmap, before, before.members[-1], 5, measure)
    expected = np.linspace(along[0], along[turn], 5)
    assert np.max(np.abs(np.array([measure(m) for m in spaced]) - expected)) <= 1e-13 * abs(expected[0])


def test_a_turning_point_needs_a_step_beyond_the_measures_noise():
    """Steps back smaller than FLAT of the measure (the rounding noise of a corrected member) are no turning point;
    one step back beyond it is, wherever it falls."""
    rising = np.linspace(1.0, 2.0, 9)
    assert families.turning_point(rising) is None
    noisy = rising + np.array([0, 0, 0, 0, 0, 1e-11, -1e-11, 0, 0])
    assert families.turning_point(np.concatenate([[1.0, 1.0 + 1e-12, 1.0], noisy])) is None
    assert families.turning_point(np.concatenate([rising, [1.9]])) == 8
