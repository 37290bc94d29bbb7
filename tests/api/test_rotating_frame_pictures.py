"""The rotating frame (issue 18, item 2): the real Earth-Moon zero-velocity curves with their forbidden regions,
a tadpole about L4 and a horseshoe through L3 integrated by heyoka (through orbits.validate.backends) and drawn in
the rotating frame, and a ring breaking up. Each picture is checked for what it draws."""

import astropy.units as u
import matplotlib
import numpy as np
import pytest

from orbits import RestrictedThreeBody
from orbits.core.errors import OrbitDomainError, UnknownNameError
from orbits.plot import coorbital_plane, lagrange_departure, lagrange_plane, ring_snapshots
from orbits.validate import backends, builders
from orbits.validate.builders import fitted_growth_rate, ring_problem

matplotlib.use("Agg")


@pytest.fixture(autouse=True)
def _close_figures():
    """Every test draws new figures; close them, or pyplot warns (an error here) past 20 open ones."""
    yield
    import matplotlib.pyplot as plt

    plt.close("all")


pytest.importorskip("heyoka")


@pytest.fixture(scope="module")
def earth_moon():
    return RestrictedThreeBody.from_primaries("Earth", "Moon")


def at_rest_on_the_unit_circle(system, degrees_from_secondary, radius=1.0, circular=False):
    """Rotating-frame state at `radius` r from the primary, `degrees_from_secondary` ahead of the secondary: at
    rest in the rotating frame, or (circular=True) on the circular two-body orbit about the primary."""
    mu, angle = float(system.mass_ratio), np.radians(degrees_from_secondary)
    r = np.array([radius * np.cos(angle) - mu, radius * np.sin(angle), 0.0]) * system.separation
    speed = np.sqrt((1 - mu) / radius) - radius if circular else 0.0  # inertial circular speed minus n r
    v = speed * np.array([-np.sin(angle), np.cos(angle), 0.0]) * (system.separation * system.angular_velocity)
    return r, v.to(u.m / u.s, u.dimensionless_angles())


def integrate_track(system, r, v, periods, outputs):
    times = np.linspace(0, periods, outputs + 1)[1:] * system.period
    result = backends.integrate("heyoka", builders.test_particle_problem(system, r, v, times))
    return system.rotating_track(result.positions)


def test_earth_moon_zero_velocity_curves_are_where_the_jacobi_constant_says(earth_moon):
    _, ax = lagrange_plane(earth_moon, points=301)
    labels = {handle.get_label() for handle in ax.get_legend().legend_handles}
    assert {"forbidden at C(L1)", "forbidden at C(L2)", "forbidden at C(L3)", "Earth (M)"} <= labels
    assert any(label.startswith("Moon (m), $\\mu$ = 0.01215") for label in labels)
    assert "384399 km" in ax.get_xlabel()
    filled, lines = ax.collections[0], ax.collections[1]
    constants = np.sort(earth_moon.jacobi_constants.to_value(u.m**2 / u.s**2)[:3])
    np.testing.assert_allclose(filled.levels[1:], constants, rtol=1e-15)  # shading bounded by C(L3), C(L2), C(L1)
    r = earth_moon.separation.to_value(u.m)
    for level, paths in zip(lines.levels, lines.get_paths()):
        xy = paths.vertices
        points = np.column_stack([xy, np.zeros(len(xy))]) * r * u.m
        drawn = -2 * earth_moon.effective_potential(points).to_value(u.J / u.kg)
        np.testing.assert_allclose(drawn, level, rtol=1e-3)  # linear interpolation on a 0.01 r grid; measured 1.4e-4


def test_a_tadpole_about_l4_stays_out_of_its_forbidden_region(earth_moon):
    """Started at rest 10 deg ahead of L4: its zero-velocity curve bounds it, it librates about L4 between about
    48 and 73 deg from the Moon, and never reaches L3 or the Moon."""
    r0, v0 = at_rest_on_the_unit_circle(earth_moon, 70.0)
    track = integrate_track(earth_moon, r0, v0, periods=60, outputs=3000)
    c0 = earth_moon.jacobi_constant(r0, v0)
    allowed = -2 * earth_moon.effective_potential(track) - c0  # = v**2 >= 0 along the motion
    # the Jacobi constant is conserved: measured min +1.2e-7 of C (the turning points fall between samples)
    assert allowed.to_value(u.m**2 / u.s**2).min() >= -1e-9 * c0.value
    mu = float(earth_moon.mass_ratio)
    scaled = track.to_value(u.m) / earth_moon.separation.to_value(u.m)
    longitude = np.degrees(np.arctan2(scaled[:, 1], scaled[:, 0] + mu))
    assert 45 < longitude.min() < 50 and 70 < longitude.max() < 75  # measured 47.9 and 73.1
    _, ax = lagrange_plane(earth_moon, trajectories={"tadpole": track}, jacobi_constants={"tadpole": c0}, points=301)
    drawn = [line for line in ax.get_lines() if line.get_gid() == "trajectory"][0]
    np.testing.assert_allclose(drawn.get_xydata(), scaled[:, :2], rtol=1e-15)
    # its own zero-velocity curve, at its own C, and the region forbidden to it instead of the C(L1..L3) shading
    own = [c for c in ax.collections if not c.filled and len(c.levels) == 1]
    assert len(own) == 1 and own[0].levels[0] == pytest.approx(c0.value, rel=1e-15)
    r = earth_moon.separation.to_value(u.m)
    for path in own[0].get_paths():
        points = np.column_stack([path.vertices, np.zeros(len(path.vertices))]) * r * u.m
        drawn_c = -2 * earth_moon.effective_potential(points).to_value(u.J / u.kg)
        np.testing.assert_allclose(drawn_c, c0.value, rtol=2e-4)  # a 0.01 r grid; measured 2.2e-5
    labels = {handle.get_label() for handle in ax.get_legend().legend_handles}
    assert "forbidden to the tadpole (its C)" in labels and "forbidden at C(L3)" not in labels
    with pytest.raises(ValueError, match="no trajectory of that label"):
        lagrange_plane(earth_moon, trajectories={"tadpole": track}, jacobi_constants={"horseshoe": c0})


def test_a_particle_leaves_l1_at_the_eigenvalue_rate(earth_moon):
    """1e-6 r off the Earth-Moon L1 along the growing mode: heyoka carries it off at the linear rate (e-folding
    1.48 d) until it is 1e-3 r away, and then round the Moon."""
    offset = 1e-6 * earth_moon.separation
    r0, v0 = earth_moon.departure_state("L1", offset)
    gap = np.linalg.norm(r0 - earth_moon.positions[0]) / offset
    assert gap.to_value(u.one) == pytest.approx(1.0, rel=6e-10)  # 384 m beside 3.2e8 m: measured 6.0e-11
    # the Jacobi constant is C(L1) to second order along the mode (the linear flow conserves it and the mode
    # grows, so its quadratic form is zero there): measured 1.1e-16
    assert earth_moon.jacobi_constant(r0, v0).value == pytest.approx(earth_moon.jacobi_constants[0].value, rel=1e-15)
    times = np.linspace(0, 30, 1501)[1:] * u.day
    result = backends.integrate("heyoka", builders.test_particle_problem(earth_moon, r0, v0, times))
    track = earth_moon.rotating_track(result.positions)
    _, (plane, distance) = lagrange_departure(earth_moon, "L1", offset, times, track)
    away = [line for line in distance.get_lines() if line.get_gid() == "trajectory"][0].get_ydata()
    rate = fitted_growth_rate(times.to_value(u.s), away, 1e-6, 1e-3)
    assert rate == pytest.approx(earth_moon.growth_rates[0].to_value(1 / u.s), rel=1.7e-3)  # measured 1.7e-4
    assert away.max() > 0.1 and "[d]" in distance.get_xlabel() and distance.get_yscale() == "log"
    x0, x1 = plane.get_xlim()
    assert x0 < earth_moon.positions[0, 0] / earth_moon.separation < x1 and x1 - x0 < 0.5  # framed on L1
    with pytest.raises(OrbitDomainError, match="L4 is linearly stable"):
        earth_moon.departure_state("L4")
    with pytest.raises(OrbitDomainError, match="at most 0.01 r"):
        earth_moon.departure_state("L1", 0.1 * earth_moon.separation)
    with pytest.raises(UnknownNameError, match="unknown point 'L6'"):
        earth_moon.departure_state("L6")


def test_a_horseshoe_of_the_sun_and_earth_goes_round_through_l3():
    sun_earth = RestrictedThreeBody.from_primaries("Sun", "Earth", 1 * u.AU)
    r0, v0 = at_rest_on_the_unit_circle(sun_earth, 180.0, radius=1.004, circular=True)
    track = integrate_track(sun_earth, r0, v0, periods=400, outputs=4000)
    _, ax = coorbital_plane(sun_earth, {"horseshoe": track})
    longitude, offset = ax.get_lines()[0].get_xydata().T
    shown = np.isfinite(longitude)
    assert longitude[shown].min() < -179 and longitude[shown].max() > 179  # it passes L3
    assert 10 < np.abs(longitude[shown]).min() < 16  # and turns back before the Earth; measured 12.8 deg
    assert 0.004 < np.nanmax(np.abs(offset)) < 0.006  # measured 0.0049 r
    assert ax.get_xlim() == (-180, 180) and "longitude" in ax.get_xlabel()


def test_ring_snapshots_mark_the_breakup_level_and_show_the_ring_in_its_own_frame():
    _, probe = ring_problem(5, [1.0])
    times = np.linspace(0, 1.5 * probe.breakup_time, 300)[1:]
    problem, expected = ring_problem(5, times)
    result = backends.integrate("heyoka", problem)
    fig, axes = ring_snapshots(result.times, result.positions, expected.growth_rate, expected.breakup_time)
    level = [line for line in axes[0].get_lines() if line.get_gid() == "break-up level"][0]
    assert tuple(level.get_ydata()) == (1e-3, 1e-3)
    first = [line for line in axes[1].get_lines() if line.get_gid() == "bodies"][0].get_xydata()
    angles = np.sort(np.mod(np.degrees(np.arctan2(first[:, 1], first[:, 0])), 360))
    np.testing.assert_allclose(angles, [0, 72, 144, 216, 288], atol=1e-9)  # the regular pentagon it starts as
    marks = [line.get_xdata()[0] for line in axes[0].get_lines() if line.get_gid() == "snapshot"]
    np.testing.assert_allclose(marks[1], expected.breakup_time / (2 * np.pi), rtol=0.01)  # nearest output, periods
    last = [line for line in axes[-1].get_lines() if line.get_gid() == "bodies"][0].get_xydata()
    assert np.abs(np.hypot(*last.T) - 1).max() > 0.05  # broken up by 1.5 break-up times
