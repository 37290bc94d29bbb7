"""`orbits cosmology`: defaults, units, epochs, JSON, and one-line errors with exit status 2."""

import json
import math
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


def test_planck_distances_equal_astropy_to_1e_12():
    """The issue's bar: D_L and D_A at z = 1 equal astropy's FlatLambdaCDM(67.66, 0.30966, Tcmb0=0) to 1e-12."""
    from astropy.cosmology import FlatLambdaCDM

    data = run_json("--z", "1", "--H0", "67.66 km/s/Mpc", "--Om", "0.30966")
    reference = FlatLambdaCDM(67.66, 0.30966, Tcmb0=0)
    for name, value in (("luminosity_distance", reference.luminosity_distance(1)),
                        ("angular_diameter_distance", reference.angular_diameter_distance(1))):
        assert data[name]["unit"] == "m"
        assert abs(data[name]["value"] / value.to_value(u.m) - 1) <= 1e-12  # measured 1.3e-15
    assert abs(data["distance_modulus"]["value"] - reference.distmod(1).value) <= 1e-12  # measured 0
    assert run_json("--model", "planck18", "--z", "1") == data


def test_named_models_and_their_errors():
    notes = run_json("--model", "notes", "--only", "age")
    assert abs(notes["age"]["value"] / GYR - 40 / 3) < 1e-13
    radiation = run_json("--model", "planck18-radiation", "--only", "age")
    assert round(radiation["age"]["value"] / GYR, 3) == 13.804
    result = runner.invoke(app, ["cosmology", "--model", "planck18", "--Om", "0.3"])
    assert result.exit_code == 2 and "fixes H0 and the densities" in result.stderr
    result = runner.invoke(app, ["cosmology", "--model", "wmap"])
    assert result.exit_code == 2 and "choose from notes, planck18, planck18-radiation" in result.stderr


def test_closed_universe_runs_through_its_big_crunch(tmp_path):
    """Om = 2, Ok = -1 with the notes' t_H = 20 Gyr: turnaround at pi t_H = 62.83 Gyr, crunch at 2 pi t_H."""
    t_h = 20.0  # Gyr, 1 / (0.5e-10 / yr)
    after = run_json("--Om", "2", "--Ok", "-1", "--t", "100 Gyr")
    assert after["hubble_parameter"]["value"] < 0 and "comoving_distance" not in after
    mirror = run_json("--Om", "2", "--Ok", "-1", "--t", f"{2 * math.pi * t_h - 100!r} Gyr", "--only", "scale_factor")
    assert abs(after["scale_factor"]["value"] / mirror["scale_factor"]["value"] - 1) < 1e-13
    crunch = run_json("--Om", "2", "--Ok", "-1", "--t", f"{2 * math.pi * t_h!r} Gyr", "--only", "scale_factor")
    assert crunch["scale_factor"]["value"] == 0.0
    result = runner.invoke(app, ["cosmology", "--Om", "2", "--Ok", "-1", "--t", "126 Gyr"])
    assert result.exit_code == 2 and "recollapses to a big crunch" in result.stderr
    picture = tmp_path / "closed.png"
    result = runner.invoke(app, ["cosmology", "--Om", "2", "--Ok", "-1", "--plot", str(picture)])
    assert result.exit_code == 0 and picture.stat().st_size > 10_000


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
