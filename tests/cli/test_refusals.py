"""Contradictory, repeated or inapplicable options are refused in one line (exit 2), never resolved silently."""

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
    (["escape", "geo", "Earth", "--period", "1 d", "--period", "2 d"], "--period '1 d', --period '2 d'"),
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
