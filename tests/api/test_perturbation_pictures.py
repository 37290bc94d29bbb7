"""The pictures of perturbed orbits (orbits.perturb.plot), drawn from records shaped as the integrations give
them (orbits.validate.perturb), for what they draw: the closed form's lines and marks where the theory puts them,
each backend's curves, each legend entry once, Greek letters typeset, and no text over other text or outside the
figure."""

import astropy.units as u
import matplotlib
import numpy as np
import pytest
from picture_checks import legend_labels, problems

from orbits.perturb.secular import DragDecay
from orbits.plot import drag_decay, frozen_eccentricity, ground_track, kozai_cycles, save, secular_elements
from orbits.validate.histories import DecayHistory, FrozenHistory, GroundTrack, KozaiHistory, SecularHistory

matplotlib.use("Agg")


@pytest.fixture(autouse=True)
def _close_figures():
    yield
    import matplotlib.pyplot as plt

    plt.close("all")


def molniya_like():
    """A SecularHistory as secular_history gives it for an eccentric orbit: 4 revolutions of 8 outputs, node
    regressing at -0.15 deg/d with a short-period wobble, periapsis still at 270 deg."""
    times = np.arange(1, 33) * 0.5 / 8
    wobble = 0.01 * np.sin(2 * np.pi * times / 0.5)
    mean_times = times.reshape(4, 8).mean(axis=1)
    states = {"node": -0.15 * times + wobble, "periapsis": 270.0 + wobble}
    means = {"node": -0.15 * mean_times + 1e-4, "periapsis": 270.0 + 0 * mean_times}
    both = {"rebound": states, "heyoka": states}
    return SecularHistory("Earth: a = 26554 km, e = 0.74, i = 63.43 deg; 4 revolutions (2 d)", times, both,
                          mean_times, {"rebound": means, "heyoka": means},
                          {"node": (0.0, -0.15), "periapsis": (270.0, 0.0)}, 3.1e-4)


def test_secular_elements_draws_node_and_periapsis_over_the_closed_form(tmp_path):
    history = molniya_like()
    fig, panels = secular_elements(history)
    assert panels.shape == (2, 2)
    line = panels[0, 0].get_lines()[0].get_xydata()
    np.testing.assert_allclose(line, [[0.0, 0.0], [history.times[-1], -0.15 * history.times[-1]]])
    assert r"$\Omega$" in panels[0, 0].get_ylabel() and r"$\omega$" in panels[1, 0].get_ylabel()
    assert "[deg]" in panels[0, 0].get_ylabel() and "[arcsec]" in panels[1, 1].get_ylabel()
    assert panels[1, 0].yaxis.get_major_formatter().get_useOffset() is False  # 270.00, not +2.7e2
    residual = panels[0, 1].get_lines()[1].get_ydata()  # rebound's means less the line, in arcsec
    np.testing.assert_allclose(residual, 1e-4 * 3600.0, rtol=1e-9)
    labels = legend_labels(fig)
    assert len(labels) == len(set(labels)) == 5  # the closed form, and each backend's osculating and means
    assert history.title in fig.get_suptitle() and "node and argument of periapsis" in fig.get_suptitle()
    assert problems(fig) == []
    save(fig, tmp_path / "secular.png")


def test_secular_elements_of_a_circular_orbit_draws_the_node_alone():
    history = molniya_like()
    circular = SecularHistory(history.title, history.times, {b: {"node": s["node"]} for b, s in
                                                             history.osculating.items()},
                              history.mean_times, {b: {"node": s["node"]} for b, s in history.mean.items()},
                              {"node": history.lines["node"]}, history.accuracy)
    fig, panels = secular_elements(circular)
    assert panels.shape == (1, 2) and "The node under J2" in fig.get_suptitle()
    assert problems(fig) == []


def kozai_like(cycles=2.0):
    """A KozaiHistory shaped as kozai_history gives it: e rising from 0.01 to 0.838 each period of 7.09 tau."""
    period = 7.086
    times = np.linspace(0.0, cycles * period, 400)[1:]
    e = 0.01 + 0.83 * np.sin(np.pi * times / period) ** 8
    inc = np.degrees(np.arccos(0.4226 / np.sqrt(1 - e**2)))
    constant = np.sqrt(1 - e**2) * np.cos(np.radians(inc)) + 0.005 * np.sin(60 * times)
    mean_times = times[:390].reshape(39, 10).mean(axis=1)
    runs = {"rebound": None, "heyoka": None}
    return KozaiHistory("a test particle at a = 1, e0 = 0.01, i0 = 65 deg, and an equal mass at 12 (circular), "
                        f"for {cycles:g} cycles", times, dict.fromkeys(runs, e), dict.fromkeys(runs, inc),
                        dict.fromkeys(runs, constant), mean_times, dict.fromkeys(runs, 0.4226 + 0 * mean_times),
                        0.8380, 39.23, 0.4226, period, 0.017, 0.5 * period)


def test_kozai_cycles_mark_the_quadrupole_prediction(tmp_path):
    history = kozai_like()
    fig, panels = kozai_cycles(history)
    e_ax, i_ax, c_ax = panels
    level = [line for line in e_ax.get_lines() if line.get_ydata()[0] == history.e_max]
    assert level and level[0].get_linestyle() == "--"
    peaks = sorted({line.get_xdata()[0] for line in e_ax.get_lines() if line.get_linestyle() == ":"})
    assert peaks == pytest.approx([0.5 * history.period, 1.5 * history.period])  # e_max at half a period, then each
    assert any(line.get_ydata()[0] == history.inclination_at_e_max for line in i_ax.get_lines())
    assert any(line.get_ydata()[0] == history.start for line in c_ax.get_lines())
    assert r"$\sqrt{1-e^2}\,\cos i$" in c_ax.get_ylabel() and r"$\tau$" in c_ax.get_xlabel()
    labels = legend_labels(fig)
    assert len(labels) == len(set(labels)) and any("0.838," in label for label in labels)
    assert problems(fig) == []
    save(fig, tmp_path / "kozai.png")


def test_drag_decay_ends_the_closed_form_where_it_stops_holding(tmp_path):
    """The standard band from 280 km: the curve ends at the band's base when the lifetime is up; a band from the
    surface of Mars: it ends at the breakdown altitude, 157.3 km, drawn in hours or days as the lifetime asks."""
    decay = DragDecay.of("Earth", altitude=280 * u.km, ballistic=0.022 * u.m**2 / u.kg)
    fig, panels = drag_decay(decay)
    ax = panels[0]
    curve = ax.get_lines()[0].get_xydata()
    assert curve[0] == pytest.approx([0.0, 280.0]) and curve[-1] == pytest.approx([5.98841, 250.0], rel=1e-5)
    star = [line for line in ax.get_lines() if line.get_marker() == "*"][0].get_xydata()[0]
    assert star == pytest.approx([5.98841, 250.0], rel=1e-5) and ax.get_xlabel() == "time [d]"
    assert any("band's base" in label for label in legend_labels(fig))
    assert problems(fig) == []
    mars = DragDecay.of("Mars", altitude=200 * u.km, ballistic=0.01 * u.m**2 / u.kg, density=0.020 * u.kg / u.m**3,
                        scale_height=11.1 * u.km, base_altitude=0 * u.km)
    fig, panels = drag_decay(mars)
    star = [line for line in panels[0].get_lines() if line.get_marker() == "*"][0].get_xydata()[0]
    assert star[1] == pytest.approx(mars.breakdown_altitude.to_value(u.km), rel=1e-12)
    assert any("reaches H" in label for label in legend_labels(fig))
    assert panels[0].get_ylim()[0] > 100.0  # the band's base at the surface does not stretch the axis
    assert problems(fig) == []
    short = DragDecay.of("Earth", altitude=175 * u.km, ballistic=0.063 * u.m**2 / u.kg)
    assert drag_decay(short)[1][0].get_xlabel() == "time [h]"  # a lifetime of 1.39 h
    save(fig, tmp_path / "decay.png")


def test_drag_decay_draws_the_integrations_and_their_difference(tmp_path):
    decay = DragDecay.of("Earth", altitude=280 * u.km, ballistic=0.022 * u.m**2 / u.kg)
    days = np.linspace(0.0, decay.lifetime.to_value(u.day), 161)[1:]
    closed = decay.altitude_after(days * u.day).to_value(u.km)
    mean_days = days.reshape(10, 16).mean(axis=1)
    mean_closed = decay.altitude_after(mean_days * u.day).to_value(u.km)
    history = DecayHistory(decay, days, {"rebound": closed, "heyoka": closed}, mean_days,
                           {"rebound": mean_closed + 1e-4, "heyoka": mean_closed + 1e-4})
    fig, panels = drag_decay(decay, history)
    assert len(panels) == 2
    difference = panels[1].get_lines()[0].get_ydata()
    np.testing.assert_allclose(difference, 0.1, rtol=1e-6)  # 1e-4 km = 0.1 m
    labels = legend_labels(fig)
    assert len(labels) == len(set(labels)) == 7
    assert problems(fig) == []
    save(fig, tmp_path / "decay.png")


def test_frozen_eccentricity_circles_the_frozen_point(tmp_path):
    """Mean eccentricity vectors on circles about e = 1.043e-3 at omega = 90 deg (radii 0.46e-3 and 1.14e-3, as
    frozen_history gives them at 700 km): the star on the frozen point, the closed form's circle through the
    origin, both backends' curves in units of 1e-3, each legend entry once."""
    e, angle = 1.043e-3, np.linspace(0.0, 2.0 * np.pi, 200)

    def circle(radius):
        return radius * np.cos(angle), e + radius * np.sin(angle)

    runs = ("rebound", "heyoka")
    history = FrozenHistory("700 km at i = 98.19 deg about Earth, 1688 revolutions (115.8 d)",
                            dict.fromkeys(runs, circle(0.46e-3)), dict.fromkeys(runs, circle(1.14e-3)), e, 90.0,
                            115.8, 1688, 9.8e-4)
    fig, ax = frozen_eccentricity(history)
    star = [line for line in ax.get_lines() if line.get_marker() == "*"][0].get_xydata()[0]
    assert star == pytest.approx([0.0, 1.043], abs=1e-12)
    theory = [line for line in ax.get_lines() if line.get_linestyle() == "--" and line.get_color() == "0.15"][0]
    assert np.min(np.hypot(*theory.get_xydata().T)) == pytest.approx(0.0, abs=1e-3)  # through the origin
    assert len([line for line in ax.get_lines() if len(line.get_xdata()) == 200]) == 4
    labels = legend_labels(fig)
    assert len(labels) == len(set(labels)) and any(r"$\omega$" in label for label in labels)
    assert "115.8 d" in fig.get_suptitle() and problems(fig) == []
    save(fig, tmp_path / "frozen.png")


def test_ground_track_breaks_at_the_date_line_and_measures_each_node(tmp_path):
    """Three revolutions in a day (nodes 120 deg apart), the second backend's nodes drifting 1 km a revolution: no
    track segment crosses the map, the nodes sit on the equator, the right panel shows 0, 1, 2, 3 km over the
    closed form's zero line, and the legend names each cycle's closure once."""
    revolutions, per, km_per_deg = 3, 200, 111.32
    phase = np.linspace(0.0, 2.0 * np.pi * revolutions, revolutions * per + 1)
    longitude = (np.degrees(phase) - 120.0 * phase / (2.0 * np.pi) + 180.0) % 360.0 - 180.0
    latitude = np.degrees(np.arcsin(np.sin(np.radians(98.0)) * np.sin(phase)))
    nodes = -480.0 * np.arange(revolutions + 1)
    drifting = nodes + np.arange(revolutions + 1) / km_per_deg
    track = GroundTrack("3 revolutions in 1 day", phase / (2 * np.pi), {"rebound": longitude, "heyoka": longitude},
                        {"rebound": latitude, "heyoka": latitude}, {"rebound": nodes, "heyoka": drifting},
                        {"rebound": 0.0, "heyoka": 3.0}, revolutions, 1, 8.7e-4, km_per_deg)
    fig, (world, closing) = ground_track(track)
    for line in (line for line in world.get_lines() if line.get_linestyle() != "None"):  # the tracks, not the nodes
        steps = np.abs(np.diff(line.get_xdata()))
        assert np.all(steps[np.isfinite(steps)] <= 180.0)
    heyoka = [line for line in closing.get_lines() if line.get_label().startswith("heyoka")][0]
    assert heyoka.get_ydata() == pytest.approx([0.0, 1.0, 2.0, 3.0], abs=1e-9)
    labels = legend_labels(fig)
    assert len(labels) == len(set(labels)) and any("3 km east of its start" in label for label in labels)
    assert problems(fig) == []
    save(fig, tmp_path / "track.png")
