"""Units and digits as astronomers write them, decided in orbits._common.display: composite units written km / s / Mpc,
headers that never break inside a unit, magnitudes in mag, a zero in its table's unit, small and large numbers
readable, a published model named, a title that names its source once, RA and Dec in h m s and d m s."""

import json
import shlex

import astropy.units as u
import pytest
from typer.testing import CliRunner

from orbits import Cosmology
from orbits._common import display
from orbits_cli.main import app


def run(command):
    result = CliRunner().invoke(app, shlex.split(command), env={"COLUMNS": "80"})
    assert result.exit_code == 0, result.output
    return result.output


@pytest.mark.parametrize(("unit", "text", "compact"), [
    (u.km / u.s / u.Mpc, "km / s / Mpc", "km/s/Mpc"),  # astropy writes km / (Mpc s)
    (u.kg * u.m**2 / u.s, "kg m2 / s", "kg\u00a0m2/s"),  # astropy writes m2 kg / s
    (u.km**3 / u.s**2, "km3 / s2", "km3/s2"),
    (u.kg / u.m**3, "kg / m3", "kg/m3"),
    (u.km / u.s, "km / s", "km/s"),
])
def test_composite_units_read_as_astronomers_write_them(unit, text, compact):
    assert display.unit_text(unit) == text and display.unit_text(unit, compact=True) == compact


def test_a_column_header_never_breaks_inside_its_unit():
    out = run('cosmology --H0 "67.66 km/s/Mpc" --Om 0.30966 --z 0,0.5,1,1100')
    assert "[km/s/Mpc]" in out and "(Mpc" not in out and "[kg/m3]" in out


def test_the_distance_modulus_is_in_magnitudes():
    assert Cosmology.planck18().distance_modulus(1).unit == u.mag
    data = json.loads(run("cosmology --model planck18 --z 1 --format json"))
    assert data["distance_modulus"]["unit"] == "mag"
    assert any(line.split()[-1] == "mag" for line in run("cosmology --model planck18 --z 1").splitlines()
               if line.strip().startswith("distance_modulus"))


def test_a_zero_takes_the_unit_its_table_gives_its_kind():
    """At z = 0 the lookback time reads 0 Gyr beside the age in Gyr, the distances 0 Mpc beside the Hubble
    distance, the comoving volume 0 Gpc3 (they read 0 s, 0 km and 0 m3)."""
    rows = {line.split()[0]: line.split()[1:] for line in run("cosmology --model planck18 --z 0").splitlines()
            if len(line.split()) >= 2}
    assert rows["lookback_time"] == ["0", "Gyr"] and rows["comoving_distance"] == ["0", "Mpc"]
    assert rows["comoving_volume"] == ["0", "Gpc3"]


@pytest.mark.parametrize(("x", "digits", "text"), [
    (0.0004739143, 7, "4.739143e-4"),  # the age at z = 1100 in Gyr read 0.0004739143
    (7700.0, 3, "7700"),  # --digits 3 gave 7.7e3
    (1.538875e7, 7, "1.538875e7"),
    (42164.17, 7, "42164.17"),
    (123456.7, 3, "1.23e5"),
    (-0.0, 7, "0"),
])
def test_numbers_read_plainly_between_a_thousandth_and_the_digits(x, digits, text):
    assert display.number(x, digits) == text


def test_digits_three_shows_a_low_orbit_in_plain_kilometres():
    out = run('orbit --primary Earth --a "7700 km" --only semi_major_axis --digits 3')
    assert "7700" in out and "e3" not in out


def test_a_published_model_is_named_in_its_title():
    assert run("cosmology --model planck18").splitlines()[0].startswith("Planck 2018: flat matter + Lambda")


@pytest.mark.parametrize(("command", "last_row", "source"), [
    ("where Mars --epoch 2026-11-25", "declination", "Positions: JPL DE421"),
    ("orbit Ceres", "time_since_periapsis", "Source: the osculating orbit of JPL Horizons"),
    ("orbit Mars --epoch 2026-01-01", "time_since_periapsis", "Positions: JPL DE421"),
    ('porkchop --from EMB --to Mars --step "10 d"', "time_of_flight", "Positions: JPL DE421"),
])
def test_the_answer_comes_first_and_its_source_once_after_it(command, last_row, source):
    """The title names what is answered; where the numbers come from, and how far to trust them, follow the
    table, once."""
    lines = run(command).splitlines()
    title = " ".join(lines[:lines.index(next(line for line in lines if not line.strip()))])
    assert "DE421" not in title and "Horizons" not in title
    after = " ".join(lines[max(k for k, line in enumerate(lines) if last_row in line) + 1:])
    assert after.strip().startswith(source) and after.count(source) == 1


def test_right_ascension_and_declination_in_hours_and_degrees_minutes_seconds():
    rows = {line.split()[0]: line.split()[1:] for line in run("where Mars --epoch 2026-11-25").splitlines()
            if len(line.split()) >= 2}
    assert rows["right_ascension"][0].startswith("10h08m") and rows["declination"][0].startswith("+13d45m")
    assert display._sexagesimal(359.9999999999, True, 2) == "00h00m00.00s"  # rounds round to 0h, not 24h
    data = json.loads(run("where Mars --epoch 2026-11-25 --format json"))
    assert data["right_ascension"]["unit"] == "rad"  # JSON keeps the exact radians


def test_an_angular_frequency_reads_in_rad_per_second():
    """The pendulum's small-angle omega0 = sqrt(g / L) = 3.131557 rad/s at 1 m read 179.425 deg / s."""
    assert " small_angle_frequency   3.131557   rad / s" in run('pendulum --length "1 m" --amplitude "170 deg"')
