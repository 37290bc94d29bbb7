"""The calculator verbs `orbits binary`, `orbits flyby` and `orbits escape`: outputs, JSON, exit codes, errors."""

import json

import pytest
from typer.testing import CliRunner

from orbits import BODIES
from orbits_cli.main import app

runner = CliRunner()


def run_json(*args):
    result = runner.invoke(app, [*args, "--format", "json"])
    assert result.exit_code == 0, result.output
    return json.loads(result.stdout)


def test_binary_from_body_names_in_json():
    data = run_json("binary", "--m1", "Earth", "--m2", "Moon", "--a", "384399 km", "--e", "0.0549")
    assert data["period"]["unit"] == "s" and abs(data["period"]["value"] / 86400 - 27.2845) < 1e-4
    assert abs(data["mass_fraction"]["value"] - 0.0121506) < 1e-7
    assert abs(data["star1_semi_major_axis"]["value"] / 1e3 - 4670.67) < 0.01  # the Earth about the barycentre
    assert data["joining_line_areal_velocity"]["unit"] == "m2 / s"


def test_binary_from_masses_and_a_period_with_only():
    data = run_json(
        "binary", "--m1", "1 solMass", "--m2", "1 jupiterMass", "--period", "4.23 d", "--only", "star1_periapsis_speed"
    )
    assert list(data) == ["star1_periapsis_speed"]
    assert abs(data["star1_periapsis_speed"]["value"] - 125.59) < 0.01  # a hot Jupiter's pull on its star


def test_binary_radial_velocity_semi_amplitudes_and_mass_function():
    """The Sun's reflex from Jupiter seen edge-on: K1 = 2 pi a1 / (P sqrt(1 - e**2)), 12.5 m/s; and back from K."""
    data = run_json("binary", "--m1", "Sun", "--m2", "Jupiter", "--a", "5.2026 AU", "--e", "0.0484", "--inc", "90",
                    "--only", "rv_semi_amplitude1,rv_semi_amplitude2,mass_function,period")
    k1, period = data["rv_semi_amplitude1"]["value"], data["period"]["value"]
    assert data["rv_semi_amplitude1"]["unit"] == "m / s" and abs(k1 - 12.47) < 0.01
    ratio = BODIES["Sun"].gm / BODIES["Jupiter"].gm  # K2 / K1 = m1 / m2
    assert data["rv_semi_amplitude2"]["value"] / k1 == pytest.approx(ratio, rel=1e-14)
    back = run_json("binary", "--K", f"{k1!r} m/s", "--period", f"{period!r} s", "--e", "0.0484", "--m1", "Sun")
    assert back["mass_function"]["value"] == pytest.approx(data["mass_function"]["value"], rel=1e-14)
    assert back["minimum_companion_mass"]["value"] == pytest.approx(BODIES["Jupiter"].mass, rel=1e-14)


def test_binary_draws_the_sky_and_the_radial_velocities(tmp_path):
    sky, rv = tmp_path / "sky.png", tmp_path / "rv.svg"
    result = runner.invoke(app, ["binary", "--m1", "1.1 solMass", "--m2", "0.8 solMass", "--period", "20 yr", "--e",
                                 "0.5", "--inc", "50", "--raan", "30", "--argp", "100", "--gamma", "12 km/s", "--sky",
                                 str(sky), "--distance", "10 pc", "--rv", str(rv), "--only", "mass_function"])
    assert result.exit_code == 0, result.output
    assert sky.read_bytes()[:4] == b"\x89PNG" and sky.stat().st_size > 20_000
    assert b"<svg" in rv.read_bytes()[:1000]


def test_binary_table():
    result = runner.invoke(app, ["binary", "--m1", "Sun", "--m2", "Jupiter", "--a", "5.2 AU", "--e", "0.048"])
    assert result.exit_code == 0, result.output
    assert "star 2 about the centre of mass" in result.stdout and "reduced_mass" in result.stdout
    assert "covertex_speed" in result.stdout.split("star 2 about the centre of mass")[1]


def test_flyby_past_a_planet_and_the_inverse():
    by_periapsis = run_json("flyby", "--primary", "Jupiter", "--v-inf", "5.6 km/s", "--periapsis", "200000 km")
    b = by_periapsis["impact_parameter"]["value"]
    assert abs(b / 1e3 - 1286817.63) < 0.01
    by_b = run_json("flyby", "--primary", "Jupiter", "--v-inf", "5.6 km/s", "--b", f"{b} m")
    assert abs(by_b["periapsis_distance"]["value"] / 2e8 - 1) < 1e-14
    assert abs(by_b["deflection_angle"]["value"] - 2.5248384630328804) < 1e-14


def test_flyby_of_two_masses_and_with_a_mass():
    pair = run_json("flyby", "--primary", "Sun", "--secondary", "Jupiter", "--v-inf", "1 km/s", "--b", "1 AU")
    assert {"star1_periapsis_speed", "star2_periapsis_speed", "energy"} <= set(pair)
    probe = run_json("flyby", "--primary", "Earth", "--mass", "722 kg", "--v-inf", "3 km/s", "--b", "20000 km")
    assert probe["energy"]["unit"] == "J" and abs(probe["energy"]["value"] - 722 * 3e3**2 / 2) < 1e-3


def test_flyby_inside_the_sun_warns_and_draws_a_4_au_picture(tmp_path):
    """The issue's example: the 84,000 km closest approach is inside the Sun; the picture spans 4 AU, not 900."""
    picture = tmp_path / "f.png"
    args = ["flyby", "--primary", "Sun", "--secondary", "Jupiter", "--v-inf", "1 km/s", "--b", "1 AU"]
    result = runner.invoke(app, [*args, "--plot", str(picture)])
    assert result.exit_code == 0, result.output
    assert result.stderr.strip().splitlines() == [
        "orbits: warning: Flyby: closest approach 84235.41 km is inside the Sun and Jupiter (radii added: 767192 km): "
        "they collide"
    ]
    assert picture.stat().st_size > 10_000
    quiet = runner.invoke(app, ["flyby", "--primary", "Jupiter", "--v-inf", "5.6 km/s", "--periapsis", "200000 km"])
    assert quiet.exit_code == 0 and quiet.stderr == ""


def test_escape_cosmic_velocities_of_the_notes():
    data = run_json("escape", "cosmic")
    speeds = [round(data[n]["value"] / 1e3, 3) for n in ("first_cosmic_velocity", "second_cosmic_velocity")]
    assert speeds == [7.904, 11.178]
    assert round(data["third_cosmic_velocity"]["value"] / 1e3, 2) == 16.65
    jupiter = run_json("escape", "cosmic", "--primary", "Jupiter", "--only", "second_cosmic_velocity")
    assert round(jupiter["second_cosmic_velocity"]["value"] / 1e3, 1) == 59.5


def test_escape_speed_geo_and_elongation():
    speed = run_json("escape", "speed", "--primary", "Earth")
    assert speed["escape_speed"]["unit"] == "km / s" and round(speed["escape_speed"]["value"], 3) == 11.18
    far = run_json("escape", "speed", "--primary", "5.9722e24 kg", "--at-r", "42164 km")
    assert round(far["escape_speed"]["value"], 3) == 4.348
    geo = run_json("escape", "geo")
    assert round(geo["altitude"]["value"] / 1e3) == 35786
    mars = run_json("escape", "geo", "--primary", "6.4171e23 kg", "--rotation-period", "88642.66 s",
                    "--body-radius", "3396.2 km")
    assert round(mars["altitude"]["value"] / 1e3) == 17032
    venus = run_json("escape", "elongation", "--inner", "0.723 AU", "--outer", "Earth")
    assert venus["max_elongation"]["unit"] == "deg" and round(venus["max_elongation"]["value"], 1) == 46.3


@pytest.mark.parametrize(
    "args, fragment",
    [
        (["binary", "--m1", "Earth", "--m2", "-1 kg", "--a", "1 km"], "mass m2 = -1.0 kg is outside the allowed range"),
        (["binary", "--m1", "Vulcan", "--m2", "Moon", "--a", "1 km"], "--m1: 'Vulcan' is neither a known body"),
        (["binary", "--m1", "Earth", "--m2", "Moon"], "give exactly one size"),
        (["binary", "--m1", "Earth", "--m2", "Moon", "--a", "1 km", "--period", "1 d"], "give exactly one size"),
        (["binary", "--m1", "Earth", "--m2", "Moon", "--period", "1 d", "--e", "1.5"], "e = 1.5 is outside"),
        (["binary", "--m1", "Earth", "--m2", "Moon", "--a", "7000 s"], "not a length"),
        (["binary", "--m1", "Earth", "--a", "1 km"], "give both masses --m1 and --m2"),
        (["binary", "--K", "59 m/s", "--period", "4 d", "--m2", "Moon", "--rv", "x.png"], "--m2, --rv do not apply"),
        (["binary", "--K", "59 m/s"], "--K needs the period"),
        (["binary", "--K", "59 km", "--period", "4 d"], "--K"),
        (["binary", "--K", "59 m/s", "--period", "4 d", "--m1", "Sun", "--inc", "0"], "inclination i = 0.0 deg"),
        (["binary", "--m1", "Sun", "--m2", "Earth", "--a", "1 AU", "--distance", "1 pc"], "give --sky FILE too"),
        (["binary", "--m1", "Sun", "--m2", "Earth", "--a", "1 AU", "--sky", "sky.gif"], "must end in .png"),
        (["flyby", "--primary", "Earth", "--v-inf", "0 km/s", "--b", "1 km"], "v_inf = 0.0 m / s is outside"),
        (["flyby", "--primary", "Earth", "--v-inf", "1 km/s", "--b", "-1 km"], "impact parameter b = -1000.0 m"),
        (["flyby", "--primary", "Earth", "--v-inf", "1 km/s"], "exactly one of --b"),
        (
            ["flyby", "--primary", "Sun", "--v-inf", "1 km/s", "--b", "1 AU", "--mass", "1 kg", "--secondary", "Earth"],
            "not both",
        ),
        (["escape", "geo", "--rotation-period", "-1 h"], "rotation period T = -3600.0 s is outside the allowed range"),
        (["escape", "speed", "--primary", "5 kg"], "has no surface"),
        (["escape", "cosmic", "--g", "9.8"], "has no unit"),
        (["escape", "cosmic", "--primary", "Earth", "--g", "9.8 m/s2"], "not both"),
        (["escape", "elongation", "--inner", "2 AU", "--outer", "1 AU"], "outside the allowed range (0, R)"),
    ],
)
def test_errors_exit_2_with_one_line_on_stderr(args, fragment):
    result = runner.invoke(app, args)
    assert result.exit_code == 2, result.output
    assert fragment in result.stderr
    assert len(result.stderr.strip().splitlines()) == 1
    assert result.stdout == ""


def test_a_warning_not_of_orbits_is_passed_on_once_and_the_command_returns():
    """orbits' own warnings become one stderr line each; any other warning goes back to Python's machinery once,
    outside the recording (re-issued inside it, it was recorded again and the loop over the record never ended)."""
    import warnings

    from orbits import OrbitsWarning
    from orbits_cli.options import reports_errors

    def command():
        warnings.warn("from a library", UserWarning, stacklevel=1)
        warnings.warn("from orbits", OrbitsWarning, stacklevel=1)
        return 42

    with warnings.catch_warnings(record=True) as passed_on:
        warnings.simplefilter("always")
        assert reports_errors(command)() == 42
    assert [(w.category, str(w.message)) for w in passed_on] == [(UserWarning, "from a library")]


def test_binary_without_an_inclination_says_what_it_left_out():
    """A hot Jupiter without --inc: no K1 = 0 and f(M) = 0 of a face-on orbit; the title and the JSON say why."""
    args = ["binary", "--m1", "1 solMass", "--m2", "1 jupiterMass", "--period", "4.23 d"]
    data = run_json(*args)
    assert "rv_semi_amplitude1" not in data and "mass_function" not in data
    assert "inclination not given" in data["about"]["inclination"] and "--inc" in data["about"]["inclination"]
    table = runner.invoke(app, args)
    assert table.exit_code == 0 and "inclination not given" in table.stdout
    asked = runner.invoke(app, [*args, "--only", "rv_semi_amplitude1"])
    assert asked.exit_code == 2 and "give --inc" in asked.output
    edge_on = run_json(*args, "--inc", "90", "--only", "rv_semi_amplitude1")
    assert edge_on["rv_semi_amplitude1"]["value"] == pytest.approx(125.59, abs=0.01)  # 2 pi a1 / P
    assert "about" not in edge_on


def test_a_flyby_through_the_sun_is_called_a_collision_once():
    result = runner.invoke(app, ["flyby", "--primary", "Sun", "--secondary", "Jupiter", "--v-inf", "1 km/s",
                                 "--b", "1 AU", "--only", "periapsis_distance"])
    assert result.exit_code == 0
    assert result.stderr.count("they collide") == 1 and "inside the Sun and Jupiter" in result.stderr
