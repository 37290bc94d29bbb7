"""The input rules (orbits.inputs): every value is checked where it enters, so that results are finite or refused
with a one-line error that names the quantity, its value, what is allowed and the unit; no RuntimeWarning."""

import os
import stat
import warnings

import astropy.units as u
import numpy as np
import pytest
from typer.testing import CliRunner

from orbits import Binary, Flyby, Orbit, OrbitDomainError, Ring, UnknownNameError, body
from orbits.io import check_target, write_atomic
from orbits_cli.main import app


@pytest.fixture(autouse=True)
def _warnings_are_errors():
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        yield


@pytest.mark.parametrize(
    "build, fragment",
    [
        (lambda: Orbit.from_elements("Earth", a=7000 * u.km, e=0.1, inc=np.nan * u.deg), "inclination i = nan rad"),
        (lambda: Orbit.from_elements("Earth", a=7000 * u.km, e=0.1, raan=np.nan * u.deg), "Omega = nan rad"),
        (lambda: Orbit.from_elements("Earth", a=7000 * u.km, e=0.1, argp=np.inf * u.deg), "omega = inf rad"),
        (lambda: Orbit.from_elements("Earth", a=1e-300 * u.km, e=0.1), "|a| = 1e-297 m is outside the range"),
        (lambda: Orbit.from_elements("Earth", a=1e300 * u.km, e=0.1), "overflow or underflow float64"),
        (lambda: Orbit.from_elements("Earth", q=7000 * u.km, e=1e300), "e = 1e+300 is outside [0, 1e+12]"),
        (lambda: Orbit.from_vectors("Earth", [1e70, 0, 0] * u.m, [0, 1, 0] * u.m / u.s), "|position r| = 1e+70"),
        (lambda: Orbit.from_vectors("Earth", [7e6, np.nan, 0] * u.m, [0, 1, 0] * u.m / u.s), "position r = nan"),
        (lambda: Binary.from_elements(1e300 * u.kg, 1e300 * u.kg, a=1 * u.AU), "mass m1 = 1e+300 kg"),
        (lambda: Orbit.circular(5e-324 * u.kg, radius=7000 * u.km), "= 5e-324 kg is outside the range"),
        (lambda: Orbit.circular("Earth", radius=-7000 * u.km), "orbit radius r = -7000000.0 m"),
        (lambda: Flyby.past("Earth", v_inf=1e70 * u.m / u.s, b=1 * u.km), "speed at infinity v_inf = 1e+70"),
        (lambda: Ring.from_masses(3, 1 * u.kg, 1e-70 * u.m), "ring radius r = 1e-70 m"),
    ],
)
def test_values_that_would_give_nan_or_overflow_are_refused(build, fragment):
    with pytest.raises(OrbitDomainError) as info:
        build()
    assert fragment in str(info.value) and "\n" not in str(info.value)


def test_the_float64_range_is_wide_enough_for_the_exact_scalings():
    """2**-100 m and 2**100 m (tests/stability: bit-identical scalings) stay inside the accepted range."""
    for scale in (2.0**-100, 2.0**100):
        orbit = Orbit.from_elements(1 * u.m**3 / u.s**2, p=scale * u.m, e=0.5)
        assert np.all(np.isfinite([q.value for q in orbit.quantities().values()]))


def test_an_unknown_body_is_an_orbits_error_and_still_a_key_error():
    with pytest.raises(UnknownNameError, match=r"unknown body 'Vulcan' \(known bodies: Sun, Mercury"):
        body("Vulcan")
    with pytest.raises(KeyError):
        Orbit.circular("Vulcan", 7000 * u.km)
    assert str(UnknownNameError("no quotes")) == "no quotes"


def test_output_targets_are_checked_before_any_work(tmp_path):
    assert check_target(tmp_path / "report.json") == tmp_path / "report.json"
    for path, fragment in [(tmp_path / "missing" / "x.json", "does not exist"), (tmp_path, "is a folder"),
                           ("", "the path is empty")]:
        with pytest.raises(OrbitDomainError, match=fragment):
            check_target(path, "--output")


def test_special_files_are_written_in_place_never_replaced(tmp_path):
    fifo = tmp_path / "pipe"
    os.mkfifo(fifo)
    reader = os.open(fifo, os.O_RDONLY | os.O_NONBLOCK)
    try:
        write_atomic(fifo, "through the pipe\n")
        assert os.read(reader, 100) == b"through the pipe\n"
    finally:
        os.close(reader)
    assert stat.S_ISFIFO(os.stat(fifo).st_mode)
    write_atomic(os.devnull, "nothing")
    assert stat.S_ISCHR(os.stat(os.devnull).st_mode)


@pytest.mark.parametrize(
    "args, fragment",
    [
        (["orbit", "--primary", "Earth", "--a", "7000 km", "--inc", "nan"], "--inc = nan deg is not finite"),
        (["orbit", "--primary", "Earth", "--a", "1e-300 km"], "outside the range orbits computes in"),
        (["binary", "--m1", "1e300 kg", "--m2", "1e300 kg", "--a", "1 AU"], "mass m1 = 1e+300 kg"),
        (["orbit", "--primary", "5e-324 kg", "--a", "7000 km"], "5e-324 kg is outside the range"),
        (["orbit", "--primary", "Earth", "--r", "7000,0,0", "--v", "0,7,0 km/s"], "'7000,0,0' has no unit"),
        (["orbit", "Vulcan"], "unknown body 'Vulcan'"),
        (["validate", "circular", "--output", "/nonexistent-folder/x.json"], "does not exist"),
        (["validate", "circular", "--plot", "/tmp"], "must end in .png"),
        (["validate", "circular", "--backend", ","], "give at least one of rebound, heyoka"),
        (["bench", "api", "--output", "/nonexistent-folder/x.json"], "does not exist"),
    ],
)
def test_the_command_line_refuses_them_in_one_line(args, fragment):
    result = CliRunner().invoke(app, args)
    assert result.exit_code == 2, result.output
    assert fragment in result.stderr and len(result.stderr.strip().splitlines()) == 1


def test_a_body_name_where_a_quantity_belongs_is_named_as_a_body():
    from orbits.inputs import parse_quantity

    with pytest.raises(OrbitDomainError, match="--r1: 'Earth' is a body, not a length"):
        parse_quantity("Earth", "length", "--r1")
    with pytest.raises(OrbitDomainError, match="cannot read 'Eartth' as a quantity"):
        parse_quantity("Eartth", "length", "--r1")
