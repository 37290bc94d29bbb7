"""`orbits periodic`: the orbit table, the family table, JSON, pictures and one-line errors (exit 2)."""

import json

import pytest
from typer.testing import CliRunner

from orbits_cli.main import app

runner = CliRunner()


def run(*args):
    return runner.invoke(app, list(args))


def test_the_gateway_orbit_as_json():
    """The 9:2 NRHO: period 6.5527 d (2/9 of the catalogue binary's synodic month), perilune 3223 km."""
    result = run("periodic", "--primary", "Earth", "--secondary", "Moon", "--family", "nrho", "--resonance", "9:2",
                 "--format", "json")
    assert result.exit_code == 0, result.output
    data = json.loads(result.stdout)
    assert data["period"]["unit"] == "s" and abs(data["period"]["value"] / 86400 - 6.5527) < 1e-4
    assert abs(data["closest_approach_secondary"]["value"] / 1e3 - 3223.2) < 0.1
    assert data["stability_indices"]["unit"] == "" and len(data["stability_indices"]["value"]) == 2
    assert data["dimensionless_period"]["unit"] == ""


def test_the_orbit_table_fits_80_columns():
    result = run("periodic", "--primary", "Earth", "--secondary", "Moon", "--family", "halo", "--point", "L2",
                 "--az", "20000 km")
    assert result.exit_code == 0, result.output
    lines = result.stdout.splitlines()
    assert lines[0].startswith("Earth-Moon L2 northern halo orbit: Az = 20000 km, T = 14.73445 d")
    assert max(map(len, lines)) <= 80
    assert any(line.split()[:2] == ["az", "20000"] for line in lines)
    assert any(line.split()[0] == "nu_1" for line in lines if line.split())


def test_only_and_given_masses():
    result = run("periodic", "--primary", "1 solMass", "--secondary", "0.001 solMass", "--separation", "5.2 AU",
                 "--family", "lyapunov", "--point", "L1",
                 "--ax", "0.01 AU", "--only", "period,ax", "--format", "json")
    assert result.exit_code == 0, result.output
    data = json.loads(result.stdout)
    assert list(data) == ["period", "ax"] and abs(data["ax"]["value"] / 1.495978707e9 - 1.0) < 1e-10


def test_the_family_table_lists_members_and_bifurcations(tmp_path):
    path = tmp_path / "family.png"
    result = run("periodic", "--primary", "Earth", "--secondary", "Moon", "--family", "nrho", "--resonance", "9:2",
                 "--members", "6", "--plot",
                 str(path))
    assert result.exit_code == 0, result.output
    lines = result.stdout.splitlines()
    assert "family: 6 members to the member with resonance = 9:2" in " ".join(lines[:3])
    assert max(map(len, lines)) <= 80 and "bifurcations" in result.stdout
    assert path.stat().st_size > 10_000


def test_the_family_as_json_and_a_picture_of_one_orbit(tmp_path):
    result = run("periodic", "--primary", "Earth", "--secondary", "Moon", "--family", "dro", "--ax", "70000 km",
                 "--members", "3",
                 "--format", "json")
    assert result.exit_code == 0, result.output
    data = json.loads(result.stdout)
    assert data["about"]["members"] == "3" and len(data["period"]["value"]) == 3
    path = tmp_path / "dro.png"
    assert run("periodic", "--primary", "Earth", "--secondary", "Moon", "--family", "dro", "--ax", "70000 km",
               "--plot", str(path)).exit_code == 0
    assert path.stat().st_size > 10_000


@pytest.mark.parametrize("args, fragment", [
    (["--family", "halo", "--point", "L4", "--az", "1000 km"], "the halo family lies about L1, L2, not L4"),
    (["--family", "nrho", "--resonance", "1:1"], "the 1:1 resonance (T = 29.48717 d) is beyond the Earth-Moon L2 "
                                                 "southern halo family"),
    (["--family", "halo", "--az", "900000 km"], "Az = 900000 km is beyond"),
    (["--family", "nrho", "--resonance", "3-1"], "must read 'p:q'"),
    (["--family", "halo", "--ax", "1 km", "--az", "1 km"], "give exactly one of"),
    (["--family", "halo", "--resonance", "9:2"], "resonance does not pick a halo orbit"),
    (["--family", "halo", "--az", "1000"], "has no unit"),
    (["--family", "halo", "--jacobi", "3 km"], "is not a speed squared"),
    (["--family", "dro", "--branch", "northern", "--ax", "1000 km"], "only halo families have a northern"),
    (["--family", "lyapunov", "--branch", "northern", "--ax", "10000 km"], "only halo families have a northern"),
    (["--family", "dro", "--point", "L1", "--ax", "70000 km"], "the dro family lies about the secondary"),
    (["--family", "vertical", "--closest-approach", "9000 km"], "closest_approach does not pick a vertical orbit"),
    (["--family", "lyapunov", "--ax", "10000 km", "--members", "3", "--az", "1 km"], "az does not pick a lyapunov"),
    (["--family", "spiral"], "'spiral' is not one of"),
])
def test_bad_requests_are_one_line_errors_with_exit_status_2(args, fragment):
    result = run("periodic", "--primary", "Earth", "--secondary", "Moon", *args)
    assert result.exit_code == 2
    message = result.stderr.strip() if result.stderr else result.output.strip()
    assert fragment in message and len(message.splitlines()) == 1, message
