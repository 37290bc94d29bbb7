"""Tests of the benchmark harness (orbits.tools.bench) on tiny sizes; no timing assertions."""

import importlib.util
import json
import math
import re
import sys

import mpmath
import mpref
import numpy as np
import pytest
from mpmath import mp

from orbits.tools.bench import api, cli, kepler, propagate, suite, validate
from orbits.tools.bench.harness import Method
from orbits.tools.bench.table import WIDTH, rows_to_json

METHODS = [
    "orbits",
    "orbits (all cores)",
    "orbits (NumPy)",
    "heyoka kepE (cfunc)",
    "heyoka kepE (all cores)",
    "rebound.M_to_E",
    "numpy Newton",
    "exoplanet-core",
    "pykep",
]
DATASETS = ["easy", "hard", "hyperbolic"]
SIZES = dict(n_easy=2000, n_hard=2000, n_hyp=2000, n_ref=50, seed=0, repeats=1)


@pytest.fixture(scope="module")
def rows():
    return kepler.bench_kepler(**SIZES)


def row(rows, method, dataset):
    (found,) = [r for r in rows if r.method == method and r.dataset == dataset]
    return found


LAYOUTS = ["easy, adjacent", "easy, offset 8 B", "easy, padded 64 B"]


def test_one_row_per_method_and_dataset(rows):
    """Every method on every set, then orbits on the easy set with its arrays end to end in one buffer."""
    assert [(r.dataset, r.method) for r in rows] == ([(d, m) for d in DATASETS for m in METHODS]
                                                     + [(layout, "orbits") for layout in LAYOUTS])
    for r in rows:
        assert r.status in ("ok", "skipped", "raised")
        if r.status == "ok":
            assert r.n > 0 and r.seconds > 0 and r.throughput_per_s == pytest.approx(r.n / r.seconds)
            assert 0 <= r.n_nan <= r.n


@pytest.mark.parametrize(
    "method, module",
    [
        ("exoplanet-core", "exoplanet_core"),
        ("pykep", "pykep"),
        ("heyoka kepE (cfunc)", "heyoka"),
        ("heyoka kepE (all cores)", "heyoka"),
        ("rebound.M_to_E", "rebound"),
    ],
)
def test_absent_peers_are_skipped_with_a_note(rows, method, module):
    installed = importlib.util.find_spec(module) is not None
    for dataset in DATASETS:
        r = row(rows, method, dataset)
        assert (r.status != "skipped") == installed or r.note == "equation not supported"
        if not installed:
            assert "not installed" in r.note


def test_orbits_is_skipped_only_when_its_module_cannot_be_imported(monkeypatch):
    monkeypatch.setitem(sys.modules, "orbits.core.twobody.kepler", None)  # makes the import raise ImportError
    rows = kepler.bench_kepler(**{**SIZES, "n_easy": 10, "n_hard": 10, "n_hyp": 10, "n_ref": 2})
    assert all(r.status == "skipped" and "not installed" in r.note for r in rows if r.method == "orbits")


def test_rebound_is_timed_per_call_on_a_subset(rows):
    r = row(rows, "rebound.M_to_E", "easy")
    assert r.n == min(SIZES["n_easy"], kepler.PER_CALL_SUBSET) and "per-call" in r.note


def test_heyoka_reports_nans_on_hyperbolic_set(rows):
    pytest.importorskip("heyoka")
    r = row(rows, "heyoka kepE (cfunc)", "hyperbolic")
    assert r.n_nan == r.n and math.isnan(r.max_ulp) and r.setup_seconds > 0


def test_branch_shift_lets_0_to_2pi_conventions_compare(rows):
    # heyoka returns E in [0, 2 pi); its easy-set errors must still be a few ulp.
    pytest.importorskip("heyoka")
    assert row(rows, "heyoka kepE (cfunc)", "easy").max_ulp < 8


def test_numpy_newton_baseline_shows_error_in_hard_corner(rows):
    easy, hard = row(rows, "numpy Newton", "easy"), row(rows, "numpy Newton", "hard")
    assert hard.max_ulp > 1000 and hard.max_ulp > 100 * easy.max_ulp


ELLIPTIC_CASES = [
    (1e-12, 1 - 1e-9),
    (math.pi - 1e-12, 1 - 1e-9),
    (3e-7, 1 - 2**-53),
    (7.5, 0.3),
    (-2.0, 0.99),
    (1e6, 0.5),
    (1.0, 0.0),
    (0.0, 0.7),
]
HYPERBOLIC_CASES = [(1e-6, 1 + 1e-9), (1e6, 1 + 1e-9), (2.0, 1.5), (1e6, 1e3), (-3.0, 2.0), (0.0, 2.0)]


@pytest.mark.parametrize("M, e", ELLIPTIC_CASES)
def test_bench_elliptic_reference_agrees_with_mpref(M, e):
    E, Mr = kepler._reference_elliptic(M, e)
    with mp.workdps(60):
        expected = mpref.kepler_E(M, e)
        assert abs(E - expected) <= mpmath.mpf(10) ** -24 * abs(expected)
        assert abs(Mr - (mpmath.mpf(M) - 2 * mp.pi * round(M / (2 * math.pi)))) <= mpmath.mpf(10) ** -24


@pytest.mark.parametrize("M, e", HYPERBOLIC_CASES)
def test_bench_hyperbolic_reference_agrees_with_mpref(M, e):
    H = kepler._reference_hyperbolic(M, e)
    with mp.workdps(60):
        expected = mpref.kepler_H(M, e)
        assert abs(H - expected) <= mpmath.mpf(10) ** -24 * abs(expected)


def test_worst_errors_measures_ulps_and_shifts_revolutions():
    E = float(mpref.kepler_E(4.0, 0.5))
    refs = [kepler._reference_elliptic(4.0, 0.5)] * 2
    rel, ulp = kepler._worst_errors(np.array([E, E + 2 * math.pi]), refs, periodic=True)
    assert ulp <= 8 and rel <= 8 * 2**-53
    rel, ulp = kepler._worst_errors(np.array([np.nextafter(E, 10.0), math.nan]), refs, periodic=True)
    assert 0.5 <= ulp <= 1.5
    assert math.isnan(kepler._worst_errors(np.array([math.nan]), refs, periodic=False)[0])


def table_rows(table):
    """The lines of the table proper (header and section rules excluded), before the legend and notes."""
    lines = table.splitlines()
    return [line for line in lines[1 : lines.index("")] if not line.startswith("-- ")]


def test_format_and_json(rows):
    table = kepler.format_rows(rows)
    assert table.splitlines()[0].split()[:3] == ["method", "M/s", "ratio"]
    assert all(f"-- {d} --" in table for d in DATASETS)
    assert all(m in table for m in METHODS) and len(table_rows(table)) == len(rows)
    records = rows_to_json(rows)
    json.dumps(records, allow_nan=False)
    assert records[0].keys() >= {
        "method",
        "dataset",
        "n",
        "seconds",
        "throughput_per_s",
        "max_rel_error",
        "max_ulp",
        "n_nan",
        "status",
        "note",
        "setup_seconds",
    }


def test_a_method_that_raises_is_reported_not_fatal(monkeypatch):
    def fail(pair, hyperbolic):
        raise FloatingPointError("no convergence\nsecond line")

    monkeypatch.setattr(kepler, "_METHODS", [("failing", lambda: Method("failing", fail))])
    rows = kepler.bench_kepler(n_easy=10, n_hard=10, n_hyp=10, n_ref=2, repeats=1)
    assert [r.status for r in rows] == ["raised"] * 3
    assert rows[0].note == "raised FloatingPointError: no convergence"
    assert "raised" in kepler.format_rows(rows)


def test_orbits_rows_are_exact_on_every_set(rows):
    for method in ("orbits", "orbits (all cores)", "orbits (NumPy)"):
        for dataset in DATASETS:
            r = row(rows, method, dataset)
            assert r.status == "ok" and r.n_nan == 0 and r.max_ulp <= 4, r


def test_kepler_table_gives_ratios_to_orbits(rows):
    table = kepler.format_rows(rows)
    assert "ratio" in table.splitlines()[0] and "ratio: throughput over that of orbits" in " ".join(table.split())
    orbits = [line.split() for line in table_rows(table) if line.startswith("orbits [")]
    assert len(orbits) == len(DATASETS) + len(LAYOUTS) and all(cells[3] == "1.00" for cells in orbits)


# --- propagation, API, CLI, validation -------------------------------------------------------------

PROPAGATORS = [name for name, _ in propagate._PROPAGATORS]


@pytest.fixture(scope="module")
def propagate_rows():
    return propagate.bench_propagate(n=3000, n_ref=8, seed=1, repeats=1)


def test_propagate_has_one_row_per_method_and_set(propagate_rows):
    expected = [(d, m) for d in ("elliptic", "mixed") for m in PROPAGATORS]
    assert [(r.dataset, r.method) for r in propagate_rows] == expected
    for method, module in (("pykep propagate_lagrangian", "pykep"), ("hapsira farnocchia", "hapsira")):
        r = row(propagate_rows, method, "mixed")
        assert (r.status == "skipped") == (importlib.util.find_spec(module) is None)


def test_orbits_propagates_every_conic_within_1e_13(propagate_rows):
    for method in ("orbits", "orbits (all cores)", "orbits (NumPy)"):
        for dataset in ("elliptic", "mixed"):
            r = row(propagate_rows, method, dataset)
            assert r.status == "ok" and r.n_nan == 0 and r.max_position_error <= 1e-13, r


def test_elliptic_only_peers_give_nan_on_open_orbits(propagate_rows):
    r = row(propagate_rows, "numpy f-and-g + Newton", "mixed")
    assert 0 < r.n_nan < r.n and row(propagate_rows, "numpy f-and-g + Newton", "elliptic").n_nan == 0
    if importlib.util.find_spec("heyoka"):
        assert row(propagate_rows, "heyoka lagrange_prop", "mixed").n_nan > 0


def test_propagate_table_and_json(propagate_rows):
    table = propagate.format_propagate(propagate_rows)
    assert len(table_rows(table)) == len(propagate_rows) and "max |dr|/r" in table
    json.dumps(rows_to_json(propagate_rows), allow_nan=False)


def test_api_rows_compare_the_same_calls():
    rows = api.bench_api(sizes=(1, 2000), repeats=1)
    assert [(r.case.split()[0], r.n) for r in rows] == [
        ("Orbit.propagate", 1),
        ("Orbit.from_elements", 1),
        ("Orbit.propagate", 2000),
        ("Orbit.from_elements", 2000),
    ]
    assert all(r.core_seconds > 0 and r.api_seconds > 0 for r in rows)
    table = api.format_api(rows)
    assert table.splitlines()[0].split()[:2] == ["n", "core"]
    assert all(f"-- {r.case} --" in table for r in rows)


def test_cli_rows_time_fresh_processes():
    rows = cli.bench_cli(runs=2, commands=[(["--help"], 0.2)])
    assert len(rows) == 1  # given commands and no first runs: none of the slow first-ever runs
    assert rows[0].command == "orbits --help" and rows[0].runs == 2 and rows[0].min_seconds <= rows[0].median_seconds
    assert "0.20" in cli.format_cli(rows)


def test_first_runs_are_timed_against_a_warm_second_run():
    """Each first run gives two rows, first ever and warm; the target of a ratio is that ratio times the warm
    time."""
    rows = cli.bench_cli(commands=[], first_runs=[(["--help"], None, 1.5)])
    first, warm = rows
    assert first.command == "orbits --help (first ever: empty kernel cache)" and first.runs == 1
    assert warm.command == "orbits --help (second run, warm cache)" and warm.target_seconds is None
    assert first.target_seconds == pytest.approx(1.5 * warm.median_seconds, rel=1e-15)


def test_validate_rows_split_the_time_by_stage():
    rows = validate.bench_validate(sweep=False)
    scenes = [r for r in rows if r.scene != "all"]
    assert scenes and all({"analytic", "rebound integration", "heyoka setup"} <= r.stages.keys() for r in scenes)
    assert all(abs(sum(r.stages.values()) - r.total_seconds) < 1e-9 for r in scenes)
    # the model scenes' predictions happen when they are built, inside the timing: no stage exceeds the total
    assert all(r.stages["other"] >= 0 for r in scenes), {r.scene: r.stages["other"] for r in scenes}
    assert rows[-1].scene == "all" and rows[-1].total_seconds >= sum(r.total_seconds for r in scenes)
    lines = validate.format_validate(rows).splitlines()
    assert all(any(line.startswith(f"{r.scene}  ") for line in lines) for r in rows)


def test_all_runs_every_benchmark_and_serialises():
    tiny = {
        "kepler": {"n_easy": 200, "n_hard": 200, "n_hyp": 200, "n_ref": 5, "repeats": 1},
        "propagate": {"n": 300, "n_ref": 3, "repeats": 1},
        "lambert": {"n": 300, "n_ref": 3, "repeats": 1},
        "periodic": {"members": 3, "repeats": 1, "numpy": False},
        "ephemeris": {"n": 300, "repeats": 1},
        "api": {"sizes": (1,), "repeats": 1},
        "cli": {"runs": 1, "commands": [(["--help"], 0.2)]},
        "validate": {"sweep": False},
    }
    report = suite.bench_all(**tiny)
    assert list(report) == list(suite.BENCHMARKS)
    text = suite.format_report(report)
    assert all(f"== {name} ==" in text for name in suite.BENCHMARKS)
    json.dumps(suite.report_to_json(report), allow_nan=False)


def test_the_ephemeris_bench_reads_what_jplephem_reads():
    from orbits.tools.bench.ephemeris import bench_ephemeris, format_ephemeris

    rows = bench_ephemeris(n=2000, repeats=1)
    timed = [r for r in rows if r.status == "ok"]
    assert [r.name.split()[0] for r in timed] == ["jplephem", "orbits.ephemeris.positions.state", "astropy"]
    assert all(r.dr == 0.0 and r.dv == 0.0 and r.per_second > 0 for r in timed)  # the same file, the same sums
    assert max(len(line) for line in format_ephemeris(rows).splitlines()) <= WIDTH


# --- 80-column tables -------------------------------------------------------------------------------

LONG_NAME = "a peer solver with an unusually long and descriptive method name (all cores, float128)"
LONG_NOTE = (
    "a deliberately long note that names the compiler, its flags, the thread count, the accuracy knob and why "
    "the package could not be imported on this machine, far beyond any column"
)
LONG_COMMAND = (
    "orbits orbit --primary Earth --a 42164 km --e 0.0001 --i 0.1 deg --raan 75 deg --argp 10 deg "
    "--nu 30 deg --only period,speed,apoapsis,periapsis,specific_energy --format table"
)


def _kepler_rows():
    """Rows of every status on three sets, with extreme figures, long names and long notes."""
    # method, note, setup s, throughput /s, rel err, ulp, NaN
    methods = [
        ("orbits", "compiled, 1 thread", 0.51, 2.713e7, 1.75e-16, 1.02, 0),
        ("heyoka lagrange_prop (all cores)", "", 0.0, 1.23456e9, 1.91e1, 1.2e17, 12),
        (LONG_NAME, LONG_NOTE, 12.5, 999.96, math.nan, math.nan, 666_667),
        ("rebound.M_to_E", "per-call Python API", 0.0, 4.2e3, 3.42e-4, 94.6, 0),
    ]
    nan4 = [math.nan] * 4
    rows = []
    for dataset in ("easy", "hard", "a data set with a long name"):
        for method, note, setup, per_s, rel, ulp, n_nan in methods:
            seconds = 1e6 / per_s
            rows.append(kepler.BenchRow(method, dataset, 10**6, seconds, per_s, rel, ulp, n_nan, "ok", note, setup))
        rows.append(kepler.BenchRow("exoplanet-core", dataset, 0, *nan4, 0, "skipped", LONG_NOTE))
        rows.append(kepler.BenchRow("pykep", dataset, 10, *nan4, 0, "raised", f"raised ValueError: {LONG_NOTE}"))
    return rows


def _propagate_rows():
    return [
        propagate.PropagateRow(r.method, r.dataset, r.n, r.seconds, r.throughput_per_s, r.max_rel_error,
                               r.max_ulp * 1e-3, r.n_nan, r.status, r.note, r.setup_seconds)
        for r in _kepler_rows()
    ]


def _api_rows():
    cases = ["Orbit.from_elements vs elements_to_state", "Orbit.propagate of a long batch vs " + LONG_NAME]
    return [
        api.ApiRow(case, n, core, core * (1 + f), core * f, f)
        for n, core, f in ((1, 2.4e-5, 0.796), (100_000, 0.0105, -0.0051), (1_000_000, 0.18296571, 12.3456))
        for case in cases
    ]


def _cli_rows():
    return [cli.CliRow("orbits --help", 10, 0.153, 0.148, 0.2), cli.CliRow(LONG_COMMAND, 10, 1.632, 1.507, None)]


def _validate_rows():
    backends = ("rebound", "heyoka", "a_third_backend")
    stages = {"analytic": 0.71}
    stages.update({f"{b} {stage}": 0.0333 for b in backends for stage in ("setup", "integration")})
    stages["other"] = -0.0025
    scenes = ["binary", "lagrange_beyond_routh", "a_scene_with_a_very_long_name_from_a_user_file"]
    rows = [validate.ValidateRow(scene, "sequential", stages, 1.473) for scene in scenes]
    rows.append(validate.ValidateRow("all", "sequential", {}, 8.472))
    sweep = {"cluster start": 0.27, "scenes": 4.06}
    rows += [validate.ValidateRow("all", f"sweep, 2 worker {workers}", sweep, 4.3)
             for workers in ("threads", "processes")]
    return rows


def _shown(text, table):
    """Whether text appears in the table as whole words, whatever the line breaks in either."""
    return re.search(r"(?<!\w)" + re.escape(" ".join(text.split())) + r"(?!\w)", " ".join(table.split()))


def _texts(kind, rows):
    """The free text of each row that its table must show in full: names and notes."""
    if kind in ("kepler", "propagate"):
        return [t for r in rows for t in (r.method, r.note, r.dataset)]
    if kind == "api":
        return [r.case for r in rows]
    if kind == "cli":
        return [r.command for r in rows]
    return [r.scene for r in rows] + [r.mode for r in rows] + [w for r in rows for s in r.stages for w in s.split()]


REPRESENTATIVE = {
    "kepler": _kepler_rows,
    "propagate": _propagate_rows,
    "api": _api_rows,
    "cli": _cli_rows,
    "validate": _validate_rows,
}


@pytest.mark.parametrize("kind", [*REPRESENTATIVE, "all"])
def test_tables_fit_80_columns_and_cut_nothing(kind):
    assert len(LONG_NAME) > 80 and len(LONG_NOTE) > 80 and len(LONG_COMMAND) > 80  # wider than any column
    report = {name: make() for name, make in REPRESENTATIVE.items()}
    if kind == "all":
        table, texts = suite.format_report(report), [t for name, rows in report.items() for t in _texts(name, rows)]
    else:
        table, texts = suite.BENCHMARKS[kind][1](report[kind]), _texts(kind, report[kind])
    assert isinstance(table, str) and table.strip()
    too_wide = [line for line in table.splitlines() if len(line) > WIDTH]
    assert not too_wide and WIDTH == 80, "\n".join(too_wide)
    missing = [text for text in texts if text and not _shown(text, table)]
    assert not missing, (missing, table)
    assert "..." not in table and "\u2026" not in table


@pytest.mark.parametrize("call, fragment", [
    ("orbits.tools.bench.kepler:bench_kepler", {"n_easy": 10**13}),
    ("orbits.tools.bench.propagate:bench_propagate", {"n": 10**9}),
    ("orbits.tools.bench.stm:bench_stm", {"n_ref": 10**7}),
    ("orbits.tools.bench.lambert:bench_lambert", {"repeats": 0}),
    ("orbits.tools.bench.ephemeris:bench_ephemeris", {"n": -1}),
    ("orbits.tools.bench.api:bench_api", {"sizes": [10**8]}),
    ("orbits.tools.bench.cli:bench_cli", {"runs": 10**6}),
])
def test_every_benchmark_refuses_a_size_before_it_allocates(call, fragment):
    """The command line bounded the sizes; the library functions, which a notebook calls, did not:
    bench_kepler(n_easy=10**13) set out to allocate 73 TiB. Each is refused at once, naming the argument."""
    import importlib

    from orbits import OrbitDomainError

    module, name = call.split(":")
    (argument, value), = fragment.items()
    argument, value = (f"{argument}[0]", value[0]) if isinstance(value, list) else (argument, value)
    with pytest.raises(OrbitDomainError, match=rf"^{re.escape(argument)} = {value} is outside \[1, "):
        getattr(importlib.import_module(module), name)(**fragment)
