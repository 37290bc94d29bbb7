"""Every picture of orbits.plot, drawn from small inputs, held to what a talk needs (picture_checks.problems): no
text over other text or outside the figure, each legend entry once, a title naming what is drawn (and when),
powers and Greek letters typeset. Then what was wrong with particular pictures: L1 and L2 apart, the inner planets
of the whole solar system shown, a flyby's impact parameter in one unit and its asymptotes told apart, the
validation panels, the porkchop's labels and its optimum on the edge of the grid."""

import warnings

import astropy.units as u
import matplotlib
import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from picture_checks import legend_labels, legends, overlapping_texts, problems, titles, untypeset

from orbits import (
    Binary,
    Collision,
    Cosmology,
    DampedOscillator,
    Flyby,
    Orbit,
    Pendulum,
    Projectile,
    RestrictedThreeBody,
    Rolling,
    VerticalCircle,
)
from orbits import plot as pictures
from orbits.core.errors import InsideBodyWarning

matplotlib.use("Agg")


def test_the_checks_find_overlaps_text_outside_and_untypeset_powers():
    """The shared checks are not vacuous: two labels on one spot overlap, a title wider than its figure reaches
    outside it, a legend entry twice, '1.287 1e+06 km', '10^3 km' and 'km2/s2' are found; their typeset forms
    are not."""
    import matplotlib.pyplot as plt

    fig, ax = plt.subplots(figsize=(3, 2))
    ax.text(0.5, 0.5, "here", transform=ax.transAxes)
    ax.text(0.5, 0.5, "and here", transform=ax.transAxes)
    fig.suptitle("a title much wider than a figure three inches across can hold")
    found = overlapping_texts(fig)
    assert ("here", "and here") in found
    assert ("a title much wider than a figure three inches across can hold", "outside the figure") in found
    fig, ax = plt.subplots(figsize=(6, 4))
    for label in ("b = 1.287 1e+06 km", "x [10^3 km]", "C3 [km2/s2]", "theta0", "x", "x"):
        ax.plot([], [], label=label)
    ax.plot([], [], label=r"b = 1.287$\times10^{6}$ km, x [$10^{3}$ km], C3 [km$^{2}$/s$^{2}$], $\theta_0$")
    ax.legend()
    assert untypeset(fig) == ["b = 1.287 1e+06 km", "x [10^3 km]", "C3 [km2/s2]", "theta0"]
    assert set(problems(fig)) == {"no title", "legend entry twice: 'x'", "blank panel: 'an untitled panel'",
                                  "blank figure: no panel draws anything", *(
        f"not typeset: {text!r}" for text in ("b = 1.287 1e+06 km", "x [10^3 km]", "C3 [km2/s2]", "theta0"))}


def test_the_checks_find_a_blank_figure_an_invisible_curve_and_a_legend_entry_with_nothing_drawn():
    """A sentence on a panel with its axes off is a blank figure; an orbit 1/1000 of the frame across, a curve
    wholly outside the view and a transparent one leave no mark, and their legend entries name nothing; a
    legend's proxy (no points, standing for marks drawn unlabelled) and a single visible marker are fine."""
    import matplotlib.pyplot as plt

    fig, ax = plt.subplots()
    ax.text(0.1, 0.5, "nothing to draw", transform=ax.transAxes)
    ax.set_axis_off()
    fig.suptitle("a title")
    assert problems(fig) == ["blank figure: no panel draws anything"]
    fig, ax = plt.subplots()
    angle = np.linspace(0, 2 * np.pi, 200)
    ax.plot(1e3 * np.cos(angle), 1e3 * np.sin(angle), label="star 2")
    ax.plot(np.cos(angle), np.sin(angle), label="star 1")  # 1/1000 of the frame: under 2 pixels
    ax.plot([5e3, 6e3], [5e3, 6e3], label="off the view")
    ax.plot([0, 500], [0, 500], alpha=0.0, label="transparent")
    ax.plot([], [], "o", label="a proxy")
    ax.plot([0.0], [0.0], "+", label="centre")
    ax.set_xlim(-1100, 1100)
    ax.set_ylim(-1100, 1100)
    ax.legend()
    ax.set_title("a binary")
    assert problems(fig) == ["nothing drawn for 'star 1'", "nothing drawn for 'off the view'",
                             "nothing drawn for 'transparent'"]


# ---- one small case of every picture -------------------------------------------------------------------------


def _quiet(build):
    """Draw with the InsideBodyWarning of a colliding flyby silenced (it is tested where it is raised)."""
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", InsideBodyWarning)
        return build()


def _molniya(**kwargs):
    return Orbit.from_elements("Earth", a=26600 * u.km, e=0.74, inc=63.4 * u.deg, argp=270 * u.deg, **kwargs)


def _visual_binary():
    return Binary.from_elements(1.1 * u.solMass, 0.8 * u.solMass, period=20 * u.yr, e=0.5, inc=50 * u.deg,
                                raan=30 * u.deg, argp=100 * u.deg, nu=40 * u.deg, com_v=[0, 0, 12] * u.km / u.s)


H0 = 67.66 * u.km / u.s / u.Mpc


def _rotating_tracks(system):
    """A tadpole about L4 and a horseshoe through L3 as drawn (rotating-frame positions, no integration)."""
    mu = float(system.mass_ratio)
    angle = np.linspace(0, 2 * np.pi, 400)
    tadpole = np.radians(60 + 25 * np.sin(angle))
    horseshoe = np.radians(180 + 170 * np.sin(angle))
    tracks = {}
    for label, longitude, wobble in (("tadpole about L4", tadpole, 0.004), ("horseshoe through L3", horseshoe, 0.01)):
        radius = 1 + wobble * np.cos(angle)
        tracks[label] = np.stack([radius * np.cos(longitude) - mu, radius * np.sin(longitude), 0 * angle],
                                 axis=1) * system.separation
    return tracks


def _departure():
    system = RestrictedThreeBody.from_primaries("Earth", "Moon")
    r0, _ = system.departure_state("L1", 100 * u.km)
    rate = float(system.growth_rates[0].to_value(1 / u.s))
    times = np.linspace(0, 4 / rate, 200) * u.s
    grow = (100 * u.km) * np.exp(rate * times.to_value(u.s))
    track = r0 + np.stack([grow, 0.3 * grow, 0 * grow], axis=1) - [100, 30, 0] * u.km
    return pictures.lagrange_departure(system, "L1", 100 * u.km, times, track)


def _ring(n=7):
    """A ring of n bodies turning once per 2 pi (code units) and breaking up at t = 20."""
    times = np.linspace(0, 30, 300)
    angles = times[:, None] + 2 * np.pi * np.arange(n) / n
    scatter = 1e-16 * np.exp(times)[:, None] * np.cos(3 * np.arange(n))[None, :]
    radius = 1 + scatter
    positions = np.stack([radius * np.cos(angles + scatter), radius * np.sin(angles + scatter), 0 * angles], axis=-1)
    return times, positions


def _ring_breakup():
    times, _ = _ring()
    return pictures.ring_breakup(times, 1e-16 * np.exp(times), 1.0, 29.9, period=2 * u.d)


def _ring_snapshots():
    times, positions = _ring()
    return pictures.ring_snapshots(times, positions, 1.0, 20.0, period=2 * u.d)


@pytest.fixture(scope="module")
def halo():
    from orbits import PeriodicOrbit

    return PeriodicOrbit.halo(RestrictedThreeBody.from_primaries("Earth", "Moon"), "L2", az=20_000 * u.km)


@pytest.fixture(scope="module")
def lyapunov_family():
    from orbits import PeriodicFamily

    return PeriodicFamily.of(RestrictedThreeBody.from_primaries("Earth", "Moon"), "lyapunov", members=6,
                             point="L1", ax=10_000 * u.km)


@pytest.fixture(scope="module")
def validated():
    """Four scenes through both integrators: two of 100 whole orbits, a flyby, the expanding sphere."""
    from orbits.validate import load
    from orbits.validate.run import validate

    return validate([load(name) for name in ("circular", "eccentric", "flyby", "expanding_universe")])


@pytest.fixture(scope="module")
def mars_chart():
    from orbits import Porkchop

    return Porkchop.between("Earth", "Mars", ("2026-09-01", "2027-01-31"), ("2027-06-01", "2028-03-01"),
                            step=10 * u.day)


@pytest.fixture(scope="module")
def jupiter_chart():
    """The least C3 of these windows lies on the last launch date (the issue's example, at a coarser step)."""
    from orbits import Porkchop

    return Porkchop.between("Earth", "Jupiter", ("2026-01-01", "2027-12-31"), ("2028-01-01", "2031-01-01"),
                            step=20 * u.day)


def _precision_rows():
    from collections import namedtuple

    row = namedtuple("Row", "problem method seconds error")
    rows = []
    for problem in ("circular, 100 periods", "eccentric e = 0.9, 100 periods"):
        rows.append(row(problem, "orbits analytic", 1e-5, 1e-16))
        for k, method in enumerate(("rebound IAS15", "heyoka taylor")):
            rows += [row(problem, method, 1e-3 * 3**j * (k + 1), 1e-6 / 10**j) for j in range(5)]
    return rows


#: name -> (draw, words the title must hold)
CASES = {
    "orbit_plane": (lambda: pictures.orbit_plane(_molniya(nu=30 * u.deg), times=[1, 2, 3] * u.h),
                    ["Earth", "t0"]),
    "orbit_plane at a date": (lambda: pictures.orbit_plane(_molniya(), epoch="2026-11-25"),
                              ["Earth", "2026-11-25"]),
    "orbits": (lambda: pictures.orbits(Orbit.circular("Earth", 42164 * u.km), _molniya(),
                                       Orbit.from_elements("Earth", q=6678 * u.km, e=0.73, raan=30 * u.deg),
                                       labels=["GEO", "Molniya", "GTO"]), ["Earth", "t0"]),
    "orbits, an array": (lambda: pictures.orbits(Orbit.from_elements("Earth", a=[8000, 9000, 10000] * u.km, e=0.1)),
                         ["Earth"]),
    "orbits in 3-D": (lambda: _molniya(nu=30 * u.deg).plot(projection="3d"), ["Earth"]),
    "the whole solar system": (lambda: pictures.solar_system("2026-11-25", which="all", highlight="Jupiter",
                                                             observer="Earth"), ["solar system", "2026-11-25"]),
    "the inner solar system": (lambda: pictures.solar_system("2026-11-25", highlight="Mars", observer="Earth"),
                               ["inner solar system", "2026-11-25"]),
    "the solar system in 3-D": (lambda: pictures.solar_system("2026-11-25", projection="3d"),
                                ["solar system", "2026-11-25"]),
    "the whole solar system in 3-D": (lambda: pictures.solar_system("2026-11-25", which="all", projection="3d"),
                                      ["solar system", "2026-11-25"]),
    "flyby_plane": (lambda: pictures.flyby_plane(Flyby.past("Jupiter", v_inf=5.6 * u.km / u.s,
                                                            periapsis=200_000 * u.km)), ["Flyby", "Jupiter"]),
    "flyby_plane, a collision": (lambda: _quiet(lambda: pictures.flyby_plane(
        Flyby.between("Sun", "Jupiter", 1 * u.km / u.s, b=1 * u.AU))), ["Flyby", "Sun", "collide"]),
    "binary_plane": (lambda: pictures.binary_plane(_visual_binary()), ["binary", "t0"]),
    "binary_sky": (lambda: pictures.binary_sky(_visual_binary(), distance=10 * u.pc), ["sky", "t0"]),
    "radial_velocity_curves": (lambda: pictures.radial_velocity_curves(_visual_binary()), ["Radial velocit"]),
    "scale_factor_curves": (lambda: pictures.scale_factor_curves(
        {"flat": Cosmology.from_densities(H0, Om0=0.31, Ol0=0.69), "planck18": Cosmology.planck18(),
         "closed": Cosmology.from_densities(H0, Om0=3.0, Ol0=0.0)}, 100 * u.Gyr, log=True),
        ["Scale factor", "100 Gyr"]),
    "hubble_diagram": (lambda: pictures.hubble_diagram({"Planck 2018": Cosmology.planck18()}, z_max=3.0),
                       ["Hubble diagram", "z = 3"]),
    "distance_curves": (lambda: pictures.distance_curves(Cosmology.planck18()), ["Distances", "z = 10"]),
    "cosmology_overview": (lambda: pictures.cosmology_overview(Cosmology.planck18(), "Planck 2018"),
                           ["Planck 2018", "Scale factor", "Distances", "Hubble diagram"]),
    "cosmology_overview, no big bang": (lambda: pictures.cosmology_overview(Cosmology.de_sitter(H0), "de Sitter"),
                                        ["de Sitter", "Scale factor"]),
    "lagrange_plane, Sun-Earth": (lambda: pictures.lagrange_plane(RestrictedThreeBody.from_primaries("Sun", "Earth"),
                                                                  points=201), ["Sun", "Earth", "Lagrange"]),
    "lagrange_plane, Earth-Moon": (lambda: pictures.lagrange_plane(
        RestrictedThreeBody.from_primaries("Earth", "Moon"), points=201), ["Earth", "Moon", "Lagrange"]),
    "lagrange_plane with trajectories": (lambda: pictures.lagrange_plane(
        RestrictedThreeBody.from_primaries("Sun", "Earth"), points=201,
        trajectories=_rotating_tracks(RestrictedThreeBody.from_primaries("Sun", "Earth"))), ["Sun", "Earth"]),
    "lagrange_departure": (_departure, ["L1", "Earth", "Moon"]),
    "coorbital_plane": (lambda: pictures.coorbital_plane(
        RestrictedThreeBody.from_primaries("Sun", "Earth"),
        _rotating_tracks(RestrictedThreeBody.from_primaries("Sun", "Earth"))), ["Co-orbital", "Sun", "Earth"]),
    "ring_breakup": (_ring_breakup, ["ring", "break"]),
    "ring_snapshots": (_ring_snapshots, ["ring of 7", "break"]),
    "work_precision": (lambda: pictures.work_precision(_precision_rows()), ["Work-precision", "circular"]),
    "collision_velocities, head on": (lambda: pictures.collision_velocities(
        Collision.head_on(2 * u.kg, 3 * u.m / u.s, 1 * u.kg, -1 * u.m / u.s, 0.5)), ["collision", "2 kg"]),
    "collision_velocities, oblique": (lambda: pictures.collision_velocities(
        Collision.oblique(2 * u.kg, [3, 1] * u.m / u.s, 1 * u.kg, [-1, 0] * u.m / u.s, 0.8, normal=[1, 0])),
        ["collision", "2 kg"]),
    "projectile_paths": (lambda: pictures.projectile_paths(
        {"no drag": Projectile.launch(30 * u.m / u.s, 60 * u.deg),
         "quadratic drag": Projectile.launch(30 * u.m / u.s, 60 * u.deg).with_quadratic_drag(25 * u.m / u.s)}),
        ["Projectile", "30 m/s", "60 deg"]),
    "projectile_paths, one": (lambda: pictures.projectile_paths(
        {"no drag": Projectile.launch(20 * u.m / u.s, 45 * u.deg)}), ["Projectile", "20 m/s", "45 deg"]),
    "pendulum_periods": (lambda: pictures.pendulum_periods(Pendulum.simple(1 * u.m, 170 * u.deg)),
                         ["pendulum", "170 deg"]),
    "damped_motion": (lambda: pictures.damped_motion(
        {"under": DampedOscillator.of(2 / u.s, 0.5 / u.s, 1 * u.m),
         "critical": DampedOscillator.of(2 / u.s, 4 / u.s, 1 * u.m),
         "over": DampedOscillator.of(2 / u.s, 8 / u.s, 1 * u.m)}, 60 * u.s), ["Damped", "60 s"]),
    "vertical_circle_forces": (lambda: pictures.vertical_circle_forces(
        {"string, 6 m/s": VerticalCircle.of(1 * u.m, 6 * u.m / u.s, mass=1 * u.kg),
         "rod, 6.5 m/s": VerticalCircle.of(1 * u.m, 6.5 * u.m / u.s, mass=1 * u.kg, support="rod"),
         "string, 3 m/s": VerticalCircle.of(1 * u.m, 3 * u.m / u.s, mass=1 * u.kg)}), ["vertical circle", "1 m"]),
    "rolling_race": (lambda: pictures.rolling_race({"ball": Rolling.down(30 * u.deg, 0.4),
                                                    "hoop": Rolling.down(30 * u.deg, 1.0)}, 2 * u.m),
                     ["Rolling", "30 deg", "2 m"]),
}

#: cases drawn from a fixture: name -> (fixture, draw, title words)
FIXTURE_CASES = {
    "periodic_orbit": ("halo", lambda o: pictures.periodic_orbit(o), ["halo", "Earth-Moon", "L2"]),
    "periodic_family": ("lyapunov_family", lambda f: pictures.periodic_family(f), ["lyapunov", "family"]),
    "stability_diagram": ("lyapunov_family", lambda f: pictures.stability_diagram(f), ["tability", "lyapunov"]),
    "validation_residuals": ("validated", lambda r: pictures.validation_residuals(r), ["Position errors"]),
    "validation_tracks": ("validated", lambda r: pictures.validation_tracks(r), ["tracks"]),
    "validation_overview": ("validated", lambda r: pictures.validation_overview(r), ["Position errors", "tracks"]),
    "porkchop": ("mars_chart", lambda c: pictures.porkchop(c), ["Earth to Mars", "2026"]),
    "porkchop, least C3 on the edge": ("jupiter_chart", lambda c: pictures.porkchop(c), ["Earth to Jupiter"]),
}


def _check(fig, words):
    shown = " ".join(titles(fig))
    missing = [word for word in words if word not in shown]
    assert not missing, f"the title {shown!r} lacks {missing}"
    assert problems(fig) == []


@pytest.mark.parametrize("name", CASES)
def test_every_picture_is_fit_for_a_talk(name, tmp_path):
    draw, words = CASES[name]
    fig = draw()[0]
    _check(fig, words)
    pictures.save(fig, tmp_path / "picture.png")


@pytest.mark.parametrize("name", FIXTURE_CASES)
def test_every_picture_of_a_computed_object_is_fit_for_a_talk(name, request, tmp_path):
    fixture, draw, words = FIXTURE_CASES[name]
    fig = draw(request.getfixturevalue(fixture))[0]
    _check(fig, words)
    pictures.save(fig, tmp_path / "picture.png")


def test_the_pictures_format_no_numbers_themselves():
    """Numbers in titles, legends and labels come from orbits._common.display (natural units, sensible digits, typeset):
    no format specification in the picture code ('{x:.4g}', '%.3g')."""
    import re
    from pathlib import Path

    import orbits

    root = Path(orbits.__file__).parent
    modules = sorted(root.rglob("plot.py")) + [root / "_common" / "frame.py"]
    assert len(modules) >= 10  # each subject's pictures, the validation's and the shared frame
    found = []
    for path in modules:
        for number, line in enumerate(path.read_text().splitlines(), 1):
            if re.search(r"\{[^{}]*:[+ ]?[\d.]*[dgfe%]\}|%[\d.]*[dgf]\b", line.replace('"%Y-%m-%d"', "")):
                found.append(f"{path.relative_to(root)}:{number}: {line.strip()}")
    assert found == []


# ---- what was wrong with particular pictures -----------------------------------------------------------------


def test_sun_earths_l1_and_l2_are_labelled_apart():
    """L1 and L2 of Sun-Earth lie 0.02 r apart, 3 pixels at the scale of the whole frame: their labels sit on
    either side, L1 towards the Sun."""
    _, ax = pictures.lagrange_plane(RestrictedThreeBody.from_primaries("Sun", "Earth"), points=201)
    ax.figure.canvas.draw()
    boxes = {text.get_text(): text.get_window_extent() for text in ax.texts if text.get_text().startswith("L")}
    assert set(boxes) == {"L1", "L2", "L3", "L4", "L5"}
    assert boxes["L1"].x1 < boxes["L2"].x0 and not boxes["L1"].overlaps(boxes["L2"])


def test_the_whole_solar_system_shows_the_inner_planets_and_a_short_legend():
    """`where Jupiter --plot`: the inner planets in a panel of their own, every name readable, the positions
    labelled with their date, and no legend entry of the length of 'system barycentre (planet and moons)'."""
    fig, ax = pictures.solar_system("2026-11-25", which="all", highlight="Jupiter", observer="Earth")
    whole, inner = fig.axes
    assert {t.get_text() for t in inner.texts if t.get_gid() == "name"} == {"Mercury", "Venus", "Earth", "Mars"}
    labels = legend_labels(fig)
    assert "body at 2026-11-25 00:01 TDB" in labels and not any("now" in label for label in labels)
    assert not any("barycentre" in label for label in labels) and max(map(len, labels)) <= 45
    assert overlapping_texts(fig) == []


def test_a_flyby_legend_gives_b_in_one_unit_and_tells_the_asymptotes_apart():
    _, ax = pictures.flyby_plane(Flyby.past("Jupiter", v_inf=5.6 * u.km / u.s, periapsis=200_000 * u.km))
    labels = [line.get_label() for line in ax.get_lines()]
    assert r"impact parameter b = 1.287$\times10^{6}$ km" in labels  # was '1.287 1e+06 km'
    incoming, outgoing = (next(line for line in ax.get_lines() if line.get_gid() == f"{way} asymptote")
                          for way in ("incoming", "outgoing"))
    assert (incoming.get_linestyle(), incoming.get_color()) != (outgoing.get_linestyle(), outgoing.get_color())


def test_validation_pictures_say_what_l_is_and_why_a_long_run_shows_two_points(validated):
    fig, _ = pictures.validation_overview(validated)
    shown = " ".join(titles(fig))
    assert "L: the largest distance of an orbiting body from its primary" in shown
    circular = next(title for title in titles(fig) if title.startswith("circular"))
    assert circular.endswith("200 outputs at 2 points")  # 100 periods sampled every half period
    assert overlapping_texts(fig) == []  # the track panels' tick labels ('-30000-20000-10000') included


def test_a_3d_legend_keeps_clear_of_the_z_label():
    """The whole solar system in 3-D: a legend of fourteen entries beside the axes ran over the z label."""
    fig, ax = pictures.solar_system("2026-11-25", which="all", projection="3d")
    fig.canvas.draw()
    (legend,) = legends(fig)
    assert not legend.get_window_extent().overlaps(ax.zaxis.label.get_window_extent())
    assert overlapping_texts(fig) == []


def test_the_porkchop_labels_each_contour_level_once(mars_chart):
    """Along the ridge of 180-degree transfers the contours crowd into short loops, and each loop got a label."""
    _, ax = pictures.porkchop(mars_chart)
    for lines in (c for c in ax.collections if c.get_gid() in ("C3", "arrival v_inf", "time of flight")):
        labelled = [text.get_text() for text in lines.labelTexts]
        assert len(labelled) == len(set(labelled)) <= len(lines.levels)
    assert overlapping_texts(ax.figure) == []


def test_a_porkchop_flags_a_least_value_on_the_edge_of_its_grid(mars_chart, jupiter_chart):
    """Earth to Jupiter, 2026-2027 launches: the least C3 lies on the last arrival date; its star is drawn whole
    and ringed, and its legend entry names the edge. The Mars window's minima lie inside: no ring."""
    _, ax = pictures.porkchop(jupiter_chart)
    star = next(line for line in ax.get_lines() if line.get_gid() == "minimum")
    assert "on the grid's edge: last arrival date" in star.get_label()
    (ring,) = [line for line in ax.get_lines() if line.get_gid() == "on the edge"]
    np.testing.assert_array_equal(ring.get_xydata(), star.get_xydata())
    x, y = star.get_xydata()[0]
    fig = ax.figure
    fig.canvas.draw()
    size = star.get_markersize() * fig.dpi / 72 / 2  # the star's half-width in pixels
    px, py = ax.transData.transform((x, y))
    box = ax.get_window_extent()
    assert box.x0 + size <= px <= box.x1 - size and box.y0 + size <= py <= box.y1 - size  # whole: not clipped
    _, ax = pictures.porkchop(mars_chart)
    assert not [line for line in ax.get_lines() if line.get_gid() == "on the edge"]


def test_the_cosmology_overview_keeps_each_legend_under_its_panel():
    """The middle legend ran in two columns into the right one, and that one to the figure's edge."""
    fig, axes = pictures.cosmology_overview(Cosmology.planck18(), "Planck 2018")
    fig.canvas.draw()
    for ax in axes:
        legend, panel = ax.get_legend().get_window_extent(), ax.get_window_extent()
        assert panel.x0 - 20 <= legend.x0 and legend.x1 <= panel.x1 + 20  # within 20 pixels of the panel
    assert [ax.get_title() for ax in axes] == ["Scale factor", "Distances", "Hubble diagram"]


def test_a_fast_oscillation_is_drawn_with_every_swing():
    """omega0 = 50 rad/s over 60 s: 477 periods, 40 samples each (400 samples in all drew a moire)."""
    fast = DampedOscillator.of(50 / u.s, 0.01 / u.s, 1 * u.m)
    _, ax = pictures.damped_motion({"fast": fast}, 60 * u.s)
    times = ax.get_lines()[0].get_xdata()
    period = 2 * np.pi / fast.damped_frequency.to_value(u.rad / u.s)
    assert np.max(np.diff(times)) <= period / 40 * (1 + 1e-9)


def test_a_position_is_labelled_with_its_time():
    """'body now' labelled the orbit's own epoch: it is 'body at t0', or the date the elements hold at."""
    assert "body at t0" in legend_labels(pictures.orbits(_molniya())[0])
    assert "body at 2026-11-25 00:01 TDB" in legend_labels(pictures.orbits(_molniya(), epoch="2026-11-25")[0])


@pytest.mark.parametrize("name, part", [("Ceres", "inner"), ("Eris", "all")])
def test_an_asteroid_or_dwarf_planet_is_drawn_beside_the_planets(name, part, tmp_path):
    """where Ceres --plot was refused ('not drawn in the inner solar system'): a body of ephemeris.PROPAGATED is
    drawn with the part of the solar system its orbit fits (the inner planets for the asteroids, all of it for
    Eris, whose panel then reaches out to it), its label in bold, and the title names its two-body orbit."""
    from orbits.plot import solar_system, solar_system_part

    assert solar_system_part(name) == part
    fig, ax = solar_system("2026-01-01", which=part, highlight=name, observer="Earth")
    assert any(text.get_text() == name and text.get_fontweight() == "bold" for text in ax.texts)
    title = fig.get_suptitle() if part == "all" else ax.get_title()
    assert f"{name} by two-body propagation" in " ".join(title.split())
    if part == "all":
        assert ax.get_title() == "out to Eris"
    assert problems(fig) == []


# ---- titles wrapped evenly ---------------------------------------------------------------------------------------

_WORDS = st.lists(st.text("abcdefghij", min_size=1, max_size=12), min_size=1, max_size=30)


@settings(max_examples=300, deadline=None)
@given(words=_WORDS, characters=st.integers(8, 90))
def test_a_title_takes_the_fewest_lines_made_as_even_as_they_can_be(words, characters):
    """The words in order, no line wider than the room (unless one word is), as few lines as a greedy fill, and
    the narrowest such layout: one character less would take another line. So "period" is never left alone on
    a last line when the line above could give it company."""
    from orbits._common.frame import wrapped

    text = " ".join(words)
    lines = wrapped(text, characters).split("\n")
    assert " ".join(lines).split() == words
    assert all(len(line) <= characters or " " not in line for line in lines)
    greedy, line = [], ""
    for word in words:
        if line and len(line) + 1 + len(word) > characters:
            greedy.append(line)
            line = word
        else:
            line = f"{line} {word}" if line else word
    assert len(lines) == len(greedy) + 1
    widest = max(len(line) for line in lines)
    if widest > max(len(word) for word in words):
        assert len(wrapped(text, widest - 1).split("\n")) > len(lines)


def test_the_pendulum_title_leaves_no_word_alone():
    from orbits._common.frame import wrapped

    text = "Period of a pendulum against its amplitude, in units of its small-angle period"
    first, second = wrapped(text, 75).split("\n")
    assert len(second.split()) > 1 and abs(len(first) - len(second)) < 15


# ---- the pictures a reader found wanting, each as it is now ----------------------------------------------------


def test_a_planar_periodic_orbit_is_drawn_in_its_plane_alone_in_the_unit_of_its_size():
    """A Lyapunov orbit never leaves the binary's plane: one panel, not four (two of them flat lines), measured from
    its point in the unit of its own size (10^3 km for 200,000 km about Sun-Earth L1, not 0.990 AU)."""
    from orbits import PeriodicOrbit

    orbit = PeriodicOrbit.lyapunov(RestrictedThreeBody.from_primaries("Sun", "Earth"), "L1", ax=200_000 * u.km)
    fig, panels = pictures.periodic_orbit(orbit)
    (plane,) = panels
    assert plane.get_xlabel() == "x from L1 [$10^{3}$ km]" and plane.get_ylabel() == "y from L1 [$10^{3}$ km]"
    x = plane.get_lines()[0].get_xdata()
    assert 150 < -float(np.min(x)) < 200 and problems(fig) == []  # Ax = 200,000 km about L1: about -170 in view


def test_a_binarys_small_orbit_gets_an_inset_and_its_velocities_an_axis_of_their_own():
    """The Earth's 4,671 km circle about the Earth-Moon barycentre beside the Moon's 379,700 km one: drawn again
    in an inset; a Sun-like star's 126 m/s beside its hot Jupiter's 132 km/s: on a right-hand axis in m/s."""
    from orbits import Binary
    from orbits_cli.commands.binary import _plane_and_velocities

    fig, ax = pictures.binary_plane(Binary.from_elements("Earth", "Moon", a=384_399 * u.km))
    (inset,) = ax.child_axes
    radius = float(np.max(inset.get_lines()[0].get_xdata()))
    assert inset.get_title() == "star 1 [km]" and radius == pytest.approx(4671, rel=1e-3)
    assert problems(fig) == []
    fig, (_, velocities) = _plane_and_velocities(
        Binary.from_elements("Sun", "Jupiter", period=4.23 * u.d, inc=90 * u.deg), with_velocities=True)
    (right,) = [other for other in fig.axes if other is not velocities and other.bbox.bounds == velocities.bbox.bounds]
    assert "[m/s]" in right.get_ylabel() and float(np.max(right.get_lines()[0].get_ydata())) == pytest.approx(
        125.6, rel=1e-3)
    assert problems(fig) == []


def test_a_projectile_with_drag_is_drawn_beside_the_same_launch_without_it(monkeypatch):
    from typer.testing import CliRunner

    from orbits_cli.commands import projectile
    from orbits_cli.main import app

    drawn = []
    monkeypatch.setattr(projectile, "save_plot", lambda draw, path: drawn.append(draw()))
    result = CliRunner().invoke(app, ["projectile", "--speed", "20 m/s", "--angle", "45", "--drag", "quadratic",
                                      "--terminal-speed", "30 m/s", "--plot", "p.png"])
    assert result.exit_code == 0, result.output
    fig, ax = drawn[0]
    assert [line.get_label() for line in ax.get_lines()[:6:3]] == ["quadratic drag", "no drag"]
    assert problems(fig) == []


def test_the_sky_chart_puts_the_body_where_the_table_says_and_the_sun_on_the_ecliptic():
    """`orbits where --plot` draws the sky seen from the observer: the body's marker at the right ascension and
    declination the table gives (the same states, read once), the Sun on the ecliptic line (its declination there
    to 1e-3 deg, the ecliptic sampled every half degree), RA growing to the left as the sky is seen."""
    from orbits.ephemeris import positions
    from orbits.ephemeris.plot import solar_system_points

    when = positions.epoch("2026-11-25")
    names = solar_system_points("all", highlight="Jupiter", observer="Earth")
    states = positions.states(["Jupiter", "Earth", *names], when, "Sun")
    fig, ax = pictures.sky_chart(when, "Jupiter", "Earth", states=states)
    seen = positions.sighting(states, "Jupiter", "Earth")
    (mark,) = [line for line in ax.get_lines() if line.get_label().startswith("Jupiter: elongation")]
    hours, dec = mark.get_xydata()[0]
    assert hours == pytest.approx(seen.right_ascension.to_value(u.hourangle), abs=1e-9)
    assert dec == pytest.approx(seen.declination.to_value(u.deg), abs=1e-9)
    (sun,) = [line for line in ax.get_lines() if line.get_label() == "the Sun"]
    ecliptic = np.concatenate([line.get_xydata() for line in ax.get_lines() if "ecliptic" in line.get_label()])
    near = ecliptic[np.argmin(np.abs(ecliptic[:, 0] - sun.get_xydata()[0, 0]))]
    assert near[1] == pytest.approx(sun.get_xydata()[0, 1], abs=0.3)  # sampled every 0.5 deg of longitude
    assert ax.get_xlim() == (24.0, 0.0) and problems(fig) == []
