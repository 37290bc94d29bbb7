"""orbits.Porkchop (orbits/porkchop.py) and plot.porkchop: cell values against independent references, the grid's
minima, masking, errors and what the picture draws.

Published values: no citeable published minimum C3 or arrival v_inf for an Earth-Mars opportunity was found with
the search tools available when this was written (NASA/TM-1998-208533, George and Kos 1998, "Interplanetary Mission
Design Handbook: Earth-to-Mars Mission Opportunities and Mars-to-Earth Return Opportunities 2009-2024", has the
tables, but its figures could not be read there). The minima are therefore checked for convergence in the grid step
and cell by cell against astropy's reading of DE421 and the mpmath propagator, not against a published number.
"""

import astropy.units as u
import matplotlib
import numpy as np
import pytest
from astropy.time import Time

from orbits import OrbitDomainError, Porkchop, ephemeris
from orbits.tools.reference import propagate

matplotlib.use("Agg")

KM2 = u.km**2 / u.s**2
LAUNCH_2026 = ("2026-09-01", "2027-01-31")
ARRIVAL_2027 = ("2027-06-01", "2028-03-01")


@pytest.fixture(scope="module")
def chart():
    return Porkchop.between("Earth", "Mars", LAUNCH_2026, ARRIVAL_2027, step=10 * u.day)


def _astropy_heliocentric(name, when):
    """Position (m) and velocity (m/s) from astropy reading the same DE421 file, Sun-centred, ICRF."""
    from astropy.coordinates import get_body_barycentric_posvel

    kernel = ephemeris.kernel_path()
    r, v = get_body_barycentric_posvel(name.lower(), when, ephemeris=kernel)
    r_sun, v_sun = get_body_barycentric_posvel("sun", when, ephemeris=kernel)
    return (r - r_sun).xyz.to_value(u.m), (v - v_sun).xyz.to_value(u.m / u.s)


@pytest.mark.parametrize("row, col", [(0, 0), (12, 6), (27, 15), (20, 3)])
def test_v1_reaches_mars_and_c3_is_recomputed_from_astropy(chart, row, col):
    launch, arrival = chart.launch_dates[col], chart.arrival_dates[row]
    r_earth, v_earth = _astropy_heliocentric("Earth", launch)
    r_mars, v_mars = _astropy_heliocentric("Mars", arrival)
    tof = (arrival - launch).to_value(u.s)
    v1 = chart.v1[row, col].unmasked.to_value(u.m / u.s)
    r, v = propagate(r_earth, v1, chart.mu, tof)
    miss = np.linalg.norm(np.array([float(x) for x in r]) - r_mars) / np.linalg.norm(r_mars)
    assert miss < 1e-13  # measured 2.6e-16 .. 1.1e-14 (astropy and jplephem read DE421 alike)
    v2 = np.array([float(x) for x in v])
    c3 = np.sum((v1 - v_earth) ** 2)
    c3_cell = chart.c3[row, col].unmasked.to_value(u.m**2 / u.s**2)
    assert c3_cell == pytest.approx(c3, rel=1e-13)  # measured 2.2e-16
    v_inf = np.linalg.norm(v2 - v_mars)
    v_inf_cell = chart.arrival_v_inf[row, col].unmasked.to_value(u.m / u.s)
    assert v_inf_cell == pytest.approx(v_inf, rel=1e-12)  # measured 2.9e-14
    assert chart.time_of_flight[row, col].unmasked.to_value(u.s) == pytest.approx(tof, rel=1e-12)


def test_transfers_are_prograde_about_the_ecliptic_pole(chart):
    h = np.cross(np.broadcast_to(chart.r_departure, chart.v1_si.shape), chart.v1_si)[chart.valid]
    assert np.all(h @ ephemeris_pole() > 0)


def ephemeris_pole():
    """The ecliptic pole of J2000 in the ICRF: (0, -sin eps, cos eps), eps = 84381.448 arcsec."""
    eps = np.radians(84381.448 / 3600)
    return np.array([0.0, -np.sin(eps), np.cos(eps)])


def test_minima_converge_with_the_grid_step():
    """The least C3 on a 5-day grid lies within the quadratic error of the step of a 1-day grid's."""
    fine = Porkchop.between("Earth", "Mars", ("2026-10-15", "2026-11-20"), ("2027-07-20", "2027-10-01"), 1 * u.day)
    coarse = Porkchop.between("Earth", "Mars", LAUNCH_2026, ARRIVAL_2027, step=5 * u.day)
    best, rough = fine.minimum_c3, coarse.minimum_c3
    assert best.c3.to_value(KM2) == pytest.approx(9.1835, abs=5e-4)  # measured 9.18349 on 2026-10-31 -> 2027-08-20
    assert rough.c3.to_value(KM2) >= best.c3.to_value(KM2) - 1e-9
    assert rough.c3.to_value(KM2) - best.c3.to_value(KM2) < 0.05  # 5 d steps; measured 2e-11 (same cell)
    assert abs((rough.launch - best.launch).to_value(u.day)) <= 5 and abs((rough.arrival - best.arrival).to_value(
        u.day)) <= 5
    total = fine.total_v_inf.min().to_value(u.km / u.s)
    assert fine.minimum_total.total_v_inf.to_value(u.km / u.s) == pytest.approx(float(total), rel=1e-15)
    assert fine.minimum_arrival_v_inf.arrival_v_inf <= fine.minimum_c3.arrival_v_inf


def test_cells_without_a_positive_time_of_flight_are_masked_never_nan():
    p = Porkchop.between("Earth", "Mars", ("2026-10-01", "2026-12-01"), ("2026-11-01", "2027-09-01"), 10 * u.day)
    assert p.shape == (31, 7) and not p.valid.all() and p.valid.any()
    np.testing.assert_array_equal(p.c3.mask, ~p.valid)
    np.testing.assert_array_equal(p.time_of_flight.mask, ~p.valid)
    assert np.all(p.time_of_flight.unmasked[p.valid] > 0)
    text = repr(p) + repr(p.minimum_c3) + str(p.c3)
    assert "nan" not in text.lower() and "\n" not in repr(p) and "\n" not in repr(p.minimum_c3)
    assert p.minimum_c3.time_of_flight > 0


def test_quantities_and_repr(chart):
    q = chart.quantities()
    assert {"min_c3_c3", "min_arrival_v_inf_arrival_v_inf", "min_total_total_v_inf", "min_c3_launch_jd_tdb"} <= set(q)
    assert q["min_c3_c3"] == chart.minimum_c3.c3
    assert q["min_c3_launch_jd_tdb"].to_value(u.day) == chart.minimum_c3.launch.tdb.jd
    assert set(chart.quantities(["min_c3_c3"])) == {"min_c3_c3"}
    assert repr(chart).startswith("Porkchop(Earth to Mars, launch 2026-09-01..2027-01-29 x arrival 2027-06-01.."
                                  "2028-02-26, 16 x 28 dates, min C3 = 9.183 km2 / s2 (2026-10-31 -> 2027-08-20)")
    assert "_jd_tdb" not in chart._repr_html_()


@pytest.mark.parametrize("kwargs, message", [
    (dict(launch=("2028-01-01", "2028-02-01"), arrival=("2027-01-01", "2027-03-01")),
     "the arrival window ends .* before the launch window starts"),
    (dict(launch=("2060-01-01", "2060-02-01"), arrival=("2060-06-01", "2060-09-01")), "outside DE421"),
    (dict(launch=("2027-01-01", "2026-01-01"), arrival=ARRIVAL_2027), "launch window: the end .* is before"),
    (dict(launch=LAUNCH_2026, arrival=ARRIVAL_2027, step=0 * u.day), "date step"),
    (dict(launch=LAUNCH_2026, arrival=ARRIVAL_2027, step=1 * u.min), "cells; at most"),
    (dict(launch="2026-09-01", arrival=ARRIVAL_2027), "give \\(start, end\\) dates"),
])
def test_bad_windows_are_one_line_errors(kwargs, message):
    with pytest.raises(OrbitDomainError, match=message) as err:
        Porkchop.between("Earth", "Mars", **kwargs)
    assert "\n" not in str(err.value)


@pytest.mark.parametrize("a, b, message", [("Earth", "Vulcan", "no ephemeris for 'Vulcan'"),
                                           ("Sun", "Mars", "Sun cannot be a departure or target"),
                                           ("mars", "Mars", "both Mars")])
def test_bad_bodies(a, b, message):
    with pytest.raises(OrbitDomainError, match=message):
        Porkchop.between(a, b, LAUNCH_2026, ARRIVAL_2027, 10 * u.day)


def test_the_picture_draws_contours_and_marks_the_minima(chart, tmp_path):
    import matplotlib.pyplot as plt

    from orbits.plot import porkchop, save

    fig, ax = porkchop(chart)
    try:
        sets = {c.get_gid(): c for c in ax.collections if c.get_gid()}
        assert set(sets) == {"C3", "arrival v_inf", "time of flight"}
        c3_levels = np.asarray(sets["C3"].levels)
        least = chart.minimum_c3.c3.to_value(KM2)
        assert len(c3_levels) >= 5 and c3_levels.min() > least and c3_levels.max() < chart.c3.max().to_value(KM2)
        marks = [line for line in ax.get_lines() if line.get_gid() == "minimum"]
        assert len(marks) == 3
        star = marks[0].get_xydata()[0]
        assert star[0] == pytest.approx(chart.minimum_c3.launch.tdb.jd - 2440587.5)
        assert star[1] == pytest.approx(chart.minimum_c3.arrival.tdb.jd - 2440587.5)
        assert "least C3: 2026-10-30" in marks[0].get_label() or "least C3: 2026-10-31" in marks[0].get_label()
        assert ax.get_xlabel() == "launch date [TDB]" and ax.get_ylabel() == "arrival date [TDB]"
        assert ax.xaxis.get_major_formatter().fmt == "%Y-%m-%d"
        save(fig, tmp_path / "porkchop.png")
        assert (tmp_path / "porkchop.png").stat().st_size > 10_000
    finally:
        plt.close(fig)


def test_dates_are_on_the_grid(chart):
    assert chart.launch_dates.scale == "tdb" and chart.launch_dates.size == 16
    steps = np.diff(chart.launch_dates.jd)
    np.testing.assert_allclose(steps, 10.0, rtol=0, atol=1e-9)
    assert abs((chart.launch_dates[0] - Time("2026-09-01", scale="utc")).to_value(u.s)) < 1e-6
