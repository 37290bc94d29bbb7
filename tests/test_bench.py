"""Tests of the benchmark harness (orbits.tools.bench) on tiny sizes; no timing assertions."""

import importlib.util
import json
import math
import sys

import mpmath
import mpref
import numpy as np
import pytest
from mpmath import mp

from orbits.tools import bench

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
    return bench.bench_kepler(**SIZES)


def row(rows, method, dataset):
    (found,) = [r for r in rows if r.method == method and r.dataset == dataset]
    return found


def test_one_row_per_method_and_dataset(rows):
    assert [(r.dataset, r.method) for r in rows] == [(d, m) for d in DATASETS for m in METHODS]
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
    monkeypatch.setitem(sys.modules, "orbits.core.kepler", None)  # makes the import raise ImportError
    rows = bench.bench_kepler(**{**SIZES, "n_easy": 10, "n_hard": 10, "n_hyp": 10, "n_ref": 2})
    assert all(r.status == "skipped" and "not installed" in r.note for r in rows if r.method == "orbits")


def test_rebound_is_timed_per_call_on_a_subset(rows):
    r = row(rows, "rebound.M_to_E", "easy")
    assert r.n == min(SIZES["n_easy"], bench.PER_CALL_SUBSET) and "per-call" in r.note


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
    E, Mr = bench._reference_elliptic(M, e)
    with mp.workdps(60):
        expected = mpref.kepler_E(M, e)
        assert abs(E - expected) <= mpmath.mpf(10) ** -24 * abs(expected)
        assert abs(Mr - (mpmath.mpf(M) - 2 * mp.pi * round(M / (2 * math.pi)))) <= mpmath.mpf(10) ** -24


@pytest.mark.parametrize("M, e", HYPERBOLIC_CASES)
def test_bench_hyperbolic_reference_agrees_with_mpref(M, e):
    H = bench._reference_hyperbolic(M, e)
    with mp.workdps(60):
        expected = mpref.kepler_H(M, e)
        assert abs(H - expected) <= mpmath.mpf(10) ** -24 * abs(expected)


def test_worst_errors_measures_ulps_and_shifts_revolutions():
    E = float(mpref.kepler_E(4.0, 0.5))
    refs = [bench._reference_elliptic(4.0, 0.5)] * 2
    rel, ulp = bench._worst_errors(np.array([E, E + 2 * math.pi]), refs, periodic=True)
    assert ulp <= 8 and rel <= 8 * 2**-53
    rel, ulp = bench._worst_errors(np.array([np.nextafter(E, 10.0), math.nan]), refs, periodic=True)
    assert 0.5 <= ulp <= 1.5
    assert math.isnan(bench._worst_errors(np.array([math.nan]), refs, periodic=False)[0])


def test_format_and_json(rows):
    table = bench.format_rows(rows)
    assert table.splitlines()[0].split()[:3] == ["method", "dataset", "M/s"]
    assert all(m in table for m in METHODS) and len(table.splitlines()) == len(rows) + 2
    records = bench.rows_to_json(rows)
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

    monkeypatch.setattr(bench, "_METHODS", [("failing", lambda: bench._Method("failing", fail))])
    rows = bench.bench_kepler(n_easy=10, n_hard=10, n_hyp=10, n_ref=2, repeats=1)
    assert [r.status for r in rows] == ["raised"] * 3
    assert rows[0].note == "raised FloatingPointError: no convergence"
    assert "raised" in bench.format_rows(rows)


def test_orbits_rows_are_exact_on_every_set(rows):
    for method in ("orbits", "orbits (all cores)", "orbits (NumPy)"):
        for dataset in DATASETS:
            r = row(rows, method, dataset)
            assert r.status == "ok" and r.n_nan == 0 and r.max_ulp <= 4, r


def test_kepler_table_gives_ratios_to_orbits(rows):
    lines = bench.format_rows(rows).splitlines()
    assert "vs orbits" in lines[0]
    assert all(line.split()[2:4][1] == "1.000" for line in lines[2:] if line.startswith("orbits  "))


# --- propagation, API, CLI, validation -------------------------------------------------------------

PROPAGATORS = [name for name, _ in bench._PROPAGATORS]


@pytest.fixture(scope="module")
def propagate_rows():
    return bench.bench_propagate(n=3000, n_ref=8, seed=1, repeats=1)


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
    table = bench.format_propagate(propagate_rows)
    assert len(table.splitlines()) == len(propagate_rows) + 2 and "max |dr|/r" in table
    json.dumps(bench.rows_to_json(propagate_rows), allow_nan=False)


def test_api_rows_compare_the_same_calls():
    rows = bench.bench_api(sizes=(1, 2000), repeats=1)
    assert [(r.case.split()[0], r.n) for r in rows] == [
        ("Orbit.propagate", 1),
        ("Orbit.from_elements", 1),
        ("Orbit.propagate", 2000),
        ("Orbit.from_elements", 2000),
    ]
    assert all(r.core_seconds > 0 and r.api_seconds > 0 for r in rows)
    assert bench.format_api(rows).splitlines()[0].split()[:2] == ["case", "n"]


def test_cli_rows_time_fresh_processes():
    rows = bench.bench_cli(runs=2, commands=[(["--help"], 0.2)])
    assert rows[0].command == "orbits --help" and rows[0].runs == 2 and rows[0].min_seconds <= rows[0].median_seconds
    assert "0.20" in bench.format_cli(rows)


def test_validate_rows_split_the_time_by_stage():
    rows = bench.bench_validate(sweep=False)
    scenes = [r for r in rows if r.scene != "all"]
    assert scenes and all({"analytic", "rebound integration", "heyoka setup"} <= r.stages.keys() for r in scenes)
    assert all(abs(sum(r.stages.values()) - r.total_seconds) < 1e-9 for r in scenes)
    assert rows[-1].scene == "all" and rows[-1].total_seconds >= sum(r.total_seconds for r in scenes)
    assert len(bench.format_validate(rows).splitlines()) == len(rows) + 2


def test_all_runs_every_benchmark_and_serialises():
    tiny = {
        "kepler": {"n_easy": 200, "n_hard": 200, "n_hyp": 200, "n_ref": 5, "repeats": 1},
        "propagate": {"n": 300, "n_ref": 3, "repeats": 1},
        "api": {"sizes": (1,), "repeats": 1},
        "cli": {"runs": 1, "commands": [(["--help"], 0.2)]},
        "validate": {"sweep": False},
    }
    report = bench.bench_all(**tiny)
    assert list(report) == list(bench.BENCHMARKS)
    text = bench.format_report(report)
    assert all(f"== {name} ==" in text for name in bench.BENCHMARKS)
    json.dumps(bench.report_to_json(report), allow_nan=False)
