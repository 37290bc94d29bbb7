"""What a person reads: 80-column tables with no cut cell, natural units, strict JSON equal to the library bit for
bit, one angle convention, one-line usage errors, and a one-line repr and an HTML table for every public object."""

import json
import math
import shlex

import astropy.units as u
import numpy as np
import pytest
from typer.testing import CliRunner

import orbits
from orbits._common.display import shown
from orbits_cli.main import app

runner = CliRunner()

#: the README's calculator examples (bench, info and the validation runs are tested elsewhere)
README_EXAMPLES = [
    "orbit Earth",
    'orbit --primary Earth --a "42164 km" --only period,speed',
    'orbit --primary Earth --r "7000,0,0 km" --v "0,7.5,1 km/s"',
    'kepler --e 0.9 --M "0.1 rad"',
    'kepler --e 1.5 --nu "60 deg"',
    'binary --m1 Sun --m2 Jupiter --a "5.2 AU" --e 0.048 --only period,star1_periapsis_speed',
    'binary --m1 "1 solMass" --m2 "1 jupiterMass" --period "4.23 d"',
    'flyby --primary Jupiter --v-inf "5.6 km/s" --periapsis "200000 km"',
    'flyby --primary Sun --secondary Jupiter --v-inf "1 km/s" --b "1 AU"',
    "escape cosmic",
    "escape geo --primary Jupiter",
    'escape speed --primary Moon --at-r "384399 km"',
    'escape elongation --inner "0.723 AU" --outer Earth',
    "cosmology",
    'cosmology --H0 "67.66 km/s/Mpc" --Om 0.30966 --z 0.5,1,1100',
    'cosmology --Om 0.3 --Ol 0.8 --t "1 Gyr"',
    "lagrange --primary Earth --secondary Moon --points L1,L2",
    'lagrange --primary "1 solMass" --secondary "0.1 solMass" --separation "1 AU" --only growth_rate',
    'ring 7 --mass "1e20 kg" --radius "1e5 km" --primary Earth',
]


def run(command, columns=80):
    result = runner.invoke(app, shlex.split(command), env={"COLUMNS": str(columns)})
    assert result.exit_code == 0, (command, result.output)
    return result.stdout


def strict_json(text):
    """Parse with a strict parser: NaN and Infinity tokens are refused."""
    def refuse(token):
        raise ValueError(f"not JSON: {token}")

    return json.loads(text, parse_constant=refuse)


@pytest.mark.parametrize("command", README_EXAMPLES)
def test_every_readme_example_fits_80_columns_with_no_cut_cell(command):
    """Every line fits; every scalar value of the JSON output appears whole in the table, in its display unit
    (a cut or wrapped cell would lose it). Lagrange tables are checked by their rows (one per point)."""
    table = run(command)
    assert max(len(line) for line in table.splitlines()) <= 80
    data = strict_json(run(command + " --format json"))
    if command.startswith("lagrange"):
        return
    cells = {cell for line in table.splitlines() for cell in line.split()}
    for name, entry in data.items():
        if name == "about":  # what answered and what was assumed, as text (cli/render.py to_json)
            continue
        value = entry["value"]
        if isinstance(value, list) or isinstance(value, str):
            continue
        text, _ = shown(value * u.Unit(entry["unit"] or u.one), name)
        assert text in cells, (name, text)


def test_natural_units_for_halley_and_a_low_orbit():
    halley = run('orbit --primary Sun --q "0.586 AU" --e 0.967 --only period,semi_major_axis')
    assert "74.83137   yr" in halley and "17.75758   AU" in halley
    leo = run('orbit --primary Earth --a "6778 km" --inc 51.64 --only period,semi_major_axis,inclination')
    assert "92.5576   min" in leo and "6778   km" in leo and "51.64   deg" in leo


def test_display_options_units_digits_and_overrides():
    si = run('orbit --primary Earth --a "6778 km" --only period --units si')
    assert "5553.456   s" in si
    digits = run('orbit --primary Earth --a "6778 km" --only period --digits 12')
    assert "92.5576031358" in digits
    days = run('orbit --primary Earth --a "6778 km" --only period --unit period=h')
    assert "1.542627   h" in days


@pytest.mark.parametrize(
    "args, fragment",
    [
        (["orbit", "--primary", "Earth", "--a", "6778 km", "--unit", "period=km"], "period is in s, not km"),
        (["orbit", "--primary", "Earth", "--a", "6778 km", "--unit", "perod=d"], "perod: no such quantity"),
        (["orbit", "--primary", "Earth", "--a", "6778 km", "--unit", "period"], "write NAME=UNIT"),
        (["orbit", "--primary", "Earth", "--a", "6778 km", "--digits", "0"], "--digits"),
        (["orbit", "Earth", "--e", "0.5"], "--e does not apply to Earth"),
        (["orbit", "Earth", "--primary", "Sun", "--inc", "3"], "--inc, --primary do not apply"),
        (["orbit", "--primary", "Earth", "--a", "6778 km", "--only", ""], "give at least one"),
        (["frobnicate"], "No such command"),
        (["orbit", "--format", "xml"], "'xml' is not one of"),
        (["kepler", "--e", "abc", "--M", "1"], "--e"),
        (["kepler", "--M", "1"], "Missing option '--e'"),
        (["ring", "-3"], "No such option"),
    ],
)
def test_errors_and_usage_errors_are_one_line_with_status_2(args, fragment):
    result = runner.invoke(app, args)
    assert result.exit_code == 2, result.output
    assert fragment in result.stderr and len(result.stderr.strip().splitlines()) == 1
    assert result.stdout == ""


def test_json_is_strict_and_equals_the_library_bit_for_bit():
    text = run('cosmology --H0 "67.66 km/s/Mpc" --Om 0.3 --z 0.5,inf --format json')
    data = strict_json(text)
    model = orbits.Cosmology.from_densities(67.66 * u.km / u.s / u.Mpc, Om0=0.3)
    library = model.quantities(z=np.array([0.5, np.inf]))
    for name, q in library.items():
        values = q.value.tolist()
        expected = [v if math.isfinite(v) else str(v) for v in values] if isinstance(values, list) else values
        assert data[name]["value"] == expected and data[name]["unit"] == q.unit.to_string(), name
    orbit = strict_json(run('orbit --primary Earth --a "6778 km" --e 0.01 --inc 51.64 --format json'))
    exact = orbits.Orbit.from_elements("Earth", a=6778 * u.km, e=0.01, inc=51.64 * u.deg).quantities()
    assert all(orbit[name]["value"] == q.value.tolist() for name, q in exact.items())


def test_a_bare_angle_is_degrees_in_every_verb():
    """--M, --nu, --inc, --raan, --argp: a bare 90 is the same as '90 deg'."""
    for verb in ("kepler --e 0.5 --M {}", "kepler --e 0.5 --nu {}", "kepler --e 1.5 --M {}"):
        bare, unit = (strict_json(run(verb.format(x) + " --format json")) for x in ("90", "'90 deg'"))
        assert bare == unit
    for option in ("--inc", "--raan", "--argp", "--nu"):
        tilt = "" if option == "--inc" else "--inc 10 "
        base = 'orbit --primary Earth --a "7000 km" --e 0.1 ' + tilt + option + " {} --format json"
        assert strict_json(run(base.format("1"))) == strict_json(run(base.format("'1 deg'")))
        assert strict_json(run(base.format("1"))) != strict_json(run(base.format("'1 rad'")))
    binary = 'binary --m1 Earth --m2 Moon --a "384399 km" --e 0.05 --inc {} --format json'
    assert strict_json(run(binary.format("30"))) == strict_json(run(binary.format("'30 deg'")))


PUBLIC_OBJECTS = [
    lambda: orbits.Orbit.circular("Earth", 6778 * u.km, inc=51.64 * u.deg),
    lambda: orbits.Binary.from_elements("Earth", "Moon", a=384399 * u.km, e=0.0549),
    lambda: orbits.Binary.from_elements("Earth", "Moon", a=384399 * u.km, e=0.0549).star1,
    lambda: orbits.Flyby.past("Jupiter", v_inf=5.6 * u.km / u.s, periapsis=200_000 * u.km),
    lambda: orbits.RestrictedThreeBody.from_primaries("Earth", "Moon"),
    lambda: orbits.Ring.from_masses(3, 1 * u.M_sun, 1 * u.AU),
    lambda: orbits.CosmicVelocities.from_surface_gravity(),
    lambda: orbits.SynchronousOrbit.of("Earth"),
    lambda: orbits.Cosmology.einstein_de_sitter(70 * u.km / u.s / u.Mpc),
    lambda: orbits.ExpandingSphere.from_mass(1 * u.M_sun),
]


@pytest.mark.parametrize("make", PUBLIC_OBJECTS)
def test_every_public_object_has_a_one_line_repr_and_an_html_table(make):
    obj = make()
    text = repr(obj)
    assert "\n" not in text and len(text) <= 120 and text.startswith(type(obj).__name__ + "(")
    assert "array(" not in text and "np.float64" not in text and "-0 " not in text
    page = obj._repr_html_()
    assert page.startswith("<table>") and page.count("<tr>") >= 2


def test_reprs_read_in_natural_units():
    assert repr(orbits.Orbit.circular("Earth", 6778 * u.km, inc=51.64 * u.deg)) == (
        "Orbit(6778 x 6778 km, e = 0, i = 51.64 deg, about Earth)")
    assert repr(orbits.Binary.from_elements("Earth", "Moon", a=384399 * u.km, e=0.0549)) == (
        "Binary(Earth + Moon, a = 384399 km, e = 0.0549, T = 27.2845 d)")
    assert repr(orbits.SynchronousOrbit.of("Earth")) == (
        "SynchronousOrbit(r = 42164.17 km, altitude = 35786.07 km, T = 23.93447 h, about Earth)")


def test_the_validation_report_fits_80_columns_and_leads_with_the_verdicts():
    report = run("validate circular lagrange_L4_L5")
    lines = report.splitlines()
    assert max(len(line) for line in lines) <= 80
    assert lines[0] == "circular: passed" and "lagrange_L4_L5: passed" in lines
    checks = [line for line in lines if line.lstrip().startswith(("pass ", "FAIL "))]
    assert len(checks) == 9 and all(line.lstrip().startswith("pass") for line in checks)
    assert "period[satellite] = 97.14195 min" in report  # the analytic value in its display unit
