"""Every name a table or its JSON shows is one --only accepts, and --only with all of them gives back the same rows:
the rows of a group (covertex_times shows covertex_time_periapsis_side and covertex_time_apoapsis_side) included."""

import json
import shlex

import pytest
from typer.testing import CliRunner

from orbits_cli.main import app

COMMANDS = [
    'orbit --primary Earth --a "7000 km" --e 0.1 --inc 51.6',
    "orbit Mars",
    "orbit Io",
    'binary --m1 "1 solMass" --m2 "1 jupiterMass" --period "4.23 d" --inc 90',
    'flyby --primary Jupiter --v-inf "5.6 km/s" --periapsis "200000 km"',
    "escape cosmic",
    'pendulum --length "1 m" --amplitude "170 deg"',
    'perturb rates --altitude "400 km" --inc 51.64',
    "periodic --primary Earth --secondary Moon --family nrho --resonance 9:2",
]


def run(command: str) -> dict:
    result = CliRunner().invoke(app, shlex.split(command), env={"COLUMNS": "80"})
    assert result.exit_code == 0, (command, result.output)
    return json.loads(result.stdout)


@pytest.mark.parametrize("command", COMMANDS)
def test_only_accepts_every_name_the_output_shows(command):
    shown = [name for name in run(f"{command} --format json") if name != "about"]
    for name in shown:
        assert list(run(f"{command} --format json --only {name}")) in ([name], [name, "about"], ["about", name])
    again = [name for name in run(f"{command} --format json --only {','.join(shown)}") if name != "about"]
    assert again == shown
