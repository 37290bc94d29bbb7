"""Each value is checked once on its way down: the command line reads the text, the public API checks the value at
its edge (orbits._common.inputs), and the core below trusts it on that path.

A profiler records every call of a rule function (orbits.core.checks, orbits._common.inputs, and the core's check_* and
require_* functions) while a command runs in this process; a rule called inside another rule, or inside the
command line's text parsers, is part of that one check. Each outermost call is charged to the quantity it names.
"""

import sys
from collections import Counter

import pytest
from typer.testing import CliRunner

from orbits_cli.main import app

#: what each rule function checks when it names no quantity itself
IMPLIED = {
    "eccentricity": ("e",),
    "inclination": ("i",),
    "true_anomaly": ("nu",),
    "semi_latus_rectum": ("size",),
    "size_element": ("size",),
    "require_eccentricity": ("e",),
    "require_inside_asymptotes": ("nu",),
    "check_conic": ("size", "e", "nu"),
    "check_elements": ("size", "e", "i", "nu", "mu"),
    "check_state": ("r", "v", "mu"),
}

#: quantity names in messages -> one key per input
KEYS = {
    "eccentricity e": "e", "semi-latus rectum p": "size", "semi-major axis a": "size", "periapsis distance q": "size",
    "semi-major axis |a|": "size", "inclination i": "i", "longitude of the ascending node Omega": "Omega",
    "argument of periapsis omega": "omega", "true anomaly nu": "nu", "primary mass M": "mu",
    "gravitational parameter mu": "mu", "primary mass or gravitational parameter": "mu", "position r": "r",
    "velocity v": "v",
}


#: helpers of the rules that check shapes and sizes or quote values, not a quantity's value
NOT_RULES = {"<module>", "broadcast", "broadcast_shape", "check_size", "check_broadcast", "first_where", "_spaced"}

#: functions of orbits._common.inputs that are no rule on one value: lookups by name, and conic_elements, which
#: reads each element through that element's own rule (counted apart)
COMPOSITES = ("names", "find_body", "named_body", "conic_elements")


def _module(frame) -> str:
    """The dotted name of the module a frame runs in: the module itself, never the folder it was loaded from (a
    checkout named `orbits` with its virtual environment inside puts every file under some `/orbits/`)."""
    return frame.f_globals.get("__name__", "")


def _is_rule(frame) -> bool:
    module, name = _module(frame), frame.f_code.co_name
    if name in NOT_RULES or name.startswith("<"):
        return False
    if module == "orbits.core.checks":
        return True
    if module == "orbits._common.inputs":
        return not name.startswith(("parse_", "_")) and name not in COMPOSITES
    return module.startswith("orbits.core.") and name.startswith(("check_", "require_"))


def _is_text_parser(frame) -> bool:
    return _module(frame) == "orbits._common.inputs" and frame.f_code.co_name.startswith("parse_")


def _importing(frame) -> bool:
    """Whether the call comes from a module of ours being imported (constants computed once, not an input)."""
    while frame is not None:
        if frame.f_code.co_name == "<module>" and _module(frame).partition(".")[0] in ("orbits", "orbits_cli"):
            return True
        frame = frame.f_back
    return False


def checks_during(call) -> Counter:
    """Counter of input key -> outermost rule calls made while `call()` runs (not those of an import)."""
    counts: Counter = Counter()
    depth = [0]

    def profile(frame, event, _arg):
        code = frame.f_code
        if not (_is_rule(frame) or _is_text_parser(frame)):
            return
        if event == "call":
            if depth[0] == 0 and _is_rule(frame) and not _importing(frame.f_back):
                named = frame.f_locals.get("name")
                keys = (KEYS.get(named, named),) if isinstance(named, str) else IMPLIED.get(code.co_name,
                                                                                           (code.co_name,))
                counts.update(keys)
            depth[0] += 1
        elif event == "return":
            depth[0] -= 1

    sys.setprofile(profile)
    try:
        call()
    finally:
        sys.setprofile(None)
    return counts


ORBIT = ["orbit", "--primary", "3.986004418e14 m3/s2", "--a", "7000 km", "--e", "0.5", "--inc", "51.6",
         "--raan", "10", "--argp", "20", "--nu", "30"]


def test_orbit_from_elements_checks_each_input_once():
    """`orbits orbit --e 0.5 ...` with every element and a GM primary: e, the size, i, Omega, omega, nu and mu
    each pass one rule, although the command prints every quantity of the orbit."""
    result = []
    counts = checks_during(lambda: result.append(CliRunner().invoke(app, ORBIT)))
    assert result[0].exit_code == 0, result[0].output
    inputs = {key: counts[key] for key in ("e", "size", "i", "Omega", "omega", "nu", "mu")}
    assert inputs == dict.fromkeys(inputs, 1), counts


def test_the_ledger_sees_the_core_checks():
    """The record is not vacuous: a direct core call (which keeps its own checks) is charged to each element."""
    from orbits.core.twobody.elements import elements_to_state

    counts = checks_during(lambda: elements_to_state(7e6, 0.5, 0.9, 0.1, 0.2, 0.3, 3.986e14))
    assert {key: counts[key] for key in ("size", "e", "i", "nu", "mu")} == dict.fromkeys(("size", "e", "i", "nu",
                                                                                           "mu"), 1)


@pytest.mark.parametrize("args", [ORBIT, ["orbit", "--primary", "Earth", "--r", "7000,0,0 km", "--v",
                                          "0,7.5,1 km/s"]])
def test_no_input_is_checked_twice(args):
    """Whatever the command, no quantity is charged twice."""
    result = []
    counts = checks_during(lambda: result.append(CliRunner().invoke(app, args)))
    assert result[0].exit_code == 0, result[0].output
    assert [key for key, n in counts.items() if n > 1] == [], counts


# ---- an epoch converted once, a state read once ----------------------------------------------------------------


def ephemeris_work_during(call) -> Counter:
    """Counter of "to TDB" (an astropy Time converted to TDB from another scale), "span check" (an epoch held
    against DE421's span) and "read <point>" (a point's barycentric state read from DE421) while `call()` runs."""
    counts: Counter = Counter()

    def profile(frame, event, _arg):
        if event != "call":
            return
        code = frame.f_code
        module = _module(frame)
        if code.co_name == "_set_scale" and module.startswith("astropy.time"):
            if frame.f_locals.get("scale") == "tdb" and frame.f_locals["self"].scale != "tdb":
                counts["to TDB"] += 1
        elif module == "orbits.ephemeris.positions":
            if code.co_name == "_require_de421_span":
                counts["span check"] += 1
            elif code.co_name == "_de421_from_ssb":
                counts["read " + frame.f_locals["point"]] += 1

    sys.setprofile(profile)
    try:
        call()
    finally:
        sys.setprofile(None)
    return counts


INNER = ("Mercury", "Venus", "Earth", "Mars", "Sun")


@pytest.mark.parametrize(("args", "points"), [
    (["where", "Mars", "--epoch", "2026-11-25"], ("Mars", "Sun", "Earth")),
    (["orbit", "Mars", "--epoch", "2026-11-25"], ("Mars", "Sun")),
    (["where", "Mars", "--epoch", "2026-11-25", "--plot", "{tmp}/x.png"], INNER),
    (["where", "Mars", "--epoch", "2026-11-25", "--observer", "Jupiter", "--plot", "{tmp}/x.png"],
     (*INNER, "Jupiter")),
    (["where", "Jupiter", "--epoch", "2026-11-25", "--plot", "{tmp}/x.png"],
     (*INNER, "Jupiter", "Saturn", "Uranus", "Neptune", "Pluto")),
])
def test_an_epoch_is_converted_once_and_each_state_read_once(args, points, tmp_path):
    """The epoch becomes TDB once and is checked against DE421 once; each body's state is read once, the picture's
    included (the command reads every body it and its picture need in one call)."""
    pytest.importorskip("jplephem")
    pytest.importorskip("matplotlib")
    args = [a.format(tmp=tmp_path) for a in args]
    result = []
    counts = ephemeris_work_during(lambda: result.append(CliRunner().invoke(app, args)))
    assert result[0].exit_code == 0, result[0].output
    assert counts == Counter({"to TDB": 1, "span check": 1, **{f"read {p}": 1 for p in points}}), counts


def test_the_solar_system_picture_reads_each_body_once():
    """orbits.plot.solar_system converts its epoch to TDB once, holds it against DE421's span once and reads each
    planet it draws, the Sun and an observer it does not draw (Jupiter, for the line of sight) once each."""
    pytest.importorskip("jplephem")
    import matplotlib

    matplotlib.use("Agg")
    from orbits.plot import solar_system

    counts = ephemeris_work_during(lambda: solar_system("2026-11-25", which="inner", highlight="Mars",
                                                       observer="Jupiter"))
    points = ("Mercury", "Venus", "Earth", "Mars", "Jupiter", "Sun")
    assert counts == Counter({"to TDB": 1, "span check": 1, **{f"read {p}": 1 for p in points}}), counts
