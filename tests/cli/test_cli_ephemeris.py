"""`orbits where`, `orbits orbit BODY --epoch` and the body table of `orbits info`: values against the library
(itself tested against astropy reading the same kernel), exit codes and one-line errors."""

import json

import astropy.units as u
import pytest
from typer.testing import CliRunner

from orbits import Orbit
from orbits.ephemeris import positions as ephemeris
from orbits_cli.main import app

runner = CliRunner()


def run(*args):
    return runner.invoke(app, list(args))


def test_where_gives_distances_elongation_and_light_time_in_json():
    result = run("where", "Mars", "--epoch", "2026-11-25", "--format", "json")
    assert result.exit_code == 0, result.output
    data = json.loads(result.stdout)
    seen = ephemeris.where("Mars", "2026-11-25")
    assert data["observer_distance"] == {"value": seen.observer_distance.to_value(u.m), "unit": "m"}
    assert data["elongation"]["value"] == seen.elongation.to_value(u.rad)
    assert data["light_time"]["value"] == pytest.approx(data["observer_distance"]["value"] / 299_792_458.0, rel=1e-15)


def test_where_table_names_the_source_and_the_point():
    result = run("where", "jupiter", "--epoch", "2026-11-25 TDB", "--observer", "Mars")
    assert result.exit_code == 0, result.output
    assert "Jupiter system barycentre" in result.stdout and "DE421" in result.stdout
    assert max(len(line) for line in result.stdout.splitlines()) <= 80


def test_orbit_at_an_epoch_is_the_osculating_orbit():
    result = run("orbit", "Mars", "--epoch", "2026-11-25", "--format", "json", "--only", "semi_major_axis")
    assert result.exit_code == 0, result.output
    expected = Orbit.from_body("Mars", "2026-11-25").semi_major_axis.to_value(u.m)
    assert json.loads(result.stdout)["semi_major_axis"]["value"] == expected


@pytest.mark.parametrize("args, message", [
    (["where", "Marz"], "did you mean Mars"),
    (["where", "Mars", "--epoch", "1800-01-01"], "outside DE421"),
    (["where", "Mars", "--epoch", "soon"], "is not a date"),
    (["where", "Mars", "--ephemeris", "de440"], "de440"),
    (["orbit", "--epoch", "2026-11-25"], "needs a BODY"),
    (["orbit", "Mars", "--epoch", "2026-11-25", "--a", "1 AU"], "drop the elements"),
    (["orbit", "Titan", "--epoch", "2026-11-25"], "not in the ephemeris"),
    (["where", "Mars", "--epoch", "2026-11-25", "--observer", "Sun"], "must not be the Sun"),
])
def test_bad_input_is_one_line_with_exit_status_2(args, message):
    result = run(*args)
    assert result.exit_code == 2
    lines = result.output.strip().splitlines()
    assert len(lines) == 1 and message in lines[0]


def test_info_lists_the_catalogue():
    result = run("info", "--format", "json")
    assert result.exit_code == 0, result.output
    bodies = {b["name"]: b for b in json.loads(result.stdout)["bodies"]}
    assert bodies["Titan"]["parent"] == "Saturn" and bodies["Venus"]["retrograde"] is True
    assert bodies["Neptune"]["j2_radius_m"] == 25_225e3 and bodies["Pallas"]["kind"] == "asteroid"
    table = run("info").stdout
    assert "Ganymede" in table and max(len(line) for line in table.splitlines()) <= 80
    assert "…" not in table  # no column cut short
    # J2 is shown (times 1e6) with the reference radius of its fit, not alone
    neptune = next(line for line in table.splitlines() if line.split()[:1] == ["Neptune"]).split()
    assert neptune[-2:] == ["3408.43", "25225"]
    assert "@ R km" in table


def test_where_help_offers_only_observers_it_accepts():
    text = " ".join(run("where", "--help").stdout.replace("│", " ").split())
    assert "a planet, Pluto, the Moon or a barycentre (not the Sun" in text


@pytest.mark.parametrize("body_name", ["Mars", "Saturn", "Moon"])
def test_where_plots_the_sky_at_that_date(tmp_path, body_name):
    target = tmp_path / f"{body_name}.png"
    result = run("where", body_name, "--epoch", "2026-11-25", "--plot", str(target), "--only", "elongation")
    assert result.exit_code == 0, result.output
    assert target.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n" and target.stat().st_size > 20_000
    assert "elongation" in result.stdout


def test_where_plot_refuses_an_unknown_format_before_any_work(tmp_path):
    result = run("where", "Mars", "--plot", str(tmp_path / "sky.gif"))
    assert result.exit_code == 2 and "must end in .png, .svg or .pdf" in result.output
