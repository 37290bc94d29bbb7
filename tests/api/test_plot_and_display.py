"""Pictures are tested for what they draw; notebook display for what it shows."""

import astropy.units as u
import matplotlib
import numpy as np
import pytest

from orbits import Orbit, scene
from orbits.plot import orbit_plane, save, validation_residuals
from orbits.validate.run import validate

matplotlib.use("Agg")


def labels(ax):
    return {line.get_label() for line in ax.get_lines()}


def test_ellipse_in_its_plane_marks_foci_apsides_and_positions():
    orbit = Orbit.from_elements("Sun", a=1 * u.AU, e=0.6, nu=40 * u.deg)
    fig, ax = orbit_plane(orbit, times=[30, 60] * u.day)
    assert {"star (focus)", "periapsis", "apoapsis", "centre", "empty focus", "body now",
            "body at given times"} <= labels(ax)
    assert "[AU]" in ax.get_xlabel() and "[AU]" in ax.get_ylabel()
    curve = ax.get_lines()[0].get_xydata()
    assert curve[:, 0].max() == pytest.approx(0.4, rel=1e-9)  # periapsis q = a (1 - e) on +x
    assert curve[:, 0].min() == pytest.approx(-1.6, rel=1e-9)  # apoapsis at -a (1 + e)
    apo = [line for line in ax.get_lines() if line.get_label() == "apoapsis"][0].get_xydata()[0]
    assert tuple(apo) == pytest.approx((-1.6, 0.0))
    later = [line for line in ax.get_lines() if line.get_label() == "body at given times"][0].get_xydata()
    radii = np.hypot(later[:, 0], later[:, 1])
    expected = [orbit.at(t).radius.to_value(u.AU) for t in [30, 60] * u.day]
    np.testing.assert_allclose(radii, expected, rtol=1e-12)


def test_hyperbola_is_drawn_around_the_encounter_in_km():
    flyby = Orbit.from_elements("Earth", q=7000 * u.km, e=1.8, nu=-60 * u.deg)
    _, ax = orbit_plane(flyby)
    assert "[km]" in ax.get_xlabel() and "apoapsis" not in labels(ax)
    curve = ax.get_lines()[0].get_xydata()
    assert np.max(np.hypot(curve[:, 0], curve[:, 1])) == pytest.approx(70000, rel=1e-6)  # 10 q


def test_orbit_plane_refuses_arrays_of_orbits():
    with pytest.raises(ValueError, match="index it first"):
        orbit_plane(Orbit.from_elements("Earth", a=[7000, 8000] * u.km, e=0.1))


def test_validation_residuals_one_line_per_scene_and_backend(tmp_path):
    report = validate([scene.load("circular"), scene.load("flyby")])
    fig, ax = validation_residuals(report)
    assert labels(ax) == {"circular: rebound", "circular: heyoka", "flyby: rebound", "flyby: heyoka"}
    assert ax.get_yscale() == "log" and "dimensionless" in ax.get_ylabel()
    top = max(np.nanmax(line.get_ydata()) for line in ax.get_lines())
    assert 0 < top < 1e-10
    for suffix in ("png", "svg", "pdf"):
        save(fig, tmp_path / f"r.{suffix}")
        assert (tmp_path / f"r.{suffix}").stat().st_size > 1000
    with pytest.raises(ValueError, match=".png, .svg or .pdf"):
        save(fig, tmp_path / "r.gif")


def test_html_and_text_display():
    orbit = Orbit.from_elements("Earth", a=7000 * u.km, e=0.1)
    assert repr(orbit) == "Orbit(6300 x 7700 km, e = 0.1, i = 0 deg, about Earth)"  # q x Q, natural units
    page = orbit._repr_html_()
    assert "<table>" in page and "period" in page and "<td style='text-align:left'>min</td>" in page
    many = Orbit.from_elements("Earth", a=[7000, 8000] * u.km, e=0.1)
    assert repr(many) == "Orbit(2 orbits, 6300..7200 x 7700..8800 km, e = 0.1, i = 0 deg, about Earth)"
    report = validate([scene.load("flyby")], ("rebound",))
    assert "flyby" in report._repr_html_() and "all checks passed" in report._repr_html_()
    assert repr(report) == "ValidationReport(1 scenes: flyby; passed)"


def test_flyby_plane_draws_asymptotes_and_the_impact_parameter():
    from orbits import Flyby
    from orbits.plot import flyby_plane

    flyby = Flyby.past("Jupiter", v_inf=5.6 * u.km / u.s, periapsis=200_000 * u.km)
    _, ax = flyby_plane(flyby)
    lines = {line.get_label(): line.get_xydata() for line in ax.get_lines()}
    assert {"incoming asymptote", "outgoing asymptote", "primary (focus)"} <= set(lines)
    segment = [xy for name, xy in lines.items() if name.startswith("impact parameter")][0]
    assert np.hypot(*segment[1]) == pytest.approx(flyby.impact_parameter.to_value(u.km), rel=1e-12)
    incoming = lines["incoming asymptote"]
    direction = incoming[1] - incoming[0]
    foot = segment[1]
    assert abs(np.dot(direction, foot)) < 1e-9 * np.linalg.norm(direction) * np.linalg.norm(foot)  # b is perpendicular
    assert "144.66 deg" in ax.get_title()
    closest = [xy for name, xy in lines.items() if name.startswith("closest approach")][0]
    assert closest[0, 0] == pytest.approx(200_000, rel=1e-12)


def test_binary_plane_keeps_the_centre_of_mass_on_the_joining_line():
    from orbits import Binary
    from orbits.plot import binary_plane

    _, ax = binary_plane(Binary.from_elements(1 * u.solMass, 0.5 * u.solMass, a=1 * u.AU, e=0.5, nu=60 * u.deg))
    lines = {line.get_label(): line.get_xydata() for line in ax.get_lines()}
    join = lines["joining line"]
    # masses 1 : 0.5, so star 1 is twice as close to the centre of mass as star 2, on the other side
    np.testing.assert_allclose(join[1], -2 * join[0], rtol=1e-12)
    star1, star2 = lines["star 1 orbit"], lines["star 2 orbit"]
    assert np.ptp(star2[:, 0]) == pytest.approx(2 * np.ptp(star1[:, 0]), rel=1e-12)
    assert np.ptp(star1[:, 0]) + np.ptp(star2[:, 0]) == pytest.approx(2.0, rel=1e-9)  # 2 a of the relative orbit


def test_scale_factor_curves_reach_one_at_the_age():
    from orbits import Cosmology
    from orbits.plot import scale_factor_curves

    eds = Cosmology.einstein_de_sitter(70 * u.km / u.s / u.Mpc)
    _, ax = scale_factor_curves({"EdS": eds}, 20 * u.Gyr)
    t, a = ax.get_lines()[0].get_xydata().T
    assert np.interp(1.0, a, t) == pytest.approx(eds.age().to_value(u.Gyr), rel=1e-3)
    assert "Gyr" in ax.get_xlabel()


def test_lagrange_plane_marks_the_five_points_and_the_zero_velocity_curves():
    from orbits import RestrictedThreeBody
    from orbits.plot import lagrange_plane

    system = RestrictedThreeBody.from_primaries(0.9 * u.kg, 0.1 * u.kg, 1 * u.m)
    _, ax = lagrange_plane(system, points=201)
    texts = sorted(t.get_text() for t in ax.texts if t.get_text().startswith("L"))
    assert texts == ["L1", "L2", "L3", "L4", "L5"]
    marks = [line for line in ax.get_lines() if line.get_marker() == "x"]
    xs = sorted(float(m.get_xdata()[0]) for m in marks)
    assert xs[2] == pytest.approx(0.5 - 0.1, rel=1e-12)  # L4, L5 at x = 1/2 - mu
    assert len(ax.collections) >= 1 and "separation r" in ax.get_xlabel()


def test_ring_breakup_draws_the_prediction_through_the_seed():
    from orbits.plot import ring_breakup

    times = np.linspace(0, 40, 50)
    _, ax = ring_breakup(times, 1e-16 * np.exp(times), 1.0, 29.9)
    prediction = [line for line in ax.get_lines() if line.get_label().startswith("round-off")][0]
    np.testing.assert_allclose(prediction.get_ydata(), 1e-16 * np.exp(times), rtol=1e-12)
    assert ax.get_yscale() == "log" and any("29.9" in line.get_label() for line in ax.get_lines())
