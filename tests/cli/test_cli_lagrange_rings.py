"""`orbits lagrange` and `orbits ring`: outputs, JSON schema, selections and one-line errors."""

import json
import math

import pytest
from typer.testing import CliRunner

from orbits_cli.main import app

runner = CliRunner()


def run(*args):
    return runner.invoke(app, list(args))


def test_lagrange_earth_moon_json_has_coordinates_and_stability():
    result = run("lagrange", "--primary", "Earth", "--secondary", "Moon", "--format", "json")
    assert result.exit_code == 0, result.output
    data = json.loads(result.stdout)
    assert data["separation"] == {"value": 384399000.0, "unit": "m"}
    assert len(data["L1_position"]["value"]) == 3 and data["L1_position"]["unit"] == "m"
    assert abs(data["L1_distance_to_secondary"]["value"] / 1e3 - 58_019) < 1
    assert data["L4_growth_rate"]["value"] == 0.0 and data["L1_growth_rate"]["value"] > 0
    assert "L4_e_folding_time" not in data and data["L3_e_folding_time"]["unit"] == "s"
    assert len(data["L2_eigenvalues"]["value"]) == 6 and data["L2_eigenvalues"]["unit"] == "1 / s"
    assert all(math.isfinite(q["value"]) for q in data.values() if not isinstance(q["value"], list))


def test_lagrange_given_masses_points_and_only():
    result = run(
        "lagrange",
        "--primary",
        "1 solMass",
        "--secondary",
        "0.1 solMass",
        "--separation",
        "1 AU",
        "--points",
        "L4,L5",
        "--only",
        "growth_rate",
        "--format",
        "json",
    )
    assert result.exit_code == 0, result.output
    data = json.loads(result.stdout)
    assert list(data) == ["L4_growth_rate", "L5_growth_rate"]
    assert data["L4_growth_rate"]["value"] > 0  # mu = 1/11 > Routh's 0.0385: L4 and L5 are unstable


def test_lagrange_table():
    result = run("lagrange", "--primary", "Sun", "--secondary", "Earth", "--points", "L2")
    assert result.exit_code == 0, result.output
    assert "mu = 3.0034" in result.stdout and "to m [km]" in result.stdout  # one row per point
    assert any(line.split()[:1] == ["L2"] and "1501" in line for line in result.stdout.splitlines())


@pytest.mark.parametrize(
    "args, fragment",
    [
        (["lagrange", "--primary", "Moon", "--secondary", "Earth"], "pass the heavier body as the primary"),
        (["lagrange", "--primary", "1 kg", "--secondary", "0 kg", "--separation", "1 m"],
         "outside the allowed range (0, inf) kg"),
        (["lagrange", "--primary", "Earth", "--secondary", "1e20 kg"], "separation r is needed"),
        (["lagrange", "--primary", "Earth", "--secondary", "Moon", "--separation", "5"], "has no unit"),
        (["lagrange", "--primary", "Earth", "--secondary", "Moon", "--points", "L6"], "unknown points"),
        (["lagrange", "--primary", "Earth", "--secondary", "Vulcan"], "--secondary"),
        (["ring", "1", "--mass", "1 kg", "--radius", "1 m"], "outside [2, inf)"),
        (["ring", "3", "--mass", "1 kg", "--radius", "-1 m"], "ring radius r = -1.0 m"),
        (["ring", "3", "--mass", "1 kg", "--radius", "1 m", "--only", "breakup"], "unknown quantities"),
        (["ring", "8", "--mass", "1 kg", "--radius", "1 m", "--primary", "1e6 kg", "--only", "breakup_time"], "stable"),
    ],
)
def test_errors_are_one_line_with_status_2(args, fragment):
    result = run(*args)
    assert result.exit_code == 2
    assert fragment in result.stderr and len(result.stderr.strip().splitlines()) == 1


def test_ring_json_with_and_without_central_mass():
    result = run("ring", "8", "--mass", "1e20 kg", "--radius", "100000 km", "--format", "json")
    assert result.exit_code == 0, result.output
    data = json.loads(result.stdout)
    assert data["unstable_mode"]["value"] == 4 and data["breakup_time"]["unit"] == "s"
    assert math.isclose(data["potential_energy"]["value"], -2 * data["kinetic_energy"]["value"], rel_tol=1e-15)
    threshold = data["central_mass_threshold"]["value"]
    stable = run(
        "ring", "8", "--mass", "1e20 kg", "--radius", "100000 km", "--primary", f"{1.1 * threshold} kg",
            "--format", "json"
    )
    assert stable.exit_code == 0, stable.output
    data = json.loads(stable.stdout)
    assert data["growth_rate"]["value"] == 0.0 and "breakup_time" not in data


def test_ring_table_and_non_integer_count():
    result = run("ring", "7", "--mass", "1e20 kg", "--radius", "1e5 km", "--primary", "Earth")
    assert result.exit_code == 0, result.output
    assert "Ring of 7 bodies about Earth" in result.stdout and "central_mass_threshold" in result.stdout
    assert run("ring", "2.5", "--mass", "1 kg", "--radius", "1 m").exit_code == 2


@pytest.mark.parametrize("args", [
    ["lagrange", "--primary", "Earth", "--secondary", "Moon", "--only", "period"],
    ["ring", "5", "--mass", "1e20 kg", "--radius", "1e5 km", "--only", "breakup_time"],
    ["ring", "8", "--mass", "1e20 kg", "--radius", "1e5 km", "--primary", "3e22 kg", "--only", "period"],
])
def test_lagrange_and_ring_draw_their_pictures(tmp_path, args):
    target = tmp_path / "picture.png"
    result = run(*args, "--plot", str(target))
    assert result.exit_code == 0, result.output
    assert target.read_bytes()[:4] == b"\x89PNG" and target.stat().st_size > 20_000


def test_lagrange_plot_refuses_a_bad_suffix_before_any_work(tmp_path):
    result = run("lagrange", "--primary", "Earth", "--secondary", "Moon", "--plot", str(tmp_path / "x.jpg"))
    assert result.exit_code == 2 and "must end in .png, .svg or .pdf" in result.output
