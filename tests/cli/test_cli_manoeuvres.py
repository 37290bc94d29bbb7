"""The verbs `orbits rocket` and `orbits transfer` (hohmann, bi-elliptic, plane-change, phasing, departure): JSON
values against the library and published figures, tables, and one-line errors with exit status 2."""

import json
import math

import pytest
from typer.testing import CliRunner

from orbits_cli.main import app

runner = CliRunner()


def run_json(*args):
    result = runner.invoke(app, [*args, "--format", "json"])
    assert result.exit_code == 0, result.output
    return json.loads(result.stdout)


def test_hohmann_leo_to_geo():
    """Wikipedia's example: 6678 km to 42164 km, 2.42 + 1.46 km/s (rounded speeds); 3.893 km/s unrounded."""
    data = run_json("transfer", "hohmann", "--radius1", "6678 km", "--radius2", "42164 km")
    assert data["delta_v"]["unit"] == "m / s" and round(data["delta_v"]["value"] / 1e3, 3) == 3.893
    assert abs(data["first_burn"]["value"] / 1e3 - 2.42) < 0.01
    assert abs(data["second_burn"]["value"] / 1e3 - 1.46) < 0.01
    assert round(data["transfer_time"]["value"] / 3600, 3) == 5.275
    turned = run_json("transfer", "hohmann", "--radius1", "6678 km", "--radius2", "42164 km", "--inc", "28.5",
                      "--only", "delta_v")
    assert list(turned) == ["delta_v"] and round(turned["delta_v"]["value"] / 1e3, 3) == 4.256


def test_bielliptic_plane_change_phasing_departure():
    bi = run_json("transfer", "bi-elliptic", "--radius1", "7000 km", "--radius2", "105000 km", "--apoapsis",
                  "210000 km")
    assert bi["saving"]["value"] > 0 and bi["hohmann_delta_v"]["value"] > bi["delta_v"]["value"]
    turn = run_json("transfer", "plane-change", "--radius", "7000 km", "--inc", "60 deg")
    assert turn["delta_v"]["value"] == pytest.approx(turn["speed"]["value"], rel=1e-15)
    chase = run_json("transfer", "phasing", "--radius", "7000 km", "--phase", "20", "--revolutions", "2")
    assert chase["burn"]["value"] < 0 and chase["delta_v"]["value"] == 2 * abs(chase["burn"]["value"])
    away = run_json("transfer", "departure", "--primary", "Earth", "--radius", "6678 km", "--v-inf", "0.001 m/s")
    assert away["departure_speed"]["value"] == pytest.approx(math.sqrt(2) * away["parking_speed"]["value"], rel=1e-12)


def test_rocket_single_and_staged():
    one = run_json("rocket", "--m0", "100 t", "--mf", "40 t", "--isp", "300 s", "--thrust", "2 MN",
                   "--g", "9.80665 m/s2")
    assert one["delta_v"]["value"] == pytest.approx(300 * 9.80665 * math.log(2.5), rel=1e-15)
    assert one["burn_time"]["unit"] == "s" and one["burn_time"]["value"] == pytest.approx(60e3 * 300 * 9.80665 / 2e6)
    assert one["vertical_ascent_speed"]["value"] == pytest.approx(
        one["delta_v"]["value"] - 9.80665 * one["burn_time"]["value"], rel=1e-14)
    staged = run_json("rocket", "--propellant", "80 t", "--propellant", "15 t", "--structure", "8 t",
                      "--structure", "2 t", "--payload", "1 t", "--exhaust-speed", "3 km/s")
    expected = 3000 * (math.log(106 / 26) + math.log(18 / 3))
    assert staged["delta_v"]["value"] == pytest.approx(expected, rel=1e-15)
    assert staged["stage_delta_v"]["value"] == pytest.approx([3000 * math.log(106 / 26), 3000 * math.log(6)])
    alone = run_json("rocket", "--propellant", "80 t", "--structure", "8 t", "--payload", "1 t", "--isp", "300 s")
    assert alone["delta_v"]["value"] == pytest.approx(300 * 9.80665 * math.log(89 / 9), rel=1e-15)  # one stage


def test_tables_fit_80_columns():
    for args in (["transfer", "hohmann", "--radius1", "6678 km", "--radius2", "42164 km"],
                 ["rocket", "--propellant", "2100 t", "--propellant", "440 t", "--propellant", "110 t",
                  "--structure", "130 t", "--structure", "40 t", "--structure", "13 t", "--payload", "45 t",
                  "--isp", "263 s", "--isp", "421 s", "--isp", "421 s", "--thrust", "34 MN", "--thrust", "5.1 MN",
                  "--thrust", "1 MN"]):
        result = runner.invoke(app, args)
        assert result.exit_code == 0, result.output
        assert "delta_v" in result.stdout and max(map(len, result.stdout.splitlines())) <= 80


@pytest.mark.parametrize("args, message", [
    (["transfer", "bi-elliptic", "--radius1", "7000 km", "--radius2", "105000 km", "--apoapsis", "2e4 km"],
     "intermediate radius rb = 20000000.0 m is outside the allowed range"),
    (["transfer", "hohmann", "--radius1", "300 km", "--radius2", "42164 km"], "is inside Earth"),
    (["transfer", "hohmann", "--radius1", "6678", "--radius2", "42164 km"], "has no unit"),
    (["transfer", "phasing", "--radius", "7000 km", "--phase", "300"], "phase = "),
    (["transfer", "hohmann", "--from", "Earth", "--to", "earth"], "Hohmann: both ends are Earth"),
    (["transfer", "plane-change", "--radius", "7000 km", "--inc", "200"],
     "inclination change = 200 deg is outside the allowed range [0, 180] deg"),
    (["rocket", "--m0", "1 t", "--mf", "2 t", "--isp", "300 s"], "final mass mf = 2000.0 kg is outside"),
    (["rocket", "--m0", "2 t", "--mf", "1 t"], "exactly one of exhaust_speed"),
    (["rocket", "--m0", "2 t", "--mf", "1 t", "--isp", "300 s", "--thrust", "3 km"], "not a force"),
    (["rocket", "--m0", "2 t", "--propellant", "1 t", "--isp", "300 s"], "give --m0 and --mf"),
    (["rocket", "--propellant", "1 t", "--structure", "1 t", "--structure", "1 t", "--payload", "1 t",
      "--isp", "300 s"], "1 --propellant but 2 --structure"),
    (["rocket", "--m0", "2 t", "--mf", "1 t", "--isp", "300 s", "--isp", "200 s"], "2 --isp for 1 stage"),
    (["rocket", "--propellant", "1 t", "--propellant", "1 t", "--structure", "1 t", "--structure", "1 t",
      "--payload", "1 t", "--isp", "300 s", "--thrust", "1 MN", "--thrust", "1 MN", "--thrust", "1 MN"],
     "3 --thrust for 2 stages"),
    (["transfer", "assist", "--primary", "Jupiter", "--v-in", "0,7.4,0 km/s", "--v-planet", "0,13.06,0 km/s",
      "--periapsis", "2000 km"], "periapsis distance rp = 2000000.0 m is inside Jupiter"),
])
def test_bad_input_is_one_line_and_exit_2(args, message):
    result = runner.invoke(app, args)
    assert result.exit_code == 2
    lines = result.stderr.strip().splitlines()
    assert len(lines) == 1 and lines[0].startswith("orbits: error:") and message in lines[0], result.stderr


def test_assist_gives_the_library_answer_in_json():
    import astropy.units as u

    from orbits import GravityAssist

    args = ["transfer", "assist", "--primary", "Jupiter", "--v-in", "0,7.4,0 km/s", "--v-planet", "0,13.06,0 km/s",
            "--periapsis", "200000 km", "--format", "json"]
    result = CliRunner().invoke(app, args)
    assert result.exit_code == 0, result.output
    data = json.loads(result.stdout)
    expected = GravityAssist.past("Jupiter", [0, 7.4, 0] * u.km / u.s, [0, 13.06, 0] * u.km / u.s, 2e5 * u.km)
    assert data["speed_gain"]["value"] == expected.speed_gain.to_value(u.m / u.s)
    assert data["outgoing_velocity"]["value"] == expected.outgoing_velocity.to_value(u.m / u.s).tolist()


def test_assist_refuses_a_zero_axis_in_one_line():
    args = ["transfer", "assist", "--primary", "Jupiter", "--v-in", "0,7.4,0 km/s", "--v-planet", "0,13.06,0 km/s",
            "--periapsis", "200000 km", "--normal", "0,0,0"]
    result = CliRunner().invoke(app, args)
    assert result.exit_code == 2 and "zero vector" in result.output and len(result.output.strip().splitlines()) == 1


def test_hohmann_between_bodies_and_a_body_where_a_radius_belongs():
    data = run_json("transfer", "hohmann", "--from", "Earth", "--to", "Mars")
    assert round(data["synodic_period"]["value"] / 86400, 1) == 779.9
    assert round(math.degrees(data["phase_angle"]["value"]), 2) == 44.35
    result = runner.invoke(app, ["transfer", "hohmann", "--radius1", "Earth", "--radius2", "Mars"])
    assert result.exit_code == 2 and "'Earth' is a body, not a radius" in result.output
    assert "--from Earth --to Mars" in result.output
    both = runner.invoke(app, ["transfer", "hohmann", "--from", "Earth", "--to", "Mars", "--radius1", "7000 km"])
    assert both.exit_code == 2 and "without --radius1" in both.output
