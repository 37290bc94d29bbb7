"""`orbits cosmology`: defaults, units, epochs, JSON, and one-line errors with exit status 2."""

import json
import subprocess
import sys

import astropy.units as u
import pytest
from typer.testing import CliRunner

from orbits_cli.main import app

runner = CliRunner()
GYR = (1 * u.Gyr).to_value(u.s)  # JSON carries the library's SI values


def run_json(*args):
    result = runner.invoke(app, ["cosmology", *args, "--format", "json"])
    assert result.exit_code == 0, result.output
    return json.loads(result.stdout)


def test_default_is_the_notes_einstein_de_sitter_universe():
    """XXIV.iv: H = 0.5e-10 / yr gives 13.33 Gyr (1.33e10 yr) and H0 = 48.89 km/s/Mpc."""
    data = run_json()
    assert data["age"]["unit"] == "s" and abs(data["age"]["value"] / GYR - 40 / 3) < 1e-13
    h0 = (data["hubble_parameter"]["value"] * u.Unit(data["hubble_parameter"]["unit"])).to_value(u.km / u.s / u.Mpc)
    assert round(h0, 2) == 48.89
    assert data["density_parameter"]["value"] == 1.0 and data["comoving_distance"]["value"] == 0.0


def test_table_names_the_model():
    result = runner.invoke(app, ["cosmology", "--H0", "70 km/s/Mpc", "--Om", "0.3"])
    assert result.exit_code == 0, result.output
    assert "Flat matter + Lambda, H0 = 70 km/s/Mpc, Om = 0.3, Ol = 0.7" in result.stdout
    assert "comoving_distance" in result.stdout and "Gyr" in result.stdout  # tables in astronomers' units


@pytest.mark.parametrize("h0", ["0.5e-10 / yr", "48.88961108403946 km/s/Mpc", "1.5844043907014474e-18 / s"])
def test_hubble_constant_in_any_rate_unit(h0):
    assert abs(run_json("--H0", h0, "--only", "age")["age"]["value"] / GYR - 40 / 3) < 1e-12


def test_redshifts_times_and_only():
    at_z = run_json("--H0", "67.66 km/s/Mpc", "--Om", "0.3", "--Ol", "0.6", "--Or", "1e-4", "--z", "0.5,1,inf")
    assert at_z["redshift"]["value"] == [0.5, 1.0, "inf"]  # strict JSON: a non-finite value is named
    assert at_z["age"]["value"][2] == 0.0 and at_z["comoving_distance"]["unit"] == "m"
    at_t = run_json("--t", "1 Gyr", "--only", "scale_factor,age,redshift")
    assert list(at_t) == ["scale_factor", "age", "redshift"] and at_t["age"]["value"] == GYR
    assert abs(at_t["scale_factor"]["value"] - 0.075 ** (2 / 3)) < 1e-15


def test_recollapsing_universe_in_its_future():
    data = run_json("--Om", "2", "--Ok", "-1", "--t", "20 Gyr", "--only", "redshift,lookback_time")
    assert data["redshift"]["value"] < 0 and data["lookback_time"]["value"] < 0


@pytest.mark.parametrize(
    "args, fragment",
    [
        (["--H0", "70"], "has no unit"),
        (["--H0", "70 km"], "not a rate"),
        (["--H0", "-70 km/s/Mpc"], "H0 = -70.0 km / (Mpc s) is outside the allowed range (0, inf)"),
        (["--z", "-1"], "z = -1.0 is outside (-1, inf]"),
        (["--z", "one"], "cannot read 'one'"),
        (["--z", "1", "--t", "1 Gyr"], "not both"),
        (["--t", "-1 Gyr"], "before the big bang"),
        (["--Om", "-0.3"], "Omega_m = -0.3 is outside [0, inf)"),
        (["--Om", "0.3", "--Ol", "0.8", "--Ok", "0.1"], "sum to"),
        (["--Ok", "0.1"], "give --Om or --Ol"),
        (["--Om", "0.3", "--Ol", "2.7", "--Ok", "-2"], "no big bang"),
        (["--only", "age,agee"], "unknown quantities"),
        (["--Ol", "1", "--t", "1 Gyr"], "no big bang"),
    ],
)
def test_errors_exit_2_with_one_line_on_stderr(args, fragment):
    result = runner.invoke(app, ["cosmology", *args])
    assert result.exit_code == 2, result.output
    assert fragment in result.stderr
    assert len(result.stderr.strip().splitlines()) == 1 and result.stdout == ""


def test_module_imports_only_typer():
    code = (
        "import sys; import orbits_cli.commands.cosmology; "
        "print(sorted(m for m in ('astropy', 'numpy', 'orbits') if m in sys.modules))"
    )
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True).stdout
    assert out.strip() == "[]"
