"""`orbits porkchop`: the tables, exact SI JSON with the dates, the picture, one-line errors with exit status 2."""

import json

import astropy.units as u
import pytest
from typer.testing import CliRunner

from orbits import Porkchop
from orbits_cli.main import app

COARSE = ["--depart", "2026-09-01:2027-01-31", "--arrive", "2027-06-01:2028-03-01", "--step", "10 d"]


def run(*args):
    return CliRunner().invoke(app, ["porkchop", *args])


def test_table_names_the_minima_and_their_dates():
    result = run(*COARSE)
    assert result.exit_code == 0, result.output
    assert "least C3: 2026-10-31 -> 2027-08-20" in result.output and "9.183492" in result.output
    assert "least arrival v_inf" in result.output and "least total v_inf" in result.output
    assert "jd_tdb" not in result.output and "nan" not in result.output
    assert max(map(len, result.output.splitlines())) <= 80


def test_json_is_the_library_exactly_with_julian_dates():
    result = run(*COARSE, "--format", "json")
    assert result.exit_code == 0, result.output
    data = json.loads(result.output)
    chart = Porkchop.between("Earth", "Mars", ("2026-09-01", "2027-01-31"), ("2027-06-01", "2028-03-01"),
                             10 * u.day)
    assert data["min_c3_c3"] == {"value": chart.minimum_c3.c3_si, "unit": "m2 / s2"}
    assert data["min_c3_launch_jd_tdb"]["value"] == chart.minimum_c3.launch.tdb.jd
    assert data["min_total_arrival_jd_tdb"]["value"] == chart.minimum_total.arrival.tdb.jd


def test_plot_file(tmp_path):
    target = tmp_path / "porkchop.png"
    result = run(*COARSE, "--plot", str(target))
    assert result.exit_code == 0, result.output
    assert target.stat().st_size > 10_000


@pytest.mark.parametrize("args, message", [
    (["--to", "Vulcan", *COARSE], "no ephemeris for 'Vulcan'"),
    (["--depart", "2026-09-01", "--step", "10 d"], "--depart '2026-09-01': write START:END"),
    (["--depart", "2028-01-01:2028-02-01", "--arrive", "2027-01-01:2027-03-01"], "no transfer has a positive"),
    (["--depart", "2060-01-01:2060-02-01", "--arrive", "2060-06-01:2060-09-01", "--step", "10 d"], "outside DE421"),
    ([*COARSE[:4], "--step", "-1 d"], "date step"),
    ([*COARSE[:4], "--step", "5 kg"], "--step"),
])
def test_bad_input_is_one_line_and_exit_2(args, message):
    result = run(*args)
    assert result.exit_code == 2, result.output
    lines = result.output.strip().splitlines()
    assert len(lines) == 1 and lines[0].startswith("orbits: error:") and message in lines[0]


def test_a_least_value_on_the_grid_edge_is_flagged_in_the_table_and_the_json():
    edge = ["--depart", "2026-09-01:2026-10-15", "--arrive", "2027-06-01:2027-11-01", "--step", "15 d"]
    table = run(*edge)
    assert table.exit_code == 0, table.output
    assert "least C3 on the grid's edge (last launch date): the minimum may lie outside" in " ".join(
        table.output.split())
    assert "(edge)" in table.output
    data = json.loads(run(*edge, "--format", "json").stdout)
    assert data["about"]["min_c3_edge"].startswith("least C3 on the grid's edge (last launch date)")
    assert "about" not in json.loads(run(*COARSE, "--format", "json").stdout)


def test_a_misspelt_row_is_refused_before_the_grid_is_computed(monkeypatch):
    """--only is checked against the chart's names before any transfer is solved (it was refused after 25 s of a
    large grid's work); the names checked are the ones the chart gives."""
    from orbits.manoeuvres.porkchop import QUANTITY_NAMES

    chart = Porkchop.between("Earth", "Mars", ("2026-09-01", "2026-10-01"), ("2027-06-01", "2027-07-01"),
                             step=15 * u.day)
    assert list(chart.quantities()) == QUANTITY_NAMES
    monkeypatch.setattr(Porkchop, "between", classmethod(lambda *a, **k: pytest.fail("the grid was computed")))
    result = run("--depart", "2026-01-01:2028-09-27", "--arrive", "2026-06-01:2029-02-25", "--only",
                 "min_c3_cc3")
    assert result.exit_code == 2 and "unknown quantities ['min_c3_cc3']" in result.output
