"""PeriodicOrbit and PeriodicFamily with units: the 9:2 NRHO against the synodic month and published figures, the
families of the Earth-Moon and Sun-Earth pairs, states in both frames, the tables and the one-line errors."""

import math

import astropy.units as u
import numpy as np
import pytest

from orbits import OrbitDomainError, PeriodicFamily, PeriodicOrbit
from orbits.core.periodic import continuation, cr3bp
from orbits.core.threebody import lagrange
from orbits.periodic.family import QUANTITY_NAMES, resonance_period, synodic_period


@pytest.fixture(scope="module")
def nrho(em):
    return PeriodicOrbit.near_rectilinear(em, resonance="9:2")


def test_the_synodic_month_of_the_catalogue_binary(em):
    """1 / (1 / T - 1 / T_year) with T = 27.2845 d (the Moon at its mean distance 384,399 km) and the Earth-Moon
    barycentre's year: 29.487 d, 0.15 % short of the observed 29.5306 d (the circular problem's Moon is faster)."""
    assert synodic_period(em).to_value(u.d) == pytest.approx(29.4872, abs=1e-4)
    assert resonance_period(em, "9:2").to_value(u.s) == pytest.approx(synodic_period(em).to_value(u.s) * 2 / 9,
                                                                      rel=1e-15)


def test_the_gateway_nrho_is_in_9_2_resonance_with_the_synodic_month(nrho, em):
    """Its period is 2/9 of the synodic month within the member search's tolerance, 1e-13 (measured 3.8e-15 and
    1.8e-15 under the AVX2 profile); perilune radius, apolune radius and period
    agree with the published round figures of the Gateway's orbit (ESA, 'Orbiting lunar Gateway', July 2019, and
    NASA: perilune about 3,200 km from the Moon's centre, apolune about 70,000 km, period about 6.56 d)."""
    assert abs(float(nrho.period / resonance_period(em, "9:2")) - 1.0) <= continuation.SEARCH_TOLERANCE
    assert nrho.closest_approaches[1].to_value(u.km) == pytest.approx(3200.0, rel=0.03)  # measured 3223.2 km
    assert nrho.farthest_from_secondary.to_value(u.km) == pytest.approx(70_000.0, rel=0.03)  # measured 71,166 km
    assert nrho.period.to_value(u.d) == pytest.approx(6.56, rel=0.003)  # measured 6.5527 d
    assert nrho.branch == "southern" and nrho.az.to_value(u.km) > 60_000  # apolune over the south pole
    assert nrho.local_state[2] > 0.0 and nrho.dimensionless_state[2] > 0.0  # starts at perilune, north of the plane


@pytest.mark.parametrize("resonance", ["4:1", "7:2", "3:1"])
def test_other_resonant_nrhos_hold_their_period_to_the_search_tolerance(em, resonance):
    """Measured 2.8e-15, 4.4e-16 and 5.6e-16."""
    orbit = PeriodicOrbit.near_rectilinear(em, resonance=resonance)
    assert abs(float(orbit.period / resonance_period(em, resonance)) - 1.0) <= continuation.SEARCH_TOLERANCE


def test_the_gateway_nrho_is_nearly_stable(nrho):
    """Its largest eigenvalue is -2.18 per period (nu = -2.64: mildly unstable, a deviation doubling every 8.4 d),
    its other pair on the unit circle (nu = 1.37); the departure scene of orbits.validate measures the first."""
    nu = nrho.stability_indices
    assert np.all(nu.imag == 0.0) and nu.real == pytest.approx([-2.6367, 1.3693], abs=1e-3)
    assert not nrho.stable
    assert nrho.e_folding_time.to_value(u.d) == pytest.approx(8.42, abs=0.01)


ORBITS = {
    "EM L1 lyapunov": ("em", "lyapunov", "L1", {"ax": 20_000 * u.km}),
    "EM L2 lyapunov": ("em", "lyapunov", "L2", {"ay": 40_000 * u.km}),
    "EM L3 lyapunov": ("em", "lyapunov", "L3", {"ax": 50_000 * u.km}),
    "EM L1 halo": ("em", "halo", "L1", {"az": 10_000 * u.km}),
    "EM L2 southern halo": ("em", "halo", "L2", {"az": 20_000 * u.km, "branch": "southern"}),
    "EM L2 vertical": ("em", "vertical", "L2", {"az": 20_000 * u.km}),
    "EM DRO": ("em", "distant_retrograde", None, {"ax": 70_000 * u.km}),
    "SE L1 lyapunov": ("se", "lyapunov", "L1", {"ax": 200_000 * u.km}),
    "SE L1 halo": ("se", "halo", "L1", {"az": 120_000 * u.km}),
    "SE L2 halo": ("se", "halo", "L2", {"period": 180 * u.d}),
    "SE L1 vertical": ("se", "vertical", "L1", {"az": 200_000 * u.km}),
    "SE DRO": ("se", "distant_retrograde", None, {"ax": 500_000 * u.km}),
}


def _build(request, key):
    pair, family, point, targets = ORBITS[key]
    system = request.getfixturevalue(pair)
    constructor = getattr(PeriodicOrbit, family)
    return constructor(system, point, **targets) if point else constructor(system, **targets)


@pytest.mark.parametrize("key", ORBITS)
def test_each_orbit_closes_keeps_its_jacobi_constant_and_hits_its_target(request, key):
    """Over one period of the orbit's own integration (states at 64 times): closure below 1e-11 of its size
    (measured at most 1.2e-12), the Jacobi constant to 3e-15 (measured 4.4e-16), and the requested quantity hit to
    4e-13 (measured 5.1e-14)."""
    orbit = _build(request, key)
    flow = orbit._flow()
    times = np.linspace(0.0, orbit.dimensionless_period, 64)
    arc = flow.arc(orbit.local_state, orbit.dimensionless_period, outputs=times)
    size = float(np.max(orbit.amplitudes.to_value(u.m))) / float(orbit.system.r)
    assert np.linalg.norm(arc.end[:3] - orbit.local_state[:3]) / size < 1e-11
    c = cr3bp.jacobi_constant(flow.barycentric(arc.states), float(orbit.system.mu))
    assert np.max(np.abs(c / orbit.dimensionless_jacobi_constant - 1.0)) < 3e-15
    name, value = orbit.request
    got = {"ax": orbit.ax, "ay": orbit.ay, "az": orbit.az, "period": orbit.period}[name]
    assert abs(float(got / value) - 1.0) < 4e-13


def test_the_stability_of_the_catalogue_families(em):
    """Lyapunov and halo orbits near their points are unstable (one large real pair), DROs stable."""
    assert not PeriodicOrbit.lyapunov(em, "L1", ax=20_000 * u.km).stable
    dro = PeriodicOrbit.distant_retrograde(em, ax=70_000 * u.km)
    assert dro.stable and math.isinf(dro.e_folding_time.value)


def test_states_repeat_with_the_period_and_turn_into_the_inertial_frame(em):
    """states(t) at t and t + 3 T agree (taken modulo the period); the inertial state is the rotating one turned by
    n t with v + n z x r added; the Jacobi constant of every state is the orbit's to 1e-14."""
    orbit = PeriodicOrbit.halo(em, "L2", az=30_000 * u.km)
    t = np.linspace(0.0, 1.0, 7) * orbit.period
    r, v = orbit.states(t)
    r3, _ = orbit.states(t + 3 * orbit.period)
    assert r.shape == (7, 3) and np.max(np.abs((r3 - r).to_value(u.km))) < 1e-6
    assert np.max(np.abs((r[-1] - orbit.position).to_value(u.km))) < 1e-6
    ri, vi = orbit.inertial_states(t)
    n = float(em.angular_velocity.to_value(u.rad / u.s))
    expected_r, expected_v = lagrange.rotating_to_inertial(r.to_value(u.m), v.to_value(u.m / u.s) / n,
                                                           n * t.to_value(u.s))
    assert np.allclose(ri.to_value(u.m), expected_r, rtol=1e-14, atol=1e-3)
    c = em.jacobi_constant(r, v)
    assert np.max(np.abs(c / orbit.jacobi_constant - 1.0)) < 1e-14


def test_nothing_is_computed_before_it_is_asked(em):
    """A corrected orbit holds its state, period and half-period transition matrix; its extent (one integration)
    and its monodromy are computed on first use."""
    orbit = PeriodicOrbit.lyapunov(em, "L1", ax=10_000 * u.km)
    assert "_extent" not in orbit.__dict__ and "monodromy" not in orbit.__dict__
    repr(orbit)
    assert "_extent" not in orbit.__dict__ and "monodromy" not in orbit.__dict__
    orbit.quantities(["period", "jacobi_constant"])
    assert "_extent" not in orbit.__dict__ and "monodromy" not in orbit.__dict__
    orbit.quantities(["stability_indices"])
    assert "monodromy" in orbit.__dict__ and "_extent" not in orbit.__dict__


def test_quantities_repr_and_html(em):
    orbit = PeriodicOrbit.halo(em, "L2", az=20_000 * u.km, branch="southern")
    table = orbit.quantities()
    assert list(table) == QUANTITY_NAMES
    assert table["stability_indices"].shape == (2, 2) and table["eigenvalues"].shape == (6, 2)
    assert table["period"].unit == u.s and table["jacobi_constant"].unit == u.m**2 / u.s**2
    assert table["richardson_period"].to_value(u.d) == pytest.approx(14.67, abs=0.01)  # corrected: 14.73 d
    assert repr(orbit) == "PeriodicOrbit(Earth-Moon L2 southern halo, Az = 20000 km, T = 14.73445 d, C = 3.140585)"
    assert "\n" not in repr(orbit) and "<table>" in orbit._repr_html_()
    dro = PeriodicOrbit.distant_retrograde(em, ax=70_000 * u.km)
    assert "e_folding_time" not in dro.quantities() and "richardson_period" not in dro.quantities()
    with pytest.raises(OrbitDomainError, match="stable orbit"):
        dro.quantities(["e_folding_time"])


def test_a_free_guess_is_corrected_by_multiple_shooting(em):
    """A halo's state a third of a period from its crossing (no symmetry there), 10 km and 1 m/s off, with its
    period: multiple shooting (8 nodes, damped Newton steps) finds the halo again, its Jacobi constant to 1e-12
    (measured 4.4e-16) and its stability indices to 1e-12 (measured 1.5e-13)."""
    halo = PeriodicOrbit.halo(em, "L2", az=20_000 * u.km, branch="southern")
    r, v = halo.states(halo.period / 3)
    orbit = PeriodicOrbit.from_state(em, r + [10.0, 0.0, 0.0] * u.km, v + [0.0, 1.0, 0.0] * u.m / u.s, halo.period)
    assert orbit.period == halo.period and orbit.origin == "L2" and orbit.family == ""
    assert abs(orbit.dimensionless_jacobi_constant - halo.dimensionless_jacobi_constant) < 1e-12
    assert np.allclose(orbit.stability_indices, halo.stability_indices, rtol=1e-12)
    assert repr(orbit).startswith("PeriodicOrbit(Earth-Moon periodic, T = 14.73")
    with pytest.raises(OrbitDomainError, match="nodes"):
        PeriodicOrbit.from_state(em, r, v, halo.period, nodes=1)


@pytest.mark.parametrize("call, fragment", [
    (lambda s: PeriodicOrbit.halo(s, "L4", az=1 * u.km), "the halo family lies about L1, L2, not L4"),
    (lambda s: PeriodicOrbit.halo(s, "L3", az=1 * u.km), "not L3"),
    (lambda s: PeriodicOrbit.halo(s, "L2", az=900_000 * u.km), "Az = 900000 km is beyond the Earth-Moon L2 "
                                                                "northern halo family: its members reach"),
    (lambda s: PeriodicOrbit.near_rectilinear(s, resonance="1:1"), "the 1:1 resonance (T = 29.48717 d) is beyond"),
    (lambda s: PeriodicOrbit.near_rectilinear(s, resonance="9-2"), "must read 'p:q'"),
    (lambda s: PeriodicOrbit.near_rectilinear(s, resonance="0:2"), "p and q must lie in [1, 1000]"),
    (lambda s: PeriodicOrbit.halo(s, "L2"), "give exactly one of az, ax, period, jacobi, closest_approach"),
    (lambda s: PeriodicOrbit.halo(s, "L2", az=1 * u.km, ax=1 * u.km), "(az, ax given)"),
    (lambda s: PeriodicOrbit.halo(s, "L2", az=-1 * u.km), "Az"),
    (lambda s: PeriodicOrbit.halo(s, "L2", az=1.0), "has no unit"),
    (lambda s: PeriodicOrbit.halo(s, "L2", az=1 * u.km, branch="eastern"), "choose from northern, southern"),
    (lambda s: PeriodicOrbit.lyapunov(s, "L6", ax=1 * u.km), "unknown point 'L6'"),
    (lambda s: PeriodicFamily.of(s, "halo", members=1), "members = 1 must be an integer in [2, 1000]"),
    (lambda s: PeriodicFamily.of(s, "spiral"), "unknown family 'spiral'"),
    (lambda s: PeriodicFamily.of(s, "halo", spacing="time"), "spacing = 'time'"),
])
def test_bad_requests_are_one_line_errors(em, call, fragment):
    with pytest.raises((OrbitDomainError, TypeError)) as caught:
        call(em)
    message = str(caught.value)
    assert fragment in message and "\n" not in message


def test_a_resonance_needs_the_primarys_own_orbit(se):
    with pytest.raises(OrbitDomainError, match="Sun orbits nothing in the catalogue"):
        PeriodicOrbit.near_rectilinear(se, resonance="2:1")


def test_a_family_runs_from_its_start_to_the_requested_member(em, nrho):
    """Ten members of the southern L2 halo family evenly spaced in arclength from its start (near the Lyapunov
    bifurcation, nu_2 = 2) to the 9:2 NRHO; their periods fall monotonically (14.83 to 6.55 d)."""
    family = PeriodicFamily.of(em, "nrho", members=10, resonance="9:2")
    assert len(family) == 10 and family.end == "the member with resonance = 9:2"
    periods = family.quantities(["period"])["period"].to_value(u.d)
    assert np.all(np.diff(periods) < 0.0) and periods[0] == pytest.approx(14.83, abs=0.01)
    assert family.members[-1].period.to_value(u.s) == pytest.approx(nrho.period.to_value(u.s), rel=1e-12)
    assert family.members[0].stability_indices[1].real == pytest.approx(2.0, abs=0.01)
    assert "bifurcations" not in family.__dict__  # found only when asked for
    assert repr(family).startswith("PeriodicFamily(Earth-Moon L2 southern near-rectilinear halo, 10 members")


def test_spacing_in_period_and_the_turning_point_in_jacobi(em):
    """Natural-parameter continuation spaces the same family evenly in period; in Jacobi constant it cannot pass
    the family's least C (3.0152) and says so."""
    family = PeriodicFamily.of(em, "nrho", members=6, spacing="period", resonance="9:2")
    periods = family.quantities(["period"])["period"].to_value(u.d)
    assert np.allclose(np.diff(periods), np.diff(periods)[0], rtol=1e-9)
    with pytest.raises(OrbitDomainError, match="cannot be spaced evenly in jacobi: it turns back in jacobi near 3.01"):
        PeriodicFamily.of(em, "nrho", members=6, spacing="jacobi", resonance="9:2")


def test_the_halo_family_branches_off_the_lyapunov_family_where_an_index_crosses_2(em):
    """The L2 Lyapunov family has a tangent bifurcation (nu = 2) at the period where the halo family starts: a halo
    of Az = 200 km has the same period to 6.5e-6 (measured 6.5e-7, the halo's period changing as Az**2)."""
    lyapunov = PeriodicFamily.of(em, "lyapunov", "L2", members=2, ax=40_000 * u.km)
    kinds = [kind for kind, _ in lyapunov.bifurcations]
    assert kinds[0] == "tangent"
    branch_point = lyapunov.bifurcations[0][1]
    halo = PeriodicOrbit.halo(em, "L2", az=200 * u.km)
    assert abs(float(branch_point.period / halo.period) - 1.0) < 6.5e-6
    assert abs(branch_point.stability_indices[1].real - 2.0) < 1e-9
