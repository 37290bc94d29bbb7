"""Pictures are tested for what they draw; notebook display for what it shows."""

import astropy.units as u
import matplotlib
import numpy as np
import pytest
from astropy.time import Time
from picture_checks import problems

import orbits
from orbits import Orbit
from orbits._common import display
from orbits.plot import orbit_plane, save, validation_residuals
from orbits.validate import scene
from orbits.validate.run import validate

matplotlib.use("Agg")


@pytest.fixture(autouse=True)
def _close_figures():
    """Every test draws new figures; close them, or pyplot warns (an error here) past 20 open ones."""
    yield
    import matplotlib.pyplot as plt

    plt.close("all")


def labels(ax):
    return {line.get_label() for line in ax.get_lines()}


def test_ellipse_in_its_plane_marks_foci_apsides_and_positions():
    orbit = Orbit.from_elements("Sun", a=1 * u.AU, e=0.6, nu=40 * u.deg)
    fig, ax = orbit_plane(orbit, times=[30, 60] * u.day)
    assert {"periapsis", "apoapsis", "centre", "empty focus", "body at t0", "body 30..60 d later"} <= labels(ax)
    assert any(label.startswith("Sun (not to scale") for label in labels(ax))  # named, not "star (focus)"
    assert "[AU]" in ax.get_xlabel() and "[AU]" in ax.get_ylabel()
    curve = ax.get_lines()[0].get_xydata()
    assert curve[:, 0].max() == pytest.approx(0.4, rel=1e-9)  # periapsis q = a (1 - e) on +x
    assert curve[:, 0].min() == pytest.approx(-1.6, rel=1e-9)  # apoapsis at -a (1 + e)
    apo = [line for line in ax.get_lines() if line.get_gid() == "apoapsis"][0].get_xydata()[0]
    assert tuple(apo) == pytest.approx((-1.6, 0.0))
    later = _by_gid(ax, "later")[0].get_xydata()
    radii = np.hypot(later[:, 0], later[:, 1])
    expected = [orbit.at(t).radius.to_value(u.AU) for t in [30, 60] * u.day]
    np.testing.assert_allclose(radii, expected, rtol=1e-12)


def test_hyperbola_is_drawn_around_the_encounter_in_km():
    flyby = Orbit.from_elements("Earth", q=7000 * u.km, e=1.8, nu=-60 * u.deg)
    _, ax = orbit_plane(flyby)
    assert "[km]" in ax.get_xlabel() and "apoapsis" not in labels(ax)
    curve = ax.get_lines()[0].get_xydata()
    assert np.max(np.hypot(curve[:, 0], curve[:, 1])) == pytest.approx(70000, rel=1e-6)  # 10 q


def test_orbit_plane_of_a_circle_a_comet_and_an_orbit_inside_its_primary():
    """No apsides, centre or empty focus on a circle; a near-parabolic comet is drawn out to 10 q, not as a line a
    million AU long; a periapsis inside the Earth warns and says so in the title; the Earth drawn to scale."""
    from orbits.plot import InsideBodyWarning

    _, ax = orbit_plane(Orbit.from_elements("Earth", a=42164 * u.km, e=0.0))
    assert not {"periapsis", "apoapsis", "centre", "empty focus"} & labels(ax)
    assert any(p.get_label() == "Earth (to scale)" for p in ax.patches)
    _, ax = orbit_plane(Orbit.from_elements("Sun", q=0.5 * u.AU, e=0.999999))
    track = ax.get_lines()[0].get_xydata()
    assert np.max(np.hypot(track[:, 0], track[:, 1])) == pytest.approx(5.0, rel=1e-6)  # 10 q, in AU
    with pytest.warns(orbits.InsideBodyWarning, match="closest approach 6000 km is inside the Earth"):
        inside = Orbit.from_elements("Earth", q=6000 * u.km, e=0.5)  # the orbit says it too, once, when built
    with pytest.warns(InsideBodyWarning, match="closest approach 6000 km is inside Earth"):
        _, ax = orbit_plane(inside)
    assert "inside Earth" in ax.get_title()


def test_orbit_plane_draws_an_open_orbit_out_to_the_body_at_the_given_times():
    """q = 7000 km, e = 1.5: after 6 h the body is 140,000 km out, twice the default 10 q window; the arc runs past
    it (to 1.05 times its distance), so every dot sits on a drawn part of the conic."""
    _, ax = orbit_plane(Orbit.from_elements("Earth", q=7000 * u.km, e=1.5), times=[3, 6] * u.h)
    lines = {line.get_label(): line.get_xydata() for line in ax.get_lines()}
    reach = np.hypot(*lines["orbit, e = 1.5"].T).max()
    furthest = np.hypot(*lines["body 3..6 h later"].T).max()
    assert furthest == pytest.approx(140.246, rel=1e-5) and "$10^{3}$ km" in ax.get_xlabel()
    assert 1.0 < reach / furthest <= 1.05 + 1e-12  # measured 1.05


def test_orbit_plane_refuses_arrays_of_orbits():
    with pytest.raises(ValueError, match="index it first"):
        orbit_plane(Orbit.from_elements("Earth", a=[8000, 9000] * u.km, e=0.1))


@pytest.fixture(scope="module")
def validated():
    """Four scenes through both integrators: two of 100 whole orbits, a flyby, the expanding sphere."""
    from orbits.validate import load

    return validate([load(name) for name in ("circular", "eccentric", "flyby", "expanding_universe")])


def test_validation_residuals_count_time_in_each_scenes_own_period(validated, tmp_path):
    fig, axes = validation_residuals(validated)
    closed, passages = axes
    assert labels(closed) == {f"{name}: {b}" for name in ("circular", "eccentric") for b in ("rebound", "heyoka")}
    assert labels(passages) == {f"{name}: {b}" for name in ("flyby", "expanding_universe")
                                for b in ("rebound", "heyoka")}
    assert closed.get_xscale() == "log" and closed.get_yscale() == "log" and "dimensionless" in closed.get_ylabel()
    for name in ("circular", "eccentric"):  # both scenes run 100 periods of their own orbit (a = 1 AU, r = 7000 km)
        line = [line for line in closed.get_lines() if line.get_label() == f"{name}: rebound"][0]
        assert line.get_xdata()[-1] == pytest.approx(100, rel=1e-13)  # measured 0 and 1.4e-16
    assert "periods" in closed.get_xlabel() and "fraction of the run" in passages.get_xlabel()
    flyby = [line for line in passages.get_lines() if line.get_label() == "flyby: heyoka"][0]
    assert flyby.get_xdata()[-1] == 1.0 and flyby.get_xdata()[0] == pytest.approx(1 / 200)
    top = max(np.nanmax(line.get_ydata()) for ax in axes for line in ax.get_lines())
    assert 0 < top < 3e-10  # measured 3.0e-11 (eccentric, heyoka)
    fig.canvas.draw()
    for ax in axes:  # each legend lies below its panel, off the data
        assert ax.get_legend().get_window_extent().y1 <= ax.get_window_extent().y0
    for suffix in ("png", "svg", "pdf"):
        save(fig, tmp_path / f"r.{suffix}")
        assert (tmp_path / f"r.{suffix}").stat().st_size > 1000
    with pytest.raises(ValueError, match=".png, .svg or .pdf"):
        save(fig, tmp_path / "r.gif")


def test_validation_overview_of_scenes_without_predicted_positions_draws_each_check_against_its_tolerance():
    from orbits.plot import validation_overview
    from orbits.validate import load

    report = validate([load("ring_3")])  # a ring checks its break-up, not positions
    fig, panels = validation_overview(report)
    (only,) = panels
    checks = report.scenes[0].checks
    assert [label.get_text() for label in only.get_yticklabels()] == [check.quantity for check in checks]
    assert only.get_xscale() == "log" and "ring_3" in only.get_title()
    for line in only.get_lines()[:2]:  # one marker a check for each backend, at its error / tolerance
        backend = line.get_label()
        assert list(line.get_xdata()) == pytest.approx(
            [max(check.errors[backend] / check.tolerance, 1e-6) for check in checks])
    assert problems(fig) == []


def test_validation_json_says_in_which_unit_its_times_are(validated):
    """A data scene's residual times and period are in seconds, a model scene's in G = 1 code time units."""
    from orbits._common.constants import BODIES

    scenes = {scene["name"]: scene for scene in validated.to_dict()["scenes"]}
    circular, sphere = scenes["circular"], scenes["expanding_universe"]
    assert circular["time_unit"] == "s" and sphere["time_unit"].startswith("code time unit")
    period = 2 * np.pi * np.sqrt(7e6**3 / BODIES["Earth"].gm)  # a test particle on a 7000 km circle about the Earth
    assert circular["period"] == pytest.approx(period, rel=1e-15) and sphere["period"] is None
    assert circular["residual_times"][-1] == pytest.approx(100 * period, rel=1e-15)  # 100 periods


def test_validation_tracks_draw_the_integrations_on_the_closed_form(validated):
    from orbits.plot import validation_tracks

    _, panels = validation_tracks(validated)
    assert [ax.get_title().split("\n")[0] for ax in panels] == ["circular", "eccentric", "flyby",
                                                                  "expanding_universe"]
    circular, eccentric, flyby, _ = panels
    curve = next(line for line in circular.get_lines() if line.get_label() == "closed form").get_xydata()
    assert np.hypot(*curve.T) == pytest.approx(7000.0, rel=1e-13)  # the 7000 km circle face on, in km: 3.2e-15
    ellipse = next(line for line in eccentric.get_lines() if line.get_label() == "closed form").get_xydata()
    distance = np.hypot(*ellipse.T)  # from the Sun: sampled evenly in E, the curve reaches both apsides
    assert (distance.min(), distance.max()) == pytest.approx((0.1, 1.9), rel=2e-14)  # measured 9.7e-16, 2.3e-15
    assert "[AU]" in eccentric.get_xlabel() and "[km]" in circular.get_xlabel()
    for ax, name in ((circular, "circular"), (flyby, "flyby")):
        outputs = next(line for line in ax.get_lines() if line.get_label() == "closed form at the outputs")
        size = np.abs(outputs.get_xydata()).max()
        for backend in ("rebound", "heyoka"):
            marks = next(line for line in ax.get_lines() if line.get_gid() == f"integrated {backend}")
            np.testing.assert_allclose(marks.get_xydata(), outputs.get_xydata(), rtol=0, atol=1e-10 * size)
        worst = {s.name: s for s in validated.scenes}[name].residuals
        assert f"heyoka {display.number_math(np.max(worst['heyoka']), 2)}" in ax.get_title()
    (legend,) = panels[0].figure.legends  # four panels fill the row: the legend goes below
    assert [text.get_text() for text in legend.get_texts()] == [
        "closed form", "closed form at the outputs", "rebound", "heyoka", "first body (the origin)"]


def test_html_and_text_display():
    orbit = Orbit.from_elements("Earth", a=8000 * u.km, e=0.1)
    assert repr(orbit) == "Orbit(7200 x 8800 km, e = 0.1, i = 0 deg, about Earth)"  # q x Q, natural units
    page = orbit._repr_html_()
    assert "<table>" in page and "period" in page and "<td style='text-align:left'>min</td>" in page
    many = Orbit.from_elements("Earth", a=[8000, 9000] * u.km, e=0.1)
    assert repr(many) == "Orbit(2 orbits, 7200..8100 x 8800..9900 km, e = 0.1, i = 0 deg, about Earth)"
    report = validate([scene.load("flyby")], ("rebound",))
    assert "flyby" in report._repr_html_() and "all checks passed" in report._repr_html_()
    assert repr(report) == "ValidationReport(1 scenes: flyby; passed)"


def test_flyby_plane_draws_asymptotes_and_the_impact_parameter():
    from orbits import Flyby
    from orbits.plot import flyby_plane

    flyby = Flyby.past("Jupiter", v_inf=5.6 * u.km / u.s, periapsis=200_000 * u.km)
    _, ax = flyby_plane(flyby)
    lines = {line.get_label(): line.get_xydata() for line in ax.get_lines()}
    assert {"incoming asymptote", "outgoing asymptote"} <= set(lines)
    assert ax.get_xlabel() == "x toward closest approach [$10^{6}$ km]"  # not km with an offset "1e6" on the axis
    jupiter = [patch for patch in ax.patches if patch.get_label() == "Jupiter (to scale)"][0]
    assert jupiter.get_radius() == pytest.approx(71492e-6, rel=1e-12)  # the primary drawn to scale
    segment = [xy for name, xy in lines.items() if name.startswith("impact parameter")][0]
    assert np.hypot(*segment[1]) == pytest.approx(flyby.impact_parameter.to_value(u.km) * 1e-6, rel=1e-12)
    incoming = lines["incoming asymptote"]
    direction = incoming[1] - incoming[0]
    foot = segment[1]
    assert abs(np.dot(direction, foot)) < 1e-9 * np.linalg.norm(direction) * np.linalg.norm(foot)  # b is perpendicular
    assert "144.66 deg" in ax.get_title()
    closest = [xy for name, xy in lines.items() if name.startswith("closest approach")][0]
    assert closest[0, 0] == pytest.approx(200_000e-6, rel=1e-12)


def test_binary_plane_keeps_the_centre_of_mass_on_the_joining_line():
    from orbits import Binary
    from orbits.plot import binary_plane

    _, ax = binary_plane(Binary.from_elements(1 * u.solMass, 0.5 * u.solMass, a=1 * u.AU, e=0.5, nu=60 * u.deg))
    lines = {line.get_label(): line.get_xydata() for line in ax.get_lines()}
    join = _by_gid(ax, "joining line")[0].get_xydata()
    # masses 1 : 0.5, so star 1 is twice as close to the centre of mass as star 2, on the other side
    np.testing.assert_allclose(join[1], -2 * join[0], rtol=2e-15)  # measured 2.2e-16
    star1, star2 = lines[r"star 1 (1 M$_\odot$)"], lines[r"star 2 (0.5 M$_\odot$)"]
    assert "the line joining the stars (dots) at t0, $\\nu$ = 60 deg" in lines
    assert np.ptp(star2[:, 0]) == pytest.approx(2 * np.ptp(star1[:, 0]), rel=2e-15)  # measured 2.2e-16
    assert np.ptp(star1[:, 0]) + np.ptp(star2[:, 0]) == pytest.approx(2.0, rel=2e-15)  # 2 a of the relative orbit: 0
    ax.figure.canvas.draw()
    assert ax.get_legend().get_window_extent().y1 <= ax.get_window_extent().y0  # the legend below, off the data


def test_scale_factor_curves_reach_one_at_the_age():
    from orbits import Cosmology
    from orbits.plot import scale_factor_curves

    eds = Cosmology.einstein_de_sitter(70 * u.km / u.s / u.Mpc)
    _, ax = scale_factor_curves({"EdS": eds}, 20 * u.Gyr)
    t, a = ax.get_lines()[0].get_xydata().T
    assert np.interp(1.0, a, t) == pytest.approx(eds.age().to_value(u.Gyr), rel=8e-6)  # 400 points: measured 8.3e-7
    assert "Gyr" in ax.get_xlabel()


def test_lagrange_plane_marks_the_five_points_and_the_zero_velocity_curves():
    from orbits import RestrictedThreeBody
    from orbits.plot import lagrange_plane

    system = RestrictedThreeBody.from_primaries(0.9 * u.kg, 0.1 * u.kg, 1 * u.m)
    _, ax = lagrange_plane(system, points=201)
    texts = sorted(t.get_text() for t in ax.texts if t.get_text().startswith("L"))
    assert texts == ["L1", "L2", "L3", "L4", "L5"]
    xs = sorted(_by_gid(ax, "Lagrange points")[0].get_xdata())
    assert xs[2] == pytest.approx(0.5 - 0.1, rel=1e-12)  # L4, L5 at x = 1/2 - mu
    assert len(ax.collections) >= 1 and "separation r" in ax.get_xlabel()


def test_ring_breakup_draws_the_prediction_through_the_seed():
    from orbits.plot import ring_breakup

    times = np.linspace(0, 40, 50)  # in 1 / omega
    fig, ax = ring_breakup(times, 1e-16 * np.exp(times), 1.0, 29.9, period=2 * u.d)
    prediction = [line for line in ax.get_lines() if line.get_label().startswith("round-off")][0]
    np.testing.assert_allclose(prediction.get_ydata(), 1e-16 * np.exp(times), rtol=1e-15)
    np.testing.assert_allclose(prediction.get_xdata(), times / (2 * np.pi), rtol=1e-15)  # in ring periods
    assert prediction.get_label() == r"round-off $\times$ exp(t / 0.159 periods)"  # 1 / (2 pi) periods
    breakup = [line for line in ax.get_lines() if line.get_label().startswith("predicted break-up")][0]
    assert breakup.get_label() == "predicted break-up, 4.76 periods" and breakup.get_xdata()[0] == 29.9 / (2 * np.pi)
    assert ax.get_yscale() == "log" and ax.get_xlabel() == r"time [ring periods $2\pi/\omega$, 1 period = 2 d]"
    fig.canvas.draw()
    legend, label = ax.get_legend().get_window_extent(), ax.xaxis.label.get_window_extent()
    assert legend.y1 <= label.y0 and len(ax.get_legend().get_texts()) == 4  # below the axes and their label


def test_scale_factor_runs_through_turnaround_to_the_big_crunch():
    from orbits import Cosmology
    from orbits.plot import scale_factor_curves

    closed = Cosmology.from_densities(70 * u.km / u.s / u.Mpc, Om0=2.0, Ok0=-1.0)
    _, ax = scale_factor_curves({"closed": closed}, 200 * u.Gyr)
    lines = {line.get_label(): line.get_xydata() for line in ax.get_lines()}
    t, a = lines["closed"].T
    crunch = closed.big_crunch_time.to_value(u.Gyr)
    assert t[-1] == pytest.approx(crunch, rel=1e-12) and a[-1] == 0 and a[0] == 0
    assert a.max() == pytest.approx(2.0, rel=3e-5)  # a_max = Om / (Om - 1); 400 points: 3.9e-6
    turnaround = lines["closed: turnaround, t = 43.88 Gyr"]  # half the crunch time, 87.77 Gyr
    assert tuple(turnaround[0]) == pytest.approx((crunch / 2, 2.0), rel=1e-12)
    assert lines["closed: big crunch, t = 87.77 Gyr"][0, 0] == pytest.approx(crunch)


def test_scale_factor_curves_tell_models_apart():
    """Planck 2018 and a flat Om = 0.31 model nearly coincide: different line styles keep both visible; a log
    axis shows a Lambda universe's exponential growth beside a closed one's crunch, each marker named."""
    from orbits import Cosmology
    from orbits.plot import scale_factor_curves

    h0 = 67.66 * u.km / u.s / u.Mpc
    models = {"flat": Cosmology.from_densities(h0, Om0=0.31, Ol0=0.69), "planck18": Cosmology.planck18(),
              "closed": Cosmology.from_densities(h0, Om0=3.0, Ol0=0.0)}
    _, ax = scale_factor_curves(models, 100 * u.Gyr, log=True)
    drawn = {line.get_label(): line for line in ax.get_lines()}
    assert [drawn[name].get_linestyle() for name in models] == ["-", "--", "-."]
    assert len({drawn[name].get_color() for name in models}) == 3
    assert ax.get_yscale() == "log" and ax.get_ylim()[0] == 1e-2
    assert drawn["planck18"].get_ydata()[-1] > 100  # exp(H0 sqrt(Ol) t): about 400 at 100 Gyr
    assert sum(name.startswith("closed: ") for name in drawn) == 2 and not any(
        name.startswith(("flat: ", "planck18: ")) for name in drawn)  # only the closed model turns round
    assert ax.get_legend().get_bbox_to_anchor().y0 < ax.bbox.y0  # legend below the axes, off the data


def test_hubble_diagram_draws_the_distance_modulus():
    from orbits import Cosmology
    from orbits.plot import cosmology_overview, hubble_diagram

    planck = Cosmology.planck18()
    _, ax = hubble_diagram({"Planck 2018": planck}, z_max=3.0)
    z, mu = ax.get_lines()[0].get_xydata().T
    np.testing.assert_allclose(mu, planck.distance_modulus(z).value, rtol=1e-15)
    assert z[-1] == pytest.approx(3.0) and ax.get_xscale() == "log"
    assert mu[np.argmin(np.abs(z - 1))] == pytest.approx(44.16, abs=0.01)  # D_L(1) = 6797 Mpc
    fig, axes = cosmology_overview(planck, "Planck 2018")
    labels_middle = [line.get_label() for line in axes[1].get_lines()]
    assert labels_middle == ["luminosity distance $D_L$", "transverse comoving distance $D_M$",
                             "angular-diameter distance $D_A$"]
    z, d_a = axes[1].get_lines()[2].get_xydata().T
    assert 1.4 < z[np.argmax(d_a)] < 1.8  # D_A peaks near z = 1.6 in Planck 2018
    # the model is drawn last, thick and black, and a reference identical to it is not drawn under it
    hubble = axes[2].get_lines()
    assert [line.get_label() for line in hubble] == ["Einstein-de Sitter, same $H_0$",
                                                     "this universe = Planck 2018 (flat, no radiation)"]
    assert hubble[-1].get_color() == "k" and hubble[-1].get_linewidth() > hubble[0].get_linewidth()
    _, axes = cosmology_overview(Cosmology.from_densities(70 * u.km / u.s / u.Mpc, Om0=0.3, Ol0=0.7), "other")
    assert len(axes[2].get_lines()) == 3 and axes[2].get_lines()[-1].get_label() == "this universe"
    _, axes = cosmology_overview(Cosmology.de_sitter(70 * u.km / u.s / u.Mpc), "de Sitter")  # no big bang
    assert axes[0].get_xlabel() == "time from today [Gyr]" and axes[0].get_yscale() == "log"


# ---- several orbits in one frame (issue 18, item 1) ----------------------------------------------------------


def _by_gid(ax, gid):
    return [line for line in ax.get_lines() if line.get_gid() == gid]


def test_orbits_overlay_in_one_frame_with_distinct_colours_and_the_primary_to_scale():
    from orbits.plot import orbits

    geo = Orbit.circular("Earth", 42164 * u.km)
    molniya = Orbit.from_elements("Earth", a=26600 * u.km, e=0.74, inc=63.4 * u.deg, argp=270 * u.deg)
    gto = Orbit.from_elements("Earth", q=6678 * u.km, e=0.73, raan=30 * u.deg)
    fig, ax = orbits(geo, molniya, gto, labels=["GEO", "Molniya", "GTO"])
    curves = {line.get_label(): line for line in ax.get_lines() if line.get_label() in ("GEO", "Molniya", "GTO")}
    assert len({line.get_color() for line in curves.values()}) == 3
    earth = [patch for patch in ax.patches if patch.get_label() == "Earth (to scale)"][0]
    assert earth.get_radius() == pytest.approx(6378.1, rel=1e-12)  # km, IAU 2015 nominal equatorial radius
    # apsides only where they mean something: none in GEO's colour, Q = a (1 + e) of GTO in its plane
    colours = {line.get_color() for line in _by_gid(ax, "periapsis") + _by_gid(ax, "apoapsis")}
    assert curves["GEO"].get_color() not in colours and len(_by_gid(ax, "apoapsis")) == 2
    gto_apo = [line for line in _by_gid(ax, "apoapsis") if line.get_color() == curves["GTO"].get_color()][0]
    assert np.hypot(*gto_apo.get_xydata()[0]) == pytest.approx(6678 / 0.27 * 1.73, rel=1e-12)
    np.testing.assert_allclose(np.hypot(*curves["GEO"].get_xydata().T), 42164, rtol=1e-12)
    legend = ax.get_legend()
    fig.canvas.draw()
    assert legend.get_window_extent().x0 >= ax.get_window_extent().x1  # the legend is off the data


@pytest.mark.parametrize("projection, drop", [("xz", 1), ("yz", 0)])
def test_orbits_projections_show_the_inclination(projection, drop):
    from orbits.plot import orbits

    polar = Orbit.circular("Earth", 7000 * u.km, inc=90 * u.deg, raan=90 * u.deg if drop == 0 else 0 * u.deg)
    _, ax = orbits(polar, projection=projection)
    track = ax.get_lines()[0].get_xydata()
    np.testing.assert_allclose(np.hypot(*track.T), 7000, rtol=1e-12)  # the orbit's own plane, seen face on
    assert ax.get_xlabel().startswith(projection[0]) and ax.get_ylabel().startswith(projection[1])


def test_orbits_3d_view_and_trajectories():
    from orbits.plot import orbits

    orbit = Orbit.from_elements("Earth", a=10000 * u.km, e=0.3, inc=40 * u.deg, raan=20 * u.deg, argp=60 * u.deg)
    r, _ = orbit.propagate(np.linspace(0, 2, 40) * u.h)
    _, ax = orbits(orbit, r, projection="3d", labels=["Kepler", "propagated"])
    line = [line for line in ax.get_lines() if line.get_label() == "propagated"][0]
    x, y, z = line.get_data_3d()
    np.testing.assert_allclose(np.stack([x, y, z], axis=-1), r.to_value(u.km), rtol=1e-12)
    assert ax.name == "3d" and "z [km]" in ax.get_zlabel()


def test_orbit_plot_draws_the_orbit_about_its_primary():
    """Orbit.plot is orbits.plot.orbits for one orbit: its conic, its apsides and where it is now, about the
    primary to scale, in labelled axes; the checks are the focal equation and the elements, not the plotter."""
    import matplotlib.pyplot as plt

    a, e = 26600.0, 0.74  # km; a Molniya-like ellipse, first in the equatorial plane with periapsis at -y
    orbit = Orbit.from_elements("Earth", a=a * u.km, e=e, argp=270 * u.deg, nu=30 * u.deg)
    fig, ax = orbit.plot()
    track = [line for line in ax.get_lines() if line.get_label() == "orbit, e = 0.74"][0].get_xydata()
    r, theta = np.hypot(*track.T), np.arctan2(track[:, 1], track[:, 0])
    assert r.min() == pytest.approx(a * (1 - e), rel=1e-15)  # measured 0: the samples include both apsides
    assert r.max() == pytest.approx(a * (1 + e), rel=1e-15)
    np.testing.assert_allclose(r * (1 + e * np.cos(theta - np.radians(270))), a * (1 - e * e),
                               rtol=5e-15)  # r = p / (1 + e cos(theta - omega)) at every point: measured 6.7e-16
    peri = _by_gid(ax, "periapsis")[0].get_xydata()[0]  # x is cos(270 deg) q: measured 1.3e-12 km
    assert tuple(peri) == pytest.approx((0, -a * (1 - e)), rel=1e-15, abs=1e-11)
    np.testing.assert_allclose(_by_gid(ax, "position")[0].get_xydata()[0], orbit.r.to_value(u.km)[:2],
                               rtol=1e-15)  # measured 0
    earth = [patch for patch in ax.patches if patch.get_label() == "Earth (to scale)"][0]
    assert earth.get_radius() == pytest.approx(6378.1, rel=1e-12)  # km, IAU 2015 nominal equatorial radius
    assert earth.get_center() == (0, 0) and {"periapsis", "apoapsis", "body at t0"} <= labels(ax)
    assert (ax.get_xlabel(), ax.get_ylabel()) == ("x [km]", "y [km]")
    fig.canvas.draw()
    assert ax.get_legend().get_window_extent().x0 >= ax.get_window_extent().x1  # the legend is off the data
    # tilted by i = 63.4 deg and seen edge-on along y: periapsis at z = -q sin i, apoapsis at z = +Q sin i
    tilted = Orbit.from_elements("Earth", a=a * u.km, e=e, inc=63.4 * u.deg, argp=270 * u.deg)
    _, given = plt.subplots()
    fig, ax = tilted.plot(ax=given, projection="xz")
    assert ax is given and fig is given.figure and (ax.get_xlabel(), ax.get_ylabel()) == ("x [km]", "z [km]")
    sin_i = np.sin(np.radians(63.4))
    assert _by_gid(ax, "periapsis")[0].get_xydata()[0, 1] == pytest.approx(-a * (1 - e) * sin_i,
                                                                         rel=1e-15)  # measured 1.1e-16
    assert _by_gid(ax, "apoapsis")[0].get_xydata()[0, 1] == pytest.approx(a * (1 + e) * sin_i,
                                                                        rel=1e-15)  # measured 0
    with pytest.raises(ValueError, match="projection 'xw'"):
        orbit.plot(projection="xw")


def test_near_parabolic_comet_is_drawn_over_a_sensible_window():
    """Notebook 02's e = 0.999999 comet: Q = 2e6 q, so only the arc within the window is drawn, not 1e6 AU."""
    from orbits.plot import orbits

    comet = Orbit.from_elements("Sun", q=1 * u.AU, e=0.999999)
    earth = Orbit.circular("Sun", 1 * u.AU)
    _, ax = orbits(comet, earth, labels=["comet", "Earth"])
    track = [line for line in ax.get_lines() if line.get_label() == "comet"][0].get_xydata()
    assert np.hypot(*track.T).max() == pytest.approx(10, rel=1e-9)  # 10 q, the window of an open orbit
    assert not _by_gid(ax, "apoapsis") and "[AU]" in ax.get_xlabel()
    sun = [line for line in ax.get_lines() if line.get_label().startswith("Sun (not to scale")]
    assert sun  # a 0.005 AU disc is invisible in a 20 AU picture: the star says where it is


def test_closest_approach_inside_the_primary_warns():
    from orbits.core.errors import InsideBodyWarning as OrbitInsideBody
    from orbits.plot import InsideBodyWarning, orbits

    with pytest.warns(OrbitInsideBody, match="inside the Earth"):
        grazing = Orbit.from_elements("Earth", q=6000 * u.km, e=0.5)
    with pytest.warns(InsideBodyWarning, match="closest approach 6000 km is inside Earth"):
        _, ax = orbits(grazing)
    assert "inside Earth" in ax.get_title()
    with pytest.raises(ValueError, match="projection 'xw' is not one of"):
        orbits(grazing, projection="xw")


def test_flyby_of_jupiter_past_the_sun_stays_in_its_window_and_warns():
    """The issue's example: q = 84,000 km, 4 AU window (it spanned 900 AU), e shown as 1 + 6.3e-07."""
    from orbits import Flyby
    from orbits.plot import InsideBodyWarning, collision_note, flyby_plane

    with pytest.warns(orbits.InsideBodyWarning, match="they collide"):
        flyby = Flyby.between("Sun", "Jupiter", 1 * u.km / u.s, b=1 * u.AU)
    with pytest.warns(InsideBodyWarning, match="inside the radii of the Sun and Jupiter added"):
        _, ax = flyby_plane(flyby)
    spans = np.concatenate([np.abs(line.get_xydata()).ravel() for line in ax.get_lines()])
    assert spans.max() <= 4.0 * (1 + 1e-12)  # AU
    assert any(line.get_label() == r"trajectory, e = 1 + 6.3$\times10^{-7}$" for line in ax.get_lines())
    assert "they collide" in ax.get_title()
    assert collision_note(Flyby.past("Jupiter", v_inf=5.6 * u.km / u.s, periapsis=200_000 * u.km)) is None


# ---- the solar system at a date (issue 16, item 5) -----------------------------------------------------------

OBLIQUITY_J2000 = np.radians(84381.448 / 3600)  # IAU 1976, the obliquity of JPL's ecliptic J2000


def _astropy_heliocentric_ecliptic_au(name, when):
    """astropy reading the same DE421 file, Sun-centred, turned about the equinox to the ecliptic of J2000."""
    from astropy.coordinates import get_body_barycentric

    from orbits.ephemeris import positions as ephemeris

    kernel = ephemeris.kernel_path()
    r = (get_body_barycentric(name.lower(), when, ephemeris=kernel)
         - get_body_barycentric("sun", when, ephemeris=kernel)).xyz.to_value(u.AU)
    c, s = np.cos(OBLIQUITY_J2000), np.sin(OBLIQUITY_J2000)
    return np.array([r[0], c * r[1] + s * r[2], -s * r[1] + c * r[2]])


def test_solar_system_puts_each_planet_where_de421_has_it():
    from orbits.plot import solar_system

    when = Time("2026-11-25", scale="utc")
    fig, ax = solar_system(when, which="all")
    title = fig.get_suptitle()
    assert "2026-11-25 00:01 TDB" in title and "DE421" in title  # TDB = UTC + 69.18 s
    assert "Jupiter to Pluto: the system barycentres (planet and moons)" in title
    dots = {line.get_color(): line.get_xydata()[0] for line in _by_gid(ax, "position")}
    curves = {line.get_label(): line for line in ax.get_lines() if line.get_gid() is None}
    for name in ["Mercury", "Venus", "Earth", "Mars", "Jupiter", "Saturn", "Uranus", "Neptune", "Pluto"]:
        curve = curves[name]
        dot = dots[curve.get_color()]
        expected = _astropy_heliocentric_ecliptic_au(name, when)
        np.testing.assert_allclose(dot, expected[:2], rtol=0, atol=8e-15 * np.linalg.norm(expected))  # measured 8e-16
        gap = np.min(np.hypot(*(curve.get_xydata() - dot).T))  # the osculating orbit runs through the body
        assert gap < 0.005 * np.linalg.norm(expected)  # 721 points, pi / 720 = 0.0044 of r apart; measured 0.0040
    names = {text.get_text() for text in ax.texts if text.get_gid() == "name"}
    assert names == {"Jupiter", "Saturn", "Uranus", "Neptune", "Pluto"}  # the inner ones crowd round the Sun
    enlarged = fig.axes[1]  # so they have a panel of their own, each named
    assert {text.get_text() for text in enlarged.texts if text.get_gid() == "name"} == {"Mercury", "Venus", "Earth",
                                                                                          "Mars"}
    assert max(abs(x) for x in enlarged.get_xlim()) < 2.0  # AU: Mars's aphelion is 1.67 AU
    assert "[AU]" in ax.get_xlabel() and any(line.get_label().startswith("Sun") for line in ax.get_lines())


def test_solar_system_inner_names_every_planet_and_highlights_one_with_its_line_of_sight():
    from orbits.plot import solar_system

    _, ax = solar_system("2026-11-25", which="inner", highlight="mars", observer="Earth")
    names = {text.get_text(): text for text in ax.texts if text.get_gid() == "name"}
    assert set(names) == {"Mercury", "Venus", "Earth", "Mars"} and names["Mars"].get_fontweight() == "bold"
    curves = {line.get_label(): line for line in ax.get_lines()}
    assert curves["Mars"].get_linewidth() == 3.0 and curves["Earth"].get_linewidth() < 3.0
    sight = _by_gid(ax, "line of sight")[0].get_xydata()
    dots = {line.get_color(): line.get_xydata()[0] for line in _by_gid(ax, "position")}
    np.testing.assert_array_equal(sight, [dots[curves["Earth"].get_color()], dots[curves["Mars"].get_color()]])
    from orbits.ephemeris import positions as ephemeris

    seen = ephemeris.where("Mars", "2026-11-25")  # the sight line's length in 3D is the Earth-Mars distance
    when = Time("2026-11-25", scale="utc")
    earth, mars = (_astropy_heliocentric_ecliptic_au(name, when) for name in ("Earth", "Mars"))
    assert np.linalg.norm(mars - earth) == pytest.approx(seen.observer_distance.to_value(u.AU), rel=1e-12)
    _, ax = solar_system("2026-11-25", which="inner", highlight="Moon")
    assert "Moon (at Earth)" in {text.get_text() for text in ax.texts}


def test_solar_system_without_de421_leaves_pluto_out_and_says_so():
    from orbits.plot import solar_system

    _, ax = solar_system("2026-11-25", which="outer", source="builtin")
    assert "left out: Pluto" in ax.get_title() and "astropy built-in" in ax.get_title()
    assert {line.get_label() for line in ax.get_lines()} >= {"Jupiter", "Saturn", "Uranus", "Neptune"}
    assert not any("Pluto" in line.get_label() for line in ax.get_lines())


def test_solar_system_3d_and_bad_choices():
    from orbits.plot import solar_system, solar_system_part

    _, ax = solar_system("J2000", which="inner", projection="3d")
    assert ax.name == "3d" and "z [AU]" in ax.get_zlabel()
    assert {"Mercury", "Venus", "Earth", "Mars"} <= {text.get_text().strip() for text in ax.texts}
    with pytest.raises(ValueError, match="which 'middle' is not one of inner, outer, all"):
        solar_system("J2000", which="middle")
    with pytest.raises(ValueError, match="Saturn is not drawn in the inner solar system"):
        solar_system("J2000", which="inner", highlight="Saturn")
    assert [solar_system_part(b) for b in ("Mars", "moon", "EMB", "Jupiter", "Pluto")] == [
        "inner", "inner", "inner", "all", "all"]


# ---- binary observables (issue 18, item 3) ------------------------------------------------------------------


def _visual_binary():
    from orbits import Binary

    return Binary.from_elements(1.1 * u.solMass, 0.8 * u.solMass, period=20 * u.yr, e=0.5, inc=50 * u.deg,
                                raan=30 * u.deg, argp=100 * u.deg, nu=40 * u.deg, com_v=[0, 0, 12] * u.km / u.s)


def test_binary_sky_draws_the_apparent_orbit_north_up_east_left():
    from orbits.plot import binary_sky

    pair = _visual_binary()
    _, ax = binary_sky(pair)
    east, north = [line for line in ax.get_lines() if line.get_label() == "apparent orbit of star 2"][0].get_xydata().T
    a, e = pair.relative.semi_major_axis.to_value(u.AU), 0.5
    area = 0.5 * abs(np.dot(east, np.roll(north, 1)) - np.dot(north, np.roll(east, 1)))  # shoelace
    projected = np.pi * a * a * np.sqrt(1 - e * e) * np.cos(np.radians(50))  # pi a b cos i
    assert area == pytest.approx(projected, rel=1e-4)  # 721 points: measured 1.9e-5
    node = _by_gid(ax, "ascending node")[0].get_xydata()[0]
    assert np.degrees(np.arctan2(node[0], node[1])) == pytest.approx(30, abs=1e-12)  # position angle Omega
    rho, theta = pair.sky_position()
    now = _by_gid(ax, "star 2 at t0")[0].get_xydata()[0]
    rho_au = rho.to_value(u.AU)
    assert tuple(now) == pytest.approx((rho_au * np.sin(theta.value), rho_au * np.cos(theta.value)), rel=1e-12)
    left, right = ax.get_xlim()
    assert left > right and "east" in ax.get_xlabel() and "north" in ax.get_ylabel()  # east to the left
    assert "i = 50 deg" in ax.get_title()
    _, ax = binary_sky(pair, distance=10 * u.pc)
    far = _by_gid(ax, "star 2 at t0")[0].get_xydata()[0]
    np.testing.assert_allclose(far, now * 0.1, rtol=1e-12)  # 1 AU at 10 pc is 0.1 arcsec
    assert "[arcsec]" in ax.get_xlabel()


def test_binary_sky_draws_no_direction_for_a_star_moving_along_the_line_of_sight():
    """A circular orbit edge on (i = 90 deg), star 2 at its node: the velocity is all along the line of sight and
    its sky part round-off, so no arrow, and the legend says why; anywhere else one arrow."""
    from orbits import Binary
    from orbits.plot import binary_sky

    def arrows(ax):
        return [a for a in ax.texts if getattr(a, "arrow_patch", None) is not None]

    edge_on = Binary.from_elements(1.0 * u.solMass, 0.5 * u.solMass, period=10 * u.yr, e=0.0, inc=90 * u.deg,
                                   raan=30 * u.deg, nu=0 * u.deg)
    _, ax = binary_sky(edge_on)
    assert arrows(ax) == [] and "line of sight" in _by_gid(ax, "star 2 at t0")[0].get_label()
    _, ax = binary_sky(_visual_binary())
    assert len(arrows(ax)) == 1 and _by_gid(ax, "star 2 at t0")[0].get_label() == "star 2 at t0"


def test_radial_velocity_curves_span_two_k_about_the_systemic_velocity():
    from orbits.plot import radial_velocity_curves

    pair = _visual_binary()
    fig, ax = radial_velocity_curves(pair, cycles=1.0, samples=4001)
    curves = {line.get_label().split(" (")[0]: line.get_ydata() for line in ax.get_lines()}
    k1, k2 = pair.rv_semi_amplitude1.to_value(u.km / u.s), pair.rv_semi_amplitude2.to_value(u.km / u.s)
    assert np.ptp(curves["star 1"]) == pytest.approx(2 * k1, rel=3e-6)  # sampled extrema; measured 3.1e-7
    assert np.ptp(curves["star 2"]) == pytest.approx(2 * k2, rel=3e-6)
    np.testing.assert_allclose(curves["star 1"] - 12, -(curves["star 2"] - 12) * 0.8 / 1.1, rtol=1e-12, atol=1e-12)
    gamma = [line for line in ax.get_lines() if line.get_label().startswith("systemic")][0]
    assert gamma.get_ydata()[0] == pytest.approx(12) and "[km/s]" in ax.get_ylabel()
    phase = ax.get_lines()[0].get_xdata()
    _, v2 = pair.radial_velocities(phase[1000] * pair.period - pair.time_since_periapsis)
    assert curves["star 2"][1000] == pytest.approx(v2.to_value(u.km / u.s), rel=1e-13)
    fig.canvas.draw()
    assert ax.get_legend().get_window_extent().x0 >= ax.get_window_extent().x1  # the legend is off the data
