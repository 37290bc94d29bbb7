"""The input rules (orbits._common.inputs): every value is checked where it enters, so that results are finite or
refused
with a one-line error that names the quantity, its value, what is allowed and the unit; no RuntimeWarning."""

import os
import re
import stat
import warnings

import astropy.units as u
import numpy as np
import pytest
from astropy.utils.masked import Masked
from typer.testing import CliRunner

from orbits import Binary, Flyby, Orbit, OrbitDomainError, Ring, UnknownNameError, body
from orbits._common.io import check_target, write_atomic
from orbits.core.twobody import anomalies, elements, kepler, propagate
from orbits_cli.main import app


@pytest.fixture(autouse=True)
def _warnings_are_errors():
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        yield


@pytest.mark.parametrize(
    "build, fragment",
    [
        (lambda: Orbit.from_elements("Earth", a=8000 * u.km, e=0.1, inc=np.nan * u.deg), "inclination i = nan rad"),
        (lambda: Orbit.from_elements("Earth", a=8000 * u.km, e=0.1, raan=np.nan * u.deg), "Omega = nan rad"),
        (lambda: Orbit.from_elements("Earth", a=8000 * u.km, e=0.1, argp=np.inf * u.deg), "omega = inf rad"),
        (lambda: Orbit.from_elements("Earth", a=1e-300 * u.km, e=0.1), "|a| = 1e-297 m is outside the range"),
        (lambda: Orbit.from_elements("Earth", a=1e300 * u.km, e=0.1), "overflow or underflow float64"),
        (lambda: Orbit.from_elements("Earth", q=7000 * u.km, e=1e300), "e = 1e+300 is outside [0, 1e+12]"),
        (lambda: Orbit.from_elements("Earth", a=[1, 1e300] * u.AU, e=0.1),
         "a = 1e+300 AU is beyond float64's range in m (at most 1.798e+308 m)"),
        (lambda: Orbit.circular("Earth", radius=7000 * u.km).speed_at(1e300 * u.AU),
         "distance r = 1e+300 AU is beyond"),
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
    with pytest.raises(UnknownNameError, match=r"unknown body 'Vulcan'; known: Sun, Mercury"):
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
    from orbits._common.inputs import parse_quantity

    with pytest.raises(OrbitDomainError, match="--r1: 'Earth' is a body, not a length"):
        parse_quantity("Earth", "length", "--r1")
    with pytest.raises(OrbitDomainError, match="cannot read 'Eartth' as a quantity"):
        parse_quantity("Eartth", "length", "--r1")


# ---- what a float64 array cannot stand for, and angles that count modulo a turn -----------------------------


@pytest.mark.parametrize("build, fragment", [
    (lambda: Orbit.from_elements("Earth", a=Masked([7000.0, 8000.0] * u.km, mask=[False, True]), e=0.1),
     "semi-major axis a is a masked array; orbits computes every element"),
    (lambda: Orbit.from_elements("Earth", a=[7000, 8000] * u.km, e=np.ma.MaskedArray([0.1, 0.2], mask=[0, 1])),
     "eccentricity e is a masked array"),
    (lambda: Orbit.from_elements("Earth", a=(7000 + 1j) * u.km, e=0.1), "is complex; pass real numbers"),
    (lambda: Orbit.from_elements("Earth", a=8000 * u.km, e=0.1 + 0j), "eccentricity e = (0.1+0j) is complex"),
])
def test_masked_and_complex_values_are_refused_not_stripped(build, fragment):
    """A masked array's masked elements were computed and the mask dropped; a complex length kept its real part
    with only NumPy's warning."""
    with pytest.raises(TypeError, match=re.escape(fragment)):
        build()


def wrapped(value: float, turn: int) -> float:
    """An integer-valued float modulo `turn`, in (-turn/2, turn/2], exactly (Python integers)."""
    rest = int(value) % turn
    return float(rest - turn if rest > turn / 2 else rest)


@pytest.mark.parametrize("degrees, exact", [(1e15, -80.0), (1e20, -80.0), (-1e20, 80.0), (720.5, 0.5), (540.0, 180.0),
                                            (-180.0, 180.0), (2.0**60 + 2.0**10, wrapped(2.0**60 + 2.0**10, 360))])
def test_an_angle_in_degrees_keeps_its_value_however_large(degrees, exact):
    """nu = 1e15 deg gave -79.954 deg (exact: 1e15 mod 360 = 280, i.e. -80); 1e20 deg as a node gave 100.35 deg."""
    orbit = Orbit.from_elements("Earth", a=8000 * u.km, e=0.1, inc=10 * u.deg, raan=degrees * u.deg,
                                nu=degrees * u.deg)
    assert orbit.true_anomaly.to_value(u.deg) == pytest.approx(exact, abs=2e-14)  # one rounding to rad and back
    assert orbit.ascending_node.to_value(u.deg) == pytest.approx(exact % 360, abs=2e-14)


def test_whole_turns_come_off_in_any_unit_a_turn_is_a_whole_number_of():
    one = Orbit.from_elements("Earth", a=8000 * u.km, e=0.1, nu=1e20 * u.arcsec).true_anomaly
    assert one.to_value(u.arcsec) == pytest.approx(wrapped(1e20, 1296000), abs=1e-9)  # 640000 arcsec
    with pytest.raises(OrbitDomainError, match=r"true anomaly nu = 1e\+20 rad is too large for an exact reduction"):
        Orbit.from_elements("Earth", a=8000 * u.km, e=0.1, nu=1e20 * u.rad)


def test_the_mean_and_true_anomalies_agree_and_e_lies_in_its_documented_range():
    """kepler --e 0.1 --nu '1e20 deg' answered while the same --M was refused, and --nu '280 deg' gave E = 285.6 deg,
    outside the documented [-180, 180]."""
    from orbits import anomalies

    from_true = anomalies(0.1, true_anomaly=280 * u.deg)
    assert -np.pi <= from_true["eccentric_anomaly"].to_value(u.rad) <= np.pi
    assert from_true["true_anomaly"].to_value(u.deg) == pytest.approx(-80, abs=1e-13)
    large = anomalies(0.1, mean_anomaly=1e20 * u.deg)  # 1e20 mod 360 = 280: the same as -80 deg
    assert large["mean_anomaly"].to_value(u.deg) == pytest.approx(-80, abs=1e-13)
    back = anomalies(0.1, true_anomaly=large["true_anomaly"])
    assert back["mean_anomaly"].to_value(u.deg) == pytest.approx(-80, abs=1e-12)
    hyperbolic = anomalies(2.0, mean_anomaly=1e5 * u.deg)  # a hyperbola's mean anomaly counts no turns
    assert hyperbolic["mean_anomaly"].to_value(u.deg) == pytest.approx(1e5, rel=1e-15)


@pytest.mark.parametrize("call, named", [
    (lambda: __import__("orbits").lambert([[1, 0, 0], [1, 0, 0]] * u.AU, [[0, 1.5, 0], [0, 1, 0], [0, 2, 0]] * u.AU,
                                          200 * u.day), "r1 (2,), r2 (3,)"),
    (lambda: __import__("orbits").lambert([1, 0, 0] * u.AU, [0, 1.5, 0] * u.AU, [200, 300, 400] * u.day,
                                          revolutions=[0, 1]), "tof (3,), mu (), revolutions (2,)"),
    (lambda: kepler.eccentric_anomaly(np.array([1.0, 2.0]), np.array([0.1, 0.2, 0.3])), "M (2,), e (3,)"),
    (lambda: propagate.propagate(np.ones((2, 3)), np.ones((2, 3)), 1.0, np.ones(3)), "r0, v0 and mu (2,), dt (3,)"),
    (lambda: elements.elements_to_state(np.ones(2), np.zeros(3), 0, 0, 0, 0, 1.0), "p (2,), e (3,)"),
    (lambda: anomalies.true_from_eccentric(np.ones(2), np.zeros(3)), "E (2,), e (3,)"),
])
def test_a_broadcast_mismatch_names_the_arguments(call, named):
    """lambert and the core said only NumPy's "arg 0 with shape (2,) and arg 1 with shape (3,)"."""
    with pytest.raises(OrbitDomainError, match="argument shapes do not broadcast together: .*" + re.escape(named)):
        call()


@pytest.mark.parametrize("args, fragment", [
    (["orbit", "--primary", "Earth", "--r", "1e-300,0,0 km", "--v", "0,7,0 km/s"],
     "|position r| = 1e-297 m is outside the range orbits computes in"),  # 'radial' or 'coincides with the primary'
    (["orbit", "--primary", "Earth", "--r", "1e-330,0,0 km", "--v", "0,7,0 km/s"],
     "--r: '1e-330' is below the smallest float64 (5e-324) and would read as 0"),
    (["orbit", "--primary", "Earth", "--a", "1e-400 km"], "--a: '1e-400' is below the smallest float64"),
])
def test_a_tiny_position_is_named_for_what_it_is(args, fragment):
    result = CliRunner().invoke(app, args)
    assert result.exit_code == 2 and fragment in result.stderr and len(result.stderr.splitlines()) == 1


def test_a_size_no_call_can_hold_is_refused_before_anything_is_made():
    """A billion-element broadcast (a view of one number: cheap to make, 8 GB to convert or propagate) is refused at
    the unit boundary, whatever the argument; so is a broadcast of orbits against times larger than one call
    takes; within the bound the call runs. Each refusal comes at once (nothing of that size was allocated)."""
    import tracemalloc

    from orbits.core.checks import MAX_ELEMENTS

    def huge(value):
        return np.broadcast_to(value, (10**9,))  # a view of one number

    orbit = Orbit.circular("Earth", 7000 * u.km)
    tracemalloc.start()
    for call, what in ((lambda: orbit.propagate(u.Quantity(huge(1.0), u.s, copy=False)), "time step dt"),
                       (lambda: Orbit.from_elements("Earth", a=u.Quantity(huge(7000.0), u.km, copy=False), e=0.1),
                        "semi-major axis a"),
                       (lambda: Orbit.from_elements("Earth", a=7000 * u.km, e=huge(0.1)), "eccentricity"),
                       (lambda: Orbit.from_elements("Earth", a=np.linspace(7000, 8000, 10**5) * u.km).propagate(
                           np.linspace(0, 1, 10**5)[:, None] * u.s), "the orbits times the time steps dt")):
        with pytest.raises(OrbitDomainError, match=f"{what}.*: [0-9,]+ elements, more than the {MAX_ELEMENTS:,}"):
            call()
    _, peak = tracemalloc.get_traced_memory()
    tracemalloc.stop()
    assert peak < 50e6  # measured 8.0 MB (the 10**5 x 10**5 case builds its orbits): nothing of 10**9 was made
    r, _ = orbit.propagate(np.zeros(1000) * u.s)
    assert r.shape == (1000, 3)


def test_a_list_of_quantities_is_one_quantity_and_a_list_that_is_not_says_why():
    """[1 * u.min, 60 * u.s, 1 / 60 * u.h] is what a notebook writes: joined as astropy joins it (it was a raw
    TypeError from astropy); units that do not convert, and numbers without a unit among them, are named."""
    orbit = Orbit.circular("Earth", radius=7000 * u.km)
    r, _, phi = orbit.propagate([1 * u.min, 60 * u.s, 1 / 60 * u.h], stm=True)
    assert r.shape == (3, 3) and phi.shape == (3, 6, 6)
    np.testing.assert_allclose(r.to_value(u.m), np.broadcast_to(r[0].to_value(u.m), (3, 3)), rtol=1e-15)
    with pytest.raises(u.UnitConversionError, match=r"^time step dt is a list whose units do not convert"):
        orbit.propagate([1 * u.min, 5 * u.m])
    with pytest.raises(TypeError, match=r"^time step dt is a list that does not join into one Quantity"):
        orbit.propagate([1 * u.min, 5])
