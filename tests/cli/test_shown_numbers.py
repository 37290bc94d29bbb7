"""No wrong number shown as right: a table's unit label says what its numbers count, and every asked quantity is
shown (or said to be absent), never a placeholder that reads as a value."""

import astropy.units as u
import pytest
from typer.testing import CliRunner

from orbits import Orbit
from orbits._common.display import shown, unit_text
from orbits_cli.main import app

runner = CliRunner()


def row(args: list[str], name: str) -> list[str]:
    """The words of the table row of `name`."""
    result = runner.invoke(app, args)
    assert result.exit_code == 0, result.output
    return next(line.split() for line in result.stdout.splitlines() if line.split()[:1] == [name])


@pytest.mark.parametrize("unit, value, label", [
    ("2 s", 1.577907e7, "2 s"),
    ("3 d", 121.7524, "3 d"),
    ("0.25 d", 1461.01, "0.25 d"),
    ("1e6 s", 31.55815, "10^6 s"),
    ("1e-3 d", 365252.9, "10^-3 d"),
])
def test_a_scaled_display_unit_is_labelled_by_its_own_scale(unit, value, label):
    words = row(["orbit", "Earth", "--only", "period", "--unit", f"period={unit}"], "period")
    assert abs(float(words[1]) / value - 1) < 1e-3  # the number counts `unit`s of the year
    assert " ".join(words[2:]) == label


def test_the_label_of_a_scaled_unit_comes_from_the_scale_not_the_spelling():
    assert unit_text(u.Unit("2 s")) == "2 s" and unit_text(u.Unit("1000 m")) == "10^3 m"
    assert unit_text(u.CompositeUnit(10.0**6, [u.km], [1])) == "10^6 km"
    assert unit_text(u.CompositeUnit(3.0 * 10.0**6, [u.km], [1])) == "3000000 km"
    value, label = shown(Orbit.circular("Earth", radius=7000 * u.km).period, "period", overrides={"period": "7 s"})
    assert float(value) * 7 == pytest.approx(5828.5, rel=1e-4) and label == "7 s"


@pytest.mark.parametrize("unit, fragment", [
    ("period=-1 d", "a unit's scale must be a positive, finite number; got -1"),
    ("period=1e400 s", "a unit's scale must be a positive, finite number; got inf"),
])
def test_a_display_unit_without_a_positive_finite_scale_is_refused(unit, fragment):
    result = runner.invoke(app, ["orbit", "Earth", "--only", "period", "--unit", unit])
    assert result.exit_code == 2 and fragment in result.stderr
    assert len(result.stderr.strip().splitlines()) == 1


@pytest.mark.parametrize("args, fragment", [
    (["orbit", "Earth", "--only", "period", "--unit", "period=1e-320 s"],
     "period = 365.2583 d cannot be shown in 10^-320 s: it would be inf, outside float64's range"),
    (["where", "Mars", "--epoch", "2026-11-25", "--only", "light_time", "--unit", "light_time=1e300 Gyr"],
     "light_time = 10.22819 min cannot be shown in 10^300 Gyr: it would be 0"),
])
def test_a_display_unit_that_would_take_a_value_out_of_float64_is_refused(args, fragment):
    """A unit with a finite scale can still carry a value out of float64: a year in 1e-320 s is 3.2e327 (it was
    printed as inf), ten minutes in 1e300 Gyr 1.9e-314 (below the normal range: its digits lost; the conversion gives
    0)."""
    result = runner.invoke(app, args)
    assert result.exit_code == 2 and fragment in result.stderr and "outside float64's range" in result.stderr
    assert len(result.stderr.strip().splitlines()) == 1


def test_a_small_value_in_float64s_normal_range_is_shown():
    assert row(["orbit", "Earth", "--only", "period", "--unit", "period=1e300 s"], "period")[1] == "3.155832e-293"


def test_an_asked_unit_for_right_ascension_or_declination_is_shown_as_asked():
    """Right ascension and declination read in hours or degrees, minutes and seconds unless a unit is asked."""
    assert row(["where", "Mars", "--epoch", "2026-11-25", "--unit", "right_ascension=deg"],
               "right_ascension")[2] == "deg"
    words = row(["where", "Mars", "--epoch", "2026-11-25", "--unit", "declination=arcmin"], "declination")
    assert words[2] == "arcmin" and 800 < float(words[1]) < 830  # +13d45m is 825 arcmin
    assert row(["where", "Mars", "--epoch", "2026-11-25"], "right_ascension")[1].startswith("10h08m")


def test_the_lagrange_table_shows_e_folding_times_only_when_asked_and_then_for_every_point():
    """--only growth_rate used to add an e-folding column of inf (L1 e-folds in 1.48 d); --only e_folding_time used to
    print the title and no rows."""
    result = runner.invoke(app, ["lagrange", "--primary", "Earth", "--secondary", "Moon", "--only", "growth_rate"])
    assert result.exit_code == 0 and "inf" not in result.stdout and "e-folding" not in result.stdout
    result = runner.invoke(app, ["lagrange", "--primary", "Earth", "--secondary", "Moon", "--only", "e_folding_time"])
    lines = {line.split()[0]: line.split()[1:] for line in result.stdout.splitlines() if line.split()[:1] and
             line.split()[0] in ("L1", "L2", "L3", "L4", "L5")}
    assert float(lines["L1"][0]) == pytest.approx(1.48103, rel=1e-5)  # d, the JSON's 1.4810 d
    assert lines["L4"] == ["inf"] and lines["L5"] == ["inf"]  # linearly stable: they never e-fold


def test_a_point_quantity_asked_for_some_points_is_shown_for_them_and_dashed_for_the_others():
    result = runner.invoke(app, ["lagrange", "--primary", "Earth", "--secondary", "Moon", "--only",
                           "L1_e_folding_time,L4_position,L2_eigenvalues"])
    rows = {line.split()[0]: line.split()[1:] for line in result.stdout.splitlines() if line.split()[:1] and
            line.split()[0] in ("L1", "L2", "L4")}
    assert rows["L4"][:2] == ["0.4878494", "0.8660254"] and rows["L4"][-1] == "-"
    assert rows["L1"][:4] == ["-"] * 4 and float(rows["L1"][-1]) == pytest.approx(35.5447, rel=1e-5)  # h
    assert "L2_eigenvalues" in result.stdout


@pytest.mark.parametrize("args", [
    ["lambert", "--from", "Earth", "--to", "Mars", "--depart", "2026-11-26", "--arrive", "2027-08-15"],
    ["porkchop", "--step", "30 d"],
    ["where", "Mars", "--epoch", "2026-11-25"],
])
def test_every_answer_from_the_built_in_ephemeris_states_its_accuracy(args):
    """The Lambert transfer and the porkchop named the built-in ephemeris but not how far it lies from DE421."""
    result = runner.invoke(app, [*args, "--ephemeris", "builtin"])
    assert result.exit_code == 0, result.output
    text = " ".join(result.stdout.split())
    assert "astropy built-in" in text and "approximate: within 41,029 km of DE421 over 1900-2050" in text
