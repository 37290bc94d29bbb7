"""`orbits lambert`: the table, exact SI JSON, and one-line errors with exit status 2."""

import json

import numpy as np
import pytest
from typer.testing import CliRunner

from orbits._common.constants import BODIES
from orbits.core.manoeuvres import lambert as core
from orbits_cli.main import app

AU = 149597870700.0


def run(*args):
    return CliRunner().invoke(app, list(args))


def test_table():
    result = run("lambert", "--r1", "1,0,0 AU", "--r2", "0,1.5,0 AU", "--tof", "200 d", "--primary", "Sun")
    assert result.exit_code == 0, result.output
    assert "Lambert transfer about Sun" in result.output
    assert "14.72688, 27.06898, 0" in result.output and "0.481889" in result.output
    assert max(map(len, result.output.splitlines())) <= 80


def test_json_is_the_exact_si_solution():
    result = run("lambert", "--r1", "1,0,0 AU", "--r2", "0,1.5,0.1 AU", "--tof", "400 d", "--revolutions", "0",
                 "--format", "json")
    assert result.exit_code == 0, result.output
    data = json.loads(result.output)
    expected = core.solve([AU, 0, 0], [0, 1.5 * AU, 0.1 * AU], 400 * 86400.0, BODIES["Sun"].gm)
    assert data["v1"]["unit"] == "m / s" and data["v1"]["value"] == expected.v1.tolist()
    assert data["transfer_angle"]["unit"] == "rad"


def test_revolutions_branch_and_retrograde():
    args = ["lambert", "--r1", "1,0,0 AU", "--r2", "0,1.5,0 AU", "--tof", "900 d", "--revolutions", "1",
            "--format", "json"]
    left, right = (json.loads(run(*args, "--branch", b).output)["v1"]["value"] for b in ("left", "right"))
    assert np.linalg.norm(np.subtract(left, right)) > 100.0
    retro = json.loads(run(*args[:-4], "--retrograde", "--format", "json").output)
    assert retro["transfer_angle"]["value"] == pytest.approx(1.5 * np.pi)


def test_opposite_positions_with_a_normal():
    result = run("lambert", "--r1", "1,0,0 AU", "--r2", "-1,0,0 AU", "--tof", "200 d", "--normal", "0,0,1",
                 "--format", "json")
    assert result.exit_code == 0, result.output
    assert json.loads(result.output)["transfer_angle"]["value"] == np.pi


@pytest.mark.parametrize(("args", "message"), [
    (["--r1", "1,0,0", "--r2", "0,1.5,0 AU", "--tof", "200 d"], "--r1: '1,0,0' has no unit"),
    (["--r1", "1,0,0 AU", "--r2", "0,1.5,0 AU", "--tof", "200 kg"], "--tof"),
    (["--r1", "1,0,0 AU", "--r2", "-1,0,0 AU", "--tof", "200 d"], "opposite"),
    (["--r1", "1,0,0 AU", "--r2", "2,0,0 AU", "--tof", "200 d"], "point the same way"),
    (["--r1", "1,0,0 AU", "--r2", "0,1.5,0 AU", "--tof", "20 d", "--revolutions", "2"], "infeasible"),
    (["--r1", "1,0,0 AU", "--r2", "0,1.5,0 AU", "--tof", "200 d", "--branch", "up"], "branch"),
    (["--r1", "1,0,0 AU", "--r2", "0,1.5,0 AU", "--tof", "200 d", "--primary", "Vulcan"], "Vulcan"),
])
def test_bad_input_is_one_line_and_exit_2(args, message):
    result = run("lambert", *args)
    assert result.exit_code == 2
    lines = [line for line in result.output.splitlines() if line.strip()]
    assert len(lines) == 1 and lines[0].startswith("orbits: error:") and message in lines[0], result.output


def test_between_bodies_on_dates():
    from orbits import lambert

    args = ["lambert", "--from", "Earth", "--to", "Mars", "--depart", "2026-11-26", "--arrive", "2027-08-15"]
    table = run(*args)
    assert table.exit_code == 0, table.output
    assert "Lambert transfer from Earth (2026-11-26 00:01:09 TDB) to Mars" in table.output and "c3" in table.output
    assert max(map(len, table.output.splitlines())) <= 80
    data = json.loads(run(*args, "--format", "json").stdout)
    trip = lambert("Earth", "Mars", depart="2026-11-26", arrive="2027-08-15")
    assert data["c3"]["value"] == trip.c3.value and data["about"]["from"] == "Earth"
    assert data["v1"]["value"] == trip.v1_si.tolist()
    body_as_position = run("lambert", "--r1", "Earth", "--r2", "Mars", "--tof", "200 d")
    assert body_as_position.exit_code == 2 and "--from and --to" in body_as_position.output
    mixed = run(*args, "--tof", "200 d")
    assert mixed.exit_code == 2 and "--tof" in mixed.output
    missing = run("lambert", "--from", "Earth", "--to", "Mars", "--depart", "2026-11-26")
    assert missing.exit_code == 2 and "needs --arrive" in missing.output
