"""`orbits perturb`: tables in natural units, exact JSON, one-line errors with exit status 2."""

import json

import pytest
from typer.testing import CliRunner

from orbits_cli.main import app

runner = CliRunner()


def run(*args):
    return runner.invoke(app, list(args), standalone_mode=True)


def test_sun_synchronous_table_and_json():
    table = run("perturb", "sun-synchronous", "--altitude", "700 km")
    assert table.exit_code == 0 and "98.18776   deg" in table.stdout and "0.9856474   deg / d" in table.stdout
    data = json.loads(run("perturb", "sun-synchronous", "--altitude", "700 km", "--format", "json").stdout)
    assert data["inclination"]["unit"] == "rad" and abs(data["inclination"]["value"] - 1.71369) < 1e-5


@pytest.mark.parametrize("args, shown", [
    (("rates", "--altitude", "400 km", "--inc", "51.64"), "-4.998052   deg / d"),
    (("decay", "--altitude", "280 km", "--ballistic", "0.022 m2/kg"), "5.988406   d"),
    (("kozai",), "0.8380471"),
    (("relativity", "Mercury"), "42.98048   arcsec"),
    (("repeat", "--revolutions", "127", "--days", "10", "--inc", "66.04"), "7714.397   km"),
])
def test_verbs(args, shown):
    result = run("perturb", *args)
    assert result.exit_code == 0, result.output
    assert shown in result.stdout


@pytest.mark.parametrize("args", [
    ("rates", "Ceres", "--a", "1000 km"),
    ("sun-synchronous", "--a", "20000 km", "--e", "0.1"),
    ("decay", "--altitude", "300 km", "--density", "1e-11 kg/m3", "--scale-height", "50 km", "--base-altitude",
     "350 km"),
    ("decay", "--altitude", "160 km", "--ballistic", "0.1 m2/kg"),
    ("rates", "--altitude", "400 km", "--plot", "rates.png", "--plot-revolutions", "0"),
    ("rates", "--altitude", "400 km", "--plot", "rates.txt"),
    ("frozen", "--altitude", "700 km", "--inc", "98.19", "--plot", "f.png", "--plot-revolutions", "4001"),
    ("repeat", "--revolutions", "2001", "--days", "137", "--inc", "98", "--plot", "t.png"),
    ("kozai", "--plot", "kozai.png"),  # 2 cycles of Jupiter's pull on a 1 AU orbit: 472,500 revolutions
    ("kozai", "--inc", "200"),  # an inclination lies in [0, 180] deg on every verb, never read as 160
    ("kozai", "--inc", "-30"),
    ("frozen", "--altitude", "700 km", "--inc", "200"),
    ("rates", "--altitude", "400 km", "--inc", "190"),
    ("rates", "--altitude", "-100 km"),  # inside the body: refused here as by sun-synchronous
    ("kozai", "--primary", "1 solMass", "--perturber", "1 solMass", "--a-out", "12 AU", "--cycles", "5", "--plot",
     "k.png"),
    ("kozai", "--primary", "1 solMass", "--perturber", "1e-9 solMass", "--a-out", "1.5 AU", "--cycles", "0.1",
     "--plot", "k.png"),
])
def test_bad_inputs_exit_2_with_one_line(args, tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    result = run("perturb", *args)
    assert result.exit_code == 2
    assert result.stderr.count("\n") == 1 and result.stderr.startswith("orbits: error: ")
    assert result.stdout == "" and not list(tmp_path.iterdir())


@pytest.mark.parametrize("args, shown", [
    (("kozai", "--inc", "200"), "inclination i = 200 deg is outside the allowed range [0, 180] deg"),
    (("kozai", "--inc", "-30"), "inclination i = -30 deg is outside the allowed range [0, 180] deg"),
    (("frozen", "--altitude", "700 km", "--inc", "200"), "inclination i = 200 deg is outside"),
    (("sun-synchronous", "--inc", "190"), "inclination i = 190 deg is outside"),
    (("repeat", "--revolutions", "15", "--days", "1", "--e", "0.99"), "periapsis a (1 - e) = 69.32"),
])
def test_a_domain_error_names_the_quantity(args, shown):
    """An inclination is checked by the one rule, said in the unit given; a repeat orbit whose periapsis would lie
    inside the body is said so (its solve overflowed, and the line said only that float64 was left)."""
    result = run("perturb", *args)
    assert result.exit_code == 2 and shown in result.stderr


def test_plots_are_written_where_a_picture_exists(tmp_path):
    """rates and sun-synchronous integrate the orbit (rebound and heyoka) for their picture, kozai the triple; decay
    draws the closed form. Each writes its PNG, and the table is printed as without --plot."""
    molniya = ("rates", "--a", "26554 km", "--e", "0.74", "--inc", "63.43", "--argp", "270", "--plot-revolutions", "3")
    for args, name in ((molniya, "rates.png"), (("sun-synchronous", "--altitude", "700 km", "--plot-revolutions", "2"),
                                                 "sso.png"),
                       (("decay", "--altitude", "280 km", "--ballistic", "0.022 m2/kg"), "decay.png"),
                       (("kozai", "--primary", "1 solMass", "--perturber", "1 solMass", "--a-out", "12 AU",
                         "--e", "0.01", "--cycles", "0.6"), "kozai.png"),
                       (("frozen", "--altitude", "700 km", "--inc", "98.19", "--plot-revolutions", "20"), "frozen.png"),
                       (("repeat", "--revolutions", "15", "--days", "1", "--inc", "98"), "track.png")):
        path = tmp_path / name
        result = run("perturb", *args, "--plot", str(path))
        assert result.exit_code == 0, result.output
        assert path.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
        table_only = [x for k, x in enumerate(args) if x not in ("--plot-revolutions", "--cycles")
                      and (k == 0 or args[k - 1] not in ("--plot-revolutions", "--cycles"))]
        assert result.stdout == run("perturb", *table_only).stdout
        if table_only != list(args):  # the options only --plot reads are refused without it
            assert run("perturb", *args).exit_code == 2
