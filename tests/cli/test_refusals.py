"""Contradictory, repeated or inapplicable options are refused in one line (exit 2), never resolved silently."""

import json

import pytest
from typer.testing import CliRunner

from orbits_cli.main import app

runner = CliRunner()


def refused(args: list[str]) -> str:
    """The one-line error of a refused command line."""
    result = runner.invoke(app, args)
    assert result.exit_code == 2, result.output
    assert result.stdout == "" and len(result.stderr.strip().splitlines()) == 1, result.stderr
    return result.stderr


@pytest.mark.parametrize("args, fragment", [
    (["orbit", "--primary", "Earth", "--a", "7000 km", "--a", "8000 km"], "--a '7000 km', --a '8000 km'"),
    (["orbit", "--primary", "Earth", "--a=7000 km", "--e", "0.1", "--a", "8000 km"], "given 2 times"),
    (["escape", "geo", "--primary", "Earth", "--rotation-period", "1 d", "--rotation-period", "2 d"],
     "--rotation-period '1 d', --rotation-period '2 d'"),
    (["validate", "circular", "--sweep", "--no-sweep"], "--sweep, --no-sweep: a switch, given 2 times"),
])
def test_an_option_of_one_value_given_twice_is_refused(args, fragment):
    assert fragment in refused(args)


def test_a_quantity_given_two_display_units_is_refused():
    assert "--unit period is given twice (d, h)" in refused(
        ["orbit", "Earth", "--only", "period", "--unit", "period=d", "--unit", "period=h"])


def test_repeatable_options_still_repeat():
    result = runner.invoke(app, ["orbit", "Earth", "--only", "period,speed", "--unit", "period=d", "--unit",
                                 "speed=m/s"])
    assert result.exit_code == 0 and " d " in result.stdout and "m / s" in result.stdout


@pytest.mark.parametrize("args, fragment", [
    (["bench", "kepler", "--repeats", "0"], "--repeats: 0 is outside [1, 1,000]"),  # was UnboundLocalError
    (["bench", "kepler", "--easy", "-5"], "--easy: -5 is outside [1, 10,000,000]"),  # 'negative dimensions ...'
    (["bench", "kepler", "--easy", "10000000000000"], "--easy: 10000000000000 is outside"),  # 73 TiB attempted
    (["bench", "kepler", "--hard", "0"], "--hard: 0 is outside [1, 10,000,000]"),  # an empty set printed nan
    (["bench", "kepler", "--reference", "0"], "--reference: 0 is outside [1, 100,000]"),
    (["bench", "propagate", "--states", "0"], "--states: 0 is outside"),
    (["bench", "api", "--sizes", "1,0"], "--sizes: 0 is outside [1, 10,000,000]"),
    (["bench", "cli", "--runs", "0"], "--runs: 0 is outside [1, 1,000]"),
    (["bench", "precision", "--target", "-1"], "error target = -1.0 is outside the allowed range (0, inf)"),
    (["bench", "precision", "--target", "nan"], "error target = nan is not finite"),
])
def test_benchmark_sizes_and_targets_are_checked_before_any_work(args, fragment):
    assert fragment in refused(args)


def test_the_harness_refuses_to_time_nothing():
    from orbits import OrbitDomainError
    from orbits.tools.bench.harness import best_time

    with pytest.raises(OrbitDomainError, match=r"repeats = 0 is outside \[1, 1,000\]"):
        best_time(lambda: None, 0)


def test_a_ring_too_large_to_sum_is_refused_with_its_limit():
    """ring 99999999999999999999999 said only 'Maximum allowed size exceeded'."""
    assert "n = 99999999999999999999999 is outside [2, 10000000]" in refused(
        ["ring", "99999999999999999999999", "--mass", "1 kg", "--radius", "1 km"])


def test_a_ring_beyond_the_stability_analysis_says_what_it_left_out():
    """A ring of n > 4096 dropped its stability rows without a note."""
    result = runner.invoke(app, ["ring", "5000", "--mass", "1 kg", "--radius", "1 km"])
    assert result.exit_code == 0 and "growth_rate and the break-up are not computed" in result.stdout
    assert "n = 5000 is outside [2, 4096] for the linear-stability analysis" in " ".join(result.stdout.split())
    data = json.loads(runner.invoke(app, ["ring", "5000", "--mass", "1 kg", "--radius", "1 km", "--format",
                      "json"]).stdout)
    assert "growth_rate" not in data and "linear-stability" in data["about"]["not computed"]
    quiet = runner.invoke(app, ["ring", "7", "--mass", "1 kg", "--radius", "1 km", "--format", "json"]).stdout
    assert "about" not in json.loads(quiet) and "growth_rate" in json.loads(quiet)


TRANSFER = ["lambert", "--r1", "1,0,0 AU", "--r2", "0,1.5,0 AU", "--tof", "200 d"]


@pytest.mark.parametrize("args, fragment", [
    (TRANSFER + ["--retrograde", "--normal", "0,0,1"], "retrograde and a normal both set the sense of motion"),
    (TRANSFER + ["--branch", "left"], "branch = 'left' chooses between the two solutions of a transfer with "
                                      "revolutions > 0; with revolutions = 0 there is one"),
    (TRANSFER + ["--revolutions", "99999999999999999999"], "revolutions N = 99999999999999999999 is outside "
                                                           "[0, 2**50]"),  # 'must be a whole number >= 0'
    (["binary", "--m1", "Sun", "--m2", "Jupiter", "--a", "5.2 AU", "--gamma", "10 km/s"],
     "--gamma, the systemic velocity, shows only in the radial-velocity curves: give --rv FILE too"),
    (["orbit", "Earth", "--format", "json", "--unit", "period=d"], "--unit: how a table shows its numbers"),
    (["kepler", "--e", "0.5", "--M", "1", "--format", "json", "--units", "si", "--digits", "4"],
     "--units si, --digits 4: how a table shows its numbers"),
    (["periodic", "--primary", "Earth", "--secondary", "Moon", "--family", "halo", "--az", "5000 km", "--spacing",
      "period"], "--spacing spreads the members of a family table: give --members N with it"),
    (["periodic", "--primary", "Earth", "--secondary", "Moon", "--family", "dro", "--point", "L1", "--ax",
      "70000 km"], "the dro family lies about the secondary (no point), not L1"),
])
def test_an_option_that_cannot_apply_is_refused_not_dropped(args, fragment):
    """--retrograde with --normal gave the prograde transfer; --branch left without revolutions and --gamma without
    --rv changed nothing and said nothing."""
    assert fragment in refused(args)


def test_the_library_refuses_the_same_contradictions():
    import astropy.units as u

    from orbits import OrbitDomainError, lambert

    r1, r2, tof = [1, 0, 0] * u.AU, [0, 1.5, 0] * u.AU, 200 * u.day
    with pytest.raises(OrbitDomainError, match="prograde and a normal both set the sense"):
        lambert(r1, r2, tof, prograde=True, normal=[0, 0, 1])
    with pytest.raises(OrbitDomainError, match="with revolutions = 0 there is one"):
        lambert(r1, r2, tof, branch="right")
    assert lambert(r1, r2, tof, normal=[0, 0, -1]).v1[1] < 0  # the normal alone sets the sense: clockwise
    several = lambert(r1, r2, [200, 2000] * u.day, revolutions=[0, 1], branch="left")  # the branch applies to one
    assert several.branch == "left" and several.shape == (2,)


def test_a_key_given_twice_in_a_json_scene_is_refused_as_in_toml(tmp_path):
    """A JSON scene with a duplicate key kept the last value; the same file in TOML is an error."""
    path = tmp_path / "twice.json"
    path.write_text('{"name": "a", "asks": ["positions"], "name": "b"}')
    assert "twice.json: not valid JSON: the key 'name' is given twice in one object" in refused(
        ["validate", str(path)])


@pytest.mark.parametrize("args, fragment", [
    (["cosmology", "--Om", "2"], "Omega_Lambda = -1.0 follows from Om0 = 2.0 in a flat universe"),  # blamed Ol
    (["cosmology", "--t", "1e30 Gyr"], "t = 1e+30 Gyr is so late that the scale factor"),  # blamed z = -1
    (["cosmology", "--z", "1e300"], "the Hubble parameter H at z = 1e+300 is larger than float64 holds"),
])
def test_cosmology_messages_name_what_the_user_gave(args, fragment):
    assert fragment in refused(args)


def test_a_one_dimensional_collision_of_equal_velocities_is_refused_as_in_two():
    """A 1-D collide with equal velocities reported a collision that 2-D refused."""
    line = refused(["collide", "--m1", "1 kg", "--v1", "2 m/s", "--m2", "1 kg", "--v2", "2 m/s"])
    plane = refused(["collide", "--m1", "1 kg", "--v1", "2,0 m/s", "--m2", "1 kg", "--v2", "2,0 m/s"])
    assert line == plane and "the bodies do not approach, so they never collide" in line


def test_a_synchronous_orbit_inside_the_body_is_said():
    """escape geo --primary Earth --rotation-period '1 min' returned an orbit inside the Earth with no warning."""
    result = runner.invoke(app, ["escape", "geo", "--primary", "Earth", "--rotation-period", "1 min"])
    assert result.exit_code == 0 and "orbit_radius" in result.stdout
    assert result.stderr.strip() == ("orbits: warning: the synchronous orbit radius r = 331.2533 km lies inside the "
                                     "body (radius 6378.1 km): no orbit of this period exists above its surface")
